// Deforms a triangle mesh as rigidly as possible with weights that follow its partition function:
// the parts move nearly rigidly and the surface bends where parts meet.
//   partition_aware_deformation [mesh.off] [output.off]
// The vertex furthest from the centroid is the handle: the vertices near it are pulled sideways,
// the half of the mesh furthest from it is fixed.
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>

#include <CGAL/Randomized_cuts/partition_aware_deformation.h>
#include <CGAL/Randomized_cuts/partition_function.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <iostream>
#include <string>
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel Kernel;
typedef Kernel::Point_3 Point;
typedef Kernel::Vector_3 Vector;
typedef CGAL::Surface_mesh<Point> Mesh;
typedef Mesh::Vertex_index vertex_descriptor;
typedef Mesh::Edge_index edge_descriptor;
namespace RC = CGAL::Randomized_cuts;

int main(int argc, char** argv)
{
#ifdef SHAPE_ANALYSIS_DATA_DIR // built in this project: CGAL's meshes extracted at configure time
  const std::string default_file = std::string(SHAPE_ANALYSIS_DATA_DIR) + "/elephant.off";
#else
  const std::string default_file = CGAL::data_file_path("meshes/elephant.off");
#endif
  const std::string filename = argc > 1 ? argv[1] : default_file;

  Mesh mesh;
  if(!CGAL::IO::read_polygon_mesh(filename, mesh)) {
    std::cerr << "Cannot read " << filename << " as a polygon mesh\n";
    return EXIT_FAILURE;
  }

  try {
    // 1. The partition function: how often random segmentations cut each edge. Min-cut samples
    //    mark the few strong boundaries (the joints) a deformation should bend at.
    Mesh::Property_map<edge_descriptor, double> values =
      mesh.add_property_map<edge_descriptor, double>("e:partition_function", 0.0).first;
    const RC::Partition_function_result pf =
      RC::partition_function(mesh, values,
                             RC::parameters::sampling_method(RC::MIN_CUT).number_of_samples(200).random_seed(1));
    double largest = 0;
    for(edge_descriptor e : edges(mesh))
      largest = (std::max)(largest, values[e]);
    std::cout << num_faces(mesh) << " faces; partition function from " << pf.number_of_samples
              << " segmentations, largest value " << largest << '\n';

    // 2. The handle (the vertex furthest from the centroid), the vertices to move and to fix.
    Vector centroid(0, 0, 0);
    for(vertex_descriptor v : vertices(mesh))
      centroid = centroid + (mesh.point(v) - CGAL::ORIGIN);
    const Point center = CGAL::ORIGIN + centroid / double(num_vertices(mesh));
    vertex_descriptor handle = *vertices(mesh).begin();
    for(vertex_descriptor v : vertices(mesh))
      if(CGAL::squared_distance(mesh.point(v), center) >
         CGAL::squared_distance(mesh.point(handle), center))
        handle = v;
    const Point tip = mesh.point(handle);
    double reach = 0; // the largest distance from the handle
    for(vertex_descriptor v : vertices(mesh))
      reach = (std::max)(reach, std::sqrt(CGAL::squared_distance(mesh.point(v), tip)));
    // Pull the handle region sideways, across the direction from the centroid to the handle.
    const Vector out = tip - center;
    Vector side = CGAL::cross_product(out, Vector(0, 0, 1));
    if(side.squared_length() < 1e-6 * out.squared_length())
      side = CGAL::cross_product(out, Vector(0, 1, 0));
    side = side * (0.15 * reach / std::sqrt(side.squared_length()));

    std::vector<vertex_descriptor> control, fixed;
    std::vector<Point> targets;
    for(vertex_descriptor v : vertices(mesh)) {
      const double d = std::sqrt(CGAL::squared_distance(mesh.point(v), tip));
      if(d < 0.05 * reach) {
        control.push_back(v);
        targets.push_back(mesh.point(v) + side);
      } else if(d > 0.5 * reach) {
        fixed.push_back(v);
      }
    }

    // 3. The deformation: stiff parts, flexible part boundaries.
    const std::vector<Point> before(mesh.points().begin(), mesh.points().end());
    const RC::Partition_aware_deformation_result r =
      RC::partition_aware_deformation(mesh, values, control, targets, fixed,
                                      RC::parameters::number_of_iterations(200));
    double largest_move = 0;
    for(vertex_descriptor v : vertices(mesh))
      largest_move = (std::max)(largest_move,
                                std::sqrt(CGAL::squared_distance(mesh.point(v), before[v])));
    std::cout << control.size() << " vertices moved by " << 0.15 * reach << ", " << fixed.size()
              << " fixed; " << r.number_of_iterations << " iterations, "
              << (r.converged ? "converged" : "not converged") << "; largest vertex move "
              << largest_move << '\n';
  } catch(const RC::Bad_input& e) {
    std::cerr << e.what() << '\n';
    return EXIT_FAILURE;
  }

  if(argc > 2) {
    if(!CGAL::IO::write_polygon_mesh(argv[2], mesh, CGAL::parameters::stream_precision(17))) {
      std::cerr << "Cannot write " << argv[2] << '\n';
      return EXIT_FAILURE;
    }
    std::cout << "Deformed mesh written to " << argv[2] << '\n';
  }
  return EXIT_SUCCESS;
}
