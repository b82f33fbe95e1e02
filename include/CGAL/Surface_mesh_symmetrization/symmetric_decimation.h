// Copyright (c) 2026 CGAL Global Shape Analysis contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_SURFACE_MESH_SYMMETRIZATION_SYMMETRIC_DECIMATION_H
#define CGAL_SURFACE_MESH_SYMMETRIZATION_SYMMETRIC_DECIMATION_H

/// \file symmetric_decimation.h
/// Symmetric connectivity: how much of a mesh's connectivity mirrors itself across a reflection
/// plane, and the decimation that keeps it (thesis section 2.5).

#include <CGAL/Surface_mesh_symmetrization/Symmetry.h>
#include <CGAL/Surface_mesh_symmetrization/internal/Symmetric_connectivity.h>
#include <CGAL/Surface_mesh_symmetrization/internal/Symmetric_decimation.h>
#include <CGAL/Shape_analysis/parameters.h>

#include <CGAL/boost/graph/Euler_operations.h>
#include <CGAL/boost/graph/helpers.h>

#include <cmath>
#include <cstddef>
#include <limits>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Surface_mesh_symmetrization {

/*!
\ingroup PkgSurfaceMeshSymmetrizationRef
The options of `measure_symmetric_connectivity()` and `symmetric_decimation()`: each member is the
named parameter of the same name, initialized to its default.
*/
struct Symmetric_decimation_options
{
  /// the number of faces to decimate to (at most that many, within the faces of one cluster); 0
  /// for none (then `maximum_error` bounds the decimation)
  std::size_t number_of_faces = 0;
  /// the largest Garland-Heckbert error of a collapse, as a distance relative to the diagonal of
  /// the mesh's bounding box (the root of the cluster's quadric error); infinite for none
  double maximum_error = std::numeric_limits<double>::infinity();
  /// two vertices are mirror partners when each is the vertex nearest to the other's mirror image
  /// and they are closer than this fraction of the mean edge length
  double pairing_tolerance = 0.1;
};

/*!
\ingroup PkgSurfaceMeshSymmetrizationRef
The options that `measure_symmetric_connectivity()` and `symmetric_decimation()` read from `np`,
the defaults of `Symmetric_decimation_options` for the others (not checked here).
\tparam NamedParameters a sequence of named parameters
\param np the named parameters
\returns the options
*/
template <typename NamedParameters = parameters::Default_named_parameters>
Symmetric_decimation_options symmetric_decimation_options(const NamedParameters& np = parameters::default_values())
{
  using CGAL::Shape_analysis::internal::parameter_value;
  namespace snp = CGAL::Shape_analysis::internal_np;
  Symmetric_decimation_options o;
  o.number_of_faces = parameter_value(np, snp::number_of_faces_tag, o.number_of_faces);
  o.maximum_error = parameter_value(np, snp::maximum_error_tag, o.maximum_error);
  o.pairing_tolerance = parameter_value(np, snp::pairing_tolerance_tag, o.pairing_tolerance);
  return o;
}

/*!
\ingroup PkgSurfaceMeshSymmetrizationRef
How much of a mesh's connectivity is symmetric under a reflection (`measure_symmetric_connectivity()`,
`symmetric_decimation()`).
*/
struct Symmetric_connectivity
{
  /// the fractions of the vertices (of faces) with a mirror partner, of the edges whose mirror
  /// (the edge between the partners of its ends) is an edge, of the faces whose mirror is a face
  double paired_vertices = 0, symmetric_edges = 0, symmetric_faces = 0;
  std::size_t number_of_vertices = 0, number_of_edges = 0, number_of_faces = 0; ///< those counted
  /// per vertex, in the order of `vertices(tm)`, the position of its mirror partner in that order
  /// (itself for a vertex on the plane), or `no_vertex`
  std::vector<std::size_t> mirror_vertex;
  static constexpr std::size_t no_vertex = std::size_t(-1); ///< see `mirror_vertex`
};

/*!
\ingroup PkgSurfaceMeshSymmetrizationRef
What `symmetric_decimation()` did.
*/
struct Symmetric_decimation_result
{
  std::size_t faces_before = 0, faces = 0; ///< the number of faces before and after
  std::size_t collapses = 0;               ///< clusters collapsed (an edge with its mirror edge, one edge on the plane, or the two edges of a vertex on the plane to a pair)
  /// the largest error of a collapse, relative to the bounding box diagonal (see `maximum_error`)
  double largest_error = 0;
  Symmetric_connectivity before, after; ///< the symmetric connectivity of the input and of the result
};

