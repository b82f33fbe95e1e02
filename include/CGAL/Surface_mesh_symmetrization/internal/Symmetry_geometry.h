// Copyright (c) 2026 CGAL Global Shape Analysis contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_SURFACE_MESH_SYMMETRIZATION_INTERNAL_SYMMETRY_GEOMETRY_H
#define CGAL_SURFACE_MESH_SYMMETRIZATION_INTERNAL_SYMMETRY_GEOMETRY_H

// The geometry shared by symmetry detection, symmetrization and attribute transfer, on plain
// arrays (independent of the mesh type):
//   - affine maps x -> L x + t and planes n.x = d, with the reflection of a plane;
//   - a triangle surface as arrays (points, triangles) read from any FaceListGraph, with face and
//     vertex normals;
//   - closest points on the surface (a bounding-volume hierarchy of the triangles, refitted when
//     the surface moves) with their face and barycentric coordinates, and the closest point whose
//     face normal agrees with a given normal;
//   - area-weighted random samples of the surface with their normals;
//   - the symmetry distance of an affine map: how far the transformed surface lies from itself.

#include <CGAL/Shape_analysis/Bad_input.h>
#include <CGAL/Shape_analysis/internal/Bvh.h>
#include <CGAL/Shape_analysis/internal/Dual_graph.h>
#include <CGAL/Shape_analysis/internal/Parallel.h>
#include <CGAL/Shape_analysis/internal/Point_tree.h>
#include <CGAL/Shape_analysis/internal/Random.h>
#include <CGAL/Shape_analysis/internal/Similarity_alignment.h>
#include <CGAL/Shape_analysis/internal/Vector_3d.h>

#include <CGAL/Simple_cartesian.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>

#include <Eigen/Dense>

#include <algorithm>
#include <atomic>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <memory>
#include <mutex>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Surface_mesh_symmetrization {
namespace internal {

namespace SAI = CGAL::Shape_analysis::internal;
using SAI::Matrix_3d;
using SAI::Vector_3d;
using CGAL::Shape_analysis::Bad_input;

// ---------------------------------------------------------------------------------------------
// Affine maps and planes.

// x -> linear * x + translation (`linear` row by row).
struct Affine_3d
{
  Matrix_3d linear = SAI::identity_matrix();
  Vector_3d translation;

  Vector_3d operator()(const Vector_3d& p) const { return SAI::multiply(linear, p) + translation; }
  Vector_3d apply_linear(const Vector_3d& v) const { return SAI::multiply(linear, v); }

  Eigen::Matrix3d eigen_linear() const
  {
    Eigen::Matrix3d m;
    for(int i = 0; i < 3; ++i)
      for(int j = 0; j < 3; ++j)
        m(i, j) = linear[std::size_t(i)][j];
    return m;
  }

  static Matrix_3d from_eigen(const Eigen::Matrix3d& m)
  {
    Matrix_3d r;
    for(int i = 0; i < 3; ++i)
      r[std::size_t(i)] = Vector_3d(m(i, 0), m(i, 1), m(i, 2));
    return r;
  }

  // Whether the linear part can be inverted (|det| not tiny relative to its entries).
  bool is_invertible() const
  {
    double scale = 0;
    for(std::size_t i = 0; i < 3; ++i)
      scale = (std::max)(scale, linear[i].length());
    const double det = SAI::determinant(linear);
    return scale > 0 && std::isfinite(det) && std::abs(det) > 1e-12 * scale * scale * scale;
  }

  Affine_3d inverse() const
  {
    Affine_3d r;
    r.linear = from_eigen(eigen_linear().inverse());
    r.translation = SAI::multiply(r.linear, translation) * -1.0;
    return r;
  }

  // The unit normal of the transformed surface at the image of a point of unit normal `n`:
  // the inverse transpose of the linear part applied to n (zero when n is zero).
  Vector_3d transform_normal(const Vector_3d& n, const Matrix_3d& inverse_transpose) const
  {
    const Vector_3d m = SAI::multiply(inverse_transpose, n);
    const double l = m.length();
    return l > 0 ? m / l : Vector_3d(0.0);
  }

