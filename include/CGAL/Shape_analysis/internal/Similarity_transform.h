// Copyright (c) 2026 CGAL Global Shape Analysis contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_SHAPE_ANALYSIS_INTERNAL_SIMILARITY_TRANSFORM_H
#define CGAL_SHAPE_ANALYSIS_INTERNAL_SIMILARITY_TRANSFORM_H

// The closed-form part of the alignment of two point sets (see Similarity_alignment.h for the
// iterative part): 3x3 matrices, similarity transforms x -> s R x + t, the weighted principal frame
// of a point set, the 24 proper orientations of a frame's axes, and the best similarity between
// weighted point pairs.

#include <CGAL/Shape_analysis/internal/Vector_3d.h>

#include <Eigen/Dense>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <vector>

namespace CGAL {
namespace Shape_analysis {
namespace internal {

// ---------------------------------------------------------------------------------------------
// 3x3 matrices as three rows.

typedef std::array<Vector_3d, 3> Matrix_3d;

inline Matrix_3d identity_matrix()
{
  return {{Vector_3d(1, 0, 0), Vector_3d(0, 1, 0), Vector_3d(0, 0, 1)}};
}

inline Vector_3d multiply(const Matrix_3d& m, const Vector_3d& v)
{
  return Vector_3d(dot(m[0], v), dot(m[1], v), dot(m[2], v));
}

inline Matrix_3d transpose(const Matrix_3d& m)
{
  Matrix_3d t;
  for(int i = 0; i < 3; ++i)
    for(int j = 0; j < 3; ++j)
      t[std::size_t(i)][j] = m[std::size_t(j)][i];
  return t;
}

inline Matrix_3d multiply(const Matrix_3d& a, const Matrix_3d& b)
{
  const Matrix_3d bt = transpose(b);
  Matrix_3d c;
  for(std::size_t i = 0; i < 3; ++i)
    for(std::size_t j = 0; j < 3; ++j)
      c[i][int(j)] = dot(a[i], bt[j]);
  return c;
}

inline double determinant(const Matrix_3d& m) { return dot(m[0], cross(m[1], m[2])); }

// The largest absolute difference of two matrices' entries.
inline double max_difference(const Matrix_3d& a, const Matrix_3d& b)
{
  double d = 0;
  for(std::size_t i = 0; i < 3; ++i)
    for(int j = 0; j < 3; ++j)
      d = (std::max)(d, std::abs(a[i][j] - b[i][j]));
  return d;
}

// The angle (radians, in [0, pi]) of the rotation a^T b, i.e. how far rotation a is from b.
inline double rotation_angle_between(const Matrix_3d& a, const Matrix_3d& b)
{
  const Matrix_3d r = multiply(transpose(a), b);
  const double c = 0.5 * (r[0][0] + r[1][1] + r[2][2] - 1.0);
  return std::acos((std::max)(-1.0, (std::min)(1.0, c)));
}

// ---------------------------------------------------------------------------------------------
// Similarity transforms.

// x -> scale * rotation * x + translation.
struct Similarity_3d
{
  Matrix_3d rotation = identity_matrix();
  double scale = 1;
  Vector_3d translation;

  Vector_3d operator()(const Vector_3d& p) const
  {
    return multiply(rotation, p) * scale + translation;
  }

  // The inverse: y -> R^T (y - t) / s.
  Similarity_3d inverse() const
  {
    Similarity_3d r;
    r.rotation = transpose(rotation);
    r.scale = 1.0 / scale;
    r.translation = multiply(r.rotation, translation) * (-r.scale);
    return r;
  }

  // This transform after `first`: x -> (*this)(first(x)).
  Similarity_3d after(const Similarity_3d& first) const
  {
    Similarity_3d r;
    r.rotation = multiply(rotation, first.rotation);
    r.scale = scale * first.scale;
    r.translation = (*this)(first.translation);
    return r;
  }

  bool is_finite() const
  {
    if(!std::isfinite(scale) || !(scale > 0))
      return false;
    for(int i = 0; i < 3; ++i)
      if(!std::isfinite(translation[i]) || !std::isfinite(rotation[std::size_t(i)].x) ||
         !std::isfinite(rotation[std::size_t(i)].y) || !std::isfinite(rotation[std::size_t(i)].z))
        return false;
    return true;
  }
};

// ---------------------------------------------------------------------------------------------
// Principal frame.

struct Pca_frame
{
  Vector_3d centroid;
  Matrix_3d axes = identity_matrix(); // rows: principal axes, by decreasing variance, right-handed
  Vector_3d variances;                // weighted variance along each axis
  double total_weight = 0;

