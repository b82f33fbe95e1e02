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
#include <memory>
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

// s-t minimum cut with terminal capacities and hard constraints on the project's own
// Boykov-Kolmogorov solver (Bk_max_flow), for the many small graphs of point-cloud segmentation:
// the graph is built in compressed rows once (`reset`, `add_edge`, `set_terminal_capacity`,
// `solve`); hard constraints added afterwards only raise capacities, so `constrain_and_resolve`
// augments the last flow instead of starting again (interactive segmentation). Not thread-safe:
// one object per thread.
class Terminal_min_cut
{
public:
  enum Side : char { FREE = 0, SOURCE = 1, SINK = 2 };

  Terminal_min_cut() = default;
  // The solver points to the arrays of this object: neither copied nor moved.
  Terminal_min_cut(const Terminal_min_cut&) = delete;
  Terminal_min_cut& operator=(const Terminal_min_cut&) = delete;

  // Forgets everything; the graph will have `n` nodes plus the two terminals.
  void reset(std::size_t n)
  {
    m_n = n;
    m_edges.clear();
    m_to_source.assign(n, 0.0);
    m_to_sink.assign(n, 0.0);
    m_constraint.assign(n, FREE);
    m_built = false;
  }

  std::size_t number_of_nodes() const { return m_n; }

  // An undirected edge u-v of capacity `c` (finite, non-negative), before the first solve.
  void add_edge(std::size_t u, std::size_t v, double c) { m_edges.push_back({std::uint32_t(u), std::uint32_t(v), c}); }

  // The cost of putting u on the sink side (`to_source`) and on the source side (`to_sink`).
  void set_terminal_capacity(std::size_t u, double to_source, double to_sink)
  {
    m_to_source[u] = to_source;
    m_to_sink[u] = to_sink;
  }
  void constrain(std::size_t u, Side s) { m_constraint[u] = s; }
  Side constraint(std::size_t u) const { return m_constraint[u]; }

  // Solves from scratch; returns the value of the cut without the hard-constraint arcs.
  double solve()
  {
    if(!m_built)
      build();
    fill_capacities(m_capacity);
    // The flow of the paths s -> u -> t goes first, without a search: both terminal arcs of u
    // lose their smaller capacity, which lowers every cut by the same amount (a cut cuts one of
    // them) and leaves the minimum cuts and the residual graph of a maximum flow as they were.
    m_pushed.resize(m_n);
    double pushed = 0;
    for(std::size_t u = 0; u < m_n; ++u) {
      double& a = m_capacity[m_terminal_arc[2 * u]];
      double& b = m_capacity[m_terminal_arc[2 * u + 1]];
      m_pushed[u] = (std::min)(a, b);
      a -= m_pushed[u];
      b -= m_pushed[u];
      pushed += m_pushed[u];
    }
    m_flow = pushed + m_solver->solve(m_capacity, source(), sink(), m_workspace);
    return finite_part();
  }

  // Adds hard constraints (pairs of node and side) to the last solve and re-solves by augmenting
  // its flow. A constraint that contradicts an earlier one (or frees a node) needs a full solve,
  // which is then made. Returns the value of the cut as solve() does.
  double constrain_and_resolve(const std::vector<std::pair<std::size_t, Side>>& constraints)
  {
    bool grows = m_built;
    for(const auto& c : constraints)
      if(c.second == FREE || (m_constraint[c.first] != FREE && m_constraint[c.first] != c.second))
        grows = false;
    for(const auto& c : constraints)
      m_constraint[c.first] = c.second;
    if(!grows)
      return solve();
    m_previous.swap(m_capacity);
    fill_capacities(m_capacity);
    // Less what went straight through each node at the first solve, as in m_previous: the
    // capacities only grow.
    for(std::size_t u = 0; u < m_n; ++u) {
      m_capacity[m_terminal_arc[2 * u]] -= m_pushed[u];
      m_capacity[m_terminal_arc[2 * u + 1]] -= m_pushed[u];
    }
    m_flow += m_solver->solve_with_larger_capacities(m_previous, m_capacity, source(), sink(), m_workspace);
    return finite_part();
  }

  // After a solve: whether node u is on the source side (the nodes the source reaches in the
  // residual graph: the smallest source side of a minimum cut).
  bool is_source_side(std::size_t u) const { return Bk_max_flow::is_source_side(m_workspace, u); }

private:
  struct Edge { std::uint32_t u, v; double c; };

  Bk_max_flow::Index source() const { return Bk_max_flow::Index(m_n); }
  Bk_max_flow::Index sink() const { return Bk_max_flow::Index(m_n + 1); }

