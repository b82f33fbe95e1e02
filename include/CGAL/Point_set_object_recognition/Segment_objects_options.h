// Copyright (c) 2026 CGAL Global Shape Analysis contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_POINT_SET_OBJECT_RECOGNITION_SEGMENT_OBJECTS_OPTIONS_H
#define CGAL_POINT_SET_OBJECT_RECOGNITION_SEGMENT_OBJECTS_OPTIONS_H

/// \file Segment_objects_options.h

#include <CGAL/Shape_analysis/parameters.h>

#include <cstddef>
#include <optional>

namespace CGAL {
namespace Point_set_object_recognition {

/// The named parameters of this package (this project's, and CGAL's usable in the same chain).
namespace parameters = CGAL::Shape_analysis::parameters;

/// \ingroup PkgPointSetObjectRecognitionRef
/// How `segment_objects()` separates an object from its surroundings.
enum class Segmentation_method {
  ALL_WITHIN_RADIUS,       ///< every point within `background_radius` (horizontally) of the location
  CONNECTED_COMPONENTS,    ///< the points within `background_radius` connected to the hard foreground (voxels of `component_spacing`)
  MIN_CUT,                 ///< the minimum cut with the background radius `background_radius`
  MIN_CUT_AUTOMATIC_RADIUS ///< the minimum cut with a background radius of 1 to 7 m chosen per object
};

/*!
\ingroup PkgPointSetObjectRecognitionRef

The options of `segment_objects()`, `segment_object()` and `Interactive_segmenter`: each member is
the named parameter of the same name, initialized to its default. This struct is where the
defaults are written; the manual, `segment_objects_options()` and the `shape_analysis points
segment` command take them from here.

`component_spacing` here (as in `locate_objects()`) groups points into objects; it is not the
`component_spacing` of `remove_background()` (`Remove_background_options::component_spacing`),
whose voxels are coarser.
*/
struct Segment_objects_options
{
  /// how the objects are segmented
  Segmentation_method segmentation_method = Segmentation_method::MIN_CUT_AUTOMATIC_RADIUS;
  /// the background radius of `MIN_CUT`, the radius of `ALL_WITHIN_RADIUS` and
  /// `CONNECTED_COMPONENTS`, in metres (positive)
  double background_radius = 2;
  /// the height of the hard foreground above the location, in metres (finite)
  double foreground_height = 1.2;
  /// the side of the cells that are the nodes of the graph, in metres (0: every point is a node;
  /// else positive)
  double graph_cell_size = 0.2;
  /// the number of nearest nodes each node is joined to (between 1 and 64)
  std::size_t number_of_neighbors = 8;
  /// the length scale \f$ \sigma \f$ of the edge weights, in metres (positive); when none is
  /// given, 4 `graph_cell_size`, or 0.2 m when `graph_cell_size` is 0
  std::optional<double> edge_sigma;
  /// the scale \f$ \beta \f$ of the data term (non-negative)
  double background_weight = 0.1;
  /// larger graphs are contracted to about this many nodes (0: never)
  std::size_t maximum_graph_size = 1000;
  /// the automatic radius wants more foreground points than this
  std::size_t minimum_foreground_size = 35;
  /// the automatic radius wants a cut cost under this (non-negative)
  double maximum_cut_cost = 0.4;
  /// the side of the voxels of `CONNECTED_COMPONENTS`, in metres (positive)
  double component_spacing = 0.3;
  /// the largest number of threads (0: TBB's choice); results do not depend on it
  std::size_t number_of_threads = 0;
};

/*!
\ingroup PkgPointSetObjectRecognitionRef

The options that `segment_objects()` reads from the named parameters `np`: the value of each named
parameter given, the default of `Segment_objects_options` for the others. The values are not
checked here; `segment_objects()` checks them. Named parameters that are not options (property
maps) are ignored.

\tparam NamedParameters a sequence of named parameters
\param np the named parameters of `segment_objects()`
\returns the options
*/
template <typename NamedParameters = parameters::Default_named_parameters>
Segment_objects_options segment_objects_options(const NamedParameters& np = parameters::default_values())
{
  using CGAL::Shape_analysis::internal::parameter_value;
  namespace snp = CGAL::Shape_analysis::internal_np;
  Segment_objects_options o;
  o.segmentation_method = parameter_value(np, snp::segmentation_method_tag, o.segmentation_method);
  o.background_radius = parameter_value(np, snp::background_radius_tag, o.background_radius);
  o.foreground_height = parameter_value(np, snp::foreground_height_tag, o.foreground_height);
  o.graph_cell_size = parameter_value(np, snp::graph_cell_size_tag, o.graph_cell_size);
  o.number_of_neighbors = parameter_value(np, snp::number_of_neighbors_tag, o.number_of_neighbors);
  o.edge_sigma = parameter_value(np, snp::edge_sigma_tag, o.edge_sigma);
  o.background_weight = parameter_value(np, snp::background_weight_tag, o.background_weight);
  o.maximum_graph_size = parameter_value(np, snp::maximum_graph_size_tag, o.maximum_graph_size);
  o.minimum_foreground_size = parameter_value(np, snp::minimum_foreground_size_tag, o.minimum_foreground_size);
  o.maximum_cut_cost = parameter_value(np, snp::maximum_cut_cost_tag, o.maximum_cut_cost);
  o.component_spacing = parameter_value(np, snp::component_spacing_tag, o.component_spacing);
  o.number_of_threads = parameter_value(np, snp::number_of_threads_tag, o.number_of_threads);
  return o;
}

} // namespace Point_set_object_recognition
} // namespace CGAL

#endif // CGAL_POINT_SET_OBJECT_RECOGNITION_SEGMENT_OBJECTS_OPTIONS_H
