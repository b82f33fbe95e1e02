// Copyright (c) 2026 CGAL Global Shape Analysis contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef SHAPE_ANALYSIS_TEST_SYMMETRIZATION_MESH_DISTANCE_CHECKS_H
#define SHAPE_ANALYSIS_TEST_SYMMETRIZATION_MESH_DISTANCE_CHECKS_H

// What the symmetric connectivity tests share: a Surface_mesh's surface as the package reads it,
// and the largest distance from the vertices of one mesh to the surface of another.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Surface_mesh_symmetrization/internal/Surface_index.h>
#include <CGAL/Surface_mesh_symmetrization/internal/Symmetry_geometry.h>

#include <algorithm>
#include <cmath>

namespace symmetric_mesh_checks {

typedef CGAL::Exact_predicates_inexact_constructions_kernel Kernel;
typedef CGAL::Surface_mesh<Kernel::Point_3> Mesh;

inline CGAL::Surface_mesh_symmetrization::internal::Surface surface_of(const Mesh& m)
{
  return CGAL::Surface_mesh_symmetrization::internal::read_mesh(
           m, get(CGAL::vertex_point, m), CGAL::Shape_analysis::internal::Point_to_vector<Kernel>{Kernel()}, "test")
    .surface;
}

// The largest distance from a vertex of `b` to the surface of `a`, relative to a's diagonal.
inline double largest_vertex_distance(const Mesh& a, const Mesh& b)
{
  const auto s = surface_of(a);
  const CGAL::Surface_mesh_symmetrization::internal::Surface_index index(s);
  double d = 0;
  for(auto v : vertices(b)) {
    const Kernel::Point_3& p = b.point(v);
    d = (std::max)(d, std::sqrt(index.closest({p.x(), p.y(), p.z()}).squared_distance));
  }
  return d / s.diagonal();
}

} // namespace symmetric_mesh_checks

#endif // SHAPE_ANALYSIS_TEST_SYMMETRIZATION_MESH_DISTANCE_CHECKS_H
