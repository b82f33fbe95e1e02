// Copyright (c) 2026 CGAL Global Shape Analysis contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_SHAPE_ANALYSIS_INTERNAL_MIN_CUT_H
#define CGAL_SHAPE_ANALYSIS_INTERNAL_MIN_CUT_H

// s-t minimum cut with terminal (unary) capacities and hard constraints, on Boost's
// Boykov-Kolmogorov max-flow. The graph topology is built once (`add_edge` ... `finalize`);
// capacities can then be changed and the cut solved again many times without reallocating the
// graph or its property arrays (randomized min-cuts solve hundreds of cuts on one dual graph).

#include <CGAL/Shape_analysis/Bad_input.h>
#include <CGAL/Shape_analysis/internal/Dual_graph.h>
#include <CGAL/Shape_analysis/internal/Max_flow.h>

#include <boost/graph/boykov_kolmogorov_max_flow.hpp>
#include <boost/graph/compressed_sparse_row_graph.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numeric>
#include <utility>
#include <vector>

namespace CGAL {
namespace Shape_analysis {
namespace internal {

class Min_cut_solver
{
  typedef boost::compressed_sparse_row_graph<boost::directedS> Graph;
  typedef boost::graph_traits<Graph>::edge_descriptor Arc;
  typedef boost::graph_traits<Graph>::vertex_descriptor Vertex;

public:
  enum Constraint : char { FREE = 0, SOURCE = 1, SINK = 2 };

  explicit Min_cut_solver(std::size_t number_of_nodes = 0) { reset(number_of_nodes); }

  // Forgets everything; the graph will have `number_of_nodes` nodes plus the two terminals.
  void reset(std::size_t number_of_nodes)
  {
    m_n = number_of_nodes;
    m_pairs.clear();
    m_finalized = false;
    m_pair_capacity.clear();
    m_to_source.assign(m_n, 0.0);
    m_to_sink.assign(m_n, 0.0);
    m_constraint.assign(m_n, FREE);
  }

  std::size_t number_of_nodes() const { return m_n; }

  // Declares an undirected pair u-v (before finalize()); returns its id.
  std::size_t add_edge(std::size_t u, std::size_t v)
  {
    m_pairs.emplace_back(static_cast<std::uint32_t>(u), static_cast<std::uint32_t>(v));
    m_pair_capacity.emplace_back(0.0, 0.0);
    return m_pairs.size() - 1;
  }

  // Builds the graph: every pair gives two opposite arcs, every node an arc from the source and
  // an arc to the sink (each with its zero-capacity reverse).
  void finalize()
  {
    const std::uint32_t s = static_cast<std::uint32_t>(m_n), t = s + 1;
    struct Directed { std::uint32_t from, to; std::size_t slot; };
    std::vector<Directed> arcs;
    arcs.reserve(2 * m_pairs.size() + 4 * m_n);
    // slots: 2p, 2p+1 for pair p (u->v, v->u); then for node i: base + 4i .. base + 4i + 3 for
    // s->i, i->s, i->t, t->i.
    for(std::size_t p = 0; p < m_pairs.size(); ++p) {
      arcs.push_back({m_pairs[p].first, m_pairs[p].second, 2 * p});
      arcs.push_back({m_pairs[p].second, m_pairs[p].first, 2 * p + 1});
    }
    const std::size_t base = 2 * m_pairs.size();
    for(std::uint32_t i = 0; i < m_n; ++i) {
      arcs.push_back({s, i, base + 4 * std::size_t(i)});
      arcs.push_back({i, s, base + 4 * std::size_t(i) + 1});
      arcs.push_back({i, t, base + 4 * std::size_t(i) + 2});
      arcs.push_back({t, i, base + 4 * std::size_t(i) + 3});
    }
    std::stable_sort(arcs.begin(), arcs.end(),
                     [](const Directed& a, const Directed& b) { return a.from < b.from; });
    std::vector<std::pair<std::uint32_t, std::uint32_t>> sorted(arcs.size());
    m_slot_to_arc.assign(arcs.size(), 0);
    for(std::size_t k = 0; k < arcs.size(); ++k) {
      sorted[k] = {arcs[k].from, arcs[k].to};
      m_slot_to_arc[arcs[k].slot] = k;
    }
    m_graph = Graph(boost::edges_are_sorted, sorted.begin(), sorted.end(), m_n + 2);
    m_arcs.assign(arcs.size(), Arc());
    auto edge_range = boost::edges(m_graph);
    for(auto it = edge_range.first; it != edge_range.second; ++it)
      m_arcs[get(boost::edge_index, m_graph, *it)] = *it;
    m_reverse.assign(arcs.size(), Arc());
    auto pair_arcs = [&](std::size_t slot_a, std::size_t slot_b) {
      const std::size_t a = m_slot_to_arc[slot_a], b = m_slot_to_arc[slot_b];
      m_reverse[a] = m_arcs[b];
      m_reverse[b] = m_arcs[a];
    };
    for(std::size_t p = 0; p < m_pairs.size(); ++p)
      pair_arcs(2 * p, 2 * p + 1);
    for(std::size_t i = 0; i < m_n; ++i) {
      pair_arcs(base + 4 * i, base + 4 * i + 1);
      pair_arcs(base + 4 * i + 2, base + 4 * i + 3);
    }
    m_capacity.assign(arcs.size(), 0.0);
    m_residual.assign(arcs.size(), 0.0);
    m_color.assign(m_n + 2, boost::white_color);
    m_predecessor.assign(m_n + 2, Arc());
    m_distance.assign(m_n + 2, 0);
    m_finalized = true;
  }

