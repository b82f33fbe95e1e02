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
//     (principal frames, 24 axis orientations, ICP with scale), then each over-segment of stage
//     one is aligned again on its own by a bounded rigid ICP (articulated parts: legs, arms and
//     wings at other angles); each sample, moved by its over-segment's transform, is linked to the
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

//
// Types and options: Cosegmentation_types.h; stage two: Coseg_correspondences.h; the merging of
// stage three: Joint_merging.h.

#include <CGAL/Consistent_segmentation/internal/Coseg_correspondences.h>
#include <CGAL/Consistent_segmentation/internal/Cosegmentation_types.h>
#include <CGAL/Consistent_segmentation/internal/Joint_merging.h>
#include <CGAL/Consistent_segmentation/internal/Segmentation_graph.h>
#include <CGAL/Shape_analysis/Bad_input.h>
#include <CGAL/Shape_analysis/internal/Component_links.h>
#include <CGAL/Shape_analysis/internal/Dual_graph.h>
#include <CGAL/Shape_analysis/internal/Normalized_cut_clustering.h>
#include <CGAL/Shape_analysis/internal/Parallel.h>
#include <CGAL/Shape_analysis/internal/Partition_refinement.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <map>
#include <set>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Consistent_segmentation {
namespace internal {

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
    so.progress_callback = {};
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
  const double small_size = (std::min)(small_segment_fraction, 0.1 / double(target)) * g.total_size();
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

// The automatic number of segments of a set (number_of_segments 0): the median, over the meshes,
// of the number hierarchical_segmentation() chooses for each (of an even number of meshes, the
// lower of the two middle ones). The meshes' graphs must not be linked yet.
inline std::size_t automatic_set_count(const std::vector<Coseg_mesh>& meshes, const Coseg_options& o)
{
  std::vector<std::size_t> counts(meshes.size(), 1);
  SAI::Parallel_workspaces<char> workers(o.number_of_threads);
  workers.for_each(0, meshes.size(), [&](std::size_t i, char&) {
    SAI::Dual_graph g = meshes[i].graph; // segment_dual_graph links it
    Segmentation_options so = o;
    so.number_of_segments = 0;
    so.progress_callback = {};
    so.boundary_refinement = false; // moves boundaries, not the count
    const std::vector<std::size_t> labels =
      segment_dual_graph(g, so, meshes[i].prior.empty() ? nullptr : &meshes[i].prior);
    for(std::size_t l : labels)
      counts[i] = (std::max)(counts[i], l + 1);
  });
  std::sort(counts.begin(), counts.end());
  return counts[(counts.size() - 1) / 2];
}

// Stage one, mesh by mesh: the over-segment of every node of every mesh.
inline std::vector<std::vector<std::size_t>> oversegment_meshes(std::vector<Coseg_mesh>& meshes,
                                                                const Coseg_options& o)
{
  const std::size_t m = meshes.size();
  std::vector<std::vector<std::size_t>> over(m);
  SAI::Parallel_workspaces<char> workers(o.number_of_threads);
  workers.for_each(0, m, [&](std::size_t i, char&) {
    over[i] = oversegment(meshes[i].graph, meshes[i], o.number_of_oversegments, o);
  });
  return over;
}

// ---------------------------------------------------------------------------------------------
// Stage three: the graph of the over-segments of all meshes, merged.

// The id of the first over-segment of every mesh in the graph of all of them; offset[m] is their
// number.
inline std::vector<std::size_t> oversegment_offsets(const std::vector<std::vector<std::size_t>>& over)
{
  const std::size_t m = over.size();
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
  return offset;
}

// The area of every over-segment (numbered from `offset`) as a fraction of its mesh's.
inline std::vector<double> oversegment_areas(const std::vector<Coseg_mesh>& meshes,
                                             const std::vector<std::vector<std::size_t>>& over,
                                             const std::vector<std::size_t>& offset)
{
  std::vector<double> size(offset.back(), 0.0);
  for(std::size_t i = 0; i < meshes.size(); ++i) {
    const SAI::Dual_graph& g = meshes[i].graph;
    const double area = g.total_size();
    for(std::size_t v = 0; v < g.number_of_nodes(); ++v)
      size[offset[i] + over[i][v]] += g.node_size[v] / area;
  }
  return size;
}

// Gives `merging` the over-segments (their area fractions `size`, see oversegment_areas(), and
// their known labels), their adjacencies and the correspondences between them; returns the number
// of correspondences.
inline std::size_t add_oversegment_graph(Joint_merging& merging, const std::vector<Coseg_mesh>& meshes,
                                         const std::vector<std::vector<std::size_t>>& over,
                                         const std::vector<std::size_t>& offset, const std::vector<double>& size,
                                         const std::vector<std::vector<Correspondence>>& links)
{
  const std::size_t m = meshes.size();
  const std::size_t total = offset[m];
  std::vector<long long> label(total, -1);
  for(std::size_t i = 0; i < m; ++i) {
    const SAI::Dual_graph& g = meshes[i].graph;
    const double length_scale = 1.0 / std::sqrt(g.total_size());
    for(std::size_t v = 0; v < g.number_of_nodes(); ++v)
      if(!meshes[i].known.empty() && meshes[i].known[v] >= 0)
        label[offset[i] + over[i][v]] = meshes[i].known[v];
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
  std::size_t count = 0;
  for(const auto& list : links)
    for(const Correspondence& c : list) {
      merging.add_link(static_cast<Joint_merging::Id>(offset[c.mesh_a] + over[c.mesh_a][c.node_a]),
                       static_cast<Joint_merging::Id>(offset[c.mesh_b] + over[c.mesh_b][c.node_b]), 0.0,
                       c.weight);
      ++count;
    }
  return count;
}

// The segments of the merged graph in `result`: labels per mesh and node, meshes, area and known
// label per segment.
inline void number_segments(const Joint_merging& merging, const std::vector<Coseg_mesh>& meshes,
                            const std::vector<std::vector<std::size_t>>& over,
                            const std::vector<std::size_t>& offset, const std::vector<double>& size,
                            Coseg_result& result)
{
  const std::size_t m = meshes.size();
  const std::size_t total = offset[m];
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
}

// Stages two and three for the over-segments `over` (area fractions `size`): samples (from
// `o.random_seed`), alignments, correspondences, and the joint merging down to `target` segments.
// `report` gets the progress from 0 to 1.
template <typename Report>
Coseg_result link_and_merge(const std::vector<Coseg_mesh>& meshes, const std::vector<std::vector<std::size_t>>& over,
                            const std::vector<std::size_t>& offset, const std::vector<double>& size,
                            std::size_t target, const Coseg_options& o, const Report& report)
{
  Coseg_result result;
  std::vector<Surface_sample> samples;
  std::vector<SAI::Point_tree> trees;
  sample_meshes(meshes, o, samples, trees);
  const std::vector<std::pair<std::uint32_t, std::uint32_t>> pairs = pairs_to_align(samples, o);
  std::vector<std::vector<Correspondence>> links;
  std::vector<double> pair_rms;
  link_meshes(meshes, samples, trees, pairs, over, o, links, pair_rms);
  report(0.5);
  result.number_of_aligned_pairs = pairs.size();
  for(double r : pair_rms)
    result.mean_alignment_rms += r / double((std::max)(std::size_t(1), pairs.size()));

  const std::size_t total = offset[meshes.size()];
  result.number_of_oversegments = total;
  Joint_merging merging(total, o.adjacency_exponent);
  result.number_of_correspondences = add_oversegment_graph(merging, meshes, over, offset, size, links);
  merging.run(target, refinement_interval, o.boundary_refinement, [&](double f) { report(0.5 + 0.5 * f); });
  number_segments(merging, meshes, over, offset, size, result);
  return result;
}

// The segment id of every over-segment (numbered from `offset`) in `result`, whose per-node labels
// are then dropped (a run's result takes little memory until it is chosen).
inline std::vector<std::size_t> oversegment_ids(Coseg_result& result, const std::vector<std::vector<std::size_t>>& over,
                                                const std::vector<std::size_t>& offset)
{
  std::vector<std::size_t> ids(offset.back(), 0);
  for(std::size_t i = 0; i < over.size(); ++i)
    for(std::size_t v = 0; v < over[i].size(); ++v)
      ids[offset[i] + over[i][v]] = result.labels[i][v];
  std::vector<std::vector<std::size_t>>().swap(result.labels);
  return ids;
}

// The area-weighted Rand distance between two segmentations `a` and `b` of the items `first` to
// `last` (excluded) of areas `area`: the probability that two points drawn on them by area lie in
// one segment of one segmentation and in two segments of the other.
inline double rand_distance(const std::vector<double>& area, const std::vector<std::size_t>& a,
                            const std::vector<std::size_t>& b, std::size_t first = 0,
                            std::size_t last = (std::numeric_limits<std::size_t>::max)())
{
  last = (std::min)(last, area.size());
  std::map<std::size_t, double> in_a, in_b;
  std::map<std::pair<std::size_t, std::size_t>, double> in_both;
  double total = 0;
  for(std::size_t v = first; v < last; ++v) {
    in_a[a[v]] += area[v];
    in_b[b[v]] += area[v];
    in_both[{a[v], b[v]}] += area[v];
    total += area[v];
  }
  if(!(total > 0))
    return 0.0;
  double d = 0;
  for(const auto& kv : in_a)
    d += kv.second * kv.second;
  for(const auto& kv : in_b)
    d += kv.second * kv.second;
  for(const auto& kv : in_both)
    d -= 2 * kv.second * kv.second;
  return (std::max)(0.0, d / (total * total));
}

// Of the runs' segment ids per over-segment (`ids[r]`; over-segments of areas `area`, mesh i's
// from offset[i] to offset[i + 1]), the run closest to the others (least Rand distance summed over
// the other runs and the meshes; the first on a tie, so of two runs the first), and in
// `disagreement` its mean distance to another run's segmentation of a mesh (0 with one run).
inline std::size_t consensus_run(const std::vector<std::vector<std::size_t>>& ids, const std::vector<double>& area,
                                 const std::vector<std::size_t>& offset, double& disagreement)
{
  const std::size_t n = ids.size(), m = offset.size() - 1;
  disagreement = 0;
  if(n < 2 || m == 0)
    return 0;
  std::vector<double> sum(n, 0.0);
  for(std::size_t r = 0; r < n; ++r)
    for(std::size_t t = r + 1; t < n; ++t)
      for(std::size_t i = 0; i < m; ++i) {
        const double d = rand_distance(area, ids[r], ids[t], offset[i], offset[i + 1]);
        sum[r] += d;
        sum[t] += d;
      }
  const std::size_t best = std::size_t(std::min_element(sum.begin(), sum.end()) - sum.begin());
  disagreement = sum[best] / double((n - 1) * m);
  return best;
}

// ---------------------------------------------------------------------------------------------
// The whole computation.

inline Coseg_result cosegment(std::vector<Coseg_mesh>& meshes, const Coseg_options& o)
{
  const std::size_t m = meshes.size();
  auto report = [&](double f) {
    if(o.progress_callback)
      o.progress_callback(f);
  };

  // More segments than faces cannot be made (hierarchical_segmentation() refuses them too); a
  // symmetry plane that leaves the mesh on one side has no mirror to pair.
  std::size_t faces = 0;
  for(const Coseg_mesh& mesh : meshes)
    faces += mesh.triangles.size();
  if(o.number_of_segments > faces)
    throw CGAL::Shape_analysis::Bad_input("consistent_segmentation: number_of_segments (" + std::to_string(o.number_of_segments) +
                    ") exceeds the number of faces of the meshes (" + std::to_string(faces) + ")");
  for(const Coseg_mesh& mesh : meshes) {
    if(!mesh.has_plane)
      continue;
    double lowest = 0, highest = 0;
    for(const auto& t : mesh.triangles)
      for(const SAI::Vector_3d& c : t) {
        const double side = SAI::dot(mesh.plane_normal, c) - mesh.plane_offset;
        lowest = (std::min)(lowest, side), highest = (std::max)(highest, side);
      }
    if(!(lowest < 0 && highest > 0))
      throw CGAL::Shape_analysis::Bad_input("symmetric_segmentation: the symmetry plane does not cross the mesh (all of it lies on one side)");
  }

  const std::size_t target = o.number_of_segments == 0 ? automatic_set_count(meshes, o) : o.number_of_segments;
  const std::vector<std::vector<std::size_t>> over = oversegment_meshes(meshes, o);
  const std::vector<std::size_t> offset = oversegment_offsets(over);
  const std::vector<double> size = oversegment_areas(meshes, over, offset);
  report(0.2);

  // Stages two and three once per run, each with its own sample points (the first with
  // random_seed itself); the result is the run closest to the others.
  const std::size_t runs = (std::max)(std::size_t(1), o.number_of_runs);
  std::vector<Coseg_result> results(runs);
  std::vector<std::vector<std::size_t>> ids(runs);
  for(std::size_t r = 0; r < runs; ++r) {
    Coseg_options ro = o;
    if(r > 0)
      ro.random_seed = SAI::Random_stream::mix(o.random_seed ^ 0x52756E73ull) + r;
    results[r] = link_and_merge(meshes, over, offset, size, target, ro,
                                [&](double f) { report(0.2 + 0.79 * (double(r) + f) / double(runs)); });
    ids[r] = oversegment_ids(results[r], over, offset);
  }
  double disagreement = 0;
  const std::size_t chosen = consensus_run(ids, size, offset, disagreement);
  Coseg_result result = std::move(results[chosen]);
  result.labels.resize(m);
  for(std::size_t i = 0; i < m; ++i) {
    result.labels[i].resize(over[i].size());
    for(std::size_t v = 0; v < over[i].size(); ++v)
      result.labels[i][v] = ids[chosen][offset[i] + over[i][v]];
  }
  result.number_of_runs = runs;
  result.chosen_run = chosen;
  result.run_disagreement = disagreement;
  report(1.0);
  return result;
}

} // namespace internal
} // namespace Consistent_segmentation
} // namespace CGAL

#endif // CGAL_CONSISTENT_SEGMENTATION_INTERNAL_COSEGMENTATION_H
