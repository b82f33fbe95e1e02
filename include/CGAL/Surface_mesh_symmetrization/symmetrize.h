// Copyright (c) 2026 CGAL Global Shape Analysis contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_SURFACE_MESH_SYMMETRIZATION_SYMMETRIZE_H
#define CGAL_SURFACE_MESH_SYMMETRIZATION_SYMMETRIZE_H

/// \file symmetrize.h

#include <CGAL/Surface_mesh_symmetrization/Symmetrize_options.h>
#include <CGAL/Surface_mesh_symmetrization/Symmetry.h>
#include <CGAL/Surface_mesh_symmetrization/compute_symmetric_map.h>
#include <CGAL/Surface_mesh_symmetrization/detect_reflective_symmetries.h>
#include <CGAL/Surface_mesh_symmetrization/internal/Symmetrization.h>

#include <CGAL/boost/graph/named_params_helper.h>

#include <array>
#include <cmath>
#include <cstddef>
#include <functional>
#include <iterator>
#include <string>
#include <vector>

namespace CGAL {
namespace Surface_mesh_symmetrization {

/*!
\ingroup PkgSurfaceMeshSymmetrizationRef

The outcome of `symmetrize()`. Per-vertex arrays are in the order of `vertices(tm)`.

\tparam Kernel the \cgal kernel of the mesh's points
*/
template <typename Kernel>
struct Symmetrization_result
{
  /// The symmetrized positions (those written into the mesh).
  std::vector<typename Kernel::Point_3> symmetric_points;
  /// The asymmetric residuals: input position minus symmetrized position. Adding them back gives
  /// the input (`restore_asymmetry()`); scaling them enhances or reduces the asymmetry
  /// (`enhance_symmetry()`).
  std::vector<typename Kernel::Vector_3> residuals;
  /// The symmetric map of the symmetrized mesh, one entry per symmetry.
  Symmetric_map symmetric_map;
  /// The RMS symmetry error after each solve, relative to the bounding-box diagonal (coarsest
  /// level first): the root mean square, over the vertices, of the distance from the preimage
  /// of each vertex under a symmetry to the closest compatible point of the surface.
  std::vector<double> symmetry_errors;
  /// The level of each solve (0: the input's resolution).
  std::vector<std::size_t> iteration_levels;
  /// The value of \f$\alpha\f$ of each solve.
  std::vector<double> iteration_alphas;
  /// The RMS symmetry error of the input (as `symmetry_errors`, with exact closest points).
  double symmetry_error_before = 0;
  /// The RMS symmetry error of the result.
  double symmetry_error_after = 0;
  /// The distortion of the result: the root mean square, over the edges, of the relative change
  /// of their lengths.
  double distortion = 0;
  /// The number of vertices of each level of the multiresolution hierarchy, the input first.
  std::vector<std::size_t> level_sizes;
};

/// \cond SKIP_IN_MANUAL
namespace internal {

// The writable vertex point map of `np` (or of the mesh).
template <typename TriangleMesh, typename NamedParameters>
auto writable_vpm(TriangleMesh& tm, const NamedParameters& np)
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  return choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point),
                          get_property_map(CGAL::vertex_point, tm));
}

// Per-vertex weights from per-face support (area-weighted mean of the incident faces).
inline std::vector<double> vertex_weights(const Surface& s, const std::vector<double>& face_support)
{
  std::vector<double> sum(s.number_of_vertices(), 0.0), area(s.number_of_vertices(), 0.0);
  for(std::size_t f = 0; f < s.number_of_faces(); ++f) {
    const double a = s.area(f);
    for(std::uint32_t v : s.triangles[f]) {
      sum[v] += a * face_support[f];
      area[v] += a;
    }
  }
  for(std::size_t v = 0; v < sum.size(); ++v)
    sum[v] = area[v] > 0 ? sum[v] / area[v] : 0.0;
  return sum;
}

