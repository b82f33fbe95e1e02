// Copyright (c) 2026 CGAL Global Shape Analysis contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_POINT_SET_OBJECT_RECOGNITION_TRAIN_OBJECT_CLASSIFIER_H
#define CGAL_POINT_SET_OBJECT_RECOGNITION_TRAIN_OBJECT_CLASSIFIER_H

/// \file train_object_classifier.h
/// Training a classifier of objects on a labelled scan, and classifying located objects with it
/// (thesis section 4.4).

#include <CGAL/Point_set_object_recognition/extract_object_features.h>
#include <CGAL/Point_set_object_recognition/locate_objects.h>
#include <CGAL/Shape_analysis/Bad_input.h>

#include <array>
#include <cmath>
#include <cstddef>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Point_set_object_recognition {

/// \ingroup PkgPointSetObjectRecognitionRef
/// An object's location and class: a labelled object to learn from, or a classified one.
struct Labelled_location
{
  std::array<double, 3> position{{0, 0, 0}}; ///< its base (x, y, ground height), as `Object_location::position`
  std::size_t label = 0;                     ///< its class index
  double confidence = 1;                     ///< the classifier's confidence (1 for a given label)
};

namespace internal {

inline void check_finite_location(const std::array<double, 3>& p, const std::string& who)
{
  for(double v : p)
    if(!std::isfinite(v))
      throw Bad_input(who + ": a location is not finite");
}

} // namespace internal

/// \ingroup PkgPointSetObjectRecognitionRef
/// The examples a classifier learns from (`object_training_examples()`): one row of features per
/// example and its class.
struct Object_training_examples
{
  Object_features features;        ///< the names of the features and one row per example
  std::vector<std::size_t> labels; ///< per row, its class (`number_of_classes`: background)
  std::vector<std::array<double, 3>> locations; ///< per row, where the features were computed
};

/*!
\ingroup PkgPointSetObjectRecognitionRef
The examples that `train_object_classifier()` learns from on one labelled scan (thesis section
4.4.2): the features (`extract_object_features()`) at the candidate locations (typically those of
`locate_objects()` on the same scan), where objects will be seen when classifying. A labelled
object is an example at each candidate within `background_distance` of it (horizontally), with
its label, or at its own location when no candidate lies that near; a candidate with no labelled
object within `background_distance` is an example of the class `background` (index
`number_of_classes`). Examples of several scans, concatenated, train one classifier on all of
them (as `shape_analysis points train` does).

\tparam PointRange a model of `ConstRange` whose iterator type is `RandomAccessIterator`
\tparam CandidateRange a range of `Object_location` or of `std::array<double, 3>`
\tparam NamedParameters a sequence of named parameters

\param points the points of the scan, without the ground (as for `segment_objects()`)
\param objects the labelled objects, labels below `number_of_classes`
\param number_of_classes the number of object classes (without the background)
\param candidates candidate locations, the unlabelled ones giving background examples
\param background_distance a candidate within this horizontal distance (metres) of a labelled
       object is an example of its class, not of the background (the thesis' match: 1 m)
\param np the named parameters of `extract_object_features()`

\returns the examples: the objects' first (in their order), then the background's

\throws CGAL::Shape_analysis::Bad_input if there is no labelled object, a label is not below
        `number_of_classes`, a location is not finite, `background_distance` is not positive, or
        as `extract_object_features()`
*/
template <typename PointRange, typename CandidateRange, typename NamedParameters = parameters::Default_named_parameters>
Object_training_examples object_training_examples(const PointRange& points, const std::vector<Labelled_location>& objects,
                                                  std::size_t number_of_classes, const CandidateRange& candidates,
                                                  double background_distance = 1.0,
                                                  const NamedParameters& np = parameters::default_values())
{
  const std::string who = "object_training_examples";
  if(objects.empty())
    throw Bad_input(who + ": no labelled object");
  if(!(background_distance > 0) || !std::isfinite(background_distance))
    throw Bad_input(who + ": background_distance must be a positive number");
  for(const Labelled_location& o : objects) {
    internal::check_finite_location(o.position, who);
    if(o.label >= number_of_classes)
      throw Bad_input(who + ": a label is not below number_of_classes");
  }
  const std::vector<std::array<double, 3>> candidate = internal::location_positions(candidates);
  for(const auto& c : candidate)
    internal::check_finite_location(c, who);
  const auto near = [&](const std::array<double, 3>& c, const Labelled_location& o) {
    return std::hypot(c[0] - o.position[0], c[1] - o.position[1]) <= background_distance;
  };
  std::vector<std::array<double, 3>> at;
  Object_training_examples r;
  for(const Labelled_location& o : objects) { // where the classification will see it
    bool seen = false;
    for(const auto& c : candidate)
      if(near(c, o)) {
        at.push_back(c), r.labels.push_back(o.label);
        seen = true;
      }
    if(!seen)
      at.push_back(o.position), r.labels.push_back(o.label);
  }
  for(const auto& c : candidate) { // background: away from every labelled object
    bool away = true;
    for(const Labelled_location& o : objects)
      away = away && !near(c, o);
    if(away)
      at.push_back(c), r.labels.push_back(number_of_classes);
  }
  r.features = extract_object_features(points, at, np);
  r.locations = std::move(at);
  return r;
}

