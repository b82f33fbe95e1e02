// Copyright (c) 2026 CGAL Global Shape Analysis contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_SURFACE_MESH_SYMMETRIZATION_INTERNAL_SURFACE_INDEX_H
#define CGAL_SURFACE_MESH_SYMMETRIZATION_INTERNAL_SURFACE_INDEX_H

// Closest points on a triangle and on a surface: a bounding-volume hierarchy of the triangles,
// refitted when the surface moves, with the face and barycentric coordinates of the answer, the
// closest point whose face normal agrees with a given normal, and a faster local search.

#include <CGAL/Shape_analysis/internal/Bvh.h>
#include <CGAL/Shape_analysis/internal/Point_tree.h>
#include <CGAL/Surface_mesh_symmetrization/internal/Distance_grid.h>
#include <CGAL/Surface_mesh_symmetrization/internal/Symmetry_geometry.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <cstdint>
#include <limits>
#include <memory>
#include <mutex>
#include <utility>
#include <vector>

namespace CGAL {
namespace Surface_mesh_symmetrization {
namespace internal {

// The closest point to p on triangle (a, b, c), with its barycentric coordinates (Voronoi
// regions of the vertices, edges and face).
inline Vector_3d closest_point_on_triangle(const Vector_3d& p, const Vector_3d& a, const Vector_3d& b,
                                           const Vector_3d& c, std::array<double, 3>& bary)
{
  const Vector_3d ab = b - a, ac = c - a, ap = p - a;
  const double d1 = SAI::dot(ab, ap), d2 = SAI::dot(ac, ap);
  if(d1 <= 0 && d2 <= 0) {
    bary = {{1, 0, 0}};
    return a;
  }
  const Vector_3d bp = p - b;
  const double d3 = SAI::dot(ab, bp), d4 = SAI::dot(ac, bp);
  if(d3 >= 0 && d4 <= d3) {
    bary = {{0, 1, 0}};
    return b;
  }
  const double vc = d1 * d4 - d3 * d2;
  if(vc <= 0 && d1 >= 0 && d3 <= 0) {
    const double v = (d1 - d3) > 0 ? d1 / (d1 - d3) : 0.0;
    bary = {{1 - v, v, 0}};
    return a + ab * v;
  }
  const Vector_3d cp = p - c;
  const double d5 = SAI::dot(ab, cp), d6 = SAI::dot(ac, cp);
  if(d6 >= 0 && d5 <= d6) {
    bary = {{0, 0, 1}};
    return c;
  }
  const double vb = d5 * d2 - d1 * d6;
  if(vb <= 0 && d2 >= 0 && d6 <= 0) {
    const double w = (d2 - d6) > 0 ? d2 / (d2 - d6) : 0.0;
    bary = {{1 - w, 0, w}};
    return a + ac * w;
  }
  const double va = d3 * d6 - d5 * d4;
  if(va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0) {
    const double denom = (d4 - d3) + (d5 - d6);
    const double w = denom > 0 ? (d4 - d3) / denom : 0.0;
    bary = {{0, 1 - w, w}};
    return b + (c - b) * w;
  }
  const double sum = va + vb + vc;
  if(!(sum > 0) || !std::isfinite(sum)) { // degenerate triangle: its closest corner
    const double da = (p - a).squared_length(), db = (p - b).squared_length(),
                 dc = (p - c).squared_length();
    if(da <= db && da <= dc) {
      bary = {{1, 0, 0}};
      return a;
    }
    if(db <= dc) {
      bary = {{0, 1, 0}};
      return b;
    }
    bary = {{0, 0, 1}};
    return c;
  }
  const double v = vb / sum, w = vc / sum;
  bary = {{1 - v - w, v, w}};
  return a + ab * v + ac * w;
}

// Offers `c` to `heap`, a max-heap that keeps the (at most) k smallest values offered.
template <typename T>
void keep_k_smallest(std::vector<T>& heap, std::size_t k, const T& c)
{
  if(heap.size() < k) {
    heap.push_back(c);
    std::push_heap(heap.begin(), heap.end());
  } else if(k > 0 && c < heap.front()) {
    std::pop_heap(heap.begin(), heap.end());
    heap.back() = c;
    std::push_heap(heap.begin(), heap.end());
  }
}

// A point of the surface: its face, barycentric coordinates and position.
struct Surface_point
{
  std::uint32_t face = 0;
  std::array<double, 3> barycentric{{1, 0, 0}};
  Vector_3d point;
  double squared_distance = std::numeric_limits<double>::infinity();
  bool found = false;
};

// Per face, the face across each of its edges (edge e from corner e to corner e + 1), among the
// faces `keep(f)` accepts, for the edges of exactly two of them; none (the largest uint32)
// otherwise.
template <typename Keep>
std::vector<std::array<std::uint32_t, 3>> face_adjacency(const std::vector<std::array<std::uint32_t, 3>>& triangles,
                                                        const Keep& keep)
{
  const std::uint32_t none = (std::numeric_limits<std::uint32_t>::max)();
  std::vector<std::array<std::uint32_t, 3>> adjacent(triangles.size(), {{none, none, none}});
  std::vector<std::array<std::uint32_t, 4>> edges; // (smaller vertex, larger, face, edge)
  edges.reserve(3 * triangles.size());
  for(std::size_t f = 0; f < triangles.size(); ++f) {
    if(!keep(f))
      continue;
    for(std::uint32_t e = 0; e < 3; ++e) {
      const std::uint32_t a = triangles[f][e], b = triangles[f][(e + 1) % 3];
      edges.push_back({{(std::min)(a, b), (std::max)(a, b), std::uint32_t(f), e}});
    }
  }
  std::sort(edges.begin(), edges.end());
  for(std::size_t i = 0; i < edges.size();) {
    std::size_t j = i + 1;
    while(j < edges.size() && edges[j][0] == edges[i][0] && edges[j][1] == edges[i][1])
      ++j;
    if(j == i + 2) {
      adjacent[edges[i][2]][edges[i][3]] = edges[i + 1][2];
      adjacent[edges[i + 1][2]][edges[i + 1][3]] = edges[i][2];
    }
    i = j;
  }
  return adjacent;
}

// Closest-point queries on a surface (the positions are copied; `update()` moves them). Faces of
// zero area are left out of the queries. Queries are thread-safe. The faces are held in a
// bounding-volume hierarchy that is refitted, not rebuilt, when the surface moves: CGAL's AABB
// tree cannot refit, and rebuilding it for every search of the symmetrization took as long as
// the search (bench/spatial_indexes.cpp: surface_index_moving 0.7, surface_index_moving_hinted
// 0.5 of the time of CGAL's AABB tree rebuilt at every move).
class Surface_index
{
public:
  explicit Surface_index(const Surface& s) : m_surface(s) { build(); }
  Surface_index(const Surface_index&) = delete;
  Surface_index& operator=(const Surface_index&) = delete;

