// Copyright (c) 2026 CGAL Global Shape Analysis contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later

// shape_analysis points train SCAN... --labels labels.csv... [--classifier forest|svm|knn1|knn5]
//                                [--features shape,column,spin,segmentations,context] --output model.json
//                                [--report R.json]
// shape_analysis points recognize SCAN --output objects.ply|.las [--model model.json]
//                                    [--locations locations.csv] [--tile-size 100] --report R.json
//
// Recognition of the objects of scans (thesis chapter 4): training a classifier on labelled scans
// into one model file, and finding, segmenting and, with a model, classifying the objects of a
// scan. The model file and the labels files are described in recognition_files.h.

#include "points_common.h"
#include "recognition_files.h"

#include <CGAL/Point_set_object_recognition/Object_context.h>
#include <CGAL/Point_set_object_recognition/locate_objects.h>
#include <CGAL/Point_set_object_recognition/recognize_objects.h>
#include <CGAL/Point_set_object_recognition/remove_background.h>
#include <CGAL/Point_set_object_recognition/train_object_classifier.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <iostream>
#include <map>
#include <memory>
#include <set>
#include <sstream>

namespace shape_analysis_cli {

namespace {

// ------------------------------------------------------------------------------------------
// points train

struct Train_options
{
  std::vector<std::string> inputs, labels;
  std::string output, report, classifier = "forest";
  std::vector<std::string> features; // empty: the classifier's best (see --features)
  std::vector<std::string> classes; // empty: every class of the labels
  double background_distance = 1.0;
  double minimum_points = 0;
  std::size_t trees = 50, seed = 0;
  std::vector<std::string> streets; // one map for every scan, or one per scan
  std::string crs;
  std::vector<double> scan_origin;
  bool quiet = false, verbose = false;
};

// What one labelled scan gives: its examples, its objects learned and its bounding box.
struct Scan_examples
{
  PSOR::Object_training_examples examples;
  std::vector<PSOR::Labelled_location> objects;
  std::array<double, 4> bbox{{0, 0, 0, 0}}; // xmin, ymin, xmax, ymax
  std::size_t number_of_points = 0;
};

std::array<double, 4> horizontal_bbox(const CGAL::Point_set_3<Point_3>& points)
{
  std::array<double, 4> b{{1e300, 1e300, -1e300, -1e300}};
  for(const Point_3& p : points.points())
    b = {std::min(b[0], p.x()), std::min(b[1], p.y()), std::max(b[2], p.x()), std::max(b[3], p.y())};
  return b;
}

// The examples of one scan: its labelled objects of the classes learned (others keep the
// candidates near them out of the background), at its candidates.
Scan_examples scan_examples(const std::string& input, const std::vector<Labelled_object>& labelled,
                            const std::map<std::string, std::size_t>& class_index, const Train_options& o,
                            Progress& progress)
{
  CGAL::Point_set_3<Point_3> points;
  double read_seconds = 0;
  read_scan_to_segment(input, points, read_seconds);
  Scan_examples r;
  r.number_of_points = points.size();
  r.bbox = horizontal_bbox(points);
  progress.stage("locating the objects of " + input);
  std::vector<Point_3> all(points.points().begin(), points.points().end());
  const PSOR::Background_removal_result background = PSOR::remove_background(all);
  std::vector<Point_3> above, foreground;
  for(std::size_t i : PSOR::points_above_ground(background))
    above.push_back(all[i]);
  for(std::size_t i : background.foreground)
    foreground.push_back(all[i]);
  std::vector<std::array<double, 3>> candidates;
  if(!foreground.empty())
    for(const PSOR::Object_location& l : PSOR::locate_objects(foreground).locations)
      candidates.push_back(l.position);
  std::vector<PSOR::Labelled_location> objects;
  std::vector<std::array<double, 2>> ignored;
  for(const Labelled_object& l : labelled) {
    const auto c = class_index.find(l.name);
    if(c == class_index.end() || (l.points >= 0 && double(l.points) < o.minimum_points)) {
      ignored.push_back({l.location[0], l.location[1]});
      continue;
    }
    PSOR::Labelled_location t;
    t.position = {l.location[0], l.location[1],
                  std::isnan(l.location[2]) ? background.ground.height(l.location[0], l.location[1]) : l.location[2]};
    t.label = c->second;
    objects.push_back(t);
  }
  r.objects = objects;
  // Candidates near an object not learned are neither that object nor background.
  candidates.erase(std::remove_if(candidates.begin(), candidates.end(),
                                  [&](const std::array<double, 3>& c) {
                                    for(const auto& i : ignored)
                                      if(std::hypot(c[0] - i[0], c[1] - i[1]) <= o.background_distance)
                                        return true;
                                    return false;
                                  }),
                   candidates.end());
  if(above.empty())
    throw Cli_error(input + ": every point is ground: nothing to learn from");
  progress.stage("features of " + std::to_string(candidates.size()) + " candidates and " +
                 std::to_string(objects.size()) + " labelled objects of " + input);
  if(!objects.empty())
    r.examples = PSOR::object_training_examples(above, objects, class_index.size(), candidates, o.background_distance);
  else { // only background here
    r.examples.features = PSOR::extract_object_features(above, candidates);
    r.examples.labels.assign(candidates.size(), class_index.size());
    r.examples.locations = candidates;
  }
  return r;
}

// The second stage (thesis section 4.3.4): context grids learned from the true objects of every
// scan, the context features of every example from them, a classifier trained on the examples'
// selected columns (`rows`, the first stage's) followed by their context. Scans are set side by side (10,000 km apart along x)
// so that the objects of one never count as neighbours of another's.
void train_context(Recognition_model& model, const std::vector<Scan_examples>& scans,
                   const std::vector<PSOR::Street_map>& maps, std::vector<std::vector<double>> rows,
                   const std::vector<std::size_t>& labels, const Train_options& o)
{
  const double apart = 1e7;
  std::vector<PSOR::Street_map::Street> streets;
  std::vector<PSOR::Labelled_location> objects;
  std::vector<std::array<double, 3>> at;
  for(std::size_t s = 0; s < scans.size(); ++s) {
    const double shift = apart * double(s);
    for(PSOR::Street_map::Street st : maps[s].streets()) {
      for(auto& p : st.points)
        p[0] += shift;
      streets.push_back(st);
    }
    for(PSOR::Labelled_location l : scans[s].objects) {
      l.position[0] += shift;
      objects.push_back(l);
    }
    for(std::array<double, 3> l : scans[s].examples.locations) {
      l[0] += shift;
      at.push_back(l);
    }
  }
  const PSOR::Street_map map(streets);
  auto grids = std::make_shared<PSOR::Context_grids>();
  grids->learn(objects, model.classes.size(), map);
  model.grids = grids;
  const PSOR::Context_features context = PSOR::context_features(at, map, *grids, objects);
  model.context_names = context.names;
  for(std::size_t k = 0; k < rows.size(); ++k)
    rows[k].insert(rows[k].end(), context.values[k].begin(), context.values[k].end());
  model.train_context(o.classifier, rows, labels, o.trees, o.seed);
}

int run_train(const Train_options& o)
{
  Stopwatch total;
  Progress progress("points train", o.quiet, o.verbose);
  Output_files outputs;
  for(const std::string& i : o.inputs)
    outputs.add_input(i);
  for(const std::string& l : o.labels)
    outputs.add_input(l);
  outputs.add_output(o.output, "model", {".json"});
  outputs.add_optional_output(o.report, "report", {".json"});
  if(o.labels.size() != o.inputs.size())
    throw Usage_error("give one --labels file per scan (" + std::to_string(o.inputs.size()) + " scans, " +
                      std::to_string(o.labels.size()) + " labels files)");
  if(!(o.background_distance > 0) || !std::isfinite(o.background_distance))
    throw Usage_error("--background-distance must be a positive number");
  Recognition_model model;
  // The SVM does best on the few shape and column features (the spin image's 50 bins dilute its
  // kernel: bench_object_recognition), the others on every feature.
  const std::vector<std::string> features =
    !o.features.empty()       ? o.features
    : o.classifier == "svm" ? std::vector<std::string>{"shape", "column", "context"}
                              : std::vector<std::string>{"shape", "column", "spin", "segmentations", "context"};
  model.feature_groups = checked_feature_groups(features);
  std::vector<std::vector<Labelled_object>> labelled;
  std::set<std::string> names;
  for(const std::string& l : o.labels) {
    labelled.push_back(read_labelled_objects(l));
    for(const Labelled_object& x : labelled.back())
      names.insert(x.name);
  }
  if(!o.classes.empty()) {
    for(const std::string& c : o.classes)
      if(!names.count(c))
        throw Usage_error("--classes: no labelled object of the class '" + c + "'");
    names = std::set<std::string>(o.classes.begin(), o.classes.end());
  }
  if(names.count("background"))
    throw Cli_error("the class name 'background' is reserved (the class of places without an object)");
  model.classes.assign(names.begin(), names.end());
  std::map<std::string, std::size_t> class_index;
  for(std::size_t c = 0; c < model.classes.size(); ++c)
    class_index[model.classes[c]] = c;

  const bool context = std::find(features.begin(), features.end(), "context") != features.end();
  if(!o.streets.empty() && o.streets.size() != 1 && o.streets.size() != o.inputs.size())
    throw Usage_error("give one --streets map for every scan, or one per scan");

  Stopwatch work;
  std::vector<std::vector<double>> rows;
  std::vector<std::size_t> labels;
  std::vector<Scan_examples> per_scan;
  std::vector<PSOR::Street_map> maps;
  Json scans = Json::array();
  for(std::size_t s = 0; s < o.inputs.size(); ++s) {
    progress.stage("reading " + o.inputs[s]);
    per_scan.push_back(scan_examples(o.inputs[s], labelled[s], class_index, o, progress));
    PSOR::Object_training_examples& e = per_scan.back().examples;
    if(context && !o.streets.empty())
      maps.push_back(read_streets(o.streets[o.streets.size() == 1 ? 0 : s], o.crs, o.scan_origin, per_scan.back().bbox));
    if(model.feature_names.empty())
      model.feature_names = e.features.names;
    for(std::size_t k = 0; k < e.labels.size(); ++k)
      rows.push_back(std::move(e.features.values[k])), labels.push_back(e.labels[k]);
    scans.push_back({{"input", o.inputs[s]}, {"labels", o.labels[s]}, {"points", per_scan.back().number_of_points},
                     {"labelled_objects", labelled[s].size()}, {"learned_objects", per_scan.back().objects.size()},
                     {"examples", e.labels.size()}});
  }
  if(model.feature_names.empty() || rows.empty())
    throw Cli_error("no example to learn from: no labelled object and no candidate location in the scans");
  if(std::find_if(labels.begin(), labels.end(), [&](std::size_t l) { return l < model.classes.size(); }) == labels.end())
    throw Cli_error("no labelled object of the classes learned (every example is background)");
  model.select_columns();
  progress.stage("training a " + o.classifier + " classifier on " + std::to_string(rows.size()) + " examples of " +
                 std::to_string(model.columns.size()) + " features");
  std::vector<std::vector<double>> chosen = model.selected(rows); // the features of the model
  rows.clear();
  model.train(o.classifier, chosen, labels, o.trees, o.seed);
  std::string context_note = "not asked for";
  if(context && maps.empty())
    context_note = "left out: no street map (--streets)";
  else if(context) {
    progress.stage("context: grids of the labelled objects, a second classifier");
    train_context(model, per_scan, maps, std::move(chosen), labels, o);
    context_note = "used: street distance and class prediction grids";
  }
  const double seconds = work.seconds();

  outputs.stage(o.output, false, [&](std::ostream& out) { model.write(out); });
  if(!o.report.empty()) {
    Json report = Json::object();
    report["command"] = "points train";
    report["scans"] = scans;
    report["classifier"] = model.kind;
    report["classes"] = model.classes;
    report["feature_groups"] = model.feature_groups;
    report["features"] = model.columns.size();
    report["context"] = context_note;
    Json per_class = Json::object();
    for(std::size_t c = 0; c <= model.classes.size(); ++c)
      per_class[model.class_name(c)] = std::count(labels.begin(), labels.end(), c);
    report["examples"] = per_class;
    report["background_distance"] = o.background_distance;
    stage_report(outputs, o.report, report, seconds, 0.0, total.seconds(), {{"model", o.output}});
  }
  outputs.commit();
  progress.done();
  std::cout << o.output << ": a " << model.kind << " classifier of " << model.classes.size() << " classes (and background) "
            << "trained on " << labels.size() << " examples of " << o.inputs.size() << " scans in " << seconds
            << " s; context " << context_note << "\n";
  return 0;
}

// ------------------------------------------------------------------------------------------
// points recognize

// The files and switches of the command; the recognition's options with the library's defaults
// (the methods by their command-line names, the tile origin as given).
struct Recognize_options
{
  std::string input, output, locations, report, model;
  PSOR::Recognize_objects_options recognition;
  std::string method = localization_method_name(recognition.localization_method);
  std::string segmentation = segmentation_method_name(recognition.segmentation_method);
  std::vector<double> origin; // empty: none
  std::string streets, crs;
  std::vector<double> scan_origin;
  bool quiet = false, verbose = false;
};

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
  Progress progress("points recognize", o.quiet, o.verbose);
  Output_files outputs;
  outputs.add_input(o.input);
  if(!o.model.empty())
    outputs.add_input(o.model);
  outputs.add_output(o.output, "segmented point cloud", {".ply", ".las"});
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

