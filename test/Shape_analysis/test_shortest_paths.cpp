// Multi-source shortest paths on a dual graph, with labels and regions.
// Part of test_shape_analysis_core (one translation unit: see test/CMakeLists.txt).

#include "test_core_fixtures.h"

#include <CGAL/Shape_analysis/internal/Shortest_paths.h>

#include <limits>
#include <set>

namespace {

TEST(ShortestPaths, MatchBellmanFordWithLabelsAndRegions)
{
  SAI::Graph_shortest_paths paths; // reused across graphs and runs
  for(std::uint64_t seed = 1; seed <= 60; ++seed) {
    SAS::Procedural_random rng(seed);
    const std::size_t n = 1 + rng.index(40);
    std::vector<std::pair<std::uint32_t, std::uint32_t>> edges;
    std::vector<double> length;
    for(std::uint32_t u = 0; u < n; ++u)
      for(std::uint32_t v = u + 1; v < n; ++v)
        if(rng.uniform() < 3.0 / double(n)) {
          edges.emplace_back(u, v);
          length.push_back(rng.uniform() < 0.1 ? 0.0 : double(rng.index(5)) + rng.uniform());
        }
    const SAI::Dual_graph g = graph_of(n, edges, length);
    std::vector<std::uint32_t> sources, labels;
    for(std::size_t k = 0, count = 1 + rng.index(3); k < count; ++k) {
      sources.push_back(static_cast<std::uint32_t>(rng.index(n)));
      labels.push_back(static_cast<std::uint32_t>(10 + k));
    }
    std::vector<char> region(n);
    for(char& r : region)
      r = rng.uniform() < 0.8 ? 1 : 0;
    for(int restricted = 0; restricted < 2; ++restricted) {
      auto allowed = [&](std::uint32_t i) { return restricted == 0 || region[i] == 1; };
      // Bellman-Ford reference.
      std::vector<double> d(n, std::numeric_limits<double>::infinity());
      for(std::uint32_t s : sources)
        if(allowed(s))
          d[s] = 0;
      for(std::size_t pass = 0; pass < n; ++pass)
        for(std::size_t e = 0; e < edges.size(); ++e) {
          const std::uint32_t u = edges[e].first, v = edges[e].second;
          if(!allowed(u) || !allowed(v))
            continue;
          d[v] = (std::min)(d[v], d[u] + length[e]);
          d[u] = (std::min)(d[u], d[v] + length[e]);
        }
      paths.run_within(g, length, sources, labels, {}, allowed);
      std::set<std::uint32_t> settled(paths.settled().begin(), paths.settled().end());
      EXPECT_EQ(settled.size(), paths.settled().size()) << "a node settled twice";
      for(std::uint32_t i = 0; i < n; ++i) {
        ASSERT_EQ(paths.distance(i), d[i]) << "seed " << seed << " node " << i;
        EXPECT_EQ(settled.count(i) == 1, std::isfinite(d[i]));
        if(!std::isfinite(d[i])) {
          EXPECT_EQ(paths.label(i), SAI::Graph_shortest_paths::no_label);
          continue;
        }
        // The label is the one of a source at that distance along some path: some source k
        // with the label has d(k, i) == d[i]; check it is one of the labels, and that a node and
        // a neighbour on a shortest path share labels consistently (nearest source wins).
        EXPECT_GE(paths.label(i), 10u);
        EXPECT_LT(paths.label(i), 10u + sources.size());
      }
      // Settled in non-decreasing distance.
      for(std::size_t k = 1; k < paths.settled().size(); ++k)
        EXPECT_LE(paths.distance(paths.settled()[k - 1]), paths.distance(paths.settled()[k]));
    }
  }
}

TEST(ShortestPaths, LabelsFormAVoronoiPartition)
{
  // A path graph 0 - 1 - ... - 9 with unit lengths, sources at 1 (label 0) and 8 (label 1).
  std::vector<std::pair<std::uint32_t, std::uint32_t>> edges;
  for(std::uint32_t i = 0; i + 1 < 10; ++i)
    edges.emplace_back(i, i + 1);
  const SAI::Dual_graph g = graph_of(10, edges, std::vector<double>(9, 1.0));
  SAI::Graph_shortest_paths paths;
  paths.run(g, std::vector<double>(9, 1.0), {1, 8}, {0, 1});
  for(std::uint32_t i = 0; i < 10; ++i)
    EXPECT_EQ(paths.label(i), i < 5 ? 0u : 1u) << i; // 4 and 5 are closer to 1 and 8 resp.
  EXPECT_EQ(paths.distance(0), 1.0);
  EXPECT_EQ(paths.distance(9), 1.0);
  // Offsets: a source that starts later loses ground.
  paths.run(g, std::vector<double>(9, 1.0), {1, 8}, {0, 1}, {0.0, 2.0});
  EXPECT_EQ(paths.label(5), 0u); // 4 from node 1, 2 + 3 from node 8
  EXPECT_EQ(paths.distance(5), 4.0);
  EXPECT_EQ(paths.label(6), 1u); // 5 from node 1, 2 + 2 from node 8
  EXPECT_EQ(paths.distance(6), 4.0);
}

} // namespace