  // The same connectivity at positions `points` (one per point of the surface): the boxes of the
  // hierarchies are refitted to them when the same faces have an area and every face still lies
  // within the cover radius of its points; otherwise the index is made anew.
  void update(const std::vector<Vector_3d>& points)
  {
    m_surface.points = points;
    m_normals = m_surface.face_normals();
    m_local_once = std::make_unique<std::once_flag>();
    m_samples_ready.store(false);
    m_grid = Distance_grid();
    for(std::size_t f = 0; f < m_surface.triangles.size(); ++f)
      if((m_normals[f].squared_length() > 0) != (m_kept_of_face[f] != no_face)) {
        build(); // other faces have an area
        return;
      }
    m_triangles.refit([&](std::uint32_t k) { return triangle_box(m_face_of[k]); });
    leaf_corners();
    place_samples();
  }

  bool empty() const { return m_face_of.empty(); }
  // The vertices of the surface, nearby ones mostly next to each other (the order of the leaves
  // of the hierarchy of the faces): queries made in this order read the memory in order.
  const std::vector<std::uint32_t>& vertex_order() const { return m_vertex_order; }
  const Surface& surface() const { return m_surface; }
  const std::vector<Vector_3d>& face_normals() const { return m_normals; }

  static constexpr std::uint32_t no_face = (std::numeric_limits<std::uint32_t>::max)();

