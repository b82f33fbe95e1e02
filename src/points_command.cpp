// Copyright (c) 2026 CGAL Global Shape Analysis contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later

// shape_analysis points generate --seed S --points N --output scene.ply --truth truth.json
//   (alias: points scene ... --objects truth.json)
// shape_analysis points background IN (.ply, .xyz, .las, .bin) --output OUT.ply --report R.json
// shape_analysis points locate IN --method nc|cc|meanshift|image --output locations.csv
//   [--truth truth.json] --report R.json
//
// The project's ground truth for point-cloud object recognition: a procedural street (road,
// curbs, sloped ground, buildings, trees, objects of the thesis' classes in clutter) scanned by a
// simulated mobile LIDAR, optionally with an airborne pass.

#include "cli_common.h"
#include "points_common.h"

#include <CGAL/Point_set_3.h>
#include <CGAL/Point_set_3/IO/PLY.h>
#include <Shape_analysis_support/Urban_scan.h>
#include <CGAL/Point_set_object_recognition/locate_objects.h>
#include <CGAL/Point_set_object_recognition/read_point_set.h>
#include <CGAL/Point_set_object_recognition/remove_background.h>
#include <CGAL/Point_set_object_recognition/write_point_set.h>
#ifdef CGAL_SHAPE_ANALYSIS_USE_OSMIUM
#include <CGAL/Point_set_object_recognition/read_street_map.h>
#include <Shape_analysis_support/Urban_osm.h>
#endif

#include <algorithm>
#include <fstream>
#include <iomanip>
#include <map>
#include <iostream>
#include <memory>
#include <sstream>

