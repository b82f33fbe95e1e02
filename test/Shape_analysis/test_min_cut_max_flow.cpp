// s-t min-cut on the dual graph and the Boykov-Kolmogorov max-flow between two nodes.
// Part of test_shape_analysis_core (one translation unit: see test/CMakeLists.txt).

#include "test_core_fixtures.h"

#include <CGAL/Shape_analysis/Bad_input.h>
#include <CGAL/Shape_analysis/internal/Max_flow.h>
#include <CGAL/Shape_analysis/internal/Min_cut.h>

#include <boost/graph/adjacency_list.hpp>
#include <boost/graph/push_relabel_max_flow.hpp>

#include <limits>
#include <set>

namespace {

// ---------------------------------------------------------------------------------------------
// Min-cut

struct Cut_problem
{
  std::size_t n = 0;
  std::vector<std::pair<std::size_t, std::size_t>> pairs;
  std::vector<std::pair<double, double>> capacity;
  std::vector<double> to_source, to_sink;
  std::vector<SAI::Terminal_min_cut::Side> constraint;

  // Cost of a side assignment (true: source side); infinity if a constraint is violated.
  double cost(const std::vector<bool>& s) const
  {
    double c = 0;
    for(std::size_t u = 0; u < n; ++u) {
      if(constraint[u] == SAI::Terminal_min_cut::SOURCE && !s[u])
        return std::numeric_limits<double>::infinity();
      if(constraint[u] == SAI::Terminal_min_cut::SINK && s[u])
        return std::numeric_limits<double>::infinity();
      c += s[u] ? to_sink[u] : to_source[u];
    }
    for(std::size_t p = 0; p < pairs.size(); ++p) {
      const std::size_t u = pairs[p].first, v = pairs[p].second;
      if(s[u] && !s[v])
        c += capacity[p].first;
      if(s[v] && !s[u])
        c += capacity[p].second;
    }
    return c;
  }

  double brute_force() const
  {
    double best = std::numeric_limits<double>::infinity();
    std::vector<bool> s(n);
    for(std::uint32_t mask = 0; mask < (1u << n); ++mask) {
      for(std::size_t u = 0; u < n; ++u)
        s[u] = (mask >> u) & 1u;
      best = (std::min)(best, cost(s));
    }
    return best;
  }

  void randomize_capacities(SAS::Procedural_random& rng, bool with_constraints)
  {
    capacity.resize(pairs.size());
    for(auto& c : capacity) {
      c.first = rng.uniform() < 0.2 ? 0.0 : rng.uniform(0, 2);
      c.second = rng.uniform() < 0.2 ? 0.0 : rng.uniform(0, 2);
    }
    to_source.assign(n, 0.0);
    to_sink.assign(n, 0.0);
    constraint.assign(n, SAI::Terminal_min_cut::FREE);
    for(std::size_t u = 0; u < n; ++u) {
      if(rng.uniform() < 0.6)
        to_source[u] = rng.uniform(0, 3);
      if(rng.uniform() < 0.6)
        to_sink[u] = rng.uniform(0, 3);
      if(with_constraints) {
        const double r = rng.uniform();
        constraint[u] = r < 0.15 ? SAI::Terminal_min_cut::SOURCE
                                 : (r < 0.3 ? SAI::Terminal_min_cut::SINK : SAI::Terminal_min_cut::FREE);
      }
    }
  }

  void load(SAI::Terminal_min_cut& solver) const
  {
    for(std::size_t p = 0; p < pairs.size(); ++p)
      solver.set_edge_capacity(p, capacity[p].first, capacity[p].second);
    for(std::size_t u = 0; u < n; ++u) {
      solver.set_terminal_capacity(u, to_source[u], to_sink[u]);
      solver.constrain(u, constraint[u]);
    }
  }

