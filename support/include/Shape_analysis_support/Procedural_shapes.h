// Copyright (c) 2026 CGAL Global Shape Analysis contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef SHAPE_ANALYSIS_SUPPORT_PROCEDURAL_SHAPES_H
#define SHAPE_ANALYSIS_SUPPORT_PROCEDURAL_SHAPES_H

// Procedural part-structured triangle meshes with known ground-truth part labels, for tests and
// benchmarks. Deterministic: the same shape, cell size and seed give the same mesh, bit for bit,
// on every platform (own random generator, no std::distribution, no unordered iteration).
//
// A shape is a union of primitives (sphere, capsule, box with optional rounding, capped
// cylinder), each with a part label. Its field is the hard minimum of the primitives' signed
// distances, so that parts meet at concave creases. The mesher samples the field on a regular
// grid, splits every cell into 6 tetrahedra (Kuhn triangulation, consistent across cells) and
// extracts the zero level set of the piecewise-linear interpolant (marching tetrahedra).
// Vertices are keyed by the grid edge they lie on, so the result is a closed, consistently
// oriented (outward) 2-manifold triangle mesh, one connected component per connected solid.
// Every triangle is labelled by the primitive whose signed distance is smallest at its
// centroid.
//
// The output is plain arrays (points, triangles, labels); `fill_polygon_mesh()` copies it into
// any CGAL `MutableFaceGraph` keeping the face order equal to the triangle order. Small
// utilities for tests: rigid transforms, face shuffling with a seed, and partition agreement
// measures (Rand index, best-matching overlap).

#include <Shape_analysis_support/Partition_agreement.h>
#include <CGAL/Shape_analysis/internal/Random.h>
#include <CGAL/Shape_analysis/internal/Vector_3d.h>

#include <CGAL/boost/graph/Euler_operations.h>
#include <CGAL/boost/graph/helpers.h>
#include <boost/graph/graph_traits.hpp>
#include <boost/property_map/property_map.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <map>
#include <numeric>
#include <stdexcept>
#include <unordered_map>
#include <utility>
#include <vector>

namespace CGAL {
namespace Shape_analysis_support {

using CGAL::Shape_analysis::internal::Random_stream;
using CGAL::Shape_analysis::internal::Vector_3d;

// Random numbers identical on every platform (splitmix64).
typedef Random_stream Procedural_random;

// ---------------------------------------------------------------------------------------------
// Primitives

struct Shape_primitive
{
  enum Kind { SPHERE, CAPSULE, BOX, CYLINDER };

  Kind kind = SPHERE;
  Vector_3d a;                 // center (sphere, box) or first end of the axis
  Vector_3d b;                 // second end of the axis (capsule, cylinder)
  double radius = 1;           // sphere, capsule, cylinder radius; box rounding radius
  Vector_3d half_extents{0.5}; // box half extents, rounding included
  std::array<Vector_3d, 3> axes{{Vector_3d(1, 0, 0), Vector_3d(0, 1, 0), Vector_3d(0, 0, 1)}};
  std::size_t label = 0;

  static Shape_primitive sphere(const Vector_3d& center, double radius, std::size_t label)
  {
    Shape_primitive p;
    p.kind = SPHERE;
    p.a = center;
    p.radius = radius;
    p.label = label;
    return p;
  }

  static Shape_primitive capsule(const Vector_3d& a, const Vector_3d& b, double radius,
                                 std::size_t label)
  {
    Shape_primitive p;
    p.kind = CAPSULE;
    p.a = a;
    p.b = b;
    p.radius = radius;
    p.label = label;
    return p;
  }

  // Flat-capped cylinder of axis a-b.
  static Shape_primitive cylinder(const Vector_3d& a, const Vector_3d& b, double radius,
                                  std::size_t label)
  {
    Shape_primitive p = capsule(a, b, radius, label);
    p.kind = CYLINDER;
    return p;
  }

