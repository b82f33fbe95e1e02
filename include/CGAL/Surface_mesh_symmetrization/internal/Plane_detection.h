// Copyright (c) 2026 CGAL Global Shape Analysis contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_SURFACE_MESH_SYMMETRIZATION_INTERNAL_PLANE_DETECTION_H
#define CGAL_SURFACE_MESH_SYMMETRIZATION_INTERNAL_PLANE_DETECTION_H

// Detection of planar reflective symmetries of a triangle surface (arrays, see
// Symmetry_geometry.h):
//   1. candidates: the three principal planes through the area centroid, and the peaks of the
//      votes of sample pairs (each pair whose normals mirror each other votes for its bisector
//      plane; votes counted in bins of a cube map of normals times offsets, peaks sharpened by
//      mean shift over the votes);
//   2. every candidate refined to minimize the symmetry distance: reflected samples paired with
//      the closest compatible surface points, robust (Tukey) weights with a shrinking reach,
//      Gauss-Newton steps on the plane's normal and offset (point to plane; border points of an
//      open surface drawn across the border to the border, which pins flat regions);
//   2b. a plane under which nearly all vertices have a mirror vertex is fitted to those pairs
//      (exact for a mesh whose vertices are exact mirror images: a remeshed one), kept when its
//      score is not worse;
//   3. the refined planes scored by the truncated RMS symmetry distance, duplicates merged,
//      ranked best first, and the support of each (per face: how closely the mirror image of the
//      face lies on the surface).

#include <CGAL/Surface_mesh_symmetrization/Detect_reflective_symmetries_options.h>
#include <CGAL/Surface_mesh_symmetrization/internal/Surface_boundary.h>
#include <CGAL/Surface_mesh_symmetrization/internal/Surface_index.h>
#include <CGAL/Surface_mesh_symmetrization/internal/Symmetric_connectivity.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <numeric>
#include <tuple>
#include <vector>

namespace CGAL {
namespace Surface_mesh_symmetrization {
namespace internal {

typedef Detect_reflective_symmetries_options Detection_options;

// The truncation of the symmetry distances in the score, relative to the diagonal.
constexpr double score_cap = 0.05;
// The largest angle between the normals of a voting pair of samples and mirror images of each
// other across the pair's bisector plane, in degrees.
constexpr double normal_tolerance_degrees = 20;

struct Detected_plane
{
  Plane_3d plane;
  double score = 0;            // truncated RMS symmetry distance / diagonal
  double support_fraction = 0; // area-weighted mean of `support`
  std::vector<double> support; // per face, in [0, 1]
  std::size_t votes = 0;       // pair votes near the plane (0 for principal planes only)
};

// A sign convention for unoriented planes: the normal's component of largest magnitude is
// positive (ties: the first such component).
inline Plane_3d canonical(const Plane_3d& p)
{
  int a = 0;
  for(int i = 1; i < 3; ++i)
    if(std::abs(p.normal[i]) > std::abs(p.normal[a]))
      a = i;
  return p.normal[a] < 0 ? p.opposite() : p;
}

// Whether two planes are the same within an angle (given by its cosine) and an offset
// difference.
inline bool same_plane_cos(const Plane_3d& a, const Plane_3d& b, double cos_angle, double offset)
{
  const double c = SAI::dot(a.normal, b.normal);
  if(std::abs(c) < cos_angle)
    return false;
  return std::abs(a.offset - (c < 0 ? -b.offset : b.offset)) <= offset;
}

// The same within an angle in radians.
inline bool same_plane(const Plane_3d& a, const Plane_3d& b, double angle, double offset)
{
  return same_plane_cos(a, b, std::cos(angle), offset);
}

// The pair votes binned by (cube-map face, u, v, offset): 24 x 24 bins per face of the cube of
// the normals, offsets in bins of `offset_bin`.
class Vote_bins
{
public:
  typedef std::array<int, 4> Key;
  static constexpr int resolution = 24;