  // Root of the mean squared distance to the centroid.
  double rms_radius() const { return std::sqrt((std::max)(0.0, variances.x + variances.y + variances.z)); }
};

// The weighted principal frame of `points` (`weights` empty: every point weighs 1). The third
// axis is the cross product of the first two, so that `axes` is a rotation. With no weight at
// all, the frame is the identity at the origin.
inline Pca_frame weighted_pca(const std::vector<Vector_3d>& points,
                              const std::vector<double>& weights = std::vector<double>())
{
  Pca_frame frame;
  const bool weighted = !weights.empty();
  double w_sum = 0;
  Vector_3d c;
  for(std::size_t i = 0; i < points.size(); ++i) {
    const double w = weighted ? weights[i] : 1.0;
    w_sum += w;
    c += points[i] * w;
  }
  if(!(w_sum > 0))
    return frame;
  c = c / w_sum;
  Eigen::Matrix3d cov = Eigen::Matrix3d::Zero();
  for(std::size_t i = 0; i < points.size(); ++i) {
    const double w = weighted ? weights[i] : 1.0;
    const Vector_3d d = points[i] - c;
    const Eigen::Vector3d e(d.x, d.y, d.z);
    cov.noalias() += w * (e * e.transpose());
  }
  cov /= w_sum;
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver(cov);
  const Eigen::Vector3d values = solver.eigenvalues();   // increasing
  const Eigen::Matrix3d vectors = solver.eigenvectors(); // columns
  frame.centroid = c;
  frame.total_weight = w_sum;
  for(int k = 0; k < 3; ++k) {
    const int column = 2 - k;
    frame.axes[std::size_t(k)] =
      Vector_3d(vectors(0, column), vectors(1, column), vectors(2, column));
    frame.variances[k] = (std::max)(0.0, values(column));
  }
  frame.axes[2] = cross(frame.axes[0], frame.axes[1]);
  return frame;
}

// The 24 rotations that map the coordinate axes onto the coordinate axes (signed permutation
// matrices of determinant +1), the identity first.
inline std::vector<Matrix_3d> axis_orientations()
{
  std::vector<Matrix_3d> result;
  std::array<int, 3> permutation = {0, 1, 2};
  do {
    for(int signs = 0; signs < 8; ++signs) {
      Matrix_3d m = {{Vector_3d(0.0), Vector_3d(0.0), Vector_3d(0.0)}};
      for(int row = 0; row < 3; ++row)
        m[std::size_t(row)][permutation[std::size_t(row)]] = ((signs >> row) & 1) ? -1.0 : 1.0;
      if(determinant(m) > 0)
        result.push_back(m);
    }
  } while(std::next_permutation(permutation.begin(), permutation.end()));
  return result;
}

// The similarity T minimizing sum_i w_i |T(from_i) - to_i|^2 (every w_i = 1 when `weights` is
// empty); with `with_scale` false, the best rigid motion (scale 1). Returns false (and leaves
// `result` unchanged) when there is no total weight or the `from` points all coincide.
inline bool best_similarity(const std::vector<Vector_3d>& from, const std::vector<Vector_3d>& to,
                            const std::vector<double>& weights, Similarity_3d& result,
                            bool with_scale = true)
{
  const std::size_t n = (std::min)(from.size(), to.size());
  const bool weighted = !weights.empty();
  double w_sum = 0;
  Vector_3d mean_from, mean_to;
  for(std::size_t i = 0; i < n; ++i) {
    const double w = weighted ? weights[i] : 1.0;
    w_sum += w;
    mean_from += from[i] * w;
    mean_to += to[i] * w;
  }
  if(!(w_sum > 0))
    return false;
  mean_from = mean_from / w_sum;
  mean_to = mean_to / w_sum;
  // Cross-covariance sum w (to - mean_to)(from - mean_from)^T and spread of `from`.
  Eigen::Matrix3d cov = Eigen::Matrix3d::Zero();
  double spread = 0;
  for(std::size_t i = 0; i < n; ++i) {
    const double w = weighted ? weights[i] : 1.0;
    const Vector_3d a = from[i] - mean_from, b = to[i] - mean_to;
    const Eigen::Vector3d ea(a.x, a.y, a.z), eb(b.x, b.y, b.z);
    cov.noalias() += w * (eb * ea.transpose());
    spread += w * a.squared_length();
  }
  cov /= w_sum;
  spread /= w_sum;
  if(!(spread > 0) || !std::isfinite(spread))
    return false;
  const Eigen::JacobiSVD<Eigen::Matrix3d> svd(cov, Eigen::ComputeFullU | Eigen::ComputeFullV);
  const Eigen::Matrix3d& U = svd.matrixU();
  const Eigen::Matrix3d& V = svd.matrixV();
  // A reflection would fit better when det(U V^T) < 0: flip the weakest direction instead.
  Eigen::Vector3d d(1, 1, 1);
  if(U.determinant() * V.determinant() < 0)
    d(2) = -1;
  const Eigen::Matrix3d R = U * d.asDiagonal() * V.transpose();
  const double s = with_scale ? svd.singularValues().dot(d) / spread : 1.0;
  if(!(s > 0) || !std::isfinite(s))
    return false;
  Similarity_3d t;
  for(int i = 0; i < 3; ++i)
    t.rotation[std::size_t(i)] = Vector_3d(R(i, 0), R(i, 1), R(i, 2));
  t.scale = s;
  t.translation = mean_to - multiply(t.rotation, mean_from) * s;
  if(!t.is_finite())
    return false;
  result = t;
  return true;
}

} // namespace internal
} // namespace Shape_analysis
} // namespace CGAL

#endif // CGAL_SHAPE_ANALYSIS_INTERNAL_SIMILARITY_TRANSFORM_H
