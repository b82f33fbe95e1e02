// Copyright (c) 2026 CGAL Global Shape Analysis contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_CONSISTENT_SEGMENTATION_INTERNAL_JOINT_MERGING_H
#define CGAL_CONSISTENT_SEGMENTATION_INTERNAL_JOINT_MERGING_H

// Stage three of the co-segmentation (see Cosegmentation.h): the greedy merging of the
// over-segments of all meshes by E = E_adj^alpha * E_corr^(1 - alpha).

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>
#include <limits>
#include <map>
#include <numeric>
#include <queue>
#include <utility>
#include <vector>

namespace CGAL {
namespace Consistent_segmentation {
namespace internal {

class Joint_merging
{
public:
  typedef std::uint32_t Id;

  struct Weights
  {
    double adjacency = 0, correspondence = 0;
  };

  Joint_merging(std::size_t n, double alpha) : m_alpha(alpha)
  {
    m_size.assign(n, 0.0);
    m_cut_a.assign(n, 0.0);
    m_cut_c.assign(n, 0.0);
    m_vol_c.assign(n, 0.0);
    m_label.assign(n, -1);
  }

  void set_size(Id v, double s) { m_size[v] = s; }
  void set_label(Id v, long long l) { m_label[v] = l; }

  // An adjacency (a != b) or correspondence link (a == b: inside one node, volume only).
  void add_link(Id a, Id b, double adjacency, double correspondence)
  {
    m_vol_c[a] += correspondence;
    m_vol_c[b] += correspondence;
    if(a == b)
      return;
    m_cut_a[a] += adjacency;
    m_cut_a[b] += adjacency;
    m_cut_c[a] += correspondence;
    m_cut_c[b] += correspondence;
    m_links.push_back(Link{a, b, Weights{adjacency, correspondence}});
  }

  // Merges down to `target` segments; with `refine`, a pass of node moves every `interval`
  // merges and at the end.
  void run(std::size_t target, std::size_t interval, bool refine,
           const std::function<void(double)>& progress)
  {
    const std::size_t n = m_size.size();
    {
      double volume = 0, size = 0;
      for(Id v = 0; v < n; ++v) {
        volume += m_vol_c[v];
        size += m_size[v];
      }
      m_unsupported = size > 0 ? unsupported_fraction * volume / size : 0.0;
    }
    m_node_arcs = arcs_of(n, [](Id v) { return v; });
    std::vector<Link>().swap(m_links);
    m_segment.resize(n);
    std::iota(m_segment.begin(), m_segment.end(), Id(0));
    m_members.assign(n, {});
    for(Id v = 0; v < n; ++v)
      m_members[v] = {v};
    // Nodes of one known label start as one segment.
    std::map<long long, Id> first_of_label;
    for(Id v = 0; v < n; ++v)
      if(m_label[v] >= 0) {
        auto it = first_of_label.emplace(m_label[v], v);
        if(!it.second)
          move_node(v, it.first->second);
      }
    rebuild_segments();
    m_floor_a = floor_fraction * m_sum_a;
    m_floor_c = floor_fraction * m_sum_c;
    const std::size_t start = m_alive.size();
    std::size_t merges = 0;
    while(m_alive.size() > target) {
      Id a = 0, b = 0;
      bool found = false;
      if(m_alive.size() > exact_threshold)
        found = queued_pair(a, b);
      if(!found)
        found = best_pair(a, b, true) || best_pair(a, b, false);
      if(!found)
        break; // only segments of different known labels are left
      merge_segments(a, b);
      ++merges;
      if(refine && interval > 0 && merges % interval == 0)
        refine_pass();
      if(progress && start > target)
        progress(double(start - m_alive.size()) / double(start - target));
    }
    if(refine)
      for(int pass = 0; pass < 3 && refine_pass() > 0; ++pass) {
      }
  }

  // Segment of node v (the id of a node of the segment).
  Id segment(Id v) const { return m_segment[v]; }
  long long segment_label(Id s) const { return m_seg_label[s]; }

private:
  struct Link
  {
    Id a, b;
    Weights w;
  };
  struct Arc
  {
    Id to;
    Weights w;
  };
  struct Entry
  {
    double key;
    Id a, b;
    std::uint32_t version_a, version_b;
    bool operator<(const Entry& o) const // max-heap: the smallest key on top
    {
      if(key != o.key)
        return key > o.key;
      if(a != o.a)
        return a > o.a;
      return b > o.b;
    }
  };