  Vote_bins(const std::vector<Plane_3d>& votes, double offset_bin) : m_votes(votes), m_offset_bin(offset_bin)
  {
    // Votes sorted by bin; the bins as runs of that order.
    m_keyed.resize(votes.size());
    for(std::size_t i = 0; i < votes.size(); ++i)
      m_keyed[i] = std::make_pair(key_of(votes[i]), std::uint32_t(i));
    std::sort(m_keyed.begin(), m_keyed.end());
    for(const auto& k : m_keyed) {
      if(m_bins.empty() || m_bins.back().first != k.first)
        m_bins.emplace_back(k.first, 0);
      ++m_bins.back().second;
    }
  }

  // The bins with the sums of the counts of their 3x3x3 neighbours, by decreasing sum.
  std::vector<std::pair<std::size_t, Key>> smoothed() const
  {
    std::vector<std::pair<std::size_t, Key>> smoothed;
    smoothed.reserve(m_bins.size());
    for(const auto& b : m_bins) {
      std::size_t sum = 0;
      for(int du = -1; du <= 1; ++du)
        for(int dv = -1; dv <= 1; ++dv)
          for(int dd = -1; dd <= 1; ++dd)
            sum += count_of(Key{{b.first[0], b.first[1] + du, b.first[2] + dv, b.first[3] + dd}});
      smoothed.emplace_back(sum, b.first);
    }
    std::sort(smoothed.begin(), smoothed.end(), [](const auto& x, const auto& y) {
      return x.first > y.first || (x.first == y.first && x.second < y.second);
    });
    return smoothed;
  }

  // The centre plane of bin k moved to the mean of the votes around it (within `cos_angle` and
  // `offset`, in the 5x5x5 bins around k), 3 steps; `count`: the votes of the last mean.
  Plane_3d mean_shift(const Key& k, double cos_angle, double offset, std::size_t& count) const
  {
    Vector_3d n;
    n[k[0]] = 1;
    n[(k[0] + 1) % 3] = (k[1] + 0.5) / resolution * 2 - 1;
    n[(k[0] + 2) % 3] = (k[2] + 0.5) / resolution * 2 - 1;
    n = n / n.length();
    Plane_3d p{n, (k[3] + 0.5) * m_offset_bin};
    count = 0;
    for(int step = 0; step < 3; ++step) {
      Vector_3d sum_n;
      double sum_d = 0;
      count = 0;
      for(int du = -2; du <= 2; ++du)
        for(int dv = -2; dv <= 2; ++dv) {
          const auto range = votes_in(k[0], k[1] + du, k[2] + dv, k[3] - 2, k[3] + 2);
          for(auto it = range.first; it != range.second; ++it) {
            const Plane_3d& v = m_votes[it->second];
            if(!same_plane_cos(p, v, cos_angle, offset))
              continue;
            const Plane_3d a = SAI::dot(p.normal, v.normal) < 0 ? v.opposite() : v;
            sum_n += a.normal;
            sum_d += a.offset;
            ++count;
          }
        }
      if(count == 0 || !(sum_n.length() > 0))
        break;
      p = Plane_3d{sum_n / sum_n.length(), sum_d / double(count)};
    }
    return p;
  }

private:
  Key key_of(const Plane_3d& p) const
  {
    int a = 0;
    for(int i = 1; i < 3; ++i)
      if(std::abs(p.normal[i]) > std::abs(p.normal[a]))
        a = i;
    const double big = std::abs(p.normal[a]);
    const double u = p.normal[(a + 1) % 3] / big, v = p.normal[(a + 2) % 3] / big; // in [-1, 1]
    const int iu = (std::min)(resolution - 1, int(std::floor((u + 1) * 0.5 * resolution)));
    const int iv = (std::min)(resolution - 1, int(std::floor((v + 1) * 0.5 * resolution)));
    const int id = int(std::floor(p.offset / m_offset_bin));
    return Key{{a, iu, iv, id}};
  }

  std::size_t count_of(const Key& k) const
  {
    const auto it = std::lower_bound(m_bins.begin(), m_bins.end(), k,
                                     [](const std::pair<Key, std::size_t>& b, const Key& key) { return b.first < key; });
    return (it != m_bins.end() && it->first == k) ? it->second : 0;
  }

  typedef std::vector<std::pair<Key, std::uint32_t>>::const_iterator Keyed_iterator;

