// Copyright (c) 2026 CGAL Global Shape Analysis contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Rotational symmetry detection: procedural k-fold shapes and a surface of revolution in random
// poses give their axis within a degree and their order; CGAL's turbine (10 bolt holes), rotor (a
// ring with a knob: a partial surface of revolution) and cow (none); the same result for any
// number of threads; rotational_symmetry() is the turn it names; symmetrize() with a detected
// turn makes a warped 5-fold shape 5-fold again; bad input. (Compiled in one translation unit
// with test_symmetrization.cpp: its own namespace.)

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/Surface_mesh_symmetrization/detect_rotational_symmetries.h>
#include <CGAL/Surface_mesh_symmetrization/symmetrize.h>
#include <Shape_analysis_support/Procedural_symmetric_shapes.h>

#include "random_pose.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>
#include <vector>

namespace rotational_symmetry_test {

typedef CGAL::Exact_predicates_inexact_constructions_kernel Kernel;
typedef Kernel::Point_3 Point;
typedef CGAL::Surface_mesh<Point> Mesh;
namespace SY = CGAL::Surface_mesh_symmetrization;
namespace SYI = CGAL::Surface_mesh_symmetrization::internal;
namespace SAI = CGAL::Shape_analysis::internal;
namespace SAS = CGAL::Shape_analysis_support;
typedef SY::Rotational_symmetry<Kernel> Rotation;
typedef SAI::Vector_3d Vector_3d;

using symmetry_test_support::Pose;
using symmetry_test_support::random_pose;

Mesh blob(std::size_t k, const Pose& pose, double warp = 0)
{
  const SAS::Procedural_mesh p = SAS::rotational_blob(k, 40, 67); // 67 sectors: no symmetric tessellation
  Mesh m;
  for(const auto& q : p.points) {
    const std::array<double, 3> w = warp > 0 ? SAS::asymmetric_warp(q, warp) : q;
    const Vector_3d x = pose(Vector_3d(w[0], w[1], w[2]));
    m.add_vertex(Point(x.x, x.y, x.z));
  }
  for(const auto& t : p.triangles)
    m.add_face(Mesh::Vertex_index(std::uint32_t(t[0])), Mesh::Vertex_index(std::uint32_t(t[1])),
               Mesh::Vertex_index(std::uint32_t(t[2])));
  return m;
}

std::vector<Rotation> detect(const Mesh& m, std::size_t threads = 0)
{
  std::vector<Rotation> r;
  SY::detect_rotational_symmetries(m, std::back_inserter(r), SY::parameters::number_of_threads(threads));
  return r;
}

Vector_3d vec(const Kernel::Vector_3& v) { return Vector_3d(v.x(), v.y(), v.z()); }
Vector_3d vec(const Point& p) { return Vector_3d(p.x(), p.y(), p.z()); }

double angle_degrees(const Vector_3d& a, const Vector_3d& b)
{
  const double c = std::abs(SAI::dot(a, b)) / (a.length() * b.length());
  return std::acos((std::min)(1.0, c)) * 180 / 3.14159265358979323846;
}

// The distance from q to the line through p along the unit vector a.
double distance_to_axis(const Vector_3d& q, const Vector_3d& p, const Vector_3d& a)
{
  const Vector_3d d = q - p;
  return (d - a * SAI::dot(d, a)).length();
}

Mesh cgal_mesh(const std::string& name)
{
  Mesh m;
  const std::string path = std::string(SHAPE_ANALYSIS_DATA_DIR) + "/" + name;
  if(!CGAL::IO::read_polygon_mesh(path, m) || faces(m).empty())
    ADD_FAILURE() << "cannot read " << path;
  return m;
}

TEST(RotationDetection, ProceduralShapesInRandomPosesGiveTheirAxisAndOrder)
{
  unsigned seed = 1;
  for(std::size_t k : {0, 2, 3, 5, 8, 12}) {
    const Pose pose = random_pose(seed++);
    const Mesh m = blob(k, pose);
    const std::vector<Rotation> r = detect(m);
    ASSERT_EQ(r.size(), 1u) << k << "-fold";
    const Vector_3d truth = SYI::turn(pose.axis, pose.angle, Vector_3d(0, 0, 1));
    EXPECT_LT(angle_degrees(vec(r[0].axis), truth), 1.0) << k << "-fold";
    EXPECT_LT(distance_to_axis(vec(r[0].point), pose.shift, truth), 1e-2) << k << "-fold"; // (the shape is about 3 across)
    EXPECT_EQ(r[0].order, k);
    EXPECT_LT(r[0].score, 0.003);
    EXPECT_GT(r[0].support_fraction, 0.95);
    EXPECT_EQ(r[0].support.size(), num_faces(m));
  }
}

TEST(RotationDetection, DoesNotDependOnTheThreadCount)
{
  const Mesh m = blob(5, random_pose(9));
  const std::vector<Rotation> one = detect(m, 1), two = detect(m, 2);
  ASSERT_EQ(one.size(), two.size());
  for(std::size_t i = 0; i < one.size(); ++i) {
    EXPECT_EQ(one[i].axis, two[i].axis);
    EXPECT_EQ(one[i].point, two[i].point);
    EXPECT_EQ(one[i].order, two[i].order);
    EXPECT_EQ(one[i].score, two[i].score);
    EXPECT_EQ(one[i].support, two[i].support);
  }
}

TEST(RotationDetection, CgalMeshes)
{
  // The turbine: a disk of revolution about x with ten bolt holes: 10-fold (not 5-fold, not of
  // revolution), its axis to rounding error.
  std::vector<Rotation> r = detect(cgal_mesh("turbine.off"));
  ASSERT_FALSE(r.empty());
  EXPECT_EQ(r[0].order, 10u);
  EXPECT_LT(angle_degrees(vec(r[0].axis), Vector_3d(1, 0, 0)), 0.01);
  EXPECT_GT(r[0].support_fraction, 0.99);
  // The rotor: a ring of revolution about x with a knob on its rim: a partial symmetry.
  r = detect(cgal_mesh("rotor.off"));
  ASSERT_FALSE(r.empty());
  EXPECT_EQ(r[0].order, 0u);
  EXPECT_LT(angle_degrees(vec(r[0].axis), Vector_3d(1, 0, 0)), 0.1);
  EXPECT_GT(r[0].support_fraction, 0.75);
  EXPECT_LT(r[0].support_fraction, 0.95);
  // The cow turns onto itself about no axis.
  EXPECT_TRUE(detect(cgal_mesh("cow.off")).empty());
}

TEST(RotationDetection, RotationalSymmetryIsTheTurnItNames)
{
  const Point p(1, 2, 3);
  const Kernel::Vector_3 a(0, 0, 2);
  const SY::Symmetry<Kernel> s = SY::rotational_symmetry<Kernel>(p, a, 3.14159265358979323846 / 2);
  EXPECT_FALSE(s.is_reflection);
  const Point q = s.transformation.transform(Point(2, 2, 5)); // a quarter turn about the line x = 1, y = 2
  EXPECT_NEAR(q.x(), 1, 1e-12);
  EXPECT_NEAR(q.y(), 3, 1e-12);
  EXPECT_NEAR(q.z(), 5, 1e-12);
  const Point on_axis = s.transformation.transform(Point(1, 2, -7));
  EXPECT_NEAR(CGAL::squared_distance(on_axis, Point(1, 2, -7)), 0, 1e-24);
  EXPECT_THROW(SY::rotational_symmetry<Kernel>(p, Kernel::Vector_3(0, 0, 0), 1.0), CGAL::Shape_analysis::Bad_input);
  EXPECT_THROW(SY::rotational_symmetry<Kernel>(p, a, std::nan("")), CGAL::Shape_analysis::Bad_input);
}

TEST(RotationDetection, SymmetrizingAboutTheDetectedTurnMakesAWarpedShapeFiveFold)
{
  Mesh m = blob(5, random_pose(4), 0.03); // warped: nearly 5-fold
  std::vector<Rotation> r = detect(m);
  ASSERT_FALSE(r.empty());
  EXPECT_EQ(r[0].order, 5u);
  const auto result = SY::symmetrize(m, std::vector<SY::Symmetry<Kernel>>{r[0].symmetry()});
  EXPECT_LT(result.symmetry_error_after, 0.2 * result.symmetry_error_before);
  r = detect(m);
  ASSERT_FALSE(r.empty());
  EXPECT_EQ(r[0].order, 5u);
  EXPECT_LT(r[0].score, 0.002);
}

TEST(RotationDetection, BadInput)
{
  const Mesh m = blob(3, random_pose(2));
  std::vector<Rotation> r;
  const auto bad = [&](const auto& np) {
    EXPECT_THROW(SY::detect_rotational_symmetries(m, std::back_inserter(r), np), CGAL::Shape_analysis::Bad_input);
  };
  bad(SY::parameters::maximum_order(1));
  bad(SY::parameters::maximum_order(361));
  bad(SY::parameters::number_of_samples(10));
  bad(SY::parameters::minimum_support(1.5));
  bad(SY::parameters::support_tolerance(0));
  EXPECT_THROW(SY::detect_rotational_symmetries(Mesh(), std::back_inserter(r)), CGAL::Shape_analysis::Bad_input);
  EXPECT_TRUE(r.empty());
}

} // namespace rotational_symmetry_test
