// Copyright (c) 2026 CGAL Global Shape Analysis contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later

// shape_analysis points recognize SCAN --output objects.ply|.las [--model model.json]
//                                    [--locations locations.csv] [--tile-size 100] [--work-dir DIR]
//                                    --report R.json
// shape_analysis points evaluate --labels labels.csv --locations locations.csv
//
// Recognition of the objects of scans (thesis chapter 4): finding, segmenting and, with a model
// of `points train`, classifying the objects of a scan, in memory or out of core
// (recognition_tiles.h), on one process or the ranks of an MPI job. The model file and the labels
// files are described in recognition_files.h.

#include "points_common.h"
#include "recognition_files.h"
#include "recognition_tiles.h"
#include "ranks.h"

#include <CGAL/Point_set_object_recognition/Object_context.h>
#include <CGAL/Point_set_object_recognition/locate_objects.h>
#include <CGAL/Point_set_object_recognition/recognize_objects.h>
#include <CGAL/Point_set_object_recognition/remove_background.h>
#include <CGAL/Point_set_object_recognition/train_object_classifier.h>
#include <CGAL/Shape_analysis/available_processors.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <map>
#include <memory>
#include <set>
#include <sstream>

namespace shape_analysis_cli {

namespace {

// ------------------------------------------------------------------------------------------
// points recognize

// The files and switches of the command; the recognition's options with the library's defaults
// (the methods by their command-line names, the tile origin as given).
struct Recognize_options
{
  std::vector<std::string> inputs; // one without --work-dir
  std::string input, output, locations, report, model, work_dir;
  bool keep_going = false;
  bool only_objects = false;
  PSOR::Recognize_objects_options recognition;
  std::string method = localization_method_name(recognition.localization_method);
  std::string segmentation = segmentation_method_name(recognition.segmentation_method);
  std::vector<double> origin; // empty: none
  std::string streets, crs;
  std::vector<double> scan_origin;
  bool quiet = false, verbose = false;
};

// What decides a tile's result beside the scan and the tiles: the methods, the radius, the model
// (its file's path, size and time).
std::string recognition_identity(const Recognize_options& o, const PSOR::Recognize_objects_options& ro)
{
  std::ostringstream id;
  id.precision(17);
  id << localization_method_name(ro.localization_method) << ' ' << segmentation_method_name(ro.segmentation_method)
     << ' ' << ro.background_radius;
  if(!o.model.empty()) {
    const std::filesystem::path m = std::filesystem::absolute(o.model);
    id << " model " << m.string() << ' ' << std::filesystem::file_size(m) << ' '
       << std::filesystem::last_write_time(m).time_since_epoch().count();
  }
  return id.str();
}

// The second stage of a model with context: the first stage's labels make the context of every
// location, and the context classifier labels them again (`r.labels`, `r.confidences` replaced).
void classify_with_context(const Recognition_model& model, const PSOR::Street_map& map,
                           PSOR::Object_recognition_result& r)
{
  std::vector<PSOR::Labelled_location> first(r.locations.size());
  std::vector<std::array<double, 3>> at(r.locations.size());
  for(std::size_t k = 0; k < first.size(); ++k) {
    at[k] = first[k].position = r.locations[k].position;
    first[k].label = r.labels[k];
  }
  const PSOR::Context_features context = PSOR::context_features(at, map, *model.grids, first);
  const Model_classifier second = model.context_classifier();
  std::vector<std::vector<double>> rows = model.selected(r.features);
  for(std::size_t k = 0; k < at.size(); ++k) {
    std::vector<double>& row = rows[k];
    row.insert(row.end(), context.values[k].begin(), context.values[k].end());
    r.labels[k] = second.predict(row, r.confidences[k]);
  }
}

// locations.csv with, when classified, the columns label and confidence.
void write_recognized_locations(std::ostream& out, const PSOR::Object_recognition_result& r,
                                const Recognition_model* model)
{
  out << std::setprecision(17) << (model ? "x,y,z,label,confidence\n" : "x,y,z\n");
  for(std::size_t k = 0; k < r.locations.size(); ++k) {
    const auto& l = r.locations[k].position;
    out << l[0] << ',' << l[1] << ',' << l[2];
    if(model)
      out << ',' << model->class_name(r.labels[k]) << ',' << std::setprecision(6) << r.confidences[k]
          << std::setprecision(17);
    out << '\n';
  }
}

Json recognize_report(const Recognize_options& o, const PSOR::Recognize_objects_options& ro,
                      const PSOR::Object_recognition_result& r, const Recognition_model* model)
{
  Json report = Json::object();
  Json parameters = Json::object();
  parameters["tile_size"] = ro.tile_size;
  parameters["tile_margin"] = ro.tile_margin;
  if(!o.origin.empty())
    parameters["tile_origin"] = Json(o.origin);
  parameters["localization_method"] = localization_method_name(ro.localization_method);
  parameters["segmentation_method"] = segmentation_method_name(ro.segmentation_method);
  parameters["background_radius"] = ro.background_radius;
  parameters["number_of_threads"] = ro.number_of_threads;
  report["parameters"] = parameters;
  report["largest_tile_points"] = r.largest_tile;
  Json tiles = Json::array();
  for(const PSOR::Scene_tile& t : r.tiles)
    tiles.push_back({{"min", {t.min[0], t.min[1]}}, {"max", {t.max[0], t.max[1]}}, {"points", t.number_of_points},
                     {"locations", t.number_of_locations}, {"seconds", t.seconds}});
  report["tiles"] = tiles;
  std::vector<std::array<double, 3>> at;
  for(const PSOR::Object_location& l : r.locations)
    at.push_back(l.position);
  Json objects = objects_report(at, r.objects);
  if(model) {
    report["model"] = o.model;
    report["classes"] = model->classes;
    Json counts = Json::object();
    for(std::size_t c = 0; c <= model->classes.size(); ++c)
      counts[model->class_name(c)] = std::count(r.labels.begin(), r.labels.end(), c);
    report["objects_per_class"] = counts;
    for(std::size_t k = 0; k < objects.size(); ++k) {
      objects[k]["label"] = model->class_name(r.labels[k]);
      objects[k]["confidence"] = r.confidences[k];
    }
  }
  report["objects"] = objects;
  return report;
}

int run_recognize(const Recognize_options& o)
{
  Stopwatch total;
  const Ranks& ranks = Ranks::world(); // the ranks of an MPI job: rank 0 shows, writes and commits
  const bool first = ranks.rank() == 0;
  Progress progress("points recognize", o.quiet || !first, o.verbose && first);
  Output_files outputs;
  for(const std::string& input : o.inputs)
    outputs.add_input(input);
  if(!o.model.empty())
    outputs.add_input(o.model);
  outputs.add_output(o.output, "segmented point cloud", {".ply", ".las"});
  if(o.inputs.size() > 1 && o.work_dir.empty())
    throw Usage_error("several scans (or a folder) are recognized with --work-dir");
  if(ranks.size() > 1 && o.work_dir.empty())
    throw Usage_error("with several MPI ranks, give --work-dir (a folder that every rank sees)");
  std::error_code special;
  if(ranks.size() > 1 && std::filesystem::exists(o.output, special) && !std::filesystem::is_regular_file(o.output, special))
    throw Usage_error("-o " + o.output + ": the ranks write into the output: it must be a regular file");
  if(o.keep_going && o.work_dir.empty())
    throw Usage_error("--keep-going goes with --work-dir");
  if(!o.locations.empty()) {
    outputs.add_output(o.locations, "locations", {".csv"});
  }
  outputs.add_optional_output(o.report, "report", {".json"});
  PSOR::Recognize_objects_options ro = o.recognition;
  ro.localization_method = localization_method(o.method);
  ro.segmentation_method = segmentation_method(o.segmentation);
  if(!(ro.tile_size > 0) || !std::isfinite(ro.tile_size))
    throw Usage_error("--tile-size must be a positive number");
  if(!(ro.tile_margin >= 0) || !std::isfinite(ro.tile_margin))
    throw Usage_error("--tile-margin must be zero or a positive number");
  if(!(ro.background_radius > 0) || !std::isfinite(ro.background_radius))
    throw Usage_error("--radius must be a positive number");
  std::unique_ptr<Recognition_model> model;
  if(!o.model.empty())
    model = std::make_unique<Recognition_model>(read_recognition_model(o.model));
  if(!o.streets.empty() && !(model && model->context))
    throw Usage_error("--streets: only a model trained with a street map (--features context --streets) uses one");
  if(model && model->context && o.streets.empty())
    throw Usage_error("the model was trained with a street map: give the scan's with --streets and --crs");

  PSOR::Object_recognition_result r;
  Recognition_in_tiles tiled;  // with --work-dir: this rank's part of the scan
  std::vector<int> object;     // without it: every point's object and kind
  std::vector<char> ground;
  std::unique_ptr<Scan_files> reader;  // with --work-dir
  CGAL::Point_set_3<Point_3> points;                   // without it
  double read_seconds = 0, seconds = 0;
  std::uint64_t n = 0;
  Json extra = Json::object();
  std::string format;
  const auto parameters = PSOR::parameters::tile_size(ro.tile_size)
                            .tile_margin(ro.tile_margin)
                            .localization_method(ro.localization_method)
                            .segmentation_method(ro.segmentation_method)
                            .background_radius(ro.background_radius)
                            .number_of_threads(ro.number_of_threads);
  if(!o.work_dir.empty()) {
    reader = std::make_unique<Scan_files>(o.inputs);
    n = reader->number_of_points();
    format = reader->format();
    if(!o.origin.empty())
      ro.tile_origin = std::array<double, 2>{{o.origin[0], o.origin[1]}};
    const Tile_recognizer recognize = [&](const PSOR::Tile_plan& plan, std::size_t t, const std::vector<Point_3>& held) {
      return model ? PSOR::recognize_tile(plan, t, held, parameters.object_classifier(model->classifier()))
                   : PSOR::recognize_tile(plan, t, held, parameters);
    };
    Stopwatch work;
    tiled = recognize_in_tiles(*reader, o.work_dir, ro, recognition_identity(o, ro), o.keep_going, recognize, progress);
    r = std::move(tiled.result);
    if(o.keep_going) {
      Json failed = Json::array();
      for(const auto& f : tiled.failed_tiles)
        failed.push_back({{"tile", f.first}, {"error", f.second}});
      extra["failed_tiles"] = failed;
    }
    extra["work_dir"] = o.work_dir;
    extra["ranks"] = ranks.size();
    extra["tiles_reused"] = tiled.tiles_reused;
    extra["seconds_indexing"] = tiled.seconds_indexing;
    extra["seconds_tiles"] = tiled.seconds_tiles;
    extra["seconds_merging"] = tiled.seconds_merging;
    if(model && model->context)
      classify_with_context(*model, read_streets(o.streets, o.crs, o.scan_origin,
                                                            {{tiled.lowest[0], tiled.lowest[1], tiled.highest[0], tiled.highest[1]}}), r);
    seconds = work.seconds();
  } else {
    progress.stage("reading " + o.input);
    const PSOR::Point_set_read_result read = read_scan_to_segment(o.input, points, read_seconds);
    n = points.size();
    format = read.format;
    PSOR::Street_map map;
    if(!o.streets.empty())
      map = read_streets(o.streets, o.crs, o.scan_origin, horizontal_bbox(points));
    std::ostringstream stage;
    stage << (model ? "recognizing and classifying" : "recognizing") << " objects among " << points.size()
          << " points, tiles of " << ro.tile_size << " m";
    progress.stage(stage.str());
    Stopwatch work;
    const auto run = [&](const auto& np) {
      if(o.origin.empty())
        return PSOR::recognize_objects(points, np);
      return PSOR::recognize_objects(points, np.tile_origin(std::array<double, 2>{{o.origin[0], o.origin[1]}}));
    };
    r = model ? run(parameters.object_classifier(model->classifier())) : run(parameters);
    if(model && model->context)
      classify_with_context(*model, map, r);
    seconds = work.seconds();
    object.assign(points.size(), -1);
    ground.assign(points.size(), 0);
    for(std::size_t k = 0; k < object.size(); ++k) {
      if(r.object_of_point[k] != PSOR::Object_recognition_result::no_object)
        object[k] = int(r.object_of_point[k]);
      ground[k] = r.kind[k] == PSOR::Point_kind::GROUND;
    }
  }

  progress.stage("writing " + o.output);
  // With a model, the class of each point's object (out of core: of each object, 4 bytes per point
  // spared).
  std::vector<int> label;
  if(model && reader)
    for(std::size_t c : r.labels)
      label.push_back(int(c));
  else if(model) {
    label.assign(object.size(), -1);
    for(std::size_t k = 0; k < object.size(); ++k)
      if(object[k] >= 0)
        label[k] = int(r.labels[std::size_t(object[k])]);
  }
  std::vector<std::string> class_names;
  if(model)
    for(std::size_t c = 0; c <= model->classes.size(); ++c)
      class_names.push_back(model->class_name(c));
  if(reader)
    stage_objects_file_in_pieces(outputs, o.output, *reader, tiled, "points recognize", label,
                                 model ? model->label_comment() : std::string(), class_names,
                                 ro.number_of_threads > 0 ? ro.number_of_threads
                                                          : CGAL::Shape_analysis::available_processors(),
                                 o.only_objects);
  else if(o.only_objects)
    stage_object_points_file(outputs, o.output, o.input, points, object, "points recognize", label,
                             model ? model->label_comment() : std::string(), class_names);
  else
    stage_objects_file(outputs, o.output, o.input, points, object, ground, "points recognize", label,
                       model ? model->label_comment() : std::string(), class_names);
  if(!first) // the other ranks wrote their part of the points
    return 0;
  if(!o.locations.empty())
    outputs.stage(o.locations, false, [&](std::ostream& out) { write_recognized_locations(out, r, model.get()); });
  if(!o.report.empty()) {
    Json report = recognize_report(o, ro, r, model.get());
    for(std::size_t k = 0; reader && k < tiled.object_points.size(); ++k) // this rank's points are not all
      report["objects"][k]["points"] = tiled.object_points[k];
    report["command"] = "points recognize";
    report["input"] = o.input;
    if(reader && reader->files().size() > 1)
      report["inputs"] = reader->files();
    report["format"] = format;
    report["number_of_points"] = n;
    report["points_per_second"] = seconds > 0 ? double(n) / seconds : 0.0;
    for(auto it = extra.begin(); it != extra.end(); ++it)
      report[it.key()] = it.value();
    stage_report(outputs, o.report, report, seconds, read_seconds, total.seconds(),
                 {{"objects", o.output}, {"locations", o.locations}});
  }
  outputs.commit();
  progress.done();
  std::cout << o.input << ": " << r.locations.size() << " objects";
  if(model) {
    std::size_t objects = 0;
    for(std::size_t l : r.labels)
      objects += l < model->classes.size();
    std::cout << " (" << objects << " classified as objects, " << r.locations.size() - objects << " as background)";
  }
  std::cout << " in " << r.tiles.size() << " tiles (at most " << r.largest_tile << " points each) in " << seconds
            << " s\n";
  if(!tiled.failed_tiles.empty())
    std::cout << tiled.failed_tiles.size() << " tiles failed and were left out (the report's failed_tiles; run again "
              << "to try them again)\n";
  return 0;
}

} // namespace

// ------------------------------------------------------------------------------------------
// points evaluate --labels

Json evaluate_recognition_files(const std::string& labels_path, const std::string& locations_path, double radius,
                                double minimum_points)
{
  const std::vector<Labelled_object> truth = read_labelled_objects(labels_path);
  const Locations_file found = read_locations_file(locations_path);
  if(!found.labelled)
    throw Cli_error(locations_path + ": no 'label' column (write it with 'points recognize --model')");
  std::set<std::string> names;
  for(const Labelled_object& t : truth)
    names.insert(t.name);
  for(const std::string& l : found.labels)
    if(l != "background")
      names.insert(l);
  const std::vector<std::string> classes(names.begin(), names.end());
  const auto index = [&](const std::string& name) {
    return std::size_t(std::lower_bound(classes.begin(), classes.end(), name) - classes.begin());
  };
  std::vector<PSOR::Labelled_location> t, p;
  for(const Labelled_object& x : truth)
    if(x.points < 0 || double(x.points) >= minimum_points) {
      PSOR::Labelled_location l;
      l.position = {x.location[0], x.location[1], 0.0};
      l.label = index(x.name);
      t.push_back(l);
    }
  for(std::size_t k = 0; k < found.locations.size(); ++k) {
    PSOR::Labelled_location l;
    l.position = {found.locations[k][0], found.locations[k][1], 0.0};
    l.label = found.labels[k] == "background" ? classes.size() : index(found.labels[k]);
    p.push_back(l);
  }
  const std::vector<PSOR::Class_recognition_score> s = PSOR::evaluate_recognition(p, t, classes.size(), radius);
  std::cout << "Recognition (a label is correct within " << radius << " m of an object of its class), as the thesis' "
            << "table 4.5:\n"
            << std::left << std::setw(24) << "class" << std::right << std::setw(8) << "objects" << std::setw(7) << "found"
            << std::setw(8) << "recall" << std::setw(10) << "predicted" << std::setw(8) << "correct" << std::setw(11)
            << "precision\n";
  Json j = Json::object();
  j["radius"] = radius;
  Json per_class = Json::array();
  for(std::size_t c = 0; c <= classes.size(); ++c) {
    const std::string name = c < classes.size() ? classes[c] : "all";
    std::cout << std::left << std::setw(24) << name << std::right << std::setw(8) << s[c].objects << std::setw(7)
              << s[c].found << std::setw(8) << std::fixed << std::setprecision(3) << s[c].recall << std::setw(10)
              << s[c].predicted << std::setw(8) << s[c].correct << std::setw(10) << s[c].precision << "\n";
    std::cout.unsetf(std::ios::fixed);
    Json jc = {{"class", name},          {"objects", s[c].objects}, {"found", s[c].found},
               {"recall", s[c].recall},  {"predicted", s[c].predicted}, {"correct", s[c].correct},
               {"precision", s[c].precision}};
    if(c < classes.size())
      per_class.push_back(jc);
    else
      j["all"] = jc;
  }
  j["classes"] = per_class;
  return j;
}

void add_points_recognize_commands(CLI::App* points, std::function<int()>& run)
{
  auto g = std::make_shared<Recognize_options>();
  CLI::App* recognize = points->add_subcommand(
    "recognize", "Find and segment the objects of a scan of any size, tile by tile (ground estimate, background "
                 "removal, localization, min-cut segmentation), tiles in parallel: the memory of one tile per "
                 "thread; with --model, classify them.");
  recognize->add_option("input", g->inputs,
                        "The scan (.ply, .xyz, .las, .bin), metres, z up; with --work-dir, several scans or folders "
                        "of them (their .las, .ply and .bin files by name) with the same properties, recognized as "
                        "one (their points one after the other in the outputs)")
    ->required();
  recognize->add_option("-o,--output", g->output,
                        "The input's points in input order (.ply or .las) with their properties, 'object' (the "
                        "0-based row of the location in --locations, -1 for none), 'ground' (1: ground) and, with "
                        "--model, 'label' (the class index of the point's object; the PLY header comment names the "
                        "classes; an input 'label' becomes 'input_label'). LAS 1.4, format 7: these as extra bytes, "
                        "the classification 2 for ground, 64 + class for classified objects (named in the "
                        "Classification Lookup record), 1 for the rest; a LAS scan's scale, offset and coordinate system "
                        "records kept")
    ->required();
  recognize->add_option("--locations", g->locations,
                        "The locations found (.csv: a header line x,y,z, then one per line; with --model the "
                        "columns label and confidence too)");
  recognize->add_option("--model", g->model, "A model file of 'points train': classify each object");
  recognize->add_option("--streets", g->streets,
                        "OpenStreetMap file (.osm, .osm.pbf) of the scan's streets, for a model trained with context");
  recognize->add_option("--crs", g->crs, "The scan's coordinate system, a UTM zone as EPSG:326zz or EPSG:327zz");
  recognize->add_option("--scan-origin", g->scan_origin,
                        "The UTM easting,northing of the scan's (0,0) (default 0,0: the scan is in UTM coordinates)")
    ->expected(2)
    ->delimiter(',');
  PSOR::Recognize_objects_options& ro = g->recognition;
  recognize->add_option("--tile-size", ro.tile_size, "Side of the square tiles (m)")->capture_default_str();
  recognize->add_option("--tile-margin", ro.tile_margin, "Band around a tile whose points it is processed with (m)")
    ->capture_default_str();
  recognize->add_option("--tile-origin", g->origin,
                        "A corner of the tiles' grid, x,y (default: the corner of the bounding box); separate runs "
                        "on bands of a scene with one origin have the same tiles")
    ->expected(2)
    ->delimiter(',');
  recognize->add_option("--method", g->method, "Localization: nc, cc, meanshift or image")
    ->capture_default_str()
    ->check(CLI::IsMember({"nc", "cc", "meanshift", "image"}));
  recognize->add_option("--segmentation", g->segmentation, "mincut-auto (radius 1-7 m chosen per object), mincut, cc or all")
    ->capture_default_str()
    ->check(CLI::IsMember({"mincut-auto", "mincut", "cc", "all"}));
  recognize->add_option("--radius", ro.background_radius, "Background radius of mincut, radius of cc and all (m)")
    ->capture_default_str();
  recognize->add_option("--report", g->report,
                        "JSON report (seconds, points per second, tiles; per object: location, points, radius, cut, "
                        "seconds, and with --model label and confidence)");
  recognize->add_option("--work-dir", g->work_dir,
                        "Work out of core in this folder (created if needed): the scan (LAS, binary PLY or KITTI) "
                        "is read piece by piece, each tile's points are written here and its result once it is "
                        "done; memory holds the tiles in flight and about 4.2 bytes per point. A run stopped midway goes "
                        "on from the finished tiles when run again with the same scan and options. Under mpirun, "
                        "the ranks share the work (the folder must be one they all see)");
  recognize->add_flag("--only-objects", g->only_objects,
                      "Write only the points of the objects found to --output (in input order, with the same "
                      "properties), not the whole scan: a city's objects are a few percent of its points");
  recognize->add_flag("--keep-going", g->keep_going,
                      "With --work-dir: a tile that cannot be processed is reported (the report's failed_tiles) "
                      "and left out (its points neither ground nor in an object) instead of failing the run; "
                      "the next run tries it again");
  recognize->add_option("--threads", ro.number_of_threads, "Largest number of threads (0: all cores)")
    ->capture_default_str();
  recognize->add_flag("-q,--quiet", g->quiet, "No progress on stderr");
  recognize->add_flag("-v,--verbose", g->verbose, "Progress on stderr even when it is not a terminal");
  recognize->callback([g, &run]() {
    g->input = g->inputs.front();
    run = [g]() { return run_recognize(*g); };
  });

  add_points_train_command(points, run);
}

} // namespace shape_analysis_cli
