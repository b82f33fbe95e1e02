// Copyright (c) 2026 CGAL Global Shape Analysis contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_SURFACE_MESH_SYMMETRIZATION_INTERNAL_SYMMETRIZATION_H
#define CGAL_SURFACE_MESH_SYMMETRIZATION_INTERNAL_SYMMETRIZATION_H

// Symmetrization of a triangle surface (arrays) under one or several affine symmetries
// (Golovinskiy's thesis, section 2.4):
//   - correspondences: every vertex y_i of the current surface gets a mirror point p_i for each
//     symmetry T: the closest point of the surface, with a compatible normal, to T^-1(y_i)
//     (kept as a face and barycentric coordinates: the symmetric map);
//   - a sparse least-squares solve of
//       E = alpha E_sym + (1 - alpha) (E_shape + beta E_disp),
//       E_sym   = 1/n sum_k sum_i w_ik |x_i - q_ik|^2,  q_ik = (y_i + T_k(p_ik)) / 2
//       E_shape = (D / h)^2 / |E| sum_edges |(x_i - x_j) - (r_i - r_j)|^2 (edge vectors kept)
//       E_disp  = 1/n sum_i |x_i - x0_i|^2
//     (w: support weights; D the bounding-box diagonal and h the mean edge length of the input,
//     so that the terms weigh alike for a smooth deformation of the whole shape; x0 the input),
//     with alpha moved from 0 to 1 (alpha / (1 - alpha) from 0.1 to 10^4) and the
//     correspondences recomputed after each solve. The reference r of the edge vectors is the
//     input; in the last, constrained steps it is the current surface, so that the shape term
//     vanishes at convergence and every vertex reaches the midpoint of itself and its mirror
//     image, i.e. its mirror point lies on the surface. In those steps, two vertices whose mirror
//     points fall next to each other (mutually, within a third of an edge) are paired exactly, so
//     that a mesh whose connectivity is (nearly) symmetric becomes exactly symmetric;
//   - the coordinates share one matrix (the targets are fixed within a solve): one sparse
//     Cholesky factorization per step (Eigen's SimplicialLDLT), three solves;
//   - multiresolution: coarser levels made with CGAL's edge collapse (each with about 1/8 of the
//     vertices of the previous one) take the steps of the schedule first (the large-scale
//     asymmetry); each finer level is seeded by the displacements of the next coarser one,
//     interpolated at the closest points of its surface, then takes the last steps and, on the
//     input's resolution, the constrained ones;
//   - meshes too large for the isometric refinement (finest level above `refinement_limit`):
//     while the error is above the target, the constrained steps go on with a weight that starts
//     at the schedule's last one and grows tenfold whenever a step gains less than 10% (up to
//     `maximum_constrained_ratio`); between exact searches (every fourth step) the mirror points
//     are tracked from the previous ones by a local descent over adjacent faces (track_mirrors()),
//     a few triangles per vertex, and the matrix keeps its factorization;
//   - isometric refinement (finest level, while the error is above the target): linearized
//     steps that trade the symmetry error against the relative change of the edge lengths, all
//     three coordinates free (refine_step()), the weight of the error growing per step.

#include <CGAL/Surface_mesh_symmetrization/internal/Symmetry_geometry.h>

#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/Euler_operations.h>
#include <CGAL/Surface_mesh_simplification/edge_collapse.h>
#include <CGAL/Surface_mesh_simplification/Policies/Edge_collapse/Count_stop_predicate.h>
#include <CGAL/Surface_mesh_simplification/Policies/Edge_collapse/Edge_length_cost.h>
#include <CGAL/Surface_mesh_simplification/Policies/Edge_collapse/Midpoint_placement.h>

#include <Eigen/IterativeLinearSolvers>
#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <functional>
#include <limits>
#include <memory>
#include <numeric>
#include <vector>

