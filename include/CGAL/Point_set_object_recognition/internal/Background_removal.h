// Copyright (c) 2026 CGAL Global Shape Analysis contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_POINT_SET_OBJECT_RECOGNITION_INTERNAL_BACKGROUND_REMOVAL_H
#define CGAL_POINT_SET_OBJECT_RECOGNITION_INTERNAL_BACKGROUND_REMOVAL_H

// The geometry of remove_background.h: the plane fit of a cell of the ground, the
// boxes of connected components and the peeling of walls off the large components.

#include <CGAL/Point_set_object_recognition/Remove_background_options.h>
#include <CGAL/Point_set_object_recognition/internal/Voxel_grid.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <unordered_map>
#include <vector>

namespace CGAL {
namespace Point_set_object_recognition {
namespace internal {

typedef Remove_background_options Background_options;

// Least-squares plane z = a x + b y + c through the points `idx` (coordinates relative to
// (cx, cy)); false when they do not determine one, or do not spread over the cell in both x and
// y (standard deviation under `spread`: the foot of a wall, a lone object).
inline bool fit_plane(const std::vector<std::array<double, 3>>& p, const std::vector<std::size_t>& idx,
                      double cx, double cy, double spread, std::array<double, 3>& plane)
{
  if(idx.size() < 3)
    return false;
  double sxx = 0, sxy = 0, syy = 0, sx = 0, sy = 0, sz = 0, sxz = 0, syz = 0;
  const double n = double(idx.size());
  for(std::size_t i : idx) {
    const double x = p[i][0] - cx, y = p[i][1] - cy, z = p[i][2];
    sxx += x * x, sxy += x * y, syy += y * y, sx += x, sy += y, sz += z, sxz += x * z, syz += y * z;
  }
  // Centred normal equations.
  const double mx = sx / n, my = sy / n, mz = sz / n;
  const double cxx = sxx / n - mx * mx, cxy = sxy / n - mx * my, cyy = syy / n - my * my;
  const double cxz = sxz / n - mx * mz, cyz = syz / n - my * mz;
  if(cxx < spread * spread || cyy < spread * spread)
    return false;
  const double det = cxx * cyy - cxy * cxy;
  double a = 0, b = 0;
  if(det > 1e-6 * (cxx + cyy) * (cxx + cyy) && det > 0) {
    a = (cxz * cyy - cyz * cxy) / det;
    b = (cyz * cxx - cxz * cxy) / det;
  }
  // A ground steeper than 45 degrees is a wall: keep it level.
  if(!(std::abs(a) < 1 && std::abs(b) < 1))
    a = b = 0;
  plane = {a, b, mz - a * mx - b * my - a * cx - b * cy};
  return std::isfinite(plane[2]);
}

// Per connected component of the selected points: its horizontal box and its lowest and highest
// heights above the ground.
struct Component_box
{
  double x0 = std::numeric_limits<double>::infinity(), y0 = x0, low = x0;
  double x1 = -std::numeric_limits<double>::infinity(), y1 = x1, high = x1;
  double width() const { return std::hypot(x1 - x0, y1 - y0); } // the horizontal diagonal
};

inline std::vector<Component_box> component_boxes(const std::vector<std::array<double, 3>>& p,
                                                  const std::vector<double>& height,
                                                  const std::vector<char>& selected,
                                                  const std::vector<std::uint32_t>& component,
                                                  std::size_t components)
{
  std::vector<Component_box> box(components);
  for(std::size_t i = 0; i < p.size(); ++i)
    if(selected[i]) {
      Component_box& b = box[component[i]];
      b.x0 = (std::min)(b.x0, p[i][0]), b.y0 = (std::min)(b.y0, p[i][1]), b.low = (std::min)(b.low, height[i]);
      b.x1 = (std::max)(b.x1, p[i][0]), b.y1 = (std::max)(b.y1, p[i][1]), b.high = (std::max)(b.high, height[i]);
    }
  return box;
}

// The points of large components (`large[i]` set) that do not belong to a wall: in a large
// component, the columns (squares of side component_spacing / 2) whose points span more than
// 2 m in height above the ground are walls. The other points of large components are grouped
// again into connected components (voxels of side component_spacing); `large[i]` is cleared for
// the points of the components no wider than `maximum_component_extent` and no taller than 2 m
// that start less than 0.5 m above the ground, so that a newspaper box against a facade is kept,
// and the remains of a facade (window sills, fragments of walls seen through gaps) are not.
inline void peel_walls(const std::vector<std::array<double, 3>>& p, const std::vector<double>& height,
                       const Background_options& o, const std::array<double, 3>& lo, std::vector<char>& large)
{
  const std::size_t n = p.size();
  const double side = o.component_spacing / 2, wall_height = 2.0, grounded = 0.5;
  std::unordered_map<std::uint64_t, std::array<double, 2>> column; // lowest, highest
  const auto key2 = [&](std::size_t i) { return voxel_key(p[i][0], p[i][1], lo[2], side, lo); };
  for(std::size_t i = 0; i < n; ++i)
    if(large[i]) {
      auto& c = column.emplace(key2(i), std::array<double, 2>{{height[i], height[i]}}).first->second;
      c[0] = (std::min)(c[0], height[i]);
      c[1] = (std::max)(c[1], height[i]);
    }
  std::vector<char> rest(n, 0);
  bool any = false;
  for(std::size_t i = 0; i < n; ++i)
    if(large[i]) {
      const auto& c = column[key2(i)];
      rest[i] = c[1] - c[0] > wall_height ? 0 : 1;
      any = any || rest[i];
    }
  if(!any)
    return;
  std::size_t components = 0;
  const std::vector<std::uint32_t> component = voxel_components(p, rest, o.component_spacing, lo, components);
  const std::vector<Component_box> box = component_boxes(p, height, rest, component, components);
  for(std::size_t i = 0; i < n; ++i)
    if(rest[i]) {
      const Component_box& b = box[component[i]];
      if(!(b.width() > o.maximum_component_extent) && b.low < grounded && b.high - b.low <= wall_height)
        large[i] = 0;
    }
}

} // namespace internal
} // namespace Point_set_object_recognition
} // namespace CGAL

#endif // CGAL_POINT_SET_OBJECT_RECOGNITION_INTERNAL_BACKGROUND_REMOVAL_H
