// Copyright (c) 2026 CGAL Global Shape Analysis contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_SURFACE_MESH_SYMMETRIZATION_INTERNAL_ISOMETRIC_REFINEMENT_H
#define CGAL_SURFACE_MESH_SYMMETRIZATION_INTERNAL_ISOMETRIC_REFINEMENT_H

// The linear system of one step of the isometric refinement (Symmetrizer::refine_step()), over
// three unknowns per active vertex, and the active vertices of the local refinement of meshes
// too large for the whole one.

#include <CGAL/Surface_mesh_symmetrization/internal/Mirror_points.h>
#include <CGAL/Surface_mesh_symmetrization/internal/Symmetrization_levels.h>

#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numeric>
#include <vector>

namespace CGAL {
namespace Surface_mesh_symmetrization {
namespace internal {

// The weights of the terms of a refinement step (see Symmetrizer::refine_step()).
struct Refinement_weights
{
  double error = 0;             // rho / (n D^2)
  double edge = 0;              // 1 / |E|
  double eta = 0.01;            // of the change of the edge vectors
  double displacement = 0;      // mu / (n h^2)
  double mean_edge = 0;         // h
  double tangential_weight = 0; // the smallest tau
};

class Refinement_system
{
public:
  typedef Eigen::SparseMatrix<double> Sparse;
  typedef Eigen::SimplicialLDLT<Sparse> LDLT;
  typedef Eigen::Triplet<double> Triplet;
  static constexpr std::uint32_t none = Surface_index::no_face;

  // `unknown`: per vertex, the position of its unknowns among those of the active vertices, or
  // `none` for a vertex that stays (its terms are constants).
  Refinement_system(const std::vector<std::uint32_t>& unknown, const Refinement_weights& c)
    : m_unknown(unknown), m_c(c)
  {
    for(std::uint32_t u : unknown)
      if(u != none)
        m_count = (std::max)(m_count, std::size_t(u) + 1);
    m_rhs = Eigen::VectorXd::Zero(Eigen::Index(3 * m_count));
  }

  void reserve(std::size_t number_of_symmetries, const Level& level)
  {
    std::size_t active_edges = 0;
    for(const auto& e : level.edges)
      active_edges += m_unknown[e.first] != none || m_unknown[e.second] != none ? 1 : 0;
    m_triplets.reserve(16 * 9 * m_count * number_of_symmetries + 36 * active_edges + 3 * m_count);
  }

  // The symmetry terms of symmetry k (inverse `inv`, weights of `level`), at positions `x` whose
  // face normals are `fnormals`.
  void add_mirror_terms(const Level& level, const std::vector<Mirror>& mirrors, std::size_t k, const Affine_3d& inv,
                        const std::vector<Vector_3d>& x, const std::vector<Vector_3d>& fnormals)
  {
    const std::vector<std::uint32_t>& unknown = m_unknown;
    const Matrix_3d L = inv.linear, Lt = SAI::transpose(L);
    for(std::size_t i = 0; i < x.size(); ++i) {
      const Mirror& m = mirrors[i];
      const double c = m_c.error * vertex_weight(level, k, i);
      if(!m.found || !(c > 0))
        continue;
      const auto& f = level.original.triangles[m.face];
      if(unknown[i] == none && unknown[f[0]] == none && unknown[f[1]] == none && unknown[f[2]] == none)
        continue;
      const Vector_3d p = x[f[0]] * m.barycentric[0] + x[f[1]] * m.barycentric[1] + x[f[2]] * m.barycentric[2];
      const Vector_3d r = inv(x[i]) - p;
      // The metric of the residual: its part along the normal of the mirror face, and tau of
      // its tangential part. A small residual is a distance to the tangent plane (the mirror
      // point may slide along the surface); one of an edge's length or more is a distance to
      // the point, whose tangent plane says little so far away.
      const Vector_3d& nf = fnormals[m.face];
      const double tau = (std::min)(1.0, (std::max)(m_c.tangential_weight, r.length() / m_c.mean_edge));
      Matrix_3d M;
      for(int a = 0; a < 3; ++a)
        for(int b = 0; b < 3; ++b)
          M[std::size_t(a)][b] = (1 - tau) * nf[a] * nf[b] + (a == b ? tau : 0.0);
      const Matrix_3d LtM = SAI::multiply(Lt, M), ML = SAI::multiply(M, L), LtML = SAI::multiply(LtM, L);
      block(i, i, LtML, c);
      const Vector_3d Mr = SAI::multiply(M, r), LtMr = SAI::multiply(Lt, Mr);
      for(int a = 0; a < 3; ++a)
        add_rhs(i, a, -c * LtMr[a]);
      for(int u = 0; u < 3; ++u) {
        const double bu = m.barycentric[std::size_t(u)];
        block(i, f[std::size_t(u)], LtM, -c * bu);
        block(f[std::size_t(u)], i, ML, -c * bu);
        for(int a = 0; a < 3; ++a)
          add_rhs(f[std::size_t(u)], a, c * bu * Mr[a]);
        for(int v = 0; v < 3; ++v)
          block(f[std::size_t(u)], f[std::size_t(v)], M, c * bu * m.barycentric[std::size_t(v)]);
      }
    }
  }