  // Box of the given center and half extents along `axes` (orthonormal, default: x, y, z),
  // its edges rounded with radius `rounding` (0: sharp).
  static Shape_primitive box(const Vector_3d& center, const Vector_3d& half_extents,
                             std::size_t label, double rounding = 0,
                             const std::array<Vector_3d, 3>& axes = {{Vector_3d(1, 0, 0),
                                                                      Vector_3d(0, 1, 0),
                                                                      Vector_3d(0, 0, 1)}})
  {
    Shape_primitive p;
    p.kind = BOX;
    p.a = center;
    p.half_extents = half_extents;
    p.radius = rounding;
    p.axes = axes;
    p.label = label;
    return p;
  }

  // Signed distance (exact for spheres, capsules and boxes; a close bound for cylinders).
  double distance(const Vector_3d& p) const
  {
    switch(kind) {
    case SPHERE:
      return (p - a).length() - radius;
    case CAPSULE: {
      const Vector_3d ab = b - a;
      const double l2 = ab.squared_length();
      const double t = l2 > 0 ? (std::max)(0.0, (std::min)(1.0, dot(p - a, ab) / l2)) : 0.0;
      return (p - (a + ab * t)).length() - radius;
    }
    case CYLINDER: {
      const Vector_3d ab = b - a;
      const double l = ab.length();
      const Vector_3d u = l > 0 ? ab / l : Vector_3d(0, 0, 1);
      const Vector_3d m = (a + b) * 0.5;
      const double axial = std::abs(dot(p - m, u)) - 0.5 * l;
      const Vector_3d radial_vector = (p - m) - u * dot(p - m, u);
      const double radial = radial_vector.length() - radius;
      const double ox = (std::max)(axial, 0.0), oy = (std::max)(radial, 0.0);
      return std::sqrt(ox * ox + oy * oy) + (std::min)((std::max)(axial, radial), 0.0);
    }
    case BOX: {
      const Vector_3d d = p - a;
      double outside = 0, inside = -std::numeric_limits<double>::infinity();
      for(int i = 0; i < 3; ++i) {
        const double q = std::abs(dot(d, axes[i])) - (half_extents[i] - radius);
        outside += q > 0 ? q * q : 0.0;
        inside = (std::max)(inside, q);
      }
      return std::sqrt(outside) + (std::min)(inside, 0.0) - radius;
    }
    }
    return std::numeric_limits<double>::infinity();
  }

  void bounding_box(Vector_3d& lo, Vector_3d& hi) const
  {
    switch(kind) {
    case SPHERE:
      lo = a - Vector_3d(radius);
      hi = a + Vector_3d(radius);
      return;
    case CAPSULE:
    case CYLINDER:
      lo = a.min(b) - Vector_3d(radius);
      hi = a.max(b) + Vector_3d(radius);
      return;
    case BOX: {
      Vector_3d r;
      for(int i = 0; i < 3; ++i)
        r[i] = std::abs(axes[0][i]) * half_extents[0] + std::abs(axes[1][i]) * half_extents[1] +
               std::abs(axes[2][i]) * half_extents[2];
      lo = a - r;
      hi = a + r;
      return;
    }
    }
  }
};

// A union of labelled primitives (hard minimum of their signed distances).
struct Procedural_shape
{
  std::vector<Shape_primitive> primitives;

  Procedural_shape& add(const Shape_primitive& p)
  {
    primitives.push_back(p);
    return *this;
  }

  // One more than the largest label.
  std::size_t number_of_labels() const
  {
    std::size_t n = 0;
    for(const Shape_primitive& p : primitives)
      n = (std::max)(n, p.label + 1);
    return n;
  }

  // Signed distance of the union; `nearest` receives the index of the primitive that realizes it.
  double field(const Vector_3d& p, std::size_t* nearest = nullptr) const
  {
    double best = std::numeric_limits<double>::infinity();
    std::size_t best_i = 0;
    for(std::size_t i = 0; i < primitives.size(); ++i) {
      const double d = primitives[i].distance(p);
      if(d < best) {
        best = d;
        best_i = i;
      }
    }
    if(nearest != nullptr)
      *nearest = best_i;
    return best;
  }

  std::size_t label_at(const Vector_3d& p) const
  {
    std::size_t i = 0;
    field(p, &i);
    return primitives.empty() ? 0 : primitives[i].label;
  }

