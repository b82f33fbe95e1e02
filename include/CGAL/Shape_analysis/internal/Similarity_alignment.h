// Copyright (c) 2026 CGAL Global Shape Analysis contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_SHAPE_ANALYSIS_INTERNAL_SIMILARITY_ALIGNMENT_H
#define CGAL_SHAPE_ANALYSIS_INTERNAL_SIMILARITY_ALIGNMENT_H

// Alignment of two point sets by a similarity transform x -> s R x + t (rotation R, uniform scale
// s > 0, translation t), independent of any mesh type:
//   - the weighted principal frame (PCA) of a point set;
//   - the 24 proper orientations of a frame's axes (signed permutation matrices of determinant
//     +1), the candidate rotations between two principal frames whose axes may be swapped or
//     flipped;
//   - the closed-form best similarity between weighted point pairs (least squares; the rotation
//     from the SVD of the cross-covariance, with a reflection fix);
//   - ICP with scale: closest points in both directions (source to target and target to source:
//     closest sample points through kd-trees, or closest surface points through CGAL's AABB
//     tree), the worst pairs of each direction trimmed, then the closed-form similarity of the
//     kept pairs (or, on surfaces, a Gauss-Newton step on the distances to the tangent planes),
//     until the trimmed RMS distance stops decreasing;
//   - restarts from the 24 orientations of the principal frames: a coarse stage on a subset of
//     the samples, a refinement of the best few candidates with every sample, and a last stage
//     against the surfaces when they are given.
// Everything is deterministic: the restarts are independent work items (any thread count gives
// the same result) and ties are broken by index.
//
// The closed-form part (matrices, similarity transforms, principal frames, orientations, best
// similarity of point pairs) is in Similarity_transform.h.

#include <CGAL/Shape_analysis/internal/Parallel.h>
#include <CGAL/Shape_analysis/internal/Nearest_sample_tree.h>
#include <CGAL/Shape_analysis/internal/Similarity_transform.h>
#include <CGAL/Shape_analysis/internal/Vector_3d.h>

#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/AABB_triangle_primitive.h>
#include <CGAL/Simple_cartesian.h>

#include <Eigen/Dense>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numeric>
#include <utility>
#include <vector>

namespace CGAL {
namespace Shape_analysis {
namespace internal {

// ---------------------------------------------------------------------------------------------
// Closest points: among sample points (kd-tree) or on a triangulated surface (AABB tree).

// The closest of a set of points.
class Closest_sample
{
public:
  Closest_sample() = default;
  explicit Closest_sample(const std::vector<Vector_3d>& points)
    : m_points(points), m_tree(points)
  {}

  bool empty() const { return m_points.empty(); }

  static constexpr bool has_normals = false;

  // The closest point to `q` (no normal: `normal` is left unchanged).
  Vector_3d operator()(const Vector_3d& q, Vector_3d* normal = nullptr) const
  {
    (void)normal;
    return m_points[m_tree.nearest(q)];
  }

private:
  std::vector<Vector_3d> m_points;
  Nearest_sample_tree m_tree;
};

// The closest point of a triangulated surface (triangles of zero area are left out). Queries are
// thread-safe once built.
class Closest_surface_point
{
public:
  typedef CGAL::Simple_cartesian<double> K;
  typedef K::Triangle_3 Triangle;
  typedef std::vector<Triangle>::const_iterator Iterator;
  typedef CGAL::AABB_triangle_primitive<K, Iterator> Primitive;
  typedef CGAL::AABB_traits<K, Primitive> Traits;
  typedef CGAL::AABB_tree<Traits> Tree;

  explicit Closest_surface_point(const std::vector<std::array<Vector_3d, 3>>& triangles)
  {
    m_triangles.reserve(triangles.size());
    for(const auto& t : triangles)
      if(cross(t[1] - t[0], t[2] - t[0]).squared_length() > 0)
        m_triangles.emplace_back(point(t[0]), point(t[1]), point(t[2]));
    m_tree.rebuild(m_triangles.begin(), m_triangles.end());
    if(!m_triangles.empty())
      m_tree.accelerate_distance_queries();
  }
  Closest_surface_point(const Closest_surface_point&) = delete;
  Closest_surface_point& operator=(const Closest_surface_point&) = delete;

