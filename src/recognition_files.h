// Copyright (c) 2026 CGAL Global Shape Analysis contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef SHAPE_ANALYSIS_RECOGNITION_FILES_H
#define SHAPE_ANALYSIS_RECOGNITION_FILES_H

// The files of `points train|recognize|evaluate`: labelled objects, and the model file.
//
// Labelled objects (`read_labelled_objects`), one of:
//  - CSV with a header naming its columns: `x`, `y`, `label` required, `z` (the object's base;
//    empty or absent: the ground's height there) and `points` (its number of points) optional;
//  - a boxes file (as in ../shared/data/lidar): `class,x,y,z,length,width,height,yaw[,points]`,
//    a box per row, z its centre (the object's base is z - height / 2);
//  - the JSON truth of `points generate --truth` (class names, locations, scanned points).
// Class names are free text (`background` is reserved); any other column is an error.
//
// The model file (JSON, one object):
//   {"format": "CGAL_Point_set_object_recognition_model", "version": 1,
//    "classes": [names; index i is class i, index <number of classes> is background],
//    "feature_groups": ["shape", "column", "spin", "segmentations", "context"],
//    "feature_names": [the names of extract_object_features(), in order],
//    "columns": [indices into feature_names of the features the classifier reads],
//    "classifier_kind": "knn" | "random_forest" | "svm",
//    "classifier": "<the classifier's own model text (Object_classifiers.h), lines joined by \n>",
//    "context": absent without a street map, else {"grids": "<Context_grids::save() text>",
//       "names": [the context features' names], "classifier": "<a classifier of the same kind
//       reading the columns above then the context features>"}}
// With context, recognition classifies in two stages (the thesis' section 4.3.4): the first
// classifier labels the objects, the grids turn those labels into context features, and the second
// classifier labels them again.

#include "cli_common.h"

#include <CGAL/Point_set_object_recognition/Object_context.h>
#include <CGAL/Point_set_object_recognition/Street_map.h>

#include <array>
#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace shape_analysis_cli {

// A labelled object: its location (z NaN when not given: the ground's height), its class name
// and, when the file says, its number of points (-1 otherwise).
struct Labelled_object
{
  std::array<double, 3> location{{0, 0, 0}};
  std::string name;
  long points = -1;
};

// Throws Cli_error on a file that cannot be read, unknown or missing columns, a value that is
// not a finite number, an empty class name, or no row.
std::vector<Labelled_object> read_labelled_objects(const std::string& path);

// The classifier names of --classifier: forest, svm (when built with libsvm), knn1, knn5.
std::vector<std::string> classifier_names();

// The feature groups given, checked (Usage_error on an unknown or repeated one, or none).
std::vector<std::string> checked_feature_groups(const std::vector<std::string>& groups);

// A classifier of the model file with its feature columns, usable as the `object_classifier` of
// recognize_objects() (a model of ObjectClassifier's predict and is_trained on full rows).
class Model_classifier
{
public:
  typedef std::function<std::size_t(const std::vector<double>&, double&)> Predict;
  Model_classifier(std::shared_ptr<const Predict> predict, std::vector<std::size_t> columns)
    : m_predict(std::move(predict)), m_columns(std::move(columns))
  {}
  bool is_trained() const { return m_predict != nullptr; }
  // The class of the columns of `row` (all of them when no column was given).
  std::size_t predict(const std::vector<double>& row, double& confidence) const;

private:
  std::shared_ptr<const Predict> m_predict;
  std::vector<std::size_t> m_columns;
};

struct Recognition_model
{
  std::vector<std::string> classes, feature_groups, feature_names;
  std::vector<std::size_t> columns;
  std::string kind;          // knn, random_forest, svm
  std::string classifier_text; // the classifier's model text
  bool context = false;        // a second stage with context features
  std::shared_ptr<const CGAL::Point_set_object_recognition::Context_grids> grids;
  std::string context_classifier_text;
  std::vector<std::string> context_names;

  // The columns of the feature groups (from feature_names).
  void select_columns();
  // The selected columns of full rows.
  std::vector<std::vector<double>> selected(const std::vector<std::vector<double>>& rows) const;
  // Trains the classifier named as --classifier (trees, seed: the forest's) on selected rows.
  void train(const std::string& name, const std::vector<std::vector<double>>& rows,
             const std::vector<std::size_t>& labels, std::size_t trees, std::size_t seed);
  // The second stage, with context: trains it on selected rows with their context columns.
  void train_context(const std::string& name, const std::vector<std::vector<double>>& rows,
                     const std::vector<std::size_t>& labels, std::size_t trees, std::size_t seed);
  Model_classifier classifier() const;
  Model_classifier context_classifier() const; // on selected rows followed by their context
  std::string class_name(std::size_t label) const { return label < classes.size() ? classes[label] : "background"; }
  // "label: 0 car, 1 pedestrian, ..., 5 background" for the header of objects.ply.
  std::string label_comment() const;
  void write(std::ostream& out) const;

private:
  mutable std::shared_ptr<const Model_classifier::Predict> m_predict, m_context_predict;
};

// The streets of an OpenStreetMap file in the coordinates of a scan whose (0, 0) is at `origin`
// (easting, northing; empty: 0, 0) of the UTM zone `crs`; throws Cli_error on a bad file or CRS,
// or when no street comes within 100 m of the scan's bounding box `scan` (xmin, ymin, xmax, ymax).
CGAL::Point_set_object_recognition::Street_map read_streets(const std::string& osm, const std::string& crs,
                                                           const std::vector<double>& origin,
                                                           const std::array<double, 4>& scan);

// Reads a model file of `points train`; throws Cli_error saying what is wrong (not a model,
// another version, truncated, features of another version of the library, a classifier model
// that does not load).
Recognition_model read_recognition_model(const std::string& path);

} // namespace shape_analysis_cli

#endif // SHAPE_ANALYSIS_RECOGNITION_FILES_H
