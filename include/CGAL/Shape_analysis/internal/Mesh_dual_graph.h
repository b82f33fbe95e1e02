// Copyright (c) 2026 CGAL Global Shape Analysis contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_SHAPE_ANALYSIS_INTERNAL_MESH_DUAL_GRAPH_H
#define CGAL_SHAPE_ANALYSIS_INTERNAL_MESH_DUAL_GRAPH_H

// What every mesh entry point does first: read the named parameters that say how to see the mesh
// (vertex_point_map, geom_traits, face_index_map), check the mesh, and build its weighted dual
// graph with the caller's concavity exponent (the caller's options struct holds it and its
// default), remembering which face and which edge each node and graph edge stands for.

#include <CGAL/Shape_analysis/Bad_input.h>
#include <CGAL/Shape_analysis/parameters.h>
#include <CGAL/Shape_analysis/internal/Dual_graph.h>
#include <CGAL/Shape_analysis/internal/Mesh_checks.h>

#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/property_map.h>

#include <cmath>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Shape_analysis {
namespace internal {

template <typename TriangleMesh, typename NamedParameters>
struct Mesh_dual_graph
{
  typedef boost::graph_traits<TriangleMesh> GT;
  typedef typename GT::face_descriptor face_descriptor;
  typedef typename GT::edge_descriptor edge_descriptor;

  Dual_graph graph;
  std::vector<face_descriptor> faces; // by node (dense face index)
  std::vector<edge_descriptor> edges; // by mesh-edge rank (the order of edges(tm))

  // Node of a face.
  template <typename Face>
  std::size_t node(const Face& f) const
  {
    return get(m_fim, f);
  }

  // Checks `tm` (non-empty triangle mesh with finite coordinates and a positive area) and
  // `concavity_exponent`, and builds its dual graph with the maps of `np`; throws Bad_input naming
  // `who` otherwise.
  Mesh_dual_graph(const TriangleMesh& tm, const NamedParameters& np, double concavity_exponent,
                  const std::string& who)
    : m_fim(tm, CGAL::get_initialized_face_index_map(tm, np), who)
  {
    using CGAL::parameters::choose_parameter;
    using CGAL::parameters::get_parameter;
    auto vpm = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point),
                                get_const_property_map(CGAL::vertex_point, tm));
    typedef typename CGAL::GetGeomTraits<TriangleMesh, NamedParameters>::type Geom_traits;
    const Point_to_vector<Geom_traits> to_vector{
      choose_parameter<Geom_traits>(get_parameter(np, CGAL::internal_np::geom_traits))};
    check_triangle_mesh(tm, vpm, to_vector, who);
    const double alpha = concavity_exponent;
    if(!(alpha >= 0) || !std::isfinite(alpha))
      throw Bad_input(who + ": concavity_exponent must be a finite number >= 0");
    build_dual_graph(tm, vpm, m_fim, alpha, graph, to_vector);
    if(!(graph.total_size() > 0))
      throw Bad_input(who + ": every face of the mesh has zero area");
    faces.resize(graph.number_of_nodes());
    for(auto f : CGAL::faces(tm))
      faces[get(m_fim, f)] = f;
    edges.reserve(graph.number_of_mesh_edges);
    for(auto e : CGAL::edges(tm))
      edges.push_back(e);
  }

  std::size_t number_of_faces() const { return m_fim.size(); }

private:
  Dense_face_index_map<decltype(CGAL::get_initialized_face_index_map(
    std::declval<const TriangleMesh&>(), std::declval<const NamedParameters&>()))>
    m_fim;
};

} // namespace internal
} // namespace Shape_analysis
} // namespace CGAL

#endif // CGAL_SHAPE_ANALYSIS_INTERNAL_MESH_DUAL_GRAPH_H
