// Copyright (c) 2026 CGAL Global Shape Analysis contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Regularization of several symmetries: three planes a degree off perpendicular come out exactly
// perpendicular and near where they were; five planes and a 5-fold turn about a slightly
// scattered axis share one axis at multiples of 36 degrees; planes about an axis at no common
// angle are made perpendicular where they nearly are; nothing moves beyond the tolerance;
// duplicates are dropped; the result follows a rigid motion of the input; a plane a degree off
// its true place, regularized, lets symmetrize() keep a two-plane blob as it is; bad input. (Compiled in one
// translation unit with test_symmetrization.cpp: its own namespace.)

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Surface_mesh_symmetrization/detect_rotational_symmetries.h>
#include <CGAL/Surface_mesh_symmetrization/regularize_symmetries.h>
#include <CGAL/Surface_mesh_symmetrization/symmetrize.h>
#include <Shape_analysis_support/Procedural_symmetric_shapes.h>

#include "random_pose.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

namespace regularize_symmetries_test {

typedef CGAL::Exact_predicates_inexact_constructions_kernel Kernel;
typedef Kernel::Point_3 Point;
typedef CGAL::Surface_mesh<Point> Mesh;
namespace SY = CGAL::Surface_mesh_symmetrization;
namespace SYI = CGAL::Surface_mesh_symmetrization::internal;
namespace SAI = CGAL::Shape_analysis::internal;
namespace SAS = CGAL::Shape_analysis_support;
typedef SY::Symmetry<Kernel> Symmetry;
typedef SAI::Vector_3d Vector_3d;

const double pi = 3.14159265358979323846;

typedef symmetry_test_support::Pose Motion;
using symmetry_test_support::random_pose;

// The blob (about 3.2 x 2 x 1.6, centred near the origin), moved.
Mesh blob(const Motion& motion, bool rotational = false, double warp = 0)
{
  const SAS::Procedural_mesh p = SAS::symmetric_blob(30, 60, rotational);
  Mesh m;
  for(const auto& q : p.points) {
    const std::array<double, 3> w = warp > 0 ? SAS::asymmetric_warp(q, warp) : q;
    const Vector_3d x = motion(Vector_3d(w[0], w[1], w[2]));
    m.add_vertex(Point(x.x, x.y, x.z));
  }
  for(const auto& t : p.triangles)
    m.add_face(Mesh::Vertex_index(std::uint32_t(t[0])), Mesh::Vertex_index(std::uint32_t(t[1])),
               Mesh::Vertex_index(std::uint32_t(t[2])));
  return m;
}

Vector_3d normal_of(const Symmetry& s)
{
  const Vector_3d n(s.plane.a(), s.plane.b(), s.plane.c());
  return n / n.length();
}
double offset_of(const Symmetry& s) { return -s.plane.d() / Vector_3d(s.plane.a(), s.plane.b(), s.plane.c()).length(); }

// The plane through `p` with normal `n`, moved.
Symmetry plane(const Vector_3d& n, const Vector_3d& p, const Motion& motion = Motion())
{
  const Vector_3d m = motion.direction(n / n.length()), q = motion(p);
  return SY::reflective_symmetry<Kernel>(Kernel::Plane_3(m.x, m.y, m.z, -SAI::dot(m, q)));
}

// `v` turned by `degrees` towards the unit vector w perpendicular to it.
Vector_3d tilt(const Vector_3d& v, const Vector_3d& w, double degrees)
{
  const double a = degrees * pi / 180;
  return v * std::cos(a) + w * std::sin(a);
}

double degrees_between(const Vector_3d& a, const Vector_3d& b)
{
  return std::acos((std::min)(1.0, std::abs(SAI::dot(a, b)) / (a.length() * b.length()))) * 180 / pi;
}

// The turn of a rotation symmetry: unit axis (angle in (0, pi]) and the point nearest `c`.
SYI::Regular_symmetry turn_of(const Symmetry& s, const Vector_3d& c)
{
  return SYI::regular_symmetry(SYI::affine_of(s, "test"), false, SYI::Plane_3d(), c);
}

TEST(RegularizeSymmetries, NearlyPerpendicularPlanesBecomePerpendicular)
{
  for(unsigned seed = 1; seed <= 4; ++seed) {
    const Motion motion = random_pose(seed);
    const Mesh mesh = blob(motion);
    const Vector_3d x(1, 0, 0), y(0, 1, 0), z(0, 0, 1);
    // Each plane 0.5 to 1.5 degrees off, 0.002 to 0.01 off the origin (diagonal about 4).
    const std::vector<Symmetry> in = {plane(tilt(y, x, 0.8), Vector_3d(0, 0.01, 0), motion),
                                      plane(tilt(x, z, -1.2), Vector_3d(0.005, 0, 0), motion),
                                      plane(tilt(z, y, 1.0), Vector_3d(0, 0, -0.002), motion)};
    const std::vector<Symmetry> out = SY::regularize_symmetries(mesh, in);
    ASSERT_EQ(out.size(), 3u) << seed;
    for(std::size_t i = 0; i < 3; ++i) {
      EXPECT_TRUE(out[i].is_reflection);
      // Each moved by at most what was wrong with the set (the first one not at all).
      EXPECT_LT(degrees_between(normal_of(out[i]), normal_of(in[i])), i == 0 ? 1e-9 : 2.5) << seed << ' ' << i;
      for(std::size_t j = i + 1; j < 3; ++j)
        EXPECT_LT(std::abs(SAI::dot(normal_of(out[i]), normal_of(out[j]))), 1e-12) << seed << ' ' << i << j;
    }
    // The planes keep their points nearest the blob's area centroid (near the moved origin): its
    // distance to each plane hardly changes.
    const Vector_3d c = motion(Vector_3d(0, 0, 0));
    for(std::size_t i = 0; i < 3; ++i)
      EXPECT_NEAR(SAI::dot(normal_of(out[i]), c) - offset_of(out[i]), SAI::dot(normal_of(in[i]), c) - offset_of(in[i]),
                  0.005) << seed << ' ' << i;
    // The three reflections generate a group of 8: the product of all three is the point
    // reflection, an involution.
    const auto t = out[0].transformation * out[1].transformation * out[2].transformation;
    const auto tt = t * t;
    for(int r = 0; r < 3; ++r)
      for(int c = 0; c < 4; ++c)
        EXPECT_NEAR(tt.m(r, c), r == c ? 1.0 : 0.0, 1e-9) << seed;
  }
}

TEST(RegularizeSymmetries, PlanesAndATurnAboutOneAxisShareItAtMultiplesOfTheirAngle)
{
  const Motion motion = random_pose(7);
  const Mesh mesh = blob(motion);
  const Vector_3d z(0, 0, 1);
  std::vector<Symmetry> in;
  std::mt19937 random(3);
  std::uniform_real_distribution<double> jitter(-1, 1);
  for(int k = 0; k < 5; ++k) { // 5 planes through the z axis, 36 degrees apart, each off by up to 0.6 degree and 0.01
    const double a = (36.0 * k + 0.6 * jitter(random)) * pi / 180;
    const Vector_3d n = tilt(Vector_3d(std::cos(a), std::sin(a), 0), z, 0.5 * jitter(random));
    in.push_back(plane(n, Vector_3d(0.01 * jitter(random), 0.01 * jitter(random), 0), motion));
  }
  // The 5-fold turn about an axis 0.7 degree and 0.01 off.
  const Vector_3d a = motion.direction(tilt(z, Vector_3d(1, 0, 0), 0.7)), p = motion(Vector_3d(0.01, -0.005, 0.3));
  in.insert(in.begin() + 2, SY::rotational_symmetry<Kernel>(Point(p.x, p.y, p.z), Kernel::Vector_3(a.x, a.y, a.z), 2 * pi / 5));
  const std::vector<Symmetry> out = SY::regularize_symmetries(mesh, in);
  ASSERT_EQ(out.size(), 6u);
  const SYI::Regular_symmetry turn = turn_of(out[2], motion(Vector_3d(0, 0, 0)));
  ASSERT_EQ(turn.kind, SYI::Regular_symmetry::ROTATION);
  EXPECT_NEAR(turn.angle, 2 * pi / 5, 1e-12);
  EXPECT_LT(degrees_between(turn.direction, motion.direction(z)), 1.0);
  for(std::size_t i = 0; i < 6; ++i) {
    if(i == 2)
      continue;
    const Vector_3d n = normal_of(out[i]);
    EXPECT_LT(std::abs(SAI::dot(n, turn.direction)), 1e-12) << i; // contains the axis' direction
    EXPECT_LT(std::abs(SAI::dot(n, turn.point) - offset_of(out[i])), 1e-10) << i; // and its point
    for(std::size_t j = i + 1; j < 6; ++j) {
      if(j == 2)
        continue;
      const double d = degrees_between(n, normal_of(out[j])); // a multiple of 36 degrees
      EXPECT_NEAR(d, 36 * std::round(d / 36), 1e-9) << i << ' ' << j;
    }
  }
  // Reflecting across a plane maps the turn to its inverse: R T R = T^-1, exactly.
  const auto rtr = out[0].transformation * out[2].transformation * out[0].transformation * out[2].transformation;
  for(int r = 0; r < 3; ++r)
    for(int c = 0; c < 4; ++c)
      EXPECT_NEAR(rtr.m(r, c), r == c ? 1.0 : 0.0, 1e-9);
}

TEST(RegularizeSymmetries, PlanesAboutOneAxisAtNoCommonAngleAreMadePerpendicularWhereTheyNearlyAre)
{
  // A table's two planes (0.8 degree from perpendicular) and a partial plane at 33.7 degrees,
  // all about the vertical axis (as detected on the Princeton benchmark's table 141): no multiple
  // of pi / k fits, the first two become perpendicular, the third keeps its angle.
  const Mesh mesh = blob(Motion());
  const auto horizontal = [](double degrees) {
    return Vector_3d(std::cos(degrees * pi / 180), std::sin(degrees * pi / 180), 0);
  };
  const std::vector<Symmetry> in = {plane(horizontal(0), Vector_3d()), plane(horizontal(90.8), Vector_3d()),
                                    plane(horizontal(33.7), Vector_3d(0.01, 0, 0))};
  const std::vector<Symmetry> out = SY::regularize_symmetries(mesh, in);
  ASSERT_EQ(out.size(), 3u);
  EXPECT_LT(std::abs(SAI::dot(normal_of(out[0]), normal_of(out[1]))), 1e-12);
  EXPECT_NEAR(degrees_between(normal_of(out[0]), normal_of(out[2])), 33.7, 0.05);
  for(std::size_t i = 0; i < 3; ++i) // through one vertical line
    EXPECT_LT(std::abs(normal_of(out[i]).z), 1e-12) << i;
  const Vector_3d p = normal_of(out[0]) * offset_of(out[0]) + normal_of(out[1]) * offset_of(out[1]);
  EXPECT_NEAR(SAI::dot(normal_of(out[2]), p), offset_of(out[2]), 1e-12);
}

TEST(RegularizeSymmetries, NothingMovesBeyondTheTolerance)
{
  const Mesh mesh = blob(Motion());
  const Vector_3d x(1, 0, 0), y(0, 1, 0), z(0, 0, 1);
  // 4 degrees from perpendicular: kept with the default 2, made perpendicular with 5.
  const std::vector<Symmetry> in = {plane(y, Vector_3d()), plane(tilt(x, y, 4), Vector_3d()), plane(z, Vector_3d(0, 0, 0.3))};
  const std::vector<Symmetry> kept = SY::regularize_symmetries(mesh, in);
  ASSERT_EQ(kept.size(), 3u);
  for(std::size_t i = 0; i < 3; ++i) {
    EXPECT_LT(degrees_between(normal_of(kept[i]), normal_of(in[i])), 1e-9) << i;
    EXPECT_NEAR(offset_of(kept[i]), offset_of(in[i]), 1e-12) << i;
  }
  const std::vector<Symmetry> snapped = SY::regularize_symmetries(mesh, in, SY::parameters::maximum_angle(5));
  EXPECT_LT(std::abs(SAI::dot(normal_of(snapped[0]), normal_of(snapped[1]))), 1e-12);
  // Three planes 0.02 apart on a common line: a group with maximum_offset 0.01 (0.04 here)...
  const std::vector<Symmetry> loose = {plane(x, Vector_3d()), plane(y, Vector_3d()),
                                       plane(Vector_3d(1, 1, 0), Vector_3d(0.02, 0, 0))};
  // (the third plane passes through the line where the first two meet)...
  const auto through_line = [&](const std::vector<Symmetry>& s) {
    const Vector_3d p = normal_of(s[0]) * offset_of(s[0]) + normal_of(s[1]) * offset_of(s[1]);
    return SAI::dot(normal_of(s[2]), p) - offset_of(s[2]);
  };
  EXPECT_NEAR(through_line(loose), -0.02 / std::sqrt(2.0), 1e-12);
  EXPECT_NEAR(through_line(SY::regularize_symmetries(mesh, loose)), 0, 1e-12);
  // ... not with 0.001.
  const std::vector<Symmetry> apart = SY::regularize_symmetries(mesh, loose, SY::parameters::maximum_offset(0.001));
  EXPECT_NEAR(offset_of(apart[2]), offset_of(loose[2]), 1e-12);
  EXPECT_NEAR(through_line(apart), through_line(loose), 1e-12);
  // maximum_angle 0: no plane turns or moves (only duplicates would be dropped).
  const std::vector<Symmetry> near = {plane(y, Vector_3d()), plane(tilt(x, y, 1.0), Vector_3d()),
                                      plane(Vector_3d(1, 1, 0), Vector_3d(0.02, 0, 0))};
  const std::vector<Symmetry> same = SY::regularize_symmetries(mesh, near, SY::parameters::maximum_angle(0));
  ASSERT_EQ(same.size(), 3u);
  for(std::size_t i = 0; i < 3; ++i) {
    EXPECT_LT(degrees_between(normal_of(same[i]), normal_of(near[i])), 1e-9) << i;
    EXPECT_NEAR(offset_of(same[i]), offset_of(near[i]), 1e-12) << i;
  }
}

TEST(RegularizeSymmetries, DuplicatesAreDroppedAndOtherMapsKept)
{
  const Mesh mesh = blob(Motion());
  const Vector_3d x(1, 0, 0), y(0, 1, 0);
  Kernel::Aff_transformation_3 shear(1, 0.2, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 1);
  Kernel::Aff_transformation_3 screw(0, -1, 0, 0, 1, 0, 0, 0, 0, 0, 1, 0.1, 1); // a quarter turn and a slide
  const std::vector<Symmetry> in = {plane(y, Vector_3d()), SY::affine_symmetry<Kernel>(shear),
                                    plane(tilt(y, x, 0.4) * -1.0, Vector_3d(0, 0.005, 0)),
                                    plane(tilt(x, y, 0.5), Vector_3d()), SY::affine_symmetry<Kernel>(screw)};
  const std::vector<Symmetry> out = SY::regularize_symmetries(mesh, in);
  ASSERT_EQ(out.size(), 4u); // the second y plane is the first one again
  EXPECT_FALSE(out[1].is_reflection);
  EXPECT_EQ(out[1].transformation.m(0, 1), 0.2);
  EXPECT_TRUE(out[2].is_reflection);
  EXPECT_LT(degrees_between(normal_of(out[2]), x), 1e-9); // made perpendicular to the first
  EXPECT_EQ(out[3].transformation.m(2, 3), 0.1);          // the screw kept as it is
  EXPECT_EQ(out[3].transformation.m(0, 1), -1.0);
  // Scores and supports are carried over.
  std::vector<Symmetry> scored = in;
  scored[3].score = 0.01;
  scored[3].support.assign(num_faces(mesh), 0.5);
  const std::vector<Symmetry> kept = SY::regularize_symmetries(mesh, scored);
  EXPECT_EQ(kept[2].score, 0.01);
  EXPECT_EQ(kept[2].support.size(), num_faces(mesh));
}

TEST(RegularizeSymmetries, FollowsARigidMotion)
{
  const Vector_3d x(1, 0, 0), y(0, 1, 0), z(0, 0, 1);
  const auto planes = [&](const Motion& m) {
    return std::vector<Symmetry>{plane(tilt(y, x, 0.8), Vector_3d(0, 0.01, 0), m),
                                 plane(tilt(x, z, -1.2), Vector_3d(0.005, 0, 0), m),
                                 plane(tilt(Vector_3d(1, 1, 0) / std::sqrt(2.0), z, 0.6), Vector_3d(0.004, 0, 0), m)};
  };
  const std::vector<Symmetry> still = SY::regularize_symmetries(blob(Motion()), planes(Motion()));
  const Motion motion = random_pose(11);
  const std::vector<Symmetry> moved = SY::regularize_symmetries(blob(motion), planes(motion));
  ASSERT_EQ(still.size(), moved.size());
  for(std::size_t i = 0; i < still.size(); ++i) {
    const Vector_3d n = motion.direction(normal_of(still[i]));
    EXPECT_LT(degrees_between(n, normal_of(moved[i])), 1e-7) << i;
    const Vector_3d foot = motion(normal_of(still[i]) * offset_of(still[i]));
    EXPECT_NEAR(SAI::dot(normal_of(moved[i]), foot), offset_of(moved[i]), 1e-9) << i;
  }
}

TEST(RegularizeSymmetries, RegularizedPlanesLetSymmetrizeReachBoth)
{
  // The blob symmetric under two perpendicular planes (the tessellation too), in a random pose;
  // the best plane found exactly, the second one a degree off, as a detection on a scanned mesh
  // may give it. Regularized, the second is the true plane again, and symmetrizing about both
  // leaves the symmetric blob nearly as it is; about the planes as given it warps the blob.
  const Motion motion = random_pose(5);
  const Mesh mesh = blob(motion, true);
  const Vector_3d x(1, 0, 0), y(0, 1, 0);
  const std::vector<Symmetry> given = {plane(y, Vector_3d(), motion), plane(tilt(x, y, 1.0), Vector_3d(), motion)};
  const std::vector<Symmetry> regular = SY::regularize_symmetries(mesh, given);
  ASSERT_EQ(regular.size(), 2u);
  EXPECT_LT(degrees_between(normal_of(regular[1]), motion.direction(x)), 1e-9);
  EXPECT_NEAR(offset_of(regular[1]), SAI::dot(normal_of(regular[1]), motion(Vector_3d())), 1e-6);
  Mesh a = mesh, b = mesh;
  const auto raw = SY::symmetrize(a, given);
  const auto reg = SY::symmetrize(b, regular);
  EXPECT_LT(reg.symmetry_error_before, 0.1 * raw.symmetry_error_before);
  EXPECT_LT(reg.distortion, 0.1 * raw.distortion) << raw.distortion << ' ' << reg.distortion;
  EXPECT_LE(reg.symmetry_error_after, raw.symmetry_error_after);
}

TEST(RegularizeSymmetries, BadInput)
{
  const Mesh mesh = blob(Motion());
  const std::vector<Symmetry> in = {plane(Vector_3d(0, 1, 0), Vector_3d())};
  EXPECT_THROW(SY::regularize_symmetries(mesh, in, SY::parameters::maximum_angle(-1)), SY::Bad_input);
  EXPECT_THROW(SY::regularize_symmetries(mesh, in, SY::parameters::maximum_angle(31)), SY::Bad_input);
  EXPECT_THROW(SY::regularize_symmetries(mesh, in, SY::parameters::maximum_angle(std::nan(""))), SY::Bad_input);
  EXPECT_THROW(SY::regularize_symmetries(mesh, in, SY::parameters::maximum_offset(1.5)), SY::Bad_input);
  Symmetry flat = in.front();
  flat.plane = Kernel::Plane_3(0, 0, 0, 1);
  EXPECT_THROW(SY::regularize_symmetries(mesh, std::vector<Symmetry>{flat}), SY::Bad_input);
  EXPECT_THROW(SY::regularize_symmetries(Mesh(), in), SY::Bad_input);
  EXPECT_TRUE(SY::regularize_symmetries(mesh, std::vector<Symmetry>()).empty());
}

} // namespace regularize_symmetries_test
