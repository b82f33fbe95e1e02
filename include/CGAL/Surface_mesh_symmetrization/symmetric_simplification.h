// Copyright (c) 2026 CGAL Global Shape Analysis contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_SURFACE_MESH_SYMMETRIZATION_SYMMETRIC_SIMPLIFICATION_H
#define CGAL_SURFACE_MESH_SYMMETRIZATION_SYMMETRIC_SIMPLIFICATION_H

/// \file symmetric_simplification.h
/// Symmetric simplification of a nearly symmetric surface: symmetrize, remesh symmetrically,
/// decimate symmetrically, restore the asymmetry (thesis section 2.6.4).

#include <CGAL/Surface_mesh_symmetrization/symmetric_remeshing.h>
#include <CGAL/Surface_mesh_symmetrization/symmetrize.h>
#include <CGAL/Surface_mesh_symmetrization/internal/Surface_index.h>
#include <CGAL/Shape_analysis/internal/Point_tree.h>

#include <CGAL/Surface_mesh.h>

#include <cstddef>
#include <string>
#include <vector>

namespace CGAL {
namespace Surface_mesh_symmetrization {

/*!
\ingroup PkgSurfaceMeshSymmetrizationRef
What `symmetric_simplification()` did.
*/
struct Symmetric_simplification_result
{
  /// the RMS symmetry error of the input and of its symmetrized surface (see `symmetrize()`)
  double symmetry_error_before = 0, symmetry_error_after = 0;
  /// the remeshing and decimation of the symmetrized surface; its `after` is the connectivity of
  /// the result by its pairs (with the residuals restored, the positions are not mirror images)
  Symmetric_remeshing_result remeshing;
  bool restored = false;                ///< whether the asymmetric residuals were added back
  std::size_t faces = 0;                ///< the faces of the result
};

/// \cond SKIP_IN_MANUAL
namespace internal {

// Moves each point of `s` by the residual interpolated at its nearest point of `symmetrized`
// (residuals per vertex of `symmetrized`).
template <typename Vector>
void restore_residuals(Surface& s, const Surface& symmetrized, const std::vector<Vector>& residuals)
{
  const Surface_index surface(symmetrized);
  const std::vector<Vector_3d> normals = s.vertex_normals();
  std::uint32_t hint = Surface_index::no_face;
  for(std::size_t i = 0; i < s.points.size(); ++i) {
    Vector_3d& p = s.points[i];
    Surface_point c = surface.closest_compatible(p, normals[i], 0.0, hint); // not onto a sheet turned away
    if(!c.found)
      c = surface.closest(p, hint);
    hint = c.face;
    for(std::size_t k = 0; k < 3; ++k) {
      const Vector& d = residuals[symmetrized.triangles[c.face][k]];
      p += Vector_3d(CGAL::to_double(d.x()), CGAL::to_double(d.y()), CGAL::to_double(d.z())) * c.barycentric[k];
    }
  }
}

// Per point of `s` (the restored meta-mesh), the plane quadrics of the faces of `input` whose
// centroid is nearer to it than to any other point: added to the meta-mesh's own, they make the
// decimation fit the input's surface too (on the camel, Hausdorff distance 0.0019 of the diagonal
// instead of 0.0027 at a fifth of the faces; weighted 0.5 or 2, 0.0020 and 0.0022).
inline std::vector<Symmetric_decimator::Quadric> input_quadrics(const Surface& s, const Surface& input)
{
  std::vector<std::uint32_t> ids(s.points.size());
  for(std::size_t i = 0; i < ids.size(); ++i)
    ids[i] = std::uint32_t(i);
  const SAI::Point_tree tree(s.points, ids);
  std::vector<Symmetric_decimator::Quadric> q(s.points.size(), Symmetric_decimator::Quadric::Zero());
  for(std::size_t f = 0; f < input.triangles.size(); ++f) {
    const auto c = input.corners(f);
    const Vector_3d a = input.area_vector(f);
    const double l = a.length();
    std::uint32_t nearest = 0;
    double d2 = 0;
    if(!(l > 0) || !tree.nearest((c[0] + c[1] + c[2]) / 3.0, std::numeric_limits<double>::infinity(), nearest, d2))
      continue;
    const Vector_3d n = a / l;
    const Eigen::Vector4d r(n.x, n.y, n.z, -SAI::dot(n, c[0]));
    q[nearest] += r * r.transpose();
  }
  return q;
}

} // namespace internal
/// \endcond

/*!
\ingroup PkgSurfaceMeshSymmetrizationRef

Simplifies `tm` to `number_of_faces` faces with a connectivity that mirrors itself across the plane
of `symmetry`, whether or not its surface is symmetric (thesis section 2.6.4): a copy of the
surface is symmetrized (`symmetrize()`, which also gives each vertex its asymmetric residual, the
input position minus the symmetrized one) and remeshed symmetrically (`symmetric_remeshing()`).
Without `restore_residuals` it is then decimated symmetrically (`symmetric_decimation()`): the
result is the symmetric mesh. With it, each vertex of that mesh first moves by the residual
interpolated at its place on the symmetrized surface, and the decimation keeps the vertex pairs of
the symmetric connectivity but places each merged vertex at the optimum of its own quadric (the
planes of its faces and of the input's faces nearest to it), so that the result follows the
input's surface again.

\tparam TriangleMesh a model of `MutableFaceGraph` and `FaceListGraph`
\tparam Kernel the kernel of the symmetry
\tparam NamedParameters a sequence of named parameters
\param tm a closed manifold triangle mesh
\param symmetry a reflective symmetry (`Symmetry::is_reflection`), detected on `tm` say
\param np an optional sequence of named parameters among the ones listed below

\cgalNamedParamsBegin
  \cgalParamNBegin{number_of_faces}
    \cgalParamDescription{the number of faces of the result (within the faces of one collapse); required}
    \cgalParamType{`std::size_t`}
  \cgalParamNEnd
  \cgalParamNBegin{restore_residuals}
    \cgalParamDescription{whether the result is moved back onto the input's surface}
    \cgalParamType{`bool`}
    \cgalParamDefault{`true`}
  \cgalParamNEnd
  \cgalParamNBegin{pairing_tolerance}
    \cgalParamDescription{as for `measure_symmetric_connectivity()`}
    \cgalParamType{`double`}
    \cgalParamDefault{`Symmetric_remeshing_options::pairing_tolerance`}
  \cgalParamNEnd
  \cgalParamNBegin{number_of_threads}
    \cgalParamDescription{the largest number of threads of the symmetrization (0: all cores); the
                          result does not depend on it}
    \cgalParamType{`std::size_t`}
    \cgalParamDefault{0}
  \cgalParamNEnd
  \cgalParamNBegin{vertex_point_map}
    \cgalParamDescription{a property map associating points to the vertices of `tm`}
    \cgalParamDefault{`get_property_map(CGAL::vertex_point, tm)`}
  \cgalParamNEnd
\cgalNamedParamsEnd
The other named parameters of `symmetrize()` (`number_of_iterations`, `final_symmetry_weight`,
`target_symmetry_error`, ...) are passed to it.

\returns the symmetry errors, what the remeshing did and the number of faces

\throws CGAL::Shape_analysis::Bad_input if `number_of_faces` is missing, 0 or above the mesh's,
        and as `symmetrize()` and `symmetric_remeshing()`; `tm` is then unchanged
*/
template <typename TriangleMesh, typename Kernel, typename NamedParameters = parameters::Default_named_parameters>
Symmetric_simplification_result symmetric_simplification(TriangleMesh& tm, const Symmetry<Kernel>& symmetry,
                                                         const NamedParameters& np = parameters::default_values())
{
  using CGAL::Shape_analysis::internal::parameter_value;
  namespace snp = CGAL::Shape_analysis::internal_np;
  const std::string who = "symmetric_simplification";
  const std::size_t faces = parameter_value(np, snp::number_of_faces_tag, std::size_t(0));
  const bool restore = parameter_value(np, snp::restore_residuals_tag, true);
  const Symmetric_remeshing_options ro = symmetric_remeshing_options(np);
  const Symmetrize_options so = symmetrize_options(np);
  const internal::Mesh_arrays<TriangleMesh> input = internal::read_mesh_np(tm, np, who);
  if(faces == 0 || faces > input.surface.triangles.size())
    throw Bad_input(who + ": number_of_faces must be between 1 and the mesh's " +
                    std::to_string(input.surface.triangles.size()) + " (got " + std::to_string(faces) + ")");
  if(!symmetry.is_reflection)
    throw Bad_input(who + ": the symmetry is not a reflection (only reflective symmetries are supported)");

  // The symmetrized copy, in the input's vertex order.
  typedef CGAL::Surface_mesh<typename Kernel::Point_3> Work;
  Work work;
  std::vector<typename Work::Vertex_index> v;
  for(const internal::Vector_3d& p : input.surface.points)
    v.push_back(work.add_vertex(typename Kernel::Point_3(p.x, p.y, p.z)));
  for(const auto& t : input.surface.triangles)
    if(work.add_face(v[t[0]], v[t[1]], v[t[2]]) == Work::null_face())
      throw Bad_input(who + ": the mesh is not manifold (or has a face twice)");
  const Symmetrization_result<Kernel> s =
    symmetrize(work, std::vector<Symmetry<Kernel>>{symmetry},
               parameters::number_of_iterations(so.number_of_iterations)
                 .shape_weight(so.shape_weight)
                 .displacement_weight(so.displacement_weight)
                 .number_of_levels(so.number_of_levels)
                 .coarsest_level_size(so.coarsest_level_size)
                 .symmetry_tolerance(so.symmetry_tolerance)
                 .target_symmetry_error(so.target_symmetry_error)
                 .final_symmetry_weight(so.final_symmetry_weight)
                 .support_weighting(so.support_weighting)
                 .number_of_threads(so.number_of_threads)
                 .progress_callback(so.progress_callback));
  internal::Surface symmetrized;
  symmetrized.triangles = input.surface.triangles;
  for(const auto& p : s.symmetric_points)
    symmetrized.points.emplace_back(CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z()));

