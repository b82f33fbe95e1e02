// Copyright (c) 2026 CGAL Global Shape Analysis contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Symmetric remeshing: symmetric surfaces with asymmetric tessellations (random diagonals: flips;
// jittered vertices: mirror points) come out with every vertex, edge and face mirrored, pairs at
// exact mirror positions, close to the input, closed; the same result in another pose; the copy
// of one side; CGAL's cow after symmetrization, then decimated to a fifth; bad input. (Compiled in
// one translation unit with test_symmetrization.cpp: its own namespace.)

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/Surface_mesh_symmetrization/symmetric_remeshing.h>
#include <CGAL/Surface_mesh_symmetrization/symmetric_simplification.h>
#include <CGAL/Surface_mesh_symmetrization/symmetrize.h>
#include <CGAL/Surface_mesh_symmetrization/internal/Restore_splits.h>
#include <CGAL/Surface_mesh_symmetrization/internal/Surface_index.h>
#include <CGAL/Surface_mesh_symmetrization/internal/Symmetric_flips.h>
#include <CGAL/Shape_analysis/internal/Point_tree.h>
#include <Shape_analysis_support/Mesh_distance.h>
#include <Shape_analysis_support/Procedural_shapes.h>
#include <Shape_analysis_support/Procedural_symmetric_shapes.h>

#include <gtest/gtest.h>

#include "mesh_distance_checks.h"

#include <algorithm>
#include <cmath>
#include <random>
#include <set>
#include <string>
#include <vector>

namespace symmetric_remeshing_test {

typedef CGAL::Exact_predicates_inexact_constructions_kernel Kernel;
typedef Kernel::Point_3 Point;
typedef CGAL::Surface_mesh<Point> Mesh;
namespace SY = CGAL::Surface_mesh_symmetrization;
namespace SYI = CGAL::Surface_mesh_symmetrization::internal;
namespace SAI = CGAL::Shape_analysis::internal;
namespace SAS = CGAL::Shape_analysis_support;
typedef SY::Symmetry<Kernel> Symmetry;
typedef SAI::Vector_3d Vector_3d;

const Symmetry y_reflection = SY::reflective_symmetry<Kernel>(Kernel::Plane_3(0, 1, 0, 0));

// An ellipsoid (symmetric under y -> -y) as a latitude-longitude mesh whose quads are split by a
// random diagonal, its vertices moved along the surface by up to `jitter` of the grid's spacing
// (angles), both from `seed`: the surface is symmetric, the tessellation is not.
Mesh ellipsoid(std::size_t rings, std::size_t sectors, double jitter, unsigned seed)
{
  const double pi = 3.14159265358979323846;
  std::mt19937 random(seed);
  std::uniform_real_distribution<double> unit(-1, 1);
  Mesh m;
  const auto add = [&](double theta, double phi) {
    return m.add_vertex(Point(1.5 * std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), 0.7 * std::cos(theta)));
  };
  const auto north = add(0, 0), south = add(pi, 0);
  std::vector<Mesh::Vertex_index> v;
  for(std::size_t i = 1; i < rings; ++i)
    for(std::size_t j = 0; j < sectors; ++j) {
      const double theta = pi * (double(i) + jitter * unit(random)) / double(rings);
      const double phi = 2 * pi * (double(j) + jitter * unit(random)) / double(sectors);
      v.push_back(add(theta, phi));
    }
  const auto id = [&](std::size_t i, std::size_t j) { return v[(i - 1) * sectors + (j % sectors)]; };
  for(std::size_t j = 0; j < sectors; ++j) {
    m.add_face(north, id(1, j), id(1, j + 1));
    m.add_face(south, id(rings - 1, j + 1), id(rings - 1, j));
  }
  for(std::size_t i = 1; i + 1 < rings; ++i)
    for(std::size_t j = 0; j < sectors; ++j)
      if(random() % 2) {
        m.add_face(id(i, j), id(i + 1, j), id(i + 1, j + 1));
        m.add_face(id(i, j), id(i + 1, j + 1), id(i, j + 1));
      } else {
        m.add_face(id(i, j), id(i + 1, j), id(i, j + 1));
        m.add_face(id(i, j + 1), id(i + 1, j), id(i + 1, j + 1));
      }
  return m;
}

using symmetric_mesh_checks::largest_vertex_distance;
using symmetric_mesh_checks::surface_of;

