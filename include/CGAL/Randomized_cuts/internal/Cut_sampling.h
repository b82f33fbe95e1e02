// Copyright (c) 2026 CGAL Global Shape Analysis contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_RANDOMIZED_CUTS_INTERNAL_CUT_SAMPLING_H
#define CGAL_RANDOMIZED_CUTS_INTERNAL_CUT_SAMPLING_H

// Random segmentations of a dual graph and the partition function they define (mesh independent).
//
// A sample is drawn by one of three samplers:
//  - min-cut: source and sink faces drawn by area; traversal-cost distances dA, dB from both;
//    every graph edge's cut cost is multiplied by the penalty W(d) of its relative distance
//    d = min(dA, dB) / (dA + dB): W = 400 s + 1 for d <= s, falling linearly to 1 at d = 3 s,
//    1 beyond (s: part size); then the minimum s-t cut. Several part sizes share the seeds and
//    the distances (one cut each: the multi-scale partition function);
//  - K-means: K seed faces drawn by area; faces go to the nearest seed (traversal cost); every
//    seed moves to the face of its segment furthest from the segment's boundary; until the seeds
//    stop moving;
//  - hierarchical: normalized-cut merging with randomness r; the run contributes its
//    segmentations into 2 .. K segments.
// Sample i draws only from its own random stream (seed, i), and samples are added up in the order
// of their indices, batch after batch: the result does not depend on the number of threads. The
// partition function of a graph edge is the weighted fraction of the sampled segmentations that
// cut it (weights 1, or 1 / J with the score-weighted option, J = sum over segments of
// cut(S) / size(S) under the plain cut costs).

#include <CGAL/Randomized_cuts/Partition_function_options.h>
#include <CGAL/Randomized_cuts/Sampling_method.h>
#include <CGAL/Shape_analysis/Bad_input.h>
#include <CGAL/Shape_analysis/internal/Dual_graph.h>
#include <CGAL/Shape_analysis/internal/Min_cut.h>
#include <CGAL/Shape_analysis/internal/Normalized_cut_clustering.h>
#include <CGAL/Shape_analysis/internal/Parallel.h>
#include <CGAL/Shape_analysis/internal/Random.h>
#include <CGAL/Shape_analysis/internal/Shortest_paths.h>
#include <CGAL/Shape_analysis/internal/Union_find.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>
#include <limits>
#include <numeric>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Randomized_cuts {
namespace internal {

namespace SAI = CGAL::Shape_analysis::internal;
using SAI::Dual_graph;

// What the samplers run with: the options of partition_function(), with the list of part sizes
// (min-cut; several: the multi-scale partition function; one by default: `part_size`) and whether
// each sample's cut edges are kept (for the consistency of cuts).
struct Sampling_options : Partition_function_options
{
  Sampling_options() : Sampling_options(Partition_function_options()) {}
  explicit Sampling_options(const Partition_function_options& o)
    : Partition_function_options(o), part_sizes{o.part_size}
  {}

