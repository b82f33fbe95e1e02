// Copyright (c) 2026 CGAL Global Shape Analysis contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Symmetric connectivity and symmetry-preserving decimation: a procedural shape whose connectivity
// is symmetric keeps it at every collapse and down to a fifth of its faces, exactly mirrored and
// close to the input; CGAL's cow before and after symmetrization; poses; bad input. (Compiled in
// one translation unit with test_symmetrization.cpp: its own namespace.)

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/Surface_mesh_symmetrization/symmetric_decimation.h>
#include <CGAL/Surface_mesh_symmetrization/symmetrize.h>
#include <CGAL/Surface_mesh_symmetrization/internal/Surface_index.h>
#include <Shape_analysis_support/Procedural_symmetric_shapes.h>
#include <Shape_analysis_support/Procedural_shapes.h>

#include <gtest/gtest.h>

#include "mesh_distance_checks.h"

#include <cmath>
#include <string>
#include <vector>

namespace symmetric_decimation_test {

typedef CGAL::Exact_predicates_inexact_constructions_kernel Kernel;
typedef Kernel::Point_3 Point;
typedef CGAL::Surface_mesh<Point> Mesh;
namespace SY = CGAL::Surface_mesh_symmetrization;
namespace SYI = CGAL::Surface_mesh_symmetrization::internal;
namespace SAI = CGAL::Shape_analysis::internal;
namespace SAS = CGAL::Shape_analysis_support;
typedef SY::Symmetry<Kernel> Symmetry;
typedef SAI::Vector_3d Vector_3d;

Mesh blob(std::size_t rings, std::size_t sectors)
{
  const SAS::Procedural_mesh m = SAS::symmetric_blob(rings, sectors);
  Mesh mesh;
  std::vector<Mesh::Vertex_index> v;
  for(const auto& p : m.points)
    v.push_back(mesh.add_vertex(Point(p[0], p[1], p[2])));
  for(const auto& t : m.triangles)
    mesh.add_face(v[t[0]], v[t[1]], v[t[2]]);
  return mesh;
}

const Symmetry y_reflection = SY::reflective_symmetry<Kernel>(Kernel::Plane_3(0, 1, 0, 0));

using symmetric_mesh_checks::largest_vertex_distance;
using symmetric_mesh_checks::surface_of;

TEST(SymmetricConnectivity, ProceduralShapeIsSymmetricAndAWarpIsNot)
{
  const Mesh m = blob(16, 24);
  const SY::Symmetric_connectivity c = SY::measure_symmetric_connectivity(m, y_reflection);
  EXPECT_EQ(c.paired_vertices, 1.0);
  EXPECT_EQ(c.symmetric_edges, 1.0);
  EXPECT_EQ(c.symmetric_faces, 1.0);
  EXPECT_EQ(c.number_of_vertices, num_vertices(m));
  ASSERT_EQ(c.mirror_vertex.size(), num_vertices(m));
  for(std::size_t v = 0; v < c.mirror_vertex.size(); ++v)
    EXPECT_EQ(c.mirror_vertex[c.mirror_vertex[v]], v) << "an involution";
  // Flip one diagonal: the four faces around it and its edge lose their mirrors.
  Mesh flipped = m;
  CGAL::Euler::flip_edge(halfedge(*std::next(edges(flipped).begin(), 100), flipped), flipped);
  const SY::Symmetric_connectivity f = SY::measure_symmetric_connectivity(flipped, y_reflection);
  EXPECT_EQ(f.paired_vertices, 1.0);
  EXPECT_LT(f.symmetric_edges, 1.0);
  EXPECT_EQ(f.number_of_edges - std::size_t(std::lround(f.symmetric_edges * double(f.number_of_edges))), 2u)
    << "the flipped edge and its mirror";
  // A warp moves vertices off their mirror positions: fewer pairs.
  Mesh warped = m;
  for(auto v : vertices(warped)) {
    const Point& p = warped.point(v);
    const auto q = SAS::asymmetric_warp({{p.x(), p.y(), p.z()}}, 0.05);
    warped.point(v) = Point(q[0], q[1], q[2]);
  }
  EXPECT_LT(SY::measure_symmetric_connectivity(warped, y_reflection).paired_vertices, 0.5);
}

// A blob in the frame of its plane (y = 0 becomes x = 0), pairs exactly mirrored: its partners.
std::vector<std::uint32_t> framed_blob(std::size_t rings, std::size_t sectors, SYI::Surface& s)
{
  s = surface_of(blob(rings, sectors));
  const SYI::Plane_frame frame(SYI::Plane_3d{Vector_3d(0, 1, 0), 0}, s.area_centroid());
  std::vector<char> used(s.points.size(), 1);
  for(Vector_3d& p : s.points)
    p = frame.to_frame(p);
  const std::vector<std::uint32_t> partner = SYI::pair_vertices(s.points, used, 0.01);
  SYI::make_pairs_exact(s.points, partner);
  return partner;
}

TEST(SymmetricDecimation, EveryCollapseKeepsTheConnectivitySymmetric)
{
  SYI::Surface s;
  const std::vector<std::uint32_t> partner = framed_blob(8, 12, s);
  SYI::Symmetric_decimator d(s, partner);
  std::size_t steps = 0;
  while(d.step()) { // down to the smallest mesh it can reach
    SYI::Surface out;
    std::vector<std::uint32_t> p;
    d.export_surface(out, p);
    const SYI::Connectivity_counts c = SYI::count_symmetric_connectivity(out, p);
    ASSERT_EQ(c.symmetric_edges, c.edges) << "after collapse " << steps;
    ASSERT_EQ(c.paired_vertices, c.vertices);
    for(std::size_t v = 0; v < p.size(); ++v) {
      ASSERT_EQ(out.points[p[v]].x, -out.points[v].x) << "exactly mirrored";
      ASSERT_EQ(out.points[p[v]].y, out.points[v].y);
    }
    ASSERT_TRUE(CGAL::is_valid_polygon_mesh(d.mesh()));
    ++steps;
  }
  EXPECT_GT(steps, 20u);
  EXPECT_LE(d.number_of_faces(), 8u);
  EXPECT_GT(d.t_clusters(), 0u) << "edges from the plane collapsed with their mirrors";
}

// Given quadrics (the symmetric simplification's: positions not mirrored) whose optima lie a mean
// edge length and a half aside: once other positions are allowed (ends and midpoints where the
// optimum folds a face), the decimation still reaches its target with every edge mirrored and a
// valid closed mesh; with mirrored positions there is nothing to allow.
TEST(SymmetricDecimation, OtherPositionsKeepTheConnectivitySymmetric)
{
  SYI::Surface s;
  const std::vector<std::uint32_t> partner = framed_blob(16, 24, s);
  const double shift = 1.5 * SYI::mean_edge_length(s);
  std::vector<SYI::Symmetric_decimator::Quadric> given;
  for(const Vector_3d& p : s.points) {
    SYI::Symmetric_decimator::Quadric q = SYI::Symmetric_decimator::Quadric::Zero();
    for(const Vector_3d& n : {Vector_3d(1, 0, 0), Vector_3d(0, 1, 0), Vector_3d(0, 0, 1)})
      q += SYI::Symmetric_decimator::plane_quadric(n, p + Vector_3d(0, 0, shift));
    given.push_back(q);
  }
  const std::size_t target = s.triangles.size() / 10;
  SYI::Symmetric_decimator d(s, partner, false, &given);
  EXPECT_TRUE(d.allow_other_positions());
  EXPECT_FALSE(d.allow_other_positions()) << "once";
  while(d.number_of_faces() > target && d.step()) {
  }
  EXPECT_LE(d.number_of_faces(), target);
  EXPECT_GE(d.number_of_faces(), target - 4);
  SYI::Surface out;
  std::vector<std::uint32_t> p;
  d.export_surface(out, p);
  const SYI::Connectivity_counts c = SYI::count_symmetric_connectivity(out, p);
  EXPECT_EQ(c.symmetric_edges, c.edges);
  EXPECT_EQ(c.paired_vertices, c.vertices);
  EXPECT_TRUE(CGAL::is_valid_polygon_mesh(d.mesh()) && CGAL::is_closed(d.mesh()));
  SYI::Symmetric_decimator mirrored(s, partner);
  EXPECT_FALSE(mirrored.allow_other_positions());
}

TEST(SymmetricDecimation, FifthOfTheFacesStaysSymmetricAndClose)
{
  const Mesh input = blob(40, 64);
  Mesh m = input;
  const std::size_t target = num_faces(m) / 5;
  const SY::Symmetric_decimation_result r = SY::symmetric_decimation(m, y_reflection, SY::parameters::number_of_faces(target));
  EXPECT_EQ(r.faces_before, num_faces(input));
  EXPECT_EQ(r.faces, num_faces(m));
  EXPECT_LE(r.faces, target);
  EXPECT_GE(double(r.faces), 0.98 * double(target));
  EXPECT_EQ(r.after.symmetric_edges, 1.0);
  EXPECT_EQ(r.after.paired_vertices, 1.0);
  EXPECT_TRUE(CGAL::is_closed(m) && CGAL::is_valid_polygon_mesh(m));
  EXPECT_EQ(SY::measure_symmetric_connectivity(m, y_reflection).symmetric_edges, 1.0);
  EXPECT_LT(largest_vertex_distance(input, m), 0.01) << "vertices stay on the input's surface";
  EXPECT_GT(r.largest_error, 0.0);
  EXPECT_LT(r.largest_error, 0.01);
  // An error bound instead of a count: fewer collapses, none above it.
  Mesh bounded = input;
  const SY::Symmetric_decimation_result b =
    SY::symmetric_decimation(bounded, y_reflection, SY::parameters::maximum_error(0.2 * r.largest_error));
  EXPECT_GT(b.faces, r.faces);
  EXPECT_LE(b.largest_error, 0.2 * r.largest_error);
}

TEST(SymmetricDecimation, SameResultMovedInAnotherPose)
{
  const Mesh input = blob(20, 32);
  const SAS::Rigid_transform t =
    SAS::Rigid_transform::from_axis_angle(Vector_3d(1, 2, -0.7), 1.3, Vector_3d(30, -50, 20));
  Mesh moved = input;
  for(auto v : vertices(moved)) {
    const Point& p = moved.point(v);
    const Vector_3d q = t(Vector_3d(p.x(), p.y(), p.z()));
    moved.point(v) = Point(q.x, q.y, q.z);
  }
  const Vector_3d n = t(Vector_3d(0, 1, 0)) - t(Vector_3d(0, 0, 0)), o = t(Vector_3d(0, 0, 0));
  const Symmetry moved_plane =
    SY::reflective_symmetry<Kernel>(Kernel::Plane_3(n.x, n.y, n.z, -SAI::dot(n, o)));
  Mesh a = input, b = moved;
  SY::symmetric_decimation(a, y_reflection, SY::parameters::number_of_faces(300));
  SY::symmetric_decimation(b, moved_plane, SY::parameters::number_of_faces(300));
  ASSERT_EQ(num_faces(a), num_faces(b));
  EXPECT_EQ(SY::measure_symmetric_connectivity(b, moved_plane).symmetric_edges, 1.0);
  double d = 0;
  auto vb = vertices(b).begin();
  for(auto v : vertices(a)) {
    const Point& p = a.point(v);
    const Vector_3d q = t(Vector_3d(p.x(), p.y(), p.z()));
    const Point& r = b.point(*vb++);
    d = (std::max)(d, (q - Vector_3d(r.x(), r.y(), r.z())).length());
  }
  EXPECT_LT(d, 1e-9 * surface_of(a).diagonal());
}

TEST(SymmetricConnectivity, SymmetrizedCowIsSymmetricInShapeNotInConnectivity)
{
  Mesh cow;
  const std::string path = std::string(SHAPE_ANALYSIS_DATA_DIR) + "/cow.off";
  ASSERT_TRUE(CGAL::IO::read_polygon_mesh(path, cow)) << path;
  std::vector<Symmetry> s;
  SY::detect_reflective_symmetries(cow, std::back_inserter(s), SY::parameters::maximum_number_of_symmetries(1));
  ASSERT_FALSE(s.empty());
  const SY::Symmetric_connectivity before = SY::measure_symmetric_connectivity(cow, s.front());
  SY::symmetrize(cow, std::vector<Symmetry>{s.front()});
  const SY::Symmetric_connectivity after = SY::measure_symmetric_connectivity(cow, s.front());
  // (The figures: 96% of the vertices and 82% of the edges after symmetrization.)
  EXPECT_GT(after.paired_vertices, before.paired_vertices);
  EXPECT_GT(after.paired_vertices, 0.9);
  EXPECT_GT(after.symmetric_edges, 0.7);
  EXPECT_LT(after.symmetric_edges, 0.99);
  // Decimation keeps what is symmetric and collapses only that.
  const std::size_t faces = num_faces(cow);
  const SY::Symmetric_decimation_result r =
    SY::symmetric_decimation(cow, s.front(), SY::parameters::number_of_faces(faces / 2));
  EXPECT_LT(r.faces, faces);
  EXPECT_GE(r.after.symmetric_edges, 0.9 * after.symmetric_edges);
  EXPECT_TRUE(CGAL::is_valid_polygon_mesh(cow));
}

TEST(SymmetricDecimation, BadInputIsRefusedAndTheMeshKept)
{
  const Mesh input = blob(8, 12);
  Mesh m = input;
  const auto expect_bad = [&](const auto& call) {
    EXPECT_THROW(call(), CGAL::Shape_analysis::Bad_input);
    EXPECT_EQ(num_faces(m), num_faces(input));
  };
  expect_bad([&] { SY::symmetric_decimation(m, y_reflection); }); // no target
  expect_bad([&] { SY::symmetric_decimation(m, y_reflection, SY::parameters::number_of_faces(num_faces(m) + 1)); });
  expect_bad([&] { SY::symmetric_decimation(m, y_reflection, SY::parameters::maximum_error(-1.0)); });
  expect_bad([&] {
    SY::symmetric_decimation(m, y_reflection, SY::parameters::number_of_faces(10).pairing_tolerance(0.0));
  });
  const Symmetry away = SY::reflective_symmetry<Kernel>(Kernel::Plane_3(0, 1, 0, -100)); // y = 100
  expect_bad([&] { SY::symmetric_decimation(m, away, SY::parameters::number_of_faces(10)); });
  const Symmetry rotation = SY::affine_symmetry<Kernel>(Kernel::Aff_transformation_3(
    -1, 0, 0, 0, 0, -1, 0, 0, 0, 0, 1, 0));
  expect_bad([&] { SY::symmetric_decimation(m, rotation, SY::parameters::number_of_faces(10)); });
  EXPECT_THROW(SY::measure_symmetric_connectivity(Mesh(), y_reflection), CGAL::Shape_analysis::Bad_input);
}

} // namespace symmetric_decimation_test
