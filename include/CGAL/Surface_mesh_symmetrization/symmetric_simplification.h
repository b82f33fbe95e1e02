// Copyright (c) 2026 CGAL Global Shape Analysis contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_SURFACE_MESH_SYMMETRIZATION_SYMMETRIC_SIMPLIFICATION_H
#define CGAL_SURFACE_MESH_SYMMETRIZATION_SYMMETRIC_SIMPLIFICATION_H

/// \file symmetric_simplification.h
/// Symmetric simplification of a nearly symmetric surface: symmetrize, remesh symmetrically,
/// decimate symmetrically, restore the asymmetry (thesis section 2.6.4).

#include <CGAL/Surface_mesh_symmetrization/symmetric_remeshing.h>
#include <CGAL/Surface_mesh_symmetrization/symmetrize.h>
#include <CGAL/Surface_mesh_symmetrization/internal/Restore_splits.h>
#include <CGAL/Surface_mesh_symmetrization/internal/Surface_index.h>
#include <CGAL/Surface_mesh_symmetrization/internal/Symmetric_flips.h>
#include <CGAL/Shape_analysis/internal/Parallel.h>

#include <CGAL/Surface_mesh.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <string>
#include <vector>

namespace CGAL {
namespace Surface_mesh_symmetrization {

/*!
\ingroup PkgSurfaceMeshSymmetrizationRef
What `symmetric_simplification()` did.
*/
struct Symmetric_simplification_result
{
  /// the RMS symmetry error of the input and of its symmetrized surface (see `symmetrize()`)
  double symmetry_error_before = 0, symmetry_error_after = 0;
  /// the remeshing and decimation of the symmetrized surface; its `after` is the connectivity of
  /// the result by its pairs (with the residuals restored, the positions are not mirror images)
  Symmetric_remeshing_result remeshing;
  bool restored = false;                ///< whether the asymmetric residuals were added back
  std::size_t restore_flips = 0;        ///< with them, edges of the decimated mesh flipped towards the input
  /// with them, the side of the plane whose faces the remeshing copied where the sides' connectivity
  /// differs, or whole when `remeshing.copied_whole_side` (1: the side the plane's normal points
  /// to, -1: the other): of the candidates tried, the one whose result came closest to the input
  int copied_side = 1;
  std::size_t faces = 0;                ///< the faces of the result
};

/// \cond SKIP_IN_MANUAL
namespace internal {

// The input's point for a point `p` near the symmetrized surface: `p`, or with `project` its nearest
// point there, moved by the residual interpolated at its nearest point (on a face turned as
// `normal`, when there is one). The meta-mesh's vertices lie on the symmetrized surface, or off it
// by its remaining asymmetry where one side was copied over the other: they keep that offset
// (projected, the PSB meshes 6, 21, 63 and 102 came out farther from the input). The midpoints
// of the refinement below are projected: a chord's midpoint lies off the surface by its sagitta.
template <typename Vector>
Vector_3d restored_point(const Surface_index& surface, const Surface& symmetrized, const std::vector<Vector>& residuals,
                         const Vector_3d& p, const Vector_3d& normal, std::uint32_t& hint, bool project)
{
  Surface_point c = surface.closest_compatible(p, normal, 0.0, hint); // not onto a sheet turned away
  if(!c.found)
    c = surface.closest(p, hint);
  hint = c.face;
  Vector_3d q = project ? c.point : p;
  for(std::size_t k = 0; k < 3; ++k) {
    const Vector& d = residuals[symmetrized.triangles[c.face][k]];
    q += Vector_3d(CGAL::to_double(d.x()), CGAL::to_double(d.y()), CGAL::to_double(d.z())) * c.barycentric[k];
  }
  return q;
}

// Refines `symmetric` (points on or near the symmetrized surface, connectivity mirrored by
// `partner`) and `restored` (the same mesh, each point restored by `restored_point()`) together
// where the restored mesh leaves the input: an edge whose restored midpoint lies farther than
// `tolerance` from the midpoint of its restored ends is split, and so are the three edges of a
// face whose centroid does, and the mirror edge of every split edge. A face with two split edges
// gets its third split too (red-green refinement: faces split in four or in two), so the splits
// and the new pairs stay mirror images. At most `rounds` rounds, none that would take the mesh
// past `max_faces` (where the symmetrization squeezed a part, the restore stretches it without
// bound). New points get their partners; returns the number of points added.
template <typename Vector>
std::size_t refine_restored(Surface& symmetric, Surface& restored, std::vector<std::uint32_t>& partner,
                            const Surface_index& surface, const Surface& symmetrized,
                            const std::vector<Vector>& residuals, double tolerance, std::size_t max_faces, int rounds)
{
  typedef std::array<std::uint32_t, 3> Triangle;
  const std::size_t points_before = symmetric.points.size();
  std::vector<char> fresh(symmetric.triangles.size(), 1); // faces not yet tested
  for(int round = 0; round < rounds; ++round) {
    const Edge_table edges(symmetric.triangles);
    const std::size_t n = edges.ends.size();
    std::vector<char> tested(n, 0), split(n, 0);
    for(std::size_t f = 0; f < symmetric.triangles.size(); ++f)
      for(std::uint32_t e : edges.of_face[f])
        tested[e] |= fresh[f];
    const std::vector<Vector_3d> normals = symmetric.vertex_normals();
    std::vector<Vector_3d> middle(n);
    std::uint32_t hint = Surface_index::no_face;
    for(std::size_t e = 0; e < n; ++e) {
      const std::uint32_t a = edges.ends[e][0], b = edges.ends[e][1];
      middle[e] = restored_point(surface, symmetrized, residuals, (symmetric.points[a] + symmetric.points[b]) * 0.5,
                                 normals[a] + normals[b], hint, true);
      split[e] = tested[e] && (middle[e] - (restored.points[a] + restored.points[b]) * 0.5).length() > tolerance;
    }
    for(std::size_t f = 0; f < symmetric.triangles.size(); ++f) {
      const Triangle& t = symmetric.triangles[f];
      if(fresh[f] && (restored_point(surface, symmetrized, residuals,
                                     (symmetric.points[t[0]] + symmetric.points[t[1]] + symmetric.points[t[2]]) / 3.0,
                                     symmetric.area_vector(f), hint, true) -
                      (restored.points[t[0]] + restored.points[t[1]] + restored.points[t[2]]) / 3.0)
                         .length() > tolerance)
        for(std::uint32_t e : edges.of_face[f])
          split[e] = 1;
    }
    const auto mirror_edge = [&](std::size_t e) { return edges.mirror(std::uint32_t(e), partner); };
    for(bool changed = true; changed;) { // closure: mirror edges, then faces with two split edges
      changed = false;
      for(std::size_t e = 0; e < n; ++e) {
        const std::uint32_t m = split[e] ? mirror_edge(e) : no_partner;
        if(m != no_partner && !split[m])
          split[m] = 1, changed = true;
      }
      for(const Triangle& fe : edges.of_face)
        if(split[fe[0]] + split[fe[1]] + split[fe[2]] == 2)
          split[fe[0]] = split[fe[1]] = split[fe[2]] = 1, changed = true;
    }
    std::size_t faces = 0;
    for(const Triangle& fe : edges.of_face)
      faces += std::size_t(1) << (split[fe[0]] + split[fe[1]] + split[fe[2]] + 1) / 2; // 1, 2 or 4
    if(faces == symmetric.triangles.size() || faces > max_faces)
      break;
    std::vector<std::uint32_t> middle_point(n, no_partner);
    for(std::size_t e = 0; e < n; ++e)
      if(split[e]) {
        middle_point[e] = std::uint32_t(symmetric.points.size());
        symmetric.points.push_back((symmetric.points[edges.ends[e][0]] + symmetric.points[edges.ends[e][1]]) * 0.5);
        restored.points.push_back(middle[e]);
        partner.push_back(no_partner);
      }
    for(std::size_t e = 0; e < n; ++e) {
      const std::uint32_t m = split[e] ? mirror_edge(e) : no_partner;
      if(m != no_partner)
        partner[middle_point[e]] = middle_point[m];
    }
    split_faces(symmetric.triangles, edges, split, middle_point, fresh);
    restored.triangles = symmetric.triangles;
  }
  return symmetric.points.size() - points_before;
}

// The refinement of the restored meta-mesh: how far (relative to the diagonal) it may leave the
// input, at most how many times its faces it may grow to, in at most how many rounds. One round,
// Hausdorff distance to the input at a fifth of the faces (of the diagonal), none -> one round:
// PSB mesh 1 0.0151 -> 0.0100, 143 0.00183 -> 0.00118, 63 0.00159 -> 0.00154, 6 0.0027 ->
// 0.0039, the cow 0.00844 -> 0.00848 (with the decimation's former quadrics, its faces' own
// planes). More rounds refine the asymmetric regions further, and the decimation then collapses
// the rest first: with the input's quadrics (provenance_quadrics()), two and three rounds give
// the cow 0.0081 and 0.025, PSB mesh 1 0.0092 and 0.0109, against 0.0070 and 0.0059 with one;
// but PSB 141 0.00078 and 142 0.00099 with two against 0.00089 and 0.00105: so the best candidate
// of restore_closest_candidate() is tried again with two.
constexpr double restore_tolerance = 5e-4;
constexpr std::size_t refinement_face_budget = 4;
constexpr int refinement_rounds = 1;

// How one candidate of restore_closest_candidate() is restored: the refinement's tolerance
// (relative to the diagonal) and rounds, and whether the restored points are snapped onto the
// input first (see restore_and_decimate()).
struct Restore_pass
{
  double tolerance = restore_tolerance;
  int rounds = refinement_rounds;
  bool snap = false;
};

// The last candidate: the closest copy of a whole side, finer and snapped. Where the two sides'
// creases do not match after the symmetrization, the copied points keep their offset from the
// input (up to 8e-4 of the diagonal on PSB mesh 141, a table) and the faces between them cut
// across its creases (1e-3 with one round of refinement); snapped and refined to 2e-4 in four
// rounds, the result of 141 at a fifth of the faces comes within 1.47 times Garland-Heckbert's
// distance instead of 3.6 (three rounds 1.89, five 1.50; unsnapped 1.70; 1e-4 or 3e-4 farther;
// on the closest candidate, a remeshing there, 2.4). For every candidate (2e-4, three rounds,
// unsnapped) it does worse on most meshes (PSB 1 1.76, 142 1.48, 242 1.36 against 1.00, 1.19,
// 1.16): the decimation then spends its collapses on the refined regions; so it is one more
// candidate, kept only when closer.
constexpr Restore_pass fine_restore_pass{2e-4, 4, true};

// The flips after the restore path's decimation (Symmetric_flipper): a pair of mirror edges flips
// when its quads' sample points come to 0.8 of their largest distance to the input or closer,
// from farther than 1e-5 of the diagonal, neither quad getting farther; at most ten rounds. At a
// fifth of the faces, Hausdorff distance to the input without -> with them: PSB mesh 22 0.00101
// -> 0.00085, 41 0.00174 -> 0.00161, 141 0.00094 -> 0.00089, 142 0.00129 -> 0.00128, 321 0.00123
// -> 0.00117, the cow 0.00698 -> 0.00698. Judged on both quads together (the largest distance
// over the two only), 22, 142 and the cow gain more (0.00081, 0.00121, 0.00672) but the
// mechanical part 321 loses (0.00181): a quad may then move away from the input. (Gains of 0.6
// and 0.95 do worse; the same flips before the decimation, on the restored meta-mesh, are worse
// on 22 and the cow; on the symmetric remeshing, against the symmetrized surface, they help 322,
// 323 and the camel but hurt 321 and the cow.)
constexpr double restore_flip_gain = 0.8;
constexpr double restore_flip_floor = 1e-5;
constexpr int restore_flip_rounds = 10;

// The last step of the restore path: the decimation stops 5% of the faces short of the count, its
// points still farther than 2e-4 of the diagonal from the input move onto it (snap_onto()), and
// the faces left are spent where the result is farthest from the input (split_farthest(): eight
// rounds, each face's own points on a grid of 8, the input's vertices and edge midpoints); the
// closer of that and the plain decimation is kept, measured on a grid of 6 on both surfaces (28
// points a face: on a grid of 3, which the splits had just been aimed at, the mechanical part PSB
// 321 chose the splits and came out at 0.00109 of the diagonal instead of 0.00066; now 0.00039).
// At a fifth of the faces, over Garland-Heckbert's Hausdorff distance, plain -> the closer of the
// two (bench_symmetric_remeshing): PSB 141 1.47 -> 1.22, 1 1.02 -> 0.74, 142 1.19 -> 1.13, 102
// 0.66 -> 0.60, 302 0.96 -> 0.35, 41 1.16 -> 1.14, but 22 1.11 -> 1.16; all 19 nearly symmetric
// meshes of the manual within 1.25. Without the choice, 242 1.16 -> 1.31, 241 1.06 -> 1.21 (the
// choice keeps the plain decimation there). On 141, a grid of 3 or 5 for the splits: 1.30 and
// 1.24; spending 3% or 10% of the faces (grid 5): 1.35, 1.25; snapping from 1e-4, 1.5e-4 or 3e-4:
// 1.52 (grid 3), 1.23, 1.23.
constexpr double restore_split_fraction = 0.05;
constexpr double restore_snap_distance = 2e-4;
constexpr int restore_split_rounds = 8;
constexpr std::uint32_t restore_split_grid = 8;
constexpr std::uint32_t restore_choice_grid = 6;
static_assert(restore_choice_grid % 3 == 0, "the choice's grid holds the grid of 3 of the distances");

// Per vertex of `s` (the restored meta-mesh), the quadric of the planes of the input faces its
// faces lie on (each face mapped by `index`, the input's, to the input face nearest to its
// centroid, turned its way), each plane once. The faces' own planes are not used: the remeshing's
// slivers, restored, have noisy normals, and a face split in k pieces would count k times. At a fifth of the faces, Hausdorff
// distance over CGAL's Garland-Heckbert, own planes plus each input face's plane at the nearest
// vertex -> these (with the T clusters of the decimation): PSB mesh 1 1.70 -> 1.00, 6 1.52 ->
// 1.18, 22 1.78 -> 1.24, 221 1.35 -> 1.04, 242 1.59 -> 1.22, the cow 0.84 -> 0.69.
inline std::vector<Symmetric_decimator::Quadric> provenance_quadrics(const Surface& s, const Surface& input,
                                                                   const Surface_index& index)
{
  std::vector<std::vector<std::uint32_t>> planes(s.points.size());
  std::uint32_t hint = Surface_index::no_face;
  for(std::size_t f = 0; f < s.triangles.size(); ++f) {
    const auto c = s.corners(f);
    Surface_point p = index.closest_compatible((c[0] + c[1] + c[2]) / 3.0, s.area_vector(f), 0.0, hint);
    if(!p.found)
      p = index.closest((c[0] + c[1] + c[2]) / 3.0, hint);
    if(!p.found)
      continue; // (an input without a face of nonzero area)
    hint = p.face;
    for(std::uint32_t v : s.triangles[f])
      if(std::find(planes[v].begin(), planes[v].end(), p.face) == planes[v].end())
        planes[v].push_back(p.face);
  }
  std::vector<Symmetric_decimator::Quadric> q(s.points.size(), Symmetric_decimator::Quadric::Zero());
  for(std::size_t v = 0; v < s.points.size(); ++v)
    for(std::uint32_t g : planes[v]) {
      const auto c = input.corners(g);
      const Vector_3d a = input.area_vector(g);
      const double l = a.length();
      if(!(l > 0))
        continue;
      q[v] += Symmetric_decimator::plane_quadric(a / l, c[0]);
    }
  return q;
}

// An estimate of the two-sided Hausdorff distance between the surfaces of `a` and `b`: the largest
// distance to the other surface of the points of every face at barycentric coordinates (i, j, k) /
// `grid` (Surface_index::samples_of(); a grid of 3: its corners, two points on each edge and its
// centroid). With `coarse`, a multiple of 3 as `grid`, and in `coarse` the estimate on the grid of
// 3 (the points of the grid whose coordinates are multiples of grid / 3: the same points), from
// the same pass. Faces in parallel; the result does not depend on the number of threads.
inline double sampled_hausdorff(const Surface_index& a, const Surface_index& b, std::size_t threads,
                                std::uint32_t grid = 3, double* coarse = nullptr)
{
  std::vector<char> on_coarse; // per point of a face's grid, numbered as samples_of() does
  for(std::uint32_t i = 0; i <= grid; ++i)
    for(std::uint32_t k = 0; i + k <= grid; ++k)
      on_coarse.push_back(grid % 3 == 0 && i % (grid / 3) == 0 && k % (grid / 3) == 0);
  double largest = 0, largest_coarse = 0;
  for(const auto* pair : {&a, &b}) {
    const Surface& s = pair->surface();
    const Surface_index& other = pair == &a ? b : a;
    std::vector<double> d(s.triangles.size(), 0), d_coarse(s.triangles.size(), 0);
    SAI::Parallel_workspaces<std::uint32_t> hints(threads);
    hints.for_each(0, s.triangles.size(), [&](std::size_t f, std::uint32_t& hint) {
      Surface_index::samples_of(s.corners(f), grid, [&](const Vector_3d& p, std::uint32_t number) {
        const Surface_point q = other.closest(p, hint);
        if(q.found) {
          hint = q.face;
          d[f] = (std::max)(d[f], q.squared_distance);
          if(on_coarse[number])
            d_coarse[f] = (std::max)(d_coarse[f], q.squared_distance);
        }
      });
    });
    for(std::size_t f = 0; f < d.size(); ++f)
      largest = (std::max)(largest, d[f]), largest_coarse = (std::max)(largest_coarse, d_coarse[f]);
  }
  if(coarse)
    *coarse = std::sqrt(largest_coarse);
  return std::sqrt(largest);
}

// Moves the points of `s` farther than `distance` from the input (`index`) to their closest points
// there.
inline void snap_onto(Surface& s, const Surface_index& index, double distance)
{
  std::uint32_t hint = Surface_index::no_face;
  for(Vector_3d& p : s.points) {
    const Surface_point q = index.closest(p, hint);
    if(!q.found)
      continue;
    hint = q.face;
    if(q.squared_distance > distance * distance)
      p = q.point;
  }
}

// The restore path of symmetric_simplification() on `out`, the symmetric remeshing of the
// symmetrized surface (its pairs `partner`): its points restored (with `pass.snap`, those still
// farther than half the tolerance from the input then moved onto it), refined where the restored
// mesh leaves the input (`pass`), decimated to `faces` with the input's quadrics and flipped
// towards the input's creases; or decimated on to 95% of `faces`, flipped, snapped and split where
// it is farthest from the input back up to `faces`: of the two, the closer to the input
// (sampled_hausdorff(), in `distance`; `threads` for the distances, the result does not depend on
// it). Returns the number of flips.
template <typename Vector>
std::size_t restore_and_decimate(Surface& out, std::vector<std::uint32_t>& partner, const Surface_index& index,
                                 const Surface& symmetrized, const std::vector<Vector>& residuals,
                                 const Surface& input, const Surface_index& input_index, std::size_t faces,
                                 const Restore_pass& pass, std::size_t threads, double& distance)
{
  Surface symmetric = out;
  const std::vector<Vector_3d> normals = out.vertex_normals();
  std::uint32_t hint = Surface_index::no_face;
  for(std::size_t i = 0; i < out.points.size(); ++i)
    out.points[i] = restored_point(index, symmetrized, residuals, symmetric.points[i], normals[i], hint, false);
  const double tolerance = pass.tolerance * symmetrized.diagonal();
  if(pass.snap)
    snap_onto(out, input_index, 0.5 * tolerance);
  refine_restored(symmetric, out, partner, index, symmetrized, residuals, tolerance,
                  refinement_face_budget * out.triangles.size(), pass.rounds);
  const std::vector<Symmetric_decimator::Quadric> quadrics = provenance_quadrics(out, input, input_index);
  Symmetric_decimator decimator(out, partner, false, &quadrics);
  const auto decimate_to = [&](std::size_t n) {
    while(decimator.number_of_faces() > n && (decimator.step() || decimator.allow_other_positions())) {
    }
  };
  // The decimated mesh's diagonals turned towards the input's creases.
  const auto flip = [&](Surface& s, const std::vector<std::uint32_t>& pairs) {
    Symmetric_flipper flipper(s, pairs, input_index);
    const std::size_t n =
      flipper.flip(restore_flip_gain, restore_flip_floor * symmetrized.diagonal(), restore_flip_rounds);
    flipper.export_surface(s);
    return n;
  };
  decimate_to(faces);
  Surface whole;
  std::vector<std::uint32_t> whole_partner;
  decimator.export_surface(whole, whole_partner);
  const std::size_t whole_flips = flip(whole, whole_partner);
  // Or the last faces spent where the result is farthest from the input: the closer of the two.
  decimate_to(faces - std::size_t(restore_split_fraction * double(faces)));
  decimator.export_surface(out, partner);
  const std::size_t flips = flip(out, partner);
  snap_onto(out, input_index, restore_snap_distance * symmetrized.diagonal());
  split_farthest(out, partner, input_index, faces, restore_split_rounds, restore_split_grid, threads);
  // Chosen on the finer grid; `distance` on the grid of 3 that compares the candidates.
  double split_distance = 0, whole_distance = 0;
  const Surface_index split_index(out), whole_index(whole);
  if(sampled_hausdorff(split_index, input_index, threads, restore_choice_grid, &split_distance) <
     sampled_hausdorff(whole_index, input_index, threads, restore_choice_grid, &whole_distance)) {
    distance = split_distance;
    return flips;
  }
  distance = whole_distance;
  out = std::move(whole);
  partner = std::move(whole_partner);
  return whole_flips;
}

// The restore path's choice among the remeshings of `work` (the symmetrized mesh): the remeshing
// and the copy of a whole side (only the latter with `ro.copy_one_side`), each copying either side
// of `symmetry`'s plane, each restored and decimated (restore_and_decimate()), then the best of
// them with one more round of refinement; the result closest to `input` (sampled_hausdorff()) goes
// to `out`, what made it to `r`.
template <typename Work, typename Kernel, typename Vector>
void restore_closest_candidate(const Work& work, const Symmetry<Kernel>& symmetry,
                               const Symmetric_remeshing_options& ro, std::size_t threads, const Surface& symmetrized,
                               const std::vector<Vector>& residuals, const Surface& input, std::size_t faces,
                               Symmetric_simplification_result& r, Surface& out)
{
  // The remeshing copies one side's faces over the other's where their connectivity differs:
  // restored, the copy may follow the other side's creases better one way than the other (PSB
  // meshes 41 and 241, at a fifth of the faces: 1.46 and 1.29 times Garland-Heckbert's distance
  // copying the positive side, 1.16 and 1.18 copying the negative one), and the copy of a whole
  // side, whose faces are the input's own there, may be closer than either (PSB 142: 1.27
  // against 1.53; 141: 4.5 against 4.1). The four are tried, then the best of them with one more
  // round of refinement; the one closest to the input is kept.
  const Surface_index index(symmetrized), input_index(input);
  Symmetry<Kernel> opposite = symmetry;
  opposite.plane = symmetry.plane.opposite();
  struct Remeshed // a candidate before its restore
  {
    Surface surface;
    std::vector<std::uint32_t> partner;
    Symmetric_remeshing_result result;
    int side;
  };
  std::string first_error;
  const auto remesh = [&](bool whole_side, int side, Remeshed& m) {
    Work copy = work;
    try {
      m.result = Surface_mesh_symmetrization::symmetric_remeshing(
        copy, side > 0 ? symmetry : opposite,
        parameters::number_of_faces(std::size_t(-1)).pairing_tolerance(ro.pairing_tolerance).copy_one_side(whole_side));
    } catch(const Bad_input& e) { // (that side, copied, is not a manifold surface: the others stand)
      if(first_error.empty())
        first_error = e.what();
      return false;
    }
    m.surface = read_mesh_np(copy, parameters::default_values(), "symmetric_simplification").surface;
    for(std::size_t v : m.result.after.mirror_vertex)
      m.partner.push_back(v == Symmetric_connectivity::no_vertex ? no_partner : std::uint32_t(v));
    m.side = side;
    return true;
  };
  double best = 0;
  bool found = false;
  // Restores, decimates and measures `m` (its distance to `distance`); whether it is the closest
  // so far (then in `out`, `r`).
  const auto evaluate = [&](const Remeshed& m, const Restore_pass& pass, double& distance) {
    Surface candidate = m.surface;
    std::vector<std::uint32_t> partner = m.partner;
    const std::size_t flips = restore_and_decimate(candidate, partner, index, symmetrized, residuals, input,
                                                   input_index, faces, pass, threads, distance);
    if(found && !(distance < best))
      return false;
    found = true;
    best = distance;
    out = std::move(candidate);
    r.remeshing = m.result;
    r.remeshing.faces = out.triangles.size();
    r.remeshing.after = public_connectivity(out, partner);
    r.restore_flips = flips;
    r.copied_side = m.side;
    return true;
  };
  std::vector<Remeshed> made; // the candidates; the closest one, the closest copy of a whole side
  const std::size_t none = std::size_t(-1);
  std::size_t closest = 0, closest_copy = none;
  double copy_distance = 0, distance = 0;
  for(bool whole_side : {false, true})
    for(int side : {1, -1}) {
      Remeshed m;
      if(!(whole_side || !ro.copy_one_side) || !remesh(whole_side, side, m))
        continue;
      if(evaluate(m, Restore_pass(), distance))
        closest = made.size();
      if(m.result.copied_whole_side && (closest_copy == none || distance < copy_distance))
        copy_distance = distance, closest_copy = made.size();
      made.push_back(std::move(m));
    }
  if(found) { // the closest once more, refined further; the closest copy finer, snapped
    Restore_pass further;
    further.rounds = refinement_rounds + 1;
    evaluate(made[closest], further, distance);
    if(closest_copy != none)
      evaluate(made[closest_copy], fine_restore_pass, distance);
  }
  if(!found)
    throw Bad_input(first_error);
}

} // namespace internal
/// \endcond

/*!
\ingroup PkgSurfaceMeshSymmetrizationRef

Simplifies `tm` to `number_of_faces` faces with a connectivity that mirrors itself across the plane
of `symmetry`, whether or not its surface is symmetric (thesis section 2.6.4): a copy of the
surface is symmetrized (`symmetrize()`, which also gives each vertex its asymmetric residual, the
input position minus the symmetrized one) and remeshed symmetrically (`symmetric_remeshing()`).
Without `restore_residuals` it is then decimated symmetrically (`symmetric_decimation()`): the
result is the symmetric mesh. With it, each vertex of that mesh first moves by the residual
interpolated at its place on the symmetrized surface; where the mesh so restored leaves the input
by more than \f$5 \cdot 10^{-4}\f$ of the diagonal (at an edge's midpoint or a face's centroid,
mapped the same way), that edge and its mirror edge are split once, the faces around them split in
two or four so that the connectivity stays mirrored (at most four times the faces); the decimation
then keeps the vertex pairs of the symmetric connectivity but places each merged vertex at the
optimum of its own quadric, so that the result follows the input's surface again. Those quadrics
are the input's: each vertex starts with the planes of the input faces that its faces lie on
(each face of the restored mesh mapped to the input face nearest to its centroid, each plane once
per vertex), so that, where the restored mesh follows the input, an original vertex starts with
the quadric Garland and Heckbert give it and a point the remeshing inserted inside a face with that
face's plane alone.
Last, pairs of mirror edges of the decimated mesh are flipped together where the new diagonals
bring the faces of both quads closer to the input (their largest distance down by a fifth at
least, neither quad farther than before), to follow the input's creases; the connectivity stays
mirrored. The decimation is also carried on to 95% of `number_of_faces`, its points still farther
than \f$2 \cdot 10^{-4}\f$ of the diagonal from the input moved onto it, and the faces left
spent where it is farthest from the input (in eight rounds, a face whose farthest point is the
input's gets that point as a vertex, the others their longest edge split, each with its mirror
face or edge, the new points on the input); of the two, the one closer to the input is kept.
Where the two sides' connectivity differs, the remeshing copies one side's faces over
the other's, and restored, one side's copy may follow the other side's creases better than the
reverse, and the copy of a whole side (`copy_one_side`), whose faces are the input's own there,
better than both: with `restore_residuals`, all of the above runs four times, remeshing and
copying a whole side, each copying either side, then once more for the best of them with a second
round of refinement, and once more for the best copy of a whole side with a finer refinement
(\f$2 \cdot 10^{-4}\f$ of the diagonal, four rounds; its restored points still farther than half
that from the input first move to their closest points there, where the two sides' creases do not
match), and the result closest to the input is kept (the larger of the two one-sided
distances between the result and the input, sampled at ten points per face;
`Symmetric_simplification_result::copied_side` and `remeshing.copied_whole_side` tell which; with
`copy_one_side`, only the copies of a whole side are tried). The result does not depend on the
orientation of the plane's normal.

\tparam TriangleMesh a model of `MutableFaceGraph` and `FaceListGraph`
\tparam Kernel the kernel of the symmetry
\tparam NamedParameters a sequence of named parameters
\param tm a closed manifold triangle mesh
\param symmetry a reflective symmetry (`Symmetry::is_reflection`), detected on `tm` say
\param np an optional sequence of named parameters among the ones listed below

\cgalNamedParamsBegin
  \cgalParamNBegin{number_of_faces}
    \cgalParamDescription{the number of faces of the result (within the faces of one collapse); required}
    \cgalParamType{`std::size_t`}
  \cgalParamNEnd
  \cgalParamNBegin{restore_residuals}
    \cgalParamDescription{whether the result is moved back onto the input's surface}
    \cgalParamType{`bool`}
    \cgalParamDefault{`true`}
  \cgalParamNEnd
  \cgalParamNBegin{pairing_tolerance}
    \cgalParamDescription{as for `measure_symmetric_connectivity()`}
    \cgalParamType{`double`}
    \cgalParamDefault{`Symmetric_remeshing_options::pairing_tolerance`}
  \cgalParamNEnd
  \cgalParamNBegin{copy_one_side}
    \cgalParamDescription{copy a whole side across the plane instead of remeshing (see `symmetric_remeshing()`)}
    \cgalParamType{`bool`}
    \cgalParamDefault{`Symmetric_remeshing_options::copy_one_side`}
  \cgalParamNEnd
  \cgalParamNBegin{number_of_threads}
    \cgalParamDescription{the largest number of threads of the symmetrization and of the comparison
                          of the candidates with the input (0: all cores); the result does not
                          depend on it}
    \cgalParamType{`std::size_t`}
    \cgalParamDefault{0}
  \cgalParamNEnd
  \cgalParamNBegin{vertex_point_map}
    \cgalParamDescription{a property map associating points to the vertices of `tm`}
    \cgalParamDefault{`get_property_map(CGAL::vertex_point, tm)`}
  \cgalParamNEnd
\cgalNamedParamsEnd
The other named parameters of `symmetrize()` (`number_of_iterations`, `final_symmetry_weight`,
`target_symmetry_error`, ...) are passed to it.

\returns the symmetry errors, what the remeshing did and the number of faces

\throws CGAL::Shape_analysis::Bad_input if `number_of_faces` is missing, 0 or above the mesh's,
        and as `symmetrize()` and `symmetric_remeshing()`; `tm` is then unchanged
*/
template <typename TriangleMesh, typename Kernel, typename NamedParameters = parameters::Default_named_parameters>
Symmetric_simplification_result symmetric_simplification(TriangleMesh& tm, const Symmetry<Kernel>& symmetry,
                                                         const NamedParameters& np = parameters::default_values())
{
  using CGAL::Shape_analysis::internal::parameter_value;
  namespace snp = CGAL::Shape_analysis::internal_np;
  const std::string who = "symmetric_simplification";
  const std::size_t faces = parameter_value(np, snp::number_of_faces_tag, std::size_t(0));
  const bool restore = parameter_value(np, snp::restore_residuals_tag, true);
  const Symmetric_remeshing_options ro = symmetric_remeshing_options(np);
  const Symmetrize_options so = symmetrize_options(np);
  const internal::Mesh_arrays<TriangleMesh> input = internal::read_mesh_np(tm, np, who);
  if(faces == 0 || faces > input.surface.triangles.size())
    throw Bad_input(who + ": number_of_faces must be between 1 and the mesh's " +
                    std::to_string(input.surface.triangles.size()) + " (got " + std::to_string(faces) + ")");
  if(!symmetry.is_reflection)
    throw Bad_input(who + ": the symmetry is not a reflection (only reflective symmetries are supported)");

  // The symmetrized copy, in the input's vertex order.
  typedef CGAL::Surface_mesh<typename Kernel::Point_3> Work;
  Work work;
  std::vector<typename Work::Vertex_index> v;
  for(const internal::Vector_3d& p : input.surface.points)
    v.push_back(work.add_vertex(typename Kernel::Point_3(p.x, p.y, p.z)));
  for(const auto& t : input.surface.triangles)
    if(work.add_face(v[t[0]], v[t[1]], v[t[2]]) == Work::null_face())
      throw Bad_input(who + ": the mesh is not manifold (or has a face twice)");
  const Symmetrization_result<Kernel> s =
    symmetrize(work, std::vector<Symmetry<Kernel>>{symmetry},
               parameters::number_of_iterations(so.number_of_iterations)
                 .shape_weight(so.shape_weight)
                 .displacement_weight(so.displacement_weight)
                 .number_of_levels(so.number_of_levels)
                 .coarsest_level_size(so.coarsest_level_size)
                 .symmetry_tolerance(so.symmetry_tolerance)
                 .target_symmetry_error(so.target_symmetry_error)
                 .final_symmetry_weight(so.final_symmetry_weight)
                 .support_weighting(so.support_weighting)
                 .number_of_threads(so.number_of_threads)
                 .progress_callback(so.progress_callback));
  internal::Surface symmetrized;
  symmetrized.triangles = input.surface.triangles;
  for(const auto& p : s.symmetric_points)
    symmetrized.points.emplace_back(CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z()));

  Symmetric_simplification_result r;
  r.symmetry_error_before = s.symmetry_error_before;
  r.symmetry_error_after = s.symmetry_error_after;
  // Without restoring: the symmetric mesh remeshed and decimated. Restoring: the symmetric mesh
  // remeshed, its vertices moved back onto the input's surface, then decimated with the pairs of
  // the symmetric connectivity, each vertex at the optimum of its own quadric, made of the planes
  // of the input faces under its faces.
  internal::Surface out;
  if(!restore) {
    r.remeshing = symmetric_remeshing(work, symmetry,
                                      parameters::number_of_faces(faces)
                                        .pairing_tolerance(ro.pairing_tolerance)
                                        .copy_one_side(ro.copy_one_side));
    out = internal::read_mesh_np(work, parameters::default_values(), who).surface;
  } else
    internal::restore_closest_candidate(work, symmetry, ro, so.number_of_threads, symmetrized, s.residuals,
                                        input.surface, faces, r, out);
  r.restored = restore;
  r.faces = out.triangles.size();
  internal::rebuild_mesh(tm, out, np);
  return r;
}

} // namespace Surface_mesh_symmetrization
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_SYMMETRIZATION_SYMMETRIC_SIMPLIFICATION_H
