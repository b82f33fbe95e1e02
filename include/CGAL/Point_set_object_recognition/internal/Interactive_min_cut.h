// Copyright (c) 2026 CGAL Global Shape Analysis contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_POINT_SET_OBJECT_RECOGNITION_INTERNAL_INTERACTIVE_MIN_CUT_H
#define CGAL_POINT_SET_OBJECT_RECOGNITION_INTERNAL_INTERACTIVE_MIN_CUT_H

// The machinery of Interactive_segmenter (segment_objects.h): the uncontracted graph of one
// object at the radius of its first segmentation, whose cut is solved again by augmenting the
// last flow as constraints come.

#include <CGAL/Point_set_object_recognition/internal/Object_min_cut.h>
#include <CGAL/Point_set_object_recognition/internal/Object_segmentation.h>
#include <CGAL/Point_set_object_recognition/internal/Point_columns.h>
#include <CGAL/Point_set_object_recognition/internal/Segmentation_graph.h>
#include <CGAL/Point_set_object_recognition/internal/Segmentation_options.h>
#include <CGAL/Shape_analysis/Bad_input.h>
#include <CGAL/Shape_analysis/internal/Min_cut.h>

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <map>
#include <memory>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

namespace CGAL {
namespace Point_set_object_recognition {
namespace internal {

// `Result`: the public segmentation (points, radius, cut_cost, seconds, seed, no_point).
template <typename Result>
class Interactive_min_cut
{
public:
  // Bad_input for a method that is not a min-cut, an empty cloud, and as segment_objects().
  Interactive_min_cut(std::vector<P3>&& points, const Segmentation_options& o, const P3& location)
    : m_points(std::move(points)), m_options(o), m_location(location)
  {
    if(m_options.segmentation_method != Segmentation_method::MIN_CUT &&
       m_options.segmentation_method != Segmentation_method::MIN_CUT_AUTOMATIC_RADIUS)
      throw CGAL::Shape_analysis::Bad_input("Interactive_segmenter: the segmentation method must be a min-cut");
    if(m_points.empty())
      throw CGAL::Shape_analysis::Bad_input("Interactive_segmenter: the point cloud is empty");
    initialize();
  }

  Interactive_min_cut(const Interactive_min_cut&) = delete;
  Interactive_min_cut& operator=(const Interactive_min_cut&) = delete;

  const Result& segmentation() const { return m_result; }
  std::size_t number_of_constraints() const { return m_constrained.size(); }

  // Constrains point i to the foreground or the background and solves again.
  const Result& add(std::size_t i, bool foreground)
  {
    if(i >= m_points.size())
      throw CGAL::Shape_analysis::Bad_input("Interactive_segmenter: point index " + std::to_string(i) + " out of range");
    const std::uint32_t v = m_index->node_of_point(i);
    const auto it = v == Segmentation_index::none ? m_local.end() : m_local.find(v);
    if(it == m_local.end() && foreground)
      throw CGAL::Shape_analysis::Bad_input("Interactive_segmenter: point " + std::to_string(i) +
                                            " lies outside the segmenter's graph and cannot be foreground");
    m_constrained[i] = foreground;
    const auto start = std::chrono::steady_clock::now();
    if(it != m_local.end()) {
      // The side of the node: its points' constraints when they agree, free when they do not,
      // its seed otherwise.
      const std::uint32_t k = it->second;
      bool any_fg = false, any_bg = false;
      m_index->for_members(v, [&](std::uint32_t q) {
        const auto c = m_constrained.find(q);
        if(c != m_constrained.end())
          (c->second ? any_fg : any_bg) = true;
      });
      const Cut::Side side = any_fg && any_bg ? Cut::FREE
                             : any_fg         ? Cut::SOURCE
                             : any_bg         ? Cut::SINK
                             : (m_graph.seed[k] ? Cut::SOURCE : Cut::FREE);
      if(side != m_cut.constraint(k))
        m_cut.constrain_and_resolve({{std::size_t(k), side}});
    }
    collect(start);
    return m_result;
  }

private:
  typedef CGAL::Shape_analysis::internal::Terminal_min_cut Cut;