namespace CGAL {
namespace Surface_mesh_symmetrization {
namespace internal {

// A symmetry as the solver sees it.
struct Solver_symmetry
{
  Affine_3d transform;
  std::vector<double> vertex_weight; // per vertex of the finest level, in [0, 1]; empty: 1
};

struct Symmetrization_options
{
  std::size_t number_of_iterations = 5;   // steps of alpha on the coarsest level
  double shape_weight = 1;                // factor of E_shape
  double displacement_weight = 0.01;      // beta
  std::size_t number_of_levels = 0;       // 0: automatic
  std::size_t coarsest_level_size = 20000; // vertices
  double symmetry_tolerance = 1e-6;       // relative to the diagonal: projection steps stop
  std::size_t projection_iterations = 8;  // most steps at alpha = 1 per level
  double stall_ratio = 0.95;              // projection steps stop when a step's error is above this times the previous one
  double constrained_ratio = 100;         // alpha / (1 - alpha) in the constrained steps (final_symmetry_weight)
  double schedule_exponent = 4;           // the schedule ends at alpha / (1 - alpha) = 10^this
  std::size_t direct_solver_limit = 2000000; // vertices
  std::size_t number_of_threads = 0;
  double target_error = 1e-4;             // relative to the diagonal: the refinement stops below it
  std::size_t refinement_steps = 14;      // most steps of the isometric refinement
  double refinement_ratio = 1e3;          // its first weight of the symmetry error against the edge lengths
  std::size_t refinement_limit = 50000;   // vertices: larger meshes are refined locally (refine_locally())
  double maximum_constrained_ratio = 1e5; // the largest weight of the constrained steps of larger meshes
  std::size_t maximum_constrained_steps = 40; // and the most constrained steps they take
  std::size_t coarsest_extra_steps = 6;   // most further steps at the last weight of the schedule on the coarsest of several levels
  std::size_t local_refinement_steps = 4; // most steps of the local refinement of larger meshes
  std::size_t local_refinement_rings = 1; // neighbour rings around its vertices
  double tangential_weight = 0.1;         // the smallest weight of the tangential part of the mirror residuals in the refinement
  std::function<void(double)> progress;
};

// The mirror point of a vertex for one symmetry.
struct Mirror
{
  std::uint32_t face = 0;
  std::array<double, 3> barycentric{{1, 0, 0}};
  double distance = 0; // from T^-1(x_i) to the mirror point
  bool found = false;
};

struct Iteration_record
{
  std::size_t level = 0; // 0: the finest
  double alpha = 0;
  double symmetry_error = 0; // RMS mirror distance after the step, relative to the diagonal
};

struct Symmetrization_output
{
  std::vector<Vector_3d> points;                  // the symmetrized positions
  std::vector<std::vector<Mirror>> mirrors;       // [symmetry][vertex], on the result
  std::vector<Iteration_record> iterations;
  double error_before = 0;                        // RMS, relative to the diagonal
  double error_after = 0;
  double distortion = 0;                          // RMS relative change of edge lengths
  std::vector<std::size_t> level_sizes;           // vertices per level, finest first
};

// ---------------------------------------------------------------------------------------------

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

// RMS relative change of the edge lengths between `x0` and `x` (edges of positive length).
inline double edge_distortion(const Surface& s, const std::vector<Vector_3d>& x0,
                              const std::vector<Vector_3d>& x)
{
  double sum = 0;
  std::size_t count = 0;
  for(const auto& e : s.edges()) {
    const double l0 = (x0[e.first] - x0[e.second]).length();
    if(!(l0 > 0))
      continue;
    const double l = (x[e.first] - x[e.second]).length();
    sum += (l / l0 - 1) * (l / l0 - 1);
    ++count;
  }
  return count > 0 ? std::sqrt(sum / double(count)) : 0.0;
}

// The naive baseline of the benchmarks: every vertex moved halfway to the image, under `t`, of
// its mirror point (the closest compatible surface point to t^-1(x_i)); vertices without one stay.
inline std::vector<Vector_3d> naive_symmetrization(const Surface& s, const Affine_3d& t,
                                                   std::size_t threads)
{
  const auto mirrors = exact_mirror_points(s, {t.inverse()}, threads);
  std::vector<Vector_3d> x = s.points;
  for(std::size_t i = 0; i < x.size(); ++i) {
    const Mirror& m = mirrors[0][i];
    if(!m.found)
      continue;
    const auto c = s.corners(m.face);
    const Vector_3d p = c[0] * m.barycentric[0] + c[1] * m.barycentric[1] + c[2] * m.barycentric[2];
    x[i] = (s.points[i] + t(p)) * 0.5;
  }
  return x;
}

// The RMS symmetry error of positions `x` (connectivity of `s`) under `t`, relative to the
// diagonal of `s`, with exact closest points.
inline double symmetry_error(const Surface& s, const std::vector<Vector_3d>& x, const Affine_3d& t,
                             std::size_t threads)
{
  const auto mirrors = exact_mirror_points(Surface{x, s.triangles}, {t.inverse()}, threads);
  return rms_mirror_distance(mirrors, {std::vector<double>()}) / s.diagonal();
}

// RMS relative change of the edge vectors between `x0` and `x`: |(x_i - x_j) - (x0_i - x0_j)|
// over |x0_i - x0_j| (edges of positive length). It counts stretching and bending alike.
inline double edge_vector_distortion(const Surface& s, const std::vector<Vector_3d>& x0,
                                     const std::vector<Vector_3d>& x)
{
  double sum = 0;
  std::size_t count = 0;
  for(const auto& e : s.edges()) {
    const Vector_3d d0 = x0[e.first] - x0[e.second];
    const double l0 = d0.length();
    if(!(l0 > 0))
      continue;
    const double d = ((x[e.first] - x[e.second]) - d0).length() / l0;
    sum += d * d;
    ++count;
  }
  return count > 0 ? std::sqrt(sum / double(count)) : 0.0;
}

// ---------------------------------------------------------------------------------------------
// One level of the multiresolution hierarchy.

struct Level
{
  Surface original;                       // positions x0 at this level
  std::vector<std::pair<std::uint32_t, std::uint32_t>> edges;
  double mean_edge = 0;
  // Per vertex of the next finer level: its closest point on this level's original surface.
  std::vector<Surface_point> finer_on_this;
  std::vector<std::vector<double>> weights; // [symmetry][vertex] (empty: 1)
  // Per face, the faces across its three edges (no_face at a border or a non-manifold edge);
  // built on first use.
  mutable std::vector<std::array<std::uint32_t, 3>> adjacent;
  // The closest-point index of the current positions of this level, refitted as they move.
  mutable std::unique_ptr<Surface_index> index;
};

// Decimates `s` with CGAL's edge collapse (edge-length cost, midpoint placement) to about
// `target` vertices. Returns false when the surface cannot be built as a halfedge mesh or does
// not get smaller.
inline bool decimate(const Surface& s, std::size_t target, Surface& result)
{
  typedef CGAL::Simple_cartesian<double> K;
  typedef CGAL::Surface_mesh<K::Point_3> Mesh;
  namespace SMS = CGAL::Surface_mesh_simplification;
  Mesh mesh;
  std::vector<std::uint32_t> used(s.points.size(), 0);
  for(const auto& t : s.triangles)
    for(std::uint32_t v : t)
      used[v] = 1;
  std::vector<Mesh::Vertex_index> vertex(s.points.size());
  for(std::size_t i = 0; i < s.points.size(); ++i)
    if(used[i])
      vertex[i] = mesh.add_vertex(K::Point_3(s.points[i].x, s.points[i].y, s.points[i].z));
  std::vector<Mesh::Vertex_index> corners(3);
  for(const auto& t : s.triangles) {
    for(int c = 0; c < 3; ++c)
      corners[std::size_t(c)] = vertex[t[std::size_t(c)]];
    if(CGAL::Euler::add_face(corners, mesh) == Mesh::null_face())
      return false; // a face that a halfedge mesh cannot hold: no coarser level
  }
  const std::size_t before = num_vertices(mesh);
  if(before <= target)
    return false;
  SMS::Count_stop_predicate<Mesh> stop(3 * target);
  SMS::edge_collapse(mesh, stop,
                     CGAL::parameters::get_cost(SMS::Edge_length_cost<Mesh>())
                       .get_placement(SMS::Midpoint_placement<Mesh>()));
  mesh.collect_garbage();
  if(num_vertices(mesh) >= before || num_faces(mesh) == 0)
    return false;
  result = Surface();
  result.points.reserve(num_vertices(mesh));
  for(Mesh::Vertex_index v : mesh.vertices()) {
    const K::Point_3& p = mesh.point(v);
    result.points.emplace_back(p.x(), p.y(), p.z());
  }
  for(Mesh::Face_index f : mesh.faces()) {
    std::array<std::uint32_t, 3> t{{0, 0, 0}};
    int c = 0;
    for(Mesh::Vertex_index v : vertices_around_face(mesh.halfedge(f), mesh))
      t[std::size_t(c++)] = std::uint32_t(v.idx());
    result.triangles.push_back(t);
  }
  return true;
}

// ---------------------------------------------------------------------------------------------
// The solver.

class Symmetrizer
{
public:
  typedef Eigen::SparseMatrix<double> Sparse;
  typedef Eigen::SimplicialLDLT<Sparse> LDLT;
  typedef Eigen::Triplet<double> Triplet;

