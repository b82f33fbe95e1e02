// Copyright (c) 2026 CGAL Global Shape Analysis contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_CONSISTENT_SEGMENTATION_CONSISTENT_SEGMENTATION_H
#define CGAL_CONSISTENT_SEGMENTATION_CONSISTENT_SEGMENTATION_H

/// \file consistent_segmentation.h

#include <CGAL/Consistent_segmentation/Consistent_segmentation_options.h>
#include <CGAL/Consistent_segmentation/hierarchical_segmentation.h>
#include <CGAL/Consistent_segmentation/internal/Cosegmentation.h>
#include <CGAL/Shape_analysis/Bad_input.h>
#include <CGAL/Shape_analysis/parameters.h>
#include <CGAL/Shape_analysis/internal/Dual_graph.h>
#include <CGAL/Shape_analysis/internal/Mesh_checks.h>
#include <CGAL/Shape_analysis/internal/Vector_3d.h>

#include <CGAL/Kernel_traits.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/property_map.h>

#include <cmath>
#include <functional>
#include <iterator>
#include <set>
#include <string>
#include <type_traits>
#include <vector>

namespace CGAL {
namespace Consistent_segmentation {

using CGAL::Shape_analysis::Bad_input;

/*!
\ingroup PkgConsistentSegmentationRef

What a consistent segmentation of a set of meshes found: which segment occurs in which mesh, and
figures of the correspondences it was built on.
*/
struct Consistent_segmentation_result
{
  /// The number of segment ids: ids go from 0 to this number minus one. Without known labels every
  /// id is used; with known labels, which keep their values as ids, the ids of labels that no face
  /// carries are unused (their entry of `meshes_of_segment` is empty).
  std::size_t number_of_segments = 0;
  /// For every segment id, the indices (in the input range) of the meshes where it occurs, in
  /// increasing order. A segment found in only some meshes is a part that the others lack.
  std::vector<std::vector<std::size_t>> meshes_of_segment;
  /// For every segment id, its area summed over the meshes, each mesh's area counting as 1.
  std::vector<double> segment_area;
  /// For every segment id, the known label it carries (see `known_segment_maps`), or -1.
  std::vector<long long> segment_label;
  /// The number of over-segments of all meshes that the joint clustering started from.
  std::size_t number_of_oversegments = 0;
  /// The number of pairs of meshes aligned to find correspondences (the links of only some of
  /// them are kept: see `number_of_partners`).
  std::size_t number_of_aligned_pairs = 0;
  /// The number of correspondences (links between sample points of two meshes, or of one mesh and
  /// its mirror image).
  std::size_t number_of_correspondences = 0;
  /// The mean trimmed RMS distance of the aligned pairs, relative to the bounding-box diagonal of
  /// the target's sample points.
  double mean_alignment_rms = 0;
  /// The number of runs of the sampling, alignments and merging (see `number_of_runs`).
  std::size_t number_of_runs = 1;
  /// The run returned (0 is the one whose sample points follow `random_seed` itself).
  std::size_t chosen_run = 0;
  /// The mean Rand distance between the returned segmentation of a mesh and another run's (the
  /// probability that two points drawn on the mesh by area are in one segment in one run and in two
  /// in the other), over the meshes and the other runs; 0 with one run. Near 0, the result hardly
  /// depends on the sample points.
  double run_disagreement = 0;

