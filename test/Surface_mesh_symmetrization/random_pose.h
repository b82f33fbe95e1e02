// Copyright (c) 2026 CGAL Global Shape Analysis contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// A random rigid motion for the symmetry tests: shapes and symmetries placed in any pose.

#ifndef SHAPE_ANALYSIS_TEST_RANDOM_POSE_H
#define SHAPE_ANALYSIS_TEST_RANDOM_POSE_H

#include <CGAL/Shape_analysis/internal/Vector_3d.h>
#include <CGAL/Surface_mesh_symmetrization/internal/Rotation_detection.h>

#include <random>

namespace symmetry_test_support {

typedef CGAL::Shape_analysis::internal::Vector_3d Vector_3d;

// A turn about an axis through the origin, then a shift; the identity by default.
struct Pose
{
  Vector_3d axis{0, 0, 1}, shift;
  double angle = 0;
  Vector_3d operator()(const Vector_3d& p) const { return direction(p) + shift; }
  Vector_3d direction(const Vector_3d& v) const
  {
    return CGAL::Surface_mesh_symmetrization::internal::turn(axis, angle, v);
  }
};

// A pose with a random axis and angle and a shift of about 3 in each coordinate, from `seed`.
inline Pose random_pose(unsigned seed)
{
  std::mt19937 random(seed);
  std::normal_distribution<double> normal;
  Pose t;
  t.axis = Vector_3d(normal(random), normal(random), normal(random));
  t.axis = t.axis / t.axis.length();
  t.angle = std::uniform_real_distribution<double>(0, 6.283)(random);
  t.shift = Vector_3d(normal(random), normal(random), normal(random)) * 3.0;
  return t;
}

} // namespace symmetry_test_support

#endif // SHAPE_ANALYSIS_TEST_RANDOM_POSE_H
