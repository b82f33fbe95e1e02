// Copyright (c) 2026 CGAL Global Shape Analysis contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_RANDOMIZED_CUTS_INTERNAL_DEFORMATION_CONSTRAINTS_H
#define CGAL_RANDOMIZED_CUTS_INTERNAL_DEFORMATION_CONSTRAINTS_H

// The checks of the input of partition_aware_deformation() and its constraints: the roles of the
// vertices (free, control, fixed), the region of interest and its size.

#include <CGAL/Shape_analysis/Bad_input.h>
#include <CGAL/Shape_analysis/internal/Union_find.h>
#include <CGAL/Shape_analysis/internal/Vector_3d.h>

#include <CGAL/boost/graph/iterator.h>

#include <boost/graph/graph_traits.hpp>
#include <boost/property_map/property_map.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

namespace CGAL {
namespace Randomized_cuts {
namespace internal {

// Throws unless the vertex indices are distinct numbers under num_vertices and every value is in
// [0, 1]; returns the largest value.
template <typename TriangleMesh, typename VertexIndexMap, typename EdgeValueMap>
double check_deformation_input(const TriangleMesh& tm, VertexIndexMap vim, EdgeValueMap values,
                               const std::string& who)
{
  using CGAL::Shape_analysis::Bad_input;
  const std::size_t n = static_cast<std::size_t>(num_vertices(tm));
  std::vector<char> seen(n, 0);
  for(auto v : vertices(tm)) {
    const std::size_t i = static_cast<std::size_t>(get(vim, v));
    if(i >= n || seen[i])
      throw Bad_input(who + ": the vertex indices are not distinct numbers under num_vertices");
    seen[i] = 1;
  }
  double largest_value = 0;
  for(auto e : edges(tm)) {
    const double v = static_cast<double>(get(values, e));
    if(!(v >= 0 && v <= 1))
      throw Bad_input(who + ": a partition-function value is not in [0, 1]");
    largest_value = (std::max)(largest_value, v);
  }
  return largest_value;
}

// The targets as points of the mesh (`to_vector` gives their coordinates); throws if one is not
// finite or if their number is not `number_of_controls`.
template <typename Point, typename TargetPointRange, typename ToVector>
std::vector<Point> deformation_targets(const TargetPointRange& targets, const ToVector& to_vector,
                                       std::size_t number_of_controls, const std::string& who)
{
  using CGAL::Shape_analysis::Bad_input;
  using CGAL::Shape_analysis::internal::Vector_3d;
  std::vector<Point> target_points;
  for(const auto& p : targets) {
    const Vector_3d q = to_vector(p);
    if(!std::isfinite(q.x) || !std::isfinite(q.y) || !std::isfinite(q.z))
      throw Bad_input(who + ": a target point has a coordinate that is not a finite number");
    target_points.push_back(Point(q.x, q.y, q.z));
  }
  if(number_of_controls != target_points.size())
    throw Bad_input(who + ": " + std::to_string(number_of_controls) + " control vertices but " +
                    std::to_string(target_points.size()) + " targets");
  return target_points;
}

// Per vertex index: 1 if the vertex is on a face, else 0.
template <typename TriangleMesh, typename VertexIndexMap>
std::vector<char> vertices_on_faces(const TriangleMesh& tm, VertexIndexMap vim)
{
  std::vector<char> on_face(static_cast<std::size_t>(num_vertices(tm)), 0);
  for(auto f : faces(tm))
    for(auto v : CGAL::vertices_around_face(halfedge(f, tm), tm))
      on_face[static_cast<std::size_t>(get(vim, v))] = 1;
  return on_face;
}

// The role of every vertex (by index) -- 0: free, 1: control, 2: fixed -- after checking the
// control and fixed vertices; `fixed` gets the fixed vertices that are on a face, once each.
template <typename TriangleMesh, typename VertexIndexMap, typename FixedVertexRange>
std::vector<char>
deformation_roles(const TriangleMesh& tm, VertexIndexMap vim, const std::vector<char>& on_face,
                  const std::vector<typename boost::graph_traits<TriangleMesh>::vertex_descriptor>& controls,
                  const FixedVertexRange& fixed_vertices,
                  std::vector<typename boost::graph_traits<TriangleMesh>::vertex_descriptor>& fixed,
                  const std::string& who)
{
  using CGAL::Shape_analysis::Bad_input;
  typedef typename boost::graph_traits<TriangleMesh>::vertex_descriptor vertex_descriptor;
  const std::size_t n = static_cast<std::size_t>(num_vertices(tm));
  std::vector<char> role(n, 0);
  auto index_of = [&](vertex_descriptor v, const char* what) {
    const std::size_t i = static_cast<std::size_t>(get(vim, v));
    if(i >= n)
      throw Bad_input(who + ": a " + what + " vertex is not a vertex of the mesh");
    return i;
  };
  for(vertex_descriptor v : controls) {
    const std::size_t i = index_of(v, "control");
    if(role[i] != 0)
      throw Bad_input(who + ": a control vertex appears twice");
    if(!on_face[i])
      throw Bad_input(who + ": a control vertex is on no face");
    role[i] = 1;
  }
  for(vertex_descriptor v : fixed_vertices) {
    const std::size_t i = index_of(v, "fixed");
    if(role[i] == 1)
      throw Bad_input(who + ": a vertex is both a control vertex and a fixed vertex");
    if(role[i] == 2 || !on_face[i])
      continue;
    role[i] = 2;
    fixed.push_back(v);
  }
  return role;
}

// Throws if a connected component of the mesh has no control or fixed vertex.
template <typename TriangleMesh, typename VertexIndexMap>
void check_components_constrained(const TriangleMesh& tm, VertexIndexMap vim,
                                  const std::vector<char>& role, const std::vector<char>& on_face,
                                  const std::string& who)
{
  const std::size_t n = role.size();
  CGAL::Shape_analysis::internal::Union_find components(n);
  for(auto e : edges(tm))
    components.unite(static_cast<std::uint32_t>(get(vim, source(e, tm))),
                     static_cast<std::uint32_t>(get(vim, target(e, tm))));
  std::vector<char> constrained(n, 0);
  for(std::size_t i = 0; i < n; ++i)
    if(role[i] != 0)
      constrained[components.find(static_cast<std::uint32_t>(i))] = 1;
  for(std::size_t i = 0; i < n; ++i)
    if(on_face[i] && !constrained[components.find(static_cast<std::uint32_t>(i))])
      throw CGAL::Shape_analysis::Bad_input(
        who + ": a connected component of the mesh has no control or fixed vertex");
}

// The vertices on a face (the region of interest of the deformation); `diagonal` gets the
// diagonal of their bounding box (for the convergence test).
template <typename TriangleMesh, typename VertexIndexMap, typename VertexPointMap, typename ToVector>
std::vector<typename boost::graph_traits<TriangleMesh>::vertex_descriptor>
deformation_roi(const TriangleMesh& tm, VertexIndexMap vim, VertexPointMap vpm,
                const ToVector& to_vector, const std::vector<char>& on_face, double& diagonal)
{
  using CGAL::Shape_analysis::internal::Vector_3d;
  Vector_3d lo(std::numeric_limits<double>::infinity()), hi(-std::numeric_limits<double>::infinity());
  std::vector<typename boost::graph_traits<TriangleMesh>::vertex_descriptor> roi;
  roi.reserve(on_face.size());
  for(auto v : vertices(tm))
    if(on_face[static_cast<std::size_t>(get(vim, v))]) {
      roi.push_back(v);
      const Vector_3d p = to_vector(get(vpm, v));
      lo = lo.min(p);
      hi = hi.max(p);
    }
  diagonal = (hi - lo).length();
  return roi;
}

} // namespace internal
} // namespace Randomized_cuts
} // namespace CGAL

#endif // CGAL_RANDOMIZED_CUTS_INTERNAL_DEFORMATION_CONSTRAINTS_H