  // The votes of bins (a, u, v, d0..d1), a run of the sorted order.
  std::pair<Keyed_iterator, Keyed_iterator> votes_in(int a, int u, int v, int d0, int d1) const
  {
    const Key lo{{a, u, v, d0}}, hi{{a, u, v, d1}};
    const auto first = std::lower_bound(m_keyed.begin(), m_keyed.end(), lo,
                                        [](const std::pair<Key, std::uint32_t>& x, const Key& key) { return x.first < key; });
    const auto last = std::upper_bound(m_keyed.begin(), m_keyed.end(), hi,
                                       [](const Key& key, const std::pair<Key, std::uint32_t>& x) { return key < x.first; });
    return std::make_pair(first, last);
  }

  const std::vector<Plane_3d>& m_votes;
  double m_offset_bin;
  std::vector<std::pair<Key, std::uint32_t>> m_keyed;
  std::vector<std::pair<Key, std::size_t>> m_bins; // (key, count)
};

// The surface samples refine and score the planes; all coordinates are relative to the area
// centroid (the caller shifts them), so that offsets stay small.
class Plane_detector
{
public:
  Plane_detector(const Surface& surface, const Surface_index& index, const Surface_samples& samples,
                 double diagonal, const Detection_options& o)
    : m_surface(surface), m_index(index), m_samples(samples), m_diagonal(diagonal), m_o(o),
      m_boundary(surface_boundary(surface, 0.002 * diagonal, 100000))
  {}

  // Candidate planes: principal planes first, then the vote peaks (strongest first).
  std::vector<std::pair<Plane_3d, std::size_t>> candidates() const
  {
    std::vector<std::pair<Plane_3d, std::size_t>> result;
    const SAI::Pca_frame frame = SAI::weighted_pca(m_samples.points);
    for(int k = 0; k < 3; ++k) {
      const Vector_3d n = frame.axes[std::size_t(k)];
      if(n.squared_length() > 0)
        result.emplace_back(canonical(Plane_3d{n, SAI::dot(n, frame.centroid)}), 0);
    }
    for(const auto& p : vote_peaks())
      result.push_back(p);
    return result;
  }

  // Refines `plane` from the first `n_samples` samples (all when 0) for at most `iterations`
  // Gauss-Newton steps, the reach of the robust weights shrinking from `reach0` to `reach1`
  // (relative to the diagonal).
  Plane_3d refine(Plane_3d plane, std::size_t n_samples, std::size_t iterations, double reach0,
                  double reach1) const
  {
    const std::size_t n = n_samples == 0 ? m_samples.points.size()
                                         : (std::min)(n_samples, m_samples.points.size());
    double reach = reach0 * m_diagonal;
    const double final_reach = reach1 * m_diagonal;
    std::vector<std::pair<double, std::uint32_t>> buffer;
    for(std::size_t it = 0; it < iterations; ++it) {
      Eigen::Matrix3d A = Eigen::Matrix3d::Zero();
      Eigen::Vector3d b = Eigen::Vector3d::Zero();
      // A basis of the plane's directions.
      const Vector_3d& nn = plane.normal;
      const Vector_3d helper = std::abs(nn.x) < 0.6 ? Vector_3d(1, 0, 0) : Vector_3d(0, 1, 0);
      Vector_3d e1 = SAI::cross(nn, helper);
      e1 = e1 / e1.length();
      const Vector_3d e2 = SAI::cross(nn, e1);
      double weight_sum = 0;
      // Adds the residual of the mirror image y of p (s: p's distance to the plane) along the unit
      // `direction` from `partner`, at `distance` from it, with a robust (Tukey) weight.
      const auto add = [&](const Vector_3d& p, double s, const Vector_3d& y, const Vector_3d& partner,
                           double distance, const Vector_3d& direction) {
        if(!(distance < reach))
          return 0.0;
        const double u = distance / reach;
        const double w = (1 - u * u) * (1 - u * u);
        // Derivatives of y = p - 2 (n.p - d) n along n + a e1 + b e2 and d + delta.
        const Vector_3d dya = (nn * SAI::dot(e1, p) + e1 * s) * -2.0;
        const Vector_3d dyb = (nn * SAI::dot(e2, p) + e2 * s) * -2.0;
        const Eigen::Vector3d J(SAI::dot(direction, dya), SAI::dot(direction, dyb), 2.0 * SAI::dot(direction, nn));
        A.noalias() += w * (J * J.transpose());
        b.noalias() += w * SAI::dot(direction, y - partner) * J;
        return w;
      };
      for(std::size_t i = 0; i < n; ++i) {
        const Vector_3d& p = m_samples.points[i];
        const double s = plane.signed_distance(p);
        const Vector_3d y = p - nn * (2 * s);
        const Vector_3d m = reflect_direction(plane, m_samples.normals[i]);
        const Surface_point c = m_index.approximate_closest_compatible(y, m, 0.0, reach, buffer);
        if(c.found) // (to the tangent plane of the closest point)
          weight_sum += add(p, s, y, c.point, std::sqrt(c.squared_distance), m_index.face_normals()[c.face]);
      }
      // The border maps onto the border: each border point's mirror image is drawn to the border
      // across it (in its face), which pins what the surface leaves free (flat regions).
      const std::size_t n_border = (std::min)(m_boundary.points.size(), n / 4);
      for(std::size_t k = 0; k < n_border; ++k) {
        const Vector_3d& p = m_boundary.points[(k * m_boundary.points.size()) / n_border];
        const double s = plane.signed_distance(p);
        const Vector_3d y = p - nn * (2 * s);
        const std::uint32_t c = m_boundary.tree.nearest(y);
        add(p, s, y, m_boundary.points[c], (y - m_boundary.points[c]).length(), m_boundary.across[c]);
      }
      if(weight_sum < 6)
        break;
      A += (1e-9 * A.trace() + 1e-300) * Eigen::Matrix3d::Identity();
      const Eigen::Vector3d x = A.ldlt().solve(-b);
      if(!x.allFinite())
        break;
      Vector_3d n2 = nn + e1 * x(0) + e2 * x(1);
      const double l = n2.length();
      if(!(l > 0))
        break;
      n2 = n2 / l;
      const Plane_3d next{n2, (plane.offset + x(2)) / l};
      const double step = std::abs(x(0)) + std::abs(x(1)) + std::abs(x(2)) / m_diagonal;
      plane = next;
      reach = (std::max)(final_reach, reach * 0.6);
      if(step < 1e-7 && reach <= final_reach)
        break;
    }
    return canonical(plane);
  }

