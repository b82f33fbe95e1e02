// Copyright (c) 2026 CGAL Global Shape Analysis contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_SHAPE_ANALYSIS_INTERNAL_UNION_FIND_H
#define CGAL_SHAPE_ANALYSIS_INTERNAL_UNION_FIND_H

// Disjoint sets over 0..n-1 (path halving), for the connected components and merge histories
// of the graph machinery.

#include <cstdint>
#include <numeric>
#include <vector>

namespace CGAL {
namespace Shape_analysis {
namespace internal {

class Union_find
{
public:
  explicit Union_find(std::size_t n = 0) { reset(n); }

  void reset(std::size_t n)
  {
    m_parent.resize(n);
    std::iota(m_parent.begin(), m_parent.end(), 0u);
  }

  std::uint32_t find(std::uint32_t x)
  {
    while(m_parent[x] != x) {
      m_parent[x] = m_parent[m_parent[x]];
      x = m_parent[x];
    }
    return x;
  }

  // Joins the sets of a and b; the smaller root id becomes the root. Returns false if they
  // were already one set.
  bool unite(std::uint32_t a, std::uint32_t b)
  {
    a = find(a);
    b = find(b);
    if(a == b)
      return false;
    if(a < b)
      m_parent[b] = a;
    else
      m_parent[a] = b;
    return true;
  }

  // Joins the set of `absorbed` into the set of `survivor`, whose root stays the root.
  void absorb(std::uint32_t survivor, std::uint32_t absorbed)
  {
    const std::uint32_t s = find(survivor), a = find(absorbed);
    if(s != a)
      m_parent[a] = s;
  }

  // Dense set numbers 0..k-1 in the order of the first element of each set; returns k.
  std::size_t dense_labels(std::vector<std::uint32_t>& label)
  {
    const std::size_t n = m_parent.size();
    const std::uint32_t none = ~std::uint32_t(0);
    std::vector<std::uint32_t> dense(n, none);
    label.resize(n);
    std::uint32_t count = 0;
    for(std::size_t i = 0; i < n; ++i) {
      const std::uint32_t r = find(static_cast<std::uint32_t>(i));
      if(dense[r] == none)
        dense[r] = count++;
      label[i] = dense[r];
    }
    return count;
  }

private:
  std::vector<std::uint32_t> m_parent;
};

} // namespace internal
} // namespace Shape_analysis
} // namespace CGAL

#endif // CGAL_SHAPE_ANALYSIS_INTERNAL_UNION_FIND_H
