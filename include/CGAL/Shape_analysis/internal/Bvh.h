// Copyright (c) 2026 CGAL Global Shape Analysis contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_SHAPE_ANALYSIS_INTERNAL_BVH_H
#define CGAL_SHAPE_ANALYSIS_INTERNAL_BVH_H

// A bounding-volume hierarchy of axis-aligned boxes over indexed items (triangles, points), for
// nearest-item queries. Its tree is made once from the items' centres; when the items move, the
// boxes are refitted in linear time and the queries stay exact (only their speed depends on how
// well the tree still fits). The caller measures the items: a query visits the leaves in order of
// box distance and skips every box farther than the best distance so far.

#include <CGAL/Shape_analysis/internal/Vector_3d.h>

#include <algorithm>
#include <cstdint>
#include <limits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Shape_analysis {
namespace internal {

class Bvh
{
public:
  struct Box
  {
    double lo[3] = {std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity(),
                    std::numeric_limits<double>::infinity()};
    double hi[3] = {-std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity(),
                    -std::numeric_limits<double>::infinity()};

    void extend(const Vector_3d& p)
    {
      const double c[3] = {p.x, p.y, p.z};
      for(int a = 0; a < 3; ++a) {
        lo[a] = (std::min)(lo[a], c[a]);
        hi[a] = (std::max)(hi[a], c[a]);
      }
    }
    void extend(const Box& b)
    {
      for(int a = 0; a < 3; ++a) {
        lo[a] = (std::min)(lo[a], b.lo[a]);
        hi[a] = (std::max)(hi[a], b.hi[a]);
      }
    }
    // The squared distance from q to the box (0 inside).
    double squared_distance(const Vector_3d& q) const
    {
      const double dx = (std::max)((std::max)(lo[0] - q.x, q.x - hi[0]), 0.0);
      const double dy = (std::max)((std::max)(lo[1] - q.y, q.y - hi[1]), 0.0);
      const double dz = (std::max)((std::max)(lo[2] - q.z, q.z - hi[2]), 0.0);
      return dx * dx + dy * dy + dz * dz;
    }
  };

  Bvh() = default;

  // The tree over items 0..n-1 (n = centers.size()), split at the median centre along the longest
  // side of the centres' box; `box_of(i)` gives item i's box.
  template <typename BoxOf>
  Bvh(const std::vector<Vector_3d>& centers, const BoxOf& box_of)
  {
    const std::size_t n = centers.size();
    if(n == 0)
      return;
    // The centres with their items, side by side in memory: the splits move them.
    std::vector<Entry> entries(n);
    for(std::size_t i = 0; i < n; ++i)
      entries[i] = Entry{{centers[i].x, centers[i].y, centers[i].z}, std::uint32_t(i)};
    m_nodes.reserve(2 * (n / leaf_size + 1));
    build(entries, 0, n);
    m_items.resize(n);
    for(std::size_t i = 0; i < n; ++i)
      m_items[i] = entries[i].item;
    refit(box_of);
  }

  bool empty() const { return m_nodes.empty(); }

  // Recomputes every box from `box_of(i)`, i an item (the items moved; the tree is kept).
  template <typename BoxOf>
  void refit(const BoxOf& box_of)
  {
    // Children come after their parent: a backward pass sees them first.
    for(std::size_t k = m_nodes.size(); k-- > 0;) {
      Node& node = m_nodes[k];
      Box b;
      if(node.count > 0) {
        for(std::uint32_t j = node.first; j < node.first + node.count; ++j)
          b.extend(box_of(m_items[j]));
      } else {
        b = m_nodes[k + 1].box;
        b.extend(m_nodes[node.first].box);
      }
      node.box = b;
    }
  }

  // The items in the order of the leaves: item `item(j)` is at position j. Positions of the
  // same leaf are consecutive, so data stored by position is read in order.
  std::uint32_t item(std::size_t j) const { return m_items[j]; }
  std::size_t size() const { return m_items.size(); }

  // Visits the items that may lie closer to q than sqrt(best): `visit(j, best)`, j the position
  // of the item (see `item()`), measures the item and lowers `best` when it is closer. Nearer boxes first; boxes farther than `best` are
  // skipped. Returns the final `best`.
  template <typename Visit>
  double nearest(const Vector_3d& q, double best, Visit&& visit) const
  {
    if(m_nodes.empty())
      return best;
    std::pair<double, std::uint32_t> stack[128];
    std::size_t top = 0;
    stack[top++] = {m_nodes[0].box.squared_distance(q), 0u};
    while(top > 0) {
      const std::pair<double, std::uint32_t> s = stack[--top];
      if(s.first > best)
        continue;
      const Node& node = m_nodes[s.second];
      if(node.count > 0) {
        for(std::uint32_t j = node.first; j < node.first + node.count; ++j)
          visit(j, best);
        continue;
      }
      const std::uint32_t a = s.second + 1, b = node.first;
      const double da = m_nodes[a].box.squared_distance(q), db = m_nodes[b].box.squared_distance(q);
      // The nearer child is popped first.
      if(da <= db) {
        if(db <= best)
          stack[top++] = {db, b};
        if(da <= best)
          stack[top++] = {da, a};
      } else {
        if(da <= best)
          stack[top++] = {da, a};
        if(db <= best)
          stack[top++] = {db, b};
      }
    }
    return best;
  }

private:
  static constexpr std::size_t leaf_size = 4;

  // A leaf holds m_items[first, first + count); an inner node (count 0) has its first child
  // right after it and its second child at `first`.
  struct Node
  {
    Box box;
    std::uint32_t first = 0;
    std::uint32_t count = 0;
  };

  struct Entry
  {
    double center[3];
    std::uint32_t item;
  };

  void build(std::vector<Entry>& entries, std::size_t begin, std::size_t end)
  {
    const std::size_t k = m_nodes.size();
    m_nodes.emplace_back();
    if(end - begin <= leaf_size) {
      m_nodes[k].first = std::uint32_t(begin);
      m_nodes[k].count = std::uint32_t(end - begin);
      return;
    }
    double lo[3] = {entries[begin].center[0], entries[begin].center[1], entries[begin].center[2]};
    double hi[3] = {lo[0], lo[1], lo[2]};
    for(std::size_t i = begin + 1; i < end; ++i)
      for(int a = 0; a < 3; ++a) {
        lo[a] = (std::min)(lo[a], entries[i].center[a]);
        hi[a] = (std::max)(hi[a], entries[i].center[a]);
      }
    const double ex = hi[0] - lo[0], ey = hi[1] - lo[1], ez = hi[2] - lo[2];
    const int axis = ex >= ey ? (ex >= ez ? 0 : 2) : (ey >= ez ? 1 : 2);
    const std::size_t mid = begin + (end - begin) / 2;
    std::nth_element(entries.begin() + std::ptrdiff_t(begin), entries.begin() + std::ptrdiff_t(mid),
                     entries.begin() + std::ptrdiff_t(end), [axis](const Entry& x, const Entry& y) {
                       return x.center[axis] < y.center[axis] || (x.center[axis] == y.center[axis] && x.item < y.item);
                     });
    build(entries, begin, mid);
    m_nodes[k].first = std::uint32_t(m_nodes.size());
    build(entries, mid, end);
  }

  std::vector<Node> m_nodes;
  std::vector<std::uint32_t> m_items;
};

} // namespace internal
} // namespace Shape_analysis
} // namespace CGAL

#endif // CGAL_SHAPE_ANALYSIS_INTERNAL_BVH_H
