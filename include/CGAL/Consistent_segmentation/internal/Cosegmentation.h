// Copyright (c) 2026 CGAL Global Shape Analysis contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_CONSISTENT_SEGMENTATION_INTERNAL_COSEGMENTATION_H
#define CGAL_CONSISTENT_SEGMENTATION_INTERNAL_COSEGMENTATION_H

// Consistent segmentation of a set of meshes, on their dual graphs (mesh independent):
//  1. every mesh is over-segmented alone by the area-normalized cut (links between its
//     components, optional prior boundaries, faces of a known label merged from the start and
//     never mixed with another known label);
//  2. points are sampled on every mesh; pairs of meshes (all of them, or each mesh with the
//     partners whose shape distributions are closest) are aligned by a similarity transform
//     (principal frames, 24 axis orientations, ICP with scale); each sample is linked to the
//     closest sample of the other mesh whose normal agrees (dot product above a threshold) within
//     a distance, in both directions; with a reflection plane, samples of a mesh are linked to
//     their mirror images in the same mesh;
//  3. the over-segments of all meshes are merged greedily by
//        E = E_adj^alpha * E_corr^(1 - alpha),
//     E_adj = sum_S cut_adj(S) / area(S) (each mesh's area scaled to 1, its lengths by the square
//     root of its area), E_corr = sum_S cut_corr(S) / vol_corr(S) (the normalized cut of the
//     correspondence links), choosing at every step the merge that lowers E the most, with a pass
//     of over-segment moves between segments every few merges, down to the requested number of
//     segments. Segments of different known labels never merge.

