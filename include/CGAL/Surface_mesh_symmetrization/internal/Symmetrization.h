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

#include <CGAL/Surface_mesh_symmetrization/Symmetrize_options.h>
#include <CGAL/Surface_mesh_symmetrization/internal/Isometric_refinement.h>
#include <CGAL/Surface_mesh_symmetrization/internal/Mirror_points.h>
#include <CGAL/Surface_mesh_symmetrization/internal/Symmetrization_levels.h>
#include <CGAL/Surface_mesh_symmetrization/internal/Symmetrization_step.h>

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

// The solver's own settings, which are not named parameters (tests change some of them to reach
// a path of the solver on a small mesh). The named parameters are in Symmetrize_options.
struct Symmetrizer_settings
{
  std::size_t projection_iterations = 8;  // most steps at alpha = 1 per level
  double stall_ratio = 0.95;              // projection steps stop when a step's error is above this times the previous one
  double schedule_exponent = 4;           // the schedule ends at alpha / (1 - alpha) = 10^this
  std::size_t direct_solver_limit = 2000000; // vertices
  std::size_t refinement_steps = 14;      // most steps of the isometric refinement (none when target_symmetry_error is 0)
  double refinement_ratio = 1e3;          // its first weight of the symmetry error against the edge lengths
  std::size_t refinement_limit = 50000;   // vertices: larger meshes are refined locally (refine_locally())
  double maximum_constrained_ratio = 1e5; // the largest weight of the constrained steps of larger meshes
  std::size_t maximum_constrained_steps = 40; // and the most constrained steps they take
  std::size_t coarsest_extra_steps = 6;   // most further steps at the last weight of the schedule on the coarsest of several levels
  std::size_t local_refinement_steps = 4; // most steps of the local refinement of larger meshes
  std::size_t local_refinement_rings = 1; // neighbour rings around its vertices
  double tangential_weight = 0.1;         // the smallest weight of the tangential part of the mirror residuals in the refinement
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

// ---------------------------------------------------------------------------------------------
// The solver.

class Symmetrizer
{
public:
  Symmetrizer(const Surface& input, const std::vector<Solver_symmetry>& symmetries,
              const Symmetrize_options& o, const Symmetrizer_settings& settings = {})
    : m_input(input), m_o(o), m_s(settings), m_step(settings.direct_solver_limit)
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
      add_coarser_levels(m_levels, o.number_of_levels, o.coarsest_level_size);
    });
    m_levels.front().index = std::move(input_index);
    link_levels(m_levels, symmetries.size(), o.number_of_threads);
  }

  Symmetrization_output run()
  {
    Symmetrization_output out;
    for(const Level& l : m_levels)
      out.level_sizes.push_back(l.original.number_of_vertices());
    out.error_before = m_error_before;
    // Work counted for progress: vertices times steps.
    m_total_work = m_done_work = 0;
    const std::size_t L = m_levels.size();
    for(std::size_t l = 0; l < L; ++l)
      m_total_work += double(m_levels[l].original.number_of_vertices()) *
                      double(schedule(l).size() + m_s.projection_iterations / 2);
    std::vector<Vector_3d> x; // positions of the current level
    for(std::size_t step = 0; step < L; ++step) {
      const std::size_t l = L - 1 - step;
      const Level& level = m_levels[l];
      // Seeded from the coarser level's displacements.
      x = step == 0 ? level.original.points : seeded_positions(level, m_levels[l + 1], x);
      run_level(l, step > 0, x, out);
      if(l == 0 && refinable(level))
        refine(level, x, out);
      else if(escalates(l) && m_s.local_refinement_steps > 0)
        refine_locally(level, x, out);
    }
    out.points = x;
    if(out.mirrors.empty()) // refine() leaves those of the positions it kept
      out.mirrors = exact_mirrors(m_levels.front(), x);
    out.error_after = rms_mirror_distance(out.mirrors, m_levels.front().weights) / m_diagonal;
    if(!out.iterations.empty())
      out.iterations.back().symmetry_error = out.error_after;
    out.distortion = edge_distortion(m_input, m_input.points, x);
    return out;
  }