  progress.stage("reading " + o.input);
  CGAL::Point_set_3<Point_3> points;
  double read_seconds = 0;
  const PSOR::Point_set_read_result read = read_scan_to_segment(o.input, points, read_seconds);
  PSOR::Street_map map;
  if(!o.streets.empty())
    map = read_streets(o.streets, o.crs, o.scan_origin, horizontal_bbox(points));

  std::ostringstream stage;
  stage << (model ? "recognizing and classifying" : "recognizing") << " objects among " << points.size()
        << " points, tiles of " << ro.tile_size << " m";
  progress.stage(stage.str());
  Stopwatch work;
  const auto parameters = PSOR::parameters::tile_size(ro.tile_size)
                            .tile_margin(ro.tile_margin)
                            .localization_method(ro.localization_method)
                            .segmentation_method(ro.segmentation_method)
                            .background_radius(ro.background_radius)
                            .number_of_threads(ro.number_of_threads);
  const auto run = [&](const auto& np) {
    if(o.origin.empty())
      return PSOR::recognize_objects(points, np);
    return PSOR::recognize_objects(points, np.tile_origin(std::array<double, 2>{{o.origin[0], o.origin[1]}}));
  };
  PSOR::Object_recognition_result r = model ? run(parameters.object_classifier(model->classifier())) : run(parameters);
  if(model && model->context)
    classify_with_context(*model, map, r);
  const double seconds = work.seconds();