  Symmetrizer(const Surface& input, const std::vector<Solver_symmetry>& symmetries,
              const Symmetrization_options& o)
    : m_input(input), m_o(o)
  {
    for(const Solver_symmetry& s : symmetries) {
      m_transforms.push_back(s.transform);
      m_inverses.push_back(s.transform.inverse());
    }
    m_diagonal = input.diagonal();
    // Levels, finest first.
    Level finest;
    finest.original = input;
    for(const Solver_symmetry& s : symmetries)
      finest.weights.push_back(s.vertex_weight);
    m_levels.push_back(std::move(finest));
    // The error of the input (an exact search, in parallel) while the levels are made (serial).
    const std::vector<std::vector<double>> finest_weights = m_levels.front().weights;
    SAI::Parallel_workspaces<char> both(o.number_of_threads);
    std::unique_ptr<Surface_index> input_index;
    both.for_each(0, 2, [&](std::size_t job, char&) {
      if(job == 1) {
        // The index of the input becomes that of the finest level, refitted as it moves, and the
        // mirror points of the input are the hints of its first search.
        input_index = std::make_unique<Surface_index>(m_input);
        m_input_mirrors = mirror_points(m_input, *input_index, m_inverses, true, o.number_of_threads);
        m_error_before = rms_mirror_distance(m_input_mirrors, finest_weights) / m_diagonal;
        return;
      }
      const std::size_t max_levels = o.number_of_levels == 0 ? 8 : o.number_of_levels;
      while(m_levels.size() < max_levels) {
        const Surface& fine = m_levels.back().original;
        std::size_t used = 0;
        {
          std::vector<char> u(fine.points.size(), 0);
          for(const auto& t : fine.triangles)
            for(std::uint32_t v : t)
              u[v] = 1;
          for(char c : u)
            used += c ? 1 : 0;
        }
        const std::size_t target = used / 8;
        if(o.number_of_levels == 0 && target < o.coarsest_level_size / 2)
          break;
        if(target < 20)
          break;
        Level coarse;
        if(!decimate(fine, target, coarse.original))
          break;
        m_levels.push_back(std::move(coarse));
      }
    });
    m_levels.front().index = std::move(input_index);
    // Links between levels and the weights of coarser levels (the weight of the closest point).
    for(std::size_t l = 1; l < m_levels.size(); ++l) {
      const Surface& fine = m_levels[l - 1].original;
      Level& coarse = m_levels[l];
      const Surface_index coarse_index(coarse.original);
      coarse.finer_on_this.resize(fine.number_of_vertices());
      SAI::Parallel_workspaces<char> parallel(o.number_of_threads);
      parallel.for_each(0, fine.number_of_vertices(), [&](std::size_t i, char&) {
        coarse.finer_on_this[i] = coarse_index.closest(fine.points[i]);
      });
      std::unique_ptr<Surface_index> fine_index; // made when a symmetry has weights
      coarse.weights.resize(symmetries.size());
      for(std::size_t k = 0; k < symmetries.size(); ++k) {
        const std::vector<double>& wf = m_levels[l - 1].weights[k];
        if(wf.empty())
          continue;
        if(!fine_index)
          fine_index = std::make_unique<Surface_index>(fine);
        std::vector<double>& wc = coarse.weights[k];
        wc.assign(coarse.original.number_of_vertices(), 0.0);
        for(std::size_t i = 0; i < wc.size(); ++i) {
          const Surface_point c = fine_index->closest(coarse.original.points[i]);
          if(!c.found)
            continue;
          const auto& t = fine.triangles[c.face];
          wc[i] = c.barycentric[0] * wf[t[0]] + c.barycentric[1] * wf[t[1]] + c.barycentric[2] * wf[t[2]];
        }
      }
    }
    for(Level& level : m_levels) {
      level.edges = level.original.edges();
      double sum = 0;
      for(const auto& e : level.edges)
        sum += (level.original.points[e.first] - level.original.points[e.second]).length();
      level.mean_edge = level.edges.empty() ? 0.0 : sum / double(level.edges.size());
    }
  }