  std::vector<double> part_sizes;
  bool keep_samples = false;
};

// Samples drawn between two convergence checks.
constexpr std::size_t sampling_batch_size = 64;
// K-means: the largest number of rounds (assignment, then seeds moved) of a sample.
constexpr std::size_t max_k_means_iterations = 30;
// Hierarchical: segments below this fraction of the total area (specks) are merged first.
constexpr double small_segment_fraction = 1e-4;

inline void check_sampling_options(const Sampling_options& o, std::size_t number_of_nodes,
                                   const std::string& who)
{
  using CGAL::Shape_analysis::Bad_input;
  if(o.sampling_method != MIN_CUT && o.sampling_method != K_MEANS && o.sampling_method != HIERARCHICAL)
    throw Bad_input(who + ": unknown sampling_method");
  if(o.number_of_samples == 0)
    throw Bad_input(who + ": number_of_samples must be at least 1");
  if(!(o.convergence_tolerance >= 0) || !std::isfinite(o.convergence_tolerance))
    throw Bad_input(who + ": convergence_tolerance must be a finite number >= 0");
  if(o.part_sizes.empty())
    throw Bad_input(who + ": part_sizes must hold at least one part size");
  for(double s : o.part_sizes)
    if(!(s > 0) || !(s <= 1.0 / 6.0))
      throw Bad_input(who + ": a part size must be in (0, 1/6], not " + std::to_string(s));
  if(o.sampling_method != MIN_CUT && o.part_sizes.size() > 1)
    throw Bad_input(who + ": several part sizes (multi-scale) need the MIN_CUT sampling_method");
  if(o.number_of_clusters < 2)
    throw Bad_input(who + ": number_of_clusters must be at least 2");
  if(!(o.randomness > 0) || !std::isfinite(o.randomness))
    throw Bad_input(who + ": randomness must be a finite number > 0");
  if(number_of_nodes < 2)
    throw Bad_input(who + ": the mesh needs at least two faces to be cut");
}

// The penalty W(d) of the min-cut sampler for relative distance d and part size s.
inline double seed_distance_penalty(double d, double s)
{
  if(d <= s)
    return 400.0 * s + 1.0;
  if(d >= 3.0 * s)
    return 1.0;
  return 1.0 + 400.0 * s * (3.0 * s - d) / (2.0 * s);
}

// One sampled segmentation: the graph edges it cuts, its weight and score.
struct Sampled_cut
{
  std::vector<std::uint32_t> cut_edges; // sorted
  double weight = 1;                    // its weight in the partition function
  double score = 0;                     // J = sum over segments of cut(S) / size(S)
};

// What one sample adds to the partition function of one scale: either every cut edge of `cut`
// with `cut.weight` (min-cut, K-means), or the (edge, amount) pairs of `amounts` (hierarchical:
// several segmentations of one run) out of a total weight `total_weight`.
struct Sample
{
  std::vector<Sampled_cut> scales; // one per part size (one for K-means and hierarchical)
  std::vector<std::pair<std::uint32_t, double>> amounts;
  double total_weight = 0;
  std::uint32_t source = 0, sink = 0; // min-cut seeds
};

// Graph edges whose nodes carry different labels, and J of the labelling (labels 0..k-1).
template <typename Label>
double cut_of_labelling(const Dual_graph& g, const std::vector<Label>& label, std::size_t k,
                        std::vector<std::uint32_t>& cut_edges, std::vector<double>& size_buffer,
                        std::vector<double>& cut_buffer)
{
  cut_edges.clear();
  size_buffer.assign(k, 0.0);
  cut_buffer.assign(k, 0.0);
  for(std::size_t i = 0; i < g.number_of_nodes(); ++i)
    size_buffer[label[i]] += g.node_size[i];
  for(std::size_t e = 0; e < g.number_of_edges(); ++e) {
    const Label a = label[g.edge_source[e]], b = label[g.edge_target[e]];
    if(a == b)
      continue;
    cut_edges.push_back(static_cast<std::uint32_t>(e));
    cut_buffer[a] += g.cut_cost[e];
    cut_buffer[b] += g.cut_cost[e];
  }
  double j = 0;
  for(std::size_t c = 0; c < k; ++c)
    if(size_buffer[c] > 0)
      j += cut_buffer[c] / size_buffer[c];
  return j;
}

// 1 / J, with J floored at 1e-9 / (bounding-box diagonal): a cut of no cost at all (zero-length
// edges only) counts as much as a very clean cut, not infinitely more.
inline double score_weight(double score, bool score_weighting, const Dual_graph& g)
{
  if(!score_weighting)
    return 1.0;
  const double floor = 1e-9 / (g.bbox_diagonal > 0 ? g.bbox_diagonal : 1.0);
  return 1.0 / (std::max)(score, floor);
}

// Faces drawn with probability proportional to their area.
class Area_sampler
{
public:
  explicit Area_sampler(const Dual_graph& g)
  {
    const std::size_t n = g.number_of_nodes();
    double total = g.total_size();
    const double floor = total > 0 ? 1e-9 * total / double(n) : 1.0;
    m_cumulative.resize(n);
    double sum = 0;
    for(std::size_t i = 0; i < n; ++i) {
      sum += (std::max)(g.node_size[i], floor);
      m_cumulative[i] = sum;
    }
  }

  std::uint32_t draw(SAI::Random_stream& rng) const
  {
    const double u = rng.uniform() * m_cumulative.back();
    const std::size_t i =
      std::upper_bound(m_cumulative.begin(), m_cumulative.end(), u) - m_cumulative.begin();
    return static_cast<std::uint32_t>((std::min)(i, m_cumulative.size() - 1));
  }

