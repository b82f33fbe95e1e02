// Copyright (c) 2026 CGAL Global Shape Analysis contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_SHAPE_ANALYSIS_INTERNAL_MESH_CHECKS_H
#define CGAL_SHAPE_ANALYSIS_INTERNAL_MESH_CHECKS_H

// Checks shared by the public entry points: what they need of a mesh, with a one-line reason.

#include <CGAL/Shape_analysis/Bad_input.h>

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/number_utils.h>

#include <cmath>
#include <string>

namespace CGAL {
namespace Shape_analysis {
namespace internal {

// Throws Bad_input unless `tm` is a non-empty triangle mesh with finite coordinates.
template <typename TriangleMesh, typename VertexPointMap>
void check_triangle_mesh(const TriangleMesh& tm, VertexPointMap vpm, const std::string& who)
{
  if(faces(tm).empty())
    throw Bad_input(who + ": the mesh has no faces");
  std::size_t index = 0;
  for(auto f : faces(tm)) {
    std::size_t degree = 0;
    for(auto h : CGAL::halfedges_around_face(halfedge(f, tm), tm)) {
      (void)h;
      if(++degree > 3)
        break;
    }
    if(degree != 3)
      throw Bad_input(who + ": face " + std::to_string(index) +
                      " is not a triangle; triangulate the mesh first");
    ++index;
  }
  index = 0;
  for(auto v : vertices(tm)) {
    const auto& p = get(vpm, v);
    if(!std::isfinite(CGAL::to_double(p.x())) || !std::isfinite(CGAL::to_double(p.y())) ||
       !std::isfinite(CGAL::to_double(p.z())))
      throw Bad_input(who + ": vertex " + std::to_string(index) +
                      " has a coordinate that is not a finite number");
    ++index;
  }
}

} // namespace internal
} // namespace Shape_analysis
} // namespace CGAL

#endif // CGAL_SHAPE_ANALYSIS_INTERNAL_MESH_CHECKS_H
