// Copyright (c) 2026 CGAL Global Shape Analysis contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_POINT_SET_OBJECT_RECOGNITION_INTERNAL_LOCALIZATION_H
#define CGAL_POINT_SET_OBJECT_RECOGNITION_INTERNAL_LOCALIZATION_H

// The clusterings behind `locate_objects()` that are more than a voxel walk: blobs of a height
// image filtered by a difference of Gaussians, and agglomerative normalized-cut clustering of a
// nearest-neighbour graph of voxels (the shared clustering core and component links). Each
// returns one cluster per point (`no_component` for points in no cluster) and their number;
// clusters are numbered in the order of their first point, so that results do not depend on the
// number of threads.

#include <CGAL/Point_set_object_recognition/internal/Voxel_grid.h>
#include <CGAL/Shape_analysis/Bad_input.h>
#include <CGAL/Shape_analysis/internal/Component_links.h>
#include <CGAL/Shape_analysis/internal/Dual_graph.h>
#include <CGAL/Shape_analysis/internal/Normalized_cut_clustering.h>
#include <CGAL/Shape_analysis/internal/Parallel.h>
#include <CGAL/Shape_analysis/internal/Point_tree.h>
#include <CGAL/Shape_analysis/internal/Union_find.h>
#include <CGAL/Shape_analysis/internal/Vector_3d.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <unordered_map>
#include <utility>
#include <vector>

