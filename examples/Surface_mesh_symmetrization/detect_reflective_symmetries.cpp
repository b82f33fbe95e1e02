// Detects the planar reflective symmetries of a triangle mesh and prints them, best first, then
// regularizes them (nearly perpendicular planes made perpendicular, planes nearly sharing an axis
// made to share it) and prints the angles between them before and after:
//   detect_reflective_symmetries [mesh.off] [N]    (default: CGAL's triceratops, N = 3 planes)

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>

#include <CGAL/Surface_mesh_symmetrization/detect_reflective_symmetries.h>
#include <CGAL/Surface_mesh_symmetrization/regularize_symmetries.h>

#include <cmath>
#include <cstdlib>
#include <iostream>
#include <string>
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel Kernel;
typedef CGAL::Surface_mesh<Kernel::Point_3> Mesh;
namespace SMSY = CGAL::Surface_mesh_symmetrization;

// The angle between two planes, in degrees (0 to 90).
double degrees_between(const Kernel::Plane_3& a, const Kernel::Plane_3& b)
{
  const Kernel::Vector_3 n = a.orthogonal_vector(), m = b.orthogonal_vector();
  const double c = std::abs(n * m) / std::sqrt(n.squared_length() * m.squared_length());
  return std::acos(c > 1 ? 1.0 : c) * 180 / 3.14159265358979323846;
}

void print_angles(const std::vector<SMSY::Symmetry<Kernel>>& planes)
{
  for(std::size_t i = 0; i < planes.size(); ++i)
    for(std::size_t j = i + 1; j < planes.size(); ++j)
      std::cout << "  planes " << i << " and " << j << ": " << degrees_between(planes[i].plane, planes[j].plane)
                << " degrees\n";
}

int main(int argc, char** argv)
{
  const std::string path = argc > 1 ? argv[1] : std::string(SHAPE_ANALYSIS_DATA_DIR) + "/triceratops.off";
  const std::size_t n = argc > 2 ? std::size_t(std::atoi(argv[2])) : 3;
  Mesh mesh;
  if(!CGAL::IO::read_polygon_mesh(path, mesh) || faces(mesh).empty()) {
    std::cerr << "cannot read " << path << "\n";
    return 1;
  }

  std::vector<SMSY::Symmetry<Kernel>> symmetries, regular;
  try {
    SMSY::detect_reflective_symmetries(mesh, std::back_inserter(symmetries),
                                       SMSY::parameters::maximum_number_of_symmetries(n).random_seed(1));
    // Within 2 degrees (the default maximum_angle) and 1% of the diagonal (maximum_offset).
    regular = SMSY::regularize_symmetries(mesh, symmetries, SMSY::parameters::maximum_angle(2));
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
  std::cout << "as detected:\n";
  print_angles(symmetries);
  std::cout << "regularized (" << regular.size() << " planes):\n";
  print_angles(regular);
  return symmetries.empty() ? 1 : 0;
}
