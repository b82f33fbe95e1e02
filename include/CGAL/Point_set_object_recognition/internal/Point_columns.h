// Copyright (c) 2026 CGAL Global Shape Analysis contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_POINT_SET_OBJECT_RECOGNITION_INTERNAL_POINT_COLUMNS_H
#define CGAL_POINT_SET_OBJECT_RECOGNITION_INTERNAL_POINT_COLUMNS_H

#include <CGAL/Point_set_object_recognition/internal/Column_index.h>
#include <CGAL/Point_set_object_recognition/internal/Voxel_grid.h>
#include <CGAL/Shape_analysis/Bad_input.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numeric>
#include <vector>

namespace CGAL {
namespace Point_set_object_recognition {
namespace internal {

// The points of a cloud by columns (squares of side 1 m in (x, y)), built once per call and
// shared by the graphs of its rounds.
class Point_columns
{
public:
  static constexpr std::uint32_t none = std::numeric_limits<std::uint32_t>::max();

  // Bad_input for too many points, a coordinate that is not finite or too large a scene.
  explicit Point_columns(const std::vector<P3>& points) : m_p(points)
  {
    if(points.size() >= std::size_t(none))
      throw CGAL::Shape_analysis::Bad_input("segment_objects: too many points (at most 2^32 - 2)");
    {
      P3 lo, hi; // locals: the loop keeps them in registers
      checked_bounds(points, m_side, "segment_objects", lo, hi);
      m_lo = lo, m_hi = hi;
    }
    const std::size_t n = points.size();
    const long ni = long((m_hi[0] - m_lo[0]) / m_side) + 1, nj = long((m_hi[1] - m_lo[1]) / m_side) + 1;
    m_column_of_point.assign(n, none);
    if(double(ni) * double(nj) <= 4.0 * double(n) + double(1 << 20)) {
      // A dense grid: column (i, j) is list j ni + i (empty lists included), by a counting sort.
      m_lists.index.reset(0, 0, ni - 1, nj - 1, n);
      m_lists.keys.resize(std::size_t(ni * nj));
      for(long j = 0; j < nj; ++j)
        for(long i = 0; i < ni; ++i) {
          const std::uint64_t k = Column_index::key(i, j);
          m_lists.index.emplace(k, std::uint32_t(j * ni + i));
          m_lists.keys[std::size_t(j * ni + i)] = k;
        }
      // Consecutive points mostly share their column (a scan's order): the counts and the fills
      // go by runs of points of one column.
      m_lists.first.assign(m_lists.keys.size() + 1, 0);
      std::uint32_t run_column = none;
      std::size_t run = 0;
      for(std::size_t i = 0; i < n; ++i) {
        const std::uint32_t c = std::uint32_t(long((m_p[i][1] - m_lo[1]) / m_side) * ni + long((m_p[i][0] - m_lo[0]) / m_side));
        m_column_of_point[i] = c;
        if(c != run_column) {
          if(run_column != none)
            m_lists.first[run_column + 1] += run;
          run_column = c, run = 0;
        }
        ++run;
      }
      if(run_column != none)
        m_lists.first[run_column + 1] += run;
      for(std::size_t c = 0; c < m_lists.keys.size(); ++c)
        m_lists.first[c + 1] += m_lists.first[c];
      m_lists.items.resize(n);
      std::vector<std::size_t> fill(m_lists.first.begin(), m_lists.first.end() - 1);
      for(std::size_t i = 0; i < n;) {
        const std::uint32_t c = m_column_of_point[i];
        std::uint32_t* out = m_lists.items.data() + fill[c];
        const std::size_t from = i;
        for(; i < n && m_column_of_point[i] == c; ++i)
          *out++ = std::uint32_t(i);
        fill[c] += i - from;
      }
    } else {
      std::vector<std::uint32_t> all(n);
      std::iota(all.begin(), all.end(), 0u);
      m_lists.assign(all, [&](std::uint32_t i) { return key(m_p[i][0], m_p[i][1]); });
      for(std::uint32_t c = 0; c < m_lists.size(); ++c)
        for(const std::uint32_t* q = m_lists.begin(c); q != m_lists.end(c); ++q)
          m_column_of_point[*q] = c;
    }
  }

  // Bad_input for a location that is not finite or lies outside the cloud's horizontal box.
  void check(const std::vector<P3>& locations) const
  {
    for(const P3& l : locations) {
      for(double c : l)
        if(!std::isfinite(c))
          throw CGAL::Shape_analysis::Bad_input("segment_objects: a location is not finite");
      if(l[0] < m_lo[0] - 1e-9 || l[0] > m_hi[0] + 1e-9 || l[1] < m_lo[1] - 1e-9 || l[1] > m_hi[1] + 1e-9)
        throw CGAL::Shape_analysis::Bad_input("segment_objects: a location lies outside the point cloud (its "
                                              "horizontal bounding box)");
    }
  }

  const std::vector<P3>& points() const { return m_p; }
  const P3& lo() const { return m_lo; }
  const P3& hi() const { return m_hi; }
  double side() const { return m_side; }
  const Key_lists& lists() const { return m_lists; }
  std::uint32_t column_of_point(std::size_t i) const { return m_column_of_point[i]; }
  std::uint64_t key(double x, double y) const
  {
    return Column_index::key(long((x - m_lo[0]) / m_side), long((y - m_lo[1]) / m_side));
  }

  // Calls f on the items of the columns of `lists` (keyed as these columns) that meet the square
  // of half side `radius` around `at`.
  template <typename F>
  void for_columns(const P3& at, double radius, const F& f, const Key_lists& lists) const
  {
    lists.for_square(m_lo, m_side, at, radius, f);
  }

  // The points within `radius` of (x, y) horizontally, increasing.
  void points_within(const P3& at, double radius, std::vector<std::uint32_t>& out) const
  {
    points_within(at, radius, out, [](std::uint32_t) { return true; });
    std::sort(out.begin(), out.end());
  }

  // The points within `radius` of (x, y) horizontally for which keep(i) holds, in no particular
  // order.
  template <typename Keep>
  void points_within(const P3& at, double radius, std::vector<std::uint32_t>& out, const Keep& keep) const
  {
    out.clear();
    for_columns(at, radius, [&](std::uint32_t i) {
      if(keep(i) && horizontally_within(m_p[i], at, radius))
        out.push_back(i);
    }, m_lists);
  }

private:
  const std::vector<P3>& m_p;
  static constexpr double m_side = 1.0;
  P3 m_lo{{0, 0, 0}}, m_hi{{0, 0, 0}};
  Key_lists m_lists;
  std::vector<std::uint32_t> m_column_of_point;
};

} // namespace internal
} // namespace Point_set_object_recognition
} // namespace CGAL

#endif // CGAL_POINT_SET_OBJECT_RECOGNITION_INTERNAL_POINT_COLUMNS_H
