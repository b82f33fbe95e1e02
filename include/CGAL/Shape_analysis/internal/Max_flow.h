// Copyright (c) 2026 CGAL Global Shape Analysis contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_SHAPE_ANALYSIS_INTERNAL_MAX_FLOW_H
#define CGAL_SHAPE_ANALYSIS_INTERNAL_MAX_FLOW_H

// Maximum flow / minimum cut between two nodes of a graph in compressed rows, by the
// Boykov-Kolmogorov augmenting-path algorithm (two search trees, grown from the source and from
// the sink, reused from one augmentation to the next; nodes cut off by a saturated arc look for a
// new parent in their tree, the one closest to its root, before being freed).
//
// Written for the many cuts of randomized sampling: the topology (rows, targets, reverse arcs) is
// given once and only read; each thread solves with its own Workspace, whose buffers are reused,
// so a solve allocates nothing once the buffers have grown. Indices are 32-bit.

#include <algorithm>
#include <cstdint>
#include <limits>
#include <vector>

namespace CGAL {
namespace Shape_analysis {
namespace internal {

class Bk_max_flow
{
public:
  typedef std::uint32_t Index;
  enum Tree : unsigned char { FREE = 0, SOURCE_TREE = 1, SINK_TREE = 2 };

  struct Workspace
  {
    std::vector<double> residual;   // per arc
    std::vector<unsigned char> tree; // per node
    std::vector<Index> parent;       // per node: the arc from the node to its parent, or a mark
    std::vector<Index> distance, stamp;
    std::vector<unsigned char> active_flag;
    std::vector<Index> active, orphans;
  };

  // The graph: arcs first[u] .. first[u+1]-1 leave u; target[a] is the head of arc a and
  // reverse[a] the arc going the other way (every arc has one). The arrays must outlive the
  // object.
  Bk_max_flow(const std::vector<std::size_t>& first, const std::vector<Index>& target,
              const std::vector<Index>& reverse)
    : m_first(&first), m_target(&target), m_reverse(&reverse)
  {}

  std::size_t number_of_nodes() const { return m_first->size() - 1; }

  // Maximum flow from `source` to `sink` with the given capacity per arc (finite, >= 0); returns
  // its value. Afterwards is_source_side(w, u) tells the side of u in a minimum cut (the nodes
  // the source can still reach in the residual graph).
  double solve(const std::vector<double>& capacity, Index source, Index sink, Workspace& w) const
  {
    w.residual.assign(capacity.begin(), capacity.end());
    return augment_to_maximum(source, sink, w);
  }

  // The maximum flow between the same `source` and `sink` as the last solve with `w`, after the
  // capacities grew from `old_capacity` (those of that solve) to `new_capacity` (no arc's
  // capacity may decrease): the flow found then stays feasible and is only augmented further.
  // Returns the flow added.
  double solve_with_larger_capacities(const std::vector<double>& old_capacity,
                                      const std::vector<double>& new_capacity, Index source,
                                      Index sink, Workspace& w) const
  {
    for(std::size_t a = 0; a < w.residual.size(); ++a)
      w.residual[a] += new_capacity[a] - old_capacity[a];
    return augment_to_maximum(source, sink, w);
  }

  static bool is_source_side(const Workspace& w, std::size_t u) { return w.tree[u] == SOURCE_TREE; }

private:
  // Augments the flow whose residual capacities are in `w.residual` to a maximum one; returns
  // the flow added. Growth, augmentation and adoption are member functions of their own, defined
  // in the class (inline) and called once per augmentation: the split costs no speed.
  double augment_to_maximum(Index source, Index sink, Workspace& w) const
  {
    const std::size_t n = number_of_nodes();
    w.tree.assign(n, FREE);
    w.parent.assign(n, none);
    w.distance.assign(n, 0);
    w.stamp.assign(n, 0);
    w.active_flag.assign(n, 0);
    w.active.clear();
    w.orphans.clear();
    if(source == sink)
      return 0;
    Index time = 1;
    w.tree[source] = SOURCE_TREE;
    w.tree[sink] = SINK_TREE;
    w.parent[source] = w.parent[sink] = terminal;
    w.stamp[source] = w.stamp[sink] = time;
    std::size_t active_head = 0;
    activate(source, w);
    activate(sink, w);
    double flow = 0;

    for(;;) {
      const Index bridge = grow(active_head, w);
      if(bridge == none)
        break;
      ++time;
      flow += augment(bridge, w);
      // Adoption.
      for(std::size_t k = 0; k < w.orphans.size(); ++k)
        adopt(w.orphans[k], time, w);
      w.orphans.clear();
    }
    return flow;
  }

  static void activate(Index v, Workspace& w)
  {
    if(!w.active_flag[v]) {
      w.active_flag[v] = 1;
      w.active.push_back(v);
    }
  }