#include <CGAL/Consistent_segmentation/internal/Segmentation_graph.h>
#include <CGAL/Shape_analysis/Bad_input.h>
#include <CGAL/Shape_analysis/internal/Component_links.h>
#include <CGAL/Shape_analysis/internal/Dual_graph.h>
#include <CGAL/Shape_analysis/internal/Normalized_cut_clustering.h>
#include <CGAL/Shape_analysis/internal/Parallel.h>
#include <CGAL/Shape_analysis/internal/Partition_refinement.h>
#include <CGAL/Shape_analysis/internal/Point_tree.h>
#include <CGAL/Shape_analysis/internal/Random.h>
#include <CGAL/Shape_analysis/internal/Similarity_alignment.h>
#include <CGAL/Shape_analysis/internal/Triangle_sampling.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <functional>
#include <limits>
#include <map>
#include <numeric>
#include <queue>
#include <set>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Consistent_segmentation {
namespace internal {

namespace SAI = CGAL::Shape_analysis::internal;

// One mesh of the set, as its dual graph and the triangles of its faces.
struct Coseg_mesh
{
  SAI::Dual_graph graph;                                // no component links yet
  std::vector<std::array<SAI::Vector_3d, 3>> triangles; // per node, in graph units
  std::vector<long long> prior;                         // empty, or a prior segment per node
  std::vector<long long> known;                         // empty, or a label per node (-1: unknown)
  bool has_plane = false;                               // mirror correspondences within the mesh
  SAI::Vector_3d plane_normal;                          // unit, graph units
  double plane_offset = 0;                              // plane: n.x = offset
};

struct Coseg_options
{
  std::size_t number_of_segments = 8;
  std::size_t number_of_oversegments = 20;
  double alpha = 0.1;
  std::size_t number_of_points = 1000;
  double normal_threshold = 0.3;
  double distance_fraction = 0.2;
  // Each mesh keeps the correspondences of its `number_of_partners` best-aligned partners; in
  // sets of more than 2 number_of_partners + 1 meshes, only the 2 number_of_partners meshes of
  // closest shape distribution are aligned with it. 0: every pair aligned and kept.
  std::size_t number_of_partners = 4;
  std::size_t refinement_interval = 12;
  std::uint64_t seed = 0;
  std::size_t number_of_threads = 0;
  Segmentation_options stage_one;   // concavity, links, prior factor, refinement (both stages)
  std::function<void(double)> progress;
};

struct Coseg_result
{
  std::vector<std::vector<std::size_t>> labels;          // per mesh, per node: segment id
  std::size_t number_of_segments = 0;
  std::vector<std::vector<std::size_t>> meshes_of_segment; // per segment: the meshes it occurs in
  std::vector<double> segment_area;                      // per segment: sum of the meshes' area fractions
  std::vector<long long> segment_label;                  // per segment: its known label, or -1
  std::size_t number_of_oversegments = 0;                // over all meshes
  std::size_t number_of_aligned_pairs = 0;
  std::size_t number_of_correspondences = 0;
  double mean_alignment_rms = 0;                         // relative to the target's sample diagonal
};

inline void check_coseg_options(const Coseg_options& o, const std::string& who)
{
  using CGAL::Shape_analysis::Bad_input;
  if(o.number_of_segments == 0)
    throw Bad_input(who + ": number_of_segments must be at least 1");
  if(o.number_of_oversegments == 0)
    throw Bad_input(who + ": number_of_oversegments must be at least 1");
  if(!(o.alpha >= 0 && o.alpha <= 1))
    throw Bad_input(who + ": adjacency_exponent must be in [0, 1]");
  if(o.number_of_points < 10 || o.number_of_points > 10000000)
    throw Bad_input(who + ": number_of_points must be in [10, 10,000,000]");
  if(!(o.normal_threshold >= -1 && o.normal_threshold < 1))
    throw Bad_input(who + ": normal_threshold must be in [-1, 1)");
  if(!(o.distance_fraction > 0) || !std::isfinite(o.distance_fraction))
    throw Bad_input(who + ": correspondence_distance must be a finite number > 0");
  check_options(o.stage_one, (std::numeric_limits<std::size_t>::max)(), who);
}

// ---------------------------------------------------------------------------------------------
// Stage one: over-segmentation of one mesh.

// Over-segments the (linked) graph `g` into at most `k` segments; nodes of one known label
// start merged and never join another known label. Returns labels 0..k'-1 by decreasing area.
inline std::vector<std::size_t> oversegment(SAI::Dual_graph& g, const Coseg_mesh& m,
                                            std::size_t k, const Segmentation_options& o)
{
  const std::size_t n = g.number_of_nodes();
  if(m.known.empty()) {
    Segmentation_options so = o;
    so.number_of_segments = (std::min)(k, n);
    so.progress = {};
    // segment_dual_graph adds the links itself: give it the unlinked graph.
    return segment_dual_graph(g, so, m.prior.empty() ? nullptr : &m.prior);
  }
  add_links_and_prior(g, o, m.prior.empty() ? nullptr : &m.prior);
  SAI::Normalized_cut_clustering clustering(g.node_size, g.edge_source, g.edge_target, g.cut_cost);
  // Known faces merged by label; unknown faces stay single.
  std::vector<long long> group(n);
  for(std::size_t i = 0; i < n; ++i)
    group[i] = m.known[i] >= 0 ? m.known[i] : -1 - static_cast<long long>(i);
  clustering.merge_groups(group);
  std::vector<long long> cluster_label(n, -1);
  for(std::size_t i = 0; i < n; ++i)
    if(m.known[i] >= 0)
      cluster_label[clustering.find(static_cast<SAI::Normalized_cut_clustering::Id>(i))] = m.known[i];
  std::set<long long> distinct(m.known.begin(), m.known.end());
  distinct.erase(-1);
  const std::size_t target = (std::max)(k, distinct.size());
  const double small_size = (std::min)(o.small_segment_fraction, 0.1 / double(target)) * g.total_size();
  clustering.run(
    target,
    [&](SAI::Normalized_cut_clustering::Id a, SAI::Normalized_cut_clustering::Id b) {
      return cluster_label[a] < 0 || cluster_label[b] < 0 || cluster_label[a] == cluster_label[b];
    },
    [&](SAI::Normalized_cut_clustering::Id survivor, SAI::Normalized_cut_clustering::Id absorbed) {
      if(cluster_label[survivor] < 0)
        cluster_label[survivor] = cluster_label[absorbed];
    },
    0.0, 0, small_size);
  return SAI::number_by_size(clustering.labels(), g.node_size);
}

// ---------------------------------------------------------------------------------------------
// Stage two: correspondences.

struct Surface_sample
{
  std::vector<SAI::Vector_3d> points, normals;
  std::vector<std::uint32_t> node;
  double diagonal = 0;
};

inline Surface_sample sample_surface(const Coseg_mesh& m, std::size_t count, std::uint64_t seed,
                                     std::size_t index)
{
  Surface_sample s;
  const SAI::Dual_graph& g = m.graph;
  const SAI::Weighted_triangle_sampler sampler(g.node_size);
  SAI::Random_stream rng(SAI::Random_stream::mix(seed ^ 0x436F736567ull), index);
  SAI::Vector_3d lo(std::numeric_limits<double>::infinity()), hi(-std::numeric_limits<double>::infinity());
  for(std::size_t k = 0; k < count; ++k) {
    const std::size_t f = sampler.triangle(rng);
    const SAI::Vector_3d p = SAI::Weighted_triangle_sampler::point_in(m.triangles[f], rng);
    s.points.push_back(p);
    s.normals.push_back(g.node_normal[f]);
    s.node.push_back(static_cast<std::uint32_t>(f));
    lo = lo.min(p);
    hi = hi.max(p);
  }
  s.diagonal = (hi - lo).length();
  return s;
}

// A shape distribution (histogram of distances between sample pairs, relative to the RMS radius)
// to choose the partners of a mesh in a large set.
inline std::vector<double> shape_distribution(const Surface_sample& s)
{
  const std::size_t bins = 32;
  std::vector<double> h(bins, 0.0);
  const std::size_t n = s.points.size();
  SAI::Vector_3d c;
  for(const auto& p : s.points)
    c += p;
  c = c / double(n);
  double r2 = 0;
  for(const auto& p : s.points)
    r2 += (p - c).squared_length();
  const double radius = std::sqrt(r2 / double(n));
  if(!(radius > 0))
    return h;
  std::size_t count = 0;
  for(std::size_t i = 0; i < n; ++i)
    for(std::size_t step : {std::size_t(1), n / 3 + 1, n / 2 + 1}) {
      const double d = (s.points[i] - s.points[(i + step) % n]).length() / radius;
      h[(std::min)(bins - 1, std::size_t(d / 3.0 * double(bins)))] += 1;
      ++count;
    }
  for(double& x : h)
    x /= double(count);
  return h;
}

struct Correspondence
{
  std::uint32_t mesh_a, node_a, mesh_b, node_b;
  double weight;
};

// Links every sample of `from` (moved by `t`) to the closest compatible sample of `to`.
inline void link_samples(const Surface_sample& from, std::uint32_t mesh_from, const SAI::Similarity_3d& t,
                         const Surface_sample& to, const SAI::Point_tree& to_tree, std::uint32_t mesh_to,
                         const Coseg_options& o, std::vector<Correspondence>& out)
{
  const double max_distance = o.distance_fraction * to.diagonal;
  const double weight = 1.0 / double(from.points.size());
  std::vector<std::pair<double, std::uint32_t>> near;
  for(std::size_t i = 0; i < from.points.size(); ++i) {
    const SAI::Vector_3d q = t(from.points[i]);
    const SAI::Vector_3d nq = SAI::multiply(t.rotation, from.normals[i]);
    to_tree.k_nearest(q, 8, near);
    for(const auto& c : near) {
      if(c.first > max_distance * max_distance)
        break;
      if(SAI::dot(nq, to.normals[c.second]) > o.normal_threshold) {
        if(mesh_from != mesh_to || from.node[i] != to.node[c.second])
          out.push_back(Correspondence{mesh_from, from.node[i], mesh_to, to.node[c.second], weight});
        break;
      }
    }
  }
}

// ---------------------------------------------------------------------------------------------
// Stage two: greedy merging of the over-segments of all meshes.

class Joint_merging
{
public:
  typedef std::uint32_t Id;

