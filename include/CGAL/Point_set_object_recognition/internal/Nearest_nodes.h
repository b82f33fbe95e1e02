// Copyright (c) 2026 CGAL Global Shape Analysis contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_POINT_SET_OBJECT_RECOGNITION_INTERNAL_NEAREST_NODES_H
#define CGAL_POINT_SET_OBJECT_RECOGNITION_INTERNAL_NEAREST_NODES_H

// The k nearest nodes of every node of the segmentation graph (Segmentation_graph.h), by their
// centroids: with cells, among the nodes of the cells around (Cell_stack_neighbors); without, in
// a kd-tree (nearest_in_tree). The cells are kept over CGAL's kd-tree for speed: 0.34 of its
// time on a street's nodes (bench/spatial_indexes.cpp, cell_stack_knn_street), and by design they
// link no node farther than three cells.

#include <CGAL/Point_set_object_recognition/internal/Column_index.h>
#include <CGAL/Shape_analysis/internal/Parallel.h>
#include <CGAL/Shape_analysis/internal/Point_tree.h>
#include <CGAL/Shape_analysis/internal/Vector_3d.h>

#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <utility>
#include <vector>

namespace CGAL {
namespace Point_set_object_recognition {
namespace internal {

namespace SAI = CGAL::Shape_analysis::internal;
typedef std::vector<std::pair<double, std::uint32_t>> Node_candidates; // squared distance, node

// The k nearest (by distance, then index) among the pairs r, in order, into `row` (the m smallest
// pairs whatever the order of r: the candidates are distinct).
inline void keep_nearest(Node_candidates& r, std::size_t k, std::uint32_t* row)
{
  const std::size_t m = (std::min)(k, r.size());
  std::size_t kept = 0;
  for(std::size_t j = 0; j < r.size(); ++j) {
    const std::pair<double, std::uint32_t> x = r[j];
    if(kept == m && !(x < r[m - 1]))
      continue;
    std::size_t f = kept < m ? kept++ : m - 1;
    for(; f > 0 && x < r[f - 1]; --f)
      r[f] = r[f - 1];
    r[f] = x;
  }
  for(std::size_t j = 0; j < m; ++j)
    row[j] = r[j].second;
}

// With cells: the nearest are looked for among the nodes of the 3 x 3 x 3 cells around, then of
// larger blocks while they hold fewer than k others (up to 7 x 7 x 7: a node farther than three
// cells is no neighbour); the nodes by vertical stacks of cells, by increasing height.
class Cell_stack_neighbors
{
public:
  // `c`: the centroids of the nodes; `cell_key`: the voxel keys of their cells; `nodes`: the
  // nodes to connect (those off walls).
  Cell_stack_neighbors(const std::vector<SAI::Vector_3d>& c, const std::vector<std::uint64_t>& cell_key,
                       const std::vector<std::uint32_t>& nodes)
  {
    m_stacks.assign(nodes, [&](std::uint32_t v) {
      return Column_index::key(long(cell_key[v] & 0x1FFFFF), long((cell_key[v] >> 21) & 0x1FFFFF));
    });
    for(std::size_t s = 0; s < m_stacks.size(); ++s)
      std::sort(m_stacks.items.begin() + long(m_stacks.first[s]), m_stacks.items.begin() + long(m_stacks.first[s + 1]),
                [&](std::uint32_t a, std::uint32_t b) { return cell_key[a] < cell_key[b]; });
    m_entries.reserve(m_stacks.items.size());
    for(std::uint32_t u : m_stacks.items)
      m_entries.push_back(Entry{c[u], std::uint32_t(cell_key[u] >> 42), u});
  }

  // Per node, its k nearest into its row of `knn` (k per node).
  void find(std::size_t k, std::size_t threads, std::vector<std::uint32_t>& knn) const
  {
    SAI::Parallel_workspaces<Node_candidates> parallel(threads);
    const std::size_t block = 32;
    parallel.for_each(0, (m_stacks.size() + block - 1) / block, [&](std::size_t b, Node_candidates& r) {
      for(std::size_t s = b * block; s < (std::min)(m_stacks.size(), (b + 1) * block); ++s)
        stack_nearest(s, k, r, knn);
    });
  }

private:
  static constexpr int maximum_reach = 3;
  static constexpr std::size_t ring_size = 8 * maximum_reach; // the most stacks in a ring
  struct Entry
  {
    SAI::Vector_3d c;
    std::uint32_t k, v;
  };
  struct Ring_stack { const Entry *cursor, *begin, *end; };

  // The stacks around one stack by rings (ring 0: the stack itself; ring d: the stacks d columns
  // away), found once per stack, each with a cursor on its first node not below the cube where
  // the ring entered (the cubes rise with the nodes).
  struct Rings
  {
    Rings(const Cell_stack_neighbors& o, long i, long j) : owner(o), ci(i), cj(j) {}

    const Cell_stack_neighbors& owner;
    long ci, cj;
    bool known[maximum_reach + 1] = {};
    std::size_t size[maximum_reach + 1] = {};
    Ring_stack ring[maximum_reach + 1][ring_size];

