// Copyright (c) 2026 CGAL Global Shape Analysis contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef SHAPE_ANALYSIS_SUPPORT_SCANNED_OBJECTS_H
#define SHAPE_ANALYSIS_SUPPORT_SCANNED_OBJECTS_H

// Ground truth for the segmentation of objects (tests, benchmarks, example): a scanned procedural
// street (Urban_scene.h) with its ground removed by remove_background(), the true object of every
// remaining point, the class of every object and the objects' true locations (their base on the
// ground), restricted to the objects the scanner saw.

#include <Shape_analysis_support/Urban_scan.h>
#include <CGAL/Point_set_object_recognition/remove_background.h>

#include <array>
#include <map>
#include <vector>

namespace CGAL {
namespace Shape_analysis_support {

struct Scanned_objects
{
  typedef CGAL::Epick::Point_3 Point;
  std::vector<Point> points;                 // the scan's points above the ground
  std::vector<std::size_t> scan_index;       // per point: its index in the scan
  std::vector<int> instance;                 // per point: its object (0: background)
  std::map<int, int> class_of_instance;
  std::vector<std::array<double, 3>> locations; // per seen object: (x, y, ground height)
  std::vector<int> location_instance;           // per seen object: its id
  std::vector<int> location_class;
  std::size_t scan_points = 0;
};

// The objects of the scene with at least `minimum_points` points above the ground are "seen".
inline Scanned_objects scanned_objects(const Urban_scene& scene, const Urban_scan& scan, std::size_t minimum_points = 36)
{
  Scanned_objects s;
  s.scan_points = scan.points.size();
  std::vector<Scanned_objects::Point> all;
  all.reserve(scan.points.size());
  for(const Urban_scan_point& p : scan.points)
    all.emplace_back(p.x, p.y, p.z);
  namespace PSOR = CGAL::Point_set_object_recognition;
  const PSOR::Background_removal_result b = PSOR::remove_background(all);
  std::map<int, std::size_t> seen;
  for(std::size_t i = 0; i < all.size(); ++i)
    if(b.kind[i] != PSOR::Point_kind::GROUND) {
      s.points.push_back(all[i]);
      s.scan_index.push_back(i);
      s.instance.push_back(scan.points[i].instance);
      if(scan.points[i].instance > 0)
        ++seen[scan.points[i].instance];
    }
  for(const Urban_object& o : scene.objects) {
    s.class_of_instance[o.id] = o.object_class;
    const auto it = seen.find(o.id);
    if(it == seen.end() || it->second < minimum_points)
      continue;
    s.locations.push_back({o.x, o.y, o.z});
    s.location_instance.push_back(o.id);
    s.location_class.push_back(o.object_class);
  }
  return s;
}

} // namespace Shape_analysis_support
} // namespace CGAL

#endif // SHAPE_ANALYSIS_SUPPORT_SCANNED_OBJECTS_H