  struct Weights
  {
    double adjacency = 0, correspondence = 0;
  };

  Joint_merging(std::size_t n, double alpha) : m_alpha(alpha)
  {
    m_size.assign(n, 0.0);
    m_cut_a.assign(n, 0.0);
    m_cut_c.assign(n, 0.0);
    m_vol_c.assign(n, 0.0);
    m_label.assign(n, -1);
  }

  void set_size(Id v, double s) { m_size[v] = s; }
  void set_label(Id v, long long l) { m_label[v] = l; }

  // An adjacency (a != b) or correspondence link (a == b: inside one node, volume only).
  void add_link(Id a, Id b, double adjacency, double correspondence)
  {
    m_vol_c[a] += correspondence;
    m_vol_c[b] += correspondence;
    if(a == b)
      return;
    m_cut_a[a] += adjacency;
    m_cut_a[b] += adjacency;
    m_cut_c[a] += correspondence;
    m_cut_c[b] += correspondence;
    m_links.push_back(Link{a, b, Weights{adjacency, correspondence}});
  }

  // Merges down to `target` segments; with `refine`, a pass of node moves every `interval`
  // merges and at the end.
  void run(std::size_t target, std::size_t interval, bool refine,
           const std::function<void(double)>& progress)
  {
    const std::size_t n = m_size.size();
    {
      double volume = 0, size = 0;
      for(Id v = 0; v < n; ++v) {
        volume += m_vol_c[v];
        size += m_size[v];
      }
      m_unsupported = size > 0 ? unsupported_fraction * volume / size : 0.0;
    }
    m_node_arcs = arcs_of(n, [](Id v) { return v; });
    std::vector<Link>().swap(m_links);
    m_segment.resize(n);
    std::iota(m_segment.begin(), m_segment.end(), Id(0));
    m_members.assign(n, {});
    for(Id v = 0; v < n; ++v)
      m_members[v] = {v};
    // Nodes of one known label start as one segment.
    std::map<long long, Id> first_of_label;
    for(Id v = 0; v < n; ++v)
      if(m_label[v] >= 0) {
        auto it = first_of_label.emplace(m_label[v], v);
        if(!it.second)
          move_node(v, it.first->second);
      }
    rebuild_segments();
    m_floor_a = floor_fraction * m_sum_a;
    m_floor_c = floor_fraction * m_sum_c;
    const std::size_t start = m_alive.size();
    std::size_t merges = 0;
    while(m_alive.size() > target) {
      Id a = 0, b = 0;
      bool found = false;
      if(m_alive.size() > exact_threshold)
        found = queued_pair(a, b);
      if(!found)
        found = best_pair(a, b, true) || best_pair(a, b, false);
      if(!found)
        break; // only segments of different known labels are left
      merge_segments(a, b);
      ++merges;
      if(refine && interval > 0 && merges % interval == 0)
        refine_pass();
      if(progress && start > target)
        progress(double(start - m_alive.size()) / double(start - target));
    }
    if(refine)
      for(int pass = 0; pass < 3 && refine_pass() > 0; ++pass) {
      }
  }

  // Segment of node v (the id of a node of the segment).
  Id segment(Id v) const { return m_segment[v]; }
  long long segment_label(Id s) const { return m_seg_label[s]; }

private:
  struct Link
  {
    Id a, b;
    Weights w;
  };
  struct Arc
  {
    Id to;
    Weights w;
  };
  struct Entry
  {
    double key;
    Id a, b;
    std::uint32_t version_a, version_b;
    bool operator<(const Entry& o) const // max-heap: the smallest key on top
    {
      if(key != o.key)
        return key > o.key;
      if(a != o.a)
        return a > o.a;
      return b > o.b;
    }
  };

  // Above this many segments, merges are taken from a priority queue keyed by the first-order
  // change of log E (refreshed when E_adj or E_corr has moved by more than 2% since the keys were
  // computed); below it, every candidate pair is evaluated exactly at every merge.
  static constexpr std::size_t exact_threshold = 400;

