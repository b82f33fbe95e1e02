// Copyright (c) 2026 CGAL Global Shape Analysis contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later

// Segmentation of objects from their locations: scanned procedural streets with known objects
// (precision and recall), a post touching a wall and two touching newspaper boxes built here,
// the interactive segmenter's constraints, determinism across thread counts, bad input; the
// whole chain tile by tile (recognize_objects) against one tile.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Point_set_3.h>

#include <Shape_analysis_support/Scanned_objects.h>
#include <CGAL/Point_set_object_recognition/recognize_objects.h>
#include <CGAL/Point_set_object_recognition/segment_objects.h>
#include <CGAL/Shape_analysis/internal/Random.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <map>
#include <set>
#include <vector>

namespace {

typedef CGAL::Exact_predicates_inexact_constructions_kernel Kernel;
typedef Kernel::Point_3 Point;
namespace PSOR = CGAL::Point_set_object_recognition;
namespace PSI = CGAL::Point_set_object_recognition::internal;
namespace SAS = CGAL::Shape_analysis_support;
using CGAL::Shape_analysis::Bad_input;

// Points on a surface sampled with jitter; label per point.
struct Cloud
{
  std::vector<Point> points;
  std::vector<int> label;
  CGAL::Shape_analysis::internal::Random_stream rng{7};

  void add(double x, double y, double z, int l)
  {
    points.emplace_back(x + rng.uniform(-0.005, 0.005), y + rng.uniform(-0.005, 0.005), z + rng.uniform(-0.005, 0.005));
    label.push_back(l);
  }
  // A vertical wall in the plane y = y0, x in [x0, x1], z in [0, h], spacing s.
  void wall(double y0, double x0, double x1, double h, double s, int l)
  {
    for(double x = x0; x <= x1; x += s)
      for(double z = 0.05; z <= h; z += s)
        add(x, y0, z, l);
  }
  // A vertical cylinder (post) at (cx, cy), radius r, height h.
  void post(double cx, double cy, double r, double h, double s, int l)
  {
    const int n = (std::max)(6, int(2 * 3.14159 * r / s));
    for(double z = 0.05; z <= h; z += s)
      for(int k = 0; k < n; ++k)
        add(cx + r * std::cos(2 * 3.14159 * k / n), cy + r * std::sin(2 * 3.14159 * k / n), z, l);
  }
  // The four sides and the top of a box [x0, x1] x [y0, y1] x [0, h].
  void box(double x0, double x1, double y0, double y1, double h, double s, int l)
  {
    for(double z = 0.05; z <= h; z += s) {
      for(double x = x0; x <= x1; x += s)
        add(x, y0, z, l), add(x, y1, z, l);
      for(double y = y0 + s; y < y1; y += s)
        add(x0, y, z, l), add(x1, y, z, l);
    }
    for(double x = x0 + s; x < x1; x += s)
      for(double y = y0 + s; y < y1; y += s)
        add(x, y, h, l);
  }
};

// Precision and recall of `segmented` against the points whose label is `l`.
std::pair<double, double> score(const std::vector<int>& labels, const std::vector<std::size_t>& segmented, int l)
{
  std::size_t correct = 0, total = 0;
  for(std::size_t i : segmented)
    correct += labels[i] == l;
  for(int x : labels)
    total += x == l;
  return {segmented.empty() ? 0.0 : double(correct) / double(segmented.size()), double(correct) / double(total)};
}

// A short street of the generator's making (Urban_scene.h): flat ground, a facade at y = 10 and
// the given objects, scanned by the simulated mobile LIDAR driving along y = 0 (occlusion and
// range-dependent density included), its ground removed.
struct Small_street
{
  SAS::Urban_scene scene;
  SAS::urban_detail::Builder builder{scene, {}};
  int next_id = 1;