  void build()
  {
    if(m_n + 2 >= std::size_t(0xFFFFFFF0u) || 2 * m_edges.size() + 4 * m_n >= std::size_t(0xFFFFFFF0u))
      throw Bad_input("min-cut: the graph is too large (at most 2^31 nodes and arcs)");
    const std::size_t total = m_n + 2;
    std::vector<std::size_t> degree(total + 1, 0);
    for(const Edge& e : m_edges)
      ++degree[e.u + 1], ++degree[e.v + 1];
    for(std::size_t u = 0; u < m_n; ++u)
      degree[u + 1] += 2, ++degree[m_n + 1], ++degree[m_n + 2];
    m_first.assign(total + 1, 0);
    for(std::size_t u = 0; u < total; ++u)
      m_first[u + 1] = m_first[u] + degree[u + 1];
    std::vector<std::size_t> fill(m_first.begin(), m_first.end() - 1);
    const std::size_t arcs = m_first[total];
    m_target.assign(arcs, 0);
    m_reverse.assign(arcs, 0);
    m_edge_arc.assign(m_edges.size(), 0);
    m_terminal_arc.assign(2 * m_n, 0);
    auto pair_arcs = [&](std::uint32_t a, std::uint32_t b) {
      const std::size_t x = fill[a]++, y = fill[b]++;
      m_target[x] = b, m_target[y] = a;
      m_reverse[x] = Bk_max_flow::Index(y), m_reverse[y] = Bk_max_flow::Index(x);
      return x;
    };
    for(std::size_t e = 0; e < m_edges.size(); ++e)
      m_edge_arc[e] = pair_arcs(m_edges[e].u, m_edges[e].v);
    for(std::size_t u = 0; u < m_n; ++u) {
      m_terminal_arc[2 * u] = pair_arcs(source(), std::uint32_t(u)); // s -> u
      m_terminal_arc[2 * u + 1] = pair_arcs(std::uint32_t(u), sink()); // u -> t
    }
    m_solver.reset(new Bk_max_flow(m_first, m_target, m_reverse));
    // A capacity larger than any finite cut stands for infinity.
    m_infinite = 1.0;
    for(const Edge& e : m_edges)
      m_infinite += 2 * checked(e.c);
    for(std::size_t u = 0; u < m_n; ++u)
      m_infinite += checked(m_to_source[u]) + checked(m_to_sink[u]);
    m_infinite *= 2;
    m_built = true;
  }

  void fill_capacities(std::vector<double>& capacity) const
  {
    capacity.assign(m_target.size(), 0.0);
    for(std::size_t e = 0; e < m_edges.size(); ++e)
      capacity[m_edge_arc[e]] = capacity[m_reverse[m_edge_arc[e]]] = m_edges[e].c;
    for(std::size_t u = 0; u < m_n; ++u) {
      capacity[m_terminal_arc[2 * u]] = m_constraint[u] == SOURCE ? m_infinite : m_to_source[u];
      capacity[m_terminal_arc[2 * u + 1]] = m_constraint[u] == SINK ? m_infinite : m_to_sink[u];
    }
  }

  // The flow minus what went through hard-constraint arcs is not the finite cut in general;
  // the finite cut is recomputed from the sides.
  double finite_part() const
  {
    double cut = 0;
    for(const Edge& e : m_edges)
      if(is_source_side(e.u) != is_source_side(e.v))
        cut += e.c;
    for(std::size_t u = 0; u < m_n; ++u) {
      if(is_source_side(u) && m_constraint[u] != SINK)
        cut += m_to_sink[u];
      if(!is_source_side(u) && m_constraint[u] != SOURCE)
        cut += m_to_source[u];
    }
    return cut;
  }

  static double checked(double c)
  {
    if(!(c >= 0) || !std::isfinite(c))
      throw Bad_input("min-cut: capacities must be finite and non-negative");
    return c;
  }

  std::size_t m_n = 0;
  bool m_built = false;
  double m_infinite = 1, m_flow = 0;
  std::vector<Edge> m_edges;
  std::vector<double> m_to_source, m_to_sink;
  std::vector<Side> m_constraint;
  std::vector<std::size_t> m_first, m_edge_arc, m_terminal_arc;
  std::vector<Bk_max_flow::Index> m_target, m_reverse;
  std::unique_ptr<Bk_max_flow> m_solver;
  Bk_max_flow::Workspace m_workspace;
  std::vector<double> m_capacity, m_previous;
  std::vector<double> m_pushed; // per node: the flow sent straight from s through it to t
};

} // namespace internal
} // namespace Shape_analysis
} // namespace CGAL

#endif // CGAL_SHAPE_ANALYSIS_INTERNAL_MIN_CUT_H
