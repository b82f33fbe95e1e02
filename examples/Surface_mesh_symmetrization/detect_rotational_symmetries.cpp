// Detects the rotational symmetries of a triangle mesh (k-fold axes, surfaces of revolution) and
// prints them, best first:
//   detect_rotational_symmetries [mesh.off]    (default: CGAL's turbine, 10-fold)

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>

#include <CGAL/Surface_mesh_symmetrization/detect_rotational_symmetries.h>

#include <iostream>
#include <string>
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel Kernel;
typedef CGAL::Surface_mesh<Kernel::Point_3> Mesh;
namespace SMSY = CGAL::Surface_mesh_symmetrization;

int main(int argc, char** argv)
{
  const std::string path = argc > 1 ? argv[1] : std::string(SHAPE_ANALYSIS_DATA_DIR) + "/turbine.off";
  Mesh mesh;
  if(!CGAL::IO::read_polygon_mesh(path, mesh) || faces(mesh).empty()) {
    std::cerr << "cannot read " << path << "\n";
    return 1;
  }

  std::vector<SMSY::Rotational_symmetry<Kernel>> rotations;
  try {
    SMSY::detect_rotational_symmetries(mesh, std::back_inserter(rotations),
                                       SMSY::parameters::maximum_order(36).random_seed(1));
  } catch(const CGAL::Shape_analysis::Bad_input& e) {
    std::cerr << e.what() << "\n";
    return 1;
  }
  std::cout << path << ": " << rotations.size() << " rotational symmetries\n";
  for(const SMSY::Rotational_symmetry<Kernel>& r : rotations) {
    // order k: the turn by 2 pi / k maps the surface onto itself; 0: any turn does.
    std::cout << "  " << (r.order == 0 ? std::string("revolution") : std::to_string(r.order) + "-fold")
              << " about the axis through " << r.point << " along " << r.axis << "  score " << r.score
              << "  support " << 100 * r.support_fraction << "% of the area\n";
  }
  // r.symmetry() is the turn by 2 pi / k, for symmetrize() say.
  return rotations.empty() ? 1 : 0;
}
