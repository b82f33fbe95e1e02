// Copyright (c) 2026 CGAL Global Shape Analysis contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_RANDOMIZED_CUTS_INTERNAL_CONSISTENT_CUTS_H
#define CGAL_RANDOMIZED_CUTS_INTERNAL_CONSISTENT_CUTS_H

// Consistency of sampled cuts and the ranked list of distinct cuts (mesh independent).
//
// The consistency of a sampled segmentation is the length-weighted mean of the partition
// function over the mesh edges it cuts: a cut that many other samples agree with scores high.
// Distinct cuts: samples are taken from the most consistent down; a sample that cuts exactly the
// same edges as a kept cut, or (two-sided cuts) whose smaller side differs from a kept cut's by
// at most `duplicate_fraction` of the smaller of the two sides' areas, is counted as that cut.

#include <CGAL/Randomized_cuts/internal/Cut_sampling.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numeric>
#include <vector>

namespace CGAL {
namespace Randomized_cuts {
namespace internal {

// Length-weighted mean of `values` over the mesh edges of `cut_edges` (the plain mean over every
// cut edge when none is a mesh edge).
inline double cut_consistency(const Dual_graph& g, const std::vector<std::uint32_t>& cut_edges,
                              const std::vector<double>& values, double* length = nullptr)
{
  double sum = 0, total = 0, plain = 0;
  for(std::uint32_t e : cut_edges) {
    plain += values[e];
    if(g.mesh_edge[e] == Dual_graph::no_mesh_edge)
      continue;
    sum += g.edge_length[e] * values[e];
    total += g.edge_length[e];
  }
  if(length != nullptr)
    *length = total;
  if(total > 0)
    return sum / total;
  return cut_edges.empty() ? 0.0 : plain / double(cut_edges.size());
}

// Nodes on the side of `start` of a cut (not crossing `cut` edges), sorted.
inline void side_of(const Dual_graph& g, std::uint32_t start, const std::vector<char>& is_cut,
                    std::vector<std::uint32_t>& side, std::vector<char>& seen)
{
  seen.assign(g.number_of_nodes(), 0);
  side.clear();
  side.push_back(start);
  seen[start] = 1;
  for(std::size_t k = 0; k < side.size(); ++k) {
    const std::uint32_t u = side[k];
    for(std::size_t a = g.first_arc[u]; a < g.first_arc[u + 1]; ++a) {
      const std::uint32_t v = g.arc_target[a];
      if(!seen[v] && !is_cut[g.arc_edge[a]]) {
        seen[v] = 1;
        side.push_back(v);
      }
    }
  }
  std::sort(side.begin(), side.end());
}

struct Graph_cut
{
  std::vector<std::uint32_t> cut_edges;    // sorted graph edges
  std::vector<std::uint32_t> smaller_side; // two-sided cuts: nodes of the side of smaller size
  bool two_sided = false;
  double consistency = 0;
  double length = 0;       // total length of the mesh edges cut
  double score = 0;        // J of the sampled segmentation
  double smaller_size = 0; // size of the smaller side
  std::size_t occurrences = 0;
  std::size_t first_sample = 0; // index of the sample it comes from
};

// Index of the most consistent sample (ties: lower J, then lower index).
inline std::size_t most_consistent_sample(const Dual_graph& g, const std::vector<Sample>& samples,
                                          const std::vector<double>& values, std::size_t scale,
                                          double* consistency = nullptr)
{
  std::size_t best = 0;
  double best_c = -1, best_j = 0;
  for(std::size_t i = 0; i < samples.size(); ++i) {
    const Sampled_cut& c = samples[i].scales[scale];
    const double ci = cut_consistency(g, c.cut_edges, values);
    if(ci > best_c || (ci == best_c && c.score < best_j)) {
      best = i;
      best_c = ci;
      best_j = c.score;
    }
  }
  if(consistency != nullptr)
    *consistency = best_c;
  return best;
}

// Both sides of a min-cut sample: `side` (0 on the source side, 1 on the other).
inline void two_sides(const Dual_graph& g, const Sample& sample, std::size_t scale,
                      std::vector<char>& side)
{
  std::vector<char> is_cut(g.number_of_edges(), 0);
  for(std::uint32_t e : sample.scales[scale].cut_edges)
    is_cut[e] = 1;
  std::vector<std::uint32_t> source_side;
  std::vector<char> seen;
  side_of(g, sample.source, is_cut, source_side, seen);
  side.assign(g.number_of_nodes(), 1);
  for(std::uint32_t i : source_side)
    side[i] = 0;
}

// The smaller side of the two-sided cut of `cut_edges` (the side of `source` or its complement,
// sorted) and its size, in `candidate`. `is_cut` (all 0, one per graph edge) is left as it was given;
// `side` and `seen` are scratch.
inline void set_smaller_side(const Dual_graph& g, std::uint32_t source,
                             const std::vector<std::uint32_t>& cut_edges, double total_size,
                             std::vector<char>& is_cut, std::vector<std::uint32_t>& side,
                             std::vector<char>& seen, Graph_cut& candidate)
{
  for(std::uint32_t e : cut_edges)
    is_cut[e] = 1;
  side_of(g, source, is_cut, side, seen);
  for(std::uint32_t e : cut_edges)
    is_cut[e] = 0;
  double size = 0;
  for(std::uint32_t v : side)
    size += g.node_size[v];
  if(2 * size <= total_size) {
    candidate.smaller_side = side;
    candidate.smaller_size = size;
  } else {
    // The complement, sorted.
    candidate.smaller_side.clear();
    std::size_t k = 0;
    for(std::uint32_t v = 0; v < g.number_of_nodes(); ++v) {
      if(k < side.size() && side[k] == v) {
        ++k;
        continue;
      }
      candidate.smaller_side.push_back(v);
    }
    candidate.smaller_size = total_size - size;
  }
}

// Whether the two-sided cut `candidate` (whose edges differ from those of `kept`) counts as `kept`:
// the smaller sides, or one and the other's complement, differ by at most `duplicate_fraction` of
// the smaller of the two sides' sizes.
inline bool same_two_sided_cut(const Dual_graph& g, const Graph_cut& kept, const Graph_cut& candidate,
                               double total_size, double duplicate_fraction)
{
  const double limit =
    duplicate_fraction * (std::min)(kept.smaller_size, candidate.smaller_size);
  // The symmetric difference of the smaller sides is at least their size difference; with
  // the sides swapped, at least the difference of one with the other's complement.
  const double direct_bound = std::abs(kept.smaller_size - candidate.smaller_size);
  const double swapped_bound =
    std::abs(kept.smaller_size - (total_size - candidate.smaller_size));
  if(direct_bound > limit && swapped_bound > limit)
    return false;
  double common = 0;
  auto a = kept.smaller_side.begin(), b = candidate.smaller_side.begin();
  while(a != kept.smaller_side.end() && b != candidate.smaller_side.end()) {
    if(*a < *b)
      ++a;
    else if(*b < *a)
      ++b;
    else {
      common += g.node_size[*a];
      ++a;
      ++b;
    }
  }
  const double difference = kept.smaller_size + candidate.smaller_size - 2 * common;
  // Swapped: kept's side against the complement of the candidate's.
  const double swapped = total_size - difference;
  // Sides of zero area (degenerate faces) are only duplicates when they are the same faces.
  return limit > 0 ? (std::min)(difference, swapped) <= limit
                   : kept.smaller_side == candidate.smaller_side;
}

// The distinct cuts of the samples, most consistent first.
inline std::vector<Graph_cut> distinct_cuts(const Dual_graph& g, const std::vector<Sample>& samples,
                                            const std::vector<double>& values, std::size_t scale,
                                            bool two_sided, double duplicate_fraction)
{
  const std::size_t count = samples.size();
  std::vector<double> consistency(count), length(count);
  for(std::size_t i = 0; i < count; ++i)
    consistency[i] = cut_consistency(g, samples[i].scales[scale].cut_edges, values, &length[i]);
  std::vector<std::size_t> order(count);
  std::iota(order.begin(), order.end(), std::size_t(0));
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    if(consistency[a] != consistency[b])
      return consistency[a] > consistency[b];
    const double ja = samples[a].scales[scale].score, jb = samples[b].scales[scale].score;
    if(ja != jb)
      return ja < jb;
    return a < b;
  });
  const double total_size = g.total_size();
  std::vector<Graph_cut> result;
  std::vector<char> is_cut(g.number_of_edges(), 0), seen;
  std::vector<std::uint32_t> side;
  for(std::size_t i : order) {
    const Sampled_cut& c = samples[i].scales[scale];
    Graph_cut candidate;
    candidate.cut_edges = c.cut_edges;
    candidate.two_sided = two_sided;
    if(two_sided)
      set_smaller_side(g, samples[i].source, c.cut_edges, total_size, is_cut, side, seen, candidate);
    // A duplicate of a kept cut?
    bool merged = false;
    for(Graph_cut& kept : result) {
      if(kept.cut_edges == candidate.cut_edges)
        merged = true;
      else if(two_sided)
        merged = same_two_sided_cut(g, kept, candidate, total_size, duplicate_fraction);
      if(merged) {
        ++kept.occurrences;
        break;
      }
    }
    if(merged)
      continue;
    candidate.consistency = consistency[i];
    candidate.length = length[i];
    candidate.score = c.score;
    candidate.occurrences = 1;
    candidate.first_sample = i;
    result.push_back(std::move(candidate));
  }
  return result;
}

} // namespace internal
} // namespace Randomized_cuts
} // namespace CGAL

#endif // CGAL_RANDOMIZED_CUTS_INTERNAL_CONSISTENT_CUTS_H