// The options' ranges (not the symmetries').
inline void check_options(const Symmetrize_options& o, const std::string& who)
{
  if(o.number_of_iterations < 1)
    throw Bad_input(who + ": number_of_iterations must be at least 1");
  if(!(o.shape_weight > 0) || !std::isfinite(o.shape_weight))
    throw Bad_input(who + ": shape_weight must be a positive number");
  if(!(o.displacement_weight > 0) || !std::isfinite(o.displacement_weight))
    throw Bad_input(who + ": displacement_weight must be a positive number");
  if(!(o.symmetry_tolerance > 0) || !std::isfinite(o.symmetry_tolerance))
    throw Bad_input(who + ": symmetry_tolerance must be a positive number");
  if(!(o.target_symmetry_error >= 0) || !std::isfinite(o.target_symmetry_error))
    throw Bad_input(who + ": target_symmetry_error must be a number, at least 0");
  if(!(o.final_symmetry_weight > 0) || !std::isfinite(o.final_symmetry_weight))
    throw Bad_input(who + ": final_symmetry_weight must be a positive number");
}

// The symmetries as the solver takes them: transforms, and vertex weights from the supports when
// `weighting`.
template <typename Kernel, typename SymmetryRange>
std::vector<Solver_symmetry> solver_symmetries(const Surface& surface, const SymmetryRange& symmetries,
                                               bool weighting, const std::string& who)
{
  std::vector<Solver_symmetry> result;
  for(const Symmetry<Kernel>& s : symmetries) {
    Solver_symmetry ss;
    ss.transform = affine_of(s, who);
    check_plane_crosses(surface, s, who); // (a plane beside the mesh would flatten it onto the plane)
    if(weighting && !s.support.empty()) {
      if(s.support.size() != surface.number_of_faces())
        throw Bad_input(who + ": a symmetry's support has " + std::to_string(s.support.size()) +
                        " values for " + std::to_string(surface.number_of_faces()) + " faces");
      for(double w : s.support)
        if(!(w >= 0 && w <= 1))
          throw Bad_input(who + ": a symmetry's support has a value outside [0, 1]");
      ss.vertex_weight = vertex_weights(surface, s.support);
    }
    result.push_back(std::move(ss));
  }
  return result;
}

} // namespace internal
/// \endcond

