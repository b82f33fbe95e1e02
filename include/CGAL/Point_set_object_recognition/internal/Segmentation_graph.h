// Copyright (c) 2026 CGAL Global Shape Analysis contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_POINT_SET_OBJECT_RECOGNITION_INTERNAL_SEGMENTATION_GRAPH_H
#define CGAL_POINT_SET_OBJECT_RECOGNITION_INTERNAL_SEGMENTATION_GRAPH_H

// The graph index of the segmentation of objects, over the points near a set of locations
// (nodes: cells of a grid, or the points themselves, weighted by their point counts; edges: the
// k nearest nodes with Gaussian weights on their length), built once and shared by all objects.

#include <CGAL/Point_set_object_recognition/internal/Column_index.h>
#include <CGAL/Point_set_object_recognition/internal/Nearest_nodes.h>
#include <CGAL/Point_set_object_recognition/internal/Point_columns.h>
#include <CGAL/Point_set_object_recognition/internal/Segmentation_options.h>
#include <CGAL/Point_set_object_recognition/internal/Voxel_grid.h>
#include <CGAL/Point_set_object_recognition/internal/Wall_detection.h>
#include <CGAL/Shape_analysis/internal/Vector_3d.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Point_set_object_recognition {
namespace internal {

// The graph nodes of the points near a set of locations: those of the columns of `columns` that
// come within `reach` of a location (horizontally).
class Segmentation_index
{
public:
  static constexpr std::uint32_t none = std::numeric_limits<std::uint32_t>::max();

  // `with_wall_nodes`: whether walls have graph nodes (the interactive segmenter's constraints).
  Segmentation_index(const Point_columns& columns, const std::vector<P3>& locations, double reach,
                     const Segmentation_options& o, bool with_graph, bool with_wall_nodes = false)
    : m_p(columns.points()), m_o(o), m_wall_nodes(with_wall_nodes), m_pc(columns)
  {
    m_lo = columns.lo(), m_side = columns.side();
    if(!with_graph)
      return;
    // The columns within `reach` of a location, and their points.
    std::vector<char> near_column(columns.lists().size(), 0);
    for(const P3& l : locations)
      columns.lists().for_square_lists(m_lo, m_side, l, reach, [&](long i, long j, std::uint32_t c) {
        const double x0 = m_lo[0] + double(i) * m_side, y0 = m_lo[1] + double(j) * m_side;
        const double dx = (std::max)(0.0, (std::max)(x0 - l[0], l[0] - x0 - m_side));
        const double dy = (std::max)(0.0, (std::max)(y0 - l[1], l[1] - y0 - m_side));
        if(dx * dx + dy * dy <= reach * reach)
          near_column[c] = 1;
      });
    // (By runs of points of one column: consecutive points mostly share it.)
    std::vector<std::uint32_t> near;
    near.reserve(m_p.size());
    for(std::size_t i = 0; i < m_p.size();) {
      const std::uint32_t c = columns.column_of_point(i);
      std::size_t j = i + 1;
      while(j < m_p.size() && columns.column_of_point(j) == c)
        ++j;
      if(near_column[c])
        for(; i < j; ++i)
          near.push_back(std::uint32_t(i));
      i = j;
    }
    build_graph(std::move(near));
  }

  const std::vector<P3>& points() const { return m_p; }

  // The points within `radius` of (x, y) horizontally, increasing.
  void points_within(const P3& at, double radius, std::vector<std::uint32_t>& out) const
  {
    m_pc.points_within(at, radius, out);
  }

  // The points off walls within `radius` of (x, y) horizontally, in no particular order.
  void points_off_walls_within(const P3& at, double radius, std::vector<std::uint32_t>& out) const
  {
    m_pc.points_within(at, radius, out, [&](std::uint32_t i) { return !is_wall(i); });
  }

  // The graph nodes whose centroids lie within `radius` of (x, y) horizontally, increasing; the
  // nodes of walls only `with_walls` (they have no edges: they never join an object).
  void nodes_within(const P3& at, double radius, std::vector<std::uint32_t>& out, bool with_walls = false) const
  {
    out.clear();
    const auto add = [&](std::uint32_t v) {
      if(horizontally_within(m_centroid[v], at, radius))
        out.push_back(v);
    };
    for_columns(at, radius, add, m_node_columns);
    if(with_walls)
      for_columns(at, radius, add, m_wall_node_columns);
    std::sort(out.begin(), out.end());
  }

