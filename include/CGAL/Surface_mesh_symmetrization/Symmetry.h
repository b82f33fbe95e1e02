// Copyright (c) 2026 CGAL Global Shape Analysis contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_SURFACE_MESH_SYMMETRIZATION_SYMMETRY_H
#define CGAL_SURFACE_MESH_SYMMETRIZATION_SYMMETRY_H

/// \file Symmetry.h

#include <CGAL/Shape_analysis/Bad_input.h>
#include <CGAL/Shape_analysis/parameters.h>
#include <CGAL/Surface_mesh_symmetrization/internal/Symmetry_geometry.h>

#include <CGAL/Aff_transformation_3.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/number_utils.h>

#include <cmath>
#include <string>
#include <vector>

namespace CGAL {
namespace Surface_mesh_symmetrization {

/// The named parameters of this package (this project's, and CGAL's usable in the same chain).
namespace parameters = CGAL::Shape_analysis::parameters;
using CGAL::Shape_analysis::Bad_input;

/*!
\ingroup PkgSurfaceMeshSymmetrizationRef

A symmetry of a surface: an affine transformation that maps the surface (or a part of it, its
support) onto itself. Planar reflections are the symmetries that `detect_reflective_symmetries()`
finds; any invertible affine transformation (a rotation about an axis, say) can be given to
`symmetrize()` and the other functions of this package.

\tparam Kernel a \cgal kernel
*/
template <typename Kernel>
struct Symmetry
{
  /// The kernel's plane type.
  typedef typename Kernel::Plane_3 Plane_3;
  /// The kernel's affine transformation type.
  typedef CGAL::Aff_transformation_3<Kernel> Transformation;

