// Copyright (c) 2026 CGAL Global Shape Analysis contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later

// The features of candidate objects (extract_object_features.h) on shapes whose features are
// known: a pole, a bar, a box, apart from each other; invariance under a turn of the scene; bad
// input.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Point_set_object_recognition/extract_object_features.h>

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <limits>
#include <random>
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
  ASSERT_EQ(f.names.size(), 3u * 6u + 50u);
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
      const double tolerance = f.names[k].find("volume") != std::string::npos ? 0.1 * f.values[o][k] + 0.05 : 1e-6;
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

} // namespace
