// Copyright (c) 2026 CGAL Global Shape Analysis contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later

// Recognition in two stages with the context of a street map (thesis section 4.3.4), with the
// thesis' classifier, an SVM. Two generated streets, each with its OpenStreetMap file placed in
// New York's UTM zone (EPSG:32618): the map is read back into the scan's coordinates; on the
// training street, the examples of object_training_examples() train a first SVM, the class
// patterns of its true objects are learned (Context_grids), and a second SVM learns from the
// features with their context; on the test street, the first SVM labels the candidates, their
// context is computed from those labels, and the second SVM labels them again.
//
//   recognize_with_context

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <Shape_analysis_support/Urban_osm.h>
#include <Shape_analysis_support/Urban_scan.h>
#include <CGAL/Point_set_object_recognition/Object_context.h>
#include <CGAL/Point_set_object_recognition/Svm_object_classifier.h>
#include <CGAL/Point_set_object_recognition/locate_objects.h>
#include <CGAL/Point_set_object_recognition/read_street_map.h>
#include <CGAL/Point_set_object_recognition/remove_background.h>
#include <CGAL/Point_set_object_recognition/train_object_classifier.h>

#include <cstdio>
#include <iostream>
#include <map>
#include <string>
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel Kernel;
typedef Kernel::Point_3 Point;
namespace PSOR = CGAL::Point_set_object_recognition;
namespace SAS = CGAL::Shape_analysis_support;

// A generated street: its points above the ground, candidates, true objects and street map.
struct Street
{
  std::vector<Point> above;
  std::vector<std::array<double, 3>> candidates;
  std::vector<PSOR::Labelled_location> truth;
  PSOR::Street_map map;
};

Street scan_street(std::uint64_t seed)
{
  SAS::Urban_scene_options o;
  o.seed = seed;
  o.street_length = 400;
  o.target_points = 1600000;
  const SAS::Urban_scene scene = SAS::make_urban_scene(o);
  std::vector<Point> all;
  std::map<int, std::size_t> scanned;
  for(const auto& p : SAS::scan_urban_scene(scene, o).points) {
    all.emplace_back(p.x, p.y, p.z);
    scanned[p.instance] += 1;
  }
  Street s;
  // The street's map, as a user would have it: an OpenStreetMap file in longitude and latitude.
  const std::array<double, 2> origin{{583000, 4507000}}; // UTM coordinates of the scan's (0, 0)
  const std::string osm = "recognize_with_context_" + std::to_string(seed) + ".osm";
  SAS::write_street_osm(osm, scene, 18, true, origin);
  s.map = PSOR::read_street_map(osm, "EPSG:32618", {{origin[0], origin[1], 0}});
  std::remove(osm.c_str());
  const PSOR::Background_removal_result b = PSOR::remove_background(all);
  std::vector<Point> foreground;
  for(std::size_t i : PSOR::points_above_ground(b))
    s.above.push_back(all[i]);
  for(std::size_t i : b.foreground)
    foreground.push_back(all[i]);
  for(const PSOR::Object_location& l : PSOR::locate_objects(foreground).locations)
    s.candidates.push_back(l.position);
  for(const SAS::Urban_object& ob : scene.objects)
    if(scanned[ob.id] >= 20) {
      PSOR::Labelled_location l;
      l.position = {{ob.x, ob.y, ob.z}};
      l.label = std::size_t(ob.object_class - SAS::first_object_class);
      s.truth.push_back(l);
    }
  return s;
}

// Appends the columns of `more` to those of `rows`.
void append(std::vector<std::vector<double>>& rows, const std::vector<std::vector<double>>& more)
{
  for(std::size_t k = 0; k < rows.size(); ++k)
    rows[k].insert(rows[k].end(), more[k].begin(), more[k].end());
}

int main()
{
  const std::size_t classes = SAS::number_of_object_classes;
  const Street train = scan_street(1), test = scan_street(2);
  std::cout << "street map: " << train.map.streets().size() << " streets; a point 3 m off the street's centre line is "
            << train.map.distance(100, 3) << " m from it\n";

  // Training: the first stage on the features, the second on the features and their context.
  const PSOR::Object_training_examples e = PSOR::object_training_examples(train.above, train.truth, classes,
                                                                          train.candidates);
  PSOR::Svm_object_classifier first, second; // C = 2.5 and degree 5 as in the thesis, feature weights
  first.train(e.features.values, e.labels, classes + 1);
  PSOR::Context_grids grids;
  grids.learn(train.truth, classes, train.map);
  std::vector<std::vector<double>> with = e.features.values;
  append(with, PSOR::context_features(e.locations, train.map, grids, train.truth).values);
  second.train(with, e.labels, classes + 1);

  // Recognition: the first stage's labels give the context of the second.
  const std::vector<PSOR::Labelled_location> first_labels = PSOR::classify_objects(first, test.above, test.candidates);
  std::vector<std::vector<double>> rows = PSOR::extract_object_features(test.above, test.candidates).values;
  append(rows, PSOR::context_features(test.candidates, test.map, grids, first_labels).values);
  std::vector<PSOR::Labelled_location> labels = first_labels;
  for(std::size_t k = 0; k < labels.size(); ++k)
    labels[k].label = second.predict(rows[k], labels[k].confidence);

  const std::vector<PSOR::Labelled_location>* stages[] = {&first_labels, &labels};
  for(const std::vector<PSOR::Labelled_location>* r : stages) {
    const std::vector<PSOR::Class_recognition_score> s = PSOR::evaluate_recognition(*r, test.truth, classes);
    std::cout << (r == &labels ? "with context:    " : "without context: ") << "precision " << s[classes].precision
              << ", recall " << s[classes].recall << " (" << s[classes].objects << " objects)\n";
  }
  return 0;
}