/*!
\ingroup PkgSurfaceMeshSymmetrizationRef

Symmetrizes a triangle mesh: moves its vertices, keeping its connectivity, so that it becomes
symmetric under the given symmetries while its shape changes as little as possible
(\cgalCite{Golovinskiy2010}, section 2.4).

Each vertex \f$y_i\f$ of the current surface gets a mirror point \f$p_i\f$ for each symmetry
\f$T\f$: the closest point of the surface to \f$T^{-1}(y_i)\f$ whose face normal agrees with the
transformed vertex normal (points whose normal points the other way are rejected; a
bounding-volume hierarchy of the faces, refitted as the vertices move). A sparse linear least-squares problem then gives the new positions:
\f[ E = \alpha E_{sym} + (1 - \alpha)(E_{shape} + \beta E_{disp}), \f]
where \f$E_{sym} = \frac{1}{n}\sum_T\sum_i w_{i,T}\,|x_i - q_i|^2\f$ draws each vertex towards
\f$q_i = (y_i + T(p_i))/2\f$, the midpoint of itself and the image of its mirror point (\f$w\f$:
the support weights), \f$E_{shape} = \frac{s D^2}{h^2 |E|}\sum_{(i,j)}|(x_i - x_j) - (r_i - r_j)|^2\f$
keeps the edge vectors of a reference \f$r\f$ (\f$D\f$ the bounding-box diagonal, \f$h\f$ the mean
edge length, \f$s\f$ the `shape_weight`), and \f$E_{disp} = \frac{1}{n}\sum_i |x_i - x^0_i|^2\f$
keeps the vertices near the input \f$x^0\f$, \f$\beta\f$ = `displacement_weight`. The three
coordinates share one sparse matrix (one Cholesky factorization, Eigen). \f$\alpha\f$ moves from 0
to 1 over `number_of_iterations` steps (\f$\alpha / (1 - \alpha)\f$ from 0.1 to \f$10^4\f$), the
mirror points being recomputed after each solve, with the input as reference \f$r\f$. The last,
constrained steps (\f$\alpha / (1 - \alpha)\f$ = `final_symmetry_weight`) use the current surface
as reference, so that the shape term vanishes at
convergence, where every vertex is the midpoint of itself and its mirror image, i.e. its mirror
point lies on the surface; two vertices whose mirror points fall next to each other (mutually,
within a third of the mean edge length) are then paired exactly, so that a mesh whose
connectivity is nearly symmetric becomes exactly symmetric. They stop when the RMS symmetry error
is below `symmetry_tolerance`, gains less than 5% in a step, or after 8 steps; the positions of
the smallest error from the last step of the schedule on are kept.

Multiresolution: meshes of more than about `4 coarsest_level_size` vertices are first decimated
with \cgal's edge collapse (each level with about 1/8 of the vertices of the previous one, down to
about `coarsest_level_size`); the coarser levels take the steps of the schedule and their
displacements, interpolated at the closest points of their surfaces, seed the finer levels, which
then take the last two steps of the schedule and, at the input's resolution, the constrained
steps.

Several partial symmetries can be given at once: each vertex's symmetry term is weighted by the
support of each symmetry, and regions between the supports blend through the shape term.

Exact symmetry needs the mirror image of every vertex on the surface. When the two sides of the
mesh do not have matching vertices, a curved surface cannot reach it without flattening or sliding
its vertices: the constrained steps stop near the sagitta of the triangles. While the error is
still above `target_symmetry_error`, an isometric refinement follows on meshes of at most 50,000
vertices (finer meshes have smaller sagittas): each step moves the vertices (all three coordinates) to minimize the linearized
\f[ \frac{\rho}{n D^2}\sum_{T,i} w_{i,T}\,\|r_i + L\,d_i - \textstyle\sum_c b_c d_c\|_{M_i}^2
    + \frac{1}{|E|}\sum_{(i,j)} \Big(\frac{l_{ij} - l^0_{ij} + u_{ij}\cdot(d_i - d_j)}{l^0_{ij}}\Big)^2
      + \eta\,\frac{|d_i - d_j|^2}{(l^0_{ij})^2}
    + \frac{\mu}{n h^2}\sum_i |d_i|^2, \f]
where \f$d\f$ are the displacements, \f$r_i = T^{-1}(y_i) - p_i\f$ the mirror residual of vertex
\f$i\f$, \f$L\f$ the linear part of \f$T^{-1}\f$, \f$b_c, d_c\f$ the barycentric coordinates and
displacements of the corners of the mirror face, \f$l, l^0, u\f$ the current and input lengths of
an edge and its direction, \f$\eta = 0.01\f$, \f$\mu = 10^{-4}\f$, and
\f$\|v\|_{M_i}^2 = (n\cdot v)^2 + \tau_i\,|v - (n\cdot v)\,n|^2\f$ with \f$n\f$ the normal of the
mirror face and \f$\tau_i = \min(1, \max(0.1, |r_i|/h))\f$ (near the surface mostly the distance to
its tangent plane, so that mirror points can slide; from one mean edge length on, the distance to
the point): the symmetry error against the relative change of the edge lengths, the distortion
itself. Bending and rigid motions of parts
leave edge lengths unchanged, so the two sides are fitted to each other where bending costs least.
\f$\rho\f$ starts at \f$10^3\f$ and grows by \f$\sqrt{10}\f$ per step (at most 14 steps,
\f$\rho \le 10^6\f$); the refinement stops at the target, and the positions of the smallest
error are kept: a smaller target gives a more symmetric and more distorted result (see the user
manual, \ref SMSYSymmetrizationLimits). Larger meshes, while their error is above the target,
take further constrained steps instead (at most 40): their weight starts at \f$10^4\f$ and grows
tenfold, up to \f$10^5\f$, whenever a step gains less than 10% (an exact closest-point search is
compared with the previous exact one); between exact searches (every fourth step) the mirror
points are followed across adjacent faces. Then up to 4
steps of the refinement, at its largest weight, move only the vertices whose mirror distance is
above twice the target, the corners of their mirror faces and one ring around them. The result does not
depend on the number of threads.

\tparam TriangleMesh a model of `FaceListGraph` (for example `CGAL::Surface_mesh` or
        `CGAL::Polyhedron_3`)
\tparam SymmetryRange a range of `Symmetry<K>`, `K` the kernel of the points
\tparam NamedParameters a sequence of named parameters

\param tm the mesh (non-empty, triangles only, finite coordinates, positive area, consistently
       oriented); its vertices are moved
\param symmetries the symmetries to enforce (at least one): for instance the first one found by
       `detect_reflective_symmetries()`, or `reflective_symmetry(plane)`
\param np an optional sequence of named parameters among the ones listed below

\cgalNamedParamsBegin
  \cgalParamNBegin{number_of_iterations}
    \cgalParamDescription{the number of steps of \f$\alpha\f$ on the coarsest level, the first
      constrained step included}
    \cgalParamType{`std::size_t`}
    \cgalParamDefault{`Symmetrize_options::number_of_iterations`}
    \cgalParamExtra{must be at least 1}
  \cgalParamNEnd
  \cgalParamNBegin{shape_weight}
    \cgalParamDescription{the factor \f$s\f$ of the shape term}
    \cgalParamType{`double`}
    \cgalParamDefault{`Symmetrize_options::shape_weight`}
    \cgalParamExtra{must be positive}
  \cgalParamNEnd
  \cgalParamNBegin{displacement_weight}
    \cgalParamDescription{the weight \f$\beta\f$ of the displacement term}
    \cgalParamType{`double`}
    \cgalParamDefault{`Symmetrize_options::displacement_weight`}
    \cgalParamExtra{must be positive}
  \cgalParamNEnd
  \cgalParamNBegin{number_of_levels}
    \cgalParamDescription{the number of levels of the multiresolution hierarchy, the input
      included (0: as many as needed to reach `coarsest_level_size`; 1: no coarser level)}
    \cgalParamType{`std::size_t`}
    \cgalParamDefault{`Symmetrize_options::number_of_levels`}
  \cgalParamNEnd
  \cgalParamNBegin{coarsest_level_size}
    \cgalParamDescription{the smallest number of vertices of a coarser level (a level is made when it
      has at least half as many)}
    \cgalParamType{`std::size_t`}
    \cgalParamDefault{`Symmetrize_options::coarsest_level_size`}
  \cgalParamNEnd
  \cgalParamNBegin{symmetry_tolerance}
    \cgalParamDescription{the RMS symmetry error, relative to the bounding-box diagonal, at which
      the constrained steps stop (at most 8)}
    \cgalParamType{`double`}
    \cgalParamDefault{`Symmetrize_options::symmetry_tolerance`}
    \cgalParamExtra{must be positive}
  \cgalParamNEnd
  \cgalParamNBegin{target_symmetry_error}
    \cgalParamDescription{the RMS symmetry error, relative to the bounding-box diagonal, at which
      the isometric refinement stops (0: no refinement)}
    \cgalParamType{`double`}
    \cgalParamDefault{`Symmetrize_options::target_symmetry_error`}
    \cgalParamExtra{must not be negative}
  \cgalParamNEnd
  \cgalParamNBegin{final_symmetry_weight}
    \cgalParamDescription{\f$\alpha / (1 - \alpha)\f$ in the constrained steps: how strongly the
      vertices are drawn to the midpoints of themselves and their mirror images against the shape
      term. Larger values give a smaller symmetry error and more distortion on meshes whose two
      sides do not have matching vertices (the cow without the isometric refinement: 100 gives an
      error of 3.9e-4 and a distortion of 0.013; 10^4 gives 4.3e-5 and 0.026)}
    \cgalParamType{`double`}
    \cgalParamDefault{`Symmetrize_options::final_symmetry_weight`}
    \cgalParamExtra{must be positive}
  \cgalParamNEnd
  \cgalParamNBegin{support_weighting}
    \cgalParamDescription{whether the symmetry term of each vertex is weighted by the support of
      each symmetry (the area-weighted mean of `Symmetry::support` over its faces; a symmetry
      with an empty support weighs 1 everywhere). Otherwise every symmetry applies to the whole
      mesh}
    \cgalParamType{`bool`}
    \cgalParamDefault{`Symmetrize_options::support_weighting`: when empty, `true` if several symmetries
      are given, `false` for one}
  \cgalParamNEnd
  \cgalParamNBegin{number_of_threads}
    \cgalParamDescription{the largest number of threads used (with TBB); 0 for all cores}
    \cgalParamType{`std::size_t`}
    \cgalParamDefault{`Symmetrize_options::number_of_threads`}
  \cgalParamNEnd
  \cgalParamNBegin{progress_callback}
    \cgalParamDescription{called with the fraction of the work done, in \f$[0, 1]\f$}
    \cgalParamType{a callable convertible to `std::function<void(double)>`}
    \cgalParamDefault{`Symmetrize_options::progress_callback`}
  \cgalParamNEnd
  \cgalParamNBegin{vertex_point_map}
    \cgalParamDescription{a property map associating points to the vertices of `tm`; read for
      the input and written with the result}
    \cgalParamType{a class model of `ReadWritePropertyMap` with `boost::graph_traits<TriangleMesh>::%vertex_descriptor`
      as key type and a point type of a \cgal kernel as value type}
    \cgalParamDefault{`boost::get(CGAL::vertex_point, tm)`}
  \cgalParamNEnd
  \cgalParamNBegin{geom_traits}
    \cgalParamDescription{an instance of a geometric traits class}
    \cgalParamType{a class model of `Kernel`}
    \cgalParamDefault{a \cgal Kernel deduced from the point type, using `CGAL::Kernel_traits`}
  \cgalParamNEnd
\cgalNamedParamsEnd

\returns the symmetrized positions, the asymmetric residuals, the symmetric map, the symmetry
         error per solve, before and after, and the distortion

\throws CGAL::Shape_analysis::Bad_input if the mesh has no faces, a face that is not a triangle, a
        coordinate that is not finite or no area; if `symmetries` is empty, a symmetry is not
        invertible or not finite (a degenerate plane), a reflection's plane leaves the whole
        mesh on one side, or its support does not have one value per face; or if a parameter is out of its range. The mesh is then left unchanged.

\sa `detect_reflective_symmetries()`, `enhance_symmetry()`, `restore_asymmetry()`,
    `transfer_vertex_attribute()`
*/
template <typename TriangleMesh, typename SymmetryRange,
          typename NamedParameters = parameters::Default_named_parameters>