  Symmetric_simplification_result r;
  r.symmetry_error_before = s.symmetry_error_before;
  r.symmetry_error_after = s.symmetry_error_after;
  // Without restoring: the symmetric mesh remeshed and decimated. Restoring: the symmetric mesh
  // remeshed, its vertices moved back onto the input's surface, then decimated with the pairs of
  // the symmetric connectivity, each vertex at its own quadric's optimum (its faces' and the
  // nearest input faces' planes).
  r.remeshing = symmetric_remeshing(work, symmetry,
                                    parameters::number_of_faces(restore ? std::size_t(-1) : faces)
                                      .pairing_tolerance(ro.pairing_tolerance)
                                      .copy_one_side(ro.copy_one_side));
  internal::Surface out = internal::read_mesh_np(work, parameters::default_values(), who).surface;
  if(restore) {
    internal::restore_residuals(out, symmetrized, s.residuals);
    std::vector<std::uint32_t> partner;
    for(std::size_t m : r.remeshing.after.mirror_vertex)
      partner.push_back(m == Symmetric_connectivity::no_vertex ? internal::no_partner : std::uint32_t(m));
    const std::vector<internal::Symmetric_decimator::Quadric> quadrics = internal::input_quadrics(out, input.surface);
    internal::Symmetric_decimator decimator(out, partner, false, &quadrics);
    while(decimator.number_of_faces() > faces && decimator.step()) {
    }
    decimator.export_surface(out, partner);
    r.remeshing.faces = out.triangles.size();
    r.remeshing.after = internal::public_connectivity(out, partner);
  }
  r.restored = restore;
  r.faces = out.triangles.size();
  internal::rebuild_mesh(tm, out, np);
  return r;
}

} // namespace Surface_mesh_symmetrization
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_SYMMETRIZATION_SYMMETRIC_SIMPLIFICATION_H
