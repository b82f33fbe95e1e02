// Copyright (c) 2026 CGAL Global Shape Analysis contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later

// shape_analysis points segment IN --locations locations.csv --method mincut-auto|mincut|cc|all
//                                  [--radius r] --output objects.ply|.las --report R.json
//                                  [--interactive constraints.csv]
// shape_analysis points evaluate --truth truth.json [--locations locations.csv] [--objects objects.ply]
//                                 --report R.json
// shape_analysis points evaluate --labels labels.csv --locations locations.csv --report R.json
//
// Segmentation of objects from their locations in a raw scan (the ground is estimated and left
// out internally), the evaluation of locations and segmentations against a generated scene's
// truth (the thesis' tables 4.1 and 4.2), and of recognized locations against labelled objects
// (table 4.5; points_recognize_command.cpp has the recognition itself).

#include "points_common.h"

#include <CGAL/Point_set_3.h>
#include <CGAL/Point_set_3/IO/PLY.h>
#include <Shape_analysis_support/Segmentation_json.h>
#include <Shape_analysis_support/Urban_scan.h>
#include <CGAL/Point_set_object_recognition/locate_objects.h>
#include <CGAL/Point_set_object_recognition/read_point_set.h>
#include <CGAL/Point_set_object_recognition/recognize_objects.h>
#include <CGAL/Point_set_object_recognition/remove_background.h>
#include <CGAL/Point_set_object_recognition/segment_objects.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <map>
#include <memory>
#include <regex>
#include <sstream>