  /// Whether a segment occurs in a mesh.
  /// \param s a segment id
  /// \param m the index of a mesh in the input range
  /// \returns whether some face of mesh `m` has id `s`
  bool occurs_in(std::size_t s, std::size_t m) const
  {
    if(s >= meshes_of_segment.size())
      return false;
    const auto& list = meshes_of_segment[s];
    return std::binary_search(list.begin(), list.end(), m);
  }
};

/// \cond SKIP_IN_MANUAL
namespace internal {

template <typename Range>
auto range_element(const Range& range, std::size_t i) -> decltype(*std::begin(range))
{
  auto it = std::begin(range);
  std::advance(it, static_cast<std::ptrdiff_t>(i));
  return *it;
}

template <typename Range>
std::size_t range_size(const Range& range)
{
  return static_cast<std::size_t>(std::distance(std::begin(range), std::end(range)));
}

// Throws unless `range` (of `what`: "face segment maps", ...) has one element per mesh.
template <typename Range>
void require_one_per_mesh(const Range& range, std::size_t m, const std::string& what, const std::string& who)
{
  if(range_size(range) != m)
    throw Bad_input(who + ": " + std::to_string(range_size(range)) + " " + what + " for " + std::to_string(m) +
                    " meshes");
}

// Builds the dual graph and the triangles of a mesh (checked first).
template <typename TriangleMesh, typename VertexPointMap>
void prepare_mesh(const TriangleMesh& tm, VertexPointMap vpm, double alpha, const std::string& who,
                  Coseg_mesh& out, std::vector<typename boost::graph_traits<TriangleMesh>::face_descriptor>& faces_by_node)
{
  namespace SAI = CGAL::Shape_analysis::internal;
  typedef typename boost::property_traits<VertexPointMap>::value_type Point;
  typedef typename CGAL::Kernel_traits<Point>::Kernel Kernel;
  const SAI::Point_to_vector<Kernel> to_vector{Kernel()};
  SAI::check_triangle_mesh(tm, vpm, to_vector, who);
  const SAI::Dense_face_index_map<decltype(CGAL::get_initialized_face_index_map(tm, parameters::default_values()))>
    fim(tm, CGAL::get_initialized_face_index_map(tm, parameters::default_values()), who);
  SAI::build_dual_graph(tm, vpm, fim, alpha, out.graph, to_vector);
  if(!(out.graph.total_size() > 0))
    throw Bad_input(who + ": every face of the mesh has zero area");
  const std::size_t n = out.graph.number_of_nodes();
  out.triangles.resize(n);
  faces_by_node.resize(n);
  const double unit = out.graph.length_unit;
  for(auto f : CGAL::faces(tm)) {
    const std::size_t i = get(fim, f);
    faces_by_node[i] = f;
    int k = 0;
    for(auto h : CGAL::halfedges_around_face(halfedge(f, tm), tm))
      out.triangles[i][std::size_t(k++)] = to_vector(get(vpm, target(h, tm))) / unit;
  }
}

inline Consistent_segmentation_result to_result(const Coseg_result& r)
{
  Consistent_segmentation_result result;
  result.number_of_segments = r.number_of_segments;
  result.meshes_of_segment = r.meshes_of_segment;
  result.segment_area = r.segment_area;
  result.segment_label = r.segment_label;
  result.number_of_oversegments = r.number_of_oversegments;
  result.number_of_aligned_pairs = r.number_of_aligned_pairs;
  result.number_of_correspondences = r.number_of_correspondences;
  result.mean_alignment_rms = r.mean_alignment_rms;
  result.number_of_runs = r.number_of_runs;
  result.chosen_run = r.chosen_run;
  result.run_disagreement = r.run_disagreement;
  return result;
}

// Known labels are segment ids: refused above this (the result has tables indexed by id).
constexpr long long largest_known_label = (1LL << 20) - 1;

// A map without any known label is no map: the mesh is over-segmented as without one. Labels
// above `largest_known_label` are refused.
inline void check_known_labels(std::vector<long long>& known, const std::string& who)
{
  bool any = false;
  for(long long l : known) {
    if(l > largest_known_label)
      throw Bad_input(who + ": known label " + std::to_string(l) + " is above the largest allowed, " +
                      std::to_string(largest_known_label));
    any = any || l >= 0;
  }
  if(!any)
    known.clear();
}

// Reads per-face labels of a mesh through a map (negative values: -1).
template <typename Map, typename Face>
std::vector<long long> read_face_labels(const Map& map, const std::vector<Face>& faces_by_node)
{
  std::vector<long long> labels(faces_by_node.size());
  for(std::size_t i = 0; i < faces_by_node.size(); ++i) {
    const long long v = static_cast<long long>(get(map, faces_by_node[i]));
    labels[i] = v < 0 ? -1 : v;
  }
  return labels;
}

} // namespace internal
/// \endcond

/*!
\ingroup PkgConsistentSegmentationRef

Segments a set of triangle meshes of one kind (chairs, tables, four-legged animals, ...)
consistently: every face of every mesh gets a segment id, and the same id marks the same part in
all meshes (the seats of all chairs, their legs, ...), following \cgalCite{Golovinskiy2010},
section 3.3. A part that only some meshes have (armrests) gets ids of its own, found only in those
meshes (`Consistent_segmentation_result::meshes_of_segment`).

The method works in two stages on the faces of all meshes:
1. every mesh is over-segmented alone into `number_of_oversegments` segments by the
   area-normalized cut of `hierarchical_segmentation()` (links between its connected components,
   prior boundaries made cheaper);
2. `number_of_points` points are sampled on every mesh; every pair of meshes (for sets larger
   than 2 `number_of_partners` + 1, the pairs of every mesh with the 2 `number_of_partners`
   meshes of most similar shape distribution, so that a mesh may also be aligned with others that
   chose it) is aligned by the similarity transform of least RMS distance between up to 400 of
   their samples (principal frames, the 24 orientations of their axes, ICP with scale from each),
   then every over-segment of one mesh is aligned again on its own with the other mesh (rigid ICP,
   a turn of at most 34 degrees and a shift of at most a tenth of the diagonal: parts of
   articulated shapes at other angles); only the pairs that are among the `number_of_partners`
   best aligned (least RMS distance) of one of their meshes are kept. For each kept pair, every
   sample, moved by its over-segment's transform, is linked to the closest, among its
   8 nearest samples of the other mesh, whose normal agrees (dot product above
   `normal_threshold`) within `correspondence_distance` of the other mesh's bounding-box
   diagonal, in both directions. The over-segments of all meshes are then merged greedily, always
   the pair that lowers
   \f$E = E_{adj}^{\alpha} E_{corr}^{1-\alpha}\f$ the most, where
   \f$E_{adj} = \sum_S \mathrm{cut}(S)/\mathrm{area}(S)\f$ is the area-normalized cut of the mesh
   edges and component links of the first stage, prior boundaries still cheaper (every mesh
   scaled to unit area), and
   \f$E_{corr} = \sum_S \mathrm{cut}_{corr}(S)/\mathrm{vol}_{corr}(S)\f$ is the normalized cut
   of the correspondence links, with \f$\alpha\f$ = `adjacency_exponent`; every 12 merges, single
   over-segments move to a neighbouring segment when that lowers \f$E\f$. Merging stops at
   `number_of_segments` segments in all.

Everything after the over-segmentation (the sampling, the alignments, the correspondences and the
merging) runs `number_of_runs` times, each run with its own sample points (the first with
`random_seed`, the others with seeds derived from it); the result is the run whose segmentations
are closest to the other runs', by the Rand distance summed over the meshes and the other runs (the
first such run on a tie; of two runs, always the first). A single run's greedy merging can go
astray on one set of samples; the run closest to the others is a consensus (on the Princeton
Segmentation Benchmark's development sets, over 16 seeds, the default 6 runs lower the mean Rand
Index error from 0.125 to 0.118; see the manual). `Consistent_segmentation_result::run_disagreement`
tells how much the runs differ.

With `known_segment_maps`, some faces of some meshes have known labels (the same value meaning the
same part in every mesh, negative values meaning unknown): faces of one label start in one segment
and two different labels are never merged, so that the known labels are kept and the other faces
are filled in. The segment that holds a known label gets that label as its id; other segments get
the ids after the largest known label. One labelled example then labels a whole set, a labelled set
labels a new mesh, and half-labelled meshes are completed.

Sample points follow `random_seed`; meshes and pairs of meshes are processed in parallel with
results that do not depend on the number of threads.

\tparam MeshRange a range of triangle meshes, models of `FaceListGraph` and `EdgeListGraph` (for
        example `std::vector<CGAL::Surface_mesh<P>>`)
\tparam FaceSegmentMapRange a range with one model of `WritablePropertyMap` per mesh, with the
        mesh's `face_descriptor` as key and an integer type as value
\tparam NamedParameters a sequence of named parameters

\param meshes the meshes: at least one; each non-empty, with only triangle faces, finite
       coordinates and a positive area
\param face_segment_maps receives the segment id of every face of every mesh, in the order of
       `meshes`
\param np an optional sequence of named parameters among the ones listed below

\cgalNamedParamsBegin
  \cgalParamNBegin{number_of_segments}
    \cgalParamDescription{the number of segments over the whole set; 0 chooses it: the median,
      over the meshes, of the number `hierarchical_segmentation()` chooses for each (with its
      `number_of_segments` 0; of an even number of meshes, the lower of the two middle ones)}
    \cgalParamType{`std::size_t`}
    \cgalParamDefault{`Consistent_segmentation_options::number_of_segments`}
    \cgalParamExtra{more segments are returned when more known labels than that are given (one
      segment per label at least), fewer when the meshes have fewer over-segments in all}
  \cgalParamNEnd
  \cgalParamNBegin{number_of_oversegments}
    \cgalParamDescription{the number of segments of each mesh after the first stage}
    \cgalParamType{`std::size_t`}
    \cgalParamDefault{`Consistent_segmentation_options::number_of_oversegments`}
  \cgalParamNEnd
  \cgalParamNBegin{adjacency_exponent}
    \cgalParamDescription{the exponent \f$\alpha\f$ of the adjacency term of \f$E\f$ (0: only the
      correspondences count; 1: only the mesh edges)}
    \cgalParamType{`double`}
    \cgalParamDefault{`Consistent_segmentation_options::adjacency_exponent`}
    \cgalParamExtra{the thesis uses 0.01; the larger default makes boundaries follow the concave
      creases of each mesh more, which gives lower errors on the Princeton Segmentation Benchmark
      (see the manual); above about 0.3 whole meshes tend to stay unsegmented}
  \cgalParamNEnd
  \cgalParamNBegin{number_of_points}
    \cgalParamDescription{the number of points sampled on each mesh for the alignments and the
      correspondences, from 10 to 10,000,000}
    \cgalParamType{`std::size_t`}
    \cgalParamDefault{`Consistent_segmentation_options::number_of_points`}
  \cgalParamNEnd
  \cgalParamNBegin{number_of_partners}
    \cgalParamDescription{the number of best-aligned partners whose correspondences each mesh keeps
      (a pair is kept when it is among the best of one of its meshes); in sets of more than
      2 `number_of_partners` + 1 meshes, each mesh is aligned only with the
      2 `number_of_partners` meshes of most similar shape distribution. 0 aligns and keeps every
      pair}
    \cgalParamType{`std::size_t`}
    \cgalParamDefault{`Consistent_segmentation_options::number_of_partners`}
  \cgalParamNEnd
  \cgalParamNBegin{normal_threshold}
    \cgalParamDescription{two samples correspond only when the dot product of their normals, after
      alignment, is above this; in [-1, 1)}
    \cgalParamType{`double`}
    \cgalParamDefault{`Consistent_segmentation_options::normal_threshold`}
  \cgalParamNEnd
  \cgalParamNBegin{correspondence_distance}
    \cgalParamDescription{two samples correspond only when, after alignment, they are closer than
      this fraction of the bounding-box diagonal of the mesh of the second one}
    \cgalParamType{`double`}
    \cgalParamDefault{`Consistent_segmentation_options::correspondence_distance`}
  \cgalParamNEnd
  \cgalParamNBegin{known_segment_maps}
    \cgalParamDescription{a range with one readable face property map per mesh giving known labels
      (integers from 0 to \f$2^{20}-1\f$; negative for unknown). A map without a non-negative
      value changes nothing for its mesh}
    \cgalParamType{a range of models of `ReadablePropertyMap` with the meshes' `face_descriptor` as
      key and an integer type as value}
    \cgalParamDefault{no known labels}
  \cgalParamNEnd
  \cgalParamNBegin{prior_segment_maps}
    \cgalParamDescription{a range with one readable face property map per mesh giving a prior
      segmentation, whose boundaries are `prior_boundary_factor` times cheaper to cut in the first
      stage}
    \cgalParamType{a range of models of `ReadablePropertyMap` with the meshes' `face_descriptor` as
      key and an integer type as value}
    \cgalParamDefault{no prior segmentation}
  \cgalParamNEnd
  \cgalParamNBegin{prior_boundary_factor}
    \cgalParamDescription{how many times cheaper the boundaries of the prior segmentations are to cut
      (in both stages)}
    \cgalParamType{`double`}
    \cgalParamDefault{`Consistent_segmentation_options::prior_boundary_factor`}
  \cgalParamNEnd
  \cgalParamNBegin{vertex_point_maps}
    \cgalParamDescription{a range with one vertex point map per mesh}
    \cgalParamType{a range of models of `ReadablePropertyMap` with the meshes' `vertex_descriptor`
      as key and a point of a \cgal kernel as value}
    \cgalParamDefault{`boost::get(CGAL::vertex_point, mesh)` for every mesh}
  \cgalParamNEnd
  \cgalParamNBegin{boundary_refinement}
    \cgalParamDescription{whether boundaries are refined (in the over-segmentation of each mesh
      without known labels, and by moves of over-segments during the joint merging)}
    \cgalParamType{`bool`}
    \cgalParamDefault{`Consistent_segmentation_options::boundary_refinement`}
  \cgalParamNEnd
  \cgalParamNBegin{concavity_exponent}
    \cgalParamDescription{the exponent \f$\alpha\f$ of the concavity weight of the cut costs, as in
      `hierarchical_segmentation()`}
    \cgalParamType{`double`}
    \cgalParamDefault{`Consistent_segmentation_options::concavity_exponent`}
  \cgalParamNEnd
  \cgalParamNBegin{component_link_distance}
    \cgalParamDescription{faces of different connected components of one mesh closer than this
      fraction of its bounding-box diagonal are linked}
    \cgalParamType{`double`}
    \cgalParamDefault{`Consistent_segmentation_options::component_link_distance`}
  \cgalParamNEnd
  \cgalParamNBegin{component_link_factor}
    \cgalParamDescription{the cut cost of a link between components, relative to the mean cut cost
      of the mesh edges}
    \cgalParamType{`double`}
    \cgalParamDefault{`Consistent_segmentation_options::component_link_factor`}
  \cgalParamNEnd
  \cgalParamNBegin{number_of_runs}
    \cgalParamDescription{the number of runs of the sampling, alignments and merging, each with
      its own sample points, from 1 to 1,000; the run closest to the others is returned. 1 is the
      fastest and depends most on `random_seed`}
    \cgalParamType{`std::size_t`}
    \cgalParamDefault{`Consistent_segmentation_options::number_of_runs`}
    \cgalParamExtra{two runs are as close to each other: the first is returned, as with one run;
      use three or more}
  \cgalParamNEnd
  \cgalParamNBegin{random_seed}
    \cgalParamDescription{the seed of the random numbers (sample points)}
    \cgalParamType{`unsigned int`}
    \cgalParamDefault{`Consistent_segmentation_options::random_seed`}
  \cgalParamNEnd
  \cgalParamNBegin{number_of_threads}
    \cgalParamDescription{the largest number of threads used (with TBB); 0 for all cores. The
      result does not depend on it}
    \cgalParamType{`std::size_t`}
    \cgalParamDefault{`Consistent_segmentation_options::number_of_threads`}
  \cgalParamNEnd
  \cgalParamNBegin{progress_callback}
    \cgalParamDescription{called from time to time with the fraction of the work done}
    \cgalParamType{a callable convertible to `std::function<void(double)>`}
    \cgalParamDefault{none}
  \cgalParamNEnd
\cgalNamedParamsEnd

\returns which segment occurs in which mesh, and figures of the correspondences

\throws CGAL::Shape_analysis::Bad_input if `meshes` is empty, if the number of face segment maps
        (or of vertex point maps, known or prior segment maps) differs from the number of meshes,
        if a mesh has no faces, a face that is not a triangle, a coordinate that is not finite or
        no area, if a known label is above \f$2^{20}-1\f$, if `number_of_segments` exceeds the
        number of faces of all the meshes, or if a parameter is out of its range; no map is
        written then.

\sa `hierarchical_segmentation()`, `symmetric_segmentation()`
*/
template <typename MeshRange, typename FaceSegmentMapRange,
          typename NamedParameters = parameters::Default_named_parameters>
Consistent_segmentation_result consistent_segmentation(const MeshRange& meshes,
                                                       const FaceSegmentMapRange& face_segment_maps,
                                                       const NamedParameters& np = parameters::default_values())
{
  using CGAL::parameters::get_parameter;
  namespace snp = CGAL::Shape_analysis::internal_np;
  typedef typename std::decay<decltype(*std::begin(meshes))>::type TriangleMesh;
  typedef typename boost::graph_traits<TriangleMesh>::face_descriptor face_descriptor;
  const std::string who = "consistent_segmentation";

  const std::size_t m = internal::range_size(meshes);
  if(m == 0)
    throw Bad_input(who + ": the set of meshes is empty");
  internal::require_one_per_mesh(face_segment_maps, m, "face segment maps", who);
  const Consistent_segmentation_options options = consistent_segmentation_options(np);
  internal::check_coseg_options(options, who);

  auto vpms = get_parameter(np, snp::vertex_point_maps_tag);
  auto known = get_parameter(np, snp::known_segment_maps_tag);
  auto prior = get_parameter(np, snp::prior_segment_maps_tag);
  constexpr bool has_vpms = !std::is_same<decltype(vpms), CGAL::internal_np::Param_not_found>::value;
  constexpr bool has_known = !std::is_same<decltype(known), CGAL::internal_np::Param_not_found>::value;
  constexpr bool has_prior = !std::is_same<decltype(prior), CGAL::internal_np::Param_not_found>::value;
  if constexpr(has_vpms)
    internal::require_one_per_mesh(vpms, m, "vertex point maps", who);
  if constexpr(has_known)
    internal::require_one_per_mesh(known, m, "known segment maps", who);
  if constexpr(has_prior)
    internal::require_one_per_mesh(prior, m, "prior segment maps", who);

  std::vector<internal::Coseg_mesh> data(m);
  std::vector<std::vector<face_descriptor>> faces_by_node(m);
  for(std::size_t i = 0; i < m; ++i) {
    const TriangleMesh& tm = internal::range_element(meshes, i);
    const std::string mesh_who = who + " (mesh " + std::to_string(i) + ")";
    if constexpr(has_vpms)
      internal::prepare_mesh(tm, internal::range_element(vpms, i), options.concavity_exponent,
                             mesh_who, data[i], faces_by_node[i]);
    else
      internal::prepare_mesh(tm, get_const_property_map(CGAL::vertex_point, tm),
                             options.concavity_exponent, mesh_who, data[i], faces_by_node[i]);
    if constexpr(has_known) {
      data[i].known = internal::read_face_labels(internal::range_element(known, i), faces_by_node[i]);
      internal::check_known_labels(data[i].known, mesh_who);
    }
    if constexpr(has_prior)
      data[i].prior = internal::read_face_labels(internal::range_element(prior, i), faces_by_node[i]);
  }

  const internal::Coseg_result r = internal::cosegment(data, options);

  for(std::size_t i = 0; i < m; ++i) {
    auto map = internal::range_element(face_segment_maps, i);
    for(std::size_t v = 0; v < faces_by_node[i].size(); ++v)
      put(map, faces_by_node[i][v], r.labels[i][v]);
  }
  return internal::to_result(r);
}

/*!
\ingroup PkgConsistentSegmentationRef

Segments a nearly mirror-symmetric triangle mesh so that the segmentation is symmetric too: the
consistent segmentation of `consistent_segmentation()` applied to one mesh, with correspondences
between every sample point and the closest sample point (with a compatible normal) of its mirror
image through `plane` instead of correspondences between meshes. Mirror parts (the left and the
right leg) then get the same segment id, and boundaries on one side mirror those on the other.

The plane can come from a symmetry detection or be known by construction (a model in its
canonical pose).

\tparam TriangleMesh a model of `FaceListGraph` and `EdgeListGraph`
\tparam Plane_3 a plane type of a \cgal kernel (`Kernel::Plane_3`)
\tparam FaceSegmentMap a model of `WritablePropertyMap` with
        `boost::graph_traits<TriangleMesh>::%face_descriptor` as key and an integer type as value
\tparam NamedParameters a sequence of named parameters

\param tm the triangle mesh (as for `hierarchical_segmentation()`)
\param plane the plane of reflective symmetry (not degenerate)
\param face_segment_map receives the segment id of every face
\param np the named parameters of `consistent_segmentation()` (but `vertex_point_maps`,
       `known_segment_maps`, `prior_segment_maps` and `number_of_partners`), with
       `vertex_point_map` and `prior_segment_map` as for `hierarchical_segmentation()`, and:

\cgalNamedParamsBegin
  \cgalParamNBegin{symmetry_support_map}
    \cgalParamDescription{per face, in \f$[0, 1]\f$, how much the face takes part in the symmetry,
      for a partial symmetry (for example the `Symmetry::support` of a plane that
      `CGAL::Surface_mesh_symmetrization::detect_reflective_symmetries()` found): the mirror link
      between two sample points counts with the lower support of their faces, and faces of support
      0 get no mirror link, so that only the symmetric part of the surface is segmented
      symmetrically}
    \cgalParamType{a model of `ReadablePropertyMap` with
      `boost::graph_traits<TriangleMesh>::%face_descriptor` as key and a floating-point type as
      value}
    \cgalParamDefault{1 for every face (the whole surface is symmetric)}
  \cgalParamNEnd
\cgalNamedParamsEnd

\returns the segments found, as for `consistent_segmentation()` with one mesh (the correspondences
         are the mirror links; no pair of meshes is aligned)

\throws CGAL::Shape_analysis::Bad_input on a mesh or a parameter that `consistent_segmentation()`
        refuses, a plane that is degenerate or does not cross the mesh (all of the mesh on one
        side), or a support outside \f$[0, 1]\f$; `face_segment_map` is then left untouched.
*/
template <typename TriangleMesh, typename Plane_3, typename FaceSegmentMap,
          typename NamedParameters = parameters::Default_named_parameters>
Consistent_segmentation_result symmetric_segmentation(const TriangleMesh& tm, const Plane_3& plane,
                                   FaceSegmentMap face_segment_map,
                                   const NamedParameters& np = parameters::default_values())
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  namespace SAI = CGAL::Shape_analysis::internal;
  namespace snp = CGAL::Shape_analysis::internal_np;
  typedef typename boost::graph_traits<TriangleMesh>::face_descriptor face_descriptor;
  const std::string who = "symmetric_segmentation";
  const Consistent_segmentation_options options = consistent_segmentation_options(np);
  internal::check_coseg_options(options, who);