  void check(SAI::Terminal_min_cut& solver, const std::string& what) const
  {
    const double flow = solver.solve();
    const double best = brute_force();
    EXPECT_NEAR(flow, best, 1e-9 * (1 + best)) << what;
    std::vector<bool> side(n);
    for(std::size_t u = 0; u < n; ++u)
      side[u] = solver.is_source_side(u);
    EXPECT_NEAR(cost(side), best, 1e-9 * (1 + best)) << what << ": the returned sides realize the cut";
  }
};

TEST(MinCut, MatchesBruteForceOnRandomGraphsWithReuse)
{
  for(std::uint64_t seed = 1; seed <= 40; ++seed) {
    SAS::Procedural_random rng(seed);
    Cut_problem problem;
    problem.n = 2 + rng.index(9); // 2..10 nodes
    for(std::size_t u = 0; u < problem.n; ++u)
      for(std::size_t v = u + 1; v < problem.n; ++v)
        if(rng.uniform() < 0.45)
          problem.pairs.emplace_back(rng.uniform() < 0.5 ? std::make_pair(u, v) : std::make_pair(v, u));
    SAI::Terminal_min_cut solver(problem.n);
    for(const auto& p : problem.pairs)
      solver.add_edge(p.first, p.second, 0.0);
    // The same topology solved several times with new capacities and constraints.
    for(int round = 0; round < 6; ++round) {
      problem.randomize_capacities(rng, round % 2 == 1);
      problem.load(solver);
      problem.check(solver, "seed " + std::to_string(seed) + " round " + std::to_string(round));
    }
    // Removing all terminals and constraints: the empty cut is free.
    solver.clear_terminals();
    EXPECT_EQ(solver.solve(), 0.0);
  }
}

TEST(MinCut, ConstraintsAddedAfterASolveAugmentTheFlow)
{
  // Solved without constraints, then constraints added two at a time (only capacities that
  // grow): the re-solve by augmentation matches brute force every time, and a constraint that
  // contradicts an earlier one falls back to a full solve that matches too.
  for(std::uint64_t seed = 1; seed <= 40; ++seed) {
    SAS::Procedural_random rng(100 + seed);
    Cut_problem problem;
    problem.n = 3 + rng.index(8); // 3..10 nodes
    for(std::size_t u = 0; u < problem.n; ++u)
      for(std::size_t v = u + 1; v < problem.n; ++v)
        if(rng.uniform() < 0.5)
          problem.pairs.emplace_back(u, v);
    problem.randomize_capacities(rng, false);
    SAI::Terminal_min_cut solver(problem.n);
    for(std::size_t p = 0; p < problem.pairs.size(); ++p)
      solver.add_edge(problem.pairs[p].first, problem.pairs[p].second, problem.capacity[p].first,
                      problem.capacity[p].second);
    for(std::size_t u = 0; u < problem.n; ++u)
      solver.set_terminal_capacity(u, problem.to_source[u], problem.to_sink[u]);
    problem.check(solver, "seed " + std::to_string(seed) + " unconstrained");
    for(int round = 0; round < 3; ++round) {
      std::vector<std::pair<std::size_t, SAI::Terminal_min_cut::Side>> added;
      for(int k = 0; k < 2; ++k) {
        const std::size_t u = rng.index(problem.n);
        const SAI::Terminal_min_cut::Side side =
          rng.uniform() < 0.5 ? SAI::Terminal_min_cut::SOURCE : SAI::Terminal_min_cut::SINK;
        added.emplace_back(u, side);
        problem.constraint[u] = side;
      }
      const double value = solver.constrain_and_resolve(added);
      const double best = problem.brute_force();
      const std::string what = "seed " + std::to_string(seed) + " round " + std::to_string(round);
      EXPECT_NEAR(value, best, 1e-9 * (1 + best)) << what;
      std::vector<bool> side(problem.n);
      for(std::size_t u = 0; u < problem.n; ++u)
        side[u] = solver.is_source_side(u);
      EXPECT_NEAR(problem.cost(side), best, 1e-9 * (1 + best)) << what << ": the sides realize the cut";
    }
  }
}

TEST(MinCut, ChangesBetweenSolvesAreTakenIntoAccount)
{
  // 0 - 1 - 2 in a chain; 0 wants the source side, 2 the sink side.
  SAI::Terminal_min_cut solver(3);
  solver.add_edge(0, 1, 1.0);
  solver.add_edge(1, 2, 2.0);
  solver.set_terminal_capacity(0, 10, 0);
  solver.set_terminal_capacity(2, 0, 10);
  EXPECT_NEAR(solver.solve(), 1.0, 1e-12); // cut 0-1
  EXPECT_FALSE(solver.is_source_side(1));
  // An edge added after the solve: the graph is rebuilt (0-2 of 0.5 now crosses every cut).
  solver.add_edge(0, 2, 0.5);
  EXPECT_NEAR(solver.solve(), 1.5, 1e-12);
  // A capacity lowered, then a constraint: the re-solve starts again (an augmentation of the
  // old flow would be wrong); with 1 on the source side the cut goes through the cheap 1-2 edge.
  solver.set_edge_capacity(1, 0.1, 0.1);
  EXPECT_NEAR(solver.constrain_and_resolve({{std::size_t(1), SAI::Terminal_min_cut::SOURCE}}), 0.6, 1e-12);
  EXPECT_TRUE(solver.is_source_side(1));
  // A solve that throws (a negative capacity) leaves nothing to augment: the next call solves.
  solver.set_edge_capacity(0, -1.0, 1.0);
  EXPECT_THROW(solver.solve(), SA::Bad_input);
  solver.set_edge_capacity(0, 1.0, 1.0);
  EXPECT_NEAR(solver.constrain_and_resolve({{std::size_t(0), SAI::Terminal_min_cut::SOURCE}}), 0.6, 1e-12);
  EXPECT_TRUE(solver.is_source_side(1));
  EXPECT_FALSE(solver.is_source_side(2));
}

TEST(MinCut, HardConstraintsWinOverExpensiveCuts)
{
  // A chain 0-1-2-3 with expensive links; node 0 prefers the sink strongly and node 3 the source,
  // but the constraints put 0 on the source side and 3 on the sink side.
  SAI::Terminal_min_cut solver(4);
  const double link[3] = {5, 1.5, 7};
  for(std::size_t u = 0; u + 1 < 4; ++u)
    solver.add_edge(u, u + 1, link[u]);
  solver.set_terminal_capacity(0, 0, 100);
  solver.set_terminal_capacity(3, 100, 0);
  solver.constrain(0, SAI::Terminal_min_cut::SOURCE);
  solver.constrain(3, SAI::Terminal_min_cut::SINK);
  const double flow = solver.solve();
  EXPECT_TRUE(solver.is_source_side(0));
  EXPECT_FALSE(solver.is_source_side(3));
  // The cheapest way: cut the middle link (1.5), plus the terminal arcs 0->t and s->3.
  EXPECT_NEAR(flow, 200 + 1.5, 1e-9);
  EXPECT_TRUE(solver.is_source_side(1));
  EXPECT_FALSE(solver.is_source_side(2));

  // Reversed constraints on the same solver.
  solver.constrain(0, SAI::Terminal_min_cut::SINK);
  solver.constrain(3, SAI::Terminal_min_cut::SOURCE);
  solver.set_terminal_capacity(0, 0, 0);
  solver.set_terminal_capacity(3, 0, 0);
  EXPECT_NEAR(solver.solve(), 1.5, 1e-9);
  EXPECT_FALSE(solver.is_source_side(0));
  EXPECT_FALSE(solver.is_source_side(1));
  EXPECT_TRUE(solver.is_source_side(2));
  EXPECT_TRUE(solver.is_source_side(3));
}

TEST(MinCut, AsymmetricCapacitiesAndReset)
{
  // Two nodes, source prefers 0, sink prefers 1: the arc 0->1 is cut, its reverse is not.
  SAI::Terminal_min_cut solver(2);
  solver.add_edge(0, 1, 0.25, 9.0);
  solver.set_terminal_capacity(0, 10, 0);
  solver.set_terminal_capacity(1, 0, 10);
  EXPECT_NEAR(solver.solve(), 0.25, 1e-12);
  EXPECT_TRUE(solver.is_source_side(0));
  EXPECT_FALSE(solver.is_source_side(1));
  // The other way around the reverse capacity counts.
  solver.set_terminal_capacity(0, 0, 10);
  solver.set_terminal_capacity(1, 10, 0);
  EXPECT_NEAR(solver.solve(), 9.0, 1e-12);
  EXPECT_TRUE(solver.is_source_side(1));
  EXPECT_FALSE(solver.is_source_side(0));

  // Reset to another graph: three isolated nodes choose their cheaper side.
  solver.reset(3);
  EXPECT_EQ(solver.number_of_nodes(), 3u);
  solver.set_terminal_capacity(0, 1, 2); // sink side costs 1, source side costs 2 -> sink
  solver.set_terminal_capacity(1, 3, 1); // -> source
  solver.set_terminal_capacity(2, 0, 0);
  EXPECT_NEAR(solver.solve(), 2.0, 1e-12);
  EXPECT_FALSE(solver.is_source_side(0));
  EXPECT_TRUE(solver.is_source_side(1));
}

TEST(MinCut, RejectsBadCapacities)
{
  SAI::Terminal_min_cut solver(2);
  solver.add_edge(0, 1, -1.0, 1.0);
  EXPECT_THROW(solver.solve(), SA::Bad_input);
  solver.set_edge_capacity(0, 1.0, 1.0);
  solver.set_terminal_capacity(1, std::numeric_limits<double>::quiet_NaN(), 0);
  EXPECT_THROW(solver.solve(), SA::Bad_input);
  solver.set_terminal_capacity(1, std::numeric_limits<double>::infinity(), 0);
  EXPECT_THROW(solver.solve(), SA::Bad_input);
  solver.set_terminal_capacity(1, 1, 0);
  EXPECT_NO_THROW(solver.solve());
}

// ---------------------------------------------------------------------------------------------
// Boykov-Kolmogorov max-flow between two nodes

// A directed graph in compressed rows where every arc has a reverse arc (its own capacity).
struct Arc_graph
{
  std::size_t n = 0;
  std::vector<std::size_t> first;
  std::vector<std::uint32_t> target, reverse, tail;

