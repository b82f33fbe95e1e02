// Copyright (c) 2026 CGAL Global Shape Analysis contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_SURFACE_MESH_SYMMETRIZATION_INTERNAL_ROTATION_DETECTION_H
#define CGAL_SURFACE_MESH_SYMMETRIZATION_INTERNAL_ROTATION_DETECTION_H

// Detection of rotational symmetries of a triangle surface (detect_rotational_symmetries()):
//   1. candidate axes through the area centroid (on the axis of every global rotational symmetry):
//      the three principal axes, tried with every order up to the largest, and directions spread
//      evenly over a hemisphere (a Fibonacci spiral), tried with the small orders and a turn by
//      an arbitrary angle (a surface of revolution); each scored on a few samples;
//   2. the best distinct axes refined: every sample turned by the candidate's angle (both ways) is
//      paired with the closest compatible surface point, Gauss-Newton steps on the axis' direction
//      and position minimize the robustly weighted distances to the partners' tangent planes;
//   3. the order read off the refined axis: the largest order whose turn scores within the
//      tolerance, or none (a surface of revolution) when three unrelated angles all do; the axis
//      refined once more for it, scored, duplicates merged, support per face.

#include <CGAL/Surface_mesh_symmetrization/Detect_rotational_symmetries_options.h>
#include <CGAL/Surface_mesh_symmetrization/internal/Plane_detection.h>

#include <Eigen/Dense>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numeric>
#include <vector>

namespace CGAL {
namespace Surface_mesh_symmetrization {
namespace internal {

constexpr double two_pi = 6.283185307179586476925;

// Turns by an arbitrary angle (fractions of a full turn far from p/q for small q): a surface
// scoring well under all three is a surface of revolution.
constexpr std::array<double, 3> revolution_probe_turns{{0.1234, 0.2718, 0.4142}};

struct Detected_rotation
{
  Vector_3d point;                  // the point of the axis nearest the area centroid
  Vector_3d axis;                   // unit direction (canonical sign)
  std::size_t order = 0;            // k of a k-fold symmetry; 0 for a surface of revolution
  double score = 0;                 // truncated RMS symmetry distance / diagonal
  double support_fraction = 0;      // area-weighted mean of `support`
  std::vector<double> support;      // per face, in [0, 1]

  // The angle of the turn the symmetry is scored by.
  double angle() const { return order == 0 ? two_pi * revolution_probe_turns[0] : two_pi / double(order); }
};

// A sign convention for axes: the component of largest magnitude positive.
inline Vector_3d canonical_axis(Vector_3d a)
{
  const double m[3] = {a.x, a.y, a.z};
  int k = 0;
  for(int i = 1; i < 3; ++i)
    if(std::abs(m[i]) > std::abs(m[k]) + 1e-12)
      k = i;
  return m[k] < 0 ? a * -1.0 : a;
}

// The rotation of w by `angle` about the unit axis a (Rodrigues).
inline Vector_3d turn(const Vector_3d& a, double angle, const Vector_3d& w)
{
  const double c = std::cos(angle), s = std::sin(angle);
  return w * c + SAI::cross(a, w) * s + a * (SAI::dot(a, w) * (1 - c));
}

// Whether two axes (lines) are the same within an angle (radians) and a distance between them.
inline bool same_axis(const Detected_rotation& x, const Detected_rotation& y, double angle, double distance)
{
  if(std::abs(SAI::dot(x.axis, y.axis)) < std::cos(angle))
    return false;
  const Vector_3d d = y.point - x.point;
  return (d - x.axis * SAI::dot(d, x.axis)).length() <= distance;
}

// Two unit vectors perpendicular to the unit vector a and to each other.
inline std::array<Vector_3d, 2> perpendicular_basis(const Vector_3d& a)
{
  const Vector_3d helper = std::abs(a.x) < 0.6 ? Vector_3d(1, 0, 0) : Vector_3d(0, 1, 0);
  Vector_3d e1 = SAI::cross(a, helper);
  e1 = e1 / e1.length();
  return {{e1, SAI::cross(a, e1)}};
}

// Refines and scores rotations on the samples of a surface given relative to its area centroid.
class Rotation_detector
{
public:
  Rotation_detector(const Surface& surface, const Surface_index& index, const Surface_samples& samples,
                    double diagonal, double support_tolerance, std::size_t threads)
    : m_surface(surface), m_index(index), m_samples(samples), m_diagonal(diagonal),
      m_support_tolerance(support_tolerance), m_threads(threads)
  {}