  Symmetrization_output run()
  {
    Symmetrization_output out;
    for(const Level& l : m_levels)
      out.level_sizes.push_back(l.original.number_of_vertices());
    out.error_before = m_error_before;
    // Work counted for progress: vertices times steps.
    double total_work = 0, done_work = 0;
    const std::size_t L = m_levels.size();
    for(std::size_t l = 0; l < L; ++l)
      total_work += double(m_levels[l].original.number_of_vertices()) *
                    double(schedule(l).size() + m_o.projection_iterations / 2);
    std::vector<Vector_3d> x; // positions of the current level
    for(std::size_t step = 0; step < L; ++step) {
      const std::size_t l = L - 1 - step;
      Level& level = m_levels[l];
      if(step == 0) {
        x = level.original.points;
      } else {
        // Seed from the coarser level's displacements.
        const Level& coarse = m_levels[l + 1];
        std::vector<Vector_3d> seeded = level.original.points;
        for(std::size_t i = 0; i < seeded.size(); ++i) {
          const Surface_point& c = coarse.finer_on_this[i];
          if(!c.found)
            continue;
          const auto& t = coarse.original.triangles[c.face];
          Vector_3d d;
          for(int j = 0; j < 3; ++j)
            d += (x[t[std::size_t(j)]] - coarse.original.points[t[std::size_t(j)]]) * c.barycentric[std::size_t(j)];
          seeded[i] += d;
        }
        x.swap(seeded);
      }
      const std::vector<double> alphas = schedule(l);
      // The steps of the schedule, then constrained steps until the error is below the
      // tolerance, stops decreasing by 5%, or `projection_iterations` were made; the positions of
      // the smallest error from the last step of the schedule on are kept.
      std::size_t projections = 0, total_projections = 0, extra_steps = 0;
      std::vector<Vector_3d> best_x;
      double best_error = std::numeric_limits<double>::infinity();
      bool last_tracked = false; // the error of the current positions is that of tracked mirrors
      double previous_constrained = std::numeric_limits<double>::infinity();
      double previous_exact = std::numeric_limits<double>::infinity(); // the error of the last exact search
      bool previous_tracked = false;
      double previous_error = std::numeric_limits<double>::infinity();
      // Finest level of a mesh too large for the refinement: growing constrained weights.
      const bool escalate = l == 0 && !refinable(level) && m_o.target_error > 0 &&
                            m_o.maximum_constrained_ratio > m_o.constrained_ratio;
      // It starts from the schedule's last weight: a smaller one would undo the last steps.
      m_constrained_ratio = escalate ? (std::max)(m_o.constrained_ratio, std::pow(10.0, m_o.schedule_exponent))
                                     : m_o.constrained_ratio;
      // On the finest level, the input's mirror points are the first hints.
      std::vector<std::vector<Mirror>> mirrors;
      if(l == 0)
        mirrors.swap(m_input_mirrors);
      for(std::size_t s = 0;; ++s) {
        const bool constrained = s + 1 >= alphas.size();
        const bool coarsest = l > 0 && l + 1 == L;
        // Coarser levels only take the steps of the schedule: their constrained steps would fit
        // their own (coarse) triangles to each other, and seed the finer level with that. The
        // coarsest one takes further steps at the schedule's last weight while they gain 5%: the
        // large-scale asymmetry is cheapest to remove there.
        if(constrained && l > 0) {
          double e = 0;
          if(s > 0) {
            mirrors = exact_mirrors(level, x, &mirrors);
            e = rms_mirror_distance(mirrors, level.weights) / m_diagonal;
            out.iterations.back().symmetry_error = e;
            if(e < best_error) {
              best_error = e;
              best_x = x;
            }
          }
          if(!coarsest || s < 2 || extra_steps >= m_o.coarsest_extra_steps || !(e < m_o.stall_ratio * previous_error))
            break;
          previous_error = e;
          ++extra_steps;
          solve(level, mirrors, alphas[alphas.size() - 2], false, x);
          out.iterations.push_back(Iteration_record{l, alphas[alphas.size() - 2], 0.0});
          --s; // stay on this step
          continue;
        }
        const double alpha = constrained ? 1.0 : alphas[s];
        bool tracked = false;
        if(escalate && projections > 0 && total_projections % 4 != 0) {
          mirrors = track_mirrors(level, x, mirrors);
          tracked = true;
        } else {
          // The input's own (the finest level not seeded: its positions are the input's).
          if(!(s == 0 && step == 0 && l == 0 && mirrors.size() == m_inverses.size()))
            mirrors = exact_mirrors(level, x, &mirrors);
        }
        if(s > 0) {
          double e = rms_mirror_distance(mirrors, level.weights) / m_diagonal;
          bool rechecked = false;
          // Tracked mirrors leave out the vertices that only an exact search finds one for, which
          // are the farthest: their error is checked once it is well below the target.
          if(tracked && e <= 0.75 * m_o.target_error) {
            mirrors = exact_mirrors(level, x, &mirrors);
            e = rms_mirror_distance(mirrors, level.weights) / m_diagonal;
            rechecked = true;
          }
          out.iterations.back().symmetry_error = e;
          // Kept: the positions of the smallest exact error from the last step of the schedule on
          // (the errors of tracked mirrors leave some vertices out: not comparable).
          last_tracked = tracked && !rechecked;
          if(!last_tracked && e < best_error && s + 2 >= alphas.size()) {
            best_error = e;
            best_x = x;
          }
          if(projections > 0) {
            // The first constrained step may pair vertices and raise the error for a step; after
            // it, stop once a step gains less than 5%. Large meshes above the target: the weight
            // grows tenfold once a step gains less than 10%.
            // An exact search after tracked ones is not compared with them (they leave out the
            // vertices that only it finds a mirror point for), but with the last exact one.
            const double reference = rechecked ? std::numeric_limits<double>::infinity()
                                   : (!tracked && previous_tracked) ? previous_exact : previous_constrained;
            previous_tracked = tracked;
            if(!tracked)
              previous_exact = e;
            const bool stalled = projections >= 2 && e > m_o.stall_ratio * reference;
            const bool slow = projections >= 2 && e > 0.9 * reference;
            previous_constrained = e;
            if(escalate && e > m_o.target_error && total_projections < m_o.maximum_constrained_steps &&
               (slow || projections >= m_o.projection_iterations) &&
               m_constrained_ratio < m_o.maximum_constrained_ratio) {
              m_constrained_ratio = (std::min)(m_o.maximum_constrained_ratio, m_constrained_ratio * 10);
              projections = 1;
              previous_constrained = std::numeric_limits<double>::infinity();
              previous_exact = std::numeric_limits<double>::infinity();
            } else if(e <= m_o.symmetry_tolerance || projections >= m_o.projection_iterations || stalled ||
                      (escalate && (e <= m_o.target_error || total_projections >= m_o.maximum_constrained_steps)))
              break;
          }
        }
        solve(level, mirrors, alpha, constrained, x);
        if(constrained) {
          ++projections;
          ++total_projections;
        }
        out.iterations.push_back(Iteration_record{l, alpha, 0.0});
        done_work += double(level.original.number_of_vertices());
        if(m_o.progress)
          m_o.progress((std::min)(0.99, done_work / (std::max)(1.0, total_work)));
      }
      if(last_tracked) { // the last positions, exactly
        mirrors = exact_mirrors(level, x, &mirrors);
        const double e = rms_mirror_distance(mirrors, level.weights) / m_diagonal;
        out.iterations.back().symmetry_error = e;
        if(e < best_error) {
          best_x.clear();
          if(l == 0)
            out.mirrors = mirrors;
        }
      }
      if(!best_x.empty())
        x.swap(best_x);
      if(l == 0 && refinable(level))
        refine(level, x, out);
      else if(escalate && m_o.local_refinement_steps > 0)
        refine_locally(level, x, out);
    }
    out.points = x;
    {
      if(out.mirrors.empty()) // refine() leaves those of the positions it kept
        out.mirrors = exact_mirrors(m_levels.front(), x);
      out.error_after = rms_mirror_distance(out.mirrors, m_levels.front().weights) / m_diagonal;
      if(!out.iterations.empty())
        out.iterations.back().symmetry_error = out.error_after;
    }
    out.distortion = edge_distortion(m_input, m_input.points, x);
    return out;
  }

private:
  // The alphas of the steps before the constrained ones: from 0 to 1 on the coarsest level; the
  // last two on finer levels (seeded). The last entry (1) marks the constrained steps.
  std::vector<double> schedule(std::size_t level) const
  {
    // alpha / (1 - alpha) grows geometrically from 10^r0 to 10^r1.
    const double r0 = -1.0, r1 = m_o.schedule_exponent;
    std::vector<double> a;
    const auto alpha_of = [](double r) { const double q = std::pow(10.0, r); return q / (1 + q); };
    if(level + 1 == m_levels.size()) {
      const std::size_t k = (std::max)(std::size_t(1), m_o.number_of_iterations);
      for(std::size_t i = 0; i + 1 < k; ++i)
        a.push_back(alpha_of(k > 2 ? r0 + (r1 - r0) * double(i) / double(k - 2) : r1));
    } else {
      a.push_back(alpha_of(r1 - 1));
      a.push_back(alpha_of(r1));
    }
    a.push_back(1.0);
    return a;
  }

