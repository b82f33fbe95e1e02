// Copyright (c) 2026 CGAL Global Shape Analysis contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_POINT_SET_OBJECT_RECOGNITION_INTERNAL_OBJECT_GRAPH_H
#define CGAL_POINT_SET_OBJECT_RECOGNITION_INTERNAL_OBJECT_GRAPH_H

#include <algorithm>
#include <array>
#include <cstdint>
#include <limits>
#include <numeric>
#include <utility>
#include <vector>

namespace CGAL {
namespace Point_set_object_recognition {
namespace internal {

// A small graph of one object: nodes with a penalty (to the sink) and a hard side, weighted
// edges; contracted by heavy-edge matching.
struct Object_graph
{
  std::vector<double> reward, penalty, points, cells; // per node: foreground reward (to the source), background
                                                      // penalty (to the sink), point count, fine nodes
  std::vector<char> seed;                     // per node: hard foreground
  std::vector<std::array<std::uint32_t, 2>> edges;
  std::vector<double> weight;
  std::vector<std::uint32_t> coarse; // per fine node: its node after contraction

  void clear()
  {
    reward.clear(), penalty.clear(), points.clear(), cells.clear(), seed.clear(), edges.clear(), weight.clear(), coarse.clear();
  }

  // Merges pairs of nodes joined by their heaviest edge (seeds only with seeds) until at most
  // `target` nodes remain or a round merges less than 5% of them.
  void contract(std::size_t target)
  {
    const std::size_t fine = penalty.size();
    coarse.resize(fine);
    std::iota(coarse.begin(), coarse.end(), 0u);
    std::vector<std::size_t> first;
    std::vector<std::pair<std::uint32_t, double>> adjacent;
    std::vector<std::uint32_t> mate, rename;
    while(target > 0 && penalty.size() > target) {
      const std::size_t n = penalty.size();
      adjacency(first, adjacent);
      if(match(first, adjacent, target, mate) < n / 20 + 1)
        break;
      merge(mate, rename);
    }
  }

private:
  static constexpr std::uint32_t unmatched = std::numeric_limits<std::uint32_t>::max();

  // Per node, its neighbours with the edges' weights (those of node v from first[v]).
  void adjacency(std::vector<std::size_t>& first, std::vector<std::pair<std::uint32_t, double>>& adjacent) const
  {
    const std::size_t n = penalty.size();
    first.assign(n + 1, 0);
    for(const auto& e : edges)
      ++first[e[0] + 1], ++first[e[1] + 1];
    for(std::size_t v = 0; v < n; ++v)
      first[v + 1] += first[v];
    adjacent.resize(2 * edges.size());
    std::vector<std::size_t> fill(first.begin(), first.end() - 1);
    for(std::size_t e = 0; e < edges.size(); ++e) {
      adjacent[fill[edges[e][0]]++] = {edges[e][1], weight[e]};
      adjacent[fill[edges[e][1]]++] = {edges[e][0], weight[e]};
    }
  }

  // Per node its mate (`unmatched` for none): by increasing node, the free neighbour of its
  // heaviest edge (the smaller at equal weights), until `target` nodes would remain; the number
  // of pairs.
  std::size_t match(const std::vector<std::size_t>& first, const std::vector<std::pair<std::uint32_t, double>>& adjacent,
                    std::size_t target, std::vector<std::uint32_t>& mate) const
  {
    const std::size_t n = penalty.size();
    mate.assign(n, unmatched);
    std::size_t merges = 0;
    for(std::size_t v = 0; v < n && n - merges > target; ++v) {
      if(mate[v] != unmatched)
        continue;
      std::uint32_t best = unmatched;
      double best_w = 0;
      for(std::size_t a = first[v]; a < first[v + 1]; ++a) {
        const std::uint32_t u = adjacent[a].first;
        if(u == v || mate[u] != unmatched || seed[u] != seed[v])
          continue;
        if(adjacent[a].second > best_w || (adjacent[a].second == best_w && u < best)) {
          best_w = adjacent[a].second;
          best = u;
        }
      }
      if(best == unmatched)
        continue;
      mate[v] = best, mate[best] = std::uint32_t(v);
      ++merges;
    }
    return merges;
  }

  // Merges every node with its mate (the pairs numbered by their first node).
  void merge(const std::vector<std::uint32_t>& mate, std::vector<std::uint32_t>& rename)
  {
    const std::size_t n = penalty.size();
    rename.assign(n, unmatched);
    std::uint32_t next = 0;
    for(std::size_t v = 0; v < n; ++v)
      if(rename[v] == unmatched) {
        rename[v] = next;
        if(mate[v] != unmatched)
          rename[mate[v]] = next;
        ++next;
      }
    std::vector<double> re(next, 0), pe(next, 0), po(next, 0), ce(next, 0);
    std::vector<char> se(next, 0);
    for(std::size_t v = 0; v < n; ++v) {
      re[rename[v]] += reward[v], pe[rename[v]] += penalty[v], po[rename[v]] += points[v], ce[rename[v]] += cells[v];
      se[rename[v]] = seed[v];
    }
    reward.swap(re), penalty.swap(pe), points.swap(po), cells.swap(ce), seed.swap(se);
    // Edges: renamed, self loops dropped, parallel ones summed.
    std::vector<std::pair<std::array<std::uint32_t, 2>, double>> merged;
    merged.reserve(edges.size());
    for(std::size_t e = 0; e < edges.size(); ++e) {
      std::uint32_t a = rename[edges[e][0]], b = rename[edges[e][1]];
      if(a == b)
        continue;
      if(a > b)
        std::swap(a, b);
      merged.push_back({{{a, b}}, weight[e]});
    }
    std::sort(merged.begin(), merged.end(),
              [](const auto& x, const auto& y) { return x.first < y.first; });
    edges.clear(), weight.clear();
    for(const auto& m : merged) {
      if(!edges.empty() && edges.back() == m.first)
        weight.back() += m.second;
      else
        edges.push_back(m.first), weight.push_back(m.second);
    }
    for(std::uint32_t& c : coarse)
      c = rename[c];
  }
};

} // namespace internal
} // namespace Point_set_object_recognition
} // namespace CGAL

#endif // CGAL_POINT_SET_OBJECT_RECOGNITION_INTERNAL_OBJECT_GRAPH_H
