// Copyright (c) 2026 CGAL Global Shape Analysis contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_SHAPE_ANALYSIS_INTERNAL_COMPONENT_LINKS_H
#define CGAL_SHAPE_ANALYSIS_INTERNAL_COMPONENT_LINKS_H

// Weak edges between the connected components of a dual graph, so that a model made of several
// pieces is analysed as one object (thesis, section 3.3):
//  - every face is linked to the nearest face (centroid distance d) of other components closer
//    than `link_distance * D` (D = bounding-box diagonal); to bound the work on scenes of many
//    pieces, only the `max_candidate_components` components nearest to its own (by bounding
//    box) are searched, and a face keeps its `max_links_per_face` nearest such links;
//  - with d_eps = epsilon * D, d' = 1.2 (d + d_eps) and d'' = d' / d_eps, a link costs
//    factor * (mean cut cost of the mesh edges) / (1 + d'') to cut and d' to traverse;
//  - components still apart after that (far from everything) are joined by a spanning tree of
//    short links between nearby components (same cost formula), so that the graph is connected.
// The work is O(n log n) in the number n of faces for any number of components.

#include <CGAL/Shape_analysis/defaults.h>
#include <CGAL/Shape_analysis/internal/Dual_graph.h>
#include <CGAL/Shape_analysis/internal/Point_tree.h>
#include <CGAL/Shape_analysis/internal/Union_find.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numeric>
#include <tuple>
#include <utility>
#include <vector>

namespace CGAL {
namespace Shape_analysis {
namespace internal {

// Callers set the distance and the factor from their options; these are the Core's defaults.
struct Component_link_options
{
  double link_distance = default_component_link_distance; // fraction of the bounding-box diagonal
  double epsilon = 0.005;     // fraction of the bounding-box diagonal
  double factor = default_component_link_factor;          // k_cc
  // Components searched for the links of one component's faces (the nearest by bounding box).
  std::size_t max_candidate_components = 8;
  // Links kept per face (to its nearest other components).
  std::size_t max_links_per_face = 2;
};

// Connected components of the graph (over all its edges); returns their number.
inline std::size_t graph_components(const Dual_graph& g, std::vector<std::uint32_t>& component)
{
  Union_find sets(g.number_of_nodes());
  for(std::size_t e = 0; e < g.number_of_edges(); ++e)
    sets.unite(g.edge_source[e], g.edge_target[e]);
  return sets.dense_labels(component);
}

class Component_linker
{
public:
  Component_linker(Dual_graph& g, const Component_link_options& options) : m_g(g), m_options(options)
  {
    m_diagonal = g.bbox_diagonal > 0 ? g.bbox_diagonal : 1.0;
    double sum = 0;
    std::size_t count = 0;
    for(std::size_t e = 0; e < g.number_of_edges(); ++e)
      if(g.mesh_edge[e] != Dual_graph::no_mesh_edge) {
        sum += g.cut_cost[e];
        ++count;
      }
    m_mean_cost = count > 0 ? sum / double(count) : g.mean_mesh_edge_length;
    if(!(m_mean_cost > 0))
      m_mean_cost = 1.0;
  }

  // Adds the links; returns the number of connected components the graph had before.
  std::size_t run()
  {
    std::vector<std::uint32_t> component;
    const std::size_t count = graph_components(m_g, component);
    if(count <= 1)
      return count;
    if(m_options.link_distance > 0)
      add_proximity_links(component, count);
    connect_remaining();
    m_g.build_adjacency();
    return count;
  }

private:
  struct Component
  {
    std::vector<std::uint32_t> faces;
    Vector_3d lo{std::numeric_limits<double>::infinity()};
    Vector_3d hi{-std::numeric_limits<double>::infinity()};
    Point_tree tree;
    Vector_3d centre() const { return (lo + hi) * 0.5; }
  };

  static double squared_distance_to_box(const Vector_3d& p, const Vector_3d& lo, const Vector_3d& hi)
  {
    double d = 0;
    for(int i = 0; i < 3; ++i) {
      const double t = p[i] < lo[i] ? lo[i] - p[i] : (p[i] > hi[i] ? p[i] - hi[i] : 0.0);
      d += t * t;
    }
    return d;
  }

  static double squared_box_distance(const Component& a, const Component& b)
  {
    double d = 0;
    for(int i = 0; i < 3; ++i) {
      const double t = (std::max)(0.0, (std::max)(a.lo[i] - b.hi[i], b.lo[i] - a.hi[i]));
      d += t * t;
    }
    return d;
  }

