// Copyright (c) 2026 CGAL Global Shape Analysis contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_SURFACE_MESH_SYMMETRIZATION_REGULARIZE_SYMMETRIES_OPTIONS_H
#define CGAL_SURFACE_MESH_SYMMETRIZATION_REGULARIZE_SYMMETRIES_OPTIONS_H

/// \file Regularize_symmetries_options.h

#include <CGAL/Shape_analysis/parameters.h>

namespace CGAL {
namespace Surface_mesh_symmetrization {

/// The named parameters of this package (this project's, and CGAL's usable in the same chain).
namespace parameters = CGAL::Shape_analysis::parameters;

/*!
\ingroup PkgSurfaceMeshSymmetrizationRef

The options of `regularize_symmetries()`: each member is the named parameter of the same name,
initialized to its default. This struct is where the defaults are written; the manual,
`regularize_symmetries_options()` and `shape_analysis symmetry symmetrize --regularize` take them
from here.
*/
struct Regularize_symmetries_options
{
  /// the largest angle, in degrees, by which a plane's normal or a rotation's axis is turned to
  /// make a relation exact (parallel, perpendicular, a common axis, angles of \f$\pi / k\f$), in
  /// \f$[0, 30]\f$; 0 changes nothing but drops the duplicates. Two degrees by default: the
  /// detected planes of CGAL's and the Princeton benchmark's meshes that are perpendicular by
  /// design are within about 0.6 degree of it
  double maximum_angle = 2;
  /// the largest distance by which a plane or an axis is moved onto a common axis (or found to
  /// repeat another), as a fraction of the bounding-box diagonal of the mesh, in \f$[0, 1]\f$
  double maximum_offset = 0.01;
};

/*!
\ingroup PkgSurfaceMeshSymmetrizationRef

The options that `regularize_symmetries()` reads from the named parameters `np`: the value of each
named parameter given, the default of `Regularize_symmetries_options` for the others. The values
are not checked here; `regularize_symmetries()` checks them.

\tparam NamedParameters a sequence of named parameters
\param np the named parameters, as given to the function whose options these are
\returns the options, each from its named parameter or its default
*/
template <typename NamedParameters = parameters::Default_named_parameters>
Regularize_symmetries_options regularize_symmetries_options(const NamedParameters& np = parameters::default_values())
{
  using CGAL::Shape_analysis::internal::parameter_value;
  Regularize_symmetries_options o;
  o.maximum_angle = parameter_value(np, CGAL::internal_np::maximum_angle, o.maximum_angle);
  o.maximum_offset = parameter_value(np, CGAL::internal_np::maximum_offset, o.maximum_offset);
  return o;
}

} // namespace Surface_mesh_symmetrization
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_SYMMETRIZATION_REGULARIZE_SYMMETRIES_OPTIONS_H