  // Above this many segments, merges are taken from a priority queue keyed by the first-order
  // change of log E (refreshed when E_adj or E_corr has moved by more than 2% since the keys were
  // computed); below it, every candidate pair is evaluated exactly at every merge.
  static constexpr std::size_t exact_threshold = 400;

  // Sorted, accumulated arcs between the groups `group(v)` of the links' ends.
  template <typename Group>
  std::vector<std::vector<Arc>> arcs_of(std::size_t n, const Group& group) const
  {
    std::vector<std::pair<std::uint64_t, Weights>> all;
    all.reserve(2 * m_links.size());
    const auto add = [&](Id x, Id y, const Weights& w) {
      const Id gx = group(x), gy = group(y);
      if(gx != gy) {
        all.emplace_back((std::uint64_t(gx) << 32) | gy, w);
        all.emplace_back((std::uint64_t(gy) << 32) | gx, w);
      }
    };
    if(!m_links.empty())
      for(const Link& l : m_links)
        add(l.a, l.b, l.w);
    else
      for(Id v = 0; v < m_node_arcs.size(); ++v)
        for(const Arc& arc : m_node_arcs[v])
          if(v < arc.to)
            add(v, arc.to, arc.w);
    std::sort(all.begin(), all.end(), [](const auto& x, const auto& y) { return x.first < y.first; });
    std::vector<std::vector<Arc>> arcs(n);
    for(std::size_t i = 0; i < all.size(); ++i) {
      const Id from = Id(all[i].first >> 32), to = Id(all[i].first & 0xFFFFFFFFu);
      auto& list = arcs[from];
      if(!list.empty() && list.back().to == to) {
        list.back().w.adjacency += all[i].second.adjacency;
        list.back().w.correspondence += all[i].second.correspondence;
      } else
        list.push_back(Arc{to, all[i].second});
    }
    return arcs;
  }

  double term_a(double cut, double size) const { return size > 0 ? cut / size : 0.0; }
  // The correspondence term of a segment of area `size`: its normalized cut, with a virtual link
  // volume proportional to its area that always counts as cut. A segment that no correspondence
  // supports (a small piece that no sample fell on, a part that matches nothing) then costs as much
  // as a fully cut one, and is merged by the adjacency evidence first, instead of being kept as a
  // free segment while real parts are merged; well supported segments barely change.
  double term_c(double cut, double vol, double size) const
  {
    const double u = m_unsupported * size;
    return vol + u > 0 ? (cut + u) / (vol + u) : 0.0;
  }
  // log E. Each factor has a floor (a small fraction of its value before any merge): without it,
  // a state where one factor vanishes (every segment a union of whole meshes, or all sampled area
  // in one segment) would score minus infinity whatever the other factor says.
  double objective(double ea, double ec) const
  {
    const double tiny = 1e-300;
    return m_alpha * std::log((std::max)(ea + m_floor_a, tiny)) +
           (1 - m_alpha) * std::log((std::max)(ec + m_floor_c, tiny));
  }

  bool compatible(Id a, Id b) const
  {
    return m_seg_label[a] < 0 || m_seg_label[b] < 0 || m_seg_label[a] == m_seg_label[b];
  }

  // The changes of E_adj and E_corr if segments a and b merged.
  void deltas(Id a, Id b, const Weights& w, double& da, double& dc) const
  {
    da = term_a((std::max)(0.0, m_ca[a] + m_ca[b] - 2 * w.adjacency), m_sa[a] + m_sa[b]) - m_ta[a] - m_ta[b];
    dc = term_c((std::max)(0.0, m_cc[a] + m_cc[b] - 2 * w.correspondence), m_vc[a] + m_vc[b],
                m_sa[a] + m_sa[b]) -
         m_tc[a] - m_tc[b];
  }

