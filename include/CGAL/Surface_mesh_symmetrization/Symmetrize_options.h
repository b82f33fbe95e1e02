// Copyright (c) 2026 CGAL Global Shape Analysis contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_SURFACE_MESH_SYMMETRIZATION_SYMMETRIZE_OPTIONS_H
#define CGAL_SURFACE_MESH_SYMMETRIZATION_SYMMETRIZE_OPTIONS_H

/// \file Symmetrize_options.h

#include <CGAL/Shape_analysis/parameters.h>

#include <cstddef>
#include <functional>
#include <optional>

namespace CGAL {
namespace Surface_mesh_symmetrization {

/// The named parameters of this package (this project's, and CGAL's usable in the same chain).
namespace parameters = CGAL::Shape_analysis::parameters;

/*!
\ingroup PkgSurfaceMeshSymmetrizationRef

The options of `symmetrize()`: each member is the named parameter of the same name, initialized to
its default. This struct is where the defaults are written; the manual, `symmetrize_options()` and
the `shape_analysis symmetry` commands take them from here.
*/
struct Symmetrize_options
{
  /// the number of steps of \f$\alpha\f$ on the coarsest level, the first constrained step
  /// included (at least 1)
  std::size_t number_of_iterations = 5;
  /// the factor \f$s\f$ of the shape term (positive)
  double shape_weight = 1;
  /// the weight \f$\beta\f$ of the displacement term (positive)
  double displacement_weight = 0.01;
  /// the number of levels of the multiresolution hierarchy, the input included (0: as many as
  /// needed to reach `coarsest_level_size`; 1: no coarser level)
  std::size_t number_of_levels = 0;
  /// the smallest number of vertices of a coarser level (a level is made when it has at least
  /// half as many)
  std::size_t coarsest_level_size = 20000;
  /// the RMS symmetry error, relative to the bounding-box diagonal, at which the constrained
  /// steps stop (positive)
  double symmetry_tolerance = 1e-6;
  /// the RMS symmetry error, relative to the bounding-box diagonal, at which the isometric
  /// refinement stops (at least 0; 0: no refinement)
  double target_symmetry_error = 1e-4;
  /// \f$\alpha / (1 - \alpha)\f$ in the constrained steps: how strongly the vertices are drawn
  /// to the midpoints of themselves and their mirror images against the shape term (positive)
  double final_symmetry_weight = 100;
  /// whether the symmetry term of each vertex is weighted by the support of each symmetry;
  /// empty: `true` when several symmetries are given, `false` for one
  std::optional<bool> support_weighting;
  /// the largest number of threads used (with TBB), 0 for all cores; the result does not depend
  /// on it
  std::size_t number_of_threads = 0;
  /// called from time to time with the fraction of the work done; none by default
  std::function<void(double)> progress_callback;
};

/*!
\ingroup PkgSurfaceMeshSymmetrizationRef

The options that `symmetrize()` reads from the named parameters `np`: the value of each named
parameter given, the default of `Symmetrize_options` for the others. The values are not checked
here; `symmetrize()` checks them. Named parameters that are not options (property maps, traits)
are ignored.

\tparam NamedParameters a sequence of named parameters
\param np the named parameters, as given to the function whose options these are
\returns the options, each from its named parameter or its default
*/
template <typename NamedParameters = parameters::Default_named_parameters>
Symmetrize_options symmetrize_options(const NamedParameters& np = parameters::default_values())
{
  using CGAL::Shape_analysis::internal::parameter_value;
  namespace snp = CGAL::Shape_analysis::internal_np;
  Symmetrize_options o;
  o.number_of_iterations = parameter_value(np, CGAL::internal_np::number_of_iterations, o.number_of_iterations);
  o.shape_weight = parameter_value(np, snp::shape_weight_tag, o.shape_weight);
  o.displacement_weight = parameter_value(np, snp::displacement_weight_tag, o.displacement_weight);
  o.number_of_levels = parameter_value(np, snp::number_of_levels_tag, o.number_of_levels);
  o.coarsest_level_size = parameter_value(np, snp::coarsest_level_size_tag, o.coarsest_level_size);
  o.symmetry_tolerance = parameter_value(np, snp::symmetry_tolerance_tag, o.symmetry_tolerance);
  o.target_symmetry_error = parameter_value(np, snp::target_symmetry_error_tag, o.target_symmetry_error);
  o.final_symmetry_weight = parameter_value(np, snp::final_symmetry_weight_tag, o.final_symmetry_weight);
  o.support_weighting = parameter_value(np, snp::support_weighting_tag, o.support_weighting);
  o.number_of_threads = parameter_value(np, snp::number_of_threads_tag, o.number_of_threads);
  o.progress_callback = parameter_value(np, snp::progress_callback_tag, o.progress_callback);
  return o;
}

} // namespace Surface_mesh_symmetrization
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_SYMMETRIZATION_SYMMETRIZE_OPTIONS_H
