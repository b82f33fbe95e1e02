// Copyright (c) 2026 CGAL Global Shape Analysis contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_SHAPE_ANALYSIS_INTERNAL_DUAL_GRAPH_H
#define CGAL_SHAPE_ANALYSIS_INTERNAL_DUAL_GRAPH_H

// The weighted dual graph of a triangle mesh (faces are nodes, adjacent faces are joined), stored
// as flat arrays, with the cut and traversal costs of the thesis:
//   w(theta) = min((theta / pi)^alpha, 1), theta the dihedral angle measured outside the surface
//   cut cost       = edge length * w(theta)        (cheap across concave creases)
//   traversal cost = centroid distance / w(theta)  (expensive across concave creases)
// Node sizes are face areas. Each graph edge remembers the mesh edge it crosses (its rank in the
// iteration order of `edges(tm)`), or `no_mesh_edge` for an edge added later (component links).

#include <CGAL/Shape_analysis/Bad_input.h>
#include <CGAL/Shape_analysis/internal/Union_find.h>
#include <CGAL/Shape_analysis/internal/Vector_3d.h>

#include <CGAL/Kernel_traits.h>

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/number_utils.h>
#include <boost/graph/graph_traits.hpp>
#include <boost/property_map/property_map.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numeric>
#include <vector>

namespace CGAL {
namespace Shape_analysis {
namespace internal {

struct Dual_graph
{
  static constexpr std::size_t no_mesh_edge = (std::numeric_limits<std::size_t>::max)();
  // Smallest concavity weight kept, so that traversal costs stay finite.
  static constexpr double min_weight = 1e-12;

  // Nodes.
  std::vector<double> node_size;        // face area
  std::vector<Vector_3d> node_position; // face centroid
  std::vector<Vector_3d> node_normal;   // unit normal, outwards (zero for a degenerate face)

  // Undirected edges.
  std::vector<std::uint32_t> edge_source;
  std::vector<std::uint32_t> edge_target;
  std::vector<double> edge_length;       // length of the mesh edge (0 for links)
  std::vector<double> concavity_weight;  // w(theta) in [min_weight, 1]
  std::vector<double> cut_cost;
  std::vector<double> traversal_cost;
  std::vector<std::size_t> mesh_edge;    // rank in edges(tm), or no_mesh_edge

  // Adjacency in compressed rows (valid after build_adjacency()).
  std::vector<std::size_t> first_arc;    // size n + 1
  std::vector<std::uint32_t> arc_target;
  std::vector<std::uint32_t> arc_edge;

  // Whole-mesh figures.
  std::size_t number_of_mesh_edges = 0;
  double mean_mesh_edge_length = 0;
  double bbox_diagonal = 0;
  // Positions, lengths and sizes are in units of `length_unit` of the mesh's coordinates: 1, or for
  // meshes of extreme coordinates a power of two that brings them below 1 in absolute value (an
  // exact scaling, which keeps squared lengths and areas finite whatever the magnitude).
  double length_unit = 1;

  std::size_t number_of_nodes() const { return node_size.size(); }
  std::size_t number_of_edges() const { return edge_source.size(); }

  std::size_t add_edge(std::uint32_t u, std::uint32_t v, double length, double weight,
                       double cut, double traversal, std::size_t mesh_edge_rank)
  {
    edge_source.push_back(u);
    edge_target.push_back(v);
    edge_length.push_back(length);
    concavity_weight.push_back(weight);
    cut_cost.push_back(cut);
    traversal_cost.push_back(traversal);
    mesh_edge.push_back(mesh_edge_rank);
    return edge_source.size() - 1;
  }

  void build_adjacency()
  {
    const std::size_t n = number_of_nodes();
    first_arc.assign(n + 1, 0);
    for(std::size_t e = 0; e < number_of_edges(); ++e) {
      ++first_arc[edge_source[e] + 1];
      ++first_arc[edge_target[e] + 1];
    }
    std::partial_sum(first_arc.begin(), first_arc.end(), first_arc.begin());
    arc_target.resize(first_arc[n]);
    arc_edge.resize(first_arc[n]);
    std::vector<std::size_t> fill(first_arc.begin(), first_arc.end() - 1);
    for(std::size_t e = 0; e < number_of_edges(); ++e) {
      const std::uint32_t u = edge_source[e], v = edge_target[e];
      arc_target[fill[u]] = v;
      arc_edge[fill[u]++] = static_cast<std::uint32_t>(e);
      arc_target[fill[v]] = u;
      arc_edge[fill[v]++] = static_cast<std::uint32_t>(e);
    }
  }