  // The merge of two segments that lowers E the most; among linked pairs (`linked`) or any two.
  bool best_pair(Id& best_a, Id& best_b, bool linked) const
  {
    double best = std::numeric_limits<double>::infinity();
    bool found = false;
    auto consider = [&](Id a, Id b, const Weights& w) {
      if(!compatible(a, b))
        return;
      double da = 0, dc = 0;
      deltas(a, b, w, da, dc);
      const double e = objective(m_sum_a + da, m_sum_c + dc);
      if(e < best) {
        best = e;
        best_a = a;
        best_b = b;
        found = true;
      }
    };
    if(linked) {
      for(Id a : m_alive)
        for(const Arc& arc : m_seg_arcs[a])
          if(a < arc.to)
            consider(a, arc.to, arc.w);
    } else {
      const Weights none;
      for(std::size_t i = 0; i < m_alive.size(); ++i)
        for(std::size_t j = i + 1; j < m_alive.size(); ++j)
          consider((std::min)(m_alive[i], m_alive[j]), (std::max)(m_alive[i], m_alive[j]), none);
    }
    return found;
  }

  void push(Id a, Id b, const Weights& w)
  {
    if(a > b)
      std::swap(a, b);
    if(!compatible(a, b))
      return;
    double da = 0, dc = 0;
    deltas(a, b, w, da, dc);
    const double key = m_alpha * da / (std::max)(m_key_a + m_floor_a, 1e-300) +
                       (1 - m_alpha) * dc / (std::max)(m_key_c + m_floor_c, 1e-300);
    m_queue.push(Entry{key, a, b, m_version[a], m_version[b]});
  }

  void rebuild_queue()
  {
    m_queue = std::priority_queue<Entry>();
    m_key_a = m_sum_a;
    m_key_c = m_sum_c;
    for(Id a : m_alive)
      for(const Arc& arc : m_seg_arcs[a])
        if(a < arc.to)
          push(a, arc.to, arc.w);
  }

  bool queued_pair(Id& a, Id& b)
  {
    const auto moved = [](double now, double then) {
      return then > 0 ? std::abs(now - then) > 0.02 * then : now > 0;
    };
    if(!m_queue_valid || moved(m_sum_a, m_key_a) || moved(m_sum_c, m_key_c)) {
      rebuild_queue();
      m_queue_valid = true;
    }
    while(!m_queue.empty()) {
      const Entry top = m_queue.top();
      m_queue.pop();
      if(m_members[top.a].empty() || m_members[top.b].empty() || m_version[top.a] != top.version_a ||
         m_version[top.b] != top.version_b)
        continue;
      a = top.a;
      b = top.b;
      return true;
    }
    return false;
  }

  void set_terms(Id s)
  {
    m_sum_a -= m_ta[s];
    m_sum_c -= m_tc[s];
    m_ta[s] = term_a(m_ca[s], m_sa[s]);
    m_tc[s] = term_c(m_cc[s], m_vc[s], m_sa[s]);
    m_sum_a += m_ta[s];
    m_sum_c += m_tc[s];
  }

  static std::vector<Arc>::iterator lower(std::vector<Arc>& list, Id id)
  {
    return std::lower_bound(list.begin(), list.end(), id, [](const Arc& x, Id v) { return x.to < v; });
  }

  void merge_segments(Id a, Id b)
  {
    if(m_members[a].size() < m_members[b].size())
      std::swap(a, b);
    Weights w;
    {
      auto it = lower(m_seg_arcs[a], b);
      if(it != m_seg_arcs[a].end() && it->to == b)
        w = it->w;
    }
    m_sa[a] += m_sa[b];
    m_ca[a] = (std::max)(0.0, m_ca[a] + m_ca[b] - 2 * w.adjacency);
    m_cc[a] = (std::max)(0.0, m_cc[a] + m_cc[b] - 2 * w.correspondence);
    m_vc[a] += m_vc[b];
    if(m_seg_label[a] < 0)
      m_seg_label[a] = m_seg_label[b];
    m_sum_a -= m_ta[b];
    m_sum_c -= m_tc[b];
    m_ta[b] = m_tc[b] = 0;
    set_terms(a);
    // Merged arc list of a (without a and b); the neighbours of b now point to a.
    std::vector<Arc> merged;
    merged.reserve(m_seg_arcs[a].size() + m_seg_arcs[b].size());
    auto i = m_seg_arcs[a].begin(), ie = m_seg_arcs[a].end();
    auto j = m_seg_arcs[b].begin(), je = m_seg_arcs[b].end();
    while(i != ie || j != je) {
      Arc next;
      if(j == je || (i != ie && i->to < j->to))
        next = *i++;
      else if(i == ie || j->to < i->to)
        next = *j++;
      else {
        next = *i;
        next.w.adjacency += j->w.adjacency;
        next.w.correspondence += j->w.correspondence;
        ++i;
        ++j;
      }
      if(next.to != a && next.to != b)
        merged.push_back(next);
    }
    for(const Arc& arc : m_seg_arcs[b]) {
      if(arc.to == a)
        continue;
      auto& list = m_seg_arcs[arc.to];
      list.erase(lower(list, b));
      auto it = lower(list, a);
      if(it != list.end() && it->to == a) {
        it->w.adjacency += arc.w.adjacency;
        it->w.correspondence += arc.w.correspondence;
      } else
        list.insert(it, Arc{a, arc.w});
    }
    m_seg_arcs[a].swap(merged);
    std::vector<Arc>().swap(m_seg_arcs[b]);
    for(Id v : m_members[b])
      m_segment[v] = a;
    m_members[a].insert(m_members[a].end(), m_members[b].begin(), m_members[b].end());
    m_members[b].clear();
    m_alive.erase(std::find(m_alive.begin(), m_alive.end(), b));
    ++m_version[a];
    ++m_version[b];
    if(m_queue_valid)
      for(const Arc& arc : m_seg_arcs[a])
        push(a, arc.to, arc.w);
  }