namespace shape_analysis_cli {

namespace {

namespace PSOR = CGAL::Point_set_object_recognition;
namespace SAS = CGAL::Shape_analysis_support;

// The files and switches of the command; the generator's options with its own defaults.
struct Scene_options
{
  std::string command = "scene"; // or "generate"
  std::string output, objects, report;
  SAS::Urban_scene_options scene;
  std::string sensor = "profile";
  // Road users and vegetation per 100 m; negative: the sensor's default (none for profile).
  double pedestrians = -1, cyclists = -1, lane_cars = -1, vegetation = -1;
  std::size_t segment_points = 10000000; // above twice this, the street is made in segments
  bool segment_files = false;            // each segment a file of its own
  std::string streets, crs = "EPSG:32618";  // the street's OpenStreetMap file, its UTM zone
  std::vector<double> scan_origin{583000, 4507000}; // the UTM coordinates of the scan's (0, 0)
  bool quiet = false, verbose = false;
};

// The truth: per object its id, class, location, height, bounding box and the number of points
// the scanner put on it (`scanned_points`: an object without points cannot be located).
Json objects_json(const std::vector<SAS::Urban_object>& objects, const std::map<int, std::size_t>& scanned)
{
  Json list = Json::array();
  for(const SAS::Urban_object& b : objects) {
    Json o = Json::object();
    o["id"] = b.id;
    o["class"] = SAS::object_class_name(b.object_class);
    o["class_id"] = b.object_class;
    o["location"] = Json(std::vector<double>{b.x, b.y, b.z});
    o["height"] = b.height;
    o["bbox"] = Json(std::vector<double>{b.bbox.xmin(), b.bbox.ymin(), b.bbox.zmin(), b.bbox.xmax(),
                                         b.bbox.ymax(), b.bbox.zmax()});
    const auto it = scanned.find(b.id);
    o["scanned_points"] = it == scanned.end() ? std::size_t(0) : it->second;
    list.push_back(o);
  }
  return list;
}

// `points generate` of more than twice --segment-points points: segments of about that many.
int run_scene_in_segments(const Scene_options& o, const SAS::Urban_scene_options& so, Output_files& outputs,
                          Progress& progress, const Stopwatch& total)
{
  if(!o.streets.empty())
    throw Usage_error("--streets: a street of more than twice --segment-points points is generated in "
                      "segments, without a map");
  Stopwatch work;
  Segmented_scene g;
  const bool las = lower_extension(o.output) == ".las";
  const std::string comment = "written by shape_analysis points " + o.command + " (CGAL Global Shape Analysis)";
  if(o.segment_files) {
    g = generate_segment_files(so, o.segment_points, progress, outputs, o.output, comment);
  } else {
    outputs.stage(o.output, true, [&](std::ostream& out) {
      g = generate_in_segments(so, out, las, comment, o.segment_points, progress);
    });
  }
  const double seconds = work.seconds();
  if(!o.objects.empty())
    outputs.stage(o.objects, false, [&](std::ostream& out) { out << SAS::to_text(objects_json(g.objects, g.scanned)) << "\n"; });
  if(!o.report.empty()) {
    Json report = Json::object();
    report["command"] = "points " + o.command;
    report["parameters"] = {{"length", so.street_length}, {"points", so.target_points}, {"seed", so.seed},
                            {"objects_per_100m", so.objects_per_100m}, {"noise", so.range_noise}};
    report["segments"] = g.segments;
    report["number_of_points"] = g.number_of_points;
    report["object_points"] = g.object_points;
    report["number_of_objects"] = g.objects.size();
    report["scanned_objects"] = g.scanned.size();
    report["number_of_triangles"] = g.triangles;
    stage_report(outputs, o.report, report, seconds, 0.0, total.seconds(), {{"scene", o.output}, {"objects", o.objects}});
  }
  outputs.commit();
  progress.done();
  std::cout << o.output << ": " << g.number_of_points << " points (" << g.object_points << " on " << g.objects.size()
            << " objects) in " << g.segments << " segments in " << seconds << " s\n";
  return 0;
}

int run_scene(const Scene_options& o)
{
  Stopwatch total;
  Progress progress("points " + o.command, o.quiet, o.verbose);
  Output_files outputs;
  outputs.add_output(o.output, "scanned scene", {".ply", ".las"});
  if(!o.objects.empty()) {
    outputs.add_output(o.objects, "ground-truth objects", {".json"});
  }
  outputs.add_optional_output(o.report, "report", {".json"});
#ifdef CGAL_SHAPE_ANALYSIS_USE_OSMIUM
  if(!o.streets.empty())
    outputs.add_output(o.streets, "street map", {".osm"});
  const CGAL::Point_set_object_recognition::Utm_zone zone = [&] {
    try {
      return CGAL::Point_set_object_recognition::parse_utm_crs(o.crs);
    } catch(const CGAL::Shape_analysis::Bad_input& e) {
      throw Usage_error(std::string("--crs: ") + e.what());
    }
  }();
#else
  if(!o.streets.empty())
    throw Usage_error("--streets: this build has no GeographicLib and libosmium");
#endif
  SAS::Urban_scene_options so = o.scene;
  const bool rotating = o.sensor == "rotating"; // with road users and vegetation by default
  so.pedestrians_per_100m = o.pedestrians >= 0 ? o.pedestrians : rotating ? 10. : 0.;
  so.cyclists_per_100m = o.cyclists >= 0 ? o.cyclists : rotating ? 4. : 0.;
  so.lane_cars_per_100m = o.lane_cars >= 0 ? o.lane_cars : rotating ? 5. : 0.;
  so.vegetation_per_100m = o.vegetation >= 0 ? o.vegetation : rotating ? 12. : 0.;
  if(rotating) { // a car's roof, a Velodyne's reach
    so.rotating_sensor = true;
    so.scanner_height = 1.73;
    so.max_range = 100;
    if(!(so.sweep_spacing >= 0.1))
      throw Usage_error("--sweep-spacing must be at least 0.1 m");
    if(so.airborne)
      throw Usage_error("--airborne goes with --sensor profile only");
  }
  // In segments (above twice segment_points), each segment up to 100 km.
  if(o.segment_points < 1000)
    throw Usage_error("--segment-points must be at least 1000");
  const bool in_segments = so.target_points > 2 * o.segment_points && !rotating;
  if(o.segment_files && !in_segments)
    throw Usage_error("--segment-files: the street is made in segments only above twice --segment-points points "
                      "(--sensor profile)");
  const double longest = in_segments ? 1e5 * double(so.target_points / o.segment_points + 1) : 1e5;
  if(!(so.street_length >= 10 && so.street_length <= longest))
    throw Usage_error("--length must be between 10 and " + std::to_string(std::size_t(longest)) + " m");
  if(so.target_points < 1000)
    throw Usage_error("--points must be at least 1000");
  if(!(so.range_noise >= 0 && so.range_noise <= 1))
    throw Usage_error("--noise must be between 0 and 1 m");

  if(in_segments)
    return run_scene_in_segments(o, so, outputs, progress, total);
  Stopwatch work;
  progress.stage("building a street of " + std::to_string(int(so.street_length)) + " m");
  const SAS::Urban_scene scene = SAS::make_urban_scene(so);
  progress.stage("scanning " + std::to_string(scene.objects.size()) + " objects, " +
                 std::to_string(scene.triangles.size()) + " triangles");
  const SAS::Urban_scan scan = SAS::scan_urban_scene(scene, so);
  const double seconds = work.seconds();

  progress.stage("writing " + std::to_string(scan.points.size()) + " points");
  outputs.stage(o.output, true, [&](std::ostream& out) {
    const CGAL::Point_set_3<Point_3> ps = scan_points(scan);
    if(lower_extension(o.output) == ".las") {
      PSOR::write_las_point_set(out, ps);
      return;
    }
    CGAL::IO::set_mode(out, CGAL::IO::BINARY);
    if(!CGAL::IO::write_PLY(out, ps, "written by shape_analysis points " + o.command + " (CGAL Global Shape Analysis)"))
      throw Cli_error("cannot write " + o.output);
  });
#ifdef CGAL_SHAPE_ANALYSIS_USE_OSMIUM
  if(!o.streets.empty())
    outputs.stage(o.streets, false, [&](std::ostream& out) {
      SAS::write_street_osm(out, scene, zone.zone, zone.north, {{o.scan_origin[0], o.scan_origin[1]}});
    });
#endif
  std::size_t object_points = 0;
  std::map<int, std::size_t> scanned;
  for(const SAS::Urban_scan_point& p : scan.points)
    if(p.instance > 0) {
      ++object_points;
      ++scanned[p.instance];
    }
  if(!o.objects.empty())
    outputs.stage(o.objects, false,
                  [&](std::ostream& out) { out << SAS::to_text(objects_json(scene.objects, scanned)) << "\n"; });
  if(!o.report.empty()) {
    Json report = Json::object();
    report["command"] = "points " + o.command;
    Json parameters = Json::object();
    parameters["length"] = so.street_length;
    parameters["points"] = so.target_points;
    parameters["objects_per_100m"] = so.objects_per_100m;
    parameters["pedestrians_per_100m"] = so.pedestrians_per_100m;
    parameters["cyclists_per_100m"] = so.cyclists_per_100m;
    parameters["lane_cars_per_100m"] = so.lane_cars_per_100m;
    parameters["vegetation_per_100m"] = so.vegetation_per_100m;
    parameters["noise"] = so.range_noise;
    parameters["airborne"] = so.airborne;
    parameters["sensor"] = o.sensor;
    if(o.sensor == "rotating") {
      parameters["sweep_spacing"] = so.sweep_spacing;
      parameters["beams"] = so.beams;
      parameters["sensor_height"] = so.scanner_height;
    }
    parameters["seed"] = so.seed;
    report["parameters"] = parameters;
    report["number_of_points"] = scan.points.size();
    report["mobile_points"] = scan.mobile_points;
    report["object_points"] = object_points;
    report["scan_lines"] = scan.scan_lines;
    report["profile_spacing"] = scan.profile_spacing;
    report["number_of_objects"] = scene.objects.size();
    report["scanned_objects"] = scanned.size();
    report["number_of_triangles"] = scene.triangles.size();
    stage_report(outputs, o.report, report, seconds, 0.0, total.seconds(),
                 {{"scene", o.output}, {"objects", o.objects}});
  }
  outputs.commit();
  progress.done();
  std::cout << o.output << ": " << scan.points.size() << " points (" << object_points << " on "
            << scene.objects.size() << " objects) in " << seconds << " s\n";
  return 0;
}

// The files and switches of the command; the background removal's options with the library's
// defaults.
struct Background_options
{
  std::string input, output, report;
  PSOR::Remove_background_options removal;
  bool all = false;
  bool quiet = false, verbose = false;
};

int run_background(const Background_options& o)
{
  Stopwatch total;
  Progress progress("points background", o.quiet, o.verbose);
  Output_files outputs;
  outputs.add_input(o.input);
  outputs.add_output(o.output, "output point cloud", {".ply"});
  outputs.add_optional_output(o.report, "report", {".json"});

  progress.stage("reading " + o.input);
  Stopwatch reading;
  CGAL::Point_set_3<Point_3> points;
  const PSOR::Point_set_read_result read = PSOR::read_point_set(o.input, points);
  const double read_seconds = reading.seconds();

  progress.stage("removing the background of " + std::to_string(points.size()) + " points");
  Stopwatch work;
  const PSOR::Remove_background_options& ro = o.removal;
  const PSOR::Background_removal_result r = PSOR::remove_background(
    points, PSOR::parameters::ground_cell_size(ro.ground_cell_size)
              .ground_threshold(ro.ground_threshold)
              .isolation_radius(ro.isolation_radius)
              .minimum_neighbors(ro.minimum_neighbors)
              .component_spacing(ro.component_spacing)
              .maximum_component_extent(ro.maximum_component_extent));
  const double seconds = work.seconds();

  outputs.stage(o.output, true, [&](std::ostream& out) {
    // The input's points and properties (in the local frame), with the kind and the height above
    // the ground; only the foreground unless --all.
    CGAL::Point_set_3<Point_3> result = points;
    auto kind = result.add_property_map<int>("kind", 0).first;
    auto height = result.add_property_map<float>("height_above_ground", 0.f).first;
    std::size_t k = 0;
    for(auto i : result) {
      kind[i] = int(r.kind[k]);
      height[i] = float(r.height_above_ground[k]);
      ++k;
    }
    if(!o.all) {
      k = 0;
      std::vector<CGAL::Point_set_3<Point_3>::Index> removed;
      for(auto i : result) {
        if(r.kind[k] != PSOR::Point_kind::FOREGROUND)
          removed.push_back(i);
        ++k;
      }
      for(auto it = removed.rbegin(); it != removed.rend(); ++it)
        result.remove(*it);
      result.collect_garbage();
    }
    CGAL::IO::set_mode(out, CGAL::IO::BINARY);
    std::ostringstream comment;
    comment << std::setprecision(17) << "written by shape_analysis points background (CGAL Global Shape Analysis); "
            << "local origin " << read.offset[0] << " " << read.offset[1] << " " << read.offset[2]
            << " (add it back for the input's coordinates)";
    if(!CGAL::IO::write_PLY(out, result, comment.str()))
      throw Cli_error("cannot write " + o.output);
  });
  if(!o.report.empty()) {
    Json report = Json::object();
    report["command"] = "points background";
    report["input"] = o.input;
    report["format"] = read.format;
    report["number_of_points"] = points.size();
    report["local_origin"] = Json(std::vector<double>{read.offset[0], read.offset[1], read.offset[2]});
    Json parameters = Json::object();
    parameters["ground_cell_size"] = ro.ground_cell_size;
    parameters["ground_threshold"] = ro.ground_threshold;
    parameters["isolation_radius"] = ro.isolation_radius;
    parameters["minimum_neighbors"] = ro.minimum_neighbors;
    parameters["component_spacing"] = ro.component_spacing;
    parameters["maximum_component_extent"] = ro.maximum_component_extent;
    report["parameters"] = parameters;
    report["ground_points"] = r.number_of_ground_points;
    report["isolated_points"] = r.number_of_isolated_points;
    report["large_component_points"] = r.number_of_large_component_points;
    report["foreground_points"] = r.foreground.size();
    stage_report(outputs, o.report, report, seconds, read_seconds, total.seconds(), {{"points", o.output}});
  }
  outputs.commit();
  progress.done();
  std::cout << o.input << ": " << points.size() << " points, " << r.number_of_ground_points << " ground, "
            << r.number_of_isolated_points << " isolated, " << r.number_of_large_component_points
            << " in large components, " << r.foreground.size() << " kept (" << seconds << " s)\n";
  return 0;
}

// The names of the localization methods on the command line ('components' and 'mean-shift' are
// accepted too).
const std::vector<std::string> localization_method_names{"nc", "cc", "meanshift", "image"};

// The command-line name of a localization method.
std::string localization_method_name(PSOR::Localization_method m)
{
  for(const std::string& name : localization_method_names)
    if(localization_method(name) == m)
      return name;
  return "cc";
}

// The files and switches of the command; the localization's options with the library's
// defaults (the method by its command-line name).
struct Locate_options
{
  std::string input, output, truth, report;
  PSOR::Locate_objects_options localization;
  std::string method = localization_method_name(localization.localization_method);
  double radius = 1;            // of evaluate_locations()
  std::size_t truth_points = 10;
  bool quiet = false, verbose = false;
};


int run_locate(const Locate_options& o)
{
  Stopwatch total;
  Progress progress("points locate", o.quiet, o.verbose);
  Output_files outputs;
  outputs.add_input(o.input);
  if(!o.truth.empty())
    outputs.add_input(o.truth);
  const bool csv = lower_extension(o.output) == ".csv";
  outputs.add_output(o.output, "locations", {".csv", ".json"});
  outputs.add_optional_output(o.report, "report", {".json"});
  if(!(o.radius > 0))
    throw Usage_error("--radius must be positive");

  progress.stage("reading " + o.input);
  Stopwatch reading;
  CGAL::Point_set_3<Point_3> points;
  // Computed in the reader's local frame (double precision for georeferenced scans), written
  // back in the file's coordinates.
  const PSOR::Point_set_read_result read = PSOR::read_point_set(o.input, points);
  const double read_seconds = reading.seconds();
  const std::vector<Truth_object> truth = o.truth.empty() ? std::vector<Truth_object>() : read_truth_objects(o.truth);

  // The input is a scan unless it holds the 'kind' property of 'points background' (then only
  // the points of kind 0, the foreground, are used).
  Stopwatch work;
  std::vector<Point_3> foreground;
  PSOR::Background_removal_result background;
  const auto kind = points.property_map<int>("kind");
  const bool scan = !kind.second;
  if(scan) {
    progress.stage("removing the background of " + std::to_string(points.size()) + " points");
    background = PSOR::remove_background(points);
    foreground.reserve(background.foreground.size());
    for(std::size_t i : background.foreground)
      foreground.push_back(points.point(*(points.begin() + std::ptrdiff_t(i))));
  } else
    for(auto i : points)
      if(kind.first[i] == 0)
        foreground.push_back(points.point(i));
  const double background_seconds = work.seconds();
  progress.stage("locating objects among " + std::to_string(foreground.size()) + " points");
  Stopwatch locating;
  PSOR::Locate_objects_options lo = o.localization;
  lo.localization_method = localization_method(o.method);
  const PSOR::Localization_result r = PSOR::locate_objects(
    foreground, PSOR::parameters::localization_method(lo.localization_method)
                  .mean_shift_radius(lo.mean_shift_radius)
                  .component_spacing(lo.component_spacing)
                  .minimum_cluster_size(lo.minimum_cluster_size)
                  .maximum_cluster_height(lo.maximum_cluster_height)
                  .localization_cell_size(lo.localization_cell_size)
                  .normalized_cut_threshold(lo.normalized_cut_threshold)
                  .height_image_sigma(lo.height_image_sigma)
                  .height_image_threshold(lo.height_image_threshold)
                  .number_of_threads(lo.number_of_threads));
  const double locate_seconds = locating.seconds();
  const double seconds = work.seconds();
  std::vector<PSOR::Object_location> located = r.locations;
  for(PSOR::Object_location& l : located)
    for(int c = 0; c < 3; ++c)
      l.position[std::size_t(c)] += read.offset[std::size_t(c)];
  outputs.stage(o.output, false, [&](std::ostream& out) {
    if(csv) {
      std::vector<std::array<double, 3>> positions;
      for(const PSOR::Object_location& l : located)
        positions.push_back(l.position);
      write_locations_csv(out, positions);
      return;
    }
    Json list = Json::array();
    for(const PSOR::Object_location& l : located) {
      Json j = Json::object();
      j["location"] = Json(std::vector<double>{l.position[0], l.position[1], l.position[2]});
      j["points"] = l.number_of_points;
      j["height"] = l.height;
      list.push_back(j);
    }
    out << SAS::to_text(list) << "\n";
  });
  // Precision against every true object; recall against the objects that received at least
  // --truth-points points from the scanner (all of them when the truth does not say).
  std::vector<std::array<double, 2>> all, visible;
  for(const Truth_object& t : truth) {
    all.push_back({t.location[0], t.location[1]});
    if(t.scanned_points < 0 || std::size_t(t.scanned_points) >= o.truth_points)
      visible.push_back({t.location[0], t.location[1]});
  }
  PSOR::Localization_evaluation e, e_all;
  if(!truth.empty()) {
    e_all = PSOR::evaluate_locations(located, all, o.radius);
    e = PSOR::evaluate_locations(located, visible, o.radius);
  }
  if(!o.report.empty()) {
    Json report = Json::object();
    report["command"] = "points locate";
    report["input"] = o.input;
    report["format"] = read.format;
    report["number_of_points"] = points.size();
    report["background_removed"] = scan;
    report["foreground_points"] = foreground.size();
    Json parameters = Json::object();
    parameters["localization_method"] = localization_method_name(lo.localization_method);
    parameters["mean_shift_radius"] = lo.mean_shift_radius;
    parameters["component_spacing"] = lo.component_spacing;
    parameters["minimum_cluster_size"] = lo.minimum_cluster_size;
    parameters["maximum_cluster_height"] = lo.maximum_cluster_height;
    parameters["localization_cell_size"] = lo.localization_cell_size;
    parameters["normalized_cut_threshold"] = lo.normalized_cut_threshold;
    parameters["height_image_sigma"] = lo.height_image_sigma;
    parameters["height_image_threshold"] = lo.height_image_threshold;
    parameters["number_of_threads"] = lo.number_of_threads;
    report["parameters"] = parameters;
    report["clusters"] = r.number_of_clusters;
    report["locations"] = r.locations.size();
    report["seconds_background_removal"] = scan ? background_seconds : 0.0;
    report["seconds_localization"] = locate_seconds;
    report["points_per_second"] = seconds > 0 ? double(points.size()) / seconds : 0.0;
    if(!truth.empty()) {
      Json ev = Json::object();
      ev["radius"] = o.radius;
      ev["minimum_scanned_points"] = o.truth_points;
      ev["objects"] = visible.size();
      ev["all_objects"] = all.size();
      ev["correct_locations"] = e_all.correct_locations;
      ev["found_objects"] = e.found_objects;
      ev["precision"] = e_all.precision;
      ev["recall"] = e.recall;
      ev["recall_all_objects"] = e_all.recall;
      report["evaluation"] = ev;
    }
    stage_report(outputs, o.report, report, seconds, read_seconds, total.seconds(), {{"locations", o.output}});
  }
  outputs.commit();
  progress.done();
  std::cout << o.input << ": " << r.locations.size() << " locations among " << foreground.size()
            << (scan ? " foreground points of " + std::to_string(points.size()) : std::string(" points"));
  if(!truth.empty())
    std::cout << "; precision " << e_all.precision << ", recall " << e.recall << " (" << visible.size()
              << " objects with at least " << o.truth_points << " points, " << o.radius << " m)";
  std::cout << "\n";
  return 0;
}

} // namespace

CGAL::Point_set_object_recognition::Localization_method localization_method(const std::string& name)
{
  if(name == "nc")
    return CGAL::Point_set_object_recognition::Localization_method::NORMALIZED_CUT;
  if(name == "meanshift" || name == "mean-shift")
    return CGAL::Point_set_object_recognition::Localization_method::MEAN_SHIFT;
  if(name == "image")
    return CGAL::Point_set_object_recognition::Localization_method::HEIGHT_IMAGE;
  return CGAL::Point_set_object_recognition::Localization_method::CONNECTED_COMPONENTS; // cc, components
}

void write_locations_csv(std::ostream& out, const std::vector<std::array<double, 3>>& locations)
{
  out << std::setprecision(17) << "x,y,z\n";
  for(const auto& l : locations)
    out << l[0] << ',' << l[1] << ',' << l[2] << '\n';
}

void add_points_command(CLI::App& app, std::function<int()>& run)
{
  CLI::App* points = app.add_subcommand("points", "Point clouds: scanned urban scenes, background removal, localization.");
  points->require_subcommand(1);

  // points generate (the name, --truth) and points scene (the first name, --objects).
  for(const std::string name : {"generate", "scene"}) {
    auto s = std::make_shared<Scene_options>();
    s->command = name;
    CLI::App* scene = points->add_subcommand(
      name, name == "generate"
              ? "Generate a street (road, curbs, sloped ground, buildings, trees and small objects of the "
                "thesis' 16 classes in clutter; with --sensor rotating also pedestrians, cyclists, cars in the "
                "lanes and vegetation) scanned by a simulated LIDAR; per point its object id and class."
              : "The same as 'points generate', with --objects for --truth.");
    scene->add_option("-o,--output", s->output,
                      "The scan (.ply: x y z double, instance and label int, intensity float, colours by class)")
      ->required();
    scene->add_option(name == "generate" ? "--truth" : "--objects", s->objects,
                      "The ground-truth objects (.json: id, class, location, height, bbox, scanned_points)");
    scene->add_option("--report", s->report, "JSON report (parameters, counts, seconds)");
    scene->add_option("--streets", s->streets,
                      "The street's map (.osm: OpenStreetMap XML; the street, two cross streets, sidewalks as "
                      "footways, building footprints), the scan's (0,0) at --scan-origin in the UTM zone --crs");
    scene->add_option("--crs", s->crs, "The UTM zone of --streets, EPSG:326zz or EPSG:327zz")->capture_default_str();
    scene->add_option("--scan-origin", s->scan_origin, "The UTM easting,northing of the scan's (0,0)")
      ->expected(2)
      ->delimiter(',')
      ->capture_default_str();
    SAS::Urban_scene_options& so = s->scene;
    scene->add_option("--length", so.street_length, "Length of the street in metres")->capture_default_str();
    scene->add_option("--points", so.target_points, "Number of mobile LIDAR points wanted (roughly)")->capture_default_str();
    scene->add_option("--segment-points", s->segment_points,
                      "Above twice this many points (--sensor profile), the street is made of segments of about "
                      "this many points, each a street of its own (its own seed) after the previous one along x, "
                      "generated and written one at a time: memory holds one segment (10^7 points: 2 GB)")
      ->capture_default_str();
    if(s->command == "generate")
      scene->add_flag("--segment-files", s->segment_files,
                      "With segments, each in a file of its own (a folder of tiles, as a city comes): the "
                      "output's name with _0000, _0001... before its extension; 'points recognize' reads the "
                      "folder as one scan");
    scene->add_option("--objects-per-100m", so.objects_per_100m, "Objects per 100 m of street")->capture_default_str();
    scene->add_option("--noise", so.range_noise, "Standard deviation of the range noise in metres")->capture_default_str();
    scene->add_flag("--airborne", so.airborne, "Add an airborne pass (points on a grid from above)");
    scene->add_option("--sensor", s->sensor,
                      "profile: two tilted profile scanners (mobile mapping, dense); rotating: a 64-beam "
                      "rotating sensor 1.73 m up on a car in the right lane, 100 m reach (Velodyne-like "
                      "rings, one full turn every --sweep-spacing metres; --points is then ignored)")
      ->check(CLI::IsMember({"profile", "rotating"}))
      ->capture_default_str();
    scene->add_option("--sweep-spacing", so.sweep_spacing, "Metres of travel between turns of the rotating sensor")
      ->capture_default_str();
    const auto density = [&](const char* flag, double& value, const char* what, const char* rotating) {
      scene->add_option(flag, value, std::string(what) + " per 100 m of street (default: 0 with --sensor profile, " +
                                       rotating + " with --sensor rotating)")
        ->check(CLI::Range(0.0, 100.0));
    };
    density("--pedestrians-per-100m", s->pedestrians,
            "Pedestrians (class 'pedestrian', 1.5-1.9 m) walking or standing on the sidewalks or crossing "
            "the road,", "10");
    density("--cyclists-per-100m", s->cyclists,
            "Cyclists (class 'cyclist') riding along the lanes' edges, or parked bicycles on the sidewalks,", "4");
    density("--lane-cars-per-100m", s->lane_cars,
            "Cars in the driving lanes (class 'car'; kept off the sensor's own path), besides the parked "
            "ones,", "5");
    density("--vegetation-per-100m", s->vegetation,
            "Hedges, bushes and low shrubs (background class 'vegetation'; any > 0 also makes tree crowns "
            "irregular),", "12");
    scene->add_option("--seed", so.seed, "Random seed (same seed, same scene)")->capture_default_str();
    scene->add_option("--threads", so.number_of_threads, "Largest number of threads (0: all cores)")->capture_default_str();
    scene->add_flag("-q,--quiet", s->quiet, "No progress on stderr");
    scene->add_flag("-v,--verbose", s->verbose, "Progress on stderr even when it is not a terminal");
    scene->callback([s, &run]() { run = [s]() { return run_scene(*s); }; });
  }

  auto b = std::make_shared<Background_options>();
  CLI::App* background = points->add_subcommand(
    "background", "Remove the ground, isolated points and very large connected components (buildings) "
                  "of a scan (metres, z up); keep the candidate small objects.");
  background->add_option("input", b->input, "The scan (.ply, .xyz/.pts/.txt, .las 1.2-1.4 uncompressed, .bin KITTI)")
    ->required();
  background->add_option("-o,--output", b->output,
                         "The points kept (.ply, in the local frame of the report's local_origin), with "
                         "'kind' and 'height_above_ground'")
    ->required();
  background->add_option("--report", b->report, "JSON report (counts, local origin, seconds)");
  background->add_flag("--all", b->all, "Write every point with its kind (0 kept, 1 ground, 2 isolated, 3 large component)");
  PSOR::Remove_background_options& ro = b->removal;
  background->add_option("--cell", ro.ground_cell_size, "Side of the ground grid's cells (m)")->capture_default_str();
  background->add_option("--ground-threshold", ro.ground_threshold, "Points less than this above the ground are ground (m)")
    ->capture_default_str();
  background->add_option("--isolation-radius", ro.isolation_radius, "Side of the voxels where neighbours are counted (m)")
    ->capture_default_str();
  background->add_option("--min-neighbors", ro.minimum_neighbors, "Fewer neighbours: isolated")->capture_default_str();
  background->add_option("--spacing", ro.component_spacing,
                         "Side of the voxels of the connected components (m; not the --spacing of 'points locate')")
    ->capture_default_str();
  background->add_option("--max-extent", ro.maximum_component_extent,
                         "Components with a wider horizontal extent are removed (m)")
    ->capture_default_str();
  background->add_flag("-q,--quiet", b->quiet, "No progress on stderr");
  background->add_flag("-v,--verbose", b->verbose, "Progress on stderr even when it is not a terminal");
  background->callback([b, &run]() { run = [b]() { return run_background(*b); }; });

  auto l = std::make_shared<Locate_options>();
  CLI::App* locate = points->add_subcommand(
    "locate", "Locate potential objects in a scan (its background removed first) or among the foreground "
              "points of 'points background'; with --truth, precision and recall of the locations.");
  locate->add_option("input", l->input,
                     "The scan or the output of 'points background' (.ply, .xyz, .las, .bin)")
    ->required();
  locate->add_option("-o,--output", l->output,
                     "The locations: .csv (a line 'x,y,z', then one location per line, in the input's "
                     "coordinates) or .json (location [x, y, z], points, height)")
    ->required();
  locate->add_option("--truth", l->truth, "True objects (.json, as written by 'points generate --truth')");
  locate->add_option("--truth-points", l->truth_points,
                     "Recall counts the true objects with at least this many scanned points")
    ->capture_default_str();
  locate->add_option("--report", l->report, "JSON report (counts, precision and recall, seconds)");
  locate->add_option("--method", l->method,
                     "nc (normalized cut), cc (connected components), meanshift, image (height image); "
                     "'components' and 'mean-shift' are accepted too")
    ->capture_default_str()
    ->check(CLI::IsMember({"nc", "cc", "meanshift", "image", "components", "mean-shift"}));
  PSOR::Locate_objects_options& lo = l->localization;
  locate->add_option("--shift-radius", lo.mean_shift_radius, "Radius of the mean shift's kernel (m)")->capture_default_str();
  locate->add_option("--spacing", lo.component_spacing,
                     "Side of the voxels whose contact makes clusters (cc, m; not the --spacing of 'points background')")
    ->capture_default_str();
  locate->add_option("--cell", lo.localization_cell_size, "Side of the voxels (nc) and of the height image's cells (image), m")
    ->capture_default_str();
  locate->add_option("--cut-threshold", lo.normalized_cut_threshold, "Normalized cut below which clusters stay apart (nc)")
    ->capture_default_str();
  locate->add_option("--sigma", lo.height_image_sigma, "Smaller Gaussian of the difference of Gaussians (image, m)")
    ->capture_default_str();
  locate->add_option("--image-threshold", lo.height_image_threshold, "Response of an object's cells (image, m)")
    ->capture_default_str();
  locate->add_option("--min-points", lo.minimum_cluster_size, "Smaller clusters are rejected")->capture_default_str();
  locate->add_option("--max-height", lo.maximum_cluster_height, "Taller clusters are rejected (m)")->capture_default_str();
  locate->add_option("--radius", l->radius, "Largest horizontal distance of a correct location (m)")->capture_default_str();
  locate->add_option("--threads", lo.number_of_threads, "Largest number of threads (0: all cores)")->capture_default_str();
  locate->add_flag("-q,--quiet", l->quiet, "No progress on stderr");
  locate->add_flag("-v,--verbose", l->verbose, "Progress on stderr even when it is not a terminal");
  locate->callback([l, &run]() { run = [l]() { return run_locate(*l); }; });
  add_points_segment_commands(points, run);
}

} // namespace shape_analysis_cli
