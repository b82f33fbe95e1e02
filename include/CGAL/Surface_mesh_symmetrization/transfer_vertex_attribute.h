// Copyright (c) 2026 CGAL Global Shape Analysis contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_SURFACE_MESH_SYMMETRIZATION_TRANSFER_VERTEX_ATTRIBUTE_H
#define CGAL_SURFACE_MESH_SYMMETRIZATION_TRANSFER_VERTEX_ATTRIBUTE_H

/// \file transfer_vertex_attribute.h

#include <CGAL/Surface_mesh_symmetrization/compute_symmetric_map.h>

#include <CGAL/IO/Color.h>

#include <boost/property_map/property_map.hpp>

#include <array>
#include <cmath>
#include <string>
#include <type_traits>
#include <vector>

namespace CGAL {
namespace Surface_mesh_symmetrization {

/*!
\ingroup PkgSurfaceMeshSymmetrizationRef

How `transfer_vertex_attribute()` combines the values of the two sides of a symmetry.
*/
enum class Transfer_mode
{
  /// The vertices of the destination side take the value at their mirror point (the other side
  /// keeps its values): one side is copied onto the other.
  COPY,
  /// Every vertex takes the mean of its own value and the value at its mirror point: the
  /// attribute becomes symmetric, both sides contributing.
  BLEND
};

/*!
\ingroup PkgSurfaceMeshSymmetrizationRef

The options of `transfer_vertex_attribute()`: each member is the named parameter of the same name,
initialized to its default. When the symmetric map is computed, the options of
`compute_symmetric_map()` apply too.
*/
struct Transfer_vertex_attribute_options
{
  /// whether one side is copied onto the other or both are blended
  Transfer_mode transfer_mode = Transfer_mode::COPY;
  /// with `Transfer_mode::COPY`, the side whose values are copied: 1 for the side the plane's
  /// normal points to, -1 for the other
  int source_side = 1;
};

/*!
\ingroup PkgSurfaceMeshSymmetrizationRef

The options that `transfer_vertex_attribute()` reads from the named parameters `np`: the value of
each named parameter given, the default of `Transfer_vertex_attribute_options` for the others. The
values are not checked here; `transfer_vertex_attribute()` checks them. Named parameters that are
not options (property maps, the symmetric map) are ignored.

\tparam NamedParameters a sequence of named parameters
\param np the named parameters, as given to the function whose options these are
\returns the options, each from its named parameter or its default
*/
template <typename NamedParameters = parameters::Default_named_parameters>
Transfer_vertex_attribute_options
transfer_vertex_attribute_options(const NamedParameters& np = parameters::default_values())
{
  using CGAL::Shape_analysis::internal::parameter_value;
  namespace snp = CGAL::Shape_analysis::internal_np;
  Transfer_vertex_attribute_options o;
  o.transfer_mode = parameter_value(np, snp::transfer_mode_tag, o.transfer_mode);
  o.source_side = parameter_value(np, snp::source_side_tag, o.source_side);
  return o;
}

/// \cond SKIP_IN_MANUAL
namespace internal {

// Interpolation of attribute values at a mirror point: floating-point scalars and arrays of them
// linearly; integers (labels) take the value of the corner of largest barycentric coordinate;
// colours per channel, rounded.
template <typename T, typename = void>
struct Attribute_interpolation
{
  static_assert(std::is_arithmetic<T>::value,
                "transfer_vertex_attribute: the value type must be arithmetic, std::array of "
                "arithmetic, or CGAL::IO::Color");
  static T combine(const std::array<T, 3>& v, const std::array<double, 3>& w)
  {
    if(std::is_floating_point<T>::value)
      return T(w[0] * double(v[0]) + w[1] * double(v[1]) + w[2] * double(v[2]));
    std::size_t best = 0;
    for(std::size_t k = 1; k < 3; ++k)
      if(w[k] > w[best])
        best = k;
    return v[best];
  }
};

template <typename T, std::size_t N>
struct Attribute_interpolation<std::array<T, N>>
{
  static std::array<T, N> combine(const std::array<std::array<T, N>, 3>& v, const std::array<double, 3>& w)
  {
    std::array<T, N> r;
    for(std::size_t c = 0; c < N; ++c)
      r[c] = Attribute_interpolation<T>::combine({{v[0][c], v[1][c], v[2][c]}}, w);
    return r;
  }
};

inline unsigned char mix_channel(double a, double b, double c, const std::array<double, 3>& w)
{
  const double m = w[0] * a + w[1] * b + w[2] * c;
  return static_cast<unsigned char>((std::max)(0.0, (std::min)(255.0, std::round(m))));
}

template <>
struct Attribute_interpolation<CGAL::IO::Color>
{
  static CGAL::IO::Color combine(const std::array<CGAL::IO::Color, 3>& v, const std::array<double, 3>& w)
  {
    return CGAL::IO::Color(mix_channel(v[0].red(), v[1].red(), v[2].red(), w),
                           mix_channel(v[0].green(), v[1].green(), v[2].green(), w),
                           mix_channel(v[0].blue(), v[1].blue(), v[2].blue(), w),
                           mix_channel(v[0].alpha(), v[1].alpha(), v[2].alpha(), w));
  }
};

} // namespace internal
/// \endcond

/*!
\ingroup PkgSurfaceMeshSymmetrizationRef

Transfers a per-vertex attribute (colours, scalars, labels...) across a symmetry through the
symmetric map: the value at the mirror point of a vertex is interpolated from the values at the
corners of the mirror point's face with its barycentric coordinates.

- `Transfer_mode::COPY` (reflections only): the vertices on the destination side of the plane
  take the value at their mirror point; the source side, and vertices on the plane, keep theirs.
  The source side is the side the plane's normal points to (`source_side(1)`) or the other one
  (`source_side(-1)`).
- `Transfer_mode::BLEND` (any symmetry): every vertex takes the mean of its value and the value
  at its mirror point, so that the attribute becomes symmetric.

Vertices without a mirror point keep their values. Values are read before any is written.

\tparam TriangleMesh a model of `FaceListGraph`
\tparam Kernel the kernel of the symmetry
\tparam VertexValueMap a model of `ReadWritePropertyMap` with
        `boost::graph_traits<TriangleMesh>::%vertex_descriptor` as key type, whose value type is
        an arithmetic type (floating-point values are interpolated; integers, such as labels, take
        the value of the corner of largest barycentric coordinate, and keep their own value with
        `Transfer_mode::BLEND`), a `std::array` of them, or `CGAL::IO::Color` (interpolated per
        channel and rounded)
\tparam NamedParameters a sequence of named parameters

\param tm the mesh
\param symmetry the symmetry (a reflection for `Transfer_mode::COPY`)
\param values the attribute, read and written
\param np an optional sequence of named parameters among the ones listed below

\cgalNamedParamsBegin
  \cgalParamNBegin{transfer_mode}
    \cgalParamDescription{copy one side onto the other, or blend both}
    \cgalParamType{`Transfer_mode`}
    \cgalParamDefault{`Transfer_vertex_attribute_options::transfer_mode`}
  \cgalParamNEnd
  \cgalParamNBegin{source_side}
    \cgalParamDescription{with `Transfer_mode::COPY`, the side whose values are copied: `1` for the
      side the plane's normal points to, `-1` for the other}
    \cgalParamType{`int`}
    \cgalParamDefault{`Transfer_vertex_attribute_options::source_side`}
  \cgalParamNEnd
  \cgalParamNBegin{symmetric_map}
    \cgalParamDescription{the mirror points of the vertices, for example `result.symmetric_map[0]`
      of a `symmetrize()` result (so that the transfer follows the symmetrization even after the
      mesh was deformed); computed with `compute_symmetric_map()` when absent}
    \cgalParamType{`std::vector<Mirror_point>`}
    \cgalParamDefault{computed}
  \cgalParamNEnd
  \cgalParamNBegin{number_of_threads}
    \cgalParamDescription{the largest number of threads used (with TBB) when the symmetric map is
      computed; 0 for all cores}
    \cgalParamType{`std::size_t`}
    \cgalParamDefault{`Compute_symmetric_map_options::number_of_threads`}
  \cgalParamNEnd
  \cgalParamNBegin{vertex_point_map}
    \cgalParamDescription{a property map associating points to the vertices of `tm`}
    \cgalParamType{a class model of `ReadablePropertyMap`}
    \cgalParamDefault{`boost::get(CGAL::vertex_point, tm)`}
  \cgalParamNEnd
\cgalNamedParamsEnd

\throws CGAL::Shape_analysis::Bad_input if the mesh cannot be read (see `symmetrize()`), if
        `Transfer_mode::COPY` is asked with a symmetry that is not a reflection, if
        `source_side` is neither 1 nor -1, if the symmetry is a reflection whose plane does not
        cross the mesh, or if the symmetric map does not have one valid entry per vertex

\sa `compute_symmetric_map()`, `symmetrize()`
*/
template <typename TriangleMesh, typename Kernel, typename VertexValueMap,
          typename NamedParameters = parameters::Default_named_parameters>
void transfer_vertex_attribute(const TriangleMesh& tm, const Symmetry<Kernel>& symmetry,
                               VertexValueMap values,
                               const NamedParameters& np = parameters::default_values())
{
  namespace snp = CGAL::Shape_analysis::internal_np;
  using CGAL::parameters::is_default_parameter;
  typedef typename boost::property_traits<VertexValueMap>::value_type Value;
  const std::string who = "transfer_vertex_attribute";

  const Transfer_vertex_attribute_options o = transfer_vertex_attribute_options(np);
  const Transfer_mode mode = o.transfer_mode;
  const int side = o.source_side;
  if(side != 1 && side != -1)
    throw Bad_input(who + ": source_side must be 1 or -1");
  if(mode == Transfer_mode::COPY && !symmetry.is_reflection)
    throw Bad_input(who + ": copying one side onto the other needs a reflection (use Transfer_mode::BLEND)");

  const internal::Mesh_arrays<TriangleMesh> mesh = internal::read_mesh_np(tm, np, who);
  std::vector<Mirror_point> computed;
  if constexpr(!is_default_parameter<NamedParameters, snp::symmetric_map_t>::value) {
    internal::check_plane_crosses(mesh.surface, symmetry, who); // (symmetric_map() checks it otherwise)
    computed = CGAL::parameters::get_parameter(np, snp::symmetric_map_tag);
  } else
    computed = internal::symmetric_map(mesh.surface, symmetry, compute_symmetric_map_options(np), who);
  const std::vector<Mirror_point>* map = &computed;
  const std::size_t n = mesh.vertices.size();
  if(map->size() != n)
    throw Bad_input(who + ": the symmetric map has " + std::to_string(map->size()) +
                    " entries for a mesh of " + std::to_string(n) + " vertices");
  for(const Mirror_point& m : *map) {
    if(!m.found)
      continue;
    if(m.face >= mesh.surface.number_of_faces())
      throw Bad_input(who + ": the symmetric map refers to a face that does not exist");
    for(double b : m.barycentric)
      if(!std::isfinite(b))
        throw Bad_input(who + ": the symmetric map has a barycentric coordinate that is not finite");
  }

  std::vector<Value> before;
  before.reserve(n);
  for(std::size_t i = 0; i < n; ++i)
    before.push_back(get(values, mesh.vertices[i]));
  internal::Plane_3d plane;
  if(mode == Transfer_mode::COPY)
    plane = internal::plane_of(symmetry, who);
  for(std::size_t i = 0; i < n; ++i) {
    const Mirror_point& m = (*map)[i];
    if(!m.found)
      continue;
    if(mode == Transfer_mode::COPY && !(double(side) * plane.signed_distance(mesh.surface.points[i]) < 0))
      continue; // a source vertex, or on the plane
    const auto& t = mesh.surface.triangles[m.face];
    const Value mirror = internal::Attribute_interpolation<Value>::combine(
      {{before[t[0]], before[t[1]], before[t[2]]}}, m.barycentric);
    if(mode == Transfer_mode::COPY)
      put(values, mesh.vertices[i], mirror);
    else
      put(values, mesh.vertices[i],
          internal::Attribute_interpolation<Value>::combine({{before[i], mirror, mirror}}, {{0.5, 0.5, 0.0}}));
  }
}

} // namespace Surface_mesh_symmetrization
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_SYMMETRIZATION_TRANSFER_VERTEX_ATTRIBUTE_H
