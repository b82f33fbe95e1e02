// Copyright (c) 2026 CGAL Global Shape Analysis contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_POINT_SET_OBJECT_RECOGNITION_INTERNAL_VOXEL_GRID_H
#define CGAL_POINT_SET_OBJECT_RECOGNITION_INTERNAL_VOXEL_GRID_H

// Sparse voxel grids over point clouds: integer keys, neighbours, connected components of
// occupied voxels (26-connected) and mean-shift clusters, as used by background removal and
// localization.

#include <CGAL/Point_set_3.h>
#include <CGAL/Shape_analysis/Bad_input.h>
#include <CGAL/Shape_analysis/internal/Union_find.h>
#include <CGAL/number_utils.h>
#include <CGAL/Named_function_parameters.h>
#include <CGAL/property_map.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <iterator>
#include <string>
#include <cstdint>
#include <limits>
#include <unordered_map>
#include <vector>

namespace CGAL {
namespace Point_set_object_recognition {
namespace internal {

// The key of the voxel of side `s` holding (x, y, z), `lo` the grid's corner (21 bits per axis:
// the callers keep the extent under two million voxels per axis).
inline std::uint64_t voxel_key(double x, double y, double z, double s, const std::array<double, 3>& lo)
{
  const std::uint64_t i = std::uint64_t((x - lo[0]) / s), j = std::uint64_t((y - lo[1]) / s),
                      k = std::uint64_t((z - lo[2]) / s);
  return (i & 0x1FFFFF) | ((j & 0x1FFFFF) << 21) | ((k & 0x1FFFFF) << 42);
}

constexpr std::uint64_t no_voxel = std::numeric_limits<std::uint64_t>::max();

// The key of the voxel offset by (di, dj, dk), or `no_voxel` below the corner.
inline std::uint64_t voxel_neighbor(std::uint64_t key, int di, int dj, int dk)
{
  const long i = long(key & 0x1FFFFF) + di, j = long((key >> 21) & 0x1FFFFF) + dj,
             k = long((key >> 42) & 0x1FFFFF) + dk;
  if(i < 0 || j < 0 || k < 0)
    return no_voxel;
  return std::uint64_t(i) | (std::uint64_t(j) << 21) | (std::uint64_t(k) << 42);
}

// The points of a range as double coordinates, through the `point_map` of the named parameters
// `np` (the identity by default).
template <typename PointRange, typename NamedParameters>
std::vector<std::array<double, 3>> point_arrays(const PointRange& points, const NamedParameters& np)
{
  typedef typename std::iterator_traits<typename PointRange::const_iterator>::value_type Value;
  const auto point_map = CGAL::parameters::choose_parameter(
    CGAL::parameters::get_parameter(np, CGAL::internal_np::point_map), CGAL::Identity_property_map<Value>());
  std::vector<std::array<double, 3>> p;
  p.reserve(std::size_t(std::distance(std::begin(points), std::end(points))));
  for(const auto& v : points) {
    const auto& q = get(point_map, v);
    p.push_back({CGAL::to_double(q.x()), CGAL::to_double(q.y()), CGAL::to_double(q.z())});
  }
  return p;
}

// The points of a point set, in its iteration order.
template <typename Point, typename Vector>
std::vector<Point> points_of(const CGAL::Point_set_3<Point, Vector>& point_set)
{
  std::vector<Point> points;
  points.reserve(point_set.size());
  for(auto i : point_set)
    points.push_back(point_set.point(i));
  return points;
}

// The bounding box of `p` (not empty); Bad_input (`who` says which function) for a coordinate
// that is not finite or an extent of more than two million voxels of side `voxel` along an axis.
inline void checked_bounds(const std::vector<std::array<double, 3>>& p, double voxel, const std::string& who,
                           std::array<double, 3>& lo, std::array<double, 3>& hi)
{
  lo = hi = p.front();
  for(const auto& q : p)
    for(std::size_t c = 0; c < 3; ++c) {
      if(!std::isfinite(q[c]))
        throw CGAL::Shape_analysis::Bad_input(who + ": a point coordinate is not a finite number");
      lo[c] = (std::min)(lo[c], q[c]);
      hi[c] = (std::max)(hi[c], q[c]);
    }
  for(std::size_t c = 0; c < 3; ++c)
    if((hi[c] - lo[c]) / voxel > 2.0e6)
      throw CGAL::Shape_analysis::Bad_input(who + ": the scene is too large for the grid sizes (more than "
                                            "two million cells along an axis); process it in tiles");
}

constexpr std::uint32_t no_component = std::numeric_limits<std::uint32_t>::max();

// Connected components of the selected points: two points are connected when their voxels of
// side `s` touch (by a face, an edge or a corner). Per point its component, numbered 0, 1, ...
// in the order of the components' first points; `no_component` for the points not selected.
inline std::vector<std::uint32_t> voxel_components(const std::vector<std::array<double, 3>>& p,
                                                   const std::vector<char>& selected, double s,
                                                   const std::array<double, 3>& lo,
                                                   std::size_t& number_of_components)
{
  std::unordered_map<std::uint64_t, std::uint32_t> voxel;
  std::vector<std::uint64_t> keys;
  std::vector<std::uint32_t> voxel_of_point(p.size(), no_component);
  for(std::size_t i = 0; i < p.size(); ++i)
    if(selected[i]) {
      const std::uint64_t k = voxel_key(p[i][0], p[i][1], p[i][2], s, lo);
      const auto ins = voxel.emplace(k, std::uint32_t(keys.size()));
      if(ins.second)
        keys.push_back(k);
      voxel_of_point[i] = ins.first->second;
    }
  CGAL::Shape_analysis::internal::Union_find uf(keys.size());
  for(std::size_t v = 0; v < keys.size(); ++v)
    for(int dk = -1; dk <= 1; ++dk)
      for(int dj = -1; dj <= 1; ++dj)
        for(int di = -1; di <= 1; ++di) {
          const auto it = voxel.find(voxel_neighbor(keys[v], di, dj, dk));
          if(it != voxel.end())
            uf.unite(std::uint32_t(v), it->second);
        }
  std::vector<std::uint32_t> dense(keys.size(), no_component), result(p.size(), no_component);
  number_of_components = 0;
  for(std::size_t i = 0; i < p.size(); ++i)
    if(voxel_of_point[i] != no_component) {
      const std::uint32_t root = uf.find(voxel_of_point[i]);
      if(dense[root] == no_component)
        dense[root] = std::uint32_t(number_of_components++);
      result[i] = dense[root];
    }
  return result;
}

// Clusters of points by mean shift in the horizontal plane with a flat kernel of `radius`: a seed
// per occupied square of side radius / 2 (at the mean of its points) climbs to a mode of the
// point density (the mean of the points within `radius` of it, until it moves less than 1% of the
// radius or after 100 steps); seeds whose modes are closer than radius / 2 are merged. Per point
// the cluster of its square, numbered 0, 1, ... by the order of the squares.
inline std::vector<std::uint32_t> mean_shift_clusters(const std::vector<std::array<double, 3>>& p, double radius,
                                                      const std::array<double, 3>& lo,
                                                      std::size_t& number_of_clusters)
{
  const auto key2 = [&](double x, double y, double s) { return voxel_key(x, y, lo[2], s, lo); };
  // Points by cell of side `radius` (for the neighbourhoods) and by square of side radius / 2.
  std::unordered_map<std::uint64_t, std::vector<std::uint32_t>> cells;
  std::unordered_map<std::uint64_t, std::uint32_t> square_index;
  std::vector<std::uint64_t> squares;
  std::vector<std::uint32_t> square_of_point(p.size());
  for(std::size_t i = 0; i < p.size(); ++i) {
    cells[key2(p[i][0], p[i][1], radius)].push_back(std::uint32_t(i));
    const auto ins = square_index.emplace(key2(p[i][0], p[i][1], radius / 2), std::uint32_t(squares.size()));
    if(ins.second)
      squares.push_back(ins.first->first);
    square_of_point[i] = ins.first->second;
  }
  std::vector<std::array<double, 3>> seed(squares.size(), {0, 0, 0}); // x, y, count
  for(std::size_t i = 0; i < p.size(); ++i) {
    auto& s = seed[square_of_point[i]];
    s[0] += p[i][0], s[1] += p[i][1], s[2] += 1;
  }
  const double r2 = radius * radius;
  std::vector<std::array<double, 2>> mode(squares.size());
  for(std::size_t k = 0; k < squares.size(); ++k) {
    double x = seed[k][0] / seed[k][2], y = seed[k][1] / seed[k][2];
    for(int step = 0; step < 100; ++step) {
      double sx = 0, sy = 0, n = 0;
      const std::uint64_t c = key2(x, y, radius);
      for(int dj = -1; dj <= 1; ++dj)
        for(int di = -1; di <= 1; ++di) {
          const auto it = cells.find(voxel_neighbor(c, di, dj, 0));
          if(it == cells.end())
            continue;
          for(std::uint32_t i : it->second) {
            const double dx = p[i][0] - x, dy = p[i][1] - y;
            if(dx * dx + dy * dy <= r2)
              sx += p[i][0], sy += p[i][1], n += 1;
          }
        }
      if(n == 0)
        break;
      const double nx = sx / n, ny = sy / n;
      const double moved = std::hypot(nx - x, ny - y);
      x = nx, y = ny;
      if(moved < 0.01 * radius)
        break;
    }
    mode[k] = {x, y};
  }
  // Merge the modes closer than radius / 2 (squares of that side: neighbours checked).
  CGAL::Shape_analysis::internal::Union_find uf(squares.size());
  std::unordered_map<std::uint64_t, std::vector<std::uint32_t>> by_mode;
  for(std::size_t k = 0; k < squares.size(); ++k)
    by_mode[key2(mode[k][0], mode[k][1], radius / 2)].push_back(std::uint32_t(k));
  for(std::size_t k = 0; k < squares.size(); ++k) {
    const std::uint64_t c = key2(mode[k][0], mode[k][1], radius / 2);
    for(int dj = -1; dj <= 1; ++dj)
      for(int di = -1; di <= 1; ++di) {
        const auto it = by_mode.find(voxel_neighbor(c, di, dj, 0));
        if(it == by_mode.end())
          continue;
        for(std::uint32_t m : it->second)
          if(std::hypot(mode[m][0] - mode[k][0], mode[m][1] - mode[k][1]) < radius / 2)
            uf.unite(std::uint32_t(k), m);
      }
  }
  std::vector<std::uint32_t> dense(squares.size(), no_component), result(p.size(), no_component);
  number_of_clusters = 0;
  for(std::size_t i = 0; i < p.size(); ++i) {
    const std::uint32_t root = uf.find(square_of_point[i]);
    if(dense[root] == no_component)
      dense[root] = std::uint32_t(number_of_clusters++);
    result[i] = dense[root];
  }
  return result;
}

} // namespace internal
} // namespace Point_set_object_recognition
} // namespace CGAL

#endif // CGAL_POINT_SET_OBJECT_RECOGNITION_INTERNAL_VOXEL_GRID_H
