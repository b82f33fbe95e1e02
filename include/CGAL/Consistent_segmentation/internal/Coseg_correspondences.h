// Copyright (c) 2026 CGAL Global Shape Analysis contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_CONSISTENT_SEGMENTATION_INTERNAL_COSEG_CORRESPONDENCES_H
#define CGAL_CONSISTENT_SEGMENTATION_INTERNAL_COSEG_CORRESPONDENCES_H

// Stage two of the co-segmentation (see Cosegmentation.h): samples on every mesh, the pairs of
// meshes to align, their alignments and the correspondences between their samples.

#include <CGAL/Consistent_segmentation/internal/Cosegmentation_types.h>
#include <CGAL/Shape_analysis/internal/Parallel.h>
#include <CGAL/Shape_analysis/internal/Point_tree.h>
#include <CGAL/Shape_analysis/internal/Random.h>
#include <CGAL/Shape_analysis/internal/Similarity_alignment.h>
#include <CGAL/Shape_analysis/internal/Triangle_sampling.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <numeric>
#include <set>
#include <utility>
#include <vector>

namespace CGAL {
namespace Consistent_segmentation {
namespace internal {

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

// Links every sample of `from` (sample i moved by `transform(i)`) to the closest compatible sample
// of `to`.
template <typename TransformOf>
void link_samples(const Surface_sample& from, std::uint32_t mesh_from, const TransformOf& transform,
                  const Surface_sample& to, const SAI::Point_tree& to_tree, std::uint32_t mesh_to,
                  const Coseg_options& o, std::vector<Correspondence>& out)
{
  const double max_distance = o.correspondence_distance * to.diagonal;
  const double weight = 1.0 / double(from.points.size());
  std::vector<std::pair<double, std::uint32_t>> near;
  for(std::size_t i = 0; i < from.points.size(); ++i) {
    const SAI::Similarity_3d& t = transform(i);
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

// Part-wise alignment, for articulated shapes (legs, arms, wings at other angles): a rigid
// correction of the mesh alignment may turn an over-segment by at most this (radians, about 34
// degrees) and move its centroid by at most this fraction of the other mesh's sample diagonal;
// over-segments of fewer samples keep the mesh alignment.
constexpr double max_part_turn = 0.6;
constexpr double max_part_shift = 0.1;
constexpr std::size_t min_part_samples = 12;

// The ICP of one over-segment: rigid, from its samples to the other mesh's (one direction,
// between samples), the closest 80% of the pairs kept.
inline SAI::Icp_options part_icp_options()
{
  SAI::Icp_options io;
  io.symmetric = false;
  io.with_scale = false;
  io.point_to_plane = false;
  io.keep_fraction = 0.8;
  io.max_iterations = 20;
  return io;
}

// The transform of every over-segment of `from` (`part_of_node`: the over-segment of each node):
// the alignment `t` of the whole mesh, corrected by a rigid ICP of the over-segment's samples alone
// against the samples of the other mesh (one direction, the closest 80% of the pairs kept; its
// steps never raise the trimmed RMS). A correction that turns by more than max_part_turn or moves
// the over-segment's centroid by more than max_part_shift is not taken.
inline std::vector<SAI::Similarity_3d>
align_parts(const Surface_sample& from, const std::vector<std::size_t>& part_of_node, const SAI::Similarity_3d& t,
            const Surface_sample& to, const SAI::Closest_sample& to_closest)
{
  std::size_t parts = 0;
  for(std::size_t p : part_of_node)
    parts = (std::max)(parts, p + 1);
  std::vector<SAI::Similarity_3d> result(parts, t);
  std::vector<std::vector<SAI::Vector_3d>> moved(parts);
  for(std::size_t i = 0; i < from.points.size(); ++i)
    moved[part_of_node[from.node[i]]].push_back(t(from.points[i]));
  const SAI::Icp_options io = part_icp_options();
  SAI::Icp_workspace w;
  for(std::size_t p = 0; p < parts; ++p) {
    const std::vector<SAI::Vector_3d>& points = moved[p];
    if(points.size() < min_part_samples)
      continue;
    // One direction: the source's closest-point query is not used, the target's stands in.
    const auto icp = SAI::make_similarity_icp(points, to_closest, to.points, to_closest);
    // run() keeps the identity unless a step does not raise the trimmed RMS.
    const SAI::Icp_result r = icp.run(SAI::Similarity_3d(), io, w);
    const double turn = SAI::rotation_angle_between(r.transform.rotation, SAI::identity_matrix());
    SAI::Vector_3d centroid;
    for(const SAI::Vector_3d& q : points)
      centroid += q;
    centroid = centroid / double(points.size());
    const double shift = (r.transform(centroid) - centroid).length();
    if(turn > max_part_turn || shift > max_part_shift * to.diagonal)
      continue;
    result[p] = r.transform.after(t);
  }
  return result;
}

// A partial symmetry's mirror links: each counts with the lower support of its two nodes, those
// of nodes outside the symmetry (support 0) are dropped. An empty `support` keeps them all.
inline void weigh_by_support(const std::vector<double>& support, std::vector<Correspondence>& mirror)
{
  if(support.empty())
    return;
  std::size_t kept = 0;
  for(const Correspondence& c : mirror) {
    const double s = (std::min)(support[c.node_a], support[c.node_b]);
    if(s > 0) {
      mirror[kept] = c;
      mirror[kept++].weight *= s;
    }
  }
  mirror.resize(kept);
}

// The samples of every mesh and their search trees.
inline void sample_meshes(const std::vector<Coseg_mesh>& meshes, const Coseg_options& o,
                          std::vector<Surface_sample>& samples, std::vector<SAI::Point_tree>& trees)
{
  const std::size_t m = meshes.size();
  samples.clear();
  samples.resize(m);
  trees.clear();
  trees.resize(m);
  SAI::Parallel_workspaces<char> workers(o.number_of_threads);
  workers.for_each(0, m, [&](std::size_t i, char&) {
    samples[i] = sample_surface(meshes[i], o.number_of_points, o.random_seed, i);
    std::vector<std::uint32_t> ids(samples[i].points.size());
    std::iota(ids.begin(), ids.end(), std::uint32_t(0));
    trees[i] = SAI::Point_tree(samples[i].points, ids);
  });
}

// The pairs of meshes to align (i < j): all of them in small sets, else each mesh with the
// 2 number_of_partners meshes of closest shape distribution.
inline std::vector<std::pair<std::uint32_t, std::uint32_t>>
pairs_to_align(const std::vector<Surface_sample>& samples, const Coseg_options& o)
{
  const std::size_t m = samples.size();
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
  return pairs;
}

// Only the pairs among the `number_of_partners` best aligned of one of their meshes keep their
// links: a poor alignment (other poses, other proportions) gives misleading correspondences.
// Returns a flag per pair (all set when number_of_partners is 0).
inline std::vector<char> best_partners(std::size_t m, const std::vector<std::pair<std::uint32_t, std::uint32_t>>& pairs,
                                       const std::vector<double>& pair_rms, std::size_t number_of_partners)
{
  if(number_of_partners == 0)
    return std::vector<char>(pairs.size(), 1);
  std::vector<std::vector<std::pair<double, std::size_t>>> of_mesh(m);
  for(std::size_t p = 0; p < pairs.size(); ++p) {
    of_mesh[pairs[p].first].emplace_back(pair_rms[p], p);
    of_mesh[pairs[p].second].emplace_back(pair_rms[p], p);
  }
  std::vector<char> keep(pairs.size(), 0);
  for(auto& list : of_mesh) {
    std::sort(list.begin(), list.end());
    for(std::size_t k = 0; k < number_of_partners && k < list.size(); ++k)
      keep[list[k].second] = 1;
  }
  return keep;
}

// Aligns every pair (the RMS of the alignment relative to the second mesh's sample diagonal in
// pair_rms[p]); for the pairs that best_partners() keeps, corrects the alignment over-segment by
// over-segment (`over`: the over-segment of every node of every mesh; align_parts()) and links the
// samples of the two meshes both ways (links[p]; empty for the other pairs); links[pairs.size() + i]
// gets the mirror correspondences of mesh i, if it has a reflection plane.
inline void link_meshes(const std::vector<Coseg_mesh>& meshes, const std::vector<Surface_sample>& samples,
                        const std::vector<SAI::Point_tree>& trees,
                        const std::vector<std::pair<std::uint32_t, std::uint32_t>>& pairs,
                        const std::vector<std::vector<std::size_t>>& over,
                        const Coseg_options& o, std::vector<std::vector<Correspondence>>& links,
                        std::vector<double>& pair_rms)
{
  const std::size_t m = meshes.size();
  links.assign(pairs.size() + m, {});
  pair_rms.assign(pairs.size(), 0.0);
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
  std::vector<SAI::Closest_sample> closest(pairs.empty() ? 0 : m); // for align_parts()
  workers.for_each(0, closest.size(), [&](std::size_t i, char&) { closest[i] = SAI::Closest_sample(samples[i].points); });
  std::vector<SAI::Similarity_3d> transform(pairs.size());
  workers.for_each(0, pairs.size(), [&](std::size_t p, char&) {
    const std::uint32_t a = pairs[p].first, b = pairs[p].second;
    const SAI::Restart_alignment_result r = SAI::align_with_restarts(prefix[a], prefix[b], ao);
    pair_rms[p] = samples[b].diagonal > 0 ? r.rms / samples[b].diagonal : 0.0;
    transform[p] = r.transform;
  });
  const std::vector<char> keep = best_partners(m, pairs, pair_rms, o.number_of_partners);
  workers.for_each(0, pairs.size(), [&](std::size_t p, char&) {
    if(!keep[p])
      return;
    const std::uint32_t a = pairs[p].first, b = pairs[p].second;
    const SAI::Similarity_3d back = transform[p].inverse();
    const std::vector<SAI::Similarity_3d> ta = align_parts(samples[a], over[a], transform[p], samples[b], closest[b]);
    const std::vector<SAI::Similarity_3d> tb = align_parts(samples[b], over[b], back, samples[a], closest[a]);
    link_samples(samples[a], a, [&](std::size_t i) -> const SAI::Similarity_3d& { return ta[over[a][samples[a].node[i]]]; },
                 samples[b], trees[b], b, o, links[p]);
    link_samples(samples[b], b, [&](std::size_t i) -> const SAI::Similarity_3d& { return tb[over[b][samples[b].node[i]]]; },
                 samples[a], trees[a], a, o, links[p]);
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
    std::vector<Correspondence>& mirror = links[pairs.size() + i];
    const SAI::Similarity_3d identity;
    link_samples(mirrored, std::uint32_t(i), [&](std::size_t) -> const SAI::Similarity_3d& { return identity; },
                 samples[i], trees[i], std::uint32_t(i), o, mirror);
    weigh_by_support(meshes[i].mirror_support, mirror);
  });
}

} // namespace internal
} // namespace Consistent_segmentation
} // namespace CGAL

#endif // CGAL_CONSISTENT_SEGMENTATION_INTERNAL_COSEG_CORRESPONDENCES_H