  // Sorted, accumulated arcs between the groups `group(v)` of the links' ends.
  template <typename Group>
  std::vector<std::vector<Arc>> arcs_of(std::size_t n, const Group& group) const
  {
    std::vector<std::pair<std::uint64_t, Weights>> all;
    all.reserve(2 * m_links.size());
    const auto add = [&](Id x, Id y, const Weights& w) {
      const Id gx = group(x), gy = group(y);
      if(gx != gy) {
        all.emplace_back((std::uint64_t(gx) << 32) | gy, w);
        all.emplace_back((std::uint64_t(gy) << 32) | gx, w);
      }
    };
    if(!m_links.empty())
      for(const Link& l : m_links)
        add(l.a, l.b, l.w);
    else
      for(Id v = 0; v < m_node_arcs.size(); ++v)
        for(const Arc& arc : m_node_arcs[v])
          if(v < arc.to)
            add(v, arc.to, arc.w);
    std::sort(all.begin(), all.end(), [](const auto& x, const auto& y) { return x.first < y.first; });
    std::vector<std::vector<Arc>> arcs(n);
    for(std::size_t i = 0; i < all.size(); ++i) {
      const Id from = Id(all[i].first >> 32), to = Id(all[i].first & 0xFFFFFFFFu);
      auto& list = arcs[from];
      if(!list.empty() && list.back().to == to) {
        list.back().w.adjacency += all[i].second.adjacency;
        list.back().w.correspondence += all[i].second.correspondence;
      } else
        list.push_back(Arc{to, all[i].second});
    }
    return arcs;
  }

  double term_a(double cut, double size) const { return size > 0 ? cut / size : 0.0; }
  // The correspondence term of a segment of area `size`: its normalized cut, with a virtual link
  // volume proportional to its area that always counts as cut. A segment that no correspondence
  // supports (a small piece that no sample fell on, a part that matches nothing) then costs as much
  // as a fully cut one, and is merged by the adjacency evidence first, instead of being kept as a
  // free segment while real parts are merged; well supported segments barely change.
  double term_c(double cut, double vol, double size) const
  {
    const double u = m_unsupported * size;
    return vol + u > 0 ? (cut + u) / (vol + u) : 0.0;
  }
  // log E. Each factor has a floor (a small fraction of its value before any merge): without it,
  // a state where one factor vanishes (every segment a union of whole meshes, or all sampled area
  // in one segment) would score minus infinity whatever the other factor says.
  double objective(double ea, double ec) const
  {
    const double tiny = 1e-300;
    return m_alpha * std::log((std::max)(ea + m_floor_a, tiny)) +
           (1 - m_alpha) * std::log((std::max)(ec + m_floor_c, tiny));
  }

  bool compatible(Id a, Id b) const
  {
    return m_seg_label[a] < 0 || m_seg_label[b] < 0 || m_seg_label[a] == m_seg_label[b];
  }

  // The changes of E_adj and E_corr if segments a and b merged.
  void deltas(Id a, Id b, const Weights& w, double& da, double& dc) const
  {
    da = term_a((std::max)(0.0, m_ca[a] + m_ca[b] - 2 * w.adjacency), m_sa[a] + m_sa[b]) - m_ta[a] - m_ta[b];
    dc = term_c((std::max)(0.0, m_cc[a] + m_cc[b] - 2 * w.correspondence), m_vc[a] + m_vc[b],
                m_sa[a] + m_sa[b]) -
         m_tc[a] - m_tc[b];
  }

  // The merge of two segments that lowers E the most; among linked pairs (`linked`) or any two.
  bool best_pair(Id& best_a, Id& best_b, bool linked) const
  {
    double best = std::numeric_limits<double>::infinity();
    bool found = false;
    auto consider = [&](Id a, Id b, const Weights& w) {
      if(!compatible(a, b))
        return;
      double da = 0, dc = 0;
      deltas(a, b, w, da, dc);
      const double e = objective(m_sum_a + da, m_sum_c + dc);
      if(e < best) {
        best = e;
        best_a = a;
        best_b = b;
        found = true;
      }
    };
    if(linked) {
      for(Id a : m_alive)
        for(const Arc& arc : m_seg_arcs[a])
          if(a < arc.to)
            consider(a, arc.to, arc.w);
    } else {
      const Weights none;
      for(std::size_t i = 0; i < m_alive.size(); ++i)
        for(std::size_t j = i + 1; j < m_alive.size(); ++j)
          consider((std::min)(m_alive[i], m_alive[j]), (std::max)(m_alive[i], m_alive[j]), none);
    }
    return found;
  }

  void push(Id a, Id b, const Weights& w)
  {
    if(a > b)
      std::swap(a, b);
    if(!compatible(a, b))
      return;
    double da = 0, dc = 0;
    deltas(a, b, w, da, dc);
    const double key = m_alpha * da / (std::max)(m_key_a + m_floor_a, 1e-300) +
                       (1 - m_alpha) * dc / (std::max)(m_key_c + m_floor_c, 1e-300);
    m_queue.push(Entry{key, a, b, m_version[a], m_version[b]});
  }

  void rebuild_queue()
  {
    m_queue = std::priority_queue<Entry>();
    m_key_a = m_sum_a;
    m_key_c = m_sum_c;
    for(Id a : m_alive)
      for(const Arc& arc : m_seg_arcs[a])
        if(a < arc.to)
          push(a, arc.to, arc.w);
  }

  bool queued_pair(Id& a, Id& b)
  {
    const auto moved = [](double now, double then) {
      return then > 0 ? std::abs(now - then) > 0.02 * then : now > 0;
    };
    if(!m_queue_valid || moved(m_sum_a, m_key_a) || moved(m_sum_c, m_key_c)) {
      rebuild_queue();
      m_queue_valid = true;
    }
    while(!m_queue.empty()) {
      const Entry top = m_queue.top();
      m_queue.pop();
      if(m_members[top.a].empty() || m_members[top.b].empty() || m_version[top.a] != top.version_a ||
         m_version[top.b] != top.version_b)
        continue;
      a = top.a;
      b = top.b;
      return true;
    }
    return false;
  }

