// Detects the planar reflective symmetries of a triangle mesh and prints them, best first:
//   detect_reflective_symmetries [mesh.off]    (default: CGAL's triceratops)

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>

#include <CGAL/Surface_mesh_symmetrization/detect_reflective_symmetries.h>

#include <iostream>
#include <string>
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel Kernel;
typedef CGAL::Surface_mesh<Kernel::Point_3> Mesh;
namespace SMSY = CGAL::Surface_mesh_symmetrization;

int main(int argc, char** argv)
{
  const std::string path = argc > 1 ? argv[1] : std::string(SHAPE_ANALYSIS_DATA_DIR) + "/triceratops.off";
  Mesh mesh;
  if(!CGAL::IO::read_polygon_mesh(path, mesh) || faces(mesh).empty()) {
    std::cerr << "cannot read " << path << "\n";
    return 1;
  }

  std::vector<SMSY::Symmetry<Kernel>> symmetries;
  try {
    SMSY::detect_reflective_symmetries(mesh, std::back_inserter(symmetries),
                                       SMSY::parameters::maximum_number_of_symmetries(3).random_seed(1));
  } catch(const CGAL::Shape_analysis::Bad_input& e) {
    std::cerr << e.what() << "\n";
    return 1;
  }
  std::cout << path << ": " << symmetries.size() << " reflective symmetries\n";
  for(const SMSY::Symmetry<Kernel>& s : symmetries) {
    // The plane n.x = d, with n a unit vector; the support: which part maps onto itself.
    std::cout << "  plane " << s.plane << "  score " << s.score << "  support "
              << 100 * s.support_fraction << "% of the area\n";
  }
  return symmetries.empty() ? 1 : 0;
}