  // `count` distinct faces (count <= number of faces).
  void draw_distinct(SAI::Random_stream& rng, std::size_t count, std::vector<std::uint32_t>& out,
                     std::vector<char>& taken) const
  {
    out.clear();
    taken.assign(m_cumulative.size(), 0);
    std::size_t attempts = 0;
    while(out.size() < count) {
      std::uint32_t f = draw(rng);
      if(taken[f]) {
        // Many repeats (a few faces hold most of the area): take the next free face.
        if(++attempts < 64 * count)
          continue;
        while(taken[f])
          f = static_cast<std::uint32_t>((f + 1) % m_cumulative.size());
      }
      taken[f] = 1;
      out.push_back(f);
    }
  }

private:
  std::vector<double> m_cumulative;
};

// ---------------------------------------------------------------------------------------------

class Min_cut_sampler
{
public:
  struct Workspace
  {
    SAI::Graph_shortest_paths from_source, from_sink;
    std::vector<double> relative, capacity, size, cut;
    std::vector<char> side;
    SAI::Dual_graph_min_cut::Workspace flow;
    std::vector<std::uint32_t> pair;
    std::vector<char> taken;
  };

  Min_cut_sampler(const Dual_graph& g, const Sampling_options& o)
    : m_g(g), m_o(o), m_cut(g), m_area(g), m_order(o.part_sizes.size())
  {
    std::iota(m_order.begin(), m_order.end(), std::size_t(0));
    std::stable_sort(m_order.begin(), m_order.end(), [&](std::size_t x, std::size_t y) {
      return o.part_sizes[x] < o.part_sizes[y];
    });
  }

  void draw(std::size_t index, Workspace& w, Sample& out) const
  {
    const Dual_graph& g = m_g;
    SAI::Random_stream rng(m_o.random_seed, index);
    m_area.draw_distinct(rng, 2, w.pair, w.taken);
    const std::uint32_t a = w.pair[0], b = w.pair[1];
    out.source = a;
    out.sink = b;
    w.from_source.run(g, g.traversal_cost, a);
    w.from_sink.run(g, g.traversal_cost, b);
    const std::size_t m = g.number_of_edges();
    w.relative.resize(m);
    for(std::size_t e = 0; e < m; ++e) {
      const std::uint32_t u = g.edge_source[e], v = g.edge_target[e];
      const double da = 0.5 * (w.from_source.distance(u) + w.from_source.distance(v));
      const double db = 0.5 * (w.from_sink.distance(u) + w.from_sink.distance(v));
      const double sum = da + db;
      w.relative[e] = (sum > 0 && std::isfinite(sum)) ? (std::min)(da, db) / sum : 0.5;
    }
    out.scales.resize(m_o.part_sizes.size());
    w.capacity.resize(m);
    w.side.resize(g.number_of_nodes());
    // Part sizes in increasing order: the penalty only grows with the part size, so each cut
    // continues from the flow of the previous one.
    for(std::size_t rank = 0; rank < m_order.size(); ++rank) {
      const std::size_t k = m_order[rank];
      const double s = m_o.part_sizes[k];
      for(std::size_t e = 0; e < m; ++e)
        w.capacity[e] = g.cut_cost[e] * seed_distance_penalty(w.relative[e], s);
      if(rank == 0)
        m_cut.solve(w.capacity, a, b, w.flow);
      else
        m_cut.solve_with_larger_capacities(w.capacity, a, b, w.flow);
      for(std::size_t i = 0; i < g.number_of_nodes(); ++i)
        w.side[i] = SAI::Dual_graph_min_cut::is_source_side(w.flow, i) ? 0 : 1;
      Sampled_cut& c = out.scales[k];
      c.score = cut_of_labelling(g, w.side, 2, c.cut_edges, w.size, w.cut);
      c.weight = score_weight(c.score, m_o.score_weighting, g);
    }
    out.total_weight = 0;
  }

private:
  const Dual_graph& m_g;
  const Sampling_options& m_o;
  SAI::Dual_graph_min_cut m_cut;
  Area_sampler m_area;
  std::vector<std::size_t> m_order; // part sizes, smallest first
};

// ---------------------------------------------------------------------------------------------

class K_means_sampler
{
public:
  struct Workspace
  {
    SAI::Graph_shortest_paths assign, depth;
    std::vector<std::uint32_t> seeds, new_seeds, seed_labels, boundary;
    std::vector<double> inside_length, best_depth, size, cut;
    std::vector<char> taken;
  };

