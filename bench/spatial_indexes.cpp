// Copyright (c) 2026 CGAL Global Shape Analysis contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later

// The project's spatial indexes against CGAL's (or the standard library's), each on the workload
// where the project uses it: seconds to build and to query (one thread), the ratio own / CGAL,
// and whether both give the same answers. It is the reason each own index is kept (issue 22):
//
//   bench_spatial_indexes [--data DIR] [--street-points 400000] [--moves 5] [--repeats 3]
//                        [--output FILE]
//
//   - point_tree_knn_street: internal::Point_tree k_nearest(k + 1 = 9) for every node of a
//     generated street (Urban_scene.h, voxel centroids in 0.2 m cells: the nodes of the
//     segmentation graph of Nearest_nodes.h nearest_in_tree and of Localization.h) against
//     CGAL::Orthogonal_k_neighbor_search on a Kd_tree (Search_traits_3, Sliding_midpoint).
//     Point_tree is that kd-tree behind the callers' interface (ids, distance bound, ties in the
//     order given), so the ratio is the price of that interface;
//   - key_map_street: the hash map of cells of the segmentation (Column_index.h Key_map) against
//     std::unordered_map on the keys of the street's points;
//   - cell_stack_knn_street: the same nodes, k = 8, with Nearest_nodes.h's Cell_stack_neighbors
//     (the graph's default, graph_cell_size 0.2 m; bounded to 7 x 7 x 7 cells, so not exact by
//     design: the report says how often and how far its k-th neighbour differs);
//   - point_tree_knn_mesh: the same on the face centroids of armadillo.off, k = 8 (the surface
//     samples of Coseg_correspondences.h);
//   - point_tree_nearest_mesh: nearest() of the face centroids of camel.off at the vertices
//     (Component_links.h, Similarity_alignment.h) against Orthogonal_k_neighbor_search with k = 1;
//   - nearest_sample_tree_icp: the ICP's own tree (Nearest_sample_tree, Similarity_alignment.h)
//     on every fifth vertex of camel.off, queried at every vertex ten times, against CGAL's
//     kd-tree with k = 1;
//   - distance_grid_far_points: Surface_mesh_symmetrization's Distance_grid dropping mirrored
//     points far from the surface before the AABB tree is asked, against the AABB tree alone;
//   - surface_index_closest: Surface_mesh_symmetrization's Surface_index::closest() (Bvh of the
//     triangles) at every vertex of armadillo.off mirrored through the plane x = centre, against
//     CGAL::AABB_tree of AABB_face_graph_triangle_primitive (with accelerate_distance_queries());
//   - surface_index_moving: --moves times, the vertices move (a smooth displacement of 0.5% of the
//     bounding-box diagonal), the index follows (Surface_index::update(), which refits the Bvh,
//     against rebuilding the AABB tree) and every mirrored vertex is queried again: the
//     symmetrization's loop (Symmetrization.h: update() then mirror_points());
//   - surface_index_moving_hinted: the same, the queries in the index's vertex order and each
//     hinted by the previous move's answer, as mirror_points() does (CGAL: the closest point of
//     the previous face as the hint of closest_point_and_primitive()).
// The static timings are the smallest of --repeats runs; the moving ones the sums over --moves.
// JSON to stdout and to FILE; progress to stderr.

#include <CGAL/AABB_face_graph_triangle_primitive.h>
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Orthogonal_k_neighbor_search.h>
#include <CGAL/Search_traits_3.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>

#include <CGAL/Point_set_object_recognition/internal/Column_index.h>
#include <CGAL/Point_set_object_recognition/internal/Nearest_nodes.h>
#include <CGAL/Shape_analysis/internal/Nearest_sample_tree.h>
#include <CGAL/Shape_analysis/internal/Point_tree.h>
#include <CGAL/Surface_mesh_symmetrization/internal/Distance_grid.h>
#include <CGAL/Surface_mesh_symmetrization/internal/Surface_index.h>
#include <Shape_analysis_support/Json.h>
#include <Shape_analysis_support/Urban_scan.h>
#include "bench_util.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <fstream>
#include <iostream>
#include <limits>
#include <string>
#include <random>
#include <unordered_map>
#include <vector>

