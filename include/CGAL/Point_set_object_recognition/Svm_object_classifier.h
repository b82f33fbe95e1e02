// Copyright (c) 2026 CGAL Global Shape Analysis contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_POINT_SET_OBJECT_RECOGNITION_SVM_OBJECT_CLASSIFIER_H
#define CGAL_POINT_SET_OBJECT_RECOGNITION_SVM_OBJECT_CLASSIFIER_H

#ifndef CGAL_SHAPE_ANALYSIS_USE_LIBSVM
#error "Svm_object_classifier.h needs libsvm: link CGAL::Shape_analysis_svm (Debian libsvm-dev)"
#endif

/// \file Svm_object_classifier.h
/// A support vector machine classifying objects from their feature vectors (A. Golovinskiy's
/// thesis, section 4.4), trained with libsvm.

#include <CGAL/Point_set_object_recognition/Object_classifiers.h>
#include <CGAL/Shape_analysis/Bad_input.h>

#include <libsvm/svm.h>

#include <algorithm>
#include <cfloat>
#include <climits>
#include <cmath>
#include <cstddef>
#include <iomanip>
#include <istream>
#include <memory>
#include <ostream>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Point_set_object_recognition {

namespace internal {

inline void libsvm_prints_nothing(const char*) {}

// libsvm prints its progress to stdout through one global function pointer: set it once, the
// first time a classifier trains (a static local is initialized once, even from several threads).
inline void silence_libsvm()
{
  static const bool silenced = (svm_set_print_string_function(&libsvm_prints_nothing), true);
  (void)silenced;
}

// libsvm's own power by squaring (svm.cpp, powi), so that our kernel values are libsvm's.
inline double libsvm_power(double base, int times)
{
  double tmp = base, result = 1.0;
  for(int t = times; t > 0; t /= 2) {
    if(t % 2 == 1)
      result *= tmp;
    tmp = tmp * tmp;
  }
  return result;
}

// Per coordinate j of the standardized vectors `z` (labels below `classes`), its Fisher score
// F_j = B_j / W_j, the between-class over the within-class sum of squares, W_j at least 0.001
// (B_j + W_j) so that F_j <= 1000 (0 for a constant coordinate), and the weight
// (F_j / mean F)^exponent, at most 100 (all 1 when every F_j is 0 or the exponent is 0).
inline std::vector<double> fisher_weights(const std::vector<std::vector<double>>& z, const std::vector<std::size_t>& labels,
                                          std::size_t classes, double exponent)
{
  const std::size_t d = z.front().size();
  std::vector<double> weights(d, 1.), score(d, 0.);
  if(exponent == 0)
    return weights;
  std::vector<double> count(classes, 0.), mean(d, 0.), class_mean(classes * d, 0.);
  for(std::size_t i = 0; i < z.size(); ++i) {
    count[labels[i]] += 1;
    for(std::size_t j = 0; j < d; ++j)
      mean[j] += z[i][j], class_mean[labels[i] * d + j] += z[i][j];
  }
  for(std::size_t j = 0; j < d; ++j)
    mean[j] /= double(z.size());
  for(std::size_t c = 0; c < classes; ++c)
    for(std::size_t j = 0; j < d && count[c] > 0; ++j)
      class_mean[c * d + j] /= count[c];
  double total = 0;
  for(std::size_t j = 0; j < d; ++j) {
    double between = 0, within = 0;
    for(std::size_t c = 0; c < classes; ++c)
      between += count[c] * (class_mean[c * d + j] - mean[j]) * (class_mean[c * d + j] - mean[j]);
    for(std::size_t i = 0; i < z.size(); ++i)
      within += (z[i][j] - class_mean[labels[i] * d + j]) * (z[i][j] - class_mean[labels[i] * d + j]);
    const double floor = 1e-3 * (between + within);
    score[j] = floor > 0 ? between / (std::max)(within, floor) : 0.;
    total += score[j];
  }
  if(!(total > 0))
    return weights;
  for(std::size_t j = 0; j < d; ++j)
    weights[j] = (std::min)(std::pow(score[j] * double(d) / total, exponent), 100.);
  return weights;
}

} // namespace internal

