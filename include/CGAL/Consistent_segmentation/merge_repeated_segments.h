// Copyright (c) 2026 CGAL Global Shape Analysis contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_CONSISTENT_SEGMENTATION_MERGE_REPEATED_SEGMENTS_H
#define CGAL_CONSISTENT_SEGMENTATION_MERGE_REPEATED_SEGMENTS_H

/// \file merge_repeated_segments.h

#include <CGAL/Consistent_segmentation/consistent_segmentation.h>
#include <CGAL/Consistent_segmentation/internal/Repeated_segments.h>
#include <CGAL/Shape_analysis/Bad_input.h>
#include <CGAL/Shape_analysis/parameters.h>
#include <CGAL/Shape_analysis/internal/Mesh_checks.h>
#include <CGAL/Shape_analysis/internal/Vector_3d.h>

#include <CGAL/Kernel_traits.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/property_map.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <type_traits>
#include <vector>

namespace CGAL {
namespace Consistent_segmentation {

/*!
\ingroup PkgConsistentSegmentationRef

The options of `merge_repeated_segments()`: each member is the named parameter of the same name,
initialized to its default. This struct is where the defaults are written; the manual,
`merge_repeated_segments_options()` and `shape_analysis coseg --merge-repeated` take them from
here.
*/
struct Merge_repeated_segments_options
{
  /// two regions are copies of each other when, after the best rigid motion (with or without a
  /// reflection), the RMS distance between their surfaces is at most this fraction of the RMS
  /// radius of one of them, in \f$[0, 1]\f$. The legs of the Princeton benchmark's chairs and
  /// tables are mostly within 0.03 of each other; the seat and the back of most procedural chairs
  /// 0.04 to 0.08 apart
  double duplicate_tolerance = 0.03;
  /// the number of points sampled on each region compared (at least 10; not the default of
  /// `consistent_segmentation()`'s parameter of the same name)
  std::size_t number_of_points = 150;
  /// the seed of the random numbers (sample points)
  std::uint64_t random_seed = 0;
  /// the largest number of threads used (with TBB); 0 for all cores. The result does not depend
  /// on it
  std::size_t number_of_threads = 0;
};

/*!
\ingroup PkgConsistentSegmentationRef

The options that `merge_repeated_segments()` reads from the named parameters `np`: the value of
each named parameter given, the default of `Merge_repeated_segments_options` for the others. The
values are not checked here; `merge_repeated_segments()` checks them.

\tparam NamedParameters a sequence of named parameters
\param np the named parameters, as given to the function whose options these are
\returns the options, each from its named parameter or its default
*/
template <typename NamedParameters = parameters::Default_named_parameters>
Merge_repeated_segments_options merge_repeated_segments_options(const NamedParameters& np = parameters::default_values())
{
  using CGAL::Shape_analysis::internal::parameter_value;
  namespace snp = CGAL::Shape_analysis::internal_np;
  Merge_repeated_segments_options o;
  o.duplicate_tolerance = parameter_value(np, snp::duplicate_tolerance_tag, o.duplicate_tolerance);
  o.number_of_points = parameter_value(np, snp::number_of_points_tag, o.number_of_points);
  o.random_seed = parameter_value(np, CGAL::internal_np::random_seed, o.random_seed);
  o.number_of_threads = parameter_value(np, snp::number_of_threads_tag, o.number_of_threads);
  return o;
}

/// \cond SKIP_IN_MANUAL
namespace internal {

// The triangles of a mesh and the segment id of each, read through `map`; ids of
// `number_of_segments` or more are refused.
template <typename TriangleMesh, typename VertexPointMap, typename FaceSegmentMap>
Segmented_triangles read_segmented_triangles(const TriangleMesh& tm, VertexPointMap vpm, const FaceSegmentMap& map,
                                             std::size_t number_of_segments, const std::string& who)
{
  namespace SAI = CGAL::Shape_analysis::internal;
  typedef typename boost::property_traits<VertexPointMap>::value_type Point;
  typedef typename CGAL::Kernel_traits<Point>::Kernel Kernel;
  const SAI::Point_to_vector<Kernel> to_vector{Kernel()};
  SAI::check_triangle_mesh(tm, vpm, to_vector, who);
  Segmented_triangles out;
  for(auto f : CGAL::faces(tm)) {
    const long long id = static_cast<long long>(get(map, f));
    if(id < 0 || static_cast<std::size_t>(id) >= number_of_segments)
      throw Bad_input(who + ": a face has segment id " + std::to_string(id) + ", not below the result's " +
                      std::to_string(number_of_segments) + " segments");
    std::array<SAI::Vector_3d, 3> t;
    std::size_t k = 0;
    for(auto h : CGAL::halfedges_around_face(halfedge(f, tm), tm))
      t[k++] = to_vector(get(vpm, target(h, tm)));
    out.triangles.push_back(t);
    out.ids.push_back(static_cast<std::size_t>(id));
  }
  return out;
}

} // namespace internal
/// \endcond

/*!
\ingroup PkgConsistentSegmentationRef

Gives one id to the segments of a consistent segmentation that are copies of one part within the
meshes: the four legs of a chair, its two armrests, the legs of an ant. `consistent_segmentation()`
gives a part that a set shares the same id in every mesh, but a part repeated within each mesh
gets one id per place (front left leg, front right leg, ...), since aligning two meshes matches
places, not kinds. Two ids are merged when, in at least half of the meshes that have both (at most
the first six such meshes are compared), their regions have areas within 25% of each other and one
region, moved by the best rigid motion with or without a reflection, lies on the other: the RMS
distance between the two surfaces (the closest 90% of the point pairs, both ways) at most
`duplicate_tolerance` of the RMS radius of the region of the lower id. Mirror images (left and
right) and copies (front and back) alike. Ids with a known label
(`Consistent_segmentation_result::segment_label`) are never merged and keep their values, as do
the ids between them that no face carries; the groups of the other ids are numbered after the
largest label (from 0 without labels), in the order of their first id.

\tparam MeshRange a range of models of `FaceListGraph`, as for `consistent_segmentation()`
\tparam FaceSegmentMapRange a range of models of `ReadWritePropertyMap` with the meshes'
        `face_descriptor` as key and `std::size_t` as value
\tparam NamedParameters a sequence of named parameters

\param meshes the meshes, as given to `consistent_segmentation()`
\param face_segment_maps the segment id of every face of every mesh, as written by
       `consistent_segmentation()`; rewritten with the merged ids
\param result what `consistent_segmentation()` returned for these maps; updated:
       `number_of_segments`, `meshes_of_segment`, `segment_area` and `segment_label` describe the
       merged ids, the other members are kept
\param np an optional sequence of named parameters among the ones listed below

\cgalNamedParamsBegin
  \cgalParamNBegin{duplicate_tolerance}
    \cgalParamDescription{the largest RMS distance between the surfaces of two copies of one part,
      after alignment (the closest 90% of the point pairs), as a fraction of the RMS radius of one
      of them, in \f$[0, 1]\f$}
    \cgalParamType{`double`}
    \cgalParamDefault{`Merge_repeated_segments_options::duplicate_tolerance`}
  \cgalParamNEnd
  \cgalParamNBegin{number_of_points}
    \cgalParamDescription{the number of points sampled on each region compared (at least 10); its
      default differs from `consistent_segmentation()`'s, so a chain of named parameters that sets
      it for one function should not be passed to the other}
    \cgalParamType{`std::size_t`}
    \cgalParamDefault{`Merge_repeated_segments_options::number_of_points`}
  \cgalParamNEnd
  \cgalParamNBegin{vertex_point_maps}
    \cgalParamDescription{a range with one vertex point map per mesh}
    \cgalParamType{a range of models of `ReadablePropertyMap` with the meshes' `vertex_descriptor`
      as key and a point of a \cgal kernel as value}
    \cgalParamDefault{`boost::get(CGAL::vertex_point, mesh)` for every mesh}
  \cgalParamNEnd
  \cgalParamNBegin{random_seed}
    \cgalParamDescription{the seed of the random numbers (sample points)}
    \cgalParamType{`unsigned int`}
    \cgalParamDefault{`Merge_repeated_segments_options::random_seed`}
  \cgalParamNEnd
  \cgalParamNBegin{number_of_threads}
    \cgalParamDescription{the largest number of threads used (with TBB); 0 for all cores. The
      result does not depend on it}
    \cgalParamType{`std::size_t`}
    \cgalParamDefault{`Merge_repeated_segments_options::number_of_threads`}
  \cgalParamNEnd
\cgalNamedParamsEnd

\returns the number of ids merged into others: the ids without a known label that faces carry,
         before minus after (0 when no two segments repeat each other)

\throws CGAL::Shape_analysis::Bad_input if `meshes` is empty, if the number of face segment maps
        (or of vertex point maps) differs from the number of meshes, if the tables of `result` do
        not have `result.number_of_segments` entries or a segment's known label is not its id,
        if a face's id is not below
        `result.number_of_segments`, if a mesh has no faces, a face that is not a triangle or a
        coordinate that is not finite, or if a parameter is out of its range; no map is written
        and `result` is not changed then.

\sa `consistent_segmentation()`
*/
template <typename MeshRange, typename FaceSegmentMapRange,
          typename NamedParameters = parameters::Default_named_parameters>
std::size_t merge_repeated_segments(const MeshRange& meshes, const FaceSegmentMapRange& face_segment_maps,
                                    Consistent_segmentation_result& result,
                                    const NamedParameters& np = parameters::default_values())
{
  using CGAL::parameters::get_parameter;
  namespace snp = CGAL::Shape_analysis::internal_np;
  const std::string who = "merge_repeated_segments";
  const std::size_t m = internal::range_size(meshes);
  if(m == 0)
    throw Bad_input(who + ": the set of meshes is empty");
  internal::require_one_per_mesh(face_segment_maps, m, "face segment maps", who);
  const std::size_t k = result.number_of_segments;
  if(result.meshes_of_segment.size() != k || result.segment_area.size() != k || result.segment_label.size() != k)
    throw Bad_input(who + ": the result's tables do not have one entry per segment (" + std::to_string(k) + ")");
  for(std::size_t s = 0; s < k; ++s)
    if(result.segment_label[s] >= 0 && result.segment_label[s] != static_cast<long long>(s))
      throw Bad_input(who + ": segment " + std::to_string(s) + " carries the known label " +
                      std::to_string(result.segment_label[s]) + ": a labelled segment's id is its label");
  const Merge_repeated_segments_options options = merge_repeated_segments_options(np);
  if(!(options.duplicate_tolerance >= 0 && options.duplicate_tolerance <= 1))
    throw Bad_input(who + ": duplicate_tolerance must be in [0, 1]");
  if(options.number_of_points < 10 || options.number_of_points > 10000000)
    throw Bad_input(who + ": number_of_points must be in [10, 10,000,000]");

  auto vpms = get_parameter(np, snp::vertex_point_maps_tag);
  constexpr bool has_vpms = !std::is_same<decltype(vpms), CGAL::internal_np::Param_not_found>::value;
  if constexpr(has_vpms)
    internal::require_one_per_mesh(vpms, m, "vertex point maps", who);

  std::vector<internal::Segmented_triangles> data(m);
  for(std::size_t i = 0; i < m; ++i) {
    const auto& tm = internal::range_element(meshes, i);
    const std::string mesh_who = who + " (mesh " + std::to_string(i) + ")";
    const auto map = internal::range_element(face_segment_maps, i);
    if constexpr(has_vpms)
      data[i] = internal::read_segmented_triangles(tm, internal::range_element(vpms, i), map, k, mesh_who);
    else
      data[i] = internal::read_segmented_triangles(tm, get_const_property_map(CGAL::vertex_point, tm), map, k, mesh_who);
  }

  internal::Repeated_segments_options ro;
  ro.tolerance = options.duplicate_tolerance;
  ro.number_of_points = options.number_of_points;
  ro.random_seed = options.random_seed;
  ro.number_of_threads = options.number_of_threads;
  const std::vector<std::size_t> group = internal::repeated_segment_groups(data, k, result.segment_label, ro);

  // New ids: labelled ids keep their values (and so do the unused ids between them, as
  // consistent_segmentation() leaves them); the groups of the other ids follow the largest label,
  // in the order of their first id; unused ids above the largest label are dropped.
  long long largest_label = -1;
  for(long long l : result.segment_label)
    largest_label = (std::max)(largest_label, l);
  const std::size_t first_free = static_cast<std::size_t>(largest_label + 1);
  std::vector<char> used(k, 0);
  for(const internal::Segmented_triangles& mesh : data)
    for(std::size_t id : mesh.ids)
      used[id] = 1;
  std::vector<std::size_t> new_id(k, 0);
  std::size_t next = first_free, unlabelled = 0;
  for(std::size_t s = 0; s < k; ++s) {
    if(result.segment_label[s] >= 0 || (!used[s] && s < first_free))
      new_id[s] = s;
    else if(used[s]) {
      ++unlabelled;
      new_id[s] = group[s] == s ? next++ : new_id[group[s]];
    }
  }
  const std::size_t total = (std::max)(first_free, next);

  Consistent_segmentation_result merged = result;
  merged.number_of_segments = total;
  merged.meshes_of_segment.assign(total, {});
  merged.segment_area.assign(total, 0.0);
  merged.segment_label.assign(total, -1);
  for(std::size_t s = 0; s < k; ++s) {
    if(!used[s] && s >= first_free)
      continue; // dropped
    const std::size_t t = new_id[s];
    merged.segment_area[t] += result.segment_area[s];
    merged.segment_label[t] = result.segment_label[s];
    auto& list = merged.meshes_of_segment[t];
    list.insert(list.end(), result.meshes_of_segment[s].begin(), result.meshes_of_segment[s].end());
  }
  for(auto& list : merged.meshes_of_segment) {
    std::sort(list.begin(), list.end());
    list.erase(std::unique(list.begin(), list.end()), list.end());
  }
  for(std::size_t i = 0; i < m; ++i) {
    auto map = internal::range_element(face_segment_maps, i);
    const auto& tm = internal::range_element(meshes, i);
    for(auto f : CGAL::faces(tm))
      put(map, f, new_id[static_cast<std::size_t>(get(map, f))]);
  }
  const std::size_t removed = unlabelled - (next - first_free);
  result = std::move(merged);
  return removed;
}

} // namespace Consistent_segmentation
} // namespace CGAL

#endif // CGAL_CONSISTENT_SEGMENTATION_MERGE_REPEATED_SEGMENTS_H