  // The plane fitted to the vertices' mirror pairs under `plane` (pair_vertices(), a tenth of
  // the mean edge length): the sum of the pairs' differences, oriented along the normal, gives
  // the normal, the mean of the pairs' midpoints the offset; twice, pairing again. False, and
  // `plane` unchanged, when fewer than 90% of the vertices have a partner.
  bool fit_to_vertex_pairs(Plane_3d& plane) const
  {
    const std::vector<Vector_3d>& p = m_surface.points;
    std::vector<char> used(p.size(), 0);
    std::size_t n_used = 0;
    for(const auto& t : m_surface.triangles)
      for(std::uint32_t v : t)
        if(!used[v]) {
          used[v] = 1;
          ++n_used;
        }
    const double tolerance = 0.1 * mean_edge_length(m_surface);
    if(!(tolerance > 0))
      return false;
    Plane_3d fitted = plane;
    for(int round = 0; round < 2; ++round) {
      const Plane_frame frame(fitted, Vector_3d(0, 0, 0));
      std::vector<Vector_3d> q(p.size());
      for(std::size_t i = 0; i < p.size(); ++i)
        q[i] = frame.to_frame(p[i]);
      const std::vector<std::uint32_t> partner = pair_vertices(q, used, tolerance);
      std::size_t paired = 0;
      Vector_3d direction(0, 0, 0);
      for(std::size_t i = 0; i < p.size(); ++i) {
        if(partner[i] == no_partner)
          continue;
        ++paired;
        if(partner[i] > i) { // (a pair whose difference lies nearly in the plane has no clear sign)
          const Vector_3d d = p[i] - p[partner[i]];
          const double along = SAI::dot(d, fitted.normal);
          if(std::abs(along) >= 0.5 * d.length())
            direction += along < 0 ? d * -1.0 : d;
        }
      }
      if(double(paired) < 0.9 * double(n_used) || !(direction.squared_length() > 0))
        return false;
      const Vector_3d n = direction / direction.length();
      double sum = 0;
      for(std::size_t i = 0; i < p.size(); ++i)
        if(partner[i] != no_partner)
          sum += SAI::dot(n, (p[i] + p[partner[i]]) * 0.5);
      fitted = canonical(Plane_3d{n, sum / double(paired)});
    }
    plane = fitted;
    return true;
  }

