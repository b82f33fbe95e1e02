// Copyright (c) 2026 CGAL Global Shape Analysis contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_POINT_SET_OBJECT_RECOGNITION_REMOVE_BACKGROUND_H
#define CGAL_POINT_SET_OBJECT_RECOGNITION_REMOVE_BACKGROUND_H

/// \file remove_background.h
/// Background removal in scanned urban scenes: the ground, isolated points and very large
/// connected components (buildings).

#include <CGAL/Point_set_3.h>
#include <CGAL/property_map.h>

#include <CGAL/Shape_analysis/Bad_input.h>
#include <CGAL/Shape_analysis/parameters.h>
#include <CGAL/Point_set_object_recognition/Remove_background_options.h>
#include <CGAL/Point_set_object_recognition/internal/Background_removal.h>
#include <CGAL/Point_set_object_recognition/internal/Voxel_grid.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>
#include <unordered_map>
#include <vector>

namespace CGAL {
namespace Point_set_object_recognition {

using CGAL::Shape_analysis::Bad_input;

/// \ingroup PkgPointSetObjectRecognitionRef
/// What `remove_background()` made of a point.
enum class Point_kind : unsigned char {
  FOREGROUND = 0,     ///< kept: a candidate part of a small object
  GROUND = 1,         ///< less than `ground_threshold` above the estimated ground
  ISOLATED = 2,       ///< fewer than `minimum_neighbors` other points within `isolation_radius`
  LARGE_COMPONENT = 3 ///< in a connected component wider than `maximum_component_extent`
};

/// \ingroup PkgPointSetObjectRecognitionRef
/// The estimated ground: one plane \f$z = a x + b y + c\f$ per cell of a uniform grid in
/// \f$(x, y)\f$, blended bilinearly between cell centres.
struct Ground_grid
{
  double x0 = 0, y0 = 0;            ///< the corner of cell (0, 0)
  double cell_size = 1;             ///< the side of a cell
  std::size_t nx = 0, ny = 0;       ///< the number of cells along x and y
  std::vector<std::array<double, 3>> planes; ///< (a, b, c) per cell, row-major (i + nx j)

