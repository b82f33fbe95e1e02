// Copyright (c) 2026 CGAL Global Shape Analysis contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_RANDOMIZED_CUTS_PARTITION_AWARE_DEFORMATION_H
#define CGAL_RANDOMIZED_CUTS_PARTITION_AWARE_DEFORMATION_H

/// \file partition_aware_deformation.h

#include <CGAL/Randomized_cuts/internal/Deformation_constraints.h>
#include <CGAL/Shape_analysis/Bad_input.h>
#include <CGAL/Shape_analysis/internal/Mesh_checks.h>
#include <CGAL/Shape_analysis/internal/Vector_3d.h>
#include <CGAL/Shape_analysis/parameters.h>

#include <CGAL/Surface_mesh_deformation.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/number_utils.h>

#include <boost/graph/graph_traits.hpp>
#include <boost/property_map/property_map.hpp>

#include <algorithm>
#include <cmath>
#include <iterator>
#include <optional>
#include <string>
#include <vector>

namespace CGAL {
namespace Randomized_cuts {

/// \cond SKIP_IN_MANUAL
namespace internal {

// The coordinates of a point of any CGAL kernel (or anything with x(), y(), z()) as doubles.
template <typename Point>
CGAL::Shape_analysis::internal::Vector_3d deformation_point(const Point& p)
{
  return CGAL::Shape_analysis::internal::Vector_3d(CGAL::to_double(p.x()), CGAL::to_double(p.y()),
                                                   CGAL::to_double(p.z()));
}

// The cotangent of the angle at `c` of the triangle (a, b, c), clamped to [0, 1000] (an obtuse
// angle gives 0; a degenerate corner, whose sine is under 1e-3 of the product of its side lengths,
// gives at most 1000).
inline double clamped_cotangent(const CGAL::Shape_analysis::internal::Vector_3d& a,
                                const CGAL::Shape_analysis::internal::Vector_3d& b,
                                const CGAL::Shape_analysis::internal::Vector_3d& c)
{
  using CGAL::Shape_analysis::internal::Vector_3d;
  const Vector_3d u = a - c, v = b - c;
  const double cosine_term = dot(u, v);
  if(!(cosine_term > 0))
    return 0.0;
  const double sine_term = (std::max)(cross(u, v).length(), 1e-3 * std::sqrt(u.squared_length() *
                                                                              v.squared_length()));
  if(!(sine_term > 0))
    return 0.0; // a corner with a zero-length side
  return (std::min)(cosine_term / sine_term, 1000.0);
}

} // namespace internal
/// \endcond

/*!
\ingroup PkgRandomizedCutsRef

The options of `partition_aware_deformation()`: each member is the named parameter of the same
name, initialized to its default (`Partition_aware_cotangent_weight` takes its default arguments
from here too).
*/
struct Partition_aware_deformation_options
{
  /// the largest number of as-rigid-as-possible iterations (at least 1)
  std::size_t number_of_iterations = 100;
  /// stop when no vertex moved by more than this fraction of the bounding-box diagonal in an
  /// iteration, from the second one on; 0 runs every iteration (at least 0)
  double convergence_tolerance = 1e-4;
  /// the stiffness factor \f$f\f$ of an edge on a part boundary, in \f$(0, 1]\f$ (1: plain
  /// cotangent weights everywhere)
  double flexible_weight = 0.01;
  /// the exponent \f$\gamma\f$ of the stiffness factor \f$f + (1 - f)(1 - \bar v)^\gamma\f$
  /// (positive)
  double stiffness_exponent = 2;
  /// the partition-function value \f$\sigma\f$ from which an edge counts as fully on a part
  /// boundary, in \f$(0, 1]\f$; none by default: half the largest value of the partition function
  /// (1 if every value is 0)
  std::optional<double> value_scale;
  /// the number of rings \f$k\f$ over which the values are spread: a whole number, at most
  /// `Partition_aware_cotangent_weight::maximum_spread_rings` (a `double`, so that a fraction is
  /// refused rather than rounded)
  double spread_rings = 2;
};

/*!
\ingroup PkgRandomizedCutsRef

The options that `partition_aware_deformation()` reads from the named parameters `np`: the value
of each named parameter given, the default of `Partition_aware_deformation_options` for the
others. The values are not checked here; `partition_aware_deformation()` checks them. Named
parameters that are not options (property maps) are ignored.

\tparam NamedParameters a sequence of named parameters
\param np the named parameters, as given to the function whose options these are
\returns the options, each from its named parameter or its default
*/
template <typename NamedParameters = CGAL::Shape_analysis::parameters::Default_named_parameters>
Partition_aware_deformation_options
partition_aware_deformation_options(const NamedParameters& np = CGAL::Shape_analysis::parameters::default_values())
{
  using CGAL::Shape_analysis::internal::parameter_value;
  namespace snp = CGAL::Shape_analysis::internal_np;
  Partition_aware_deformation_options o;
  o.number_of_iterations = parameter_value(np, CGAL::internal_np::number_of_iterations, o.number_of_iterations);
  o.convergence_tolerance = parameter_value(np, snp::convergence_tolerance_tag, o.convergence_tolerance);
  o.flexible_weight = parameter_value(np, snp::flexible_weight_tag, o.flexible_weight);
  o.stiffness_exponent = parameter_value(np, snp::stiffness_exponent_tag, o.stiffness_exponent);
  o.value_scale = parameter_value(np, snp::value_scale_tag, o.value_scale);
  o.spread_rings = parameter_value(np, snp::spread_rings_tag, o.spread_rings);
  return o;
}

/*!
\ingroup PkgRandomizedCutsRef

A weight calculator for `CGAL::Surface_mesh_deformation` (its `WC` template argument) that makes a
triangle mesh stiff inside its parts and flexible at their boundaries, following a partition
function (see `partition_function()`; sampled with `MIN_CUT`, whose few strong boundaries are the
joints a deformation should bend at, where the default sampler also grades weaker boundaries
inside parts): the weight of a halfedge \f$h\f$ of the edge \f$e\f$ is
\f[
  w(h) = c(e)\, s(e), \qquad
  c(e) = \max\left(\frac{1}{2} (\cot^+\alpha + \cot^+\beta),\ 10^{-6}\right), \qquad
  s(e) = f + (1 - f)\,(1 - \bar v(e))^{\gamma},
\f]
where
- \f$\alpha\f$ and \f$\beta\f$ are the angles opposite to \f$e\f$ in its (one or two) incident
  triangles, and \f$\cot^+\f$ is the cotangent clamped to \f$[0, 1000]\f$ (an obtuse angle does not
  count, a degenerate corner counts at most 1000): \f$c\f$ is the usual cotangent weight, kept
  positive so that the as-rigid-as-possible energy is well posed;
- \f$\bar v(e)\f$ is the partition-function value spread over \f$k\f$ rings and scaled: the largest
  value \f$v\f$ of the edges that are at most \f$k\f$ rings away from \f$e\f$ (\f$k = 0\f$: \f$e\f$
  alone; \f$k = 1\f$: the edges that share a vertex with \f$e\f$; \f$k = 2\f$: also the edges that
  share a vertex with those, ...), divided by the value scale \f$\sigma\f$ and clamped to
  \f$[0, 1]\f$. The cuts of randomized segmentations run along a part boundary within a band one or
  two edges wide; the spread widens the band, so that the bending it has to absorb is shared by
  several rows of triangles, and the scale makes a boundary that a fraction \f$\sigma\f$ of the
  cuts follow fully flexible;
- \f$f \in (0, 1]\f$ is the flexible weight (the share of its stiffness that an edge on a part
  boundary keeps) and \f$\gamma > 0\f$ the stiffness exponent (larger: the stiffness falls
  faster as the value grows).

Edges inside a part (\f$\bar v = 0\f$) keep their cotangent weight, edges on a part boundary
(\f$\bar v = 1\f$) get a fraction \f$f\f$ of it: as-rigid-as-possible deformation then moves parts
nearly rigidly and bends at their boundaries. Without values (default constructor), \f$s = 1\f$:
the plain (positive) cotangent weights.

Both halfedges of an edge get the same weight, on the scale of `CGAL::Weights::Cotangent_weight`
(the weight that the `ORIGINAL_ARAP` and `SRE_ARAP` algorithms use by default, with which this
class is meant to be used). For example, with `values` filled by `partition_function()` with
`sampling_method(MIN_CUT)`:
\code
typedef CGAL::Randomized_cuts::Partition_aware_cotangent_weight<Mesh, Edge_value_map> Weight;
typedef CGAL::Surface_mesh_deformation<Mesh, CGAL::Default, CGAL::Default, CGAL::ORIGINAL_ARAP,
                                       Weight> Deformation;
Deformation deformation(mesh, CGAL::get_initialized_vertex_index_map(mesh),
                        CGAL::get_initialized_halfedge_index_map(mesh),
                        get(CGAL::vertex_point, mesh), Weight(values, 0.01, 2.0, sigma, 2));
\endcode
The values are read from the map when the
deformation object computes its weights (at its construction and in
`overwrite_initial_geometry()`), each weight looking at the \f$O(d^{k+1})\f$ edges around its edge
(\f$d\f$ the vertex degree).

\tparam TriangleMesh a model of `HalfedgeGraph` (for example `CGAL::Surface_mesh`)
\tparam EdgeValueMap a model of `ReadablePropertyMap` with
        `boost::graph_traits<TriangleMesh>::%edge_descriptor` as key and a floating-point type
        as value (the partition function, in \f$[0, 1]\f$; negative values and NaN count as 0)

\sa `partition_aware_deformation()`, which sets up the whole deformation.
*/
template <typename TriangleMesh, typename EdgeValueMap>
class Partition_aware_cotangent_weight
{
public:
  /// The mesh type (as `CGAL::Surface_mesh_deformation` expects of a weight calculator).
  typedef TriangleMesh Triangle_mesh;
  /// The halfedge type.
  typedef typename boost::graph_traits<TriangleMesh>::halfedge_descriptor halfedge_descriptor;
  /// The edge type.
  typedef typename boost::graph_traits<TriangleMesh>::edge_descriptor edge_descriptor;
  /// The vertex type.
  typedef typename boost::graph_traits<TriangleMesh>::vertex_descriptor vertex_descriptor;

