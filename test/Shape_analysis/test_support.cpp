// The support code the other suites and the tool rely on: JSON reports, procedural shapes and
// partition agreement.
// Part of test_shape_analysis_core (one translation unit: see test/CMakeLists.txt).

#include "test_core_fixtures.h"

#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Polygon_mesh_processing/orientation.h>
#include <Shape_analysis_support/Json.h>
#include <Shape_analysis_support/Partition_agreement.h>

#include <array>
#include <limits>
#include <set>
#include <stdexcept>
#include <string>

namespace {

// ---------------------------------------------------------------------------------------------
// JSON (nlohmann-json; only what to_text() adds to it)

TEST(Json, TextWritesNanAsNullAndReplacesInvalidUtf8)
{
  SAS::Json j = SAS::Json::object();
  j["nan"] = std::numeric_limits<double>::quiet_NaN();
  j["name"] = std::string("caf\xE9.off"); // Latin-1, not UTF-8: a file name in another encoding
  EXPECT_THROW(j.dump(), SAS::Json::type_error); // what to_text() guards against
  std::string text;
  ASSERT_NO_THROW(text = SAS::to_text(j));
  EXPECT_NE(text.find("\"nan\": null"), std::string::npos) << text;
  EXPECT_NE(text.find("\"name\": \"caf\xEF\xBF\xBD.off\""), std::string::npos) << text; // U+FFFD
}

// ---------------------------------------------------------------------------------------------
// Procedural shapes

void expect_closed_manifold(const SAS::Labelled_triangle_mesh& lm, std::size_t components)
{
  ASSERT_EQ(lm.labels.size(), lm.triangles.size());
  Mesh m;
  ASSERT_NO_THROW(SAS::fill_polygon_mesh(lm, m));
  EXPECT_EQ(num_faces(m), lm.triangles.size());
  EXPECT_TRUE(m.is_valid(false));
  EXPECT_TRUE(CGAL::is_closed(m));
  EXPECT_TRUE(CGAL::is_triangle_mesh(m));
  EXPECT_EQ(SAS::number_of_components(lm), components);
  EXPECT_TRUE(PMP::is_outward_oriented(m));
  EXPECT_GT(PMP::volume(m), 0.0);
  // Every vertex is used and no triangle repeats a vertex.
  std::vector<char> used(lm.points.size(), 0);
  for(const auto& t : lm.triangles) {
    EXPECT_TRUE(t[0] != t[1] && t[1] != t[2] && t[0] != t[2]);
    for(std::size_t v : t)
      used[v] = 1;
  }
  EXPECT_EQ(std::count(used.begin(), used.end(), 0), 0);
}

TEST(ProceduralShapes, ClosedManifoldsWithEveryPartLabelled)
{
  struct Case
  {
    const char* name;
    SAS::Procedural_shape shape;
    double cell;
    std::size_t components;
  };
  const std::vector<Case> cases = {{"chain", SAS::three_sphere_chain(), 0.2, 1},
                                   {"chain seed 3", SAS::three_sphere_chain(3), 0.2, 1},
                                   {"body", SAS::body_with_limbs(), 0.15, 1},
                                   {"body with head", SAS::body_with_limbs(2, true), 0.15, 1},
                                   {"star", SAS::star(6), 0.17, 1},
                                   {"star 9", SAS::star(9, 4), 0.17, 1},
                                   {"boxes", SAS::separate_boxes(4), 0.15, 4}};
  const std::vector<std::size_t> labels = {3, 3, 5, 6, 7, 10, 4};
  for(std::size_t c = 0; c < cases.size(); ++c) {
    SCOPED_TRACE(cases[c].name);
    const SAS::Labelled_triangle_mesh lm = SAS::mesh_procedural_shape(cases[c].shape, cases[c].cell);
    EXPECT_EQ(lm.number_of_labels, labels[c]);
    EXPECT_GT(lm.number_of_faces(), 1000u);
    EXPECT_LT(lm.number_of_faces(), 20000u);
    expect_closed_manifold(lm, cases[c].components);
    std::vector<std::size_t> count(lm.number_of_labels, 0);
    for(std::size_t l : lm.labels) {
      ASSERT_LT(l, lm.number_of_labels);
      ++count[l];
    }
    for(std::size_t l = 0; l < count.size(); ++l)
      EXPECT_GT(count[l], 50u) << "label " << l;
    // The surface lies on the zero set of the field (within a fraction of a cell).
    for(const auto& p : lm.points)
      EXPECT_LT(std::abs(cases[c].shape.field(Vector_3d(p[0], p[1], p[2]))), 0.5 * cases[c].cell);
  }
}

TEST(ProceduralShapes, SphereAreaAndVolumeConverge)
{
  SAS::Procedural_shape s;
  s.add(SAS::Shape_primitive::sphere(Vector_3d(0.3, -0.2, 0.1), 1.0, 0));
  const SAS::Labelled_triangle_mesh lm = SAS::mesh_procedural_shape(s, 0.1);
  const Mesh m = to_surface_mesh(lm);
  EXPECT_NEAR(PMP::volume(m), 4.0 / 3.0 * CGAL_PI, 0.02 * 4.0 / 3.0 * CGAL_PI);
  EXPECT_NEAR(PMP::area(m), 4 * CGAL_PI, 0.03 * 4 * CGAL_PI);
  // Primitive distances.
  EXPECT_NEAR(SAS::Shape_primitive::capsule(Vector_3d(0, 0, 0), Vector_3d(2, 0, 0), 0.5, 0)
                .distance(Vector_3d(1, 1, 0)), 0.5, 1e-12);
  EXPECT_NEAR(SAS::Shape_primitive::box(Vector_3d(0, 0, 0), Vector_3d(1, 2, 3), 0)
                .distance(Vector_3d(0, 0, 0)), -1.0, 1e-12);
  EXPECT_NEAR(SAS::Shape_primitive::box(Vector_3d(0, 0, 0), Vector_3d(1, 1, 1), 0, 0.25)
                .distance(Vector_3d(2, 2, 0)), std::sqrt(2 * 1.25 * 1.25) - 0.25, 1e-12);
  EXPECT_NEAR(SAS::Shape_primitive::cylinder(Vector_3d(0, 0, 0), Vector_3d(0, 0, 2), 1, 0)
                .distance(Vector_3d(0, 0, 3)), 1.0, 1e-12);
  EXPECT_NEAR(SAS::Shape_primitive::cylinder(Vector_3d(0, 0, 0), Vector_3d(0, 0, 2), 1, 0)
                .distance(Vector_3d(3, 0, 1)), 2.0, 1e-12);
}

TEST(ProceduralShapes, DeterministicTransformsAndShuffles)
{
  const SAS::Labelled_triangle_mesh a = SAS::mesh_procedural_shape(SAS::body_with_limbs(5), 0.15);
  const SAS::Labelled_triangle_mesh b = SAS::mesh_procedural_shape(SAS::body_with_limbs(5), 0.15);
  EXPECT_EQ(a.points, b.points);
  EXPECT_EQ(a.triangles, b.triangles);
  EXPECT_EQ(a.labels, b.labels);
  const SAS::Labelled_triangle_mesh c = SAS::mesh_procedural_shape(SAS::body_with_limbs(6), 0.15);
  EXPECT_NE(a.points, c.points) << "another seed, another shape";

  // Rigid transform: areas and labels are kept, the rotation is orthonormal.
  SAS::Labelled_triangle_mesh t = a;
  const auto transform = SAS::Rigid_transform::from_axis_angle(Vector_3d(1, 2, 3), 0.7, Vector_3d(5, -1, 2));
  SAS::transform_points(t, transform);
  for(int i = 0; i < 3; ++i)
    for(int j = 0; j < 3; ++j)
      EXPECT_NEAR(SAI::dot(transform.rotation[i], transform.rotation[j]), i == j ? 1.0 : 0.0, 1e-12);
  EXPECT_NEAR(SAI::dot(SAI::cross(transform.rotation[0], transform.rotation[1]), transform.rotation[2]), 1.0, 1e-12);
  for(std::size_t f = 0; f < a.number_of_faces(); f += 97)
    EXPECT_NEAR(t.area(f), a.area(f), 1e-12);
  expect_closed_manifold(t, 1);

  // Shuffle: a permutation, same labels per triangle, reproducible from the seed.
  SAS::Labelled_triangle_mesh s = a;
  const std::vector<std::size_t> order = SAS::shuffle_faces(s, 21, true);
  std::vector<std::size_t> sorted = order;
  std::sort(sorted.begin(), sorted.end());
  for(std::size_t i = 0; i < sorted.size(); ++i)
    ASSERT_EQ(sorted[i], i);
  std::size_t moved = 0;
  for(std::size_t i = 0; i < order.size(); ++i) {
    moved += order[i] != i ? 1 : 0;
    EXPECT_EQ(s.labels[i], a.labels[order[i]]);
    std::array<std::size_t, 3> x = s.triangles[i], y = a.triangles[order[i]];
    // Same oriented triangle, possibly another first corner.
    std::rotate(x.begin(), std::min_element(x.begin(), x.end()), x.end());
    std::rotate(y.begin(), std::min_element(y.begin(), y.end()), y.end());
    EXPECT_EQ(x, y);
  }
  EXPECT_GT(moved, order.size() / 2);
  SAS::Labelled_triangle_mesh s2 = a;
  EXPECT_EQ(SAS::shuffle_faces(s2, 21, true), order);
  EXPECT_EQ(s2.triangles, s.triangles);
  expect_closed_manifold(s, 1);
}

TEST(ProceduralShapes, PartitionAgreementMeasures)
{
  const std::vector<int> a = {0, 0, 0, 1, 1, 2};
  EXPECT_EQ(SAS::rand_index(a, a), 1.0);
  EXPECT_EQ(SAS::rand_index(a, std::vector<int>{5, 5, 5, 3, 3, 9}), 1.0); // relabelled
  EXPECT_EQ(SAS::matched_overlap(a, std::vector<int>{5, 5, 5, 3, 3, 9}), 1.0);
  // 15 pairs; {0,0,0,1,1,2} vs all-in-one: agree on the 3 + 1 same pairs: 4/15.
  EXPECT_NEAR(SAS::rand_index(a, std::vector<int>(6, 0)), 4.0 / 15.0, 1e-15);
  EXPECT_NEAR(SAS::matched_overlap(a, std::vector<int>(6, 0)), 3.0 / 6.0, 1e-15);
  // Moving one item: pairs (item 2 with 0, 1, 3, 4) change: 11/15.
  EXPECT_NEAR(SAS::rand_index(a, std::vector<int>{0, 0, 1, 1, 1, 2}), 11.0 / 15.0, 1e-15);
  EXPECT_NEAR(SAS::matched_overlap(a, std::vector<int>{0, 0, 1, 1, 1, 2}), 5.0 / 6.0, 1e-15);
  // Weights.
  const std::vector<double> w = {1, 1, 1, 1, 1, 5};
  EXPECT_NEAR(SAS::matched_overlap(a, std::vector<int>{0, 0, 1, 1, 1, 2}, &w), 9.0 / 10.0, 1e-15);
  EXPECT_EQ(SAS::rand_index(a, a, &w), 1.0);
  EXPECT_THROW(SAS::rand_index(a, std::vector<int>{0}), std::invalid_argument);
}

} // namespace