// The largest distance between a vertex and the mirror image of its partner, relative to the
// diagonal (a vertex without a partner: infinite).
double largest_pair_error(const Mesh& m, const Symmetry& s)
{
  const SY::Symmetric_connectivity c = SY::measure_symmetric_connectivity(m, s);
  std::vector<Point> p;
  for(auto v : vertices(m))
    p.push_back(m.point(v));
  double e = 0;
  for(std::size_t i = 0; i < p.size(); ++i) {
    if(c.mirror_vertex[i] == SY::Symmetric_connectivity::no_vertex)
      return std::numeric_limits<double>::infinity();
    e = (std::max)(e, std::sqrt(CGAL::squared_distance(p[i], s.transformation(p[c.mirror_vertex[i]]))));
  }
  return e / surface_of(m).diagonal();
}

// Checks that `m` is closed, valid and fully mirrored, with exact pairs.
void expect_symmetric_mesh(const Mesh& m, const Symmetry& s)
{
  EXPECT_TRUE(CGAL::is_valid_polygon_mesh(m));
  EXPECT_TRUE(CGAL::is_closed(m));
  const SY::Symmetric_connectivity c = SY::measure_symmetric_connectivity(m, s);
  EXPECT_EQ(c.paired_vertices, 1.0);
  EXPECT_EQ(c.symmetric_edges, 1.0);
  EXPECT_EQ(c.symmetric_faces, 1.0);
  EXPECT_LT(largest_pair_error(m, s), 1e-12);
}

TEST(SymmetricRemeshing, RandomDiagonalsAreFlippedIntoMirrors)
{
  const Mesh input = ellipsoid(14, 24, 0.0, 7);
  const SY::Symmetric_connectivity before = SY::measure_symmetric_connectivity(input, y_reflection);
  EXPECT_EQ(before.paired_vertices, 1.0);
  EXPECT_LT(before.symmetric_edges, 0.9);
  Mesh m = input;
  const SY::Symmetric_remeshing_result r = SY::symmetric_remeshing(m, y_reflection);
  EXPECT_EQ(r.mirror_points, 0u);
  EXPECT_GT(r.flips, 0u);
  EXPECT_EQ(r.after.symmetric_edges, 1.0);
  expect_symmetric_mesh(m, y_reflection);
  EXPECT_LE(std::abs(double(num_faces(m)) - double(num_faces(input))), 0.05 * double(num_faces(input)));
  EXPECT_LT(largest_vertex_distance(input, m), 0.01);
}

TEST(SymmetricRemeshing, JitteredVerticesGetMirrorPoints)
{
  for(unsigned seed : {1u, 2u, 3u}) {
    const Mesh input = ellipsoid(16, 28, 0.3, seed);
    EXPECT_LT(SY::measure_symmetric_connectivity(input, y_reflection).paired_vertices, 0.2);
    Mesh m = input;
    const SY::Symmetric_remeshing_result r = SY::symmetric_remeshing(m, y_reflection);
    EXPECT_GT(r.mirror_points, num_vertices(input) / 2) << seed;
    EXPECT_GT(r.meta_mesh_faces, num_faces(input)) << seed;
    expect_symmetric_mesh(m, y_reflection);
    EXPECT_LE(std::abs(double(num_faces(m)) - double(num_faces(input))), 0.05 * double(num_faces(input))) << seed;
    EXPECT_LT(largest_vertex_distance(input, m), 0.01) << seed;
    EXPECT_LT(largest_vertex_distance(m, input), 0.02) << seed;
  }
}

TEST(SymmetricRemeshing, CopyOfOneSideIsSymmetricToo)
{
  const Mesh input = ellipsoid(16, 28, 0.3, 4);
  Mesh m = input;
  const SY::Symmetric_remeshing_result r =
    SY::symmetric_remeshing(m, y_reflection, SY::parameters::copy_one_side(true).number_of_faces(10000));
  EXPECT_TRUE(r.copied_whole_side);
  EXPECT_EQ(r.mirror_points + r.flips, 0u);
  EXPECT_EQ(r.faces, r.meta_mesh_faces) << "no decimation above the copy's face count";
  EXPECT_EQ(r.faces, 2 * r.copied_faces) << "every face of the result, or its mirror image, copied";
  expect_symmetric_mesh(m, y_reflection);
  EXPECT_LT(largest_vertex_distance(input, m), 0.01);
}

