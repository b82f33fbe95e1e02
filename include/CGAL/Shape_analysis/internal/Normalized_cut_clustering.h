// Copyright (c) 2026 CGAL Global Shape Analysis contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_SHAPE_ANALYSIS_INTERNAL_NORMALIZED_CUT_CLUSTERING_H
#define CGAL_SHAPE_ANALYSIS_INTERNAL_NORMALIZED_CUT_CLUSTERING_H

// Agglomerative clustering of a weighted graph by the area-normalized cut
//   J = sum over clusters S of cut(S) / size(S)
// Starting from singletons (or from a given initial partition, which acts as must-link
// constraints), the pair of adjacent clusters whose merge lowers J the most is merged, until the
// requested number of clusters remains or no allowed merge is left. Merging S and T changes J by
//   dJ = (cut(S) + cut(T) - 2 w(S,T)) / (size(S) + size(T)) - cut(S)/size(S) - cut(T)/size(T) <= 0
// and only the pairs that involve the new cluster change, so a priority queue with lazy
// invalidation (a version counter per cluster) keeps every step O(degree log n).
//
// Clusters smaller than `small_size` are merged before any pair of larger clusters is (so that a
// speck bounded by near-zero cut costs, such as a folded-over face, cannot survive as a segment).
// Options: a constraints hook `can_merge(a, b)` (cluster ids) consulted before a pair is queued,
// a notification `on_merge(survivor, absorbed)`, and a randomized choice: with randomness r > 0
// the pair picked is drawn with probability proportional to |dJ|^(1/r) among the merges that
// lower J (Gumbel perturbation of log|dJ|), from a generator seeded by the caller.

#include <CGAL/Shape_analysis/internal/Random.h>
#include <CGAL/Shape_analysis/internal/Union_find.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>
#include <limits>
#include <queue>
#include <utility>
#include <vector>

namespace CGAL {
namespace Shape_analysis {
namespace internal {

class Normalized_cut_clustering
{
public:
  typedef std::uint32_t Id;

  struct Merge
  {
    Id survivor;
    Id absorbed;
    double delta;          // change of J
    double size;           // size of the merged cluster
  };

  // `sizes[i]` is the size of node i; edges are (source[e], target[e], weight[e]).
  Normalized_cut_clustering(const std::vector<double>& sizes,
                            const std::vector<std::uint32_t>& source,
                            const std::vector<std::uint32_t>& target,
                            const std::vector<double>& weight)
  {
    const std::size_t n = sizes.size();
    double total = 0;
    for(double s : sizes)
      total += s;
    // Zero-size nodes (degenerate faces) get a tiny size so that they merge first.
    const double tiny = (n > 0 && total > 0) ? 1e-9 * total / double(n) : 1e-300;
    m_size.resize(n);
    for(std::size_t i = 0; i < n; ++i)
      m_size[i] = sizes[i] > tiny ? sizes[i] : tiny;
    m_cut.assign(n, 0.0);
    m_version.assign(n, 0);
    m_sets.reset(n);
    m_alive.assign(n, 1);
    m_number_of_clusters = n;
    m_adjacency.assign(n, {});
    for(std::size_t e = 0; e < source.size(); ++e) {
      const Id u = source[e], v = target[e];
      if(u == v || !(weight[e] >= 0))
        continue;
      m_adjacency[u].emplace_back(v, weight[e]);
      m_adjacency[v].emplace_back(u, weight[e]);
      m_cut[u] += weight[e];
      m_cut[v] += weight[e];
    }
    for(auto& list : m_adjacency)
      normalize(list);
  }

  std::size_t number_of_clusters() const { return m_number_of_clusters; }
  bool is_cluster(Id c) const { return m_alive[c] != 0; }
  double cluster_size(Id c) const { return m_size[c]; }
  double cluster_cut(Id c) const { return m_cut[c]; }
  const std::vector<std::pair<Id, double>>& neighbors(Id c) const { return m_adjacency[c]; }
  const std::vector<Merge>& merges() const { return m_merges; }

