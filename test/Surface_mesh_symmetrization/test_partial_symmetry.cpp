// Copyright (c) 2026 CGAL Global Shape Analysis contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// A shape symmetric only in part: the blob (symmetric under y -> -y) with a bump on its +y side
// only. Detection finds the plane with a support that varies over the surface (low on the bump
// and on its mirror region, high elsewhere); symmetrizing with that support keeps the bump where
// uniform weights flatten it towards its mirror image. (Compiled in one translation unit with
// test_symmetrization.cpp: its own namespace.)

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Surface_mesh_symmetrization/detect_reflective_symmetries.h>
#include <CGAL/Surface_mesh_symmetrization/symmetrize.h>
#include <Shape_analysis_support/Procedural_symmetric_shapes.h>

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace partial_symmetry_test {

typedef CGAL::Exact_predicates_inexact_constructions_kernel Kernel;
typedef Kernel::Point_3 Point;
typedef CGAL::Surface_mesh<Point> Mesh;
namespace SY = CGAL::Surface_mesh_symmetrization;
namespace SAS = CGAL::Shape_analysis_support;

// The bump's centre direction (on the +y side) and its mirror image.
const double bump[3] = {0.0, 0.75, 0.66}, mirror_bump[3] = {0.0, -0.75, 0.66};

double angular_distance(const Point& p, const double* c)
{
  const double l = std::sqrt(CGAL::to_double(p.x() * p.x() + p.y() * p.y() + p.z() * p.z()));
  return std::acos((std::max)(-1.0, (std::min)(1.0, (CGAL::to_double(p.x()) * c[0] + CGAL::to_double(p.y()) * c[1] +
                                                     CGAL::to_double(p.z()) * c[2]) / l)));
}

// The blob, its points pushed outwards by a bump of height 0.35 around `bump` (+y side only).
Mesh bumped_blob(std::size_t& apex)
{
  const SAS::Procedural_mesh blob = SAS::symmetric_blob(40, 80);
  Mesh m;
  double best = 1e9;
  for(const auto& q : blob.points) {
    const Point p(q[0], q[1], q[2]);
    const double a = angular_distance(p, bump);
    const double f = 1 + 0.35 * std::exp(-a * a / (2 * 0.15 * 0.15));
    const auto v = m.add_vertex(Point(q[0] * f, q[1] * f, q[2] * f));
    if(a < best)
      best = a, apex = std::size_t(v);
  }
  for(const auto& t : blob.triangles)
    m.add_face(Mesh::Vertex_index(std::uint32_t(t[0])), Mesh::Vertex_index(std::uint32_t(t[1])),
               Mesh::Vertex_index(std::uint32_t(t[2])));
  return m;
}

TEST(PartialSymmetry, SupportIsLowOnTheBumpAndItsMirrorAndKeepsTheBump)
{
  std::size_t apex = 0;
  Mesh m = bumped_blob(apex);
  std::vector<SY::Symmetry<Kernel>> found;
  SY::detect_reflective_symmetries(m, std::back_inserter(found), SY::parameters::maximum_number_of_symmetries(1));
  ASSERT_EQ(found.size(), 1u);
  const SY::Symmetry<Kernel>& s = found.front();
  EXPECT_NEAR(std::abs(CGAL::to_double(s.plane.b())), 1.0, 1e-3); // y = 0
  EXPECT_GT(s.support_fraction, 0.7);
  EXPECT_LT(s.support_fraction, 0.98);
  // Mean support of the faces near the bump, near its mirror region, and far from both (0.002,
  // 0.03 and 0.9997 when written; support fraction 0.966).
  double near_sum = 0, mirror_sum = 0, far_sum = 0;
  std::size_t near_n = 0, mirror_n = 0, far_n = 0;
  std::size_t f_index = 0;
  for(auto f : faces(m)) {
    const Point c = CGAL::centroid(m.point(target(halfedge(f, m), m)), m.point(target(next(halfedge(f, m), m), m)),
                                   m.point(source(halfedge(f, m), m)));
    const double w = s.support[f_index++];
    if(angular_distance(c, bump) < 0.2)
      near_sum += w, ++near_n;
    else if(angular_distance(c, mirror_bump) < 0.2)
      mirror_sum += w, ++mirror_n;
    else if(angular_distance(c, bump) > 0.6 && angular_distance(c, mirror_bump) > 0.6)
      far_sum += w, ++far_n;
  }
  ASSERT_GT(near_n, 10u);
  ASSERT_GT(mirror_n, 10u);
  EXPECT_LT(near_sum / double(near_n), 0.2);
  EXPECT_LT(mirror_sum / double(mirror_n), 0.2);
  EXPECT_GT(far_sum / double(far_n), 0.9);

  // Symmetrized with uniform weights, the bump is pulled towards its (flat) mirror; weighted by
  // the support, it stays: the apex moves much less (0.137 and 0.035 when written).
  const Point apex_before = m.point(Mesh::Vertex_index(std::uint32_t(apex)));
  Mesh uniform = m, weighted = m;
  SY::symmetrize(uniform, found, SY::parameters::support_weighting(false));
  SY::symmetrize(weighted, found, SY::parameters::support_weighting(true));
  const double moved_uniform =
    std::sqrt(CGAL::to_double(CGAL::squared_distance(apex_before, uniform.point(Mesh::Vertex_index(std::uint32_t(apex))))));
  const double moved_weighted =
    std::sqrt(CGAL::to_double(CGAL::squared_distance(apex_before, weighted.point(Mesh::Vertex_index(std::uint32_t(apex))))));
  EXPECT_GT(moved_uniform, 0.1);
  EXPECT_LT(moved_weighted, 0.4 * moved_uniform);
}

} // namespace partial_symmetry_test
