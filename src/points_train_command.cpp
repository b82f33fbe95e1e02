// Copyright (c) 2026 CGAL Global Shape Analysis contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later

// shape_analysis points train SCAN... --labels labels.csv... [--classifier forest|svm|knn1|knn5]
//                                [--features shape,column,spin,segmentations,context] --output model.json
//                                [--report R.json]
//
// Training a classifier of objects on labelled scans (thesis chapter 4) into one model file
// (recognition_files.h), which `points recognize --model` uses.

#include "points_common.h"
#include "recognition_files.h"

#include <CGAL/Point_set_object_recognition/Object_context.h>
#include <CGAL/Point_set_object_recognition/locate_objects.h>
#include <CGAL/Point_set_object_recognition/remove_background.h>
#include <CGAL/Point_set_object_recognition/train_object_classifier.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <map>
#include <memory>
#include <set>

namespace shape_analysis_cli {

namespace {

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


} // namespace

std::array<double, 4> horizontal_bbox(const CGAL::Point_set_3<Point_3>& points)
{
  std::array<double, 4> b{{1e300, 1e300, -1e300, -1e300}};
  for(const Point_3& p : points.points())
    b = {std::min(b[0], p.x()), std::min(b[1], p.y()), std::max(b[2], p.x()), std::max(b[3], p.y())};
  return b;
}

void add_points_train_command(CLI::App* points, std::function<int()>& run)
{
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