  void bounding_box(Vector_3d& lo, Vector_3d& hi) const
  {
    lo = Vector_3d(std::numeric_limits<double>::infinity());
    hi = Vector_3d(-std::numeric_limits<double>::infinity());
    for(const Shape_primitive& p : primitives) {
      Vector_3d l, h;
      p.bounding_box(l, h);
      lo = lo.min(l);
      hi = hi.max(h);
    }
  }
};

// ---------------------------------------------------------------------------------------------
// Output: a labelled triangle soup that is a closed manifold mesh.

struct Labelled_triangle_mesh
{
  std::vector<std::array<double, 3>> points;
  std::vector<std::array<std::size_t, 3>> triangles; // outward orientation
  std::vector<std::size_t> labels;                    // one per triangle
  std::size_t number_of_labels = 0;

  std::size_t number_of_faces() const { return triangles.size(); }

  Vector_3d point(std::size_t v) const { return Vector_3d(points[v][0], points[v][1], points[v][2]); }

  double area(std::size_t f) const
  {
    const Vector_3d p = point(triangles[f][0]), q = point(triangles[f][1]), r = point(triangles[f][2]);
    return 0.5 * cross(q - p, r - p).length();
  }

  std::vector<double> areas() const
  {
    std::vector<double> result(triangles.size());
    for(std::size_t f = 0; f < triangles.size(); ++f)
      result[f] = area(f);
    return result;
  }