  // The truncated RMS symmetry distance of the reflection across `plane`, relative to the
  // diagonal, over the first `n_samples` samples (all when 0).
  double score(const Plane_3d& plane, std::size_t n_samples = 0) const
  {
    const std::size_t n = n_samples == 0 ? m_samples.points.size()
                                         : (std::min)(n_samples, m_samples.points.size());
    const double cap = score_cap * m_diagonal;
    double sum = 0;
    std::uint32_t hint = Surface_index::no_face;
    for(std::size_t i = 0; i < n; ++i) {
      const Vector_3d y = reflect(plane, m_samples.points[i]);
      const Vector_3d m = reflect_direction(plane, m_samples.normals[i]);
      const Surface_point c = m_index.closest_compatible(y, m, 0.0, hint, cap);
      double d = cap;
      if(c.found && SAI::dot(m_index.face_normals()[c.face], m) > 0)
        d = (std::min)(cap, std::sqrt(c.squared_distance));
      sum += d * d;
    }
    return n > 0 ? std::sqrt(sum / double(n)) / m_diagonal : 0.0;
  }

  // Per face: exp(-delta^2 / (2 sigma^2)) with delta the distance of the reflected centroid to the
  // closest compatible surface point (0 without one); and the area-weighted mean.
  std::vector<double> support(const Plane_3d& plane, double& fraction) const
  {
    const std::size_t nf = m_surface.number_of_faces();
    std::vector<double> w(nf, 0.0);
    const std::vector<Vector_3d>& normals = m_index.face_normals();
    const double sigma = m_o.support_tolerance * m_diagonal;
    const double reach = 5 * sigma; // weights below 4e-6 are 0
    SAI::Parallel_workspaces<char> parallel(m_o.number_of_threads);
    const std::size_t block = 512;
    parallel.for_each(0, (nf + block - 1) / block, [&](std::size_t blk, char&) {
      std::vector<std::pair<double, std::uint32_t>> buffer;
      for(std::size_t f = blk * block; f < (std::min)(nf, (blk + 1) * block); ++f) {
        if(!(normals[f].squared_length() > 0))
          continue;
        const auto c = m_surface.corners(f);
        const Vector_3d y = reflect(plane, (c[0] + c[1] + c[2]) / 3.0);
        const Vector_3d m = reflect_direction(plane, normals[f]);
        const Surface_point s = m_index.approximate_closest_compatible(y, m, 0.0, reach, buffer);
        if(s.found && s.squared_distance < reach * reach)
          w[f] = std::exp(-s.squared_distance / (2 * sigma * sigma));
      }
    });
    double area = 0, sum = 0;
    for(std::size_t f = 0; f < nf; ++f) {
      const double a = m_surface.area(f);
      area += a;
      sum += a * w[f];
    }
    fraction = area > 0 ? sum / area : 0.0;
    return w;
  }

private:
  // Pair votes: (canonical plane), for pairs of samples whose normals mirror each other across
  // their bisector plane.
  std::vector<Plane_3d> votes() const
  {
    const std::size_t n = m_samples.points.size();
    const double min_length = 0.01 * m_diagonal;
    const double cos_tolerance = std::cos(normal_tolerance_degrees * 3.14159265358979323846 / 180.0);
    std::vector<std::vector<Plane_3d>> per_row(n);
    SAI::Parallel_workspaces<char> parallel(m_o.number_of_threads);
    parallel.for_each(0, n, [&](std::size_t i, char&) {
      const Vector_3d& p = m_samples.points[i];
      const Vector_3d& np = m_samples.normals[i];
      std::vector<Plane_3d>& out = per_row[i];
      for(std::size_t j = i + 1; j < n; ++j) {
        Vector_3d u = p - m_samples.points[j];
        const double l = u.length();
        if(!(l > min_length))
          continue;
        u = u / l;
        const Vector_3d r = np - u * (2 * SAI::dot(np, u));
        if(!(SAI::dot(r, m_samples.normals[j]) > cos_tolerance))
          continue;
        out.push_back(canonical(Plane_3d{u, SAI::dot(u, (p + m_samples.points[j]) * 0.5)}));
      }
    });
    std::vector<Plane_3d> all;
    for(auto& row : per_row)
      all.insert(all.end(), row.begin(), row.end());
    return all;
  }

