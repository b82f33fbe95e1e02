// Uses the installed library: segments two tetrahedra joined into one mesh of two components.
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/generators.h>
#include <CGAL/Consistent_segmentation/hierarchical_segmentation.h>

#include <iostream>

typedef CGAL::Simple_cartesian<double> Kernel;
typedef CGAL::Surface_mesh<Kernel::Point_3> Mesh;
namespace CS = CGAL::Consistent_segmentation;

int main()
{
  Mesh mesh;
  CGAL::make_tetrahedron(Kernel::Point_3(0, 0, 0), Kernel::Point_3(1, 0, 0),
                         Kernel::Point_3(0, 1, 0), Kernel::Point_3(0, 0, 1), mesh);
  CGAL::make_tetrahedron(Kernel::Point_3(5, 0, 0), Kernel::Point_3(6, 0, 0),
                         Kernel::Point_3(5, 1, 0), Kernel::Point_3(5, 0, 1), mesh);
  auto segment = mesh.add_property_map<Mesh::Face_index, std::size_t>("f:segment", 0).first;
  const std::size_t k =
    CS::hierarchical_segmentation(mesh, segment, CS::parameters::number_of_segments(2));
  // Each tetrahedron must be one segment.
  for(auto f : faces(mesh)) {
    const bool first = mesh.point(mesh.target(mesh.halfedge(f))).x() < 2;
    const auto expected = segment[*faces(mesh).begin()];
    if((segment[f] == expected) != first) {
      std::cerr << "wrong segmentation\n";
      return 1;
    }
  }
  std::cout << "consumer: " << k << " segments\n";
  return k == 2 ? 0 : 1;
}