// A box [-1, 1]^3, symmetric under y -> -y, with the corner (1, 1, 1) pulled out to y = 2 and its
// mirror image to y = -2: its faces y = 1 and y = -1 are bent quads (mirror images as surfaces),
// split by crossing diagonals (a-c on one side, the mirror image of b-d on the other), so the two
// sides fold along different lines. The four faces across the plane are fans around a centre on it.
Mesh bent_box()
{
  Mesh m;
  const auto add = [&](double x, double y, double z) { return m.add_vertex(Point(x, y, z)); };
  const auto a = add(-1, 1, -1), b = add(1, 1, -1), c = add(1, 2, 1), d = add(-1, 1, 1);
  const auto ma = add(-1, -1, -1), mb = add(1, -1, -1), mc = add(1, -2, 1), md = add(-1, -1, 1);
  m.add_face(a, d, c); // y > 0, outward: diagonal a-c
  m.add_face(a, c, b);
  m.add_face(ma, mb, md); // y < 0, outward: diagonal mb-md
  m.add_face(mb, mc, md);
  const auto fan = [&](Mesh::Vertex_index centre, std::vector<Mesh::Vertex_index> ring) {
    for(std::size_t i = 0; i < ring.size(); ++i)
      m.add_face(centre, ring[i], ring[(i + 1) % ring.size()]);
  };
  fan(add(1, 0, 0), {mb, b, c, mc});    // x = 1
  fan(add(-1, 0, 0), {ma, md, d, a});   // x = -1
  fan(add(0, 0, 1), {md, mc, c, d});    // z = 1
  fan(add(0, 0, -1), {ma, a, b, mb});   // z = -1
  return m;
}

TEST(SymmetricRemeshing, BothSidesFoldsAreOverlaid)
{
  const Mesh input = bent_box();
  ASSERT_TRUE(CGAL::is_valid_polygon_mesh(input) && CGAL::is_closed(input));
  const double diagonal = surface_of(input).diagonal();
  Mesh overlaid = input, copied = input;
  const SY::Symmetric_remeshing_result r =
    SY::symmetric_remeshing(overlaid, y_reflection, SY::parameters::number_of_faces(1000));
  EXPECT_EQ(r.flips, 0u) << "the flip across the fold moves the surface too far";
  EXPECT_EQ(r.overlaid_regions, 1u);
  EXPECT_EQ(r.overlay_points, 2u) << "the diagonals cross once on each side";
  EXPECT_EQ(r.copied_faces, 0u);
  EXPECT_EQ(r.faces, num_faces(input) + 4) << "each bent quad in four triangles around the crossing";
  expect_symmetric_mesh(overlaid, y_reflection);
  SY::symmetric_remeshing(copied, y_reflection, SY::parameters::number_of_faces(1000).copy_one_side(true));
  expect_symmetric_mesh(copied, y_reflection);
  // The copy puts one side's fold on both; the overlay keeps both folds, half way.
  const double overlay_distance = SAS::mesh_distance(overlaid, input, diagonal).hausdorff,
               copy_distance = SAS::mesh_distance(copied, input, diagonal).hausdorff;
  EXPECT_GT(copy_distance, 0.01);
  EXPECT_LT(overlay_distance, 0.75 * copy_distance);
}

TEST(SymmetricRemeshing, SameResultMovedInAnotherPose)
{
  const Mesh input = ellipsoid(12, 20, 0.25, 9);
  const SAS::Rigid_transform t =
    SAS::Rigid_transform::from_axis_angle(Vector_3d(1, 2, -0.7), 1.3, Vector_3d(30, -50, 20));
  Mesh moved = input;
  for(auto v : vertices(moved)) {
    const Point& p = moved.point(v);
    const Vector_3d q = t(Vector_3d(p.x(), p.y(), p.z()));
    moved.point(v) = Point(q.x, q.y, q.z);
  }
  const Vector_3d n = t(Vector_3d(0, 1, 0)) - t(Vector_3d(0, 0, 0)), o = t(Vector_3d(0, 0, 0));
  const Symmetry moved_plane = SY::reflective_symmetry<Kernel>(Kernel::Plane_3(n.x, n.y, n.z, -SAI::dot(n, o)));
  Mesh a = input, b = moved;
  SY::symmetric_remeshing(a, y_reflection);
  SY::symmetric_remeshing(b, moved_plane);
  ASSERT_EQ(num_faces(a), num_faces(b));
  expect_symmetric_mesh(b, moved_plane);
  // The same vertices (each one's image has a vertex of the other result within 1e-9).
  std::vector<Vector_3d> moved_a, in_b;
  std::vector<std::uint32_t> ids;
  for(auto v : vertices(b)) {
    const Point& p = b.point(v);
    in_b.emplace_back(p.x(), p.y(), p.z());
    ids.push_back(std::uint32_t(ids.size()));
  }
  const SAI::Point_tree tree(in_b, ids);
  double d = 0;
  for(auto v : vertices(a)) {
    const Point& p = a.point(v);
    std::uint32_t nearest = 0;
    double d2 = 0;
    ASSERT_TRUE(tree.nearest(t(Vector_3d(p.x(), p.y(), p.z())), 1.0, nearest, d2));
    d = (std::max)(d, std::sqrt(d2));
  }
  EXPECT_LT(d, 1e-9 * surface_of(a).diagonal());
}