  // The vote peaks: bins of (cube-map face, u, v, offset), summed over their 3x3x3 neighbours,
  // greedily taken by decreasing sum away from the peaks already taken, each then moved to the
  // mean of the votes around it (mean shift over the votes of the 5x5x5 bins around it, 3
  // steps). At most 16 peaks of at least 4 votes.
  std::vector<std::pair<Plane_3d, std::size_t>> vote_peaks() const
  {
    const std::vector<Plane_3d> all = votes();
    std::vector<std::pair<Plane_3d, std::size_t>> peaks;
    if(all.empty())
      return peaks;
    const Vote_bins bins(all, 0.02 * m_diagonal);
    const double angle = 6.0 * 3.14159265358979323846 / 180.0, offset = 0.03 * m_diagonal;
    const double cos_angle = std::cos(angle);
    for(const auto& s : bins.smoothed()) {
      if(peaks.size() >= 16 || s.first < 4)
        break;
      std::size_t count = 0;
      const Plane_3d p = bins.mean_shift(s.second, cos_angle, offset, count);
      if(count < 4)
        continue;
      bool near = false;
      for(const auto& q : peaks)
        if(same_plane(q.first, p, 2 * angle, 2 * offset))
          near = true;
      if(!near)
        peaks.emplace_back(canonical(p), count);
    }
    return peaks;
  }