  // One solve with fixed targets: every vertex is drawn toward the midpoint q_i = (y_i + T(p_i)) / 2
  // of its current position y_i and the image of its mirror point p_i (for every symmetry, with
  // its weight), E_sym = 1/n sum w |x_i - q_i|^2. The coordinates decouple and share one matrix.
  // `anchor_current`: the edge vectors are kept relative to the current positions (the constrained
  // steps: at a fixed point the shape term vanishes and x_i = q_i, i.e. the mirror points lie on
  // the surface); otherwise relative to the input.
  void solve(const Level& level, const std::vector<std::vector<Mirror>>& mirrors, double alpha,
             bool anchor_current, std::vector<Vector_3d>& x) const
  {
    const std::size_t n = level.original.number_of_vertices();
    const double D = m_diagonal;
    const double h = m_levels.front().mean_edge > 0 ? m_levels.front().mean_edge : D;
    const double rho = alpha >= 1 ? m_constrained_ratio : alpha / (1 - alpha);
    const double a_sym = rho / double(n);
    const double a_edge = m_o.shape_weight * (D * D) / (h * h) /
                          double((std::max)(std::size_t(1), level.edges.size()));
    const double a_disp = m_o.displacement_weight / double(n);
    const std::vector<Vector_3d>& x0 = level.original.points;
    const std::vector<Vector_3d> y = x;
    std::vector<double> w(n, 0.0);
    std::vector<Vector_3d> wq(n); // sum of weight * target
    const bool snap = anchor_current;
    for(std::size_t k = 0; k < mirrors.size(); ++k) {
      // Mutual vertex pairs: the corner of the mirror face nearest to the mirror point of i is j,
      // and that of j is i, both within a third of the mean edge length.
      std::vector<std::uint32_t> nearest(n, Surface_index::no_face);
      for(std::size_t i = 0; i < n; ++i) {
        const Mirror& m = mirrors[k][i];
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
      for(std::size_t i = 0; i < n; ++i) {
        const Mirror& m = mirrors[k][i];
        const double wi = a_sym * weight(level, k, i);
        if(!m.found || !(wi > 0))
          continue;
        const auto& f = level.original.triangles[m.face];
        Vector_3d p = y[f[0]] * m.barycentric[0] + y[f[1]] * m.barycentric[1] + y[f[2]] * m.barycentric[2];
        const std::uint32_t j = nearest[i];
        if(snap && j != Surface_index::no_face && nearest[j] == i)
          p = y[j];
        const Vector_3d q = (y[i] + m_transforms[k](p)) * 0.5;
        w[i] += wi;
        wq[i] += q * wi;
      }
    }
    std::vector<Vector_3d> b(n);
    for(const auto& e : level.edges) {
      const std::vector<Vector_3d>& ref = anchor_current ? y : x0;
      const Vector_3d d = ref[e.first] - ref[e.second];
      b[e.first] += d * a_edge;
      b[e.second] -= d * a_edge;
    }
    for(std::size_t i = 0; i < n; ++i)
      b[i] += wq[i] + x0[i] * a_disp;
    // The matrix only depends on the level, alpha and the weights: its factorization is kept
    // for the next solve with the same ones (the constrained steps).
    // Its pattern (edges and diagonal) only depends on the level: the ordering and symbolic
    // analysis are made once per level.
    Factorization& F = m_factorization;
    if(!(F.level == &level && F.ratio == rho && F.weights == w)) {
      std::vector<Triplet> tr;
      tr.reserve(4 * level.edges.size() + n);
      for(const auto& e : level.edges) {
        tr.emplace_back(Eigen::Index(e.first), Eigen::Index(e.first), a_edge);
        tr.emplace_back(Eigen::Index(e.second), Eigen::Index(e.second), a_edge);
        tr.emplace_back(Eigen::Index(e.first), Eigen::Index(e.second), -a_edge);
        tr.emplace_back(Eigen::Index(e.second), Eigen::Index(e.first), -a_edge);
      }
      for(std::size_t i = 0; i < n; ++i)
        tr.emplace_back(Eigen::Index(i), Eigen::Index(i), w[i] + a_disp);
      // Kept with the factorization: the iterative solver refers to it.
      Sparse& A = F.matrix;
      A.resize(static_cast<Eigen::Index>(n), static_cast<Eigen::Index>(n));
      A.setFromTriplets(tr.begin(), tr.end());
      const bool analyzed = F.analyzed == &level;
      F.level = &level;
      F.ratio = rho;
      F.weights = w;
      F.direct = n <= m_o.direct_solver_limit;
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
    for(int c = 0; c < 3; ++c) {
      Eigen::VectorXd rhs(static_cast<Eigen::Index>(n)), guess(static_cast<Eigen::Index>(n));
      for(std::size_t i = 0; i < n; ++i) {
        rhs(Eigen::Index(i)) = b[i][c];
        guess(Eigen::Index(i)) = y[i][c];
      }
      const Eigen::VectorXd sol = F.direct ? Eigen::VectorXd(F.ldlt.solve(rhs))
                                           : Eigen::VectorXd(F.cg.solveWithGuess(rhs, guess));
      for(std::size_t i = 0; i < n; ++i)
        if(std::isfinite(sol(Eigen::Index(i))))
          x[i][c] = sol(Eigen::Index(i));
    }
  }

  // The mirror points of positions `x` found from `previous` ones (same connectivity, slightly
  // moved): from each previous mirror face, a descent to edge-adjacent faces whose normal is
  // compatible while the distance to the vertex's transformed position decreases. A few
  // triangles per vertex, no tree; the result is a local minimum next to the previous mirror
  // point. The vertices that had one keep one (even if its face turned incompatible), so that
  // the weights, hence the matrix and its factorization, stay those of the last exact search.
  std::vector<std::vector<Mirror>> track_mirrors(const Level& level, const std::vector<Vector_3d>& x,
                                                 const std::vector<std::vector<Mirror>>& previous) const
  {
    const std::size_t n = level.original.number_of_vertices();
    const Surface current{x, level.original.triangles};
    const std::vector<Vector_3d> vn = current.vertex_normals();
    const std::vector<Vector_3d> fn = current.face_normals();
    const std::vector<std::array<std::uint32_t, 3>>& adjacent = face_adjacency(level);
    std::vector<std::vector<Mirror>> result(previous.size(), std::vector<Mirror>(n));
    SAI::Parallel_workspaces<char> parallel(m_o.number_of_threads);
    const std::size_t block = 1024;
    for(std::size_t k = 0; k < previous.size(); ++k) {
      const Affine_3d& inv = m_inverses[k];
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

  // The exact mirror points of the surface of `level` at positions `x`.
  std::vector<std::vector<Mirror>> exact_mirrors(const Level& level, const std::vector<Vector_3d>& x,
                                                 const std::vector<std::vector<Mirror>>* hints = nullptr) const
  {
    if(!level.index)
      level.index = std::make_unique<Surface_index>(Surface{x, level.original.triangles});
    else
      level.index->update(x);
    return mirror_points(level.index->surface(), *level.index, m_inverses, true, m_o.number_of_threads,
                         hints != nullptr && hints->size() == m_inverses.size() &&
                             hints->front().size() == x.size() ? hints : nullptr);
  }

  const std::vector<std::array<std::uint32_t, 3>>& face_adjacency(const Level& level) const
  {
    if(level.adjacent.empty())
      level.adjacent = internal::face_adjacency(level.original.triangles, [](std::size_t) { return true; });
    return level.adjacent;
  }

  bool refinable(const Level& level) const
  {
    return m_o.refinement_steps > 0 && level.original.number_of_vertices() <= m_o.refinement_limit;
  }

  // The isometric refinement of the finest level, after the constrained steps: while the error
  // is above the target, a step of refine_step() with a weight of the symmetry error that grows
  // by sqrt(10) per step (from refinement_ratio to 1000 times it); the positions of the smallest
  // error are kept, and their mirror points are left in `out.mirrors`.
  void refine(const Level& level, std::vector<Vector_3d>& x, Symmetrization_output& out) const
  {
    double rho = m_o.refinement_ratio;
    std::vector<Vector_3d> best_x = x;
    double best_error = std::numeric_limits<double>::infinity();
    std::vector<std::vector<Mirror>> mirrors;
    std::size_t halvings = 0;
    for(std::size_t step = 0;; ++step) {
      mirrors = exact_mirrors(level, x, &mirrors);
      const double e = rms_mirror_distance(mirrors, level.weights) / m_diagonal;
      if(step > 0)
        out.iterations.back().symmetry_error = e;
      if(e < best_error) {
        best_error = e;
        best_x = x;
        out.mirrors = mirrors;
        halvings = 0;
      } else if(step < m_o.refinement_steps && halvings < 2) {
        // A step that made the error larger (the linearization does not hold that far): half of
        // it, from the best positions (one more search, no solve).
        ++halvings;
        for(std::size_t i = 0; i < x.size(); ++i)
          x[i] = (x[i] + best_x[i]) * 0.5;
        out.iterations.push_back(Iteration_record{0, 1.0, 0.0});
        --step;
        continue;
      }
      if(e <= m_o.target_error || step >= m_o.refinement_steps)
        break;
      refine_step(level, mirrors, rho, x);
      out.iterations.push_back(Iteration_record{0, 1.0, 0.0});
      rho = (std::min)(rho * std::sqrt(10.0), 1000 * m_o.refinement_ratio);
    }
    x.swap(best_x);
  }

  // Meshes too large for the refinement, while their error is above the target: its steps, at
  // its largest weight of the error, on the vertices whose mirror distance is above twice the target,
  // the corners of their mirror faces and `local_refinement_rings` rings of neighbours around
  // them, all others staying (a few percent of the vertices hold most of the squared error).
  // Each step takes new mirror points (exact search); the positions of the smallest error are
  // kept.
  void refine_locally(const Level& level, std::vector<Vector_3d>& x, Symmetrization_output& out) const
  {
    const std::size_t n = level.original.number_of_vertices();
    const std::uint32_t none = Surface_index::no_face;
    std::vector<std::vector<Mirror>> mirrors = out.mirrors.empty() ? exact_mirrors(level, x) : out.mirrors;
    double best_error = rms_mirror_distance(mirrors, level.weights) / m_diagonal;
    out.mirrors = mirrors;
    // Vertex neighbours.
    std::vector<std::size_t> first(n + 1, 0);
    for(const auto& e : level.edges)
      ++first[e.first + 1], ++first[e.second + 1];
    for(std::size_t i = 0; i < n; ++i)
      first[i + 1] += first[i];
    std::vector<std::uint32_t> neighbours(first[n]);
    {
      std::vector<std::size_t> fill(first.begin(), first.end() - 1);
      for(const auto& e : level.edges)
        neighbours[fill[e.first]++] = e.second, neighbours[fill[e.second]++] = e.first;
    }
    std::vector<Vector_3d> best_x = x;
    const double rho = 1000 * m_o.refinement_ratio;
    const double threshold = 2 * m_o.target_error * m_diagonal;
    for(std::size_t step = 0; step < m_o.local_refinement_steps && best_error > m_o.target_error; ++step) {
      std::vector<char> on(n, 0);
      std::vector<std::uint32_t> front;
      for(std::size_t k = 0; k < mirrors.size(); ++k)
        for(std::size_t i = 0; i < n; ++i) {
          const Mirror& m = mirrors[k][i];
          if(!m.found || !(m.distance > threshold) || !(weight(level, k, i) > 0))
            continue;
          for(std::uint32_t v : {std::uint32_t(i), level.original.triangles[m.face][0],
                                 level.original.triangles[m.face][1], level.original.triangles[m.face][2]})
            if(!on[v]) {
              on[v] = 1;
              front.push_back(v);
            }
        }
      if(front.empty())
        break;
      for(std::size_t ring = 0; ring < m_o.local_refinement_rings; ++ring) {
        std::vector<std::uint32_t> next;
        for(std::uint32_t v : front)
          for(std::size_t q = first[v]; q < first[v + 1]; ++q)
            if(!on[neighbours[q]]) {
              on[neighbours[q]] = 1;
              next.push_back(neighbours[q]);
            }
        front.swap(next);
      }
      std::vector<std::uint32_t> unknown(n, none);
      std::uint32_t count = 0;
      for(std::size_t i = 0; i < n; ++i)
        if(on[i])
          unknown[i] = count++;
      refine_step(level, mirrors, rho, x, &unknown);
      mirrors = exact_mirrors(level, x, &mirrors);
      const double e = rms_mirror_distance(mirrors, level.weights) / m_diagonal;
      out.iterations.push_back(Iteration_record{0, 1.0, e});
      const bool gained = e < m_o.stall_ratio * best_error;
      if(e < best_error) {
        best_error = e;
        best_x = x;
        out.mirrors = mirrors;
      }
      if(!gained)
        break;
    }
    x.swap(best_x);
  }

  // One step of the isometric refinement: the displacements d_i of the vertices minimize the
  // linearized
  //   rho / (n D^2) sum_ik w_ik |r_ik + L_k d_i - sum_c b_c d_c|_M^2
  //   + 1/|E| sum_e [((l_e - l0_e + u_e . (d_i - d_j)) / l0_e)^2 + eta |d_i - d_j|^2 / l0_e^2]
  //   + mu / (n h^2) sum_i |d_i|^2,
  // r_ik = T_k^-1(y_i) - p_ik being the mirror residual of vertex i (p_ik its mirror point, on the
  // face of corners c with barycentric coordinates b_c), L_k the linear part of T_k^-1, l_e and
  // l0_e the current and input lengths of edge e and u_e its direction, |v|_M^2 = (n.v)^2 +
  // tau |v - (n.v) n|^2 with n the normal of the mirror face and tau = min(1, max(0.1, |r_ik| / h))
  // (near the surface, mostly the distance to its tangent plane, so that mirror points slide;
  // point to point at an edge's length and beyond): the symmetry error against
  // the relative change of the edge lengths (the distortion). Bending and rigid motions of parts
  // leave the edge lengths unchanged: the two sides meet where their triangulations do not match
  // at the least cost in distortion, which the constrained steps (edge vectors kept) cannot do.
  // The 3n coordinates are coupled by L_k and by the edge directions: one sparse LDL^T solve.
  // With `active` (per vertex its unknown, `Surface_index::no_face` for a vertex that stays), only
  // the active vertices move: the terms of the others are constants.
  void refine_step(const Level& level, const std::vector<std::vector<Mirror>>& mirrors, double rho,
                   std::vector<Vector_3d>& x, const std::vector<std::uint32_t>* active = nullptr) const
  {
    const std::size_t n = level.original.number_of_vertices();
    const std::uint32_t none = Surface_index::no_face;
    std::vector<std::uint32_t> identity;
    if(active == nullptr) {
      identity.resize(n);
      std::iota(identity.begin(), identity.end(), 0u);
      active = &identity;
    }
    const std::vector<std::uint32_t>& unknown = *active;
    std::size_t m_unknowns = 0;
    for(std::uint32_t u : unknown)
      if(u != none)
        m_unknowns = (std::max)(m_unknowns, std::size_t(u) + 1);
    const double D = m_diagonal;
    const double h = m_levels.front().mean_edge > 0 ? m_levels.front().mean_edge : D;
    const double a_err = rho / (double(n) * D * D);
    const double a_edge = 1.0 / double((std::max)(std::size_t(1), level.edges.size()));
    const double eta = 0.01, mu = 1e-4;
    const double a_disp = mu / (double(n) * h * h);
    std::vector<Triplet> tr;
    std::size_t active_edges = 0;
    for(const auto& e : level.edges)
      active_edges += unknown[e.first] != none || unknown[e.second] != none ? 1 : 0;
    tr.reserve(16 * 9 * m_unknowns * mirrors.size() + 36 * active_edges + 3 * m_unknowns);
    Eigen::VectorXd rhs = Eigen::VectorXd::Zero(Eigen::Index(3 * m_unknowns));
    const auto block = [&](std::size_t u, std::size_t v, const Matrix_3d& m, double c) {
      const std::uint32_t iu = unknown[u], iv = unknown[v];
      if(iu == none || iv == none)
        return;
      for(int a = 0; a < 3; ++a)
        for(int b = 0; b < 3; ++b)
          if(m[std::size_t(a)][b] != 0)
            tr.emplace_back(Eigen::Index(3 * std::size_t(iu) + std::size_t(a)), Eigen::Index(3 * std::size_t(iv) + std::size_t(b)),
                            c * m[std::size_t(a)][b]);
    };
    const auto add_rhs = [&](std::size_t u, int a, double value) {
      if(unknown[u] != none)
        rhs(Eigen::Index(3 * std::size_t(unknown[u]) + std::size_t(a))) += value;
    };
    const std::vector<Vector_3d> fnormals = Surface{x, level.original.triangles}.face_normals();
    for(std::size_t k = 0; k < mirrors.size(); ++k) {
      const Affine_3d& inv = m_inverses[k];
      const Matrix_3d L = inv.linear, Lt = SAI::transpose(L);
      for(std::size_t i = 0; i < n; ++i) {
        const Mirror& m = mirrors[k][i];
        const double c = a_err * weight(level, k, i);
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
        const double tau = (std::min)(1.0, (std::max)(m_o.tangential_weight, r.length() / h));
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
    for(const auto& e : level.edges) {
      if(unknown[e.first] == none && unknown[e.second] == none)
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
    for(std::size_t i = 0; i < 3 * m_unknowns; ++i)
      tr.emplace_back(Eigen::Index(i), Eigen::Index(i), a_disp);
    Sparse A(static_cast<Eigen::Index>(3 * m_unknowns), static_cast<Eigen::Index>(3 * m_unknowns));
    A.setFromTriplets(tr.begin(), tr.end());
    LDLT ldlt(A);
    if(ldlt.info() != Eigen::Success)
      return;
    const Eigen::VectorXd delta = ldlt.solve(rhs);
    for(std::size_t i = 0; i < n; ++i) {
      if(unknown[i] == none)
        continue;
      for(int a = 0; a < 3; ++a) {
        const double v = delta(Eigen::Index(3 * std::size_t(unknown[i]) + std::size_t(a)));
        if(std::isfinite(v))
          x[i][a] += v;
      }
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
  mutable Factorization m_factorization;
  double m_constrained_ratio = 100; // alpha / (1 - alpha) of the current constrained steps
  double m_error_before = 0;        // RMS mirror distance of the input, relative to the diagonal
  std::vector<std::vector<Mirror>> m_input_mirrors; // the mirror points of the input

  double weight(const Level& level, std::size_t k, std::size_t i) const
  {
    const std::vector<double>& w = level.weights[k];
    return w.empty() ? 1.0 : w[i];
  }

  const Surface& m_input;
  Symmetrization_options m_o;
  std::vector<Affine_3d> m_transforms, m_inverses;
  double m_diagonal = 1;
  std::vector<Level> m_levels;
};

} // namespace internal
} // namespace Surface_mesh_symmetrization
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_SYMMETRIZATION_INTERNAL_SYMMETRIZATION_H
