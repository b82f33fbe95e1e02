// Copyright (c) 2026 CGAL Global Shape Analysis contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_SURFACE_MESH_SYMMETRIZATION_INTERNAL_SYMMETRY_GEOMETRY_H
#define CGAL_SURFACE_MESH_SYMMETRIZATION_INTERNAL_SYMMETRY_GEOMETRY_H

// The geometry shared by symmetry detection, symmetrization and attribute transfer, on plain
// arrays (independent of the mesh type):
//   - affine maps x -> L x + t and planes n.x = d, with the reflection of a plane;
//   - a triangle surface as arrays (points, triangles) read from any FaceListGraph, with face and
//     vertex normals;
//   - area-weighted random samples of the surface with their normals.
// Closest points on the surface are in Surface_index.h.

#include <CGAL/Shape_analysis/Bad_input.h>
#include <CGAL/Shape_analysis/internal/Dual_graph.h>
#include <CGAL/Shape_analysis/internal/Parallel.h>
#include <CGAL/Shape_analysis/internal/Random.h>
#include <CGAL/Shape_analysis/internal/Similarity_alignment.h>
#include <CGAL/Shape_analysis/internal/Vector_3d.h>

#include <CGAL/Simple_cartesian.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>

#include <Eigen/Dense>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
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
// (a, b, c) is zero or a coefficient is not finite. The coefficients are scaled first
// (SAI::scale_plane_coefficients()): 0,0,1e-300,0 is the plane z = 0.
inline Plane_3d plane_from_coefficients(double a, double b, double c, double d, const std::string& who)
{
  if(!std::isfinite(a) || !std::isfinite(b) || !std::isfinite(c) || !std::isfinite(d))
    throw Bad_input(who + ": the plane has a coefficient that is not a finite number");
  SAI::scale_plane_coefficients(a, b, c, d);
  if(!std::isfinite(d))
    throw Bad_input(who + ": the plane's offset is too large for its normal (a, b, c)");
  const Vector_3d n(a, b, c);
  const double l = n.length();
  if(!(l > 0) || !std::isfinite(l))
    throw Bad_input(who + ": the plane is degenerate (its normal vector is zero)");
  return Plane_3d{n / l, -d / l};
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

} // namespace internal
} // namespace Surface_mesh_symmetrization
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_SYMMETRIZATION_INTERNAL_SYMMETRY_GEOMETRY_H