  K_means_sampler(const Dual_graph& g, const Sampling_options& o) : m_g(g), m_o(o), m_area(g) {}

  void draw(std::size_t index, Workspace& w, Sample& out) const
  {
    const Dual_graph& g = m_g;
    const std::size_t n = g.number_of_nodes(), m = g.number_of_edges();
    const std::size_t k = (std::min)(m_o.number_of_clusters, n);
    SAI::Random_stream rng(m_o.random_seed, index);
    m_area.draw_distinct(rng, k, w.seeds, w.taken);
    w.seed_labels.resize(k);
    std::iota(w.seed_labels.begin(), w.seed_labels.end(), 0u);
    w.inside_length.resize(m);
    for(std::size_t iteration = 0;; ++iteration) {
      w.assign.run(g, g.traversal_cost, w.seeds, w.seed_labels);
      if(iteration + 1 >= max_k_means_iterations)
        break;
      // Depth of every face in its segment: distance from the segment's boundary faces, without
      // leaving the segment.
      w.boundary.clear();
      for(std::size_t e = 0; e < m; ++e) {
        const std::uint32_t u = g.edge_source[e], v = g.edge_target[e];
        const bool inside = w.assign.label(u) == w.assign.label(v);
        w.inside_length[e] = inside ? g.traversal_cost[e] : SAI::Graph_shortest_paths::infinity;
        if(!inside) {
          w.boundary.push_back(u);
          w.boundary.push_back(v);
        }
      }
      w.depth.run(g, w.inside_length, w.boundary);
      w.new_seeds = w.seeds;
      w.best_depth.assign(k, -1.0);
      for(std::uint32_t i = 0; i < n; ++i) {
        const std::uint32_t l = w.assign.label(i);
        if(l == SAI::Graph_shortest_paths::no_label)
          continue;
        const double d = w.depth.distance(i);
        if(std::isfinite(d) && d > w.best_depth[l]) {
          w.best_depth[l] = d;
          w.new_seeds[l] = i;
        }
      }
      if(w.new_seeds == w.seeds)
        break;
      w.seeds.swap(w.new_seeds);
    }
    // Faces no seed reaches (another component with no link; not in a linked graph): segment 0.
    std::vector<std::uint32_t>& label = w.new_seeds;
    label.resize(n);
    for(std::size_t i = 0; i < n; ++i) {
      const std::uint32_t l = w.assign.label(i);
      label[i] = l == SAI::Graph_shortest_paths::no_label ? 0 : l;
    }
    out.scales.resize(1);
    Sampled_cut& c = out.scales[0];
    c.score = cut_of_labelling(g, label, k, c.cut_edges, w.size, w.cut);
    c.weight = score_weight(c.score, m_o.score_weighting, g);
    out.total_weight = 0;
  }

private:
  const Dual_graph& m_g;
  const Sampling_options& m_o;
  Area_sampler m_area;
};

// ---------------------------------------------------------------------------------------------

class Hierarchical_sampler
{
public:
  struct Workspace
  {
    SAI::Union_find sets;
    std::vector<std::uint32_t> dense, label;
    std::vector<double> size, cut;
    std::vector<char> cut_at;
  };

  Hierarchical_sampler(const Dual_graph& g, const Sampling_options& o) : m_g(g), m_o(o) {}