/*!
\ingroup PkgPointSetObjectRecognitionRef
Trains `classifier` on the objects of a labelled scan (thesis section 4.4.2): on the examples of
`object_training_examples()`, that is on the features at the candidate locations, where objects
will be seen when classifying, a candidate away from every labelled object being an example of
the class `background` (index `number_of_classes`). The classifier thus learns
`number_of_classes + 1` classes. (Learning the objects at their true locations only, the random
forest recognized 0.66 / 0.63 of a generated street's objects, against 0.80 / 0.76 this way:
`bench_object_recognition`.)

\tparam Classifier a model of the `ObjectClassifier` concept (\ref ObjectClassifierConcept)
\tparam PointRange a model of `ConstRange` whose iterator type is `RandomAccessIterator`
\tparam CandidateRange a range of `Object_location` or of `std::array<double, 3>`
\tparam NamedParameters a sequence of named parameters

\param classifier the classifier trained (its previous model replaced)
\param points the points of the scan, without the ground (as for `segment_objects()`)
\param objects the labelled objects, labels below `number_of_classes`
\param number_of_classes the number of object classes (without the background)
\param candidates candidate locations, the unlabelled ones giving background examples
\param background_distance a candidate within this horizontal distance (metres) of a labelled
       object is an example of its class, not of the background (the thesis' match: 1 m)
\param np the named parameters of `extract_object_features()`

\returns the features the classifier learned from, one row per example

\throws CGAL::Shape_analysis::Bad_input as `object_training_examples()` and the classifier's
        `train()`
*/
template <typename Classifier, typename PointRange, typename CandidateRange,
          typename NamedParameters = parameters::Default_named_parameters>
Object_features train_object_classifier(Classifier& classifier, const PointRange& points,
                                        const std::vector<Labelled_location>& objects, std::size_t number_of_classes,
                                        const CandidateRange& candidates, double background_distance = 1.0,
                                        const NamedParameters& np = parameters::default_values())
{
  Object_training_examples e =
    object_training_examples(points, objects, number_of_classes, candidates, background_distance, np);
  classifier.train(e.features.values, e.labels, number_of_classes + 1);
  return std::move(e.features);
}

/*!
\ingroup PkgPointSetObjectRecognitionRef
Classifies the objects at `locations` with a trained classifier: their features
(`extract_object_features()`, with the named parameters the classifier was trained with) and the
classifier's prediction, with its confidence. With a classifier trained by
`train_object_classifier()`, the label `number_of_classes` means background (no object).

\tparam Classifier a model of the `ObjectClassifier` concept (\ref ObjectClassifierConcept)
\tparam PointRange a model of `ConstRange` whose iterator type is `RandomAccessIterator`
\tparam LocationRange a range of `Object_location` or of `std::array<double, 3>`
\tparam NamedParameters a sequence of named parameters

\param classifier a trained classifier
\param points the points of the scan, without the ground
\param locations the locations of the objects
\param np the named parameters of `extract_object_features()`

\returns per location (in their order) its position, label and confidence

\throws CGAL::Shape_analysis::Bad_input as `extract_object_features()` and the classifier's
        `predict()` (an untrained classifier, features of another dimension)
*/
template <typename Classifier, typename PointRange, typename LocationRange,
          typename NamedParameters = parameters::Default_named_parameters>