  /// The largest number of spread rings.
  static constexpr std::size_t maximum_spread_rings = 4;

  /// The plain cotangent weights (every stiffness factor is 1).
  Partition_aware_cotangent_weight() : m_values(), m_has_values(false) {}

  /// Weights following the values of `values`, with the flexible weight \f$f\f$, the stiffness
  /// exponent \f$\gamma\f$, the value scale \f$\sigma\f$ and \f$k\f$ spread rings.
  /// \param values the partition function of the edges
  /// \param flexible_weight the stiffness factor \f$f\f$ of an edge on a part boundary
  /// \param stiffness_exponent the exponent \f$\gamma\f$
  /// \param value_scale the value scale \f$\sigma\f$
  /// \param spread_rings the number of rings \f$k\f$ the values are spread over
  /// \pre `0 < flexible_weight <= 1`, `stiffness_exponent > 0`, `value_scale > 0`,
  ///      `spread_rings <= maximum_spread_rings`
  explicit Partition_aware_cotangent_weight(
    EdgeValueMap values,
    double flexible_weight = Partition_aware_deformation_options().flexible_weight,
    double stiffness_exponent = Partition_aware_deformation_options().stiffness_exponent,
    double value_scale = 1.0,
    std::size_t spread_rings = std::size_t(Partition_aware_deformation_options().spread_rings))
    : m_values(values), m_has_values(true), m_flexible_weight(flexible_weight),
      m_exponent(stiffness_exponent), m_scale(value_scale),
      m_rings((std::min)(spread_rings, maximum_spread_rings))
  {}

