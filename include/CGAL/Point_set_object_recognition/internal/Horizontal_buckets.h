// Copyright (c) 2026 CGAL Global Shape Analysis contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_POINT_SET_OBJECT_RECOGNITION_INTERNAL_HORIZONTAL_BUCKETS_H
#define CGAL_POINT_SET_OBJECT_RECOGNITION_INTERNAL_HORIZONTAL_BUCKETS_H

// Indices of points by square horizontal cells, to visit those near a location (the features'
// spin images and columns, the context grids' neighbours).

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <unordered_map>
#include <vector>

namespace CGAL {
namespace Point_set_object_recognition {
namespace internal {

class Horizontal_buckets
{
public:
  // `points[i][0]` and `points[i][1]`: the horizontal coordinates of point i.
  template <typename PointVector>
  Horizontal_buckets(const PointVector& points, double cell) : m_cell(cell)
  {
    for(std::size_t i = 0; i < points.size(); ++i) {
      const std::int64_t a = index(points[i][0]), b = index(points[i][1]);
      m_cells[key(a, b)].push_back(i);
      if(i == 0)
        m_a0 = m_a1 = a, m_b0 = m_b1 = b;
      m_a0 = (std::min)(m_a0, a), m_a1 = (std::max)(m_a1, a);
      m_b0 = (std::min)(m_b0, b), m_b1 = (std::max)(m_b1, b);
    }
  }

  // Calls f(i) for the points of the cells within `radius` of (x, y) (a superset of the points
  // within it), cell by cell in a fixed order. Only the cells of the points' box are visited,
  // however large `radius`.
  template <typename F>
  void around(double x, double y, double radius, const F& f) const
  {
    const std::int64_t a0 = (std::max)(m_a0, index(x - radius)), a1 = (std::min)(m_a1, index(x + radius));
    const std::int64_t b0 = (std::max)(m_b0, index(y - radius)), b1 = (std::min)(m_b1, index(y + radius));
    for(std::int64_t a = a0; a <= a1; ++a)
      for(std::int64_t b = b0; b <= b1; ++b) {
        const auto it = m_cells.find(key(a, b));
        if(it != m_cells.end())
          for(std::size_t i : it->second)
            f(i);
      }
  }

private:
  // The cell of coordinate v, clamped to 32 bits (the keys' range; also no overflow for 1e300).
  std::int64_t index(double v) const
  {
    const double c = std::floor(v / m_cell), limit = double(std::int64_t(1) << 31);
    if(!(c > -limit))
      return -(std::int64_t(1) << 31);
    if(!(c < limit - 1))
      return (std::int64_t(1) << 31) - 1;
    return std::int64_t(c);
  }
  static std::uint64_t key(std::int64_t a, std::int64_t b)
  {
    return (std::uint64_t(a + (std::int64_t(1) << 31)) & 0xFFFFFFFFu) | (std::uint64_t(b + (std::int64_t(1) << 31)) << 32);
  }
  double m_cell;
  std::int64_t m_a0 = 0, m_a1 = -1, m_b0 = 0, m_b1 = -1; // the cells' box (empty without points)
  std::unordered_map<std::uint64_t, std::vector<std::size_t>> m_cells;
};

} // namespace internal
} // namespace Point_set_object_recognition
} // namespace CGAL

#endif // CGAL_POINT_SET_OBJECT_RECOGNITION_INTERNAL_HORIZONTAL_BUCKETS_H