Symmetrization_result<typename CGAL::GetGeomTraits<TriangleMesh, NamedParameters>::type>
symmetrize(TriangleMesh& tm, const SymmetryRange& symmetries,
           const NamedParameters& np = parameters::default_values())
{
  typedef typename CGAL::GetGeomTraits<TriangleMesh, NamedParameters>::type Kernel;
  typedef typename Kernel::FT FT;
  const std::string who = "symmetrize";

  const Symmetrize_options o = symmetrize_options(np);
  const std::size_t n_symmetries = std::size_t(std::distance(std::begin(symmetries), std::end(symmetries)));
  internal::check_options(o, who);
  if(n_symmetries == 0)
    throw Bad_input(who + ": no symmetry given");

  const internal::Mesh_arrays<TriangleMesh> mesh = internal::read_mesh_np(tm, np, who);
  internal::require_area(mesh.surface, who);
  const bool weighting = o.support_weighting.value_or(n_symmetries > 1);
  internal::Symmetrizer solver(mesh.surface,
                               internal::solver_symmetries<Kernel>(mesh.surface, symmetries, weighting, who), o);
  const internal::Symmetrization_output out = solver.run();

  Symmetrization_result<Kernel> r;
  const std::size_t n = mesh.vertices.size();
  r.symmetric_points.reserve(n);
  r.residuals.reserve(n);
  for(std::size_t i = 0; i < n; ++i) {
    const internal::Vector_3d& p = out.points[i];
    const internal::Vector_3d d = mesh.surface.points[i] - p;
    r.symmetric_points.emplace_back(FT(p.x), FT(p.y), FT(p.z));
    r.residuals.emplace_back(FT(d.x), FT(d.y), FT(d.z));
  }
  for(const auto& per_symmetry : out.mirrors) {
    std::vector<Mirror_point> m;
    m.reserve(per_symmetry.size());
    for(const internal::Mirror& x : per_symmetry)
      m.push_back(internal::public_mirror(x));
    r.symmetric_map.push_back(std::move(m));
  }
  for(const internal::Iteration_record& it : out.iterations) {
    r.symmetry_errors.push_back(it.symmetry_error);
    r.iteration_levels.push_back(it.level);
    r.iteration_alphas.push_back(it.alpha);
  }
  r.symmetry_error_before = out.error_before;
  r.symmetry_error_after = out.error_after;
  r.distortion = out.distortion;
  r.level_sizes = out.level_sizes;

  auto vpm = internal::writable_vpm(tm, np);
  typedef typename boost::property_traits<decltype(vpm)>::value_type Point;
  for(std::size_t i = 0; i < n; ++i) {
    const internal::Vector_3d& p = out.points[i];
    put(vpm, mesh.vertices[i], Point(p.x, p.y, p.z));
  }
  if(o.progress_callback)
    o.progress_callback(1.0);
  return r;
}