  bool empty() const { return m_triangles.empty(); }

  static constexpr bool has_normals = true;

  // The closest point to `q`, and the unit normal of its triangle in `normal` if not null.
  Vector_3d operator()(const Vector_3d& q, Vector_3d* normal = nullptr) const
  {
    const auto c = m_tree.closest_point_and_primitive(point(q));
    if(normal != nullptr) {
      const Triangle& t = *c.second;
      const Vector_3d a(t[0].x(), t[0].y(), t[0].z()), b(t[1].x(), t[1].y(), t[1].z()),
        d(t[2].x(), t[2].y(), t[2].z());
      const Vector_3d n = cross(b - a, d - a);
      const double l = n.length();
      *normal = l > 0 ? n / l : Vector_3d(0.0);
    }
    return Vector_3d(c.first.x(), c.first.y(), c.first.z());
  }

private:
  static K::Point_3 point(const Vector_3d& v) { return K::Point_3(v.x, v.y, v.z); }

  std::vector<Triangle> m_triangles;
  Tree m_tree;
};

// ---------------------------------------------------------------------------------------------
// ICP with scale between two shapes, each given by sample points and a closest-point query.

struct Icp_options
{
  std::size_t max_iterations = 50;
  // Stop when the trimmed RMS distance decreased by less than this fraction in one iteration.
  double tolerance = 1e-5;
  // Fraction of the pairs of each direction kept (the closest ones), in (0, 1].
  double keep_fraction = 0.9;
  // Pairs from target points to their closest source points too (otherwise source to target
  // only; a scale is then only reliable when the source covers a part of the target).
  bool symmetric = true;
  bool with_scale = true;
  // With closest points that have normals (surfaces): minimize the distances to the tangent
  // planes at the closest points (Gauss-Newton steps; converges in a few iterations near the
  // solution) rather than to the closest points themselves (closed form; converges linearly).
  bool point_to_plane = true;
  // Threads for the closest-point queries of one ICP (1: the calling thread only).
  std::size_t number_of_threads = 1;
};

struct Icp_result
{
  Similarity_3d transform;
  double rms = std::numeric_limits<double>::infinity(); // trimmed RMS distance of `transform`
  std::size_t iterations = 0;
  bool converged = false;
};

// Buffers of one ICP, reused from call to call.
struct Icp_workspace
{
  std::vector<std::pair<double, std::uint32_t>> forward, backward; // (squared distance, point)
  std::vector<Vector_3d> forward_match, backward_match;             // the closest other point
  std::vector<Vector_3d> forward_normal, backward_normal;           // its normal (surfaces)
  std::vector<std::pair<double, std::uint32_t>> sorted;
  std::vector<Vector_3d> from, to;                                  // the kept pairs
  std::vector<Vector_3d> normals; // of the kept pairs, in target coordinates (point to plane)
};

// Rotation by the vector `w` (axis times angle in radians).
inline Matrix_3d rotation_from_vector(const Vector_3d& w)
{
  const double angle = w.length();
  if(!(angle > 0))
    return identity_matrix();
  const Vector_3d u = w / angle;
  const double c = std::cos(angle), s = std::sin(angle), t = 1 - c;
  return {{Vector_3d(t * u.x * u.x + c, t * u.x * u.y - s * u.z, t * u.x * u.z + s * u.y),
           Vector_3d(t * u.x * u.y + s * u.z, t * u.y * u.y + c, t * u.y * u.z - s * u.x),
           Vector_3d(t * u.x * u.z - s * u.y, t * u.y * u.z + s * u.x, t * u.z * u.z + c)}};
}

// One Gauss-Newton step for the similarity T' = U o t, U close to the identity, minimizing
// sum_i (n_i . (T'(from_i) - to_i))^2: the sum of squared distances of the moved points to the
// planes through `to_i` of unit normals `n_i` (zero normals are ignored). With p_i = t(from_i)
// and m their mean, U(x) = e^sigma R_omega (x - m) + m + delta, linearized as
// x + omega x (x - m) + sigma (x - m) + delta. Returns false when the system is singular.
inline bool point_to_plane_step(const Similarity_3d& t, const std::vector<Vector_3d>& from,
                                const std::vector<Vector_3d>& to,
                                const std::vector<Vector_3d>& normals, bool with_scale,
                                Similarity_3d& result)
{
  const std::size_t n = (std::min)(from.size(), (std::min)(to.size(), normals.size()));
  if(n < 7)
    return false;
  std::vector<Vector_3d> moved(n);
  Vector_3d m;
  for(std::size_t i = 0; i < n; ++i) {
    moved[i] = t(from[i]);
    m += moved[i];
  }
  m = m / double(n);
  typedef Eigen::Matrix<double, 7, 7> Matrix7;
  typedef Eigen::Matrix<double, 7, 1> Vector7;
  Matrix7 A = Matrix7::Zero();
  Vector7 b = Vector7::Zero();
  for(std::size_t i = 0; i < n; ++i) {
    const Vector_3d& normal = normals[i];
    if(!(normal.squared_length() > 0))
      continue;
    const Vector_3d d = moved[i] - m;
    const Vector_3d dn = cross(d, normal);
    Vector7 J;
    J << dn.x, dn.y, dn.z, (with_scale ? dot(normal, d) : 0.0), normal.x, normal.y, normal.z;
    const double r = dot(normal, moved[i] - to[i]);
    A.noalias() += J * J.transpose();
    b.noalias() += J * r;
  }
  if(!with_scale)
    A(3, 3) = 1;
  // A little damping keeps directions that the planes do not constrain (sliding along a flat or
  // round region) where they are.
  const double damping = 1e-9 * A.trace() / 7.0;
  if(!(damping > 0) || !std::isfinite(damping))
    return false;
  A += damping * Matrix7::Identity();
  const Eigen::LDLT<Matrix7> ldlt(A);
  if(ldlt.info() != Eigen::Success)
    return false;
  const Vector7 x = ldlt.solve(-b);
  if(!x.allFinite())
    return false;
  const Matrix_3d R = rotation_from_vector(Vector_3d(x(0), x(1), x(2)));
  const double f = with_scale ? std::exp(x(3)) : 1.0;
  const Vector_3d delta(x(4), x(5), x(6));
  Similarity_3d u;
  u.rotation = multiply(R, t.rotation);
  u.scale = f * t.scale;
  u.translation = multiply(R, t.translation - m) * f + m + delta;
  if(!u.is_finite())
    return false;
  result = u;
  return true;
}

// Squared distances `pairs` (with point indices): the pair that is the k-th smallest, ties by
// index, k = max(3, ceil(keep_fraction * n)); pairs not above it are kept.
inline std::pair<double, std::uint32_t>
trimming_threshold(const std::vector<std::pair<double, std::uint32_t>>& pairs, double keep_fraction,
                   std::vector<std::pair<double, std::uint32_t>>& buffer)
{
  const std::size_t n = pairs.size();
  const std::size_t k = (std::min)(
    n, (std::max)(std::size_t(3), static_cast<std::size_t>(std::ceil(keep_fraction * double(n)))));
  if(k == n)
    return *std::max_element(pairs.begin(), pairs.end());
  buffer = pairs;
  std::nth_element(buffer.begin(), buffer.begin() + std::ptrdiff_t(k - 1), buffer.end());
  return buffer[k - 1];
}

// ICP between a source and a target shape. `SourceClosest` / `TargetClosest` give the closest
// point of the source / target shape to a point in its own coordinates (closest sample, or
// closest surface point); the pairs start from the sample points of each shape.
template <typename SourceClosest, typename TargetClosest>
class Similarity_icp
{
public:
  Similarity_icp(const std::vector<Vector_3d>& source, const SourceClosest& source_closest,
                 const std::vector<Vector_3d>& target, const TargetClosest& target_closest)
    : m_source(source), m_target(target), m_source_closest(source_closest),
      m_target_closest(target_closest)
  {}

