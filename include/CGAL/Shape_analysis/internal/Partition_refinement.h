// Copyright (c) 2026 CGAL Global Shape Analysis contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_SHAPE_ANALYSIS_INTERNAL_PARTITION_REFINEMENT_H
#define CGAL_SHAPE_ANALYSIS_INTERNAL_PARTITION_REFINEMENT_H

// Multilevel refinement of a partition under the area-normalized cut
//   J = sum over segments S of cut(S) / size(S).
// The merge history of the agglomerative clustering gives nested coarser partitions of the
// nodes. From the coarsest level to the nodes themselves, every unit (a cluster of that level) is
// moved to a neighbouring segment whenever that lowers J; moving whole clusters at coarse levels
// lets a large misplaced region change sides, the finer levels then straighten the boundaries.

#include <CGAL/Shape_analysis/internal/Normalized_cut_clustering.h>
#include <CGAL/Shape_analysis/internal/Union_find.h>

#include <algorithm>
#include <cstdint>
#include <numeric>
#include <vector>

namespace CGAL {
namespace Shape_analysis {
namespace internal {

// A weighted graph in compressed rows.
struct Weighted_graph
{
  std::vector<double> size;
  std::vector<std::size_t> first;
  std::vector<std::uint32_t> target;
  std::vector<double> weight;

