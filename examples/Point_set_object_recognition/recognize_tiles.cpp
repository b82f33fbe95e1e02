// Copyright (c) 2026 CGAL Global Shape Analysis contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later

// Drives the recognition tile by tile as an engine of one's own would (out of core, on a
// cluster): the plan of the tiles from a first pass over the points, then each tile recognized
// on its own with the points it holds, and the locations merged in the order of the tiles. Here
// the scan (a generated street of 200 m) is in memory; an engine would read each tile's points
// from its files instead.
//
//   recognize_tiles [tile size in metres]

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <Shape_analysis_support/Urban_scan.h>
#include <CGAL/Point_set_object_recognition/recognize_tile.h>

#include <iostream>
#include <string>
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel Kernel;
typedef Kernel::Point_3 Point;
namespace PSOR = CGAL::Point_set_object_recognition;
namespace SAS = CGAL::Shape_analysis_support;

int main(int argc, char** argv)
{
  SAS::Urban_scene_options so;
  so.street_length = 200;
  so.target_points = 400000;
  const SAS::Urban_scene scene = SAS::make_urban_scene(so);
  std::vector<Point> scan;
  for(const auto& p : SAS::scan_urban_scene(scene, so).points)
    scan.emplace_back(p.x, p.y, p.z);

  const double size = argc > 1 ? std::stod(argv[1]) : 50.0;
  try {
    // The first pass: the box and the points of every tile (a streaming engine would call
    // plan_tiles(box) then Tile_plan::add_point() for each point it reads).
    const auto np = PSOR::parameters::tile_size(size).tile_margin(10.0);
    const PSOR::Tile_plan plan = PSOR::plan_tiles(scan, np);
    std::vector<std::array<double, 3>> locations;
    for(std::size_t t : plan.tiles_with_points()) {
      // The points the tile holds: its own and those of its margin, in the scan's order.
      std::vector<Point> held;
      for(const Point& p : scan)
        if(plan.holds(t, p.x(), p.y()))
          held.push_back(p);
      const PSOR::Tile_recognition r = PSOR::recognize_tile(plan, t, held, np);
      std::cout << "tile " << t << " [" << r.tile.min[0] << ", " << r.tile.max[0] << ") x [" << r.tile.min[1] << ", "
                << r.tile.max[1] << "): " << held.size() << " points held, " << r.locations.size() << " objects kept\n";
      for(const PSOR::Object_location& l : r.locations)
        locations.push_back(l.position);
    }
    std::cout << scan.size() << " points in " << plan.tiles_with_points().size() << " tiles: " << locations.size()
              << " objects\n";
    return locations.empty() ? 1 : 0;
  } catch(const CGAL::Shape_analysis::Bad_input& e) { // a tile size <= 0, ...
    std::cerr << e.what() << "\n";
    return 1;
  }
}
