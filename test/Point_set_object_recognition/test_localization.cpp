// Copyright (c) 2026 CGAL Global Shape Analysis contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later

// Localization (connected components, mean shift, height image, normalized cut) on scanned
// procedural streets (the objects' locations are known), and the evaluation of locations.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Point_set_3.h>

#include <Shape_analysis_support/Urban_scan.h>
#include <CGAL/Point_set_object_recognition/locate_objects.h>
#include <CGAL/Point_set_object_recognition/remove_background.h>

#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <map>
#include <vector>

namespace {

typedef CGAL::Exact_predicates_inexact_constructions_kernel Kernel;
typedef Kernel::Point_3 Point;
namespace PSOR = CGAL::Point_set_object_recognition;
namespace PSI = CGAL::Point_set_object_recognition::internal;
namespace SAS = CGAL::Shape_analysis_support;

PSOR::Object_location at(double x, double y)
{
  PSOR::Object_location l;
  l.position = {x, y, 0};
  return l;
}

TEST(Localization, EvaluationCountsLocationsAndObjectsWithinTheRadius)
{
  const std::vector<std::array<double, 2>> truth = {{0, 0}, {10, 0}, {20, 0}};
  // Two locations near the first object, one near the second, one far from all.
  const std::vector<PSOR::Object_location> found = {at(0.2, 0), at(-0.5, 0.5), at(10.9, 0), at(30, 0)};
  const auto e = PSOR::evaluate_locations(found, truth);
  EXPECT_EQ(e.correct_locations, 3u);
  EXPECT_EQ(e.found_objects, 2u);
  EXPECT_DOUBLE_EQ(e.precision, 0.75);
  EXPECT_DOUBLE_EQ(e.recall, 2.0 / 3.0);
  // A smaller radius: the location 0.9 m from the second object no longer counts.
  const auto f = PSOR::evaluate_locations(found, truth, 0.8);
  EXPECT_EQ(f.correct_locations, 2u);
  EXPECT_EQ(f.found_objects, 1u);
  EXPECT_EQ(PSOR::evaluate_locations(found, truth, 0.1).found_objects, 0u);
  EXPECT_DOUBLE_EQ(PSOR::evaluate_locations(std::vector<PSOR::Object_location>(), truth).precision, 1.0);
  EXPECT_DOUBLE_EQ(PSOR::evaluate_locations(std::vector<PSOR::Object_location>(), truth).recall, 0.0);
  EXPECT_THROW(PSOR::evaluate_locations(found, truth, 0.0), CGAL::Shape_analysis::Bad_input);
}

TEST(Localization, ClustersAreSizedAndFiltered)
{
  std::vector<Point> points;
  // A post: 100 points on a vertical segment 1 m high at (0, 0).
  for(int k = 0; k < 100; ++k)
    points.emplace_back(0.01 * (k % 3), 0, 0.01 * k);
  // A pole 20 m high at (10, 0): too high.
  for(int k = 0; k < 400; ++k)
    points.emplace_back(10, 0, 0.05 * k);
  // Five points at (20, 0): too small.
  for(int k = 0; k < 5; ++k)
    points.emplace_back(20, 0, 0.05 * k);
  const auto r = PSOR::locate_objects(points);
  EXPECT_EQ(r.number_of_clusters, 3u);
  ASSERT_EQ(r.locations.size(), 1u);
  EXPECT_NEAR(r.locations[0].position[0], 0.01, 0.005);
  EXPECT_NEAR(r.locations[0].position[2], 0.0, 1e-12);
  EXPECT_NEAR(r.locations[0].height, 0.99, 1e-9);
  EXPECT_EQ(r.locations[0].number_of_points, 100u);
  for(std::size_t i = 0; i < points.size(); ++i)
    EXPECT_EQ(r.location_of_point[i], i < 100 ? 0u : PSOR::Localization_result::no_location);
  EXPECT_EQ(PSOR::locate_objects(points, PSOR::parameters::maximum_cluster_height(25.0)).locations.size(), 2u);
  EXPECT_EQ(PSOR::locate_objects(points, PSOR::parameters::minimum_cluster_size(5)).locations.size(), 2u);
  // A larger spacing joins clusters: two posts 1 m apart (voxels touch, corners included, so
  // points up to about twice the spacing apart can be joined).
  std::vector<Point> two;
  for(int k = 0; k < 50; ++k) {
    two.emplace_back(0, 0, 0.02 * k);
    two.emplace_back(1.0, 0, 0.02 * k);
  }
  EXPECT_EQ(PSOR::locate_objects(two).locations.size(), 2u);
  EXPECT_EQ(PSOR::locate_objects(two, PSOR::parameters::component_spacing(0.6)).locations.size(), 1u);
  EXPECT_THROW(PSOR::locate_objects(two, PSOR::parameters::component_spacing(0.0)), CGAL::Shape_analysis::Bad_input);
  two.emplace_back(std::nan(""), 0, 0);
  EXPECT_THROW(PSOR::locate_objects(two), CGAL::Shape_analysis::Bad_input);
  EXPECT_TRUE(PSOR::locate_objects(std::vector<Point>()).locations.empty());
}

TEST(Localization, MeanShiftFindsTheModes)
{
  // Three posts: two 1 m apart (one mode at the 2 m radius, two at 0.5 m), one 10 m away.
  std::vector<Point> points;
  for(int k = 0; k < 60; ++k) {
    const double a = 0.4 * k;
    points.emplace_back(0.05 * std::cos(a), 0.05 * std::sin(a), 0.02 * k);
    points.emplace_back(1 + 0.05 * std::cos(a), 0.05 * std::sin(a), 0.02 * k);
    points.emplace_back(10 + 0.05 * std::cos(a), 0.05 * std::sin(a), 0.02 * k);
  }
  const auto ms = PSOR::parameters::localization_method(PSOR::Localization_method::MEAN_SHIFT);
  const auto r = PSOR::locate_objects(points, ms);
  ASSERT_EQ(r.locations.size(), 2u);
  EXPECT_NEAR(r.locations[0].position[0], 0.5, 0.05);
  EXPECT_EQ(r.locations[0].number_of_points, 120u);
  EXPECT_NEAR(r.locations[1].position[0], 10.0, 0.05);
  const auto fine = PSOR::locate_objects(points, PSOR::parameters::localization_method(PSOR::Localization_method::MEAN_SHIFT)
                                                   .mean_shift_radius(0.5));
  ASSERT_EQ(fine.locations.size(), 3u);
  EXPECT_NEAR(fine.locations[1].position[0], 1.0, 0.05);
  // The order of the points does not change the locations.
  std::vector<Point> reversed(points.rbegin(), points.rend());
  const auto back = PSOR::locate_objects(reversed, ms);
  ASSERT_EQ(back.locations.size(), 2u);
  EXPECT_NEAR(back.locations[0].position[0], r.locations[0].position[0], 1e-9);
  EXPECT_THROW(PSOR::locate_objects(points, PSOR::parameters::mean_shift_radius(-1.0)), CGAL::Shape_analysis::Bad_input);
}

// A scanned street, its foreground, and the true objects that received at least 10 points.
struct Located_street
{
  CGAL::Point_set_3<Point> foreground;
  std::vector<std::array<double, 2>> all, visible;
  double back_y = 0; // the back of the buildings
};

const Located_street& located_street()
{
  static const Located_street s = [] {
    Located_street r;
    SAS::Urban_scene_options o;
    o.seed = 11;
    o.street_length = 200;
    o.target_points = 500000;
    const SAS::Urban_scene scene = SAS::make_urban_scene(o);
    const SAS::Urban_scan scan = SAS::scan_urban_scene(scene, o);
    r.back_y = scene.back_y;
    std::vector<Point> points;
    std::map<int, std::size_t> scanned;
    for(const auto& p : scan.points) {
      points.emplace_back(p.x, p.y, p.z);
      if(p.instance > 0)
        ++scanned[p.instance];
    }
    for(std::size_t i : PSOR::remove_background(points).foreground)
      r.foreground.insert(points[i]);
    for(const auto& b : scene.objects) {
      r.all.push_back({b.x, b.y});
      if(scanned[b.id] >= 10)
        r.visible.push_back({b.x, b.y});
    }
    return r;
  }();
  return s;
}

TEST(Localization, ScannedStreetObjectsAreFound)
{
  const Located_street& s = located_street();
  const CGAL::Point_set_3<Point>& foreground = s.foreground;
  const std::vector<std::array<double, 2>>& truth = s.all;
  for(const auto method : {PSOR::Localization_method::CONNECTED_COMPONENTS, PSOR::Localization_method::MEAN_SHIFT}) {
    const auto r = PSOR::locate_objects(foreground, PSOR::parameters::localization_method(method));
    const auto e = PSOR::evaluate_locations(r.locations, truth);
    std::cout << (method == PSOR::Localization_method::MEAN_SHIFT ? "mean shift: " : "connected components: ")
              << r.locations.size() << " locations, " << truth.size() << " objects, precision "
              << e.precision << ", recall " << e.recall << "\n";
    // Mean shift (2 m) merges neighbours more often than 0.3 m voxels do.
    EXPECT_GT(e.recall, method == PSOR::Localization_method::MEAN_SHIFT ? 0.4 : 0.5);
    EXPECT_GT(e.precision, 0.4);
    // Every location lies on the sidewalks or the road, not inside the buildings.
    for(const auto& l : r.locations)
      EXPECT_LT(std::abs(l.position[1]), s.back_y) << l.position[0] << ' ' << l.position[1];
  }
}

TEST(Localization, NormalizedCutAndHeightImageFindTheObjects)
{
  const Located_street& s = located_street();
  ASSERT_GT(s.visible.size(), 40u);
  // Recall over the objects the scanner saw (10 points or more), precision over all objects
  // (trees are not objects: their locations count as wrong).
  for(const auto method : {PSOR::Localization_method::NORMALIZED_CUT, PSOR::Localization_method::HEIGHT_IMAGE}) {
    const auto r = PSOR::locate_objects(s.foreground, PSOR::parameters::localization_method(method));
    const auto recall = PSOR::evaluate_locations(r.locations, s.visible);
    const auto precision = PSOR::evaluate_locations(r.locations, s.all);
    const bool nc = method == PSOR::Localization_method::NORMALIZED_CUT;
    std::cout << (nc ? "normalized cut: " : "height image: ") << r.locations.size() << " locations, "
              << s.visible.size() << " visible objects, precision " << precision.precision << ", recall "
              << recall.recall << "\n";
    EXPECT_GT(recall.recall, nc ? 0.88 : 0.8);
    EXPECT_GT(precision.precision, nc ? 0.55 : 0.65);
    EXPECT_GT(r.number_of_clusters, r.locations.size());
    // Every point of a location's cluster lies within its cluster's extent of the location.
    std::vector<double> reach(r.locations.size(), 0.0);
    std::size_t k = 0;
    for(auto i : s.foreground) {
      const std::size_t l = r.location_of_point[k++];
      if(l == PSOR::Localization_result::no_location)
        continue;
      ASSERT_LT(l, r.locations.size());
      const Point& q = s.foreground.point(i);
      reach[l] = (std::max)(reach[l], std::hypot(q.x() - r.locations[l].position[0], q.y() - r.locations[l].position[1]));
      EXPECT_GE(q.z(), r.locations[l].position[2]);
    }
    for(double d : reach)
      EXPECT_LT(d, 12.0);
  }
}

TEST(Localization, SameLocationsForAnyNumberOfThreads)
{
  const Located_street& s = located_street();
  for(const auto method : {PSOR::Localization_method::NORMALIZED_CUT, PSOR::Localization_method::HEIGHT_IMAGE}) {
    const auto one = PSOR::locate_objects(s.foreground, PSOR::parameters::localization_method(method).number_of_threads(1));
    const auto two = PSOR::locate_objects(s.foreground, PSOR::parameters::localization_method(method).number_of_threads(2));
    const auto all = PSOR::locate_objects(s.foreground, PSOR::parameters::localization_method(method));
    ASSERT_EQ(one.locations.size(), two.locations.size());
    ASSERT_EQ(one.locations.size(), all.locations.size());
    for(std::size_t k = 0; k < one.locations.size(); ++k) {
      EXPECT_EQ(one.locations[k].position, two.locations[k].position);
      EXPECT_EQ(one.locations[k].position, all.locations[k].position);
      EXPECT_EQ(one.locations[k].number_of_points, two.locations[k].number_of_points);
    }
    EXPECT_EQ(one.location_of_point, two.location_of_point);
    EXPECT_EQ(one.location_of_point, all.location_of_point);
  }
}

// A post of `n` points on a vertical segment from z0 to z1 at (x, y) (a ring of radius 0.05).
void add_post(std::vector<Point>& points, double x, double y, double z0, double z1, int n)
{
  for(int k = 0; k < n; ++k) {
    const double a = 0.7 * k;
    points.emplace_back(x + 0.05 * std::cos(a), y + 0.05 * std::sin(a), z0 + (z1 - z0) * k / (n - 1));
  }
}

TEST(Localization, NormalizedCutJoinsPiecesAndSeparatesObjects)
{
  std::vector<Point> points;
  add_post(points, 0, 0, 0.2, 1.0, 60);  // a post seen in two pieces (a gap of 0.2 m)
  add_post(points, 0, 0, 1.2, 2.4, 80);
  add_post(points, 1.5, 0, 0.2, 1.2, 60); // a post 1.5 m away
  add_post(points, 9.0, 0, 0.2, 2.0, 90); // a lamp post at 9 m, its head 1.5 m aside at 6 m
  for(int k = 0; k < 40; ++k)
    points.emplace_back(10.5 + 0.01 * (k % 8), 0.01 * (k / 8), 6.0);
  const auto nc = PSOR::parameters::localization_method(PSOR::Localization_method::NORMALIZED_CUT);
  const auto r = PSOR::locate_objects(points, nc);
  ASSERT_EQ(r.locations.size(), 3u);
  EXPECT_NEAR(r.locations[0].position[0], 0.0, 0.05);
  EXPECT_EQ(r.locations[0].number_of_points, 140u);
  EXPECT_NEAR(r.locations[0].position[2], 0.2, 1e-9);
  EXPECT_NEAR(r.locations[1].position[0], 1.5, 0.05);
  EXPECT_NEAR(r.locations[2].position[0], 9.0, 0.05);
  // The head floats 4 m above the lamp post's foot: no location, its points in none.
  EXPECT_EQ(r.location_of_point.back(), PSOR::Localization_result::no_location);
  EXPECT_GE(r.number_of_clusters, 4u);
  // A threshold above any cut: every voxel of side 0.15 m is its own cluster (more locations).
  const auto apart = PSOR::locate_objects(points, nc.normalized_cut_threshold(1e6));
  EXPECT_GT(apart.locations.size(), 6u);
  EXPECT_GT(apart.number_of_clusters, r.number_of_clusters);
  // The height image sees the same three posts.
  const auto image = PSOR::locate_objects(
    points, PSOR::parameters::localization_method(PSOR::Localization_method::HEIGHT_IMAGE));
  ASSERT_EQ(image.locations.size(), 3u);
  EXPECT_NEAR(image.locations[0].position[0], 0.0, 0.1);
  EXPECT_NEAR(image.locations[1].position[0], 1.5, 0.1);
  EXPECT_NEAR(image.locations[2].position[0], 9.0, 0.1);
}

TEST(Localization, BadParametersAreRefused)
{
  std::vector<Point> points;
  add_post(points, 0, 0, 0.2, 1.0, 60);
  const auto nc = PSOR::parameters::localization_method(PSOR::Localization_method::NORMALIZED_CUT);
  const auto image = PSOR::parameters::localization_method(PSOR::Localization_method::HEIGHT_IMAGE);
  using CGAL::Shape_analysis::Bad_input;
  EXPECT_THROW(PSOR::locate_objects(points, nc.localization_cell_size(0.0)), Bad_input);
  EXPECT_THROW(PSOR::locate_objects(points, nc.localization_cell_size(-0.1)), Bad_input);
  EXPECT_THROW(PSOR::locate_objects(points, nc.normalized_cut_threshold(-1.0)), Bad_input);
  EXPECT_THROW(PSOR::locate_objects(points, nc.normalized_cut_threshold(std::nan(""))), Bad_input);
  EXPECT_THROW(PSOR::locate_objects(points, image.height_image_sigma(0.0)), Bad_input);
  EXPECT_THROW(PSOR::locate_objects(points, image.height_image_threshold(std::nan(""))), Bad_input);
  // A height image of more than 2e8 cells is refused (tiles are the answer).
  std::vector<Point> wide = points;
  wide.emplace_back(5000, 5000, 0);
  EXPECT_THROW(PSOR::locate_objects(wide, image.localization_cell_size(0.1)), Bad_input);
  points.emplace_back(0, std::nan(""), 0);
  EXPECT_THROW(PSOR::locate_objects(points, nc), Bad_input);
  EXPECT_THROW(PSOR::locate_objects(points, image), Bad_input);
  EXPECT_TRUE(PSOR::locate_objects(std::vector<Point>(), nc).locations.empty());
}

// The options come from one place: without named parameters, the struct's defaults; a named
// parameter given lands in its member.
TEST(Localization, OptionsFromNamedParameters)
{
  const PSOR::Locate_objects_options d;
  const PSOR::Locate_objects_options o = PSOR::locate_objects_options();
  EXPECT_EQ(o.localization_method, d.localization_method);
  EXPECT_EQ(o.mean_shift_radius, d.mean_shift_radius);
  EXPECT_EQ(o.component_spacing, d.component_spacing);
  EXPECT_EQ(o.localization_cell_size, d.localization_cell_size);
  EXPECT_EQ(o.normalized_cut_threshold, d.normalized_cut_threshold);
  EXPECT_EQ(o.height_image_sigma, d.height_image_sigma);
  EXPECT_EQ(o.height_image_threshold, d.height_image_threshold);
  EXPECT_EQ(o.number_of_threads, d.number_of_threads);
  EXPECT_EQ(o.minimum_cluster_size, d.minimum_cluster_size);
  EXPECT_EQ(o.maximum_cluster_height, d.maximum_cluster_height);
  const PSOR::Locate_objects_options g = PSOR::locate_objects_options(
    PSOR::parameters::maximum_cluster_height(7.5).localization_method(PSOR::Localization_method::MEAN_SHIFT));
  EXPECT_EQ(g.maximum_cluster_height, 7.5);
  EXPECT_EQ(g.localization_method, PSOR::Localization_method::MEAN_SHIFT);
  EXPECT_EQ(g.component_spacing, d.component_spacing);
}

} // namespace