  // Capacity of the pair's arcs u->v and v->u (non-negative, finite).
  void set_edge_capacity(std::size_t pair, double cap_uv, double cap_vu)
  {
    m_pair_capacity[pair] = {cap_uv, cap_vu};
  }

  // Terminal capacities of node u: cost of putting u on the sink side (`to_source`, the source->u
  // arc) and on the source side (`to_sink`, the u->sink arc).
  void set_terminal_capacity(std::size_t u, double to_source, double to_sink)
  {
    m_to_source[u] = to_source;
    m_to_sink[u] = to_sink;
  }

  // Hard constraint: node u must be on the given side (FREE removes the constraint).
  void constrain(std::size_t u, Constraint c) { m_constraint[u] = c; }

  void clear_terminals()
  {
    std::fill(m_to_source.begin(), m_to_source.end(), 0.0);
    std::fill(m_to_sink.begin(), m_to_sink.end(), 0.0);
    std::fill(m_constraint.begin(), m_constraint.end(), FREE);
  }

  // Solves the cut; returns its value (the max flow), not counting hard-constraint arcs.
  double solve()
  {
    if(!m_finalized)
      finalize();
    // A capacity larger than any finite cut stands for infinity.
    double total = 1.0;
    for(const auto& c : m_pair_capacity)
      total += c.first + c.second;
    for(std::size_t i = 0; i < m_n; ++i)
      total += m_to_source[i] + m_to_sink[i];
    const double infinite = 2 * total;
    const std::size_t base = 2 * m_pairs.size();
    for(std::size_t p = 0; p < m_pairs.size(); ++p) {
      m_capacity[m_slot_to_arc[2 * p]] = checked(m_pair_capacity[p].first);
      m_capacity[m_slot_to_arc[2 * p + 1]] = checked(m_pair_capacity[p].second);
    }
    for(std::size_t i = 0; i < m_n; ++i) {
      double cs = checked(m_to_source[i]), ct = checked(m_to_sink[i]);
      if(m_constraint[i] == SOURCE)
        cs = infinite;
      else if(m_constraint[i] == SINK)
        ct = infinite;
      m_capacity[m_slot_to_arc[base + 4 * i]] = cs;
      m_capacity[m_slot_to_arc[base + 4 * i + 2]] = ct;
      m_capacity[m_slot_to_arc[base + 4 * i + 1]] = 0;
      m_capacity[m_slot_to_arc[base + 4 * i + 3]] = 0;
    }
    auto index = get(boost::vertex_index, m_graph);
    auto edge_index = get(boost::edge_index, m_graph);
    const double flow = boost::boykov_kolmogorov_max_flow(
      m_graph, boost::make_iterator_property_map(m_capacity.begin(), edge_index),
      boost::make_iterator_property_map(m_residual.begin(), edge_index),
      boost::make_iterator_property_map(m_reverse.begin(), edge_index),
      boost::make_iterator_property_map(m_predecessor.begin(), index),
      boost::make_iterator_property_map(m_color.begin(), index),
      boost::make_iterator_property_map(m_distance.begin(), index), index,
      static_cast<Vertex>(m_n), static_cast<Vertex>(m_n + 1));
    return flow;
  }

  // After solve(): whether node u is on the source side of the minimum cut.
  bool is_source_side(std::size_t u) const { return m_color[u] == boost::black_color; }

private:
  static double checked(double c)
  {
    if(!(c >= 0) || !std::isfinite(c))
      throw Bad_input("min-cut: capacities must be finite and non-negative");
    return c;
  }

