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

#include <CGAL/Point_set_3.h>
#include <CGAL/Point_set_3/IO/PLY.h>
#include <Shape_analysis_support/Urban_scene.h>
#include <CGAL/Point_set_object_recognition/locate_objects.h>
#include <CGAL/Point_set_object_recognition/read_point_set.h>
#include <CGAL/Point_set_object_recognition/remove_background.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <map>
#include <iostream>
#include <memory>
#include <sstream>

namespace shape_analysis_cli {

namespace {

namespace PSI = CGAL::Point_set_object_recognition::internal;
namespace PSOR = CGAL::Point_set_object_recognition;
namespace SAS = CGAL::Shape_analysis_support;

struct Scene_options
{
  std::string command = "scene"; // or "generate"
  std::string output, objects, report;
  double length = 200;
  std::size_t points = 1000000;
  std::size_t objects_per_100m = 30;
  double noise = 0.015;
  bool airborne = false;
  std::uint64_t seed = 1;
  std::size_t threads = 0;
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

int run_scene(const Scene_options& o)
{
  Stopwatch total;
  Progress progress("points " + o.command, o.quiet, o.verbose);
  Output_files outputs;
  require_extension(o.output, ".ply", "scanned scene");
  outputs.add_output(o.output, "scanned scene");
  if(!o.objects.empty()) {
    require_extension(o.objects, ".json", "ground-truth objects");
    outputs.add_output(o.objects, "ground-truth objects");
  }
  outputs.add_optional_output(o.report, "report");
  if(!(o.length >= 10 && o.length <= 1e5))
    throw Usage_error("--length must be between 10 and 100000 m");
  if(o.points < 1000)
    throw Usage_error("--points must be at least 1000");
  if(!(o.noise >= 0 && o.noise <= 1))
    throw Usage_error("--noise must be between 0 and 1 m");

  SAS::Urban_scene_options so;
  so.seed = o.seed;
  so.street_length = o.length;
  so.objects_per_100m = o.objects_per_100m;
  so.target_points = o.points;
  so.range_noise = o.noise;
  so.airborne = o.airborne;
  so.number_of_threads = o.threads;

  Stopwatch work;
  progress.stage("building a street of " + std::to_string(int(o.length)) + " m");
  const SAS::Urban_scene scene = SAS::make_urban_scene(so);
  progress.stage("scanning " + std::to_string(scene.objects.size()) + " objects, " +
                 std::to_string(scene.triangles.size()) + " triangles");
  const SAS::Urban_scan scan = SAS::scan_urban_scene(scene, so);
  const double seconds = work.seconds();

  progress.stage("writing " + std::to_string(scan.points.size()) + " points");
  outputs.stage(o.output, true, [&](std::ostream& out) {
    CGAL::Point_set_3<Point_3> ps;
    SAS::fill_point_set(scan, ps, true);
    // Colours by class, so that MeshLab shows them; CloudCompare also shows the scalar fields.
    auto red = ps.add_property_map<unsigned char>("red", 0).first;
    auto green = ps.add_property_map<unsigned char>("green", 0).first;
    auto blue = ps.add_property_map<unsigned char>("blue", 0).first;
    auto label = ps.property_map<int>("label").first;
    for(auto i : ps) {
      const auto c = label_colour(std::size_t(label[i]));
      red[i] = c[0];
      green[i] = c[1];
      blue[i] = c[2];
    }
    CGAL::IO::set_mode(out, CGAL::IO::BINARY);
    if(!CGAL::IO::write_PLY(out, ps, "written by shape_analysis points " + o.command + " (CGAL Global Shape Analysis)"))
      throw Cli_error("cannot write " + o.output);
  });
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
    parameters["length"] = o.length;
    parameters["points"] = o.points;
    parameters["objects_per_100m"] = o.objects_per_100m;
    parameters["noise"] = o.noise;
    parameters["airborne"] = o.airborne;
    parameters["seed"] = o.seed;
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

struct Background_options
{
  std::string input, output, report;
  double cell = 5, threshold = 0.2, isolation = 0.5, spacing = 0.5, extent = 12;
  std::size_t neighbors = 3;
  bool all = false;
  bool quiet = false, verbose = false;
};

int run_background(const Background_options& o)
{
  Stopwatch total;
  Progress progress("points background", o.quiet, o.verbose);
  Output_files outputs;
  outputs.add_input(o.input);
  require_extension(o.output, ".ply", "output point cloud");
  outputs.add_output(o.output, "output point cloud");
  outputs.add_optional_output(o.report, "report");

  progress.stage("reading " + o.input);
  Stopwatch reading;
  CGAL::Point_set_3<Point_3> points;
  const PSOR::Point_set_read_result read = PSOR::read_point_set(o.input, points);
  const double read_seconds = reading.seconds();

  progress.stage("removing the background of " + std::to_string(points.size()) + " points");
  Stopwatch work;
  const PSOR::Background_removal_result r = PSOR::remove_background(
    points, PSOR::parameters::ground_cell_size(o.cell)
              .ground_threshold(o.threshold)
              .isolation_radius(o.isolation)
              .minimum_neighbors(o.neighbors)
              .component_spacing(o.spacing)
              .maximum_component_extent(o.extent));
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
    parameters["ground_cell_size"] = o.cell;
    parameters["ground_threshold"] = o.threshold;
    parameters["isolation_radius"] = o.isolation;
    parameters["minimum_neighbors"] = o.neighbors;
    parameters["component_spacing"] = o.spacing;
    parameters["maximum_component_extent"] = o.extent;
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

struct Locate_options
{
  std::string input, output, truth, report, method = "nc";
  double spacing = 0.3, tallest = 12, radius = 1, shift_radius = 2, cell = 0.15, cut_threshold = 0.002,
         sigma = 0.2, image_threshold = 0.02;
  std::size_t minimum = 10, truth_points = 10, threads = 0;
  bool quiet = false, verbose = false;
};

bool has_extension(const std::string& path, const std::string& extension)
{
  std::string ext = std::filesystem::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  return ext == extension;
}


int run_locate(const Locate_options& o)
{
  Stopwatch total;
  Progress progress("points locate", o.quiet, o.verbose);
  Output_files outputs;
  outputs.add_input(o.input);
  if(!o.truth.empty())
    outputs.add_input(o.truth);
  const bool csv = has_extension(o.output, ".csv");
  if(!csv && !has_extension(o.output, ".json"))
    throw Usage_error("the locations must be written to a .csv file (x,y,z per line) or a .json file, not " +
                      o.output);
  outputs.add_output(o.output, "locations");
  outputs.add_optional_output(o.report, "report");
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
  const PSOR::Localization_result r = PSOR::locate_objects(
    foreground, PSOR::parameters::localization_method(localization_method(o.method))
                  .mean_shift_radius(o.shift_radius)
                  .component_spacing(o.spacing)
                  .minimum_cluster_size(o.minimum)
                  .maximum_cluster_height(o.tallest)
                  .localization_cell_size(o.cell)
                  .normalized_cut_threshold(o.cut_threshold)
                  .height_image_sigma(o.sigma)
                  .height_image_threshold(o.image_threshold)
                  .number_of_threads(o.threads));
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
    parameters["method"] = o.method;
    parameters["mean_shift_radius"] = o.shift_radius;
    parameters["component_spacing"] = o.spacing;
    parameters["minimum_cluster_size"] = o.minimum;
    parameters["maximum_cluster_height"] = o.tallest;
    parameters["localization_cell_size"] = o.cell;
    parameters["normalized_cut_threshold"] = o.cut_threshold;
    parameters["height_image_sigma"] = o.sigma;
    parameters["height_image_threshold"] = o.image_threshold;
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

std::vector<Truth_object> read_truth_objects(const std::string& path)
{
  std::ifstream in(path);
  if(!in)
    throw Cli_error("cannot open " + path);
  Json file;
  try {
    file = Json::parse(in);
  } catch(const Json::parse_error& e) {
    throw Cli_error(path + ": not JSON (" + e.what() + ")");
  }
  if(!file.is_array())
    throw Cli_error(path + ": not a JSON array of objects (write it with 'points generate --truth')");
  std::vector<Truth_object> r;
  for(const Json& object : file) {
    Truth_object t;
    t.id = int(r.size());
    const std::string which = "object " + std::to_string(r.size());
    // A member of the wanted type, or the default when it is absent.
    const auto member = [&](const char* key, auto fallback) {
      const auto it = object.find(key);
      if(it == object.end() || it->is_null())
        return fallback;
      try {
        return it->template get<decltype(fallback)>();
      } catch(const Json::exception&) {
        throw Cli_error(path + ": \"" + key + "\" of " + which + " is not a number or name of the right kind");
      }
    };
    if(!object.is_object())
      throw Cli_error(path + ": " + which + " is not a JSON object");
    t.id = member("id", t.id);
    t.object_class = member("class_id", 0);
    t.name = member("class", std::string());
    t.scanned_points = member("scanned_points", -1L);
    const auto location = object.find("location");
    if(location == object.end() || !location->is_array() || location->size() < 2 || location->size() > 3)
      throw Cli_error(path + ": object " + std::to_string(t.id) + " has no \"location\": [x, y, z]");
    for(std::size_t k = 0; k < location->size(); ++k) {
      if(!(*location)[k].is_number())
        throw Cli_error(path + ": a coordinate of object " + std::to_string(t.id) + " is not a number");
      t.location[k] = (*location)[k].get<double>();
      if(!std::isfinite(t.location[k]))
        throw Cli_error(path + ": a coordinate of object " + std::to_string(t.id) + " is not finite");
    }
    r.push_back(t);
  }
  return r;
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
              ? "Generate a street (road, curbs, sloped ground, buildings, trees and small objects of 16 "
                "classes in clutter) scanned by a simulated mobile LIDAR; per point its object id and class."
              : "The same as 'points generate', with --objects for --truth.");
    scene->add_option("-o,--output", s->output,
                      "The scan (.ply: x y z double, instance and label int, intensity float, colours by class)")
      ->required();
    scene->add_option(name == "generate" ? "--truth" : "--objects", s->objects,
                      "The ground-truth objects (.json: id, class, location, height, bbox, scanned_points)");
    scene->add_option("--report", s->report, "JSON report (parameters, counts, seconds)");
    scene->add_option("--length", s->length, "Length of the street in metres")->capture_default_str();
    scene->add_option("--points", s->points, "Number of mobile LIDAR points wanted (roughly)")->capture_default_str();
    scene->add_option("--objects-per-100m", s->objects_per_100m, "Objects per 100 m of street")->capture_default_str();
    scene->add_option("--noise", s->noise, "Standard deviation of the range noise in metres")->capture_default_str();
    scene->add_flag("--airborne", s->airborne, "Add an airborne pass (points on a 0.5 m grid from above)");
    scene->add_option("--seed", s->seed, "Random seed (same seed, same scene)")->capture_default_str();
    scene->add_option("--threads", s->threads, "Largest number of threads (0: all cores)")->capture_default_str();
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
  background->add_option("--cell", b->cell, "Side of the ground grid's cells (m)")->capture_default_str();
  background->add_option("--ground-threshold", b->threshold, "Points less than this above the ground are ground (m)")
    ->capture_default_str();
  background->add_option("--isolation-radius", b->isolation, "Side of the voxels where neighbours are counted (m)")
    ->capture_default_str();
  background->add_option("--min-neighbors", b->neighbors, "Fewer neighbours: isolated")->capture_default_str();
  background->add_option("--spacing", b->spacing, "Side of the voxels of the connected components (m)")
    ->capture_default_str();
  background->add_option("--max-extent", b->extent, "Components with a wider horizontal extent are removed (m)")
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
  locate->add_option("--shift-radius", l->shift_radius, "Radius of the mean shift's kernel (m)")->capture_default_str();
  locate->add_option("--spacing", l->spacing, "Side of the voxels whose contact makes clusters (cc, m)")
    ->capture_default_str();
  locate->add_option("--cell", l->cell, "Side of the voxels (nc) and of the height image's cells (image), m")
    ->capture_default_str();
  locate->add_option("--cut-threshold", l->cut_threshold, "Normalized cut below which clusters stay apart (nc)")
    ->capture_default_str();
  locate->add_option("--sigma", l->sigma, "Smaller Gaussian of the difference of Gaussians (image, m)")
    ->capture_default_str();
  locate->add_option("--image-threshold", l->image_threshold, "Response of an object's cells (image, m)")
    ->capture_default_str();
  locate->add_option("--min-points", l->minimum, "Smaller clusters are rejected")->capture_default_str();
  locate->add_option("--max-height", l->tallest, "Taller clusters are rejected (m)")->capture_default_str();
  locate->add_option("--radius", l->radius, "Largest horizontal distance of a correct location (m)")->capture_default_str();
  locate->add_option("--threads", l->threads, "Largest number of threads (0: all cores)")->capture_default_str();
  locate->add_flag("-q,--quiet", l->quiet, "No progress on stderr");
  locate->add_flag("-v,--verbose", l->verbose, "Progress on stderr even when it is not a terminal");
  locate->callback([l, &run]() { run = [l]() { return run_locate(*l); }; });
  add_points_segment_commands(points, run);
}

} // namespace shape_analysis_cli
