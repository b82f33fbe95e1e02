// Copyright (c) 2026 CGAL Global Shape Analysis contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_SURFACE_MESH_SYMMETRIZATION_INTERNAL_SYMMETRIZATION_STEP_H
#define CGAL_SURFACE_MESH_SYMMETRIZATION_INTERNAL_SYMMETRIZATION_STEP_H

// One step of the symmetrization's schedule: the sparse least-squares solve of
//   E = rho / n sum_k sum_i w_ik |x_i - q_ik|^2 + a_edge sum_edges |(x_i - x_j) - (r_i - r_j)|^2
//       + a_disp sum_i |x_i - x0_i|^2
// with fixed targets q_ik (see Symmetrization.h). The coordinates decouple and share one matrix,
// whose factorization is kept for the next step with the same level, weight and vertex weights.

#include <CGAL/Surface_mesh_symmetrization/internal/Mirror_points.h>
#include <CGAL/Surface_mesh_symmetrization/internal/Symmetrization_levels.h>

#include <Eigen/IterativeLinearSolvers>
#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

namespace CGAL {
namespace Surface_mesh_symmetrization {
namespace internal {

// The weights of the terms of one step.
struct Step_weights
{
  double rho = 0;          // alpha / (1 - alpha)
  double symmetry = 0;     // rho / n
  double edge = 0;         // of the shape term, per edge
  double displacement = 0; // beta / n
  double mean_edge = 0;    // h: mutual vertex pairs lie within h / 3
};

class Step_solver
{
public:
  typedef Eigen::SparseMatrix<double> Sparse;
  typedef Eigen::SimplicialLDLT<Sparse> LDLT;
  typedef Eigen::Triplet<double> Triplet;

  explicit Step_solver(std::size_t direct_solver_limit) : m_direct_solver_limit(direct_solver_limit) {}

  // One solve with fixed targets: every vertex is drawn toward the midpoint q_i = (y_i + T(p_i)) / 2
  // of its current position y_i and the image of its mirror point p_i (for every symmetry, with
  // its weight), E_sym = 1/n sum w |x_i - q_i|^2. The coordinates decouple and share one matrix.
  // `anchor_current`: the edge vectors are kept relative to the current positions (the constrained
  // steps: at a fixed point the shape term vanishes and x_i = q_i, i.e. the mirror points lie on
  // the surface); otherwise relative to the input.
  void solve(const Level& level, const std::vector<std::vector<Mirror>>& mirrors,
             const std::vector<Affine_3d>& transforms, const Step_weights& c, bool anchor_current,
             std::vector<Vector_3d>& x)
  {
    const std::size_t n = level.original.number_of_vertices();
    const std::vector<Vector_3d>& x0 = level.original.points;
    const std::vector<Vector_3d> y = x;
    std::vector<double> w(n, 0.0);
    std::vector<Vector_3d> wq(n); // sum of weight * target
    for(std::size_t k = 0; k < mirrors.size(); ++k)
      add_targets(level, mirrors[k], k, transforms[k], y, c, anchor_current, w, wq);
    std::vector<Vector_3d> b(n);
    for(const auto& e : level.edges) {
      const std::vector<Vector_3d>& ref = anchor_current ? y : x0;
      const Vector_3d d = ref[e.first] - ref[e.second];
      b[e.first] += d * c.edge;
      b[e.second] -= d * c.edge;
    }
    for(std::size_t i = 0; i < n; ++i)
      b[i] += wq[i] + x0[i] * c.displacement;
    factorize(level, c, w);
    const Factorization& F = m_factorization;
    for(int d = 0; d < 3; ++d) {
      Eigen::VectorXd rhs(static_cast<Eigen::Index>(n)), guess(static_cast<Eigen::Index>(n));
      for(std::size_t i = 0; i < n; ++i) {
        rhs(Eigen::Index(i)) = b[i][d];
        guess(Eigen::Index(i)) = y[i][d];
      }
      const Eigen::VectorXd sol = F.direct ? Eigen::VectorXd(F.ldlt.solve(rhs))
                                           : Eigen::VectorXd(F.cg.solveWithGuess(rhs, guess));
      for(std::size_t i = 0; i < n; ++i)
        if(std::isfinite(sol(Eigen::Index(i))))
          x[i][d] = sol(Eigen::Index(i));
    }
  }

private:
  // Per vertex, for mutual vertex pairs: the corner of its mirror face nearest to its mirror
  // point, when within a third of the mean edge length (otherwise none).
  static std::vector<std::uint32_t> nearest_corners(const Level& level, const std::vector<Mirror>& mirrors,
                                                    const std::vector<Vector_3d>& y, double h)
  {
    const std::size_t n = level.original.number_of_vertices();
    std::vector<std::uint32_t> nearest(n, Surface_index::no_face);
    for(std::size_t i = 0; i < n; ++i) {
      const Mirror& m = mirrors[i];
      if(!m.found)
        continue;
      const auto& f = level.original.triangles[m.face];
      const Vector_3d p = y[f[0]] * m.barycentric[0] + y[f[1]] * m.barycentric[1] + y[f[2]] * m.barycentric[2];
      std::size_t best = 0;
      double best_d = std::numeric_limits<double>::infinity();
      for(std::size_t c = 0; c < 3; ++c) {
        const double d = (y[f[c]] - p).squared_length();
        if(d < best_d) {
          best_d = d;
          best = c;
        }
      }
      if(best_d < h * h / 9)
        nearest[i] = f[best];
    }
    return nearest;
  }

