// Copyright (c) 2026 CGAL Global Shape Analysis contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_POINT_SET_OBJECT_RECOGNITION_REMOVE_BACKGROUND_OPTIONS_H
#define CGAL_POINT_SET_OBJECT_RECOGNITION_REMOVE_BACKGROUND_OPTIONS_H

/// \file Remove_background_options.h

#include <CGAL/Shape_analysis/parameters.h>

#include <cstddef>

namespace CGAL {
namespace Point_set_object_recognition {

/// The named parameters of this package (this project's, and CGAL's usable in the same chain).
namespace parameters = CGAL::Shape_analysis::parameters;

/*!
\ingroup PkgPointSetObjectRecognitionRef

The options of `remove_background()`: each member is the named parameter of the same name,
initialized to its default. This struct is where the defaults are written; the manual,
`remove_background_options()` and the `shape_analysis points background` command take them from
here.

`component_spacing` here is the side of the voxels that make the connected components of the
background removal (buildings are large ones); it is not the `component_spacing` of
`locate_objects()` and `segment_objects()` (`Locate_objects_options::component_spacing`,
`Segment_objects_options::component_spacing`), which groups the foreground into objects and has
its own, smaller default.
*/
struct Remove_background_options
{
  /// the side of the cells of the ground grid, in metres (positive)
  double ground_cell_size = 5;
  /// points less than this above the ground are ground, in metres (finite)
  double ground_threshold = 0.2;
  /// the side of the voxels in which neighbours are counted, in metres (positive)
  double isolation_radius = 0.5;
  /// a point with fewer neighbours is isolated (0: none is)
  std::size_t minimum_neighbors = 3;
  /// the side of the voxels whose contact makes connected components, in metres (positive)
  double component_spacing = 0.5;
  /// components with a wider horizontal bounding box are removed, in metres (positive)
  double maximum_component_extent = 12;
};

/*!
\ingroup PkgPointSetObjectRecognitionRef

The options that `remove_background()` reads from the named parameters `np`: the value of each
named parameter given, the default of `Remove_background_options` for the others. The values are
not checked here; `remove_background()` checks them. Named parameters that are not options
(property maps) are ignored.

\tparam NamedParameters a sequence of named parameters
\param np the named parameters of `remove_background()`
\returns the options
*/
template <typename NamedParameters = parameters::Default_named_parameters>
Remove_background_options remove_background_options(const NamedParameters& np = parameters::default_values())
{
  using CGAL::Shape_analysis::internal::parameter_value;
  namespace snp = CGAL::Shape_analysis::internal_np;
  Remove_background_options o;
  o.ground_cell_size = parameter_value(np, snp::ground_cell_size_tag, o.ground_cell_size);
  o.ground_threshold = parameter_value(np, snp::ground_threshold_tag, o.ground_threshold);
  o.isolation_radius = parameter_value(np, snp::isolation_radius_tag, o.isolation_radius);
  o.minimum_neighbors = parameter_value(np, snp::minimum_neighbors_tag, o.minimum_neighbors);
  o.component_spacing = parameter_value(np, snp::component_spacing_tag, o.component_spacing);
  o.maximum_component_extent = parameter_value(np, snp::maximum_component_extent_tag, o.maximum_component_extent);
  return o;
}

} // namespace Point_set_object_recognition
} // namespace CGAL

#endif // CGAL_POINT_SET_OBJECT_RECOGNITION_REMOVE_BACKGROUND_OPTIONS_H
