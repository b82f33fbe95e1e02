// Copyright (c) 2026 CGAL Global Shape Analysis contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_POINT_SET_OBJECT_RECOGNITION_INTERNAL_CLASSIFIER_DATA_H
#define CGAL_POINT_SET_OBJECT_RECOGNITION_INTERNAL_CLASSIFIER_DATA_H

// What the object classifiers share: the checked training input and its standardization, and
// the strict reading of the tokens of a model file (Object_classifiers.h documents the format).

#include <CGAL/Point_set_object_recognition/internal/Token_reader.h>
#include <CGAL/Shape_analysis/Bad_input.h>

#include <cmath>
#include <cstdlib>
#include <iomanip>
#include <istream>
#include <ostream>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Point_set_object_recognition {

using CGAL::Shape_analysis::Bad_input;

namespace internal {

// Feature vectors checked, their dimension, the number of classes and the standardization.
class Classifier_data
{
public:
  std::size_t dimension = 0, classes = 0;
  std::vector<double> mean, scale;

  bool trained() const { return dimension != 0; }

  // Checks the training input (throws Bad_input) and computes the standardization.
  void prepare(const std::vector<std::vector<double>>& features, const std::vector<std::size_t>& labels,
               std::size_t number_of_classes)
  {
    if(features.empty())
      throw Bad_input("classifier training: no feature vector");
    if(features.size() != labels.size())
      throw Bad_input("classifier training: " + std::to_string(features.size()) + " feature vectors but " +
                      std::to_string(labels.size()) + " labels");
    if(number_of_classes == 0)
      throw Bad_input("classifier training: the number of classes is 0");
    const std::size_t d = features.front().size();
    if(d == 0)
      throw Bad_input("classifier training: feature vectors of dimension 0");
    for(std::size_t i = 0; i < features.size(); ++i) {
      if(features[i].size() != d)
        throw Bad_input("classifier training: feature vector " + std::to_string(i) + " has dimension " +
                        std::to_string(features[i].size()) + ", feature vector 0 has " + std::to_string(d));
      if(labels[i] >= number_of_classes)
        throw Bad_input("classifier training: label " + std::to_string(labels[i]) + " of feature vector " +
                        std::to_string(i) + " is not below the number of classes " +
                        std::to_string(number_of_classes));
      for(double x : features[i])
        if(!std::isfinite(x))
          throw Bad_input("classifier training: feature vector " + std::to_string(i) + " has a value that is not finite");
    }
    Classifier_data out;
    out.dimension = d;
    out.classes = number_of_classes;
    out.mean.assign(d, 0.);
    out.scale.assign(d, 0.);
    for(const auto& f : features)
      for(std::size_t j = 0; j < d; ++j)
        out.mean[j] += f[j];
    for(double& m : out.mean)
      m /= double(features.size());
    for(const auto& f : features)
      for(std::size_t j = 0; j < d; ++j)
        out.scale[j] += (f[j] - out.mean[j]) * (f[j] - out.mean[j]);
    for(double& s : out.scale) {
      s = std::sqrt(s / double(features.size()));
      if(!(s > 0) || !std::isfinite(s))
        s = 1.;
    }
    *this = std::move(out);
  }

  // The standardized vector; throws Bad_input on a wrong dimension or a value that is not finite.
  std::vector<double> standardize(const std::vector<double>& f) const
  {
    if(!trained())
      throw Bad_input("classifier: predict() before train() or load()");
    if(f.size() != dimension)
      throw Bad_input("classifier: feature vector of dimension " + std::to_string(f.size()) +
                      ", the classifier was trained with dimension " + std::to_string(dimension));
    std::vector<double> out(dimension);
    for(std::size_t j = 0; j < dimension; ++j) {
      if(!std::isfinite(f[j]))
        throw Bad_input("classifier: feature value " + std::to_string(j) + " is not finite");
      out[j] = (f[j] - mean[j]) / scale[j];
    }
    return out;
  }

  void write(std::ostream& os, const char* kind) const
  {
    if(!trained())
      throw Bad_input("classifier: save() before train() or load()");
    os << "CGAL_Point_set_object_recognition_classifier 1\n"
       << "kind " << kind << "\ndimension " << dimension << "\nclasses " << classes << "\nmean";
    os << std::setprecision(17);
    for(double m : mean)
      os << ' ' << m;
    os << "\nscale";
    for(double s : scale)
      os << ' ' << s;
    os << '\n';
  }
};

// Strict reading of the tokens of a model file: every failure throws Bad_input.
class Model_reader : public Token_reader
{
public:
  explicit Model_reader(std::istream& is) : Token_reader(is, "classifier model file") {}

  [[noreturn]] static void fail(const std::string& what) { Token_reader::fail_as("classifier model file", what); }

  // Reads the first line, the kind and the standardization.
  Classifier_data header(const std::string& kind)
  {
    first_line("CGAL_Point_set_object_recognition_classifier", "a classifier model");
    expect("kind");
    const std::string k = token("the kind");
    if(k != kind)
      fail("a model of kind '" + k + "', expected '" + kind + "'");
    Classifier_data data;
    expect("dimension");
    data.dimension = count("the dimension", 1u << 20);
    expect("classes");
    data.classes = count("the number of classes", 1u << 20);
    if(data.dimension == 0 || data.classes == 0)
      fail("dimension and number of classes must be positive");
    expect("mean");
    for(std::size_t j = 0; j < data.dimension; ++j)
      data.mean.push_back(real("a mean"));
    expect("scale");
    for(std::size_t j = 0; j < data.dimension; ++j) {
      data.scale.push_back(real("a scale"));
      if(!(data.scale.back() > 0))
        fail("a scale is not positive");
    }
    return data;
  }
};

} // namespace internal

} // namespace Point_set_object_recognition
} // namespace CGAL

#endif // CGAL_POINT_SET_OBJECT_RECOGNITION_INTERNAL_CLASSIFIER_DATA_H
