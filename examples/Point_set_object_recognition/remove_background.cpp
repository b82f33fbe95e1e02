// Copyright (c) 2026 CGAL Global Shape Analysis contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later

// Removes the ground, the isolated points and the buildings of a LIDAR scan, writes what is left
// (the candidate small objects) to a PLY file and locates the objects among those points by
// normalized-cut clustering.
//
//   remove_background [scan.ply] [foreground.ply]     (default: CGAL's b9_training.ply)

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Point_set_3.h>
#include <CGAL/Point_set_3/IO/PLY.h>

#include <CGAL/Point_set_object_recognition/locate_objects.h>
#include <CGAL/Point_set_object_recognition/remove_background.h>

#include <fstream>
#include <iostream>
#include <string>

typedef CGAL::Exact_predicates_inexact_constructions_kernel Kernel;
typedef CGAL::Point_set_3<Kernel::Point_3> Point_set;
namespace PSOR = CGAL::Point_set_object_recognition;

int main(int argc, char** argv)
{
  const std::string input = argc > 1 ? argv[1] : std::string(SHAPE_ANALYSIS_DATA_DIR) + "/b9_training.ply";
  const std::string output = argc > 2 ? argv[2] : "foreground.ply";
  Point_set points;
  std::ifstream in(input, std::ios::binary);
  if(!in || !CGAL::IO::read_PLY(in, points) || points.empty()) {
    std::cerr << "cannot read " << input << "\n";
    return 1;
  }
  try {
    // An airborne scan: sparser than a mobile one, hence voxels of 1 m; buildings wider than 6 m.
    const PSOR::Background_removal_result r = PSOR::remove_background(
      points, PSOR::parameters::isolation_radius(1.0).component_spacing(1.0).maximum_component_extent(6.0));
    std::cout << points.size() << " points: " << r.number_of_ground_points << " ground, "
              << r.number_of_isolated_points << " isolated, " << r.number_of_large_component_points
              << " in large components, " << r.foreground.size() << " kept\n";
    Point_set kept;
    for(std::size_t i : r.foreground)
      kept.insert(points.point(*(points.begin() + std::ptrdiff_t(i))));
    // Normalized-cut clustering of a 4-nearest-neighbour graph of 1 m voxels (airborne spacing).
    const PSOR::Localization_result l = PSOR::locate_objects(
      kept, PSOR::parameters::localization_method(PSOR::Localization_method::NORMALIZED_CUT).localization_cell_size(1.0));
    std::cout << l.locations.size() << " potential objects";
    for(std::size_t k = 0; k < l.locations.size() && k < 5; ++k)
      std::cout << (k ? ", " : ": ") << "(" << l.locations[k].position[0] << ", " << l.locations[k].position[1]
                << ") " << l.locations[k].number_of_points << " points";
    std::cout << (l.locations.size() > 5 ? ", ...\n" : "\n");
    std::ofstream out(output, std::ios::binary);
    CGAL::IO::set_mode(out, CGAL::IO::BINARY);
    if(!CGAL::IO::write_PLY(out, kept)) {
      std::cerr << "cannot write " << output << "\n";
      return 1;
    }
  } catch(const CGAL::Shape_analysis::Bad_input& e) {
    std::cerr << "bad input: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
