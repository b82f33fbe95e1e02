// Copyright (c) 2026 CGAL Global Shape Analysis contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later

// The object classifiers (k nearest neighbours, random forest, and with libsvm the support vector
// machine): training labels recovered, well separated Gaussian classes in 6-D classified on
// held-out vectors, votes on overlapping classes, standardization, save/load round trips,
// determinism of the forest, the SVM's predictions equal to libsvm's own, and bad input (training,
// prediction and model files) refused with the classifier left as it was.

#include <CGAL/Point_set_object_recognition/Object_classifiers.h>
#include <CGAL/Shape_analysis/internal/Random.h>
#ifdef CGAL_SHAPE_ANALYSIS_USE_LIBSVM
#include <CGAL/Point_set_object_recognition/Svm_object_classifier.h>
#include <libsvm/svm.h>
#endif

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

namespace {

namespace PSOR = CGAL::Point_set_object_recognition;
using CGAL::Shape_analysis::Bad_input;
typedef std::vector<std::vector<double>> Features;
typedef std::vector<std::size_t> Labels;

struct Data
{
  Features features;
  Labels labels;
};

double normal(CGAL::Shape_analysis::internal::Random_stream& rng)
{
  const double u = 1. - rng.uniform(), v = rng.uniform();
  return std::sqrt(-2. * std::log(u)) * std::cos(2. * 3.141592653589793 * v);
}

// `per_class` vectors of each of `classes` Gaussian classes (standard deviation `sigma`) in
// dimension `d`, centred on random points of [-5,5]^d drawn from `center_seed`.
Data gaussian_classes(std::size_t classes, std::size_t per_class, std::size_t d, double sigma,
                      std::uint64_t center_seed, std::uint64_t sample_seed)
{
  CGAL::Shape_analysis::internal::Random_stream centers(center_seed), rng(sample_seed);
  std::vector<std::vector<double>> c(classes, std::vector<double>(d));
  for(auto& v : c)
    for(double& x : v)
      x = centers.uniform(-5., 5.);
  Data out;
  for(std::size_t i = 0; i < per_class; ++i)
    for(std::size_t k = 0; k < classes; ++k) {
      std::vector<double> f(d);
      for(std::size_t j = 0; j < d; ++j)
        f[j] = c[k][j] + sigma * normal(rng);
      out.features.push_back(f);
      out.labels.push_back(k);
    }
  return out;
}

template <typename Classifier>
std::string text(const Classifier& classifier)
{
  std::ostringstream os;
  classifier.save(os);
  return os.str();
}

template <typename Classifier>
double accuracy(const Classifier& classifier, const Data& data)
{
  std::size_t right = 0;
  for(std::size_t i = 0; i < data.features.size(); ++i) {
    double confidence = -1;
    right += classifier.predict(data.features[i], confidence) == data.labels[i];
    EXPECT_GE(confidence, 0.);
    EXPECT_LE(confidence, 1.);
  }
  return double(right) / double(data.features.size());
}

template <typename Classifier>
void expect_same_predictions(const Classifier& a, const Classifier& b, const Features& features)
{
  for(const auto& f : features) {
    double ca = -1, cb = -2;
    EXPECT_EQ(a.predict(f, ca), b.predict(f, cb));
    EXPECT_EQ(ca, cb);
  }
}

TEST(ObjectClassifiers, KnnOneReturnsTheTrainingLabels)
{
  // Labels unrelated to the positions: only a nearest neighbour that is the point itself works.
  Data data = gaussian_classes(1, 200, 6, 1., 1, 2);
  CGAL::Shape_analysis::internal::Random_stream rng(3);
  for(std::size_t& l : data.labels)
    l = std::size_t(rng.uniform() * 5) % 5;
  PSOR::Knn_object_classifier knn(1);
  knn.train(data.features, data.labels, 5);
  EXPECT_EQ(knn.dimension(), 6u);
  EXPECT_EQ(knn.number_of_classes(), 5u);
  for(std::size_t i = 0; i < data.features.size(); ++i) {
    double confidence = 0;
    EXPECT_EQ(knn.predict(data.features[i], confidence), data.labels[i]);
    EXPECT_EQ(confidence, 1.);
  }
}

TEST(ObjectClassifiers, SeparatedClassesAreClassifiedOnHeldOutVectors)
{
  const Data train = gaussian_classes(4, 60, 6, 1., 11, 12), test = gaussian_classes(4, 100, 6, 1., 11, 13);
  PSOR::Knn_object_classifier knn1(1), knn5(5);
  PSOR::Random_forest_object_classifier forest(50, 20, 7);
  knn1.train(train.features, train.labels, 4);
  knn5.train(train.features, train.labels, 4);
  forest.train(train.features, train.labels, 4);
  EXPECT_GE(accuracy(knn1, test), 0.95);
  EXPECT_GE(accuracy(knn5, test), 0.95);
  EXPECT_GE(accuracy(forest, test), 0.95);
}

TEST(ObjectClassifiers, OverlappingClassesGiveSplitVotes)
{
  // Two classes drawn from the same distribution: the votes cannot all agree everywhere.
  Data data = gaussian_classes(1, 300, 6, 1., 21, 22);
  for(std::size_t i = 0; i < data.labels.size(); ++i)
    data.labels[i] = i % 2;
  const Data test = gaussian_classes(1, 200, 6, 1., 21, 23);
  PSOR::Knn_object_classifier knn(5);
  knn.train(data.features, data.labels, 2);
  PSOR::Random_forest_object_classifier forest(30, 20, 1);
  forest.train(data.features, data.labels, 2);
  double knn_min = 1, forest_min = 1;
  std::size_t votes[2] = {0, 0};
  for(const auto& f : test.features) {
    double c = -1;
    ++votes[knn.predict(f, c)];
    EXPECT_GE(c, 0.6 - 1e-12); // a majority of 5 votes between 2 classes
    knn_min = (std::min)(knn_min, c);
    forest.predict(f, c);
    EXPECT_GE(c, 0.5 - 1e-6);
    forest_min = (std::min)(forest_min, c);
  }
  EXPECT_LT(knn_min, 1.);
  EXPECT_LT(forest_min, 1.);
  EXPECT_GT(votes[0], 0u);
  EXPECT_GT(votes[1], 0u);
}

TEST(ObjectClassifiers, KnnVoteTiesGoToTheSmallerClass)
{
  // Two neighbours, one of each class, at the same distance from the query: class 0 wins.
  const Features features = {{-1., 0.}, {1., 0.}, {0., 9.}};
  PSOR::Knn_object_classifier knn(2);
  knn.train(features, {1, 0, 1}, 3);
  double c = 0;
  EXPECT_EQ(knn.predict({0., 0.}, c), 0u);
  EXPECT_DOUBLE_EQ(c, 0.5);
  PSOR::Knn_object_classifier knn3(3);
  knn3.train(features, {1, 0, 1}, 3);
  EXPECT_EQ(knn3.predict({0., 0.}, c), 1u);
  EXPECT_DOUBLE_EQ(c, 2. / 3.);
}

TEST(ObjectClassifiers, KnnIsUnchangedByScalingAFeature)
{
  const Data train = gaussian_classes(3, 40, 6, 2., 31, 32), test = gaussian_classes(3, 60, 6, 2., 31, 33);
  Data scaled_train = train, scaled_test = test;
  for(auto* d : {&scaled_train, &scaled_test})
    for(auto& f : d->features)
      f[2] *= 1000.;
  for(std::size_t k : {1u, 5u}) {
    PSOR::Knn_object_classifier a(k), b(k);
    a.train(train.features, train.labels, 3);
    b.train(scaled_train.features, scaled_train.labels, 3);
    for(std::size_t i = 0; i < test.features.size(); ++i) {
      double ca = -1, cb = -2;
      EXPECT_EQ(a.predict(test.features[i], ca), b.predict(scaled_test.features[i], cb));
      EXPECT_DOUBLE_EQ(ca, cb);
    }
  }
}

TEST(ObjectClassifiers, SaveLoadGivesIdenticalPredictions)
{
  const Data train = gaussian_classes(3, 50, 6, 2.5, 41, 42), test = gaussian_classes(3, 80, 6, 2.5, 41, 43);
  PSOR::Knn_object_classifier knn(5), knn_loaded(1);
  knn.train(train.features, train.labels, 3);
  std::istringstream knn_text(text(knn));
  knn_loaded.load(knn_text);
  EXPECT_EQ(knn_loaded.k(), 5u);
  EXPECT_EQ(text(knn_loaded), text(knn));
  expect_same_predictions(knn, knn_loaded, test.features);

  PSOR::Random_forest_object_classifier forest(40, 15, 3), forest_loaded;
  forest.train(train.features, train.labels, 3);
  std::istringstream forest_text(text(forest));
  forest_loaded.load(forest_text);
  EXPECT_EQ(forest_loaded.number_of_trees(), 40u);
  EXPECT_EQ(forest_loaded.random_seed(), 3u);
  EXPECT_EQ(text(forest_loaded), text(forest));
  expect_same_predictions(forest, forest_loaded, test.features);
  expect_same_predictions(forest, forest_loaded, train.features);
}

TEST(ObjectClassifiers, ForestTrainingIsDeterministic)
{
  const Data train = gaussian_classes(3, 50, 6, 2.5, 51, 52);
  PSOR::Random_forest_object_classifier a(30, 20, 9), b(30, 20, 9), c(30, 20, 10);
  a.train(train.features, train.labels, 3);
  // The same seed on another thread, while a third forest trains concurrently.
  std::thread tb([&] { b.train(train.features, train.labels, 3); });
  std::thread tc([&] { c.train(train.features, train.labels, 3); });
  tb.join();
  tc.join();
  EXPECT_EQ(text(a), text(b));
  EXPECT_NE(text(a), text(c));
  // The trees differ from each other (each has its own bootstrap and feature draws).
  const std::string t = text(a);
  const std::size_t first = t.find("tree "), second = t.find("tree ", first + 1), third = t.find("tree ", second + 1);
  EXPECT_NE(t.substr(first, second - first), t.substr(second, third - second));
}

TEST(ObjectClassifiers, IdenticalVectorsWithDifferentLabels)
{
  // No split separates them: every model still answers, with split votes.
  const Features features(12, std::vector<double>{1., 2., 3.});
  Labels labels(12);
  for(std::size_t i = 0; i < labels.size(); ++i)
    labels[i] = i % 3 == 0 ? 1 : 0;
  PSOR::Knn_object_classifier knn(12);
  PSOR::Random_forest_object_classifier forest(10, 20, 2);
  knn.train(features, labels, 2);
  forest.train(features, labels, 2);
  double c = 0;
  EXPECT_EQ(knn.predict({1., 2., 3.}, c), 0u);
  EXPECT_DOUBLE_EQ(c, 8. / 12.);
  EXPECT_EQ(forest.predict({1., 2., 3.}, c), 0u);
  EXPECT_GT(c, 0.5);
  EXPECT_LT(c, 1.);
}

template <typename Classifier>
void expect_bad_training_refused(Classifier& classifier)
{
  const Data data = gaussian_classes(2, 20, 3, 1., 61, 62);
  classifier.train(data.features, data.labels, 2);
  const std::string before = text(classifier);
  const double nan = std::numeric_limits<double>::quiet_NaN(), inf = std::numeric_limits<double>::infinity();
  EXPECT_THROW(classifier.train({}, {}, 2), Bad_input);
  EXPECT_THROW(classifier.train(data.features, Labels(data.labels.begin(), data.labels.end() - 1), 2), Bad_input);
  EXPECT_THROW(classifier.train(data.features, data.labels, 1), Bad_input);
  EXPECT_THROW(classifier.train(data.features, data.labels, 0), Bad_input);
  Features bad = data.features;
  bad[5][1] = nan;
  EXPECT_THROW(classifier.train(bad, data.labels, 2), Bad_input);
  bad[5][1] = inf;
  EXPECT_THROW(classifier.train(bad, data.labels, 2), Bad_input);
  bad = data.features;
  bad[7].push_back(1.);
  EXPECT_THROW(classifier.train(bad, data.labels, 2), Bad_input);
  EXPECT_THROW(classifier.train(Features(3, std::vector<double>()), Labels(3, 0), 2), Bad_input);
  double c = 0;
  EXPECT_THROW(classifier.predict({1., 2.}, c), Bad_input);
  EXPECT_THROW(classifier.predict({1., 2., 3., 4.}, c), Bad_input);
  EXPECT_THROW(classifier.predict({1., nan, 3.}, c), Bad_input);
  EXPECT_EQ(text(classifier), before);
  std::size_t right = 0;
  for(std::size_t i = 0; i < data.features.size(); ++i)
    right += classifier.predict(data.features[i], c) == data.labels[i];
  EXPECT_GE(right, data.features.size() * 9 / 10);
}

TEST(ObjectClassifiers, BadTrainingInputIsRefused)
{
  PSOR::Knn_object_classifier knn(3);
  expect_bad_training_refused(knn);
  PSOR::Random_forest_object_classifier forest(10, 10, 1);
  expect_bad_training_refused(forest);
  EXPECT_THROW(PSOR::Knn_object_classifier(0), Bad_input);
  EXPECT_THROW(PSOR::Random_forest_object_classifier(0), Bad_input);
  PSOR::Knn_object_classifier untrained;
  double c = 0;
  EXPECT_FALSE(untrained.is_trained());
  EXPECT_THROW(untrained.predict({1.}, c), Bad_input);
  std::ostringstream os;
  EXPECT_THROW(untrained.save(os), Bad_input);
}

std::string replace_first(std::string s, const std::string& from, const std::string& to)
{
  const std::size_t at = s.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  return at == std::string::npos ? s : s.replace(at, from.size(), to);
}

template <typename Classifier>
void expect_load_refused(Classifier& classifier, const std::string& bad)
{
  const std::string before = text(classifier);
  std::istringstream is(bad);
  EXPECT_THROW(classifier.load(is), Bad_input) << bad.substr(0, 200);
  EXPECT_EQ(text(classifier), before);
}

template <typename Classifier>
void expect_bad_files_refused(Classifier& classifier, const std::string& other_kind)
{
  const Data data = gaussian_classes(2, 8, 2, 1., 71, 72);
  classifier.train(data.features, data.labels, 2);
  const std::string good = text(classifier);
  expect_load_refused(classifier, "");
  expect_load_refused(classifier, "hello\n" + good);
  expect_load_refused(classifier, replace_first(good, "classifier 1\n", "classifier 2\n"));
  expect_load_refused(classifier, replace_first(good, "classifier 1\n", "classifier\n"));
  expect_load_refused(classifier, other_kind);
  expect_load_refused(classifier, replace_first(good, "\nmean ", "\nmean abc "));
  expect_load_refused(classifier, replace_first(good, "\nmean ", "\nmean nan "));
  expect_load_refused(classifier, replace_first(good, "\nscale ", "\nscale 1e9999 "));
  expect_load_refused(classifier, replace_first(good, "\nscale ", "\nscale -1 "));
  expect_load_refused(classifier, replace_first(good, "dimension 2", "dimension x"));
  expect_load_refused(classifier, replace_first(good, "classes 2", "classes 0"));
  expect_load_refused(classifier, replace_first(good, "end\n", "fin\n"));
  // Every truncation before the final "end".
  for(std::size_t size = 0; size + 4 < good.size(); size += 3)
    expect_load_refused(classifier, good.substr(0, size));
  // A good file still loads afterwards.
  std::istringstream is(good);
  classifier.load(is);
  EXPECT_EQ(text(classifier), good);
}

TEST(ObjectClassifiers, BadModelFilesAreRefused)
{
  const Data data = gaussian_classes(2, 8, 2, 1., 71, 72);
  PSOR::Knn_object_classifier knn(3);
  PSOR::Random_forest_object_classifier forest(3, 5, 1);
  knn.train(data.features, data.labels, 2);
  forest.train(data.features, data.labels, 2);
  const std::string knn_text = text(knn), forest_text = text(forest);
  expect_bad_files_refused(knn, forest_text);
  expect_bad_files_refused(forest, knn_text);
  // Model-specific corruption.
  expect_load_refused(knn, replace_first(knn_text, "samples 16\n0 ", "samples 16\n2 "));   // label >= classes
  expect_load_refused(knn, replace_first(knn_text, "samples 16\n", "samples 17\n"));       // a sample missing
  expect_load_refused(knn, replace_first(knn_text, "k 3\n", "k 0\n"));
  expect_load_refused(forest, replace_first(forest_text, "split ", "split 2 "));           // feature >= dimension
  expect_load_refused(forest, replace_first(forest_text, "leaf ", "leaf 1.5 "));           // probability > 1
  expect_load_refused(forest, replace_first(forest_text, "split ", "branch "));
  expect_load_refused(forest, replace_first(forest_text, "tree ", "tree 9"));              // wrong node count
  expect_load_refused(forest, replace_first(forest_text, "trees 3", "trees 4"));
}

#ifdef CGAL_SHAPE_ANALYSIS_USE_LIBSVM

typedef PSOR::Svm_object_classifier Svm;

TEST(ObjectClassifiers, SvmClassifiesSeparatedClassesAndRecoversTrainingLabels)
{
  const Data train = gaussian_classes(4, 60, 6, 1., 11, 12), test = gaussian_classes(4, 100, 6, 1., 11, 13);
  for(const Svm& prototype : {Svm(), Svm(2.5, 5, 0, 0, 0), Svm(2.5, 3, 0, 1, 1, Svm::BALANCED_WEIGHTS)}) {
    Svm svm = prototype;
    EXPECT_FALSE(svm.is_trained());
    svm.train(train.features, train.labels, 4);
    EXPECT_TRUE(svm.is_trained());
    EXPECT_EQ(svm.dimension(), 6u);
    EXPECT_EQ(svm.number_of_classes(), 4u);
    EXPECT_GT(svm.number_of_support_vectors(), 0u);
    EXPECT_LT(svm.number_of_support_vectors(), train.features.size());
    // The thesis' homogeneous kernel (r = 0: an odd function of x'.y') misses one of the 240.
    EXPECT_GE(accuracy(svm, train), svm.coef0() == 0 ? 0.99 : 1.);
    EXPECT_GE(accuracy(svm, test), 0.95);
    // Four classes, three duels each: a clear winner wins them all.
    double c = 0;
    svm.predict(test.features[0], c);
    EXPECT_EQ(c, 1.);
  }
}

// The standardized and weighted vectors of `features`, as Svm_object_classifier computes them.
Features svm_inputs(const Features& train, const Features& features, const std::vector<double>& weights)
{
  const std::size_t d = train.front().size();
  std::vector<double> mean(d, 0.), scale(d, 0.);
  for(const auto& f : train)
    for(std::size_t j = 0; j < d; ++j)
      mean[j] += f[j];
  for(double& m : mean)
    m /= double(train.size());
  for(const auto& f : train)
    for(std::size_t j = 0; j < d; ++j)
      scale[j] += (f[j] - mean[j]) * (f[j] - mean[j]);
  for(double& s : scale)
    s = std::sqrt(s / double(train.size()));
  Features out;
  for(const auto& f : features) {
    std::vector<double> x(d);
    for(std::size_t j = 0; j < d; ++j)
      x[j] = (f[j] - mean[j]) / scale[j] * weights[j];
    out.push_back(x);
  }
  return out;
}

std::vector<svm_node> svm_nodes(const std::vector<double>& x)
{
  std::vector<svm_node> nodes(x.size() + 1);
  for(std::size_t j = 0; j < x.size(); ++j)
    nodes[j].index = int(j + 1), nodes[j].value = x[j];
  nodes.back().index = -1;
  return nodes;
}

TEST(ObjectClassifiers, SvmPredictionsAreLibsvmPredictions)
{
  // Overlapping classes (many vectors near the decision boundaries), trained by libsvm directly
  // on the same vectors with the same parameters: svm_predict() and predict() agree everywhere.
  const Data train = gaussian_classes(4, 50, 6, 2.5, 81, 82), test = gaussian_classes(4, 250, 6, 2.5, 81, 83);
  for(const Svm& prototype : {Svm(), Svm(2.5, 5, 0, 0, 0), Svm(10, 3, 0.3, 0.5, 1, Svm::BALANCED_WEIGHTS)}) {
    Svm svm = prototype;
    svm.train(train.features, train.labels, 4);
    const std::vector<double> weights = svm.feature_weights();
    ASSERT_EQ(weights.size(), 6u);
    if(svm.feature_weight_exponent() == 0)
      EXPECT_EQ(weights, std::vector<double>(6, 1.));
    else
      EXPECT_NE(weights, std::vector<double>(6, 1.));
    const Features x = svm_inputs(train.features, train.features, weights);
    std::vector<std::vector<svm_node>> nodes;
    std::vector<svm_node*> rows;
    std::vector<double> y;
    for(std::size_t i = 0; i < x.size(); ++i)
      nodes.push_back(svm_nodes(x[i])), y.push_back(double(train.labels[i]));
    for(auto& n : nodes)
      rows.push_back(n.data());
    svm_problem problem{int(x.size()), y.data(), rows.data()};
    std::vector<int> weight_labels = {0, 1, 2, 3};
    std::vector<double> class_weights(4, 1.); // 50 vectors in each class
    svm_parameter p{};
    p.svm_type = C_SVC, p.kernel_type = POLY, p.degree = svm.degree(), p.coef0 = svm.coef0();
    p.gamma = svm.gamma() > 0 ? svm.gamma() : 1. / 6;
    p.cache_size = 100, p.eps = 1e-3, p.C = svm.C(), p.shrinking = 1;
    p.nr_weight = svm.class_weights() == Svm::BALANCED_WEIGHTS ? 4 : 0;
    p.weight_label = weight_labels.data(), p.weight = class_weights.data();
    ASSERT_EQ(svm_check_parameter(&problem, &p), nullptr);
    std::unique_ptr<svm_model, void (*)(svm_model*)> model(svm_train(&problem, &p),
                                                          [](svm_model* m) { svm_free_and_destroy_model(&m); });
    EXPECT_EQ(std::size_t(svm_get_nr_sv(model.get())), svm.number_of_support_vectors());
    const Features tx = svm_inputs(train.features, test.features, weights);
    std::size_t right = 0;
    for(std::size_t i = 0; i < tx.size(); ++i) {
      double c = -1;
      const std::size_t label = svm.predict(test.features[i], c);
      EXPECT_EQ(double(label), svm_predict(model.get(), svm_nodes(tx[i]).data())) << i;
      right += label == test.labels[i];
    }
    EXPECT_GT(right, tx.size() / 2); // overlapping, but far better than chance (1/4)
    EXPECT_LT(right, tx.size());
  }
}

TEST(ObjectClassifiers, SvmSaveLoadGivesIdenticalPredictions)
{
  const Data train = gaussian_classes(3, 50, 6, 2.5, 41, 42), test = gaussian_classes(3, 80, 6, 2.5, 41, 43);
  Svm svm(3., 4, 0.2, 0.5, 1.5, Svm::BALANCED_WEIGHTS), loaded;
  svm.train(train.features, train.labels, 3);
  std::istringstream is(text(svm));
  loaded.load(is);
  EXPECT_EQ(loaded.C(), 3.);
  EXPECT_EQ(loaded.degree(), 4);
  EXPECT_EQ(loaded.gamma(), 0.2);
  EXPECT_EQ(loaded.coef0(), 0.5);
  EXPECT_EQ(loaded.feature_weight_exponent(), 1.5);
  EXPECT_EQ(loaded.class_weights(), Svm::BALANCED_WEIGHTS);
  EXPECT_EQ(loaded.feature_weights(), svm.feature_weights());
  EXPECT_EQ(loaded.number_of_support_vectors(), svm.number_of_support_vectors());
  EXPECT_EQ(text(loaded), text(svm));
  expect_same_predictions(svm, loaded, test.features);
  expect_same_predictions(svm, loaded, train.features);
}

TEST(ObjectClassifiers, SvmIsDeterministicAndPredictsFromSeveralThreads)
{
  const Data train = gaussian_classes(5, 40, 6, 2., 91, 92), test = gaussian_classes(5, 100, 6, 2., 91, 93);
  Svm a, b, c;
  a.train(train.features, train.labels, 5);
  // The same training on two other threads at once gives the same model.
  std::thread tb([&] { b.train(train.features, train.labels, 5); });
  std::thread tc([&] { c.train(train.features, train.labels, 5); });
  tb.join();
  tc.join();
  EXPECT_EQ(text(a), text(b));
  EXPECT_EQ(text(a), text(c));
  std::vector<std::size_t> labels(test.features.size());
  std::vector<double> confidences(test.features.size());
  for(std::size_t i = 0; i < labels.size(); ++i)
    labels[i] = a.predict(test.features[i], confidences[i]);
  EXPECT_LT(*std::min_element(confidences.begin(), confidences.end()), 1.); // some split votes
  // Four threads predict the whole set at once, two of them from copies.
  const Svm copy = a;
  std::vector<std::vector<std::size_t>> thread_labels(4, std::vector<std::size_t>(labels.size()));
  std::vector<std::vector<double>> thread_confidences(4, std::vector<double>(labels.size()));
  std::vector<std::thread> threads;
  for(std::size_t t = 0; t < 4; ++t)
    threads.emplace_back([&, t] {
      const Svm& svm = t % 2 == 0 ? a : copy;
      for(std::size_t i = 0; i < labels.size(); ++i)
        thread_labels[t][i] = svm.predict(test.features[i], thread_confidences[t][i]);
    });
  for(auto& t : threads)
    t.join();
  for(std::size_t t = 0; t < 4; ++t) {
    EXPECT_EQ(thread_labels[t], labels);
    EXPECT_EQ(thread_confidences[t], confidences);
  }
}

TEST(ObjectClassifiers, SvmCopiesShareTheModel)
{
  const Data one = gaussian_classes(3, 30, 4, 1., 101, 102), other = gaussian_classes(2, 30, 4, 1., 103, 104);
  Svm svm;
  svm.train(one.features, one.labels, 3);
  const Svm copy = svm;
  const std::string before = text(svm);
  EXPECT_EQ(text(copy), before);
  // Training the original again replaces its model; the copy keeps the one it shares.
  svm.train(other.features, other.labels, 2);
  EXPECT_EQ(svm.number_of_classes(), 2u);
  EXPECT_EQ(text(copy), before);
  EXPECT_EQ(copy.number_of_classes(), 3u);
  EXPECT_GE(accuracy(copy, one), 0.95);
}

TEST(ObjectClassifiers, SvmNeverPredictsAClassAbsentFromTheTrainingLabels)
{
  // Five classes declared, classes 1 and 3 absent.
  const Data data = gaussian_classes(5, 30, 6, 1.5, 111, 112), test = gaussian_classes(5, 60, 6, 1.5, 111, 113);
  Data present;
  for(std::size_t i = 0; i < data.labels.size(); ++i)
    if(data.labels[i] % 2 == 0)
      present.features.push_back(data.features[i]), present.labels.push_back(data.labels[i]);
  Svm svm;
  svm.train(present.features, present.labels, 5);
  EXPECT_EQ(svm.number_of_classes(), 5u);
  std::size_t seen[5] = {0, 0, 0, 0, 0};
  for(const auto& f : test.features) {
    double c = -1;
    const std::size_t label = svm.predict(f, c);
    ASSERT_LT(label, 5u);
    ++seen[label];
    EXPECT_TRUE(c == 0.5 || c == 1.) << c; // three classes present: two duels
  }
  EXPECT_EQ(seen[1] + seen[3], 0u);
  EXPECT_GT(seen[0] * seen[2] * seen[4], 0u);
  Svm loaded;
  std::istringstream is(text(svm));
  loaded.load(is);
  expect_same_predictions(svm, loaded, test.features);
  // A single class present: always that class, with confidence 1.
  svm.train(present.features, Labels(present.labels.size(), 3), 5);
  double c = 0;
  EXPECT_EQ(svm.predict(test.features[0], c), 3u);
  EXPECT_EQ(c, 1.);
  EXPECT_EQ(svm.number_of_support_vectors(), 0u);
}

TEST(ObjectClassifiers, SvmBadInputIsRefused)
{
  Svm svm;
  expect_bad_training_refused(svm);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(Svm(0.), Bad_input);
  EXPECT_THROW(Svm(-1.), Bad_input);
  EXPECT_THROW(Svm(2.5, 0), Bad_input);
  EXPECT_THROW(Svm(2.5, 5, -1.), Bad_input);
  EXPECT_THROW(Svm(2.5, 5, 0, nan), Bad_input);
  EXPECT_THROW(Svm(2.5, 5, 0, 1, -1.), Bad_input);
  // A kernel whose values overflow libsvm's float cache is refused, the model kept.
  const Data data = gaussian_classes(2, 20, 3, 1., 61, 62);
  Svm huge(2.5, 5, 1e10);
  EXPECT_THROW(huge.train(data.features, data.labels, 2), Bad_input); // kernel values up to ~1e60
  EXPECT_FALSE(huge.is_trained());
  // Identical vectors with different labels: an answer, no crash.
  const Features same(12, std::vector<double>{1., 2., 3.});
  Labels labels(12);
  for(std::size_t i = 0; i < labels.size(); ++i)
    labels[i] = i % 3 == 0 ? 1 : 0;
  svm.train(same, labels, 2);
  double c = 0;
  EXPECT_LT(svm.predict({1., 2., 3.}, c), 2u);
  EXPECT_EQ(c, 1.);
}

TEST(ObjectClassifiers, SvmBadModelFilesAreRefused)
{
  const Data data = gaussian_classes(2, 8, 2, 1., 71, 72);
  PSOR::Knn_object_classifier knn(3);
  knn.train(data.features, data.labels, 2);
  Svm svm;
  expect_bad_files_refused(svm, text(knn));
  const std::string good = text(svm);
  expect_load_refused(svm, replace_first(good, "degree 5", "degree 0"));
  expect_load_refused(svm, replace_first(good, "C 2.5", "C -2.5"));
  expect_load_refused(svm, replace_first(good, "class_weights uniform", "class_weights heavy"));
  expect_load_refused(svm, replace_first(good, "feature_weight_exponent 2", "feature_weight_exponent -2"));
  expect_load_refused(svm, replace_first(good, "kernel_gamma ", "kernel_gamma 0 "));
  expect_load_refused(svm, replace_first(good, "feature_weights ", "feature_weights -1 "));
  expect_load_refused(svm, replace_first(good, "labels 2 0 1", "labels 2 1 0"));   // not increasing
  expect_load_refused(svm, replace_first(good, "labels 2 0 1", "labels 2 0 2"));   // class >= classes
  expect_load_refused(svm, replace_first(good, "labels 2 0 1", "labels 3 0 1 1")); // more than classes
  expect_load_refused(svm, replace_first(good, "per_class ", "per_class 1"));      // wrong sum
  expect_load_refused(svm, replace_first(good, "support_vectors ", "support_vectors 1"));
  expect_load_refused(svm, replace_first(good, "\nend\n", "\n1 2 3\nend\n"));      // a vector too many
  // Its own file in another classifier: another kind.
  expect_load_refused(knn, good);
}

#endif // CGAL_SHAPE_ANALYSIS_USE_LIBSVM

} // namespace
