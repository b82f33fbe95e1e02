// Copyright (c) 2026 CGAL Global Shape Analysis contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later

// Trains a k-nearest-neighbour classifier and a random forest on a few object feature vectors
// (height, width, number of points: a made-up example with classes 0 = post, 1 = car, 2 = tree),
// saves both models, loads them back and classifies two new objects.

#include <CGAL/Point_set_object_recognition/Object_classifiers.h>

#include <cstdlib>
#include <iostream>
#include <sstream>
#include <vector>

namespace PSOR = CGAL::Point_set_object_recognition;

int main()
{
  const std::vector<std::vector<double>> features = {
    {3.1, 0.3, 400}, {2.9, 0.2, 350}, {3.3, 0.3, 420}, {2.7, 0.4, 380},       // posts
    {1.5, 4.2, 3000}, {1.4, 4.6, 3500}, {1.6, 3.9, 2800}, {1.5, 4.4, 3100},   // cars
    {8.0, 5.0, 9000}, {7.2, 4.1, 8000}, {9.1, 6.0, 12000}, {6.5, 4.5, 7000}}; // trees
  const std::vector<std::size_t> labels = {0, 0, 0, 0, 1, 1, 1, 1, 2, 2, 2, 2};
  const char* names[] = {"post", "car", "tree"};

  try {
    PSOR::Knn_object_classifier knn(3);
    PSOR::Random_forest_object_classifier forest(/* trees */ 25, /* max depth */ 10, /* random seed */ 1);
    knn.train(features, labels, 3);
    forest.train(features, labels, 3);

    // Save both models (to strings here; to files just as well) and load them back.
    std::stringstream knn_file, forest_file;
    knn.save(knn_file);
    forest.save(forest_file);
    PSOR::Knn_object_classifier knn_loaded;
    PSOR::Random_forest_object_classifier forest_loaded;
    knn_loaded.load(knn_file);
    forest_loaded.load(forest_file);

    for(const std::vector<double>& object : {std::vector<double>{3.0, 0.25, 390}, std::vector<double>{1.5, 4.0, 2900}}) {
      double knn_confidence = 0, forest_confidence = 0;
      const std::size_t a = knn_loaded.predict(object, knn_confidence);
      const std::size_t b = forest_loaded.predict(object, forest_confidence);
      std::cout << "kNN: " << names[a] << " (" << knn_confidence << "), random forest: " << names[b] << " ("
                << forest_confidence << ")\n";
    }
  } catch(const CGAL::Shape_analysis::Bad_input& e) {
    std::cerr << "error: " << e.what() << std::endl;
    return EXIT_FAILURE;
  }
  return EXIT_SUCCESS;
}
