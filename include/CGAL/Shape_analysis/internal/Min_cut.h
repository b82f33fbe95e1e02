// Copyright (c) 2026 CGAL Global Shape Analysis contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_SHAPE_ANALYSIS_INTERNAL_MIN_CUT_H
#define CGAL_SHAPE_ANALYSIS_INTERNAL_MIN_CUT_H

// s-t minimum cuts on the project's Boykov-Kolmogorov max-flow (Max_flow.h): between two nodes
// of a Dual_graph (randomized cuts), and with terminal (unary) capacities and hard constraints
// (point-cloud segmentation). In both, the topology is built once and capacities can change
// between solves without reallocating it.

#include <CGAL/Shape_analysis/Bad_input.h>
#include <CGAL/Shape_analysis/internal/Dual_graph.h>
#include <CGAL/Shape_analysis/internal/Max_flow.h>

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
// the graph is built in compressed rows at the first solve (`reset`, `add_edge`,
// `set_terminal_capacity`, `solve`). Capacities (of edges, each way, and of terminal arcs) and
// constraints may then change and the cut be solved again on the same topology; hard
// constraints added afterwards only raise capacities, so `constrain_and_resolve` augments the last
// flow instead of starting again (interactive segmentation). Not thread-safe: one object per
// thread.
class Terminal_min_cut
{
public:
  enum Side : char { FREE = 0, SOURCE = 1, SINK = 2 };

  explicit Terminal_min_cut(std::size_t n = 0) { reset(n); }
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
    m_solved = false;
  }

  std::size_t number_of_nodes() const { return m_n; }

  // An edge u-v whose arc u->v has capacity `c_uv` and v->u `c_vu` (finite, non-negative: checked
  // at the solve); returns its index. (Edges added after a solve make the next one rebuild.)
  std::size_t add_edge(std::size_t u, std::size_t v, double c_uv, double c_vu)
  {
    m_built = false, m_solved = false;
    m_edges.push_back({std::uint32_t(u), std::uint32_t(v), c_uv, c_vu});
    return m_edges.size() - 1;
  }
  // An undirected edge: capacity `c` both ways.
  std::size_t add_edge(std::size_t u, std::size_t v, double c) { return add_edge(u, v, c, c); }
  // New capacities of edge `e` (the topology stays).
  void set_edge_capacity(std::size_t e, double c_uv, double c_vu)
  {
    m_edges[e].c_uv = c_uv, m_edges[e].c_vu = c_vu;
    m_solved = false;
  }

  // The cost of putting u on the sink side (`to_source`) and on the source side (`to_sink`).
  void set_terminal_capacity(std::size_t u, double to_source, double to_sink)
  {
    m_to_source[u] = to_source;
    m_to_sink[u] = to_sink;
    m_solved = false;
  }
  void constrain(std::size_t u, Side s)
  {
    m_constraint[u] = s;
    m_solved = false;
  }
  Side constraint(std::size_t u) const { return m_constraint[u]; }
  // No terminal capacity and no constraint left (edges kept).
  void clear_terminals()
  {
    std::fill(m_to_source.begin(), m_to_source.end(), 0.0);
    std::fill(m_to_sink.begin(), m_to_sink.end(), 0.0);
    std::fill(m_constraint.begin(), m_constraint.end(), FREE);
    m_solved = false;
  }

  // Solves from scratch; returns the value of the cut: the capacities of the arcs from the source
  // side to the sink side, the terminal arcs that constraints make infinite left out.
  double solve()
  {
    m_solved = false;
    if(!m_built)
      build();
    fill_capacities(m_capacity);
    // The flow of the paths s -> u -> t goes first, without a search: both terminal arcs of u
    // lose their smaller capacity, which lowers every cut by the same amount (a cut cuts one of
    // them) and leaves the minimum cuts and the residual graph of a maximum flow as they were.
    m_pushed.resize(m_n);
    for(std::size_t u = 0; u < m_n; ++u) {
      double& a = m_capacity[m_terminal_arc[2 * u]];
      double& b = m_capacity[m_terminal_arc[2 * u + 1]];
      m_pushed[u] = (std::min)(a, b);
      a -= m_pushed[u];
      b -= m_pushed[u];
    }
    m_solver->solve(m_capacity, source(), sink(), m_workspace);
    m_solved = true;
    return finite_part();
  }

  // Adds hard constraints (pairs of node and side) to the last solve and re-solves by augmenting
  // its flow; after any other change since that solve (or without one), solves from scratch. A constraint that contradicts an earlier one (or frees a node) needs a full solve,
  // which is then made. Returns the value of the cut as solve() does.
  double constrain_and_resolve(const std::vector<std::pair<std::size_t, Side>>& constraints)
  {
    bool grows = m_solved;
    for(const auto& c : constraints)
      if(c.second == FREE || (m_constraint[c.first] != FREE && m_constraint[c.first] != c.second))
        grows = false;
    for(const auto& c : constraints)
      m_constraint[c.first] = c.second;
    m_solved = false;
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
    m_solver->solve_with_larger_capacities(m_previous, m_capacity, source(), sink(), m_workspace);
    m_solved = true;
    return finite_part();
  }

  // After a solve: whether node u is on the source side (the nodes the source reaches in the
  // residual graph: the smallest source side of a minimum cut).
  bool is_source_side(std::size_t u) const { return Bk_max_flow::is_source_side(m_workspace, u); }

private:
  struct Edge { std::uint32_t u, v; double c_uv, c_vu; };

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
    m_built = true;
  }

  // The capacities of the arcs for the current edges, terminals and constraints (a capacity
  // larger than any finite cut stands for infinity).
  void fill_capacities(std::vector<double>& capacity)
  {
    m_infinite = 1.0;
    for(const Edge& e : m_edges)
      m_infinite += checked(e.c_uv) + checked(e.c_vu);
    for(std::size_t u = 0; u < m_n; ++u)
      m_infinite += checked(m_to_source[u]) + checked(m_to_sink[u]);
    m_infinite *= 2;
    capacity.assign(m_target.size(), 0.0);
    for(std::size_t e = 0; e < m_edges.size(); ++e) {
      capacity[m_edge_arc[e]] = m_edges[e].c_uv;
      capacity[m_reverse[m_edge_arc[e]]] = m_edges[e].c_vu;
    }
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
    for(const Edge& e : m_edges) {
      const bool su = is_source_side(e.u), sv = is_source_side(e.v);
      cut += su && !sv ? e.c_uv : (sv && !su ? e.c_vu : 0.0);
    }
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
  bool m_solved = false; // the last solve succeeded and nothing changed since
  double m_infinite = 1;
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
