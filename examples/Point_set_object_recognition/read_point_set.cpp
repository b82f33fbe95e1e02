// Copyright (c) 2026 CGAL Global Shape Analysis contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later

// Reads a scan (PLY, XYZ, LAS or KITTI .bin) and prints its size, the local origin its
// georeferenced coordinates were shifted by, its properties and its extent; with an output name,
// writes it as LAS 1.4 with all its properties, in the coordinates of the file read.
//
//   read_point_set [scan] [output.las]     (default: CGAL's b9_training.ply, no output)

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Point_set_3.h>
#include <CGAL/bounding_box.h>

#include <CGAL/Point_set_object_recognition/read_point_set.h>
#include <CGAL/Point_set_object_recognition/write_point_set.h>

#include <iomanip>
#include <iostream>
#include <string>

typedef CGAL::Exact_predicates_inexact_constructions_kernel Kernel;
namespace PSOR = CGAL::Point_set_object_recognition;

int main(int argc, char** argv)
{
  const std::string input = argc > 1 ? argv[1] : std::string(SHAPE_ANALYSIS_DATA_DIR) + "/b9_training.ply";
  CGAL::Point_set_3<Kernel::Point_3> points;
  try {
    const PSOR::Point_set_read_result r = PSOR::read_point_set(input, points);
    std::cout << std::setprecision(12) << input << ": " << r.number_of_points << " points (" << r.format
              << "), local origin " << r.offset[0] << ' ' << r.offset[1] << ' ' << r.offset[2] << "\nproperties:";
    for(const std::string& name : r.property_names)
      std::cout << ' ' << name;
    const auto box = CGAL::bounding_box(points.points().begin(), points.points().end());
    std::cout << "\nextent in the local frame: " << box << "\n";
    if(argc > 2) { // the local origin added back, and a LAS scan's scale, offset and CRS kept
      PSOR::write_las_point_set(argv[2], points,
                                PSOR::parameters::local_origin(r.offset).las_georeference(r.las_georeference));
      std::cout << "written to " << argv[2] << "\n";
    }
  } catch(const CGAL::Shape_analysis::Bad_input& e) {
    std::cerr << "cannot use " << input << ": " << e.what() << "\n"; // (or cannot write the output)
    return 1;
  }
  return 0;
}
