// Tests of the street maps and context features of CGAL::Point_set_object_recognition: UTM
// EPSG codes; the nearest street against brute force, from several threads; a generated street
// scene written as OpenStreetMap (XML, gzip, PBF) and read back into the scan's frame, north and
// south; bad maps refused with Bad_input (not OSM, no street, missing file, not UTM, elsewhere);
// the class autocorrelation grids on patterns with a known answer, invariant under a move of the
// scene, with and without a map; their save/load.

#include <CGAL/Point_set_object_recognition/Object_context.h>
#include <CGAL/Point_set_object_recognition/read_street_map.h>

#include <Shape_analysis_support/Urban_osm.h>
#include <Shape_analysis_support/Urban_scene.h>

#include <osmium/io/gzip_compression.hpp>
#include <osmium/io/pbf_output.hpp>
#include <osmium/io/reader.hpp>
#include <osmium/io/writer.hpp>
#include <osmium/io/xml_input.hpp>
#include <osmium/io/xml_output.hpp>

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <limits>
#include <random>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

namespace {

namespace PR = CGAL::Point_set_object_recognition;
namespace SAS = CGAL::Shape_analysis_support;
using CGAL::Shape_analysis::Bad_input;
typedef std::array<double, 2> P2;

// The message of the Bad_input that f throws ("" if none).
std::string bad_input_message(const std::function<void()>& f)
{
  try {
    f();
  } catch(const Bad_input& e) {
    return e.what();
  }
  return "";
}

bool contains(const std::string& s, const std::string& part) { return s.find(part) != std::string::npos; }

// ---------------------------------------------------------------------------------------------
// CRS

TEST(UtmCrs, AcceptsTheUtmCodesOfWgs84)
{
  const PR::Utm_zone a = PR::parse_utm_crs("EPSG:32618");
  EXPECT_EQ(a.zone, 18);
  EXPECT_TRUE(a.north);
  const PR::Utm_zone b = PR::parse_utm_crs("epsg:32718");
  EXPECT_EQ(b.zone, 18);
  EXPECT_FALSE(b.north);
  EXPECT_EQ(PR::parse_utm_crs("32601").zone, 1);
  const PR::Utm_zone c = PR::parse_utm_crs(" EPSG:32760 ");
  EXPECT_EQ(c.zone, 60);
  EXPECT_FALSE(c.north);
}

TEST(UtmCrs, RefusesOtherCodesSayingWhatIsAccepted)
{
  for(const char* crs : {"EPSG:4326", "EPSG:32661", "EPSG:32761", "EPSG:32600", "EPSG:32700", "UTM18", "",
                         "EPSG:326180", "EPSG:3857", "EPSG:3261", "EPSG:32618x", "EPSG:-3261"}) {
    const std::string m = bad_input_message([&] { PR::parse_utm_crs(crs); });
    EXPECT_TRUE(contains(m, "EPSG:326zz") && contains(m, "EPSG:327zz")) << crs << ": " << m;
  }
}

// ---------------------------------------------------------------------------------------------
// Street_map

double brute_force_distance(const std::vector<PR::Street_map::Street>& streets, double x, double y)
{
  double best = std::numeric_limits<double>::infinity();
  for(const PR::Street_map::Street& s : streets)
    for(std::size_t i = 0; i + 1 < s.points.size(); ++i) {
      const P2 a = s.points[i], b = s.points[i + 1];
      const double dx = b[0] - a[0], dy = b[1] - a[1], l2 = dx * dx + dy * dy;
      const double t = l2 == 0 ? 0 : std::clamp(((x - a[0]) * dx + (y - a[1]) * dy) / l2, 0.0, 1.0);
      best = std::min(best, std::hypot(a[0] + t * dx - x, a[1] + t * dy - y));
    }
  return best;
}

// Random polylines in [0, 2000] x [0, 1000]: short wiggly streets and a few long straight ones.
std::vector<PR::Street_map::Street> random_streets(unsigned seed)
{
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(0, 1);
  std::vector<PR::Street_map::Street> streets;
  for(int s = 0; s < 60; ++s) {
    PR::Street_map::Street st;
    P2 p{{2000 * u(rng), 1000 * u(rng)}};
    const int n = s < 5 ? 2 : 2 + int(20 * u(rng));
    const double step = s < 5 ? 1500 : 5 + 40 * u(rng);
    double heading = 6.3 * u(rng);
    for(int i = 0; i < n; ++i) {
      st.points.push_back(p);
      if(i == 3)
        st.points.push_back(p); // a repeated point: a segment of length 0
      heading += 0.6 * (u(rng) - 0.5);
      p = {{p[0] + step * std::cos(heading), p[1] + step * std::sin(heading)}};
    }
    streets.push_back(st);
  }
  return streets;
}

TEST(StreetMap, NearestStreetIsExactNearAndFar)
{
  const std::vector<PR::Street_map::Street> streets = random_streets(3);
  const PR::Street_map map(streets);
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> near_x(-200, 2200), near_y(-200, 1200), far(-1e5, 1e5);
  for(int q = 0; q < 3000; ++q) {
    const double x = q % 10 == 0 ? far(rng) : near_x(rng), y = q % 10 == 0 ? far(rng) : near_y(rng);
    const PR::Street_point s = map.nearest(x, y);
    ASSERT_NEAR(s.distance, brute_force_distance(streets, x, y), 1e-9 * (1 + s.distance)) << x << " " << y;
    EXPECT_NEAR(std::hypot(s.point[0] - x, s.point[1] - y), s.distance, 1e-9 * (1 + s.distance));
    EXPECT_NEAR(std::hypot(s.direction[0], s.direction[1]), 1, 1e-12);
    // The nearest point lies on the street it names.
    EXPECT_NEAR(brute_force_distance({streets[s.street]}, s.point[0], s.point[1]), 0, 1e-9);
  }
}

TEST(StreetMap, DirectionFollowsTheStreetAndTheMapIsCopyable)
{
  PR::Street_map::Street l;
  l.points = {{{0, 0}}, {{100, 0}}, {{100, 50}}};
  l.highway = "residential";
  const PR::Street_map original({l});
  const PR::Street_map map = original; // copies are independent and answer the same
  EXPECT_EQ(map.number_of_segments(), 2u);
  const PR::Street_point a = map.nearest(40, -3);
  EXPECT_DOUBLE_EQ(a.distance, 3);
  EXPECT_DOUBLE_EQ(a.direction[0], 1);
  EXPECT_DOUBLE_EQ(a.point[0], 40);
  const PR::Street_point b = map.nearest(97, 30);
  EXPECT_DOUBLE_EQ(b.distance, 3);
  EXPECT_DOUBLE_EQ(b.direction[1], 1);
  EXPECT_EQ(map.streets()[b.street].highway, "residential");
  EXPECT_TRUE(std::isinf(PR::Street_map().distance(0, 0)));
  EXPECT_TRUE(PR::Street_map().empty());
  EXPECT_FALSE(bad_input_message([&] { map.distance(std::nan(""), 0); }).empty());
}

TEST(StreetMap, QueriesFromSeveralThreadsAgree)
{
  const PR::Street_map map(random_streets(5));
  std::vector<P2> queries;
  std::mt19937 rng(2);
  std::uniform_real_distribution<double> u(-300, 2300);
  for(int i = 0; i < 20000; ++i)
    queries.push_back({{u(rng), u(rng) / 2}});
  std::vector<double> sequential(queries.size()), parallel(queries.size());
  for(std::size_t i = 0; i < queries.size(); ++i)
    sequential[i] = map.distance(queries[i][0], queries[i][1]);
  std::vector<std::thread> threads;
  for(std::size_t t = 0; t < 4; ++t)
    threads.emplace_back([&, t] {
      for(std::size_t i = t; i < queries.size(); i += 4)
        parallel[i] = map.distance(queries[i][0], queries[i][1]);
    });
  for(std::thread& t : threads)
    t.join();
  EXPECT_EQ(sequential, parallel);
}

TEST(StreetMap, RefusesBadStreetsAndChecksOverlap)
{
  PR::Street_map::Street one;
  one.points = {{{0, 0}}};
  EXPECT_FALSE(bad_input_message([&] { PR::Street_map m({one}); }).empty());
  PR::Street_map::Street nan;
  nan.points = {{{0, 0}}, {{std::nan(""), 1}}};
  EXPECT_FALSE(bad_input_message([&] { PR::Street_map m({nan}); }).empty());

  PR::Street_map::Street l;
  l.points = {{{0, 0}}, {{100, 100}}};
  const PR::Street_map map({l});
  EXPECT_NO_THROW(PR::check_street_map_overlap(map, CGAL::Bbox_2(40, 42, 45, 50), 0));    // crossed
  EXPECT_NO_THROW(PR::check_street_map_overlap(map, CGAL::Bbox_2(150, 0, 200, 20), 100)); // within the margin
  const std::string m = bad_input_message([&] { PR::check_street_map_overlap(map, CGAL::Bbox_2(5000, 0, 5200, 20), 100); });
  EXPECT_TRUE(contains(m, "does not overlap the scan")) << m;
  EXPECT_FALSE(bad_input_message([&] { PR::check_street_map_overlap(PR::Street_map(), CGAL::Bbox_2(0, 0, 1, 1)); }).empty());
  EXPECT_FALSE(bad_input_message([&] { PR::check_street_map_overlap(map, CGAL::Bbox_2(0, 0, 1, 1), -1); }).empty());
}

// ---------------------------------------------------------------------------------------------
// OpenStreetMap files

// A scratch directory under the build directory (the tests' working directory), removed at the end.
class OsmFiles : public ::testing::Test
{
protected:
  void SetUp() override
  {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    dir = std::filesystem::current_path() / (std::string("street_map_test_") + info->name());
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
  }
  void TearDown() override { std::filesystem::remove_all(dir); }
  std::string path(const std::string& name) const { return (dir / name).string(); }
  std::string write(const std::string& name, const std::string& text) const
  {
    std::ofstream(path(name)) << text;
    return path(name);
  }
  std::filesystem::path dir;
};

const SAS::Urban_scene& scene()
{
  static const SAS::Urban_scene s = [] {
    SAS::Urban_scene_options o;
    o.seed = 4;
    o.street_length = 200;
    return SAS::make_urban_scene(o);
  }();
  return s;
}

// The street lies at y = 0 from x = -30 to 230, the cross streets at x = -30 and x = 230.
void expect_scene_streets(const PR::Street_map& map, const std::array<double, 2>& shift = {{0, 0}})
{
  for(double x : {0.0, 37.5, 100.0, 163.2, 199.0}) {
    const PR::Street_point s = map.nearest(x - shift[0], 3 - shift[1]);
    EXPECT_NEAR(s.distance, 3, 0.05) << x;
    EXPECT_GT(std::abs(s.direction[0]), 0.9999) << x;
    EXPECT_NEAR(map.distance(x - shift[0], -6.5 - shift[1]), 6.5, 0.05) << x; // footways are not streets
  }
  EXPECT_NEAR(map.distance(-30 - shift[0], 50 - shift[1]), 0, 0.05);
  EXPECT_GT(std::abs(map.direction(230 - shift[0], -50 - shift[1])[1]), 0.9999);
}

TEST_F(OsmFiles, GeneratedSceneComesBackAtItsPlaceNorthAndSouth)
{
  // New York (zone 18 north), then Sydney (zone 56 south).
  const std::array<double, 2> ny{{585000, 4511000}}, sydney{{334000, 6252000}};
  SAS::write_street_osm(path("ny.osm"), scene(), 18, true, ny);
  SAS::write_street_osm(path("sydney.osm"), scene(), 56, false, sydney);
  PR::Street_map_read_statistics stats;
  const PR::Street_map map = PR::read_street_map(path("ny.osm"), "EPSG:32618", {{ny[0], ny[1], 12.}}, false, &stats);
  EXPECT_EQ(map.streets().size(), 3u);
  EXPECT_EQ(stats.highway_ways, 5u);
  EXPECT_EQ(stats.path_ways, 2u);
  EXPECT_EQ(stats.ways, 5 + scene().buildings.size());
  EXPECT_EQ(map.streets()[0].highway, "residential");
  expect_scene_streets(map);
  // Another local origin moves the streets by the difference.
  expect_scene_streets(PR::read_street_map(path("ny.osm"), "epsg:32618", {{ny[0] - 100, ny[1] + 40, 0}}),
                       {{-100, 40}});
  expect_scene_streets(PR::read_street_map(path("sydney.osm"), "EPSG:32756", {{sydney[0], sydney[1], 0}}));
  // Footways kept on request.
  const PR::Street_map all = PR::read_street_map(path("ny.osm"), "EPSG:32618", {{ny[0], ny[1], 0}}, true);
  EXPECT_EQ(all.streets().size(), 5u);
  EXPECT_NEAR(all.distance(50, 7.75), 0, 0.05);
  // The scene's box overlaps its map; the true objects are at their |y| from the street.
  CGAL::Bbox_2 box;
  for(const SAS::Urban_object& o : scene().objects)
    box += CGAL::Bbox_2(o.x, o.y, o.x, o.y);
  EXPECT_NO_THROW(PR::check_street_map_overlap(map, box));
  for(const SAS::Urban_object& o : scene().objects)
    EXPECT_NEAR(map.distance(o.x, o.y), std::abs(o.y), 0.05) << o.id;
}

TEST_F(OsmFiles, CompressedAndPbfFilesAreRead)
{
  const std::array<double, 2> offset{{500000, 5000000}};
  SAS::write_street_osm(path("scene.osm"), scene(), 32, true, offset);
  for(const char* name : {"scene.osm.gz", "scene.osm.pbf"}) {
    osmium::io::Reader reader(path("scene.osm"));
    osmium::io::Writer writer(path(name));
    while(osmium::memory::Buffer buffer = reader.read())
      writer(std::move(buffer));
    writer.close();
    reader.close();
    expect_scene_streets(PR::read_street_map(path(name), "EPSG:32632", {{offset[0], offset[1], 0}}));
  }
}

TEST_F(OsmFiles, BadMapsAreRefusedClearly)
{
  const std::array<double, 3> origin{{585000, 4511000, 0}};
  const auto message = [&](const std::string& file, const std::string& crs = "EPSG:32618") {
    return bad_input_message([&] { PR::read_street_map(file, crs, origin); });
  };
  std::string m = message(path("missing.osm"));
  EXPECT_TRUE(contains(m, "missing.osm") && contains(m, "cannot open")) << m;
  m = message(write("text.osm", "this is not a map\n"));
  EXPECT_TRUE(contains(m, "text.osm") && contains(m, "not an OpenStreetMap file")) << m;
  m = message(write("page.osm", "<?xml version='1.0'?>\n<html><body>a page</body></html>\n"));
  EXPECT_TRUE(contains(m, "page.osm") && contains(m, "not an OpenStreetMap file")) << m;
  m = message(write("empty.osm", ""));
  EXPECT_TRUE(contains(m, "empty.osm")) << m;
  m = message(write("garbage.osm.pbf", "not protocol buffers at all"));
  EXPECT_TRUE(contains(m, "garbage.osm.pbf") && contains(m, "not an OpenStreetMap file")) << m;
  const std::string head = "<?xml version='1.0'?>\n<osm version=\"0.6\">\n"
                           "<node id=\"1\" version=\"1\" lat=\"40.7\" lon=\"-74.0\"/>\n"
                           "<node id=\"2\" version=\"1\" lat=\"40.7001\" lon=\"-74.0\"/>\n"
                           "<node id=\"3\" version=\"1\" lat=\"40.7001\" lon=\"-74.0001\"/>\n";
  m = message(write("buildings.osm", head + "<way id=\"1\" version=\"1\"><nd ref=\"1\"/><nd ref=\"2\"/><nd ref=\"3\"/>"
                                            "<nd ref=\"1\"/><tag k=\"building\" v=\"yes\"/></way>\n</osm>\n"));
  EXPECT_TRUE(contains(m, "buildings.osm") && contains(m, "no street")) << m;
  m = message(write("paths.osm", head + "<way id=\"1\" version=\"1\"><nd ref=\"1\"/><nd ref=\"2\"/>"
                                        "<tag k=\"highway\" v=\"footway\"/></way>\n</osm>\n"));
  EXPECT_TRUE(contains(m, "no street") && contains(m, "1 paths")) << m;
  m = message(write("lost.osm", head + "<way id=\"1\" version=\"1\"><nd ref=\"1\"/><nd ref=\"8\"/><nd ref=\"2\"/>"
                                       "<nd ref=\"9\"/><tag k=\"highway\" v=\"primary\"/></way>\n</osm>\n"));
  EXPECT_TRUE(contains(m, "no street") && contains(m, "1 without two consecutive nodes")) << m;
  // A way cut by the extract keeps its runs of consecutive nodes.
  PR::Street_map_read_statistics stats;
  const PR::Street_map cut = PR::read_street_map(
      write("cut.osm", head + "<way id=\"1\" version=\"1\"><nd ref=\"7\"/><nd ref=\"1\"/><nd ref=\"2\"/><nd ref=\"8\"/>"
                              "<nd ref=\"3\"/><tag k=\"highway\" v=\"primary\"/></way>\n</osm>\n"),
      "EPSG:32618", origin, false, &stats);
  EXPECT_EQ(cut.streets().size(), 1u);
  EXPECT_EQ(cut.streets()[0].points.size(), 2u);
  EXPECT_EQ(stats.incomplete_ways, 1u);
  EXPECT_EQ(stats.skipped_ways, 0u);
  // Not a UTM code: refused before the file is read.
  SAS::write_street_osm(path("scene.osm"), scene(), 18, true, {{origin[0], origin[1]}});
  for(const char* crs : {"EPSG:4326", "EPSG:32661", "UTM18"}) {
    m = message(path("scene.osm"), crs);
    EXPECT_TRUE(contains(m, crs) && contains(m, "EPSG:326zz")) << m;
  }
  // The map of another place (50 km east): read, but it does not overlap the scan.
  SAS::write_street_osm(path("elsewhere.osm"), scene(), 18, true, {{origin[0] + 50000, origin[1]}});
  const PR::Street_map far = PR::read_street_map(path("elsewhere.osm"), "EPSG:32618", origin);
  m = bad_input_message([&] { PR::check_street_map_overlap(far, CGAL::Bbox_2(0, -20, 200, 20)); });
  EXPECT_TRUE(contains(m, "does not overlap the scan")) << m;
  EXPECT_NO_THROW(PR::check_street_map_overlap(far, CGAL::Bbox_2(50000, -20, 50200, 20)));
}

// ---------------------------------------------------------------------------------------------
// Context grids

struct Labelled
{
  std::array<double, 3> position;
  std::size_t label;
};

// A straight street along x, as a map.
PR::Street_map straight_street(double x0, double x1)
{
  PR::Street_map::Street s;
  s.points = {{{x0, 0}}, {{x1, 0}}};
  return PR::Street_map({s});
}

// Class 0 every 10 m at y = 7 and, shifted by 5 m, at y = -7; class 1 at random on the sidewalks.
std::vector<Labelled> training_objects()
{
  std::vector<Labelled> objects;
  for(double x = 0; x <= 300; x += 10) {
    objects.push_back({{{x, 7, 0}}, 0});
    objects.push_back({{{x + 5, -7, 0}}, 0});
  }
  std::mt19937 rng(8);
  std::uniform_real_distribution<double> u(0, 1);
  for(int i = 0; i < 40; ++i)
    objects.push_back({{{300 * u(rng), (u(rng) < 0.5 ? -1 : 1) * (6 + 3 * u(rng)), 0}}, 1});
  return objects;
}

// The first classification of a test scan: class 0 every 10 m from 0 to 100 at y = 7, a few of class 1.
std::vector<Labelled> classified_objects()
{
  std::vector<Labelled> objects;
  for(double x = 0; x <= 100; x += 10)
    objects.push_back({{{x, 7, 0}}, 0});
  for(double x : {12.3, 47.9, 81.4})
    objects.push_back({{{x, -8.2, 0}}, 1});
  objects.push_back({{{55, 8, 0}}, 2}); // background of a classifier with 2 classes: ignored
  return objects;
}

const std::vector<std::array<double, 3>> candidates = {
    {{110, 7, 0}}, {{105, 7, 0}}, {{53.7, 8.6, 0}}, {{105, -7, 0}}, {{100.4, -7, 0}}};

TEST(ContextGrids, PredictThePatternOfEachClass)
{
  const PR::Street_map map = straight_street(-100, 400);
  PR::Context_grids grids;
  grids.learn(training_objects(), 2, map);
  EXPECT_EQ(grids.cells_per_side(), 80u);
  EXPECT_EQ(grids.number_of_objects(0), 62u);
  // In a class-0 object's frame: class 0 10 m along, and 5 m along across the street (14 m away).
  EXPECT_GT(grids.value(0, 10, 0), 20 * grids.value(0, 5, 0));
  EXPECT_GT(grids.value(0, -15, -14), 20 * grids.value(0, -10, -14));
  EXPECT_DOUBLE_EQ(grids.value(0, 10, 0), grids.value(0, -10, 0)); // symmetric along the street
  EXPECT_EQ(grids.value(0, 45, 0), 0.0);                              // outside the grid

  const std::vector<std::vector<double>> p = grids.prediction(candidates, classified_objects(), map);
  ASSERT_EQ(p.size(), candidates.size());
  // 110 m continues the row (the objects at 100 m and 90 m predict it); 105 m and a random place
  // do not; across the street the row shifted by 5 m is predicted, not the unshifted one.
  // Each of the 4 objects of the row within 40 m adds about the peak of a Gaussian of 1 m
  // (1 / 2 pi per square metre, less the cut), the farthest at the grid's edge half of it.
  EXPECT_GT(p[0][0], 0.3);
  EXPECT_LT(p[0][0], 0.6);
  EXPECT_GT(p[0][0], 20 * p[1][0]);
  EXPECT_GT(p[0][0], 5 * p[2][0]);
  EXPECT_GT(p[3][0], 0.05);
  EXPECT_GT(p[3][0], 5 * p[4][0]);
  EXPECT_GT(p[0][0], 5 * p[0][1]); // the random class predicts little
  // A labelled object within self_radius of the candidate is the candidate itself: not counted.
  std::vector<Labelled> with_itself = classified_objects();
  with_itself.push_back({{{110.3, 7.2, 0}}, 0});
  EXPECT_EQ(grids.prediction(candidates, with_itself, map)[0], p[0]);
}

TEST(ContextGrids, SameAfterATurnAndAMoveOfTheScene)
{
  const double c = std::cos(0.7), s = std::sin(0.7), tx = 1234.5, ty = -678.9;
  const auto move = [&](double x, double y) { return std::array<double, 3>{{c * x - s * y + tx, s * x + c * y + ty, 0}}; };
  const auto moved_objects = [&](std::vector<Labelled> objects) {
    for(Labelled& o : objects)
      o.position = move(o.position[0], o.position[1]);
    return objects;
  };
  PR::Street_map::Street street;
  street.points = {{{move(400, 0)[0], move(400, 0)[1]}}, {{move(-100, 0)[0], move(-100, 0)[1]}}}; // reversed too
  const PR::Street_map map = straight_street(-100, 400), moved_map({street});
  std::vector<std::array<double, 3>> moved_candidates;
  for(const std::array<double, 3>& q : candidates)
    moved_candidates.push_back(move(q[0], q[1]));
  PR::Context_grids grids, moved;
  grids.learn(training_objects(), 2, map);
  moved.learn(moved_objects(training_objects()), 2, moved_map);
  const auto p = grids.prediction(candidates, classified_objects(), map);
  const auto q = moved.prediction(moved_candidates, moved_objects(classified_objects()), moved_map);
  for(std::size_t i = 0; i < p.size(); ++i)
    for(std::size_t k = 0; k < 2; ++k)
      EXPECT_NEAR(p[i][k], q[i][k], 1e-9 * (1 + p[i][k])) << i << " " << k;
}

TEST(ContextGrids, WorkWithoutAStreetMap)
{
  const PR::Street_map none, map = straight_street(-100, 400);
  PR::Context_grids axes, streets;
  axes.learn(training_objects(), 2, none);
  streets.learn(training_objects(), 2, map);
  EXPECT_FALSE(axes.uses_streets());
  EXPECT_TRUE(streets.uses_streets());
  // The street runs along x: the scan's axes find the row, less the across pattern's sign.
  const auto p = axes.prediction(candidates, classified_objects(), none);
  EXPECT_GT(p[0][0], 20 * p[1][0]);
  EXPECT_GT(p[0][0], 5 * p[2][0]);
  // A map given to grids learned without one, and the reverse: refused.
  EXPECT_TRUE(contains(bad_input_message([&] { axes.prediction(candidates, classified_objects(), map); }), "empty map"));
  EXPECT_TRUE(contains(bad_input_message([&] { streets.prediction(candidates, classified_objects(), none); }), "street map"));
  // The features: the street distance only with a map, then the predictions.
  const PR::Context_features without = PR::context_features(candidates, none, axes, classified_objects());
  EXPECT_EQ(without.names, (std::vector<std::string>{"context.prediction.0", "context.prediction.1"}));
  EXPECT_EQ(without.values[0], p[0]);
  const PR::Context_features with = PR::context_features(candidates, map, streets, classified_objects());
  EXPECT_EQ(with.names.size(), 3u);
  EXPECT_EQ(with.names[0], "context.street_distance");
  EXPECT_DOUBLE_EQ(with.values[0][0], 7);
  const PR::Context_features distance_only =
      PR::context_features(candidates, map, PR::Context_grids(), std::vector<Labelled>());
  EXPECT_EQ(distance_only.names, std::vector<std::string>{"context.street_distance"});
  EXPECT_DOUBLE_EQ(distance_only.values[3][0], 7);
}

TEST(ContextGrids, SaveAndLoad)
{
  const PR::Street_map map = straight_street(-100, 400);
  PR::Context_grids grids;
  PR::Context_grid_options o;
  o.cell_size = 0.5, o.extent = 12, o.smoothing = 0.8, o.self_radius = 0.5;
  grids.learn(training_objects(), 2, map, o);
  std::stringstream saved;
  grids.save(saved);
  PR::Context_grids loaded;
  loaded.load(saved);
  EXPECT_EQ(loaded.cells_per_side(), 48u);
  EXPECT_EQ(loaded.options().smoothing, 0.8);
  const auto p = grids.prediction(candidates, classified_objects(), map);
  EXPECT_EQ(loaded.prediction(candidates, classified_objects(), map), p); // bit-identical
  std::stringstream again;
  loaded.save(again);
  EXPECT_EQ(again.str(), saved.str());

  // Refused, the grids unchanged: truncated, another version, not grids, a negative value.
  const std::string text = saved.str();
  const auto refused = [&](const std::string& bad, const std::string& words) {
    std::istringstream in(bad);
    const std::string m = bad_input_message([&] { loaded.load(in); });
    EXPECT_TRUE(contains(m, words)) << m;
    EXPECT_EQ(loaded.prediction(candidates, classified_objects(), map), p);
  };
  refused(text.substr(0, text.size() / 2), "truncated");
  refused(text.substr(0, text.size() - 4), "truncated");
  refused("CGAL_Point_set_object_recognition_context_grids 2\n" + text.substr(text.find('\n') + 1), "version");
  refused("CGAL_Point_set_object_recognition_classifier 1\n", "not context grids");
  std::string negative = text;
  negative.replace(negative.find("grid 0\n") + 7, 1, "-");
  refused(negative, "grid value");
  std::string wrong_cells = text;
  wrong_cells.replace(wrong_cells.find("cells 48"), 8, "cells 46");
  refused(wrong_cells, "does not match");
  std::istringstream empty("");
  EXPECT_FALSE(bad_input_message([&] { loaded.load(empty); }).empty());
}

TEST(ContextGrids, RefuseBadInput)
{
  const PR::Street_map map = straight_street(-100, 400);
  PR::Context_grids grids;
  EXPECT_TRUE(contains(bad_input_message([&] { grids.prediction(candidates, classified_objects(), map); }), "not learned"));
  std::stringstream out;
  EXPECT_FALSE(bad_input_message([&] { grids.save(out); }).empty());
  EXPECT_TRUE(contains(bad_input_message([&] { grids.learn(std::vector<Labelled>(), 2, map); }), "no labelled object"));
  EXPECT_TRUE(contains(bad_input_message([&] { grids.learn(classified_objects(), 2, map); }), "label 2"));
  EXPECT_FALSE(bad_input_message([&] { grids.learn(training_objects(), 0, map); }).empty());
  for(int k = 0; k < 4; ++k) {
    PR::Context_grid_options o;
    (k == 0 ? o.cell_size : k == 1 ? o.extent : k == 2 ? o.smoothing : o.self_radius) = -1;
    EXPECT_FALSE(bad_input_message([&] { grids.learn(training_objects(), 2, map, o); }).empty()) << k;
  }
  EXPECT_FALSE(grids.is_trained()); // unchanged by the failures
  std::vector<Labelled> nan = training_objects();
  nan[3].position[1] = std::nan("");
  EXPECT_FALSE(bad_input_message([&] { grids.learn(nan, 2, map); }).empty());
  grids.learn(training_objects(), 2, map);
  EXPECT_FALSE(bad_input_message([&] {
                 grids.prediction({{{std::nan(""), 0, 0}}}, classified_objects(), map);
               }).empty());
  EXPECT_FALSE(bad_input_message([&] { grids.value(2, 0, 0); }).empty());
}

} // namespace