/*!
\ingroup PkgPointSetObjectRecognitionRef
A support vector machine with a polynomial kernel \f$ K(x, y) = (\gamma\, x' \cdot y' + r)^p \f$, a
model of the `ObjectClassifier` concept (see \ref ObjectClassifierConcept), trained with libsvm's
C-SVC: one-vs-one between the classes present in the training labels, with libsvm's tolerance
0.001 and shrinking. \f$ x' \f$ is the feature vector standardized with the mean and standard
deviation of each coordinate over the training set, each coordinate \f$ j \f$ then multiplied by
the weight \f$ w_j = (F_j / \bar F)^a \f$ (at most 100), where \f$ F_j \f$ is the Fisher score of
the coordinate over the training set (its between-class over its within-class sum of squares, at
most 1000), \f$ \bar F \f$ their mean and \f$ a \f$ the `feature_weight_exponent`: the
coordinates that separate the classes count more (Y.-W. Chen and C.-J. Lin, 2006, select features
for libsvm by such scores).

The thesis (section 4.4) used \f$ C = 2.5 \f$ and \f$ p = 5 \f$ on standardized features, with
libsvm's defaults \f$ \gamma = 1/d \f$ and \f$ r = 0 \f$ (here \f$ a = 0 \f$). Trained on one generated
800 m street and tested on another (`bench_object_recognition`, six pairs of streets), that
setting recognizes 0.56 / 0.54 of the objects (mean precision / recall); \f$ r = 1 \f$, which gives
the kernel every monomial of degree up to \f$ p \f$ rather than those of degree \f$ p \f$ only (an odd
function of \f$ x' \cdot y' \f$ for odd \f$ p \f$), 0.67 / 0.64; the Fisher weights with \f$ a = 1 \f$
0.74 / 0.70 and with \f$ a = 2 \f$ (the default) 0.75 / 0.72, against 0.83 / 0.77 for the random
forest. `C` from 1 to 100 gives the same figures, degree 3 the same as 5, balanced class weights
lower ones (0.72 / 0.66).

The trained model (feature weights, support vectors, their coefficients, the offsets) is copied
out of libsvm, so that copies of a classifier share it, it is never modified in place, and
`predict()` evaluates it without libsvm, from several threads at once, with libsvm's arithmetic:
it returns what libsvm's `svm_predict()` returns. Each one-vs-one decision function votes for one
of its two classes; `predict()` returns the class with most votes (ties: the smaller class index)
and, as confidence, the fraction of its duels that class won, votes / (k - 1) for k classes present
in the training labels (1 when only one is present). Classes absent from the training labels are
never predicted. libsvm's probability estimates are not used: they draw cross-validation folds
with `rand()`, neither deterministic nor thread-safe.

The model file (kind `svm`, see \ref ObjectClassifierConcept) holds, after the standardization,
the parameters (`C`, `degree`, `gamma`, `coef0`, `feature_weight_exponent`, `class_weights`
`uniform` or `balanced`); `kernel_gamma`, the \f$ \gamma \f$ of the kernel; `feature_weights`, the
\f$ w_j \f$; `labels`, the k classes present in the training labels, increasing; `rho`, the offsets
of the k (k - 1) / 2 decision functions (i, j), i < j, in that order; `support_vectors` l and
`per_class`, the number of support vectors of each class; then per support vector, class by
class, its k - 1 coefficients and its d coordinates \f$ x' \f$ (libsvm's `sv_coef` and `SV`). The
function (i, j) of \f$ x' \f$ is the sum, over the support vectors s of classes i and j, of their
coefficient j - 1 (s of class i) or i (s of class j) times \f$ K(x', s) \f$, minus its `rho`;
positive, it votes for i, else for j.

libsvm prints its progress through one process-wide function (`svm_set_print_string_function()`):
the first training sets it to print nothing. (libsvm writes a warning on reaching its iteration
limit to `stderr` directly.)

Needs libsvm (Debian `libsvm-dev`): link the CMake target `CGAL::Shape_analysis_svm`.
*/
class Svm_object_classifier
{
public:
  /// How the cost `C` is weighted per class.
  enum Class_weights
  {
    UNIFORM_WEIGHTS, ///< the same `C` for every class
    BALANCED_WEIGHTS ///< class `c` gets `C n / (k n_c)` (n vectors, n_c of class c, k classes present)
  };

private:
  struct Model
  {
    internal::Classifier_data data;
    double gamma = 0, coef0 = 0; // of the kernel
    int degree = 1;
    std::vector<double> feature_weights; // per coordinate, applied after the standardization
    std::vector<std::size_t> labels;     // the classes present, ascending: libsvm's class order
    std::vector<std::size_t> counts;     // support vectors per class, in that order
    std::vector<double> rho;             // per one-vs-one pair (i, j), i < j, in libsvm's order
    std::vector<double> coefficients;    // per support vector, its k - 1 coefficients (libsvm's sv_coef)
    std::vector<double> vectors;         // per support vector, its d coordinates (standardized, weighted)
  };