  void initialize()
  {
    const std::vector<P3> at{m_location};
    m_columns.reset(new Point_columns(m_points));
    m_columns->check(at);
    // The segmenter's graph keeps the nodes of walls (without edges): a point on a wall can be
    // constrained to the foreground.
    m_index.reset(new Segmentation_index(*m_columns, at, segmentation_reach(m_options), m_options, true, true));
    Segmentation_workspace w;
    Segmentation_output first = segment_one(*m_index, m_location, m_options, w);
    m_result.radius = first.radius;
    m_result.seed = first.seed == std::size_t(-1) ? Result::no_point : first.seed;
    // The graph of that radius, uncontracted.
    const double largest = largest_background_radius(m_options);
    const std::vector<std::uint32_t> seeds = object_seeds(*m_index, m_location, largest, m_options, w.candidates);
    std::vector<double> outside;
    build_object_graph(*m_index, m_location, first.radius, seeds, m_options, w, outside, true);
    m_nodes = w.nodes;
    m_graph = w.graph;
    m_outside = outside;
    m_local.clear();
    for(std::size_t k = 0; k < m_nodes.size(); ++k)
      m_local.emplace(m_nodes[k], std::uint32_t(k));
    load_cut(m_graph, m_cut);
    const auto start = std::chrono::steady_clock::now();
    m_cut.solve();
    collect(start);
  }

  void collect(std::chrono::steady_clock::time_point start)
  {
    m_result.points.clear();
    const std::size_t n = m_nodes.size();
    // The source side connected to the hard foreground (seeds and foreground constraints).
    std::vector<char> source_side(n), hard(n);
    for(std::size_t k = 0; k < n; ++k) {
      source_side[k] = m_cut.is_source_side(k) ? 1 : 0;
      hard[k] = m_cut.constraint(k) == Cut::SOURCE ? 1 : 0;
    }
    for(const auto& c : m_constrained)
      if(c.second) {
        const auto it = m_local.find(m_index->node_of_point(c.first));
        if(it != m_local.end())
          hard[it->second] = 1;
      }
    const std::vector<char> fg = connected_to_seeds(n, m_graph.edges, hard, source_side);
    double edge_cut = 0, fg_points = 0, fg_nodes = 0;
    for(std::size_t e = 0; e < m_graph.edges.size(); ++e)
      if(fg[m_graph.edges[e][0]] != fg[m_graph.edges[e][1]])
        edge_cut += m_graph.weight[e];
    for(std::size_t k = 0; k < n; ++k)
      if(fg[k]) {
        edge_cut += m_outside[k];
        fg_points += m_graph.points[k];
        fg_nodes += 1;
        m_index->for_members(m_nodes[k], [&](std::uint32_t q) { m_result.points.push_back(q); });
      }
    // The constrained points override their nodes.
    for(const auto& c : m_constrained)
      if(c.second)
        m_result.points.push_back(c.first);
    std::sort(m_result.points.begin(), m_result.points.end());
    m_result.points.erase(std::unique(m_result.points.begin(), m_result.points.end()), m_result.points.end());
    m_result.points.erase(std::remove_if(m_result.points.begin(), m_result.points.end(),
                                         [&](std::size_t q) {
                                           const auto c = m_constrained.find(q);
                                           return c != m_constrained.end() && !c->second;
                                         }),
                          m_result.points.end());
    m_result.cut_cost = fg_nodes > 0 ? edge_cut / (fg_points / fg_nodes) : 0.0;
    m_result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  }

  std::vector<P3> m_points;
  Segmentation_options m_options;
  P3 m_location;
  std::unique_ptr<Point_columns> m_columns; // before m_index, which refers to it
  std::unique_ptr<Segmentation_index> m_index;
  std::vector<std::uint32_t> m_nodes;
  std::unordered_map<std::uint32_t, std::uint32_t> m_local;
  Object_graph m_graph;
  std::vector<double> m_outside;
  Cut m_cut;
  std::map<std::size_t, bool> m_constrained;
  Result m_result;
};

} // namespace internal
} // namespace Point_set_object_recognition
} // namespace CGAL

#endif // CGAL_POINT_SET_OBJECT_RECOGNITION_INTERNAL_INTERACTIVE_MIN_CUT_H
