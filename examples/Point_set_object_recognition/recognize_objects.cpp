// Copyright (c) 2026 CGAL Global Shape Analysis contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later

// Finds and segments the objects of a scan tile by tile: by default a generated street of 400 m
// (10^6 points) in tiles of 100 m, each processed with the points within 10 m of it. Prints the
// tiles, the objects found, and the largest number of points one tile needed.
//
//   recognize_objects [scan.ply|.las|.xyz|.bin] [tile size in metres]

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Point_set_3.h>

#include <Shape_analysis_support/Urban_scan.h>
#include <CGAL/Point_set_object_recognition/read_point_set.h>
#include <CGAL/Point_set_object_recognition/recognize_objects.h>

#include <iostream>
#include <string>
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel Kernel;
typedef Kernel::Point_3 Point;
namespace PSOR = CGAL::Point_set_object_recognition;
namespace SAS = CGAL::Shape_analysis_support;

int main(int argc, char** argv)
{
  std::vector<Point> scan;
  if(argc > 1 && std::string(argv[1]) != "-") {
    CGAL::Point_set_3<Point> ps;
    try {
      PSOR::read_point_set(argv[1], ps);
    } catch(const CGAL::Shape_analysis::Bad_input& e) {
      std::cerr << argv[1] << ": " << e.what() << "\n";
      return 1;
    }
    for(auto i : ps)
      scan.push_back(ps.point(i));
  } else { // a generated street of 400 m
    SAS::Urban_scene_options o;
    o.street_length = 400;
    o.target_points = 1000000;
    const SAS::Urban_scene scene = SAS::make_urban_scene(o);
    for(const auto& p : SAS::scan_urban_scene(scene, o).points)
      scan.emplace_back(p.x, p.y, p.z);
  }
  const double tile = argc > 2 ? std::stod(argv[2]) : PSOR::Recognize_objects_options().tile_size;
  // Ground, background, normalized-cut localization and min-cut segmentation, tile by tile (the
  // tiles in parallel; the result does not depend on the number of threads).
  PSOR::Object_recognition_result r;
  try {
    r = PSOR::recognize_objects(scan, PSOR::parameters::tile_size(tile));
  } catch(const CGAL::Shape_analysis::Bad_input& e) { // an empty cloud, a tile size <= 0, ...
    std::cerr << e.what() << "\n";
    return 1;
  }
  for(const PSOR::Scene_tile& t : r.tiles)
    std::cout << "tile [" << t.min[0] << ", " << t.max[0] << ") x [" << t.min[1] << ", " << t.max[1] << "): "
              << t.number_of_points << " points, " << t.number_of_locations << " objects, " << t.seconds << " s\n";
  std::size_t claimed = 0;
  for(std::size_t o : r.object_of_point)
    claimed += o != PSOR::Object_recognition_result::no_object;
  std::cout << scan.size() << " points: " << r.locations.size() << " objects (" << claimed << " points) in "
            << r.tiles.size() << " tiles of at most " << r.largest_tile << " points, " << r.seconds << " s\n";
  for(std::size_t k = 0; k < r.objects.size() && k < 5; ++k)
    std::cout << "  object " << k << " at (" << r.locations[k].position[0] << ", " << r.locations[k].position[1]
              << "): " << r.objects[k].points.size() << " points, radius " << r.objects[k].radius << " m\n";
  return r.locations.empty() ? 1 : 0;
}