  Vector_3d centroid(std::size_t f) const
  {
    return (point(triangles[f][0]) + point(triangles[f][1]) + point(triangles[f][2])) / 3.0;
  }
};

// ---------------------------------------------------------------------------------------------
// The mesher: marching tetrahedra on a Kuhn-triangulated grid.

// Meshes the boundary of `shape` with grid cells of size `cell_size` (7 to 9 triangles per
// cell^2 of surface area; parts thinner than 2 cells may vanish or break up). The triangles come
// in grid order (slice by slice along z).
inline Labelled_triangle_mesh mesh_procedural_shape(const Procedural_shape& shape, double cell_size)
{
  if(!(cell_size > 0) || shape.primitives.empty())
    throw std::invalid_argument("mesh_procedural_shape: empty shape or non-positive cell size");
  Vector_3d lo, hi;
  shape.bounding_box(lo, hi);
  // A margin of two cells keeps the grid boundary outside the solid; a fixed irrational-looking
  // offset keeps grid vertices off the symmetry planes of the primitives.
  const Vector_3d origin = lo - Vector_3d(2 * cell_size) +
                           Vector_3d(0.1173, 0.2311, 0.3359) * cell_size;
  std::array<std::size_t, 3> cells;
  for(int i = 0; i < 3; ++i)
    cells[i] = static_cast<std::size_t>(std::ceil((hi[i] + 2 * cell_size - origin[i]) / cell_size));
  const std::size_t sx = cells[0] + 1, sy = cells[1] + 1, sz = cells[2] + 1;
  const std::size_t grid_size = sx * sy * sz;
  if(!(grid_size < (std::size_t(1) << 31)))
    throw std::invalid_argument("mesh_procedural_shape: grid too fine for the shape");
  auto grid_point = [&](std::size_t i, std::size_t j, std::size_t k) {
    return origin + Vector_3d(double(i), double(j), double(k)) * cell_size;
  };
  auto grid_id = [&](std::size_t i, std::size_t j, std::size_t k) { return i + sx * (j + sy * k); };

  // Field values, pushed away from zero so that no mesh vertex sits on a grid vertex.
  const double nudge = 1e-4 * cell_size;
  std::vector<double> value(grid_size);
  for(std::size_t k = 0; k < sz; ++k)
    for(std::size_t j = 0; j < sy; ++j)
      for(std::size_t i = 0; i < sx; ++i) {
        double v = shape.field(grid_point(i, j, k));
        if(v >= 0 && v < nudge)
          v = nudge;
        else if(v < 0 && v > -nudge)
          v = -nudge;
        value[grid_id(i, j, k)] = v;
      }

  Labelled_triangle_mesh mesh;
  mesh.number_of_labels = shape.number_of_labels();
  std::unordered_map<std::uint64_t, std::size_t> vertex_on_edge;
  auto edge_vertex = [&](std::size_t u, const Vector_3d& pu, std::size_t v, const Vector_3d& pv) {
    const std::uint64_t lo_id = (std::min)(u, v), hi_id = (std::max)(u, v);
    const std::uint64_t key = lo_id * std::uint64_t(grid_size) + hi_id;
    auto it = vertex_on_edge.find(key);
    if(it != vertex_on_edge.end())
      return it->second;
    // Interpolate from the lower id so that the point does not depend on the tetrahedron.
    const bool u_first = u < v;
    const double fa = u_first ? value[u] : value[v], fb = u_first ? value[v] : value[u];
    const Vector_3d& pa = u_first ? pu : pv;
    const Vector_3d& pb = u_first ? pv : pu;
    const double t = fa / (fa - fb);
    const Vector_3d p = pa + (pb - pa) * t;
    mesh.points.push_back({p.x, p.y, p.z});
    vertex_on_edge.emplace(key, mesh.points.size() - 1);
    return mesh.points.size() - 1;
  };
  auto add_triangle = [&](std::size_t a, std::size_t b, std::size_t c) {
    mesh.triangles.push_back({a, b, c});
  };

  // The 6 tetrahedra of a cell: from corner 000 to 111 along the axes in the order of a
  // permutation; the orientation of the tetrahedron is the sign of the permutation.
  static const int permutations[6][3] = {{0, 1, 2}, {1, 2, 0}, {2, 0, 1},
                                         {0, 2, 1}, {2, 1, 0}, {1, 0, 2}};
  static const int permutation_sign[6] = {1, 1, 1, -1, -1, -1};

  for(std::size_t k = 0; k + 1 < sz; ++k)
    for(std::size_t j = 0; j + 1 < sy; ++j)
      for(std::size_t i = 0; i + 1 < sx; ++i) {
        // Skip cells without a sign change.
        bool has_in = false, has_out = false;
        for(int c = 0; c < 8; ++c) {
          const double v = value[grid_id(i + (c & 1), j + ((c >> 1) & 1), k + ((c >> 2) & 1))];
          (v < 0 ? has_in : has_out) = true;
        }
        if(!has_in || !has_out)
          continue;
        for(int t = 0; t < 6; ++t) {
          std::array<std::size_t, 3> corner = {i, j, k};
          std::size_t id[4];
          Vector_3d pos[4];
          bool inside[4];
          for(int c = 0; c < 4; ++c) {
            if(c > 0)
              ++corner[std::size_t(permutations[t][c - 1])];
            id[c] = grid_id(corner[0], corner[1], corner[2]);
            pos[c] = grid_point(corner[0], corner[1], corner[2]);
            inside[c] = value[id[c]] < 0;
          }
          int n_in = 0;
          for(int c = 0; c < 4; ++c)
            n_in += inside[c] ? 1 : 0;
          if(n_in == 0 || n_in == 4)
            continue;
          // Order the corners: for 1 or 2 inside corners, inside ones first; for 3, the outside
          // one first. Then make the ordered tetrahedron positively oriented by swapping the last
          // two corners (which are of the same kind) if needed.
          int p[4];
          int m = 0;
          const bool outside_first = n_in == 3;
          for(int c = 0; c < 4; ++c)
            if(inside[c] != outside_first)
              p[m++] = c;
          for(int c = 0; c < 4; ++c)
            if(inside[c] == outside_first)
              p[m++] = c;
          int inversions = 0;
          for(int x = 0; x < 4; ++x)
            for(int y = x + 1; y < 4; ++y)
              if(p[x] > p[y])
                ++inversions;
          const int orientation = permutation_sign[t] * ((inversions % 2) == 0 ? 1 : -1);
          if(orientation < 0)
            std::swap(p[2], p[3]);
          auto e = [&](int x, int y) { return edge_vertex(id[p[x]], pos[p[x]], id[p[y]], pos[p[y]]); };
          if(n_in == 1) {
            add_triangle(e(0, 1), e(0, 2), e(0, 3));
          } else if(n_in == 3) {
            add_triangle(e(0, 1), e(0, 3), e(0, 2));
          } else {
            const std::size_t q0 = e(0, 2), q1 = e(0, 3), q2 = e(1, 3), q3 = e(1, 2);
            add_triangle(q0, q1, q2);
            add_triangle(q0, q2, q3);
          }
        }
      }

  mesh.labels.resize(mesh.triangles.size());
  for(std::size_t f = 0; f < mesh.triangles.size(); ++f)
    mesh.labels[f] = shape.label_at(mesh.centroid(f));
  return mesh;
}

// ---------------------------------------------------------------------------------------------
// Shapes. Seed 0 gives the canonical shape; other seeds jitter sizes and positions by a few
// percent (the part structure stays the same).

namespace procedural_detail {
inline double jitter(Procedural_random& rng, std::uint64_t seed, double amplitude)
{
  return seed == 0 ? 1.0 : 1.0 + rng.uniform(-amplitude, amplitude);
}
} // namespace procedural_detail

// Three overlapping spheres on the x axis (labels 0, 1, 2 from left to right), the middle one
// smaller: two concave creases. Cell size 0.2: about 6200 faces; 0.25: about 3900.
inline Procedural_shape three_sphere_chain(std::uint64_t seed = 0)
{
  Procedural_random rng(seed);
  using procedural_detail::jitter;
  Procedural_shape s;
  const double r0 = 1.0 * jitter(rng, seed, 0.08), r1 = 0.8 * jitter(rng, seed, 0.08),
               r2 = 0.95 * jitter(rng, seed, 0.08);
  s.add(Shape_primitive::sphere(Vector_3d(-1.45, 0, 0), r0, 0));
  s.add(Shape_primitive::sphere(Vector_3d(0, 0.05 * (jitter(rng, seed, 1) - 1), 0), r1, 1));
  s.add(Shape_primitive::sphere(Vector_3d(1.4, 0, 0), r2, 2));
  return s;
}

// A four-legged body: a capsule torso along x (label 0) and four capsule legs pointing down and
// slightly outwards (labels 1..4), plus a spherical head (label 5) when `with_head`. Legs have
// radius 0.2: use cells of at most 0.15 (about 6800 faces; 0.14: about 7800).
inline Procedural_shape body_with_limbs(std::uint64_t seed = 0, bool with_head = false)
{
  Procedural_random rng(seed);
  using procedural_detail::jitter;
  Procedural_shape s;
  const double torso_radius = 0.55 * jitter(rng, seed, 0.06);
  s.add(Shape_primitive::capsule(Vector_3d(-1.1, 0, 0), Vector_3d(1.1, 0, 0), torso_radius, 0));
  std::size_t label = 1;
  for(int sx = -1; sx <= 1; sx += 2)
    for(int sy = -1; sy <= 1; sy += 2) {
      const double length = 1.5 * jitter(rng, seed, 0.08);
      const double radius = 0.2 * jitter(rng, seed, 0.08);
      const Vector_3d top(0.8 * sx, 0.25 * sy, -0.1);
      const Vector_3d foot(0.95 * sx, 0.45 * sy, -0.1 - length);
      s.add(Shape_primitive::capsule(top, foot, radius, label++));
    }
  if(with_head)
    s.add(Shape_primitive::sphere(Vector_3d(1.85, 0, 0.45), 0.5 * jitter(rng, seed, 0.06), label++));
  return s;
}

// A star: a central sphere (label 0) with `arms` capsule arms (labels 1..arms) along directions
// spread over the sphere (the 6 axis directions first). Arms have radius 0.25: cell size 0.16
// gives about 5000 faces for 6 arms.
inline Procedural_shape star(std::size_t arms = 6, std::uint64_t seed = 0)
{
  Procedural_random rng(seed);
  using procedural_detail::jitter;
  Procedural_shape s;
  s.add(Shape_primitive::sphere(Vector_3d(0, 0, 0), 0.8 * jitter(rng, seed, 0.05), 0));
  for(std::size_t i = 0; i < arms; ++i) {
    Vector_3d d;
    if(i < 6) {
      d[int(i / 2)] = (i % 2 == 0) ? 1.0 : -1.0;
    } else { // golden-angle spiral for more arms
      const double z = 1.0 - 2.0 * (double(i - 6) + 0.5) / double(arms - 6);
      const double phi = 2.399963229728653 * double(i - 6);
      const double r = std::sqrt((std::max)(0.0, 1.0 - z * z));
      d = Vector_3d(r * std::cos(phi), r * std::sin(phi), z);
    }
    const double length = 1.7 * jitter(rng, seed, 0.08);
    s.add(Shape_primitive::capsule(d * 0.3, d * length, 0.25 * jitter(rng, seed, 0.08), i + 1));
  }
  return s;
}

// `n` separate rounded boxes on the x axis (label i for box i), each larger than the previous
// one, `gap` apart: `n` connected components (keep `gap` above 2 cells so that the boxes stay
// apart). Four boxes, cell size 0.2: about 3700 faces.
inline Procedural_shape separate_boxes(std::size_t n, double gap = 1.0, std::uint64_t seed = 0)
{
  Procedural_random rng(seed);
  using procedural_detail::jitter;
  Procedural_shape s;
  double x = 0;
  for(std::size_t i = 0; i < n; ++i) {
    const double scale = (1.0 + 0.12 * double(i)) * jitter(rng, seed, 0.03);
    const Vector_3d half(0.5 * scale, 0.4 * scale, 0.3 * scale);
    s.add(Shape_primitive::box(Vector_3d(x + half.x, 0, 0), half, i, 0.08));
    x += 2 * half.x + gap;
  }
  return s;
}

// A flat square [-0.5, 0.5] x [-0.5, 0.5] at z = 0 of n x n cells, two triangles a cell (each cut
// along the same diagonal), one label: an open surface whose symmetry planes (x = 0, y = 0 and
// the diagonals) only its border tells apart, and whose turns within its plane the surface alone
// does not show.
inline Labelled_triangle_mesh flat_square(std::size_t n)
{
  Labelled_triangle_mesh m;
  for(std::size_t j = 0; j <= n; ++j)
    for(std::size_t i = 0; i <= n; ++i)
      m.points.push_back({{double(i) / double(n) - 0.5, double(j) / double(n) - 0.5, 0.0}});
  for(std::size_t j = 0; j < n; ++j)
    for(std::size_t i = 0; i < n; ++i) {
      const std::size_t a = j * (n + 1) + i;
      m.triangles.push_back({{a, a + 1, a + n + 2}});
      m.triangles.push_back({{a, a + n + 2, a + n + 1}});
    }
  m.labels.assign(m.triangles.size(), 0);
  m.number_of_labels = 1;
  return m;
}

// ---------------------------------------------------------------------------------------------
// Utilities

// x -> R x + t with R a rotation (rows of `rotation`).
struct Rigid_transform
{
  std::array<Vector_3d, 3> rotation{{Vector_3d(1, 0, 0), Vector_3d(0, 1, 0), Vector_3d(0, 0, 1)}};
  Vector_3d translation;

