// Copyright (c) 2026 CGAL Global Shape Analysis contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_RANDOMIZED_CUTS_INTERNAL_PARTITION_SEGMENTATION_H
#define CGAL_RANDOMIZED_CUTS_INTERNAL_PARTITION_SEGMENTATION_H

// Segmentation by recursive most consistent cuts (mesh independent):
//  1. the whole graph is cut along the most consistent of its sampled min-cuts;
//  2. for each new segment, the partition function is sampled again inside it (the subgraph
//     it induces), and its most consistent cut is proposed as its split, with the area-normalized
//     cut cut(A, B) (1 / size(A) + 1 / size(B)) of that split as priority;
//  3. the proposal of lowest normalized cut is applied; repeat from 2 until the requested number
//     of segments. With number_of_segments 0 the number is chosen (see automatic_crease_weight).
// Optionally the boundaries are then refined by moving single faces between segments while the
// area-normalized cut J = sum cut(S) / size(S) decreases.

#include <CGAL/Randomized_cuts/Segment_with_partition_function_options.h>
#include <CGAL/Randomized_cuts/internal/Consistent_cuts.h>
#include <CGAL/Randomized_cuts/internal/Cut_sampling.h>
#include <CGAL/Shape_analysis/defaults.h>
#include <CGAL/Shape_analysis/internal/Component_links.h>
#include <CGAL/Shape_analysis/internal/Labels.h>
#include <CGAL/Shape_analysis/internal/Partition_refinement.h>
#include <CGAL/Shape_analysis/internal/Random.h>

#include <algorithm>
#include <cstdint>
#include <functional>
#include <limits>
#include <numeric>
#include <vector>

namespace CGAL {
namespace Randomized_cuts {
namespace internal {

// The options of the segmentation. Only its own members (number_of_segments,
// boundary_refinement) are read from it: the partition functions are sampled with the sampling
// options given beside it, which hold the part size actually used.
typedef Segment_with_partition_function_options Partition_segmentation_options;

// The automatic number of segments (number_of_segments 0): the splits go on, in their usual order,
// while the cut to apply next runs along concave creases: its mean concavity weight (cut cost over
// cut length) below automatic_crease_weight, 1 where it crosses flat or convex surface. The first
// split whose cut does not, once there are automatic_minimum_segments segments, stops the
// segmentation; at most automatic_maximum_segments segments. Measured on the 152 meshes of the
// Princeton Segmentation Benchmark's development subset (see the manual).
constexpr double automatic_crease_weight = 0.8;
constexpr std::size_t automatic_minimum_segments = 4;
using CGAL::Shape_analysis::automatic_maximum_segments;

class Partition_segmentation
{
public:
  Partition_segmentation(const Dual_graph& g, const Partition_segmentation_options& o,
                         const Sampling_options& sampling)
    : m_g(g), m_o(o), m_sampling(sampling)
  {}

  // Labels 0..k-1 per node, numbered by decreasing size. `whole_values` (if not null) receives
  // the partition function of the whole graph, per graph edge.
  std::vector<std::size_t> run(std::vector<double>* whole_values = nullptr)
  {
    const std::size_t n = m_g.number_of_nodes();
    const bool automatic = m_o.number_of_segments == 0;
    const std::size_t k = (std::min)(automatic ? automatic_maximum_segments : m_o.number_of_segments, n);
    std::vector<std::size_t> label(n, 0);
    if(k <= 1 && whole_values == nullptr)
      return label; // one segment: nothing to sample
    std::vector<Proposal> proposals; // by segment label
    std::vector<std::uint32_t> all(n);
    std::iota(all.begin(), all.end(), 0u);
    m_total_steps = 2 * k; // proposals to compute, about
    m_steps_done = 0;
    proposals.push_back(propose(all, whole_values));
    std::size_t segments = 1;
    while(segments < k) {
      // The best pending proposal.
      std::size_t best = proposals.size();
      for(std::size_t s = 0; s < proposals.size(); ++s)
        if(proposals[s].valid &&
           (best == proposals.size() || proposals[s].priority < proposals[best].priority))
          best = s;
      if(best == proposals.size())
        break; // nothing left to split
      if(automatic && segments >= automatic_minimum_segments &&
         proposals[best].weight >= automatic_crease_weight)
        break; // the next cut would cross the surface rather than follow a crease
      const std::size_t new_label = segments++;
      for(std::uint32_t v : proposals[best].part)
        label[v] = new_label;
      // New proposals for both pieces.
      std::vector<std::uint32_t> kept, split;
      for(std::uint32_t v = 0; v < n; ++v) {
        if(label[v] == best)
          kept.push_back(v);
        else if(label[v] == new_label)
          split.push_back(v);
      }
      if(segments < k) {
        proposals[best] = propose(kept, nullptr);
        proposals.push_back(propose(split, nullptr));
      } else {
        proposals[best].valid = false;
      }
    }
    if(m_o.boundary_refinement && segments > 1)
      refine(label, segments);
    if(m_sampling.progress_callback)
      m_sampling.progress_callback(1.0);
    return CGAL::Shape_analysis::internal::number_by_size(label, m_g.node_size);
  }

private:
  struct Proposal
  {
    bool valid = false;
    double priority = 0;
    double weight = 0; // mean concavity weight of the cut (0 when it cuts component links only)
    std::vector<std::uint32_t> part; // the nodes that would form the new segment
  };

