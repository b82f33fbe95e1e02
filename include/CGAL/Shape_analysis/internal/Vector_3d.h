// Copyright (c) 2026 CGAL Global Shape Analysis contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_SHAPE_ANALYSIS_INTERNAL_VECTOR_3D_H
#define CGAL_SHAPE_ANALYSIS_INTERNAL_VECTOR_3D_H

// A plain double 3-vector for the inner loops of the graph machinery (kernel-independent, cheap).

#include <algorithm>
#include <cmath>

namespace CGAL {
namespace Shape_analysis {
namespace internal {

struct Vector_3d
{
  double x = 0, y = 0, z = 0;

  Vector_3d() = default;
  explicit Vector_3d(double v) : x(v), y(v), z(v) {}
  Vector_3d(double x_, double y_, double z_) : x(x_), y(y_), z(z_) {}

  double operator[](int i) const { return i == 0 ? x : (i == 1 ? y : z); }
  double& operator[](int i) { return i == 0 ? x : (i == 1 ? y : z); }

  Vector_3d operator+(const Vector_3d& o) const { return {x + o.x, y + o.y, z + o.z}; }
  Vector_3d operator-(const Vector_3d& o) const { return {x - o.x, y - o.y, z - o.z}; }
  Vector_3d operator*(double s) const { return {x * s, y * s, z * s}; }
  Vector_3d operator/(double s) const { return {x / s, y / s, z / s}; }
  Vector_3d& operator+=(const Vector_3d& o) { x += o.x; y += o.y; z += o.z; return *this; }
  Vector_3d& operator-=(const Vector_3d& o) { x -= o.x; y -= o.y; z -= o.z; return *this; }
  Vector_3d& operator*=(double s) { x *= s; y *= s; z *= s; return *this; }

  double squared_length() const { return x * x + y * y + z * z; }
  double length() const { return std::sqrt(squared_length()); }
  Vector_3d min(const Vector_3d& o) const { return {(std::min)(x, o.x), (std::min)(y, o.y), (std::min)(z, o.z)}; }
  Vector_3d max(const Vector_3d& o) const { return {(std::max)(x, o.x), (std::max)(y, o.y), (std::max)(z, o.z)}; }
};

inline double dot(const Vector_3d& a, const Vector_3d& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }

inline Vector_3d cross(const Vector_3d& a, const Vector_3d& b)
{
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}

// Divides the coefficients of the plane a x + b y + c z + d = 0 by a power of two near the largest
// of |a|, |b|, |c| (exact; the same plane): a normal of 1e-300 then has a square that does not
// underflow to zero. Nothing when (a, b, c) is zero or not finite.
inline void scale_plane_coefficients(double& a, double& b, double& c, double& d)
{
  const double largest = (std::max)((std::max)(std::abs(a), std::abs(b)), std::abs(c));
  if(!(largest > 0) || !std::isfinite(largest))
    return;
  int exponent = 0;
  std::frexp(largest, &exponent);
  a = std::ldexp(a, -exponent), b = std::ldexp(b, -exponent), c = std::ldexp(c, -exponent);
  d = std::ldexp(d, -exponent);
}

} // namespace internal
} // namespace Shape_analysis
} // namespace CGAL

#endif // CGAL_SHAPE_ANALYSIS_INTERNAL_VECTOR_3D_H