  // The truncated RMS distance (relative to the diagonal) of the first `n` samples (all when 0)
  // turned by `angle` about the axis (a through c) to the surface, normals compatible; with
  // `median`, also the median distance (relative to the diagonal). Without it, once the score is
  // sure to exceed `bound`, a value above `bound` (not the score) is returned early.
  double score(const Vector_3d& a, const Vector_3d& c, double angle, std::size_t n = 0, double* median = nullptr,
               double bound = std::numeric_limits<double>::infinity()) const
  {
    n = n == 0 ? m_samples.points.size() : (std::min)(n, m_samples.points.size());
    const double cap = score_cap * m_diagonal;
    double sum = 0;
    std::vector<double> all;
    std::uint32_t hint = Surface_index::no_face;
    for(std::size_t i = 0; i < n; ++i) {
      const Vector_3d y = c + turn(a, angle, m_samples.points[i] - c);
      const Vector_3d m = turn(a, angle, m_samples.normals[i]);
      const Surface_point s = m_index.closest_compatible(y, m, 0.0, hint, cap);
      double d = cap;
      if(s.found && SAI::dot(m_index.face_normals()[s.face], m) > 0)
        d = (std::min)(cap, std::sqrt(s.squared_distance));
      sum += d * d;
      if(median != nullptr)
        all.push_back(d);
      else if(sum > bound * bound * m_diagonal * m_diagonal * double(n))
        return std::sqrt(sum / double(n)) / m_diagonal;
    }
    if(median != nullptr && n > 0) {
      std::nth_element(all.begin(), all.begin() + std::ptrdiff_t(n / 2), all.end());
      *median = all[n / 2] / m_diagonal;
    }
    return n > 0 ? std::sqrt(sum / double(n)) / m_diagonal : 0.0;
  }

  // The score of the symmetry of `order`: the worst of its turns by 2 pi j / order, j = 1 ... order
  // / 2 (a small turn alone slides a smooth surface along itself), or of the revolution probes
  // (order 0).
  // Once it is sure to exceed `bound`, a value above `bound` is returned early.
  double order_score(const Vector_3d& a, const Vector_3d& c, std::size_t order, std::size_t n = 0,
                     double bound = std::numeric_limits<double>::infinity()) const
  {
    std::vector<double> turns;
    if(order == 0)
      for(double t : revolution_probe_turns)
        turns.push_back(two_pi * t);
    for(std::size_t j = 1; order > 0 && 2 * j <= order; ++j)
      turns.push_back(two_pi * double(j) / double(order));
    double worst = 0;
    for(double t : turns)
      if((worst = (std::max)(worst, score(a, c, t, n, nullptr, bound))) > bound)
        break;
    return worst;
  }

