// Copyright (c) 2026 CGAL Global Shape Analysis contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_POINT_SET_OBJECT_RECOGNITION_INTERNAL_HORIZONTAL_BUCKETS_H
#define CGAL_POINT_SET_OBJECT_RECOGNITION_INTERNAL_HORIZONTAL_BUCKETS_H

// Indices of points by square horizontal cells, to visit those near a location (the features'
// spin images and columns, the context grids' neighbours).

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
    for(std::size_t i = 0; i < points.size(); ++i)
      m_cells[key(index(points[i][0]), index(points[i][1]))].push_back(i);
  }

  // Calls f(i) for the points of the cells within `radius` of (x, y) (a superset of the points
  // within it), cell by cell in a fixed order.
  template <typename F>
  void around(double x, double y, double radius, const F& f) const
  {
    for(std::int64_t a = index(x - radius); a <= index(x + radius); ++a)
      for(std::int64_t b = index(y - radius); b <= index(y + radius); ++b) {
        const auto it = m_cells.find(key(a, b));
        if(it != m_cells.end())
          for(std::size_t i : it->second)
            f(i);
      }
  }

private:
  std::int64_t index(double v) const { return std::int64_t(std::floor(v / m_cell)); }
  static std::uint64_t key(std::int64_t a, std::int64_t b)
  {
    return (std::uint64_t(a + (std::int64_t(1) << 31)) & 0xFFFFFFFFu) | (std::uint64_t(b + (std::int64_t(1) << 31)) << 32);
  }
  double m_cell;
  std::unordered_map<std::uint64_t, std::vector<std::size_t>> m_cells;
};

} // namespace internal
} // namespace Point_set_object_recognition
} // namespace CGAL

#endif // CGAL_POINT_SET_OBJECT_RECOGNITION_INTERNAL_HORIZONTAL_BUCKETS_H
