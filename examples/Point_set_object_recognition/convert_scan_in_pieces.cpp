// Copyright (c) 2026 CGAL Global Shape Analysis contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later

// Converts a scan (LAS, binary PLY or KITTI .bin) of any size to LAS 1.4 with all its
// properties, never holding more than a piece of it: Point_set_file_reader reads a range of its
// points at a time, Las_point_set_pieces writes their records, and the header (counts and box of
// every piece) is written last, at the start of the file. The file is the one
// write_las_point_set() writes from the whole scan.
//
//   convert_scan_in_pieces [scan] [output.las] [points per piece]
//   (default: CGAL's b9_training.ply, converted into a temporary file, pieces of 5000 points)

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Point_set_3.h>

#include <CGAL/Point_set_object_recognition/Point_set_file_reader.h>
#include <CGAL/Point_set_object_recognition/write_point_set.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel Kernel;
typedef Kernel::Point_3 Point;
namespace PSOR = CGAL::Point_set_object_recognition;

int main(int argc, char** argv)
{
  const std::string input = argc > 1 ? argv[1] : std::string(SHAPE_ANALYSIS_DATA_DIR) + "/b9_training.ply";
  const std::string output =
    argc > 2 ? argv[2] : (std::filesystem::temp_directory_path() / "convert_scan_in_pieces.las").string();
  const std::size_t piece = argc > 3 ? std::stoul(argv[3]) : 5000;
  try {
    const PSOR::Point_set_file_reader reader(input);
    const std::uint64_t n = reader.number_of_points();
    // The smallest coordinates (the file's offset is chosen from them) in a first pass.
    std::array<double, 3> lowest{{1e300, 1e300, 1e300}};
    std::vector<double> xyz;
    for(std::uint64_t first = 0; first < n; first += piece) {
      reader.read_coordinates(first, std::size_t(std::min<std::uint64_t>(piece, n - first)), xyz);
      for(std::size_t k = 0; k < xyz.size(); ++k)
        lowest[k % 3] = (std::min)(lowest[k % 3], xyz[k]);
    }
    CGAL::Point_set_3<Point> points;
    reader.read(0, 1, points); // the layout: the properties of every piece
    const PSOR::Las_point_set_pieces<Point> pieces(points, lowest);
    std::ofstream out(output, std::ios::binary);
    out.write(std::string(pieces.header({}).size(), '\0').data(), std::streamsize(pieces.header({}).size()));
    PSOR::Las_point_set_pieces<Point>::Summary all;
    std::vector<unsigned char> records;
    for(std::uint64_t first = 0; first < n; first += piece) {
      reader.read(first, std::size_t(std::min<std::uint64_t>(piece, n - first)), points);
      records.clear();
      all.merge(pieces.records(points, records));
      out.write(reinterpret_cast<const char*>(records.data()), std::streamsize(records.size()));
    }
    const std::vector<unsigned char> header = pieces.header(all);
    out.seekp(0);
    out.write(reinterpret_cast<const char*>(header.data()), std::streamsize(header.size()));
    if(!out.flush()) {
      std::cerr << output << ": cannot write\n";
      return 1;
    }
    std::cout << input << " (" << reader.format() << "): " << all.number_of_points << " points written to " << output
              << " in pieces of " << piece << ", " << pieces.record_length() << " bytes each; box [" << all.min[0]
              << ", " << all.max[0] << "] x [" << all.min[1] << ", " << all.max[1] << "]\n";
    return all.number_of_points == n ? 0 : 1;
  } catch(const CGAL::Shape_analysis::Bad_input& e) { // not a file read in pieces, a point too far, ...
    std::cerr << e.what() << "\n";
    return 1;
  }
}
