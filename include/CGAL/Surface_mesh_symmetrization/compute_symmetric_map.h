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
\param np an optional sequence of named parameters: `vertex_point_map`, `geom_traits` and
       `number_of_threads`, as for `symmetrize()`

\returns one mirror point per vertex, in the order of `vertices(tm)`

\throws CGAL::Shape_analysis::Bad_input if the mesh has no faces, a face that is not a triangle, a
        coordinate that is not finite or no area, or if the symmetry is not invertible or not
        finite
*/
template <typename TriangleMesh, typename Kernel,
          typename NamedParameters = parameters::Default_named_parameters>
std::vector<Mirror_point> compute_symmetric_map(const TriangleMesh& tm, const Symmetry<Kernel>& symmetry,
                                                const NamedParameters& np = parameters::default_values())
{
  namespace SAI = CGAL::Shape_analysis::internal;
  namespace snp = CGAL::Shape_analysis::internal_np;
  const std::string who = "compute_symmetric_map";
  const std::size_t threads = SAI::parameter_value<std::size_t>(np, snp::number_of_threads_tag, std::size_t(0));
  const internal::Mesh_arrays<TriangleMesh> mesh = internal::read_mesh_np(tm, np, who);
  const double area = mesh.surface.total_area();
  if(!(area > 0) || !std::isfinite(area))
    throw Bad_input(who + ": the mesh has no area");
  const internal::Affine_3d t = internal::affine_of(symmetry, who);
  const internal::Surface_index index(mesh.surface);
  const auto mirrors = internal::mirror_points(mesh.surface, index, {t.inverse()}, true, threads);
  std::vector<Mirror_point> result;
  result.reserve(mirrors.front().size());
  for(const internal::Mirror& m : mirrors.front())
    result.push_back(internal::public_mirror(m));
  return result;
}

} // namespace Surface_mesh_symmetrization
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_SYMMETRIZATION_COMPUTE_SYMMETRIC_MAP_H
