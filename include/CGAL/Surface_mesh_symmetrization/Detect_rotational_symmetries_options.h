// Copyright (c) 2026 CGAL Global Shape Analysis contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_SURFACE_MESH_SYMMETRIZATION_DETECT_ROTATIONAL_SYMMETRIES_OPTIONS_H
#define CGAL_SURFACE_MESH_SYMMETRIZATION_DETECT_ROTATIONAL_SYMMETRIES_OPTIONS_H

/// \file Detect_rotational_symmetries_options.h

#include <CGAL/Shape_analysis/parameters.h>

#include <cstddef>
#include <cstdint>

namespace CGAL {
namespace Surface_mesh_symmetrization {

/// The named parameters of this package (this project's, and CGAL's usable in the same chain).
namespace parameters = CGAL::Shape_analysis::parameters;

/*!
\ingroup PkgSurfaceMeshSymmetrizationRef

The options of `detect_rotational_symmetries()`: each member is the named parameter of the same
name, initialized to its default. This struct is where the defaults are written; the manual,
`detect_rotational_symmetries_options()` and `shape_analysis symmetry detect --rotational` take
them from here.
*/
struct Detect_rotational_symmetries_options
{
  /// the number of points sampled on the surface (they refine and score the axes), between 20 and
  /// 1,000,000
  std::size_t number_of_samples = 1000;
  /// the largest number of symmetries reported
  std::size_t maximum_number_of_symmetries = 5;
  /// the largest order \f$k\f$ of a \f$k\f$-fold symmetry tried, between 2 and 360
  std::size_t maximum_order = 24;
  /// the smallest support fraction of a reported symmetry, in \f$[0, 1]\f$: the part of the
  /// surface that the turn maps onto itself (three quarters by default: a turn of a smooth
  /// surface slides it along itself, so that parts of most shapes map close to the surface)
  double minimum_support = 0.75;
  /// the tolerance \f$\sigma\f$ of the support weights, as a fraction of the bounding-box
  /// diagonal (positive)
  double support_tolerance = 0.01;
  /// the seed of the random sample points (same seed, same result)
  std::uint64_t random_seed = 0;
  /// the largest number of threads used (with TBB), 0 for all cores; the result does not depend
  /// on it
  std::size_t number_of_threads = 0;
};

/*!
\ingroup PkgSurfaceMeshSymmetrizationRef

The options that `detect_rotational_symmetries()` reads from the named parameters `np`: the value
of each named parameter given, the default of `Detect_rotational_symmetries_options` for the
others. The values are not checked here; `detect_rotational_symmetries()` checks them.

\tparam NamedParameters a sequence of named parameters
\param np the named parameters, as given to the function whose options these are
\returns the options, each from its named parameter or its default
*/
template <typename NamedParameters = parameters::Default_named_parameters>
Detect_rotational_symmetries_options
detect_rotational_symmetries_options(const NamedParameters& np = parameters::default_values())
{
  using CGAL::Shape_analysis::internal::parameter_value;
  namespace snp = CGAL::Shape_analysis::internal_np;
  Detect_rotational_symmetries_options o;
  o.number_of_samples = parameter_value(np, CGAL::internal_np::number_of_samples, o.number_of_samples);
  o.maximum_number_of_symmetries =
    parameter_value(np, snp::maximum_number_of_symmetries_tag, o.maximum_number_of_symmetries);
  o.maximum_order = parameter_value(np, snp::maximum_order_tag, o.maximum_order);
  o.minimum_support = parameter_value(np, snp::minimum_support_tag, o.minimum_support);
  o.support_tolerance = parameter_value(np, snp::support_tolerance_tag, o.support_tolerance);
  o.random_seed = parameter_value(np, CGAL::internal_np::random_seed, o.random_seed);
  o.number_of_threads = parameter_value(np, snp::number_of_threads_tag, o.number_of_threads);
  return o;
}

} // namespace Surface_mesh_symmetrization
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_SYMMETRIZATION_DETECT_ROTATIONAL_SYMMETRIES_OPTIONS_H