  progress.stage("writing " + o.output);
  std::vector<int> object(points.size(), -1), label;
  std::vector<char> ground(points.size(), 0);
  if(model)
    label.assign(points.size(), -1);
  for(std::size_t k = 0; k < object.size(); ++k) {
    if(r.object_of_point[k] != PSOR::Object_recognition_result::no_object) {
      object[k] = int(r.object_of_point[k]);
      if(model)
        label[k] = int(r.labels[r.object_of_point[k]]);
    }
    ground[k] = r.kind[k] == PSOR::Point_kind::GROUND;
  }
  std::vector<std::string> class_names;
  if(model)
    for(std::size_t c = 0; c <= model->classes.size(); ++c)
      class_names.push_back(model->class_name(c));
  stage_objects_file(outputs, o.output, o.input, points, object, ground, "points recognize", label,
                     model ? model->label_comment() : std::string(), class_names);
  if(!o.locations.empty())
    outputs.stage(o.locations, false, [&](std::ostream& out) { write_recognized_locations(out, r, model.get()); });
  if(!o.report.empty()) {
    Json report = recognize_report(o, ro, r, model.get());
    report["command"] = "points recognize";
    report["input"] = o.input;
    report["format"] = read.format;
    report["number_of_points"] = points.size();
    report["points_per_second"] = seconds > 0 ? double(points.size()) / seconds : 0.0;
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
  recognize->add_option("input", g->input, "The scan (.ply, .xyz, .las, .bin), metres, z up")->required();
  recognize->add_option("-o,--output", g->output,
                        "The input's points in input order (.ply or .las) with their properties, 'object' (the "
                        "0-based row of the location in --locations, -1 for none), 'ground' (1: ground) and, with "
                        "--model, 'label' (the class index of the point's object; the PLY header comment names the "
                        "classes; an input 'label' becomes 'input_label'). LAS 1.4, format 7: these as extra bytes, "
                        "the classification 2 for ground, 64 + class for classified objects (named in the "
                        "Classification Lookup record), 1 for the rest")
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
  recognize->add_option("--threads", ro.number_of_threads, "Largest number of threads (0: all cores)")
    ->capture_default_str();
  recognize->add_flag("-q,--quiet", g->quiet, "No progress on stderr");
  recognize->add_flag("-v,--verbose", g->verbose, "Progress on stderr even when it is not a terminal");
  recognize->callback([g, &run]() { run = [g]() { return run_recognize(*g); }; });

  auto t = std::make_shared<Train_options>();
  CLI::App* train = points->add_subcommand(
    "train", "Train a classifier of objects on labelled scans: the features at the places where 'points recognize' "
             "finds objects, places away from every labelled object being 'background'; one model file.");
  train->add_option("inputs", t->inputs, "The scans (.ply, .xyz, .las, .bin), metres, z up")->required();
  train->add_option("--labels", t->labels,
                    "Per scan, its labelled objects: .csv with a header 'x,y,label' (or 'x,y,z,label'; z: the base), "
                    "a boxes file 'class,x,y,z,length,width,height,yaw[,points]' (z: the box centre), or the .json "
                    "of 'points generate --truth'")
    ->required();
  train->add_option("--classifier", t->classifier, "forest (random forest), svm, knn1 or knn5")
    ->capture_default_str()
    ->check(CLI::IsMember(classifier_names()));
  train->add_option("--features", t->features,
                    "Feature groups: shape (6 of the object's segmentation), column (5 heights and areas around "
                    "it), spin (its spin image), segmentations (6 of each of two more segmentations), context "
                    "(distance to the nearest street, class patterns along it; needs --streets, left out without "
                    "it). Default: shape,column,context for svm, all for the others")
    ->delimiter(',');
  train->add_option("--streets", t->streets,
                    "OpenStreetMap file(s) (.osm, .osm.pbf; ways tagged highway) covering the scans: one for all, or "
                    "one per scan");
  train->add_option("--crs", t->crs, "The scans' coordinate system, a UTM zone as EPSG:326zz (north) or EPSG:327zz (south)");
  train->add_option("--scan-origin", t->scan_origin,
                    "The UTM easting,northing of the scans' (0,0) (default 0,0: the scans are in UTM coordinates)")
    ->expected(2)
    ->delimiter(',');
  train->add_option("--classes", t->classes, "Learn these classes only (comma-separated names; default: all)")
    ->delimiter(',');
  train->add_option("--background-distance", t->background_distance,
                    "A place farther than this from every labelled object is a background example (m)")
    ->capture_default_str();
  train->add_option("--min-points", t->minimum_points,
                    "Learn no labelled object with fewer points, when the labels file says (boxes 'points', truth "
                    "'scanned_points'); places near it are not background either")
    ->capture_default_str();
  train->add_option("--trees", t->trees, "Trees of the random forest")->capture_default_str();
  train->add_option("--seed", t->seed, "Seed of the random forest")->capture_default_str();
  train->add_option("-o,--output", t->output, "The model file (.json; classes, features, classifier)")->required();
  train->add_option("--report", t->report, "JSON report (scans, examples per class, seconds)");
  train->add_flag("-q,--quiet", t->quiet, "No progress on stderr");
  train->add_flag("-v,--verbose", t->verbose, "Progress on stderr even when it is not a terminal");
  train->callback([t, &run]() { run = [t]() { return run_train(*t); }; });
}

} // namespace shape_analysis_cli
