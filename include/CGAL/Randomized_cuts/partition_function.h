// Copyright (c) 2026 CGAL Global Shape Analysis contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_RANDOMIZED_CUTS_PARTITION_FUNCTION_H
#define CGAL_RANDOMIZED_CUTS_PARTITION_FUNCTION_H

/// \file partition_function.h

#include <CGAL/Randomized_cuts/Partition_function_options.h>
#include <CGAL/Randomized_cuts/Sampling_method.h>
#include <CGAL/Randomized_cuts/internal/Mesh_sampling.h>
#include <CGAL/Shape_analysis/Bad_input.h>
#include <CGAL/Shape_analysis/parameters.h>

#include <boost/property_map/property_map.hpp>

#include <string>
#include <vector>

namespace CGAL {
namespace Randomized_cuts {

using CGAL::Shape_analysis::Bad_input;

/*!
\ingroup PkgRandomizedCutsRef

What a computation of the partition function did.
*/
struct Partition_function_result
{
  /// The number of segmentations sampled.
  std::size_t number_of_samples = 0;
  /// Whether sampling stopped because the largest change of an edge value over the last batch of
  /// samples fell under `convergence_tolerance` (always `false` without a tolerance).
  bool converged = false;
  /// The largest change of an edge value over the last batch of samples (computed only with a
  /// `convergence_tolerance`; 0 otherwise).
  double largest_change = 0;
};

/// \cond SKIP_IN_MANUAL
namespace internal {

template <typename Sampling, typename EdgeValueMap, typename Value>
void write_edge_values(const Sampling& sampling, const std::vector<double>& values,
                       EdgeValueMap edge_value_map, std::vector<Value>& by_rank)
{
  const auto& g = sampling.graph();
  by_rank.assign(g.number_of_mesh_edges, Value(0));
  for(std::size_t e = 0; e < g.number_of_edges(); ++e)
    if(g.mesh_edge[e] != Dual_graph::no_mesh_edge)
      by_rank[g.mesh_edge[e]] = static_cast<Value>(values[e]);
  const auto& edges = sampling.mesh_graph.edges;
  for(std::size_t r = 0; r < edges.size(); ++r)
    put(edge_value_map, edges[r], by_rank[r]);
}

inline Partition_function_result make_result(const Sampling_result& r)
{
  Partition_function_result result;
  result.number_of_samples = r.number_of_samples;
  result.converged = r.converged;
  result.largest_change = r.largest_change;
  return result;
}

// partition_function() with the maps of `mesh_np` and the options `o`.
template <typename TriangleMesh, typename EdgeValueMap, typename MeshNamedParameters>
Partition_function_result partition_function_impl(const TriangleMesh& tm, EdgeValueMap edge_value_map,
                                                  const MeshNamedParameters& mesh_np,
                                                  const Sampling_options& o)
{
  typedef typename boost::property_traits<EdgeValueMap>::value_type Value;
  const Mesh_sampling<TriangleMesh, MeshNamedParameters> sampling(tm, mesh_np, o, "partition_function");
  if(sampling.options.part_sizes.size() != 1)
    throw Bad_input("partition_function: one part size only (use multiscale_partition_function)");
  const Sampling_result r = sampling.run();
  std::vector<Value> by_rank;
  write_edge_values(sampling, r.values[0], edge_value_map, by_rank);
  return make_result(r);
}

} // namespace internal
/// \endcond

/*!
\ingroup PkgRandomizedCutsRef

Computes the partition function of a triangle mesh: for every edge, the fraction of randomly
sampled segmentations of the mesh whose boundaries go through it (\cgalCite{Golovinskiy2010},
section 3.4). Edges where natural parts meet get values near 1; edges inside parts, near 0.

Segmentations are drawn from the weighted dual graph of the mesh (faces are nodes), where cutting
the edge between two faces costs its length times \f$\min((\theta/\pi)^\alpha, 1)\f$ and
crossing it costs the distance of the face centroids divided by the same weight (\f$\theta\f$ is
the dihedral angle measured outside the surface): cheap to cut and long to cross at concave
creases. Three samplers are available (`sampling_method`):
- `MIN_CUT`: a random source face and a random sink face (drawn by area); the cut cost
  of every edge is multiplied by a penalty of its relative distance
  \f$d = \min(d_A, d_B)/(d_A + d_B)\f$ from the two faces (traversal-cost geodesics): \f$W = 400s+1\f$
  for \f$d \le s\f$, falling linearly to 1 at \f$d = 3s\f$ and 1 beyond, so that neither side is
  smaller than about the part size \f$s\f$; then the minimum cut between the two faces.
- `K_MEANS`: `number_of_clusters` random seed faces; every face joins its nearest seed; every seed
  moves to the face of its segment furthest from the segment's boundary; until the seeds stop
  (at most 30 rounds).
- `HIERARCHICAL`: area-normalized-cut merging where each merge is drawn at random among the
  candidates, with probability about proportional to \f$|\Delta J|^{1/r}\f$ (the candidates' gains
  mapped to their share of the best one, raised to \f$1/r\f$); each run contributes its
  segmentations into 2, ..., `number_of_clusters` segments. The default: its values rank the edges
  where people draw part boundaries better than local concavity does, by ROC area and by the
  precision of the top 2% (the other two samplers do not; see the manual).

Faces of different connected components are joined by weak links (as in
`CGAL::Consistent_segmentation::hierarchical_segmentation()`), so that a model made of pieces is
cut as one object. Sample \f$i\f$ draws its random numbers from a stream of its own, seeded by
(`random_seed`, \f$i\f$), and samples are added up in order: the result is the same for any number of
threads.

\tparam TriangleMesh a model of `FaceListGraph` and `EdgeListGraph` (for example
        `CGAL::Surface_mesh` or `CGAL::Polyhedron_3`)
\tparam EdgeValueMap a model of `WritablePropertyMap` with
        `boost::graph_traits<TriangleMesh>::%edge_descriptor` as key and a floating-point type as
        value
\tparam NamedParameters a sequence of named parameters

\param tm the triangle mesh: non-empty, triangles only, finite coordinates, positive area, at
          least two faces
\param edge_value_map receives the value of every edge, in \f$[0, 1]\f$ (0 on border edges)
\param np an optional sequence of named parameters among the ones listed below

\cgalNamedParamsBegin
  \cgalParamNBegin{sampling_method}
    \cgalParamDescription{how segmentations are sampled}
    \cgalParamType{`CGAL::Randomized_cuts::Sampling_method`}
    \cgalParamDefault{`Partition_function_options::sampling_method`}
  \cgalParamNEnd
  \cgalParamNBegin{number_of_samples}
    \cgalParamDescription{the number of segmentations to sample}
    \cgalParamType{`std::size_t`}
    \cgalParamDefault{`Partition_function_options::number_of_samples`}
  \cgalParamNEnd
  \cgalParamNBegin{convergence_tolerance}
    \cgalParamDescription{stop early, after a batch of 64 samples, when no edge value changed by
      more than this over the batch; 0 draws every sample}
    \cgalParamType{`double`}
    \cgalParamDefault{`Partition_function_options::convergence_tolerance`}
  \cgalParamNEnd
  \cgalParamNBegin{random_seed}
    \cgalParamDescription{the seed of the random numbers}
    \cgalParamType{`unsigned int`}
    \cgalParamDefault{`Partition_function_options::random_seed`}
  \cgalParamNEnd
  \cgalParamNBegin{part_size}
    \cgalParamDescription{`MIN_CUT`: the part size \f$s\f$ of the penalty near the source and sink
      faces, as a fraction of the relative distance; given without `sampling_method`, it selects
      `MIN_CUT`}
    \cgalParamType{`double`}
    \cgalParamDefault{`Partition_function_options::part_size`}
    \cgalParamExtra{must be in \f$(0, 1/6]\f$}
  \cgalParamNEnd
  \cgalParamNBegin{number_of_clusters}
    \cgalParamDescription{`K_MEANS`: the number of seeds; `HIERARCHICAL`: the largest number of
      segments of the segmentations a run contributes}
    \cgalParamType{`std::size_t`}
    \cgalParamDefault{`Partition_function_options::number_of_clusters`}
    \cgalParamExtra{must be at least 2}
  \cgalParamNEnd
  \cgalParamNBegin{randomness}
    \cgalParamDescription{`HIERARCHICAL`: the randomness \f$r\f$ of the merge choice (smaller is
      closer to the deterministic clustering)}
    \cgalParamType{`double`}
    \cgalParamDefault{`Partition_function_options::randomness`}
  \cgalParamNEnd
  \cgalParamNBegin{score_weighting}
    \cgalParamDescription{whether each sampled segmentation counts with weight
      \f$1/J\f$, \f$J = \sum_S \mathrm{cut}(S)/\mathrm{area}(S)\f$ under the plain cut costs, so that
      segmentations along deep creases count more; otherwise every sample counts the same}
    \cgalParamType{`bool`}
    \cgalParamDefault{`Partition_function_options::score_weighting`}
  \cgalParamNEnd
  \cgalParamNBegin{number_of_threads}
    \cgalParamDescription{the largest number of threads used (with TBB); 0 for all cores. The
      result does not depend on it}
    \cgalParamType{`std::size_t`}
    \cgalParamDefault{`Partition_function_options::number_of_threads`}
  \cgalParamNEnd
  \cgalParamNBegin{concavity_exponent}
    \cgalParamDescription{the exponent \f$\alpha\f$ of the concavity weight}
    \cgalParamType{`double`}
    \cgalParamDefault{`Partition_function_options::concavity_exponent`}
  \cgalParamNEnd
  \cgalParamNBegin{component_link_distance}
    \cgalParamDescription{faces of different connected components closer than this fraction of
      the bounding-box diagonal are linked}
    \cgalParamType{`double`}
    \cgalParamDefault{`Partition_function_options::component_link_distance`}
  \cgalParamNEnd
  \cgalParamNBegin{component_link_factor}
    \cgalParamDescription{the cut cost of a link between components, relative to the mean cut cost
      of the mesh edges}
    \cgalParamType{`double`}
    \cgalParamDefault{`Partition_function_options::component_link_factor`}
  \cgalParamNEnd
  \cgalParamNBegin{progress_callback}
    \cgalParamDescription{called after every batch of samples with the fraction drawn}
    \cgalParamType{a callable convertible to `std::function<void(double)>`}
    \cgalParamDefault{none}
  \cgalParamNEnd
  \cgalParamNBegin{vertex_point_map}
    \cgalParamDescription{a property map associating points to the vertices of `tm`}
    \cgalParamType{a class model of `ReadablePropertyMap` with `vertex_descriptor` as key and
      a point type of a CGAL kernel as value}
    \cgalParamDefault{`boost::get(CGAL::vertex_point, tm)`}
  \cgalParamNEnd
  \cgalParamNBegin{geom_traits}
    \cgalParamDescription{an instance of a geometric traits class, used to read the coordinates}
    \cgalParamType{a class model of `Kernel`}
    \cgalParamDefault{a \cgal Kernel deduced from the point type, using `CGAL::Kernel_traits`}
  \cgalParamNEnd
  \cgalParamNBegin{face_index_map}
    \cgalParamDescription{a property map associating to each face of `tm` a unique index}
    \cgalParamType{a class model of `ReadablePropertyMap` with `face_descriptor` as key and
      `std::size_t` as value}
    \cgalParamDefault{an automatically indexed internal map}
  \cgalParamNEnd
\cgalNamedParamsEnd

\returns the number of samples drawn and whether they converged

\throws CGAL::Shape_analysis::Bad_input if `tm` has no faces, a single face, a face that is not a
        triangle, a coordinate that is not finite or no area, or if a parameter is out of its
        range; `edge_value_map` is then left untouched.

\sa `multiscale_partition_function()`, `most_consistent_cuts()`
*/
template <typename TriangleMesh, typename EdgeValueMap,
          typename NamedParameters = parameters::Default_named_parameters>
Partition_function_result partition_function(const TriangleMesh& tm, EdgeValueMap edge_value_map,
                                             const NamedParameters& np = parameters::default_values())
{
  return internal::partition_function_impl(tm, edge_value_map, np, internal::sampling_options(np));
}

/*!
\ingroup PkgRandomizedCutsRef

The options of `multiscale_partition_function()`: those of `partition_function()` (its `part_size`
is not used) and the list of part sizes; each member is the named parameter of the same name,
initialized to its default.
*/
struct Multiscale_partition_function_options : Partition_function_options
{
  /// The defaults of `Partition_function_options`, except `sampling_method`: `MIN_CUT`, the only
  /// sampler with a part size.
  Multiscale_partition_function_options() { sampling_method = MIN_CUT; }