  Matrix_3d normal_matrix() const { return from_eigen(eigen_linear().inverse().transpose()); }

  bool is_finite() const
  {
    for(std::size_t i = 0; i < 3; ++i)
      for(int j = 0; j < 3; ++j)
        if(!std::isfinite(linear[i][j]))
          return false;
    return std::isfinite(translation.x) && std::isfinite(translation.y) &&
           std::isfinite(translation.z);
  }
};

// The plane n.x = d, n a unit vector.
struct Plane_3d
{
  Vector_3d normal{0, 0, 1};
  double offset = 0;

  double signed_distance(const Vector_3d& p) const { return SAI::dot(normal, p) - offset; }

  // The same plane with the normal pointing the other way.
  Plane_3d opposite() const { return Plane_3d{normal * -1.0, -offset}; }
};

// The reflection across `plane`: x -> x - 2 (n.x - d) n.
inline Affine_3d reflection(const Plane_3d& plane)
{
  Affine_3d r;
  const Vector_3d& n = plane.normal;
  for(int i = 0; i < 3; ++i)
    for(int j = 0; j < 3; ++j)
      r.linear[std::size_t(i)][j] = (i == j ? 1.0 : 0.0) - 2.0 * n[i] * n[j];
  r.translation = n * (2.0 * plane.offset);
  return r;
}

inline Vector_3d reflect(const Plane_3d& plane, const Vector_3d& p)
{
  return p - plane.normal * (2.0 * plane.signed_distance(p));
}

inline Vector_3d reflect_direction(const Plane_3d& plane, const Vector_3d& v)
{
  return v - plane.normal * (2.0 * SAI::dot(plane.normal, v));
}

// The plane a x + b y + c z + d = 0 as n.x = offset with n a unit vector; throws Bad_input when
// (a, b, c) is zero or a coefficient is not finite.
inline Plane_3d plane_from_coefficients(double a, double b, double c, double d, const std::string& who)
{
  if(!std::isfinite(a) || !std::isfinite(b) || !std::isfinite(c) || !std::isfinite(d))
    throw Bad_input(who + ": the plane has a coefficient that is not a finite number");
  const Vector_3d n(a, b, c);
  const double l = n.length();
  if(!(l > 0) || !std::isfinite(l))
    throw Bad_input(who + ": the plane is degenerate (its normal vector is zero)");
  return Plane_3d{n / l, -d / l};
}

// The angle (radians, in [0, pi/2]) between the normals of two planes (unoriented).
inline double plane_angle(const Plane_3d& a, const Plane_3d& b)
{
  const double c = std::abs(SAI::dot(a.normal, b.normal));
  return std::acos((std::min)(1.0, c));
}

// ---------------------------------------------------------------------------------------------
// A triangle surface as arrays.

struct Surface
{
  std::vector<Vector_3d> points;                         // per vertex
  std::vector<std::array<std::uint32_t, 3>> triangles;   // per face: three vertex indices

  std::size_t number_of_vertices() const { return points.size(); }
  std::size_t number_of_faces() const { return triangles.size(); }

  std::array<Vector_3d, 3> corners(std::size_t f) const
  {
    const auto& t = triangles[f];
    return {{points[t[0]], points[t[1]], points[t[2]]}};
  }

  // Twice the area vector of face f (normal times twice the area).
  Vector_3d area_vector(std::size_t f) const
  {
    const auto c = corners(f);
    return SAI::cross(c[1] - c[0], c[2] - c[0]);
  }

  double area(std::size_t f) const { return 0.5 * area_vector(f).length(); }

  double total_area() const
  {
    double a = 0;
    for(std::size_t f = 0; f < triangles.size(); ++f)
      a += area(f);
    return a;
  }

