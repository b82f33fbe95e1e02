// Registers a moved copy of a triangle mesh (rotated by 120 degrees, scaled by 1.7, translated)
// back onto the mesh and prints the recovered similarity transform.
//   register_meshes [mesh.off] [number_of_points]
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/Polygon_mesh_processing/transform.h>
#include <CGAL/Randomized_cuts/register_meshes.h>

#include <cmath>
#include <cstdlib>
#include <iostream>

typedef CGAL::Exact_predicates_inexact_constructions_kernel Kernel;
typedef Kernel::Point_3 Point;
typedef CGAL::Surface_mesh<Point> Mesh;
typedef CGAL::Aff_transformation_3<Kernel> Transformation;
namespace RC = CGAL::Randomized_cuts;

int main(int argc, char** argv)
{
#ifdef SHAPE_ANALYSIS_DATA_DIR // built in this project: CGAL's meshes extracted at configure time
  const std::string default_file = std::string(SHAPE_ANALYSIS_DATA_DIR) + "/elephant.off";
#else
  const std::string default_file = CGAL::data_file_path("meshes/elephant.off");
#endif
  const std::string filename = argc > 1 ? argv[1] : default_file;
  const std::size_t points =
    argc > 2 ? std::strtoul(argv[2], nullptr, 10) : RC::Register_meshes_options().number_of_points;

  Mesh mesh;
  if(!CGAL::IO::read_polygon_mesh(filename, mesh)) {
    std::cerr << "Cannot read " << filename << " as a polygon mesh\n";
    return EXIT_FAILURE;
  }

  // The motion: 120 degrees about the axis (1, 2, -0.7), scale 1.7, then a translation.
  const double angle = 2.0 * 3.14159265358979323846 / 3.0, c = std::cos(angle), s = std::sin(angle);
  const double n = std::sqrt(1.0 + 4.0 + 0.49), x = 1.0 / n, y = 2.0 / n, z = -0.7 / n;
  const double k = 1.7;
  const Transformation motion(
    k * (c + x * x * (1 - c)), k * (x * y * (1 - c) - z * s), k * (x * z * (1 - c) + y * s), 3.0,
    k * (y * x * (1 - c) + z * s), k * (c + y * y * (1 - c)), k * (y * z * (1 - c) - x * s), -5.0,
    k * (z * x * (1 - c) - y * s), k * (z * y * (1 - c) + x * s), k * (c + z * z * (1 - c)), 2.0);
  Mesh moved = mesh;
  CGAL::Polygon_mesh_processing::transform(motion, moved);

  try {
    // Find the transform that puts the moved copy back onto the original.
    const RC::Registration_result<Kernel> r =
      RC::register_meshes(moved, mesh, RC::parameters::number_of_points(points).random_seed(1));

    std::cout << "registered " << num_faces(moved) << " faces onto " << num_faces(mesh)
              << " faces: scale " << r.scale << " (expected " << 1 / k << "), trimmed RMS distance "
              << r.rms_distance << " (before: " << r.initial_rms_distance << "), best of "
              << r.number_of_restarts << " restarts: " << r.best_restart << ", "
              << r.number_of_iterations << " ICP iterations\n";
    std::cout << "transform (3x4):\n";
    for(int i = 0; i < 3; ++i) {
      for(int j = 0; j < 4; ++j)
        std::cout << ' ' << r.transformation.m(i, j);
      std::cout << '\n';
    }
    // The recovered transform after the motion should be the identity.
    const Transformation round_trip = r.transformation * motion;
    double deviation = 0;
    for(int i = 0; i < 3; ++i)
      for(int j = 0; j < 4; ++j)
        deviation = (std::max)(deviation, std::abs(round_trip.m(i, j) - (i == j ? 1.0 : 0.0)));
    std::cout << "largest entry of (recovered o motion - identity): " << deviation << '\n';
    return deviation < 1e-3 ? EXIT_SUCCESS : EXIT_FAILURE;
  } catch(const RC::Bad_input& e) {
    std::cerr << e.what() << '\n';
    return EXIT_FAILURE;
  }
}