  // The trimmed RMS distance of `t`: every source point moved by `t` is paired with the closest
  // point of the target shape, and (symmetric) every target point with the closest point of the
  // moved source shape; in each direction the closest `keep_fraction` of the pairs are kept (ties
  // by point index); the RMS is taken over the kept pairs of both directions. The kept pairs are
  // left in `w.from` (source coordinates) / `w.to` (target coordinates).
  double trimmed_rms(const Similarity_3d& t, const Icp_options& o, Icp_workspace& w) const
  {
    const Similarity_3d inverse = t.inverse();
    const std::size_t ns = m_source.size(), nt = o.symmetric ? m_target.size() : 0;
    const bool planes = uses_planes(o);
    w.forward.resize(ns);
    w.forward_match.resize(ns);
    w.backward.resize(nt);
    w.backward_match.resize(nt);
    w.forward_normal.resize(planes ? ns : 0);
    w.backward_normal.resize(planes ? nt : 0);
    const auto query = [&](std::size_t k) {
      if(k < ns) {
        const Vector_3d q = t(m_source[k]);
        const Vector_3d c = m_target_closest(q, planes ? &w.forward_normal[k] : nullptr);
        w.forward[k] = std::make_pair((q - c).squared_length(), std::uint32_t(k));
        w.forward_match[k] = c;
      } else {
        const std::size_t j = k - ns;
        const Vector_3d c =
          m_source_closest(inverse(m_target[j]), planes ? &w.backward_normal[j] : nullptr);
        w.backward[j] = std::make_pair((t(c) - m_target[j]).squared_length(), std::uint32_t(j));
        w.backward_match[j] = c;
        if(planes) // in target coordinates
          w.backward_normal[j] = multiply(t.rotation, w.backward_normal[j]);
      }
    };
    if(o.number_of_threads == 1) {
      for(std::size_t k = 0; k < ns + nt; ++k)
        query(k);
    } else {
      Parallel_workspaces<char> parallel(o.number_of_threads);
      parallel.for_each(0, ns + nt, [&](std::size_t k, char&) { query(k); });
    }
    w.from.clear();
    w.to.clear();
    w.normals.clear();
    double sum = 0;
    if(ns > 0) {
      const auto threshold = trimming_threshold(w.forward, o.keep_fraction, w.sorted);
      for(std::size_t i = 0; i < ns; ++i) // in point order: sums independent of the selection
        if(!(threshold < w.forward[i])) {
          sum += w.forward[i].first;
          w.from.push_back(m_source[i]);
          w.to.push_back(w.forward_match[i]);
          if(planes)
            w.normals.push_back(w.forward_normal[i]);
        }
    }
    if(nt > 0) {
      const auto threshold = trimming_threshold(w.backward, o.keep_fraction, w.sorted);
      for(std::size_t j = 0; j < nt; ++j)
        if(!(threshold < w.backward[j])) {
          sum += w.backward[j].first;
          w.from.push_back(w.backward_match[j]);
          w.to.push_back(m_target[j]);
          if(planes)
            w.normals.push_back(w.backward_normal[j]);
        }
    }
    if(w.from.empty())
      return std::numeric_limits<double>::infinity();
    return std::sqrt(sum / double(w.from.size()));
  }

