// Copyright (c) 2026 CGAL Global Shape Analysis contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef SHAPE_ANALYSIS_SUPPORT_PARTITION_AGREEMENT_H
#define SHAPE_ANALYSIS_SUPPORT_PARTITION_AGREEMENT_H

// Agreement measures between two partitions of the same items (tests, benchmarks, and later the
// comparison of segmentations): Rand index and best-matching overlap.

#include <algorithm>
#include <cstddef>
#include <map>
#include <stdexcept>
#include <utility>
#include <vector>

namespace CGAL {
namespace Shape_analysis_support {

// Agreement of two partitions of the same items (labels are arbitrary non-negative integers;
// weights default to 1 per item).

namespace agreement_detail {
// Contingency table of two labelings: sorted ((a, b), weight).
template <typename LabelA, typename LabelB>
std::map<std::pair<std::size_t, std::size_t>, double>
contingency(const std::vector<LabelA>& a, const std::vector<LabelB>& b,
            const std::vector<double>* weights)
{
  if(a.size() != b.size() || (weights != nullptr && weights->size() != a.size()))
    throw std::invalid_argument("partition agreement: sizes differ");
  std::map<std::pair<std::size_t, std::size_t>, double> table;
  for(std::size_t i = 0; i < a.size(); ++i)
    table[{static_cast<std::size_t>(a[i]), static_cast<std::size_t>(b[i])}] +=
      weights != nullptr ? (*weights)[i] : 1.0;
  return table;
}
} // namespace agreement_detail

// Rand index: the fraction of pairs of items on which the two partitions agree (same part in
// both, or different parts in both); 1 for identical partitions up to relabelling. With weights,
// pairs are weighted by the product of their weights (self-pairs excluded only without weights).
template <typename LabelA, typename LabelB>
double rand_index(const std::vector<LabelA>& a, const std::vector<LabelB>& b,
                  const std::vector<double>* weights = nullptr)
{
  const auto table = agreement_detail::contingency(a, b, weights);
  std::map<std::size_t, double> row, column;
  double total = 0;
  for(const auto& cell : table) {
    row[cell.first.first] += cell.second;
    column[cell.first.second] += cell.second;
    total += cell.second;
  }
  // Sum over pairs: with unit weights, number of pairs C(x, 2) = x (x - 1) / 2; with weights,
  // the weighted analogue x^2 / 2.
  const bool unit = weights == nullptr;
  auto pairs = [unit](double x) { return unit ? 0.5 * x * (x - 1) : 0.5 * x * x; };
  double same_both = 0, same_a = 0, same_b = 0;
  for(const auto& cell : table)
    same_both += pairs(cell.second);
  for(const auto& r : row)
    same_a += pairs(r.second);
  for(const auto& c : column)
    same_b += pairs(c.second);
  const double all = pairs(total);
  if(!(all > 0))
    return 1.0;
  // disagreements: pairs together in exactly one of the two partitions
  const double disagree = same_a + same_b - 2 * same_both;
  return 1.0 - disagree / all;
}

// Best-matching overlap: parts of `a` and parts of `b` are matched one to one, greedily by
// largest overlap; returns the matched (weighted) fraction of the items, 1 for identical
// partitions up to relabelling.
template <typename LabelA, typename LabelB>
double matched_overlap(const std::vector<LabelA>& a, const std::vector<LabelB>& b,
                       const std::vector<double>* weights = nullptr)
{
  const auto table = agreement_detail::contingency(a, b, weights);
  std::vector<std::pair<double, std::pair<std::size_t, std::size_t>>> cells;
  double total = 0;
  for(const auto& cell : table) {
    cells.emplace_back(cell.second, cell.first);
    total += cell.second;
  }
  std::sort(cells.begin(), cells.end(), [](const auto& x, const auto& y) {
    return x.first != y.first ? x.first > y.first : x.second < y.second;
  });
  std::map<std::size_t, bool> used_a, used_b;
  double matched = 0;
  for(const auto& c : cells) {
    if(used_a[c.second.first] || used_b[c.second.second])
      continue;
    used_a[c.second.first] = used_b[c.second.second] = true;
    matched += c.first;
  }
  return total > 0 ? matched / total : 1.0;
}

} // namespace Shape_analysis_support
} // namespace CGAL

#endif // SHAPE_ANALYSIS_SUPPORT_PARTITION_AGREEMENT_H