  // Refines the axis (a through c) of the turns by `angles` (each both ways) from the first `n`
  // samples (all when 0), `iterations` Gauss-Newton steps, the reach of the robust weights
  // shrinking from reach0 to reach1 (relative to the diagonal). c comes back as the axis' point
  // nearest the origin.
  void refine(Vector_3d& a, Vector_3d& c, const std::vector<double>& angles, std::size_t n, std::size_t iterations,
              double reach0, double reach1) const
  {
    n = n == 0 ? m_samples.points.size() : (std::min)(n, m_samples.points.size());
    double reach = reach0 * m_diagonal;
    const double final_reach = reach1 * m_diagonal;
    std::vector<std::pair<double, std::uint32_t>> buffer;
    for(std::size_t it = 0; it < iterations; ++it) {
      const std::array<Vector_3d, 2> e = perpendicular_basis(a);
      Eigen::Matrix4d A = Eigen::Matrix4d::Zero();
      Eigen::Vector4d b = Eigen::Vector4d::Zero();
      double weight_sum = 0;
      for(double angle0 : angles)
        for(double angle : {angle0, -angle0}) {
          const double cs = std::cos(angle), sn = std::sin(angle);
          for(std::size_t i = 0; i < n; ++i) {
            const Vector_3d w = m_samples.points[i] - c;
            const Vector_3d y = c + turn(a, angle, w);
            const Vector_3d m = turn(a, angle, m_samples.normals[i]);
            const Surface_point s = m_index.approximate_closest_compatible(y, m, 0.0, reach, buffer);
            if(!s.found)
              continue;
            const double distance = std::sqrt(s.squared_distance);
            if(!(distance < reach))
              continue;
            const double u = distance / reach, wt = (1 - u * u) * (1 - u * u);
            const Vector_3d& nn = m_index.face_normals()[s.face];
            Eigen::Vector4d J;
            for(int k = 0; k < 2; ++k) {
              // d(turned w)/da along e_k, and d y / dc along e_k: (I - M) e_k.
              const Vector_3d da = SAI::cross(e[std::size_t(k)], w) * sn +
                                   (e[std::size_t(k)] * SAI::dot(a, w) + a * SAI::dot(e[std::size_t(k)], w)) * (1 - cs);
              J(k) = SAI::dot(nn, da);
              J(k + 2) = SAI::dot(nn, e[std::size_t(k)] - turn(a, angle, e[std::size_t(k)]));
            }
            A.noalias() += wt * (J * J.transpose());
            b.noalias() += wt * SAI::dot(nn, y - s.point) * J;
            weight_sum += wt;
          }
        }
      if(weight_sum < 8)
        break;
      A += (1e-9 * A.trace() + 1e-300) * Eigen::Matrix4d::Identity();
      const Eigen::Vector4d x = A.ldlt().solve(-b);
      if(!x.allFinite())
        break;
      Vector_3d a2 = a + e[0] * x(0) + e[1] * x(1);
      const double l = a2.length();
      if(!(l > 0))
        break;
      a2 = a2 / l;
      Vector_3d c2 = c + e[0] * x(2) + e[1] * x(3);
      c2 = c2 - a2 * SAI::dot(a2, c2);
      a = a2;
      c = c2;
      const double step = std::abs(x(0)) + std::abs(x(1)) + (std::abs(x(2)) + std::abs(x(3))) / m_diagonal;
      reach = (std::max)(final_reach, reach * 0.6);
      if(step < 1e-8 && reach <= final_reach)
        break;
    }
    a = canonical_axis(a);
  }