  double total_size() const { return std::accumulate(node_size.begin(), node_size.end(), 0.0); }
};

// The subgraph induced by `nodes` (sorted, distinct node ids of `g`): node k of `sub` is
// nodes[k]; its edges are the edges of `g` with both ends among `nodes`, in the order of `g`
// (`parent_edge[j]` is the edge of `g` that edge j of `sub` is), keeping their mesh edges.
inline void induced_subgraph(const Dual_graph& g, const std::vector<std::uint32_t>& nodes,
                             Dual_graph& sub, std::vector<std::uint32_t>& parent_edge)
{
  const std::uint32_t none = ~std::uint32_t(0);
  std::vector<std::uint32_t> local(g.number_of_nodes(), none);
  for(std::size_t k = 0; k < nodes.size(); ++k)
    local[nodes[k]] = static_cast<std::uint32_t>(k);
  sub = Dual_graph();
  sub.node_size.reserve(nodes.size());
  sub.node_position.reserve(nodes.size());
  sub.node_normal.reserve(nodes.size());
  for(std::uint32_t v : nodes) {
    sub.node_size.push_back(g.node_size[v]);
    sub.node_position.push_back(g.node_position[v]);
    sub.node_normal.push_back(g.node_normal[v]);
  }
  parent_edge.clear();
  for(std::size_t e = 0; e < g.number_of_edges(); ++e) {
    const std::uint32_t u = local[g.edge_source[e]], v = local[g.edge_target[e]];
    if(u == none || v == none)
      continue;
    sub.add_edge(u, v, g.edge_length[e], g.concavity_weight[e], g.cut_cost[e], g.traversal_cost[e],
                 g.mesh_edge[e]);
    parent_edge.push_back(static_cast<std::uint32_t>(e));
  }
  sub.number_of_mesh_edges = g.number_of_mesh_edges;
  sub.mean_mesh_edge_length = g.mean_mesh_edge_length;
  sub.bbox_diagonal = g.bbox_diagonal;
  sub.length_unit = g.length_unit;
  sub.build_adjacency();
}

// w(theta) for the angle `phi` between the two face normals (0 = flat) and the crease type.
inline double concavity_weight(double phi, bool concave, double alpha)
{
  if(!concave)
    return 1.0; // flat or convex: theta >= pi
  const double theta_over_pi = (std::max)(0.0, 1.0 - phi / CGAL_PI);
  return (std::max)(Dual_graph::min_weight, (std::min)(1.0, std::pow(theta_over_pi, alpha)));
}

// Reads the coordinates of a point as doubles through the functors of a geometric traits class
// (a CGAL kernel).
template <typename GeomTraits>
struct Point_to_vector
{
  GeomTraits gt;
  template <typename Point>
  Vector_3d operator()(const Point& p) const
  {
    return Vector_3d(CGAL::to_double(gt.compute_x_3_object()(p)),
                     CGAL::to_double(gt.compute_y_3_object()(p)),
                     CGAL::to_double(gt.compute_z_3_object()(p)));
  }
};

// The exponent of the power of two by which build_dual_graph() scales the coordinates (0: none).
template <typename TriangleMesh, typename VertexPointMap, typename ToVector>
int dual_graph_exponent(const TriangleMesh& tm, VertexPointMap vpm, const ToVector& to_vector)
{
  // Coordinates beyond 2^128 or under 2^-128 (in the largest absolute value over the face
  // corners) would overflow or underflow the squared lengths of cross products: they are scaled
  // exactly, by the power of two that brings that value into [0.5, 1). Others are left alone.
  double largest = 0;
  for(auto f : faces(tm))
    for(auto v : CGAL::vertices_around_face(halfedge(f, tm), tm)) {
      const Vector_3d p = to_vector(get(vpm, v));
      largest = (std::max)(largest, (std::max)(std::abs(p.x), (std::max)(std::abs(p.y), std::abs(p.z))));
    }
  int exponent = 0;
  if(largest > 0 && std::isfinite(largest) && (largest > 0x1p128 || largest < 0x1p-128))
    std::frexp(largest, &exponent);
  return exponent;
}

// The nodes of the dual graph `g` (sized already): area, centroid and normal of every face of
// `tm` (`point` gives the scaled coordinates of a vertex), and the bounding-box diagonal.
template <typename TriangleMesh, typename FaceIndexMap, typename PointOf>
void set_dual_graph_nodes(const TriangleMesh& tm, FaceIndexMap fim, const PointOf& point, Dual_graph& g)
{
  typedef typename boost::graph_traits<TriangleMesh>::halfedge_descriptor halfedge_descriptor;
  const std::size_t n = g.number_of_nodes();
  // Faces: area, centroid, normal; bounding box of the face corners (unused vertices ignored).
  Vector_3d lo(std::numeric_limits<double>::infinity()), hi(-std::numeric_limits<double>::infinity());
  for(auto f : faces(tm)) {
    const std::size_t i = static_cast<std::size_t>(get(fim, f));
    const halfedge_descriptor h = halfedge(f, tm);
    const Vector_3d p = point(source(h, tm)), q = point(target(h, tm)),
                    r = point(target(next(h, tm), tm));
    lo = lo.min(p).min(q).min(r);
    hi = hi.max(p).max(q).max(r);
    const Vector_3d c = cross(q - p, r - p);
    const double twice_area = c.length();
    g.node_size[i] = 0.5 * twice_area;
    g.node_position[i] = (p + q + r) / 3.0;
    g.node_normal[i] = twice_area > 0 ? c / twice_area : Vector_3d();
  }
  g.bbox_diagonal = n > 0 ? (hi - lo).length() : 0.0;
}

// Flips the normals of the nodes of every closed or nearly closed component whose faces point
// inwards (see build_dual_graph()).
template <typename TriangleMesh, typename FaceIndexMap, typename PointOf>
void orient_dual_graph_nodes(const TriangleMesh& tm, FaceIndexMap fim, const PointOf& point, Dual_graph& g)
{
  typedef typename boost::graph_traits<TriangleMesh>::halfedge_descriptor halfedge_descriptor;
  const std::size_t n = g.number_of_nodes();
  // Connected components through interior edges, then one orientation per component. Each edge's
  // length is credited to one of its faces (and to the border when it has only one), then
  // summed per component.
  Union_find sets(n);
  std::vector<double> border_length(n, 0.0), edge_length_sum(n, 0.0);
  for(auto e : edges(tm)) {
    const halfedge_descriptor h = halfedge(e, tm), ho = opposite(h, tm);
    const bool border = is_border(h, tm) || is_border(ho, tm);
    const std::size_t f = static_cast<std::size_t>(get(fim, face(is_border(h, tm) ? ho : h, tm)));
    const double length = (point(target(h, tm)) - point(source(h, tm))).length();
    edge_length_sum[f] += length;
    if(border)
      border_length[f] += length;
    else
      sets.unite(static_cast<std::uint32_t>(f), static_cast<std::uint32_t>(get(fim, face(ho, tm))));
  }
  auto find = [&](std::size_t i) { return sets.find(static_cast<std::uint32_t>(i)); };
  for(std::size_t i = 0; i < n; ++i) {
    const std::uint32_t c = find(i);
    if(c != i) {
      edge_length_sum[c] += edge_length_sum[i];
      border_length[c] += border_length[i];
    }
  }
  std::vector<Vector_3d> weighted_centroid(n);
  std::vector<double> area(n, 0.0), signed_volume(n, 0.0);
  for(std::size_t i = 0; i < n; ++i) {
    const std::uint32_t c = find(i);
    weighted_centroid[c] += g.node_position[i] * g.node_size[i];
    area[c] += g.node_size[i];
  }
  for(std::size_t i = 0; i < n; ++i) {
    const std::uint32_t c = find(i);
    const Vector_3d centre = area[c] > 0 ? weighted_centroid[c] / area[c] : Vector_3d();
    signed_volume[c] += dot(g.node_position[i] - centre, g.node_normal[i]) * g.node_size[i];
  }
  for(std::size_t i = 0; i < n; ++i) {
    const std::uint32_t c = find(i);
    if(signed_volume[c] < 0 && border_length[c] < 0.3 * edge_length_sum[c])
      g.node_normal[i] *= -1.0;
  }
}

// The edges of the dual graph: one per interior mesh edge between two distinct faces, with its
// length, concavity weight and costs; the mesh edge count and mean length.
template <typename TriangleMesh, typename FaceIndexMap, typename PointOf>
void add_dual_graph_edges(const TriangleMesh& tm, FaceIndexMap fim, const PointOf& point, double alpha,
                          Dual_graph& g)
{
  typedef typename boost::graph_traits<TriangleMesh>::halfedge_descriptor halfedge_descriptor;
  std::size_t rank = 0;
  double length_sum = 0;
  g.edge_source.reserve(static_cast<std::size_t>(num_edges(tm)));
  for(auto e : edges(tm)) {
    const std::size_t this_rank = rank++;
    const halfedge_descriptor h = halfedge(e, tm), ho = opposite(h, tm);
    const Vector_3d p = point(source(h, tm)), q = point(target(h, tm));
    const double length = (q - p).length();
    length_sum += length;
    if(is_border(h, tm) || is_border(ho, tm))
      continue;
    const std::size_t f = static_cast<std::size_t>(get(fim, face(h, tm)));
    const std::size_t o = static_cast<std::size_t>(get(fim, face(ho, tm)));
    if(f == o)
      continue;
    const Vector_3d& nf = g.node_normal[f];
    const Vector_3d& no = g.node_normal[o];
    double w = 1.0;
    if(nf.squared_length() > 0 && no.squared_length() > 0) {
      const double cos_phi = (std::max)(-1.0, (std::min)(1.0, dot(nf, no)));
      const double phi = std::acos(cos_phi);
      // Concave when the apex of the other face lies above the plane of this face (normals
      // point outwards after the orientation above).
      const Vector_3d s = point(target(next(ho, tm), tm));
      const bool concave = dot(nf, s - p) > 0;
      w = concavity_weight(phi, concave, alpha);
    }
    const double centroid_distance = (g.node_position[f] - g.node_position[o]).length();
    g.add_edge(static_cast<std::uint32_t>(f), static_cast<std::uint32_t>(o), length, w, length * w,
               centroid_distance / w, this_rank);
  }
  g.number_of_mesh_edges = rank;
  g.mean_mesh_edge_length = rank > 0 ? length_sum / double(rank) : 0.0;
}

// Builds the dual graph of a triangle mesh. `fim` maps the faces to 0..n-1; `to_vector` turns
// the points of `vpm` into Vector_3d.
//
// Concavity needs the outward orientation. A halfedge mesh is consistently oriented within each
// connected component; a component that is closed or nearly closed (border edges under 30% of
// its edge length, e.g. a scan with a few holes) and whose faces point inwards (negative signed
// volume, measured from its centroid) has its normals flipped, so that the result does not
// depend on the orientation the file happened to have. An open surface (a strip, a terrain)
// has no inside: it keeps the orientation it was given.
template <typename TriangleMesh, typename VertexPointMap, typename FaceIndexMap, typename ToVector>
void build_dual_graph(const TriangleMesh& tm, VertexPointMap vpm, FaceIndexMap fim, double alpha,
                      Dual_graph& g, const ToVector& to_vector)
{
  typedef boost::graph_traits<TriangleMesh> GT;
  const int exponent = dual_graph_exponent(tm, vpm, to_vector);
  const double scale = std::ldexp(1.0, -exponent);
  auto point = [&](typename GT::vertex_descriptor v) { return to_vector(get(vpm, v)) * scale; };

  // Faces are counted through the index map (num_faces() of a Surface_mesh with removed faces
  // counts them too): `fim` must map the faces to 0..n-1.
  std::size_t n = 0;
  for(auto f : faces(tm))
    n = (std::max)(n, static_cast<std::size_t>(get(fim, f)) + 1);
  if(n >= std::size_t((std::numeric_limits<std::uint32_t>::max)()))
    throw Bad_input("the mesh has too many faces (at most 2^32 - 2)");
  g = Dual_graph();
  g.length_unit = std::ldexp(1.0, exponent);
  g.node_size.assign(n, 0.0);
  g.node_position.assign(n, Vector_3d());
  g.node_normal.assign(n, Vector_3d());

  set_dual_graph_nodes(tm, fim, point, g);
  orient_dual_graph_nodes(tm, fim, point, g);
  add_dual_graph_edges(tm, fim, point, alpha, g);
  g.build_adjacency();
}

// The same, with the points of `vpm` read as the points of a CGAL kernel (x(), y(), z()).
template <typename TriangleMesh, typename VertexPointMap, typename FaceIndexMap>
void build_dual_graph(const TriangleMesh& tm, VertexPointMap vpm, FaceIndexMap fim, double alpha,
                      Dual_graph& g)
{
  typedef typename boost::property_traits<VertexPointMap>::value_type Point;
  typedef typename CGAL::Kernel_traits<Point>::Kernel Kernel;
  build_dual_graph(tm, vpm, fim, alpha, g, Point_to_vector<Kernel>());
}

} // namespace internal
} // namespace Shape_analysis
} // namespace CGAL

#endif // CGAL_SHAPE_ANALYSIS_INTERNAL_DUAL_GRAPH_H
