// Copyright (c) 2026 CGAL Global Shape Analysis contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later

// Background removal on scanned procedural streets whose points know what they are: the ground
// goes, buildings go, isolated points go, the small objects stay.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Point_set_3.h>
#include <CGAL/Point_set_3/IO/PLY.h>

#include <Shape_analysis_support/Urban_scan.h>
#include <CGAL/Point_set_object_recognition/locate_objects.h>
#include <CGAL/Point_set_object_recognition/remove_background.h>
#include <CGAL/Shape_analysis/internal/Random.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <map>
#include <vector>

namespace {

typedef CGAL::Exact_predicates_inexact_constructions_kernel Kernel;
typedef Kernel::Point_3 Point;
namespace PSOR = CGAL::Point_set_object_recognition;
namespace PSI = CGAL::Point_set_object_recognition::internal;
namespace SAS = CGAL::Shape_analysis_support;
using PSOR::Point_kind;

struct Scanned
{
  SAS::Urban_scene scene;
  SAS::Urban_scan scan;
  std::vector<Point> points;
};

const Scanned& street()
{
  static const Scanned s = [] {
    Scanned r;
    SAS::Urban_scene_options o;
    o.seed = 7;
    o.street_length = 150;
    o.target_points = 300000;
    r.scene = SAS::make_urban_scene(o);
    r.scan = SAS::scan_urban_scene(r.scene, o);
    for(const auto& p : r.scan.points)
      r.points.emplace_back(p.x, p.y, p.z);
    return r;
  }();
  return s;
}

TEST(BackgroundRemoval, GroundBuildingsGoObjectsStay)
{
  const Scanned& s = street();
  const auto r = PSOR::remove_background(s.points);
  ASSERT_EQ(r.kind.size(), s.points.size());
  std::size_t ground = 0, ground_removed = 0, building = 0, building_removed = 0, high_object = 0,
              high_object_ground = 0, object = 0, object_kept = 0;
  std::map<int, std::pair<std::size_t, std::size_t>> per_object; // id -> (points, kept)
  for(std::size_t i = 0; i < s.points.size(); ++i) {
    const auto& p = s.scan.points[i];
    const bool kept = r.kind[i] == Point_kind::FOREGROUND;
    if(p.label == SAS::GROUND) {
      ++ground;
      ground_removed += kept ? 0 : 1;
    } else if(p.label == SAS::BUILDING) {
      ++building;
      building_removed += kept ? 0 : 1;
    } else if(p.instance > 0) {
      ++object;
      object_kept += kept ? 1 : 0;
      if(p.z - s.scene.ground_height(p.x, p.y) > 0.3) {
        ++high_object;
        high_object_ground += r.kind[i] == Point_kind::GROUND ? 1 : 0;
      }
      auto& po = per_object[p.instance];
      ++po.first;
      po.second += kept ? 1 : 0;
    }
  }
  ASSERT_GT(ground, 10000u);
  ASSERT_GT(building, 10000u);
  ASSERT_GT(object, 2000u);
  EXPECT_GT(double(ground_removed), 0.99 * double(ground));
  EXPECT_GT(double(building_removed), 0.9 * double(building));
  // The estimated ground is the real one: object points well above it are not taken for it.
  EXPECT_LT(double(high_object_ground), 0.01 * double(high_object));
  EXPECT_GT(double(object_kept), 0.6 * double(object));
  std::size_t objects_found = 0;
  for(const auto& kv : per_object)
    objects_found += 2 * kv.second.second >= kv.second.first ? 1 : 0;
  EXPECT_GT(double(objects_found), 0.7 * double(per_object.size()));
  // The ground grid follows the terrain (road and sidewalks) within a few centimetres where it
  // was seen.
  for(double x = 10; x < 140; x += 7)
    for(double y : {-8.0, -3.0, 0.0, 3.0, 8.0})
      EXPECT_LT(std::abs(r.ground.height(x, y) - s.scene.ground_height(x, y)), 0.15) << x << ' ' << y;
  EXPECT_EQ(r.foreground.size(), std::size_t(std::count(r.kind.begin(), r.kind.end(), Point_kind::FOREGROUND)));
  EXPECT_EQ(r.number_of_ground_points + r.number_of_isolated_points + r.number_of_large_component_points +
              r.foreground.size(), s.points.size());
}

TEST(BackgroundRemoval, ObjectsAgainstWallsStay)
{
  // On the street: the objects standing against a facade (newspaper boxes, mailing boxes...)
  // keep most of their points; the facades go.
  const Scanned& s = street();
  const auto r = PSOR::remove_background(s.points);
  std::map<int, std::pair<std::size_t, std::size_t>> per_object; // id -> (points, kept)
  for(std::size_t i = 0; i < s.points.size(); ++i) {
    const auto& p = s.scan.points[i];
    if(p.instance <= 0)
      continue;
    const auto& b = s.scene.objects[std::size_t(p.instance - 1)].bbox;
    if((std::max)(std::abs(b.ymin()), std::abs(b.ymax())) < s.scene.facade_y - 0.05)
      continue;
    auto& po = per_object[p.instance];
    ++po.first;
    po.second += r.kind[i] == Point_kind::FOREGROUND ? 1 : 0;
  }
  ASSERT_GE(per_object.size(), 5u);
  std::size_t kept_half = 0;
  for(const auto& kv : per_object)
    kept_half += 2 * kv.second.second >= kv.second.first ? 1 : 0;
  EXPECT_GT(double(kept_half), 0.6 * double(per_object.size())) << kept_half << " of " << per_object.size();

  // A box of 0.5 x 0.5 x 1.2 m against a wall 8 m high and 30 m long, on flat ground.
  std::vector<Point> points;
  for(double x = 0; x <= 30; x += 0.05)
    for(double y = 0; y <= 10; y += 0.1)
      points.emplace_back(x, y, 0);
  for(double x = 0; x <= 30; x += 0.05)
    for(double z = 0.05; z <= 8; z += 0.05)
      points.emplace_back(x, 10, z);
  const std::size_t box = points.size();
  for(double x = 14.75; x <= 15.25; x += 0.03)
    for(double z = 0.05; z <= 1.2; z += 0.03)
      points.emplace_back(x, 9.5, z); // its front face
  for(double x = 14.75; x <= 15.25; x += 0.03)
    for(double y = 9.5; y < 10; y += 0.03)
      points.emplace_back(x, y, 1.2); // its top
  const auto w = PSOR::remove_background(points);
  std::size_t wall = 0, wall_kept = 0, box_kept = 0, box_high = 0;
  for(std::size_t i = 0; i < points.size(); ++i) {
    const bool kept = w.kind[i] == Point_kind::FOREGROUND;
    if(i >= box) {
      box_high += points[i].z() > 0.3 ? 1 : 0;
      box_kept += kept && points[i].z() > 0.3 ? 1 : 0;
    } else if(points[i].y() == 10 && points[i].z() > 0.3) {
      ++wall;
      wall_kept += kept ? 1 : 0;
    }
  }
  EXPECT_GT(double(box_kept), 0.8 * double(box_high));
  EXPECT_LT(double(wall_kept), 0.01 * double(wall));
}

TEST(BackgroundRemoval, IsolatedPointsGo)
{
  std::vector<Point> points = street().points;
  const std::size_t n = points.size();
  CGAL::Shape_analysis::internal::Random_stream rng(3, 0);
  for(int k = 0; k < 300; ++k) // alone in the air above the road
    points.emplace_back(rng.uniform(5, 145), rng.uniform(-4, 4), rng.uniform(15, 40));
  const auto r = PSOR::remove_background(points);
  for(std::size_t i = n; i < points.size(); ++i)
    EXPECT_EQ(r.kind[i], Point_kind::ISOLATED) << i;
  // Without the rule, they stay.
  const auto r0 = PSOR::remove_background(points, PSOR::parameters::minimum_neighbors(0));
  std::size_t kept = 0;
  for(std::size_t i = n; i < points.size(); ++i)
    kept += r0.kind[i] == Point_kind::FOREGROUND ? 1 : 0;
  EXPECT_GT(kept, 250u);
}

TEST(BackgroundRemoval, OrderOfThePointsDoesNotMatter)
{
  const std::vector<Point>& points = street().points;
  std::vector<std::size_t> perm(points.size());
  for(std::size_t i = 0; i < perm.size(); ++i)
    perm[i] = (i * 7919) % perm.size(); // 7919 is prime and does not divide the size
  ASSERT_NE(points.size() % 7919, 0u);
  std::vector<Point> shuffled;
  for(std::size_t i : perm)
    shuffled.push_back(points[i]);
  const auto a = PSOR::remove_background(points), b = PSOR::remove_background(shuffled);
  std::size_t differ = 0;
  for(std::size_t k = 0; k < perm.size(); ++k)
    differ += a.kind[perm[k]] != b.kind[k] ? 1 : 0;
  EXPECT_LE(differ, points.size() / 10000);
}

TEST(BackgroundRemoval, PointSetAndParameters)
{
  const Scanned& s = street();
  CGAL::Point_set_3<Point> ps;
  for(const Point& p : s.points)
    ps.insert(p);
  const auto a = PSOR::remove_background(ps), b = PSOR::remove_background(s.points);
  EXPECT_EQ(a.kind, b.kind);
  // A point map: the points of (point, index) pairs.
  std::vector<std::pair<Point, int>> pairs;
  for(const Point& p : s.points)
    pairs.emplace_back(p, 0);
  const auto c = PSOR::remove_background(
    pairs, PSOR::parameters::point_map(CGAL::First_of_pair_property_map<std::pair<Point, int>>()));
  EXPECT_EQ(c.kind, b.kind);
  // A larger extent keeps more (the smaller buildings); a larger threshold takes more as ground.
  const auto wide = PSOR::remove_background(s.points, PSOR::parameters::maximum_component_extent(1000.0));
  EXPECT_LT(wide.number_of_large_component_points, b.number_of_large_component_points);
  const auto high = PSOR::remove_background(s.points, PSOR::parameters::ground_threshold(1.0));
  EXPECT_GT(high.number_of_ground_points, b.number_of_ground_points);
}

TEST(BackgroundRemoval, CgalAirborneScan)
{
  // CGAL's b9_training.ply: an airborne scan of 91 x 112 m (georeferenced, heights 73-97 m) with
  // some points labelled ground (0), vegetation (1) and roof (2).
  const std::string file = std::string(SHAPE_ANALYSIS_DATA_DIR) + "/b9_training.ply";
  if(!std::filesystem::exists(file))
    GTEST_SKIP() << file << " is missing";
  CGAL::Point_set_3<Point> ps;
  std::ifstream in(file, std::ios::binary);
  ASSERT_TRUE(CGAL::IO::read_PLY(in, ps));
  ASSERT_EQ(ps.size(), 22300u);
  auto label = ps.property_map<int>("label");
  ASSERT_TRUE(label.second);
  // Roofs are wide: the smallest building here is wider than 6 m. The airborne points are
  // sparser than the mobile ones: larger voxels.
  const auto r = PSOR::remove_background(ps, PSOR::parameters::maximum_component_extent(6.0)
                                               .isolation_radius(1.0)
                                               .component_spacing(1.0));
  std::size_t ground = 0, ground_ok = 0, roof = 0, roof_removed = 0, roof_ground = 0;
  std::size_t k = 0;
  for(auto i : ps) {
    const int l = label.first[i];
    if(l == 0) {
      ++ground;
      ground_ok += r.kind[k] == Point_kind::GROUND ? 1 : 0;
    } else if(l == 2) {
      ++roof;
      roof_removed += r.kind[k] == Point_kind::FOREGROUND ? 0 : 1;
      roof_ground += r.kind[k] == Point_kind::GROUND ? 1 : 0;
    }
    ++k;
  }
  ASSERT_GT(ground, 1000u);
  ASSERT_GT(roof, 500u);
  EXPECT_GT(double(ground_ok), 0.95 * double(ground));
  EXPECT_GT(double(roof_removed), 0.9 * double(roof));
  EXPECT_LT(roof_ground, roof / 100); // roofs are metres above the ground
}

TEST(BackgroundRemoval, BadInput)
{
  using CGAL::Shape_analysis::Bad_input;
  std::vector<Point> points = {Point(0, 0, 0), Point(1, 0, 0), Point(0, 1, 0)};
  EXPECT_NO_THROW(PSOR::remove_background(std::vector<Point>()));
  EXPECT_THROW(PSOR::remove_background(points, PSOR::parameters::ground_cell_size(0.0)), Bad_input);
  EXPECT_THROW(PSOR::remove_background(points, PSOR::parameters::isolation_radius(-1.0)), Bad_input);
  EXPECT_THROW(PSOR::remove_background(points, PSOR::parameters::maximum_component_extent(std::nan(""))), Bad_input);
  points.emplace_back(std::nan(""), 0, 0);
  EXPECT_THROW(PSOR::remove_background(points), Bad_input);
  // A grid too fine for the extent of the scene: refused, not an allocation failure.
  std::vector<Point> far = {Point(0, 0, 0), Point(1e7, 0, 0)};
  EXPECT_THROW(PSOR::remove_background(far, PSOR::parameters::isolation_radius(0.001)), Bad_input);
}

// The options come from one place: without named parameters, the struct's defaults; a named
// parameter given lands in its member.
TEST(BackgroundRemoval, OptionsFromNamedParameters)
{
  const PSOR::Remove_background_options d;
  const PSOR::Remove_background_options o = PSOR::remove_background_options();
  EXPECT_EQ(o.ground_cell_size, d.ground_cell_size);
  EXPECT_EQ(o.ground_threshold, d.ground_threshold);
  EXPECT_EQ(o.isolation_radius, d.isolation_radius);
  EXPECT_EQ(o.minimum_neighbors, d.minimum_neighbors);
  EXPECT_EQ(o.component_spacing, d.component_spacing);
  EXPECT_EQ(o.maximum_component_extent, d.maximum_component_extent);
  const PSOR::Remove_background_options g =
    PSOR::remove_background_options(PSOR::parameters::component_spacing(0.75).minimum_neighbors(7));
  EXPECT_EQ(g.component_spacing, 0.75);
  EXPECT_EQ(g.minimum_neighbors, 7u);
  EXPECT_EQ(g.ground_cell_size, d.ground_cell_size);
  // Two parameters of the same name, each with its function's default.
  EXPECT_NE(d.component_spacing, PSOR::Locate_objects_options().component_spacing);
}

} // namespace
