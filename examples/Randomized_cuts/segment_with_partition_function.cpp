// Segments a triangle mesh along its most consistent cuts and prints the size of each part.
//   segment_with_partition_function [mesh.off] [number_of_segments] [number_of_samples]
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/Randomized_cuts/segment_with_partition_function.h>

#include <cstdlib>
#include <iostream>
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel Kernel;
typedef CGAL::Surface_mesh<Kernel::Point_3> Mesh;
typedef Mesh::Face_index face_descriptor;
namespace RC = CGAL::Randomized_cuts;

int main(int argc, char** argv)
{
#ifdef SHAPE_ANALYSIS_DATA_DIR // built in this project: CGAL's meshes extracted at configure time
  const std::string default_file = std::string(SHAPE_ANALYSIS_DATA_DIR) + "/elephant.off";
#else
  const std::string default_file = CGAL::data_file_path("meshes/elephant.off");
#endif
  const std::string filename = argc > 1 ? argv[1] : default_file;
  const std::size_t k = argc > 2 ? std::strtoul(argv[2], nullptr, 10) : 6;
  const std::size_t samples =
    argc > 3 ? std::strtoul(argv[3], nullptr, 10) : RC::Segment_with_partition_function_options().number_of_samples;

  Mesh mesh;
  if(!CGAL::IO::read_polygon_mesh(filename, mesh)) {
    std::cerr << "Cannot read " << filename << " as a polygon mesh\n";
    return EXIT_FAILURE;
  }
  Mesh::Property_map<face_descriptor, std::size_t> segment =
    mesh.add_property_map<face_descriptor, std::size_t>("f:segment", 0).first;
  try {
    // The partition function of the whole mesh is also kept, as an edge property.
    auto value = mesh.add_property_map<Mesh::Edge_index, double>("e:partition_function", 0.0).first;
    const std::size_t n = RC::segment_with_partition_function(
      mesh, segment,
      RC::parameters::number_of_segments(k).number_of_samples(samples).edge_value_map(value));
    std::vector<std::size_t> faces_of(n, 0);
    for(face_descriptor f : faces(mesh))
      ++faces_of[segment[f]];
    std::cout << n << " segments of " << num_faces(mesh) << " faces; faces per segment:";
    for(std::size_t c : faces_of)
      std::cout << ' ' << c;
    std::cout << '\n';
  } catch(const RC::Bad_input& e) {
    std::cerr << e.what() << '\n';
    return EXIT_FAILURE;
  }
  return EXIT_SUCCESS;
}