  // Merges directly every group of nodes that share a label (must-link constraints). Labels are
  // arbitrary integers, one per node.
  template <typename Label>
  void merge_groups(const std::vector<Label>& labels)
  {
    std::vector<std::pair<Label, Id>> order;
    order.reserve(labels.size());
    for(std::size_t i = 0; i < labels.size(); ++i)
      order.emplace_back(labels[i], static_cast<Id>(i));
    std::sort(order.begin(), order.end());
    for(std::size_t i = 1; i < order.size(); ++i)
      if(order[i].first == order[i - 1].first) {
        const Id a = find(order[i - 1].second), b = find(order[i].second);
        if(a != b)
          merge(a, b, delta(a, b, weight_between(a, b)));
      }
  }

  // Merges until `target` clusters remain or no allowed pair is left.
  void run(std::size_t target,
           const std::function<bool(Id, Id)>& can_merge = {},
           const std::function<void(Id, Id)>& on_merge = {},
           double randomness = 0, std::uint64_t seed = 0, double small_size = 0)
  {
    m_can_merge = can_merge;
    m_small_size = small_size;
    m_randomness = randomness;
    m_rng = Random_stream(seed);
    m_queue = Queue();
    for(Id a = 0; a < m_alive.size(); ++a) {
      if(!m_alive[a])
        continue;
      for(const auto& nb : m_adjacency[a])
        if(a < nb.first)
          push(a, nb.first, nb.second);
    }
    while(m_number_of_clusters > target && !m_queue.empty()) {
      const Entry top = m_queue.top();
      m_queue.pop();
      if(!m_alive[top.a] || !m_alive[top.b] || m_version[top.a] != top.version_a ||
         m_version[top.b] != top.version_b)
        continue;
      const Id survivor = merge(top.a, top.b, top.delta);
      const Id absorbed = survivor == top.a ? top.b : top.a;
      if(on_merge)
        on_merge(survivor, absorbed);
      for(const auto& nb : m_adjacency[survivor])
        push(survivor, nb.first, nb.second);
    }
    m_queue = Queue();
  }

  // Cluster id (the id of a surviving node) of node i.
  Id find(Id i) { return m_sets.find(i); }

  // Dense labels 0..k-1, numbered in the order of the first node of each cluster.
  std::vector<std::size_t> labels()
  {
    std::vector<std::uint32_t> dense;
    m_sets.dense_labels(dense);
    return std::vector<std::size_t>(dense.begin(), dense.end());
  }

  double delta(Id a, Id b, double w_ab) const
  {
    return (m_cut[a] + m_cut[b] - 2 * w_ab) / (m_size[a] + m_size[b]) - m_cut[a] / m_size[a] -
           m_cut[b] / m_size[b];
  }

private:
  struct Entry
  {
    int level; // 0-1: a cluster smaller than `small_size` is involved; such pairs go first
    double key;
    double delta;
    Id a, b;
    std::uint32_t version_a, version_b;
    bool operator<(const Entry& o) const // for a max-heap: the smallest key on top
    {
      if(level != o.level)
        return level > o.level;
      if(key != o.key)
        return key > o.key;
      if(a != o.a)
        return a > o.a;
      return b > o.b;
    }
  };
  typedef std::priority_queue<Entry> Queue;

  static void normalize(std::vector<std::pair<Id, double>>& list)
  {
    std::sort(list.begin(), list.end(),
              [](const auto& x, const auto& y) { return x.first < y.first; });
    std::size_t out = 0;
    for(std::size_t i = 0; i < list.size(); ++i) {
      if(out > 0 && list[out - 1].first == list[i].first)
        list[out - 1].second += list[i].second;
      else
        list[out++] = list[i];
    }
    list.resize(out);
  }

  static std::vector<std::pair<Id, double>>::iterator
  lower(std::vector<std::pair<Id, double>>& list, Id id)
  {
    return std::lower_bound(list.begin(), list.end(), id,
                            [](const std::pair<Id, double>& x, Id v) { return x.first < v; });
  }

  double weight_between(Id a, Id b)
  {
    auto it = lower(m_adjacency[a], b);
    return (it != m_adjacency[a].end() && it->first == b) ? it->second : 0.0;
  }