  /// The spread and scaled value \f$\bar v(e) \in [0, 1]\f$ of the edge of `h` (0 without
  /// values).
  /// \param h a halfedge of `tm`
  /// \param tm the mesh
  /// \returns \f$\bar v(e)\f$
  double spread_value(halfedge_descriptor h, const TriangleMesh& tm) const
  {
    if(!m_has_values)
      return 0.0;
    double v = value(edge(h, tm));
    if(m_rings > 0)
      v = (std::max)(vertex_value(source(h, tm), tm, m_rings - 1),
                     vertex_value(target(h, tm), tm, m_rings - 1));
    return (std::min)(1.0, v / m_scale);
  }

  /// The stiffness factor \f$s(e) \in [f, 1]\f$ of the edge of `h`.
  /// \param h a halfedge of `tm`
  /// \param tm the mesh
  /// \returns \f$s(e)\f$
  double stiffness(halfedge_descriptor h, const TriangleMesh& tm) const
  {
    if(!m_has_values)
      return 1.0;
    const double v = spread_value(h, tm);
    return m_flexible_weight + (1.0 - m_flexible_weight) * std::pow(1.0 - v, m_exponent);
  }

  /// The positive cotangent weight \f$c(e)\f$ of the edge of `h`, with the points of `vpm`.
  /// \param h a halfedge of `tm`
  /// \param tm the mesh
  /// \param vpm the points of the vertices of `tm`
  /// \returns \f$c(e)\f$
  template <typename VertexPointMap>
  static double cotangent_weight(halfedge_descriptor h, const TriangleMesh& tm, VertexPointMap vpm)
  {
    using internal::deformation_point;
    const auto a = deformation_point(get(vpm, source(h, tm)));
    const auto b = deformation_point(get(vpm, target(h, tm)));
    double w = 0;
    const halfedge_descriptor sides[2] = {h, opposite(h, tm)};
    for(const halfedge_descriptor side : sides)
      if(!is_border(side, tm))
        w += 0.5 * internal::clamped_cotangent(
                     a, b, deformation_point(get(vpm, target(next(side, tm), tm))));
    return (std::max)(w, 1e-6);
  }

