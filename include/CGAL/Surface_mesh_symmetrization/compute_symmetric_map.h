// Copyright (c) 2026 CGAL Global Shape Analysis contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_SURFACE_MESH_SYMMETRIZATION_COMPUTE_SYMMETRIC_MAP_H
#define CGAL_SURFACE_MESH_SYMMETRIZATION_COMPUTE_SYMMETRIC_MAP_H

/// \file compute_symmetric_map.h

#include <CGAL/Surface_mesh_symmetrization/Symmetry.h>
#include <CGAL/Surface_mesh_symmetrization/internal/Mirror_points.h>

#include <array>
#include <cmath>
#include <cstddef>
#include <string>
#include <vector>

namespace CGAL {
namespace Surface_mesh_symmetrization {

/*!
\ingroup PkgSurfaceMeshSymmetrizationRef

A point of a triangle mesh given by a face and barycentric coordinates: the image of a vertex
under a symmetry, in the symmetric map. Because it is tied to the mesh's elements and not to
coordinates, it follows any later deformation of the mesh.
*/
struct Mirror_point
{
  /// The face: its position in the order of `faces(tm)`.
  std::size_t face = 0;
  /// The barycentric coordinates with respect to the face's vertices, in the order of
  /// `vertices_around_face(halfedge(f, tm), tm)`; they sum to 1.
  std::array<double, 3> barycentric{{1, 0, 0}};
  /// The distance from the vertex's preimage to the point when the map was computed (0 when the
  /// surface is exactly symmetric there).
  double distance = 0;
  /// Whether the vertex has a mirror point: false for a vertex without faces, or when no face
  /// of a compatible orientation was found.
  bool found = false;
};

/*!
\ingroup PkgSurfaceMeshSymmetrizationRef

The symmetric map of a mesh for some symmetries: per symmetry, per vertex (in the order of
`vertices(tm)`), the point of the mesh that the symmetry maps onto the vertex.
*/
typedef std::vector<std::vector<Mirror_point>> Symmetric_map;

/*!
\ingroup PkgSurfaceMeshSymmetrizationRef

The options of `compute_symmetric_map()` (and of `transfer_vertex_attribute()` when it computes the
map): each member is the named parameter of the same name, initialized to its default.
*/
struct Compute_symmetric_map_options
{
  /// the largest number of threads used (with TBB), 0 for all cores; the result does not depend
  /// on it
  std::size_t number_of_threads = 0;
};

/*!
\ingroup PkgSurfaceMeshSymmetrizationRef

The options that `compute_symmetric_map()` reads from the named parameters `np`: the value of each
named parameter given, the default of `Compute_symmetric_map_options` for the others. Named
parameters that are not options (property maps, traits) are ignored.

\tparam NamedParameters a sequence of named parameters
\param np the named parameters, as given to the function whose options these are
\returns the options, each from its named parameter or its default
*/
template <typename NamedParameters = parameters::Default_named_parameters>
Compute_symmetric_map_options
compute_symmetric_map_options(const NamedParameters& np = parameters::default_values())
{
  using CGAL::Shape_analysis::internal::parameter_value;
  namespace snp = CGAL::Shape_analysis::internal_np;
  Compute_symmetric_map_options o;
  o.number_of_threads = parameter_value(np, snp::number_of_threads_tag, o.number_of_threads);
  return o;
}

/// \cond SKIP_IN_MANUAL
namespace internal {

inline Mirror_point public_mirror(const Mirror& m)
{
  Mirror_point p;
  p.face = m.face;
  p.barycentric = m.barycentric;
  p.distance = m.distance;
  p.found = m.found;
  return p;
}

// Bad_input unless the plane of `symmetry`, a reflection, has points of `surface` on both of its
// sides (a plane beside the mesh maps it onto nothing of itself; the symmetrization would flatten
// it onto the plane). Nothing for other symmetries.
template <typename Kernel>
void check_plane_crosses(const Surface& surface, const Symmetry<Kernel>& symmetry, const std::string& who)
{
  if(!symmetry.is_reflection)
    return;
  const Plane_3d plane = plane_of(symmetry, who);
  bool positive = false, negative = false;
  for(const Vector_3d& p : surface.points) {
    const double d = plane.signed_distance(p);
    positive = positive || d > 0, negative = negative || d < 0;
  }
  if(!positive || !negative)
    throw Bad_input(who + ": the plane of a reflection does not cross the mesh (all of it lies on one side)");
}

// compute_symmetric_map() on a mesh already read.
template <typename Kernel>
std::vector<Mirror_point> symmetric_map(const Surface& surface, const Symmetry<Kernel>& symmetry,
                                        const Compute_symmetric_map_options& o, const std::string& who)
{
  require_area(surface, who);
  const Affine_3d t = affine_of(symmetry, who);
  check_plane_crosses(surface, symmetry, who);
  const Surface_index index(surface);
  const auto mirrors = mirror_points(surface, index, {t.inverse()}, true, o.number_of_threads);
  std::vector<Mirror_point> result;
  result.reserve(mirrors.front().size());
  for(const Mirror& m : mirrors.front())
    result.push_back(public_mirror(m));
  return result;
}

} // namespace internal
/// \endcond

/*!
\ingroup PkgSurfaceMeshSymmetrizationRef

Computes the symmetric map of a mesh for one symmetry without moving it: for every vertex
\f$x_i\f$, the closest point of the surface to \f$T^{-1}(x_i)\f$ whose face normal agrees with the
transformed vertex normal (a bounding-volume hierarchy of the faces). On a symmetric mesh (after `symmetrize()`), the
mirror points are exact; on a nearly symmetric one they are the natural correspondences of
`transfer_vertex_attribute()`.

\tparam TriangleMesh a model of `FaceListGraph`
\tparam Kernel the kernel of the symmetry
\tparam NamedParameters a sequence of named parameters

\param tm the mesh (as for `symmetrize()`)
\param symmetry the symmetry
\param np an optional sequence of named parameters among the ones listed below

\cgalNamedParamsBegin
  \cgalParamNBegin{number_of_threads}
    \cgalParamDescription{the largest number of threads used (with TBB); 0 for all cores}
    \cgalParamType{`std::size_t`}
    \cgalParamDefault{`Compute_symmetric_map_options::number_of_threads`}
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

\returns one mirror point per vertex, in the order of `vertices(tm)`

\throws CGAL::Shape_analysis::Bad_input if the mesh has no faces, a face that is not a triangle, a
        coordinate that is not finite or no area, or if the symmetry is not invertible or not
        finite, or is a reflection whose plane does not cross the mesh
*/
template <typename TriangleMesh, typename Kernel,
          typename NamedParameters = parameters::Default_named_parameters>
std::vector<Mirror_point> compute_symmetric_map(const TriangleMesh& tm, const Symmetry<Kernel>& symmetry,
                                                const NamedParameters& np = parameters::default_values())
{
  const std::string who = "compute_symmetric_map";
  const internal::Mesh_arrays<TriangleMesh> mesh = internal::read_mesh_np(tm, np, who);
  return internal::symmetric_map(mesh.surface, symmetry, compute_symmetric_map_options(np), who);
}

} // namespace Surface_mesh_symmetrization
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_SYMMETRIZATION_COMPUTE_SYMMETRIC_MAP_H
