// Copyright (c) 2026 CGAL Global Shape Analysis contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_POINT_SET_OBJECT_RECOGNITION_OBJECT_CLASSIFIERS_H
#define CGAL_POINT_SET_OBJECT_RECOGNITION_OBJECT_CLASSIFIERS_H

/// \file Object_classifiers.h
/// Classifiers of candidate objects from their feature vectors (A. Golovinskiy's thesis, section
/// 4.4): k nearest neighbours and a random forest, trained from labelled feature vectors, saved
/// to and loaded from one versioned text file.

#include <CGAL/Epick_d.h>
#include <CGAL/Orthogonal_k_neighbor_search.h>
#include <CGAL/Search_traits_adapter.h>
#include <CGAL/Search_traits_d.h>
#include <CGAL/property_map.h>
#include <CGAL/tags.h>

#include <CGAL/Classification/ETHZ/internal/random-forest/forest.hpp>
#include <CGAL/Classification/ETHZ/internal/random-forest/node-gini.hpp>

#include <CGAL/Point_set_object_recognition/internal/Classifier_data.h>
#include <CGAL/Shape_analysis/Bad_input.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <istream>
#include <iomanip>
#include <limits>
#include <memory>
#include <ostream>
#include <random>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Point_set_object_recognition {

using CGAL::Shape_analysis::Bad_input;

/*!
\ingroup PkgPointSetObjectRecognitionRef
\page ObjectClassifierConcept The `ObjectClassifier` concept

A classifier of objects from their feature vectors: every feature vector has the same dimension
`d`, every label is a class index in `[0, number_of_classes)`. Models:
`Knn_object_classifier`, `Random_forest_object_classifier`, `Svm_object_classifier` (libsvm).

- `void train(const std::vector<std::vector<double>>& features, const std::vector<std::size_t>& labels, std::size_t number_of_classes)`
  learns from `features[i]` labelled `labels[i]`, replacing any previous model. Throws
  `CGAL::Shape_analysis::Bad_input` (the classifier unchanged) when `features` is empty, when the
  sizes of `features` and `labels` differ, when a label is not below `number_of_classes`, when a
  feature is not finite or when two feature vectors have different dimensions (or dimension 0).
- `std::size_t predict(const std::vector<double>& feature, double& confidence) const` returns the
  class of `feature` and sets `confidence` in `[0,1]` (1: every vote for that class). Throws
  `Bad_input` when the classifier is not trained, when `feature` does not have the dimension of
  the training features or is not finite. Safe to call from several threads at once.
- `void save(std::ostream& os) const` writes the model in the text format below (throws
  `Bad_input` when the classifier is not trained).
- `void load(std::istream& is)` reads a model written by `save()` of the same class; throws
  `Bad_input` on a wrong first line, another format version, another kind of classifier, a
  truncated file or a value that is not a finite number, and then leaves the classifier
  unchanged. A model saved then loaded gives the same predictions and confidences.
- `bool is_trained() const`, `std::size_t dimension() const`, `std::size_t number_of_classes() const`.

<b>Model file</b> (text, whitespace-separated tokens, doubles written with 17 significant
digits and floats with 9, so that a loaded model is bit-identical):
\code
CGAL_Point_set_object_recognition_classifier 1
kind knn | random_forest | svm
dimension <d>
classes <c>
mean <d values>          (the standardization: x' = (x - mean) / scale, per coordinate)
scale <d values>         (the standard deviations of the training features, 1 where 0)
knn: k <k>
     samples <n>  then n lines: <label> <d raw feature values>
random_forest: max_depth <m> min_samples <s> seed <seed>
     trees <t>  then per tree: tree <number of nodes>, then its nodes in pre-order, one per line:
       split <feature index> <threshold>   (x'[feature] > threshold goes right, else left;
                                            the left subtree follows, then the right one)
       leaf <c class probabilities>
svm: C <C> degree <p> gamma <0: 1/d> coef0 <r> feature_weight_exponent <a> class_weights <w>
     kernel_gamma <g> feature_weights <d> labels <k> <k classes> rho <k (k - 1) / 2> support_vectors
     <l> per_class <k counts>, then l lines: <k - 1 coefficients> <d coordinates> (Svm_object_classifier)
end
\endcode
*/

