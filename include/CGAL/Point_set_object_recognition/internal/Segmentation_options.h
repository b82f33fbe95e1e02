// Copyright (c) 2026 CGAL Global Shape Analysis contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_POINT_SET_OBJECT_RECOGNITION_INTERNAL_SEGMENTATION_OPTIONS_H
#define CGAL_POINT_SET_OBJECT_RECOGNITION_INTERNAL_SEGMENTATION_OPTIONS_H

// The options and the result of the segmentation of one object (Object_segmentation.h).

#include <CGAL/Shape_analysis/Bad_input.h>

#include <cmath>
#include <cstddef>
#include <string>
#include <vector>

namespace CGAL {
namespace Point_set_object_recognition {
namespace internal {

enum class Segmentation_kind { ALL, COMPONENTS, MIN_CUT, MIN_CUT_AUTO };

struct Segmentation_options
{
  Segmentation_kind kind = Segmentation_kind::MIN_CUT_AUTO;
  double radius = 2;               // fixed background radius (min-cut), or radius (all, components)
  double foreground_height = 1.2;  // height of the hard foreground above the location
  std::size_t neighbors = 8;       // k of the kNN graph
  double sigma = 0.8;              // edge weight exp(-(d / sigma)^2): 4 cells by default
  double background_weight = 0.1;  // foreground reward per point at the location (data term scale)
  double outer_factor = 10.0;      // ... times this at radius + ramp width (then hard background)
  double ramp_width = 1.0;         // width of the second ramp (m)
  double cell = 0.2;               // graph nodes: cells of this side; 0: the points
  std::size_t maximum_nodes = 1000; // contraction target (0: none)
  std::size_t seed_neighbors = 3;   // nodes nearest to the seed's node also in the hard foreground
  std::size_t minimum_foreground = 35;
  double maximum_cut = 0.4;
  double spacing = 0.3;            // connected components
  std::vector<double> radii{1, 2, 3, 4, 5}; // automatic radius
  std::size_t threads = 0;
  // Walls (facades): points of the columns of side `wall_column` that span more than
  // `wall_height` of height, within `wall_tolerance` of the line fitted to the high points of such
  // columns around when that line is long and thin (a pole or a tree is not; 0: no walls). They
  // form their own graph nodes, with no edge to the others, and never seed the foreground.
  double wall_height = 3.5, wall_column = 0.2, wall_tolerance = 0.05;
  bool wall_nodes = false; // whether walls have graph nodes (the interactive segmenter's constraints)
};

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
  if(!positive(o.radius))
    throw Bad_input(who + ": background_radius must be a positive number");
  if(!std::isfinite(o.foreground_height))
    throw Bad_input(who + ": foreground_height must be a finite number");
  if(o.neighbors < 1 || o.neighbors > 64)
    throw Bad_input(who + ": number_of_neighbors must be between 1 and 64");
  if(!(o.cell >= 0) || !std::isfinite(o.cell))
    throw Bad_input(who + ": graph_cell_size must be zero or a positive number");
  if(!positive(o.sigma))
    throw Bad_input(who + ": edge_sigma must be a positive number");
  if(!(o.background_weight >= 0) || !std::isfinite(o.background_weight))
    throw Bad_input(who + ": background_weight must be a non-negative number");
  if(!(o.maximum_cut >= 0))
    throw Bad_input(who + ": maximum_cut_cost must be a non-negative number");
  if(!positive(o.spacing))
    throw Bad_input(who + ": component_spacing must be a positive number");
}

} // namespace internal
} // namespace Point_set_object_recognition
} // namespace CGAL

#endif // CGAL_POINT_SET_OBJECT_RECOGNITION_INTERNAL_SEGMENTATION_OPTIONS_H
