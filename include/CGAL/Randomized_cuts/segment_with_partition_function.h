// Copyright (c) 2026 CGAL Global Shape Analysis contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_RANDOMIZED_CUTS_SEGMENT_WITH_PARTITION_FUNCTION_H
#define CGAL_RANDOMIZED_CUTS_SEGMENT_WITH_PARTITION_FUNCTION_H

/// \file segment_with_partition_function.h

#include <CGAL/Randomized_cuts/Segment_with_partition_function_options.h>
#include <CGAL/Randomized_cuts/partition_function.h>
#include <CGAL/Randomized_cuts/internal/Partition_segmentation.h>

#include <string>
#include <type_traits>
#include <vector>

namespace CGAL {
namespace Randomized_cuts {

/*!
\ingroup PkgRandomizedCutsRef

Segments a triangle mesh into parts with its partition function (\cgalCite{Golovinskiy2010},
section 3.4): the mesh is cut along its most consistent cut (see `most_consistent_cuts()`); then,
inside each piece, the partition function is sampled again and the piece's most consistent cut is
proposed as its split; the proposal with the lowest area-normalized cut
\f$\mathrm{cut}(A,B)\,(1/\mathrm{area}(A) + 1/\mathrm{area}(B))\f$ is applied, and so on until
`number_of_segments` segments. The boundaries are finally refined: single faces move to a
neighbouring segment while \f$\sum_S \mathrm{cut}(S)/\mathrm{area}(S)\f$ decreases.

With `number_of_segments` 0 the number is chosen: the splits go on in the same order while the cut
to apply next follows concave creases, that is while its mean concavity weight (its cut cost over
its length, 1 across flat or convex surface) stays below 0.8; the first cut that does not stops
the segmentation once there are 4 segments, and there are at most 12 (fewer when the mesh has
fewer faces). The manual gives the errors of this choice against the human segmentations' own
counts on the Princeton Segmentation Benchmark.

Segment ids are `0 .. n-1`, numbered by decreasing area. The result is the same for any number of
threads.

\tparam TriangleMesh a model of `FaceListGraph` and `EdgeListGraph`
\tparam FaceSegmentMap a model of `WritablePropertyMap` with
        `boost::graph_traits<TriangleMesh>::%face_descriptor` as key and an integer type as value
\tparam NamedParameters a sequence of named parameters

\param tm the triangle mesh (as for `partition_function()`)
\param face_segment_map receives the segment id of every face
\param np the named parameters of `partition_function()` (every partition function is sampled
       with them; `MIN_CUT` is the only `sampling_method` whose samples are cuts, the default), and:

\cgalNamedParamsBegin
  \cgalParamNBegin{number_of_segments}
    \cgalParamDescription{the number of segments to produce, or 0 to choose it (see above)}
    \cgalParamType{`std::size_t`}
    \cgalParamDefault{`Segment_with_partition_function_options::number_of_segments`}
    \cgalParamExtra{must be at most the number of faces}
  \cgalParamNEnd
  \cgalParamNBegin{boundary_refinement}
    \cgalParamDescription{whether single faces are moved between segments at the end while the
      normalized cut decreases}
    \cgalParamType{`bool`}
    \cgalParamDefault{`Segment_with_partition_function_options::boundary_refinement`}
  \cgalParamNEnd
  \cgalParamNBegin{edge_value_map}
    \cgalParamDescription{receives the partition function of the whole mesh}
    \cgalParamType{a model of `WritablePropertyMap` with `edge_descriptor` as key and a
      floating-point type as value}
    \cgalParamDefault{not written}
  \cgalParamNEnd
\cgalNamedParamsEnd

\returns the number of segments written to `face_segment_map` (fewer than `number_of_segments`
         only if the mesh has fewer faces; with `number_of_segments` 0, the number chosen)

\throws CGAL::Shape_analysis::Bad_input as `partition_function()`, if `number_of_segments` is out
        of range, or if the `sampling_method` is not `MIN_CUT`.
*/
template <typename TriangleMesh, typename FaceSegmentMap,
          typename NamedParameters = parameters::Default_named_parameters>
std::size_t segment_with_partition_function(const TriangleMesh& tm, FaceSegmentMap face_segment_map,
                                            const NamedParameters& np = parameters::default_values())
{
  using CGAL::parameters::get_parameter;
  namespace snp = CGAL::Shape_analysis::internal_np;
  const std::string who = "segment_with_partition_function";
  const Segment_with_partition_function_options o = segment_with_partition_function_options(np);
  const std::size_t k = o.number_of_segments; // 0: chosen
  internal::Mesh_sampling<TriangleMesh, NamedParameters> sampling(tm, np, internal::sampling_options(o, np), who);
  const auto& g = sampling.graph();
  if(k > g.number_of_nodes())
    throw Bad_input(who + ": number_of_segments (" + std::to_string(k) +
                    ") exceeds the number of faces (" + std::to_string(g.number_of_nodes()) + ")");
  if(sampling.options.sampling_method != MIN_CUT)
    throw Bad_input(who + ": the sampling_method must be MIN_CUT (its samples are cuts)");
  if(sampling.options.part_sizes.size() != 1)
    throw Bad_input(who + ": one part size only");

  std::vector<double> values;
  auto value_map = get_parameter(np, snp::edge_value_map_tag);
  constexpr bool want_values =
    !std::is_same<decltype(value_map), CGAL::internal_np::Param_not_found>::value;
  internal::Partition_segmentation segmentation(g, o, sampling.options);
  const std::vector<std::size_t> labels = segmentation.run(want_values ? &values : nullptr);
  if constexpr(want_values) {
    std::vector<double> by_rank;
    internal::write_edge_values(sampling, values, value_map, by_rank);
  }
  std::size_t count = 0;
  const auto& faces = sampling.mesh_graph.faces;
  for(std::size_t i = 0; i < faces.size(); ++i) {
    put(face_segment_map, faces[i], labels[i]);
    count = (std::max)(count, labels[i] + 1);
  }
  return count;
}

} // namespace Randomized_cuts
} // namespace CGAL

#endif // CGAL_RANDOMIZED_CUTS_SEGMENT_WITH_PARTITION_FUNCTION_H
