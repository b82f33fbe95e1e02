// Copyright (c) 2026 CGAL Global Shape Analysis contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_RANDOMIZED_CUTS_MOST_CONSISTENT_CUTS_H
#define CGAL_RANDOMIZED_CUTS_MOST_CONSISTENT_CUTS_H

/// \file most_consistent_cuts.h

#include <CGAL/Randomized_cuts/partition_function.h>
#include <CGAL/Randomized_cuts/internal/Consistent_cuts.h>

#include <boost/graph/graph_traits.hpp>

#include <cmath>
#include <limits>
#include <string>
#include <type_traits>
#include <vector>

namespace CGAL {
namespace Randomized_cuts {

/*!
\ingroup PkgRandomizedCutsRef

One distinct cut among the sampled segmentations of a mesh, as `most_consistent_cuts()` returns
them.

\tparam TriangleMesh the mesh type
*/
template <typename TriangleMesh>
struct Cut
{
  /// The edge type of the mesh.
  typedef typename boost::graph_traits<TriangleMesh>::edge_descriptor edge_descriptor;
  /// The face type of the mesh.
  typedef typename boost::graph_traits<TriangleMesh>::face_descriptor face_descriptor;

  /// The mesh edges the cut goes through, in the order of `edges(tm)`. A cut that only separates
  /// connected components of the mesh from each other crosses no edge: it is empty then.
  std::vector<edge_descriptor> edges;
  /// `MIN_CUT` sampling: the faces of the side of smaller area; empty for the segmentations of the
  /// other samplers, which have more than two segments.
  std::vector<face_descriptor> smaller_side;
  /// The consistency: the length-weighted mean of the partition function over `edges`, in
  /// \f$[0, 1]\f$ (for a cut that only separates connected components, the mean value of the
  /// links between components that it cuts).
  double consistency = 0;
  /// The total length of `edges`.
  double length = 0;
  /// The area-normalized cut \f$J = \sum_S \mathrm{cut}(S)/\mathrm{area}(S)\f$ of the sampled
  /// segmentation, under the concavity-weighted cut costs (lower is a cleaner cut).
  double normalized_cut = 0;
  /// The number of samples that gave this cut (itself and its duplicates).
  std::size_t number_of_samples = 0;
  /// The index of the sample that represents it (its most consistent sample; the index of its
  /// random stream).
  std::size_t sample_index = 0;
};

/*!
\ingroup PkgRandomizedCutsRef

The options of `most_consistent_cuts()`: those of the partition function it samples
(`Partition_function_options`) and those of the list of cuts; each member is the named parameter
of the same name, initialized to its default.
*/
struct Most_consistent_cuts_options : Partition_function_options
{
  /// The defaults of `Partition_function_options`, except `sampling_method`: `MIN_CUT`, whose
  /// samples are single cuts (the thesis' most consistent cuts); the other samplers' segmentations
  /// are listed as their sets of cut edges.
  Most_consistent_cuts_options() { sampling_method = MIN_CUT; }