  double m_C, m_gamma, m_coef0, m_exponent;
  int m_degree;
  Class_weights m_weights;
  std::shared_ptr<const Model> m_model;

  static bool valid(double C, int degree, double gamma, double coef0, double exponent)
  {
    return C > 0 && std::isfinite(C) && degree >= 1 && degree <= 1024 && gamma >= 0 && std::isfinite(gamma) &&
           std::isfinite(coef0) && exponent >= 0 && std::isfinite(exponent);
  }

  // The standardized and weighted vector.
  static std::vector<double> transform(const Model& m, const std::vector<double>& feature)
  {
    std::vector<double> x = m.data.standardize(feature);
    for(std::size_t j = 0; j < x.size(); ++j)
      x[j] *= m.feature_weights[j];
    return x;
  }

  // libsvm caches kernel values as floats: refuse a kernel that may overflow them (by Cauchy-Schwarz,
  // |K(x, y)| <= (gamma max |x|^2 + |r|)^p).
  static void check_kernel_range(const std::vector<std::vector<double>>& x, const Model& m)
  {
    double largest = 0;
    for(const auto& v : x) {
      double s = 0;
      for(double c : v)
        s += c * c;
      largest = (std::max)(largest, s);
    }
    if(!(internal::libsvm_power(m.gamma * largest + std::abs(m.coef0), m.degree) <= double(FLT_MAX)))
      throw Bad_input("Svm_object_classifier: the kernel values of the training vectors may overflow libsvm's "
                      "single-precision cache: lower gamma, coef0, the degree or the feature weight exponent");
  }

