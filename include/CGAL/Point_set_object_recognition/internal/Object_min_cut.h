// Copyright (c) 2026 CGAL Global Shape Analysis contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_POINT_SET_OBJECT_RECOGNITION_INTERNAL_OBJECT_MIN_CUT_H
#define CGAL_POINT_SET_OBJECT_RECOGNITION_INTERNAL_OBJECT_MIN_CUT_H

// The min-cut of one object: the subgraph around its location with the background penalty, hard
// foreground seeds, optional contraction, and the s-t minimum cut
// (Shape_analysis/internal/Min_cut.h).

#include <CGAL/Point_set_object_recognition/internal/Column_index.h>
#include <CGAL/Point_set_object_recognition/internal/Object_graph.h>
#include <CGAL/Point_set_object_recognition/internal/Segmentation_graph.h>
#include <CGAL/Point_set_object_recognition/internal/Segmentation_options.h>
#include <CGAL/Shape_analysis/internal/Min_cut.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <numeric>
#include <utility>
#include <vector>

namespace CGAL {
namespace Point_set_object_recognition {
namespace internal {

namespace SAI = CGAL::Shape_analysis::internal;

// Per-thread buffers of the segmentation of objects.
struct Segmentation_workspace
{
  SAI::Terminal_min_cut cut;
  Object_graph graph;
  std::vector<std::uint32_t> local_of, nodes, candidates;
};

// The data term per point at horizontal distance d from the location, for the background radius
// R, in two linear ramps: a foreground reward (the cost of putting the point in the background)
// falling from `background_weight` at the location to 0 at R, then a background penalty (the
// cost of putting it in the foreground) rising from 0 at R to `outer_factor` times that weight
// at R + ramp_width; beyond, the hard background.
inline double foreground_reward(double d, double R, const Segmentation_options& o)
{
  return d < R ? o.background_weight * (1 - d / R) : 0.0;
}
inline double background_penalty(double d, double R, const Segmentation_options& o)
{
  return d <= R ? 0.0 : o.background_weight * outer_factor * (std::min)(1.0, (d - R) / ramp_width);
}

// The hard foreground: the point nearest to the vertical segment from the location up to
// `height` above it (the thesis takes the point nearest to the segment's top; the segment
// prefers the object to a wall right behind it), the nearest to the top among equally near
// ones, and its three nearest neighbours, among `candidates` (in any order); empty when there is none.
inline std::vector<std::uint32_t> foreground_seeds(const std::vector<P3>& p, const std::vector<std::uint32_t>& candidates,
                                                   const P3& location, double height)
{
  std::vector<std::uint32_t> seeds;
  if(candidates.empty())
    return seeds;
  const P3 target{{location[0], location[1], location[2] + height}};
  auto d2 = [&](const P3& a, const P3& b) {
    return (a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) + (a[2] - b[2]) * (a[2] - b[2]);
  };
  const double z0 = (std::min)(location[2], target[2]), z1 = (std::max)(location[2], target[2]);
  auto to_segment = [&](const P3& a) {
    const double z = (std::min)(z1, (std::max)(z0, a[2]));
    return d2(a, P3{{location[0], location[1], z}});
  };
  std::uint32_t best = candidates.front();
  double best_d = to_segment(p[best]), best_top = d2(p[best], target);
  for(std::uint32_t i : candidates) {
    const double d = to_segment(p[i]), top = d2(p[i], target);
    if(d < best_d || (d == best_d && (top < best_top || (top == best_top && i < best)))) // ties: the first point
      best_d = d, best_top = top, best = i;
  }
  std::vector<std::pair<double, std::uint32_t>> near;
  for(std::uint32_t i : candidates)
    if(i != best)
      near.emplace_back(d2(p[i], p[best]), i);
  const std::size_t m = (std::min)(near.size(), std::size_t(3));
  std::partial_sort(near.begin(), near.begin() + long(m), near.end());
  seeds.push_back(best);
  for(std::size_t k = 0; k < m; ++k)
    seeds.push_back(near[k].second);
  return seeds;
}

// The hard foreground of the object at `location` among the points within 2 m of it (within the
// graph of radius R when there is none).
inline std::vector<std::uint32_t> object_seeds(const Segmentation_index& index, const P3& location, double R,
                                               const Segmentation_options& o, std::vector<std::uint32_t>& candidates)
{
  index.points_off_walls_within(location, (std::min)(R + ramp_width, 2.0), candidates);
  if(candidates.empty())
    index.points_off_walls_within(location, R + ramp_width, candidates);
  return foreground_seeds(index.points(), candidates, location, o.foreground_height);
}

// One min-cut at background radius R: fills `w.graph` (and w.nodes, the index's nodes of the
// graph), solves, and returns the foreground nodes (indices into w.nodes) with the cut cost:
// the weight of the edges cut, inside the graph and to the hard background beyond it, over the
// mean point count of the foreground's nodes (so that with one point per node it is the plain
// sum of the Gaussian weights cut).
struct Cut_outcome
{
  std::vector<std::uint32_t> foreground; // positions in w.nodes
  double cut = 0;
  std::size_t points = 0;
};

inline void build_object_graph(const Segmentation_index& index, const P3& location, double R,
                               const std::vector<std::uint32_t>& seed_points, const Segmentation_options& o,
                               Segmentation_workspace& w, std::vector<double>& outside, bool with_walls = false)
{
  index.nodes_within(location, R + ramp_width, w.nodes, with_walls);
  if(w.local_of.size() < index.number_of_nodes())
    w.local_of.assign(index.number_of_nodes(), Segmentation_index::none);
  for(std::size_t k = 0; k < w.nodes.size(); ++k)
    w.local_of[w.nodes[k]] = std::uint32_t(k);
  Object_graph& g = w.graph;
  g.clear();
  const std::size_t n = w.nodes.size();
  g.reward.resize(n), g.penalty.resize(n), g.points.resize(n), g.cells.assign(n, 1.0), g.seed.assign(n, 0);
  outside.assign(n, 0.0);
  for(std::size_t k = 0; k < n; ++k) {
    const std::uint32_t v = w.nodes[k];
    g.points[k] = index.count(v);
    const double d = horizontal_distance(index.centroid(v), location);
    g.reward[k] = index.count(v) * foreground_reward(d, R, o);
    g.penalty[k] = index.count(v) * background_penalty(d, R, o);
    index.for_adjacent(v, [&](std::uint32_t u, double weight) {
      const std::uint32_t l = w.local_of[u];
      if(l == Segmentation_index::none)
        outside[k] += weight;
      else if(l > k)
        g.edges.push_back({{std::uint32_t(k), l}}), g.weight.push_back(weight);
    });
    g.penalty[k] += outside[k];
  }
  // The hard foreground: the nodes of the seed points and, with cells, the `seed_neighbors`
  // nodes nearest to the first one (the thesis' point and its three neighbours, on nodes).
  std::vector<std::uint32_t> seed_nodes;
  for(std::uint32_t i : seed_points)
    seed_nodes.push_back(index.node_of_point(i));
  if(!seed_points.empty() && o.graph_cell_size > 0 && seed_nodes.front() != Segmentation_index::none) {
    const std::uint32_t v0 = seed_nodes.front();
    std::vector<std::pair<double, std::uint32_t>> near;
    index.for_adjacent(v0, [&](std::uint32_t u, double) {
      const P3& a = index.centroid(u);
      const P3& b = index.centroid(v0);
      near.emplace_back((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) + (a[2] - b[2]) * (a[2] - b[2]), u);
    });
    std::sort(near.begin(), near.end());
    for(std::size_t k = 0; k < near.size() && k < seed_neighbors; ++k)
      seed_nodes.push_back(near[k].second);
  }
  for(std::uint32_t v : seed_nodes)
    if(v != Segmentation_index::none && w.local_of[v] != Segmentation_index::none)
      g.seed[w.local_of[v]] = 1;
  for(std::uint32_t v : w.nodes)
    w.local_of[v] = Segmentation_index::none;
}

// The nodes of the source side connected to a seed through edges of the source side: the
// foreground (the reward of the data term would otherwise add any separate cluster within the
// radius for free).
inline std::vector<char> connected_to_seeds(std::size_t n, const std::vector<std::array<std::uint32_t, 2>>& edges,
                                            const std::vector<char>& seed, const std::vector<char>& source_side)
{
  std::vector<std::size_t> first(n + 1, 0);
  for(const auto& e : edges)
    if(source_side[e[0]] && source_side[e[1]])
      ++first[e[0] + 1], ++first[e[1] + 1];
  for(std::size_t v = 0; v < n; ++v)
    first[v + 1] += first[v];
  std::vector<std::uint32_t> adjacent(first[n]);
  {
    std::vector<std::size_t> fill(first.begin(), first.end() - 1);
    for(const auto& e : edges)
      if(source_side[e[0]] && source_side[e[1]])
        adjacent[fill[e[0]]++] = e[1], adjacent[fill[e[1]]++] = e[0];
  }
  std::vector<char> reached(n, 0);
  std::vector<std::uint32_t> stack;
  for(std::size_t v = 0; v < n; ++v)
    if(seed[v] && source_side[v])
      reached[v] = 1, stack.push_back(std::uint32_t(v));
  while(!stack.empty()) {
    const std::uint32_t v = stack.back();
    stack.pop_back();
    for(std::size_t a = first[v]; a < first[v + 1]; ++a)
      if(!reached[adjacent[a]])
        reached[adjacent[a]] = 1, stack.push_back(adjacent[a]);
  }
  return reached;
}

// The cut problem of `g`: its edges, its terminal capacities, its seeds bound to the source.
inline void load_cut(const Object_graph& g, SAI::Terminal_min_cut& cut)
{
  const std::size_t n = g.penalty.size();
  cut.reset(n);
  for(std::size_t e = 0; e < g.edges.size(); ++e)
    cut.add_edge(g.edges[e][0], g.edges[e][1], g.weight[e]);
  for(std::size_t k = 0; k < n; ++k) {
    cut.set_terminal_capacity(k, g.reward[k], g.penalty[k]);
    if(g.seed[k])
      cut.constrain(k, SAI::Terminal_min_cut::SOURCE);
  }
}

inline Cut_outcome min_cut_at_radius(const Segmentation_index& index, const P3& location, double R,
                                     const std::vector<std::uint32_t>& seed_points, const Segmentation_options& o,
                                     Segmentation_workspace& w)
{
  std::vector<double> outside;
  build_object_graph(index, location, R, seed_points, o, w, outside);
  Object_graph& g = w.graph;
  const std::size_t fine = g.penalty.size();
  // Per fine node, the weight to the hard background beyond the graph (already in its penalty).
  std::vector<double> fine_outside = outside;
  g.contract(o.maximum_graph_size);
  if(g.coarse.empty()) {
    g.coarse.resize(fine);
    std::iota(g.coarse.begin(), g.coarse.end(), 0u);
  }
  const std::size_t n = g.penalty.size();
  std::vector<double> coarse_outside(n, 0.0);
  for(std::size_t k = 0; k < fine; ++k)
    coarse_outside[g.coarse[k]] += fine_outside[k];
  SAI::Terminal_min_cut& cut = w.cut;
  load_cut(g, cut);
  cut.solve();
  std::vector<char> source_side(n);
  for(std::size_t k = 0; k < n; ++k)
    source_side[k] = cut.is_source_side(k) ? 1 : 0;
  const std::vector<char> fg = connected_to_seeds(n, g.edges, g.seed, source_side);
  Cut_outcome r;
  double edge_cut = 0, fg_points = 0, fg_cells = 0;
  for(std::size_t e = 0; e < g.edges.size(); ++e)
    if(fg[g.edges[e][0]] != fg[g.edges[e][1]])
      edge_cut += g.weight[e];
  for(std::size_t k = 0; k < n; ++k)
    if(fg[k]) {
      edge_cut += coarse_outside[k];
      fg_points += g.points[k];
      fg_cells += g.cells[k];
    }
  for(std::size_t k = 0; k < fine; ++k)
    if(fg[g.coarse[k]])
      r.foreground.push_back(std::uint32_t(k));
  r.points = std::size_t(fg_points + 0.5);
  r.cut = fg_cells > 0 ? edge_cut / (fg_points / fg_cells) : 0.0;
  return r;
}

} // namespace internal
} // namespace Point_set_object_recognition
} // namespace CGAL

#endif // CGAL_POINT_SET_OBJECT_RECOGNITION_INTERNAL_OBJECT_MIN_CUT_H