TEST(SymmetricRemeshing, SymmetrizedCowThenAFifthOfItsFaces)
{
  Mesh cow;
  const std::string path = std::string(SHAPE_ANALYSIS_DATA_DIR) + "/cow.off";
  ASSERT_TRUE(CGAL::IO::read_polygon_mesh(path, cow)) << path;
  std::vector<Symmetry> s;
  SY::detect_reflective_symmetries(cow, std::back_inserter(s), SY::parameters::maximum_number_of_symmetries(1));
  ASSERT_FALSE(s.empty());
  SY::symmetrize(cow, std::vector<Symmetry>{s.front()});
  const Mesh symmetrized = cow;
  const SY::Symmetric_remeshing_result r = SY::symmetric_remeshing(cow, s.front());
  EXPECT_LT(r.before.symmetric_edges, 0.95);
  expect_symmetric_mesh(cow, s.front());
  EXPECT_LE(std::abs(double(r.faces) - double(r.faces_before)), 0.05 * double(r.faces_before));
  EXPECT_LT(largest_vertex_distance(symmetrized, cow), 0.02);
  EXPECT_LT(largest_vertex_distance(cow, symmetrized), 0.02);
  // Decimation to a fifth keeps all of it.
  const SY::Symmetric_decimation_result d =
    SY::symmetric_decimation(cow, s.front(), SY::parameters::number_of_faces(r.faces_before / 5));
  EXPECT_LE(std::abs(double(d.faces) - double(r.faces_before / 5)), 0.02 * double(r.faces_before / 5));
  expect_symmetric_mesh(cow, s.front());
  EXPECT_LT(largest_vertex_distance(symmetrized, cow), 0.02);
}

TEST(SymmetricRemeshing, BadInputIsRefusedAndTheMeshKept)
{
  const Mesh input = ellipsoid(8, 12, 0.2, 5);
  Mesh m = input;
  const auto expect_bad = [&](const auto& call) {
    EXPECT_THROW(call(), CGAL::Shape_analysis::Bad_input);
    EXPECT_EQ(num_faces(m), num_faces(input));
    EXPECT_EQ(num_vertices(m), num_vertices(input));
  };
  const Symmetry away = SY::reflective_symmetry<Kernel>(Kernel::Plane_3(0, 1, 0, -100)); // y = 100
  expect_bad([&] { SY::symmetric_remeshing(m, away); });
  expect_bad([&] { SY::symmetrize(m, std::vector<Symmetry>{away}); }); // would flatten the mesh onto the plane
  const Symmetry rotation =
    SY::affine_symmetry<Kernel>(Kernel::Aff_transformation_3(-1, 0, 0, 0, 0, -1, 0, 0, 0, 0, 1, 0));
  expect_bad([&] { SY::symmetric_remeshing(m, rotation); });
  expect_bad([&] { SY::symmetric_remeshing(m, y_reflection, SY::parameters::pairing_tolerance(-1.0)); });
  Mesh open = input;
  CGAL::Euler::remove_face(halfedge(*faces(open).begin(), open), open);
  open.collect_garbage();
  const std::size_t open_faces = num_faces(open);
  EXPECT_THROW(SY::symmetric_remeshing(open, y_reflection), CGAL::Shape_analysis::Bad_input);
  EXPECT_EQ(num_faces(open), open_faces);
  EXPECT_THROW(SY::symmetric_remeshing(m = Mesh(), y_reflection), CGAL::Shape_analysis::Bad_input);
}

// ellipsoid(18, 32, 0.2, seed) warped asymmetrically (by 0.05): a nearly symmetric surface.
Mesh warped_ellipsoid(unsigned seed)
{
  Mesh input = ellipsoid(18, 32, 0.2, seed);
  for(auto v : vertices(input)) {
    const Point& p = input.point(v);
    const auto q = SAS::asymmetric_warp({{p.x(), p.y(), p.z()}}, 0.05);
    input.point(v) = Point(q[0], q[1], q[2]);
  }
  return input;
}

