// Copyright (c) 2026 CGAL Global Shape Analysis contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_SURFACE_MESH_SYMMETRIZATION_INTERNAL_MIRROR_POINTS_H
#define CGAL_SURFACE_MESH_SYMMETRIZATION_INTERNAL_MIRROR_POINTS_H

// The symmetric map on plain arrays: the mirror point of every vertex for every symmetry (the
// closest point of the surface, with a compatible normal, to the vertex's preimage), found
// exactly or tracked from previous ones as the surface moves, and the RMS of their distances, the
// symmetry error.

#include <CGAL/Shape_analysis/internal/Parallel.h>
#include <CGAL/Surface_mesh_symmetrization/internal/Surface_index.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Surface_mesh_symmetrization {
namespace internal {

// The mirror point of a vertex for one symmetry.
struct Mirror
{
  std::uint32_t face = 0;
  std::array<double, 3> barycentric{{1, 0, 0}};
  double distance = 0; // from T^-1(x_i) to the mirror point
  bool found = false;
};

// The weighted RMS of the mirror distances of `mirrors` (weights: per symmetry and vertex, empty
// for 1), over the vertices that have a mirror point (a vertex without faces has none).
inline double rms_mirror_distance(const std::vector<std::vector<Mirror>>& mirrors,
                                  const std::vector<std::vector<double>>& weights)
{
  double sum = 0, w_sum = 0;
  for(std::size_t k = 0; k < mirrors.size(); ++k)
    for(std::size_t i = 0; i < mirrors[k].size(); ++i) {
      const double w = weights[k].empty() ? 1.0 : weights[k][i];
      if(!mirrors[k][i].found || !(w > 0))
        continue;
      sum += w * mirrors[k][i].distance * mirrors[k][i].distance;
      w_sum += w;
    }
  return w_sum > 0 ? std::sqrt(sum / w_sum) : 0.0;
}

// Mirror points of every vertex of `s` for every symmetry; `exact`: closest points through the
// closest-point hierarchy (otherwise the faster local search, exact on smooth regions). `hints`:
// mirror points of nearby positions (the previous step's), which speed the exact search up.
inline std::vector<std::vector<Mirror>>
mirror_points(const Surface& s, const Surface_index& index, const std::vector<Affine_3d>& inverses,
              bool exact, std::size_t threads, const std::vector<std::vector<Mirror>>* hints = nullptr)
{
  const std::size_t n = s.number_of_vertices();
  const std::vector<Vector_3d> normals = s.vertex_normals();
  std::vector<std::vector<Mirror>> result(inverses.size(), std::vector<Mirror>(n));
  SAI::Parallel_workspaces<std::vector<std::pair<double, std::uint32_t>>> parallel(threads);
  const std::size_t block = 512;
  // Nearby vertices one after the other when `s` is the surface of the index.
  const bool ordered = index.vertex_order().size() == n;
  for(std::size_t k = 0; k < inverses.size(); ++k) {
    const Affine_3d& inv = inverses[k];
    const Matrix_3d nm = inv.normal_matrix();
    parallel.for_each(0, (n + block - 1) / block, [&](std::size_t b, std::vector<std::pair<double, std::uint32_t>>& buffer) {
      for(std::size_t o = b * block; o < (std::min)(n, (b + 1) * block); ++o) {
        const std::size_t i = ordered ? index.vertex_order()[o] : o;
        if(!(normals[i].squared_length() > 0))
          continue; // no face: no mirror point
        const Vector_3d q = inv(s.points[i]);
        const Vector_3d m = inv.transform_normal(normals[i], nm);
        const std::uint32_t hint = hints != nullptr && (*hints)[k][i].found ? (*hints)[k][i].face : Surface_index::no_face;
        const Surface_point c = exact ? index.closest_compatible(q, m, 0.0, hint)
                                      : index.approximate_closest_compatible(q, m, 0.0,
                                                                             std::numeric_limits<double>::infinity(), buffer);
        Mirror& r = result[k][i];
        if(!c.found)
          continue;
        r.found = true;
        r.face = c.face;
        r.barycentric = c.barycentric;
        r.distance = std::sqrt(c.squared_distance);
      }
    });
  }
  return result;
}

// The exact mirror points of every vertex of `s` (a closest-point tree built for it).
inline std::vector<std::vector<Mirror>> exact_mirror_points(const Surface& s, const std::vector<Affine_3d>& inverses,
                                                            std::size_t threads,
                                                            const std::vector<std::vector<Mirror>>* hints = nullptr)
{
  const Surface_index index(s);
  return mirror_points(s, index, inverses, true, threads, hints);
}

// The mirror points of positions `x` found from `previous` ones (same connectivity, slightly
// moved): from each previous mirror face, a descent to edge-adjacent faces whose normal is
// compatible while the distance to the vertex's transformed position decreases. A few
// triangles per vertex, no tree; the result is a local minimum next to the previous mirror
// point. The vertices that had one keep one (even if its face turned incompatible), so that
// the weights, hence the matrix and its factorization, stay those of the last exact search.
// `adjacent`: per face, the faces across its edges (face_adjacency()).
inline std::vector<std::vector<Mirror>>
track_mirrors(const Surface& current, const std::vector<std::array<std::uint32_t, 3>>& adjacent,
              const std::vector<Affine_3d>& inverses, const std::vector<std::vector<Mirror>>& previous,
              std::size_t threads)
{
  const std::size_t n = current.number_of_vertices();
  const std::vector<Vector_3d>& x = current.points;
  const std::vector<Vector_3d> vn = current.vertex_normals();
  const std::vector<Vector_3d> fn = current.face_normals();
  std::vector<std::vector<Mirror>> result(previous.size(), std::vector<Mirror>(n));
  SAI::Parallel_workspaces<char> parallel(threads);
  const std::size_t block = 1024;
  for(std::size_t k = 0; k < previous.size(); ++k) {
    const Affine_3d& inv = inverses[k];
    const Matrix_3d nm = inv.normal_matrix();
    parallel.for_each(0, (n + block - 1) / block, [&](std::size_t b, char&) {
      for(std::size_t i = b * block; i < (std::min)(n, (b + 1) * block); ++i) {
        const Mirror& p = previous[k][i];
        if(!p.found || !(vn[i].squared_length() > 0))
          continue;
        const Vector_3d q = inv(x[i]);
        const Vector_3d m = inv.transform_normal(vn[i], nm);
        const auto on_face = [&](std::uint32_t f, std::array<double, 3>& bary) {
          const auto c = current.corners(f);
          return (closest_point_on_triangle(q, c[0], c[1], c[2], bary) - q).squared_length();
        };
        std::uint32_t face = p.face;
        std::array<double, 3> bary;
        double d2 = on_face(face, bary);
        for(int step = 0; step < 32; ++step) {
          const std::uint32_t at = face;
          for(std::size_t e = 0; e < 3; ++e) {
            const std::uint32_t g = adjacent[at][e];
            if(g == Surface_index::no_face || !(SAI::dot(fn[g], m) > 0))
              continue;
            std::array<double, 3> bg;
            const double dg = on_face(g, bg);
            if(dg < d2) {
              d2 = dg;
              face = g;
              bary = bg;
            }
          }
          if(face == at)
            break;
        }
        Mirror& r = result[k][i];
        r.found = true;
        r.face = face;
        r.barycentric = bary;
        r.distance = std::sqrt(d2);
      }
    });
  }
  return result;
}

} // namespace internal
} // namespace Surface_mesh_symmetrization
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_SYMMETRIZATION_INTERNAL_MIRROR_POINTS_H