  // The diagonal of the bounding box of the face corners (0 without faces).
  double diagonal() const
  {
    if(triangles.empty())
      return 0;
    Vector_3d lo(std::numeric_limits<double>::infinity()), hi(-std::numeric_limits<double>::infinity());
    for(const auto& t : triangles)
      for(std::uint32_t v : t) {
        lo = lo.min(points[v]);
        hi = hi.max(points[v]);
      }
    return (hi - lo).length();
  }

  // The area-weighted centroid of the surface.
  Vector_3d area_centroid() const
  {
    Vector_3d c;
    double a = 0;
    for(std::size_t f = 0; f < triangles.size(); ++f) {
      const auto k = corners(f);
      const double w = area(f);
      c += (k[0] + k[1] + k[2]) * (w / 3.0);
      a += w;
    }
    return a > 0 ? c / a : c;
  }

  // Unit face normals (zero for degenerate faces).
  std::vector<Vector_3d> face_normals() const
  {
    std::vector<Vector_3d> n(triangles.size());
    for(std::size_t f = 0; f < triangles.size(); ++f) {
      const Vector_3d a = area_vector(f);
      const double l = a.length();
      n[f] = l > 0 ? a / l : Vector_3d(0.0);
    }
    return n;
  }

  // Unit vertex normals: the sum of the area vectors of the incident faces, normalized (zero for
  // a vertex without faces of positive area).
  std::vector<Vector_3d> vertex_normals() const
  {
    std::vector<Vector_3d> n(points.size());
    for(std::size_t f = 0; f < triangles.size(); ++f) {
      const Vector_3d a = area_vector(f);
      for(std::uint32_t v : triangles[f])
        n[v] += a;
    }
    for(Vector_3d& v : n) {
      const double l = v.length();
      v = l > 0 ? v / l : Vector_3d(0.0);
    }
    return n;
  }

  // The undirected edges (i < j), each once, sorted.
  std::vector<std::pair<std::uint32_t, std::uint32_t>> edges() const
  {
    std::vector<std::pair<std::uint32_t, std::uint32_t>> e;
    e.reserve(3 * triangles.size());
    for(const auto& t : triangles)
      for(int k = 0; k < 3; ++k) {
        std::uint32_t a = t[std::size_t(k)], b = t[std::size_t((k + 1) % 3)];
        if(a > b)
          std::swap(a, b);
        e.emplace_back(a, b);
      }
    std::sort(e.begin(), e.end());
    e.erase(std::unique(e.begin(), e.end()), e.end());
    return e;
  }
};

// The vertices and faces of a mesh in the order of vertices(tm) and faces(tm), with the dense
// index of every vertex (its position in vertices(tm)).
template <typename TriangleMesh>
struct Mesh_arrays
{
  typedef boost::graph_traits<TriangleMesh> GT;
  typedef typename GT::vertex_descriptor vertex_descriptor;
  typedef typename GT::face_descriptor face_descriptor;

