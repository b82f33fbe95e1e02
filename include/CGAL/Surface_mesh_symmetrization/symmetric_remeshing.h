// Copyright (c) 2026 CGAL Global Shape Analysis contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_SURFACE_MESH_SYMMETRIZATION_SYMMETRIC_REMESHING_H
#define CGAL_SURFACE_MESH_SYMMETRIZATION_SYMMETRIC_REMESHING_H

/// \file symmetric_remeshing.h
/// Symmetric remeshing: a mesh whose connectivity mirrors itself across a reflection plane, from
/// a mesh whose surface does (thesis section 2.5).

#include <CGAL/Surface_mesh_symmetrization/symmetric_decimation.h>
#include <CGAL/Surface_mesh_symmetrization/internal/Side_copy.h>
#include <CGAL/Surface_mesh_symmetrization/internal/Side_overlay.h>
#include <CGAL/Surface_mesh_symmetrization/internal/Symmetric_remeshing.h>

#include <cstddef>
#include <string>
#include <vector>

namespace CGAL {
namespace Surface_mesh_symmetrization {

/*!
\ingroup PkgSurfaceMeshSymmetrizationRef
The options of `symmetric_remeshing()`: each member is the named parameter of the same name,
initialized to its default.
*/
struct Symmetric_remeshing_options
{
  /// the number of faces of the result (it is decimated to it with `symmetric_decimation()`); 0
  /// for the input's
  std::size_t number_of_faces = 0;
  /// as for `measure_symmetric_connectivity()`
  double pairing_tolerance = 0.1;
  /// the simple alternative to the remeshing: cut the surface at the plane and copy the positive
  /// side (where the plane's normal points) across it, connectivity and positions
  bool copy_one_side = false;
};

/*!
\ingroup PkgSurfaceMeshSymmetrizationRef
The options that `symmetric_remeshing()` reads from `np`, the defaults of
`Symmetric_remeshing_options` for the others (not checked here).
\tparam NamedParameters a sequence of named parameters
\param np the named parameters
\returns the options
*/
template <typename NamedParameters = parameters::Default_named_parameters>
Symmetric_remeshing_options symmetric_remeshing_options(const NamedParameters& np = parameters::default_values())
{
  using CGAL::Shape_analysis::internal::parameter_value;
  namespace snp = CGAL::Shape_analysis::internal_np;
  Symmetric_remeshing_options o;
  o.number_of_faces = parameter_value(np, snp::number_of_faces_tag, o.number_of_faces);
  o.pairing_tolerance = parameter_value(np, snp::pairing_tolerance_tag, o.pairing_tolerance);
  o.copy_one_side = parameter_value(np, snp::copy_one_side_tag, o.copy_one_side);
  return o;
}

/*!
\ingroup PkgSurfaceMeshSymmetrizationRef
What `symmetric_remeshing()` did.
*/
struct Symmetric_remeshing_result
{
  std::size_t faces_before = 0;      ///< the input's faces
  std::size_t mirror_points = 0;     ///< vertices given a partner by inserting their mirror point
  std::size_t flips = 0;             ///< edges flipped to give them a mirror edge
  std::size_t overlaid_regions = 0;  ///< regions where both sides' triangulations were overlaid
  std::size_t overlay_points = 0;    ///< vertices the overlay made where their edges cross (in pairs)
  std::size_t copied_faces = 0;      ///< faces (pieces cut at the plane) copied across it
  bool copied_whole_side = false;    ///< whether the whole positive side was copied
  std::size_t meta_mesh_faces = 0;   ///< the faces of the symmetric mesh before its decimation
  std::size_t faces = 0;             ///< the faces of the result
  Symmetric_connectivity before, after; ///< the symmetric connectivity of the input and of the result
};

/// \cond SKIP_IN_MANUAL
namespace internal {

// How far (times the mean edge length) a flip of the remeshing may move the surface. The flips
// give edges mirror edges without new points, but across a crease they cut it; the overlay
// (Side_overlay.h) keeps both sides' creases where the flips leave edges without mirror. With the
// overlay, Hausdorff distance to the input at the input's faces, 0.1 -> 0.05: PSB mesh 321
// 0.00184 -> 0.00147, 323 0.00070 -> 0.00049, the cow and the camel unchanged (0.0107, 0.00154);
// 0.01 gives 321 0.00235 once decimated.
constexpr double flip_bound = 0.05;

// The symmetric mesh of a closed surface in its plane's frame with exact pairs: mirror points,
// flips, the overlay of both sides where they still differ at creases, and the copy of what is left
// (of the whole side when `copy_one_side`, or when copying the rest only would pinch the surface).
inline void symmetric_meta_mesh(const Surface& s, const std::vector<std::uint32_t>& partner, bool copy_one_side,
                                Symmetric_remeshing_result& r, Surface& meta, std::vector<std::uint32_t>& meta_partner,
                                const std::string& who)
{
  Symmetric_remesher remesher(s, partner, who); // checks that the surface is closed and manifold
  if(!copy_one_side) {
    const double h = mean_edge_length(s);
    r.mirror_points = remesher.insert_mirror_points(h);
    remesher.make_pairs_exact();
    r.flips = remesher.flip(flip_bound * h);
  }
  remesher.export_surface(meta, meta_partner);
  if(!copy_one_side) {
    const Side_overlay::Counts c = Side_overlay::overlay(meta, meta_partner);
    r.overlaid_regions = c.overlaid;
    r.overlay_points = 2 * c.crossings;
  }
  std::size_t copied = copy_one_side ? no_partner : copy_across_plane(meta, meta_partner, false);
  if(copied == no_partner) {
    r.copied_whole_side = true;
    copied = copy_across_plane(meta, meta_partner, true);
    if(copied == no_partner)
      throw Bad_input(who + ": the surface's positive side, copied across the plane, is not a manifold surface "
                            "(it touches the plane at a vertex or along a face)");
  }
  r.copied_faces = copied;
}

} // namespace internal
/// \endcond

/*!
\ingroup PkgSurfaceMeshSymmetrizationRef

Remeshes `tm` so that its connectivity mirrors itself across the plane of `symmetry`: every
vertex has a mirror partner at the exact mirror position (a vertex on the plane is its own), every
edge a mirror edge, every face a mirror face (thesis section 2.5). `tm` should be symmetric as a
surface (`symmetrize()`): the remeshing changes its connectivity, not its shape.

The steps: vertices are paired as `measure_symmetric_connectivity()` does; each vertex left
without a partner gets one, a new vertex where its mirror image meets the surface (the face or
edge there split); pairs move to exact mirror positions (their mean); edges without a mirror edge
are flipped when the new edge has one, best first, unless the flip folds the surface or moves it
by more than a twentieth of the mean edge length; where the sides' triangulations still differ
around an edge sharper than 0.5 rad, they are overlaid (each region between the edges they share
mapped to the plane, the edges of both inserted into a constrained triangulation that splits them
where they cross, each crossing half way between its points on the two sides, the result mirrored
onto the negative side); the faces still without a mirror face are cut at
the plane and those on the positive side (where the plane's normal points) copied across it in
place of those on the negative side (a vertex on the plane where the copy would pinch the surface
first moves off it by a hundredth of the mean edge length; the whole positive side is copied when
copying only those faces still does not give a closed manifold surface). The result, about one and a half times as many faces as the input on a symmetrized
mesh, is then decimated with `symmetric_decimation()` to `number_of_faces`.

Supported: one reflection plane, applied to the whole surface (partial symmetries are remeshed
as whole ones; several planes one after the other do not keep each other's connectivity); closed
manifold triangle meshes.

\tparam TriangleMesh a model of `MutableFaceGraph` and `FaceListGraph`
\tparam Kernel the kernel of the symmetry
\tparam NamedParameters a sequence of named parameters
\param tm a closed manifold triangle mesh, symmetric as a surface
\param symmetry a reflective symmetry (`Symmetry::is_reflection`)
\param np an optional sequence of named parameters among the ones listed below

\cgalNamedParamsBegin
  \cgalParamNBegin{number_of_faces}
    \cgalParamDescription{the number of faces to decimate the symmetric mesh to (within the faces of one collapse); 0 for the input's}
    \cgalParamType{`std::size_t`}
    \cgalParamDefault{`Symmetric_remeshing_options::number_of_faces`}
  \cgalParamNEnd
  \cgalParamNBegin{pairing_tolerance}
    \cgalParamDescription{as for `measure_symmetric_connectivity()`}
    \cgalParamType{`double`}
    \cgalParamDefault{`Symmetric_remeshing_options::pairing_tolerance`}
  \cgalParamNEnd
  \cgalParamNBegin{copy_one_side}
    \cgalParamDescription{copy the positive side across the plane instead of remeshing (the simple alternative)}
    \cgalParamType{`bool`}
    \cgalParamDefault{`Symmetric_remeshing_options::copy_one_side`}
  \cgalParamNEnd
  \cgalParamNBegin{vertex_point_map}
    \cgalParamDescription{a property map associating points to the vertices of `tm`}
    \cgalParamDefault{`get_property_map(CGAL::vertex_point, tm)`}
  \cgalParamNEnd
\cgalNamedParamsEnd

\returns the counts of each step and the symmetric connectivity before and after

\throws CGAL::Shape_analysis::Bad_input as `measure_symmetric_connectivity()`, if the mesh is not
        closed or not manifold, or if its positive side copied across the plane is not a manifold
        surface; `tm` is then unchanged
*/
template <typename TriangleMesh, typename Kernel, typename NamedParameters = parameters::Default_named_parameters>
Symmetric_remeshing_result symmetric_remeshing(TriangleMesh& tm, const Symmetry<Kernel>& symmetry,
                                               const NamedParameters& np = parameters::default_values())
{
  const std::string who = "symmetric_remeshing";
  const Symmetric_remeshing_options o = symmetric_remeshing_options(np);
  Symmetric_decimation_options pairing;
  pairing.pairing_tolerance = o.pairing_tolerance;
  internal::Mirrored_mesh<TriangleMesh> m = internal::mirrored_mesh(tm, symmetry, pairing, np, who);
  Symmetric_remeshing_result r;
  r.before = internal::public_connectivity(m.frame_surface, m.partner);
  r.faces_before = m.frame_surface.triangles.size();
  internal::make_pairs_exact(m.frame_surface.points, m.partner);
  internal::Surface meta;
  std::vector<std::uint32_t> partner;
  internal::symmetric_meta_mesh(m.frame_surface, m.partner, o.copy_one_side, r, meta, partner, who);
  r.meta_mesh_faces = meta.triangles.size();
  const std::size_t target = o.number_of_faces > 0 ? o.number_of_faces : r.faces_before;
  internal::Surface out;
  if(meta.triangles.size() > target) {
    internal::Symmetric_decimator decimator(meta, partner);
    while(decimator.number_of_faces() > target && decimator.step()) {
    }
    decimator.export_surface(out, partner);
  } else
    out = meta;
  r.faces = out.triangles.size();
  r.after = internal::public_connectivity(out, partner);
  internal::replace_mesh(tm, out, m.frame, np);
  return r;
}

} // namespace Surface_mesh_symmetrization
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_SYMMETRIZATION_SYMMETRIC_REMESHING_H