TEST(SymmetricSimplification, RestoredResultLiesOnTheAsymmetricInput)
{
  const Mesh input = warped_ellipsoid(11);
  const std::size_t target = num_faces(input) / 5;
  Mesh restored = input, symmetric = input;
  const SY::Symmetric_simplification_result r =
    SY::symmetric_simplification(restored, y_reflection, SY::parameters::number_of_faces(target));
  const SY::Symmetric_simplification_result s = SY::symmetric_simplification(
    symmetric, y_reflection, SY::parameters::number_of_faces(target).restore_residuals(false));
  EXPECT_TRUE(r.restored);
  EXPECT_FALSE(s.restored);
  EXPECT_GT(r.symmetry_error_before, 10 * r.symmetry_error_after);
  for(const SY::Symmetric_simplification_result* x : {&r, &s}) {
    EXPECT_LE(std::abs(double(x->faces) - double(target)), 0.02 * double(target));
    EXPECT_EQ(x->remeshing.after.symmetric_edges, 1.0);
    EXPECT_EQ(x->remeshing.after.paired_vertices, 1.0);
  }
  for(const Mesh* m : {&restored, &symmetric}) {
    EXPECT_TRUE(CGAL::is_valid_polygon_mesh(*m));
    EXPECT_TRUE(CGAL::is_closed(*m));
  }
  expect_symmetric_mesh(symmetric, y_reflection);
  // Restoring brings the vertices back onto the input's surface.
  const double on_input = largest_vertex_distance(input, restored), off_input = largest_vertex_distance(input, symmetric);
  EXPECT_LT(on_input, 0.01) << off_input;
  EXPECT_LT(on_input, 0.25 * off_input);
}

// Restoring, both sides of the plane are tried as the side copied over the other: given the plane
// with its normal turned over, the result is the same mesh, its copied side the other one (the
// warped ellipsoid's sides, triangulated at random, differ in many places, so a wrong choice, or
// none, shows).
TEST(SymmetricSimplification, EitherOrientationOfThePlaneGivesTheSameMesh)
{
  const Mesh input = warped_ellipsoid(5);
  const std::size_t target = num_faces(input) / 5;
  const Symmetry turned = SY::reflective_symmetry<Kernel>(Kernel::Plane_3(0, -1, 0, 0));
  Mesh a = input, b = input;
  const SY::Symmetric_simplification_result ra =
    SY::symmetric_simplification(a, y_reflection, SY::parameters::number_of_faces(target));
  const SY::Symmetric_simplification_result rb =
    SY::symmetric_simplification(b, turned, SY::parameters::number_of_faces(target));
  EXPECT_EQ(ra.copied_side, -rb.copied_side);
  EXPECT_EQ(num_faces(a), num_faces(b));
  EXPECT_LT(largest_vertex_distance(a, b), 1e-9);
  EXPECT_LT(largest_vertex_distance(b, a), 1e-9);
  EXPECT_EQ(ra.remeshing.after.symmetric_edges, 1.0);
}

// Restoring, the remeshing and the copy of a whole side are both tried, and the closest to the input
// kept (measured as the function measures): on this warped ellipsoid the remeshing, closer than
// both copies (copy_one_side keeps the better copy).
TEST(SymmetricSimplification, TheClosestCandidateIsKept)
{
  const Mesh input = warped_ellipsoid(7);
  const std::size_t target = num_faces(input) / 5;
  Mesh best = input, copied = input;
  const SY::Symmetric_simplification_result rb =
    SY::symmetric_simplification(best, y_reflection, SY::parameters::number_of_faces(target));
  const SY::Symmetric_simplification_result rc =
    SY::symmetric_simplification(copied, y_reflection, SY::parameters::number_of_faces(target).copy_one_side(true));
  EXPECT_TRUE(rc.remeshing.copied_whole_side);
  EXPECT_EQ(rc.remeshing.after.symmetric_edges, 1.0);
  const SYI::Surface_index to(surface_of(input));
  const double db = SYI::sampled_hausdorff(SYI::Surface_index(surface_of(best)), to, 1);
  const double dc = SYI::sampled_hausdorff(SYI::Surface_index(surface_of(copied)), to, 1);
  EXPECT_FALSE(rb.remeshing.copied_whole_side);
  EXPECT_LT(db, dc);
  EXPECT_GT(db, 0.0);
}

