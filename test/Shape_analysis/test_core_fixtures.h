// Tests of the machinery shared by the packages: named parameters, weighted dual graph, s-t
// min-cut and max-flow, agglomerative normalized-cut clustering, partition refinement, component
// links, kd-tree, bounding-volume hierarchy (refitted), mesh checks, shortest paths, JSON, and the
// procedural shape generator used by the other suites.
//
// The suite is one executable, test_shape_analysis_core, built from the test_*.cpp files of this
// directory as one translation unit (a CGAL translation unit takes about a minute to compile);
// this header holds what they share.

#ifndef SHAPE_ANALYSIS_TEST_CORE_FIXTURES_H
#define SHAPE_ANALYSIS_TEST_CORE_FIXTURES_H

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/helpers.h>

#include <CGAL/Polygon_mesh_processing/measure.h> // for the namespace aliases below
#include <CGAL/Shape_analysis/parameters.h>
#include <CGAL/Shape_analysis/internal/Dual_graph.h>
#include <CGAL/Shape_analysis/internal/Vector_3d.h>
#include <Shape_analysis_support/Procedural_shapes.h>

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <utility>
#include <vector>

namespace {

typedef CGAL::Exact_predicates_inexact_constructions_kernel Kernel;
typedef Kernel::Point_3 Point;
typedef CGAL::Surface_mesh<Point> Mesh;
typedef Mesh::Vertex_index vertex_descriptor;
typedef Mesh::Face_index face_descriptor;

namespace SA = CGAL::Shape_analysis;
namespace SAI = CGAL::Shape_analysis::internal;
namespace SP = CGAL::Shape_analysis::parameters;
namespace SNP = CGAL::Shape_analysis::internal_np;
namespace PMP = CGAL::Polygon_mesh_processing;
namespace SAS = CGAL::Shape_analysis_support;
using SAI::Vector_3d;

// ---------------------------------------------------------------------------------------------
// Helpers

Mesh make_mesh(const std::vector<Point>& points, const std::vector<std::vector<std::size_t>>& faces)
{
  Mesh m;
  std::vector<vertex_descriptor> v;
  for(const Point& p : points)
    v.push_back(m.add_vertex(p));
  for(const auto& f : faces) {
    std::vector<vertex_descriptor> corners;
    for(std::size_t i : f)
      corners.push_back(v[i]);
    const face_descriptor fd = m.add_face(corners);
    EXPECT_TRUE(fd != Mesh::null_face());
  }
  return m;
}

// The unit cube [0,1]^3 as 12 outward-oriented triangles.
Mesh unit_cube()
{
  std::vector<Point> p;
  for(int i = 0; i < 8; ++i)
    p.emplace_back(i & 1, (i >> 1) & 1, (i >> 2) & 1);
  // Quads with outward orientation (counter-clockwise seen from outside), split in two.
  const std::vector<std::array<std::size_t, 4>> quads = {
    {0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  std::vector<std::vector<std::size_t>> f;
  for(const auto& q : quads) {
    f.push_back({q[0], q[1], q[2]});
    f.push_back({q[0], q[2], q[3]});
  }
  return make_mesh(p, f);
}

// A strip folded along the y axis: a floor at z = 0 for x in [-1, 0] (normal +z) and a wall rising
// from x = 0 at angle `a` from the floor (a > 0: a valley, concave; a < 0: a ridge, convex).
// Faces: 0,1 floor; 2,3 wall. Vertices: A=0 (0,0,0), B=1 (0,1,0) on the fold.
Mesh folded_strip(double a)
{
  const double c = std::cos(a), s = std::sin(a);
  return make_mesh({Point(0, 0, 0), Point(0, 1, 0), Point(-1, 0, 0), Point(-1, 1, 0),
                    Point(c, 0, s), Point(c, 1, s)},
                   {{2, 0, 1}, {2, 1, 3}, {0, 4, 5}, {0, 5, 1}});
}

Mesh to_surface_mesh(const SAS::Labelled_triangle_mesh& lm)
{
  Mesh m;
  SAS::fill_polygon_mesh(lm, m);
  return m;
}

void build_graph(const Mesh& m, double alpha, SAI::Dual_graph& g)
{
  SAI::build_dual_graph(m, get(CGAL::vertex_point, m), get(CGAL::face_index, m), alpha, g);
}

// The rank (in edges(m)) of the edge joining vertices a and b.
std::size_t edge_rank(const Mesh& m, std::size_t a, std::size_t b)
{
  std::size_t rank = 0;
  for(auto e : edges(m)) {
    const std::size_t s = source(e, m), t = target(e, m);
    if((s == a && t == b) || (s == b && t == a))
      return rank;
    ++rank;
  }
  return SAI::Dual_graph::no_mesh_edge;
}

std::size_t graph_edge_of_mesh_edge(const SAI::Dual_graph& g, std::size_t rank)
{
  for(std::size_t e = 0; e < g.number_of_edges(); ++e)
    if(g.mesh_edge[e] == rank)
      return e;
  return SAI::Dual_graph::no_mesh_edge;
}

// A small dual graph given by its edges (positions and sizes unused).
SAI::Dual_graph graph_of(std::size_t n, const std::vector<std::pair<std::uint32_t, std::uint32_t>>& edges,
                         const std::vector<double>& lengths)
{
  SAI::Dual_graph g;
  g.node_size.assign(n, 1.0);
  g.node_position.assign(n, Vector_3d());
  g.node_normal.assign(n, Vector_3d());
  for(std::size_t e = 0; e < edges.size(); ++e)
    g.add_edge(edges[e].first, edges[e].second, 1.0, 1.0, 1.0, lengths[e], e);
  g.number_of_mesh_edges = edges.size();
  g.build_adjacency();
  return g;
}

} // namespace

#endif // SHAPE_ANALYSIS_TEST_CORE_FIXTURES_H