namespace CGAL {
namespace Point_set_object_recognition {
namespace internal {

// Renumbers per-point labels (any values, `no_component` kept) 0, 1, ... in the order of the
// labels' first points; returns their number.
inline std::size_t renumber_by_first_point(std::vector<std::uint32_t>& label)
{
  std::unordered_map<std::uint32_t, std::uint32_t> dense;
  for(std::uint32_t& l : label)
    if(l != no_component)
      l = dense.emplace(l, std::uint32_t(dense.size())).first->second;
  return dense.size();
}

// Gaussian blur of a row-major image (nx by ny) with standard deviation `sigma` in cells
// (separable, truncated at 3 sigma, zero outside).
inline std::vector<double> gaussian_blur(const std::vector<double>& image, std::size_t nx, std::size_t ny,
                                         double sigma)
{
  const long r = (std::max)(1L, long(std::ceil(3 * sigma)));
  std::vector<double> kernel(std::size_t(2 * r + 1));
  double sum = 0;
  for(long k = -r; k <= r; ++k)
    sum += kernel[std::size_t(k + r)] = std::exp(-0.5 * double(k * k) / (sigma * sigma));
  for(double& k : kernel)
    k /= sum;
  // One pass along x (step 1, length nx) or y (step nx, length ny), scattering every non-zero cell.
  const auto pass = [&](const std::vector<double>& in, std::vector<double>& out, bool along_x) {
    const std::size_t step = along_x ? 1 : nx, length = along_x ? nx : ny;
    for(std::size_t j = 0; j < ny; ++j)
      for(std::size_t i = 0; i < nx; ++i) {
        const double v = in[i + nx * j];
        if(v == 0)
          continue;
        const long at = long(along_x ? i : j);
        for(long k = (std::max)(-r, -at); k <= r && at + k < long(length); ++k)
          out[std::size_t(long(i + nx * j) + k * long(step))] += v * kernel[std::size_t(k + r)];
      }
  };
  std::vector<double> tmp(image.size(), 0.0), out(image.size(), 0.0);
  pass(image, tmp, true);
  pass(tmp, out, false);
  return out;
}

// Height image: cells of side `cell` in (x, y) hold the height of their highest point above the
// lowest point within `ground_radius` (the local ground of the foreground); the image filtered by
// the difference of Gaussians of standard deviations sigma and 3 sigma (metres) responds to
// blobs of about sigma; the cells whose response exceeds `threshold` (metres) form 8-connected
// components, each a cluster of the points of its cells.
inline std::vector<std::uint32_t> height_image_clusters(const std::vector<std::array<double, 3>>& p, double cell,
                                                        double sigma, double threshold,
                                                        const std::array<double, 3>& lo,
                                                        const std::array<double, 3>& hi,
                                                        std::size_t& number_of_clusters)
{
  const std::size_t nx = std::size_t((hi[0] - lo[0]) / cell) + 1, ny = std::size_t((hi[1] - lo[1]) / cell) + 1;
  if(double(nx) * double(ny) > 2.0e8)
    throw CGAL::Shape_analysis::Bad_input("locate_objects: the height image would have more than 2e8 cells; "
                                          "process the scene in tiles or use larger cells");
  const double inf = std::numeric_limits<double>::infinity();
  std::vector<double> top(nx * ny, -inf), bottom(nx * ny, inf);
  std::vector<std::size_t> cell_of(p.size());
  for(std::size_t i = 0; i < p.size(); ++i) {
    const std::size_t ci = (std::min)(nx - 1, std::size_t((p[i][0] - lo[0]) / cell));
    const std::size_t cj = (std::min)(ny - 1, std::size_t((p[i][1] - lo[1]) / cell));
    const std::size_t c = ci + nx * cj;
    cell_of[i] = c;
    top[c] = (std::max)(top[c], p[i][2]);
    bottom[c] = (std::min)(bottom[c], p[i][2]);
  }
  // Local ground: separable minimum filter of the lowest heights over +-ground_radius.
  const double ground_radius = 1.5;
  const long w = (std::max)(1L, long(std::ceil(ground_radius / cell)));
  // Sliding minimum over +-w cells with a monotone deque, along x (rows) or y (columns).
  const auto pass = [&](const std::vector<double>& in, std::vector<double>& out, bool along_x) {
    const std::size_t step = along_x ? 1 : nx, length = along_x ? nx : ny, lines = along_x ? ny : nx;
    std::vector<std::size_t> dq;
    for(std::size_t line = 0; line < lines; ++line) {
      const std::size_t first = along_x ? nx * line : line;
      dq.clear();
      std::size_t head = 0;
      for(long t = 0; t < long(length) + w; ++t) {
        if(t < long(length)) {
          const double v = in[first + step * std::size_t(t)];
          while(dq.size() > head && in[first + step * dq.back()] >= v)
            dq.pop_back();
          dq.push_back(std::size_t(t));
        }
        const long centre = t - w;
        if(centre < 0)
          continue;
        while(long(dq[head]) < centre - w)
          ++head;
        out[first + step * std::size_t(centre)] = in[first + step * dq[head]];
      }
    }
  };
  std::vector<double> rows(nx * ny, inf), ground(nx * ny, inf);
  pass(bottom, rows, true);
  pass(rows, ground, false);
  std::vector<double> image(nx * ny, 0.0);
  for(std::size_t c = 0; c < nx * ny; ++c)
    if(top[c] > -inf)
      image[c] = top[c] - ground[c];
  const std::vector<double> fine = gaussian_blur(image, nx, ny, sigma / cell);
  const std::vector<double> coarse = gaussian_blur(image, nx, ny, 3 * sigma / cell);
  // Components of the cells above the threshold (8-connected), numbered by their first point.
  const std::uint32_t none = no_component;
  std::vector<std::uint32_t> cell_component(nx * ny, none);
  CGAL::Shape_analysis::internal::Union_find uf(nx * ny);
  for(std::size_t j = 0; j < ny; ++j)
    for(std::size_t i = 0; i < nx; ++i) {
      const std::size_t c = i + nx * j;
      if(!(fine[c] - coarse[c] > threshold))
        continue;
      cell_component[c] = std::uint32_t(c);
      for(const auto& d : {std::array<long, 2>{{-1, 0}}, std::array<long, 2>{{-1, -1}}, std::array<long, 2>{{0, -1}},
                           std::array<long, 2>{{1, -1}}}) {
        const long ii = long(i) + d[0], jj = long(j) + d[1];
        if(ii < 0 || jj < 0 || ii >= long(nx))
          continue;
        const std::size_t e = std::size_t(ii) + nx * std::size_t(jj);
        if(cell_component[e] != none)
          uf.unite(std::uint32_t(c), std::uint32_t(e));
      }
    }
  std::vector<std::uint32_t> cluster(p.size(), none);
  for(std::size_t i = 0; i < p.size(); ++i)
    if(cell_component[cell_of[i]] != none)
      cluster[i] = uf.find(std::uint32_t(cell_of[i]));
  number_of_clusters = renumber_by_first_point(cluster);
  return cluster;
}

// The nodes of normalized_cut_clusters(): the voxels of side `cell`, numbered by their first
// point (per point its node), at their centroids, of size 1 each.
inline void voxel_nodes(const std::vector<std::array<double, 3>>& p, double cell, const std::array<double, 3>& lo,
                        std::vector<std::uint32_t>& node_of_point, CGAL::Shape_analysis::internal::Dual_graph& g)
{
  namespace SAI = CGAL::Shape_analysis::internal;
  std::unordered_map<std::uint64_t, std::uint32_t> index;
  node_of_point.resize(p.size());
  std::vector<std::array<double, 4>> sum; // x, y, z, count
  for(std::size_t i = 0; i < p.size(); ++i) {
    const auto ins = index.emplace(voxel_key(p[i][0], p[i][1], p[i][2], cell, lo), std::uint32_t(sum.size()));
    if(ins.second)
      sum.push_back({0, 0, 0, 0});
    auto& s = sum[ins.first->second];
    s[0] += p[i][0] - lo[0], s[1] += p[i][1] - lo[1], s[2] += p[i][2] - lo[2], s[3] += 1;
    node_of_point[i] = ins.first->second;
  }
  const std::size_t n = sum.size();
  g.node_size.assign(n, 1.0);
  g.node_position.resize(n);
  g.node_normal.assign(n, SAI::Vector_3d(0.0));
  SAI::Vector_3d box_lo(std::numeric_limits<double>::infinity()), box_hi(-std::numeric_limits<double>::infinity());
  for(std::size_t v = 0; v < n; ++v) {
    g.node_position[v] = SAI::Vector_3d(sum[v][0] / sum[v][3], sum[v][1] / sum[v][3], sum[v][2] / sum[v][3]);
    box_lo = box_lo.min(g.node_position[v]);
    box_hi = box_hi.max(g.node_position[v]);
  }
  g.bbox_diagonal = (std::max)(cell, (box_hi - box_lo).length());
}

// The weight exp(-d^2 / (2 cell^2)) of the edge between nodes a and b of `g`.
inline double voxel_edge_weight(const CGAL::Shape_analysis::internal::Dual_graph& g, double cell, std::uint32_t a,
                                std::uint32_t b)
{
  const double s2 = 2 * cell * cell;
  return std::exp(-(g.node_position[a] - g.node_position[b]).squared_length() / s2);
}

// The edges of every node of `g` to its 4 nearest neighbours (found in parallel, one result per
// node), each once, by increasing pair of nodes.
inline void add_nearest_voxel_edges(CGAL::Shape_analysis::internal::Dual_graph& g, double cell, std::size_t threads)
{
  namespace SAI = CGAL::Shape_analysis::internal;
  const std::size_t n = g.node_position.size(), k = 4;
  std::vector<std::uint32_t> ids(n);
  for(std::size_t v = 0; v < n; ++v)
    ids[v] = std::uint32_t(v);
  const SAI::Point_tree tree(g.node_position, ids);
  std::vector<std::array<std::uint32_t, 4>> near(n);
  SAI::Parallel_workspaces<std::vector<std::pair<double, std::uint32_t>>> parallel(threads);
  parallel.for_each(0, n, [&](std::size_t v, std::vector<std::pair<double, std::uint32_t>>& found) {
    tree.k_nearest(g.node_position[v], k + 1, found);
    std::size_t m = 0;
    near[v].fill(no_component);
    for(const auto& f : found)
      if(f.second != v && m < k)
        near[v][m++] = f.second;
  });
  std::vector<std::uint64_t> pairs;
  pairs.reserve(k * n);
  for(std::size_t v = 0; v < n; ++v)
    for(std::uint32_t u : near[v])
      if(u != no_component)
        pairs.push_back((std::uint64_t((std::min)(std::uint32_t(v), u)) << 32) | (std::max)(std::uint32_t(v), u));
  std::sort(pairs.begin(), pairs.end());
  pairs.erase(std::unique(pairs.begin(), pairs.end()), pairs.end());
  for(std::size_t e = 0; e < pairs.size(); ++e) {
    const std::uint32_t a = std::uint32_t(pairs[e] >> 32), b = std::uint32_t(pairs[e] & 0xffffffffu);
    g.add_edge(a, b, 0.0, 1.0, voxel_edge_weight(g, cell, a, b), 0.0, e);
  }
}

// Voxels joined by strong edges (closer than 1.5 voxels: the normalized cut between two such
// voxels, 2 w, is far above any sensible threshold) start together, which spares the queue most
// of its work on large scenes.
inline void merge_strong_edges(CGAL::Shape_analysis::internal::Normalized_cut_clustering& clustering, std::size_t n,
                               const std::vector<std::uint32_t>& source, const std::vector<std::uint32_t>& target,
                               const std::vector<double>& w, double threshold)
{
  const double strong = 0.3;
  CGAL::Shape_analysis::internal::Union_find together(n);
  for(std::size_t e = 0; e < w.size(); ++e)
    if(w[e] >= strong && 2 * w[e] >= threshold)
      together.unite(source[e], target[e]);
  std::vector<std::uint32_t> group;
  together.dense_labels(group);
  clustering.merge_groups(group);
}

// Normalized-cut clustering of the voxels of side `cell` (nodes: the voxels' centroids, of size
// 1 each), joined to their 4 nearest neighbours with weights exp(-d^2 / (2 cell^2)); the closest
// nodes of disconnected components within 5 cells are linked (shared component links, reweighted
// the same way). Clusters merge greedily by the decrease of sum cut(S) / size(S) (shared
// clustering core), while the normalized cut between the two, w(S, T) (1/|S| + 1/|T|), is at
// least `threshold`. Nearest-neighbour searches run on `threads` threads.
inline std::vector<std::uint32_t> normalized_cut_clusters(const std::vector<std::array<double, 3>>& p, double cell,
                                                          double threshold, const std::array<double, 3>& lo,
                                                          std::size_t threads, std::size_t& number_of_clusters)
{
  namespace SAI = CGAL::Shape_analysis::internal;
  std::vector<std::uint32_t> node_of_point;
  SAI::Dual_graph g;
  voxel_nodes(p, cell, lo, node_of_point, g);
  const std::size_t n = g.node_position.size();
  add_nearest_voxel_edges(g, cell, threads);
  // Links between the components of the graph: the closest nodes within 5 cells.
  SAI::Component_link_options links;
  links.link_distance = 5 * cell / g.bbox_diagonal;
  links.epsilon = cell / g.bbox_diagonal;
  SAI::add_component_links(g, links);
  std::vector<double> sizes = g.node_size;
  std::vector<std::uint32_t> source, target;
  std::vector<double> w;
  for(std::size_t e = 0; e < g.number_of_edges(); ++e) {
    const double we = g.mesh_edge[e] == SAI::Dual_graph::no_mesh_edge
                        ? voxel_edge_weight(g, cell, g.edge_source[e], g.edge_target[e])
                        : g.cut_cost[e];
    if(!(we > 1e-9))
      continue;
    source.push_back(g.edge_source[e]);
    target.push_back(g.edge_target[e]);
    w.push_back(we);
  }
  SAI::Normalized_cut_clustering clustering(sizes, source, target, w);
  merge_strong_edges(clustering, n, source, target, w, threshold);
  const auto between = [&](std::uint32_t a, std::uint32_t b) {
    const auto& list = clustering.neighbors(a);
    const auto it = std::lower_bound(list.begin(), list.end(), b,
                                     [](const std::pair<std::uint32_t, double>& x, std::uint32_t y) { return x.first < y; });
    return (it != list.end() && it->first == b) ? it->second : 0.0;
  };
  clustering.run(1, [&](std::uint32_t a, std::uint32_t b) {
    return between(a, b) * (1 / clustering.cluster_size(a) + 1 / clustering.cluster_size(b)) >= threshold;
  });
  std::vector<std::uint32_t> cluster(p.size());
  for(std::size_t i = 0; i < p.size(); ++i)
    cluster[i] = clustering.find(node_of_point[i]);
  number_of_clusters = renumber_by_first_point(cluster);
  return cluster;
}

} // namespace internal
} // namespace Point_set_object_recognition
} // namespace CGAL

#endif // CGAL_POINT_SET_OBJECT_RECOGNITION_INTERNAL_LOCALIZATION_H