std::vector<Labelled_location> classify_objects(const Classifier& classifier, const PointRange& points,
                                                const LocationRange& locations,
                                                const NamedParameters& np = parameters::default_values())
{
  const std::vector<std::array<double, 3>> at = internal::location_positions(locations);
  std::vector<Labelled_location> r(at.size());
  if(at.empty())
    return r;
  const Object_features f = extract_object_features(points, at, np);
  for(std::size_t k = 0; k < at.size(); ++k) {
    r[k].position = at[k];
    r[k].label = classifier.predict(f.values[k], r[k].confidence);
  }
  return r;
}

/// \ingroup PkgPointSetObjectRecognitionRef
/// Recognition precision and recall of one class (`evaluate_recognition()`).
struct Class_recognition_score
{
  std::size_t predicted = 0; ///< locations given this class
  std::size_t correct = 0;   ///< of those, within the radius of a true object of this class
  std::size_t objects = 0;   ///< true objects of this class
  std::size_t found = 0;     ///< of those, within the radius of a location given this class
  double precision = 1;      ///< correct / predicted (1 when nothing is predicted)
  double recall = 1;         ///< found / objects (1 when there is no object)
};

/*!
\ingroup PkgPointSetObjectRecognitionRef
Evaluates recognition as in the thesis (section 4.4.1): a location given a class is correct when
a true object of that class lies within `radius` of it (horizontally), and a true object is found
when a location given its class lies within `radius` of it. Locations labelled `background` (a
label of `number_of_classes` or more) are left out.

\param predicted the classified locations (`classify_objects()`)
\param truth the true objects, labels below `number_of_classes`
\param number_of_classes the number of object classes
\param radius the largest horizontal distance of a match, in metres (the thesis: 1 m)

\returns per class its counts, precision and recall, then, at index `number_of_classes`, the
         counts over all classes

\throws CGAL::Shape_analysis::Bad_input if `radius` is not positive, a position is not finite or
        a true label is not below `number_of_classes`
*/
inline std::vector<Class_recognition_score> evaluate_recognition(const std::vector<Labelled_location>& predicted,
                                                                 const std::vector<Labelled_location>& truth,
                                                                 std::size_t number_of_classes, double radius = 1.0)
{
  const std::string who = "evaluate_recognition";
  if(!(radius > 0) || !std::isfinite(radius))
    throw Bad_input(who + ": radius must be a positive number");
  for(const Labelled_location& t : truth) {
    internal::check_finite_location(t.position, who);
    if(t.label >= number_of_classes)
      throw Bad_input(who + ": a true label is not below number_of_classes");
  }
  for(const Labelled_location& p : predicted)
    internal::check_finite_location(p.position, who);
  // Per class, the matching of evaluate_locations() between its locations and its objects.
  std::vector<std::vector<Object_location>> located(number_of_classes);
  std::vector<std::vector<std::array<double, 3>>> objects(number_of_classes);
  for(const Labelled_location& p : predicted)
    if(p.label < number_of_classes) {
      Object_location l;
      l.position = p.position;
      located[p.label].push_back(l);
    }
  for(const Labelled_location& t : truth)
    objects[t.label].push_back(t.position);
  std::vector<Class_recognition_score> s(number_of_classes + 1);
  for(std::size_t c = 0; c < number_of_classes; ++c) {
    const Localization_evaluation e = evaluate_locations(located[c], objects[c], radius);
    s[c].predicted = e.number_of_locations, s[c].correct = e.correct_locations;
    s[c].objects = e.number_of_objects, s[c].found = e.found_objects;
  }
  Class_recognition_score& all = s[number_of_classes];
  for(std::size_t c = 0; c < number_of_classes; ++c) {
    all.predicted += s[c].predicted, all.correct += s[c].correct, all.objects += s[c].objects, all.found += s[c].found;
  }
  for(Class_recognition_score& c : s) {
    c.precision = c.predicted == 0 ? 1.0 : double(c.correct) / double(c.predicted);
    c.recall = c.objects == 0 ? 1.0 : double(c.found) / double(c.objects);
  }
  return s;
}

} // namespace Point_set_object_recognition
} // namespace CGAL

#endif // CGAL_POINT_SET_OBJECT_RECOGNITION_TRAIN_OBJECT_CLASSIFIER_H