  // The closest point of the surface to q. `hint`: a face close to the answer (the answer of a
  // nearby query, say), which speeds the search up, or `no_face`.
  Surface_point closest(const Vector_3d& q, std::uint32_t hint = no_face) const
  {
    Surface_point r;
    if(empty())
      return r;
    if(!(hint < m_kept_of_face.size() && m_kept_of_face[hint] != no_face)) {
      double d2 = 0;
      nearest_sample(q, std::numeric_limits<double>::infinity(), hint, d2);
    }
    r = exact_on_face(q, hint);
    std::array<double, 3> bary;
    m_triangles.nearest(q, r.squared_distance, [&](std::uint32_t j, double& best) {
      const std::array<Vector_3d, 3>& c = m_leaf_corners[j];
      const Vector_3d p = closest_point_on_triangle(q, c[0], c[1], c[2], bary);
      const double d = (p - q).squared_length();
      // Ties go to the smallest face: the answer does not depend on the hint or the hierarchy.
      if(d < best || (d == best && m_leaf_face[j] < r.face)) {
        best = d;
        r.face = m_leaf_face[j];
        r.point = p;
        r.barycentric = bary;
        r.squared_distance = d;
      }
    });
    return r;
  }

  // The closest point of the surface to q among the faces whose unit normal n_f satisfies
  // n_f . normal > min_dot: the closest point overall when its face qualifies, otherwise the best
  // of the faces whose centroids are among the `candidates` nearest to q (not found when none
  // qualifies).
  // With `reach` finite, a point farther than `reach` is not looked for: the result is then not
  // found, or the closest point overall whatever its normal, and the caller treats it as too far.
  Surface_point closest_compatible(const Vector_3d& q, const Vector_3d& normal, double min_dot,
                                   std::uint32_t hint = no_face,
                                   double reach = std::numeric_limits<double>::infinity(),
                                   std::size_t candidates = 24) const
  {
    Surface_point r = closest(q, hint);
    if(!r.found || SAI::dot(m_normals[r.face], normal) > min_dot || !(r.squared_distance < reach * reach))
      return r;
    return closest_among_nearest(q, normal, min_dot, candidates);
  }

  // The structures of the local search (built on its first use, by one thread).
  void ensure_local_search() const
  {
    std::call_once(*m_local_once, [this]() {
      m_grid = Distance_grid(m_surface);
      // The faces' points in a point tree (made here, for the many queries of a local search;
      // numbered in the order of the faces, then of their points, so that its answers, ties
      // included, are those of the hierarchy).
      std::vector<Vector_3d> points;
      std::vector<std::uint32_t> ids;
      m_sample_face.clear();
      std::vector<std::uint32_t> grid(m_surface.triangles.size(), 0);
      for(std::size_t j = 0; j < m_leaf_face.size(); ++j)
        grid[m_leaf_face[j]] = m_leaf_grid[j];
      for(std::uint32_t f : m_face_of)
        samples_of(m_surface.corners(f), grid[f], [&](const Vector_3d& p, std::uint32_t) {
          ids.push_back(std::uint32_t(points.size()));
          points.push_back(p);
          m_sample_face.push_back(f);
        });
      m_sample_tree = SAI::Point_tree(points, ids);
      m_samples_ready.store(true, std::memory_order_release);
      // Faces across each edge (edges of exactly two faces of positive area).
      if(m_adjacent.empty())
        m_adjacent = face_adjacency(m_surface.triangles, [this](std::size_t f) { return m_kept_of_face[f] != no_face; });
    });
  }

