// Copyright (c) 2026 CGAL Global Shape Analysis contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_SHAPE_ANALYSIS_INTERNAL_COMPONENT_LINKS_H
#define CGAL_SHAPE_ANALYSIS_INTERNAL_COMPONENT_LINKS_H

// Weak edges between the connected components of a dual graph, so that a model made of several
// pieces is analysed as one object (thesis, section 3.3):
//  - every face is linked to the nearest face (centroid distance d) of each other component
//    closer than `link_distance * D` (D = bounding-box diagonal);
//  - with d_eps = epsilon * D, d' = 1.2 (d + d_eps) and d'' = d' / d_eps, a link costs
//    factor * (mean cut cost of the mesh edges) / (1 + d'') to cut and d' to traverse;
//  - components still apart after that (far from everything) are joined along a spanning tree of
//    their nearest face pairs, with the same cost formula, so that the graph is connected.

#include <CGAL/Shape_analysis/internal/Dual_graph.h>
#include <CGAL/Shape_analysis/internal/Point_tree.h>

#include <algorithm>
#include <cstdint>
#include <limits>
#include <numeric>
#include <utility>
#include <vector>

namespace CGAL {
namespace Shape_analysis {
namespace internal {

struct Component_link_options
{
  double link_distance = 0.1; // fraction of the bounding-box diagonal
  double epsilon = 0.005;     // fraction of the bounding-box diagonal
  double factor = 0.01;       // k_cc
  // Above this many components, only the spanning links are added (bounded work on soups).
  std::size_t max_components_for_proximity_links = 2000;
  // Each face is linked to at most this many other components (the nearest by bounding box).
  std::size_t max_linked_components_per_component = 32;
};

// Connected components of the graph (over all its edges); returns their number.
inline std::size_t graph_components(const Dual_graph& g, std::vector<std::uint32_t>& component)
{
  const std::size_t n = g.number_of_nodes();
  std::vector<std::uint32_t> parent(n);
  std::iota(parent.begin(), parent.end(), 0u);
  auto find = [&](std::uint32_t x) {
    while(parent[x] != x) {
      parent[x] = parent[parent[x]];
      x = parent[x];
    }
    return x;
  };
  for(std::size_t e = 0; e < g.number_of_edges(); ++e) {
    const std::uint32_t a = find(g.edge_source[e]), b = find(g.edge_target[e]);
    if(a != b)
      parent[(std::max)(a, b)] = (std::min)(a, b);
  }
  component.assign(n, 0);
  std::vector<std::uint32_t> dense(n, (std::numeric_limits<std::uint32_t>::max)());
  std::uint32_t count = 0;
  for(std::size_t i = 0; i < n; ++i) {
    const std::uint32_t r = find(static_cast<std::uint32_t>(i));
    if(dense[r] == (std::numeric_limits<std::uint32_t>::max)())
      dense[r] = count++;
    component[i] = dense[r];
  }
  return count;
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
    if(count <= m_options.max_components_for_proximity_links && m_options.link_distance > 0)
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
    std::vector<std::pair<std::uint64_t, double>> links;
    for(std::size_t a = 0; a < count; ++a) {
      std::vector<std::pair<double, std::size_t>> near;
      for(std::size_t b = 0; b < count; ++b)
        if(b != a) {
          const double d = squared_box_distance(comps[a], comps[b]);
          if(d < r2)
            near.emplace_back(d, b);
        }
      if(near.size() > m_options.max_linked_components_per_component) {
        std::nth_element(near.begin(), near.begin() + m_options.max_linked_components_per_component,
                         near.end());
        near.resize(m_options.max_linked_components_per_component);
      }
      for(const auto& nb : near) {
        const Component& other = comps[nb.second];
        for(std::uint32_t f : comps[a].faces) {
          const Vector_3d& p = m_g.node_position[f];
          if(squared_distance_to_box(p, other.lo, other.hi) >= r2)
            continue;
          std::uint32_t g;
          double d2;
          if(other.tree.nearest(p, r2, g, d2)) {
            const std::uint32_t lo = (std::min)(f, g), hi = (std::max)(f, g);
            links.emplace_back((std::uint64_t(lo) << 32) | hi, std::sqrt(d2));
          }
        }
      }
    }
    std::sort(links.begin(), links.end());
    for(std::size_t i = 0; i < links.size(); ++i)
      if(i == 0 || links[i].first != links[i - 1].first)
        add_link(static_cast<std::uint32_t>(links[i].first >> 32),
                 static_cast<std::uint32_t>(links[i].first & 0xffffffffu), links[i].second);
  }