  /// The ground height at (x, y): the planes of the four nearest cell centres evaluated at
  /// (x, y), blended bilinearly (the grid is clamped at its border).
  /// \param x the first coordinate of the point
  /// \param y the second coordinate of the point
  /// \returns the height of the ground at (x, y), 0 for an empty grid
  double height(double x, double y) const
  {
    if(planes.empty())
      return 0;
    const double u = (x - x0) / cell_size - 0.5, v = (y - y0) / cell_size - 0.5;
    const double fu = std::floor(u), fv = std::floor(v);
    const double su = u - fu, sv = v - fv;
    double h = 0;
    for(int dj = 0; dj < 2; ++dj)
      for(int di = 0; di < 2; ++di) {
        const long i = (std::min)((std::max)(long(fu) + di, 0L), long(nx) - 1);
        const long j = (std::min)((std::max)(long(fv) + dj, 0L), long(ny) - 1);
        const auto& p = planes[std::size_t(i) + nx * std::size_t(j)];
        const double w = (di ? su : 1 - su) * (dj ? sv : 1 - sv);
        h += w * (p[0] * x + p[1] * y + p[2]);
      }
    return h;
  }
};

/// \ingroup PkgPointSetObjectRecognitionRef
/// The result of `remove_background()`.
struct Background_removal_result
{
  std::vector<Point_kind> kind;             ///< per point, in input order
  std::vector<double> height_above_ground;  ///< per point
  std::vector<std::size_t> foreground;      ///< the indices of the points kept, increasing
  std::size_t number_of_ground_points = 0;
  std::size_t number_of_isolated_points = 0;
  std::size_t number_of_large_component_points = 0;
  Ground_grid ground;                       ///< the estimated ground
};

/// \cond SKIP_IN_MANUAL
namespace internal {

// The points by the cells of the ground grid `g`: those of cell c are order[start[c]] to
// order[start[c + 1] - 1], increasing.
inline void sort_by_cell(const std::vector<std::array<double, 3>>& p, const Ground_grid& g, double cell,
                         std::vector<std::size_t>& start, std::vector<std::size_t>& order)
{
  const std::size_t n = p.size(), cells = g.nx * g.ny;
  start.assign(cells + 1, 0);
  order.assign(n, 0);
  const auto cell_of = [&](std::size_t i) {
    const std::size_t ci = (std::min)(std::size_t((p[i][0] - g.x0) / cell), g.nx - 1);
    const std::size_t cj = (std::min)(std::size_t((p[i][1] - g.y0) / cell), g.ny - 1);
    return ci + g.nx * cj;
  };
  for(std::size_t i = 0; i < n; ++i)
    ++start[cell_of(i) + 1];
  for(std::size_t c = 0; c < cells; ++c)
    start[c + 1] += start[c];
  std::vector<std::size_t> fill(start.begin(), start.end() - 1);
  for(std::size_t i = 0; i < n; ++i)
    order[fill[cell_of(i)]++] = i;
}

// The buffers of fit_cell_ground, shared by the cells.
struct Cell_ground_buffers
{
  std::vector<double> zs;
  std::vector<std::size_t> near, lowest, column_point;
};

// The ground plane of cell c (its points `points`, `count` of them), started at its low points
// and refitted to the points near it, with a shrinking band, in g.planes[c]; valid[c] when it
// was fitted. A cell of fewer than three columns keeps the level plane 0.
inline void fit_cell_ground(const std::vector<std::array<double, 3>>& p, const Background_options& o, std::size_t c,
                            const std::size_t* points, std::size_t count, Ground_grid& g, std::vector<char>& valid,
                            Cell_ground_buffers& buffers)
{
  // The fits see only the lowest point of each column of side cell / 16: a wall or an object
  // standing on the ground then weighs no more than the ground beside it (their bottom rows
  // would otherwise lift the plane towards them).
  constexpr std::size_t columns = 16;
  const std::size_t none = std::size_t(-1);
  std::vector<std::size_t>& column_point = buffers.column_point;
  std::vector<std::size_t>& lowest = buffers.lowest;
  const double xa = g.x0 + double(c % g.nx) * o.ground_cell_size, ya = g.y0 + double(c / g.nx) * o.ground_cell_size;
  column_point.assign(columns * columns, none);
  for(std::size_t k = 0; k < count; ++k) {
    const std::size_t i = points[k];
    const auto sub = [&](double t) {
      return (std::min)(columns - 1, std::size_t((std::max)(0.0, t) * double(columns) / o.ground_cell_size));
    };
    std::size_t& best = column_point[sub(p[i][0] - xa) + columns * sub(p[i][1] - ya)];
    if(best == none || p[i][2] < p[best][2] || (p[i][2] == p[best][2] && i < best))
      best = i;
  }
  lowest.clear();
  for(std::size_t i : column_point)
    if(i != none)
      lowest.push_back(i);
  std::sort(lowest.begin(), lowest.end());
  if(lowest.size() < 3)
    return;
  std::vector<double>& zs = buffers.zs;
  zs.clear();
  for(std::size_t i : lowest)
    zs.push_back(p[i][2]);
  const std::size_t q = (zs.size() - 1) / 20; // the 5th percentile: below it, noise
  std::nth_element(zs.begin(), zs.begin() + long(q), zs.end());
  std::array<double, 3> plane{{0, 0, zs[q]}};
  bool fitted = false;
  const double cx = xa + 0.5 * o.ground_cell_size, cy = ya + 0.5 * o.ground_cell_size;
  // Above the plane, the band stops at 0.3 m: the lowest points of a car or a bench, 0.3 to 1 m
  // above the road, lifted the ground of vehicle scans by 0.5 to 1.8 m, and the object with it
  // (bench/real_scans.cpp).
  const double above = 0.3;
  for(double band : {1.0, 0.5, 0.3, 0.2}) {
    buffers.near.clear();
    for(std::size_t i : lowest) {
      const double d = p[i][2] - (plane[0] * p[i][0] + plane[1] * p[i][1] + plane[2]);
      if(d > -band && d < (std::min)(band, above))
        buffers.near.push_back(i);
    }
    std::array<double, 3> next;
    if(!fit_plane(p, buffers.near, cx, cy, o.ground_cell_size / 8, next))
      break;
    plane = next;
    fitted = true;
  }
  g.planes[c] = plane;
  valid[c] = fitted ? 1 : 0;
}

// The height of the ground plane of cell c at the cell's centre.
inline double centre_height(const Ground_grid& g, double cell, std::size_t c)
{
  const auto& pl = g.planes[c];
  const double cx = g.x0 + (double(c % g.nx) + 0.5) * cell, cy = g.y0 + (double(c / g.nx) + 0.5) * cell;
  return pl[0] * cx + pl[1] * cy + pl[2];
}

// The fitted cells (`valid`) whose ground does not stand well above all its neighbours' (a roof,
// a car seen alone): compared with the lowest fitted ground within 20 m, a rise of more than
// 1 m plus 30% of the distance is not ground.
inline std::vector<char> grounded_cells(const Ground_grid& g, double cell, const std::vector<char>& valid)
{
  std::vector<char> keep = valid;
  const long reach = (std::max)(1L, long(std::ceil(20.0 / cell)));
  for(std::size_t c = 0; c < valid.size(); ++c) {
    if(!valid[c])
      continue;
    const long ci = long(c % g.nx), cj = long(c / g.nx);
    const double h = centre_height(g, cell, c);
    for(long dj = -reach; dj <= reach && keep[c]; ++dj)
      for(long di = -reach; di <= reach; ++di) {
        const long i = ci + di, j = cj + dj;
        if((di == 0 && dj == 0) || i < 0 || j < 0 || i >= long(g.nx) || j >= long(g.ny))
          continue;
        const std::size_t d = std::size_t(i) + g.nx * std::size_t(j);
        if(valid[d] && h > centre_height(g, cell, d) + 1.0 + 0.3 * cell * std::hypot(double(di), double(dj))) {
          keep[c] = 0;
          break;
        }
      }
  }
  return keep;
}

// The other cells take the planes of the nearest kept cells (all fitted cells when none is
// kept), level, by a breadth-first filling (deterministic order).
inline void fill_ground(Ground_grid& g, double cell, const std::vector<char>& valid, std::vector<char>& keep)
{
  std::vector<std::size_t> frontier, next;
  for(std::size_t c = 0; c < keep.size(); ++c)
    if(keep[c])
      frontier.push_back(c);
  if(frontier.empty()) {
    for(std::size_t c = 0; c < keep.size(); ++c)
      if(valid[c]) {
        keep[c] = 1;
        frontier.push_back(c);
      }
  }
  while(!frontier.empty()) {
    next.clear();
    for(std::size_t c : frontier) {
      const long ci = long(c % g.nx), cj = long(c / g.nx);
      for(const auto& d4 : {std::array<long, 2>{{1, 0}}, std::array<long, 2>{{-1, 0}},
                            std::array<long, 2>{{0, 1}}, std::array<long, 2>{{0, -1}}}) {
        const long i = ci + d4[0], j = cj + d4[1];
        if(i < 0 || j < 0 || i >= long(g.nx) || j >= long(g.ny))
          continue;
        const std::size_t d = std::size_t(i) + g.nx * std::size_t(j);
        if(keep[d])
          continue;
        keep[d] = 1;
        // The neighbour's plane, level, at its height at this cell's centre.
        const auto& pl = g.planes[c];
        const double cx = g.x0 + (double(i) + 0.5) * cell, cy = g.y0 + (double(j) + 0.5) * cell;
        g.planes[d] = {0, 0, pl[0] * cx + pl[1] * cy + pl[2]};
        next.push_back(d);
      }
    }
    frontier.swap(next);
  }
}

// 1. The ground: per cell, a plane started at the cell's low points and refitted to the points
//    near it, with a shrinking band. A cell whose ground stands well above all its neighbours'
//    (a roof, a car seen alone) takes theirs; empty cells take the ones of the nearest filled
//    cells.
inline void estimate_ground(const std::vector<std::array<double, 3>>& p, const Background_options& o,
                            const std::array<double, 3>& lo, const std::array<double, 3>& hi, Ground_grid& g)
{
  g.cell_size = o.ground_cell_size;
  g.x0 = lo[0];
  g.y0 = lo[1];
  g.nx = std::size_t((hi[0] - lo[0]) / o.ground_cell_size) + 1;
  g.ny = std::size_t((hi[1] - lo[1]) / o.ground_cell_size) + 1;
  const std::size_t cells = g.nx * g.ny;
  std::vector<std::size_t> start, order;
  sort_by_cell(p, g, o.ground_cell_size, start, order);
  g.planes.assign(cells, {0, 0, 0});
  std::vector<char> valid(cells, 0);
  Cell_ground_buffers buffers;
  for(std::size_t c = 0; c < cells; ++c)
    if(start[c + 1] - start[c] >= 3)
      fit_cell_ground(p, o, c, order.data() + start[c], start[c + 1] - start[c], g, valid, buffers);
  std::vector<char> keep = grounded_cells(g, o.ground_cell_size, valid);
  fill_ground(g, o.ground_cell_size, valid, keep);
}

// 2. Isolated points: too few other non-ground points in the voxels around them.
inline void mark_isolated(const std::vector<std::array<double, 3>>& p, const Background_options& o,
                          const std::array<double, 3>& lo, Background_removal_result& r)
{
  const std::size_t n = p.size();
  std::unordered_map<std::uint64_t, std::uint32_t> count;
  count.reserve(n - r.number_of_ground_points);
  for(std::size_t i = 0; i < n; ++i)
    if(r.kind[i] == Point_kind::FOREGROUND)
      ++count[voxel_key(p[i][0], p[i][1], p[i][2], o.isolation_radius, lo)];
  std::unordered_map<std::uint64_t, std::uint32_t> around;
  around.reserve(count.size());
  for(const auto& kv : count) {
    std::uint32_t s = 0;
    for(int dk = -1; dk <= 1; ++dk)
      for(int dj = -1; dj <= 1; ++dj)
        for(int di = -1; di <= 1; ++di) {
          const auto it = count.find(voxel_neighbor(kv.first, di, dj, dk));
          if(it != count.end())
            s += it->second;
        }
    around[kv.first] = s;
  }
  for(std::size_t i = 0; i < n; ++i)
    if(r.kind[i] == Point_kind::FOREGROUND &&
       around[voxel_key(p[i][0], p[i][1], p[i][2], o.isolation_radius, lo)] < o.minimum_neighbors + 1) {
      r.kind[i] = Point_kind::ISOLATED;
      ++r.number_of_isolated_points;
    }
}

// 3. Connected components of the remaining points (occupied voxels of side
//    `component_spacing`, 26-connected); the ones wider than `maximum_component_extent` go.
// 4. Small things against walls: the points of the large components outside the walls (tall
//    columns) are grouped again; the small groups standing on the ground stay.
inline void mark_large_components(const std::vector<std::array<double, 3>>& p, const Background_options& o,
                                  const std::array<double, 3>& lo, Background_removal_result& r)
{
  const std::size_t n = p.size();
  std::vector<char> remaining(n, 0);
  for(std::size_t i = 0; i < n; ++i)
    remaining[i] = r.kind[i] == Point_kind::FOREGROUND;
  std::size_t components = 0;
  const std::vector<std::uint32_t> component = voxel_components(p, remaining, o.component_spacing, lo, components);
  const std::vector<Component_box> box = component_boxes(p, r.height_above_ground, remaining, component, components);
  std::vector<char> large(n, 0);
  for(std::size_t i = 0; i < n; ++i)
    if(remaining[i])
      large[i] = box[component[i]].width() > o.maximum_component_extent ? 1 : 0;
  peel_walls(p, r.height_above_ground, o, lo, large);
  for(std::size_t i = 0; i < n; ++i) {
    if(!remaining[i])
      continue;
    if(large[i]) {
      r.kind[i] = Point_kind::LARGE_COMPONENT;
      ++r.number_of_large_component_points;
    } else
      r.foreground.push_back(i);
  }
}

inline Background_removal_result remove_background(const std::vector<std::array<double, 3>>& p,
                                                   const Background_options& o)
{
  Background_removal_result r;
  const std::size_t n = p.size();
  r.kind.assign(n, Point_kind::FOREGROUND);
  r.height_above_ground.assign(n, 0.0);
  if(n == 0)
    return r;
  std::array<double, 3> lo, hi;
  checked_bounds(p, (std::min)(o.ground_cell_size, (std::min)(o.isolation_radius, o.component_spacing)), "remove_background", lo, hi);
  estimate_ground(p, o, lo, hi, r.ground);
  for(std::size_t i = 0; i < n; ++i) {
    r.height_above_ground[i] = p[i][2] - r.ground.height(p[i][0], p[i][1]);
    if(r.height_above_ground[i] < o.ground_threshold) {
      r.kind[i] = Point_kind::GROUND;
      ++r.number_of_ground_points;
    }
  }
  mark_isolated(p, o, lo, r);
  mark_large_components(p, o, lo, r);
  return r;
}

} // namespace internal
/// \endcond

/*!
\ingroup PkgPointSetObjectRecognitionRef

Removes the background of a scanned urban scene (\cgalCite{Golovinskiy2010}, section 4.3.2), so
that what remains are candidate parts of small objects:

1. <b>Ground.</b> The points are binned in a uniform grid of `ground_cell_size` in \f$(x, y)\f$.
   In each cell, only the lowest point of each of its \f$16 \times 16\f$ columns takes part (so
   that the foot of a wall or an object does not lift the plane towards it): a plane starts level
   at the 5th percentile of their heights and is refitted by
   least squares to the points within a band around it, the band shrinking from 1 m to 0.2 m below
   it and at most 0.3 m above it (so that the low parts of a car do not lift it). A
   cell whose points near that plane do not spread over it (the foot of a wall seen from the
   street, a lone object), whose ground rises above another cell's within 20 m by more than 1 m
   plus 30% of their distance (a roof), or that is empty takes the ground of its neighbours. The ground height is blended
   bilinearly between cell centres; points less than `ground_threshold` above it are ground.
2. <b>Isolated points.</b> A remaining point with fewer than `minimum_neighbors` other remaining
   points in the \f$3 \times 3 \times 3\f$ voxels of side `isolation_radius` around its own is
   isolated.
3. <b>Large components.</b> The other points are grouped into connected components (occupied
   voxels of side `component_spacing`, touching by a face, an edge or a corner); components whose
   horizontal bounding-box diagonal exceeds `maximum_component_extent` (buildings, long walls)
   are removed, but for the small things standing against them: in a large component, the
   columns (squares of side `component_spacing` / 2) whose points span more than 2 m in height
   are walls; its other points are grouped again into connected components, and those no wider
   than `maximum_component_extent`, no taller than 2 m and starting less than 0.5 m above the
   ground (a newspaper box against a facade) are kept.

Coordinates are expected in metres with \f$z\f$ up. The result does not depend on the order of the
points (up to the rounding of the plane fits).

\tparam PointRange a model of `ConstRange` whose iterator type is `RandomAccessIterator`
\tparam NamedParameters a sequence of named parameters

\param points the points (for a `CGAL::Point_set_3`, use the overload taking it)
\param np an optional sequence of named parameters among the ones listed below

\cgalNamedParamsBegin
  \cgalParamNBegin{point_map}
    \cgalParamDescription{a property map associating points to the elements of `points`}
    \cgalParamType{a model of `ReadablePropertyMap` whose value type is a point of a \cgal kernel}
    \cgalParamDefault{`CGAL::Identity_property_map`}
  \cgalParamNEnd
  \cgalParamNBegin{ground_cell_size}
    \cgalParamDescription{the side of the cells of the ground grid, in metres}
    \cgalParamType{`double`}
    \cgalParamDefault{`Remove_background_options::ground_cell_size`}
    \cgalParamExtra{must be positive}
  \cgalParamNEnd
  \cgalParamNBegin{ground_threshold}
    \cgalParamDescription{points less than this above the ground are ground, in metres}
    \cgalParamType{`double`}
    \cgalParamDefault{`Remove_background_options::ground_threshold`}
  \cgalParamNEnd
  \cgalParamNBegin{isolation_radius}
    \cgalParamDescription{the side of the voxels in which neighbours are counted, in metres}
    \cgalParamType{`double`}
    \cgalParamDefault{`Remove_background_options::isolation_radius`}
    \cgalParamExtra{must be positive}
  \cgalParamNEnd
  \cgalParamNBegin{minimum_neighbors}
    \cgalParamDescription{a point with fewer neighbours is isolated (0: none is)}
    \cgalParamType{`std::size_t`}
    \cgalParamDefault{`Remove_background_options::minimum_neighbors`}
  \cgalParamNEnd
  \cgalParamNBegin{component_spacing}
    \cgalParamDescription{the side of the voxels whose contact makes connected components, in metres}
    \cgalParamType{`double`}
    \cgalParamDefault{`Remove_background_options::component_spacing`}
    \cgalParamExtra{must be positive; a parameter of its own, coarser by default than the
      `component_spacing` that groups objects in `locate_objects()` and `segment_objects()`
      (`Locate_objects_options::component_spacing`)}
  \cgalParamNEnd
  \cgalParamNBegin{maximum_component_extent}
    \cgalParamDescription{components with a wider horizontal bounding box are removed, in metres}
    \cgalParamType{`double`}
    \cgalParamDefault{`Remove_background_options::maximum_component_extent`}
    \cgalParamExtra{must be positive}
  \cgalParamNEnd
\cgalNamedParamsEnd

\returns per point its `Point_kind` and height above the ground, the indices of the points kept,
         counts, and the ground grid

\throws CGAL::Shape_analysis::Bad_input if a coordinate is not finite, a parameter is out of its
        range, or the scene is too large for the grid sizes (more than two million cells along an
        axis: process it in tiles)
*/
template <typename PointRange, typename NamedParameters = parameters::Default_named_parameters>
Background_removal_result remove_background(const PointRange& points,
                                            const NamedParameters& np = parameters::default_values())
{
  const Remove_background_options o = remove_background_options(np);
  const auto positive = [](double v) { return v > 0 && std::isfinite(v); };
  if(!positive(o.ground_cell_size))
    throw Bad_input("remove_background: ground_cell_size must be a positive number");
  if(!std::isfinite(o.ground_threshold))
    throw Bad_input("remove_background: ground_threshold must be a finite number");
  if(!positive(o.isolation_radius))
    throw Bad_input("remove_background: isolation_radius must be a positive number");
  if(!positive(o.component_spacing))
    throw Bad_input("remove_background: component_spacing must be a positive number");
  if(!positive(o.maximum_component_extent))
    throw Bad_input("remove_background: maximum_component_extent must be a positive number");
  return internal::remove_background(internal::point_arrays(points, np), o);
}

/*!
\ingroup PkgPointSetObjectRecognitionRef
`remove_background()` of the points of a `CGAL::Point_set_3` (its point map).
\tparam Point the point type of the point set
\tparam Vector the normal type of the point set
\tparam NamedParameters a sequence of named parameters
\param point_set the points
\param np the same named parameters as the other overload, but `point_map`
\returns as the other overload; indices follow the point set's iteration order
*/
template <typename Point, typename Vector, typename NamedParameters = parameters::Default_named_parameters>
Background_removal_result remove_background(const CGAL::Point_set_3<Point, Vector>& point_set,
                                            const NamedParameters& np = parameters::default_values())
{
  return remove_background(internal::points_of(point_set), np);
}

} // namespace Point_set_object_recognition
} // namespace CGAL

#endif // CGAL_POINT_SET_OBJECT_RECOGNITION_REMOVE_BACKGROUND_H