  // Trains libsvm on the vectors `x` (standardized, weighted) and copies its model into `m`.
  void train_libsvm(const std::vector<std::vector<double>>& x, const std::vector<std::size_t>& labels,
                    std::size_t classes, Model& m) const
  {
    const std::size_t n = x.size(), d = m.data.dimension;
    // libsvm numbers the classes in the order it first meets them: sorted by label, that order is
    // ascending, and its vote ties (the first class of most votes) go to the smaller class index.
    std::vector<std::size_t> order(n), per_class(classes, 0);
    for(std::size_t i = 0; i < n; ++i)
      order[i] = i, ++per_class[labels[i]];
    std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return labels[a] < labels[b]; });
    std::vector<svm_node> nodes(n * (d + 1));
    std::vector<svm_node*> rows(n);
    std::vector<double> y(n);
    for(std::size_t r = 0; r < n; ++r) {
      svm_node* row = &nodes[r * (d + 1)];
      for(std::size_t j = 0; j < d; ++j)
        row[j].index = int(j + 1), row[j].value = x[order[r]][j];
      row[d].index = -1, row[d].value = 0;
      rows[r] = row;
      y[r] = double(labels[order[r]]);
    }
    svm_problem problem;
    problem.l = int(n), problem.y = y.data(), problem.x = rows.data();
    std::vector<int> weight_labels;
    std::vector<double> weights;
    const std::size_t present = std::size_t(std::count_if(per_class.begin(), per_class.end(), [](std::size_t c) { return c > 0; }));
    for(std::size_t c = 0; c < classes && m_weights == BALANCED_WEIGHTS; ++c)
      if(per_class[c] > 0)
        weight_labels.push_back(int(c)), weights.push_back(double(n) / (double(present) * double(per_class[c])));
    svm_parameter p{};
    p.svm_type = C_SVC, p.kernel_type = POLY, p.degree = m.degree, p.gamma = m.gamma, p.coef0 = m.coef0;
    p.cache_size = 100, p.eps = 1e-3, p.C = m_C, p.shrinking = 1, p.probability = 0;
    p.nr_weight = int(weights.size()), p.weight_label = weight_labels.data(), p.weight = weights.data();
    if(const char* error = svm_check_parameter(&problem, &p))
      throw Bad_input(std::string("Svm_object_classifier: libsvm refuses the problem: ") + error);
    internal::silence_libsvm();
    svm_model* trained = svm_train(&problem, &p);
    if(trained == nullptr)
      throw Bad_input("Svm_object_classifier: libsvm could not train");
    // Its support vectors point into `nodes`: copy them before libsvm's model is freed.
    std::unique_ptr<svm_model, void (*)(svm_model*)> owner(trained, [](svm_model* t) { svm_free_and_destroy_model(&t); });
    const std::size_t k = std::size_t(trained->nr_class), l = std::size_t(trained->l);
    for(std::size_t i = 0; i < k; ++i)
      m.labels.push_back(std::size_t(trained->label[i])), m.counts.push_back(std::size_t(trained->nSV[i]));
    m.rho.assign(trained->rho, trained->rho + k * (k - 1) / 2);
    m.coefficients.resize(l * (k - 1));
    m.vectors.assign(l * d, 0.);
    for(std::size_t s = 0; s < l; ++s) {
      for(std::size_t c = 0; c + 1 < k; ++c)
        m.coefficients[s * (k - 1) + c] = trained->sv_coef[c][s];
      for(const svm_node* q = trained->SV[s]; q->index != -1; ++q)
        m.vectors[s * d + std::size_t(q->index - 1)] = q->value;
    }
  }

  // The one-vs-one votes of the classes present (libsvm's svm_predict_values and svm_predict).
  static std::vector<std::size_t> votes(const Model& m, const std::vector<double>& x)
  {
    const std::size_t k = m.labels.size(), d = m.data.dimension, l = m.vectors.size() / d;
    std::vector<double> kernel(l);
    for(std::size_t s = 0; s < l; ++s) {
      double dot = 0;
      for(std::size_t j = 0; j < d; ++j)
        dot += x[j] * m.vectors[s * d + j];
      kernel[s] = internal::libsvm_power(m.gamma * dot + m.coef0, m.degree);
    }
    std::vector<std::size_t> start(k, 0), out(k, 0);
    for(std::size_t i = 1; i < k; ++i)
      start[i] = start[i - 1] + m.counts[i - 1];
    std::size_t pair = 0;
    for(std::size_t i = 0; i < k; ++i)
      for(std::size_t j = i + 1; j < k; ++j) {
        double sum = 0;
        for(std::size_t s = start[i]; s < start[i] + m.counts[i]; ++s)
          sum += m.coefficients[s * (k - 1) + j - 1] * kernel[s];
        for(std::size_t s = start[j]; s < start[j] + m.counts[j]; ++s)
          sum += m.coefficients[s * (k - 1) + i] * kernel[s];
        sum -= m.rho[pair++];
        ++out[sum > 0 ? i : j];
      }
    return out;
  }

  // Reads the model after the common header (see save()).
  static void read_model(internal::Model_reader& in, Model& m)
  {
    typedef internal::Model_reader Reader;
    in.expect("kernel_gamma");
    m.gamma = in.real("the kernel's gamma");
    if(!(m.gamma > 0))
      Reader::fail("the kernel's gamma is not positive");
    in.expect("feature_weights");
    for(std::size_t j = 0; j < m.data.dimension; ++j)
      if(m.feature_weights.emplace_back(in.real("a feature weight")) < 0)
        Reader::fail("a feature weight is negative");
    in.expect("labels");
    const std::size_t k = in.count("the number of classes trained", m.data.classes);
    if(k == 0)
      Reader::fail("no class trained");
    for(std::size_t i = 0; i < k; ++i) {
      const std::size_t c = in.count("a class", m.data.classes - 1);
      if(i > 0 && c <= m.labels.back())
        Reader::fail("the classes trained are not in increasing order");
      m.labels.push_back(c);
    }
    in.expect("rho");
    for(std::size_t p = 0; p < k * (k - 1) / 2; ++p)
      m.rho.push_back(in.real("an offset rho"));
    in.expect("support_vectors");
    const std::size_t l = in.count("the number of support vectors", std::size_t(INT_MAX));
    in.expect("per_class");
    std::size_t total = 0;
    for(std::size_t i = 0; i < k; ++i)
      total += m.counts.emplace_back(in.count("a number of support vectors", l));
    if(total != l)
      Reader::fail("the support vectors per class do not add up to " + std::to_string(l));
    for(std::size_t s = 0; s < l; ++s) {
      for(std::size_t i = 0; i + 1 < k; ++i)
        m.coefficients.push_back(in.real("a coefficient"));
      for(std::size_t j = 0; j < m.data.dimension; ++j)
        m.vectors.push_back(in.real("a support vector coordinate"));
    }
    in.expect("end");
  }