namespace {

typedef CGAL::Exact_predicates_inexact_constructions_kernel Kernel;
typedef Kernel::Point_3 Point;
typedef CGAL::Surface_mesh<Point> Mesh;
typedef CGAL::Search_traits_3<Kernel> Traits;
typedef CGAL::Sliding_midpoint<Traits> Splitter;
typedef CGAL::Orthogonal_k_neighbor_search<Traits, CGAL::Euclidean_distance<Traits>, Splitter> Knn;
typedef Knn::Tree Kd_tree;
typedef CGAL::AABB_face_graph_triangle_primitive<Mesh> Primitive;
typedef CGAL::AABB_traits<Kernel, Primitive> Aabb_traits;
typedef CGAL::AABB_tree<Aabb_traits> Aabb_tree;

namespace SAI = CGAL::Shape_analysis::internal;
namespace SYI = CGAL::Surface_mesh_symmetrization::internal;
namespace SAS = CGAL::Shape_analysis_support;
using SAS::Json;
using bench_util::seconds_since;
typedef std::chrono::steady_clock Clock;

// Equal up to rounding (the two libraries sum the squares in their own order).
bool same(double a, double b) { return std::abs(a - b) <= 1e-9 * (std::max)(1.0, std::max(std::abs(a), std::abs(b))); }

Json comparison(double own_build, double own_query, double cgal_build, double cgal_query, std::size_t queries,
                std::size_t unequal)
{
  Json j;
  const double own = own_build + own_query, cgal = cgal_build + cgal_query;
  j["queries"] = queries;
  j["own_seconds"] = own;
  j["own_build_seconds"] = own_build;
  j["own_query_seconds"] = own_query;
  j["cgal_seconds"] = cgal;
  j["cgal_build_seconds"] = cgal_build;
  j["cgal_query_seconds"] = cgal_query;
  j["ratio_own_over_cgal"] = cgal > 0 ? own / cgal : 0.0;
  j["unequal_answers"] = unequal;
  j["answers_equal"] = unequal == 0;
  return j;
}

// CGAL's kd-tree over `points`: the k nearest distances of every query (asked `rounds` times)
// into `d` (k per query); the smallest build and query times so far kept in `build`, `query`.
void cgal_knn(const std::vector<SAI::Vector_3d>& points, const std::vector<SAI::Vector_3d>& queries, std::size_t k,
              int rounds, double& build, double& query, std::vector<double>& d)
{
  auto t = Clock::now();
  std::vector<Point> cp;
  cp.reserve(points.size());
  for(const auto& p : points)
    cp.emplace_back(p.x, p.y, p.z);
  Kd_tree kd(cp.begin(), cp.end());
  kd.build();
  build = (std::min)(build, seconds_since(t));
  t = Clock::now();
  for(int round = 0; round < rounds; ++round)
    for(std::size_t q = 0; q < queries.size(); ++q) {
      const Knn search(kd, Point(queries[q].x, queries[q].y, queries[q].z), unsigned(k));
      std::size_t r = 0;
      for(auto it = search.begin(); it != search.end() && r < k; ++it, ++r)
        d[q * k + r] = it->second;
    }
  query = (std::min)(query, seconds_since(t));
}

// k nearest of every query among `points`: Point_tree against CGAL's kd-tree. The distances are
// compared rank by rank.
Json knn_comparison(const std::vector<SAI::Vector_3d>& points, const std::vector<SAI::Vector_3d>& queries, std::size_t k,
                    int repeats)
{
  std::vector<std::uint32_t> ids(points.size());
  for(std::size_t i = 0; i < ids.size(); ++i)
    ids[i] = std::uint32_t(i);
  std::vector<double> own_d(queries.size() * k, -1.0), cgal_d(queries.size() * k, -1.0);

  double own_build = 1e300, own_query = 1e300, cgal_build = 1e300, cgal_query = 1e300;
  for(int repeat = 0; repeat < repeats; ++repeat) {
    auto t = Clock::now();
    const SAI::Point_tree tree(points, ids);
    own_build = (std::min)(own_build, seconds_since(t));
    t = Clock::now();
    std::vector<std::pair<double, std::uint32_t>> found;
    for(std::size_t q = 0; q < queries.size(); ++q) {
      if(k == 1) { // nearest(), as Component_links.h and Similarity_alignment.h ask
        std::uint32_t id = 0;
        if(tree.nearest(queries[q], std::numeric_limits<double>::infinity(), id, own_d[q]))
          continue;
      }
      tree.k_nearest(queries[q], k, found);
      for(std::size_t r = 0; r < found.size(); ++r)
        own_d[q * k + r] = found[r].first;
    }
    own_query = (std::min)(own_query, seconds_since(t));

    cgal_knn(points, queries, k, 1, cgal_build, cgal_query, cgal_d);
  }

  std::size_t unequal = 0;
  for(std::size_t q = 0; q < queries.size(); ++q)
    for(std::size_t r = 0; r < k; ++r)
      if(!same(own_d[q * k + r], cgal_d[q * k + r])) {
        ++unequal;
        break;
      }
  Json j = comparison(own_build, own_query, cgal_build, cgal_query, queries.size(), unequal);
  j["points"] = points.size();
  j["k"] = k;
  return j;
}

// The nearest of a few thousand samples, asked again and again (the ICP of
// Similarity_alignment.h, Closest_sample): Nearest_sample_tree against CGAL's kd-tree with k = 1,
// both over the same points, every query asked `rounds` times (the ICP's iterations).
Json nearest_sample_comparison(const std::vector<SAI::Vector_3d>& points, const std::vector<SAI::Vector_3d>& queries,
                               int rounds, int repeats)
{
  std::vector<double> own_d(queries.size()), cgal_d(queries.size());
  double own_build = 1e300, own_query = 1e300, cgal_build = 1e300, cgal_query = 1e300;
  for(int repeat = 0; repeat < repeats; ++repeat) {
    auto t = Clock::now();
    const SAI::Nearest_sample_tree tree(points);
    own_build = (std::min)(own_build, seconds_since(t));
    t = Clock::now();
    for(int round = 0; round < rounds; ++round)
      for(std::size_t q = 0; q < queries.size(); ++q)
        own_d[q] = (points[tree.nearest(queries[q])] - queries[q]).squared_length();
    own_query = (std::min)(own_query, seconds_since(t));

    cgal_knn(points, queries, 1, rounds, cgal_build, cgal_query, cgal_d);
  }
  std::size_t unequal = 0;
  for(std::size_t q = 0; q < queries.size(); ++q)
    unequal += same(own_d[q], cgal_d[q]) ? 0 : 1;
  Json j = comparison(own_build, own_query, cgal_build, cgal_query, queries.size() * std::size_t(rounds), unequal);
  j["points"] = points.size();
  return j;
}

// Voxel centroids of a generated street in cells of side `cell` (the nodes of the segmentation
// graph).
std::vector<SAI::Vector_3d> street_nodes(std::size_t target_points, double cell, std::size_t& scan_points,
                                         std::vector<std::uint64_t>& cell_key, std::vector<std::uint64_t>& point_key)
{
  SAS::Urban_scene_options o;
  o.target_points = target_points;
  o.street_length = (std::max)(100.0, 400.0 * double(target_points) / 1e6);
  const SAS::Urban_scene scene = SAS::make_urban_scene(o);
  const SAS::Urban_scan scan = SAS::scan_urban_scene(scene, o);
  scan_points = scan.points.size();
  std::unordered_map<std::uint64_t, std::size_t> node_of;
  std::vector<SAI::Vector_3d> sum;
  std::vector<double> count;
  for(const auto& p : scan.points) {
    const auto key = [&](double v, double off) { return std::uint64_t(std::int64_t(std::floor(v / cell)) + std::int64_t(off)) & 0x1FFFFF; };
    const std::uint64_t k = key(p.x, 1 << 20) | (key(p.y, 1 << 20) << 21) | (key(p.z, 1 << 20) << 42);
    point_key.push_back(k);
    auto it = node_of.emplace(k, sum.size());
    if(it.second) {
      cell_key.push_back(k);
      sum.emplace_back(0.0);
      count.push_back(0);
    }
    sum[it.first->second] = sum[it.first->second] + SAI::Vector_3d(p.x, p.y, p.z);
    count[it.first->second] += 1;
  }
  for(std::size_t v = 0; v < sum.size(); ++v)
    sum[v] = sum[v] / count[v];
  return sum;
}

// The k nearest other nodes of every node of the street: Nearest_nodes.h's Cell_stack_neighbors
// (the segmentation graph's default, graph_cell_size 0.2 m: the nodes of the cells around, up to
// 7 x 7 x 7 cells) against CGAL's kd-tree (k + 1 nearest, the node itself dropped). The cell
// search is bounded by design: a node whose neighbours lie farther than three cells gets other
// (or fewer) neighbours; "unequal_answers" counts the nodes whose k distances differ.
Json cell_stack_comparison(const std::vector<SAI::Vector_3d>& c, const std::vector<std::uint64_t>& cell_key,
                           std::size_t k, int repeats)
{
  namespace PI = CGAL::Point_set_object_recognition::internal;
  const std::uint32_t none = (std::numeric_limits<std::uint32_t>::max)();
  const std::size_t n = c.size();
  std::vector<std::uint32_t> all(n);
  for(std::size_t v = 0; v < n; ++v)
    all[v] = std::uint32_t(v);
  std::vector<std::uint32_t> knn;
  std::vector<double> cgal_d(n * k, -1.0);
  double own_build = 1e300, own_query = 1e300, cgal_build = 1e300, cgal_query = 1e300;
  for(int repeat = 0; repeat < repeats; ++repeat) {
    auto t = Clock::now();
    const PI::Cell_stack_neighbors cells(c, cell_key, all);
    own_build = (std::min)(own_build, seconds_since(t));
    knn.assign(n * k, none);
    t = Clock::now();
    cells.find(k, 1, knn);
    own_query = (std::min)(own_query, seconds_since(t));

    t = Clock::now();
    std::vector<Point> cp;
    cp.reserve(n);
    for(const auto& p : c)
      cp.emplace_back(p.x, p.y, p.z);
    Kd_tree kd(cp.begin(), cp.end());
    kd.build();
    cgal_build = (std::min)(cgal_build, seconds_since(t));
    t = Clock::now();
    for(std::size_t q = 0; q < n; ++q) {
      const Knn search(kd, cp[q], unsigned(k + 1));
      std::size_t r = 0;
      bool self = false;
      for(auto it = search.begin(); it != search.end() && r < k; ++it) {
        if(!self && it->second == 0.0) { // the node itself (centroids are distinct)
          self = true;
          continue;
        }
        cgal_d[q * k + r++] = it->second;
      }
    }
    cgal_query = (std::min)(cgal_query, seconds_since(t));
  }
  std::size_t unequal = 0, short_rows = 0;
  double ratio_sum = 0, ratio_max = 0;
  std::vector<double> d;
  for(std::size_t v = 0; v < n; ++v) {
    d.clear();
    for(std::size_t r = 0; r < k; ++r)
      if(knn[v * k + r] != none)
        d.push_back((c[knn[v * k + r]] - c[v]).squared_length());
    short_rows += d.size() < k ? 1 : 0;
    std::sort(d.begin(), d.end());
    if(d.size() == k && cgal_d[v * k + k - 1] > 0) {
      const double ratio = std::sqrt(d[k - 1] / cgal_d[v * k + k - 1]);
      ratio_sum += ratio;
      ratio_max = (std::max)(ratio_max, ratio);
    }
    d.resize(k, -1.0);
    for(std::size_t r = 0; r < k; ++r)
      if(!same(d[r], cgal_d[v * k + r])) {
        ++unequal;
        break;
      }
  }
  Json j = comparison(own_build, own_query, cgal_build, cgal_query, n, unequal);
  j["points"] = n;
  j["k"] = k;
  j["own_nodes_with_fewer_than_k"] = short_rows;
  // How far the k-th neighbour of the cells is, relative to the exact k-th (nodes with k found).
  j["own_kth_distance_over_exact_mean"] = n > short_rows ? ratio_sum / double(n - short_rows) : 0.0;
  j["own_kth_distance_over_exact_max"] = ratio_max;
  return j;
}

// The cells of the street's points, as the segmentation graph numbers its nodes
// (Segmentation_graph.h make_nodes(); Wall_detection.h, Column_index.h alike): Key_map against
// std::unordered_map (reserved alike), every point's key inserted in scan order, then every key
// looked up together with the key of the cell above (mostly absent).
Json key_map_comparison(const std::vector<std::uint64_t>& keys, int repeats)
{
  namespace PI = CGAL::Point_set_object_recognition::internal;
  const std::uint32_t none = PI::Key_map::none;
  std::vector<std::uint32_t> own(2 * keys.size()), std_answers(2 * keys.size());
  double own_build = 1e300, own_query = 1e300, std_build = 1e300, std_query = 1e300;
  for(int repeat = 0; repeat < repeats; ++repeat) {
    auto t = Clock::now();
    PI::Key_map map(keys.size() / 4 + 16);
    std::uint32_t n = 0;
    for(std::uint64_t k : keys)
      n += map.emplace(k, n).second ? 1 : 0;
    own_build = (std::min)(own_build, seconds_since(t));
    t = Clock::now();
    for(std::size_t i = 0; i < keys.size(); ++i) {
      own[2 * i] = map.find(keys[i]);
      own[2 * i + 1] = map.find(keys[i] + (std::uint64_t(1) << 42));
    }
    own_query = (std::min)(own_query, seconds_since(t));

    t = Clock::now();
    std::unordered_map<std::uint64_t, std::uint32_t> umap;
    umap.reserve(keys.size() / 4 + 16);
    std::uint32_t m = 0;
    for(std::uint64_t k : keys)
      m += umap.emplace(k, m).second ? 1 : 0;
    std_build = (std::min)(std_build, seconds_since(t));
    t = Clock::now();
    for(std::size_t i = 0; i < keys.size(); ++i) {
      auto a = umap.find(keys[i]);
      std_answers[2 * i] = a == umap.end() ? none : a->second;
      auto b = umap.find(keys[i] + (std::uint64_t(1) << 42));
      std_answers[2 * i + 1] = b == umap.end() ? none : b->second;
    }
    std_query = (std::min)(std_query, seconds_since(t));
  }
  std::size_t unequal = 0, absent = 0;
  for(std::size_t i = 0; i < own.size(); ++i) {
    unequal += own[i] != std_answers[i] ? 1 : 0;
    absent += own[i] == none ? 1 : 0;
  }
  Json j = comparison(own_build, own_query, std_build, std_query, own.size(), unequal);
  j["keys_inserted"] = keys.size();
  j["absent_lookups"] = absent;
  return j;
}

SYI::Surface to_surface(const Mesh& m)
{
  SYI::Surface s;
  for(auto v : m.vertices())
    s.points.emplace_back(m.point(v).x(), m.point(v).y(), m.point(v).z());
  for(auto f : m.faces()) {
    std::array<std::uint32_t, 3> t;
    int i = 0;
    for(auto v : CGAL::vertices_around_face(m.halfedge(f), m))
      t[std::size_t(i++)] = std::uint32_t(v);
    s.triangles.push_back(t);
  }
  return s;
}

std::vector<SAI::Vector_3d> face_centroids(const SYI::Surface& s)
{
  std::vector<SAI::Vector_3d> c;
  for(std::size_t f = 0; f < s.triangles.size(); ++f) {
    const auto k = s.corners(f);
    c.push_back((k[0] + k[1] + k[2]) / 3.0);
  }
  return c;
}

// The vertices mirrored through the plane x = centre of their bounding box.
std::vector<SAI::Vector_3d> mirrored(const std::vector<SAI::Vector_3d>& points)
{
  double lo = points[0].x, hi = lo;
  for(const auto& p : points) {
    lo = (std::min)(lo, p.x);
    hi = (std::max)(hi, p.x);
  }
  std::vector<SAI::Vector_3d> m;
  for(const auto& p : points)
    m.emplace_back(lo + hi - p.x, p.y, p.z);
  return m;
}

double diagonal(const std::vector<SAI::Vector_3d>& points)
{
  SAI::Vector_3d lo = points[0], hi = points[0];
  for(const auto& p : points)
    for(int a = 0; a < 3; ++a) {
      lo[a] = (std::min)(lo[a], p[a]);
      hi[a] = (std::max)(hi[a], p[a]);
    }
  return (hi - lo).length();
}

// Closest points at `queries`: Surface_index (own Bvh) against CGAL's AABB tree; `own_d` and
// `cgal_d` receive the squared distances.
void own_queries(const SYI::Surface_index& index, const std::vector<SAI::Vector_3d>& queries, std::vector<double>& d)
{
  d.resize(queries.size());
  for(std::size_t q = 0; q < queries.size(); ++q)
    d[q] = index.closest(queries[q]).squared_distance;
}

void cgal_queries(const Aabb_tree& tree, const std::vector<SAI::Vector_3d>& queries, std::vector<double>& d)
{
  d.resize(queries.size());
  for(std::size_t q = 0; q < queries.size(); ++q) {
    const Point p(queries[q].x, queries[q].y, queries[q].z);
    d[q] = CGAL::squared_distance(p, tree.closest_point(p));
  }
}

std::size_t unequal(const std::vector<double>& a, const std::vector<double>& b)
{
  std::size_t n = 0;
  for(std::size_t i = 0; i < a.size(); ++i)
    n += same(a[i], b[i]) ? 0 : 1;
  return n;
}

// The positions moved by a smooth field of amplitude `amplitude`, different at each `step`.
std::vector<SAI::Vector_3d> moved(const std::vector<SAI::Vector_3d>& p, double amplitude, double scale, int step)
{
  std::vector<SAI::Vector_3d> m(p.size());
  for(std::size_t i = 0; i < p.size(); ++i) {
    const double a = 0.7 * step;
    m[i] = p[i] + SAI::Vector_3d(std::sin(p[i].y / scale * 6 + a), std::sin(p[i].z / scale * 5 + 2 * a),
                                 std::sin(p[i].x / scale * 7 + 3 * a)) * amplitude;
  }
  return m;
}

Json surface_comparisons(const std::string& file, int moves, int repeats)
{
  Mesh mesh;
  if(!CGAL::IO::read_polygon_mesh(file, mesh) || mesh.is_empty()) {
    Json j;
    j["skipped"] = "cannot read " + file;
    return j;
  }
  const SYI::Surface s = to_surface(mesh);
  const std::vector<SAI::Vector_3d> queries = mirrored(s.points);
  Json out;
  std::vector<double> own_d, cgal_d;

  // Static surface: build and one query per mirrored vertex.
  double own_build = 1e300, own_query = 1e300, cgal_build = 1e300, cgal_query = 1e300;
  for(int repeat = 0; repeat < repeats; ++repeat) {
    auto t = Clock::now();
    SYI::Surface_index index(s);
    own_build = (std::min)(own_build, seconds_since(t));
    t = Clock::now();
    own_queries(index, queries, own_d);
    own_query = (std::min)(own_query, seconds_since(t));
    t = Clock::now();
    Aabb_tree tree(faces(mesh).first, faces(mesh).second, mesh);
    tree.build();
    tree.accelerate_distance_queries();
    cgal_build = (std::min)(cgal_build, seconds_since(t));
    t = Clock::now();
    cgal_queries(tree, queries, cgal_d);
    cgal_query = (std::min)(cgal_query, seconds_since(t));
  }
  out["surface_index_closest"] =
    comparison(own_build, own_query, cgal_build, cgal_query, queries.size(), unequal(own_d, cgal_d));
  out["surface_index_closest"]["mesh"] = file.substr(file.find_last_of('/') + 1);
  out["surface_index_closest"]["faces"] = s.triangles.size();
  out["surface_index_closest"]["own_index"] = "Surface_mesh_symmetrization::internal::Surface_index::closest (Bvh)";
  out["surface_index_closest"]["cgal_index"] = "AABB_tree<AABB_face_graph_triangle_primitive> + accelerate_distance_queries";

  // Moving surface: the symmetrization's loop (update, then query every mirrored vertex).
  SYI::Surface_index index(s);
  Aabb_tree tree(faces(mesh).first, faces(mesh).second, mesh);
  tree.build();
  tree.accelerate_distance_queries();
  auto t = Clock::now();
  const double amplitude = 0.005 * diagonal(s.points), scale = diagonal(s.points);
  double own_update = 0, own_q = 0, cgal_rebuild = 0, cgal_q = 0;
  std::size_t bad = 0, total = 0;
  // CGAL's side of a move: the mesh takes the new positions, the AABB tree is rebuilt (seconds).
  const auto move_and_rebuild = [&](const std::vector<SAI::Vector_3d>& x) {
    for(auto v : mesh.vertices())
      mesh.point(v) = Point(x[std::size_t(v)].x, x[std::size_t(v)].y, x[std::size_t(v)].z);
    const auto start = Clock::now();
    tree.rebuild(faces(mesh).first, faces(mesh).second, mesh);
    tree.accelerate_distance_queries();
    return seconds_since(start);
  };
  for(int step = 1; step <= moves; ++step) {
    const std::vector<SAI::Vector_3d> x = moved(s.points, amplitude, scale, step);
    const std::vector<SAI::Vector_3d> mq = mirrored(x);
    t = Clock::now();
    index.update(x);
    own_update += seconds_since(t);
    t = Clock::now();
    own_queries(index, mq, own_d);
    own_q += seconds_since(t);
    cgal_rebuild += move_and_rebuild(x);
    t = Clock::now();
    cgal_queries(tree, mq, cgal_d);
    cgal_q += seconds_since(t);
    bad += unequal(own_d, cgal_d);
    total += mq.size();
  }
  out["surface_index_moving"] = comparison(own_update, own_q, cgal_rebuild, cgal_q, total, bad);
  out["surface_index_moving"]["moves"] = moves;
  out["surface_index_moving"]["own_build_seconds_is"] = "Surface_index::update (Bvh refit)";
  out["surface_index_moving"]["cgal_build_seconds_is"] = "AABB_tree::rebuild + accelerate_distance_queries";

  // The same with the symmetrization's hints: the queries in the index's vertex order, each
  // starting from the previous move's answer (own: its face; CGAL: closest_point_and_primitive
  // with the previous point and primitive as hint).
  own_update = own_q = cgal_rebuild = cgal_q = 0;
  bad = total = 0;
  std::vector<std::uint32_t> own_hint(s.points.size(), SYI::Surface_index::no_face);
  std::vector<Aabb_tree::Point_and_primitive_id> cgal_hint;
  for(int step = moves + 1; step <= 2 * moves; ++step) {
    const std::vector<SAI::Vector_3d> x = moved(s.points, amplitude, scale, step);
    const std::vector<SAI::Vector_3d> mq = mirrored(x);
    t = Clock::now();
    index.update(x);
    own_update += seconds_since(t);
    const std::vector<std::uint32_t>& order = index.vertex_order();
    own_d.assign(mq.size(), 0.0);
    cgal_d.assign(mq.size(), 0.0);
    t = Clock::now();
    for(std::uint32_t i : order) {
      const SYI::Surface_point r = index.closest(mq[i], own_hint[i]);
      own_d[i] = r.squared_distance;
      own_hint[i] = r.face;
    }
    own_q += seconds_since(t);
    cgal_rebuild += move_and_rebuild(x);
    t = Clock::now();
    const bool hinted = !cgal_hint.empty();
    cgal_hint.resize(mq.size());
    for(std::uint32_t i : order) {
      const Point p(mq[i].x, mq[i].y, mq[i].z);
      // CGAL's hint must lie on the surface: the closest point to p on the previous answer's face
      // at the current positions (what Surface_index does with its hint).
      Aabb_tree::Point_and_primitive_id r;
      if(hinted) {
        const Mesh::Face_index f = cgal_hint[i].second;
        const Mesh::Halfedge_index h = mesh.halfedge(f);
        const Kernel::Triangle_3 tr(mesh.point(mesh.source(h)), mesh.point(mesh.target(h)),
                                    mesh.point(mesh.target(mesh.next(h))));
        r = tree.closest_point_and_primitive(p, Aabb_tree::Point_and_primitive_id(
                                                  Kernel().construct_projected_point_3_object()(tr, p), f));
      } else
        r = tree.closest_point_and_primitive(p);
      cgal_d[i] = CGAL::squared_distance(p, r.first);
      cgal_hint[i] = r;
    }
    cgal_q += seconds_since(t);
    bad += unequal(own_d, cgal_d);
    total += mq.size();
  }
  out["surface_index_moving_hinted"] = comparison(own_update, own_q, cgal_rebuild, cgal_q, total, bad);
  out["surface_index_moving_hinted"]["moves"] = moves;
  return out;
}

// The far-point test of the plane search (Plane_detection.h, approximate_closest_compatible()):
// armadillo's face centroids (a twentieth of them per plane) mirrored through 20 random planes
// through the centre; a point farther than the reach (5% of the bounding-box diagonal, the
// refinement's smallest) from the surface is dropped. Own: Distance_grid::lower_bound() drops what it can, CGAL's AABB tree
// answers the rest; CGAL alone: the AABB tree's closest point for every point. The two must keep
// the same points ("unequal_answers"); the tree is built outside both timings.
Json distance_grid_comparison(const Mesh& m, const SYI::Surface& s, int repeats)
{
  const std::vector<SAI::Vector_3d> centroids = face_centroids(s);
  SAI::Vector_3d centre(0.0);
  for(const auto& p : s.points)
    centre = centre + p;
  centre = centre / double(s.points.size());
  const double reach = 0.05 * diagonal(s.points);
  std::vector<SAI::Vector_3d> queries;
  std::mt19937 rng(11);
  std::normal_distribution<double> gauss;
  for(int plane = 0; plane < 20; ++plane) {
    SAI::Vector_3d n(gauss(rng), gauss(rng), gauss(rng));
    n = n / n.length();
    for(std::size_t f = std::size_t(plane); f < centroids.size(); f += 20) // a twentieth each
      queries.push_back(centroids[f] - n * (2 * SAI::dot(centroids[f] - centre, n)));
  }
  Aabb_tree tree(faces(m).first, faces(m).second, m);
  tree.accelerate_distance_queries();
  std::vector<char> own_near(queries.size()), cgal_near(queries.size());
  double own_build = 1e300, own_query = 1e300, cgal_query = 1e300;
  std::size_t dropped = 0;
  for(int repeat = 0; repeat < repeats; ++repeat) {
    auto t = Clock::now();
    const SYI::Distance_grid grid(s);
    own_build = (std::min)(own_build, seconds_since(t));
    t = Clock::now();
    dropped = 0;
    for(std::size_t q = 0; q < queries.size(); ++q) {
      if(grid.lower_bound(queries[q]) > reach) {
        own_near[q] = 0, ++dropped;
        continue;
      }
      const Point p(queries[q].x, queries[q].y, queries[q].z);
      own_near[q] = CGAL::squared_distance(p, tree.closest_point(p)) < reach * reach;
    }
    own_query = (std::min)(own_query, seconds_since(t));
    t = Clock::now();
    for(std::size_t q = 0; q < queries.size(); ++q) {
      const Point p(queries[q].x, queries[q].y, queries[q].z);
      cgal_near[q] = CGAL::squared_distance(p, tree.closest_point(p)) < reach * reach;
    }
    cgal_query = (std::min)(cgal_query, seconds_since(t));
  }
  std::size_t unequal = 0;
  for(std::size_t q = 0; q < queries.size(); ++q)
    unequal += own_near[q] != cgal_near[q] ? 1 : 0;
  Json j = comparison(own_build, own_query, 0.0, cgal_query, queries.size(), unequal);
  j["dropped_by_the_grid"] = dropped;
  j["reach_over_diagonal"] = 0.05;
  return j;
}

} // namespace

