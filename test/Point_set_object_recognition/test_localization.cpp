// Copyright (c) 2026 CGAL Global Shape Analysis contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later

// Localization by connected components on scanned procedural streets (the objects' locations are
// known), and the one-to-one evaluation of locations.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Point_set_3.h>

#include <CGAL/Point_set_object_recognition/internal/Urban_scene.h>
#include <CGAL/Point_set_object_recognition/locate_objects.h>
#include <CGAL/Point_set_object_recognition/remove_background.h>

#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <vector>

namespace {

typedef CGAL::Exact_predicates_inexact_constructions_kernel Kernel;
typedef Kernel::Point_3 Point;
namespace PSOR = CGAL::Point_set_object_recognition;
namespace PSI = CGAL::Point_set_object_recognition::internal;

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

TEST(Localization, ScannedStreetObjectsAreFound)
{
  PSI::Urban_scene_options o;
  o.seed = 11;
  o.street_length = 200;
  o.target_points = 500000;
  const PSI::Urban_scene scene = PSI::make_urban_scene(o);
  const PSI::Urban_scan scan = PSI::scan_urban_scene(scene, o);
  std::vector<Point> points;
  for(const auto& p : scan.points)
    points.emplace_back(p.x, p.y, p.z);
  const auto background = PSOR::remove_background(points);
  CGAL::Point_set_3<Point> foreground;
  for(std::size_t i : background.foreground)
    foreground.insert(points[i]);
  std::vector<std::array<double, 2>> truth;
  for(const auto& b : scene.objects)
    truth.push_back({b.x, b.y});
  for(const auto method : {PSOR::Localization_method::CONNECTED_COMPONENTS, PSOR::Localization_method::MEAN_SHIFT}) {
    const auto r = PSOR::locate_objects(foreground, PSOR::parameters::localization_method(method));
    const auto e = PSOR::evaluate_locations(r.locations, truth);
    std::cout << (method == PSOR::Localization_method::MEAN_SHIFT ? "mean shift: " : "connected components: ")
              << r.locations.size() << " locations, " << scene.objects.size() << " objects, precision "
              << e.precision << ", recall " << e.recall << "\n";
    // Mean shift (2 m) merges neighbours more often than 0.3 m voxels do.
    EXPECT_GT(e.recall, method == PSOR::Localization_method::MEAN_SHIFT ? 0.4 : 0.5);
    EXPECT_GT(e.precision, 0.4);
    // Every location lies on the sidewalks or the road, not inside the buildings.
    for(const auto& l : r.locations)
      EXPECT_LT(std::abs(l.position[1]), scene.back_y) << l.position[0] << ' ' << l.position[1];
  }
}

} // namespace
