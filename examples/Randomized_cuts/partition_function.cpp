// Computes the partition function of a triangle mesh, prints its strongest edges and its most
// consistent cuts.
//   partition_function [mesh.off] [number_of_samples]
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/Randomized_cuts/most_consistent_cuts.h>
#include <CGAL/Randomized_cuts/partition_function.h>
#include <CGAL/Shape_analysis/available_processors.h>

#include <algorithm>
#include <cstdlib>
#include <iostream>
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel Kernel;
typedef CGAL::Surface_mesh<Kernel::Point_3> Mesh;
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
  const std::size_t samples =
    argc > 2 ? std::strtoul(argv[2], nullptr, 10) : RC::Partition_function_options().number_of_samples;

  Mesh mesh;
  if(!CGAL::IO::read_polygon_mesh(filename, mesh)) {
    std::cerr << "Cannot read " << filename << " as a polygon mesh\n";
    return EXIT_FAILURE;
  }

  // One value per edge, in [0, 1]: how often the sampled segmentations cut it.
  Mesh::Property_map<edge_descriptor, double> value =
    mesh.add_property_map<edge_descriptor, double>("e:partition_function", 0.0).first;
  try {
    const RC::Partition_function_result r = RC::partition_function(
      mesh, value, RC::parameters::number_of_samples(samples).random_seed(1));
    std::vector<double> sorted;
    for(edge_descriptor e : edges(mesh))
      sorted.push_back(value[e]);
    std::sort(sorted.begin(), sorted.end(), std::greater<double>());
    // number_of_threads (default 0) ran one thread per processor this process may use; the
    // values are the same for any number of threads.
    std::cout << r.number_of_samples << " hierarchical samples of " << num_faces(mesh) << " faces on "
              << CGAL::Shape_analysis::available_processors() << " threads; largest edge value " << sorted.front() << ", 99th percentile "
              << sorted[sorted.size() / 100] << "\n";

    // The five most consistent cuts, from min-cut samples (most_consistent_cuts()'s default).
    const std::vector<RC::Cut<Mesh>> cuts = RC::most_consistent_cuts(
      mesh, RC::parameters::number_of_samples(samples).random_seed(1).number_of_cuts(5));
    for(const RC::Cut<Mesh>& c : cuts)
      std::cout << "cut of " << c.edges.size() << " edges (length " << c.length
                << "): consistency " << c.consistency << ", drawn " << c.number_of_samples
                << " times, separates " << c.smaller_side.size() << " faces\n";
  } catch(const RC::Bad_input& e) {
    std::cerr << e.what() << '\n';
    return EXIT_FAILURE;
  }
  return EXIT_SUCCESS;
}