  const Surface& m_surface;
  const Surface_index& m_index;
  const Surface_samples& m_samples;
  double m_diagonal;
  Detection_options m_o;
  Surface_boundary m_boundary;
};

// The baseline of the benchmarks: an exhaustive search over orientations. Every one of
// `directions` unit normals spread evenly over a hemisphere (a Fibonacci spiral) gives the plane
// through the area centroid; all are scored on the samples; the `refined` best are refined like
// the candidates of `detect_planes()` and the best refined plane is returned with its score.
inline Detected_plane exhaustive_plane(const Surface& input, const Detection_options& o,
                                       std::size_t directions, std::size_t refined = 10)
{
  Detected_plane best;
  const double diagonal = input.diagonal();
  Surface surface = input;
  const Vector_3d centroid = input.area_centroid();
  for(Vector_3d& p : surface.points)
    p -= centroid;
  const Surface_index index(surface);
  const Surface_samples samples = sample_surface(surface, (std::max)(std::size_t(20), o.number_of_samples), o.random_seed, 0);
  const Plane_detector detector(surface, index, samples, diagonal, o);
  std::vector<std::pair<double, Plane_3d>> scored(directions);
  SAI::Parallel_workspaces<char> parallel(o.number_of_threads);
  parallel.for_each(0, directions, [&](std::size_t i, char&) {
    const double z = 1.0 - (double(i) + 0.5) / double(directions); // (0, 1): a hemisphere
    const double r = std::sqrt((std::max)(0.0, 1 - z * z));
    const double phi = 2.399963229728653 * double(i);
    const Plane_3d p{Vector_3d(r * std::cos(phi), r * std::sin(phi), z), 0.0};
    scored[i] = std::make_pair(detector.score(p), p);
  });
  std::stable_sort(scored.begin(), scored.end(),
                   [](const auto& a, const auto& b) { return a.first < b.first; });
  const std::size_t k = (std::min)(refined, scored.size());
  std::vector<Detected_plane> result(k);
  parallel.for_each(0, k, [&](std::size_t i, char&) {
    Plane_3d p = detector.refine(scored[i].second, 300, 8, 0.15, 0.05);
    p = detector.refine(p, 0, 20, 0.05, 0.02);
    result[i].plane = p;
    result[i].score = detector.score(p);
  });
  for(std::size_t i = 0; i < k; ++i)
    if(i == 0 || result[i].score < best.score)
      best = result[i];
  best.plane.offset += SAI::dot(best.plane.normal, centroid);
  return best;
}

// The score (see Plane_detector::score) of `plane` on `n` samples of `input` drawn with `seed`:
// an evaluation independent of the samples a detection used.
inline double evaluate_plane(const Surface& input, const Plane_3d& plane, std::size_t n,
                             std::uint64_t seed)
{
  Detection_options o;
  o.number_of_samples = n;
  const double diagonal = input.diagonal();
  const Surface_index index(input);
  const Surface_samples samples = sample_surface(input, n, seed, 7);
  const Plane_detector detector(input, index, samples, diagonal, o);
  return detector.score(plane);
}

// Detects the reflective symmetries of `input` (positions in any pose), best first.
inline std::vector<Detected_plane> detect_planes(const Surface& input, const Detection_options& o)
{
  std::vector<Detected_plane> result;
  const double diagonal = input.diagonal();
  if(!(diagonal > 0) || !std::isfinite(diagonal))
    return result;
  // Work relative to the area centroid.
  Surface surface = input;
  const Vector_3d centroid = input.area_centroid();
  for(Vector_3d& p : surface.points)
    p -= centroid;
  const Surface_index index(surface);
  if(index.empty())
    return result;
  const Surface_samples samples = sample_surface(surface, (std::max)(std::size_t(20), o.number_of_samples), o.random_seed, 0);
  const Plane_detector detector(surface, index, samples, diagonal, o);

  // Stage 1: every candidate refined on a subset of the samples.
  const std::vector<std::pair<Plane_3d, std::size_t>> candidates = detector.candidates();
  const std::size_t coarse_samples = 300;
  std::vector<std::pair<Plane_3d, double>> coarse(candidates.size());
  SAI::Parallel_workspaces<char> parallel(o.number_of_threads);
  parallel.for_each(0, candidates.size(), [&](std::size_t k, char&) {
    const Plane_3d p = detector.refine(candidates[k].first, coarse_samples, 8, 0.15, 0.05);
    coarse[k] = std::make_pair(p, detector.score(p, coarse_samples));
  });
  // Stage 2: the best distinct ones refined on every sample.
  std::vector<std::size_t> order(candidates.size());
  std::iota(order.begin(), order.end(), std::size_t(0));
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t a, std::size_t b) { return coarse[a].second < coarse[b].second; });
  const double same_angle = 2.0 * 3.14159265358979323846 / 180.0, same_offset = 0.01 * diagonal;
  std::vector<std::size_t> kept;
  for(std::size_t k : order) {
    bool duplicate = false;
    for(std::size_t j : kept)
      if(same_plane(coarse[j].first, coarse[k].first, same_angle, same_offset))
        duplicate = true;
    if(!duplicate)
      kept.push_back(k);
    if(kept.size() >= (std::max)(std::size_t(4), o.maximum_number_of_symmetries + 1))
      break;
  }
  std::vector<Detected_plane> refined(kept.size());
  parallel.for_each(0, kept.size(), [&](std::size_t i, char&) {
    Detected_plane& d = refined[i];
    d.plane = detector.refine(coarse[kept[i]].first, 0, 20, 0.05, 0.02);
    d.score = detector.score(d.plane);
    Plane_3d fitted = d.plane;
    if(detector.fit_to_vertex_pairs(fitted)) {
      const double fitted_score = detector.score(fitted);
      if(fitted_score <= d.score) {
        d.plane = fitted;
        d.score = fitted_score;
      }
    }
    d.votes = candidates[kept[i]].second;
  });
  std::stable_sort(refined.begin(), refined.end(),
                   [](const Detected_plane& a, const Detected_plane& b) { return a.score < b.score; });
  // Stage 3: duplicates merged, support, the best `maximum_number_of_symmetries` kept.
  for(Detected_plane& d : refined) {
    if(result.size() >= o.maximum_number_of_symmetries)
      break;
    bool duplicate = false;
    for(const Detected_plane& r : result)
      if(same_plane(r.plane, d.plane, same_angle, same_offset))
        duplicate = true;
    if(duplicate)
      continue;
    d.support = detector.support(d.plane, d.support_fraction);
    if(d.support_fraction < o.minimum_support)
      continue;
    result.push_back(std::move(d));
  }
  // Back to the input's coordinates.
  for(Detected_plane& d : result)
    d.plane.offset += SAI::dot(d.plane.normal, centroid);
  return result;
}

} // namespace internal
} // namespace Surface_mesh_symmetrization
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_SYMMETRIZATION_INTERNAL_PLANE_DETECTION_H
