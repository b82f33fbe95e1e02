// Copyright (c) 2026 CGAL Global Shape Analysis contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_SHAPE_ANALYSIS_INTERNAL_NEAREST_SAMPLE_TREE_H
#define CGAL_SHAPE_ANALYSIS_INTERNAL_NEAREST_SAMPLE_TREE_H

// The nearest of a few thousand surface samples, asked millions of times by the ICP of
// Similarity_alignment.h (Closest_sample): a median-split kd-tree over the samples' positions,
// nearest-point queries only, no allocation per query, ties to the sample given first. Measured
// (bench/spatial_indexes.cpp, nearest_sample_tree_icp): 0.90 of the time of CGAL's kd-tree with
// k = 1; through Point_tree.h (CGAL's tree behind ids and exact ties) the co-segmentation
// benchmark took 1.31 s instead of 1.05 s (bench/consistent_segmentation.cpp, chairs16).

#include <CGAL/Shape_analysis/internal/Vector_3d.h>

#include <algorithm>
#include <cstdint>
#include <limits>
#include <vector>

namespace CGAL {
namespace Shape_analysis {
namespace internal {

class Nearest_sample_tree
{
public:
  Nearest_sample_tree() = default;

  explicit Nearest_sample_tree(const std::vector<Vector_3d>& points)
    : m_points(points)
  {
    m_order.resize(points.size());
    for(std::size_t i = 0; i < points.size(); ++i)
      m_order[i] = static_cast<std::uint32_t>(i);
    if(!points.empty())
      build(0, points.size(), 0);
  }

  bool empty() const { return m_points.empty(); }

  // The index of the nearest point to `q` (the first given among equally near ones); the tree
  // must not be empty.
  std::uint32_t nearest(const Vector_3d& q) const
  {
    double best = std::numeric_limits<double>::infinity();
    std::uint32_t best_k = (std::numeric_limits<std::uint32_t>::max)();
    Vector_3d offset(0.0);
    search(0, m_points.size(), 0, q, best, best_k, offset, 0.0);
    return best_k;
  }

private:
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

  // `offset` holds, per axis, how far q lies outside the current cell (0 inside) and
  // `cell_distance` the squared length of `offset`: a lower bound of the squared distance to any
  // point of the cell, so that a cell is skipped whenever it cannot hold a closer point.
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
  std::vector<std::uint32_t> m_order;
};

} // namespace internal
} // namespace Shape_analysis
} // namespace CGAL

#endif // CGAL_SHAPE_ANALYSIS_INTERNAL_NEAREST_SAMPLE_TREE_H