private:
  // The state of the steps of one level.
  struct Level_steps
  {
    std::vector<double> alphas; // schedule()
    bool escalate = false;      // escalates()
    std::vector<std::vector<Mirror>> mirrors;
    std::size_t projections = 0, total_projections = 0, extra_steps = 0;
    // The positions of the smallest exact error from the last step of the schedule on.
    std::vector<Vector_3d> best_x;
    double best_error = std::numeric_limits<double>::infinity();
    bool last_tracked = false; // the error of the current positions is that of tracked mirrors
    double previous_constrained = std::numeric_limits<double>::infinity();
    double previous_exact = std::numeric_limits<double>::infinity(); // the error of the last exact search
    bool previous_tracked = false;
    double previous_error = std::numeric_limits<double>::infinity();
  };

  // Whether level l is the finest level of a mesh too large for the refinement: it takes
  // growing constrained weights.
  bool escalates(std::size_t l) const
  {
    return l == 0 && !refinable(m_levels[l]) && m_o.target_symmetry_error > 0 &&
           m_s.maximum_constrained_ratio > m_o.final_symmetry_weight;
  }

  // The steps of the schedule on level l, then constrained steps until the error is below the
  // tolerance, stops decreasing by 5%, or `projection_iterations` were made; the positions of
  // the smallest error from the last step of the schedule on are kept. `seeded`: `x` comes from
  // a coarser level (otherwise it is the input's).
  void run_level(std::size_t l, bool seeded, std::vector<Vector_3d>& x, Symmetrization_output& out)
  {
    const Level& level = m_levels[l];
    Level_steps r;
    r.alphas = schedule(l);
    r.escalate = escalates(l);
    // It starts from the schedule's last weight: a smaller one would undo the last steps.
    m_constrained_ratio = r.escalate ? (std::max)(m_o.final_symmetry_weight, std::pow(10.0, m_s.schedule_exponent))
                                     : m_o.final_symmetry_weight;
    // On the finest level, the input's mirror points are the first hints.
    if(l == 0)
      r.mirrors.swap(m_input_mirrors);
    for(std::size_t s = 0;; ++s) {
      const bool constrained = s + 1 >= r.alphas.size();
      if(constrained && l > 0) {
        if(!coarse_extra_step(l, s, x, out, r))
          break;
        --s; // stay on this step
        continue;
      }
      const double alpha = constrained ? 1.0 : r.alphas[s];
      // The input's own mirror points (the finest level not seeded: its positions are the input's).
      const bool tracked = update_mirrors(level, s == 0 && !seeded && l == 0, x, r);
      if(s > 0 && record_error(level, s, tracked, x, out, r))
        break;
      solve(level, r.mirrors, alpha, constrained, x);
      if(constrained) {
        ++r.projections;
        ++r.total_projections;
      }
      out.iterations.push_back(Iteration_record{l, alpha, 0.0});
      m_done_work += double(level.original.number_of_vertices());
      if(m_o.progress_callback)
        m_o.progress_callback((std::min)(0.99, m_done_work / (std::max)(1.0, m_total_work)));
    }
    if(r.last_tracked) { // the last positions, exactly
      r.mirrors = exact_mirrors(level, x, &r.mirrors);
      const double e = rms_mirror_distance(r.mirrors, level.weights) / m_diagonal;
      out.iterations.back().symmetry_error = e;
      if(e < r.best_error) {
        r.best_x.clear();
        if(l == 0)
          out.mirrors = r.mirrors;
      }
    }
    if(!r.best_x.empty())
      x.swap(r.best_x);
  }

  // Coarser levels only take the steps of the schedule: their constrained steps would fit their
  // own (coarse) triangles to each other, and seed the finer level with that. The coarsest one
  // takes further steps at the schedule's last weight while they gain 5%: the large-scale
  // asymmetry is cheapest to remove there. Returns whether it took one.
  bool coarse_extra_step(std::size_t l, std::size_t s, std::vector<Vector_3d>& x, Symmetrization_output& out,
                         Level_steps& r)
  {
    const Level& level = m_levels[l];
    const bool coarsest = l + 1 == m_levels.size();
    double e = 0;
    if(s > 0) {
      r.mirrors = exact_mirrors(level, x, &r.mirrors);
      e = rms_mirror_distance(r.mirrors, level.weights) / m_diagonal;
      out.iterations.back().symmetry_error = e;
      if(e < r.best_error) {
        r.best_error = e;
        r.best_x = x;
      }
    }
    if(!coarsest || s < 2 || r.extra_steps >= m_s.coarsest_extra_steps || !(e < m_s.stall_ratio * r.previous_error))
      return false;
    r.previous_error = e;
    ++r.extra_steps;
    const double alpha = r.alphas[r.alphas.size() - 2];
    solve(level, r.mirrors, alpha, false, x);
    out.iterations.push_back(Iteration_record{l, alpha, 0.0});
    return true;
  }

  // The mirror points of positions `x` for the next step: tracked from the previous ones between
  // the exact searches (every fourth step) of escalating constrained steps (returns true), exact
  // otherwise; `input`: `x` is the input, whose mirror points are known.
  bool update_mirrors(const Level& level, bool input, const std::vector<Vector_3d>& x, Level_steps& r) const
  {
    if(r.escalate && r.projections > 0 && r.total_projections % 4 != 0) {
      r.mirrors = track_mirrors(Surface{x, level.original.triangles}, face_adjacency(level), m_inverses, r.mirrors,
                                m_o.number_of_threads);
      return true;
    }
    if(!(input && r.mirrors.size() == m_inverses.size()))
      r.mirrors = exact_mirrors(level, x, &r.mirrors);
    return false;
  }

  // Records the error of the positions `x` reached by step s - 1 and keeps the best positions;
  // returns whether the constrained steps stop.
  bool record_error(const Level& level, std::size_t s, bool tracked, const std::vector<Vector_3d>& x,
                    Symmetrization_output& out, Level_steps& r)
  {
    double e = rms_mirror_distance(r.mirrors, level.weights) / m_diagonal;
    bool rechecked = false;
    // Tracked mirrors leave out the vertices that only an exact search finds one for, which
    // are the farthest: their error is checked once it is well below the target.
    if(tracked && e <= 0.75 * m_o.target_symmetry_error) {
      r.mirrors = exact_mirrors(level, x, &r.mirrors);
      e = rms_mirror_distance(r.mirrors, level.weights) / m_diagonal;
      rechecked = true;
    }
    out.iterations.back().symmetry_error = e;
    // Kept: the positions of the smallest exact error from the last step of the schedule on
    // (the errors of tracked mirrors leave some vertices out: not comparable).
    r.last_tracked = tracked && !rechecked;
    if(!r.last_tracked && e < r.best_error && s + 2 >= r.alphas.size()) {
      r.best_error = e;
      r.best_x = x;
    }
    return r.projections > 0 && constrained_steps_stop(e, tracked, rechecked, r);
  }

  // The first constrained step may pair vertices and raise the error for a step; after it, the
  // steps stop once one gains less than 5%. Large meshes above the target: the weight grows
  // tenfold once a step gains less than 10%. An exact search after tracked ones is not compared
  // with them (they leave out the vertices that only it finds a mirror point for), but with the
  // last exact one.
  bool constrained_steps_stop(double e, bool tracked, bool rechecked, Level_steps& r)
  {
    const double reference = rechecked ? std::numeric_limits<double>::infinity()
                           : (!tracked && r.previous_tracked) ? r.previous_exact : r.previous_constrained;
    r.previous_tracked = tracked;
    if(!tracked)
      r.previous_exact = e;
    const bool stalled = r.projections >= 2 && e > m_s.stall_ratio * reference;
    const bool slow = r.projections >= 2 && e > 0.9 * reference;
    r.previous_constrained = e;
    if(r.escalate && e > m_o.target_symmetry_error && r.total_projections < m_s.maximum_constrained_steps &&
       (slow || r.projections >= m_s.projection_iterations) && m_constrained_ratio < m_s.maximum_constrained_ratio) {
      m_constrained_ratio = (std::min)(m_s.maximum_constrained_ratio, m_constrained_ratio * 10);
      r.projections = 1;
      r.previous_constrained = std::numeric_limits<double>::infinity();
      r.previous_exact = std::numeric_limits<double>::infinity();
      return false;
    }
    return e <= m_o.symmetry_tolerance || r.projections >= m_s.projection_iterations || stalled ||
           (r.escalate && (e <= m_o.target_symmetry_error || r.total_projections >= m_s.maximum_constrained_steps));
  }

  // The alphas of the steps before the constrained ones: from 0 to 1 on the coarsest level; the
  // last two on finer levels (seeded). The last entry (1) marks the constrained steps.
  std::vector<double> schedule(std::size_t level) const
  {
    // alpha / (1 - alpha) grows geometrically from 10^r0 to 10^r1.
    const double r0 = -1.0, r1 = m_s.schedule_exponent;
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

  // One step of the schedule at `alpha` (1: a constrained step, at the current constrained
  // weight), with fixed targets (Step_solver::solve()).
  void solve(const Level& level, const std::vector<std::vector<Mirror>>& mirrors, double alpha,
             bool anchor_current, std::vector<Vector_3d>& x) const
  {
    const std::size_t n = level.original.number_of_vertices();
    const double D = m_diagonal;
    Step_weights c;
    c.mean_edge = m_levels.front().mean_edge > 0 ? m_levels.front().mean_edge : D;
    c.rho = alpha >= 1 ? m_constrained_ratio : alpha / (1 - alpha);
    c.symmetry = c.rho / double(n);
    c.edge = m_o.shape_weight * (D * D) / (c.mean_edge * c.mean_edge) /
             double((std::max)(std::size_t(1), level.edges.size()));
    c.displacement = m_o.displacement_weight / double(n);
    m_step.solve(level, mirrors, m_transforms, c, anchor_current, x);
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
    return m_o.target_symmetry_error > 0 && m_s.refinement_steps > 0 &&
           level.original.number_of_vertices() <= m_s.refinement_limit;
  }

  // The isometric refinement of the finest level, after the constrained steps: while the error
  // is above the target, a step of refine_step() with a weight of the symmetry error that grows
  // by sqrt(10) per step (from refinement_ratio to 1000 times it); the positions of the smallest
  // error are kept, and their mirror points are left in `out.mirrors`.
  void refine(const Level& level, std::vector<Vector_3d>& x, Symmetrization_output& out) const
  {
    double rho = m_s.refinement_ratio;
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
      } else if(step < m_s.refinement_steps && halvings < 2) {
        // A step that made the error larger (the linearization does not hold that far): half of
        // it, from the best positions (one more search, no solve).
        ++halvings;
        for(std::size_t i = 0; i < x.size(); ++i)
          x[i] = (x[i] + best_x[i]) * 0.5;
        out.iterations.push_back(Iteration_record{0, 1.0, 0.0});
        --step;
        continue;
      }
      if(e <= m_o.target_symmetry_error || step >= m_s.refinement_steps)
        break;
      refine_step(level, mirrors, rho, x);
      out.iterations.push_back(Iteration_record{0, 1.0, 0.0});
      rho = (std::min)(rho * std::sqrt(10.0), 1000 * m_s.refinement_ratio);
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
    std::vector<std::vector<Mirror>> mirrors = out.mirrors.empty() ? exact_mirrors(level, x) : out.mirrors;
    double best_error = rms_mirror_distance(mirrors, level.weights) / m_diagonal;
    out.mirrors = mirrors;
    const Vertex_neighbours neighbours(level);
    std::vector<Vector_3d> best_x = x;
    const double rho = 1000 * m_s.refinement_ratio;
    const double threshold = 2 * m_o.target_symmetry_error * m_diagonal;
    for(std::size_t step = 0; step < m_s.local_refinement_steps && best_error > m_o.target_symmetry_error; ++step) {
      const std::vector<std::uint32_t> unknown =
        local_unknowns(level, neighbours, mirrors, threshold, m_s.local_refinement_rings);
      if(unknown.empty())
        break;
      refine_step(level, mirrors, rho, x, &unknown);
      mirrors = exact_mirrors(level, x, &mirrors);
      const double e = rms_mirror_distance(mirrors, level.weights) / m_diagonal;
      out.iterations.push_back(Iteration_record{0, 1.0, e});
      const bool gained = e < m_s.stall_ratio * best_error;
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
    std::vector<std::uint32_t> identity;
    if(active == nullptr) {
      identity.resize(n);
      std::iota(identity.begin(), identity.end(), 0u);
      active = &identity;
    }
    const double D = m_diagonal;
    Refinement_weights c;
    c.mean_edge = m_levels.front().mean_edge > 0 ? m_levels.front().mean_edge : D;
    c.error = rho / (double(n) * D * D);
    c.edge = 1.0 / double((std::max)(std::size_t(1), level.edges.size()));
    c.eta = 0.01;
    c.displacement = 1e-4 / (double(n) * c.mean_edge * c.mean_edge); // mu = 1e-4
    c.tangential_weight = m_s.tangential_weight;
    Refinement_system system(*active, c);
    system.reserve(mirrors.size(), level);
    const std::vector<Vector_3d> fnormals = Surface{x, level.original.triangles}.face_normals();
    for(std::size_t k = 0; k < mirrors.size(); ++k)
      system.add_mirror_terms(level, mirrors[k], k, m_inverses[k], x, fnormals);
    system.add_edge_terms(level, x);
    system.solve(x);
  }

  const Surface& m_input;
  Symmetrize_options m_o;
  Symmetrizer_settings m_s;
  std::vector<Affine_3d> m_transforms, m_inverses;
  double m_diagonal = 1;
  std::vector<Level> m_levels;
  mutable Step_solver m_step;       // the last solve's factorization, kept
  double m_constrained_ratio = 0;   // alpha / (1 - alpha) of the current constrained steps (run_level())
  double m_error_before = 0;        // RMS mirror distance of the input, relative to the diagonal
  std::vector<std::vector<Mirror>> m_input_mirrors; // the mirror points of the input
  double m_total_work = 0, m_done_work = 0;         // for progress: vertices times steps
};

} // namespace internal
} // namespace Surface_mesh_symmetrization
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_SYMMETRIZATION_INTERNAL_SYMMETRIZATION_H