public:
  /// A support vector machine with the kernel \f$ (\gamma\, x' \cdot y' + r)^p \f$ and the cost `C`
  /// of a training vector on the wrong side of a margin.
  /// \param C the cost `C` (the thesis: 2.5)
  /// \param degree the degree \f$ p \f$ of the kernel (the thesis: 5)
  /// \param gamma the factor \f$ \gamma \f$; 0 for 1 / dimension
  /// \param coef0 the constant term \f$ r \f$ of the kernel (the thesis, with libsvm's default: 0)
  /// \param feature_weight_exponent the exponent \f$ a \f$ of the Fisher weights of the
  ///        coordinates (0: no weighting, as the thesis)
  /// \param class_weights the weights of `C` per class
  /// \throws Bad_input when `C` is not positive, `degree` is not in [1, 1024], `gamma` or
  ///         `feature_weight_exponent` is negative or a parameter is not finite.
  explicit Svm_object_classifier(double C = 2.5, int degree = 5, double gamma = 0, double coef0 = 1,
                                 double feature_weight_exponent = 2, Class_weights class_weights = UNIFORM_WEIGHTS)
    : m_C(C), m_gamma(gamma), m_coef0(coef0), m_exponent(feature_weight_exponent), m_degree(degree),
      m_weights(class_weights)
  {
    if(!valid(C, degree, gamma, coef0, feature_weight_exponent))
      throw Bad_input("Svm_object_classifier: C must be positive, the degree in [1, 1024], gamma (0: 1/dimension) "
                      "and the feature weight exponent not negative, and every parameter finite");
  }

  /// \returns the cost `C`
  double C() const { return m_C; }
  /// \returns the degree of the kernel
  int degree() const { return m_degree; }
  /// \returns the factor \f$ \gamma \f$ as given (0: 1 / dimension)
  double gamma() const { return m_gamma; }
  /// \returns the constant term of the kernel
  double coef0() const { return m_coef0; }
  /// \returns the exponent of the Fisher weights of the coordinates
  double feature_weight_exponent() const { return m_exponent; }
  /// \returns the weights of `C` per class
  Class_weights class_weights() const { return m_weights; }
  /// \returns the weights of the standardized coordinates learned (empty before training)
  std::vector<double> feature_weights() const { return m_model ? m_model->feature_weights : std::vector<double>(); }
  /// \returns the number of support vectors of the trained model (0 before training)
  std::size_t number_of_support_vectors() const { return m_model ? m_model->vectors.size() / m_model->data.dimension : 0; }
  /// \returns whether a `train()` or a `load()` succeeded
  bool is_trained() const { return m_model != nullptr; }
  /// \returns the dimension of the feature vectors (0 before training)
  std::size_t dimension() const { return m_model ? m_model->data.dimension : 0; }
  /// \returns the number of classes (0 before training)
  std::size_t number_of_classes() const { return m_model ? m_model->data.classes : 0; }

  /// Learns from `features[i]` labelled `labels[i]`, see \ref ObjectClassifierConcept.
  /// \param features the training vectors, all of the same dimension, finite
  /// \param labels their classes, each below `number_of_classes`
  /// \param number_of_classes the number of classes
  /// \throws Bad_input on bad input, when the kernel values may overflow libsvm's cache, or when
  ///         libsvm refuses the problem (the classifier unchanged).
  void train(const std::vector<std::vector<double>>& features, const std::vector<std::size_t>& labels,
             std::size_t number_of_classes)
  {
    auto model = std::make_shared<Model>();
    model->data.prepare(features, labels, number_of_classes);
    const std::size_t n = features.size(), d = model->data.dimension;
    if(n > std::size_t(INT_MAX) / (d + 1) || number_of_classes > std::size_t(INT_MAX))
      throw Bad_input("Svm_object_classifier: too many feature values for libsvm");
    std::vector<std::vector<double>> x(n);
    for(std::size_t i = 0; i < n; ++i)
      x[i] = model->data.standardize(features[i]);
    model->feature_weights = internal::fisher_weights(x, labels, number_of_classes, m_exponent);
    for(auto& v : x)
      for(std::size_t j = 0; j < d; ++j)
        v[j] *= model->feature_weights[j];
    model->gamma = m_gamma > 0 ? m_gamma : 1. / double(d);
    model->coef0 = m_coef0;
    model->degree = m_degree;
    check_kernel_range(x, *model);
    train_libsvm(x, labels, number_of_classes, *model);
    m_model = std::move(model);
  }

  /// The class with most one-vs-one votes, with the fraction of its duels it won in `confidence`.
  /// \param feature a vector of the training dimension
  /// \param confidence receives the votes of the class returned / (k - 1), k classes trained
  /// \returns the class with most votes (the smaller at equal votes), as libsvm's `svm_predict()`
  /// \throws Bad_input when not trained, or on a wrong dimension or a value that is not finite.
  std::size_t predict(const std::vector<double>& feature, double& confidence) const
  {
    if(!m_model)
      throw Bad_input("Svm_object_classifier: predict() before train() or load()");
    const std::vector<std::size_t> v = votes(*m_model, transform(*m_model, feature));
    const std::size_t best = std::size_t(std::max_element(v.begin(), v.end()) - v.begin());
    confidence = v.size() < 2 ? 1. : double(v[best]) / double(v.size() - 1);
    return m_model->labels[best];
  }

  /// Writes the model (kind `svm`), see \ref ObjectClassifierConcept.
  /// \param os the stream written to
  /// \throws Bad_input when not trained.
  void save(std::ostream& os) const
  {
    if(!m_model)
      throw Bad_input("Svm_object_classifier: save() before train() or load()");
    const Model& m = *m_model;
    m.data.write(os, "svm");
    os << std::setprecision(17) << "C " << m_C << " degree " << m_degree << " gamma " << m_gamma << " coef0 "
       << m_coef0 << " feature_weight_exponent " << m_exponent << " class_weights "
       << (m_weights == BALANCED_WEIGHTS ? "balanced" : "uniform") << "\nkernel_gamma " << m.gamma
       << "\nfeature_weights";
    for(double w : m.feature_weights)
      os << ' ' << w;
    os << "\nlabels " << m.labels.size();
    for(std::size_t c : m.labels)
      os << ' ' << c;
    os << "\nrho";
    for(double r : m.rho)
      os << ' ' << r;
    const std::size_t k = m.labels.size(), d = m.data.dimension, l = m.vectors.size() / d;
    os << "\nsupport_vectors " << l << "\nper_class";
    for(std::size_t c : m.counts)
      os << ' ' << c;
    os << '\n';
    for(std::size_t s = 0; s < l; ++s) {
      for(std::size_t i = 0; i + 1 < k; ++i)
        os << m.coefficients[s * (k - 1) + i] << ' ';
      for(std::size_t j = 0; j < d; ++j)
        os << m.vectors[s * d + j] << (j + 1 < d ? ' ' : '\n');
    }
    os << "end\n";
  }

  /// Reads a model written by `save()` (kind `svm`, which also sets the parameters).
  /// \param is the stream read from
  /// \throws Bad_input on a file that is not such a model (the classifier unchanged).
  void load(std::istream& is)
  {
    typedef internal::Model_reader Reader;
    Reader in(is);
    auto model = std::make_shared<Model>();
    model->data = in.header("svm");
    in.expect("C");
    const double C = in.real("C");
    in.expect("degree");
    const int degree = int(in.count("the degree", 1024));
    in.expect("gamma");
    const double gamma = in.real("gamma");
    in.expect("coef0");
    const double coef0 = in.real("coef0");
    in.expect("feature_weight_exponent");
    const double exponent = in.real("the feature weight exponent");
    in.expect("class_weights");
    const std::string w = in.token("the class weights");
    if(w != "uniform" && w != "balanced")
      Reader::fail("class weights '" + w + "', expected 'uniform' or 'balanced'");
    if(!valid(C, degree, gamma, coef0, exponent))
      Reader::fail("C must be positive, the degree at least 1, gamma and the feature weight exponent not negative");
    model->degree = degree, model->coef0 = coef0;
    read_model(in, *model);
    m_C = C, m_degree = degree, m_gamma = gamma, m_coef0 = coef0, m_exponent = exponent;
    m_weights = w == "balanced" ? BALANCED_WEIGHTS : UNIFORM_WEIGHTS;
    m_model = std::move(model);
  }
};

} // namespace Point_set_object_recognition
} // namespace CGAL

#endif // CGAL_POINT_SET_OBJECT_RECOGNITION_SVM_OBJECT_CLASSIFIER_H