  std::size_t number_of_nodes() const { return size.size(); }
};

// Graph of the units `unit_of[i]` (0..m-1) of the nodes of a graph given by its edges.
inline Weighted_graph quotient_graph(const std::vector<double>& node_size,
                                     const std::vector<std::uint32_t>& source,
                                     const std::vector<std::uint32_t>& target,
                                     const std::vector<double>& weight,
                                     const std::vector<std::uint32_t>& unit_of, std::size_t m)
{
  Weighted_graph q;
  q.size.assign(m, 0.0);
  for(std::size_t i = 0; i < node_size.size(); ++i)
    q.size[unit_of[i]] += node_size[i];
  std::vector<std::pair<std::uint64_t, double>> arcs;
  arcs.reserve(2 * source.size());
  for(std::size_t e = 0; e < source.size(); ++e) {
    const std::uint32_t a = unit_of[source[e]], b = unit_of[target[e]];
    if(a == b)
      continue;
    arcs.emplace_back((std::uint64_t(a) << 32) | b, weight[e]);
    arcs.emplace_back((std::uint64_t(b) << 32) | a, weight[e]);
  }
  std::sort(arcs.begin(), arcs.end(),
            [](const auto& x, const auto& y) { return x.first < y.first; });
  q.first.assign(m + 1, 0);
  for(std::size_t i = 0; i < arcs.size(); ++i) {
    if(i > 0 && arcs[i].first == arcs[i - 1].first) {
      q.weight.back() += arcs[i].second;
      continue;
    }
    const std::uint32_t a = static_cast<std::uint32_t>(arcs[i].first >> 32);
    ++q.first[a + 1];
    q.target.push_back(static_cast<std::uint32_t>(arcs[i].first & 0xffffffffu));
    q.weight.push_back(arcs[i].second);
  }
  std::partial_sum(q.first.begin(), q.first.end(), q.first.begin());
  return q;
}

// Greedy moves of single units between segments while J decreases; `segment[u]` in 0..k-1.
// A unit is only moved if its segment keeps other units (no segment disappears).
inline std::size_t move_units(const Weighted_graph& g, std::vector<std::size_t>& segment,
                              std::size_t k, std::size_t passes)
{
  const std::size_t m = g.number_of_nodes();
  std::vector<double> cut(k, 0.0), size(k, 0.0);
  std::vector<std::size_t> count(k, 0);
  for(std::size_t u = 0; u < m; ++u) {
    size[segment[u]] += g.size[u];
    ++count[segment[u]];
    for(std::size_t a = g.first[u]; a < g.first[u + 1]; ++a)
      if(segment[g.target[a]] != segment[u])
        cut[segment[u]] += g.weight[a];
  }
  std::size_t total_moves = 0;
  std::vector<std::pair<std::size_t, double>> around;
  for(std::size_t pass = 0; pass < passes; ++pass) {
    std::size_t moved = 0;
    for(std::size_t u = 0; u < m; ++u) {
      const std::size_t a = segment[u];
      if(count[a] <= 1)
        continue;
      around.clear();
      double total = 0, to_a = 0;
      for(std::size_t arc = g.first[u]; arc < g.first[u + 1]; ++arc) {
        const std::size_t l = segment[g.target[arc]];
        const double w = g.weight[arc];
        total += w;
        if(l == a) {
          to_a += w;
          continue;
        }
        auto it = std::find_if(around.begin(), around.end(),
                               [l](const std::pair<std::size_t, double>& x) { return x.first == l; });
        if(it == around.end())
          around.emplace_back(l, w);
        else
          it->second += w;
      }
      if(around.empty())
        continue;
      const double su = g.size[u];
      const double new_size_a = size[a] - su;
      if(!(new_size_a > 0))
        continue;
      const double new_cut_a = cut[a] - (total - to_a) + to_a;
      const double before_a = cut[a] / size[a];
      double best = 0;
      std::size_t best_b = a;
      double best_cut_b = 0;
      for(const auto& nb : around) {
        const std::size_t b = nb.first;
        const double new_cut_b = cut[b] - nb.second + (total - nb.second);
        const double before = before_a + cut[b] / size[b];
        const double change = new_cut_a / new_size_a + new_cut_b / (size[b] + su) - before;
        if(change < best && change < -1e-12 * before) {
          best = change;
          best_b = b;
          best_cut_b = new_cut_b;
        }
      }
      if(best_b == a)
        continue;
      cut[a] = (std::max)(0.0, new_cut_a);
      cut[best_b] = (std::max)(0.0, best_cut_b);
      size[a] = new_size_a;
      size[best_b] += su;
      --count[a];
      ++count[best_b];
      segment[u] = best_b;
      ++moved;
    }
    total_moves += moved;
    if(moved == 0)
      break;
  }
  return total_moves;
}

// Refines `labels` (0..k-1, one per node) with the units of the merge history of `clustering`
// (which was run on the same nodes and edges), at levels of about k * growth^j units.
inline void multilevel_refinement(const std::vector<double>& node_size,
                                  const std::vector<std::uint32_t>& source,
                                  const std::vector<std::uint32_t>& target,
                                  const std::vector<double>& weight,
                                  const std::vector<Normalized_cut_clustering::Merge>& merges,
                                  std::vector<std::size_t>& labels, std::size_t passes = 8,
                                  double growth = 4.0)
{
  const std::size_t n = node_size.size();
  std::size_t k = 0;
  for(std::size_t l : labels)
    k = (std::max)(k, l + 1);
  if(n == 0 || k < 2)
    return;
  // Levels, coarsest first: number of units m; the partition with m units is the one reached
  // after the first (n - m) merges (merges never undo each other).
  std::vector<std::size_t> levels;
  for(double m = double(k) * growth; m < double(n); m *= growth)
    levels.push_back(static_cast<std::size_t>(m));
  levels.push_back(n);
  std::vector<std::uint32_t> unit_of(n);
  Union_find sets;
  for(std::size_t m : levels) {
    if(m > n || n - m > merges.size())
      continue;
    sets.reset(n);
    for(std::size_t j = 0; j < n - m; ++j)
      sets.absorb(merges[j].survivor, merges[j].absorbed);
    // Dense unit ids; the segment of a unit is the label of its nodes (units are nested in
    // segments at the first level, and move as a whole afterwards).
    sets.dense_labels(unit_of);
    // A unit may straddle segments after finer moves of an earlier level: split it by segment.
    std::vector<std::uint64_t> key(n);
    for(std::size_t i = 0; i < n; ++i)
      key[i] = (std::uint64_t(unit_of[i]) << 32) | labels[i];
    std::vector<std::uint64_t> keys(key);
    std::sort(keys.begin(), keys.end());
    keys.erase(std::unique(keys.begin(), keys.end()), keys.end());
    for(std::size_t i = 0; i < n; ++i)
      unit_of[i] = static_cast<std::uint32_t>(std::lower_bound(keys.begin(), keys.end(), key[i]) -
                                              keys.begin());
    const std::size_t units = keys.size();
    std::vector<std::size_t> segment(units);
    for(std::size_t u = 0; u < units; ++u)
      segment[u] = static_cast<std::size_t>(keys[u] & 0xffffffffu);
    const Weighted_graph q = quotient_graph(node_size, source, target, weight, unit_of, units);
    if(move_units(q, segment, k, passes) == 0)
      continue;
    for(std::size_t i = 0; i < n; ++i)
      labels[i] = segment[unit_of[i]];
  }
}

} // namespace internal
} // namespace Shape_analysis
} // namespace CGAL

#endif // CGAL_SHAPE_ANALYSIS_INTERNAL_PARTITION_REFINEMENT_H