  std::vector<vertex_descriptor> vertices;
  std::vector<face_descriptor> faces;
  Surface surface;
};

// Reads `tm` (checked: non-empty, triangles only, finite coordinates, at most 2^32 - 1 vertices)
// through `vpm`, with `to_vector` turning a point into a Vector_3d. Vertices that no face uses
// are kept (they are listed in vertices(tm)).
template <typename TriangleMesh, typename VertexPointMap, typename ToVector>
Mesh_arrays<TriangleMesh> read_mesh(const TriangleMesh& tm, VertexPointMap vpm,
                                    const ToVector& to_vector, const std::string& who)
{
  typedef Mesh_arrays<TriangleMesh> Arrays;
  Arrays a;
  if(faces(tm).empty())
    throw Bad_input(who + ": the mesh has no faces");
  for(auto v : vertices(tm))
    a.vertices.push_back(v);
  if(a.vertices.size() >= std::size_t((std::numeric_limits<std::uint32_t>::max)()))
    throw Bad_input(who + ": the mesh has too many vertices");
  // Dense vertex indices through a sorted copy of the descriptors (works for any descriptor
  // type with operator<, as CGAL's are).
  std::vector<std::pair<typename Arrays::vertex_descriptor, std::uint32_t>> order;
  order.reserve(a.vertices.size());
  for(std::size_t i = 0; i < a.vertices.size(); ++i)
    order.emplace_back(a.vertices[i], std::uint32_t(i));
  std::sort(order.begin(), order.end(),
            [](const auto& x, const auto& y) { return x.first < y.first; });
  const auto index_of = [&](typename Arrays::vertex_descriptor v) {
    const auto it = std::lower_bound(order.begin(), order.end(), v,
                                     [](const auto& x, const auto& key) { return x.first < key; });
    return it->second;
  };
  a.surface.points.resize(a.vertices.size());
  for(std::size_t i = 0; i < a.vertices.size(); ++i) {
    const Vector_3d p = to_vector(get(vpm, a.vertices[i]));
    if(!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
      throw Bad_input(who + ": vertex " + std::to_string(i) +
                      " has a coordinate that is not a finite number");
    a.surface.points[i] = p;
  }
  std::size_t index = 0;
  for(auto f : faces(tm)) {
    std::array<std::uint32_t, 3> t{{0, 0, 0}};
    std::size_t degree = 0;
    for(auto h : CGAL::halfedges_around_face(halfedge(f, tm), tm)) {
      if(degree < 3)
        t[degree] = index_of(target(h, tm));
      if(++degree > 3)
        break;
    }
    if(degree != 3)
      throw Bad_input(who + ": face " + std::to_string(index) +
                      " is not a triangle; triangulate the mesh first");
    a.faces.push_back(f);
    a.surface.triangles.push_back(t);
    ++index;
  }
  return a;
}

// ---------------------------------------------------------------------------------------------
// Closest points on a triangle and on a surface.

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

// A coarse lower bound of the distance to a surface, to skip the queries of points that are far
// from it: a grid over the bounding box (plus a margin), about 64 cells along its longest side;
// the cells the surface crosses are found by sampling every triangle at half the cell size; the
// other cells get a chamfer distance (26 neighbours, weights 1, sqrt 2, sqrt 3, two passes) to
// the nearest crossed cell.
class Distance_grid
{
public:
  Distance_grid() = default;

  explicit Distance_grid(const Surface& s, std::size_t resolution = 64)
  {
    if(s.triangles.empty())
      return;
    Vector_3d lo(std::numeric_limits<double>::infinity()), hi(-std::numeric_limits<double>::infinity());
    for(const auto& t : s.triangles)
      for(std::uint32_t v : t) {
        lo = lo.min(s.points[v]);
        hi = hi.max(s.points[v]);
      }
    const Vector_3d extent = hi - lo;
    const double longest = (std::max)(extent.x, (std::max)(extent.y, extent.z));
    if(!(longest > 0) || !std::isfinite(longest))
      return;
    m_cell = longest / double(resolution);
    m_origin = lo - Vector_3d(2 * m_cell);
    for(int a = 0; a < 3; ++a)
      m_size[std::size_t(a)] = std::size_t(std::ceil(extent[a] / m_cell)) + 4;
    const std::size_t n = m_size[0] * m_size[1] * m_size[2];
    const float unknown = std::numeric_limits<float>::infinity();
    m_distance.assign(n, unknown);
    const double step = 0.5 * m_cell;
    for(std::size_t f = 0; f < s.triangles.size(); ++f) {
      const auto c = s.corners(f);
      const double l = (std::max)((c[1] - c[0]).length(), (std::max)((c[2] - c[1]).length(), (c[0] - c[2]).length()));
      const std::size_t k = (std::max)(std::size_t(1), std::size_t(std::ceil(l / step)));
      for(std::size_t i = 0; i <= k; ++i)
        for(std::size_t j = 0; i + j <= k; ++j) {
          const double u = double(i) / double(k), v = double(j) / double(k);
          m_distance[cell_of(c[0] * (1 - u - v) + c[1] * u + c[2] * v)] = 0;
        }
    }
    // Chamfer distance in cell units: a forward and a backward pass.
    const float w[3] = {1.0f, 1.41421356f, 1.73205081f};
    const long sx = long(m_size[0]), sy = long(m_size[1]), sz = long(m_size[2]);
    const auto index = [&](long x, long y, long z) { return std::size_t((z * sy + y) * sx + x); };
    for(int pass = 0; pass < 2; ++pass) {
      const long dir = pass == 0 ? 1 : -1;
      for(long zz = 0; zz < sz; ++zz)
        for(long yy = 0; yy < sy; ++yy)
          for(long xx = 0; xx < sx; ++xx) {
            const long x = pass == 0 ? xx : sx - 1 - xx, y = pass == 0 ? yy : sy - 1 - yy,
                       z = pass == 0 ? zz : sz - 1 - zz;
            float best = m_distance[index(x, y, z)];
            for(long dz = -1; dz <= 0; ++dz)
              for(long dy = -1; dy <= 1; ++dy)
                for(long dx = -1; dx <= 1; ++dx) {
                  // the neighbours already visited by this pass
                  if(dz == 0 && (dy > 0 || (dy == 0 && dx >= 0)))
                    continue;
                  const long nx = x + dir * dx, ny = y + dir * dy, nz = z + dir * dz;
                  if(nx < 0 || ny < 0 || nz < 0 || nx >= sx || ny >= sy || nz >= sz)
                    continue;
                  const float d = m_distance[index(nx, ny, nz)] + w[std::abs(dx) + std::abs(dy) + std::abs(dz) - 1];
                  best = (std::min)(best, d);
                }
            m_distance[index(x, y, z)] = best;
          }
    }
  }

  bool empty() const { return m_distance.empty(); }

  // A lower bound of the distance from q to the surface (0 when unsure).
  double lower_bound(const Vector_3d& q) const
  {
    if(m_distance.empty())
      return 0;
    // Outside the grid: the distance to the grid's box, plus the margin of two cells.
    double outside = 0;
    Vector_3d clamped = q;
    for(int a = 0; a < 3; ++a) {
      const double lo = m_origin[a], hi = m_origin[a] + double(m_size[std::size_t(a)]) * m_cell;
      if(q[a] < lo) {
        outside += (lo - q[a]) * (lo - q[a]);
        clamped[a] = lo;
      } else if(q[a] > hi) {
        outside += (q[a] - hi) * (q[a] - hi);
        clamped[a] = hi;
      }
    }
    const double inside = double(m_distance[cell_of(clamped)]);
    // The chamfer distance overestimates the distance between cell centres by at most 9%; each
    // end may lie sqrt(3)/2 cells from its centre.
    const double bound = (inside / 1.09 - 1.7320508) * m_cell;
    return std::sqrt(outside) + (std::max)(0.0, bound);
  }

private:
  std::size_t cell_of(const Vector_3d& p) const
  {
    std::size_t c[3];
    for(int a = 0; a < 3; ++a) {
      const double t = (p[a] - m_origin[a]) / m_cell;
      const long i = long(std::floor(t));
      c[a] = std::size_t((std::max)(0L, (std::min)(long(m_size[std::size_t(a)]) - 1, i)));
    }
    return (c[2] * m_size[1] + c[1]) * m_size[0] + c[0];
  }

  Vector_3d m_origin;
  double m_cell = 0;
  std::array<std::size_t, 3> m_size{{0, 0, 0}};
  std::vector<float> m_distance;
};

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
// the search.
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

  // Whether some point of the surface may lie within `radius` of q (false only when none does;
  // a quick test through the face centroids, to skip the exact query of far points).
  bool may_be_near(const Vector_3d& q, double radius) const
  {
    if(empty())
      return false;
    if(!std::isfinite(radius))
      return true;
    const double r = radius + m_cover;
    std::uint32_t f = no_face;
    double d2 = 0;
    return nearest_sample(q, r * r, f, d2);
  }

  // The point of face f at barycentric coordinates b.
  Vector_3d point_at(std::uint32_t f, const std::array<double, 3>& b) const
  {
    const auto c = m_surface.corners(f);
    return c[0] * b[0] + c[1] * b[1] + c[2] * b[2];
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
        SAI::keep_k_smallest(heap, count, c);
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

// ---------------------------------------------------------------------------------------------
// Surface samples.

struct Surface_samples
{
  std::vector<Vector_3d> points;
  std::vector<Vector_3d> normals; // unit normal of the face each point lies on
  std::vector<std::uint32_t> faces;
};

// `n` points drawn on the faces of positive area, each face with probability proportional to its
// area, uniformly inside it; from the random stream (seed, stream).
inline Surface_samples sample_surface(const Surface& s, std::size_t n, std::uint64_t seed,
                                      std::uint64_t stream)
{
  Surface_samples r;
  const std::vector<Vector_3d> normals = s.face_normals();
  std::vector<double> cumulative(s.triangles.size());
  double total = 0;
  for(std::size_t f = 0; f < s.triangles.size(); ++f) {
    total += normals[f].squared_length() > 0 ? s.area(f) : 0.0;
    cumulative[f] = total;
  }
  if(!(total > 0))
    return r;
  SAI::Random_stream rng(seed, stream);
  r.points.reserve(n);
  r.normals.reserve(n);
  r.faces.reserve(n);
  for(std::size_t i = 0; i < n; ++i) {
    const double u = rng.uniform() * total;
    std::size_t f = std::size_t(std::upper_bound(cumulative.begin(), cumulative.end(), u) - cumulative.begin());
    f = (std::min)(f, cumulative.size() - 1);
    while(f > 0 && !(normals[f].squared_length() > 0))
      --f;
    const auto c = s.corners(f);
    const double r1 = std::sqrt(rng.uniform()), r2 = rng.uniform();
    r.points.push_back(c[0] * (1 - r1) + c[1] * (r1 * (1 - r2)) + c[2] * (r1 * r2));
    r.normals.push_back(normals[f]);
    r.faces.push_back(std::uint32_t(f));
  }
  return r;
}

// ---------------------------------------------------------------------------------------------
// Symmetry distance.

// The truncated distances of transformed samples to the surface: sample i moved by `t` is paired
// with the closest point of the surface whose face normal agrees with the transformed normal
// (dot product > 0); its distance, at most `cap`, is `cap` when there is no such point.
struct Symmetry_distances
{
  std::vector<double> distance;
  double rms = 0; // root mean square of `distance`
};

inline Symmetry_distances symmetry_distances(const Surface_samples& samples, const Affine_3d& t,
                                             const Surface_index& index, double cap,
                                             std::size_t threads)
{
  Symmetry_distances r;
  const std::size_t n = samples.points.size();
  r.distance.assign(n, cap);
  if(n == 0)
    return r;
  const Matrix_3d nm = t.normal_matrix();
  SAI::Parallel_workspaces<char> parallel(threads);
  const std::size_t block = 256;
  parallel.for_each(0, (n + block - 1) / block, [&](std::size_t b, char&) {
    for(std::size_t i = b * block; i < (std::min)(n, (b + 1) * block); ++i) {
      const Vector_3d q = t(samples.points[i]);
      const Vector_3d m = t.transform_normal(samples.normals[i], nm);
      const Surface_point c = index.closest_compatible(q, m, 0.0);
      if(c.found)
        r.distance[i] = (std::min)(cap, std::sqrt(c.squared_distance));
    }
  });
  double sum = 0;
  for(double d : r.distance)
    sum += d * d;
  r.rms = std::sqrt(sum / double(n));
  return r;
}

} // namespace internal
} // namespace Surface_mesh_symmetrization
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_SYMMETRIZATION_INTERNAL_SYMMETRY_GEOMETRY_H
