// Copyright (c) 2026 CGAL Global Shape Analysis contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef SHAPE_ANALYSIS_SUPPORT_PROCEDURAL_SYMMETRIC_SHAPES_H
#define SHAPE_ANALYSIS_SUPPORT_PROCEDURAL_SYMMETRIC_SHAPES_H

// Procedural shapes with known symmetries, for tests, benchmarks and examples (deterministic,
// plain arrays):
//   - a "blob": a closed surface of latitude-longitude connectivity, an ellipsoid with bumps,
//     exactly symmetric under the reflection y -> -y, with a connectivity that is symmetric too
//     (the diagonals of the quads are mirrored), so that an exactly symmetric mesh exists near any
//     warped copy; optionally also symmetric under the rotation by pi about the z axis;
//   - a smooth asymmetric warp of space, to make nearly symmetric copies.

#include <CGAL/Shape_analysis/internal/Vector_3d.h>

#include <array>
#include <cmath>
#include <cstddef>
#include <vector>

namespace CGAL {
namespace Shape_analysis_support {

struct Procedural_mesh
{
  std::vector<std::array<double, 3>> points;
  std::vector<std::array<std::size_t, 3>> triangles;
};

// A latitude-longitude mesh: the poles position(0, 0) and position(pi, 0), then `rings` - 1 rings
// of `sectors` points position(theta, phi); the quad of ring i and sector j is split along its
// diagonal from (i, j) to (i + 1, j + 1) when `forward(j)`, along the other one otherwise.
template <typename Position, typename Forward>
Procedural_mesh latitude_longitude_mesh(std::size_t rings, std::size_t sectors, const Position& position,
                                        const Forward& forward)
{
  const double pi = 3.14159265358979323846;
  Procedural_mesh m;
  m.points.push_back(position(0, 0));  // north pole
  m.points.push_back(position(pi, 0)); // south pole
  for(std::size_t i = 1; i < rings; ++i)
    for(std::size_t j = 0; j < sectors; ++j)
      m.points.push_back(position(pi * double(i) / double(rings), 2 * pi * double(j) / double(sectors)));
  const auto id = [&](std::size_t i, std::size_t j) { return 2 + (i - 1) * sectors + (j % sectors); };
  for(std::size_t j = 0; j < sectors; ++j)
    m.triangles.push_back({{0, id(1, j), id(1, j + 1)}});
  for(std::size_t i = 1; i + 1 < rings; ++i)
    for(std::size_t j = 0; j < sectors; ++j) {
      if(forward(j)) {
        m.triangles.push_back({{id(i, j), id(i + 1, j), id(i + 1, j + 1)}});
        m.triangles.push_back({{id(i, j), id(i + 1, j + 1), id(i, j + 1)}});
      } else {
        m.triangles.push_back({{id(i, j), id(i + 1, j), id(i, j + 1)}});
        m.triangles.push_back({{id(i, j + 1), id(i + 1, j), id(i + 1, j + 1)}});
      }
    }
  for(std::size_t j = 0; j < sectors; ++j)
    m.triangles.push_back({{1, id(rings - 1, j + 1), id(rings - 1, j)}});
  return m;
}

// The blob with `rings` latitude rings (>= 3) of `sectors` vertices (even, >= 4): about
// rings * sectors vertices. Symmetric under y -> -y; with `rotational`, the bumps come in pairs
// so that the rotation by pi about the z axis is a symmetry too (and the reflection y -> -y
// remains one).
inline Procedural_mesh symmetric_blob(std::size_t rings, std::size_t sectors, bool rotational = false)
{
  typedef CGAL::Shape_analysis::internal::Vector_3d V;
  const auto bump = [](const V& p, const V& c, double height, double width) {
    return height * std::exp(-(p - c).squared_length() * width);
  };
  const auto position = [&](double theta, double phi) {
    const V u(std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta));
    double r = 1 + bump(u, V(0.8, 0, 0.5), 0.25, 6.0);
    // A pair of mirrored bumps (y and -y).
    r += bump(u, V(-0.4, 0.7, 0.1), 0.18, 8.0) + bump(u, V(-0.4, -0.7, 0.1), 0.18, 8.0);
    if(rotational) // the images of the bumps under the rotation by pi about z
      r += bump(u, V(-0.8, 0, 0.5), 0.25, 6.0) + bump(u, V(0.4, -0.7, 0.1), 0.18, 8.0) +
           bump(u, V(0.4, 0.7, 0.1), 0.18, 8.0);
    return std::array<double, 3>{{1.6 * r * u.x, r * u.y, 0.8 * r * u.z}};
  };
  // Sector j lies at angles [j, j+1] 2 pi / sectors; its mirror image under y -> -y is sector
  // sectors - 1 - j: the diagonals are chosen so that they mirror each other.
  return latitude_longitude_mesh(rings, sectors, position, [&](std::size_t j) { return j < sectors / 2; });
}

// A closed surface turned k times onto itself about the z axis (k-fold rotational symmetry;
// k = 0: a surface of revolution), with no other rotational symmetry: `k` lobes around the axis,
// a top unlike the bottom, and a twist so that no plane through the axis mirrors it (for k >= 1).
// Latitude-longitude connectivity of `rings` rings (>= 3) of `sectors` vertices (>= 3); choose
// `sectors` not a multiple of k for a tessellation that is not itself symmetric.
inline Procedural_mesh rotational_blob(std::size_t k, std::size_t rings, std::size_t sectors)
{
  const auto position = [&](double theta, double phi) {
    const double s = std::sin(theta), c = std::cos(theta);
    double r = 1 + 0.25 * c + 0.15 * std::cos(2 * theta);
    if(k > 0) // lobes, twisted with the height, with a second harmonic to break their mirror planes
      r += s * s * (0.3 * std::cos(double(k) * (phi + 0.6 * c)) + 0.1 * std::sin(2.0 * double(k) * phi));
    return std::array<double, 3>{{r * s * std::cos(phi), r * s * std::sin(phi), 1.3 * r * c}};
  };
  return latitude_longitude_mesh(rings, sectors, position, [](std::size_t) { return true; });
}

// A smooth asymmetric warp of amplitude `a` (a displacement of at most about 1.5 a): a sideways
// bend, a shear and a twist, none of them symmetric under y -> -y.
inline std::array<double, 3> asymmetric_warp(const std::array<double, 3>& p, double a)
{
  const double x = p[0], y = p[1], z = p[2];
  return {{x + 0.3 * a * std::sin(1.1 * z + 0.4), y + a * std::sin(1.3 * x + 0.7) + 0.5 * a * x * z,
           z + 0.5 * a * std::cos(2 * y + x)}};
}

} // namespace Shape_analysis_support
} // namespace CGAL

#endif // SHAPE_ANALYSIS_SUPPORT_PROCEDURAL_SYMMETRIC_SHAPES_H