  std::size_t number_of_nodes() const { return m_count.size(); }
  const P3& centroid(std::size_t v) const { return m_centroid[v]; }
  double count(std::size_t v) const { return m_count[v]; }
  std::uint32_t node_of_point(std::size_t i) const { return m_node_of_point[i]; }
  // Whether point i was found on a wall (only with the graph).
  bool is_wall(std::size_t i) const { return !m_wall.empty() && m_wall[i] != 0; }
  template <typename F> void for_members(std::size_t v, const F& f) const
  {
    for(std::size_t k = m_member_first[v]; k < m_member_first[v + 1]; ++k)
      f(m_members[k]);
  }
  template <typename F> void for_adjacent(std::size_t v, const F& f) const
  {
    for(std::size_t k = m_adjacent_first[v]; k < m_adjacent_first[v + 1]; ++k)
      f(m_adjacent[k], m_adjacent_weight[k]);
  }

private:
  std::uint64_t column_of(double x, double y) const
  {
    return Column_index::key(long((x - m_lo[0]) / m_side), long((y - m_lo[1]) / m_side));
  }
  // Calls f on the items of the columns of `lists` that meet the square of half side `radius`
  // around `at`.
  template <typename F>
  void for_columns(const P3& at, double radius, const F& f, const Key_lists& lists) const
  {
    lists.for_square(m_lo, m_side, at, radius, f);
  }


  // The graph of the points `active` (increasing).
  void build_graph(std::vector<std::uint32_t> active)
  {
    Wall_finder(m_pc).find(active, !m_wall_nodes, m_wall); // without wall nodes, the walls never join an object
    const std::vector<std::uint32_t> first_of_node = make_nodes(active);
    const std::size_t n = first_of_node.size();
    gather_members(active, n);
    std::vector<std::uint32_t> other_nodes; // off walls
    place_nodes(first_of_node, other_nodes);
    // Edges: the k nearest nodes of every node, symmetrized, with weights
    // exp(-(d / sigma)^2) times the smaller point count of their two nodes.
    std::vector<SAI::Vector_3d> c(n);
    for(std::size_t v = 0; v < n; ++v)
      c[v] = SAI::Vector_3d(m_centroid[v][0], m_centroid[v][1], m_centroid[v][2]);
    const std::size_t k = m_o.number_of_neighbors;
    std::vector<std::uint32_t> knn(n * k, none);
    if(m_o.graph_cell_size > 0) {
      std::vector<std::uint64_t> cell_key(n, 0);
      for(std::size_t v = 0; v < n; ++v) {
        const P3& q = m_p[first_of_node[v]];
        cell_key[v] = voxel_key(q[0], q[1], q[2], m_o.graph_cell_size, m_lo);
      }
      Cell_stack_neighbors(c, cell_key, other_nodes).find(k, m_o.number_of_threads, knn);
    } else
      nearest_in_tree(c, [&](std::size_t v) { return m_wall[first_of_node[v]]; }, k, m_o.number_of_threads, knn);
    make_edges(c, knn);
  }

  // Nodes: the cells of side `cell` (or the points), numbered by their first point; per node its
  // first point.
  std::vector<std::uint32_t> make_nodes(const std::vector<std::uint32_t>& active)
  {
    m_node_of_point.assign(m_p.size(), none);
    std::vector<std::uint32_t> first_of_node;
    if(m_o.graph_cell_size > 0) {
      Key_map cell(active.size() / 4 + 16); // key -> node
      std::uint64_t last_key = 0;
      std::uint32_t last_node = none; // of the previous point (consecutive points often share it)
      for(std::uint32_t i : active) {
        const std::uint64_t key = voxel_key(m_p[i][0], m_p[i][1], m_p[i][2], m_o.graph_cell_size, m_lo) | wall_bit(i);
        if(last_node == none || key != last_key) {
          const auto ins = cell.emplace(key, std::uint32_t(first_of_node.size()));
          if(ins.second)
            first_of_node.push_back(i);
          last_key = key, last_node = ins.first;
        }
        m_node_of_point[i] = last_node;
      }
    } else
      for(std::uint32_t i : active) {
        m_node_of_point[i] = std::uint32_t(first_of_node.size());
        first_of_node.push_back(i);
      }
    return first_of_node;
  }

  // Per node of the n, its points (those of `active`, in order).
  void gather_members(const std::vector<std::uint32_t>& active, std::size_t n)
  {
    m_member_first.assign(n + 1, 0);
    for(std::uint32_t i : active)
      ++m_member_first[m_node_of_point[i] + 1];
    for(std::size_t v = 0; v < n; ++v)
      m_member_first[v + 1] += m_member_first[v];
    m_members.assign(active.size(), 0);
    std::vector<std::size_t> fill(m_member_first.begin(), m_member_first.end() - 1);
    for(std::uint32_t i : active)
      m_members[fill[m_node_of_point[i]]++] = i;
  }

