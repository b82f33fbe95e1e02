// Copyright (c) 2026 CGAL Global Shape Analysis contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_CONSISTENT_SEGMENTATION_INTERNAL_SEGMENTATION_GRAPH_H
#define CGAL_CONSISTENT_SEGMENTATION_INTERNAL_SEGMENTATION_GRAPH_H

// Hierarchical segmentation on a dual graph (mesh independent): prior boundaries, component links,
// normalized-cut merging, boundary refinement, and numbering of the segments by decreasing area.

#include <CGAL/Consistent_segmentation/Hierarchical_segmentation_options.h>
#include <CGAL/Shape_analysis/Bad_input.h>
#include <CGAL/Shape_analysis/internal/Component_links.h>
#include <CGAL/Shape_analysis/internal/Dual_graph.h>
#include <CGAL/Shape_analysis/internal/Labels.h>
#include <CGAL/Shape_analysis/internal/Normalized_cut_clustering.h>
#include <CGAL/Shape_analysis/internal/Partition_refinement.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <numeric>
#include <string>
#include <vector>

namespace CGAL {
namespace Consistent_segmentation {
namespace internal {

typedef Hierarchical_segmentation_options Segmentation_options;

// Segments below this fraction of the total area (specks: a folded-over face, whose edges all look
// like deep creases) are merged into their neighbours before any two larger segments are.
constexpr double small_segment_fraction = 1e-4;

inline void check_options(const Segmentation_options& o, std::size_t number_of_faces,
                          const std::string& who)
{
  using CGAL::Shape_analysis::Bad_input;
  if(o.number_of_segments == 0)
    throw Bad_input(who + ": number_of_segments must be at least 1");
  if(o.number_of_segments > number_of_faces)
    throw Bad_input(who + ": number_of_segments (" + std::to_string(o.number_of_segments) +
                    ") exceeds the number of faces (" + std::to_string(number_of_faces) + ")");
  if(!(o.concavity_exponent >= 0) || !std::isfinite(o.concavity_exponent))
    throw Bad_input(who + ": concavity_exponent must be a finite number >= 0");
  if(!(o.prior_boundary_factor >= 1) || !std::isfinite(o.prior_boundary_factor))
    throw Bad_input(who + ": prior_boundary_factor must be a finite number >= 1");
  if(!(o.component_link_distance >= 0) || !std::isfinite(o.component_link_distance))
    throw Bad_input(who + ": component_link_distance must be a finite number >= 0");
  if(!(o.component_link_factor > 0) || !std::isfinite(o.component_link_factor))
    throw Bad_input(who + ": component_link_factor must be a finite number > 0");
}

using CGAL::Shape_analysis::internal::number_by_size;

// Adds the links between the components of `g` and makes the boundaries of the prior labels
// (if any) cheaper to cut.
inline void add_links_and_prior(CGAL::Shape_analysis::internal::Dual_graph& g, const Segmentation_options& o,
                                const std::vector<long long>* prior_labels)
{
  namespace SAI = CGAL::Shape_analysis::internal;
  SAI::Component_link_options link_options;
  link_options.link_distance = o.component_link_distance;
  link_options.factor = o.component_link_factor;
  SAI::add_component_links(g, link_options);

  // Prior boundaries (after the links, whose cost is relative to the plain mesh-edge costs).
  if(prior_labels != nullptr)
    for(std::size_t e = 0; e < g.number_of_edges(); ++e)
      if((*prior_labels)[g.edge_source[e]] != (*prior_labels)[g.edge_target[e]])
        g.cut_cost[e] /= o.prior_boundary_factor;
}

// Segments the dual graph `g` (modified: prior boundaries and links are applied to it).
inline std::vector<std::size_t> segment_dual_graph(CGAL::Shape_analysis::internal::Dual_graph& g,
                                                   const Segmentation_options& o,
                                                   const std::vector<long long>* prior_labels)
{
  namespace SAI = CGAL::Shape_analysis::internal;
  add_links_and_prior(g, o, prior_labels);

  SAI::Normalized_cut_clustering clustering(g.node_size, g.edge_source, g.edge_target, g.cut_cost);
  const std::size_t n = g.number_of_nodes();
  const std::size_t to_merge = n > o.number_of_segments ? n - o.number_of_segments : 0;
  const std::size_t report_every = (std::max<std::size_t>)(1, to_merge / 100);
  std::size_t merged = 0;
  std::function<void(SAI::Normalized_cut_clustering::Id, SAI::Normalized_cut_clustering::Id)> on_merge;
  if(o.progress_callback)
    on_merge = [&](SAI::Normalized_cut_clustering::Id, SAI::Normalized_cut_clustering::Id) {
      if(++merged % report_every == 0)
        o.progress_callback(0.9 * double(merged) / double(to_merge));
    };
  const double small_size = (std::min)(small_segment_fraction, 0.1 / double(o.number_of_segments)) * g.total_size();
  clustering.run(o.number_of_segments, {}, on_merge, 0.0, 0, small_size);
  std::vector<std::size_t> labels = clustering.labels();
  if(o.boundary_refinement)
    SAI::multilevel_refinement(g.node_size, g.edge_source, g.edge_target, g.cut_cost,
                               clustering.merges(), labels);
  if(o.progress_callback)
    o.progress_callback(1.0);
  return number_by_size(labels, g.node_size);
}

} // namespace internal
} // namespace Consistent_segmentation
} // namespace CGAL

#endif // CGAL_CONSISTENT_SEGMENTATION_INTERNAL_SEGMENTATION_GRAPH_H