  // Undirected pairs, each giving the arcs u->v and v->u.
  Arc_graph(std::size_t nodes, const std::vector<std::pair<std::uint32_t, std::uint32_t>>& pairs) : n(nodes)
  {
    std::vector<std::vector<std::pair<std::uint32_t, std::size_t>>> out(n); // (target, slot)
    for(std::size_t p = 0; p < pairs.size(); ++p) {
      out[pairs[p].first].emplace_back(pairs[p].second, 2 * p);
      out[pairs[p].second].emplace_back(pairs[p].first, 2 * p + 1);
    }
    std::vector<std::uint32_t> arc_of_slot(2 * pairs.size());
    first.assign(1, 0);
    for(std::uint32_t u = 0; u < n; ++u) {
      for(const auto& a : out[u]) {
        arc_of_slot[a.second] = static_cast<std::uint32_t>(target.size());
        target.push_back(a.first);
        tail.push_back(u);
      }
      first.push_back(target.size());
    }
    reverse.resize(target.size());
    for(std::size_t p = 0; p < pairs.size(); ++p) {
      reverse[arc_of_slot[2 * p]] = arc_of_slot[2 * p + 1];
      reverse[arc_of_slot[2 * p + 1]] = arc_of_slot[2 * p];
    }
  }

  // Capacity of the arcs leaving the node set `side` (true) to the rest.
  double cut(const std::vector<double>& capacity, const std::vector<bool>& side) const
  {
    double c = 0;
    for(std::size_t a = 0; a < target.size(); ++a)
      if(side[tail[a]] && !side[target[a]])
        c += capacity[a];
    return c;
  }
};

TEST(MaxFlow, MatchesBruteForceOnRandomDirectedGraphs)
{
  SAI::Bk_max_flow::Workspace w; // reused across problems of different sizes
  for(std::uint64_t seed = 1; seed <= 300; ++seed) {
    SAS::Procedural_random rng(seed);
    const std::size_t n = 2 + rng.index(10); // 2..11 nodes
    std::vector<std::pair<std::uint32_t, std::uint32_t>> pairs;
    for(std::uint32_t u = 0; u < n; ++u)
      for(std::uint32_t v = u + 1; v < n; ++v)
        if(rng.uniform() < 0.5)
          pairs.emplace_back(u, v);
    const Arc_graph g(n, pairs);
    std::vector<double> capacity(g.target.size());
    for(double& c : capacity) // zeros, ties and one-way arcs included
      c = rng.uniform() < 0.25 ? 0.0 : double(1 + rng.index(6));
    const std::uint32_t s = static_cast<std::uint32_t>(rng.index(n));
    std::uint32_t t = static_cast<std::uint32_t>(rng.index(n));
    if(t == s)
      t = static_cast<std::uint32_t>((s + 1) % n);
    SAI::Bk_max_flow flow(g.first, g.target, g.reverse);
    const double value = flow.solve(capacity, s, t, w);
    double best = std::numeric_limits<double>::infinity();
    std::vector<bool> side(n);
    for(std::uint32_t mask = 0; mask < (1u << n); ++mask) {
      if(!((mask >> s) & 1u) || ((mask >> t) & 1u))
        continue;
      for(std::size_t u = 0; u < n; ++u)
        side[u] = (mask >> u) & 1u;
      best = (std::min)(best, g.cut(capacity, side));
    }
    ASSERT_EQ(value, best) << "seed " << seed; // integer capacities: exact
    for(std::size_t u = 0; u < n; ++u)
      side[u] = SAI::Bk_max_flow::is_source_side(w, u);
    EXPECT_TRUE(side[s]);
    EXPECT_FALSE(side[t]);
    EXPECT_EQ(g.cut(capacity, side), best) << "seed " << seed << ": the sides realize the minimum";

    // Larger capacities: the flow continues from the last one and reaches the new maximum.
    std::vector<double> larger(capacity);
    for(double& c : larger)
      c += rng.uniform() < 0.5 ? 0.0 : double(rng.index(4));
    const double added = flow.solve_with_larger_capacities(capacity, larger, s, t, w);
    double best_larger = std::numeric_limits<double>::infinity();
    for(std::uint32_t mask = 0; mask < (1u << n); ++mask) {
      if(!((mask >> s) & 1u) || ((mask >> t) & 1u))
        continue;
      for(std::size_t u = 0; u < n; ++u)
        side[u] = (mask >> u) & 1u;
      best_larger = (std::min)(best_larger, g.cut(larger, side));
    }
    ASSERT_EQ(value + added, best_larger) << "seed " << seed;
    for(std::size_t u = 0; u < n; ++u)
      side[u] = SAI::Bk_max_flow::is_source_side(w, u);
    EXPECT_EQ(g.cut(larger, side), best_larger) << "seed " << seed;
  }
}

// The maximum flow from s to t of an undirected graph (capacity c both ways) by Boost's
// push-relabel: a reference computed by another algorithm and another implementation.
double boost_push_relabel_flow(std::size_t n, const std::vector<std::uint32_t>& from, const std::vector<std::uint32_t>& to,
                               const std::vector<double>& capacity, std::size_t s, std::size_t t)
{
  typedef boost::adjacency_list_traits<boost::vecS, boost::vecS, boost::directedS> Traits;
  typedef boost::adjacency_list<
    boost::vecS, boost::vecS, boost::directedS, boost::no_property,
    boost::property<boost::edge_capacity_t, double,
                    boost::property<boost::edge_residual_capacity_t, double,
                                    boost::property<boost::edge_reverse_t, Traits::edge_descriptor>>>>
    Graph;
  Graph g(n);
  auto cap = get(boost::edge_capacity, g);
  auto rev = get(boost::edge_reverse, g);
  for(std::size_t e = 0; e < from.size(); ++e) {
    const auto a = boost::add_edge(from[e], to[e], g).first, b = boost::add_edge(to[e], from[e], g).first;
    cap[a] = cap[b] = capacity[e];
    rev[a] = b, rev[b] = a;
  }
  return boost::push_relabel_max_flow(g, boost::vertex(s, g), boost::vertex(t, g));
}

TEST(MaxFlow, AgreesWithBoostOnAMeshDualGraph)
{
  // Many cuts on the dual graph of a real shape, with random capacities: the flow value of our
  // solver equals the one of Boost's push-relabel, and its sides realize it.
  const SAS::Labelled_triangle_mesh lm = SAS::mesh_procedural_shape(SAS::three_sphere_chain(), 0.3);
  Mesh m;
  SAS::fill_polygon_mesh(lm, m);
  SAI::Dual_graph g;
  SAI::build_dual_graph(m, get(CGAL::vertex_point, m), get(CGAL::face_index, m), 10.0, g);
  SAI::Dual_graph_min_cut ours(g);
  SAI::Dual_graph_min_cut::Workspace w;
  SAS::Procedural_random rng(11);
  std::vector<double> capacity(g.number_of_edges());
  for(int round = 0; round < 25; ++round) {
    for(double& c : capacity)
      c = round % 2 == 0 ? rng.uniform(0, 1) : std::pow(rng.uniform(), 8.0);
    const std::size_t s = rng.index(g.number_of_nodes());
    std::size_t t = rng.index(g.number_of_nodes());
    if(t == s)
      t = (s + 1) % g.number_of_nodes();
    const double expected = boost_push_relabel_flow(g.number_of_nodes(), g.edge_source, g.edge_target, capacity, s, t);
    const double value = ours.solve(capacity, s, t, w);
    EXPECT_NEAR(value, expected, 1e-9 * (1 + expected)) << "round " << round;
    double across = 0;
    for(std::size_t e = 0; e < g.number_of_edges(); ++e)
      if(SAI::Dual_graph_min_cut::is_source_side(w, g.edge_source[e]) !=
         SAI::Dual_graph_min_cut::is_source_side(w, g.edge_target[e]))
        across += capacity[e];
    EXPECT_NEAR(across, value, 1e-9 * (1 + value)) << "round " << round;
    EXPECT_TRUE(SAI::Dual_graph_min_cut::is_source_side(w, s));
    EXPECT_FALSE(SAI::Dual_graph_min_cut::is_source_side(w, t));
  }
}

} // namespace