  std::size_t m_n = 0;
  bool m_finalized = false;
  std::vector<std::pair<std::uint32_t, std::uint32_t>> m_pairs;
  std::vector<std::pair<double, double>> m_pair_capacity;
  std::vector<double> m_to_source, m_to_sink;
  std::vector<Constraint> m_constraint;

  Graph m_graph;
  std::vector<std::size_t> m_slot_to_arc;
  std::vector<Arc> m_arcs, m_reverse;
  std::vector<double> m_capacity, m_residual;
  std::vector<boost::default_color_type> m_color;
  std::vector<Arc> m_predecessor;
  std::vector<std::size_t> m_distance;
};

// Minimum cut between two nodes of a Dual_graph (no terminal arcs): the cut cost of a graph
// edge is the capacity of both of its arcs. The topology is built once and only read afterwards,
// so that several threads can solve cuts on one graph, each with its own Workspace.
class Dual_graph_min_cut
{
public:
  struct Workspace
  {
    std::vector<double> capacity, previous_capacity; // per arc
    Bk_max_flow::Workspace flow;
  };

  explicit Dual_graph_min_cut(const Dual_graph& g) : m_g(g), m_flow(g.first_arc, g.arc_target, m_reverse)
  {
    const std::size_t arcs = g.arc_target.size();
    if(arcs >= std::size_t(0xFFFFFFF0u))
      throw Bad_input("min-cut: the graph has too many edges (at most 2^31 - 8)");
    // The two arcs of each graph edge: the first and the second one met.
    std::vector<std::uint32_t> first(g.number_of_edges(), no_arc);
    m_reverse.assign(arcs, no_arc);
    for(std::size_t a = 0; a < arcs; ++a) {
      const std::uint32_t e = g.arc_edge[a];
      if(first[e] == no_arc)
        first[e] = static_cast<std::uint32_t>(a);
      else {
        m_reverse[a] = first[e];
        m_reverse[first[e]] = static_cast<std::uint32_t>(a);
      }
    }
  }

  Dual_graph_min_cut(const Dual_graph_min_cut&) = delete;
  Dual_graph_min_cut& operator=(const Dual_graph_min_cut&) = delete;

  std::size_t number_of_nodes() const { return m_g.number_of_nodes(); }

  // Solves the minimum cut between `source` and `sink` with capacity `edge_capacity[e]` on both
  // arcs of graph edge e (finite, non-negative); returns its value. The sides are read with
  // is_source_side().
  double solve(const std::vector<double>& edge_capacity, std::size_t source, std::size_t sink,
               Workspace& w) const
  {
    fill_arc_capacities(edge_capacity, w.capacity);
    return m_flow.solve(w.capacity, static_cast<std::uint32_t>(source),
                        static_cast<std::uint32_t>(sink), w.flow);
  }

  // The same cut after the capacities grew (no edge's capacity lower than in the last solve with
  // `w`, same source and sink): the last flow is augmented further instead of starting again.
  // Returns the flow added.
  double solve_with_larger_capacities(const std::vector<double>& edge_capacity, std::size_t source,
                                      std::size_t sink, Workspace& w) const
  {
    w.previous_capacity.swap(w.capacity);
    fill_arc_capacities(edge_capacity, w.capacity);
    return m_flow.solve_with_larger_capacities(w.previous_capacity, w.capacity,
                                               static_cast<std::uint32_t>(source),
                                               static_cast<std::uint32_t>(sink), w.flow);
  }

  // After solve() with `w`: whether node u is on the source side of the cut.
  static bool is_source_side(const Workspace& w, std::size_t u)
  {
    return Bk_max_flow::is_source_side(w.flow, u);
  }

private:
  void fill_arc_capacities(const std::vector<double>& edge_capacity, std::vector<double>& arc) const
  {
    arc.resize(m_g.arc_edge.size());
    for(std::size_t a = 0; a < arc.size(); ++a)
      arc[a] = edge_capacity[m_g.arc_edge[a]];
  }

  static constexpr std::uint32_t no_arc = ~std::uint32_t(0);
  const Dual_graph& m_g;
  std::vector<std::uint32_t> m_reverse;
  Bk_max_flow m_flow;
};

} // namespace internal
} // namespace Shape_analysis
} // namespace CGAL

#endif // CGAL_SHAPE_ANALYSIS_INTERNAL_MIN_CUT_H
