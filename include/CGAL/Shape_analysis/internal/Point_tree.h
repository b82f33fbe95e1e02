// Copyright (c) 2026 CGAL Global Shape Analysis contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_SHAPE_ANALYSIS_INTERNAL_POINT_TREE_H
#define CGAL_SHAPE_ANALYSIS_INTERNAL_POINT_TREE_H

// A small static kd-tree over indexed 3D points (double), for the nearest-neighbour queries of
// the graph machinery (component links). Built once, queried many times; no allocation per query.

#include <CGAL/Shape_analysis/internal/Vector_3d.h>

#include <algorithm>
#include <cstdint>
#include <limits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Shape_analysis {
namespace internal {

// Offers `c` to `heap`, a max-heap that keeps the (at most) k smallest values offered.
template <typename T>
void keep_k_smallest(std::vector<T>& heap, std::size_t k, const T& c)
{
  if(heap.size() < k) {
    heap.push_back(c);
    std::push_heap(heap.begin(), heap.end());
  } else if(k > 0 && c < heap.front()) {
    std::pop_heap(heap.begin(), heap.end());
    heap.back() = c;
    std::push_heap(heap.begin(), heap.end());
  }
}

class Point_tree
{
public:
  Point_tree() = default;

  // `ids[k]` is the caller's id of point `points[k]`.
  Point_tree(const std::vector<Vector_3d>& points, const std::vector<std::uint32_t>& ids)
    : m_points(points), m_ids(ids)
  {
    m_order.resize(points.size());
    for(std::size_t i = 0; i < points.size(); ++i)
      m_order[i] = static_cast<std::uint32_t>(i);
    if(!points.empty())
      build(0, points.size(), 0);
  }

  bool empty() const { return m_points.empty(); }

  // The id of the nearest point to `q` closer than sqrt(max_squared_distance), and its squared
  // distance; returns false when there is none.
  bool nearest(const Vector_3d& q, double max_squared_distance, std::uint32_t& id,
               double& squared_distance) const
  {
    if(m_points.empty())
      return false;
    double best = max_squared_distance;
    std::uint32_t best_k = (std::numeric_limits<std::uint32_t>::max)();
    Vector_3d offset(0.0);
    search(0, m_points.size(), 0, q, best, best_k, offset, 0.0);
    if(best_k == (std::numeric_limits<std::uint32_t>::max)())
      return false;
    id = m_ids[best_k];
    squared_distance = best;
    return true;
  }

  // The ids of the (at most) `k` nearest points to `q` closer than sqrt(max_squared_distance)
  // (every point by default), nearest first, with their squared distances, in `result` (cleared
  // first).
  void k_nearest(const Vector_3d& q, std::size_t k,
                 std::vector<std::pair<double, std::uint32_t>>& result,
                 double max_squared_distance = std::numeric_limits<double>::infinity()) const
  {
    result.clear();
    if(m_points.empty() || k == 0)
      return;
    Vector_3d offset(0.0);
    search_k(0, m_points.size(), 0, q, k, result, offset, 0.0, max_squared_distance);
    if(max_squared_distance < std::numeric_limits<double>::infinity())
      result.erase(std::remove_if(result.begin(), result.end(),
                                  [&](const std::pair<double, std::uint32_t>& r) {
                                    return !(r.first < max_squared_distance);
                                  }),
                   result.end());
    std::sort(result.begin(), result.end());
    for(auto& r : result)
      r.second = m_ids[r.second];
  }

private:
  // `heap` is a max-heap on (squared distance, position) of the best candidates so far. `offset`
  // holds, per axis, how far q lies outside the current cell (0 inside) and `cell_distance` the
  // squared length of `offset`: a lower bound of the squared distance to any point of the cell
  // (incremental distance, as in Arya and Mount's ANN), so that a cell is skipped whenever it
  // cannot hold a closer point.
  void search_k(std::size_t begin, std::size_t end, int depth, const Vector_3d& q, std::size_t k,
                std::vector<std::pair<double, std::uint32_t>>& heap, Vector_3d& offset,
                double cell_distance, double max_squared_distance) const
  {
    if(!(cell_distance < max_squared_distance))
      return;
    auto offer = [&](std::uint32_t position) {
      keep_k_smallest(heap, k, std::pair<double, std::uint32_t>((m_points[position] - q).squared_length(), position));
    };
    if(end - begin <= leaf_size) {
      for(std::size_t i = begin; i < end; ++i)
        offer(m_order[i]);
      return;
    }
    const int axis = depth % 3;
    const std::size_t mid = (begin + end) / 2;
    const std::uint32_t position = m_order[mid];
    offer(position);
    const double diff = q[axis] - m_points[position][axis];
    const bool left_first = diff < 0;
    if(left_first)
      search_k(begin, mid, depth + 1, q, k, heap, offset, cell_distance, max_squared_distance);
    else
      search_k(mid + 1, end, depth + 1, q, k, heap, offset, cell_distance, max_squared_distance);
    const double old = offset[axis];
    const double far_distance = cell_distance - old * old + diff * diff;
    if(heap.size() < k || far_distance <= heap.front().first) {
      offset[axis] = diff;
      if(left_first)
        search_k(mid + 1, end, depth + 1, q, k, heap, offset, far_distance, max_squared_distance);
      else
        search_k(begin, mid, depth + 1, q, k, heap, offset, far_distance, max_squared_distance);
      offset[axis] = old;
    }
  }