/*!
\ingroup PkgPointSetObjectRecognitionRef
Classifies a feature vector by the majority vote of its `k` nearest training feature vectors, a
model of the `ObjectClassifier` concept (see \ref ObjectClassifierConcept). Features are
standardized with the mean and standard deviation of each coordinate over the training set, so
that scaling a coordinate does not change the result. Neighbours come from a kd-tree of CGAL's
Spatial Searching (`CGAL::Orthogonal_k_neighbor_search`); the vote is over the `min(k, n)`
nearest of the `n` training vectors (at equal distances, the kd-tree's order), ties are broken by
the smaller class index, and the confidence is the fraction of the votes that the returned class
got. Copies share the trained model, which is never modified in place.
*/
class Knn_object_classifier
{
  typedef CGAL::Epick_d<CGAL::Dynamic_dimension_tag> Kernel;
  typedef Kernel::Point_d Point;
  typedef CGAL::Pointer_property_map<Point>::const_type Point_map;
  typedef CGAL::Search_traits_d<Kernel, CGAL::Dynamic_dimension_tag> Base_traits;
  typedef CGAL::Search_traits_adapter<std::size_t, Point_map, Base_traits> Traits;
  typedef CGAL::Orthogonal_k_neighbor_search<Traits> Search;
  typedef Search::Tree Tree;
  typedef Search::Distance Distance;

  struct Model
  {
    internal::Classifier_data data;
    std::vector<std::vector<double>> features; // as given, for save()
    std::vector<std::size_t> labels;
    std::vector<Point> points; // standardized
    std::unique_ptr<Tree> tree;
  };

  std::size_t m_k;
  std::shared_ptr<const Model> m_model;

  static std::shared_ptr<const Model> build(internal::Classifier_data data, std::vector<std::vector<double>> features,
                                            std::vector<std::size_t> labels)
  {
    auto model = std::make_shared<Model>();
    model->data = std::move(data);
    model->features = std::move(features);
    model->labels = std::move(labels);
    model->points.reserve(model->features.size());
    for(const auto& f : model->features) {
      const std::vector<double> s = model->data.standardize(f);
      model->points.emplace_back(s.begin(), s.end());
    }
    std::vector<std::size_t> indices(model->points.size());
    for(std::size_t i = 0; i < indices.size(); ++i)
      indices[i] = i;
    const Point_map map = CGAL::make_property_map(std::as_const(model->points));
    model->tree = std::make_unique<Tree>(indices.begin(), indices.end(), Tree::Splitter(), Traits(map));
    model->tree->build(); // before any concurrent query
    return model;
  }

public:
  /// A classifier voting over the `k` nearest neighbours.
  /// \param k the number of neighbours that vote
  /// \throws Bad_input when `k` is 0.
  explicit Knn_object_classifier(std::size_t k = 1) : m_k(k)
  {
    if(k == 0)
      throw Bad_input("Knn_object_classifier: k must be at least 1");
  }

  /// \returns the number of neighbours that vote
  std::size_t k() const { return m_k; }
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
  /// \throws Bad_input on bad input (the classifier unchanged).
  void train(const std::vector<std::vector<double>>& features, const std::vector<std::size_t>& labels,
             std::size_t number_of_classes)
  {
    internal::Classifier_data data;
    data.prepare(features, labels, number_of_classes);
    m_model = build(std::move(data), features, labels);
  }

  /// The class of `feature`, with the fraction of the `k` votes it got in `confidence`.
  /// \param feature a vector of the training dimension
  /// \param confidence receives the fraction of the votes for the class returned
  /// \returns the class with most votes (the smaller at equal votes)
  /// \throws Bad_input when not trained, or on a wrong dimension or a value that is not finite.
  std::size_t predict(const std::vector<double>& feature, double& confidence) const
  {
    if(!m_model)
      throw Bad_input("Knn_object_classifier: predict() before train() or load()");
    const std::vector<double> s = m_model->data.standardize(feature);
    const Point query(s.begin(), s.end());
    const Point_map map = CGAL::make_property_map(m_model->points);
    Search search(*m_model->tree, query, unsigned(std::min<std::size_t>(m_k, m_model->points.size())), 0, true,
                  Distance(map));
    std::vector<std::size_t> votes(m_model->data.classes, 0);
    std::size_t total = 0;
    for(const auto& neighbour : search) {
      ++votes[m_model->labels[neighbour.first]];
      ++total;
    }
    const std::size_t best = std::size_t(std::max_element(votes.begin(), votes.end()) - votes.begin());
    confidence = total == 0 ? 0. : double(votes[best]) / double(total);
    return best;
  }

  /// Writes the model (kind `knn`), see \ref ObjectClassifierConcept.
  /// \param os the stream written to
  /// \throws Bad_input when not trained.
  void save(std::ostream& os) const
  {
    if(!m_model)
      throw Bad_input("Knn_object_classifier: save() before train() or load()");
    m_model->data.write(os, "knn");
    os << "k " << m_k << "\nsamples " << m_model->features.size() << '\n' << std::setprecision(17);
    for(std::size_t i = 0; i < m_model->features.size(); ++i) {
      os << m_model->labels[i];
      for(double x : m_model->features[i])
        os << ' ' << x;
      os << '\n';
    }
    os << "end\n";
  }