  // A fast approximation of `closest_compatible()`: from the face of the nearest of the points
  // that represent the faces (the first of the 8 nearest whose normal agrees with `normal` when
  // that one does not), a descent to edge-adjacent faces of agreeing normals while the distance
  // decreases. Exact on smooth regions; not found when no face point lies within
  // `max_distance` plus the cover radius, or none of the 8 nearest agrees.
  Surface_point approximate_closest_compatible(const Vector_3d& q, const Vector_3d& normal,
                                               double min_dot, double max_distance,
                                               std::vector<std::pair<double, std::uint32_t>>& buffer) const
  {
    Surface_point best;
    if(empty())
      return best;
    ensure_local_search();
    if(m_grid.lower_bound(q) > max_distance)
      return best;
    const double radius = max_distance + m_cover;
    const double r2 = std::isfinite(radius) ? radius * radius : std::numeric_limits<double>::infinity();
    std::uint32_t f = no_face;
    double d2 = 0;
    if(!nearest_sample(q, r2, f, d2))
      return best;
    if(!(SAI::dot(m_normals[f], normal) > min_dot)) {
      f = no_face;
      nearest_samples(q, 8, buffer, r2);
      for(const auto& c : buffer)
        if(SAI::dot(m_normals[c.second], normal) > min_dot) {
          f = c.second;
          break;
        }
      if(f == no_face)
        return best;
    }
    best = exact_on_face(q, f);
    for(int step = 0; step < 16; ++step) {
      const std::uint32_t current = best.face;
      for(int e = 0; e < 3; ++e) {
        const std::uint32_t g = m_adjacent[current][std::size_t(e)];
        if(g == no_face || !(SAI::dot(m_normals[g], normal) > min_dot))
          continue;
        const Surface_point s = exact_on_face(q, g);
        if(s.squared_distance < best.squared_distance)
          best = s;
      }
      if(best.face == current)
        break;
    }
    return best;
  }

  // The points of a face of corners c and grid size n (0: the centroid), numbered in order.
  template <typename Visit>
  static void samples_of(const std::array<Vector_3d, 3>& c, std::uint32_t n, const Visit& visit)
  {
    if(n == 0) {
      visit((c[0] + c[1] + c[2]) / 3.0, 0u);
      return;
    }
    std::uint32_t number = 0;
    for(std::uint32_t i = 0; i <= n; ++i)
      for(std::uint32_t k = 0; i + k <= n; ++k) {
        const double u = double(i) / double(n), v = double(k) / double(n);
        visit(c[0] * (1 - u - v) + c[1] * u + c[2] * v, number++);
      }
  }

private:
  typedef SAI::Bvh::Box Box;

  // The faces of positive area, their points (centroids, and grids on faces much longer than
  // usual, so that every point of a face lies within `m_cover` of one of its points: twice the
  // median longest edge) and the two hierarchies.
  void build()
  {
    const Surface& s = m_surface;
    m_normals = s.face_normals();
    m_local_once = std::make_unique<std::once_flag>();
    m_samples_ready.store(false);
    m_grid = Distance_grid();
    m_face_of.clear();
    m_kept_of_face.assign(s.triangles.size(), no_face);
    m_adjacent.clear();
    m_triangles = SAI::Bvh();
    std::vector<Vector_3d> centroids;
    for(std::size_t f = 0; f < s.triangles.size(); ++f) {
      if(!(m_normals[f].squared_length() > 0))
        continue;
      const auto c = s.corners(f);
      m_kept_of_face[f] = std::uint32_t(m_face_of.size());
      m_face_of.push_back(std::uint32_t(f));
      centroids.push_back((c[0] + c[1] + c[2]) / 3.0);
    }
    if(m_face_of.empty())
      return;
    m_triangles = SAI::Bvh(centroids, [&](std::uint32_t k) { return triangle_box(m_face_of[k]); });
    m_leaf_face.resize(m_triangles.size());
    for(std::size_t j = 0; j < m_leaf_face.size(); ++j)
      m_leaf_face[j] = m_face_of[m_triangles.item(j)];
    leaf_corners();
    place_samples();
    // The vertices in the order of the leaves (each where its first face is met).
    m_vertex_order.clear();
    std::vector<char> seen(s.points.size(), 0);
    for(std::uint32_t f : m_leaf_face)
      for(std::uint32_t v : s.triangles[f])
        if(!seen[v]) {
          seen[v] = 1;
          m_vertex_order.push_back(v);
        }
    for(std::size_t v = 0; v < seen.size(); ++v)
      if(!seen[v])
        m_vertex_order.push_back(std::uint32_t(v));
  }