  void set_terms(Id s)
  {
    m_sum_a -= m_ta[s];
    m_sum_c -= m_tc[s];
    m_ta[s] = term_a(m_ca[s], m_sa[s]);
    m_tc[s] = term_c(m_cc[s], m_vc[s], m_sa[s]);
    m_sum_a += m_ta[s];
    m_sum_c += m_tc[s];
  }

  static std::vector<Arc>::iterator lower(std::vector<Arc>& list, Id id)
  {
    return std::lower_bound(list.begin(), list.end(), id, [](const Arc& x, Id v) { return x.to < v; });
  }

  void merge_segments(Id a, Id b)
  {
    if(m_members[a].size() < m_members[b].size())
      std::swap(a, b);
    Weights w;
    {
      auto it = lower(m_seg_arcs[a], b);
      if(it != m_seg_arcs[a].end() && it->to == b)
        w = it->w;
    }
    m_sa[a] += m_sa[b];
    m_ca[a] = (std::max)(0.0, m_ca[a] + m_ca[b] - 2 * w.adjacency);
    m_cc[a] = (std::max)(0.0, m_cc[a] + m_cc[b] - 2 * w.correspondence);
    m_vc[a] += m_vc[b];
    if(m_seg_label[a] < 0)
      m_seg_label[a] = m_seg_label[b];
    m_sum_a -= m_ta[b];
    m_sum_c -= m_tc[b];
    m_ta[b] = m_tc[b] = 0;
    set_terms(a);
    // Merged arc list of a (without a and b); the neighbours of b now point to a.
    std::vector<Arc> merged;
    merged.reserve(m_seg_arcs[a].size() + m_seg_arcs[b].size());
    auto i = m_seg_arcs[a].begin(), ie = m_seg_arcs[a].end();
    auto j = m_seg_arcs[b].begin(), je = m_seg_arcs[b].end();
    while(i != ie || j != je) {
      Arc next;
      if(j == je || (i != ie && i->to < j->to))
        next = *i++;
      else if(i == ie || j->to < i->to)
        next = *j++;
      else {
        next = *i;
        next.w.adjacency += j->w.adjacency;
        next.w.correspondence += j->w.correspondence;
        ++i;
        ++j;
      }
      if(next.to != a && next.to != b)
        merged.push_back(next);
    }
    for(const Arc& arc : m_seg_arcs[b]) {
      if(arc.to == a)
        continue;
      auto& list = m_seg_arcs[arc.to];
      list.erase(lower(list, b));
      auto it = lower(list, a);
      if(it != list.end() && it->to == a) {
        it->w.adjacency += arc.w.adjacency;
        it->w.correspondence += arc.w.correspondence;
      } else
        list.insert(it, Arc{a, arc.w});
    }
    m_seg_arcs[a].swap(merged);
    std::vector<Arc>().swap(m_seg_arcs[b]);
    for(Id v : m_members[b])
      m_segment[v] = a;
    m_members[a].insert(m_members[a].end(), m_members[b].begin(), m_members[b].end());
    m_members[b].clear();
    m_alive.erase(std::find(m_alive.begin(), m_alive.end(), b));
    ++m_version[a];
    ++m_version[b];
    if(m_queue_valid)
      for(const Arc& arc : m_seg_arcs[a])
        push(a, arc.to, arc.w);
  }

  // Moves node v into segment t (membership only; sums are rebuilt by rebuild_segments()).
  void move_node(Id v, Id t)
  {
    auto& from = m_members[m_segment[v]];
    from.erase(std::find(from.begin(), from.end(), v));
    m_members[t].push_back(v);
    m_segment[v] = t;
  }

  // Segment sums, terms and arcs from the node memberships.
  void rebuild_segments()
  {
    const std::size_t n = m_size.size();
    m_sa.assign(n, 0.0);
    m_ca.assign(n, 0.0);
    m_cc.assign(n, 0.0);
    m_vc.assign(n, 0.0);
    m_ta.assign(n, 0.0);
    m_tc.assign(n, 0.0);
    m_seg_label.assign(n, -1);
    m_version.resize(n, 0);
    for(auto& v : m_version)
      ++v;
    m_seg_arcs = arcs_of(n, [&](Id v) { return m_segment[v]; });
    for(Id v = 0; v < n; ++v) {
      const Id s = m_segment[v];
      m_sa[s] += m_size[v];
      m_vc[s] += m_vol_c[v];
      if(m_label[v] >= 0)
        m_seg_label[s] = m_label[v];
    }
    for(Id s = 0; s < n; ++s)
      for(const Arc& arc : m_seg_arcs[s]) {
        m_ca[s] += arc.w.adjacency;
        m_cc[s] += arc.w.correspondence;
      }
    m_alive.clear();
    m_sum_a = m_sum_c = 0;
    for(Id s = 0; s < n; ++s)
      if(!m_members[s].empty()) {
        m_alive.push_back(s);
        m_ta[s] = term_a(m_ca[s], m_sa[s]);
        m_tc[s] = term_c(m_cc[s], m_vc[s], m_sa[s]);
        m_sum_a += m_ta[s];
        m_sum_c += m_tc[s];
      }
    m_queue_valid = false;
  }