  Small_street()
  {
    scene.street_length = 20;
    for(int i = -5; i < 25; ++i)
      for(int j = -12; j < 12; ++j)
        builder.quad({double(i), double(j), 0}, {double(i + 1), double(j), 0}, {double(i + 1), double(j + 1), 0},
                     {double(i), double(j + 1), 0}, SAS::GROUND);
    SAS::urban_detail::Shape facade;
    facade.aabox(-5, 10, -0.5, 25, 14, 8);
    builder.place(facade, 0, 0, 0, 0, 0, SAS::BUILDING, false);
  }
  // An object of class c, its local origin at (x, y) on the ground.
  void add(const SAS::urban_detail::Shape& shape, double x, double y, int c)
  {
    ASSERT_TRUE(builder.place(shape, x, y, 0, 0, next_id++, c, false));
  }
  SAS::Scanned_objects scan() const
  {
    SAS::Urban_scene_options o;
    o.street_length = 20;
    o.target_points = 150000;
    return SAS::scanned_objects(scene, SAS::scan_urban_scene(scene, o));
  }
};

TEST(Segmentation, PostTouchingAWall)
{
  // A post of 15 cm radius whose surface is 1 cm from a facade: the scanner sees about 150 of its
  // points and tens of thousands of the facade's around it. The facade is found as a wall (its
  // columns rise higher than 3.5 m, its high points lie along a line, the points under them are
  // the wall's) and kept out of the graph. Measured: precision 1, recall 1 (without the walls:
  // recall 0.25, the cut going through the post, whose 0.2 m cells also held facade points); all
  // points within 1 m: precision under 0.02.
  Small_street street;
  SAS::urban_detail::Shape post;
  post.post(0, 0, -0.05, 2.5, 0.15);
  street.add(post, 10, 10 - 0.15 - 0.01, SAS::TALL_POST);
  const SAS::Scanned_objects s = street.scan();
  ASSERT_EQ(s.locations.size(), 1u);
  const PSOR::Object_segmentation r = PSOR::segment_object(s.points, s.locations[0]);
  const auto pr = score(s.instance, r.points, 1);
  std::cerr << "post at a wall: " << r.points.size() << " points, precision " << pr.first << ", recall " << pr.second
            << ", radius " << r.radius << ", cut " << r.cut_cost << "\n";
  ASSERT_NE(r.seed, PSOR::Object_segmentation::no_point);
  EXPECT_EQ(s.instance[r.seed], 1);
  EXPECT_GE(pr.first, 0.9);
  EXPECT_GE(pr.second, 0.9);
  // All points within 1 m are mostly the facade.
  const auto all = PSOR::segment_object(s.points, s.locations[0],
                                        PSOR::parameters::segmentation_method(PSOR::Segmentation_method::ALL_WITHIN_RADIUS)
                                          .background_radius(1.0));
  EXPECT_LT(score(s.instance, all.points, 1).first, 0.1);
  // Away from the facade (30 cm), the post is found whole and alone.
  Small_street apart;
  apart.add(post, 10, 10 - 0.15 - 0.3, SAS::TALL_POST);
  const SAS::Scanned_objects t = apart.scan();
  const auto q = score(t.instance, PSOR::segment_object(t.points, t.locations[0]).points, 1);
  std::cerr << "post 30 cm from a wall: precision " << q.first << ", recall " << q.second << "\n";
  EXPECT_GE(q.first, 0.9);
  EXPECT_GE(q.second, 0.9);
}

TEST(Segmentation, TwoTouchingNewspaperBoxes)
{
  Small_street street;
  SAS::urban_detail::Shape box;
  box.aabox(-0.25, -0.22, -0.05, 0.25, 0.22, 1.1);
  street.add(box, 10, 6, SAS::NEWSPAPER_BOX);
  street.add(box, 10.51, 6, SAS::NEWSPAPER_BOX); // 1 cm apart
  const SAS::Scanned_objects s = street.scan();
  ASSERT_EQ(s.locations.size(), 2u);
  const PSOR::Segmentation_result r = PSOR::segment_objects(s.points, s.locations);
  for(int k = 0; k < 2; ++k) {
    const auto pr = score(s.instance, r.objects[k].points, k + 1);
    std::cerr << "box " << k + 1 << ": " << r.objects[k].points.size() << " points, precision " << pr.first
              << ", recall " << pr.second << ", radius " << r.objects[k].radius << "\n";
    EXPECT_GE(pr.second, 0.9); // each box is found whole
    EXPECT_EQ(s.instance[r.objects[k].seed], k + 1);
  }
  // Each point is claimed by one object, the nearest location where both took it: the labelling
  // separates the boxes.
  const PSOR::Segmentation_evaluation e = PSOR::evaluate_labelling(r.object_of_point, s.instance, s.class_of_instance);
  ASSERT_EQ(e.objects.size(), 2u);
  std::cerr << "labelling: precision " << e.precision << ", recall " << e.recall << "\n";
  EXPECT_GE(e.precision, 0.8);
  EXPECT_GE(e.recall, 0.8);
}

TEST(Segmentation, MethodsAndParameters)
{
  Cloud c;
  c.post(0, 0, 0.1, 2, 0.03, 1);
  c.post(1.5, 0, 0.1, 2, 0.03, 2); // 1.5 m away
  const std::array<double, 3> at{{0, 0, 0}};
  const auto method = [](PSOR::Segmentation_method m, double r) {
    return PSOR::parameters::segmentation_method(m).background_radius(r);
  };
  // Within 2 m: both posts; within 1 m: the first.
  EXPECT_EQ(PSOR::segment_object(c.points, at, method(PSOR::Segmentation_method::ALL_WITHIN_RADIUS, 2.0)).points.size(),
            c.points.size());
  EXPECT_DOUBLE_EQ(score(c.label, PSOR::segment_object(c.points, at, method(PSOR::Segmentation_method::ALL_WITHIN_RADIUS, 1.0)).points, 1).first, 1.0);
  // Connected components: only the first, even within 2 m.
  const auto cc = PSOR::segment_object(c.points, at, method(PSOR::Segmentation_method::CONNECTED_COMPONENTS, 2.0));
  EXPECT_EQ(score(c.label, cc.points, 1), std::make_pair(1.0, 1.0));
  // Min-cut, fixed radius, with cells and with one node per point, contracted or not.
  for(double cell : {0.2, 0.0})
    for(std::size_t size : {std::size_t(0), std::size_t(50)}) {
      const auto m = PSOR::segment_object(
        c.points, at, method(PSOR::Segmentation_method::MIN_CUT, 2.0).graph_cell_size(cell).maximum_graph_size(size));
      EXPECT_EQ(score(c.label, m.points, 1), std::make_pair(1.0, 1.0)) << "cell " << cell << ", size " << size;
      EXPECT_DOUBLE_EQ(m.radius, 2.0);
    }
  // The automatic radius stops at 1 m: a clean cut with more than 35 points.
  const auto a = PSOR::segment_object(c.points, at);
  EXPECT_DOUBLE_EQ(a.radius, 1.0);
  EXPECT_LT(a.cut_cost, 0.4);
  // A Point_set_3 gives the same.
  CGAL::Point_set_3<Point> ps;
  for(const Point& p : c.points)
    ps.insert(p);
  EXPECT_EQ(PSOR::segment_objects(ps, std::vector<std::array<double, 3>>{at}).objects[0].points, a.points);
}

// A radius far beyond the cloud visits the cloud's columns only (it walked (2r)^2 cells, and
// 1e300 overflowed the cell index): every point within it, at once.
TEST(Segmentation, HugeRadiiVisitOnlyTheCloud)
{
  Cloud c;
  c.post(0, 0, 0.1, 2, 0.03, 1);
  c.post(1.5, 0, 0.1, 2, 0.03, 2);
  const std::array<double, 3> at{{0, 0, 0}};
  for(double r : {1e9, 1e300}) {
    const auto all = PSOR::segment_object(
      c.points, at, PSOR::parameters::segmentation_method(PSOR::Segmentation_method::ALL_WITHIN_RADIUS).background_radius(r));
    EXPECT_EQ(all.points.size(), c.points.size()) << r;
    const auto cut = PSOR::segment_object(
      c.points, at, PSOR::parameters::segmentation_method(PSOR::Segmentation_method::MIN_CUT).background_radius(r));
    EXPECT_FALSE(cut.points.empty()) << r;
    EXPECT_LE(cut.points.size(), c.points.size()) << r;
  }
}

TEST(Segmentation, InteractiveConstraintsAreHonoured)
{
  Cloud c;
  c.wall(0.0, -4, 4, 5, 0.06, 0);
  c.post(0.0, 0.12, 0.1, 2.5, 0.04, 1);
  c.box(0.3, 0.8, 0.02, 0.5, 1.0, 0.05, 2); // a box touching both
  PSOR::Interactive_segmenter seg(c.points, {0.0, 0.12, 0.0});
  CGAL::Shape_analysis::internal::Random_stream rng(3);
  std::map<std::size_t, bool> wanted;
  const double first_seconds = seg.segmentation().seconds;
  double later_seconds = 0;
  for(int step = 0; step < 40; ++step) {
    // Random points, mostly near the location (inside the graph), sometimes contradicting an
    // earlier constraint on the same point.
    std::size_t i = rng.index(c.points.size());
    if(step % 5 == 4 && !wanted.empty())
      i = wanted.begin()->first;
    const bool fg = rng.uniform() < 0.5;
    const Point& p = c.points[i];
    if(fg && std::hypot(p.x(), p.y() - 0.12) > seg.segmentation().radius)
      continue;
    const PSOR::Object_segmentation& s = fg ? seg.add_foreground(i) : seg.add_background(i);
    later_seconds += s.seconds;
    wanted[i] = fg;
    const std::set<std::size_t> in(s.points.begin(), s.points.end());
    for(const auto& w : wanted)
      ASSERT_EQ(in.count(w.first) == 1, w.second) << "constraint on point " << w.first << " at step " << step;
  }
  EXPECT_GT(seg.number_of_constraints(), 10u);
  std::cerr << "interactive: first solve " << first_seconds << " s, " << seg.number_of_constraints()
            << " constraints re-solved in " << later_seconds << " s in all\n";
  // Far points cannot be foreground.
  c.points.emplace_back(30, 30, 1);
  PSOR::Interactive_segmenter far(c.points, {0.0, 0.12, 0.0});
  EXPECT_THROW(far.add_foreground(c.points.size() - 1), Bad_input);
  EXPECT_NO_THROW(far.add_background(c.points.size() - 1));
  EXPECT_THROW(far.add_background(c.points.size()), Bad_input);
  EXPECT_THROW(PSOR::Interactive_segmenter(c.points, {0.0, 0.12, 0.0},
                                           PSOR::parameters::segmentation_method(PSOR::Segmentation_method::ALL_WITHIN_RADIUS)),
               Bad_input);
}

// A generated street: ground removed, objects segmented at their true locations.
const SAS::Scanned_objects& street()
{
  static const SAS::Scanned_objects s = [] {
    SAS::Urban_scene_options o;
    o.seed = 4;
    o.target_points = 300000;
    o.street_length = 80;
    const SAS::Urban_scene scene = SAS::make_urban_scene(o);
    return SAS::scanned_objects(scene, SAS::scan_urban_scene(scene, o));
  }();
  return s;
}

TEST(Segmentation, ScannedStreetObjects)
{
  const SAS::Scanned_objects& s = street();
  ASSERT_GE(s.locations.size(), 10u);
  const PSOR::Segmentation_result r = PSOR::segment_objects(s.points, s.locations);
  const PSOR::Segmentation_evaluation e = PSOR::evaluate_segmentations(r.objects, s.instance, s.class_of_instance);
  PSOR::print_segmentation_table(std::cerr, e, [](int c) { return std::string(SAS::object_class_name(c)); });
  // Measured 0.87 / 0.90 on seed 1 (tuning) and about the same on others: margins below.
  EXPECT_GE(e.precision, 0.75);
  EXPECT_GE(e.recall, 0.8);
  // Min-cut beats all points within 1 m on precision.
  const PSOR::Segmentation_result all = PSOR::segment_objects(
    s.points, s.locations,
    PSOR::parameters::segmentation_method(PSOR::Segmentation_method::ALL_WITHIN_RADIUS).background_radius(1.0));
  EXPECT_GT(e.precision, PSOR::evaluate_segmentations(all.objects, s.instance, s.class_of_instance).precision);
  // The labelling gives one segmentation per location.
  const PSOR::Segmentation_evaluation l = PSOR::evaluate_labelling(r.object_of_point, s.instance, s.class_of_instance);
  EXPECT_GE(l.recall, 0.7);
}

TEST(Segmentation, SameResultForAnyThreadCount)
{
  const SAS::Scanned_objects& s = street();
  const auto one = PSOR::segment_objects(s.points, s.locations, PSOR::parameters::number_of_threads(1));
  for(std::size_t t : {std::size_t(2), std::size_t(0)}) {
    const auto many = PSOR::segment_objects(s.points, s.locations, PSOR::parameters::number_of_threads(t));
    ASSERT_EQ(many.objects.size(), one.objects.size());
    for(std::size_t k = 0; k < one.objects.size(); ++k) {
      EXPECT_EQ(many.objects[k].points, one.objects[k].points);
      EXPECT_EQ(many.objects[k].radius, one.objects[k].radius);
      EXPECT_EQ(many.objects[k].cut_cost, one.objects[k].cut_cost);
    }
    EXPECT_EQ(many.object_of_point, one.object_of_point);
  }
}

TEST(Segmentation, EvaluationCounts)
{
  // Points 0-3: object 1; 4-5: object 2; 6: background; 7: ignored.
  const std::vector<int> instance = {1, 1, 1, 1, 2, 2, 0, -1};
  PSOR::Object_segmentation a, b, c;
  a.points = {0, 1, 2, 6, 7}; // 3 of object 1 and one background: precision 3/4, recall 3/4
  b.points = {4, 5};          // object 2 whole
  c.points = {6};             // background only
  const auto e = PSOR::evaluate_segmentations({a, b, c}, instance, {{1, 10}, {2, 11}});
  ASSERT_EQ(e.objects.size(), 2u);
  EXPECT_EQ(e.unmatched, 1u);
  EXPECT_DOUBLE_EQ(e.objects[0].precision, 0.75);
  EXPECT_DOUBLE_EQ(e.objects[0].recall, 0.75);
  EXPECT_DOUBLE_EQ(e.precision, 0.875);
  ASSERT_EQ(e.classes.size(), 2u);
  EXPECT_EQ(e.classes[1].object_class, 11);
  EXPECT_DOUBLE_EQ(e.classes[1].recall, 1.0);
  EXPECT_THROW(PSOR::evaluate_labelling(std::vector<int>{0, 1}, instance, {}), Bad_input);
}

TEST(Segmentation, BadInput)
{
  Cloud c;
  c.post(0, 0, 0.1, 2, 0.03, 1);
  const std::array<double, 3> at{{0, 0, 0}};
  EXPECT_THROW(PSOR::segment_object(std::vector<Point>(), at), Bad_input);
  EXPECT_THROW(PSOR::segment_object(c.points, {50.0, 0.0, 0.0}), Bad_input); // outside the cloud
  EXPECT_THROW(PSOR::segment_object(c.points, {0.0, 0.0, std::nan("")}), Bad_input);
  EXPECT_THROW(PSOR::segment_object(c.points, at, PSOR::parameters::background_radius(0.0)), Bad_input);
  EXPECT_THROW(PSOR::segment_object(c.points, at, PSOR::parameters::background_radius(-1.0)), Bad_input);
  EXPECT_THROW(PSOR::segment_object(c.points, at, PSOR::parameters::number_of_neighbors(0)), Bad_input);
  EXPECT_THROW(PSOR::segment_object(c.points, at, PSOR::parameters::edge_sigma(0.0)), Bad_input);
  EXPECT_THROW(PSOR::segment_object(c.points, at, PSOR::parameters::graph_cell_size(-0.1)), Bad_input);
  std::vector<Point> nan = c.points;
  nan.emplace_back(std::nan(""), 0, 0);
  EXPECT_THROW(PSOR::segment_object(nan, at), Bad_input);
  try {
    PSOR::segment_object(c.points, {50.0, 0.0, 0.0});
  } catch(const Bad_input& e) {
    EXPECT_NE(std::string(e.what()).find("outside"), std::string::npos);
  }
  // No location: no object.
  EXPECT_TRUE(PSOR::segment_objects(c.points, std::vector<std::array<double, 3>>()).objects.empty());
}

// A whole generated scan (ground included) with its truth: the input of recognize_objects().
struct Whole_scan
{
  std::vector<Point> points;
  std::vector<int> instance;
  std::map<int, int> class_of_instance;
  std::vector<std::array<double, 2>> seen; // objects with enough points above the ground
};

const Whole_scan& whole_scan()
{
  static const Whole_scan w = [] {
    SAS::Urban_scene_options o;
    o.seed = 5;
    o.target_points = 400000;
    o.street_length = 160;
    const SAS::Urban_scene scene = SAS::make_urban_scene(o);
    const SAS::Urban_scan scan = SAS::scan_urban_scene(scene, o);
    Whole_scan r;
    for(const auto& p : scan.points) {
      r.points.emplace_back(p.x, p.y, p.z);
      r.instance.push_back(p.instance);
      if(p.instance > 0)
        r.class_of_instance[p.instance] = p.label;
    }
    for(const auto& l : SAS::scanned_objects(scene, scan).locations)
      r.seen.push_back({l[0], l[1]});
    return r;
  }();
  return w;
}

// The number of locations of `a` with one of `b` within `radius` (horizontally).
std::size_t matched_locations(const std::vector<PSOR::Object_location>& a, const std::vector<PSOR::Object_location>& b,
                              double radius)
{
  std::size_t m = 0;
  for(const auto& x : a)
    for(const auto& y : b)
      if(std::hypot(x.position[0] - y.position[0], x.position[1] - y.position[1]) <= radius) {
        ++m;
        break;
      }
  return m;
}

TEST(Segmentation, RecognitionInTilesAgreesWithOneTile)
{
  const Whole_scan& w = whole_scan();
  const PSOR::Object_recognition_result one = PSOR::recognize_objects(w.points, PSOR::parameters::tile_size(1000.0));
  ASSERT_EQ(one.tiles.size(), 1u);
  EXPECT_EQ(one.largest_tile, w.points.size());
  // Tiles of 40 m along a street of 160 m (and across it): at least 8 of them.
  const PSOR::Object_recognition_result tiled =
    PSOR::recognize_objects(w.points, PSOR::parameters::tile_size(40.0).tile_margin(10.0));
  ASSERT_GE(tiled.tiles.size(), 8u);
  EXPECT_LT(tiled.largest_tile, w.points.size() / 2);
  std::size_t sum = 0;
  for(const auto& t : tiled.tiles) {
    sum += t.number_of_locations;
    EXPECT_LE(t.number_of_points, tiled.largest_tile);
  }
  EXPECT_EQ(sum, tiled.locations.size());
  ASSERT_EQ(tiled.objects.size(), tiled.locations.size());
  ASSERT_EQ(tiled.object_of_point.size(), w.points.size());

  // The same objects are found: objects across a border are found once, not twice or never.
  const PSOR::Localization_evaluation e1 = PSOR::evaluate_locations(one.locations, w.seen, 1.0);
  const PSOR::Localization_evaluation et = PSOR::evaluate_locations(tiled.locations, w.seen, 1.0);
  std::cerr << "one tile: " << one.locations.size() << " locations, recall " << e1.recall << ", precision "
            << e1.precision << "; " << tiled.tiles.size() << " tiles: " << tiled.locations.size() << " locations, recall "
            << et.recall << ", precision " << et.precision << "\n";
  EXPECT_GE(et.recall, 0.85);
  EXPECT_GE(et.recall, e1.recall - 0.03);
  EXPECT_GE(double(matched_locations(one.locations, tiled.locations, 0.5)), 0.9 * double(one.locations.size()));
  EXPECT_LE(tiled.locations.size(), one.locations.size() + one.locations.size() / 20 + 1);
  for(std::size_t a = 0; a < tiled.locations.size(); ++a)
    for(std::size_t b = a + 1; b < tiled.locations.size(); ++b)
      EXPECT_GT(std::hypot(tiled.locations[a].position[0] - tiled.locations[b].position[0],
                           tiled.locations[a].position[1] - tiled.locations[b].position[1]),
                0.05);

  // The segmentations are as good.
  const auto s1 = PSOR::evaluate_segmentations(one.objects, w.instance, w.class_of_instance);
  const auto st = PSOR::evaluate_segmentations(tiled.objects, w.instance, w.class_of_instance);
  std::cerr << "segmentation: one tile " << s1.precision << " / " << s1.recall << ", tiles " << st.precision << " / "
            << st.recall << "\n";
  EXPECT_GE(st.precision, s1.precision - 0.03);
  EXPECT_GE(st.recall, s1.recall - 0.03);
  EXPECT_GE(st.recall, 0.85);
  // A point's object holds it; points never claimed by an object are not in any.
  std::vector<char> in_some(w.points.size(), 0);
  for(std::size_t k = 0; k < tiled.objects.size(); ++k)
    for(std::size_t i : tiled.objects[k].points)
      in_some[i] = 1;
  for(std::size_t i = 0; i < w.points.size(); ++i) {
    const std::size_t c = tiled.object_of_point[i];
    if(c == PSOR::Object_recognition_result::no_object) {
      EXPECT_FALSE(in_some[i]);
      continue;
    }
    ASSERT_LT(c, tiled.objects.size());
    EXPECT_TRUE(std::binary_search(tiled.objects[c].points.begin(), tiled.objects[c].points.end(), i));
  }
  // The ground is found in every tile: nearly the same points as with one tile.
  std::size_t ground1 = 0, groundt = 0, both = 0;
  for(std::size_t i = 0; i < w.points.size(); ++i) {
    const bool a = one.kind[i] == PSOR::Point_kind::GROUND, b = tiled.kind[i] == PSOR::Point_kind::GROUND;
    ground1 += a, groundt += b, both += a && b;
  }
  EXPECT_GE(double(both), 0.98 * double(ground1));
  EXPECT_GE(double(both), 0.98 * double(groundt));
}

TEST(Segmentation, RecognitionWithAMarginCoveringTheSceneLocatesAsOneTile)
{
  // With a margin over the whole scene every tile sees all of it: the locations found are exactly
  // those of one tile (each kept by one tile), and so are the kinds of the points.
  const Whole_scan& w = whole_scan();
  const auto one = PSOR::recognize_objects(w.points, PSOR::parameters::tile_size(1000.0));
  const auto all = PSOR::recognize_objects(w.points, PSOR::parameters::tile_size(80.0).tile_margin(1e30));
  ASSERT_GE(all.tiles.size(), 2u);
  EXPECT_EQ(all.largest_tile, w.points.size());
  auto sorted = [](const std::vector<PSOR::Object_location>& l) {
    std::vector<std::array<double, 3>> r;
    for(const auto& x : l)
      r.push_back(x.position);
    std::sort(r.begin(), r.end());
    return r;
  };
  EXPECT_EQ(sorted(all.locations), sorted(one.locations));
  EXPECT_TRUE(all.kind == one.kind);
  // No margin: objects near the borders lose their surroundings, but nothing breaks, and no
  // object holds a ground point.
  const auto bare = PSOR::recognize_objects(w.points, PSOR::parameters::tile_size(40.0).tile_margin(0.0));
  ASSERT_EQ(bare.objects.size(), bare.locations.size());
  for(const auto& o : bare.objects)
    for(std::size_t i : o.points)
      ASSERT_NE(bare.kind[i], PSOR::Point_kind::GROUND);
}

TEST(Segmentation, RecognitionOfABandReproducesItsTiles)
{
  // A cluster's share: the tiles of the band 0 <= x < 80 (tiles of 40 m on the grid through the
  // origin) from the band's points and its margin alone find the same objects as the whole run.
  const Whole_scan& w = whole_scan();
  const std::array<double, 2> origin{{0, 0}};
  const auto params = PSOR::parameters::tile_size(40.0).tile_margin(10.0).tile_origin(origin);
  const auto whole = PSOR::recognize_objects(w.points, params);
  std::vector<Point> band;
  std::vector<std::size_t> index;
  for(std::size_t i = 0; i < w.points.size(); ++i)
    if(w.points[i].x() >= -10 && w.points[i].x() <= 90)
      band.push_back(w.points[i]), index.push_back(i);
  const auto part = PSOR::recognize_objects(band, params);
  auto in_band = [](const PSOR::Object_recognition_result& r, const std::vector<std::size_t>& to_input) {
    std::vector<std::pair<std::array<double, 3>, std::vector<std::size_t>>> found;
    for(std::size_t k = 0; k < r.locations.size(); ++k)
      if(r.locations[k].position[0] >= 0 && r.locations[k].position[0] < 80) {
        std::vector<std::size_t> points;
        for(std::size_t i : r.objects[k].points)
          points.push_back(to_input.empty() ? i : to_input[i]);
        found.emplace_back(r.locations[k].position, points);
      }
    std::sort(found.begin(), found.end());
    return found;
  };
  const auto expected = in_band(whole, {});
  ASSERT_GE(expected.size(), 5u);
  EXPECT_TRUE(in_band(part, index) == expected);
  for(const auto& t : whole.tiles) // the grid goes through the origin
    EXPECT_EQ(std::fmod(std::abs(t.min[0]), 40.0), 0.0);
  EXPECT_THROW(PSOR::recognize_objects(w.points, PSOR::parameters::tile_origin(std::array<double, 2>{{std::nan(""), 0.0}})),
               Bad_input);
}

TEST(Segmentation, RecognitionSameForAnyThreadCount)
{
  const Whole_scan& w = whole_scan();
  const auto one = PSOR::recognize_objects(w.points, PSOR::parameters::tile_size(50.0).number_of_threads(1));
  // The tiles run in parallel (2 threads, and as many as TBB chooses) and are merged in order.
  for(std::size_t threads : {std::size_t(2), std::size_t(0)}) {
    const auto two = PSOR::recognize_objects(w.points, PSOR::parameters::tile_size(50.0).number_of_threads(threads));
    ASSERT_GT(two.tiles.size(), 2u);
    ASSERT_EQ(one.tiles.size(), two.tiles.size());
    for(std::size_t t = 0; t < one.tiles.size(); ++t) {
      EXPECT_EQ(one.tiles[t].min, two.tiles[t].min);
      EXPECT_EQ(one.tiles[t].number_of_points, two.tiles[t].number_of_points);
      EXPECT_EQ(one.tiles[t].number_of_locations, two.tiles[t].number_of_locations);
    }
    ASSERT_EQ(one.locations.size(), two.locations.size());
    for(std::size_t k = 0; k < one.locations.size(); ++k) {
      EXPECT_EQ(one.locations[k].position, two.locations[k].position);
      EXPECT_EQ(one.objects[k].points, two.objects[k].points);
      EXPECT_EQ(one.objects[k].seed, two.objects[k].seed);
    }
    EXPECT_EQ(one.object_of_point, two.object_of_point);
    EXPECT_EQ(one.kind, two.kind);
    EXPECT_EQ(one.largest_tile, two.largest_tile);
  }
  // The same from a CGAL::Point_set_3.
  CGAL::Point_set_3<Point> ps;
  for(const Point& p : w.points)
    ps.insert(p);
  const auto set = PSOR::recognize_objects(ps, PSOR::parameters::tile_size(50.0).number_of_threads(1));
  EXPECT_EQ(set.object_of_point, one.object_of_point);
  EXPECT_EQ(set.locations.size(), one.locations.size());
}

TEST(Segmentation, RecognitionBadInput)
{
  Cloud c;
  c.post(0, 0, 0.1, 2, 0.03, 1);
  EXPECT_THROW(PSOR::recognize_objects(std::vector<Point>()), Bad_input);
  EXPECT_THROW(PSOR::recognize_objects(c.points, PSOR::parameters::tile_size(0.0)), Bad_input);
  EXPECT_THROW(PSOR::recognize_objects(c.points, PSOR::parameters::tile_size(std::nan(""))), Bad_input);
  EXPECT_THROW(PSOR::recognize_objects(c.points, PSOR::parameters::tile_margin(-1.0)), Bad_input);
  EXPECT_THROW(PSOR::recognize_objects(c.points, PSOR::parameters::tile_size(1e-6)), Bad_input); // too many tiles
  std::vector<Point> nan = c.points;
  nan.emplace_back(0, std::nan(""), 0);
  EXPECT_THROW(PSOR::recognize_objects(nan), Bad_input);
}

// The options come from one place: without named parameters, the struct's defaults; a named
// parameter given lands in its member.
TEST(Segmentation, OptionsFromNamedParameters)
{
  const PSOR::Segment_objects_options d;
  const PSOR::Segment_objects_options o = PSOR::segment_objects_options();
  EXPECT_EQ(o.segmentation_method, d.segmentation_method);
  EXPECT_EQ(o.background_radius, d.background_radius);
  EXPECT_EQ(o.foreground_height, d.foreground_height);
  EXPECT_EQ(o.graph_cell_size, d.graph_cell_size);
  EXPECT_EQ(o.number_of_neighbors, d.number_of_neighbors);
  EXPECT_EQ(o.edge_sigma, d.edge_sigma);
  EXPECT_FALSE(o.edge_sigma.has_value());
  EXPECT_EQ(o.background_weight, d.background_weight);
  EXPECT_EQ(o.maximum_graph_size, d.maximum_graph_size);
  EXPECT_EQ(o.minimum_foreground_size, d.minimum_foreground_size);
  EXPECT_EQ(o.maximum_cut_cost, d.maximum_cut_cost);
  EXPECT_EQ(o.component_spacing, d.component_spacing);
  EXPECT_EQ(o.number_of_threads, d.number_of_threads);
  const PSOR::Segment_objects_options g =
    PSOR::segment_objects_options(PSOR::parameters::edge_sigma(0.5).maximum_cut_cost(0.25));
  ASSERT_TRUE(g.edge_sigma.has_value());
  EXPECT_EQ(*g.edge_sigma, 0.5);
  EXPECT_EQ(g.maximum_cut_cost, 0.25);
  EXPECT_EQ(g.background_radius, d.background_radius);
}

TEST(Segmentation, RecognitionOptionsFromNamedParameters)
{
  const PSOR::Recognize_objects_options d;
  const PSOR::Recognize_objects_options o = PSOR::recognize_objects_options();
  EXPECT_EQ(o.tile_size, d.tile_size);
  EXPECT_EQ(o.tile_margin, d.tile_margin);
  EXPECT_FALSE(o.tile_origin.has_value());
  EXPECT_EQ(o.localization_method, d.localization_method);
  EXPECT_EQ(o.segmentation_method, d.segmentation_method);
  EXPECT_EQ(o.background_radius, d.background_radius);
  EXPECT_EQ(o.number_of_threads, d.number_of_threads);
  // The segmentation's defaults are segment_objects()'s.
  EXPECT_EQ(d.segmentation_method, PSOR::Segment_objects_options().segmentation_method);
  EXPECT_EQ(d.background_radius, PSOR::Segment_objects_options().background_radius);
  const PSOR::Recognize_objects_options g = PSOR::recognize_objects_options(
    PSOR::parameters::tile_margin(4.0).tile_origin(std::array<double, 2>{{1.0, -2.0}}));
  EXPECT_EQ(g.tile_margin, 4.0);
  ASSERT_TRUE(g.tile_origin.has_value());
  EXPECT_EQ((*g.tile_origin)[0], 1.0);
  EXPECT_EQ((*g.tile_origin)[1], -2.0);
  EXPECT_EQ(g.tile_size, d.tile_size);
}

// An engine of its own: the tiles of the plan recognized one by one with recognize_tile(), in
// reverse order, each on the points it holds, merged by the documented rule, give exactly what
// recognize_objects() gives.
TEST(Segmentation, TilesDrivenOneByOneGiveTheWholeRecognition)
{
  const Whole_scan& w = whole_scan();
  const auto np = PSOR::parameters::tile_size(40.0).tile_margin(10.0).number_of_threads(1);
  const PSOR::Object_recognition_result whole = PSOR::recognize_objects(w.points, np);
  const PSOR::Tile_plan plan = PSOR::plan_tiles(w.points, np);
  std::vector<std::size_t> busy = plan.tiles_with_points();
  ASSERT_EQ(busy.size(), whole.tiles.size());
  std::vector<PSOR::Tile_recognition> found(plan.number_of_tiles());
  std::vector<std::vector<std::size_t>> held(plan.number_of_tiles());
  for(auto t = busy.rbegin(); t != busy.rend(); ++t) {
    std::vector<Point> points;
    for(std::size_t i = 0; i < w.points.size(); ++i)
      if(plan.holds(*t, w.points[i].x(), w.points[i].y()))
        points.push_back(w.points[i]), held[*t].push_back(i);
    found[*t] = PSOR::recognize_tile(plan, *t, points, np);
  }
  // The merge: locations tile after tile, kinds from the own tile, the nearest location's object.
  std::vector<std::array<double, 3>> at;
  std::vector<PSOR::Point_kind> kind(w.points.size(), PSOR::Point_kind::GROUND);
  std::vector<std::size_t> object(w.points.size(), PSOR::Object_recognition_result::no_object);
  std::vector<double> distance(w.points.size(), 0);
  for(std::size_t t : busy) {
    const PSOR::Tile_recognition& r = found[t];
    for(std::size_t k = 0; k < r.kind.size(); ++k) {
      const Point& p = w.points[held[t][k]];
      if(plan.tile_of(p.x(), p.y()) == t)
        kind[held[t][k]] = r.kind[k];
    }
    for(std::size_t k = 0; k < r.locations.size(); ++k) {
      at.push_back(r.locations[k].position);
      for(std::size_t local : r.objects[k].points) {
        const std::size_t i = held[t][local];
        const double d = std::hypot(w.points[i].x() - at.back()[0], w.points[i].y() - at.back()[1]);
        if(object[i] == PSOR::Object_recognition_result::no_object || d < distance[i])
          object[i] = at.size() - 1, distance[i] = d;
      }
    }
  }
  for(std::size_t i = 0; i < object.size(); ++i)
    if(kind[i] == PSOR::Point_kind::GROUND)
      object[i] = PSOR::Object_recognition_result::no_object;
  ASSERT_GE(at.size(), 5u);
  ASSERT_EQ(at.size(), whole.locations.size());
  for(std::size_t k = 0; k < at.size(); ++k)
    EXPECT_EQ(at[k], whole.locations[k].position);
  EXPECT_TRUE(kind == whole.kind);
  EXPECT_TRUE(object == whole.object_of_point);
}

// The plan: every point is owned by one tile and held by it; the tiles holding a point are those
// whose square grown by the margin contains it; a location over an empty square goes to a
// neighbour that owns points.
TEST(Segmentation, TilePlanOwnsHoldsAndKeeps)
{
  PSOR::Tile_plan plan = PSOR::plan_tiles(CGAL::Bbox_2(0, 0, 99, 49), PSOR::parameters::tile_size(20.0).tile_margin(3.0));
  ASSERT_EQ(plan.columns, 5u);
  ASSERT_EQ(plan.rows, 3u);
  CGAL::Shape_analysis::internal::Random_stream rng(3);
  for(int k = 0; k < 2000; ++k) {
    const double x = rng.uniform(-10.0, 110.0), y = rng.uniform(-10.0, 60.0);
    const std::size_t own = plan.tile_of(x, y);
    ASSERT_LT(own, plan.number_of_tiles());
    EXPECT_TRUE(plan.holds(own, x, y));
    std::vector<std::size_t> listed;
    plan.for_each_tile_holding(x, y, [&](std::size_t t) { listed.push_back(t); });
    for(std::size_t t = 0; t < plan.number_of_tiles(); ++t) {
      const PSOR::Scene_tile s = plan.tile(t);
      const bool near = x >= s.min[0] - 3 && x <= s.max[0] + 3 && y >= s.min[1] - 3 && y <= s.max[1] + 3;
      const bool in = std::find(listed.begin(), listed.end(), t) != listed.end();
      EXPECT_EQ(in, t == own || near) << x << " " << y << " tile " << t;
      EXPECT_EQ(plan.holds(t, x, y), in);
    }
  }
  plan.add_point(50, 25); // tile 7 (column 2, row 1) alone owns points
  EXPECT_EQ(plan.number_of_points[7], 1u);
  EXPECT_EQ(plan.tiles_with_points(), std::vector<std::size_t>{7});
  EXPECT_EQ(plan.owner_of_location(50, 25), 7u);
  EXPECT_EQ(plan.owner_of_location(30, 5), 7u);    // tile 1, empty, next to 7
  EXPECT_EQ(plan.owner_of_location(5, 5), plan.number_of_tiles()); // tile 0: no neighbour owns points
}

TEST(Segmentation, RecognizeTileBadInput)
{
  const Whole_scan& w = whole_scan();
  const PSOR::Tile_plan plan = PSOR::plan_tiles(w.points, PSOR::parameters::tile_size(40.0));
  const std::size_t t = plan.tiles_with_points().front();
  std::vector<Point> held, foreign;
  for(const Point& p : w.points)
    (plan.holds(t, p.x(), p.y()) ? held : foreign).push_back(p);
  ASSERT_FALSE(foreign.empty());
  std::vector<Point> mixed = held;
  mixed.push_back(foreign.front());
  EXPECT_THROW(PSOR::recognize_tile(plan, t, mixed), Bad_input);                   // a point it does not hold
  EXPECT_THROW(PSOR::recognize_tile(plan, plan.number_of_tiles(), held), Bad_input); // not a tile of the plan
  EXPECT_THROW(PSOR::recognize_tile(plan, t, std::vector<Point>()), Bad_input);     // owns none
  PSOR::Tile_plan uncounted = plan;
  uncounted.number_of_points.clear();
  EXPECT_THROW(PSOR::recognize_tile(uncounted, t, held), Bad_input);
  std::vector<Point> nan = held;
  nan.emplace_back(held.front().x(), held.front().y(), std::nan(""));
  EXPECT_THROW(PSOR::recognize_tile(plan, t, nan), Bad_input);
  EXPECT_THROW(PSOR::plan_tiles(CGAL::Bbox_2(0, 0, std::nan(""), 1)), Bad_input);
  EXPECT_THROW(PSOR::plan_tiles(CGAL::Bbox_2(2, 0, 1, 1)), Bad_input); // empty box
  EXPECT_THROW(PSOR::plan_tiles(CGAL::Bbox_2(0, 0, 1, 1), PSOR::parameters::tile_size(0.0)), Bad_input);
  EXPECT_THROW(PSOR::plan_tiles(std::vector<Point>()), Bad_input);
}

} // namespace