// The refinement of a restored meta-mesh: a coarse mesh of symmetric connectivity on a symmetric
// ellipsoid, restored onto a warped fine copy of it, is refined where it leaves that copy; the
// splits keep it mirrored (the new points paired, mutually, and at mirror positions) and bring it
// closer to the warped surface.
TEST(SymmetricSimplification, RefinementFollowsTheInputAndStaysMirrored)
{
  Mesh coarse = ellipsoid(8, 12, 0.0, 3);
  SY::symmetric_remeshing(coarse, y_reflection);
  const SY::Symmetric_connectivity c = SY::measure_symmetric_connectivity(coarse, y_reflection);
  ASSERT_EQ(c.symmetric_edges, 1.0);
  std::vector<std::uint32_t> partner;
  for(std::size_t m : c.mirror_vertex)
    partner.push_back(std::uint32_t(m));
  const Mesh fine = ellipsoid(40, 64, 0.0, 4);
  const SYI::Surface symmetrized = surface_of(fine);
  std::vector<Kernel::Vector_3> residuals;
  Mesh input = fine;
  for(auto v : vertices(input)) {
    const Point p = input.point(v);
    const auto q = SAS::asymmetric_warp({{p.x(), p.y(), p.z()}}, 0.08);
    input.point(v) = Point(q[0], q[1], q[2]);
    residuals.push_back(input.point(v) - p);
  }
  SYI::Surface symmetric = surface_of(coarse), restored = symmetric;
  const SYI::Surface_index index(symmetrized);
  const std::vector<Vector_3d> normals = symmetric.vertex_normals();
  std::uint32_t hint = SYI::Surface_index::no_face;
  for(std::size_t i = 0; i < restored.points.size(); ++i)
    restored.points[i] = SYI::restored_point(index, symmetrized, residuals, symmetric.points[i], normals[i], hint, true);
  const auto to_mesh = [](const SYI::Surface& s) {
    Mesh m;
    SYI::rebuild_mesh(m, s, SY::parameters::default_values());
    return m;
  };
  const double diagonal = symmetrized.diagonal();
  const double before = SAS::mesh_distance(to_mesh(restored), input, diagonal, 20000).hausdorff;
  const std::size_t faces = symmetric.triangles.size();
  const std::size_t added = SYI::refine_restored(symmetric, restored, partner, index, symmetrized, residuals,
                                                 0.002 * diagonal, 100 * faces, 3);
  EXPECT_GT(added, 0u);
  EXPECT_EQ(partner.size(), symmetric.points.size());
  for(std::size_t i = 0; i < partner.size(); ++i)
    ASSERT_EQ(partner[partner[i]], i) << "pairs are mutual";
  const Mesh refined = to_mesh(symmetric);
  EXPECT_TRUE(CGAL::is_valid_polygon_mesh(refined));
  EXPECT_TRUE(CGAL::is_closed(refined));
  const SY::Symmetric_connectivity after = SY::measure_symmetric_connectivity(refined, y_reflection);
  EXPECT_EQ(after.symmetric_edges, 1.0);
  EXPECT_EQ(after.symmetric_faces, 1.0);
  for(std::size_t i = 0; i < partner.size(); ++i)
    EXPECT_EQ(after.mirror_vertex[i], partner[i]);
  const double now = SAS::mesh_distance(to_mesh(restored), input, diagonal, 20000).hausdorff;
  EXPECT_LT(now, 0.5 * before) << before;
  // A face budget below the first round's faces stops it.
  SYI::Surface s2 = surface_of(coarse), r2 = s2;
  std::vector<std::uint32_t> p2(c.mirror_vertex.begin(), c.mirror_vertex.end());
  EXPECT_EQ(SYI::refine_restored(s2, r2, p2, index, symmetrized, residuals, 0.002 * diagonal, faces, 3), 0u);
  EXPECT_EQ(s2.triangles.size(), faces);
}

// The splits that spend the restore's last faces: a coarse mesh of symmetric connectivity, its
// points moved onto a warped fine ellipsoid, split where it is farthest from that surface. The
// face count stays within the budget, the connectivity mirrored by the pairs (new points paired
// mutually), the new points on the warped surface, the mesh closed; the largest distance drops;
// the same result with one thread and with two.
TEST(SymmetricSimplification, FarthestSplitsFollowTheInputAndStayMirrored)
{
  Mesh coarse = ellipsoid(8, 12, 0.0, 3);
  SY::symmetric_remeshing(coarse, y_reflection);
  const SY::Symmetric_connectivity c = SY::measure_symmetric_connectivity(coarse, y_reflection);
  ASSERT_EQ(c.symmetric_edges, 1.0);
  Mesh input = ellipsoid(40, 64, 0.0, 4);
  for(auto v : vertices(input)) {
    const Point p = input.point(v);
    const auto q = SAS::asymmetric_warp({{p.x(), p.y(), p.z()}}, 0.08);
    input.point(v) = Point(q[0], q[1], q[2]);
  }
  const SYI::Surface_index reference(surface_of(input));
  SYI::Surface start = surface_of(coarse);
  SYI::snap_onto(start, reference, 0.0);
  const double diagonal = reference.surface().diagonal();
  const double before = SYI::sampled_hausdorff(SYI::Surface_index(start), reference, 1);
  const std::size_t budget = start.triangles.size() * 3 / 2;
  SYI::Surface one = start, two = start;
  std::vector<std::uint32_t> partner_one(c.mirror_vertex.begin(), c.mirror_vertex.end()), partner_two = partner_one;
  const std::size_t added = SYI::split_farthest(one, partner_one, reference, budget, 4, 8, 1);
  SYI::split_farthest(two, partner_two, reference, budget, 4, 8, 2);
  EXPECT_GT(added, 0u);
  EXPECT_LE(one.triangles.size(), budget);
  EXPECT_GT(one.triangles.size(), budget - 12) << "the budget is spent";
  EXPECT_EQ(one.triangles, two.triangles);
  EXPECT_EQ(partner_one, partner_two);
  for(std::size_t i = 0; i < one.points.size(); ++i)
    ASSERT_EQ((one.points[i] - two.points[i]).length(), 0.0) << i;
  ASSERT_EQ(partner_one.size(), one.points.size());
  std::set<std::array<std::uint32_t, 3>> faces;
  const auto sorted = [](std::array<std::uint32_t, 3> t) {
    std::sort(t.begin(), t.end());
    return t;
  };
  for(const auto& t : one.triangles)
    faces.insert(sorted(t));
  for(const auto& t : one.triangles)
    EXPECT_EQ(faces.count(sorted({{partner_one[t[0]], partner_one[t[1]], partner_one[t[2]]}})), 1u) << "mirror face";
  for(std::size_t i = 0; i < partner_one.size(); ++i)
    ASSERT_EQ(partner_one[partner_one[i]], i) << "pairs are mutual";
  for(std::size_t i = start.points.size(); i < one.points.size(); ++i)
    EXPECT_LT(std::sqrt(reference.closest(one.points[i]).squared_distance), 1e-9 * diagonal) << i;
  Mesh split;
  SYI::rebuild_mesh(split, one, SY::parameters::default_values());
  EXPECT_TRUE(CGAL::is_valid_polygon_mesh(split));
  EXPECT_TRUE(CGAL::is_closed(split));
  const double now = SYI::sampled_hausdorff(SYI::Surface_index(one), reference, 1);
  EXPECT_LT(now, 0.8 * before) << before;
}