  // Moves node v into segment t (membership only; sums are rebuilt by rebuild_segments()).
  void move_node(Id v, Id t)
  {
    auto& from = m_members[m_segment[v]];
    from.erase(std::find(from.begin(), from.end(), v));
    m_members[t].push_back(v);
    m_segment[v] = t;
  }

  // Segment sums, terms and arcs from the node memberships.
  void rebuild_segments()
  {
    const std::size_t n = m_size.size();
    m_sa.assign(n, 0.0);
    m_ca.assign(n, 0.0);
    m_cc.assign(n, 0.0);
    m_vc.assign(n, 0.0);
    m_ta.assign(n, 0.0);
    m_tc.assign(n, 0.0);
    m_seg_label.assign(n, -1);
    m_version.resize(n, 0);
    for(auto& v : m_version)
      ++v;
    m_seg_arcs = arcs_of(n, [&](Id v) { return m_segment[v]; });
    for(Id v = 0; v < n; ++v) {
      const Id s = m_segment[v];
      m_sa[s] += m_size[v];
      m_vc[s] += m_vol_c[v];
      if(m_label[v] >= 0)
        m_seg_label[s] = m_label[v];
    }
    for(Id s = 0; s < n; ++s)
      for(const Arc& arc : m_seg_arcs[s]) {
        m_ca[s] += arc.w.adjacency;
        m_cc[s] += arc.w.correspondence;
      }
    m_alive.clear();
    m_sum_a = m_sum_c = 0;
    for(Id s = 0; s < n; ++s)
      if(!m_members[s].empty()) {
        m_alive.push_back(s);
        m_ta[s] = term_a(m_ca[s], m_sa[s]);
        m_tc[s] = term_c(m_cc[s], m_vc[s], m_sa[s]);
        m_sum_a += m_ta[s];
        m_sum_c += m_tc[s];
      }
    m_queue_valid = false;
  }