  // The terms of the relative change of the edge lengths (and eta of the edge vectors).
  void add_edge_terms(const Level& level, const std::vector<Vector_3d>& x)
  {
    const double a_edge = m_c.edge, eta = m_c.eta;
    for(const auto& e : level.edges) {
      if(m_unknown[e.first] == none && m_unknown[e.second] == none)
        continue;
      const Vector_3d d = x[e.first] - x[e.second];
      const double l = d.length();
      const double l0 = (level.original.points[e.first] - level.original.points[e.second]).length();
      if(!(l > 0) || !(l0 > 0))
        continue;
      const Vector_3d g = d / (l * l0);
      const double r = (l - l0) / l0;
      Matrix_3d G;
      for(int a = 0; a < 3; ++a)
        for(int b = 0; b < 3; ++b)
          G[std::size_t(a)][b] = g[a] * g[b] + (a == b ? eta / (l0 * l0) : 0.0);
      block(e.first, e.first, G, a_edge);
      block(e.second, e.second, G, a_edge);
      block(e.first, e.second, G, -a_edge);
      block(e.second, e.first, G, -a_edge);
      for(int a = 0; a < 3; ++a) {
        add_rhs(e.first, a, -a_edge * g[a] * r);
        add_rhs(e.second, a, a_edge * g[a] * r);
      }
    }
  }

  // Adds the displacement term, solves (LDL^T) and moves the active vertices of `x`; `x` is
  // left as it is when the factorization fails.
  void solve(std::vector<Vector_3d>& x)
  {
    for(std::size_t i = 0; i < 3 * m_count; ++i)
      m_triplets.emplace_back(Eigen::Index(i), Eigen::Index(i), m_c.displacement);
    Sparse A(static_cast<Eigen::Index>(3 * m_count), static_cast<Eigen::Index>(3 * m_count));
    A.setFromTriplets(m_triplets.begin(), m_triplets.end());
    LDLT ldlt(A);
    if(ldlt.info() != Eigen::Success)
      return;
    const Eigen::VectorXd delta = ldlt.solve(m_rhs);
    for(std::size_t i = 0; i < x.size(); ++i) {
      if(m_unknown[i] == none)
        continue;
      for(int a = 0; a < 3; ++a) {
        const double v = delta(Eigen::Index(3 * std::size_t(m_unknown[i]) + std::size_t(a)));
        if(std::isfinite(v))
          x[i][a] += v;
      }
    }
  }

private:
  void block(std::size_t u, std::size_t v, const Matrix_3d& m, double c)
  {
    const std::uint32_t iu = m_unknown[u], iv = m_unknown[v];
    if(iu == none || iv == none)
      return;
    for(int a = 0; a < 3; ++a)
      for(int b = 0; b < 3; ++b)
        if(m[std::size_t(a)][b] != 0)
          m_triplets.emplace_back(Eigen::Index(3 * std::size_t(iu) + std::size_t(a)),
                                  Eigen::Index(3 * std::size_t(iv) + std::size_t(b)), c * m[std::size_t(a)][b]);
  }