  std::vector<Component> make_components(const std::vector<std::uint32_t>& component,
                                         std::size_t count) const
  {
    std::vector<Component> comps(count);
    for(std::size_t i = 0; i < component.size(); ++i) {
      Component& c = comps[component[i]];
      c.faces.push_back(static_cast<std::uint32_t>(i));
      c.lo = c.lo.min(m_g.node_position[i]);
      c.hi = c.hi.max(m_g.node_position[i]);
    }
    for(Component& c : comps) {
      std::vector<Vector_3d> points;
      points.reserve(c.faces.size());
      for(std::uint32_t f : c.faces)
        points.push_back(m_g.node_position[f]);
      c.tree = Point_tree(points, c.faces);
    }
    return comps;
  }

  // Candidate neighbours of every component, nearest first by (squared box distance, id): all
  // other components when there are few, otherwise those among the nearest by box centre.
  std::vector<std::vector<std::pair<double, std::uint32_t>>>
  candidate_components(const std::vector<Component>& comps, std::size_t keep) const
  {
    const std::size_t count = comps.size();
    std::vector<std::vector<std::pair<double, std::uint32_t>>> result(count);
    if(count <= 64) {
      for(std::size_t a = 0; a < count; ++a)
        for(std::size_t b = 0; b < count; ++b)
          if(a != b)
            result[a].emplace_back(squared_box_distance(comps[a], comps[b]), std::uint32_t(b));
    } else {
      std::vector<Vector_3d> centres;
      std::vector<std::uint32_t> ids;
      for(std::size_t c = 0; c < count; ++c) {
        centres.push_back(comps[c].centre());
        ids.push_back(static_cast<std::uint32_t>(c));
      }
      const Point_tree tree(centres, ids);
      std::vector<std::pair<double, std::uint32_t>> near;
      for(std::size_t a = 0; a < count; ++a) {
        tree.k_nearest(centres[a], 2 * keep + 1, near);
        for(const auto& nb : near)
          if(nb.second != a)
            result[a].emplace_back(squared_box_distance(comps[a], comps[nb.second]), nb.second);
      }
    }
    for(auto& list : result) {
      std::sort(list.begin(), list.end());
      if(list.size() > keep)
        list.resize(keep);
    }
    return result;
  }

  void add_link(std::uint32_t a, std::uint32_t b, double distance)
  {
    const double eps = m_options.epsilon * m_diagonal;
    const double d1 = 1.2 * (distance + eps);
    const double d2 = eps > 0 ? d1 / eps : 0.0;
    m_g.add_edge(a, b, 0.0, 1.0, m_options.factor * m_mean_cost / (1.0 + d2), d1,
                 Dual_graph::no_mesh_edge);
  }

  void add_proximity_links(const std::vector<std::uint32_t>& component, std::size_t count)
  {
    const std::vector<Component> comps = make_components(component, count);
    const double r = m_options.link_distance * m_diagonal;
    const double r2 = r * r;
    const auto candidates = candidate_components(comps, m_options.max_candidate_components);
    std::vector<std::pair<std::uint64_t, double>> links;
    std::vector<std::pair<double, std::uint32_t>> found; // (squared distance, face) of one face
    for(std::size_t a = 0; a < count; ++a) {
      for(std::uint32_t f : comps[a].faces) {
        const Vector_3d& p = m_g.node_position[f];
        found.clear();
        for(const auto& nb : candidates[a]) {
          if(nb.first >= r2)
            break;
          const Component& other = comps[nb.second];
          if(squared_distance_to_box(p, other.lo, other.hi) >= r2)
            continue;
          std::uint32_t g;
          double d2;
          if(other.tree.nearest(p, r2, g, d2))
            found.emplace_back(d2, g);
        }
        if(found.size() > m_options.max_links_per_face) {
          std::sort(found.begin(), found.end());
          found.resize(m_options.max_links_per_face);
        }
        for(const auto& x : found) {
          const std::uint32_t lo = (std::min)(f, x.second), hi = (std::max)(f, x.second);
          links.emplace_back((std::uint64_t(lo) << 32) | hi, std::sqrt(x.first));
        }
      }
    }
    std::sort(links.begin(), links.end());
    for(std::size_t i = 0; i < links.size(); ++i)
      if(i == 0 || links[i].first != links[i - 1].first)
        add_link(static_cast<std::uint32_t>(links[i].first >> 32),
                 static_cast<std::uint32_t>(links[i].first & 0xffffffffu), links[i].second);
  }