  double a = CGAL::to_double(plane.a()), b = CGAL::to_double(plane.b()), c = CGAL::to_double(plane.c()),
         d = CGAL::to_double(plane.d());
  SAI::scale_plane_coefficients(a, b, c, d); // (0,0,1e-300,0 is z = 0)
  const double length = std::sqrt(a * a + b * b + c * c);
  if(!(length > 0) || !std::isfinite(length) || !std::isfinite(d))
    throw Bad_input(who + ": the symmetry plane is degenerate (its normal is zero or not finite)");

  std::vector<internal::Coseg_mesh> data(1);
  std::vector<face_descriptor> faces_by_node;
  internal::prepare_mesh(tm,
                         choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point),
                                          get_const_property_map(CGAL::vertex_point, tm)),
                         options.concavity_exponent, who, data[0], faces_by_node);
  auto prior = get_parameter(np, snp::prior_segment_map_tag);
  if constexpr(!std::is_same<decltype(prior), CGAL::internal_np::Param_not_found>::value)
    data[0].prior = internal::read_face_labels(prior, faces_by_node);
  auto support = get_parameter(np, snp::symmetry_support_map_tag);
  if constexpr(!std::is_same<decltype(support), CGAL::internal_np::Param_not_found>::value) {
    data[0].mirror_support.resize(faces_by_node.size());
    for(std::size_t v = 0; v < faces_by_node.size(); ++v) {
      const double s = double(get(support, faces_by_node[v]));
      if(!(s >= 0 && s <= 1))
        throw Bad_input(who + ": a symmetry support is outside [0, 1]");
      data[0].mirror_support[v] = s;
    }
  }
  // a x + b y + c z + d = 0  <=>  n.x = -d / |(a, b, c)|, in graph units.
  data[0].has_plane = true;
  data[0].plane_normal = SAI::Vector_3d(a, b, c) / length;
  data[0].plane_offset = -d / length / data[0].graph.length_unit;

  const internal::Coseg_result r = internal::cosegment(data, options);
  for(std::size_t v = 0; v < faces_by_node.size(); ++v)
    put(face_segment_map, faces_by_node[v], r.labels[0][v]);
  return internal::to_result(r);
}

} // namespace Consistent_segmentation
} // namespace CGAL

#endif // CGAL_CONSISTENT_SEGMENTATION_CONSISTENT_SEGMENTATION_H
