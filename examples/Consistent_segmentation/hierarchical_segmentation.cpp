// Segments a triangle mesh into parts and prints the area of each part.
//   hierarchical_segmentation [mesh.off] [number_of_segments]
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Consistent_segmentation/hierarchical_segmentation.h>

#include <cstdlib>
#include <iostream>
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel Kernel;
typedef CGAL::Surface_mesh<Kernel::Point_3> Mesh;
typedef Mesh::Face_index face_descriptor;
namespace CS = CGAL::Consistent_segmentation;

int main(int argc, char** argv)
{
#ifdef SHAPE_ANALYSIS_DATA_DIR // built in this project: CGAL's meshes extracted at configure time
  const std::string default_file = std::string(SHAPE_ANALYSIS_DATA_DIR) + "/elephant.off";
#else
  const std::string default_file = CGAL::data_file_path("meshes/elephant.off");
#endif
  const std::string filename = argc > 1 ? argv[1] : default_file;
  const std::size_t k = argc > 2 ? std::strtoul(argv[2], nullptr, 10) : 6;

  Mesh mesh;
  if(!CGAL::IO::read_polygon_mesh(filename, mesh)) {
    std::cerr << "Cannot read " << filename << " as a polygon mesh\n";
    return EXIT_FAILURE;
  }

  // One segment id per face, written by the segmentation.
  Mesh::Property_map<face_descriptor, std::size_t> segment =
    mesh.add_property_map<face_descriptor, std::size_t>("f:segment", 0).first;

  try {
    const std::size_t n = CS::hierarchical_segmentation(mesh, segment,
                                                        CS::parameters::number_of_segments(k));
    std::vector<double> area(n, 0.0);
    for(face_descriptor f : faces(mesh))
      area[segment[f]] += CGAL::Polygon_mesh_processing::face_area(f, mesh);
    std::cout << n << " segments of " << num_faces(mesh) << " faces; areas:";
    for(double a : area)
      std::cout << ' ' << a;
    std::cout << '\n';
  } catch(const CS::Bad_input& e) {
    std::cerr << e.what() << '\n';
    return EXIT_FAILURE;
  }
  return EXIT_SUCCESS;
}