  /// The transformation that maps the surface onto itself.
  Transformation transformation;
  /// Whether the transformation is the reflection across `plane`.
  bool is_reflection = false;
  /// The plane of a reflection (meaningless otherwise), with a unit normal: the reflection maps
  /// a point \f$x\f$ to \f$x - 2\,(n \cdot x - d)\,n\f$ for the plane \f$n \cdot x = d\f$, i.e.
  /// `Plane_3(n.x(), n.y(), n.z(), -d)`.
  Plane_3 plane;
  /// How far the transformed surface lies from the surface: the root mean square, over points
  /// sampled uniformly on the surface, of the distance from each transformed point to the closest
  /// surface point whose normal agrees with the transformed normal, each distance truncated at 5%
  /// of the bounding-box diagonal, divided by the bounding-box diagonal. 0 for a perfect global
  /// symmetry; about 0.05 when no part of the surface is symmetric. Set by
  /// `detect_reflective_symmetries()`; 0 for a symmetry made by hand.
  double score = 0;
  /// The area-weighted mean of `support` (1 when `support` is empty).
  double support_fraction = 1;
  /// Per face, in the order of `faces(tm)`, in \f$[0, 1]\f$: how closely the image of the face
  /// lies on the surface (\f$e^{-\delta^2 / 2\sigma^2}\f$ for the distance \f$\delta\f$ of its
  /// transformed centroid to the surface and the support tolerance \f$\sigma\f$). Empty: the
  /// symmetry applies to the whole surface.
  std::vector<double> support;
};

/*!
\ingroup PkgSurfaceMeshSymmetrizationRef

The symmetry that is the reflection across a plane, for the whole surface.

\tparam Kernel a \cgal kernel
\param plane the plane (any non-zero normal vector; it is normalized)
\returns the symmetry, with an empty support (the whole surface), score 0
\throws CGAL::Shape_analysis::Bad_input if the plane is degenerate (zero normal vector) or a
        coefficient is not finite
*/
template <typename Kernel>
Symmetry<Kernel> reflective_symmetry(const typename Kernel::Plane_3& plane)
{
  typedef typename Kernel::FT FT;
  const internal::Plane_3d p = internal::plane_from_coefficients(
    CGAL::to_double(plane.a()), CGAL::to_double(plane.b()), CGAL::to_double(plane.c()),
    CGAL::to_double(plane.d()), "reflective_symmetry");
  const internal::Affine_3d r = internal::reflection(p);
  Symmetry<Kernel> s;
  s.is_reflection = true;
  s.plane = typename Kernel::Plane_3(FT(p.normal.x), FT(p.normal.y), FT(p.normal.z), FT(-p.offset));
  s.transformation = typename Symmetry<Kernel>::Transformation(
    FT(r.linear[0].x), FT(r.linear[0].y), FT(r.linear[0].z), FT(r.translation.x),
    FT(r.linear[1].x), FT(r.linear[1].y), FT(r.linear[1].z), FT(r.translation.y),
    FT(r.linear[2].x), FT(r.linear[2].y), FT(r.linear[2].z), FT(r.translation.z), FT(1));
  return s;
}

/*!
\ingroup PkgSurfaceMeshSymmetrizationRef

The symmetry given by an affine transformation (a rotation, say), for the whole surface.

\tparam Kernel a \cgal kernel
\param transformation an invertible affine transformation
\returns the symmetry, with an empty support (the whole surface), score 0; `is_reflection` is
         `false` (use `reflective_symmetry()` for reflections)
\throws CGAL::Shape_analysis::Bad_input if the transformation is not invertible or has an entry
        that is not finite
*/
template <typename Kernel>
Symmetry<Kernel> affine_symmetry(const CGAL::Aff_transformation_3<Kernel>& transformation)
{
  Symmetry<Kernel> s;
  s.transformation = transformation;
  internal::Affine_3d a;
  for(int i = 0; i < 3; ++i) {
    for(int j = 0; j < 3; ++j)
      a.linear[std::size_t(i)][j] = CGAL::to_double(transformation.m(i, j));
    a.translation[i] = CGAL::to_double(transformation.m(i, 3));
  }
  if(!a.is_finite())
    throw Bad_input("affine_symmetry: the transformation has an entry that is not a finite number");
  if(!a.is_invertible())
    throw Bad_input("affine_symmetry: the transformation is not invertible");
  return s;
}

/// \cond SKIP_IN_MANUAL
namespace internal {

// The transformation of a symmetry as plain doubles; throws Bad_input when it is not finite or
// not invertible.
template <typename Kernel>
Affine_3d affine_of(const Symmetry<Kernel>& s, const std::string& who)
{
  Affine_3d a;
  for(int i = 0; i < 3; ++i) {
    for(int j = 0; j < 3; ++j)
      a.linear[std::size_t(i)][j] = CGAL::to_double(s.transformation.m(i, j));
    a.translation[i] = CGAL::to_double(s.transformation.m(i, 3));
  }
  if(!a.is_finite())
    throw Bad_input(who + ": a symmetry's transformation has an entry that is not a finite number");
  if(!a.is_invertible())
    throw Bad_input(who + ": a symmetry's transformation is not invertible (degenerate plane?)");
  return a;
}

// The plane of a reflective symmetry as n.x = d with n a unit vector.
template <typename Kernel>
Plane_3d plane_of(const Symmetry<Kernel>& s, const std::string& who)
{
  return plane_from_coefficients(CGAL::to_double(s.plane.a()), CGAL::to_double(s.plane.b()),
                                 CGAL::to_double(s.plane.c()), CGAL::to_double(s.plane.d()), who);
}

// Bad_input naming `who` when the surface has no area (or an area that is not finite).
inline void require_area(const Surface& surface, const std::string& who)
{
  const double area = surface.total_area();
  if(!(area > 0) || !std::isfinite(area))
    throw Bad_input(who + ": the mesh has no area");
}

// A mesh read through the vertex point map and traits of `np`.
template <typename TriangleMesh, typename NamedParameters>
Mesh_arrays<TriangleMesh> read_mesh_np(const TriangleMesh& tm, const NamedParameters& np,
                                       const std::string& who)
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  auto vpm = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point),
                              get_const_property_map(CGAL::vertex_point, tm));
  typedef typename CGAL::GetGeomTraits<TriangleMesh, NamedParameters>::type Geom_traits;
  const SAI::Point_to_vector<Geom_traits> to_vector{
    choose_parameter<Geom_traits>(get_parameter(np, CGAL::internal_np::geom_traits))};
  return read_mesh(tm, vpm, to_vector, who);
}

// The surface of `tm` for a detection (reflective or rotational), after the checks of the options
// they share (`number_of_samples`, `minimum_support`, `support_tolerance`) and of the mesh's
// area; Bad_input naming `who` otherwise.
template <typename TriangleMesh, typename NamedParameters, typename Options>
Mesh_arrays<TriangleMesh> detection_surface(const TriangleMesh& tm, const NamedParameters& np, const Options& o,
                                            const std::string& who)
{
  if(o.number_of_samples < 20 || o.number_of_samples > 1000000)
    throw Bad_input(who + ": number_of_samples must be between 20 and 1000000");
  if(!(o.minimum_support >= 0 && o.minimum_support <= 1))
    throw Bad_input(who + ": minimum_support must be in [0, 1]");
  if(!(o.support_tolerance > 0) || !std::isfinite(o.support_tolerance))
    throw Bad_input(who + ": support_tolerance must be a positive number");
  Mesh_arrays<TriangleMesh> mesh = read_mesh_np(tm, np, who);
  require_area(mesh.surface, who);
  return mesh;
}

} // namespace internal
/// \endcond

} // namespace Surface_mesh_symmetrization
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_SYMMETRIZATION_SYMMETRY_H
