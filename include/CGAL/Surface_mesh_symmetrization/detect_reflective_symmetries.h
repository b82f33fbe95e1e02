// Copyright (c) 2026 CGAL Global Shape Analysis contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_SURFACE_MESH_SYMMETRIZATION_DETECT_REFLECTIVE_SYMMETRIES_H
#define CGAL_SURFACE_MESH_SYMMETRIZATION_DETECT_REFLECTIVE_SYMMETRIES_H

/// \file detect_reflective_symmetries.h

#include <CGAL/Surface_mesh_symmetrization/Detect_reflective_symmetries_options.h>
#include <CGAL/Surface_mesh_symmetrization/Symmetry.h>
#include <CGAL/Surface_mesh_symmetrization/internal/Plane_detection.h>

#include <CGAL/boost/graph/named_params_helper.h>

#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

namespace CGAL {
namespace Surface_mesh_symmetrization {

/// \cond SKIP_IN_MANUAL
namespace internal {

template <typename Kernel>
Symmetry<Kernel> symmetry_of(const Detected_plane& d)
{
  Symmetry<Kernel> s = reflective_symmetry<Kernel>(
    typename Kernel::Plane_3(typename Kernel::FT(d.plane.normal.x), typename Kernel::FT(d.plane.normal.y),
                             typename Kernel::FT(d.plane.normal.z), typename Kernel::FT(-d.plane.offset)));
  s.score = d.score;
  s.support_fraction = d.support_fraction;
  s.support = d.support;
  return s;
}

} // namespace internal
/// \endcond

/*!
\ingroup PkgSurfaceMeshSymmetrizationRef

Detects the planar reflective symmetries of a triangle mesh, global and partial, in any pose
(\cgalCite{Golovinskiy2010}, section 2.3; candidate planes voted in the manner of
\cgalCite{Mitra2006} and \cgalCite{Podolak2006}).

1. `number_of_samples` points are drawn uniformly on the surface, with the normals of their faces.
2. Candidate planes: the three principal planes of the samples through their centroid, and the
   peaks of the votes of sample pairs: a pair whose normals are mirror images of each other
   (within 20 degrees) across its bisector plane votes for that plane. Votes are counted in bins
   of normal direction (about 4 degrees) and offset (2% of the bounding-box diagonal); the
   strongest bins, away from each other, are sharpened by mean shift over the votes around them.
3. Each candidate is refined to minimize the symmetry distance: every sample is reflected and
   paired with the closest surface point whose normal agrees with the reflected normal (a
   bounding-volume hierarchy of the faces); Gauss-Newton steps on the plane's normal and offset minimize the robustly
   weighted (Tukey) distances of the reflected samples to the tangent planes of their partners,
   with a reach that shrinks from 15% to 2% of the diagonal. On an open mesh the border takes part
   too (a quarter as many border points as samples, along the border edges): the reflection of a
   border point is drawn to the nearest border point, across the border within its face, since a
   symmetry maps the border onto itself; this pins planes that the surface leaves free (a flat
   region is its own mirror image under every plane perpendicular to it). All candidates are first refined on
   300 samples; the best distinct ones continue on every sample. When at least 90% of the mesh's
   vertices then have a mirror vertex (the nearest vertex to their reflection, mutually, within a
   tenth of the mean edge length), the plane is also fitted to those pairs (normal along their
   differences, through their midpoints), and that plane is kept if it scores no worse: a mesh
   whose vertices are exact mirror images (a remeshed one) gets its plane to rounding error.
4. The refined planes are scored (see `Symmetry::score`), planes closer than 2 degrees and 1% of
   the diagonal are merged, and the support of each plane is computed (see
   `Symmetry::support`). Planes whose support fraction is below `minimum_support` are dropped.

Results are ranked by increasing score, best first: the global symmetries (support close to 1)
come first, partial ones after. A mesh of perfect symmetry gives its plane to within a small
fraction of a degree. The result depends only on the shape and `random_seed`, not on the pose of
the mesh, and is the same for any number of threads.

The surface should be consistently oriented (normals of a component all pointing outside, or all
inside); it may be open or made of several components.

\tparam TriangleMesh a model of `FaceListGraph` (for example `CGAL::Surface_mesh` or
        `CGAL::Polyhedron_3`)
\tparam OutputIterator an output iterator accepting `Symmetry<K>`, `K` the kernel of the mesh's
        points (see `geom_traits`)
\tparam NamedParameters a sequence of named parameters

\param tm the mesh: non-empty, triangles only, finite coordinates, positive area
\param out receives the symmetries found, best first
\param np an optional sequence of named parameters among the ones listed below

\cgalNamedParamsBegin
  \cgalParamNBegin{number_of_samples}
    \cgalParamDescription{the number of points sampled on the surface (votes come from every pair
      of them; the refinement and the score use them too)}
    \cgalParamType{`std::size_t`}
    \cgalParamDefault{`Detect_reflective_symmetries_options::number_of_samples`}
    \cgalParamExtra{must be at least 20}
  \cgalParamNEnd
  \cgalParamNBegin{maximum_number_of_symmetries}
    \cgalParamDescription{the largest number of symmetries reported}
    \cgalParamType{`std::size_t`}
    \cgalParamDefault{`Detect_reflective_symmetries_options::maximum_number_of_symmetries`}
  \cgalParamNEnd
  \cgalParamNBegin{minimum_support}
    \cgalParamDescription{the smallest support fraction of a reported symmetry}
    \cgalParamType{`double`}
    \cgalParamDefault{`Detect_reflective_symmetries_options::minimum_support`}
    \cgalParamExtra{must be in \f$[0, 1]\f$}
  \cgalParamNEnd
  \cgalParamNBegin{support_tolerance}
    \cgalParamDescription{the tolerance \f$\sigma\f$ of the support weights, as a fraction of the
      bounding-box diagonal}
    \cgalParamType{`double`}
    \cgalParamDefault{`Detect_reflective_symmetries_options::support_tolerance`}
    \cgalParamExtra{must be positive}
  \cgalParamNEnd
  \cgalParamNBegin{random_seed}
    \cgalParamDescription{the seed of the random sample points}
    \cgalParamType{`unsigned int`}
    \cgalParamDefault{`Detect_reflective_symmetries_options::random_seed`}
  \cgalParamNEnd
  \cgalParamNBegin{number_of_threads}
    \cgalParamDescription{the largest number of threads used (with TBB); 0 for all cores. The
      result does not depend on it}
    \cgalParamType{`std::size_t`}
    \cgalParamDefault{`Detect_reflective_symmetries_options::number_of_threads`}
  \cgalParamNEnd
  \cgalParamNBegin{vertex_point_map}
    \cgalParamDescription{a property map associating points to the vertices of `tm`}
    \cgalParamType{a class model of `ReadablePropertyMap` with `boost::graph_traits<TriangleMesh>::%vertex_descriptor`
      as key type and a point type of a \cgal kernel as value type}
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

\sa `symmetrize()`
*/
template <typename TriangleMesh, typename OutputIterator,
          typename NamedParameters = parameters::Default_named_parameters>
OutputIterator detect_reflective_symmetries(const TriangleMesh& tm, OutputIterator out,
                                            const NamedParameters& np = parameters::default_values())
{
  typedef typename CGAL::GetGeomTraits<TriangleMesh, NamedParameters>::type Kernel;
  const std::string who = "detect_reflective_symmetries";

  const Detect_reflective_symmetries_options o = detect_reflective_symmetries_options(np);
  const internal::Mesh_arrays<TriangleMesh> mesh = internal::detection_surface(tm, np, o, who);
  for(const internal::Detected_plane& d : internal::detect_planes(mesh.surface, o))
    *out++ = internal::symmetry_of<Kernel>(d);
  return out;
}

} // namespace Surface_mesh_symmetrization
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_SYMMETRIZATION_DETECT_REFLECTIVE_SYMMETRIES_H
