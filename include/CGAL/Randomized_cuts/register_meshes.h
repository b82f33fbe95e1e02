// Copyright (c) 2026 CGAL Global Shape Analysis contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_RANDOMIZED_CUTS_REGISTER_MESHES_H
#define CGAL_RANDOMIZED_CUTS_REGISTER_MESHES_H

/// \file register_meshes.h

#include <CGAL/Randomized_cuts/partition_function.h>
#include <CGAL/Shape_analysis/Bad_input.h>
#include <CGAL/Shape_analysis/parameters.h>
#include <CGAL/Shape_analysis/internal/Dual_graph.h>
#include <CGAL/Shape_analysis/internal/Mesh_checks.h>
#include <CGAL/Shape_analysis/internal/Random.h>
#include <CGAL/Shape_analysis/internal/Similarity_alignment.h>
#include <CGAL/Shape_analysis/internal/Triangle_sampling.h>

#include <CGAL/Aff_transformation_3.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/named_params_helper.h>

#include <boost/property_map/property_map.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <functional>
#include <limits>
#include <map>
#include <string>
#include <vector>

namespace CGAL {
namespace Randomized_cuts {

/*!
\ingroup PkgRandomizedCutsRef

The outcome of `register_meshes()`: the similarity transform that maps the source mesh onto the
target mesh, and how well it fits.

\tparam Kernel the \cgal kernel of the meshes' points
*/
template <typename Kernel>
struct Registration_result
{
  /// The similarity transform \f$x \mapsto sRx + t\f$ (rotation \f$R\f$, uniform scale \f$s\f$,
  /// translation \f$t\f$) that maps the points of the source mesh onto the target mesh.
  CGAL::Aff_transformation_3<Kernel> transformation;
  /// The rotation \f$R\f$, row by row (a proper rotation: orthonormal, determinant +1).
  std::array<std::array<double, 3>, 3> rotation{{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}};
  /// The uniform scale \f$s > 0\f$.
  double scale = 1;
  /// The translation \f$t\f$.
  std::array<double, 3> translation{{0, 0, 0}};
  /// The trimmed, symmetric RMS distance after alignment, in the target's units: the distance of
  /// every sample point of the transformed source to the target surface and of every target sample
  /// point to the transformed source surface; the smallest `overlap` fraction of the distances of
  /// each direction is kept. 0 for an exact copy; about the noise level for a noisy copy.
  double rms_distance = 0;
  /// The same distance for the identity transform (the meshes as given), for comparison.
  double initial_rms_distance = 0;
  /// The number of restarts tried (24: every proper mapping of the source's principal axes onto
  /// the target's principal axes).
  std::size_t number_of_restarts = 0;
  /// The index, in `[0, number_of_restarts)`, of the restart that gave the result (0: the
  /// principal axes mapped onto each other in order, with their signs as computed), or
  /// `number_of_restarts` when no restart did better than the meshes as given (the result is then
  /// the identity).
  std::size_t best_restart = 0;
  /// The number of ICP iterations of the best restart, every stage.
  std::size_t number_of_iterations = 0;
  /// Whether the last ICP stage stopped because the RMS distance no longer decreased (rather than
  /// after its largest number of iterations).
  bool converged = false;
  /// The number of sample points on each mesh.
  std::size_t number_of_points = 0;
};

/*!
\ingroup PkgRandomizedCutsRef

The options of `register_meshes()`: those of the partition function of each mesh
(`Partition_function_options`, whose `random_seed`, `number_of_threads` and `progress_callback`
also serve the registration) and those of the registration; each member is the named parameter of
the same name, initialized to its default. The `shape_analysis register` command takes its
defaults from here.
*/
struct Register_meshes_options : Partition_function_options
{
  /// The defaults of `Partition_function_options`, except `number_of_samples`: the registration
  /// only needs to know roughly where the part boundaries are, and samples fewer segmentations;
  /// and `sampling_method`: `MIN_CUT`, whose few strong boundaries weigh the sample points.
  Register_meshes_options()
  {
    number_of_samples = 100;
    sampling_method = MIN_CUT;
  }