  // Growth: returns an arc from the source tree to the sink tree (`none` when there is none left:
  // the flow is maximum), growing the trees from the active nodes `w.active[active_head..]`.
  Index grow(std::size_t& active_head, Workspace& w) const
  {
    const std::vector<std::size_t>& first = *m_first;
    const std::vector<Index>& target = *m_target;
    const std::vector<Index>& reverse = *m_reverse;
    Index bridge = none; // arc from a source-tree node to a sink-tree node
    while(active_head < w.active.size()) {
      const Index p = w.active[active_head];
      if(w.tree[p] == FREE) {
        w.active_flag[p] = 0;
        ++active_head;
        continue;
      }
      const bool in_source = w.tree[p] == SOURCE_TREE;
      for(std::size_t a = first[p]; a < first[p + 1]; ++a) {
        const Index q = target[a];
        // Residual capacity in the direction of the flow: p->q in the source tree, q->p in
        // the sink tree.
        if(!(w.residual[in_source ? a : reverse[a]] > 0))
          continue;
        if(w.tree[q] == FREE) {
          w.tree[q] = w.tree[p];
          w.parent[q] = reverse[a];
          w.distance[q] = w.distance[p] + 1;
          w.stamp[q] = w.stamp[p];
          activate(q, w);
        } else if(w.tree[q] != w.tree[p]) {
          bridge = in_source ? Index(a) : reverse[a];
          break;
        } else if(w.stamp[q] <= w.stamp[p] && w.distance[q] > w.distance[p]) {
          // A shorter way to the root for q.
          w.parent[q] = reverse[a];
          w.distance[q] = w.distance[p] + 1;
          w.stamp[q] = w.stamp[p];
        }
      }
      if(bridge != none)
        break; // p stays active
      w.active_flag[p] = 0;
      ++active_head;
    }
    if(bridge != none && active_head > 4096 && 2 * active_head > w.active.size()) {
      w.active.erase(w.active.begin(), w.active.begin() + std::ptrdiff_t(active_head));
      active_head = 0;
    }
    return bridge;
  }

  // Augmentation along source ... x -> y ... sink through the arc `bridge` (x -> y): pushes the
  // bottleneck capacity of the path, returned; the nodes cut off from their parent become orphans.
  double augment(Index bridge, Workspace& w) const
  {
    const std::vector<Index>& target = *m_target;
    const std::vector<Index>& reverse = *m_reverse;
    const Index x = target[reverse[bridge]], y = target[bridge];
    double bottleneck = w.residual[bridge];
    for(Index v = x; w.parent[v] != terminal; v = target[w.parent[v]])
      bottleneck = (std::min)(bottleneck, w.residual[reverse[w.parent[v]]]);
    for(Index v = y; w.parent[v] != terminal; v = target[w.parent[v]])
      bottleneck = (std::min)(bottleneck, w.residual[w.parent[v]]);
    w.residual[bridge] -= bottleneck;
    w.residual[reverse[bridge]] += bottleneck;
    for(Index v = x; w.parent[v] != terminal;) {
      const Index up = w.parent[v]; // v -> parent; the flow goes parent -> v
      const Index next = target[up];
      w.residual[reverse[up]] -= bottleneck;
      w.residual[up] += bottleneck;
      if(!(w.residual[reverse[up]] > 0)) {
        w.parent[v] = orphan;
        w.orphans.push_back(v);
      }
      v = next;
    }
    for(Index v = y; w.parent[v] != terminal;) {
      const Index up = w.parent[v]; // the flow goes v -> parent
      const Index next = target[up];
      w.residual[up] -= bottleneck;
      w.residual[reverse[up]] += bottleneck;
      if(!(w.residual[up] > 0)) {
        w.parent[v] = orphan;
        w.orphans.push_back(v);
      }
      v = next;
    }
    return bottleneck;
  }

  static constexpr Index none = ~Index(0);
  static constexpr Index terminal = ~Index(0) - 1;
  static constexpr Index orphan = ~Index(0) - 2;

  void adopt(Index v, Index time, Workspace& w) const
  {
    const std::vector<std::size_t>& first = *m_first;
    const std::vector<Index>& target = *m_target;
    const std::vector<Index>& reverse = *m_reverse;
    const unsigned char tree = w.tree[v];
    const bool in_source = tree == SOURCE_TREE;
    Index best_arc = none, best_distance = none;
    for(std::size_t a = first[v]; a < first[v + 1]; ++a) {
      const Index q = target[a];
      if(w.tree[q] != tree)
        continue;
      // The arc must carry flow from the new parent to v (source tree) or from v to it (sink).
      if(!(w.residual[in_source ? reverse[a] : a] > 0))
        continue;
      // Does q still hang from the root? Walk up until a node checked at this time, the root, or
      // an orphan.
      Index d = 0;
      Index u = q;
      bool rooted = false;
      for(;;) {
        if(w.stamp[u] == time) {
          d += w.distance[u];
          rooted = true;
          break;
        }
        const Index up = w.parent[u];
        if(up == terminal) {
          w.stamp[u] = time;
          w.distance[u] = 0;
          rooted = true;
          break;
        }
        if(up == orphan)
          break;
        ++d;
        u = target[up];
      }
      if(!rooted)
        continue;
      if(d < best_distance) {
        best_distance = d;
        best_arc = static_cast<Index>(a);
      }
      // Remember the distances along the checked path.
      Index dd = d;
      for(u = q; w.stamp[u] != time; u = target[w.parent[u]]) {
        w.stamp[u] = time;
        w.distance[u] = dd--;
      }
    }
    if(best_arc != none) {
      w.parent[v] = best_arc;
      w.stamp[v] = time;
      w.distance[v] = best_distance + 1;
      return;
    }
    // No parent: v leaves its tree; its children become orphans, and the neighbours that could
    // grow into it become active.
    for(std::size_t a = first[v]; a < first[v + 1]; ++a) {
      const Index q = target[a];
      if(w.tree[q] != tree)
        continue;
      if(w.residual[in_source ? reverse[a] : a] > 0)
        activate(q, w);
      const Index up = w.parent[q];
      if(up != terminal && up != orphan && up != none && target[up] == v) {
        w.parent[q] = orphan;
        w.orphans.push_back(q);
      }
    }
    w.tree[v] = FREE;
    w.parent[v] = none;
  }

  const std::vector<std::size_t>* m_first;
  const std::vector<Index>* m_target;
  const std::vector<Index>* m_reverse;
};

} // namespace internal
} // namespace Shape_analysis
} // namespace CGAL

#endif // CGAL_SHAPE_ANALYSIS_INTERNAL_MAX_FLOW_H