  /// the largest number of cuts returned (the largest `std::size_t`: all distinct cuts)
  std::size_t number_of_cuts = (std::numeric_limits<std::size_t>::max)();
  /// `MIN_CUT` sampling: two cuts whose smaller sides differ by at most this fraction of the
  /// smaller side's area are one cut (in \f$[0, 1]\f$)
  double duplicate_tolerance = 0.1;
};

/*!
\ingroup PkgRandomizedCutsRef

The options that `most_consistent_cuts()` reads from the named parameters `np`: the value of each
named parameter given, the default of `Most_consistent_cuts_options` for the others. The values
are not checked here; `most_consistent_cuts()` checks them. Named parameters that are not options
(property maps, traits) are ignored.

\tparam NamedParameters a sequence of named parameters
\param np the named parameters, as given to the function whose options these are
\returns the options, each from its named parameter or its default
*/
template <typename NamedParameters = parameters::Default_named_parameters>
Most_consistent_cuts_options most_consistent_cuts_options(const NamedParameters& np = parameters::default_values())
{
  using CGAL::Shape_analysis::internal::parameter_value;
  namespace snp = CGAL::Shape_analysis::internal_np;
  Most_consistent_cuts_options o;
  internal::read_partition_function_options(np, o);
  o.number_of_cuts = parameter_value(np, snp::number_of_cuts_tag, o.number_of_cuts);
  o.duplicate_tolerance = parameter_value(np, snp::duplicate_tolerance_tag, o.duplicate_tolerance);
  return o;
}

/*!
\ingroup PkgRandomizedCutsRef

Samples segmentations of a triangle mesh as `partition_function()` does (with `MIN_CUT` by default,
see `Most_consistent_cuts_options`) and returns their distinct
cuts, the most consistent first (\cgalCite{Golovinskiy2010}, section 3.4).

The consistency of a sampled segmentation is the length-weighted mean of the partition function
over the edges it cuts: a cut that most other samples also make (along a neck, a crease) has a
consistency near 1, a cut through the middle of a part a low one. Duplicates are merged: samples
that cut the same edges, and, with `MIN_CUT` sampling, samples whose smaller sides differ by at most
`duplicate_tolerance` of the smaller of the two sides' areas (the same part, cut a few faces
away), count as one cut, represented by its most consistent sample.

\tparam TriangleMesh a model of `FaceListGraph` and `EdgeListGraph`
\tparam NamedParameters a sequence of named parameters

\param tm the triangle mesh (as for `partition_function()`)
\param np the named parameters of `partition_function()`, and:

\cgalNamedParamsBegin
  \cgalParamNBegin{number_of_cuts}
    \cgalParamDescription{the largest number of cuts returned}
    \cgalParamType{`std::size_t`}
    \cgalParamDefault{`Most_consistent_cuts_options::number_of_cuts` (all distinct cuts)}
  \cgalParamNEnd
  \cgalParamNBegin{duplicate_tolerance}
    \cgalParamDescription{`MIN_CUT` sampling: two cuts whose smaller sides differ by at most this
      fraction of the smaller side's area are one cut}
    \cgalParamType{`double`}
    \cgalParamDefault{`Most_consistent_cuts_options::duplicate_tolerance`}
    \cgalParamExtra{must be in \f$[0, 1]\f$}
  \cgalParamNEnd
  \cgalParamNBegin{edge_value_map}
    \cgalParamDescription{receives the partition function of the edges the cuts were ranked with}
    \cgalParamType{a model of `WritablePropertyMap` with `edge_descriptor` as key and a
      floating-point type as value}
    \cgalParamDefault{not written}
  \cgalParamNEnd
\cgalNamedParamsEnd

\returns the distinct cuts, by decreasing consistency (ties: lower `normalized_cut` first)

\throws CGAL::Shape_analysis::Bad_input as `partition_function()`, or if a parameter is out of
        its range.
*/
template <typename TriangleMesh, typename NamedParameters = parameters::Default_named_parameters>
std::vector<Cut<TriangleMesh>>
most_consistent_cuts(const TriangleMesh& tm, const NamedParameters& np = parameters::default_values())
{
  using CGAL::parameters::get_parameter;
  namespace snp = CGAL::Shape_analysis::internal_np;
  const std::string who = "most_consistent_cuts";
  const Most_consistent_cuts_options o = most_consistent_cuts_options(np);
  internal::Mesh_sampling<TriangleMesh, NamedParameters> sampling(tm, np, internal::sampling_options(o, np), who);
  if(sampling.options.part_sizes.size() != 1)
    throw Bad_input(who + ": one part size only");
  const double tolerance = o.duplicate_tolerance;
  if(!(tolerance >= 0 && tolerance <= 1))
    throw Bad_input(who + ": duplicate_tolerance must be in [0, 1]");
  const std::size_t max_cuts = o.number_of_cuts;
  sampling.options.keep_samples = true;
  const internal::Sampling_result r = sampling.run();
  const auto& g = sampling.graph();

  auto value_map = get_parameter(np, snp::edge_value_map_tag);
  if constexpr(!std::is_same<decltype(value_map), CGAL::internal_np::Param_not_found>::value) {
    std::vector<double> by_rank;
    internal::write_edge_values(sampling, r.values[0], value_map, by_rank);
  }

  const std::vector<internal::Graph_cut> cuts = internal::distinct_cuts(
    g, r.samples, r.values[0], 0, sampling.options.sampling_method == MIN_CUT, tolerance);
  std::vector<Cut<TriangleMesh>> result;
  const auto& mg = sampling.mesh_graph;
  for(const internal::Graph_cut& c : cuts) {
    if(result.size() >= max_cuts)
      break;
    Cut<TriangleMesh> cut;
    std::vector<std::size_t> ranks;
    for(std::uint32_t e : c.cut_edges)
      if(g.mesh_edge[e] != internal::Dual_graph::no_mesh_edge)
        ranks.push_back(g.mesh_edge[e]);
    std::sort(ranks.begin(), ranks.end());
    for(std::size_t rank : ranks)
      cut.edges.push_back(mg.edges[rank]);
    for(std::uint32_t v : c.smaller_side)
      cut.smaller_side.push_back(mg.faces[v]);
    cut.consistency = c.consistency;
    cut.length = c.length * g.length_unit; // the graph's lengths are in units of length_unit
    cut.normalized_cut = c.score / g.length_unit;
    cut.number_of_samples = c.occurrences;
    cut.sample_index = c.first_sample;
    result.push_back(std::move(cut));
  }
  return result;
}

} // namespace Randomized_cuts
} // namespace CGAL

#endif // CGAL_RANDOMIZED_CUTS_MOST_CONSISTENT_CUTS_H
