// Copyright (c) 2026 CGAL Global Shape Analysis contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later

// Labelled objects and the model file of `points train|recognize|evaluate` (recognition_files.h).

#include "recognition_files.h"
#include "points_common.h"

#include <CGAL/Point_set_object_recognition/Object_classifiers.h>
#include <CGAL/Point_set_object_recognition/Object_context.h>
#include <CGAL/Point_set_object_recognition/extract_object_features.h>
#ifdef CGAL_SHAPE_ANALYSIS_USE_LIBSVM
#include <CGAL/Point_set_object_recognition/Svm_object_classifier.h>
#endif
#ifdef CGAL_SHAPE_ANALYSIS_USE_OSMIUM
#include <CGAL/Point_set_object_recognition/read_street_map.h>
#endif

#include <algorithm>
#include <cmath>
#include <fstream>
#include <limits>
#include <map>
#include <set>
#include <sstream>
#include <type_traits>

namespace shape_analysis_cli {

namespace {

const char* const model_format = "CGAL_Point_set_object_recognition_model";

// Feature groups and the prefixes of their columns' names.
const std::vector<std::pair<std::string, std::vector<std::string>>>& feature_group_prefixes()
{
  static const std::vector<std::pair<std::string, std::vector<std::string>>> groups{
    {"shape", {"automatic."}}, {"column", {"column."}}, {"spin", {"spin."}},
    {"segmentations", {"min_cut_4m.", "within_2m."}},
    {"context", {}}}; // context: the second stage's features, not columns of extract_object_features()
  return groups;
}

std::vector<Labelled_object> read_labelled_csv(const std::string& path)
{
  check_input_file(path);
  std::ifstream in(path);
  const std::set<std::string> known{"x", "y", "z", "label", "class", "length", "width", "height", "yaw", "points"};
  std::map<std::string, std::size_t> column;
  std::vector<Labelled_object> r;
  std::size_t number = 0, columns = 0;
  bool boxes = false;
  std::vector<std::string> cells;
  while(next_csv_row(in, number, cells)) {
    const std::string where = path + ": line " + std::to_string(number) + ": ";
    if(columns == 0) {
      for(std::size_t c = 0; c < cells.size(); ++c) {
        if(!known.count(cells[c]))
          throw Cli_error(where + "unknown column '" + cells[c] +
                          "' (labels: x,y,label with z and points optional; boxes: class,x,y,z,length,width,height,"
                          "yaw with points optional)");
        if(!column.emplace(cells[c], c).second)
          throw Cli_error(where + "the column '" + cells[c] + "' appears twice");
      }
      boxes = column.count("class") != 0;
      const std::vector<std::string> need =
        boxes ? std::vector<std::string>{"x", "y", "z", "length", "width", "height", "yaw"} : std::vector<std::string>{"x", "y", "label"};
      for(const std::string& n : need)
        if(!column.count(n))
          throw Cli_error(where + "no column '" + n + "' (labels: x,y,label; boxes: class,x,y,z,length,width,height,yaw)");
      if(boxes && column.count("label"))
        throw Cli_error(where + "both 'class' and 'label' columns: give one");
      if(!boxes && (column.count("length") || column.count("width") || column.count("height") || column.count("yaw")))
        throw Cli_error(where + "box columns without 'class': a boxes file starts 'class,x,y,z,length,width,height,yaw'");
      columns = cells.size();
      continue;
    }
    if(cells.size() != columns)
      throw Cli_error(where + std::to_string(cells.size()) + " values, the header has " + std::to_string(columns));
    Labelled_object o;
    o.location[0] = finite_number(cells[column["x"]], where);
    o.location[1] = finite_number(cells[column["y"]], where);
    o.location[2] = std::numeric_limits<double>::quiet_NaN();
    if(column.count("z") && !(cells[column["z"]].empty() && !boxes))
      o.location[2] = finite_number(cells[column["z"]], where);
    if(boxes) {
      const double height = finite_number(cells[column["height"]], where);
      for(const char* c : {"length", "width", "yaw"})
        finite_number(cells[column[c]], where);
      o.location[2] -= height / 2; // the base of the box
    }
    o.name = cells[column[boxes ? "class" : "label"]];
    if(o.name.empty())
      throw Cli_error(where + "the class name is empty");
    if(column.count("points")) {
      const double p = finite_number(cells[column["points"]], where);
      if(p < 0 || p != std::floor(p))
        throw Cli_error(where + "'points' must be a non-negative integer");
      o.points = long(p);
    }
    r.push_back(o);
  }
  if(columns == 0)
    throw Cli_error(path + ": empty (expected a header line such as 'x,y,label')");
  return r;
}

// The feature names of this version of the library.
std::vector<std::string> library_feature_names()
{
  const std::vector<Point_3> one{Point_3(0, 0, 0)};
  return CGAL::Point_set_object_recognition::extract_object_features(one, std::vector<std::array<double, 3>>()).names;
}

template <typename Classifier>
std::shared_ptr<const Model_classifier::Predict> predictor(const Classifier& c)
{
  return std::make_shared<const Model_classifier::Predict>(
    [c](const std::vector<double>& x, double& confidence) { return c.predict(x, confidence); });
}

// The classifier of a model text of the kind given.
std::shared_ptr<const Model_classifier::Predict> load_classifier(const std::string& kind, const std::string& text)
{
  std::istringstream in(text);
  if(kind == "knn") {
    CGAL::Point_set_object_recognition::Knn_object_classifier c;
    c.load(in);
    return predictor(c);
  }
  if(kind == "random_forest") {
    CGAL::Point_set_object_recognition::Random_forest_object_classifier c;
    c.load(in);
    return predictor(c);
  }
#ifdef CGAL_SHAPE_ANALYSIS_USE_LIBSVM
  if(kind == "svm") {
    CGAL::Point_set_object_recognition::Svm_object_classifier c;
    c.load(in);
    return predictor(c);
  }
#endif
  throw Cli_error("a classifier of kind '" + kind + "', which this build does not have");
}

} // namespace

std::vector<Labelled_object> read_labelled_objects(const std::string& path)
{
  std::vector<Labelled_object> r;
  const bool json = path.size() >= 5 && path.compare(path.size() - 5, 5, ".json") == 0;
  if(json) {
    for(const Truth_object& t : read_truth_objects(path)) {
      Labelled_object o;
      o.location = t.location;
      o.name = t.name.empty() ? "class " + std::to_string(t.object_class) : t.name;
      o.points = t.scanned_points;
      r.push_back(o);
    }
  } else
    r = read_labelled_csv(path);
  if(r.empty())
    throw Cli_error(path + ": no labelled object in it");
  for(const Labelled_object& o : r)
    if(o.name == "background")
      throw Cli_error(path + ": the class name 'background' is reserved (the class of places without an object)");
  return r;
}

std::vector<std::string> classifier_names()
{
#ifdef CGAL_SHAPE_ANALYSIS_USE_LIBSVM
  return {"forest", "svm", "knn1", "knn5"};
#else
  return {"forest", "knn1", "knn5"};
#endif
}

std::vector<std::string> checked_feature_groups(const std::vector<std::string>& groups)
{
  if(groups.empty())
    throw Usage_error("--features: give at least one feature group");
  std::vector<std::string> r;
  for(const std::string& g : groups) {
    const auto& all = feature_group_prefixes();
    if(std::find_if(all.begin(), all.end(), [&](const auto& p) { return p.first == g; }) == all.end())
      throw Usage_error("--features: unknown feature group '" + g + "' (shape, column, spin, segmentations, context)");
    if(std::find(r.begin(), r.end(), g) != r.end())
      throw Usage_error("--features: '" + g + "' given twice");
    r.push_back(g);
  }
  if(r.size() == 1 && r[0] == "context")
    throw Usage_error("--features: context adds to other features: give shape, column, spin or segmentations too");
  return r;
}

std::size_t Model_classifier::predict(const std::vector<double>& row, double& confidence) const
{
  if(m_columns.empty())
    return (*m_predict)(row, confidence);
  std::vector<double> x;
  x.reserve(m_columns.size());
  for(std::size_t c : m_columns)
    x.push_back(row.at(c));
  return (*m_predict)(x, confidence);
}

void Recognition_model::select_columns()
{
  columns.clear();
  for(std::size_t c = 0; c < feature_names.size(); ++c)
    for(const auto& g : feature_group_prefixes())
      if(std::find(feature_groups.begin(), feature_groups.end(), g.first) != feature_groups.end())
        for(const std::string& prefix : g.second)
          if(feature_names[c].compare(0, prefix.size(), prefix) == 0)
            columns.push_back(c);
}

std::vector<std::vector<double>> Recognition_model::selected(const std::vector<std::vector<double>>& rows) const
{
  std::vector<std::vector<double>> r(rows.size());
  for(std::size_t k = 0; k < rows.size(); ++k)
    for(std::size_t c : columns)
      r[k].push_back(rows[k].at(c));
  return r;
}

namespace {

// Trains the classifier named as --classifier; its kind, model text and predictor.
std::string train_classifier(const std::string& name, const std::vector<std::vector<double>>& rows,
                             const std::vector<std::size_t>& labels, std::size_t n, std::size_t trees,
                             std::size_t seed, std::string& kind, std::shared_ptr<const Model_classifier::Predict>& p)
{
  std::ostringstream text;
  try {
    if(name == "knn1" || name == "knn5") {
      CGAL::Point_set_object_recognition::Knn_object_classifier c(name == "knn1" ? 1 : 5);
      c.train(rows, labels, n);
      c.save(text);
      kind = "knn", p = predictor(c);
    } else if(name == "forest") {
      CGAL::Point_set_object_recognition::Random_forest_object_classifier c(trees, 20, (unsigned int)seed);
      c.train(rows, labels, n);
      c.save(text);
      kind = "random_forest", p = predictor(c);
    } else {
#ifdef CGAL_SHAPE_ANALYSIS_USE_LIBSVM
      CGAL::Point_set_object_recognition::Svm_object_classifier c;
      c.train(rows, labels, n);
      c.save(text);
      kind = "svm", p = predictor(c);
#else
      throw Usage_error("--classifier " + name + ": this build has no libsvm (Debian libsvm-dev)");
#endif
    }
  } catch(const CGAL::Shape_analysis::Bad_input& e) {
    throw Cli_error(std::string("training the classifier: ") + e.what());
  }
  return text.str();
}

} // namespace

void Recognition_model::train(const std::string& name, const std::vector<std::vector<double>>& rows,
                              const std::vector<std::size_t>& labels, std::size_t trees, std::size_t seed)
{
  classifier_text = train_classifier(name, rows, labels, classes.size() + 1, trees, seed, kind, m_predict);
}

void Recognition_model::train_context(const std::string& name, const std::vector<std::vector<double>>& rows,
                                      const std::vector<std::size_t>& labels, std::size_t trees, std::size_t seed)
{
  std::string k;
  context_classifier_text = train_classifier(name, rows, labels, classes.size() + 1, trees, seed, k, m_context_predict);
  context = true;
}

Model_classifier Recognition_model::classifier() const
{
  if(!m_predict)
    m_predict = load_classifier(kind, classifier_text);
  return Model_classifier(m_predict, columns);
}

Model_classifier Recognition_model::context_classifier() const
{
  if(!m_context_predict)
    m_context_predict = load_classifier(kind, context_classifier_text);
  return Model_classifier(m_context_predict, {}); // every column: selected features, then context
}

std::string Recognition_model::label_comment() const
{
  std::string s = "label:";
  for(std::size_t c = 0; c <= classes.size(); ++c)
    s += (c ? ", " : " ") + std::to_string(c) + " " + class_name(c);
  return s + " (-1: no object)";
}

void Recognition_model::write(std::ostream& out) const
{
  Json j = Json::object();
  j["format"] = model_format;
  j["version"] = 1;
  j["classes"] = classes;
  j["feature_groups"] = feature_groups;
  j["feature_names"] = feature_names;
  j["columns"] = columns;
  j["classifier_kind"] = kind;
  j["classifier"] = classifier_text;
  if(context) {
    std::ostringstream text;
    grids->save(text);
    j["context"] = {{"grids", text.str()}, {"names", context_names}, {"classifier", context_classifier_text}};
  }
  out << j.dump(1) << '\n';
}

CGAL::Point_set_object_recognition::Street_map read_streets(const std::string& osm, const std::string& crs,
                                                           const std::vector<double>& origin,
                                                           const std::array<double, 4>& scan)
{
#ifdef CGAL_SHAPE_ANALYSIS_USE_OSMIUM
  namespace PSOR = CGAL::Point_set_object_recognition;
  if(crs.empty())
    throw Usage_error("--streets needs --crs (the scan's UTM zone, e.g. EPSG:32618)");
  const std::array<double, 3> at{{origin.empty() ? 0.0 : origin[0], origin.empty() ? 0.0 : origin[1], 0.0}};
  try {
    PSOR::Street_map map = PSOR::read_street_map(osm, crs, at);
    PSOR::check_street_map_overlap(map, CGAL::Bbox_2(scan[0], scan[1], scan[2], scan[3]));
    return map;
  } catch(const CGAL::Shape_analysis::Bad_input& e) {
    throw Cli_error(osm + ": " + e.what());
  }
#else
  (void)crs, (void)origin, (void)scan;
  throw Usage_error("--streets " + osm + ": this build has no libosmium (Debian libosmium2-dev)");
#endif
}

Recognition_model read_recognition_model(const std::string& path)
{
  check_input_file(path);
  std::ifstream in(path);
  Json j;
  try {
    j = Json::parse(in);
  } catch(const Json::exception&) { // (a syntax error, or a number that overflows)
    throw Cli_error(path + ": not a model file of 'points train' (not JSON, or truncated)");
  }
  if(!j.is_object() || j.value("format", std::string()) != model_format)
    throw Cli_error(path + ": not a model file of 'points train' (no \"format\": \"" + std::string(model_format) + "\")");
  Recognition_model m;
  std::string grids_text;
  try {
    const int version = j.at("version").get<int>();
    if(version != 1)
      throw Cli_error(path + ": a model file of version " + std::to_string(version) + "; this tool reads version 1");
    m.classes = j.at("classes").get<std::vector<std::string>>();
    m.feature_groups = j.at("feature_groups").get<std::vector<std::string>>();
    m.feature_names = j.at("feature_names").get<std::vector<std::string>>();
    m.columns = j.at("columns").get<std::vector<std::size_t>>();
    m.kind = j.at("classifier_kind").get<std::string>();
    m.classifier_text = j.at("classifier").get<std::string>();
    if(j.contains("context")) {
      const Json& c = j.at("context");
      m.context = true;
      grids_text = c.at("grids").get<std::string>();
      m.context_names = c.at("names").get<std::vector<std::string>>();
      m.context_classifier_text = c.at("classifier").get<std::string>();
    }
  } catch(const Json::exception& e) {
    throw Cli_error(path + ": a member is missing or of the wrong type (" + e.what() + ")");
  }
  if(m.classes.empty())
    throw Cli_error(path + ": no class");
  if(m.feature_names != library_feature_names())
    throw Cli_error(path + ": its features are not those of this version of the library: train the model again");
  for(std::size_t c : m.columns)
    if(c >= m.feature_names.size())
      throw Cli_error(path + ": a column is not a feature");
  try {
    m.classifier(); // loads and checks it
    if(m.context) {
      m.context_classifier();
      auto g = std::make_shared<CGAL::Point_set_object_recognition::Context_grids>();
      std::istringstream in(grids_text);
      g->load(in);
      m.grids = g;
      if(g->number_of_classes() != m.classes.size() || m.context_names.size() != m.classes.size() + 1)
        throw Cli_error(path + ": its context grids or features do not match its classes");
    }
  } catch(const CGAL::Shape_analysis::Bad_input& e) {
    throw Cli_error(path + ": " + e.what());
  }
  return m;
}

// The ground truth of 'points generate --truth' (locate, evaluate, train).
std::vector<Truth_object> read_truth_objects(const std::string& path)
{
  check_input_file(path);
  std::ifstream in(path);
  Json file;
  try {
    file = Json::parse(in);
  } catch(const Json::exception& e) { // (a syntax error, or a number that overflows)
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
      typedef decltype(fallback) T;
      if constexpr(std::is_integral_v<T>) { // a whole number in T's range (a double out of it is UB)
        const bool whole = it->is_number_integer() || it->is_number_unsigned();
        const bool fits = whole && (it->is_number_unsigned()
                                      ? it->template get<unsigned long long>() <= (unsigned long long)(std::numeric_limits<T>::max())
                                      : it->template get<long long>() >= (long long)(std::numeric_limits<T>::min()) &&
                                          it->template get<long long>() <= (long long)(std::numeric_limits<T>::max()));
        if(!fits)
          throw Cli_error(path + ": \"" + key + "\" of " + which + " is not a whole number in range");
      }
      try {
        return it->template get<T>();
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

} // namespace shape_analysis_cli