  // Adds the weights and weighted targets of symmetry k to `w` and `wq`. `snap` (the constrained
  // steps): a mutual vertex pair (the corner of the mirror face nearest to the mirror point of i
  // is j, and that of j is i) takes the other vertex itself as mirror point.
  static void add_targets(const Level& level, const std::vector<Mirror>& mirrors, std::size_t k,
                          const Affine_3d& transform, const std::vector<Vector_3d>& y, const Step_weights& c,
                          bool snap, std::vector<double>& w, std::vector<Vector_3d>& wq)
  {
    const std::vector<std::uint32_t> nearest = nearest_corners(level, mirrors, y, c.mean_edge);
    for(std::size_t i = 0; i < y.size(); ++i) {
      const Mirror& m = mirrors[i];
      const double wi = c.symmetry * vertex_weight(level, k, i);
      if(!m.found || !(wi > 0))
        continue;
      const auto& f = level.original.triangles[m.face];
      Vector_3d p = y[f[0]] * m.barycentric[0] + y[f[1]] * m.barycentric[1] + y[f[2]] * m.barycentric[2];
      const std::uint32_t j = nearest[i];
      if(snap && j != Surface_index::no_face && nearest[j] == i)
        p = y[j];
      const Vector_3d q = (y[i] + transform(p)) * 0.5;
      w[i] += wi;
      wq[i] += q * wi;
    }
  }

  // The matrix only depends on the level, rho and the weights: its factorization is kept for the
  // next solve with the same ones (the constrained steps). Its pattern (edges and diagonal) only
  // depends on the level: the ordering and symbolic analysis are made once per level.
  void factorize(const Level& level, const Step_weights& c, const std::vector<double>& w)
  {
    const std::size_t n = w.size();
    Factorization& F = m_factorization;
    if(F.level == &level && F.ratio == c.rho && F.weights == w)
      return;
    std::vector<Triplet> tr;
    tr.reserve(4 * level.edges.size() + n);
    for(const auto& e : level.edges) {
      tr.emplace_back(Eigen::Index(e.first), Eigen::Index(e.first), c.edge);
      tr.emplace_back(Eigen::Index(e.second), Eigen::Index(e.second), c.edge);
      tr.emplace_back(Eigen::Index(e.first), Eigen::Index(e.second), -c.edge);
      tr.emplace_back(Eigen::Index(e.second), Eigen::Index(e.first), -c.edge);
    }
    for(std::size_t i = 0; i < n; ++i)
      tr.emplace_back(Eigen::Index(i), Eigen::Index(i), w[i] + c.displacement);
    // Kept with the factorization: the iterative solver refers to it.
    Sparse& A = F.matrix;
    A.resize(static_cast<Eigen::Index>(n), static_cast<Eigen::Index>(n));
    A.setFromTriplets(tr.begin(), tr.end());
    const bool analyzed = F.analyzed == &level;
    F.level = &level;
    F.ratio = c.rho;
    F.weights = w;
    F.direct = n <= m_direct_solver_limit;
    if(F.direct) {
      if(!analyzed) {
        F.ldlt.analyzePattern(A);
        F.analyzed = &level;
      }
      F.ldlt.factorize(A);
      F.direct = F.ldlt.info() == Eigen::Success;
    }
    if(!F.direct) {
      F.cg.setTolerance(1e-10);
      F.cg.setMaxIterations(1000);
      F.cg.compute(A);
    }
  }

  // The factorization of the last solve's matrix.
  struct Factorization
  {
    const Level* level = nullptr;
    const Level* analyzed = nullptr; // the level of the symbolic analysis
    double ratio = -1;
    std::vector<double> weights;
    bool direct = true;
    Sparse matrix;
    LDLT ldlt;
    Eigen::ConjugateGradient<Sparse, Eigen::Lower | Eigen::Upper, Eigen::IncompleteCholesky<double>> cg;
  };
  Factorization m_factorization;
  std::size_t m_direct_solver_limit;
};

} // namespace internal
} // namespace Surface_mesh_symmetrization
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_SYMMETRIZATION_INTERNAL_SYMMETRIZATION_STEP_H