  void draw(std::size_t index, Workspace& w, Sample& out) const
  {
    const Dual_graph& g = m_g;
    const std::size_t n = g.number_of_nodes();
    const std::size_t k_max = (std::min)(m_o.number_of_clusters, n);
    SAI::Normalized_cut_clustering clustering(g.node_size, g.edge_source, g.edge_target, g.cut_cost);
    const double small_size = small_segment_fraction * g.total_size();
    const std::uint64_t seed = SAI::Random_stream(m_o.random_seed, index).next();
    clustering.run(2, {}, {}, m_o.randomness, seed, small_size);
    const auto& merges = clustering.merges();
    // The segmentation into k_max segments (or fewer, if the graph has fewer components... it is
    // linked, so the run reaches 2 unless it is smaller).
    const std::size_t reached = n - merges.size();
    const std::size_t k_top = (std::max)(reached, k_max);
    const std::size_t head = n > k_top ? n - k_top : 0;
    w.sets.reset(n);
    for(std::size_t j = 0; j < head && j < merges.size(); ++j)
      w.sets.absorb(merges[j].survivor, merges[j].absorbed);
    const std::size_t k = w.sets.dense_labels(w.label);
    out.scales.resize(1);
    Sampled_cut& c = out.scales[0];
    c.score = cut_of_labelling(g, w.label, k, c.cut_edges, w.size, w.cut);
    c.weight = score_weight(c.score, m_o.score_weighting, g);

    coarse_levels(merges, head, k, c, w, out);
  }

private:
  // The coarser levels of draw(): the k segments of `c` merged further, as the run did, down to
  // two; every cut edge of `c` weighted by the levels at which it is still cut. Per segment the
  // cut edges it touches (those between the two segments of a merge found from the shorter list,
  // the lists then joined), and the score kept up to date: O(E log k) per sample, where a k x k
  // table of cut weights took O(k^3) time and O(k^2) memory (the cow, 5804 faces, 4 samples on
  // one thread: 2000 clusters 28.9 s -> 0.03 s, as many clusters as faces over 100 s -> 0.04 s).
  void coarse_levels(const std::vector<SAI::Normalized_cut_clustering::Merge>& merges, std::size_t head,
                     std::size_t k, const Sampled_cut& c, Workspace& w, Sample& out) const
  {
    const Dual_graph& g = m_g;
    const double not_joined = -1;
    std::vector<std::vector<std::uint32_t>> touching(k); // per segment, indices into c.cut_edges
    for(std::size_t i = 0; i < c.cut_edges.size(); ++i) {
      const std::uint32_t e = c.cut_edges[i];
      touching[w.label[g.edge_source[e]]].push_back(std::uint32_t(i));
      touching[w.label[g.edge_target[e]]].push_back(std::uint32_t(i));
    }
    std::vector<double> weight_before_join(c.cut_edges.size(), not_joined);
    SAI::Union_find coarse(k);
    std::vector<double> level_size(w.size.begin(), w.size.begin() + std::ptrdiff_t(k));
    std::vector<double> level_cut(w.cut.begin(), w.cut.begin() + std::ptrdiff_t(k));
    const auto term = [&](std::uint32_t x) { return level_size[x] > 0 ? level_cut[x] / level_size[x] : 0.0; };
    double score = 0;
    for(std::uint32_t x = 0; x < k; ++x)
      score += term(x);
    double levels = 0; // the weights of the levels after the top one, so far
    std::size_t clusters = k;
    for(std::size_t j = head; j < merges.size() && clusters > 2; ++j) {
      const std::uint32_t a = coarse.find(w.label[merges[j].survivor]);
      const std::uint32_t b = coarse.find(w.label[merges[j].absorbed]);
      if(a == b)
        continue;
      // Merge b into a: sizes, cuts (the weight between them leaves both cuts).
      std::vector<std::uint32_t>& shorter = touching[a].size() < touching[b].size() ? touching[a] : touching[b];
      double between = 0;
      for(std::uint32_t i : shorter) {
        const std::uint32_t e = c.cut_edges[i];
        const std::uint32_t x = coarse.find(w.label[g.edge_source[e]]), y = coarse.find(w.label[g.edge_target[e]]);
        if(weight_before_join[i] == not_joined && ((x == a && y == b) || (x == b && y == a))) {
          weight_before_join[i] = levels;
          between += g.cut_cost[e];
        }
      }
      score -= term(a) + term(b);
      level_cut[a] = (std::max)(0.0, level_cut[a] + level_cut[b] - 2 * between);
      level_size[a] += level_size[b];
      score += term(a);
      coarse.absorb(a, b);
      --clusters;
      std::vector<std::uint32_t>& longer = &shorter == &touching[a] ? touching[b] : touching[a];
      for(std::uint32_t i : shorter)
        if(weight_before_join[i] == not_joined)
          longer.push_back(i);
      std::vector<std::uint32_t>().swap(shorter);
      if(&longer != &touching[a])
        touching[a].swap(longer);
      levels += score_weight(score, m_o.score_weighting, g);
    }
    out.amounts.clear();
    out.amounts.reserve(c.cut_edges.size());
    for(std::size_t i = 0; i < c.cut_edges.size(); ++i)
      out.amounts.emplace_back(c.cut_edges[i],
                               c.weight + (weight_before_join[i] == not_joined ? levels : weight_before_join[i]));
    out.total_weight = c.weight + levels;
  }

private:
  const Dual_graph& m_g;
  const Sampling_options& m_o;
};

// ---------------------------------------------------------------------------------------------

struct Sampling_result
{
  std::vector<std::vector<double>> values; // per scale, per graph edge, in [0, 1]
  std::size_t number_of_samples = 0;
  bool converged = false;     // the largest change of a batch fell under the tolerance
  double largest_change = 0; // over the last batch (checked with a tolerance only)
  std::vector<Sample> samples; // with keep_samples
};

// Draws the samples and adds them up.
class Cut_sampling
{
public:
  Cut_sampling(const Dual_graph& g, const Sampling_options& o) : m_g(g), m_o(o) {}