  // The corners of the faces in the order of the leaves of their hierarchy.
  void leaf_corners()
  {
    m_leaf_corners.resize(m_leaf_face.size());
    for(std::size_t j = 0; j < m_leaf_face.size(); ++j)
      m_leaf_corners[j] = m_surface.corners(m_leaf_face[j]);
  }

  // The points that represent the faces of positive area, and `m_cover`: twice the median longest
  // edge. A face whose longest edge is longer is represented by a grid of n + 1 points a side
  // (spacing at most m_cover), the others by their centroid, so that every point of a face lies
  // within m_cover of one of its points. A function of the positions only, so that queries do
  // not depend on the history of the index; the points are made when a query meets their face
  // (per position of the hierarchy: n, 0 for the centroid).
  void place_samples()
  {
    m_leaf_grid.assign(m_leaf_face.size(), 0);
    if(m_leaf_face.empty())
      return;
    std::vector<double> longest(m_leaf_face.size());
    for(std::size_t j = 0; j < m_leaf_face.size(); ++j)
      longest[j] = longest_edge(m_leaf_face[j]);
    std::vector<double> sorted = longest;
    std::nth_element(sorted.begin(), sorted.begin() + std::ptrdiff_t(sorted.size() / 2), sorted.end());
    m_cover = 2 * sorted[sorted.size() / 2];
    for(std::size_t j = 0; j < m_leaf_face.size(); ++j)
      if(longest[j] > m_cover)
        m_leaf_grid[j] = std::uint32_t(std::ceil(longest[j] / m_cover));
  }

  // Calls visit(point, number) for the points of the face at position j of the hierarchy, numbered
  // in order.
  template <typename Visit>
  void face_samples(std::size_t j, const Visit& visit) const
  {
    samples_of(m_leaf_corners[j], m_leaf_grid[j], visit);
  }

  double longest_edge(std::size_t f) const
  {
    const auto c = m_surface.corners(f);
    return (std::max)((c[1] - c[0]).length(), (std::max)((c[2] - c[1]).length(), (c[0] - c[2]).length()));
  }

  Box triangle_box(std::uint32_t f) const
  {
    Box b;
    for(std::uint32_t v : m_surface.triangles[f])
      b.extend(m_surface.points[v]);
    return b;
  }

  // The face of the nearest of the faces' points to q within sqrt(max_squared_distance), and its
  // squared distance; false when there is none. Ties go to the smallest face, then the first of
  // its points. From the point tree once a local search has made it (the same answers).
  bool nearest_sample(const Vector_3d& q, double max_squared_distance, std::uint32_t& face, double& squared_distance) const
  {
    if(m_samples_ready.load(std::memory_order_acquire)) {
      std::uint32_t id = 0;
      if(!m_sample_tree.nearest(q, max_squared_distance, id, squared_distance))
        return false;
      face = m_sample_face[id];
      return true;
    }
    std::uint32_t found = no_face, found_number = 0;
    double best_d = max_squared_distance;
    m_triangles.nearest(q, max_squared_distance, [&](std::uint32_t j, double& best) {
      const std::uint32_t f = m_leaf_face[j];
      face_samples(j, [&](const Vector_3d& p, std::uint32_t number) {
        const double d = (p - q).squared_length();
        if(d < best_d || (d == best_d && (found == no_face || f < found || (f == found && number < found_number)))) {
          best_d = d;
          found = f;
          found_number = number;
          best = d;
        }
      });
    });
    if(found == no_face)
      return false;
    face = found;
    squared_distance = best_d;
    return true;
  }