/// \cond SKIP_IN_MANUAL
namespace internal {

// A mesh, its points in the frame of the reflection of `symmetry`, and their partners.
template <typename TriangleMesh>
struct Mirrored_mesh
{
  Mesh_arrays<TriangleMesh> arrays;
  Plane_frame frame;
  Surface frame_surface;
  std::vector<std::uint32_t> partner;
};

template <typename TriangleMesh, typename Kernel, typename NamedParameters>
Mirrored_mesh<TriangleMesh> mirrored_mesh(const TriangleMesh& tm, const Symmetry<Kernel>& symmetry,
                                          const Symmetric_decimation_options& o, const NamedParameters& np,
                                          const std::string& who)
{
  if(!symmetry.is_reflection)
    throw Bad_input(who + ": the symmetry is not a reflection (only reflective symmetries are supported)");
  if(!(o.pairing_tolerance > 0) || !std::isfinite(o.pairing_tolerance))
    throw Bad_input(who + ": pairing_tolerance must be positive and finite");
  Mesh_arrays<TriangleMesh> arrays = read_mesh_np(tm, np, who);
  const Plane_frame frame(plane_of(symmetry, who), arrays.surface.area_centroid());
  Mirrored_mesh<TriangleMesh> m{std::move(arrays), frame, Surface(), {}};
  m.frame_surface.triangles = m.arrays.surface.triangles;
  std::vector<char> used(m.arrays.surface.points.size(), 0);
  bool left = false, right = false;
  for(const auto& t : m.frame_surface.triangles)
    for(std::uint32_t v : t)
      used[v] = 1;
  for(std::size_t i = 0; i < m.arrays.surface.points.size(); ++i) {
    m.frame_surface.points.push_back(frame.to_frame(m.arrays.surface.points[i]));
    left = left || (used[i] && m.frame_surface.points.back().x < 0);
    right = right || (used[i] && m.frame_surface.points.back().x > 0);
  }
  if(!left || !right)
    throw Bad_input(who + ": the plane does not cross the mesh (all of it lies on one side)");
  m.partner = pair_vertices(m.frame_surface.points, used, o.pairing_tolerance * mean_edge_length(m.frame_surface));
  unpair_faces_in_plane(m.frame_surface, m.partner);
  return m;
}

inline Symmetric_connectivity public_connectivity(const Surface& s, const std::vector<std::uint32_t>& partner)
{
  const Connectivity_counts c = count_symmetric_connectivity(s, partner);
  Symmetric_connectivity r;
  const auto fraction = [](std::size_t k, std::size_t n) { return n > 0 ? double(k) / double(n) : 1.0; };
  r.paired_vertices = fraction(c.paired_vertices, c.vertices);
  r.symmetric_edges = fraction(c.symmetric_edges, c.edges);
  r.symmetric_faces = fraction(c.symmetric_faces, c.faces);
  r.number_of_vertices = c.vertices, r.number_of_edges = c.edges, r.number_of_faces = c.faces;
  for(std::uint32_t p : partner)
    r.mirror_vertex.push_back(p == no_partner ? Symmetric_connectivity::no_vertex : std::size_t(p));
  return r;
}


// Replaces the vertices and faces of tm by those of `s`.
template <typename TriangleMesh, typename NamedParameters>
void rebuild_mesh(TriangleMesh& tm, const Surface& s, const NamedParameters& np)
{
  auto vpm = CGAL::parameters::choose_parameter(CGAL::parameters::get_parameter(np, CGAL::internal_np::vertex_point),
                                                get_property_map(CGAL::vertex_point, tm));
  typedef typename boost::property_traits<decltype(vpm)>::value_type Point;
  typedef typename boost::graph_traits<TriangleMesh>::vertex_descriptor vertex_descriptor;
  CGAL::clear(tm);
  std::vector<vertex_descriptor> v;
  for(const Vector_3d& p : s.points) {
    v.push_back(add_vertex(tm));
    put(vpm, v.back(), Point(p.x, p.y, p.z));
  }
  for(const auto& t : s.triangles)
    CGAL::Euler::add_face(std::vector<vertex_descriptor>{v[t[0]], v[t[1]], v[t[2]]}, tm);
}

// Replaces the vertices and faces of tm by those of `s`, moved from the frame to tm's coordinates.
template <typename TriangleMesh, typename NamedParameters>
void replace_mesh(TriangleMesh& tm, Surface s, const Plane_frame& frame, const NamedParameters& np)
{
  for(Vector_3d& p : s.points)
    p = frame.from_frame(p);
  rebuild_mesh(tm, s, np);
}

} // namespace internal
/// \endcond