  /// the part sizes \f$s\f$, each in \f$(0, 1/6]\f$ (at least one)
  std::vector<double> part_sizes = {0.02, 0.05, 0.1};
};

/*!
\ingroup PkgRandomizedCutsRef

The options that `multiscale_partition_function()` reads from the named parameters `np`: the value
of each named parameter given, the default of `Multiscale_partition_function_options` for the
others. The values are not checked here; `multiscale_partition_function()` checks them. Named
parameters that are not options (property maps, traits) are ignored.

\tparam NamedParameters a sequence of named parameters
\param np the named parameters, as given to the function whose options these are
\returns the options, each from its named parameter or its default
*/
template <typename NamedParameters = parameters::Default_named_parameters>
Multiscale_partition_function_options
multiscale_partition_function_options(const NamedParameters& np = parameters::default_values())
{
  using CGAL::Shape_analysis::internal::parameter_value;
  namespace snp = CGAL::Shape_analysis::internal_np;
  Multiscale_partition_function_options o;
  internal::read_partition_function_options(np, o);
  o.part_sizes = parameter_value(np, snp::part_sizes_tag, o.part_sizes);
  return o;
}

/*!
\ingroup PkgRandomizedCutsRef

Computes the partition function of a triangle mesh for several part sizes at once (min-cut
sampling): every sample draws one source face and one sink face, computes the distances from both
once, and solves one minimum cut per part size, from the smallest part size to the largest; as
the penalties only grow with the part size, each cut continues from the flow of the previous one
instead of starting again (three part sizes cost about 1.5 times one). Small part sizes show small
features (fingers), large ones the main parts (limbs); the values of one part size are those
`partition_function()` gives with the same `random_seed` and that `part_size`, except where
rounding decides between two equally cheap cuts of a sample.

\tparam TriangleMesh a model of `FaceListGraph` and `EdgeListGraph`
\tparam EdgeValuesMap a model of `WritablePropertyMap` with
        `boost::graph_traits<TriangleMesh>::%edge_descriptor` as key and `std::vector<double>` as
        value
\tparam NamedParameters a sequence of named parameters

\param tm the triangle mesh (as for `partition_function()`)
\param edge_values_map receives, for every edge, one value per part size, in the order of
       `part_sizes`
\param np the named parameters of `partition_function()` (its `sampling_method` must be `MIN_CUT`,
       its `part_size` is not used), and:

\cgalNamedParamsBegin
  \cgalParamNBegin{part_sizes}
    \cgalParamDescription{the part sizes \f$s\f$}
    \cgalParamType{`std::vector<double>`}
    \cgalParamDefault{`Multiscale_partition_function_options::part_sizes`}
    \cgalParamExtra{each must be in \f$(0, 1/6]\f$}
  \cgalParamNEnd
\cgalNamedParamsEnd

\returns the number of samples drawn and whether they converged (the largest change is taken
         over every part size)

\throws CGAL::Shape_analysis::Bad_input as `partition_function()`, or if `part_sizes` is empty.
*/
template <typename TriangleMesh, typename EdgeValuesMap,
          typename NamedParameters = parameters::Default_named_parameters>
Partition_function_result
multiscale_partition_function(const TriangleMesh& tm, EdgeValuesMap edge_values_map,
                              const NamedParameters& np = parameters::default_values())
{
  typedef internal::Mesh_sampling<TriangleMesh, NamedParameters> Sampling;
  const Multiscale_partition_function_options o = multiscale_partition_function_options(np);
  // The options are checked as partition_function() checks them first (with `part_size` if no
  // `part_sizes` are given), then with the part sizes.
  Sampling sampling(tm, np, internal::sampling_options(o, np), "multiscale_partition_function");
  sampling.options.part_sizes = o.part_sizes;
  internal::check_sampling_options(sampling.options, sampling.graph().number_of_nodes(),
                                   "multiscale_partition_function");
  if(sampling.options.sampling_method != MIN_CUT)
    throw Bad_input("multiscale_partition_function: the sampling_method must be MIN_CUT");
  const internal::Sampling_result r = sampling.run();
  const auto& g = sampling.graph();
  const std::size_t scales = r.values.size();
  std::vector<std::vector<double>> by_rank(g.number_of_mesh_edges, std::vector<double>(scales, 0.0));
  for(std::size_t e = 0; e < g.number_of_edges(); ++e)
    if(g.mesh_edge[e] != internal::Dual_graph::no_mesh_edge)
      for(std::size_t k = 0; k < scales; ++k)
        by_rank[g.mesh_edge[e]][k] = r.values[k][e];
  const auto& edges = sampling.mesh_graph.edges;
  for(std::size_t rank = 0; rank < edges.size(); ++rank)
    put(edge_values_map, edges[rank], by_rank[rank]);
  return internal::make_result(r);
}

} // namespace Randomized_cuts
} // namespace CGAL

#endif // CGAL_RANDOMIZED_CUTS_PARTITION_FUNCTION_H