  void build(std::size_t begin, std::size_t end, int depth)
  {
    if(end - begin <= leaf_size)
      return;
    const int axis = depth % 3;
    const std::size_t mid = (begin + end) / 2;
    std::nth_element(m_order.begin() + begin, m_order.begin() + mid, m_order.begin() + end,
                     [&](std::uint32_t a, std::uint32_t b) {
                       return m_points[a][axis] < m_points[b][axis];
                     });
    build(begin, mid, depth + 1);
    build(mid + 1, end, depth + 1);
  }

  // Nearest point, with the same incremental cell distance as `search_k()`.
  void search(std::size_t begin, std::size_t end, int depth, const Vector_3d& q, double& best,
              std::uint32_t& best_k, Vector_3d& offset, double cell_distance) const
  {
    if(end - begin <= leaf_size) {
      for(std::size_t i = begin; i < end; ++i) {
        const std::uint32_t k = m_order[i];
        const double d = (m_points[k] - q).squared_length();
        if(d < best || (d == best && k < best_k)) {
          best = d;
          best_k = k;
        }
      }
      return;
    }
    const int axis = depth % 3;
    const std::size_t mid = (begin + end) / 2;
    const std::uint32_t k = m_order[mid];
    const double diff = q[axis] - m_points[k][axis];
    const double d = (m_points[k] - q).squared_length();
    if(d < best || (d == best && k < best_k)) {
      best = d;
      best_k = k;
    }
    const double old = offset[axis];
    const double far_distance = cell_distance - old * old + diff * diff;
    if(diff < 0) {
      search(begin, mid, depth + 1, q, best, best_k, offset, cell_distance);
      if(far_distance <= best) {
        offset[axis] = diff;
        search(mid + 1, end, depth + 1, q, best, best_k, offset, far_distance);
        offset[axis] = old;
      }
    } else {
      search(mid + 1, end, depth + 1, q, best, best_k, offset, cell_distance);
      if(far_distance <= best) {
        offset[axis] = diff;
        search(begin, mid, depth + 1, q, best, best_k, offset, far_distance);
        offset[axis] = old;
      }
    }
  }

  static constexpr std::size_t leaf_size = 8;
  std::vector<Vector_3d> m_points;
  std::vector<std::uint32_t> m_ids;
  std::vector<std::uint32_t> m_order;
};

} // namespace internal
} // namespace Shape_analysis
} // namespace CGAL

#endif // CGAL_SHAPE_ANALYSIS_INTERNAL_POINT_TREE_H
