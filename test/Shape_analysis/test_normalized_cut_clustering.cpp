// Agglomerative normalized-cut clustering and partition refinement.
// Part of test_shape_analysis_core (one translation unit: see test/CMakeLists.txt).

#include "test_core_fixtures.h"

#include <CGAL/Shape_analysis/internal/Normalized_cut_clustering.h>
#include <CGAL/Shape_analysis/internal/Partition_refinement.h>

#include <map>
#include <set>

namespace {

// ---------------------------------------------------------------------------------------------
// Normalized-cut clustering

struct Small_graph
{
  std::vector<double> size;
  std::vector<std::uint32_t> source, target;
  std::vector<double> weight;
  void edge(std::uint32_t u, std::uint32_t v, double w)
  {
    source.push_back(u);
    target.push_back(v);
    weight.push_back(w);
  }
};

// Two 4-cliques (0..3 and 4..7) joined by the weak edge 3-4.
Small_graph two_cliques()
{
  Small_graph g;
  g.size.assign(8, 1.0);
  for(std::uint32_t base : {0u, 4u})
    for(std::uint32_t u = 0; u < 4; ++u)
      for(std::uint32_t v = u + 1; v < 4; ++v)
        g.edge(base + u, base + v, 1.0);
  g.edge(3, 4, 0.01);
  return g;
}

Small_graph random_grid(std::size_t side, std::uint64_t seed)
{
  SAS::Procedural_random rng(seed);
  Small_graph g;
  for(std::size_t i = 0; i < side * side; ++i)
    g.size.push_back(rng.uniform(0.5, 1.5));
  for(std::uint32_t r = 0; r < side; ++r)
    for(std::uint32_t c = 0; c < side; ++c) {
      const std::uint32_t u = r * std::uint32_t(side) + c;
      if(c + 1 < side)
        g.edge(u, u + 1, rng.uniform(0.01, 1.0));
      if(r + 1 < side)
        g.edge(u, u + std::uint32_t(side), rng.uniform(0.01, 1.0));
    }
  return g;
}

TEST(NormalizedCutClustering, TwoCliquesSplitAtTheWeakEdge)
{
  const Small_graph g = two_cliques();
  SAI::Normalized_cut_clustering c(g.size, g.source, g.target, g.weight);
  EXPECT_EQ(c.number_of_clusters(), 8u);
  c.run(2);
  EXPECT_EQ(c.number_of_clusters(), 2u);
  EXPECT_EQ(c.merges().size(), 6u);
  const std::vector<std::size_t> labels = c.labels();
  for(std::size_t i = 0; i < 8; ++i)
    EXPECT_EQ(labels[i], i < 4 ? 0u : 1u);
  const auto r0 = c.find(0), r1 = c.find(7);
  EXPECT_NEAR(c.cluster_cut(r0), 0.01, 1e-12);
  EXPECT_NEAR(c.cluster_size(r0) + c.cluster_size(r1), 8.0, 1e-12);
  ASSERT_EQ(c.neighbors(r0).size(), 1u);
  EXPECT_EQ(c.neighbors(r0)[0].first, r1);
  EXPECT_NEAR(c.neighbors(r0)[0].second, 0.01, 1e-12);
  // Then everything merges into one.
  c.run(1);
  EXPECT_EQ(c.number_of_clusters(), 1u);
  EXPECT_EQ(c.labels(), std::vector<std::size_t>(8, 0));
}

// Reference greedy: recompute every adjacent pair's change of J at every step.
std::vector<std::vector<std::size_t>> reference_greedy(const Small_graph& g)
{
  const std::size_t n = g.size.size();
  std::vector<std::size_t> label(n);
  std::iota(label.begin(), label.end(), std::size_t(0));
  std::vector<std::vector<std::size_t>> levels; // levels[k] = partition with n - k clusters
  levels.push_back(label);
  while(true) {
    std::map<std::size_t, double> size, cut;
    std::map<std::pair<std::size_t, std::size_t>, double> between;
    for(std::size_t i = 0; i < n; ++i)
      size[label[i]] += g.size[i];
    for(std::size_t e = 0; e < g.source.size(); ++e) {
      std::size_t a = label[g.source[e]], b = label[g.target[e]];
      if(a == b)
        continue;
      cut[a] += g.weight[e];
      cut[b] += g.weight[e];
      between[{(std::min)(a, b), (std::max)(a, b)}] += g.weight[e];
    }
    double best = std::numeric_limits<double>::infinity();
    std::pair<std::size_t, std::size_t> best_pair;
    for(const auto& p : between) {
      const std::size_t a = p.first.first, b = p.first.second;
      const double d = (cut[a] + cut[b] - 2 * p.second) / (size[a] + size[b]) - cut[a] / size[a] -
                       cut[b] / size[b];
      if(d < best) {
        best = d;
        best_pair = p.first;
      }
    }
    if(between.empty())
      break;
    for(auto& l : label)
      if(l == best_pair.second)
        l = best_pair.first;
    levels.push_back(label);
  }
  return levels;
}

TEST(NormalizedCutClustering, MatchesReferenceGreedyAtEveryLevel)
{
  for(std::uint64_t seed : {3u, 4u, 5u}) {
    const Small_graph g = random_grid(4, seed); // 16 nodes, random weights: no ties
    const auto levels = reference_greedy(g);
    ASSERT_EQ(levels.size(), 16u);
    for(std::size_t k = 1; k <= 16; ++k) {
      SAI::Normalized_cut_clustering c(g.size, g.source, g.target, g.weight);
      c.run(k);
      EXPECT_EQ(c.number_of_clusters(), k);
      EXPECT_EQ(SAS::rand_index(c.labels(), levels[16 - k]), 1.0)
        << "seed " << seed << ", " << k << " clusters";
    }
    // The recorded change of J of the first merge is the smallest over all edges.
    SAI::Normalized_cut_clustering c(g.size, g.source, g.target, g.weight);
    double best = std::numeric_limits<double>::infinity();
    for(std::size_t e = 0; e < g.source.size(); ++e)
      best = (std::min)(best, c.delta(g.source[e], g.target[e], g.weight[e]));
    c.run(15);
    ASSERT_EQ(c.merges().size(), 1u);
    EXPECT_DOUBLE_EQ(c.merges()[0].delta, best);
  }
}

TEST(NormalizedCutClustering, CanMergeConstraintIsHonoured)
{
  // A path 0-1-...-9; nodes 0 and 9 must not end in the same cluster (cannot-link tracked through
  // on_merge), and node 5 must stay alone.
  Small_graph g;
  g.size.assign(10, 1.0);
  for(std::uint32_t u = 0; u + 1 < 10; ++u)
    g.edge(u, u + 1, 1.0);
  SAI::Normalized_cut_clustering c(g.size, g.source, g.target, g.weight);
  std::vector<char> has0(10, 0), has9(10, 0);
  has0[0] = 1;
  has9[9] = 1;
  std::size_t calls = 0;
  auto can_merge = [&](std::uint32_t a, std::uint32_t b) {
    EXPECT_TRUE(c.is_cluster(a));
    EXPECT_TRUE(c.is_cluster(b));
    if(a == 5 || b == 5)
      return false;
    return !((has0[a] && has9[b]) || (has9[a] && has0[b]));
  };
  auto on_merge = [&](std::uint32_t survivor, std::uint32_t absorbed) {
    ++calls;
    EXPECT_TRUE(c.is_cluster(survivor));
    EXPECT_FALSE(c.is_cluster(absorbed));
    has0[survivor] = has0[survivor] || has0[absorbed];
    has9[survivor] = has9[survivor] || has9[absorbed];
  };
  c.run(1, can_merge, on_merge);
  // Node 5 alone cuts the path: {0..4}, {5}, {6..9}.
  EXPECT_EQ(c.number_of_clusters(), 3u);
  EXPECT_EQ(calls, 7u);
  EXPECT_EQ(c.merges().size(), 7u);
  EXPECT_NE(c.find(0), c.find(9));
  EXPECT_EQ(c.find(5), 5u);
  for(std::uint32_t u = 1; u < 5; ++u)
    EXPECT_EQ(c.find(u), c.find(0));
  for(std::uint32_t u = 6; u < 9; ++u)
    EXPECT_EQ(c.find(u), c.find(9));

  // Without node 5's constraint, the cannot-link alone stops at 2 clusters.
  SAI::Normalized_cut_clustering d(g.size, g.source, g.target, g.weight);
  std::fill(has0.begin(), has0.end(), 0);
  std::fill(has9.begin(), has9.end(), 0);
  has0[0] = has9[9] = 1;
  d.run(1,
        [&](std::uint32_t a, std::uint32_t b) { return !((has0[a] && has9[b]) || (has9[a] && has0[b])); },
        [&](std::uint32_t s, std::uint32_t t) {
          has0[s] = has0[s] || has0[t];
          has9[s] = has9[s] || has9[t];
        });
  EXPECT_EQ(d.number_of_clusters(), 2u);
  EXPECT_NE(d.find(0), d.find(9));
}

TEST(NormalizedCutClustering, RandomizedChoiceDependsOnlyOnTheSeed)
{
  const Small_graph g = random_grid(12, 17);
  auto run = [&](double randomness, unsigned seed) {
    SAI::Normalized_cut_clustering c(g.size, g.source, g.target, g.weight);
    c.run(6, {}, {}, randomness, seed);
    EXPECT_EQ(c.number_of_clusters(), 6u);
    return c.labels();
  };
  const auto a = run(1.0, 5);
  EXPECT_EQ(run(1.0, 5), a) << "same seed, same result";
  std::set<std::vector<std::size_t>> distinct;
  for(unsigned seed = 1; seed <= 8; ++seed)
    distinct.insert(run(1.0, seed));
  EXPECT_GE(distinct.size(), 3u) << "different seeds give different clusterings";
  // Without randomness the seed does not matter, and the result is the greedy one.
  const auto greedy = run(0.0, 1);
  EXPECT_EQ(run(0.0, 99), greedy);
  // A tiny randomness keeps the greedy choice when the changes of J are well apart.
  const Small_graph cliques = two_cliques();
  SAI::Normalized_cut_clustering c(cliques.size, cliques.source, cliques.target, cliques.weight);
  c.run(2, {}, {}, 1e-3, 42);
  EXPECT_NE(c.find(0), c.find(7));
}

TEST(NormalizedCutClustering, MergeGroupsActAsMustLink)
{
  // A path 0..9 whose cheapest edges are 1-2, 3-4, 5-6, 7-8 (the pairs' boundaries), grouped in
  // pairs {0,1}, {2,3}, ... by labels: the pairs must never be split.
  Small_graph g;
  g.size.assign(10, 1.0);
  for(std::uint32_t u = 0; u + 1 < 10; ++u)
    g.edge(u, u + 1, u % 2 == 1 ? 0.05 : 1.0);
  SAI::Normalized_cut_clustering c(g.size, g.source, g.target, g.weight);
  std::vector<int> groups(10);
  for(std::size_t i = 0; i < 10; ++i)
    groups[i] = 100 - int(i / 2); // arbitrary label values
  c.merge_groups(groups);
  EXPECT_EQ(c.number_of_clusters(), 5u);
  EXPECT_EQ(c.merges().size(), 5u);
  for(std::uint32_t i = 0; i < 10; i += 2) {
    EXPECT_EQ(c.find(i), c.find(i + 1));
    EXPECT_NEAR(c.cluster_size(c.find(i)), 2.0, 1e-12);
  }
  c.run(2);
  EXPECT_EQ(c.number_of_clusters(), 2u);
  const auto labels = c.labels();
  for(std::size_t i = 0; i < 10; i += 2)
    EXPECT_EQ(labels[i], labels[i + 1]);
  // The two clusters are contiguous runs of pairs.
  std::size_t changes = 0;
  for(std::size_t i = 0; i + 1 < 10; ++i)
    changes += labels[i] != labels[i + 1] ? 1 : 0;
  EXPECT_EQ(changes, 1u);
}

TEST(NormalizedCutClustering, SmallClustersMergeFirst)
{
  // A and B (size 1) joined by a strong edge, a speck T (tiny size) hanging on A by a near-zero
  // edge. Plain greedy merges A and B and leaves the speck alone; with small_size the speck goes
  // first.
  Small_graph g;
  g.size = {1.0, 1.0, 1e-6};
  g.edge(0, 1, 1.0);
  g.edge(0, 2, 1e-9);
  SAI::Normalized_cut_clustering plain(g.size, g.source, g.target, g.weight);
  plain.run(2);
  EXPECT_EQ(plain.find(0), plain.find(1));
  EXPECT_NE(plain.find(2), plain.find(0));
  SAI::Normalized_cut_clustering small(g.size, g.source, g.target, g.weight);
  small.run(2, {}, {}, 0.0, 0, 1e-3);
  EXPECT_EQ(small.find(2), small.find(0));
  EXPECT_NE(small.find(0), small.find(1));
}

TEST(NormalizedCutClustering, DisconnectedGraphStopsWhenNoPairIsLeft)
{
  Small_graph g;
  g.size.assign(4, 1.0);
  g.edge(0, 1, 1.0);
  g.edge(2, 3, 1.0);
  SAI::Normalized_cut_clustering c(g.size, g.source, g.target, g.weight);
  c.run(1);
  EXPECT_EQ(c.number_of_clusters(), 2u);
  EXPECT_EQ(c.labels(), (std::vector<std::size_t>{0, 0, 1, 1}));
}

// ---------------------------------------------------------------------------------------------
// Partition refinement

double normalized_cut(const std::vector<double>& size, const std::vector<std::uint32_t>& source,
                      const std::vector<std::uint32_t>& target, const std::vector<double>& weight,
                      const std::vector<std::size_t>& labels)
{
  std::map<std::size_t, double> cut, area;
  for(std::size_t i = 0; i < size.size(); ++i)
    area[labels[i]] += size[i];
  for(std::size_t e = 0; e < source.size(); ++e)
    if(labels[source[e]] != labels[target[e]]) {
      cut[labels[source[e]]] += weight[e];
      cut[labels[target[e]]] += weight[e];
    }
  double j = 0;
  for(const auto& c : cut)
    j += c.second / area[c.first];
  return j;
}

TEST(PartitionRefinement, NeverIncreasesTheNormalizedCut)
{
  for(std::uint64_t seed : {7u, 8u, 9u}) {
    const Small_graph g = random_grid(10, seed);
    SAI::Normalized_cut_clustering c(g.size, g.source, g.target, g.weight);
    c.run(4);
    std::vector<std::size_t> labels = c.labels();
    const double before = normalized_cut(g.size, g.source, g.target, g.weight, labels);
    SAI::multilevel_refinement(g.size, g.source, g.target, g.weight, c.merges(), labels);
    const double after = normalized_cut(g.size, g.source, g.target, g.weight, labels);
    EXPECT_LE(after, before + 1e-12) << "seed " << seed;
    std::set<std::size_t> used(labels.begin(), labels.end());
    EXPECT_EQ(used.size(), 4u) << "no segment disappears";
  }
  // A path whose greedy boundary is off by one node gets straightened: 0-1-2-3 | 4-5 with the
  // cheap edge between 2 and 3.
  Small_graph p;
  p.size.assign(6, 1.0);
  const double w[5] = {1, 1, 0.01, 1, 1};
  for(std::uint32_t u = 0; u < 5; ++u)
    p.edge(u, u + 1, w[u]);
  std::vector<std::size_t> labels = {0, 0, 0, 0, 1, 1};
  SAI::Weighted_graph q = SAI::quotient_graph(p.size, p.source, p.target, p.weight,
                                              {0, 1, 2, 3, 4, 5}, 6);
  std::vector<std::size_t> segment = labels;
  EXPECT_GE(SAI::move_units(q, segment, 2, 8), 1u);
  EXPECT_EQ(segment, (std::vector<std::size_t>{0, 0, 0, 1, 1, 1}));
}

} // namespace