  void add_rhs(std::size_t u, int a, double value)
  {
    if(m_unknown[u] != none)
      m_rhs(Eigen::Index(3 * std::size_t(m_unknown[u]) + std::size_t(a))) += value;
  }

  const std::vector<std::uint32_t>& m_unknown;
  Refinement_weights m_c;
  std::size_t m_count = 0; // active vertices
  std::vector<Triplet> m_triplets;
  Eigen::VectorXd m_rhs;
};

// The neighbours of every vertex of a level, as compressed rows: those of vertex v are
// `list[first[v]]` to `list[first[v + 1] - 1]`.
struct Vertex_neighbours
{
  std::vector<std::size_t> first;
  std::vector<std::uint32_t> list;

  explicit Vertex_neighbours(const Level& level)
  {
    const std::size_t n = level.original.number_of_vertices();
    first.assign(n + 1, 0);
    for(const auto& e : level.edges)
      ++first[e.first + 1], ++first[e.second + 1];
    for(std::size_t i = 0; i < n; ++i)
      first[i + 1] += first[i];
    list.resize(first[n]);
    std::vector<std::size_t> fill(first.begin(), first.end() - 1);
    for(const auto& e : level.edges)
      list[fill[e.first]++] = e.second, list[fill[e.second]++] = e.first;
  }
};

// The unknowns of a step of the local refinement (as Refinement_system takes them): the vertices
// whose mirror distance is above `threshold` (of a positive weight), the corners of their mirror
// faces and `rings` rings of neighbours around them. Empty when no vertex is above the threshold.
inline std::vector<std::uint32_t> local_unknowns(const Level& level, const Vertex_neighbours& neighbours,
                                                 const std::vector<std::vector<Mirror>>& mirrors,
                                                 double threshold, std::size_t rings)
{
  const std::size_t n = level.original.number_of_vertices();
  std::vector<char> on(n, 0);
  std::vector<std::uint32_t> front;
  for(std::size_t k = 0; k < mirrors.size(); ++k)
    for(std::size_t i = 0; i < n; ++i) {
      const Mirror& m = mirrors[k][i];
      if(!m.found || !(m.distance > threshold) || !(vertex_weight(level, k, i) > 0))
        continue;
      for(std::uint32_t v : {std::uint32_t(i), level.original.triangles[m.face][0],
                             level.original.triangles[m.face][1], level.original.triangles[m.face][2]})
        if(!on[v]) {
          on[v] = 1;
          front.push_back(v);
        }
    }
  if(front.empty())
    return {};
  for(std::size_t ring = 0; ring < rings; ++ring) {
    std::vector<std::uint32_t> next;
    for(std::uint32_t v : front)
      for(std::size_t q = neighbours.first[v]; q < neighbours.first[v + 1]; ++q)
        if(!on[neighbours.list[q]]) {
          on[neighbours.list[q]] = 1;
          next.push_back(neighbours.list[q]);
        }
    front.swap(next);
  }
  std::vector<std::uint32_t> unknown(n, Refinement_system::none);
  std::uint32_t count = 0;
  for(std::size_t i = 0; i < n; ++i)
    if(on[i])
      unknown[i] = count++;
  return unknown;
}

} // namespace internal
} // namespace Surface_mesh_symmetrization
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_SYMMETRIZATION_INTERNAL_ISOMETRIC_REFINEMENT_H
