// Copyright (c) 2026 CGAL Global Shape Analysis contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_CONSISTENT_SEGMENTATION_HIERARCHICAL_SEGMENTATION_OPTIONS_H
#define CGAL_CONSISTENT_SEGMENTATION_HIERARCHICAL_SEGMENTATION_OPTIONS_H

/// \file Hierarchical_segmentation_options.h

#include <CGAL/Shape_analysis/defaults.h>
#include <CGAL/Shape_analysis/parameters.h>

#include <cstddef>
#include <functional>

namespace CGAL {
namespace Consistent_segmentation {

/// The named parameters of this package (this project's, and CGAL's usable in the same chain).
namespace parameters = CGAL::Shape_analysis::parameters;

/*!
\ingroup PkgConsistentSegmentationRef

The options of `hierarchical_segmentation()` and the first stage of `consistent_segmentation()`:
each member is the named parameter of the same name, initialized to its default. This struct is
where the defaults are written; the manual, `hierarchical_segmentation_options()` and the
`shape_analysis segment` command take them from here.
*/
struct Hierarchical_segmentation_options
{
  /// the number of segments to produce, between 1 and the number of faces; 0 chooses it
  /// automatically, from 2 to 12, as the number whose boundaries run most along concave creases
  /// (see `hierarchical_segmentation()`)
  std::size_t number_of_segments = 8;
  /// the exponent \f$\alpha\f$ of the concavity weight \f$\min((\theta/\pi)^\alpha, 1)\f$: larger
  /// values make concave creases relatively cheaper to cut (at least 0)
  double concavity_exponent = CGAL::Shape_analysis::default_concavity_exponent;
  /// the factor by which the cut cost of an edge on a prior segmentation's boundary is divided
  /// (at least 1)
  double prior_boundary_factor = 10;
  /// faces of different connected components closer than this fraction of the bounding-box
  /// diagonal are linked (at least 0)
  double component_link_distance = CGAL::Shape_analysis::default_component_link_distance;
  /// the cost of a link between components, relative to the mean cut cost of the mesh edges
  /// (\f$k_{cc}\f$, positive)
  double component_link_factor = CGAL::Shape_analysis::default_component_link_factor;
  /// whether the segment boundaries are refined after the clustering
  bool boundary_refinement = true;
  /// called from time to time with the fraction of the work done; none by default
  std::function<void(double)> progress_callback;
};

/// \cond SKIP_IN_MANUAL
namespace internal {

// Sets the members of `o` whose named parameters `np` gives (the others keep their values: the
// defaults of `o`'s own type, which may be an options struct derived from this one).
template <typename NamedParameters>
void read_hierarchical_segmentation_options(const NamedParameters& np, Hierarchical_segmentation_options& o)
{
  using CGAL::Shape_analysis::internal::parameter_value;
  namespace snp = CGAL::Shape_analysis::internal_np;
  o.number_of_segments = parameter_value(np, snp::number_of_segments_tag, o.number_of_segments);
  o.concavity_exponent = parameter_value(np, snp::concavity_exponent_tag, o.concavity_exponent);
  o.prior_boundary_factor = parameter_value(np, snp::prior_boundary_factor_tag, o.prior_boundary_factor);
  o.component_link_distance = parameter_value(np, snp::component_link_distance_tag, o.component_link_distance);
  o.component_link_factor = parameter_value(np, snp::component_link_factor_tag, o.component_link_factor);
  o.boundary_refinement = parameter_value(np, snp::boundary_refinement_tag, o.boundary_refinement);
  o.progress_callback = parameter_value(np, snp::progress_callback_tag, o.progress_callback);
}

} // namespace internal
/// \endcond

/*!
\ingroup PkgConsistentSegmentationRef

The options that `hierarchical_segmentation()` reads from the named parameters `np`: the value of
each named parameter given, the default of `Hierarchical_segmentation_options` for the others.
The values are not checked here; `hierarchical_segmentation()` checks them. Named parameters
that are not options (property maps, traits) are ignored.

\tparam NamedParameters a sequence of named parameters
\param np the named parameters, as given to the function whose options these are
\returns the options, each from its named parameter or its default
*/
template <typename NamedParameters = parameters::Default_named_parameters>
Hierarchical_segmentation_options
hierarchical_segmentation_options(const NamedParameters& np = parameters::default_values())
{
  Hierarchical_segmentation_options o;
  internal::read_hierarchical_segmentation_options(np, o);
  return o;
}

} // namespace Consistent_segmentation
} // namespace CGAL

#endif // CGAL_CONSISTENT_SEGMENTATION_HIERARCHICAL_SEGMENTATION_OPTIONS_H