/*!
\ingroup PkgSurfaceMeshSymmetrizationRef

Sets the vertices of a symmetrized mesh between, or beyond, its symmetric and its input shape:
vertex \f$i\f$ is placed at \f$s_i + (1 - t)\,r_i\f$, with \f$s_i\f$ the symmetrized position and
\f$r_i\f$ the asymmetric residual of `result`. \f$t = 1\f$ gives the symmetric shape, \f$t = 0\f$
the input, \f$0 < t < 1\f$ a shape in between, \f$t < 0\f$ exaggerates the asymmetries and
\f$t > 1\f$ mirrors them. This is a linear blend of stored vectors: it runs in real time for any
\f$t\f$ once the mesh is symmetrized.

\tparam TriangleMesh a model of `FaceListGraph`
\tparam Kernel the kernel of `result`
\tparam NamedParameters a sequence of named parameters

\param tm the mesh that was symmetrized (same vertices)
\param result what `symmetrize()` returned for it
\param amount \f$t\f$
\param np an optional sequence of named parameters: `vertex_point_map` (written)

\throws CGAL::Shape_analysis::Bad_input if `amount` is not finite or `result` does not have one
        position per vertex of `tm`
*/
template <typename TriangleMesh, typename Kernel,
          typename NamedParameters = parameters::Default_named_parameters>