int main(int argc, char** argv)
{
  std::string data = SHAPE_ANALYSIS_DATA_DIR, output;
  std::size_t street_points = 400000;
  int moves = 5, repeats = 3;
  for(int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if(a == "--data" && i + 1 < argc)
      data = argv[++i];
    else if(a == "--street-points" && i + 1 < argc)
      street_points = std::stoull(argv[++i]);
    else if(a == "--moves" && i + 1 < argc)
      moves = std::stoi(argv[++i]);
    else if(a == "--repeats" && i + 1 < argc)
      repeats = (std::max)(1, std::stoi(argv[++i]));
    else if(a == "--output" && i + 1 < argc)
      output = argv[++i];
    else {
      std::cerr << "usage: bench_spatial_indexes [--data DIR] [--street-points N] [--moves N] [--repeats N] [--output FILE]\n";
      return 1;
    }
  }

  Json report;
  report["threads"] = 1;
  report["repeats"] = repeats; // the static timings are the smallest of these runs

  std::cerr << "street of " << street_points << " points...\n";
  std::size_t scan_points = 0;
  std::vector<std::uint64_t> cell_key, point_key;
  const std::vector<SAI::Vector_3d> nodes = street_nodes(street_points, 0.2, scan_points, cell_key, point_key);
  report["point_tree_knn_street"] = knn_comparison(nodes, nodes, 9, repeats);
  report["point_tree_knn_street"]["scan_points"] = scan_points;
  report["point_tree_knn_street"]["own_index"] = "Shape_analysis::internal::Point_tree::k_nearest";
  report["point_tree_knn_street"]["cgal_index"] = "Orthogonal_k_neighbor_search, Kd_tree<Search_traits_3>, Sliding_midpoint";
  report["cell_stack_knn_street"] = cell_stack_comparison(nodes, cell_key, 8, repeats);
  report["cell_stack_knn_street"]["own_index"] = "Point_set_object_recognition::internal::Cell_stack_neighbors (Column_index)";
  report["cell_stack_knn_street"]["cgal_index"] = "Orthogonal_k_neighbor_search (k + 1, self dropped)";
  report["key_map_street"] = key_map_comparison(point_key, repeats);
  report["key_map_street"]["own_index"] = "Point_set_object_recognition::internal::Key_map";
  report["key_map_street"]["cgal_index"] = "std::unordered_map (CGAL has no hash map of cells; the ratio is own / std)";

  std::cerr << "meshes...\n";
  {
    Mesh m;
    const std::string f = data + "/armadillo.off";
    if(CGAL::IO::read_polygon_mesh(f, m) && !m.is_empty()) {
      const std::vector<SAI::Vector_3d> c = face_centroids(to_surface(m));
      report["point_tree_knn_mesh"] = knn_comparison(c, c, 8, repeats);
      report["point_tree_knn_mesh"]["mesh"] = "armadillo.off face centroids";
    } else
      report["point_tree_knn_mesh"]["skipped"] = "cannot read " + f;
  }
  {
    Mesh m;
    const std::string f = data + "/camel.off";
    if(CGAL::IO::read_polygon_mesh(f, m) && !m.is_empty()) {
      const SYI::Surface s = to_surface(m);
      report["point_tree_nearest_mesh"] = knn_comparison(face_centroids(s), s.points, 1, repeats);
      report["point_tree_nearest_mesh"]["mesh"] = "camel.off: face centroids, queried at the vertices";
      std::vector<SAI::Vector_3d> samples;
      for(std::size_t v = 0; v < s.points.size(); v += 5)
        samples.push_back(s.points[v]);
      report["nearest_sample_tree_icp"] = nearest_sample_comparison(samples, s.points, 10, repeats);
      report["nearest_sample_tree_icp"]["mesh"] = "camel.off: every fifth vertex, queried at every vertex 10 times";
      report["nearest_sample_tree_icp"]["own_index"] = "Shape_analysis::internal::Nearest_sample_tree::nearest";
      report["nearest_sample_tree_icp"]["cgal_index"] = "Orthogonal_k_neighbor_search, k = 1";
    } else
      report["point_tree_nearest_mesh"]["skipped"] = "cannot read " + f;
  }

  {
    Mesh m;
    const std::string f = data + "/armadillo.off";
    if(CGAL::IO::read_polygon_mesh(f, m) && !m.is_empty()) {
      report["distance_grid_far_points"] = distance_grid_comparison(m, to_surface(m), repeats);
      report["distance_grid_far_points"]["own_index"] = "Surface_mesh_symmetrization::internal::Distance_grid, then the AABB tree";
      report["distance_grid_far_points"]["cgal_index"] = "AABB_tree closest_point() alone";
    } else
      report["distance_grid_far_points"]["skipped"] = "cannot read " + f;
  }

  std::cerr << "closest points...\n";
  const Json surface = surface_comparisons(data + "/armadillo.off", moves, repeats);
  for(auto it = surface.begin(); it != surface.end(); ++it)
    report[it.key()] = it.value();

  const std::string text = SAS::to_text(report);
  std::cout << text << "\n";
  if(!output.empty())
    std::ofstream(output) << text << "\n";
  return 0;
}