  // One pass over the nodes: each node without a known label moves to the neighbouring segment
  // that lowers E the most, if any (a segment is never emptied). Returns the number of moves.
  std::size_t refine_pass()
  {
    std::size_t moves = 0;
    const std::size_t n = m_size.size();
    m_scratch.resize(n);
    m_touched.clear();
    for(Id v = 0; v < n; ++v) {
      const Id s = m_segment[v];
      if(m_label[v] >= 0 || m_members[s].size() < 2)
        continue;
      for(Id t : m_touched)
        m_scratch[t] = Weights();
      m_touched.clear();
      for(const Arc& arc : m_node_arcs[v]) {
        const Id t = m_segment[arc.to];
        if(m_scratch[t].adjacency == 0 && m_scratch[t].correspondence == 0)
          m_touched.push_back(t);
        m_scratch[t].adjacency += arc.w.adjacency;
        m_scratch[t].correspondence += arc.w.correspondence;
      }
      const Weights inside = m_scratch[s];
      // s without v.
      const double sa_s = m_sa[s] - m_size[v];
      const double ca_s = (std::max)(0.0, m_ca[s] - m_cut_a[v] + 2 * inside.adjacency);
      const double cc_s = (std::max)(0.0, m_cc[s] - m_cut_c[v] + 2 * inside.correspondence);
      const double vc_s = m_vc[s] - m_vol_c[v];
      const double ta_s = term_a(ca_s, sa_s), tc_s = term_c(cc_s, vc_s, sa_s);
      const double current = objective(m_sum_a, m_sum_c);
      double best = current - 1e-12 * std::abs(current) - 1e-15;
      Id best_t = s;
      double best_ta = 0, best_tc = 0;
      for(Id t : m_touched) {
        if(t == s)
          continue;
        const Weights& w = m_scratch[t];
        const double ta_t = term_a((std::max)(0.0, m_ca[t] + m_cut_a[v] - 2 * w.adjacency), m_sa[t] + m_size[v]);
        const double tc_t =
          term_c((std::max)(0.0, m_cc[t] + m_cut_c[v] - 2 * w.correspondence), m_vc[t] + m_vol_c[v],
                 m_sa[t] + m_size[v]);
        const double e = objective(m_sum_a - m_ta[s] - m_ta[t] + ta_s + ta_t,
                                   m_sum_c - m_tc[s] - m_tc[t] + tc_s + tc_t);
        if(e < best || (e == best && best_t != s && t < best_t)) {
          best = e;
          best_t = t;
          best_ta = ta_t;
          best_tc = tc_t;
        }
      }
      if(best_t == s)
        continue;
      const Id t = best_t;
      const Weights to_t = m_scratch[t];
      m_sum_a += ta_s + best_ta - m_ta[s] - m_ta[t];
      m_sum_c += tc_s + best_tc - m_tc[s] - m_tc[t];
      m_sa[s] = sa_s;
      m_ca[s] = ca_s;
      m_cc[s] = cc_s;
      m_vc[s] = vc_s;
      m_ta[s] = ta_s;
      m_tc[s] = tc_s;
      m_sa[t] += m_size[v];
      m_ca[t] = (std::max)(0.0, m_ca[t] + m_cut_a[v] - 2 * to_t.adjacency);
      m_cc[t] = (std::max)(0.0, m_cc[t] + m_cut_c[v] - 2 * to_t.correspondence);
      m_vc[t] += m_vol_c[v];
      m_ta[t] = best_ta;
      m_tc[t] = best_tc;
      move_node(v, t);
      ++moves;
    }
    for(Id t : m_touched)
      m_scratch[t] = Weights();
    m_touched.clear();
    if(moves > 0)
      rebuild_segments(); // arcs between segments changed (sums are recomputed exactly too)
    return moves;
  }

