// Segments a nearly mirror-symmetric mesh so that its segmentation is symmetric too, and prints
// how often a face and the face nearest to its mirror image share a segment.
//   symmetric_segmentation [mesh.off a b c d [number_of_segments]]
// The plane is a x + b y + c z + d = 0; without arguments: CGAL's cow.off and its plane z = 0.
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/Polygon_mesh_processing/compute_normal.h>
#include <CGAL/Search_traits_3.h>
#include <CGAL/Search_traits_adapter.h>
#include <CGAL/Orthogonal_k_neighbor_search.h>
#include <CGAL/Consistent_segmentation/consistent_segmentation.h>
#include <CGAL/Consistent_segmentation/hierarchical_segmentation.h>

#include <cstdlib>
#include <iostream>
#include <string>
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel Kernel;
typedef Kernel::Point_3 Point;
typedef CGAL::Surface_mesh<Point> Mesh;
typedef Mesh::Face_index face_descriptor;
typedef Mesh::Property_map<face_descriptor, std::size_t> Segment_map;
namespace CS = CGAL::Consistent_segmentation;

// The fraction of faces whose segment is the segment of the face closest to their mirror image.
double mirror_agreement(const Mesh& mesh, const Kernel::Plane_3& plane, const Segment_map& segment)
{
  typedef CGAL::Search_traits_3<Kernel> Traits;
  typedef CGAL::Orthogonal_k_neighbor_search<Traits> Search;
  std::vector<Point> centers;
  std::map<Point, face_descriptor> face_of;
  for(face_descriptor f : faces(mesh)) {
    const auto h = halfedge(f, mesh);
    const Point c = CGAL::centroid(mesh.point(source(h, mesh)), mesh.point(target(h, mesh)),
                                   mesh.point(target(next(h, mesh), mesh)));
    centers.push_back(c);
    face_of.emplace(c, f);
  }
  Search::Tree tree(centers.begin(), centers.end());
  const Kernel::Aff_transformation_3 mirror = [&] {
    const Kernel::Vector_3 n = plane.orthogonal_vector();
    const double nn = n.squared_length(), a = n.x(), b = n.y(), c = n.z(), d = plane.d();
    return Kernel::Aff_transformation_3(1 - 2 * a * a / nn, -2 * a * b / nn, -2 * a * c / nn, -2 * a * d / nn,
                                        -2 * a * b / nn, 1 - 2 * b * b / nn, -2 * b * c / nn, -2 * b * d / nn,
                                        -2 * a * c / nn, -2 * b * c / nn, 1 - 2 * c * c / nn, -2 * c * d / nn);
  }();
  std::size_t same = 0, i = 0;
  for(face_descriptor f : faces(mesh)) {
    Search search(tree, mirror.transform(centers[i++]), 1);
    if(segment[face_of[search.begin()->first]] == segment[f])
      ++same;
  }
  return double(same) / double(num_faces(mesh));
}

int main(int argc, char** argv)
{
#ifdef SHAPE_ANALYSIS_DATA_DIR // built in this project: CGAL's meshes extracted at configure time
  const std::string default_file = std::string(SHAPE_ANALYSIS_DATA_DIR) + "/cow.off";
#else
  const std::string default_file = CGAL::data_file_path("meshes/cow.off");
#endif
  const bool given = argc >= 6;
  const std::string filename = given ? argv[1] : default_file;
  const Kernel::Plane_3 plane = given ? Kernel::Plane_3(std::atof(argv[2]), std::atof(argv[3]),
                                                        std::atof(argv[4]), std::atof(argv[5]))
                                      : Kernel::Plane_3(0, 0, 1, 0);
  const std::size_t k = argc > 6 ? std::strtoul(argv[6], nullptr, 10) : 7;

  Mesh mesh;
  if(!CGAL::IO::read_polygon_mesh(filename, mesh)) {
    std::cerr << "Cannot read " << filename << " as a polygon mesh\n";
    return EXIT_FAILURE;
  }
  Segment_map symmetric = mesh.add_property_map<face_descriptor, std::size_t>("f:symmetric", 0).first;
  Segment_map alone = mesh.add_property_map<face_descriptor, std::size_t>("f:alone", 0).first;
  try {
    const CS::Consistent_segmentation_result r =
      CS::symmetric_segmentation(mesh, plane, symmetric, CS::parameters::number_of_segments(k));
    CS::hierarchical_segmentation(mesh, alone, CS::parameters::number_of_segments(k));
    std::cout << r.number_of_segments << " segments, " << r.number_of_correspondences
              << " mirror correspondences\n"
              << "faces in the segment of their mirror face: " << mirror_agreement(mesh, plane, symmetric)
              << " (symmetric_segmentation), " << mirror_agreement(mesh, plane, alone)
              << " (hierarchical_segmentation)\n";
  } catch(const CS::Bad_input& e) {
    std::cerr << e.what() << '\n';
    return EXIT_FAILURE;
  }
  return EXIT_SUCCESS;
}
