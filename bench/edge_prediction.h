// Copyright (c) 2026 CGAL Global Shape Analysis contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_SHAPE_ANALYSIS_BENCH_EDGE_PREDICTION_H
#define CGAL_SHAPE_ANALYSIS_BENCH_EDGE_PREDICTION_H

// How well a score per mesh edge predicts where people cut a mesh: the edges are positives when
// at least one human segmentation puts their two faces in different segments. Figures: the area
// under the ROC curve (the probability that a random positive edge scores above a random negative
// one, ties counting one half) and the precision of the top 2% of the edges by score.

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numeric>
#include <vector>

namespace psb {

struct Edge_prediction
{
  double auc = 0.5;
  double top_precision = 0;
  std::size_t positives = 0;
  std::size_t edges = 0;
};

// `score[e]` and `positive[e]` for the edges considered (interior edges).
inline Edge_prediction predict_edges(const std::vector<double>& score,
                                     const std::vector<char>& positive, double top_fraction = 0.02)
{
  Edge_prediction r;
  const std::size_t m = score.size();
  r.edges = m;
  if(m == 0)
    return r;
  std::vector<std::size_t> order(m);
  std::iota(order.begin(), order.end(), std::size_t(0));
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    return score[a] != score[b] ? score[a] < score[b] : a < b;
  });
  // Mann-Whitney: mean ranks over ties.
  double rank_sum = 0;
  std::size_t positives = 0;
  for(std::size_t i = 0; i < m;) {
    std::size_t j = i;
    while(j < m && score[order[j]] == score[order[i]])
      ++j;
    const double mean_rank = 0.5 * double(i + 1 + j); // ranks i+1 .. j
    for(std::size_t k = i; k < j; ++k)
      if(positive[order[k]]) {
        rank_sum += mean_rank;
        ++positives;
      }
    i = j;
  }
  r.positives = positives;
  const double p = double(positives), n = double(m - positives);
  if(positives > 0 && positives < m)
    r.auc = (rank_sum - p * (p + 1) / 2) / (p * n);
  // Top fraction, highest scores first (ties: lower edge index first).
  const std::size_t top = (std::max<std::size_t>)(1, static_cast<std::size_t>(std::ceil(top_fraction * double(m))));
  std::vector<std::size_t> best(order);
  std::stable_sort(best.begin(), best.end(), [&](std::size_t a, std::size_t b) {
    return score[a] != score[b] ? score[a] > score[b] : a < b;
  });
  std::size_t hits = 0;
  for(std::size_t k = 0; k < top; ++k)
    hits += positive[best[k]] ? 1 : 0;
  r.top_precision = double(hits) / double(top);
  return r;
}

} // namespace psb

#endif // CGAL_SHAPE_ANALYSIS_BENCH_EDGE_PREDICTION_H
