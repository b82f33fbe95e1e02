// Copyright (c) 2026 CGAL Global Shape Analysis contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_SHAPE_ANALYSIS_INTERNAL_SHORTEST_PATHS_H
#define CGAL_SHAPE_ANALYSIS_INTERNAL_SHORTEST_PATHS_H

// Shortest paths (Dijkstra) on the compressed rows of a Dual_graph, with a length per graph edge
// (the traversal costs, usually). Several sources at once; optionally each source carries a label
// that spreads with it (the label of a node is the label of its nearest source: a Voronoi
// partition of the graph); optionally the search stays inside the nodes of one region. The
// buffers live in the object, so that many searches on one graph allocate nothing. One object per
// thread: the graph is only read.

#include <CGAL/Shape_analysis/internal/Dual_graph.h>

#include <algorithm>
#include <cstdint>
#include <functional>
#include <limits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Shape_analysis {
namespace internal {

class Graph_shortest_paths
{
public:
  static constexpr double infinity = std::numeric_limits<double>::infinity();
  static constexpr std::uint32_t no_label = ~std::uint32_t(0);

  // Distances from the given sources (source k at distance `offsets[k]`, 0 when `offsets` is
  // empty). `length[e]` is the length of graph edge e. Only nodes `i` with `allowed(i)` are
  // entered. `labels` (when not empty, one per source) spread to every node reached: `label(i)`
  // is the label of the source nearest to i.
  template <typename Allowed>
  void run_within(const Dual_graph& g, const std::vector<double>& length,
                  const std::vector<std::uint32_t>& sources, const std::vector<std::uint32_t>& labels,
                  const std::vector<double>& offsets, const Allowed& allowed)
  {
    run_impl(g, length, sources, labels, offsets, allowed);
  }

  // The same, without a region (every node may be entered).
  void run(const Dual_graph& g, const std::vector<double>& length,
           const std::vector<std::uint32_t>& sources, const std::vector<std::uint32_t>& labels = {},
           const std::vector<double>& offsets = {})
  {
    run_impl(g, length, sources, labels, offsets, [](std::uint32_t) { return true; });
  }

  // Single source.
  void run(const Dual_graph& g, const std::vector<double>& length, std::uint32_t source)
  {
    m_sources.assign(1, source);
    run_impl(g, length, m_sources, {}, {}, [](std::uint32_t) { return true; });
  }

  double distance(std::size_t i) const { return m_distance[i]; }
  std::uint32_t label(std::size_t i) const { return m_label[i]; }
  const std::vector<double>& distances() const { return m_distance; }
  const std::vector<std::uint32_t>& labels() const { return m_label; }
  // Nodes reached, in the order they were settled (nearest first).
  const std::vector<std::uint32_t>& settled() const { return m_settled; }

private:
  template <typename Allowed>
  void run_impl(const Dual_graph& g, const std::vector<double>& length,
                const std::vector<std::uint32_t>& sources, const std::vector<std::uint32_t>& labels,
                const std::vector<double>& offsets, const Allowed& allowed)
  {
    const std::size_t n = g.number_of_nodes();
    if(m_distance.size() != n) {
      m_distance.assign(n, infinity);
      m_label.assign(n, no_label);
    } else {
      // Only the nodes reached last time need resetting.
      for(std::uint32_t i : m_touched) {
        m_distance[i] = infinity;
        m_label[i] = no_label;
      }
    }
    m_touched.clear();
    m_settled.clear();
    m_heap.clear();
    for(std::size_t k = 0; k < sources.size(); ++k) {
      const std::uint32_t s = sources[k];
      if(!allowed(s))
        continue;
      const double d = offsets.empty() ? 0.0 : offsets[k];
      if(!(d < m_distance[s]))
        continue;
      if(m_distance[s] == infinity)
        m_touched.push_back(s);
      m_distance[s] = d;
      m_label[s] = labels.empty() ? 0 : labels[k];
      push(Entry{d, s});
    }
    while(!m_heap.empty()) {
      const Entry top = pop();
      const std::uint32_t u = top.node;
      if(top.key > m_distance[u])
        continue; // a stale entry: u was reached again, closer (keys of one node all differ)
      m_settled.push_back(u);
      const double du = top.key;
      const std::uint32_t lu = m_label[u];
      for(std::size_t a = g.first_arc[u], end = g.first_arc[u + 1]; a < end; ++a) {
        const std::uint32_t v = g.arc_target[a];
        const double dv = du + length[g.arc_edge[a]];
        if(dv < m_distance[v] && allowed(v)) {
          if(m_distance[v] == infinity)
            m_touched.push_back(v);
          m_distance[v] = dv;
          m_label[v] = lu;
          push(Entry{dv, v});
        }
      }
    }
  }

  // A 4-ary min-heap of (distance, node) entries with lazy deletion: a node reached again closer
  // is pushed again, and its older entries are skipped when they come out. (Keys in the entries:
  // comparisons need no indirection, which is faster than an indexed heap with decrease-key.)
  struct Entry
  {
    double key;
    std::uint32_t node;
  };

  void push(const Entry& e)
  {
    std::size_t i = m_heap.size();
    m_heap.push_back(e);
    while(i > 0) {
      const std::size_t parent = (i - 1) / 4;
      if(!(e.key < m_heap[parent].key))
        break;
      m_heap[i] = m_heap[parent];
      i = parent;
    }
    m_heap[i] = e;
  }

  Entry pop()
  {
    const Entry top = m_heap.front();
    const Entry last = m_heap.back();
    m_heap.pop_back();
    const std::size_t size = m_heap.size();
    if(size > 0) {
      std::size_t i = 0;
      for(;;) {
        const std::size_t child = 4 * i + 1;
        if(child >= size)
          break;
        std::size_t best = child;
        const std::size_t end = (std::min)(child + 4, size);
        for(std::size_t c = child + 1; c < end; ++c)
          if(m_heap[c].key < m_heap[best].key)
            best = c;
        if(!(m_heap[best].key < last.key))
          break;
        m_heap[i] = m_heap[best];
        i = best;
      }
      m_heap[i] = last;
    }
    return top;
  }

  std::vector<double> m_distance;
  std::vector<std::uint32_t> m_label;
  std::vector<std::uint32_t> m_touched, m_settled, m_sources;
  std::vector<Entry> m_heap;
};

} // namespace internal
} // namespace Shape_analysis
} // namespace CGAL

#endif // CGAL_SHAPE_ANALYSIS_INTERNAL_SHORTEST_PATHS_H