/*!
\ingroup PkgSurfaceMeshSymmetrizationRef

Measures how much of the connectivity of `tm` mirrors itself across the plane of `symmetry`:
vertices are paired with their mirror partners (mutual nearest neighbours of each other's mirror
images, within `pairing_tolerance` of the mean edge length; a vertex nearest to its own image is
on the plane), then an edge is symmetric when the partners of its ends are joined by an edge, a
face when the partners of its corners make a face. A symmetrized mesh (`symmetrize()`) has a
symmetric surface but, in general, not a symmetric connectivity.

\tparam TriangleMesh a model of `FaceListGraph`
\tparam Kernel the kernel of the symmetry
\tparam NamedParameters a sequence of named parameters
\param tm a triangle mesh
\param symmetry a reflective symmetry (`Symmetry::is_reflection`)
\param np an optional sequence of named parameters among the ones listed below

\cgalNamedParamsBegin
  \cgalParamNBegin{pairing_tolerance}
    \cgalParamDescription{the largest distance between a vertex and its partner's mirror image, as a fraction of the mean edge length}
    \cgalParamType{`double`}
    \cgalParamDefault{`Symmetric_decimation_options::pairing_tolerance`}
  \cgalParamNEnd
  \cgalParamNBegin{vertex_point_map}
    \cgalParamDescription{a property map associating points to the vertices of `tm`}
    \cgalParamDefault{`get_const_property_map(CGAL::vertex_point, tm)`}
  \cgalParamNEnd
\cgalNamedParamsEnd

\returns the fractions and counts, and each vertex's partner

\throws CGAL::Shape_analysis::Bad_input if the mesh is empty, has a face that is not a triangle or
        a coordinate that is not finite, if the symmetry is not a reflection, if its plane leaves
        the whole mesh on one side, or if `pairing_tolerance` is not positive
*/
template <typename TriangleMesh, typename Kernel, typename NamedParameters = parameters::Default_named_parameters>
Symmetric_connectivity measure_symmetric_connectivity(const TriangleMesh& tm, const Symmetry<Kernel>& symmetry,
                                                      const NamedParameters& np = parameters::default_values())
{
  const internal::Mirrored_mesh<TriangleMesh> m =
    internal::mirrored_mesh(tm, symmetry, symmetric_decimation_options(np), np, "measure_symmetric_connectivity");
  return internal::public_connectivity(m.frame_surface, m.partner);
}