  // Nearest face pair between two components, searching from at most `samples` faces of `a`.
  static void nearest_pair(const Component& a, const Component& b, std::size_t samples,
                           std::uint32_t& fa, std::uint32_t& fb, double& d2,
                           const std::vector<Vector_3d>& positions)
  {
    d2 = std::numeric_limits<double>::infinity();
    const std::size_t step = (std::max<std::size_t>)(1, a.faces.size() / samples);
    for(std::size_t k = 0; k < a.faces.size(); k += step) {
      std::uint32_t g;
      double d;
      if(b.tree.nearest(positions[a.faces[k]], d2, g, d) && d < d2) {
        d2 = d;
        fa = a.faces[k];
        fb = g;
      }
    }
  }

  void connect_remaining()
  {
    std::vector<std::uint32_t> component;
    const std::size_t count = graph_components(m_g, component);
    if(count <= 1)
      return;
    const std::vector<Component> comps = make_components(component, count);
    const std::size_t samples = 64;
    if(count <= 128) {
      // Prim's spanning tree over the components, distances from sampled nearest pairs.
      std::vector<double> best(count, std::numeric_limits<double>::infinity());
      std::vector<std::uint32_t> best_a(count), best_b(count);
      std::vector<char> in_tree(count, 0);
      std::size_t current = 0;
      in_tree[0] = 1;
      for(std::size_t step = 1; step < count; ++step) {
        for(std::size_t c = 0; c < count; ++c) {
          if(in_tree[c])
            continue;
          std::uint32_t fa = 0, fb = 0;
          double d2;
          nearest_pair(comps[c], comps[current], samples, fa, fb, d2, m_g.node_position);
          if(d2 < best[c]) {
            best[c] = d2;
            best_a[c] = fa;
            best_b[c] = fb;
          }
        }
        std::size_t next = count;
        for(std::size_t c = 0; c < count; ++c)
          if(!in_tree[c] && (next == count || best[c] < best[next]))
            next = c;
        in_tree[next] = 1;
        add_link(best_a[next], best_b[next], std::sqrt(best[next]));
        current = next;
      }
    } else {
      // Many components: chain them along the longest axis of the bounding box.
      Vector_3d lo(std::numeric_limits<double>::infinity()), hi(-std::numeric_limits<double>::infinity());
      for(const Component& c : comps) {
        lo = lo.min(c.lo);
        hi = hi.max(c.hi);
      }
      const Vector_3d extent = hi - lo;
      const int axis = extent.x >= extent.y && extent.x >= extent.z ? 0 : (extent.y >= extent.z ? 1 : 2);
      std::vector<std::size_t> order(count);
      std::iota(order.begin(), order.end(), std::size_t(0));
      std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
        const double ca = comps[a].lo[axis] + comps[a].hi[axis];
        const double cb = comps[b].lo[axis] + comps[b].hi[axis];
        return ca != cb ? ca < cb : a < b;
      });
      for(std::size_t k = 1; k < count; ++k) {
        std::uint32_t fa = 0, fb = 0;
        double d2;
        nearest_pair(comps[order[k]], comps[order[k - 1]], 8, fa, fb, d2, m_g.node_position);
        add_link(fa, fb, std::sqrt(d2));
      }
    }
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