    // The nodes of ring d within the cube of half side `reach` around height ck (as the ring
    // enters).
    template <typename Take> void enter(long d, long reach, long ck, const Take& take)
    {
      if(!known[d]) {
        std::size_t a = 0;
        for(long dj = -d; dj <= d; ++dj)
          for(long di = -d; di <= d; ++di) {
            if((std::max)(std::abs(di), std::abs(dj)) != d || ci + di < 0 || cj + dj < 0)
              continue;
            const std::uint32_t t = owner.m_stacks.find(Column_index::key(ci + di, cj + dj));
            if(t != Key_map::none)
              ring[d][a++] = Ring_stack{owner.stack_begin(t), owner.stack_begin(t), owner.stack_begin(t + 1)};
          }
        size[d] = a, known[d] = true;
      }
      const std::uint32_t k0 = std::uint32_t((std::max)(0L, ck - reach)), k1 = std::uint32_t(ck + reach);
      for(std::size_t a = 0; a < size[d]; ++a) {
        Ring_stack& t = ring[d][a];
        const Entry* e = t.cursor;
        while(e != t.end && e->k < k0)
          ++e;
        t.cursor = e;
        for(; e != t.end && e->k <= k1; ++e)
          take(e);
      }
    }

    // The nodes of ring d at heights ck +- reach (the ring entered at a smaller reach).
    template <typename Take> void extend(long d, long reach, long ck, const Take& take) const
    {
      const long below = ck - reach, above = ck + reach;
      for(std::size_t a = 0; a < size[d]; ++a) {
        const Ring_stack& t = ring[d][a];
        for(const Entry* e = t.cursor; e != t.begin && long((e - 1)->k) >= below;) {
          --e;
          if(long(e->k) == below)
            take(e);
        }
        for(const Entry* e = t.cursor; e != t.end && long(e->k) <= above; ++e)
          if(long(e->k) == above)
            take(e);
      }
    }
  };

  const Entry* stack_begin(std::uint32_t t) const { return m_entries.data() + m_stacks.first[t]; }

  // The nodes of stack s by increasing height. The cube of half side `reach` is that of
  // reach - 1 and the nodes of its new layers (heights ck +- reach) in the rings already in,
  // and those of the new ring.
  void stack_nearest(std::size_t s, std::size_t k, Node_candidates& r, std::vector<std::uint32_t>& knn) const
  {
    Rings rings(*this, long(m_stacks.keys[s] & 0xFFFFFFFFu), long(m_stacks.keys[s] >> 32));
    for(const Entry* node = stack_begin(std::uint32_t(s)); node != stack_begin(std::uint32_t(s + 1)); ++node) {
      const std::uint32_t v = node->v;
      const long ck = long(node->k);
      const SAI::Vector_3d cv = node->c;
      const auto take = [&](const Entry* e) {
        if(e->v != v)
          r.emplace_back((e->c - cv).squared_length(), e->v);
      };
      // The 3 x 3 x 3 cells, else the smallest block (up to 7 x 7 x 7) holding k others.
      r.clear();
      rings.enter(0, 1, ck, take), rings.enter(1, 1, ck, take);
      for(long reach = 2; reach <= maximum_reach && r.size() < k; ++reach) {
        for(long d = 0; d < reach; ++d)
          rings.extend(d, reach, ck, take);
        rings.enter(reach, reach, ck, take);
      }
      keep_nearest(r, k, knn.data() + std::size_t(v) * k);
    }
  }

  Key_lists m_stacks;           // the nodes by their cells' columns (i, j), by increasing height
  std::vector<Entry> m_entries; // the nodes of `m_stacks.items`, with their centroids and heights
};

// Without cells: per node v that is not a wall (is_wall(v)), its k nearest nodes on the same side
// (walls or not) among its k + 1 nearest in a kd-tree of the centroids `c`, into its row of
// `knn` (k per node).
template <typename IsWall>
void nearest_in_tree(const std::vector<SAI::Vector_3d>& c, const IsWall& is_wall, std::size_t k,
                     std::size_t threads, std::vector<std::uint32_t>& knn)
{
  const std::size_t n = c.size();
  std::vector<std::uint32_t> ids(n);
  for(std::size_t v = 0; v < n; ++v)
    ids[v] = std::uint32_t(v);
  const SAI::Point_tree tree(c, ids);
  SAI::Parallel_workspaces<Node_candidates> parallel(threads);
  const std::size_t block = 256;
  parallel.for_each(0, (n + block - 1) / block, [&](std::size_t b, Node_candidates& r) {
    for(std::size_t v = b * block; v < (std::min)(n, (b + 1) * block); ++v) {
      if(is_wall(v))
        continue; // walls have no edges
      tree.k_nearest(c[v], k + 1, r);
      std::size_t m = 0;
      for(const auto& q : r)
        if(q.second != v && m < k && is_wall(q.second) == is_wall(v))
          knn[v * k + m++] = q.second;
    }
  });
}

} // namespace internal
} // namespace Point_set_object_recognition
} // namespace CGAL

#endif // CGAL_POINT_SET_OBJECT_RECOGNITION_INTERNAL_NEAREST_NODES_H