/*!
\ingroup PkgSurfaceMeshSymmetrizationRef

Decimates `tm` by edge collapses that keep its symmetric connectivity across the plane of
`symmetry` (thesis section 2.5): an edge and its mirror edge collapse together, to mirrored
positions; an edge that is its own mirror image (on the plane, or across it between partners)
collapses onto the plane; an edge from a vertex on the plane to one off it collapses with its
mirror edge into the vertex on the plane, which stays on the plane. The collapses follow the
Garland-Heckbert error (the sum of the squared distances to the planes of the faces merged, the
worst of the two edges of a pair, that of the three vertices merged for the two edges from the
plane), each placed
at its quadric's optimum, cheapest first, while a collapse keeps the link condition, folds no face
and makes none degenerate. Vertices are paired as `measure_symmetric_connectivity()` does, then
moved to exact mirror positions (by at most `pairing_tolerance` of the mean edge length) so that
the result is exactly symmetric where its connectivity is. Edges without a mirror edge, and edges
at a border, are not collapsed: on a mesh whose connectivity is not symmetric the decimation stops
early; the result's symmetric connectivity is at least the input's.

`tm` is rebuilt (its vertices and faces replaced): the vertices of the result in the order of
the collapses' survivors, their mirror partners in `Symmetric_decimation_result::after`.

\tparam TriangleMesh a model of `MutableFaceGraph` and `FaceListGraph`
\tparam Kernel the kernel of the symmetry
\tparam NamedParameters a sequence of named parameters
\param tm a closed or open triangle mesh, manifold
\param symmetry a reflective symmetry (`Symmetry::is_reflection`)
\param np an optional sequence of named parameters among the ones listed below

\cgalNamedParamsBegin
  \cgalParamNBegin{number_of_faces}
    \cgalParamDescription{the number of faces to decimate to; 0 for none}
    \cgalParamType{`std::size_t`}
    \cgalParamDefault{`Symmetric_decimation_options::number_of_faces`}
  \cgalParamNEnd
  \cgalParamNBegin{maximum_error}
    \cgalParamDescription{the largest error of a collapse, relative to the bounding box diagonal}
    \cgalParamType{`double`}
    \cgalParamDefault{`Symmetric_decimation_options::maximum_error`}
  \cgalParamNEnd
  \cgalParamNBegin{pairing_tolerance}
    \cgalParamDescription{as for `measure_symmetric_connectivity()`}
    \cgalParamType{`double`}
    \cgalParamDefault{`Symmetric_decimation_options::pairing_tolerance`}
  \cgalParamNEnd
  \cgalParamNBegin{vertex_point_map}
    \cgalParamDescription{a property map associating points to the vertices of `tm`}
    \cgalParamDefault{`get_property_map(CGAL::vertex_point, tm)`}
  \cgalParamNEnd
\cgalNamedParamsEnd

\returns the face counts, the collapses, the largest error and the symmetric connectivity before and after

\throws CGAL::Shape_analysis::Bad_input as `measure_symmetric_connectivity()`, if neither
        `number_of_faces` nor a finite `maximum_error` is given, if `number_of_faces` is above the
        mesh's, if `maximum_error` is negative, or if the mesh is not manifold; `tm` is then
        unchanged
*/
template <typename TriangleMesh, typename Kernel, typename NamedParameters = parameters::Default_named_parameters>
Symmetric_decimation_result symmetric_decimation(TriangleMesh& tm, const Symmetry<Kernel>& symmetry,
                                                 const NamedParameters& np = parameters::default_values())
{
  const std::string who = "symmetric_decimation";
  const Symmetric_decimation_options o = symmetric_decimation_options(np);
  if(o.number_of_faces == 0 && !std::isfinite(o.maximum_error))
    throw Bad_input(who + ": give number_of_faces or a finite maximum_error");
  if(!(o.maximum_error >= 0))
    throw Bad_input(who + ": maximum_error must not be negative");
  internal::Mirrored_mesh<TriangleMesh> m = internal::mirrored_mesh(tm, symmetry, o, np, who);
  if(o.number_of_faces > m.frame_surface.triangles.size())
    throw Bad_input(who + ": number_of_faces (" + std::to_string(o.number_of_faces) + ") is above the mesh's " +
                    std::to_string(m.frame_surface.triangles.size()));
  Symmetric_decimation_result r;
  r.before = internal::public_connectivity(m.frame_surface, m.partner);
  r.faces_before = m.frame_surface.triangles.size();
  internal::make_pairs_exact(m.frame_surface.points, m.partner);
  internal::Symmetric_decimator decimator(m.frame_surface, m.partner);
  const double diagonal = m.arrays.surface.diagonal(), bound = o.maximum_error * diagonal;
  const double cost_bound = std::isfinite(bound) ? bound * bound : std::numeric_limits<double>::infinity();
  while(decimator.number_of_faces() > o.number_of_faces && decimator.step(cost_bound)) {
  }
  internal::Surface out;
  std::vector<std::uint32_t> partner;
  decimator.export_surface(out, partner);
  r.faces = out.triangles.size();
  r.collapses = decimator.collapses();
  r.largest_error = diagonal > 0 ? std::sqrt(decimator.largest_cost()) / diagonal : 0.0;
  r.after = internal::public_connectivity(out, partner);

  internal::replace_mesh(tm, out, m.frame, np);
  return r;
}

} // namespace Surface_mesh_symmetrization
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_SYMMETRIZATION_SYMMETRIC_DECIMATION_H