  // One pass over the nodes: each node without a known label moves to the neighbouring segment
  // that lowers E the most, if any (a segment is never emptied). Returns the number of moves.
  std::size_t refine_pass()
  {
    std::size_t moves = 0;
    const std::size_t n = m_size.size();
    m_scratch.resize(n);
    m_touched.clear();
    for(Id v = 0; v < n; ++v) {
      const Id s = m_segment[v];
      if(m_label[v] >= 0 || m_members[s].size() < 2)
        continue;
      for(Id t : m_touched)
        m_scratch[t] = Weights();
      m_touched.clear();
      for(const Arc& arc : m_node_arcs[v]) {
        const Id t = m_segment[arc.to];
        if(m_scratch[t].adjacency == 0 && m_scratch[t].correspondence == 0)
          m_touched.push_back(t);
        m_scratch[t].adjacency += arc.w.adjacency;
        m_scratch[t].correspondence += arc.w.correspondence;
      }
      const Weights inside = m_scratch[s];
      // s without v.
      const double sa_s = m_sa[s] - m_size[v];
      const double ca_s = (std::max)(0.0, m_ca[s] - m_cut_a[v] + 2 * inside.adjacency);
      const double cc_s = (std::max)(0.0, m_cc[s] - m_cut_c[v] + 2 * inside.correspondence);
      const double vc_s = m_vc[s] - m_vol_c[v];
      const double ta_s = term_a(ca_s, sa_s), tc_s = term_c(cc_s, vc_s, sa_s);
      const double current = objective(m_sum_a, m_sum_c);
      double best = current - 1e-12 * std::abs(current) - 1e-15;
      Id best_t = s;
      double best_ta = 0, best_tc = 0;
      for(Id t : m_touched) {
        if(t == s)
          continue;
        const Weights& w = m_scratch[t];
        const double ta_t = term_a((std::max)(0.0, m_ca[t] + m_cut_a[v] - 2 * w.adjacency), m_sa[t] + m_size[v]);
        const double tc_t =
          term_c((std::max)(0.0, m_cc[t] + m_cut_c[v] - 2 * w.correspondence), m_vc[t] + m_vol_c[v],
                 m_sa[t] + m_size[v]);
        const double e = objective(m_sum_a - m_ta[s] - m_ta[t] + ta_s + ta_t,
                                   m_sum_c - m_tc[s] - m_tc[t] + tc_s + tc_t);
        if(e < best || (e == best && best_t != s && t < best_t)) {
          best = e;
          best_t = t;
          best_ta = ta_t;
          best_tc = tc_t;
        }
      }
      if(best_t == s)
        continue;
      const Id t = best_t;
      const Weights to_t = m_scratch[t];
      m_sum_a += ta_s + best_ta - m_ta[s] - m_ta[t];
      m_sum_c += tc_s + best_tc - m_tc[s] - m_tc[t];
      m_sa[s] = sa_s;
      m_ca[s] = ca_s;
      m_cc[s] = cc_s;
      m_vc[s] = vc_s;
      m_ta[s] = ta_s;
      m_tc[s] = tc_s;
      m_sa[t] += m_size[v];
      m_ca[t] = (std::max)(0.0, m_ca[t] + m_cut_a[v] - 2 * to_t.adjacency);
      m_cc[t] = (std::max)(0.0, m_cc[t] + m_cut_c[v] - 2 * to_t.correspondence);
      m_vc[t] += m_vol_c[v];
      m_ta[t] = best_ta;
      m_tc[t] = best_tc;
      move_node(v, t);
      ++moves;
    }
    for(Id t : m_touched)
      m_scratch[t] = Weights();
    m_touched.clear();
    if(moves > 0)
      rebuild_segments(); // arcs between segments changed (sums are recomputed exactly too)
    return moves;
  }

  // The virtual, always cut, correspondence volume of a segment, per unit of area, relative to
  // the mean volume per unit of area of the real links.
  static constexpr double unsupported_fraction = 0.01;
  // The floors of E_adj and E_corr, relative to their values before any merge.
  static constexpr double floor_fraction = 0.01;
  double m_alpha;
  double m_unsupported = 0;
  double m_floor_a = 0, m_floor_c = 0;
  // Nodes.
  std::vector<double> m_size, m_cut_a, m_cut_c, m_vol_c;
  std::vector<long long> m_label;
  std::vector<Link> m_links;                 // until run() turns them into arcs
  std::vector<std::vector<Arc>> m_node_arcs; // per node, sorted
  // Segments (indexed by the id of one of their nodes).
  std::vector<Id> m_segment;
  std::vector<std::vector<Id>> m_members;
  std::vector<double> m_sa, m_ca, m_cc, m_vc, m_ta, m_tc;
  std::vector<long long> m_seg_label;
  std::vector<std::vector<Arc>> m_seg_arcs; // per segment, sorted
  std::vector<std::uint32_t> m_version;
  std::vector<Id> m_alive;
  double m_sum_a = 0, m_sum_c = 0;
  // Queue of candidate merges, keyed with the sums of E at its last rebuild.
  std::priority_queue<Entry> m_queue;
  bool m_queue_valid = false;
  double m_key_a = 0, m_key_c = 0;
  // Refinement scratch.
  std::vector<Weights> m_scratch;
  std::vector<Id> m_touched;
};

} // namespace internal
} // namespace Consistent_segmentation
} // namespace CGAL

#endif // CGAL_CONSISTENT_SEGMENTATION_INTERNAL_JOINT_MERGING_H
