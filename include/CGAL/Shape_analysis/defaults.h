// Copyright (c) 2026 CGAL Global Shape Analysis contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_SHAPE_ANALYSIS_DEFAULTS_H
#define CGAL_SHAPE_ANALYSIS_DEFAULTS_H

/// \file defaults.h
/// The defaults of the named parameters that several packages share: the weighted dual graph of a
/// mesh and the links between its connected components; and the bound of the automatic numbers of
/// segments. The options structs of the packages'
/// functions (for example `CGAL::Consistent_segmentation::Hierarchical_segmentation_options` and
/// `CGAL::Randomized_cuts::Partition_function_options`) initialize their members with these
/// constants, so that the same parameter has the same default everywhere.

#include <cstddef>

namespace CGAL {
namespace Shape_analysis {

/// \ingroup PkgShapeAnalysisCore
/// The default of the named parameter `concavity_exponent`: the exponent \f$\alpha\f$ of the
/// concavity weight \f$\min((\theta/\pi)^\alpha, 1)\f$ of the cut cost of a mesh edge.
constexpr double default_concavity_exponent = 10;

/// \ingroup PkgShapeAnalysisCore
/// The default of the named parameter `component_link_distance`: faces of different connected
/// components closer than this fraction of the bounding-box diagonal are linked.
constexpr double default_component_link_distance = 0.1;

/// \ingroup PkgShapeAnalysisCore
/// The default of the named parameter `component_link_factor`: the cut cost of a link between
/// components, relative to the mean cut cost of the mesh edges (\f$k_{cc}\f$).
constexpr double default_component_link_factor = 0.01;

/// \ingroup PkgShapeAnalysisCore
/// The largest number of segments that an automatic count (`number_of_segments` 0) chooses in
/// `CGAL::Consistent_segmentation::hierarchical_segmentation()`,
/// `CGAL::Consistent_segmentation::consistent_segmentation()` and
/// `CGAL::Randomized_cuts::segment_with_partition_function()`.
constexpr std::size_t automatic_maximum_segments = 12;

} // namespace Shape_analysis
} // namespace CGAL

#endif // CGAL_SHAPE_ANALYSIS_DEFAULTS_H