  /// Reads a model written by `save()` (kind `knn`, which also sets `k()`).
  /// \param is the stream read from
  /// \throws Bad_input on a file that is not such a model (the classifier unchanged).
  void load(std::istream& is)
  {
    internal::Model_reader in(is);
    internal::Classifier_data data = in.header("knn");
    in.expect("k");
    const std::size_t k = in.count("k", std::size_t(1) << 30);
    if(k == 0)
      internal::Model_reader::fail("k is 0");
    in.expect("samples");
    const std::size_t n = in.count("the number of samples", std::size_t(1) << 40);
    if(n == 0)
      internal::Model_reader::fail("no sample");
    std::vector<std::vector<double>> features;
    std::vector<std::size_t> labels;
    for(std::size_t i = 0; i < n; ++i) {
      labels.push_back(in.count("a label", data.classes - 1));
      std::vector<double> f(data.dimension);
      for(double& x : f)
        x = in.real("a feature value");
      features.push_back(std::move(f));
    }
    in.expect("end");
    auto model = build(std::move(data), std::move(features), std::move(labels));
    m_k = k;
    m_model = std::move(model);
  }
};

namespace internal {

// The axis-aligned split of CGAL's ETHZ forest, made safe when no split was found (all values equal
// in the node for the proposed features): the default (feature -1) then sends every sample left.
struct Safe_axis_splitter
{
  typedef float FeatureType;
  typedef CGAL::internal::liblearning::RandomForest::FeatureClassDataFloat FeatureClassData;
  int feature = -1;
  FeatureType threshold = 0;

  Safe_axis_splitter() = default;
  Safe_axis_splitter(const CGAL::internal::liblearning::RandomForest::AxisAlignedSplitter& s) : feature(s.feature) {}

  void set_threshold(FeatureType t) { threshold = t; }
  bool classify_sample(const FeatureType* v) const { return feature >= 0 && v[feature] > threshold; }

  void map_points(CGAL::internal::liblearning::DataView2D<FeatureType> samples,
                  CGAL::internal::liblearning::DataView2D<int> labels, const int* sample_indices, int n,
                  FeatureClassData& out) const
  {
    out.clear();
    for(int i = 0; i < n; ++i)
      out.emplace_back(samples(sample_indices[i], feature), labels(sample_indices[i], 0));
  }
};

} // namespace internal

/*!
\ingroup PkgPointSetObjectRecognitionRef
A random forest of axis-aligned decision trees split by the Gini criterion (the forest of CGAL's
`CGAL::Classification::ETHZ::Random_forest_classifier`, used directly on feature vectors), a model
of the `ObjectClassifier` concept (see \ref ObjectClassifierConcept). Each tree learns from its own
bootstrap of about 63% of the (standardized) training vectors, drawn from a generator seeded by
(`random_seed`, tree index), and tries √d random coordinates per node: the same seed gives the same
forest and the same predictions, whatever the number of threads. `predict()` returns the class of
highest mean leaf probability over the trees (ties: the smaller class index) with that mean as
confidence. Copies share the trained model, which is never modified in place.
*/
class Random_forest_object_classifier
{
  typedef CGAL::internal::liblearning::RandomForest::NodeGini<internal::Safe_axis_splitter> Node;
  typedef CGAL::internal::liblearning::RandomForest::RandomForest<Node> Forest;
  typedef CGAL::internal::liblearning::RandomForest::Tree<Node> Tree;

  struct Model
  {
    internal::Classifier_data data;
    std::shared_ptr<Forest> forest;
  };

  std::size_t m_trees, m_max_depth, m_min_samples;
  unsigned int m_seed;
  std::shared_ptr<const Model> m_model;

  // A node that found no split (every coordinate tried was constant over its vectors) has feature
  // -1 and sends every vector left: it is written as its left subtree, which predicts the same.
  static std::size_t count_nodes(const Node& n)
  {
    if(!n.is_leaf && n.splitter.feature < 0)
      return count_nodes(*n.left);
    return n.is_leaf ? 1 : 1 + count_nodes(*n.left) + count_nodes(*n.right);
  }