  /// The weight \f$w(h) = c(e)\,s(e)\f$, as `CGAL::Surface_mesh_deformation` calls it.
  /// \param h a halfedge of `tm`
  /// \param tm the mesh
  /// \param vpm the points of the vertices of `tm`
  /// \returns \f$w(h)\f$
  template <typename VertexPointMap>
  double operator()(halfedge_descriptor h, const TriangleMesh& tm, VertexPointMap vpm) const
  {
    return cotangent_weight(h, tm, vpm) * stiffness(h, tm);
  }

private:
  double value(edge_descriptor e) const
  {
    const double v = static_cast<double>(get(m_values, e));
    return v > 0 ? v : 0.0; // NaN and negative values count as 0
  }

  // The largest value of the edges at most `depth` rings away from the edges around `v`.
  double vertex_value(vertex_descriptor v, const TriangleMesh& tm, std::size_t depth) const
  {
    double result = 0;
    if(halfedge(v, tm) == boost::graph_traits<TriangleMesh>::null_halfedge())
      return result;
    for(const halfedge_descriptor g : CGAL::halfedges_around_target(v, tm)) {
      result = (std::max)(result, value(edge(g, tm)));
      if(depth > 0)
        result = (std::max)(result, vertex_value(source(g, tm), tm, depth - 1));
    }
    return result;
  }

