// Copyright (c) 2026 CGAL Global Shape Analysis contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later

// Trains a random forest on the objects of one generated street and recognizes those of another:
// per street the ground is removed and the objects located; the training street's true objects
// (and its located places away from them, as background) teach the classifier; the test
// street's locations are classified and scored against its true objects (within 1 m).
//
//   train_object_classifier

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <Shape_analysis_support/Urban_scan.h>
#include <CGAL/Point_set_object_recognition/Object_classifiers.h>
#include <CGAL/Point_set_object_recognition/locate_objects.h>
#include <CGAL/Point_set_object_recognition/remove_background.h>
#include <CGAL/Point_set_object_recognition/train_object_classifier.h>

#include <iostream>
#include <map>
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel Kernel;
typedef Kernel::Point_3 Point;
namespace PSOR = CGAL::Point_set_object_recognition;
namespace SAS = CGAL::Shape_analysis_support;

// A generated street: its points above the ground, its located objects and its true objects.
struct Street
{
  std::vector<Point> above;
  std::vector<PSOR::Object_location> located;
  std::vector<PSOR::Labelled_location> truth;
};

Street scan_street(std::uint64_t seed)
{
  SAS::Urban_scene_options o;
  o.seed = seed;
  o.street_length = 150;
  o.target_points = 600000;
  const SAS::Urban_scene scene = SAS::make_urban_scene(o);
  std::vector<Point> all;
  std::map<int, std::size_t> scanned;
  for(const auto& p : SAS::scan_urban_scene(scene, o).points) {
    all.emplace_back(p.x, p.y, p.z);
    scanned[p.instance] += 1;
  }
  const PSOR::Background_removal_result b = PSOR::remove_background(all);
  Street s;
  std::vector<Point> foreground;
  for(std::size_t i : PSOR::points_above_ground(b))
    s.above.push_back(all[i]);
  for(std::size_t i : b.foreground)
    foreground.push_back(all[i]);
  s.located = PSOR::locate_objects(foreground).locations;
  for(const SAS::Urban_object& ob : scene.objects)
    if(scanned[ob.id] >= 20) { // objects the scanner saw
      PSOR::Labelled_location l;
      l.position = {{ob.x, ob.y, ob.z}};
      l.label = std::size_t(ob.object_class - SAS::first_object_class);
      s.truth.push_back(l);
    }
  return s;
}

int main()
{
  const std::size_t classes = SAS::number_of_object_classes;
  const Street train = scan_street(1), test = scan_street(2);
  PSOR::Random_forest_object_classifier forest; // 50 trees, seed 0
  PSOR::train_object_classifier(forest, train.above, train.truth, classes, train.located);
  const std::vector<PSOR::Labelled_location> found = PSOR::classify_objects(forest, test.above, test.located);
  const std::vector<PSOR::Class_recognition_score> s = PSOR::evaluate_recognition(found, test.truth, classes);
  std::cout << train.truth.size() << " objects to learn from, " << test.located.size() << " locations classified\n";
  for(std::size_t c = 0; c < classes; ++c)
    if(s[c].objects > 0)
      std::cout << "  " << SAS::object_class_name(int(c) + SAS::first_object_class) << ": precision "
                << s[c].precision << ", recall " << s[c].recall << " (" << s[c].objects << " objects)\n";
  std::cout << "all classes: precision " << s[classes].precision << ", recall " << s[classes].recall << "\n";
  return 0;
}