  // The proposed split of the segment made of `nodes` (sorted).
  Proposal propose(const std::vector<std::uint32_t>& nodes, std::vector<double>* values_out)
  {
    Proposal p;
    const std::uint64_t index = m_proposals++;
    if(nodes.size() < 2) {
      ++m_steps_done;
      return p;
    }
    Dual_graph sub;
    std::vector<std::uint32_t> parent_edge;
    SAI::induced_subgraph(m_g, nodes, sub, parent_edge);
    std::vector<std::uint32_t> component;
    const std::size_t components = SAI::graph_components(sub, component);
    if(components > 1) {
      // A segment in pieces (no edge between them): separating them costs nothing.
      for(std::size_t i = 0; i < nodes.size(); ++i)
        if(component[i] != component[0])
          p.part.push_back(nodes[i]);
      p.valid = true;
      p.priority = 0;
      ++m_steps_done;
      return p;
    }
    Sampling_options so = m_sampling;
    // The whole graph is sampled with the caller's seed (its partition function is then the one
    // partition_function() gives with MIN_CUT); every later segment with a seed of its own.
    so.random_seed = index == 0 ? m_sampling.random_seed
                                : SAI::Random_stream::mix(m_sampling.random_seed + 0x9E3779B97F4A7C15ull * index);
    so.keep_samples = true;
    const std::size_t step = m_steps_done;
    if(m_sampling.progress_callback) {
      const double total = double((std::max)(m_total_steps, step + 1));
      so.progress_callback = [this, step, total](double f) {
        m_sampling.progress_callback(0.99 * (double(step) + f) / total);
      };
    }
    const Sampling_result r = Cut_sampling(sub, so).run();
    ++m_steps_done;
    if(values_out != nullptr) {
      values_out->assign(m_g.number_of_edges(), 0.0);
      for(std::size_t e = 0; e < parent_edge.size(); ++e)
        (*values_out)[parent_edge[e]] = r.values[0][e];
    }
    const std::size_t best = most_consistent_sample(sub, r.samples, r.values[0], 0);
    std::vector<char> side;
    two_sides(sub, r.samples[best], 0, side);
    double size[2] = {0, 0}, cut = 0, length = 0, crease_cut = 0;
    for(std::size_t i = 0; i < nodes.size(); ++i)
      size[int(side[i])] += sub.node_size[i];
    for(std::size_t e = 0; e < sub.number_of_edges(); ++e)
      if(side[sub.edge_source[e]] != side[sub.edge_target[e]]) {
        cut += sub.cut_cost[e];
        if(sub.edge_length[e] > 0) { // a mesh edge, not a component link
          length += sub.edge_length[e];
          crease_cut += sub.cut_cost[e];
        }
      }
    p.weight = length > 0 ? crease_cut / length : 0;
    // The smaller side becomes the new segment. A side of zero area (degenerate faces only) gets
    // a tiny size: its split is proposed, but after every other.
    const char moving = size[1] <= size[0] ? 1 : 0;
    for(std::size_t i = 0; i < nodes.size(); ++i)
      if(side[i] == moving)
        p.part.push_back(nodes[i]);
    const double floor = 1e-9 * m_g.total_size() / double(m_g.number_of_nodes());
    p.valid = !p.part.empty() && p.part.size() < nodes.size();
    p.priority = cut * (1.0 / (std::max)(size[0], floor) + 1.0 / (std::max)(size[1], floor));
    return p;
  }

  // Single faces move to a neighbouring segment while J decreases.
  void refine(std::vector<std::size_t>& label, std::size_t k) const
  {
    const std::size_t n = m_g.number_of_nodes();
    std::vector<std::uint32_t> unit(n);
    std::iota(unit.begin(), unit.end(), 0u);
    const SAI::Weighted_graph q = SAI::quotient_graph(m_g.node_size, m_g.edge_source,
                                                      m_g.edge_target, m_g.cut_cost, unit, n);
    SAI::move_units(q, label, k, 8);
  }

  const Dual_graph& m_g;
  const Partition_segmentation_options& m_o;
  const Sampling_options& m_sampling;
  std::uint64_t m_proposals = 0;
  std::size_t m_total_steps = 1, m_steps_done = 0;
};

} // namespace internal
} // namespace Randomized_cuts
} // namespace CGAL

#endif // CGAL_RANDOMIZED_CUTS_INTERNAL_PARTITION_SEGMENTATION_H
