// Copyright (c) 2026 CGAL Global Shape Analysis contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_SURFACE_MESH_SYMMETRIZATION_INTERNAL_SURFACE_BOUNDARY_H
#define CGAL_SURFACE_MESH_SYMMETRIZATION_INTERNAL_SURFACE_BOUNDARY_H

// The border of an open surface as dense points, for the refinement of symmetry planes: a
// reflection that maps a surface onto itself maps its border onto its border. The surface alone
// does not pin a plane everywhere: a flat region is its own mirror image under every plane
// perpendicular to it, and only its border tells those planes apart.

#include <CGAL/Shape_analysis/internal/Nearest_sample_tree.h>
#include <CGAL/Surface_mesh_symmetrization/internal/Symmetry_geometry.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <vector>

namespace CGAL {
namespace Surface_mesh_symmetrization {
namespace internal {

struct Surface_boundary
{
  std::vector<Vector_3d> points;        // along the border edges
  std::vector<Vector_3d> across;        // per point: the unit direction in its face across the border
  std::vector<Vector_3d> normals;       // per point: the unit normal of its face
  SAI::Nearest_sample_tree tree;        // over `points`

  bool empty() const { return points.empty(); }
};

// The border edges of `s` (edges of exactly one non-degenerate triangle), sampled every
// `spacing` at most (coarser when that would exceed `max_points`).
inline Surface_boundary surface_boundary(const Surface& s, double spacing, std::size_t max_points)
{
  Surface_boundary b;
  struct Half
  {
    std::uint32_t lo, hi, face, from;
    bool operator<(const Half& o) const
    {
      return lo != o.lo ? lo < o.lo : hi != o.hi ? hi < o.hi : face < o.face;
    }
  };
  std::vector<Half> halves;
  for(std::size_t f = 0; f < s.triangles.size(); ++f) {
    if(!(s.area_vector(f).squared_length() > 0))
      continue;
    const auto& t = s.triangles[f];
    for(int i = 0; i < 3; ++i) {
      const std::uint32_t u = t[std::size_t(i)], v = t[std::size_t((i + 1) % 3)];
      halves.push_back(Half{(std::min)(u, v), (std::max)(u, v), std::uint32_t(f), u});
    }
  }
  std::sort(halves.begin(), halves.end());
  std::vector<Half> border;
  double length = 0;
  for(std::size_t i = 0; i < halves.size();) {
    std::size_t j = i;
    while(j < halves.size() && halves[j].lo == halves[i].lo && halves[j].hi == halves[i].hi)
      ++j;
    if(j == i + 1) {
      border.push_back(halves[i]);
      length += (s.points[halves[i].hi] - s.points[halves[i].lo]).length();
    }
    i = j;
  }
  if(border.empty() || !(spacing > 0) || !(length > 0))
    return b;
  spacing = (std::max)(spacing, length / double((std::max)(std::size_t(1), max_points)));
  for(const Half& h : border) {
    const Vector_3d p = s.points[h.lo], q = s.points[h.hi];
    const Vector_3d area = s.area_vector(h.face);
    const Vector_3d normal = area / area.length();
    Vector_3d across = SAI::cross(normal, (q - p) / (q - p).length());
    const double across_length = across.length();
    if(!(across_length > 0))
      continue;
    across = across / across_length;
    const std::size_t n = (std::max)(std::size_t(1), std::size_t(std::ceil((q - p).length() / spacing)));
    for(std::size_t k = 0; k < n; ++k) {
      const double t = (double(k) + 0.5) / double(n);
      b.points.push_back(p + (q - p) * t);
      b.across.push_back(across);
      b.normals.push_back(normal);
    }
  }
  if(!b.points.empty())
    b.tree = SAI::Nearest_sample_tree(b.points);
  return b;
}

} // namespace internal
} // namespace Surface_mesh_symmetrization
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_SYMMETRIZATION_INTERNAL_SURFACE_BOUNDARY_H
