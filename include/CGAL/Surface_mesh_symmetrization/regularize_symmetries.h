// Copyright (c) 2026 CGAL Global Shape Analysis contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_SURFACE_MESH_SYMMETRIZATION_REGULARIZE_SYMMETRIES_H
#define CGAL_SURFACE_MESH_SYMMETRIZATION_REGULARIZE_SYMMETRIES_H

/// \file regularize_symmetries.h

#include <CGAL/Surface_mesh_symmetrization/Regularize_symmetries_options.h>
#include <CGAL/Surface_mesh_symmetrization/Symmetry.h>
#include <CGAL/Surface_mesh_symmetrization/detect_rotational_symmetries.h>
#include <CGAL/Surface_mesh_symmetrization/internal/Symmetry_regularization.h>

#include <cmath>
#include <iterator>
#include <string>
#include <vector>

namespace CGAL {
namespace Surface_mesh_symmetrization {

/*!
\ingroup PkgSurfaceMeshSymmetrizationRef

Makes the relations between several symmetries of a mesh exact (beautification, thesis section
2.6.1): detected planes that are nearly perpendicular become perpendicular, planes and rotation
axes that nearly share an axis share it exactly, the angles between the planes about such an
axis become multiples of \f$\pi / k\f$. Detected symmetries are each a little off (a tenth to
half a degree on scanned meshes), and the group that several of them generate is then not finite:
two planes \f$89.5\f$ degrees apart compose to a turn by \f$179\f$ degrees, which no shape has.
`symmetrize()` about such planes cannot reach all of them and distorts the mesh trying; about the
regularized planes it can.

Each reflection is a plane, each affine map whose linear part is a rotation (not the identity)
and that slides nothing along its axis a turn about an axis (a turn within \f$\theta\f$ of
\f$2\pi/k\f$ becomes exactly \f$2\pi/k\f$); other affine symmetries are returned unchanged. With \f$\theta\f$ =
`maximum_angle` and \f$\delta\f$ = `maximum_offset` times the bounding-box diagonal:

1. **Common axes.** The lines of the rotations, then the lines where two planes meet (in the order
   of the input), are candidate axes. The symmetries not yet in a group that lie on a candidate
   line (a plane whose normal is within \f$\theta\f$ of perpendicular to it and that passes within
   \f$\delta\f$ of its point; a rotation whose axis is within \f$\theta\f$ of it and passes within
   \f$\delta\f$) form a group if they are three or more, or two with a rotation. The group's axis
   is the direction most nearly perpendicular to its planes' normals and parallel to its rotations'
   axes (least squares), the planes' normals are made perpendicular to it, then turned to multiples
   of \f$\pi / k\f$ about it when they are all within \f$\theta\f$ of such angles (\f$k\f$ the
   order of one of its rotations, or else the smallest from its number of planes \f$m\f$ to
   \f$2m\f$: planes of a \f$k\f$-fold set may be missing), or else each perpendicular to an
   earlier plane of the group that it is within \f$\theta\f$ of perpendicular to; and everything
   passes through one point (least squares).
2. **Parallel and perpendicular directions.** In the order of the input, each group's axis (with
   its group), ungrouped plane normal and ungrouped rotation axis is made parallel to a direction
   fixed before it if within \f$\theta\f$ of parallel; otherwise, if it is within \f$\theta\f$ of
   perpendicular to two fixed directions and within \f$\theta\f$ of their cross product, made
   that cross product, else perpendicular to the first fixed direction it is within \f$\theta\f$
   of perpendicular to. A group is then turned about
   its axis so that one of its planes is parallel to a fixed direction, when one is within
   \f$\theta\f$. A plane that turns keeps its point nearest the mesh's area centroid; a rotation
   keeps its angle.
3. **Duplicates.** A plane that is, within \f$\theta\f$ and \f$\delta\f$, a plane before it, or a
   rotation that is a rotation before it (same axis, same angle), is dropped: before the first
   step (a duplicate would count twice in a group) and again after the second.

Earlier symmetries therefore take precedence: give the best first (as the detections return
them); the first does not turn unless it belongs to a group, whose members are all fitted
together. `maximum_angle` 0 only drops the duplicates. The relations are exact to rounding (about \f$10^{-15}\f$): three perpendicular planes
generate a group of 8 maps, \f$k\f$ planes about one axis at angles of \f$\pi/k\f$ a group of
\f$2k\f$. The result depends on the input's order only, not on the pose of the mesh; it is
equivariant under rigid motions.

Each symmetry returned keeps its `score`, `support_fraction` and `support` (measured for the
symmetry before the change). The change is small but its bounds are approximate: a normal turns
by about \f$\theta\f$ at most (a group's least-squares fit, then its turn, may add to it), and a
plane moves by about \f$\delta\f$ plus its turn times its distance to the centroid.

\tparam TriangleMesh a model of `FaceListGraph`
\tparam SymmetryRange a range of `Symmetry<K>`, `K` the kernel of the mesh's points
\tparam NamedParameters a sequence of named parameters

\param tm the mesh whose symmetries these are (its bounding box and area centroid are used):
          non-empty, triangles only, finite coordinates, positive area
\param symmetries the symmetries, best first
\param np an optional sequence of named parameters among the ones listed below

\cgalNamedParamsBegin
  \cgalParamNBegin{maximum_angle}
    \cgalParamDescription{the largest turn, in degrees, of a normal or an axis that makes a
      relation exact}
    \cgalParamType{`double`}
    \cgalParamDefault{`Regularize_symmetries_options::maximum_angle`}
    \cgalParamExtra{in \f$[0, 30]\f$}
  \cgalParamNEnd
  \cgalParamNBegin{maximum_offset}
    \cgalParamDescription{the largest move of a plane or an axis onto a common axis, and the
      largest distance between duplicates, as a fraction of the bounding-box diagonal}
    \cgalParamType{`double`}
    \cgalParamDefault{`Regularize_symmetries_options::maximum_offset`}
    \cgalParamExtra{in \f$[0, 1]\f$}
  \cgalParamNEnd
  \cgalParamNBegin{vertex_point_map}
    \cgalParamDescription{a property map associating points to the vertices of `tm`}
    \cgalParamType{a class model of `ReadablePropertyMap`}
    \cgalParamDefault{`boost::get(CGAL::vertex_point, tm)`}
  \cgalParamNEnd
  \cgalParamNBegin{geom_traits}
    \cgalParamDescription{an instance of a geometric traits class}
    \cgalParamType{a class model of `Kernel`}
    \cgalParamDefault{a \cgal Kernel deduced from the point type, using `CGAL::Kernel_traits`}
  \cgalParamNEnd
\cgalNamedParamsEnd

\returns the regularized symmetries, in the order of `symmetries`, without the dropped duplicates

\throws CGAL::Shape_analysis::Bad_input if the mesh has no faces, a face that is not a triangle, a
        coordinate that is not finite or no area; if a symmetry's plane is degenerate or its
        transformation has an entry that is not finite or is not invertible; or if a parameter is
        out of its range

\sa `detect_reflective_symmetries()`, `detect_rotational_symmetries()`, `symmetrize()`
*/
template <typename TriangleMesh, typename SymmetryRange,
          typename NamedParameters = parameters::Default_named_parameters>
std::vector<typename std::iterator_traits<typename SymmetryRange::const_iterator>::value_type>
regularize_symmetries(const TriangleMesh& tm, const SymmetryRange& symmetries,
                      const NamedParameters& np = parameters::default_values())
{
  typedef typename std::iterator_traits<typename SymmetryRange::const_iterator>::value_type Symmetry_type;
  typedef typename Symmetry_type::Plane_3 Plane_3;
  typedef typename Plane_3::R Kernel;
  typedef typename Kernel::FT FT;
  const std::string who = "regularize_symmetries";
  const Regularize_symmetries_options o = regularize_symmetries_options(np);
  if(!(o.maximum_angle >= 0 && o.maximum_angle <= 30))
    throw Bad_input(who + ": maximum_angle must be between 0 and 30 (degrees)");
  if(!(o.maximum_offset >= 0 && o.maximum_offset <= 1))
    throw Bad_input(who + ": maximum_offset must be in [0, 1] (a fraction of the bounding-box diagonal)");
  const internal::Mesh_arrays<TriangleMesh> mesh = internal::read_mesh_np(tm, np, who);
  internal::require_area(mesh.surface, who);
  const internal::Vector_3d centre = mesh.surface.area_centroid();

  std::vector<internal::Regular_symmetry> in;
  for(const Symmetry_type& s : symmetries) {
    const internal::Affine_3d a = internal::affine_of(s, who);
    const internal::Plane_3d p = s.is_reflection ? internal::plane_of(s, who) : internal::Plane_3d();
    in.push_back(internal::regular_symmetry(a, s.is_reflection, p, centre));
  }
  const internal::Symmetry_regularization r(in, o.maximum_angle * 3.14159265358979323846 / 180,
                                            o.maximum_offset * mesh.surface.diagonal(), centre);

  std::vector<Symmetry_type> result;
  std::size_t i = 0;
  for(const Symmetry_type& s : symmetries) {
    const internal::Regular_symmetry& x = r.symmetries()[i++];
    if(x.dropped)
      continue;
    Symmetry_type y;
    if(x.kind == internal::Regular_symmetry::PLANE)
      y = reflective_symmetry<Kernel>(Plane_3(FT(x.direction.x), FT(x.direction.y), FT(x.direction.z), FT(-x.offset)));
    else if(x.kind == internal::Regular_symmetry::ROTATION)
      y = rotational_symmetry<Kernel>(typename Kernel::Point_3(FT(x.point.x), FT(x.point.y), FT(x.point.z)),
                                      typename Kernel::Vector_3(FT(x.direction.x), FT(x.direction.y), FT(x.direction.z)),
                                      x.angle);
    else
      y = s;
    y.score = s.score;
    y.support_fraction = s.support_fraction;
    y.support = s.support;
    result.push_back(std::move(y));
  }
  return result;
}

} // namespace Surface_mesh_symmetrization
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_SYMMETRIZATION_REGULARIZE_SYMMETRIES_H