// The snap of the finer restore pass: points of an ellipsoid pushed off it along their normals by
// growing offsets; those farther than the threshold end on the surface, the others stay put.
TEST(SymmetricSimplification, SnapMovesOnlyTheFarPointsOntoTheInput)
{
  const SYI::Surface surface = surface_of(ellipsoid(16, 24, 0.2, 5));
  const SYI::Surface_index index(surface);
  const std::vector<Vector_3d> normals = surface.vertex_normals();
  const double diagonal = surface.diagonal(), threshold = 0.01 * diagonal;
  SYI::Surface moved = surface;
  std::vector<double> offset(moved.points.size());
  for(std::size_t i = 0; i < moved.points.size(); ++i) {
    offset[i] = 0.02 * diagonal * double(i % 7) / 6.0; // 0 to twice the threshold
    moved.points[i] += normals[i] / normals[i].length() * offset[i];
  }
  const SYI::Surface before = moved;
  SYI::snap_onto(moved, index, threshold);
  std::size_t snapped = 0;
  for(std::size_t i = 0; i < moved.points.size(); ++i) {
    const double d = std::sqrt(index.closest(moved.points[i]).squared_distance);
    if(offset[i] > 1.1 * threshold) {
      EXPECT_LT(d, 1e-9 * diagonal) << i;
      EXPECT_LT((moved.points[i] - surface.points[i]).length(), 0.05 * diagonal) << "to its own place, near";
      ++snapped;
    } else if(offset[i] < 0.9 * threshold)
      EXPECT_EQ((moved.points[i] - before.points[i]).length(), 0.0) << i;
  }
  EXPECT_GT(snapped, moved.points.size() / 4);
}