  // The faces of the (at most) `count` nearest of the faces' points to q closer than
  // sqrt(max_squared_distance), nearest first, with their squared distances (a long face may
  // come several times; ties in the order of the faces, then of their points).
  void nearest_samples(const Vector_3d& q, std::size_t count, std::vector<std::pair<double, std::uint32_t>>& result,
                       double max_squared_distance = std::numeric_limits<double>::infinity()) const
  {
    result.clear();
    if(count == 0)
      return;
    if(m_samples_ready.load(std::memory_order_acquire)) {
      m_sample_tree.k_nearest(q, count, result, max_squared_distance);
      for(auto& r : result)
        r.second = m_sample_face[r.second];
      return;
    }
    typedef std::pair<double, std::pair<std::uint32_t, std::uint32_t>> Candidate; // (d, (face, number))
    std::vector<Candidate> heap;
    heap.reserve(count);
    m_triangles.nearest(q, max_squared_distance, [&](std::uint32_t j, double& best) {
      const std::uint32_t f = m_leaf_face[j];
      face_samples(j, [&](const Vector_3d& p, std::uint32_t number) {
        const Candidate c((p - q).squared_length(), {f, number});
        if(!(c.first < max_squared_distance))
          return;
        keep_k_smallest(heap, count, c);
        if(heap.size() == count)
          best = heap.front().first;
      });
    });
    std::sort(heap.begin(), heap.end());
    for(const Candidate& c : heap)
      result.emplace_back(c.first, c.second.first);
  }

  Surface_point exact_on_face(const Vector_3d& q, std::uint32_t f) const
  {
    Surface_point r;
    const auto c = m_surface.corners(f);
    r.face = f;
    r.point = closest_point_on_triangle(q, c[0], c[1], c[2], r.barycentric);
    r.squared_distance = (r.point - q).squared_length();
    r.found = true;
    return r;
  }

  Surface_point closest_among_nearest(const Vector_3d& q, const Vector_3d& normal, double min_dot,
                                      std::size_t candidates) const
  {
    Surface_point best;
    std::vector<std::pair<double, std::uint32_t>> near;
    nearest_samples(q, candidates, near);
    for(const auto& c : near) {
      if(!(SAI::dot(m_normals[c.second], normal) > min_dot))
        continue;
      // A face farther than the best point found by more than the largest edge cannot be closer.
      if(best.found) {
        const double reach = std::sqrt(best.squared_distance) + m_cover;
        if(c.first > reach * reach)
          break;
      }
      const Surface_point s = exact_on_face(q, c.second);
      if(!best.found || s.squared_distance < best.squared_distance ||
         (s.squared_distance == best.squared_distance && s.face < best.face))
        best = s;
    }
    return best;
  }

  Surface m_surface;
  std::vector<Vector_3d> m_normals;
  std::vector<std::uint32_t> m_face_of;      // per face of positive area: its face
  std::vector<std::uint32_t> m_kept_of_face; // per face: its position among those, or no_face
  std::unique_ptr<std::once_flag> m_local_once = std::make_unique<std::once_flag>();
  mutable std::vector<std::array<std::uint32_t, 3>> m_adjacent; // per face: the face across each edge
  mutable Distance_grid m_grid;
  double m_cover = 0;
  SAI::Bvh m_triangles; // over the faces of positive area (their positions in m_face_of)
  std::vector<std::uint32_t> m_leaf_face;                // per position of m_triangles: its face
  std::vector<std::array<Vector_3d, 3>> m_leaf_corners;  // and its corners
  std::vector<std::uint32_t> m_leaf_grid;                // and the size of the grid of its points
  std::vector<std::uint32_t> m_vertex_order;
  // Made by the first local search: the faces' points in a point tree, with their faces.
  mutable SAI::Point_tree m_sample_tree;
  mutable std::vector<std::uint32_t> m_sample_face;
  mutable std::atomic<bool> m_samples_ready{false};
};

} // namespace internal
} // namespace Surface_mesh_symmetrization
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_SYMMETRIZATION_INTERNAL_SURFACE_INDEX_H
