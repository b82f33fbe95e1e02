// Copyright (c) 2026 CGAL Global Shape Analysis contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_POINT_SET_OBJECT_RECOGNITION_INTERNAL_SEGMENTATION_OPTIONS_H
#define CGAL_POINT_SET_OBJECT_RECOGNITION_INTERNAL_SEGMENTATION_OPTIONS_H

// The options and the result of the segmentation of one object (Object_segmentation.h).

#include <CGAL/Point_set_object_recognition/Segment_objects_options.h>
#include <CGAL/Shape_analysis/Bad_input.h>

#include <array>
#include <cmath>
#include <cstddef>
#include <string>
#include <vector>

namespace CGAL {
namespace Point_set_object_recognition {
namespace internal {

typedef Segment_objects_options Segmentation_options;

// The data term: the penalty for being foreground rises linearly from the background radius R to
// outer_factor times the reward at the location, over ramp_width metres (then hard background).
constexpr double outer_factor = 10.0;
constexpr double ramp_width = 1.0;
// With cells, the nodes nearest to the seed's node that are also in the hard foreground.
constexpr std::size_t seed_neighbors = 3;
// The background radii that the automatic radius tries, increasing (metres): up to 7 m, so
// that a bus or a truck (10-12 m long, seen from its middle) finds a clean cut.
constexpr std::array<double, 7> automatic_radii{{1, 2, 3, 4, 5, 6, 7}};
// Walls (facades): points of the columns of side `wall_column_side` that span more than
// `wall_column_height` of height, within `wall_line_tolerance` of the line fitted to the high
// points of such columns around when that line is long and thin (a pole or a tree is not). They
// form their own graph nodes, with no edge to the others, and never seed the foreground.
constexpr double wall_column_height = 3.5, wall_column_side = 0.2, wall_line_tolerance = 0.05;
// The edge sigma without `edge_sigma` given: so many graph cells, or this when there are no cells.
constexpr double edge_sigma_in_cells = 4, edge_sigma_without_cells = 0.2;

// The length scale of the edge weights.
inline double edge_sigma(const Segmentation_options& o)
{
  if(o.edge_sigma)
    return *o.edge_sigma;
  return o.graph_cell_size > 0 ? edge_sigma_in_cells * o.graph_cell_size : edge_sigma_without_cells;
}

// The largest background radius of a min-cut method.
inline double largest_background_radius(const Segmentation_options& o)
{
  return o.segmentation_method == Segmentation_method::MIN_CUT ? o.background_radius : automatic_radii.back();
}

struct Segmentation_output
{
  std::vector<std::size_t> points; // increasing
  double radius = 0, cut = 0, seconds = 0;
  std::size_t seed = std::size_t(-1);
};

// Bad_input, from `who`, for an option out of its range.
inline void check_segmentation_options(const Segmentation_options& o, const std::string& who)
{
  typedef CGAL::Shape_analysis::Bad_input Bad_input;
  const auto positive = [](double v) { return v > 0 && std::isfinite(v); };
  if(!positive(o.background_radius))
    throw Bad_input(who + ": background_radius must be a positive number");
  if(!std::isfinite(o.foreground_height))
    throw Bad_input(who + ": foreground_height must be a finite number");
  if(o.number_of_neighbors < 1 || o.number_of_neighbors > 64)
    throw Bad_input(who + ": number_of_neighbors must be between 1 and 64");
  if(!(o.graph_cell_size >= 0) || !std::isfinite(o.graph_cell_size))
    throw Bad_input(who + ": graph_cell_size must be zero or a positive number");
  if(!positive(edge_sigma(o)))
    throw Bad_input(who + ": edge_sigma must be a positive number");
  if(!(o.background_weight >= 0) || !std::isfinite(o.background_weight))
    throw Bad_input(who + ": background_weight must be a non-negative number");
  if(!(o.maximum_cut_cost >= 0))
    throw Bad_input(who + ": maximum_cut_cost must be a non-negative number");
  if(!positive(o.component_spacing))
    throw Bad_input(who + ": component_spacing must be a positive number");
}

} // namespace internal
} // namespace Point_set_object_recognition
} // namespace CGAL

#endif // CGAL_POINT_SET_OBJECT_RECOGNITION_INTERNAL_SEGMENTATION_OPTIONS_H
