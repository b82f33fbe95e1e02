// Copyright (c) 2026 CGAL Global Shape Analysis contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_SURFACE_MESH_SYMMETRIZATION_DETECT_ROTATIONAL_SYMMETRIES_H
#define CGAL_SURFACE_MESH_SYMMETRIZATION_DETECT_ROTATIONAL_SYMMETRIES_H

/// \file detect_rotational_symmetries.h

#include <CGAL/Surface_mesh_symmetrization/Detect_rotational_symmetries_options.h>
#include <CGAL/Surface_mesh_symmetrization/Symmetry.h>
#include <CGAL/Surface_mesh_symmetrization/internal/Rotation_detection.h>

#include <CGAL/boost/graph/named_params_helper.h>

#include <cmath>
#include <cstddef>
#include <string>
#include <vector>

namespace CGAL {
namespace Surface_mesh_symmetrization {

/*!
\ingroup PkgSurfaceMeshSymmetrizationRef

The symmetry that is the rotation by `angle` (radians, counterclockwise seen from where `axis`
points) about the line through `point` along `axis`, for the whole surface.

\tparam Kernel a \cgal kernel
\param point a point of the axis
\param axis the axis' direction (any length but zero)
\param angle the angle of the turn, in radians
\returns the symmetry, with an empty support (the whole surface), score 0, `is_reflection` false
\throws CGAL::Shape_analysis::Bad_input if the axis is the zero vector or a value is not finite
*/
template <typename Kernel>
Symmetry<Kernel> rotational_symmetry(const typename Kernel::Point_3& point, const typename Kernel::Vector_3& axis,
                                     double angle)
{
  typedef typename Kernel::FT FT;
  const internal::Vector_3d p(CGAL::to_double(point.x()), CGAL::to_double(point.y()), CGAL::to_double(point.z()));
  internal::Vector_3d a(CGAL::to_double(axis.x()), CGAL::to_double(axis.y()), CGAL::to_double(axis.z()));
  const double l = a.length();
  if(!std::isfinite(l) || !std::isfinite(angle) || !std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
    throw Bad_input("rotational_symmetry: a value is not a finite number");
  if(!(l > 0))
    throw Bad_input("rotational_symmetry: the axis is the zero vector");
  a = a / l;
  internal::Vector_3d column[3];
  const internal::Vector_3d unit[3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  for(int j = 0; j < 3; ++j)
    column[j] = internal::turn(a, angle, unit[j]);
  const internal::Vector_3d t = p - internal::turn(a, angle, p);
  Symmetry<Kernel> s;
  s.transformation = typename Symmetry<Kernel>::Transformation(
    FT(column[0].x), FT(column[1].x), FT(column[2].x), FT(t.x), FT(column[0].y), FT(column[1].y), FT(column[2].y),
    FT(t.y), FT(column[0].z), FT(column[1].z), FT(column[2].z), FT(t.z), FT(1));
  return s;
}

/*!
\ingroup PkgSurfaceMeshSymmetrizationRef

A rotational symmetry found by `detect_rotational_symmetries()`: the surface (or its support)
turns onto itself about an axis, \f$k\f$ times in a full turn (\f$k\f$-fold), or by any angle (a
surface of revolution, `order` 0).

\tparam Kernel a \cgal kernel
*/
template <typename Kernel>
struct Rotational_symmetry
{
  /// the point of the axis nearest the surface's area centroid
  typename Kernel::Point_3 point;
  /// the axis' unit direction (its component of largest magnitude positive)
  typename Kernel::Vector_3 axis;
  /// \f$k\f$ of a \f$k\f$-fold symmetry (2 or more), 0 for a surface of revolution
  std::size_t order = 0;
  /// how far the turned surface lies from the surface, as `Symmetry::score`, for the worst of the
  /// turns by \f$2\pi j / k\f$ (a surface of revolution: by three unrelated angles)
  double score = 0;
  /// the area-weighted mean of `support`
  double support_fraction = 1;
  /// per face, in the order of `faces(tm)`, in \f$[0, 1]\f$: how closely the face turned by
  /// `angle()` lies on the surface, as `Symmetry::support`
  std::vector<double> support;

  /// \returns the smallest turn: \f$2\pi / k\f$, or for a surface of revolution an angle of no
  /// particular value (0.775 radians)
  double angle() const { return order == 0 ? 2 * 3.14159265358979323846 * 0.1234 : 2 * 3.14159265358979323846 / double(order); }
  /// \returns the symmetry that is the turn by `angle()` (for `symmetrize()`), with this support and
  /// score
  Symmetry<Kernel> symmetry() const
  {
    Symmetry<Kernel> s = rotational_symmetry<Kernel>(point, axis, angle());
    s.score = score;
    s.support_fraction = support_fraction;
    s.support = support;
    return s;
  }
};

/*!
\ingroup PkgSurfaceMeshSymmetrizationRef

Detects the rotational symmetries of a triangle mesh in any pose: \f$k\f$-fold symmetries (a
turn by \f$2\pi / k\f$ maps the surface onto itself) and surfaces of revolution, global or of a
large part of the surface (thesis section 2.3 extended from planes to axes).

1. `number_of_samples` points are drawn uniformly on the surface, with the normals of their faces.
2. Candidate axes pass through the area centroid (every global rotational symmetry fixes it): the
   three principal axes of the samples, tried with every order up to `maximum_order`, and 400
   directions spread evenly over a hemisphere, tried with the orders up to 6 and as a surface of
   revolution. An order is scored by the worst of its turns by \f$2\pi j / k\f$ (a small turn
   alone slides a smooth surface along itself), a surface of revolution by the worst of three
   turns by unrelated angles; each on 150 samples.
3. The best distinct axes are refined: the samples turned by the smallest turn and by the one
   nearest a half turn (both ways) are paired with the closest surface points whose normals agree,
   and Gauss-Newton steps on the axis' direction and position minimize the robustly weighted
   (Tukey) distances to the partners' tangent planes, with a reach shrinking from 15% to 2% of the
   diagonal.
4. The order is read off the refined axis: of the orders whose turns move the median sample at
   most 0.4% of the diagonal from the surface, those scoring within four times the best one: a
   surface of revolution if the unrelated turns do, else the largest such \f$k\f$ (a 10-fold
   turbine is also 5-fold and 2-fold; it is reported 10-fold). The axis is refined again for that
   order, scored (`Rotational_symmetry::score`), axes within 2 degrees and 10% of the diagonal of
   a better one dropped, and the support of each computed; those whose support fraction is below
   `minimum_support` are dropped.

Results are ranked by increasing score, best first. The result depends only on the shape and
`random_seed`, not on the pose of the mesh, and is the same for any number of threads. The
surface should be consistently oriented; it may be open or made of several components.

\tparam TriangleMesh a model of `FaceListGraph`
\tparam OutputIterator an output iterator accepting `Rotational_symmetry<K>`, `K` the kernel of
        the mesh's points (see `geom_traits`)
\tparam NamedParameters a sequence of named parameters

\param tm the mesh: non-empty, triangles only, finite coordinates, positive area
\param out receives the symmetries found, best first
\param np an optional sequence of named parameters among the ones listed below

\cgalNamedParamsBegin
  \cgalParamNBegin{number_of_samples}
    \cgalParamDescription{the number of points sampled on the surface}
    \cgalParamType{`std::size_t`}
    \cgalParamDefault{`Detect_rotational_symmetries_options::number_of_samples`}
    \cgalParamExtra{between 20 and 1,000,000}
  \cgalParamNEnd
  \cgalParamNBegin{maximum_number_of_symmetries}
    \cgalParamDescription{the largest number of symmetries reported}
    \cgalParamType{`std::size_t`}
    \cgalParamDefault{`Detect_rotational_symmetries_options::maximum_number_of_symmetries`}
  \cgalParamNEnd
  \cgalParamNBegin{maximum_order}
    \cgalParamDescription{the largest order \f$k\f$ tried}
    \cgalParamType{`std::size_t`}
    \cgalParamDefault{`Detect_rotational_symmetries_options::maximum_order`}
    \cgalParamExtra{between 2 and 360}
  \cgalParamNEnd
  \cgalParamNBegin{minimum_support}
    \cgalParamDescription{the smallest support fraction of a reported symmetry}
    \cgalParamType{`double`}
    \cgalParamDefault{`Detect_rotational_symmetries_options::minimum_support`}
    \cgalParamExtra{in \f$[0, 1]\f$}
  \cgalParamNEnd
  \cgalParamNBegin{support_tolerance}
    \cgalParamDescription{the tolerance \f$\sigma\f$ of the support weights, as a fraction of the
      bounding-box diagonal}
    \cgalParamType{`double`}
    \cgalParamDefault{`Detect_rotational_symmetries_options::support_tolerance`}
    \cgalParamExtra{positive}
  \cgalParamNEnd
  \cgalParamNBegin{random_seed}
    \cgalParamDescription{the seed of the random sample points}
    \cgalParamType{`unsigned int`}
    \cgalParamDefault{`Detect_rotational_symmetries_options::random_seed`}
  \cgalParamNEnd
  \cgalParamNBegin{number_of_threads}
    \cgalParamDescription{the largest number of threads used (with TBB); 0 for all cores. The
      result does not depend on it}
    \cgalParamType{`std::size_t`}
    \cgalParamDefault{`Detect_rotational_symmetries_options::number_of_threads`}
  \cgalParamNEnd
  \cgalParamNBegin{vertex_point_map}
    \cgalParamDescription{a property map associating points to the vertices of `tm`}
    \cgalParamDefault{`boost::get(CGAL::vertex_point, tm)`}
  \cgalParamNEnd
  \cgalParamNBegin{geom_traits}
    \cgalParamDescription{an instance of a geometric traits class, whose kernel is that of the
      symmetries reported}
    \cgalParamType{a class model of `Kernel`}
    \cgalParamDefault{a \cgal Kernel deduced from the point type, using `CGAL::Kernel_traits`}
  \cgalParamNEnd
\cgalNamedParamsEnd

\returns the output iterator past the last symmetry written

\throws CGAL::Shape_analysis::Bad_input if the mesh has no faces, a face that is not a triangle, a
        coordinate that is not finite or no area, or if a parameter is out of its range

\sa `detect_reflective_symmetries()`, `rotational_symmetry()`, `symmetrize()`
*/
template <typename TriangleMesh, typename OutputIterator,
          typename NamedParameters = parameters::Default_named_parameters>
OutputIterator detect_rotational_symmetries(const TriangleMesh& tm, OutputIterator out,
                                            const NamedParameters& np = parameters::default_values())
{
  typedef typename CGAL::GetGeomTraits<TriangleMesh, NamedParameters>::type Kernel;
  typedef typename Kernel::FT FT;
  const std::string who = "detect_rotational_symmetries";
  const Detect_rotational_symmetries_options o = detect_rotational_symmetries_options(np);
  if(o.maximum_order < 2 || o.maximum_order > 360)
    throw Bad_input(who + ": maximum_order must be between 2 and 360");
  const internal::Mesh_arrays<TriangleMesh> mesh = internal::detection_surface(tm, np, o, who);
  for(const internal::Detected_rotation& d : internal::detect_rotations(mesh.surface, o)) {
    Rotational_symmetry<Kernel> r;
    r.point = typename Kernel::Point_3(FT(d.point.x), FT(d.point.y), FT(d.point.z));
    r.axis = typename Kernel::Vector_3(FT(d.axis.x), FT(d.axis.y), FT(d.axis.z));
    r.order = d.order;
    r.score = d.score;
    r.support_fraction = d.support_fraction;
    r.support = d.support;
    *out++ = r;
  }
  return out;
}

} // namespace Surface_mesh_symmetrization
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_SYMMETRIZATION_DETECT_ROTATIONAL_SYMMETRIES_H