  // Nearest face pair between two components, searched from at most `samples` faces of the
  // smaller one (evenly spread in its face order) into the tree of the larger one.
  void nearest_pair(const Component& a, const Component& b, std::uint32_t& fa, std::uint32_t& fb,
                    double& d2) const
  {
    const bool swap = a.faces.size() > b.faces.size();
    const Component& from = swap ? b : a;
    const Component& into = swap ? a : b;
    const std::size_t samples = 64;
    const std::size_t step = (std::max<std::size_t>)(1, from.faces.size() / samples);
    d2 = std::numeric_limits<double>::infinity();
    std::uint32_t best_from = from.faces.front(), best_into = into.faces.front();
    for(std::size_t k = 0; k < from.faces.size(); k += step) {
      std::uint32_t g;
      double d;
      if(into.tree.nearest(m_g.node_position[from.faces[k]], d2, g, d) && d < d2) {
        d2 = d;
        best_from = from.faces[k];
        best_into = g;
      }
    }
    if(!(d2 < std::numeric_limits<double>::infinity()))
      d2 = (m_g.node_position[best_from] - m_g.node_position[best_into]).squared_length();
    fa = swap ? best_into : best_from;
    fb = swap ? best_from : best_into;
  }

  // Joins the components left apart: Kruskal's spanning forest over the pairs of components near
  // each other (by bounding box), then a chain of what is still apart along the longest axis.
  void connect_remaining()
  {
    std::vector<std::uint32_t> component;
    const std::size_t count = graph_components(m_g, component);
    if(count <= 1)
      return;
    const std::vector<Component> comps = make_components(component, count);
    const auto candidates = candidate_components(comps, 8);
    std::vector<std::tuple<double, std::uint32_t, std::uint32_t>> pairs;
    for(std::size_t a = 0; a < count; ++a)
      for(const auto& nb : candidates[a])
        pairs.emplace_back(nb.first, (std::min)(std::uint32_t(a), nb.second),
                           (std::max)(std::uint32_t(a), nb.second));
    std::sort(pairs.begin(), pairs.end());
    Union_find sets(count);
    auto join = [&](std::uint32_t a, std::uint32_t b) {
      std::uint32_t fa = 0, fb = 0;
      double d2 = 0;
      nearest_pair(comps[a], comps[b], fa, fb, d2);
      add_link(fa, fb, std::sqrt(d2));
      sets.unite(a, b);
    };
    std::size_t groups = count;
    for(const auto& p : pairs)
      if(sets.find(std::get<1>(p)) != sets.find(std::get<2>(p))) {
        join(std::get<1>(p), std::get<2>(p));
        --groups;
      }
    if(groups <= 1)
      return;
    // Still apart (clusters of components far from each other): chain one component of each
    // group, in the order of their centres along the longest axis of the whole box.
    Vector_3d lo(std::numeric_limits<double>::infinity()), hi(-std::numeric_limits<double>::infinity());
    for(const Component& c : comps) {
      lo = lo.min(c.lo);
      hi = hi.max(c.hi);
    }
    const Vector_3d extent = hi - lo;
    const int axis = extent.x >= extent.y && extent.x >= extent.z ? 0 : (extent.y >= extent.z ? 1 : 2);
    std::vector<std::uint32_t> representatives;
    for(std::uint32_t c = 0; c < count; ++c)
      if(sets.find(c) == c)
        representatives.push_back(c);
    std::sort(representatives.begin(), representatives.end(), [&](std::uint32_t a, std::uint32_t b) {
      const double ca = comps[a].centre()[axis], cb = comps[b].centre()[axis];
      return ca != cb ? ca < cb : a < b;
    });
    for(std::size_t k = 1; k < representatives.size(); ++k)
      join(representatives[k - 1], representatives[k]);
  }

  Dual_graph& m_g;
  Component_link_options m_options;
  double m_diagonal = 1;
  double m_mean_cost = 1;
};

// Adds the component links to `g`; returns the number of connected components it had before.
inline std::size_t add_component_links(Dual_graph& g, const Component_link_options& options)
{
  return Component_linker(g, options).run();
}

} // namespace internal
} // namespace Shape_analysis
} // namespace CGAL

#endif // CGAL_SHAPE_ANALYSIS_INTERNAL_COMPONENT_LINKS_H