  // ICP from `initial`: pair (trimmed, as `trimmed_rms()`), solve the best similarity of the
  // kept pairs (closed form; or one point-to-plane step with surfaces), repeat. The trimmed RMS never increases: a step that would increase it is undone
  // and ends the iterations.
  Icp_result run(const Similarity_3d& initial, const Icp_options& o, Icp_workspace& w) const
  {
    Icp_result r;
    r.transform = initial;
    r.rms = trimmed_rms(initial, o, w);
    const std::vector<double> no_weights;
    for(std::size_t it = 0; it < o.max_iterations; ++it) {
      Similarity_3d next;
      const bool solved =
        uses_planes(o) ? point_to_plane_step(r.transform, w.from, w.to, w.normals, o.with_scale, next)
                       : best_similarity(w.from, w.to, no_weights, next, o.with_scale);
      if(!(r.rms > 0) || !solved) {
        r.converged = true; // exact fit, or nothing left to solve
        break;
      }
      const double rms = trimmed_rms(next, o, w);
      ++r.iterations;
      if(!(rms <= r.rms)) { // worse (or not a number): keep the previous transform
        r.converged = true;
        break;
      }
      const double previous = r.rms;
      r.transform = next;
      r.rms = rms;
      if(previous - rms <= o.tolerance * previous) {
        r.converged = true;
        break;
      }
    }
    return r;
  }

private:
  static bool uses_planes(const Icp_options& o)
  {
    return o.point_to_plane && SourceClosest::has_normals && TargetClosest::has_normals;
  }