  // Rotation by `angle` (radians) about `axis` (any non-zero length), then translation.
  static Rigid_transform from_axis_angle(const Vector_3d& axis, double angle,
                                         const Vector_3d& translation)
  {
    const Vector_3d u = axis / axis.length();
    const double c = std::cos(angle), s = std::sin(angle), t = 1 - c;
    Rigid_transform r;
    r.rotation[0] = Vector_3d(t * u.x * u.x + c, t * u.x * u.y - s * u.z, t * u.x * u.z + s * u.y);
    r.rotation[1] = Vector_3d(t * u.x * u.y + s * u.z, t * u.y * u.y + c, t * u.y * u.z - s * u.x);
    r.rotation[2] = Vector_3d(t * u.x * u.z - s * u.y, t * u.y * u.z + s * u.x, t * u.z * u.z + c);
    r.translation = translation;
    return r;
  }

  Vector_3d operator()(const Vector_3d& p) const
  {
    return Vector_3d(dot(rotation[0], p), dot(rotation[1], p), dot(rotation[2], p)) + translation;
  }
};

// Applies `transform` to every point of `mesh`.
inline void transform_points(Labelled_triangle_mesh& mesh, const Rigid_transform& transform)
{
  for(auto& p : mesh.points) {
    const Vector_3d q = transform(Vector_3d(p[0], p[1], p[2]));
    p = {q.x, q.y, q.z};
  }
}

// Shuffles the triangles (and their labels) with a seed; with `rotate_corners`, also rotates the
// corners of each triangle (same orientation, another first corner). Returns the permutation:
// new triangle i is old triangle result[i].
inline std::vector<std::size_t> shuffle_faces(Labelled_triangle_mesh& mesh, std::uint64_t seed,
                                              bool rotate_corners = false)
{
  Procedural_random rng(seed);
  const std::size_t n = mesh.triangles.size();
  std::vector<std::size_t> order(n);
  std::iota(order.begin(), order.end(), std::size_t(0));
  for(std::size_t i = n; i > 1; --i)
    std::swap(order[i - 1], order[rng.index(i)]);
  std::vector<std::array<std::size_t, 3>> triangles(n);
  std::vector<std::size_t> labels(n);
  for(std::size_t i = 0; i < n; ++i) {
    std::array<std::size_t, 3> t = mesh.triangles[order[i]];
    if(rotate_corners)
      std::rotate(t.begin(), t.begin() + std::ptrdiff_t(rng.index(3)), t.end());
    triangles[i] = t;
    labels[i] = mesh.labels[order[i]];
  }
  mesh.triangles.swap(triangles);
  mesh.labels.swap(labels);
  return order;
}

// Copies `mesh` into the (empty or not) `PolygonMesh` through its vertex point map. Returns the
// new faces in triangle order; throws std::runtime_error if a face cannot be added.
template <typename PolygonMesh>
std::vector<typename boost::graph_traits<PolygonMesh>::face_descriptor>
fill_polygon_mesh(const Labelled_triangle_mesh& mesh, PolygonMesh& pm)
{
  typedef boost::graph_traits<PolygonMesh> GT;
  typedef typename GT::vertex_descriptor vertex_descriptor;
  typedef typename GT::face_descriptor face_descriptor;
  auto vpm = get(CGAL::vertex_point, pm);
  typedef typename boost::property_traits<decltype(vpm)>::value_type Point;
  std::vector<vertex_descriptor> vertices;
  vertices.reserve(mesh.points.size());
  for(const auto& p : mesh.points) {
    const vertex_descriptor v = add_vertex(pm);
    put(vpm, v, Point(p[0], p[1], p[2]));
    vertices.push_back(v);
  }
  std::vector<face_descriptor> faces_out;
  faces_out.reserve(mesh.triangles.size());
  std::vector<vertex_descriptor> corners(3);
  for(const auto& t : mesh.triangles) {
    for(int i = 0; i < 3; ++i)
      corners[std::size_t(i)] = vertices[t[std::size_t(i)]];
    const face_descriptor f = CGAL::Euler::add_face(corners, pm);
    if(f == GT::null_face())
      throw std::runtime_error("fill_polygon_mesh: a triangle could not be added");
    faces_out.push_back(f);
  }
  return faces_out;
}

// Number of connected components of the triangles (through shared edges).
inline std::size_t number_of_components(const Labelled_triangle_mesh& mesh,
                                        std::vector<std::size_t>* component = nullptr)
{
  const std::size_t n = mesh.triangles.size();
  std::vector<std::size_t> parent(n);
  std::iota(parent.begin(), parent.end(), std::size_t(0));
  auto find = [&](std::size_t x) {
    while(parent[x] != x) {
      parent[x] = parent[parent[x]];
      x = parent[x];
    }
    return x;
  };
  std::map<std::pair<std::size_t, std::size_t>, std::size_t> edge_face;
  for(std::size_t f = 0; f < n; ++f)
    for(int i = 0; i < 3; ++i) {
      std::size_t a = mesh.triangles[f][std::size_t(i)], b = mesh.triangles[f][std::size_t((i + 1) % 3)];
      if(a > b)
        std::swap(a, b);
      auto it = edge_face.emplace(std::make_pair(a, b), f);
      if(!it.second)
        parent[find(f)] = find(it.first->second);
    }
  std::vector<std::size_t> dense(n, n), result(n);
  std::size_t count = 0;
  for(std::size_t f = 0; f < n; ++f) {
    const std::size_t r = find(f);
    if(dense[r] == n)
      dense[r] = count++;
    result[f] = dense[r];
  }
  if(component != nullptr)
    component->swap(result);
  return count;
}

} // namespace Shape_analysis_support
} // namespace CGAL

#endif // SHAPE_ANALYSIS_SUPPORT_PROCEDURAL_SHAPES_H