  // Per face: exp(-delta^2 / (2 sigma^2)) with delta the distance of the turned centroid to the
  // closest compatible surface point (0 without one); and the area-weighted mean.
  std::vector<double> support(const Vector_3d& a, const Vector_3d& c, double angle, double& fraction) const
  {
    const std::size_t nf = m_surface.number_of_faces();
    std::vector<double> w(nf, 0.0);
    const std::vector<Vector_3d>& normals = m_index.face_normals();
    const double sigma = m_support_tolerance * m_diagonal, reach = 5 * sigma;
    SAI::Parallel_workspaces<char> parallel(m_threads);
    const std::size_t block = 512;
    parallel.for_each(0, (nf + block - 1) / block, [&](std::size_t blk, char&) {
      std::vector<std::pair<double, std::uint32_t>> buffer;
      for(std::size_t f = blk * block; f < (std::min)(nf, (blk + 1) * block); ++f) {
        if(!(normals[f].squared_length() > 0))
          continue;
        const auto k = m_surface.corners(f);
        const Vector_3d y = c + turn(a, angle, (k[0] + k[1] + k[2]) / 3.0 - c);
        const Surface_point s =
          m_index.approximate_closest_compatible(y, turn(a, angle, normals[f]), 0.0, reach, buffer);
        if(s.found && s.squared_distance < reach * reach)
          w[f] = std::exp(-s.squared_distance / (2 * sigma * sigma));
      }
    });
    double area = 0, sum = 0;
    for(std::size_t f = 0; f < nf; ++f) {
      area += m_surface.area(f);
      sum += m_surface.area(f) * w[f];
    }
    fraction = area > 0 ? sum / area : 0.0;
    return w;
  }

private:
  const Surface& m_surface;
  const Surface_index& m_index;
  const Surface_samples& m_samples;
  double m_diagonal, m_support_tolerance;
  std::size_t m_threads;
};

typedef Detect_rotational_symmetries_options Rotation_detection_options;

// The largest median distance (relative to the diagonal) from the surface of the samples turned
// by an order's turns for it to count as a symmetry of most of the surface (order_of()). The
// median ignores a part that does not turn onto itself (the rotor's knob, 17% of its area, adds
// 0.011 to the RMS); 0.004 passes CGAL's rotor and turbine and the tests' procedural shapes
// (medians under 0.001), and rejects the half turns about axes across them (0.01 to 0.02).
constexpr double order_tolerance = 0.004;

// The order of the rotation about the axis (a through c), from the worst of the scores (RMS and
// median distances, Rotation_detector::score()) of each order's turns by 2 pi j / k (or of the
// revolution probes, order 0): an order is a symmetry of most of the surface when its median is
// within `tolerance` (relative to the diagonal: what a symmetric part adds to the RMS is not
// counted); of those, the ones whose RMS is within 4 times the best one's (or 2.5e-4) are
// symmetries of the whole surface as closely as the best: a surface of revolution when the
// revolution probes are, else the largest such k. 1 when no order is. Each turn is scored once
// (by its reduced fraction of a full turn).
inline std::size_t order_of(const Rotation_detector& d, const Vector_3d& a, const Vector_3d& c, std::size_t maximum,
                            double tolerance, std::size_t n)
{
  const std::size_t w = maximum + 1;
  std::vector<std::array<double, 2>> turns(w * w, std::array<double, 2>{{-1.0, 0.0}}); // by reduced (j, k)
  const auto turn_of = [&](std::size_t j, std::size_t k) {
    const std::size_t g = std::gcd(j, k);
    std::array<double, 2>& x = turns[(j / g) * w + k / g];
    if(x[0] < 0)
      x[0] = d.score(a, c, two_pi * double(j) / double(k), n, &x[1]);
    return x;
  };
  std::vector<std::array<double, 2>> s(w, std::array<double, 2>{{0.0, 0.0}}); // per order: RMS, median
  for(double t : revolution_probe_turns) {
    double median = 0;
    s[0][0] = (std::max)(s[0][0], d.score(a, c, two_pi * t, n, &median));
    s[0][1] = (std::max)(s[0][1], median);
  }
  for(std::size_t k = 2; k <= maximum; ++k)
    for(std::size_t j = 1; 2 * j <= k; ++j) { // (the other turns of an order failing one are not scored)
      const std::array<double, 2> x = turn_of(j, k);
      s[k][0] = (std::max)(s[k][0], x[0]);
      s[k][1] = (std::max)(s[k][1], x[1]);
      if(s[k][1] > tolerance)
        break;
    }
  double best = std::numeric_limits<double>::infinity();
  for(std::size_t k = 0; k <= maximum; ++k)
    if(k != 1 && s[k][1] <= tolerance)
      best = (std::min)(best, s[k][0]);
  if(!std::isfinite(best))
    return 1;
  const double limit = (std::max)(4 * best, 2.5e-4);
  const auto accepted = [&](std::size_t k) { return s[k][1] <= tolerance && s[k][0] <= limit; };
  if(accepted(0))
    return 0;
  for(std::size_t k = maximum; k >= 2; --k)
    if(accepted(k))
      return k;
  return 1;
}

// A candidate axis of detect_rotations(): through the origin (the area centroid), with its best
// order on few samples and that order's score.
struct Rotation_candidate
{
  Vector_3d axis, point;
  std::size_t order = 0;
  double score = 1;
};

// Stage 1 of detect_rotations(): the principal axes (every order) and directions over a
// hemisphere (small orders, revolution), each with its best order on 150 samples; the best ones at
// least 8 degrees apart, at most `count`.
inline std::vector<Rotation_candidate> candidate_axes(const Rotation_detector& detector, const Surface_samples& samples,
                                                      const Rotation_detection_options& o, std::size_t count)
{
  typedef Rotation_candidate Candidate;
  std::vector<Candidate> candidates;
  const SAI::Pca_frame frame = SAI::weighted_pca(samples.points);
  for(const Vector_3d& n : frame.axes)
    if(n.squared_length() > 0)
      candidates.push_back(Candidate{canonical_axis(n / n.length()), Vector_3d(0, 0, 0), 0, 1});
  const std::size_t directions = 400, few = 150, small_orders = 6;
  for(std::size_t i = 0; i < directions; ++i) {
    const double z = 1.0 - (double(i) + 0.5) / double(directions);
    const double r = std::sqrt((std::max)(0.0, 1 - z * z)), phi = 2.399963229728653 * double(i);
    candidates.push_back(Candidate{canonical_axis(Vector_3d(r * std::cos(phi), r * std::sin(phi), z)),
                                   Vector_3d(0, 0, 0), 0, 1});
  }
  SAI::Parallel_workspaces<char> parallel(o.number_of_threads);
  parallel.for_each(0, candidates.size(), [&](std::size_t i, char&) {
    Candidate& c = candidates[i];
    const std::size_t last = i < 3 ? o.maximum_order : (std::min)(o.maximum_order, small_orders);
    for(std::size_t k = 0; k <= last; ++k) {
      if(k == 1)
        continue;
      const double s = detector.order_score(c.axis, c.point, k, few, c.score);
      if(s < c.score - 1e-12)
        c.score = s, c.order = k;
    }
  });
  std::vector<std::size_t> order(candidates.size());
  std::iota(order.begin(), order.end(), std::size_t(0));
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t x, std::size_t y) { return candidates[x].score < candidates[y].score; });
  const double angle_apart = 8.0 * two_pi / 360.0;
  std::vector<Candidate> kept;
  for(std::size_t k : order) {
    bool near = false;
    for(const Candidate& j : kept)
      near = near || std::abs(SAI::dot(j.axis, candidates[k].axis)) > std::cos(angle_apart);
    if(!near)
      kept.push_back(candidates[k]);
    if(kept.size() >= count)
      break;
  }
  return kept;
}

// Detects the rotational symmetries of `input` (positions in any pose), best first.
inline std::vector<Detected_rotation> detect_rotations(const Surface& input, const Rotation_detection_options& o)
{
  std::vector<Detected_rotation> result;
  const double diagonal = input.diagonal();
  if(!(diagonal > 0) || !std::isfinite(diagonal))
    return result;
  Surface surface = input;
  const Vector_3d centroid = input.area_centroid();
  for(Vector_3d& p : surface.points)
    p -= centroid;
  const Surface_index index(surface);
  if(index.empty())
    return result;
  const Surface_samples samples =
    sample_surface(surface, (std::max)(std::size_t(20), o.number_of_samples), o.random_seed, 1);
  const Rotation_detector detector(surface, index, samples, diagonal, o.support_tolerance, o.number_of_threads);

  const std::vector<Rotation_candidate> kept =
    candidate_axes(detector, samples, o, (std::max)(std::size_t(6), 2 * o.maximum_number_of_symmetries));
  SAI::Parallel_workspaces<char> parallel(o.number_of_threads);

  // Stage 2: each refined for its order, its order read off again, refined for that, scored.
  std::vector<Detected_rotation> refined(kept.size());
  parallel.for_each(0, kept.size(), [&](std::size_t i, char&) {
    const Rotation_candidate& c = kept[i];
    Detected_rotation& r = refined[i];
    r.axis = c.axis;
    r.point = c.point;
    const auto angles = [](std::size_t k) { // the smallest turn and the one nearest a half turn
      if(k == 0)
        return std::vector<double>{two_pi * revolution_probe_turns[0], two_pi * revolution_probe_turns[2]};
      std::vector<double> x{two_pi / double(k)};
      if(k / 2 > 1)
        x.push_back(two_pi * double(k / 2) / double(k));
      return x;
    };
    detector.refine(r.axis, r.point, angles(c.order), 300, 10, 0.15, 0.05);
    r.order = order_of(detector, r.axis, r.point, o.maximum_order, order_tolerance, 300);
    if(r.order == 1) {
      r.score = 1;
      return;
    }
    detector.refine(r.axis, r.point, angles(r.order), 0, 20, 0.05, 0.02);
    r.order = order_of(detector, r.axis, r.point, o.maximum_order, order_tolerance, 300);
    r.score = r.order == 1 ? 1.0 : detector.order_score(r.axis, r.point, r.order);
  });
  std::stable_sort(refined.begin(), refined.end(),
                   [](const Detected_rotation& x, const Detected_rotation& y) { return x.score < y.score; });

  // Stage 3: duplicates merged, support, the best kept.
  for(Detected_rotation& r : refined) {
    if(result.size() >= o.maximum_number_of_symmetries)
      break;
    if(r.order == 1)
      continue;
    bool duplicate = false;
    for(const Detected_rotation& x : result)
      duplicate = duplicate || same_axis(x, r, 2.0 * two_pi / 360.0, 0.1 * diagonal);
    if(duplicate)
      continue;
    r.support = detector.support(r.axis, r.point, r.angle(), r.support_fraction);
    if(r.support_fraction < o.minimum_support)
      continue;
    result.push_back(std::move(r));
  }
  for(Detected_rotation& r : result)
    r.point += centroid;
  return result;
}

} // namespace internal
} // namespace Surface_mesh_symmetrization
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_SYMMETRIZATION_INTERNAL_ROTATION_DETECTION_H