namespace shape_analysis_cli {

std::string trim(const std::string& s)
{
  const std::size_t a = s.find_first_not_of(" \t\r\n"), b = s.find_last_not_of(" \t\r\n");
  return a == std::string::npos ? std::string() : s.substr(a, b - a + 1);
}

std::vector<std::string> csv_cells(const std::string& t)
{
  std::vector<std::string> cells;
  std::stringstream ss(t);
  std::string cell;
  while(std::getline(ss, cell, ','))
    cells.push_back(trim(cell));
  if(!t.empty() && t.back() == ',')
    cells.push_back("");
  return cells;
}

bool next_csv_row(std::istream& in, std::size_t& number, std::vector<std::string>& cells)
{
  std::string line;
  while(std::getline(in, line)) {
    ++number;
    if(number == 1 && line.size() >= 3 && (unsigned char)line[0] == 0xEF)
      line = line.substr(3); // UTF-8 byte order mark
    const std::string t = trim(line);
    if(!t.empty()) {
      cells = csv_cells(t);
      return true;
    }
  }
  return false;
}

Locations_file read_locations_file(const std::string& path)
{
  check_input_file(path);
  std::ifstream in(path);
  std::size_t number = 0, columns = 0;
  Locations_file r;
  const auto where = [&]() { return path + ": line " + std::to_string(number) + ": "; };
  const auto number_of = [&](const std::string& cell) { return finite_number(cell, where()); };
  std::vector<std::string> cells;
  while(next_csv_row(in, number, cells)) {
    if(columns == 0) {
      const std::vector<std::string> plain{"x", "y", "z"}, labelled{"x", "y", "z", "label", "confidence"};
      if(cells != plain && cells != labelled)
        throw Cli_error(where() + "the header must be 'x,y,z' or 'x,y,z,label,confidence'");
      columns = cells.size();
      r.labelled = columns == 5;
      continue;
    }
    if(cells.size() != columns)
      throw Cli_error(where() + (columns == 3 ? "expected x,y,z (z may be empty)" : "expected x,y,z,label,confidence"));
    Location l;
    l[0] = number_of(cells[0]), l[1] = number_of(cells[1]);
    l[2] = cells[2].empty() ? std::numeric_limits<double>::quiet_NaN() : number_of(cells[2]);
    r.locations.push_back(l);
    if(r.labelled) {
      if(cells[3].empty())
        throw Cli_error(where() + "the label is empty");
      r.labels.push_back(cells[3]);
      r.confidences.push_back(cells[4].empty() ? std::numeric_limits<double>::quiet_NaN() : number_of(cells[4]));
    }
  }
  if(columns == 0)
    throw Cli_error(path + ": empty (expected a header line 'x,y,z')");
  return r;
}

std::vector<Location> read_locations(const std::string& path)
{
  return read_locations_file(path).locations;
}

// The segmentation method of a command-line name: all, cc, mincut, mincut-auto.
PSOR::Segmentation_method segmentation_method(const std::string& name)
{
  return name == "all"      ? PSOR::Segmentation_method::ALL_WITHIN_RADIUS
         : name == "cc"     ? PSOR::Segmentation_method::CONNECTED_COMPONENTS
         : name == "mincut" ? PSOR::Segmentation_method::MIN_CUT
                            : PSOR::Segmentation_method::MIN_CUT_AUTOMATIC_RADIUS;
}

// The command-line names of the segmentation and localization methods.
const std::vector<std::string> segmentation_method_names{"mincut-auto", "mincut", "cc", "all"};
const std::vector<std::string> localization_method_names{"nc", "cc", "meanshift", "image"};

// The command-line name of a segmentation method.
std::string segmentation_method_name(PSOR::Segmentation_method m)
{
  for(const std::string& name : segmentation_method_names)
    if(segmentation_method(name) == m)
      return name;
  return "mincut-auto";
}

// The command-line name of a localization method.
std::string localization_method_name(PSOR::Localization_method m)
{
  for(const std::string& name : localization_method_names)
    if(localization_method(name) == m)
      return name;
  return "cc";
}

// The report's "objects": per object its location, points, radius, cut and seconds.
Json objects_report(const std::vector<std::array<double, 3>>& locations, const std::vector<PSOR::Object_segmentation>& objects)
{
  Json list = Json::array();
  for(std::size_t k = 0; k < objects.size(); ++k) {
    Json j = Json::object();
    j["location"] = Json(std::vector<double>{locations[k][0], locations[k][1], locations[k][2]});
    j["points"] = objects[k].points.size();
    j["radius"] = objects[k].radius;
    j["cut"] = objects[k].cut_cost;
    j["seconds"] = objects[k].seconds;
    list.push_back(j);
  }
  return list;
}

// Reads the scan of 'points segment' and 'points recognize' in the file's coordinates (no shift:
// doubles keep UTM coordinates to 0.1 um, and the locations are in those coordinates); refuses an
// empty one, and one that has the properties objects.ply adds ('object', 'ground') before any
// work. `read_seconds`: the time it took.
PSOR::Point_set_read_result read_scan_to_segment(const std::string& input, CGAL::Point_set_3<Point_3>& points,
                                                 double& read_seconds)
{
  Stopwatch reading;
  const PSOR::Point_set_read_result read =
    PSOR::read_point_set(input, points, PSOR::parameters::shift_to_local_origin(false));
  read_seconds = reading.seconds();
  if(points.empty())
    throw Cli_error(input + ": the point cloud is empty");
  for(const std::string& name : points.properties())
    if(name == "object" || name == "ground")
      throw Cli_error(input + " already has an 'object' or a 'ground' property");
  return read;
}

namespace {

// The files and switches of the command; the segmentation's options with the library's defaults
// (the method by its command-line name).
struct Segment_options
{
  std::string input, locations, output, report, interactive;
  PSOR::Segment_objects_options segmentation;
  std::string method = segmentation_method_name(segmentation.segmentation_method);
  bool quiet = false, verbose = false;
};

// A constraint of --interactive: a point (x, y, z) the object must hold, or must not.
struct Constraint
{
  bool foreground = true;
  std::array<double, 3> point{{0, 0, 0}};
};

// The lines 'foreground,x,y,z' or 'background,x,y,z' of `path` (a first line that is not one, a
// header, is skipped); Cli_error naming the line otherwise.
std::vector<Constraint> read_constraints(const std::string& path)
{
  std::ifstream in(path);
  if(!in)
    throw Cli_error("cannot open the constraints '" + path + "'");
  std::vector<Constraint> result;
  std::string line;
  for(std::size_t number = 1; std::getline(in, line); ++number) {
    if(!line.empty() && line.back() == '\r')
      line.pop_back();
    if(line.find_first_not_of(" \t") == std::string::npos)
      continue;
    std::vector<std::string> field;
    std::stringstream ss(line);
    for(std::string f; std::getline(ss, f, ',');)
      field.push_back(f.substr(f.find_first_not_of(" \t") == std::string::npos ? f.size() : f.find_first_not_of(" \t")));
    Constraint c;
    const bool kind = !field.empty() && (field[0].rfind("foreground", 0) == 0 || field[0].rfind("background", 0) == 0);
    if(!kind && number == 1)
      continue; // a header
    if(!kind || field.size() != 4)
      throw Cli_error(path + ": line " + std::to_string(number) + ": expected 'foreground,x,y,z' or 'background,x,y,z'");
    c.foreground = field[0].rfind("foreground", 0) == 0;
    for(std::size_t k = 0; k < 3; ++k) {
      std::string cell = field[k + 1];
      cell.erase(cell.find_last_not_of(" \t") + 1); // (leading blanks are gone already)
      c.point[k] = finite_number(cell, path + ": line " + std::to_string(number) + ": ");
    }
    result.push_back(c);
  }
  if(result.empty())
    throw Cli_error(path + ": no constraint (lines 'foreground,x,y,z' or 'background,x,y,z')");
  return result;
}

// `points segment --interactive`: the object of the one location, then each constraint (the
// point above the ground nearest to it) added in order and the cut solved again; per step in
// `steps` (JSON), the last segmentation returned.
PSOR::Object_segmentation segment_interactively(const std::vector<Point_3>& kept, const std::array<double, 3>& location,
                                                const PSOR::Segment_objects_options& so,
                                                const std::vector<Constraint>& constraints, Json& steps)
{
  PSOR::Interactive_segmenter segmenter(kept, location,
                                        PSOR::parameters::segmentation_method(so.segmentation_method)
                                          .background_radius(so.background_radius)
                                          .number_of_threads(so.number_of_threads));
  const auto step_json = [&](const PSOR::Object_segmentation& g, const std::vector<std::size_t>& before) {
    Json j = Json::object();
    j["object_points"] = g.points.size();
    std::vector<std::size_t> diff;
    std::set_difference(g.points.begin(), g.points.end(), before.begin(), before.end(), std::back_inserter(diff));
    j["points_added"] = diff.size();
    diff.clear();
    std::set_difference(before.begin(), before.end(), g.points.begin(), g.points.end(), std::back_inserter(diff));
    j["points_removed"] = diff.size();
    j["cut_cost"] = g.cut_cost;
    j["seconds"] = g.seconds;
    return j;
  };
  steps = Json::array();
  Json first = step_json(segmenter.segmentation(), {});
  first["constraint"] = Json();
  first["radius"] = segmenter.segmentation().radius;
  steps.push_back(first);
  for(const Constraint& c : constraints) {
    std::size_t nearest = 0;
    double best = std::numeric_limits<double>::infinity();
    for(std::size_t i = 0; i < kept.size(); ++i) {
      const double d = CGAL::to_double(CGAL::squared_distance(kept[i], Point_3(c.point[0], c.point[1], c.point[2])));
      if(d < best)
        best = d, nearest = i;
    }
    const std::vector<std::size_t> before = segmenter.segmentation().points;
    const PSOR::Object_segmentation& g = c.foreground ? segmenter.add_foreground(nearest) : segmenter.add_background(nearest);
    Json j = step_json(g, before);
    j["constraint"] = c.foreground ? "foreground" : "background";
    j["at"] = Json(std::vector<double>{c.point[0], c.point[1], c.point[2]});
    j["point_distance"] = std::sqrt(best);
    steps.push_back(j);
  }
  return segmenter.segmentation();
}

int run_segment(const Segment_options& o)
{
  Stopwatch total;
  Progress progress("points segment", o.quiet, o.verbose);
  Output_files outputs;
  outputs.add_input(o.input);
  outputs.add_input(o.locations);
  outputs.add_output(o.output, "segmented point cloud", {".ply", ".las"});
  outputs.add_optional_output(o.report, "report", {".json"});
  PSOR::Segment_objects_options so = o.segmentation;
  so.segmentation_method = segmentation_method(o.method);
  if(!(so.background_radius > 0) || !std::isfinite(so.background_radius))
    throw Usage_error("--radius must be a positive number");

  const std::vector<Location> requested = read_locations(o.locations);
  std::vector<Constraint> constraints;
  if(!o.interactive.empty()) {
    outputs.add_input(o.interactive);
    if(so.segmentation_method != PSOR::Segmentation_method::MIN_CUT &&
       so.segmentation_method != PSOR::Segmentation_method::MIN_CUT_AUTOMATIC_RADIUS)
      throw Usage_error("--interactive needs a min-cut method (mincut or mincut-auto)");
    if(requested.size() != 1)
      throw Cli_error("--interactive segments one object: '" + o.locations + "' has " +
                      std::to_string(requested.size()) + " locations");
    constraints = read_constraints(o.interactive);
  }
  progress.stage("reading " + o.input);
  CGAL::Point_set_3<Point_3> points;
  double read_seconds = 0;
  const PSOR::Point_set_read_result read = read_scan_to_segment(o.input, points, read_seconds);

  progress.stage("estimating the ground of " + std::to_string(points.size()) + " points");
  Stopwatch work;
  std::vector<Point_3> all;
  all.reserve(points.size());
  for(auto i : points)
    all.push_back(points.point(i));
  const PSOR::Background_removal_result background = PSOR::remove_background(all);
  const std::vector<std::size_t> above = PSOR::points_above_ground(background);
  std::vector<Point_3> kept;
  kept.reserve(above.size());
  for(std::size_t i : above)
    kept.push_back(all[i]);
  std::vector<std::array<double, 3>> locations;
  for(const Location& l : requested)
    locations.push_back({l[0], l[1], std::isnan(l[2]) ? background.ground.height(l[0], l[1]) : l[2]});

  progress.stage("segmenting " + std::to_string(locations.size()) + " objects among " + std::to_string(kept.size()) +
                 " points above the ground");
  PSOR::Segmentation_result r;
  Json steps;
  if(!constraints.empty()) {
    if(kept.empty())
      throw Cli_error(o.input + ": every point is ground: nothing to segment");
    r.objects.push_back(segment_interactively(kept, locations.front(), so, constraints, steps));
    r.object_of_point.assign(kept.size(), PSOR::Segmentation_result::no_object);
    for(std::size_t i : r.objects.front().points)
      r.object_of_point[i] = 0;
  } else if(!locations.empty()) {
    if(kept.empty())
      throw Cli_error(o.input + ": every point is ground: nothing to segment");
    r = PSOR::segment_objects(kept, locations,
                              PSOR::parameters::segmentation_method(so.segmentation_method)
                                .background_radius(so.background_radius)
                                .number_of_threads(so.number_of_threads));
  }
  const double seconds = work.seconds();

  progress.stage("writing " + o.output);
  std::vector<int> object(points.size(), -1);
  for(std::size_t k = 0; k < above.size() && !r.object_of_point.empty(); ++k)
    if(r.object_of_point[k] != PSOR::Segmentation_result::no_object)
      object[above[k]] = int(r.object_of_point[k]);
  std::vector<char> ground(points.size(), 0);
  for(std::size_t k = 0; k < ground.size(); ++k)
    ground[k] = background.kind[k] == PSOR::Point_kind::GROUND;
  stage_objects_file(outputs, o.output, o.input, points, object, ground, "points segment");
  if(!o.report.empty()) {
    Json report = Json::object();
    report["command"] = "points segment";
    report["input"] = o.input;
    report["format"] = read.format;
    report["locations_file"] = o.locations;
    report["number_of_points"] = points.size();
    report["ground_points"] = background.number_of_ground_points;
    report["points_above_ground"] = kept.size();
    Json parameters = Json::object();
    parameters["segmentation_method"] = segmentation_method_name(so.segmentation_method);
    parameters["background_radius"] = so.background_radius;
    parameters["number_of_threads"] = so.number_of_threads;
    report["parameters"] = parameters;
    report["seconds_segmentation"] = seconds;
    report["seconds_graph"] = r.preparation_seconds;
    report["objects"] = objects_report(locations, r.objects);
    if(!constraints.empty()) {
      report["interactive"] = o.interactive;
      report["steps"] = steps; // the first: before any constraint
    }
    // "seconds": the whole run, reading included.
    stage_report(outputs, o.report, report, total.seconds(), read_seconds, total.seconds(), {{"objects", o.output}});
  }
  outputs.commit();
  progress.done();
  std::size_t claimed = 0;
  for(int v : object)
    claimed += v >= 0;
  std::cout << o.input << ": " << locations.size() << " objects segmented (" << claimed << " of " << points.size()
            << " points) in " << seconds << " s\n";
  return 0;
}

struct Evaluate_options
{
  std::string truth, labels, locations, objects, report;
  double radius = 1;
  double minimum_points = 0; // labelled objects with fewer points (when their file says) left out
  bool quiet = false;
};

// An integer property of a point set, whatever its integer type in the file.
template <typename Point_set>
bool integer_property(const Point_set& ps, const std::string& name, std::vector<int>& values)
{
  values.clear();
  auto take = [&](auto map) {
    for(auto i : ps)
      values.push_back(int(map[i]));
  };
  if(ps.template has_property_map<int>(name))
    take(ps.template property_map<int>(name).first);
  else if(ps.template has_property_map<unsigned char>(name))
    take(ps.template property_map<unsigned char>(name).first);
  else if(ps.template has_property_map<unsigned int>(name))
    take(ps.template property_map<unsigned int>(name).first);
  else if(ps.template has_property_map<short>(name))
    take(ps.template property_map<short>(name).first);
  else if(ps.template has_property_map<signed char>(name))
    take(ps.template property_map<signed char>(name).first);
  else
    return false;
  return true;
}

// Recognition: the labelled locations against labelled objects (the thesis' table 4.5).
int run_evaluate_recognition(const Evaluate_options& o)
{
  Stopwatch total;
  Output_files outputs;
  outputs.add_input(o.labels);
  outputs.add_input(o.locations);
  outputs.add_optional_output(o.report, "report", {".json"});
  if(o.locations.empty() || !o.objects.empty() || !o.truth.empty())
    throw Usage_error("--labels goes with --locations (a locations.csv of 'points recognize --model') alone");
  if(!(o.radius > 0) || !std::isfinite(o.radius))
    throw Usage_error("--radius must be a positive number");
  Json report = Json::object();
  report["command"] = "points evaluate";
  report["labels"] = o.labels;
  report["locations"] = o.locations;
  Stopwatch work;
  report["recognition"] = evaluate_recognition_files(o.labels, o.locations, o.radius, o.minimum_points);
  if(!o.report.empty())
    stage_report(outputs, o.report, report, work.seconds(), 0.0, total.seconds(), {});
  outputs.commit();
  return 0;
}

int run_evaluate(const Evaluate_options& o)
{
  if(!o.labels.empty())
    return run_evaluate_recognition(o);
  if(o.truth.empty())
    throw Usage_error("give --truth (a generated scene's objects) or --labels (labelled objects)");
  Stopwatch total;
  Output_files outputs;
  outputs.add_input(o.truth);
  if(!o.locations.empty())
    outputs.add_input(o.locations);
  if(!o.objects.empty())
    outputs.add_input(o.objects);
  outputs.add_optional_output(o.report, "report", {".json"});
  if(o.locations.empty() && o.objects.empty())
    throw Usage_error("give --locations, --objects or both");
  if(!(o.radius > 0) || !std::isfinite(o.radius))
    throw Usage_error("--radius must be a positive number");
  const std::vector<Truth_object> truth = read_truth_objects(o.truth);
  if(truth.empty())
    throw Cli_error(o.truth + ": no objects in it (write it with 'points generate --truth')");
  std::map<int, int> class_of_instance;
  std::map<int, std::string> class_names;
  for(const Truth_object& t : truth) {
    class_of_instance[t.id] = t.object_class;
    class_names[t.object_class] = t.name.empty() ? SAS::object_class_name(t.object_class) : t.name;
  }
  const auto name_of = [&](int c) {
    const auto it = class_names.find(c);
    return it == class_names.end() ? std::to_string(c) : it->second;
  };
  Json report = Json::object();
  report["command"] = "points evaluate";
  report["truth"] = o.truth;
  report["objects"] = truth.size();
  Stopwatch work;
  if(!o.locations.empty()) {
    const std::vector<Location> found = read_locations(o.locations);
    std::vector<PSOR::Object_location> locations;
    for(const Location& l : found) {
      PSOR::Object_location ol;
      ol.position = {l[0], l[1], std::isnan(l[2]) ? 0.0 : l[2]};
      locations.push_back(ol);
    }
    std::vector<std::array<double, 2>> all;
    std::map<int, std::vector<std::array<double, 2>>> by_class;
    for(const Truth_object& t : truth) {
      all.push_back({t.location[0], t.location[1]});
      by_class[t.object_class].push_back({t.location[0], t.location[1]});
    }
    const PSOR::Localization_evaluation e = PSOR::evaluate_locations(locations, all, o.radius);
    Json j = Json::object();
    j["radius"] = o.radius;
    j["locations"] = e.number_of_locations;
    j["correct_locations"] = e.correct_locations;
    j["found_objects"] = e.found_objects;
    j["precision"] = e.precision;
    j["recall"] = e.recall;
    Json classes = Json::array();
    std::cout << "Localization (a location within " << o.radius << " m of an object), as the thesis' table 4.1:\n";
    std::cout << std::left << std::setw(24) << "class" << std::right << std::setw(8) << "objects" << std::setw(8)
              << "found" << std::setw(9) << "recall" << "\n";
    for(const auto& c : by_class) {
      const PSOR::Localization_evaluation ec = PSOR::evaluate_locations(locations, c.second, o.radius);
      Json jc = Json::object();
      jc["class"] = name_of(c.first);
      jc["objects"] = ec.number_of_objects;
      jc["found"] = ec.found_objects;
      jc["recall"] = ec.recall;
      classes.push_back(jc);
      std::cout << std::left << std::setw(24) << name_of(c.first) << std::right << std::setw(8) << ec.number_of_objects
                << std::setw(8) << ec.found_objects << std::setw(8) << std::fixed << std::setprecision(1)
                << 100 * ec.recall << "%\n";
    }
    std::cout << std::left << std::setw(24) << "all" << std::right << std::setw(8) << e.number_of_objects << std::setw(8)
              << e.found_objects << std::setw(8) << 100 * e.recall << "%\n"
              << "precision " << 100 * e.precision << "% (" << e.correct_locations << " of " << e.number_of_locations
              << " locations)\n";
    std::cout.unsetf(std::ios::fixed);
    j["classes"] = classes;
    report["localization"] = j;
  }
  if(!o.objects.empty()) {
    CGAL::Point_set_3<Point_3> points;
    PSOR::read_point_set(o.objects, points, PSOR::parameters::shift_to_local_origin(false));
    std::vector<int> object, instance, ground;
    if(!integer_property(points, "object", object))
      throw Cli_error(o.objects + " has no integer 'object' property (write it with 'points segment')");
    if(!integer_property(points, "instance", instance))
      throw Cli_error(o.objects + " has no integer 'instance' property: segment a scan written by 'points generate' "
                                  "(its points keep their true objects)");
    // The ground left out before segmenting is left out of the evaluation.
    if(integer_property(points, "ground", ground))
      for(std::size_t i = 0; i < instance.size(); ++i)
        if(ground[i] != 0)
          instance[i] = -1;
    const PSOR::Segmentation_evaluation e = PSOR::evaluate_labelling(object, instance, class_of_instance);
    std::cout << "Segmentation (points of the matched object, ground left out), as the thesis' table 4.2:\n";
    PSOR::print_segmentation_table(std::cout, e, name_of);
    Json j = SAS::segmentation_evaluation_json(e, name_of);
    Json list = Json::array();
    for(const auto& s : e.objects) {
      Json js = Json::object();
      js["object"] = s.object;
      js["instance"] = s.instance;
      js["class"] = name_of(s.object_class);
      js["segmented_points"] = s.segmented_points;
      js["true_points"] = s.true_points;
      js["precision"] = s.precision;
      js["recall"] = s.recall;
      list.push_back(js);
    }
    j["per_object"] = list;
    report["segmentation"] = j;
  }
  if(!o.report.empty())
    stage_report(outputs, o.report, report, work.seconds(), 0.0, total.seconds(), {});
  outputs.commit();
  return 0;
}

} // namespace

void add_points_segment_commands(CLI::App* points, std::function<int()>& run)
{
  auto s = std::make_shared<Segment_options>();
  CLI::App* segment = points->add_subcommand(
    "segment", "Segment the objects at given locations from a scan (its ground is estimated and left out), by "
               "min-cut with an automatic or fixed background radius, connected components or a radius.");
  segment->add_option("input", s->input, "The scan (.ply, .xyz, .las, .bin), metres, z up")->required();
  segment->add_option("--locations", s->locations,
                      "The locations (.csv: a header line x,y,z, then one location per line; an empty z is the "
                      "ground's height)")
    ->required();
  segment->add_option("--method", s->method, "mincut-auto (radius 1-7 m chosen per object), mincut, cc or all")
    ->capture_default_str()
    ->check(CLI::IsMember({"mincut-auto", "mincut", "cc", "all"}));
  segment->add_option("--radius", s->segmentation.background_radius, "Background radius of mincut, radius of cc and all (m)")
    ->capture_default_str();
  segment->add_option("-o,--output", s->output,
                      "The input's points in input order (.ply or .las) with their properties, 'object' (the "
                      "0-based row of the location, -1 for none) and 'ground' (1: left out as ground); LAS 1.4, "
                      "format 7: these as extra bytes, the classification 2 for ground, 1 for the rest")
    ->required();
  segment->add_option("--report", s->report, "JSON report (seconds; per object: points, radius, cut, seconds)");
  segment->add_option("--interactive", s->interactive,
                      "Constraints on the one object of --locations, added in order (.csv lines "
                      "'foreground,x,y,z' or 'background,x,y,z': the point above the ground nearest to x,y,z "
                      "must or must not be in it), the cut solved again after each (the report's steps); "
                      "the output is the last result");
  segment->add_option("--threads", s->segmentation.number_of_threads, "Largest number of threads (0: all cores)")
    ->capture_default_str();
  segment->add_flag("-q,--quiet", s->quiet, "No progress on stderr");
  segment->add_flag("-v,--verbose", s->verbose, "Progress on stderr even when it is not a terminal");
  segment->callback([s, &run]() { run = [s]() { return run_segment(*s); }; });

  add_points_recognize_commands(points, run);

  auto e = std::make_shared<Evaluate_options>();
  CLI::App* evaluate = points->add_subcommand(
    "evaluate", "Evaluate locations (per class recall, precision) and segmentations (per class precision and "
                "recall of the points) against the truth of a generated scene, or recognized locations against "
                "labelled objects (per class recognition precision and recall).");
  evaluate->add_option("--truth", e->truth, "The true objects (.json written by 'points generate --truth')");
  evaluate->add_option("--labels", e->labels,
                       "Labelled objects (.csv 'x,y,label' or a boxes file 'class,x,y,z,length,width,height,yaw', "
                       "or a --truth .json) to score the labels of --locations against: recognition precision and "
                       "recall per class (the thesis' table 4.5)");
  evaluate->add_option("--min-points", e->minimum_points,
                       "Leave out labelled objects with fewer points, when the labels file says (boxes 'points', "
                       "truth 'scanned_points')")
    ->capture_default_str();
  evaluate->add_option("--locations", e->locations, "Locations to evaluate (.csv: x,y,z)");
  evaluate->add_option("--objects", e->objects,
                       "Segmented points to evaluate (.ply or .las written by 'points segment' or 'points "
                       "recognize' on a generated scan: its 'instance' property holds the truth)");
  evaluate->add_option("--radius", e->radius, "Largest horizontal distance of a correct location (m)")->capture_default_str();
  evaluate->add_option("--report", e->report, "JSON report (tables 4.1 and 4.2: per class and overall)");
  evaluate->add_flag("-q,--quiet", e->quiet, "No progress on stderr");
  evaluate->callback([e, &run]() { run = [e]() { return run_evaluate(*e); }; });
}

} // namespace shape_analysis_cli
