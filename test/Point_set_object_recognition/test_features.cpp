// Copyright (c) 2026 CGAL Global Shape Analysis contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later

// The features of candidate objects (extract_object_features.h) on shapes whose features are
// known: a pole, a bar, a box, apart from each other; invariance under a turn of the scene; bad
// input. Training on such shapes and classifying others (train_object_classifier.h), and the
// evaluation of recognition.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Point_set_object_recognition/Object_classifiers.h>
#include <CGAL/Point_set_object_recognition/extract_object_features.h>
#include <CGAL/Point_set_object_recognition/recognize_objects.h>
#include <CGAL/Point_set_object_recognition/train_object_classifier.h>

#include <Shape_analysis_support/Urban_scan.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <random>
#include <sstream>
#include <string>
#include <vector>

namespace {

namespace PSOR = CGAL::Point_set_object_recognition;
typedef std::array<double, 3> P3;
typedef CGAL::Exact_predicates_inexact_constructions_kernel::Point_3 Point;

// A pole at (0, 0): 600 points on a vertical segment from 0 to 3 m (within 1 cm of its axis);
// a horizontal bar at (12, 0), 4 m long at 30 degrees, 1 m high; a box at (0, 12), 3 x 1.6 x 1.5
// m, its top and sides sampled every 5 cm. The points jitter horizontally by a millimetre (fixed
// seed).
struct Scene
{
  std::vector<Point> points;
  std::vector<P3> locations{{{0, 0, 0}}, {{12, 0, 0}}, {{0, 12, 0}}};
  std::vector<std::size_t> begin; // per object, its first point