  Sampling_result run()
  {
    switch(m_o.sampling_method) {
    case K_MEANS: return run_with<K_means_sampler>();
    case HIERARCHICAL: return run_with<Hierarchical_sampler>();
    default: return run_with<Min_cut_sampler>();
    }
  }

private:
  template <typename Sampler>
  Sampling_result run_with()
  {
    const std::size_t scales = m_o.sampling_method == MIN_CUT ? m_o.part_sizes.size() : 1;
    const std::size_t m = m_g.number_of_edges();
    Sampler sampler(m_g, m_o);
    SAI::Parallel_workspaces<typename Sampler::Workspace> workspaces(m_o.number_of_threads);
    std::vector<std::vector<double>> sum(scales, std::vector<double>(m, 0.0));
    std::vector<double> total(scales, 0.0);
    std::vector<std::vector<double>> previous;
    Sampling_result result;
    std::vector<Sample> batch;
    const std::size_t batch_size = sampling_batch_size;
    for(std::size_t begin = 0; begin < m_o.number_of_samples; begin += batch_size) {
      const std::size_t end = (std::min)(m_o.number_of_samples, begin + batch_size);
      batch.assign(end - begin, Sample());
      workspaces.for_each(begin, end, [&](std::size_t i, typename Sampler::Workspace& w) {
        sampler.draw(i, w, batch[i - begin]);
      });
      // Added in index order: the same sums for any number of threads.
      for(Sample& s : batch) {
        for(std::size_t k = 0; k < scales; ++k) {
          if(!s.amounts.empty() || s.total_weight > 0) {
            for(const auto& a : s.amounts)
              sum[k][a.first] += a.second;
            total[k] += s.total_weight;
          } else {
            const Sampled_cut& c = s.scales[k];
            for(std::uint32_t e : c.cut_edges)
              sum[k][e] += c.weight;
            total[k] += c.weight;
          }
        }
        if(m_o.keep_samples) {
          s.amounts.clear();
          s.amounts.shrink_to_fit();
          result.samples.push_back(std::move(s));
        }
      }
      result.number_of_samples = end;
      if(m_o.progress_callback)
        m_o.progress_callback(double(end) / double(m_o.number_of_samples));
      if(m_o.convergence_tolerance > 0) {
        values(sum, total, result.values);
        if(!previous.empty()) {
          double change = 0;
          for(std::size_t k = 0; k < scales; ++k)
            for(std::size_t e = 0; e < m; ++e)
              change = (std::max)(change, std::abs(result.values[k][e] - previous[k][e]));
          result.largest_change = change;
          if(change < m_o.convergence_tolerance) {
            result.converged = true;
            break;
          }
        }
        previous = result.values;
      }
    }
    values(sum, total, result.values);
    return result;
  }

  static void values(const std::vector<std::vector<double>>& sum, const std::vector<double>& total,
                     std::vector<std::vector<double>>& out)
  {
    out.resize(sum.size());
    for(std::size_t k = 0; k < sum.size(); ++k) {
      out[k].resize(sum[k].size());
      for(std::size_t e = 0; e < sum[k].size(); ++e)
        out[k][e] = total[k] > 0 ? (std::min)(1.0, sum[k][e] / total[k]) : 0.0;
    }
  }

  const Dual_graph& m_g;
  const Sampling_options& m_o;
};

} // namespace internal
} // namespace Randomized_cuts
} // namespace CGAL

#endif // CGAL_RANDOMIZED_CUTS_INTERNAL_CUT_SAMPLING_H
