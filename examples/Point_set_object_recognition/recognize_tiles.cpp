// Copyright (c) 2026 CGAL Global Shape Analysis contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later

// Drives the recognition tile by tile as an engine of one's own would, never holding the whole
// scan: the scan is read a piece at a time (Point_set_file_reader), a first pass finds its box,
// a second counts the points of each tile (Tile_plan::add_point), then each tile is recognized
// from the points it holds (recognize_tile), read again from the file, and the locations are
// merged in the order of the tiles. By default the scan is a generated street of 200 m written
// to a binary PLY file first.
//
//   recognize_tiles [scan.las|.ply|.bin] [tile size in metres]

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Point_set_3.h>
#include <CGAL/Point_set_3/IO/PLY.h>

#include <Shape_analysis_support/Urban_scan.h>
#include <CGAL/Point_set_object_recognition/Point_set_file_reader.h>
#include <CGAL/Point_set_object_recognition/recognize_tile.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <string>
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel Kernel;
typedef Kernel::Point_3 Point;
namespace PSOR = CGAL::Point_set_object_recognition;
namespace SAS = CGAL::Shape_analysis_support;

// Calls f(first, xyz) for the pieces of the scan (coordinates as stored).
template <typename F>
void for_each_piece(const PSOR::Point_set_file_reader& reader, const F& f)
{
  const std::size_t piece = 100000;
  std::vector<double> xyz;
  for(std::uint64_t first = 0; first < reader.number_of_points(); first += piece) {
    reader.read_coordinates(first, std::size_t(std::min<std::uint64_t>(piece, reader.number_of_points() - first)), xyz);
    f(first, xyz);
  }
}

int main(int argc, char** argv)
{
  std::string file = argc > 1 ? argv[1] : "";
  if(file.empty()) { // a generated street of 200 m, as a binary PLY file
    SAS::Urban_scene_options so;
    so.street_length = 200;
    so.target_points = 400000;
    CGAL::Point_set_3<Point> street;
    for(const auto& p : SAS::scan_urban_scene(SAS::make_urban_scene(so), so).points)
      street.insert(Point(p.x, p.y, p.z));
    file = (std::filesystem::temp_directory_path() / "recognize_tiles_street.ply").string();
    std::ofstream out(file, std::ios::binary);
    CGAL::IO::set_mode(out, CGAL::IO::BINARY);
    CGAL::IO::write_PLY(out, street);
  }
  const double size = argc > 2 ? std::stod(argv[2]) : 50.0;
  try {
    const PSOR::Point_set_file_reader reader(file);
    // First pass: the box. Second pass: the points of every tile.
    double lo[2] = {1e300, 1e300}, hi[2] = {-1e300, -1e300};
    for_each_piece(reader, [&](std::uint64_t, const std::vector<double>& xyz) {
      for(std::size_t k = 0; k < xyz.size(); k += 3)
        for(int c = 0; c < 2; ++c)
          lo[c] = (std::min)(lo[c], xyz[k + c]), hi[c] = (std::max)(hi[c], xyz[k + c]);
    });
    const auto np = PSOR::parameters::tile_size(size).tile_margin(10.0);
    PSOR::Tile_plan plan = PSOR::plan_tiles(CGAL::Bbox_2(lo[0], lo[1], hi[0], hi[1]), np);
    for_each_piece(reader, [&](std::uint64_t, const std::vector<double>& xyz) {
      for(std::size_t k = 0; k < xyz.size(); k += 3)
        plan.add_point(xyz[k], xyz[k + 1]);
    });
    // Each tile from the points it holds, in the scan's order (an engine would keep them in a
    // file per tile, or hand the tiles to other processes).
    std::vector<std::array<double, 3>> locations;
    for(std::size_t t : plan.tiles_with_points()) {
      std::vector<Point> held;
      for_each_piece(reader, [&](std::uint64_t, const std::vector<double>& xyz) {
        for(std::size_t k = 0; k < xyz.size(); k += 3)
          if(plan.holds(t, xyz[k], xyz[k + 1]))
            held.emplace_back(xyz[k], xyz[k + 1], xyz[k + 2]);
      });
      const PSOR::Tile_recognition r = PSOR::recognize_tile(plan, t, held, np);
      std::cout << "tile " << t << " [" << r.tile.min[0] << ", " << r.tile.max[0] << ") x [" << r.tile.min[1] << ", "
                << r.tile.max[1] << "): " << held.size() << " points held, " << r.locations.size() << " objects kept\n";
      for(const PSOR::Object_location& l : r.locations)
        locations.push_back(l.position);
    }
    std::cout << reader.number_of_points() << " points in " << plan.tiles_with_points().size() << " tiles: "
              << locations.size() << " objects\n";
    return locations.empty() ? 1 : 0;
  } catch(const CGAL::Shape_analysis::Bad_input& e) { // a file that cannot be read in pieces, a tile size <= 0, ...
    std::cerr << e.what() << "\n";
    return 1;
  }
}