  static void write_node(std::ostream& os, const Node& n)
  {
    if(!n.is_leaf && n.splitter.feature < 0) {
      write_node(os, *n.left);
      return;
    }
    if(n.is_leaf) {
      os << "leaf";
      for(float p : n.node_dist)
        os << ' ' << p;
      os << '\n';
      return;
    }
    os << "split " << n.splitter.feature << ' ' << n.splitter.threshold << '\n';
    write_node(os, *n.left);
    write_node(os, *n.right);
  }

  // Reads the node at `depth` and its subtree; `nodes` counts the nodes read.
  static Node* read_node(internal::Model_reader& in, const Forest& forest, std::size_t depth, std::size_t& nodes)
  {
    if(depth > 10000)
      internal::Model_reader::fail("a tree deeper than 10000");
    std::unique_ptr<Node> n(new Node(int(depth), &forest.params));
    ++nodes;
    const std::string kind = in.token("a node");
    n->node_dist.assign(forest.params.n_classes, 0.f);
    if(kind == "leaf") {
      n->is_leaf = true;
      for(float& p : n->node_dist) {
        const double x = in.real("a class probability");
        if(x < 0 || x > 1)
          internal::Model_reader::fail("a class probability is not in [0,1]");
        p = float(x);
      }
    } else if(kind == "split") {
      n->is_leaf = false;
      n->splitter.feature = int(in.count("a split feature", forest.params.n_features - 1));
      n->splitter.threshold = float(in.real("a split threshold"));
      n->left.reset(read_node(in, forest, depth + 1, nodes));
      n->right.reset(read_node(in, forest, depth + 1, nodes));
    } else
      internal::Model_reader::fail("expected 'leaf' or 'split', read '" + kind + "'");
    return n.release();
  }

public:
  /// A forest of `number_of_trees` trees of depth at most `max_depth`; nodes with fewer than
  /// `min_samples_per_node` training vectors are leaves.
  /// \param number_of_trees the number of trees
  /// \param max_depth the largest depth of a tree
  /// \param random_seed the seed of the training (the same seed gives the same forest)
  /// \param min_samples_per_node the fewest training vectors a node splits
  /// \throws Bad_input when a count is 0.
  explicit Random_forest_object_classifier(std::size_t number_of_trees = 50, std::size_t max_depth = 20,
                                           unsigned int random_seed = 0, std::size_t min_samples_per_node = 2)
    : m_trees(number_of_trees), m_max_depth(max_depth), m_min_samples(min_samples_per_node), m_seed(random_seed)
  {
    if(number_of_trees == 0 || max_depth == 0 || min_samples_per_node == 0)
      throw Bad_input("Random_forest_object_classifier: the number of trees, the maximum depth and the minimum "
                      "number of samples per node must be positive");
  }

  /// \returns the number of trees trained
  std::size_t number_of_trees() const { return m_trees; }
  /// \returns the seed of the training
  unsigned int random_seed() const { return m_seed; }
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
  /// \throws Bad_input on bad input (the classifier unchanged).
  void train(const std::vector<std::vector<double>>& features, const std::vector<std::size_t>& labels,
             std::size_t number_of_classes)
  {
    namespace RF = CGAL::internal::liblearning::RandomForest;
    auto model = std::make_shared<Model>();
    model->data.prepare(features, labels, number_of_classes);
    if(features.size() > std::size_t((std::numeric_limits<int>::max)()))
      throw Bad_input("Random_forest_object_classifier: too many feature vectors");
    const std::size_t n = features.size(), d = model->data.dimension;
    std::vector<float> samples(n * d);
    std::vector<int> classes(n);
    for(std::size_t i = 0; i < n; ++i) {
      const std::vector<double> s = model->data.standardize(features[i]);
      for(std::size_t j = 0; j < d; ++j)
        samples[i * d + j] = float(s[j]);
      classes[i] = int(labels[i]);
    }
    RF::ForestParams params;
    params.n_trees = 1; // one tree per call below, each with its own bootstrap
    params.max_depth = m_max_depth;
    params.min_samples_per_node = m_min_samples;
    model->forest = std::make_shared<Forest>(params);
    const CGAL::internal::liblearning::DataView2D<float> sample_view(samples.data(), n, d);
    const CGAL::internal::liblearning::DataView2D<int> label_view(classes.data(), n, 1);
    RF::AxisAlignedRandomSplitGenerator generator;
    // The forest draws its bootstrap as the first 63% of a fixed permutation of the indices it
    // gets: give each tree the indices in its own random order, seeded by (seed, tree).
    std::vector<int> order(n);
    for(std::size_t t = 0; t < m_trees; ++t) {
      for(std::size_t i = 0; i < n; ++i)
        order[i] = int(i);
      std::seed_seq seq{std::uint32_t(m_seed), std::uint32_t(t), std::uint32_t(std::uint64_t(t) >> 32)};
      std::mt19937 rng(seq);
      for(std::size_t i = n; i > 1; --i) // Fisher-Yates with a portable draw
        std::swap(order[i - 1], order[std::size_t(rng() % i)]);
      const CGAL::internal::liblearning::DataView2D<int> order_view(order.data(), n, 1);
      model->forest->train<CGAL::Sequential_tag>(sample_view, label_view, order_view, generator,
                                                 std::size_t(m_seed) * 1000003u, false, number_of_classes);
    }
    model->forest->params.n_trees = model->forest->trees.size();
    m_model = std::move(model);
  }