// The flips after the restore's decimation: a square pyramid (mirror plane x = 0) meshed on a
// grid whose squares across the pyramid's edges take the diagonal that cuts them, mirrored,
// comes out on the pyramid (the reference surface) with its connectivity still mirrored.
TEST(SymmetricSimplification, MirroredFlipsFollowTheReferenceCreases)
{
  const int n = 3; // the grid from -n to n
  SYI::Surface wrong, right;
  for(int j = -n; j <= n; ++j)
    for(int i = -n; i <= n; ++i)
      wrong.points.emplace_back(i, j, 1.0 - 0.5 * (std::max)(std::abs(i), std::abs(j)));
  const auto id = [&](int i, int j) { return std::uint32_t((j + n) * (2 * n + 1) + (i + n)); };
  for(SYI::Surface* s : {&wrong, &right}) {
    s->points = wrong.points;
    s->triangles.clear();
    for(int j = -n; j < n; ++j)
      for(int i = 0; i < n; ++i) { // the right half, then its mirror image
        // The diagonal from (i, j) to (i + 1, j + 1) (rising), or from (i + 1, j) to (i, j + 1):
        // the pyramid's edge y = x rises across square (i, i), y = -x falls across (i, -i - 1).
        const bool crease = j == i || j == -i - 1;
        const bool use_rising = !crease || ((j == i) == (s == &right));
        std::vector<std::array<int, 6>> half; // corners (i, j) of two triangles, counterclockwise
        if(use_rising)
          half = {{{i, j, i + 1, j, i + 1, j + 1}}, {{i, j, i + 1, j + 1, i, j + 1}}};
        else
          half = {{{i, j, i + 1, j, i, j + 1}}, {{i + 1, j, i + 1, j + 1, i, j + 1}}};
        for(const auto& t : half) {
          s->triangles.push_back({{id(t[0], t[1]), id(t[2], t[3]), id(t[4], t[5])}});
          s->triangles.push_back({{id(-t[0], t[1]), id(-t[4], t[5]), id(-t[2], t[3])}}); // mirrored
        }
      }
  }
  const std::vector<char> used(wrong.points.size(), 1);
  const std::vector<std::uint32_t> partner = SYI::pair_vertices(wrong.points, used, 0.1);
  const SYI::Surface_index reference(right);
  const auto deviation = [&](const SYI::Surface& s) {
    double largest = 0;
    std::uint32_t hint = SYI::Surface_index::no_face;
    for(std::size_t f = 0; f < s.triangles.size(); ++f) {
      const auto c = s.corners(f);
      largest = (std::max)(largest, std::sqrt(reference.closest((c[0] + c[1] + c[2]) / 3.0, hint).squared_distance));
    }
    return largest;
  };
  ASSERT_GT(deviation(wrong), 0.05);
  ASSERT_EQ(SYI::count_symmetric_connectivity(wrong, partner).symmetric_edges,
            SYI::count_symmetric_connectivity(wrong, partner).edges);
  SYI::Symmetric_flipper flipper(wrong, partner, reference);
  const std::size_t flips = flipper.flip(0.8, 1e-9, 10);
  SYI::Surface flipped;
  flipper.export_surface(flipped);
  EXPECT_EQ(flips, std::size_t(4 * n)); // the squares across the pyramid's four edges
  EXPECT_LT(deviation(flipped), 1e-12);
  const SYI::Connectivity_counts c = SYI::count_symmetric_connectivity(flipped, partner);
  EXPECT_EQ(c.symmetric_edges, c.edges);
  EXPECT_EQ(c.symmetric_faces, c.faces);
  EXPECT_EQ(flipper.flip(0.8, 1e-9, 10), 0u); // nothing left to gain

  // Asymmetric positions (as the restore gives): the left half flattened to a tenth of its height,
  // and the reference that flattened left half as it is meshed. A flip would bring the right quads
  // onto the pyramid but move the left ones off the reference (by a tenth of what the right ones
  // gain): no pair flips, and the surface is exported as it was.
  SYI::Surface flat_left = wrong, reference_mesh = right;
  for(std::size_t i = 0; i < flat_left.points.size(); ++i)
    if(flat_left.points[i].x < 0)
      flat_left.points[i].z *= 0.1;
  reference_mesh.points = flat_left.points;
  for(std::size_t f = 0; f < right.triangles.size(); ++f) // the left faces as the mesh has them
    if(wrong.corners(f)[0].x + wrong.corners(f)[1].x + wrong.corners(f)[2].x < 0)
      reference_mesh.triangles[f] = wrong.triangles[f];
  const SYI::Surface_index asymmetric_reference(reference_mesh);
  SYI::Symmetric_flipper keeper(flat_left, partner, asymmetric_reference);
  EXPECT_EQ(keeper.flip(0.8, 1e-9, 10), 0u);
  SYI::Surface kept;
  keeper.export_surface(kept);
  const auto rotated = [](std::vector<std::array<std::uint32_t, 3>> t) { // smallest corner first
    for(auto& f : t)
      std::rotate(f.begin(), std::min_element(f.begin(), f.end()), f.end());
    return t;
  };
  EXPECT_EQ(rotated(kept.triangles), rotated(flat_left.triangles));
}

TEST(SymmetricSimplification, BadFaceCountsAreRefused)
{
  const Mesh input = ellipsoid(8, 12, 0.2, 5);
  Mesh m = input;
  for(std::size_t faces : {std::size_t(0), std::size_t(num_faces(input)) + 1}) {
    EXPECT_THROW(SY::symmetric_simplification(m, y_reflection, SY::parameters::number_of_faces(faces)),
                 CGAL::Shape_analysis::Bad_input);
    EXPECT_EQ(num_faces(m), num_faces(input));
  }
  EXPECT_THROW(SY::symmetric_simplification(m, y_reflection), CGAL::Shape_analysis::Bad_input) << "no face count";
}

} // namespace symmetric_remeshing_test