  EdgeValueMap m_values;
  bool m_has_values;
  double m_flexible_weight = 1.0;
  double m_exponent = 1.0;
  double m_scale = 1.0;
  std::size_t m_rings = 0;
};

/*!
\ingroup PkgRandomizedCutsRef

What a call to `partition_aware_deformation()` did.
*/
struct Partition_aware_deformation_result
{
  /// The number of as-rigid-as-possible iterations run (each: one linear solve for the positions,
  /// then one closest rotation per vertex).
  std::size_t number_of_iterations = 0;
  /// Whether the iterations stopped because no vertex moved by more than `convergence_tolerance`
  /// (relative to the bounding-box diagonal) in the last iteration.
  bool converged = false;
  /// The largest distance a vertex moved in the last iteration, divided by the diagonal of the
  /// bounding box of the mesh before the deformation.
  double largest_displacement = 0;
};

/// \cond SKIP_IN_MANUAL
namespace internal {

// Runs `deformation` one iteration at a time, up to `iterations`, until the largest move of a
// vertex of `roi` in an iteration (after the first), relative to `diagonal`, is at most
// `tolerance`.
template <typename Deformation, typename VertexPointMap, typename ToVector, typename Vertex>
Partition_aware_deformation_result run_deformation(Deformation& deformation, VertexPointMap vpm,
                                                   const ToVector& to_vector, const std::vector<Vertex>& roi,
                                                   std::size_t iterations, double tolerance, double diagonal)
{
  using CGAL::Shape_analysis::internal::Vector_3d;
  Partition_aware_deformation_result result;
  std::vector<Vector_3d> previous(roi.size());
  for(std::size_t k = 0; k < roi.size(); ++k)
    previous[k] = to_vector(get(vpm, roi[k]));
  for(std::size_t it = 0; it < iterations; ++it) {
    deformation.deform(1, 0.0);
    ++result.number_of_iterations;
    double largest = 0;
    for(std::size_t k = 0; k < roi.size(); ++k) {
      const Vector_3d p = to_vector(get(vpm, roi[k]));
      largest = (std::max)(largest, (p - previous[k]).squared_length());
      previous[k] = p;
    }
    result.largest_displacement = diagonal > 0 ? std::sqrt(largest) / diagonal : 0.0;
    if(it > 0 && tolerance > 0 && result.largest_displacement <= tolerance) {
      result.converged = true;
      break;
    }
  }
  return result;
}

} // namespace internal
/// \endcond

/*!
\ingroup PkgRandomizedCutsRef

Deforms a triangle mesh as rigidly as possible (\cgal's `Surface_mesh_deformation`, algorithm
`ORIGINAL_ARAP`) with weights that follow a partition function, so that parts move nearly rigidly
and the surface bends where parts meet: the weights of `Partition_aware_cotangent_weight`, the
cotangent weights scaled by a stiffness factor that falls from 1 inside parts to
`flexible_weight` on edges near which the partition function reaches `value_scale` (by default,
half its largest value).

Every vertex of `tm` that belongs to a face is free, except the control vertices, moved to their
targets, and the fixed vertices, kept where they are; the points of `tm` are then updated
(vertices on no face are not moved). The original algorithm is used rather than `SRE_ARAP`, whose
extra term makes neighbouring rotations alike and so works against bending concentrated at part
boundaries.

\tparam TriangleMesh a model of `FaceListGraph`, `EdgeListGraph` and `VertexListGraph` (for
        example `CGAL::Surface_mesh`)
\tparam EdgeValueMap a model of `ReadablePropertyMap` with
        `boost::graph_traits<TriangleMesh>::%edge_descriptor` as key and a floating-point type as
        value, for example the map filled by `partition_function()` with `sampling_method(MIN_CUT)`
\tparam ControlVertexRange a range of `boost::graph_traits<TriangleMesh>::%vertex_descriptor`
\tparam TargetPointRange a range of points (of the point type of the vertex point map, or of any
        type with `x()`, `y()`, `z()`), one per control vertex, in the same order
\tparam FixedVertexRange a range of `boost::graph_traits<TriangleMesh>::%vertex_descriptor`
\tparam NamedParameters a sequence of named parameters

\param tm the triangle mesh, deformed in place: non-empty, triangles only, finite coordinates
\param partition_function_values the value of every edge, in \f$[0, 1]\f$
\param control_vertices the vertices to move, distinct, each on a face
\param targets where the control vertices go (finite coordinates)
\param fixed_vertices the vertices to keep in place (none of them a control vertex; repeated ones
       and ones on no face are ignored). Every connected component of `tm` needs at least one
       control or fixed vertex
\param np an optional sequence of named parameters among the ones listed below

\cgalNamedParamsBegin
  \cgalParamNBegin{number_of_iterations}
    \cgalParamDescription{the largest number of as-rigid-as-possible iterations}
    \cgalParamType{`unsigned int`}
    \cgalParamDefault{`Partition_aware_deformation_options::number_of_iterations`}
    \cgalParamExtra{must be at least 1}
  \cgalParamNEnd
  \cgalParamNBegin{convergence_tolerance}
    \cgalParamDescription{stop when no vertex moved by more than this fraction of the
      bounding-box diagonal in an iteration (from the second one on); 0 runs every iteration}
    \cgalParamType{`double`}
    \cgalParamDefault{`Partition_aware_deformation_options::convergence_tolerance`}
  \cgalParamNEnd
  \cgalParamNBegin{flexible_weight}
    \cgalParamDescription{the stiffness factor \f$f\f$ of an edge on a part boundary (1: plain
      cotangent weights everywhere)}
    \cgalParamType{`double`}
    \cgalParamDefault{`Partition_aware_deformation_options::flexible_weight`}
    \cgalParamExtra{must be in \f$(0, 1]\f$}
  \cgalParamNEnd
  \cgalParamNBegin{stiffness_exponent}
    \cgalParamDescription{the exponent \f$\gamma\f$ of the stiffness factor
      \f$f + (1 - f)(1 - \bar v)^\gamma\f$}
    \cgalParamType{`double`}
    \cgalParamDefault{`Partition_aware_deformation_options::stiffness_exponent`}
    \cgalParamExtra{must be positive}
  \cgalParamNEnd
  \cgalParamNBegin{value_scale}
    \cgalParamDescription{the partition-function value \f$\sigma\f$ from which an edge counts as
      fully on a part boundary (the spread values are divided by it)}
    \cgalParamType{`double`}
    \cgalParamDefault{`Partition_aware_deformation_options::value_scale`: none, that is half the
      largest value of `partition_function_values` (1 if every value is 0): a boundary that the
      cuts follow at least half as often as the most often cut one is fully flexible}
    \cgalParamExtra{must be in \f$(0, 1]\f$}
  \cgalParamNEnd
  \cgalParamNBegin{spread_rings}
    \cgalParamDescription{the number of rings \f$k\f$ over which the values are spread}
    \cgalParamType{`std::size_t`}
    \cgalParamDefault{`Partition_aware_deformation_options::spread_rings`}
    \cgalParamExtra{must be at most 4}
  \cgalParamNEnd
  \cgalParamNBegin{vertex_point_map}
    \cgalParamDescription{a property map associating points to the vertices of `tm`, read and
      written}
    \cgalParamType{a class model of `ReadWritePropertyMap` with `vertex_descriptor` as key and a
      point type of a \cgal kernel as value}
    \cgalParamDefault{`boost::get(CGAL::vertex_point, tm)`}
  \cgalParamNEnd
\cgalNamedParamsEnd

\returns the number of iterations run and whether they converged

\throws CGAL::Shape_analysis::Bad_input if `tm` has no faces, a face that is not a triangle, a
        coordinate that is not finite, or a vertex index map that does not give distinct
        indices under `num_vertices(tm)`; if a value of
        `partition_function_values` is not in \f$[0, 1]\f$; if the numbers of control vertices
        and of targets differ, a target is not finite, a control vertex appears twice, is fixed
        too, is not a vertex of `tm` or is on no face; if there is no control and no fixed vertex
        in a connected component of `tm`; if a parameter is out of its range. `tm` is then left
        untouched.

\sa `Partition_aware_cotangent_weight`, `partition_function()`
*/
template <typename TriangleMesh, typename EdgeValueMap, typename ControlVertexRange,
          typename TargetPointRange, typename FixedVertexRange,
          typename NamedParameters = CGAL::Shape_analysis::parameters::Default_named_parameters>
Partition_aware_deformation_result
partition_aware_deformation(TriangleMesh& tm, EdgeValueMap partition_function_values,
                            const ControlVertexRange& control_vertices,
                            const TargetPointRange& targets,
                            const FixedVertexRange& fixed_vertices,
                            const NamedParameters& np =
                              CGAL::Shape_analysis::parameters::default_values())
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  using CGAL::Shape_analysis::Bad_input;
  typedef boost::graph_traits<TriangleMesh> GT;
  typedef typename GT::vertex_descriptor vertex_descriptor;
  typedef Partition_aware_cotangent_weight<TriangleMesh, EdgeValueMap> Weight;
  const std::string who = "partition_aware_deformation";

