// Copyright (c) 2026 CGAL Global Shape Analysis contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later

// The features that classify candidate objects: a scan (by default a short generated street) has
// its ground removed and its objects located; every location then gets the shape features of
// three segmentations and a spin image, printed for the first few.
//
//   extract_object_features [scan.ply|.las|.xyz]

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Point_set_3.h>

#include <Shape_analysis_support/Urban_scan.h>
#include <CGAL/Point_set_object_recognition/extract_object_features.h>
#include <CGAL/Point_set_object_recognition/locate_objects.h>
#include <CGAL/Point_set_object_recognition/read_point_set.h>
#include <CGAL/Point_set_object_recognition/remove_background.h>

#include <iostream>
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel Kernel;
typedef Kernel::Point_3 Point;
namespace PSOR = CGAL::Point_set_object_recognition;
namespace SAS = CGAL::Shape_analysis_support;

int main(int argc, char** argv)
{
  std::vector<Point> scan;
  if(argc > 1) {
    CGAL::Point_set_3<Point> ps;
    PSOR::read_point_set(argv[1], ps);
    for(auto i : ps)
      scan.push_back(ps.point(i));
  } else { // a generated street of 60 m
    SAS::Urban_scene_options o;
    o.street_length = 60;
    o.target_points = 200000;
    const SAS::Urban_scene scene = SAS::make_urban_scene(o);
    for(const auto& p : SAS::scan_urban_scene(scene, o).points)
      scan.emplace_back(p.x, p.y, p.z);
  }
  const PSOR::Background_removal_result b = PSOR::remove_background(scan);
  std::vector<Point> above, foreground;
  for(std::size_t i : PSOR::points_above_ground(b))
    above.push_back(scan[i]);
  for(std::size_t i : b.foreground)
    foreground.push_back(scan[i]);
  const PSOR::Localization_result l = PSOR::locate_objects(foreground);
  const PSOR::Object_features f = PSOR::extract_object_features(above, l.locations);
  std::cout << l.locations.size() << " locations, " << f.names.size() << " features each\n";
  for(std::size_t k = 0; k < f.values.size() && k < 5; ++k) {
    std::cout << "location " << k << ":";
    for(std::size_t j = 0; j < 18; ++j) // the shape features of the three segmentations
      std::cout << " " << f.names[j] << " " << f.values[k][j];
    std::cout << "\n";
  }
  return 0;
}
