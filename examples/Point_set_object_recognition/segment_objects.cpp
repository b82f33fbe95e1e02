// Copyright (c) 2026 CGAL Global Shape Analysis contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later

// Segments objects from their locations: a scan (by default a short generated street) has its
// ground removed, its objects are located, each location is segmented by min-cut with the
// automatic background radius, and one object is then corrected interactively.
//
//   segment_objects [scan.ply|.las|.xyz]

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Point_set_3.h>

#include <Shape_analysis_support/Urban_scan.h>
#include <CGAL/Point_set_object_recognition/locate_objects.h>
#include <CGAL/Point_set_object_recognition/read_point_set.h>
#include <CGAL/Point_set_object_recognition/remove_background.h>
#include <CGAL/Point_set_object_recognition/segment_objects.h>

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
  // 1. The ground goes (objects touching walls stay with the walls: the cut separates them).
  const PSOR::Background_removal_result b = PSOR::remove_background(scan);
  std::vector<Point> above, foreground;
  for(std::size_t i : PSOR::points_above_ground(b))
    above.push_back(scan[i]);
  for(std::size_t i : b.foreground)
    foreground.push_back(scan[i]);
  // 2. Locations among the foreground.
  const PSOR::Localization_result l = PSOR::locate_objects(foreground);
  // 3. Every location segmented among the points above the ground (in parallel).
  const PSOR::Segmentation_result r = PSOR::segment_objects(above, l.locations);
  std::cout << scan.size() << " points, " << above.size() << " above the ground, " << l.locations.size()
            << " locations segmented in " << r.seconds << " s\n";
  for(std::size_t k = 0; k < r.objects.size() && k < 10; ++k)
    std::cout << "  object " << k << ": " << r.objects[k].points.size() << " points, radius " << r.objects[k].radius
              << " m, cut " << r.objects[k].cut_cost << ", " << 1000 * r.objects[k].seconds << " ms\n";
  if(l.locations.empty())
    return 0;
  // 4. The first object, corrected: its farthest point put in the background, the seed's
  //    neighbour kept in the foreground.
  PSOR::Interactive_segmenter segmenter(above, l.locations.front().position);
  const PSOR::Object_segmentation& s = segmenter.segmentation();
  std::cout << "interactive: " << s.points.size() << " points";
  if(!s.points.empty()) {
    const std::size_t last = s.points.back();
    const PSOR::Object_segmentation& t = segmenter.add_background(last);
    std::cout << ", " << t.points.size() << " after a background constraint (" << 1000 * t.seconds << " ms)";
  }
  std::cout << "\n";
  return 0;
}