  // Parameters.
  typedef typename CGAL::GetVertexPointMap<TriangleMesh, NamedParameters>::type Vertex_point_map;
  Vertex_point_map vpm = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point),
                                          get_property_map(CGAL::vertex_point, tm));
  typedef typename boost::property_traits<Vertex_point_map>::value_type Point;
  const Partition_aware_deformation_options o = partition_aware_deformation_options(np);
  const double rings = o.spread_rings;
  if(!(o.number_of_iterations >= 1) || !(double(o.number_of_iterations) < 1e9))
    throw Bad_input(who + ": number_of_iterations must be at least 1");
  if(!(o.convergence_tolerance >= 0) || !std::isfinite(o.convergence_tolerance))
    throw Bad_input(who + ": convergence_tolerance must be a finite number >= 0");
  if(!(o.flexible_weight > 0 && o.flexible_weight <= 1))
    throw Bad_input(who + ": flexible_weight must be in (0, 1]");
  if(!(o.stiffness_exponent > 0) || !std::isfinite(o.stiffness_exponent))
    throw Bad_input(who + ": stiffness_exponent must be a finite positive number");
  if(o.value_scale && !(*o.value_scale > 0 && *o.value_scale <= 1))
    throw Bad_input(who + ": value_scale must be in (0, 1]");
  if(!(rings >= 0 && rings <= double(Weight::maximum_spread_rings)) || rings != std::floor(rings))
    throw Bad_input(who + ": spread_rings must be at most " +
                    std::to_string(Weight::maximum_spread_rings));

  // The mesh and the constraints.
  auto to_vector = [](const Point& p) { return internal::deformation_point(p); };
  CGAL::Shape_analysis::internal::check_triangle_mesh(tm, vpm, to_vector, who);
  auto vim = CGAL::get_initialized_vertex_index_map(tm);
  const double largest_value = internal::check_deformation_input(tm, vim, partition_function_values, who);
  const double scale = o.value_scale ? *o.value_scale : (largest_value > 0 ? 0.5 * largest_value : 1.0);
  std::vector<vertex_descriptor> controls(std::begin(control_vertices), std::end(control_vertices));
  const std::vector<Point> target_points = internal::deformation_targets<Point>(
    targets, [](const auto& p) { return internal::deformation_point(p); }, controls.size(), who);
  const std::vector<char> on_face = internal::vertices_on_faces(tm, vim);
  std::vector<vertex_descriptor> fixed;
  const std::vector<char> role = internal::deformation_roles(tm, vim, on_face, controls, fixed_vertices, fixed, who);
  internal::check_components_constrained(tm, vim, role, on_face, who);
  double diagonal = 0;
  const std::vector<vertex_descriptor> roi = internal::deformation_roi(tm, vim, vpm, to_vector, on_face, diagonal);

  // The deformation.
  typedef CGAL::Surface_mesh_deformation<TriangleMesh, CGAL::Default, CGAL::Default,
                                         CGAL::ORIGINAL_ARAP, Weight, CGAL::Default,
                                         CGAL::Default, Vertex_point_map>
    Deformation;
  Deformation deformation(tm, vim, CGAL::get_initialized_halfedge_index_map(tm), vpm,
                          Weight(partition_function_values, o.flexible_weight, o.stiffness_exponent,
                                 scale, static_cast<std::size_t>(rings)));
  deformation.insert_roi_vertices(roi.begin(), roi.end());
  deformation.insert_control_vertices(controls.begin(), controls.end());
  deformation.insert_control_vertices(fixed.begin(), fixed.end());
  if(!deformation.preprocess())
    throw Bad_input(who + ": the deformation system cannot be factorized");
  for(std::size_t k = 0; k < controls.size(); ++k)
    deformation.set_target_position(controls[k], target_points[k]);

  return internal::run_deformation(deformation, vpm, to_vector, roi, o.number_of_iterations,
                                   o.convergence_tolerance, diagonal);
}

} // namespace Randomized_cuts
} // namespace CGAL

#endif // CGAL_RANDOMIZED_CUTS_PARTITION_AWARE_DEFORMATION_H
