// The checks of input meshes.
// Part of test_shape_analysis_core (one translation unit: see test/CMakeLists.txt).

#include "test_core_fixtures.h"

#include <CGAL/Shape_analysis/Bad_input.h>
#include <CGAL/Shape_analysis/internal/Mesh_checks.h>

#include <limits>
#include <string>

namespace {

// ---------------------------------------------------------------------------------------------
// Mesh checks

TEST(MeshChecks, RefuseEmptyPolygonalAndNonFiniteMeshes)
{
  const SAI::Point_to_vector<Kernel> to_vector{};
  Mesh empty;
  try {
    SAI::check_triangle_mesh(empty, get(CGAL::vertex_point, empty), to_vector, "who");
    FAIL() << "no exception";
  } catch(const SA::Bad_input& e) {
    EXPECT_NE(std::string(e.what()).find("who"), std::string::npos);
    EXPECT_NE(std::string(e.what()).find("no faces"), std::string::npos);
  }
  Mesh quad = make_mesh({Point(0, 0, 0), Point(1, 0, 0), Point(1, 1, 0), Point(0, 1, 0)}, {{0, 1, 2, 3}});
  EXPECT_THROW(SAI::check_triangle_mesh(quad, get(CGAL::vertex_point, quad), to_vector, "who"), SA::Bad_input);
  Mesh cube = unit_cube();
  EXPECT_NO_THROW(SAI::check_triangle_mesh(cube, get(CGAL::vertex_point, cube), to_vector, "who"));
  cube.point(*vertices(cube).begin()) = Point(std::numeric_limits<double>::quiet_NaN(), 0, 0);
  try {
    SAI::check_triangle_mesh(cube, get(CGAL::vertex_point, cube), to_vector, "who");
    FAIL() << "no exception";
  } catch(const SA::Bad_input& e) {
    EXPECT_NE(std::string(e.what()).find("finite"), std::string::npos);
  }
  // A non-finite vertex that no face uses is not looked at.
  Mesh tetra = unit_cube();
  tetra.add_vertex(Point(std::numeric_limits<double>::infinity(), 0, 0));
  EXPECT_NO_THROW(SAI::check_triangle_mesh(tetra, get(CGAL::vertex_point, tetra), to_vector, "who"));
}

} // namespace