  const std::vector<Vector_3d>& m_source;
  const std::vector<Vector_3d>& m_target;
  const SourceClosest& m_source_closest;
  const TargetClosest& m_target_closest;
};

template <typename SourceClosest, typename TargetClosest>
Similarity_icp<SourceClosest, TargetClosest>
make_similarity_icp(const std::vector<Vector_3d>& source, const SourceClosest& source_closest,
                    const std::vector<Vector_3d>& target, const TargetClosest& target_closest)
{
  return Similarity_icp<SourceClosest, TargetClosest>(source, source_closest, target, target_closest);
}

// ---------------------------------------------------------------------------------------------
// Alignment with restarts from the 24 orientations of the principal frames.

struct Restart_alignment_options
{
  Icp_options icp;
  // First stage: every restart runs ICP between the first `coarse_points` sample points of each
  // set (all of them when there are fewer) for at most `coarse_iterations` iterations.
  std::size_t coarse_points = 400;
  std::size_t coarse_iterations = 20;
  // Second stage: the `refined_restarts` best restarts of the first stage continue between every
  // sample point for at most `icp.max_iterations` iterations.
  std::size_t refined_restarts = 3;
  // Third stage (when surfaces are given): the best restart continues with closest points on the
  // surfaces (point to plane) for at most `surface_iterations` iterations.
  std::size_t surface_iterations = 20;
  std::size_t number_of_threads = 0;
};

struct Restart_alignment_result
{
  Similarity_3d transform;                                      // maps the source onto the target
  double rms = std::numeric_limits<double>::infinity();         // trimmed RMS distance
  double initial_rms = std::numeric_limits<double>::infinity(); // the same, of the identity
  std::size_t number_of_restarts = 0;
  std::size_t best_restart = 0; // index in axis_orientations(); their number: the identity
  std::size_t iterations = 0;   // ICP iterations of the best restart, every stage
  bool converged = false;       // whether the best restart's last stage converged
  std::vector<double> coarse_rms; // per restart, after the first stage
};

// The initial transform of restart `k`: centroids matched, scales matched by the RMS radii (1
// without scale), and the source's principal axes mapped onto the target's by orientation k.
inline Similarity_3d restart_transform(const Pca_frame& source, const Pca_frame& target,
                                       const Matrix_3d& orientation, bool with_scale)
{
  Similarity_3d t;
  t.rotation = multiply(transpose(target.axes), multiply(orientation, source.axes));
  const double rs = source.rms_radius(), rt = target.rms_radius();
  t.scale = (with_scale && rs > 0 && rt > 0) ? rt / rs : 1.0;
  t.translation = target.centroid - multiply(t.rotation, source.centroid) * t.scale;
  return t;
}

// Aligns the `source` sample onto the `target` sample (both non-empty) by ICP with scale from the
// 24 restarts. With surfaces (`source_surface` and `target_surface`, the shapes the samples were
// drawn from), the best restart is finished against the surfaces, and the RMS distances are
// measured to the surfaces (no sampling floor); otherwise between the samples. The result does
// not depend on the number of threads.
inline Restart_alignment_result
align_with_restarts(const std::vector<Vector_3d>& source, const std::vector<Vector_3d>& target,
                    const Restart_alignment_options& o,
                    const Closest_surface_point* source_surface = nullptr,
                    const Closest_surface_point* target_surface = nullptr)
{
  Restart_alignment_result result;
  if(source.empty() || target.empty())
    return result;
  const Pca_frame source_frame = weighted_pca(source), target_frame = weighted_pca(target);
  const std::vector<Matrix_3d> orientations = axis_orientations();
  const std::size_t n_restarts = orientations.size();
  result.number_of_restarts = n_restarts;

  const auto prefix = [](const std::vector<Vector_3d>& p, std::size_t n) {
    return (n == 0 || n >= p.size()) ? p
                                     : std::vector<Vector_3d>(p.begin(), p.begin() + std::ptrdiff_t(n));
  };
  const std::vector<Vector_3d> coarse_source = prefix(source, o.coarse_points),
                               coarse_target = prefix(target, o.coarse_points);
  const Closest_sample coarse_source_closest(coarse_source), coarse_target_closest(coarse_target);
  const auto coarse = make_similarity_icp(coarse_source, coarse_source_closest, coarse_target,
                                          coarse_target_closest);
  const Closest_sample source_closest(source), target_closest(target);
  const auto full = make_similarity_icp(source, source_closest, target, target_closest);

  // Restarts are spread over threads; each ICP runs on one thread.
  Icp_options coarse_options = o.icp;
  coarse_options.max_iterations = (std::min)(o.icp.max_iterations, o.coarse_iterations);
  coarse_options.number_of_threads = 1;
  Icp_options full_options = o.icp;
  full_options.number_of_threads = 1;
  std::vector<Icp_result> stage1(n_restarts);
  Parallel_workspaces<Icp_workspace> workspaces(o.number_of_threads);
  workspaces.for_each(0, n_restarts, [&](std::size_t k, Icp_workspace& w) {
    const Similarity_3d initial =
      restart_transform(source_frame, target_frame, orientations[k], o.icp.with_scale);
    stage1[k] = coarse.run(initial, coarse_options, w);
  });
  result.coarse_rms.resize(n_restarts);
  for(std::size_t k = 0; k < n_restarts; ++k)
    result.coarse_rms[k] = stage1[k].rms;

  // The best restarts of the first stage, ties by index.
  std::vector<std::size_t> order(n_restarts);
  std::iota(order.begin(), order.end(), std::size_t(0));
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    return stage1[a].rms < stage1[b].rms;
  });
  const std::size_t n_refined = (std::max)(std::size_t(1), (std::min)(o.refined_restarts, n_restarts));
  std::vector<Icp_result> stage2(n_refined);
  workspaces.for_each(0, n_refined, [&](std::size_t i, Icp_workspace& w) {
    stage2[i] = full.run(stage1[order[i]].transform, full_options, w);
  });
  std::size_t best = 0;
  for(std::size_t i = 1; i < n_refined; ++i)
    if(stage2[i].rms < stage2[best].rms ||
       (stage2[i].rms == stage2[best].rms && order[i] < order[best]))
      best = i;
  result.transform = stage2[best].transform;
  result.rms = stage2[best].rms;
  result.best_restart = order[best];
  result.iterations = stage1[order[best]].iterations + stage2[best].iterations;
  result.converged = stage2[best].converged;
  Icp_workspace& w = workspaces.local();
  if(source_surface != nullptr && target_surface != nullptr && !source_surface->empty() &&
     !target_surface->empty()) {
    const auto surfaces = make_similarity_icp(source, *source_surface, target, *target_surface);
    Icp_options surface_options = o.icp;
    surface_options.max_iterations = o.surface_iterations;
    surface_options.number_of_threads = o.number_of_threads;
    const Icp_result stage3 = surfaces.run(result.transform, surface_options, w);
    result.transform = stage3.transform;
    result.rms = stage3.rms;
    result.iterations += stage3.iterations;
    result.converged = stage3.converged;
    result.initial_rms = surfaces.trimmed_rms(Similarity_3d(), surface_options, w);
  } else {
    result.initial_rms = full.trimmed_rms(Similarity_3d(), full_options, w);
  }
  // The shapes as given compete too: when no restart aligns them better (a shape onto itself, a
  // flat shape whose in-plane turns the trimmed distance does not see), they stay as they are.
  if(result.initial_rms <= result.rms) {
    result.transform = Similarity_3d();
    result.rms = result.initial_rms;
    result.best_restart = n_restarts;
    result.iterations = 0;
    result.converged = true;
  }
  return result;
}

} // namespace internal
} // namespace Shape_analysis
} // namespace CGAL

#endif // CGAL_SHAPE_ANALYSIS_INTERNAL_SIMILARITY_ALIGNMENT_H