  // The virtual, always cut, correspondence volume of a segment, per unit of area, relative to
  // the mean volume per unit of area of the real links.
  static constexpr double unsupported_fraction = 0.01;
  // The floors of E_adj and E_corr, relative to their values before any merge.
  static constexpr double floor_fraction = 0.01;
  double m_alpha;
  double m_unsupported = 0;
  double m_floor_a = 0, m_floor_c = 0;
  // Nodes.
  std::vector<double> m_size, m_cut_a, m_cut_c, m_vol_c;
  std::vector<long long> m_label;
  std::vector<Link> m_links;                 // until run() turns them into arcs
  std::vector<std::vector<Arc>> m_node_arcs; // per node, sorted
  // Segments (indexed by the id of one of their nodes).
  std::vector<Id> m_segment;
  std::vector<std::vector<Id>> m_members;
  std::vector<double> m_sa, m_ca, m_cc, m_vc, m_ta, m_tc;
  std::vector<long long> m_seg_label;
  std::vector<std::vector<Arc>> m_seg_arcs; // per segment, sorted
  std::vector<std::uint32_t> m_version;
  std::vector<Id> m_alive;
  double m_sum_a = 0, m_sum_c = 0;
  // Queue of candidate merges, keyed with the sums of E at its last rebuild.
  std::priority_queue<Entry> m_queue;
  bool m_queue_valid = false;
  double m_key_a = 0, m_key_c = 0;
  // Refinement scratch.
  std::vector<Weights> m_scratch;
  std::vector<Id> m_touched;
};

// ---------------------------------------------------------------------------------------------
// The whole computation.

inline Coseg_result cosegment(std::vector<Coseg_mesh>& meshes, const Coseg_options& o)
{
  const std::size_t m = meshes.size();
  Coseg_result result;
  auto report = [&](double f) {
    if(o.progress)
      o.progress(f);
  };

  // Stage one, mesh by mesh.
  std::vector<std::vector<std::size_t>> over(m);
  {
    SAI::Parallel_workspaces<char> workers(o.number_of_threads);
    workers.for_each(0, m, [&](std::size_t i, char&) {
      over[i] = oversegment(meshes[i].graph, meshes[i], o.number_of_oversegments, o.stage_one);
    });
  }
  report(0.2);

  // Samples, partners, alignments and correspondences.
  std::vector<Surface_sample> samples(m);
  std::vector<SAI::Point_tree> trees(m);
  {
    SAI::Parallel_workspaces<char> workers(o.number_of_threads);
    workers.for_each(0, m, [&](std::size_t i, char&) {
      samples[i] = sample_surface(meshes[i], o.number_of_points, o.seed, i);
      std::vector<std::uint32_t> ids(samples[i].points.size());
      std::iota(ids.begin(), ids.end(), std::uint32_t(0));
      trees[i] = SAI::Point_tree(samples[i].points, ids);
    });
  }
  std::vector<std::pair<std::uint32_t, std::uint32_t>> pairs;
  const std::size_t candidates = 2 * o.number_of_partners;
  if(o.number_of_partners == 0 || m <= candidates + 1) {
    for(std::uint32_t i = 0; i < m; ++i)
      for(std::uint32_t j = i + 1; j < m; ++j)
        pairs.emplace_back(i, j);
  } else {
    std::vector<std::vector<double>> d2(m);
    for(std::size_t i = 0; i < m; ++i)
      d2[i] = shape_distribution(samples[i]);
    std::set<std::pair<std::uint32_t, std::uint32_t>> chosen;
    for(std::uint32_t i = 0; i < m; ++i) {
      std::vector<std::pair<double, std::uint32_t>> by_distance;
      for(std::uint32_t j = 0; j < m; ++j)
        if(j != i) {
          double d = 0;
          for(std::size_t b = 0; b < d2[i].size(); ++b)
            d += std::abs(d2[i][b] - d2[j][b]);
          by_distance.emplace_back(d, j);
        }
      std::sort(by_distance.begin(), by_distance.end());
      for(std::size_t k = 0; k < candidates && k < by_distance.size(); ++k)
        chosen.emplace((std::min)(i, by_distance[k].second), (std::max)(i, by_distance[k].second));
    }
    pairs.assign(chosen.begin(), chosen.end());
  }
  std::vector<std::vector<Correspondence>> links(pairs.size() + m);
  std::vector<double> pair_rms(pairs.size(), 0.0);
  {
    SAI::Restart_alignment_options ao;
    ao.coarse_points = 100;
    ao.coarse_iterations = 15;
    ao.refined_restarts = 2;
    ao.icp.max_iterations = 30;
    ao.icp.keep_fraction = 0.9;
    ao.number_of_threads = 1;
    // The alignments use the first points of the samples (in random order), the
    // correspondences all of them.
    const std::size_t aligned_points = (std::min)(o.number_of_points, std::size_t(400));
    std::vector<std::vector<SAI::Vector_3d>> prefix(m);
    for(std::size_t i = 0; i < m; ++i)
      prefix[i].assign(samples[i].points.begin(),
                       samples[i].points.begin() + std::ptrdiff_t((std::min)(aligned_points, samples[i].points.size())));
    SAI::Parallel_workspaces<char> workers(o.number_of_threads);
    workers.for_each(0, pairs.size(), [&](std::size_t p, char&) {
      const std::uint32_t a = pairs[p].first, b = pairs[p].second;
      const SAI::Restart_alignment_result r = SAI::align_with_restarts(prefix[a], prefix[b], ao);
      pair_rms[p] = samples[b].diagonal > 0 ? r.rms / samples[b].diagonal : 0.0;
      link_samples(samples[a], a, r.transform, samples[b], trees[b], b, o, links[p]);
      link_samples(samples[b], b, r.transform.inverse(), samples[a], trees[a], a, o, links[p]);
    });
    workers.for_each(0, m, [&](std::size_t i, char&) {
      if(!meshes[i].has_plane)
        return;
      // The reflection x -> x - 2 (n.x - d) n as a similarity: R = I - 2 n n^T (det -1) is not a
      // rotation, so it is applied by hand.
      const SAI::Vector_3d nn = meshes[i].plane_normal;
      const double d = meshes[i].plane_offset;
      Surface_sample mirrored = samples[i];
      for(std::size_t k = 0; k < mirrored.points.size(); ++k) {
        const SAI::Vector_3d& p = samples[i].points[k];
        mirrored.points[k] = p - nn * (2 * (SAI::dot(nn, p) - d));
        const SAI::Vector_3d& q = samples[i].normals[k];
        mirrored.normals[k] = q - nn * (2 * SAI::dot(nn, q));
      }
      link_samples(mirrored, std::uint32_t(i), SAI::Similarity_3d(), samples[i], trees[i],
                   std::uint32_t(i), o, links[pairs.size() + i]);
    });
  }
  // Only the pairs among the `number_of_partners` best aligned of one of their meshes keep their
  // links: a poor alignment (other poses, other proportions) gives misleading correspondences.
  if(o.number_of_partners > 0) {
    std::vector<std::vector<std::pair<double, std::size_t>>> of_mesh(m);
    for(std::size_t p = 0; p < pairs.size(); ++p) {
      of_mesh[pairs[p].first].emplace_back(pair_rms[p], p);
      of_mesh[pairs[p].second].emplace_back(pair_rms[p], p);
    }
    std::vector<char> keep(pairs.size(), 0);
    for(auto& list : of_mesh) {
      std::sort(list.begin(), list.end());
      for(std::size_t k = 0; k < o.number_of_partners && k < list.size(); ++k)
        keep[list[k].second] = 1;
    }
    for(std::size_t p = 0; p < pairs.size(); ++p)
      if(!keep[p])
        std::vector<Correspondence>().swap(links[p]);
  }
  report(0.6);
  result.number_of_aligned_pairs = pairs.size();
  for(double r : pair_rms)
    result.mean_alignment_rms += r / double((std::max)(std::size_t(1), pairs.size()));

  // The graph of the over-segments of all meshes.
  std::vector<std::size_t> offset(m + 1, 0);
  for(std::size_t i = 0; i < m; ++i) {
    std::size_t k = 0;
    for(std::size_t l : over[i])
      k = (std::max)(k, l + 1);
    offset[i + 1] = offset[i] + k;
  }
  const std::size_t total = offset[m];
  if(total >= std::size_t((std::numeric_limits<std::uint32_t>::max)()))
    throw CGAL::Shape_analysis::Bad_input("consistent_segmentation: too many over-segments in all (" +
                                          std::to_string(total) + ")");
  result.number_of_oversegments = total;
  Joint_merging merging(total, o.alpha);
  std::vector<double> size(total, 0.0);
  std::vector<long long> label(total, -1);
  for(std::size_t i = 0; i < m; ++i) {
    const SAI::Dual_graph& g = meshes[i].graph;
    const double area = g.total_size();
    const double length_scale = 1.0 / std::sqrt(area);
    for(std::size_t v = 0; v < g.number_of_nodes(); ++v) {
      size[offset[i] + over[i][v]] += g.node_size[v] / area;
      if(!meshes[i].known.empty() && meshes[i].known[v] >= 0)
        label[offset[i] + over[i][v]] = meshes[i].known[v];
    }
    for(std::size_t e = 0; e < g.number_of_edges(); ++e) {
      const std::size_t a = over[i][g.edge_source[e]], b = over[i][g.edge_target[e]];
      if(a != b)
        merging.add_link(static_cast<Joint_merging::Id>(offset[i] + a),
                         static_cast<Joint_merging::Id>(offset[i] + b), g.cut_cost[e] * length_scale, 0.0);
    }
  }
  for(std::size_t v = 0; v < total; ++v) {
    merging.set_size(static_cast<Joint_merging::Id>(v), size[v]);
    merging.set_label(static_cast<Joint_merging::Id>(v), label[v]);
  }
  for(const auto& list : links)
    for(const Correspondence& c : list) {
      merging.add_link(static_cast<Joint_merging::Id>(offset[c.mesh_a] + over[c.mesh_a][c.node_a]),
                       static_cast<Joint_merging::Id>(offset[c.mesh_b] + over[c.mesh_b][c.node_b]), 0.0,
                       c.weight);
      ++result.number_of_correspondences;
    }

  merging.run(o.number_of_segments, o.refinement_interval, o.stage_one.boundary_refinement,
              [&](double f) { report(0.6 + 0.4 * f); });

  // Segment ids: known labels keep their value; the other segments follow, by decreasing area.
  std::map<Joint_merging::Id, double> area;
  std::map<Joint_merging::Id, std::size_t> first_node;
  for(std::size_t v = 0; v < total; ++v) {
    const auto s = merging.segment(static_cast<Joint_merging::Id>(v));
    area[s] += size[v];
    first_node.emplace(s, v);
  }
  long long next = 0;
  for(const auto& kv : area)
    next = (std::max)(next, merging.segment_label(kv.first) + 1);
  std::vector<std::pair<Joint_merging::Id, double>> unlabelled;
  std::map<Joint_merging::Id, std::size_t> id_of;
  for(const auto& kv : area) {
    if(merging.segment_label(kv.first) >= 0)
      id_of[kv.first] = static_cast<std::size_t>(merging.segment_label(kv.first));
    else
      unlabelled.push_back(kv);
  }
  std::sort(unlabelled.begin(), unlabelled.end(), [&](const auto& x, const auto& y) {
    return x.second != y.second ? x.second > y.second : first_node[x.first] < first_node[y.first];
  });
  for(const auto& kv : unlabelled)
    id_of[kv.first] = static_cast<std::size_t>(next++);
  std::size_t count = 0;
  for(const auto& kv : id_of)
    count = (std::max)(count, kv.second + 1);
  result.number_of_segments = count;
  result.meshes_of_segment.assign(count, {});
  result.segment_area.assign(count, 0.0);
  result.segment_label.assign(count, -1);
  for(const auto& kv : area) {
    result.segment_area[id_of[kv.first]] = kv.second;
    result.segment_label[id_of[kv.first]] = merging.segment_label(kv.first);
  }
  result.labels.resize(m);
  for(std::size_t i = 0; i < m; ++i) {
    const std::size_t n = meshes[i].graph.number_of_nodes();
    result.labels[i].resize(n);
    std::set<std::size_t> present;
    for(std::size_t v = 0; v < n; ++v) {
      const std::size_t id = id_of[merging.segment(static_cast<Joint_merging::Id>(offset[i] + over[i][v]))];
      result.labels[i][v] = id;
      present.insert(id);
    }
    for(std::size_t id : present)
      result.meshes_of_segment[id].push_back(i);
  }
  report(1.0);
  return result;
}

} // namespace internal
} // namespace Consistent_segmentation
} // namespace CGAL

#endif // CGAL_CONSISTENT_SEGMENTATION_INTERNAL_COSEGMENTATION_H