  // Per node, its centroid and point count; the nodes of walls and the others (`other_nodes`,
  // increasing) by the columns of their centroids.
  void place_nodes(const std::vector<std::uint32_t>& first_of_node, std::vector<std::uint32_t>& other_nodes)
  {
    const std::size_t n = first_of_node.size();
    m_centroid.assign(n, P3{{0, 0, 0}});
    m_count.assign(n, 0);
    std::vector<std::uint32_t> wall_nodes;
    for(std::size_t v = 0; v < n; ++v) {
      P3 c{{0, 0, 0}};
      for_members(v, [&](std::uint32_t i) {
        for(int a = 0; a < 3; ++a)
          c[a] += m_p[i][a];
      });
      const double k = double(m_member_first[v + 1] - m_member_first[v]);
      m_centroid[v] = {c[0] / k, c[1] / k, c[2] / k};
      m_count[v] = k;
      (m_wall[first_of_node[v]] ? wall_nodes : other_nodes).push_back(std::uint32_t(v));
    }
    const auto centroid_column = [&](std::uint32_t v) { return column_of(m_centroid[v][0], m_centroid[v][1]); };
    m_node_columns.assign(other_nodes, centroid_column);
    m_wall_node_columns.assign(wall_nodes, centroid_column);
  }

  // The adjacency of the nodes from their k nearest (`knn`, k per node; `c` their centroids),
  // per node by increasing index.
  void make_edges(const std::vector<SAI::Vector_3d>& c, const std::vector<std::uint32_t>& knn)
  {
    const std::size_t n = c.size(), k = m_o.number_of_neighbors;
    // The edges, each once: from its first node unless the other holds it too and is smaller.
    std::vector<char> emit(n * k, 0);
    m_adjacent_first.assign(n + 1, 0);
    for(std::size_t v = 0; v < n; ++v) {
      std::size_t degree = 0;
      for(std::size_t m = 0; m < k; ++m) {
        const std::uint32_t u = knn[v * k + m];
        if(u == none)
          break;
        bool twice = false;
        if(u < v) {
          const std::uint32_t* row = knn.data() + u * k; // `none` never matches: a full scan
          for(std::size_t j = 0; j < k; ++j)
            twice |= row[j] == v;
        }
        const char once = twice ? 0 : 1; // (no branch)
        emit[v * k + m] = once, degree += std::size_t(once), m_adjacent_first[u + 1] += std::size_t(once);
      }
      m_adjacent_first[v + 1] += degree;
    }
    for(std::size_t v = 0; v < n; ++v)
      m_adjacent_first[v + 1] += m_adjacent_first[v];
    m_adjacent.assign(m_adjacent_first[n], 0);
    m_adjacent_weight.assign(m_adjacent_first[n], 0);
    std::vector<std::size_t> fill(m_adjacent_first.begin(), m_adjacent_first.end() - 1);
    const double sigma = edge_sigma(m_o), s2 = sigma * sigma;
    for(std::size_t v = 0; v < n; ++v)
      for(std::size_t m = 0; m < k; ++m) {
        if(!emit[v * k + m])
          continue;
        const std::uint32_t u = knn[v * k + m];
        const std::uint32_t a = (std::min)(std::uint32_t(v), u), b = (std::max)(std::uint32_t(v), u);
        const double d2 = (c[a] - c[b]).squared_length();
        const double w = std::exp(-d2 / s2) * (std::min)(m_count[a], m_count[b]);
        m_adjacent[fill[a]] = b, m_adjacent_weight[fill[a]++] = w;
        m_adjacent[fill[b]] = a, m_adjacent_weight[fill[b]++] = w;
      }
    sort_adjacency(n);
  }

  // Per node, its neighbours by increasing index (an insertion sort: the lists are short).
  void sort_adjacency(std::size_t n)
  {
    for(std::size_t v = 0; v < n; ++v)
      for(std::size_t e = m_adjacent_first[v] + 1; e < m_adjacent_first[v + 1]; ++e) {
        const std::uint32_t a = m_adjacent[e];
        const double w = m_adjacent_weight[e];
        std::size_t f = e;
        for(; f > m_adjacent_first[v] && m_adjacent[f - 1] > a; --f)
          m_adjacent[f] = m_adjacent[f - 1], m_adjacent_weight[f] = m_adjacent_weight[f - 1];
        m_adjacent[f] = a, m_adjacent_weight[f] = w;
      }
  }

  // Wall points have their own cells: a high bit of the key that voxel keys never use.
  std::uint64_t wall_bit(std::uint32_t i) const { return m_wall[i] ? (std::uint64_t(1) << 63) : 0; }

  const std::vector<P3>& m_p;
  const Segmentation_options& m_o;
  const bool m_wall_nodes;
  std::vector<char> m_wall;
  double m_side = 1.0;
  P3 m_lo{{0, 0, 0}};
  const Point_columns& m_pc;
  Key_lists m_node_columns, m_wall_node_columns;
  std::vector<std::uint32_t> m_node_of_point, m_members, m_adjacent;
  std::vector<std::size_t> m_member_first, m_adjacent_first;
  std::vector<P3> m_centroid;
  std::vector<double> m_count, m_adjacent_weight;
};

} // namespace internal
} // namespace Point_set_object_recognition
} // namespace CGAL

#endif // CGAL_POINT_SET_OBJECT_RECOGNITION_INTERNAL_SEGMENTATION_GRAPH_H
