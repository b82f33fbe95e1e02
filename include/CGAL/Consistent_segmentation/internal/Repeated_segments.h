// Copyright (c) 2026 CGAL Global Shape Analysis contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_CONSISTENT_SEGMENTATION_INTERNAL_REPEATED_SEGMENTS_H
#define CGAL_CONSISTENT_SEGMENTATION_INTERNAL_REPEATED_SEGMENTS_H

// The ids of a consistent segmentation whose parts repeat within the meshes (the legs of a chair,
// its two armrests), mesh independent: two ids are repeats of one part when, in at least half of
// the meshes that have both, their regions have about the same area and one region, moved by a
// rigid motion or a rigid motion and a reflection, lies on the other.

#include <CGAL/Shape_analysis/internal/Parallel.h>
#include <CGAL/Shape_analysis/internal/Random.h>
#include <CGAL/Shape_analysis/internal/Similarity_alignment.h>
#include <CGAL/Shape_analysis/internal/Triangle_sampling.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <memory>
#include <numeric>
#include <utility>
#include <vector>

namespace CGAL {
namespace Consistent_segmentation {
namespace internal {

namespace SAI = CGAL::Shape_analysis::internal;

struct Repeated_segments_options
{
  double tolerance = 0.03;            // RMS distance after alignment / RMS radius of a region
  double minimum_area_ratio = 0.75;   // smaller / larger area of two regions
  std::size_t number_of_points = 150; // per region
  std::size_t meshes_per_pair = 6;    // at most this many meshes decide whether two ids repeat
  std::uint64_t random_seed = 0;
  std::size_t number_of_threads = 0;
};

// One mesh: its triangles and the segment id of each.
struct Segmented_triangles
{
  std::vector<std::array<SAI::Vector_3d, 3>> triangles;
  std::vector<std::size_t> ids;
};

// One region (the triangles of one id in one mesh): points drawn on it (uniform by area), and its
// surface as it is and mirrored (x negated) for the closest-point queries of the alignments.
struct Region
{
  std::vector<SAI::Vector_3d> points, mirrored_points;
  std::unique_ptr<SAI::Closest_surface_point> surface, mirrored_surface;
};

inline std::array<SAI::Vector_3d, 3> mirrored(const std::array<SAI::Vector_3d, 3>& t)
{
  std::array<SAI::Vector_3d, 3> r = {t[0], t[2], t[1]}; // the orientation flips with the reflection
  for(SAI::Vector_3d& p : r)
    p.x = -p.x;
  return r;
}

inline Region make_region(const Segmented_triangles& mesh, std::size_t s, const std::vector<double>& area,
                          std::size_t count, std::uint64_t seed, std::uint64_t stream)
{
  std::vector<double> weights(mesh.triangles.size(), 0.0);
  std::vector<std::array<SAI::Vector_3d, 3>> triangles, flipped;
  for(std::size_t f = 0; f < mesh.triangles.size(); ++f)
    if(mesh.ids[f] == s) {
      weights[f] = area[f];
      triangles.push_back(mesh.triangles[f]);
      flipped.push_back(mirrored(mesh.triangles[f]));
    }
  const SAI::Weighted_triangle_sampler sampler(weights);
  SAI::Random_stream rng(SAI::Random_stream::mix(seed ^ 0x5265706561747321ull), stream);
  Region r;
  r.points.resize(count);
  for(SAI::Vector_3d& p : r.points)
    p = SAI::Weighted_triangle_sampler::point_in(mesh.triangles[sampler.triangle(rng)], rng);
  r.mirrored_points = r.points;
  for(SAI::Vector_3d& p : r.mirrored_points)
    p.x = -p.x;
  r.surface = std::make_unique<SAI::Closest_surface_point>(triangles);
  r.mirrored_surface = std::make_unique<SAI::Closest_surface_point>(flipped);
  return r;
}

// How far region `b` is from being a copy of region `a`: the trimmed RMS distance between the
// surfaces after the best rigid alignment of b (as it is, or mirrored) onto a, over the RMS radius
// of a.
inline double repeat_distance(const Region& a, const Region& b)
{
  const double radius = SAI::weighted_pca(a.points).rms_radius();
  if(!(radius > 0))
    return std::numeric_limits<double>::infinity();
  SAI::Restart_alignment_options ao;
  ao.icp.with_scale = false;
  ao.coarse_points = 60;
  ao.coarse_iterations = 10;
  ao.refined_restarts = 2;
  ao.icp.max_iterations = 20;
  ao.surface_iterations = 10;
  ao.number_of_threads = 1;
  const double direct = SAI::align_with_restarts(b.points, a.points, ao, b.surface.get(), a.surface.get()).rms;
  const double reflected =
    SAI::align_with_restarts(b.mirrored_points, a.points, ao, b.mirrored_surface.get(), a.surface.get()).rms;
  return (std::min)(direct, reflected) / radius;
}

// For every id (0 .. number_of_ids - 1), the id of its group of repeats: the smallest id of the
// group. Ids with a known label (`label[s]` >= 0) are never grouped.
inline std::vector<std::size_t> repeated_segment_groups(const std::vector<Segmented_triangles>& meshes,
                                                        std::size_t number_of_ids,
                                                        const std::vector<long long>& label,
                                                        const Repeated_segments_options& o)
{
  const std::size_t m = meshes.size();
  // Area of every triangle, and of every id in every mesh.
  std::vector<std::vector<double>> triangle_area(m);
  std::vector<std::vector<double>> area(m, std::vector<double>(number_of_ids, 0.0));
  for(std::size_t i = 0; i < m; ++i) {
    const Segmented_triangles& mesh = meshes[i];
    triangle_area[i].resize(mesh.triangles.size());
    for(std::size_t f = 0; f < mesh.triangles.size(); ++f) {
      const auto& t = mesh.triangles[f];
      triangle_area[i][f] = 0.5 * SAI::cross(t[1] - t[0], t[2] - t[0]).length();
      area[i][mesh.ids[f]] += triangle_area[i][f];
    }
  }
  // The work: (pair of ids, mesh) where both regions have area and about the same.
  struct Item
  {
    std::size_t a, b, mesh;
  };
  std::vector<Item> items;
  std::vector<std::size_t> compared; // per pair with items: the meshes that have both
  for(std::size_t a = 0; a < number_of_ids; ++a)
    for(std::size_t b = a + 1; b < number_of_ids; ++b) {
      if((a < label.size() && label[a] >= 0) || (b < label.size() && label[b] >= 0))
        continue;
      std::size_t both = 0;
      const std::size_t first = items.size();
      for(std::size_t i = 0; i < m && both < o.meshes_per_pair; ++i) {
        const double x = area[i][a], y = area[i][b];
        if(!(x > 0 && y > 0))
          continue;
        ++both;
        if((std::min)(x, y) >= o.minimum_area_ratio * (std::max)(x, y))
          items.push_back(Item{a, b, i});
      }
      if(2 * (items.size() - first) < both || both == 0)
        items.resize(first); // too few meshes where the areas agree
      else
        compared.push_back(both);
    }
  // The samples of every (mesh, id) that some item compares, drawn once.
  std::vector<std::pair<std::size_t, std::size_t>> regions;
  for(const Item& it : items) {
    regions.emplace_back(it.mesh, it.a);
    regions.emplace_back(it.mesh, it.b);
  }
  std::sort(regions.begin(), regions.end());
  regions.erase(std::unique(regions.begin(), regions.end()), regions.end());
  std::vector<Region> samples(regions.size());
  SAI::Parallel_workspaces<char> workers(o.number_of_threads);
  workers.for_each(0, regions.size(), [&](std::size_t k, char&) {
    const std::size_t i = regions[k].first, s = regions[k].second;
    samples[k] = make_region(meshes[i], s, triangle_area[i], o.number_of_points, o.random_seed,
                             (std::uint64_t(i) << 32) ^ std::uint64_t(s));
  });
  auto sample_of = [&](std::size_t i, std::size_t s) -> const Region& {
    return samples[std::size_t(std::lower_bound(regions.begin(), regions.end(), std::make_pair(i, s)) - regions.begin())];
  };
  std::vector<char> repeat(items.size(), 0);
  workers.for_each(0, items.size(), [&](std::size_t k, char&) {
    const Item& it = items[k];
    repeat[k] = repeat_distance(sample_of(it.mesh, it.a), sample_of(it.mesh, it.b)) <= o.tolerance ? 1 : 0;
  });
  // A pair repeats when it does in at least half of the meshes that have both.
  std::vector<std::size_t> group(number_of_ids);
  std::iota(group.begin(), group.end(), std::size_t(0));
  auto find = [&](std::size_t x) {
    while(group[x] != x)
      x = group[x] = group[group[x]];
    return x;
  };
  for(std::size_t k = 0, pair = 0; k < items.size(); ++pair) {
    const std::size_t a = items[k].a, b = items[k].b;
    std::size_t yes = 0;
    for(; k < items.size() && items[k].a == a && items[k].b == b; ++k)
      yes += std::size_t(repeat[k]);
    if(2 * yes >= compared[pair]) {
      const std::size_t ra = find(a), rb = find(b);
      group[(std::max)(ra, rb)] = (std::min)(ra, rb);
    }
  }
  for(std::size_t s = 0; s < number_of_ids; ++s)
    group[s] = find(s);
  return group;
}

} // namespace internal
} // namespace Consistent_segmentation
} // namespace CGAL

#endif // CGAL_CONSISTENT_SEGMENTATION_INTERNAL_REPEATED_SEGMENTS_H
