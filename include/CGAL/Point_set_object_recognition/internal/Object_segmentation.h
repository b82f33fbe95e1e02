// Copyright (c) 2026 CGAL Global Shape Analysis contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_POINT_SET_OBJECT_RECOGNITION_INTERNAL_OBJECT_SEGMENTATION_H
#define CGAL_POINT_SET_OBJECT_RECOGNITION_INTERNAL_OBJECT_SEGMENTATION_H

// The machinery of segment_objects.h: a graph index over the points near a set of locations
// (Segmentation_graph.h), built once and shared by all objects; per object, the points within a
// radius, their connected components, or the min-cut around its location (Object_min_cut.h) at
// a fixed or an automatic background radius (segment_one).

#include <CGAL/Point_set_object_recognition/internal/Column_index.h>
#include <CGAL/Point_set_object_recognition/internal/Object_min_cut.h>
#include <CGAL/Point_set_object_recognition/internal/Point_columns.h>
#include <CGAL/Point_set_object_recognition/internal/Segmentation_graph.h>
#include <CGAL/Point_set_object_recognition/internal/Segmentation_options.h>
#include <CGAL/Point_set_object_recognition/internal/Voxel_grid.h>

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <utility>
#include <vector>

namespace CGAL {
namespace Point_set_object_recognition {
namespace internal {

// The largest horizontal distance from a location that a segmentation looks at.
inline double segmentation_reach(const Segmentation_options& o)
{
  const bool automatic = o.segmentation_method == Segmentation_method::MIN_CUT_AUTOMATIC_RADIUS;
  return (automatic ? automatic_radii.back() : o.background_radius) + ramp_width + 1.0;
}

// The object at `location` as all points within the radius, or those of them connected to the
// hard foreground.
inline void segment_within_radius(const Segmentation_index& index, const P3& location, const Segmentation_options& o,
                                  Segmentation_workspace& w, Segmentation_output& out)
{
  const std::vector<P3>& p = index.points();
  index.points_within(location, o.background_radius, w.candidates);
  const std::vector<std::uint32_t> seeds = foreground_seeds(p, w.candidates, location, o.foreground_height);
  out.radius = o.background_radius;
  if(!seeds.empty())
    out.seed = seeds.front();
  if(o.segmentation_method == Segmentation_method::ALL_WITHIN_RADIUS || w.candidates.empty()) {
    out.points.assign(w.candidates.begin(), w.candidates.end());
    return;
  }
  std::vector<P3> q;
  q.reserve(w.candidates.size());
  std::size_t seed_k = 0;
  for(std::size_t k = 0; k < w.candidates.size(); ++k) {
    q.push_back(p[w.candidates[k]]);
    if(w.candidates[k] == out.seed)
      seed_k = k;
  }
  P3 lo, hi;
  checked_bounds(q, o.component_spacing, "segment_objects", lo, hi);
  std::size_t components = 0;
  const std::vector<std::uint32_t> c = voxel_components(q, std::vector<char>(q.size(), 1), o.component_spacing, lo,
                                                    components);
  for(std::size_t k = 0; k < q.size(); ++k)
    if(c[k] == c[seed_k])
      out.points.push_back(w.candidates[k]);
}

// The object at `location` by the min-cut at the fixed radius, or at the automatic one.
inline void segment_by_min_cut(const Segmentation_index& index, const P3& location, const Segmentation_options& o,
                               Segmentation_workspace& w, Segmentation_output& out)
{
  const double largest = largest_background_radius(o);
  const std::vector<std::uint32_t> seeds = object_seeds(index, location, largest, o, w.candidates);
  if(seeds.empty()) {
    out.radius = largest;
    return;
  }
  out.seed = seeds.front();
  const std::vector<double> radii = o.segmentation_method == Segmentation_method::MIN_CUT
                                      ? std::vector<double>{o.background_radius}
                                      : std::vector<double>(automatic_radii.begin(), automatic_radii.end());
  Cut_outcome best;
  std::vector<std::uint32_t> best_nodes;
  double best_radius = radii.back();
  // The first radius whose foreground is big enough with a cut cost under the threshold;
  // when none is, the smallest radius with a foreground big enough (a larger radius that
  // does not give a clean cut only takes more of what the object touches), else the largest.
  bool fallback_big = false;
  for(double R : radii) {
    Cut_outcome c = min_cut_at_radius(index, location, R, seeds, o, w);
    const bool big = c.points > o.minimum_foreground_size;
    if(radii.size() == 1 || (big && c.cut < o.maximum_cut_cost)) {
      best = std::move(c), best_nodes = w.nodes, best_radius = R;
      break;
    }
    if((big && !fallback_big) || (!fallback_big && R == radii.back())) {
      fallback_big = big;
      best = std::move(c), best_nodes = w.nodes, best_radius = R;
    }
  }
  out.radius = best_radius;
  out.cut = best.cut;
  for(std::uint32_t k : best.foreground)
    index.for_members(best_nodes[k], [&](std::uint32_t i) { out.points.push_back(i); });
  std::sort(out.points.begin(), out.points.end());
}

// Per point of `p`, the location whose object (`out`, one per location) holds it (when several
// do: the one horizontally nearest to the point, the first at equal distances), or
// std::size_t(-1).
inline void claim_points(const std::vector<P3>& p, const std::vector<P3>& locations,
                         const std::vector<Segmentation_output>& out, std::vector<std::size_t>& object_of_point)
{
  const std::size_t none = std::size_t(-1);
  object_of_point.assign(p.size(), none);
  for(std::size_t k = 0; k < out.size(); ++k)
    for(std::size_t i : out[k].points) {
      std::size_t& claim = object_of_point[i];
      if(claim == none || horizontal_distance(p[i], locations[k]) < horizontal_distance(p[i], locations[claim]))
        claim = k;
    }
}

// Segments the object at `location` (index built with the graph for min-cut methods).
inline Segmentation_output segment_one(const Segmentation_index& index, const P3& location,
                                       const Segmentation_options& o, Segmentation_workspace& w)
{
  const auto start = std::chrono::steady_clock::now();
  Segmentation_output out;
  if(o.segmentation_method == Segmentation_method::ALL_WITHIN_RADIUS ||
     o.segmentation_method == Segmentation_method::CONNECTED_COMPONENTS)
    segment_within_radius(index, location, o, w, out);
  else
    segment_by_min_cut(index, location, o, w, out);
  out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return out;
}

} // namespace internal
} // namespace Point_set_object_recognition
} // namespace CGAL

#endif // CGAL_POINT_SET_OBJECT_RECOGNITION_INTERNAL_OBJECT_SEGMENTATION_H