  void push(Id a, Id b, double w_ab)
  {
    if(a > b)
      std::swap(a, b);
    if(m_can_merge && !m_can_merge(a, b))
      return;
    const double d = delta(a, b, w_ab);
    double key = d;
    // Pairs with a speck first (level 0-1), then the others (2-3).
    int level = (m_size[a] < m_small_size || m_size[b] < m_small_size) ? 0 : 2;
    if(m_randomness > 0) {
      // Gumbel-max trick, in the log domain: the smallest key among the queued pairs is a draw
      // from them with probability proportional to |d|^(1/r) among the merges that lower J
      // (d < 0; the noise of a pair is drawn when it is queued, so later draws are only about
      // so distributed); merges that do not lower J come after all of those (level + 1), drawn
      // with probability proportional to d^(-1/r).
      const double u = (std::max)(1e-300, m_rng.uniform());
      const double gumbel = -std::log(-std::log(u));
      if(d < 0)
        key = -(std::log(-d) + m_randomness * gumbel);
      else {
        key = (d > 0 ? std::log(d) : -std::numeric_limits<double>::infinity()) - m_randomness * gumbel;
        ++level;
      }
    }
    m_queue.push(Entry{level, key, d, a, b, m_version[a], m_version[b]});
  }

  // Merges clusters a and b; returns the surviving id.
  Id merge(Id a, Id b, double d)
  {
    if(m_adjacency[a].size() < m_adjacency[b].size())
      std::swap(a, b);
    const Id s = a, t = b;
    const double w_st = weight_between(s, t);

    // Merge the sorted neighbor lists, dropping s and t.
    std::vector<std::pair<Id, double>>& merged = m_buffer; // reused across merges
    merged.clear();
    merged.reserve(m_adjacency[s].size() + m_adjacency[t].size());
    auto i = m_adjacency[s].begin(), ie = m_adjacency[s].end();
    auto j = m_adjacency[t].begin(), je = m_adjacency[t].end();
    while(i != ie || j != je) {
      std::pair<Id, double> next;
      if(j == je || (i != ie && i->first < j->first))
        next = *i++;
      else if(i == ie || j->first < i->first)
        next = *j++;
      else {
        next = {i->first, i->second + j->second};
        ++i;
        ++j;
      }
      if(next.first != s && next.first != t)
        merged.push_back(next);
    }
    // Redirect t's neighbors to s.
    for(const auto& nb : m_adjacency[t]) {
      if(nb.first == s)
        continue;
      auto& list = m_adjacency[nb.first];
      auto it_t = lower(list, t);
      const double w = it_t->second;
      list.erase(it_t);
      auto it_s = lower(list, s);
      if(it_s != list.end() && it_s->first == s)
        it_s->second += w;
      else
        list.insert(it_s, std::make_pair(s, w));
    }
    m_adjacency[s].swap(merged); // the old list of s becomes the buffer
    std::vector<std::pair<Id, double>>().swap(m_adjacency[t]);

    m_cut[s] = (std::max)(0.0, m_cut[s] + m_cut[t] - 2 * w_st);
    m_size[s] += m_size[t];
    m_alive[t] = 0;
    m_sets.absorb(s, t);
    ++m_version[s];
    ++m_version[t];
    --m_number_of_clusters;
    m_merges.push_back(Merge{s, t, d, m_size[s]});
    return s;
  }

  std::vector<double> m_size, m_cut;
  std::vector<std::uint32_t> m_version;
  Union_find m_sets; // node -> cluster
  std::vector<char> m_alive;
  std::vector<std::vector<std::pair<Id, double>>> m_adjacency;
  std::vector<Merge> m_merges;
  std::vector<std::pair<Id, double>> m_buffer;
  std::size_t m_number_of_clusters = 0;
  std::function<bool(Id, Id)> m_can_merge;
  double m_randomness = 0;
  double m_small_size = 0;
  Random_stream m_rng;
  Queue m_queue;
};

} // namespace internal
} // namespace Shape_analysis
} // namespace CGAL

#endif // CGAL_SHAPE_ANALYSIS_INTERNAL_NORMALIZED_CUT_CLUSTERING_H