void enhance_symmetry(TriangleMesh& tm, const Symmetrization_result<Kernel>& result, double amount,
                      const NamedParameters& np = parameters::default_values())
{
  const std::string who = "enhance_symmetry";
  if(!std::isfinite(amount))
    throw Bad_input(who + ": the amount is not a finite number");
  const std::size_t n = std::size_t(std::distance(vertices(tm).begin(), vertices(tm).end()));
  if(result.symmetric_points.size() != n || result.residuals.size() != n)
    throw Bad_input(who + ": the result has " + std::to_string(result.symmetric_points.size()) +
                    " positions for a mesh of " + std::to_string(n) + " vertices");
  auto vpm = internal::writable_vpm(tm, np);
  typedef typename boost::property_traits<decltype(vpm)>::value_type Point;
  const typename Kernel::FT f(1 - amount);
  std::size_t i = 0;
  for(auto v : vertices(tm)) {
    const typename Kernel::Point_3 p = result.symmetric_points[i] + result.residuals[i] * f;
    put(vpm, v, Point(p.x(), p.y(), p.z()));
    ++i;
  }
}

/*!
\ingroup PkgSurfaceMeshSymmetrizationRef

Gives a symmetrized mesh its input shape back: every vertex is set to its symmetrized position
plus its asymmetric residual, which is the input position (up to one rounding of each
coordinate). The same as `enhance_symmetry(tm, result, 0, np)`.

\tparam TriangleMesh a model of `FaceListGraph`
\tparam Kernel the kernel of `result`
\tparam NamedParameters a sequence of named parameters

\param tm the mesh that was symmetrized (same vertices)
\param result what `symmetrize()` returned for it
\param np an optional sequence of named parameters: `vertex_point_map` (written)

\throws CGAL::Shape_analysis::Bad_input if `result` does not have one position per vertex of `tm`
*/
template <typename TriangleMesh, typename Kernel,
          typename NamedParameters = parameters::Default_named_parameters>
void restore_asymmetry(TriangleMesh& tm, const Symmetrization_result<Kernel>& result,
                       const NamedParameters& np = parameters::default_values())
{
  enhance_symmetry(tm, result, 0.0, np);
}

} // namespace Surface_mesh_symmetrization
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_SYMMETRIZATION_SYMMETRIZE_H