  /// the number of points sampled on each mesh (at least 10)
  std::size_t number_of_points = 2000;
  /// the largest number of ICP iterations of a restart between all sample points (0: the initial
  /// alignments of the principal frames only)
  std::size_t number_of_iterations = 50;
  /// the fraction of the closest-point pairs of each direction kept by ICP and by the RMS
  /// distance (in \f$(0, 1]\f$; 1 keeps every pair)
  double overlap = 0.9;
  /// whether the sample points are concentrated on part boundaries with the partition function;
  /// otherwise they are uniform by area (and no partition function is computed)
  bool partition_weighting = true;
};

/*!
\ingroup PkgRandomizedCutsRef

The options that `register_meshes()` reads from the named parameters `np` (its `np_source`): the
value of each named parameter given, the default of `Register_meshes_options` for the others. The
values are not checked here; `register_meshes()` checks them. Named parameters that are not
options (property maps, traits) are ignored.

\tparam NamedParameters a sequence of named parameters
\param np the named parameters, as given to the function whose options these are
\returns the options, each from its named parameter or its default
*/
template <typename NamedParameters = parameters::Default_named_parameters>
Register_meshes_options register_meshes_options(const NamedParameters& np = parameters::default_values())
{
  using CGAL::Shape_analysis::internal::parameter_value;
  namespace snp = CGAL::Shape_analysis::internal_np;
  Register_meshes_options o;
  internal::read_partition_function_options(np, o);
  o.number_of_points = parameter_value(np, snp::number_of_points_tag, o.number_of_points);
  o.number_of_iterations = parameter_value(np, CGAL::internal_np::number_of_iterations, o.number_of_iterations);
  o.overlap = parameter_value(np, CGAL::internal_np::overlap, o.overlap);
  o.partition_weighting = parameter_value(np, snp::partition_weighting_tag, o.partition_weighting);
  return o;
}

/// \cond SKIP_IN_MANUAL
namespace internal {

namespace SAI = CGAL::Shape_analysis::internal;

// The triangles of a mesh as plain points, in the order of faces(tm), with an emphasis per
// triangle (1 each unless partition values are given).
struct Surface_triangles
{
  std::vector<std::array<SAI::Vector_3d, 3>> corners;
  std::vector<double> areas;
  std::vector<double> emphasis;
  double total_area = 0;
};

// Sampling weights are area * (floor + face value / mean face value): `floor` keeps a share of
// the samples spread uniformly, so that regions without part boundaries are still represented.
constexpr double partition_weight_floor = 0.5;

template <typename TriangleMesh, typename VertexPointMap, typename ToVector, typename EdgeValue>
Surface_triangles surface_triangles(const TriangleMesh& tm, VertexPointMap vpm,
                                    const ToVector& to_vector, const EdgeValue* edge_value)
{
  Surface_triangles s;
  const std::size_t n = num_faces(tm);
  s.corners.reserve(n);
  s.areas.reserve(n);
  std::vector<double> face_value;
  face_value.reserve(n);
  for(auto f : faces(tm)) {
    std::array<SAI::Vector_3d, 3> c;
    double value = 0;
    int i = 0;
    for(auto h : CGAL::halfedges_around_face(halfedge(f, tm), tm)) {
      c[std::size_t(i++)] = to_vector(get(vpm, target(h, tm)));
      if(edge_value != nullptr)
        value += edge_value->at(edge(h, tm));
    }
    const double area = 0.5 * SAI::cross(c[1] - c[0], c[2] - c[0]).length();
    s.corners.push_back(c);
    s.areas.push_back(std::isfinite(area) ? area : 0.0);
    face_value.push_back(value / 3.0);
    s.total_area += s.areas.back();
  }
  double mean = 0;
  for(std::size_t f = 0; f < n; ++f)
    mean += s.areas[f] * face_value[f];
  mean = s.total_area > 0 ? mean / s.total_area : 0.0;
  s.emphasis.assign(n, 1.0);
  if(edge_value != nullptr && mean > 0)
    for(std::size_t f = 0; f < n; ++f)
      s.emphasis[f] = partition_weight_floor + face_value[f] / mean;
  return s;
}

// `n` points drawn independently on the triangles, each triangle with probability proportional to
// its area times its emphasis, uniformly inside it.
inline std::vector<SAI::Vector_3d> sample_triangles(const Surface_triangles& s, std::size_t n,
                                                    SAI::Random_stream& rng)
{
  std::vector<double> weights(s.areas.size());
  for(std::size_t f = 0; f < s.areas.size(); ++f)
    weights[f] = s.areas[f] * s.emphasis[f]; // zero exactly for zero-area triangles
  const SAI::Weighted_triangle_sampler sampler(weights);
  std::vector<SAI::Vector_3d> points;
  points.reserve(n);
  for(std::size_t i = 0; i < n; ++i)
    points.push_back(SAI::Weighted_triangle_sampler::point_in(s.corners[sampler.triangle(rng)], rng));
  return points;
}

// Checks a mesh for registration and returns its triangles (with partition emphasis, the partition
// function sampled with `partition`, when it is not null).
template <typename TriangleMesh, typename MeshNP>
Surface_triangles registration_triangles(const TriangleMesh& tm, const MeshNP& mesh_np,
                                         const Sampling_options* partition, const std::string& who)
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  typedef boost::graph_traits<TriangleMesh> GT;
  typedef typename GT::edge_descriptor edge_descriptor;
  auto vpm = choose_parameter(get_parameter(mesh_np, CGAL::internal_np::vertex_point),
                              get_const_property_map(CGAL::vertex_point, tm));
  typedef typename CGAL::GetGeomTraits<TriangleMesh, MeshNP>::type Geom_traits;
  const SAI::Point_to_vector<Geom_traits> to_vector{
    choose_parameter<Geom_traits>(get_parameter(mesh_np, CGAL::internal_np::geom_traits))};
  SAI::check_triangle_mesh(tm, vpm, to_vector, who);
  std::map<edge_descriptor, double> values;
  if(partition != nullptr) {
    try {
      partition_function_impl(tm, boost::associative_property_map<std::map<edge_descriptor, double>>(values),
                              mesh_np, *partition);
    } catch(const Bad_input& e) {
      throw Bad_input(who + ": " + e.what());
    }
  }
  const Surface_triangles s =
    surface_triangles(tm, vpm, to_vector, partition != nullptr ? &values : nullptr);
  if(!(s.total_area > 0) || !std::isfinite(s.total_area))
    throw Bad_input(who + ": the mesh has no area");
  return s;
}

// `n` points sampled on the triangles of a mesh with the registration's stream `stream` (0: the
// source, 1: the target). Two streams of their own, apart from the partition function's (seed,
// sample) streams.
inline std::vector<SAI::Vector_3d> registration_points(const Surface_triangles& s, std::size_t n,
                                                       std::uint64_t seed, std::uint64_t stream)
{
  const std::uint64_t sampling_seed = SAI::Random_stream::mix(seed ^ 0x52656769737465ull);
  SAI::Random_stream rng(sampling_seed, stream);
  return sample_triangles(s, n, rng);
}

// Aligns the source points onto the target points by ICP with scale from the restarts, finished
// against the triangles of the meshes.
inline SAI::Restart_alignment_result
align_registration_points(const Surface_triangles& source_triangles, const std::vector<SAI::Vector_3d>& source_points,
                          const Surface_triangles& target_triangles, const std::vector<SAI::Vector_3d>& target_points,
                          std::size_t iterations, double overlap, std::size_t threads)
{
  SAI::Restart_alignment_options o;
  o.icp.max_iterations = iterations;
  o.icp.keep_fraction = overlap;
  o.number_of_threads = threads;
  const SAI::Closest_surface_point source_surface(source_triangles.corners),
    target_surface(target_triangles.corners);
  return SAI::align_with_restarts(source_points, target_points, o, &source_surface, &target_surface);
}

// The result of register_meshes() from the alignment of `n_points` samples of each mesh.
template <typename Kernel>
Registration_result<Kernel> registration_result(const SAI::Restart_alignment_result& a, std::size_t n_points)
{
  typedef typename Kernel::FT FT;
  Registration_result<Kernel> r;
  const SAI::Similarity_3d& t = a.transform;
  for(std::size_t i = 0; i < 3; ++i) {
    for(int j = 0; j < 3; ++j)
      r.rotation[i][std::size_t(j)] = t.rotation[i][j];
    r.translation[i] = t.translation[int(i)];
  }
  const double s = t.scale;
  r.transformation = CGAL::Aff_transformation_3<Kernel>(
    FT(s * t.rotation[0].x), FT(s * t.rotation[0].y), FT(s * t.rotation[0].z), FT(t.translation.x),
    FT(s * t.rotation[1].x), FT(s * t.rotation[1].y), FT(s * t.rotation[1].z), FT(t.translation.y),
    FT(s * t.rotation[2].x), FT(s * t.rotation[2].y), FT(s * t.rotation[2].z), FT(t.translation.z),
    FT(1));
  r.scale = s;
  r.rms_distance = a.rms;
  r.initial_rms_distance = a.initial_rms;
  r.number_of_restarts = a.number_of_restarts;
  r.best_restart = a.best_restart;
  r.number_of_iterations = a.iterations;
  r.converged = a.converged;
  r.number_of_points = n_points;
  return r;
}

} // namespace internal
/// \endcond

/*!
\ingroup PkgRandomizedCutsRef

Registers two triangle meshes: finds the similarity transform (rotation, uniform scale and
translation) that best maps the surface of `source` onto the surface of `target`, with points
sampled preferably along part boundaries (\cgalCite{Golovinskiy2010}, registration with the
partition function).

1. The partition function of each mesh is computed (see `partition_function()`; its named
   parameters are passed on, with fewer `number_of_samples` by default: see
   `Register_meshes_options`).
2. `number_of_points` points are sampled on each surface, each face with a probability
   proportional to its area times \f$(0.5 + v_f/\bar v)\f$, where \f$v_f\f$ is the mean partition
   function value of the face's three edges and \f$\bar v\f$ the area-weighted mean of \f$v_f\f$ over
   the mesh: part boundaries (necks, creases) get more samples than part interiors, while a third of
   the sampling mass stays spread uniformly. With `partition_weighting(false)`, the samples are
   uniform by area and no partition function is computed.
3. The centroids of the two point samples are matched, and their scales by their root mean square
   distances to the centroid; the source's principal axes are mapped onto the target's in each of
   the 24 proper ways (axis permutations and sign changes of determinant +1): 24 restarts.
4. From each restart, ICP with scale: every transformed source point is paired with its closest
   target point and every target point with its closest transformed source point; in each
   direction the closest `overlap` fraction of the pairs is kept; the best similarity of the kept
   pairs (closed form, least squares) is the next transform; until the trimmed RMS distance
   decreases by less than \f$10^{-5}\f$ of itself, or `number_of_iterations` iterations. All 24
   restarts first run at most 20 iterations on the first 400 points of each sample; the 3 best then
   continue with every point.
5. The restart with the smallest trimmed symmetric RMS distance wins (ties: the smaller index).
6. It is finished by at most 20 ICP iterations where the sample points are paired with the
   closest points of the other surface (AABB trees) rather than with the other sample's points, and
   each step minimizes the distances to the tangent planes at those points (a Gauss-Newton step on
   rotation, scale and translation): this removes the sampling noise from the transform (an exact
   copy is recovered to rounding error) and converges in a few iterations. `rms_distance` is
   measured between sample points and surfaces in the same way.
7. The identity (the meshes as given) competes with that result and wins a tie: a mesh registered
   onto itself, or onto a copy already in place, stays where it is, also when it is flat and turns
   within its plane hardly change the trimmed distance.

Sampling draws from random streams derived from `random_seed`, and the restarts are independent:
the result is the same for any number of threads.

\tparam TriangleMesh a model of `FaceListGraph` and `EdgeListGraph` (for example
        `CGAL::Surface_mesh` or `CGAL::Polyhedron_3`)
\tparam NamedParameters1 a sequence of named parameters
\tparam NamedParameters2 a sequence of named parameters

\param source the mesh to move: non-empty, triangles only, finite coordinates, positive area
       (at least two faces with partition weighting)
\param target the mesh to move onto (same requirements)
\param np_source an optional sequence of named parameters among the ones listed below: the
       parameters of the registration, those of `partition_function()` (used for both meshes), and
       the `vertex_point_map`, `geom_traits` and `face_index_map` of `source`
\param np_target an optional sequence of named parameters: the `vertex_point_map`,
       `geom_traits` and `face_index_map` of `target` (other parameters are read from
       `np_source` only)

\cgalNamedParamsBegin
  \cgalParamNBegin{number_of_points}
    \cgalParamDescription{the number of points sampled on each mesh}
    \cgalParamType{`std::size_t`}
    \cgalParamDefault{`Register_meshes_options::number_of_points`}
    \cgalParamExtra{must be at least 10}
  \cgalParamNEnd
  \cgalParamNBegin{number_of_iterations}
    \cgalParamDescription{the largest number of ICP iterations of a restart between all sample
      points (step 4; 0: the initial alignments of the principal frames only)}
    \cgalParamType{`std::size_t`}
    \cgalParamDefault{`Register_meshes_options::number_of_iterations`}
  \cgalParamNEnd
  \cgalParamNBegin{overlap}
    \cgalParamDescription{the fraction of the closest-point pairs of each direction kept by ICP and
      by the RMS distance (the worst pairs are treated as outliers); 1 keeps every pair}
    \cgalParamType{`double`}
    \cgalParamDefault{`Register_meshes_options::overlap`}
    \cgalParamExtra{must be in \f$(0, 1]\f$}
  \cgalParamNEnd
  \cgalParamNBegin{partition_weighting}
    \cgalParamDescription{whether the sample points are concentrated on part boundaries with the
      partition function; otherwise they are uniform by area (and no partition function is
      computed)}
    \cgalParamType{`bool`}
    \cgalParamDefault{`Register_meshes_options::partition_weighting`}
  \cgalParamNEnd
  \cgalParamNBegin{number_of_samples}
    \cgalParamDescription{the number of segmentations sampled for each partition function (by
      default fewer than `partition_function()` samples: see `Register_meshes_options()`)}
    \cgalParamType{`std::size_t`}
    \cgalParamDefault{`Register_meshes_options::number_of_samples`}
  \cgalParamNEnd
  \cgalParamNBegin{random_seed}
    \cgalParamDescription{the seed of the random numbers (partition functions and point samples)}
    \cgalParamType{`unsigned int`}
    \cgalParamDefault{`Partition_function_options::random_seed`}
  \cgalParamNEnd
  \cgalParamNBegin{number_of_threads}
    \cgalParamDescription{the largest number of threads used (with TBB); 0 for all cores. The
      result does not depend on it}
    \cgalParamType{`std::size_t`}
    \cgalParamDefault{`Partition_function_options::number_of_threads`}
  \cgalParamNEnd
  \cgalParamNBegin{progress_callback}
    \cgalParamDescription{called with the fraction of the work done, in \f$[0, 1]\f$: during the
      partition functions (up to 0.8), then after the restarts and after the refinement}
    \cgalParamType{a callable convertible to `std::function<void(double)>`}
    \cgalParamDefault{none}
  \cgalParamNEnd
  \cgalParamNBegin{sampling_method / part_size / number_of_clusters / randomness / convergence_tolerance / score_weighting / concavity_exponent / component_link_distance / component_link_factor}
    \cgalParamDescription{passed on to `partition_function()` for both meshes}
    \cgalParamType{see `partition_function()`}
    \cgalParamDefault{those of `Register_meshes_options` (`sampling_method`: `MIN_CUT`), the others
      as for `partition_function()`}
  \cgalParamNEnd
  \cgalParamNBegin{vertex_point_map}
    \cgalParamDescription{a property map associating points to the vertices of the mesh}
    \cgalParamType{a class model of `ReadablePropertyMap` with `vertex_descriptor` as key and
      a point type of a CGAL kernel as value}
    \cgalParamDefault{`boost::get(CGAL::vertex_point, tm)`}
  \cgalParamNEnd
  \cgalParamNBegin{geom_traits}
    \cgalParamDescription{an instance of a geometric traits class, used to read the coordinates
      (the kernel of `np_source`'s is that of the result)}
    \cgalParamType{a class model of `Kernel`}
    \cgalParamDefault{a \cgal Kernel deduced from the point type, using `CGAL::Kernel_traits`}
  \cgalParamNEnd
  \cgalParamNBegin{face_index_map}
    \cgalParamDescription{a property map associating to each face of the mesh a unique index}
    \cgalParamType{a class model of `ReadablePropertyMap` with `face_descriptor` as key and
      `std::size_t` as value}
    \cgalParamDefault{an automatically indexed internal map}
  \cgalParamNEnd
\cgalNamedParamsEnd

\returns the transform, its scale, the trimmed RMS distance before and after, and which restart
         won

\throws CGAL::Shape_analysis::Bad_input if a mesh has no faces, a face that is not a triangle, a
        coordinate that is not finite or no area (the message says which mesh), if the partition
        function refuses a mesh or a parameter (see `partition_function()`), if
        `number_of_points` is less than 10 or if `overlap` is not in \f$(0, 1]\f$.

\sa `partition_function()`
*/
template <typename TriangleMesh,
          typename NamedParameters1 = parameters::Default_named_parameters,
          typename NamedParameters2 = parameters::Default_named_parameters>
Registration_result<typename CGAL::GetGeomTraits<TriangleMesh, NamedParameters1>::type>
register_meshes(const TriangleMesh& source, const TriangleMesh& target,
                const NamedParameters1& np_source = parameters::default_values(),
                const NamedParameters2& np_target = parameters::default_values())
{
  namespace SAI = CGAL::Shape_analysis::internal;
  typedef typename CGAL::GetGeomTraits<TriangleMesh, NamedParameters1>::type Kernel;
  const std::string who = "register_meshes";

  const Register_meshes_options o = register_meshes_options(np_source);
  const std::size_t n_points = o.number_of_points;
  if(n_points < 10)
    throw Bad_input(who + ": number_of_points must be at least 10");
  if(n_points > std::size_t((std::numeric_limits<std::uint32_t>::max)()))
    throw Bad_input(who + ": number_of_points is too large");
  if(!(o.overlap > 0 && o.overlap <= 1))
    throw Bad_input(who + ": overlap must be in (0, 1]");

  const std::function<void(double)>& progress = o.progress_callback;
  const auto report = [&](double offset, double span) {
    return progress ? std::function<void(double)>([progress, offset, span](double f) {
                        progress(offset + span * f);
                      })
                    : std::function<void(double)>();
  };

  // The partition function of each mesh: the options of `np_source`, the maps of its own
  // parameters, the progress in its share of the work.
  internal::Sampling_options source_partition = internal::sampling_options(o, np_source);
  internal::Sampling_options target_partition = source_partition;
  source_partition.progress_callback = report(0.0, 0.4);
  target_partition.progress_callback = report(0.4, 0.4);
  const bool weighting = o.partition_weighting;

  const internal::Surface_triangles source_triangles = internal::registration_triangles(
    source, np_source, weighting ? &source_partition : nullptr, who + " (source mesh)");
  const internal::Surface_triangles target_triangles = internal::registration_triangles(
    target, np_target, weighting ? &target_partition : nullptr, who + " (target mesh)");

  const std::vector<SAI::Vector_3d> source_points =
    internal::registration_points(source_triangles, n_points, o.random_seed, 0);
  const std::vector<SAI::Vector_3d> target_points =
    internal::registration_points(target_triangles, n_points, o.random_seed, 1);

  const double alignment_start = weighting ? 0.8 : 0.0;
  if(progress)
    progress(alignment_start);
  const SAI::Restart_alignment_result a = internal::align_registration_points(
    source_triangles, source_points, target_triangles, target_points, o.number_of_iterations,
    o.overlap, o.number_of_threads);
  if(progress)
    progress(1.0);

  return internal::registration_result<Kernel>(a, n_points);
}

} // namespace Randomized_cuts
} // namespace CGAL

#endif // CGAL_RANDOMIZED_CUTS_REGISTER_MESHES_H