  Scene()
  {
    std::mt19937 rng(5);
    std::uniform_real_distribution<double> jitter(-0.001, 0.001);
    const auto add = [&](double x, double y, double z) { points.emplace_back(x + jitter(rng), y + jitter(rng), z); };
    begin.push_back(points.size());
    for(int k = 0; k < 600; ++k)
      add(0.01 * std::cos(k), 0.01 * std::sin(k), 3.0 * (k + 0.5) / 600);
    begin.push_back(points.size());
    const double c = std::cos(M_PI / 6), s = std::sin(M_PI / 6);
    for(int k = 0; k < 400; ++k) {
      const double t = -2 + 4.0 * (k + 0.5) / 400;
      add(12 + t * c, t * s, 1.0);
    }
    begin.push_back(points.size());
    const double l = 1.5, w = 0.8, h = 1.5, step = 0.05;
    // (its heights start 13 mm up: on the grid of 5 cm they would sit on the spin image's bin
    // edges, where a move of the scene rounds them to either side)
    const auto add_box = [&](double x, double y, double z) { add(x, y, z + 0.013); };
    for(double x = -l; x <= l + 1e-9; x += step)
      for(double y = -w; y <= w + 1e-9; y += step)
        add_box(x, 12 + y, h);
    for(double z = step; z < h - 1e-9; z += step) {
      for(double x = -l; x <= l + 1e-9; x += step)
        add_box(x, 12 - w, z), add_box(x, 12 + w, z);
      for(double y = -w + step; y < w - 1e-9; y += step)
        add_box(-l, 12 + y, z), add_box(l, 12 + y, z);
    }
    begin.push_back(points.size());
  }
};

double feature(const PSOR::Object_features& f, std::size_t row, const std::string& name)
{
  for(std::size_t k = 0; k < f.names.size(); ++k)
    if(f.names[k] == name)
      return f.values[row][k];
  ADD_FAILURE() << "no feature " << name;
  return std::numeric_limits<double>::quiet_NaN();
}

TEST(ObjectFeatures, KnownShapes)
{
  const Scene scene;
  const PSOR::Object_features f = PSOR::extract_object_features(scene.points, scene.locations);
  ASSERT_EQ(f.names.size(), 3u * 6u + 50u + 5u);
  ASSERT_EQ(f.values.size(), 3u);
  for(const auto& row : f.values)
    ASSERT_EQ(row.size(), f.names.size());
  for(const std::string seg : {"automatic.", "min_cut_4m.", "within_2m."}) {
    // Every object is alone: each segmentation holds all its points.
    for(std::size_t o = 0; o < 3; ++o)
      EXPECT_EQ(feature(f, o, seg + "points"), double(scene.begin[o + 1] - scene.begin[o])) << seg << o;
    // The pole: heights uniform on [0, 3], nothing horizontal.
    EXPECT_NEAR(feature(f, 0, seg + "mean_height"), 1.5, 1e-3);
    EXPECT_NEAR(feature(f, 0, seg + "height_deviation"), 3 / std::sqrt(12.0), 1e-3);
    EXPECT_LT(feature(f, 0, seg + "major_deviation"), 0.01);
    EXPECT_LT(feature(f, 0, seg + "volume"), 4 * 0.04 * 3);
    // The bar: 4 m long whatever its direction, at 1 m.
    EXPECT_NEAR(feature(f, 1, seg + "major_deviation"), 4 / std::sqrt(12.0), 2e-3);
    EXPECT_LT(feature(f, 1, seg + "minor_deviation"), 2e-3);
    EXPECT_NEAR(feature(f, 1, seg + "mean_height"), 1.0, 1e-9);
    EXPECT_NEAR(feature(f, 1, seg + "height_deviation"), 0.0, 1e-6);
    // The box: 7.2 cubic metres, the columns on its rim overlapping it by up to a cell.
    EXPECT_GT(feature(f, 2, seg + "volume"), 0.95 * 7.2);
    EXPECT_LT(feature(f, 2, seg + "volume"), 1.35 * 7.2);
    EXPECT_GT(feature(f, 2, seg + "major_deviation"), feature(f, 2, seg + "minor_deviation"));
  }
  // The pole's spin image: every point in the first ring, spread evenly over the heights up to 3 m
  // (bins of 0.4 m: the eighth holds half a bin).
  double total = 0;
  for(int i = 0; i < 5; ++i)
    for(int j = 0; j < 10; ++j) {
      const double v = feature(f, 0, "spin." + std::to_string(i) + "." + std::to_string(j));
      total += v;
      if(i > 0 || j > 7)
        EXPECT_EQ(v, 0.0) << i << " " << j;
      else
        EXPECT_NEAR(v, j < 7 ? 0.4 / 3 : 0.2 / 3, 0.01) << j;
    }
  EXPECT_NEAR(total, 1.0, 1e-12);
  // Column features. The pole: 3 m high in one cell of 0.2 m, the 90th percentile of heights
  // uniform on [0, 3] at 2.7 m.
  for(const char* top : {"column.top_0.5m", "column.top_1m", "column.top_2m"})
    EXPECT_NEAR(feature(f, 0, top), 3.0, 0.01) << top;
  EXPECT_NEAR(feature(f, 0, "column.area_1m"), 0.04, 1e-12);
  EXPECT_NEAR(feature(f, 0, "column.height_90_1m"), 2.7, 0.01);
  // The bar at 1 m: 2 m of it within 1 m of its middle, across about ten cells.
  EXPECT_NEAR(feature(f, 1, "column.top_1m"), 1.0, 1e-9);
  EXPECT_NEAR(feature(f, 1, "column.height_90_1m"), 1.0, 1e-9);
  EXPECT_GT(feature(f, 1, "column.area_1m"), 0.3);
  EXPECT_LT(feature(f, 1, "column.area_1m"), 0.8);
  // The box: its top (1.513 m) over the disc of 1 m clipped to its width of 1.6 m (2.87 m2; the
  // cells of 0.2 m on the rim of that, about 5 m long, count whole).
  EXPECT_NEAR(feature(f, 2, "column.top_0.5m"), 1.513, 1e-9);
  EXPECT_NEAR(feature(f, 2, "column.height_90_1m"), 1.513, 1e-9);
  EXPECT_GT(feature(f, 2, "column.area_1m"), 2.87);
  EXPECT_LT(feature(f, 2, "column.area_1m"), 2.87 + 5 * 0.2);
}

TEST(ObjectFeatures, SameWhenTheSceneTurnsAndMoves)
{
  const Scene scene;
  const double a = 0.65, c = std::cos(a), s = std::sin(a), dx = 310.25, dy = -72.5, dz = 14;
  const auto move = [&](const P3& p) { return P3{{c * p[0] - s * p[1] + dx, s * p[0] + c * p[1] + dy, p[2] + dz}}; };
  std::vector<Point> points;
  std::vector<P3> locations;
  for(const Point& p : scene.points) {
    const P3 q = move(P3{{p.x(), p.y(), p.z()}});
    points.emplace_back(q[0], q[1], q[2]);
  }
  for(const P3& l : scene.locations)
    locations.push_back(move(l));
  const PSOR::Object_features f = PSOR::extract_object_features(scene.points, scene.locations);
  const PSOR::Object_features g = PSOR::extract_object_features(points, locations);
  ASSERT_EQ(f.names, g.names);
  for(std::size_t o = 0; o < 3; ++o)
    for(std::size_t k = 0; k < f.names.size(); ++k) {
      // (the volume's columns and the area's cells are on grids, which turn with the scene)
      const bool grid = f.names[k].find("volume") != std::string::npos || f.names[k].find("area") != std::string::npos;
      const double tolerance = grid ? 0.1 * f.values[o][k] + 0.05 : 1e-6;
      EXPECT_NEAR(f.values[o][k], g.values[o][k], tolerance) << f.names[k] << " of object " << o;
    }
}

TEST(ObjectFeatures, SpinImageRadiusAndBadInput)
{
  const Scene scene;
  // With a radius of 1 m the bar (2 m to each side) keeps only its middle in the image.
  const PSOR::Object_features f =
      PSOR::extract_object_features(scene.points, scene.locations, PSOR::parameters::spin_image_radius(1.0));
  double outer = 0;
  for(int j = 0; j < 10; ++j)
    outer += feature(f, 1, "spin.4." + std::to_string(j));
  EXPECT_NEAR(outer, 0.2, 0.02) << "a fifth of the bar's middle metre lies in the outer ring";
  EXPECT_THROW(PSOR::extract_object_features(scene.points, scene.locations, PSOR::parameters::spin_image_radius(0.0)),
               CGAL::Shape_analysis::Bad_input);
  EXPECT_THROW(PSOR::extract_object_features(scene.points, scene.locations,
                                             PSOR::parameters::spin_image_radius(std::numeric_limits<double>::infinity())),
               CGAL::Shape_analysis::Bad_input);
  EXPECT_THROW(PSOR::extract_object_features(std::vector<Point>(), scene.locations), CGAL::Shape_analysis::Bad_input);
  std::vector<P3> bad = scene.locations;
  bad[1][0] = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(PSOR::extract_object_features(scene.points, bad), CGAL::Shape_analysis::Bad_input);
}

// Poles (class 0) and boxes (class 1) of random sizes every 15 m along x from `x0`, turned by
// random angles; their bases in `objects`.
void add_poles_and_boxes(std::uint32_t seed, double x0, std::size_t count, std::vector<Point>& points,
                         std::vector<PSOR::Labelled_location>& objects)
{
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(0, 1);
  for(std::size_t k = 0; k < count; ++k) {
    const double cx = x0 + 15.0 * double(k), cy = 0, a = 6.28 * u(rng), c = std::cos(a), s = std::sin(a);
    const auto add = [&](double x, double y, double z) { points.emplace_back(cx + c * x - s * y, cy + s * x + c * y, z); };
    PSOR::Labelled_location l;
    l.position = {{cx, cy, 0}};
    l.label = k % 2;
    objects.push_back(l);
    if(l.label == 0) { // a pole 2.5 to 4 m high
      const double h = 2.5 + 1.5 * u(rng);
      for(double z = 0.02; z < h; z += 0.02)
        add(0.05 * std::cos(50 * z), 0.05 * std::sin(50 * z), z);
    } else { // a box 2-4 x 1.5-2 x 1-1.6 m
      const double l2 = 1 + u(rng), w2 = 0.75 + 0.25 * u(rng), h = 1 + 0.6 * u(rng);
      for(double x = -l2; x <= l2; x += 0.1)
        for(double y = -w2; y <= w2; y += 0.1)
          add(x, y, h);
      for(double z = 0.05; z < h; z += 0.1)
        for(double x = -l2; x <= l2; x += 0.1)
          add(x, -w2, z), add(x, w2, z);
    }
  }
}

// Trained on one row of shapes (and empty places as background), kNN and the forest name the
// shapes of another row, and call an empty place background.
TEST(ObjectRecognition, TrainOnOneSceneClassifyAnother)
{
  std::vector<Point> train_points, test_points;
  std::vector<PSOR::Labelled_location> train_objects, test_objects;
  add_poles_and_boxes(1, 0, 8, train_points, train_objects);
  add_poles_and_boxes(2, 200, 6, test_points, test_objects);
  std::vector<std::array<double, 3>> train_candidates, test_candidates;
  for(const auto& o : train_objects)
    train_candidates.push_back(o.position); // near objects: no background example
  for(double x : {-30.0, -45.0, 150.0})
    train_candidates.push_back({{x, 0, 0}});
  for(const auto& o : test_objects)
    test_candidates.push_back(o.position);
  test_candidates.push_back({{400, 0, 0}});
  std::vector<Point> all_test = test_points;
  PSOR::Knn_object_classifier knn(1);
  PSOR::Random_forest_object_classifier forest(20, 10, 3);
  std::vector<Point> all_train = train_points;
  // A point beyond the empty places, so that they lie inside the scans' extents.
  all_train.emplace_back(-50, 0, 0.5), all_train.emplace_back(160, 0, 0.5);
  all_test.emplace_back(410, 0, 0.5);
  const PSOR::Object_features f = PSOR::train_object_classifier(knn, all_train, train_objects, 2, train_candidates);
  EXPECT_EQ(f.values.size(), train_objects.size() + 3) << "every object and the three empty places";
  PSOR::train_object_classifier(forest, all_train, train_objects, 2, train_candidates);
  for(const auto* c : {static_cast<const void*>(&knn), static_cast<const void*>(&forest)}) {
    const std::vector<PSOR::Labelled_location> r =
        c == &knn ? PSOR::classify_objects(knn, all_test, test_candidates)
                  : PSOR::classify_objects(forest, all_test, test_candidates);
    ASSERT_EQ(r.size(), test_candidates.size());
    for(std::size_t k = 0; k < test_objects.size(); ++k)
      EXPECT_EQ(r[k].label, test_objects[k].label) << "object " << k;
    EXPECT_EQ(r.back().label, 2u) << "the empty place is background";
    const auto s = PSOR::evaluate_recognition(r, test_objects, 2);
    EXPECT_EQ(s[2].precision, 1.0);
    EXPECT_EQ(s[2].recall, 1.0);
  }
  EXPECT_THROW(PSOR::train_object_classifier(knn, all_train, std::vector<PSOR::Labelled_location>(), 2, train_candidates),
               CGAL::Shape_analysis::Bad_input);
  EXPECT_THROW(PSOR::train_object_classifier(knn, all_train, train_objects, 1, train_candidates),
               CGAL::Shape_analysis::Bad_input)
      << "a label not below the number of classes";
}

// The examples of a labelled scan: an object at each candidate near it (with its label), at its
// own place when no candidate is near, the far candidates as background; two scans pooled train
// the same classifier as their examples concatenated.
TEST(ObjectRecognition, TrainingExamples)
{
  std::vector<Point> points;
  std::vector<PSOR::Labelled_location> objects;
  add_poles_and_boxes(5, 0, 4, points, objects);
  points.emplace_back(-60, 0, 0.5);
  std::vector<std::array<double, 3>> candidates;
  candidates.push_back({{objects[0].position[0] + 0.5, 0, 0}}); // near object 0 (two candidates)
  candidates.push_back({{objects[0].position[0] - 0.5, 0, 0}});
  candidates.push_back({{-50, 0, 0}}); // background
  // objects 1..3 have no candidate: learned at their own places
  const PSOR::Object_training_examples e = PSOR::object_training_examples(points, objects, 2, candidates);
  ASSERT_EQ(e.labels.size(), 2u + 3u + 1u);
  ASSERT_EQ(e.features.values.size(), e.labels.size());
  EXPECT_EQ(e.labels[0], objects[0].label);
  EXPECT_EQ(e.labels[1], objects[0].label);
  for(std::size_t k = 1; k < 4; ++k)
    EXPECT_EQ(e.labels[k + 1], objects[k].label);
  EXPECT_EQ(e.labels.back(), 2u) << "the far candidate is background";
  // With a larger background distance, the far candidate is still background, and nothing else
  // changes; with a tiny one, the two near candidates become background and object 0 is learned
  // at its own place.
  const PSOR::Object_training_examples tight = PSOR::object_training_examples(points, objects, 2, candidates, 0.1);
  ASSERT_EQ(tight.labels.size(), 4u + 3u);
  EXPECT_EQ(std::count(tight.labels.begin(), tight.labels.end(), std::size_t(2)), 3);
  // Training on the examples equals train_object_classifier().
  PSOR::Knn_object_classifier a(1), b(1);
  a.train(e.features.values, e.labels, 3);
  PSOR::train_object_classifier(b, points, objects, 2, candidates);
  for(const auto& row : e.features.values) {
    double ca = 0, cb = 0;
    EXPECT_EQ(a.predict(row, ca), b.predict(row, cb));
    EXPECT_EQ(ca, cb);
  }
  EXPECT_THROW(PSOR::object_training_examples(points, objects, 2, candidates, 0.0), CGAL::Shape_analysis::Bad_input);
  std::vector<std::array<double, 3>> bad = candidates;
  bad[0][1] = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(PSOR::object_training_examples(points, objects, 2, bad), CGAL::Shape_analysis::Bad_input);
}

// Identical vectors of two classes leave the forest's nodes without a split (every coordinate
// constant): the model still saves, loads and predicts the same (a real street's examples did).
TEST(ObjectRecognition, ForestWithUnsplittableNodesSavesAndLoads)
{
  std::vector<std::vector<double>> features;
  std::vector<std::size_t> labels;
  for(int k = 0; k < 40; ++k) {
    features.push_back(k < 30 ? std::vector<double>{1.0, 2.0, 3.0} : std::vector<double>{double(k), 0.5 * k, 1.0});
    labels.push_back(k < 30 ? std::size_t(k % 2) : std::size_t(2));
  }
  PSOR::Random_forest_object_classifier forest(10, 20, 1);
  forest.train(features, labels, 3);
  std::stringstream text;
  forest.save(text);
  PSOR::Random_forest_object_classifier loaded;
  ASSERT_NO_THROW(loaded.load(text));
  for(const auto& f : features) {
    double a = 0, b = 0;
    EXPECT_EQ(forest.predict(f, a), loaded.predict(f, b));
    EXPECT_EQ(a, b);
  }
}

TEST(ObjectRecognition, EvaluationCounts)
{
  const auto at = [](double x, std::size_t label) {
    PSOR::Labelled_location l;
    l.position = {{x, 0, 0}};
    l.label = label;
    return l;
  };
  // Right class at 0.9 m; wrong class at 5; background at 20 (left out); truth 0, 5 (class 0), 21 (1).
  const std::vector<PSOR::Labelled_location> predicted{at(0.9, 0), at(5, 1), at(20, 2)};
  const std::vector<PSOR::Labelled_location> truth{at(0, 0), at(5, 0), at(21, 1)};
  const auto s = PSOR::evaluate_recognition(predicted, truth, 2);
  ASSERT_EQ(s.size(), 3u);
  EXPECT_EQ(s[0].predicted, 1u);
  EXPECT_EQ(s[0].correct, 1u);
  EXPECT_EQ(s[0].objects, 2u);
  EXPECT_EQ(s[0].found, 1u);
  EXPECT_EQ(s[1].predicted, 1u);
  EXPECT_EQ(s[1].correct, 0u);
  EXPECT_EQ(s[1].objects, 1u);
  EXPECT_EQ(s[1].found, 0u);
  EXPECT_DOUBLE_EQ(s[2].precision, 0.5);
  EXPECT_DOUBLE_EQ(s[2].recall, 1.0 / 3.0);
  EXPECT_EQ(PSOR::evaluate_recognition(predicted, truth, 2, 0.5)[0].correct, 0u) << "0.9 m is beyond 0.5 m";
  EXPECT_THROW(PSOR::evaluate_recognition(predicted, truth, 1), CGAL::Shape_analysis::Bad_input);
  EXPECT_THROW(PSOR::evaluate_recognition(predicted, truth, 2, 0.0), CGAL::Shape_analysis::Bad_input);
}

// recognize_objects() with a classifier: with one tile, each location gets the class that
// classify_objects() gives it on the same points; the same for any number of threads and, as
// far as tiles see the same surroundings, tile by tile; an untrained classifier is refused.
TEST(ObjectRecognition, RecognizeObjectsWithAClassifier)
{
  namespace SAS = CGAL::Shape_analysis_support;
  SAS::Urban_scene_options o;
  o.seed = 3, o.street_length = 80, o.target_points = 300000;
  const SAS::Urban_scene scene = SAS::make_urban_scene(o);
  std::vector<Point> scan;
  for(const auto& p : SAS::scan_urban_scene(scene, o).points)
    scan.emplace_back(p.x, p.y, p.z);
  std::vector<PSOR::Labelled_location> truth;
  for(const SAS::Urban_object& ob : scene.objects) {
    PSOR::Labelled_location l;
    l.position = {{ob.x, ob.y, ob.z}};
    l.label = std::size_t(ob.object_class - SAS::first_object_class);
    truth.push_back(l);
  }
  const PSOR::Background_removal_result b = PSOR::remove_background(scan);
  std::vector<Point> above, foreground;
  for(std::size_t i : PSOR::points_above_ground(b))
    above.push_back(scan[i]);
  for(std::size_t i : b.foreground)
    foreground.push_back(scan[i]);
  const PSOR::Localization_result located = PSOR::locate_objects(foreground);
  PSOR::Random_forest_object_classifier forest(20, 12, 5);
  PSOR::train_object_classifier(forest, above, truth, SAS::number_of_object_classes, located.locations);

  const PSOR::Object_recognition_result r =
      PSOR::recognize_objects(scan, PSOR::parameters::object_classifier(forest).tile_size(1000.0));
  ASSERT_FALSE(r.locations.empty());
  ASSERT_EQ(r.labels.size(), r.locations.size());
  ASSERT_EQ(r.confidences.size(), r.locations.size());
  std::vector<Point> kept;
  for(std::size_t i = 0; i < scan.size(); ++i)
    if(r.kind[i] != PSOR::Point_kind::GROUND)
      kept.push_back(scan[i]);
  const std::vector<PSOR::Labelled_location> c = PSOR::classify_objects(forest, kept, r.locations);
  ASSERT_EQ(r.features.size(), r.locations.size()) << "the rows the labels came from";
  const PSOR::Object_features direct = PSOR::extract_object_features(kept, r.locations);
  std::size_t objects = 0;
  for(std::size_t k = 0; k < c.size(); ++k) {
    EXPECT_EQ(r.features[k], direct.values[k]) << "location " << k;
    EXPECT_EQ(r.labels[k], c[k].label) << "location " << k;
    EXPECT_DOUBLE_EQ(r.confidences[k], c[k].confidence);
    objects += r.labels[k] < std::size_t(SAS::number_of_object_classes) ? 1 : 0;
  }
  EXPECT_GT(objects, r.locations.size() / 2) << "most locations hold an object of a class";
  const PSOR::Object_recognition_result one =
      PSOR::recognize_objects(scan, PSOR::parameters::object_classifier(forest).tile_size(1000.0).number_of_threads(1));
  EXPECT_EQ(one.labels, r.labels);
  const PSOR::Object_recognition_result tiles =
      PSOR::recognize_objects(scan, PSOR::parameters::object_classifier(forest).tile_size(30.0));
  EXPECT_EQ(tiles.labels.size(), tiles.locations.size());
  const PSOR::Object_recognition_result plain = PSOR::recognize_objects(scan, PSOR::parameters::tile_size(1000.0));
  EXPECT_TRUE(plain.labels.empty());
  EXPECT_TRUE(plain.features.empty());
  // The features' segmentations share the objects' graph: the objects stay those without a classifier.
  EXPECT_EQ(plain.object_of_point, r.object_of_point);
  const PSOR::Object_features serial = PSOR::extract_object_features(kept, r.locations, PSOR::parameters::number_of_threads(1));
  EXPECT_EQ(serial.values, direct.values) << "the same rows for any number of threads";
  EXPECT_THROW(PSOR::recognize_objects(scan, PSOR::parameters::object_classifier(PSOR::Knn_object_classifier(1))),
               CGAL::Shape_analysis::Bad_input);
}

} // namespace