  /// The class of highest mean probability over the trees, that mean in `confidence`.
  /// \param feature a vector of the training dimension
  /// \param confidence receives the mean probability of the class returned
  /// \returns the class of highest mean probability (the smaller at equal ones)
  /// \throws Bad_input when not trained, or on a wrong dimension or a value that is not finite.
  std::size_t predict(const std::vector<double>& feature, double& confidence) const
  {
    if(!m_model)
      throw Bad_input("Random_forest_object_classifier: predict() before train() or load()");
    const std::vector<double> s = m_model->data.standardize(feature);
    std::vector<float> sample(s.begin(), s.end());
    std::vector<float> votes(m_model->data.classes, 0.f);
    const int best = m_model->forest->evaluate(sample.data(), votes.data());
    confidence = std::clamp(double(votes[std::size_t(best)]), 0., 1.);
    return std::size_t(best);
  }

  /// Writes the model (kind `random_forest`), see \ref ObjectClassifierConcept.
  /// \param os the stream written to
  /// \throws Bad_input when not trained.
  void save(std::ostream& os) const
  {
    if(!m_model)
      throw Bad_input("Random_forest_object_classifier: save() before train() or load()");
    m_model->data.write(os, "random_forest");
    const Forest& forest = *m_model->forest;
    os << "max_depth " << m_max_depth << " min_samples " << m_min_samples << " seed " << m_seed << '\n'
       << "trees " << forest.trees.size() << '\n' << std::setprecision(9);
    for(std::size_t t = 0; t < forest.trees.size(); ++t) {
      os << "tree " << count_nodes(*forest.trees[t].root_node) << '\n';
      write_node(os, *forest.trees[t].root_node);
    }
    os << "end\n";
  }

  /// Reads a model written by `save()` (kind `random_forest`, which also sets the parameters).
  /// \param is the stream read from
  /// \throws Bad_input on a file that is not such a model (the classifier unchanged).
  void load(std::istream& is)
  {
    internal::Model_reader in(is);
    auto model = std::make_shared<Model>();
    model->data = in.header("random_forest");
    in.expect("max_depth");
    const std::size_t max_depth = in.count("the maximum depth", 1u << 20);
    in.expect("min_samples");
    const std::size_t min_samples = in.count("the minimum number of samples", std::size_t(1) << 40);
    in.expect("seed");
    const unsigned int seed = unsigned(in.count("the seed", (std::numeric_limits<unsigned int>::max)()));
    in.expect("trees");
    const std::size_t trees = in.count("the number of trees", 1u << 24);
    if(trees == 0 || max_depth == 0 || min_samples == 0)
      internal::Model_reader::fail("the number of trees, the maximum depth and the minimum samples must be positive");
    CGAL::internal::liblearning::RandomForest::ForestParams params;
    params.n_classes = model->data.classes;
    params.n_features = model->data.dimension;
    params.n_trees = trees;
    params.max_depth = max_depth;
    params.min_samples_per_node = min_samples;
    model->forest = std::make_shared<Forest>(params);
    for(std::size_t t = 0; t < trees; ++t) {
      in.expect("tree");
      const std::size_t expected = in.count("the number of nodes", std::size_t(1) << 40);
      std::size_t nodes = 0;
      model->forest->trees.push_back(new Tree(&model->forest->params));
      model->forest->trees.back().root_node.reset(read_node(in, *model->forest, 0, nodes));
      if(nodes != expected)
        internal::Model_reader::fail("tree " + std::to_string(t) + " has " + std::to_string(nodes) +
                                     " nodes, its header says " + std::to_string(expected));
    }
    in.expect("end");
    m_trees = trees;
    m_max_depth = max_depth;
    m_min_samples = min_samples;
    m_seed = seed;
    m_model = std::move(model);
  }
};

} // namespace Point_set_object_recognition
} // namespace CGAL

#endif // CGAL_POINT_SET_OBJECT_RECOGNITION_OBJECT_CLASSIFIERS_H
