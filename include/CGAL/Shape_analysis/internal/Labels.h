// Copyright (c) 2026 CGAL Global Shape Analysis contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_SHAPE_ANALYSIS_INTERNAL_LABELS_H
#define CGAL_SHAPE_ANALYSIS_INTERNAL_LABELS_H

// Segment labels of graph nodes: numbering by size.

#include <algorithm>
#include <numeric>
#include <vector>

namespace CGAL {
namespace Shape_analysis {
namespace internal {

// Numbers the segments 0..k-1 by decreasing total size (ties: smallest node first).
inline std::vector<std::size_t> number_by_size(const std::vector<std::size_t>& labels,
                                               const std::vector<double>& sizes)
{
  std::size_t k = 0;
  for(std::size_t l : labels)
    k = (std::max)(k, l + 1);
  std::vector<double> area(k, 0.0);
  std::vector<std::size_t> first(k, labels.size());
  for(std::size_t i = 0; i < labels.size(); ++i) {
    area[labels[i]] += sizes[i];
    first[labels[i]] = (std::min)(first[labels[i]], i);
  }
  std::vector<std::size_t> order(k);
  std::iota(order.begin(), order.end(), std::size_t(0));
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    return area[a] != area[b] ? area[a] > area[b] : first[a] < first[b];
  });
  std::vector<std::size_t> rank(k);
  for(std::size_t r = 0; r < k; ++r)
    rank[order[r]] = r;
  std::vector<std::size_t> result(labels.size());
  for(std::size_t i = 0; i < labels.size(); ++i)
    result[i] = rank[labels[i]];
  return result;
}

} // namespace internal
} // namespace Shape_analysis
} // namespace CGAL

#endif // CGAL_SHAPE_ANALYSIS_INTERNAL_LABELS_H
