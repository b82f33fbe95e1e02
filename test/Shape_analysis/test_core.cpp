// Tests of the machinery shared by the packages: named parameters, weighted dual graph, s-t
// min-cut, agglomerative normalized-cut clustering, component links, partition refinement, kd-tree,
// bounding-volume hierarchy (refitted),
// mesh checks, JSON, and the procedural shape generator used by the other suites.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Polygon_mesh_processing/orientation.h>

#include <CGAL/Shape_analysis/Bad_input.h>
#include <CGAL/Shape_analysis/parameters.h>
#include <CGAL/Shape_analysis/internal/Bvh.h>
#include <CGAL/Shape_analysis/internal/Component_links.h>
#include <CGAL/Shape_analysis/internal/Dual_graph.h>
#include <CGAL/Shape_analysis/internal/Json.h>
#include <CGAL/Shape_analysis/internal/Max_flow.h>
#include <CGAL/Shape_analysis/internal/Mesh_checks.h>
#include <CGAL/Shape_analysis/internal/Min_cut.h>
#include <CGAL/Shape_analysis/internal/Normalized_cut_clustering.h>
#include <CGAL/Shape_analysis/internal/Partition_refinement.h>
#include <CGAL/Shape_analysis/internal/Point_tree.h>
#include <CGAL/Shape_analysis/internal/Procedural_shapes.h>
#include <CGAL/Shape_analysis/internal/Shortest_paths.h>

#include <boost/graph/adjacency_list.hpp>
#include <boost/graph/push_relabel_max_flow.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>
#include <limits>
#include <map>
#include <set>
#include <string>
#include <type_traits>
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

Mesh to_surface_mesh(const SAI::Labelled_triangle_mesh& lm)
{
  Mesh m;
  SAI::fill_polygon_mesh(lm, m);
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

double normalized_cut(const std::vector<double>& size, const std::vector<std::uint32_t>& source,
                      const std::vector<std::uint32_t>& target, const std::vector<double>& weight,
                      const std::vector<std::size_t>& labels)
{
  std::map<std::size_t, double> cut, area;
  for(std::size_t i = 0; i < size.size(); ++i)
    area[labels[i]] += size[i];
  for(std::size_t e = 0; e < source.size(); ++e)
    if(labels[source[e]] != labels[target[e]]) {
      cut[labels[source[e]]] += weight[e];
      cut[labels[target[e]]] += weight[e];
    }
  double j = 0;
  for(const auto& c : cut)
    j += c.second / area[c.first];
  return j;
}

// ---------------------------------------------------------------------------------------------
// Named parameters

TEST(NamedParameters, MixedChainReadsBackEveryValue)
{
  Mesh m = unit_cube();
  auto vpm = get(CGAL::vertex_point, m);
  const auto np = SP::number_of_segments(3).vertex_point_map(vpm).random_seed(5);

  EXPECT_EQ(SP::choose_parameter(SP::get_parameter(np, SNP::number_of_segments_tag), 0), 3);
  EXPECT_EQ(SP::choose_parameter(SP::get_parameter(np, CGAL::internal_np::random_seed), 0u), 5u);
  auto got_vpm = SP::get_parameter(np, CGAL::internal_np::vertex_point);
  static_assert(std::is_same<decltype(got_vpm), decltype(vpm)>::value, "vertex_point_map type");
  for(auto v : vertices(m))
    EXPECT_EQ(get(got_vpm, v), m.point(v));

  // Absent parameters fall back to the default given to choose_parameter.
  EXPECT_EQ(SP::choose_parameter(SP::get_parameter(np, SNP::concavity_exponent_tag), 10.5), 10.5);
  static_assert(SP::is_default_parameter<decltype(np), SNP::concavity_exponent_t>::value, "default");
  static_assert(SP::is_default_parameter<decltype(np), CGAL::internal_np::geom_traits_t>::value, "default");
  static_assert(!SP::is_default_parameter<decltype(np), SNP::number_of_segments_t>::value, "given");
  static_assert(!SP::is_default_parameter<decltype(np), CGAL::internal_np::random_seed_t>::value, "given");
  static_assert(!SP::is_default_parameter<decltype(np), CGAL::internal_np::vertex_point_t>::value, "given");

  // The pack is a CGAL pack.
  static_assert(std::is_base_of<CGAL::Named_function_parameters<int, SNP::number_of_segments_t>,
                                std::decay_t<decltype(SP::number_of_segments(3))>>::value,
                "our pack derives from CGAL's");
}

TEST(NamedParameters, ChainStartingWithCgalStarterKeepsOurMembers)
{
  const auto np = SP::random_seed(11).concavity_exponent(2.5).prior_boundary_factor(4.0)
                    .component_link_distance(0.2).component_link_factor(0.03)
                    .boundary_refinement(false).verbose(true);
  EXPECT_EQ(SP::choose_parameter(SP::get_parameter(np, CGAL::internal_np::random_seed), 0u), 11u);
  EXPECT_DOUBLE_EQ(SP::choose_parameter(SP::get_parameter(np, SNP::concavity_exponent_tag), 0.0), 2.5);
  EXPECT_DOUBLE_EQ(SP::choose_parameter(SP::get_parameter(np, SNP::prior_boundary_factor_tag), 0.0), 4.0);
  EXPECT_DOUBLE_EQ(SP::choose_parameter(SP::get_parameter(np, SNP::component_link_distance_tag), 0.0), 0.2);
  EXPECT_DOUBLE_EQ(SP::choose_parameter(SP::get_parameter(np, SNP::component_link_factor_tag), 0.0), 0.03);
  EXPECT_FALSE(SP::choose_parameter(SP::get_parameter(np, SNP::boundary_refinement_tag), true));
  EXPECT_TRUE(SP::choose_parameter(SP::get_parameter(np, CGAL::internal_np::verbose), false));
  static_assert(SP::is_default_parameter<decltype(np), SNP::number_of_segments_t>::value, "default");
}

TEST(NamedParameters, ExtendWrapsCgalPacks)
{
  const auto np = SP::extend(CGAL::parameters::random_seed(7)).number_of_segments(2);
  EXPECT_EQ(SP::choose_parameter(SP::get_parameter(np, CGAL::internal_np::random_seed), 0u), 7u);
  EXPECT_EQ(SP::choose_parameter(SP::get_parameter(np, SNP::number_of_segments_tag), 0), 2);

  // A longer CGAL chain keeps all its values.
  const auto np2 = SP::extend(CGAL::parameters::random_seed(9).number_of_iterations(4).verbose(true))
                     .concavity_exponent(3.0);
  EXPECT_EQ(SP::choose_parameter(SP::get_parameter(np2, CGAL::internal_np::random_seed), 0u), 9u);
  EXPECT_EQ(SP::choose_parameter(SP::get_parameter(np2, CGAL::internal_np::number_of_iterations), 0), 4);
  EXPECT_TRUE(SP::choose_parameter(SP::get_parameter(np2, CGAL::internal_np::verbose), false));
  EXPECT_DOUBLE_EQ(SP::choose_parameter(SP::get_parameter(np2, SNP::concavity_exponent_tag), 0.0), 3.0);
  static_assert(SP::is_default_parameter<decltype(np2), SNP::number_of_segments_t>::value, "default");
}

TEST(NamedParameters, DefaultValuesAndParameterValue)
{
  const auto np = SP::default_values();
  static_assert(SP::is_default_parameter<decltype(np), SNP::number_of_segments_t>::value, "default");
  static_assert(SP::is_default_parameter<decltype(np), CGAL::internal_np::random_seed_t>::value, "default");
  EXPECT_EQ(SAI::parameter_value<std::size_t>(np, SNP::number_of_segments_tag, std::size_t(8)), 8u);
  // parameter_value converts the stored value.
  const auto np2 = SP::number_of_segments(5).concavity_exponent(2);
  EXPECT_EQ(SAI::parameter_value<std::size_t>(np2, SNP::number_of_segments_tag, std::size_t(8)), 5u);
  EXPECT_DOUBLE_EQ(SAI::parameter_value<double>(np2, SNP::concavity_exponent_tag, 10.0), 2.0);

  // A progress callback goes through as a callable.
  double last = -1;
  const auto np3 = SP::progress_callback([&last](double x) { last = x; });
  auto callback = SAI::parameter_value<std::function<void(double)>>(
    np3, SNP::progress_callback_tag, std::function<void(double)>());
  ASSERT_TRUE(static_cast<bool>(callback));
  callback(0.25);
  EXPECT_EQ(last, 0.25);
}

TEST(NamedParameters, CgalFunctionsAcceptThePack)
{
  // The area through a vertex point map that doubles the coordinates is 4 times the cube's; the
  // pack also selects the right PMP overload (GetGeomTraits specialization) and the geom traits.
  Mesh m = unit_cube();
  auto doubled = m.add_property_map<vertex_descriptor, Point>("v:doubled").first;
  for(auto v : vertices(m))
    doubled[v] = Point(2 * m.point(v).x(), 2 * m.point(v).y(), 2 * m.point(v).z());
  EXPECT_NEAR(PMP::area(m, SP::vertex_point_map(doubled).geom_traits(Kernel())), 24.0, 1e-12);
  EXPECT_NEAR(PMP::area(m, SP::number_of_segments(2).vertex_point_map(doubled)), 24.0, 1e-12);
  EXPECT_NEAR(PMP::area(m, SP::default_values()), 6.0, 1e-12);
  EXPECT_NEAR(PMP::volume(m, SP::vertex_point_map(doubled)), 8.0, 1e-12);
  auto fim = CGAL::get_initialized_face_index_map(m, SP::number_of_segments(2));
  std::set<std::size_t> ids;
  for(auto f : faces(m))
    ids.insert(static_cast<std::size_t>(get(fim, f)));
  EXPECT_EQ(ids.size(), 12u);
  EXPECT_EQ(*ids.rbegin(), 11u);
}

// ---------------------------------------------------------------------------------------------
// Dual graph

TEST(DualGraph, ConcavityWeight)
{
  EXPECT_EQ(SAI::concavity_weight(1.0, false, 10), 1.0);
  EXPECT_EQ(SAI::concavity_weight(0.0, true, 10), 1.0);
  EXPECT_NEAR(SAI::concavity_weight(CGAL_PI / 2, true, 10), std::pow(0.5, 10), 1e-15);
  EXPECT_NEAR(SAI::concavity_weight(CGAL_PI / 3, true, 2), 4.0 / 9.0, 1e-15);
  EXPECT_EQ(SAI::concavity_weight(CGAL_PI, true, 10), SAI::Dual_graph::min_weight);
  // Sharper concave creases are cheaper.
  EXPECT_LT(SAI::concavity_weight(2.0, true, 10), SAI::concavity_weight(1.0, true, 10));
}

TEST(DualGraph, CubeHasOnlyConvexAndFlatEdges)
{
  const Mesh m = unit_cube();
  ASSERT_TRUE(CGAL::is_closed(m));
  ASSERT_TRUE(PMP::is_outward_oriented(m));
  SAI::Dual_graph g;
  build_graph(m, 10, g);
  ASSERT_EQ(g.number_of_nodes(), 12u);
  ASSERT_EQ(g.number_of_edges(), 18u); // every edge of a closed mesh joins two faces
  EXPECT_EQ(g.number_of_mesh_edges, 18u);
  EXPECT_NEAR(g.total_size(), 6.0, 1e-12);
  EXPECT_NEAR(g.bbox_diagonal, std::sqrt(3.0), 1e-12);
  EXPECT_NEAR(g.mean_mesh_edge_length, (12 + 6 * std::sqrt(2.0)) / 18, 1e-12);
  std::set<std::size_t> ranks;
  for(std::size_t e = 0; e < g.number_of_edges(); ++e) {
    EXPECT_EQ(g.concavity_weight[e], 1.0);
    EXPECT_DOUBLE_EQ(g.cut_cost[e], g.edge_length[e]);
    EXPECT_DOUBLE_EQ(g.traversal_cost[e],
                     (g.node_position[g.edge_source[e]] - g.node_position[g.edge_target[e]]).length());
    ranks.insert(g.mesh_edge[e]);
  }
  EXPECT_EQ(ranks.size(), 18u);
  EXPECT_EQ(*ranks.rbegin(), 17u);
  // Each graph edge joins the two faces of its mesh edge.
  std::vector<std::pair<std::size_t, std::size_t>> faces_of_rank;
  std::vector<double> length_of_rank;
  for(auto e : edges(m)) {
    faces_of_rank.emplace_back(face(halfedge(e, m), m), face(opposite(halfedge(e, m), m), m));
    length_of_rank.push_back(PMP::edge_length(halfedge(e, m), m));
  }
  for(std::size_t e = 0; e < g.number_of_edges(); ++e) {
    const auto fs = faces_of_rank[g.mesh_edge[e]];
    const std::set<std::size_t> expected = {fs.first, fs.second};
    const std::set<std::size_t> got = {g.edge_source[e], g.edge_target[e]};
    EXPECT_EQ(got, expected);
    EXPECT_NEAR(g.edge_length[e], length_of_rank[g.mesh_edge[e]], 1e-12);
  }
  // Compressed adjacency: every triangle of a closed mesh has 3 neighbours.
  ASSERT_EQ(g.first_arc.size(), 13u);
  for(std::size_t u = 0; u < 12; ++u) {
    EXPECT_EQ(g.first_arc[u + 1] - g.first_arc[u], 3u);
    for(std::size_t a = g.first_arc[u]; a < g.first_arc[u + 1]; ++a) {
      const std::size_t e = g.arc_edge[a];
      const std::set<std::size_t> ends = {g.edge_source[e], g.edge_target[e]};
      EXPECT_EQ(ends, (std::set<std::size_t>{u, g.arc_target[a]}));
    }
  }
  for(std::size_t f = 0; f < 12; ++f) {
    EXPECT_DOUBLE_EQ(g.node_size[f], 0.5);
    EXPECT_NEAR(g.node_normal[f].length(), 1.0, 1e-12);
  }
}

TEST(DualGraph, ConcaveCreaseIsCheapConvexCreaseCostsItsLength)
{
  for(double degrees : {30.0, 60.0, 90.0, 120.0}) {
    const double a = degrees * CGAL_PI / 180;
    for(double alpha : {10.0, 2.0}) {
      // Valley: concave crease of outside angle pi - a.
      const Mesh valley = folded_strip(a);
      SAI::Dual_graph g;
      build_graph(valley, alpha, g);
      ASSERT_EQ(g.number_of_nodes(), 4u);
      EXPECT_EQ(g.number_of_mesh_edges, 9u);
      ASSERT_EQ(g.number_of_edges(), 3u) << "boundary edges give no graph edge";
      const std::size_t crease = graph_edge_of_mesh_edge(g, edge_rank(valley, 0, 1));
      ASSERT_NE(crease, SAI::Dual_graph::no_mesh_edge);
      const double w = std::pow((CGAL_PI - a) / CGAL_PI, alpha);
      EXPECT_NEAR(g.concavity_weight[crease], w, 1e-9 * w) << degrees << " degrees";
      EXPECT_NEAR(g.cut_cost[crease], 1.0 * w, 1e-9 * w);
      const double distance =
        (g.node_position[g.edge_source[crease]] - g.node_position[g.edge_target[crease]]).length();
      EXPECT_NEAR(g.traversal_cost[crease], distance / w, 1e-9 * distance / w);
      for(std::size_t e = 0; e < 3; ++e)
        if(e != crease) { // the flat diagonals
          EXPECT_EQ(g.concavity_weight[e], 1.0);
          EXPECT_NEAR(g.cut_cost[e], std::sqrt(2.0), 1e-12);
        }
      EXPECT_NEAR(g.total_size(), 2.0, 1e-12);

      // Ridge: the same fold the other way is convex and costs its length.
      const Mesh ridge = folded_strip(-a);
      build_graph(ridge, alpha, g);
      const std::size_t ridge_crease = graph_edge_of_mesh_edge(g, edge_rank(ridge, 0, 1));
      ASSERT_NE(ridge_crease, SAI::Dual_graph::no_mesh_edge);
      EXPECT_EQ(g.concavity_weight[ridge_crease], 1.0);
      EXPECT_NEAR(g.cut_cost[ridge_crease], 1.0, 1e-12);
    }
  }
}

TEST(DualGraph, ProceduralCreasesAreCheapAndSizesSumToArea)
{
  const SAI::Labelled_triangle_mesh lm =
    SAI::mesh_procedural_shape(SAI::three_sphere_chain(), 0.2);
  const Mesh m = to_surface_mesh(lm);
  SAI::Dual_graph g;
  build_graph(m, 10, g);
  ASSERT_EQ(g.number_of_nodes(), lm.number_of_faces());
  EXPECT_NEAR(g.total_size(), PMP::area(m), 1e-9 * PMP::area(m));
  EXPECT_EQ(g.number_of_edges(), num_edges(m)); // closed: one graph edge per mesh edge
  std::set<std::size_t> ranks(g.mesh_edge.begin(), g.mesh_edge.end());
  EXPECT_EQ(ranks.size(), g.number_of_edges());

  // Within a part (a sphere: convex, or nearly flat where the marching tetrahedra leave small
  // wiggles) edges cost about their length.
  std::vector<double> within;
  for(std::size_t e = 0; e < g.number_of_edges(); ++e)
    if(lm.labels[g.edge_source[e]] == lm.labels[g.edge_target[e]])
      within.push_back(g.concavity_weight[e]);
  std::sort(within.begin(), within.end());
  EXPECT_GT(within[within.size() / 20], 0.8) << "5th percentile of the weights within parts";

  // The cheapest separation of the left sphere from the rest (a min-cut between faces far on
  // either side of the crease) follows the concave crease, a circle of radius about 0.53 (length
  // 3.3): with alpha = 10 it costs a small fraction of that length, with alpha = 0 (no concavity
  // weighting) about the length itself.
  auto separation_cost = [&](const SAI::Dual_graph& graph) {
    SAI::Terminal_min_cut solver(graph.number_of_nodes());
    for(std::size_t e = 0; e < graph.number_of_edges(); ++e)
      solver.add_edge(graph.edge_source[e], graph.edge_target[e], graph.cut_cost[e]);
    std::size_t sources = 0, sinks = 0;
    for(std::size_t f = 0; f < graph.number_of_nodes(); ++f) {
      const double x = graph.node_position[f].x;
      if(x < -1.6) {
        solver.constrain(f, SAI::Terminal_min_cut::SOURCE);
        ++sources;
      } else if(x > -0.3) {
        solver.constrain(f, SAI::Terminal_min_cut::SINK);
        ++sinks;
      }
    }
    EXPECT_GT(sources, 100u);
    EXPECT_GT(sinks, 100u);
    const double cost = solver.solve();
    // The source side is (about) the left sphere's part.
    std::size_t agree = 0;
    for(std::size_t f = 0; f < graph.number_of_nodes(); ++f)
      agree += (solver.is_source_side(f) == (lm.labels[f] == 0)) ? 1 : 0;
    return std::make_pair(cost, double(agree) / double(graph.number_of_nodes()));
  };
  const double crease_length = 2 * CGAL_PI * 0.528;
  const auto concave = separation_cost(g);
  EXPECT_LT(concave.first, 0.1 * crease_length);
  EXPECT_GT(concave.second, 0.97) << "the cheapest cut is the crease";
  SAI::Dual_graph flat;
  build_graph(m, 0, flat);
  for(double w : flat.concavity_weight)
    EXPECT_EQ(w, 1.0);
  const auto unweighted = separation_cost(flat);
  EXPECT_GT(unweighted.first, 0.8 * crease_length);
  EXPECT_LT(unweighted.first, 1.5 * crease_length);
}

TEST(DualGraph, OpenMeshWithHolesHasNoBoundaryEdges)
{
  // A cube without its top two triangles.
  Mesh m = unit_cube();
  std::vector<face_descriptor> top;
  for(auto f : faces(m)) {
    bool all_top = true;
    for(auto v : vertices_around_face(halfedge(f, m), m))
      all_top = all_top && m.point(v).z() == 1;
    if(all_top)
      top.push_back(f);
  }
  ASSERT_EQ(top.size(), 2u);
  for(auto f : top)
    CGAL::Euler::remove_face(halfedge(f, m), m);
  m.collect_garbage();
  SAI::Dual_graph g;
  build_graph(m, 10, g);
  EXPECT_EQ(g.number_of_nodes(), 10u);
  EXPECT_EQ(g.number_of_mesh_edges, 17u);
  EXPECT_EQ(g.number_of_edges(), 13u); // the 4 edges of the hole join one face only
}

// ---------------------------------------------------------------------------------------------
// Min-cut

struct Cut_problem
{
  std::size_t n = 0;
  std::vector<std::pair<std::size_t, std::size_t>> pairs;
  std::vector<std::pair<double, double>> capacity;
  std::vector<double> to_source, to_sink;
  std::vector<SAI::Terminal_min_cut::Side> constraint;

  // Cost of a side assignment (true: source side); infinity if a constraint is violated.
  double cost(const std::vector<bool>& s) const
  {
    double c = 0;
    for(std::size_t u = 0; u < n; ++u) {
      if(constraint[u] == SAI::Terminal_min_cut::SOURCE && !s[u])
        return std::numeric_limits<double>::infinity();
      if(constraint[u] == SAI::Terminal_min_cut::SINK && s[u])
        return std::numeric_limits<double>::infinity();
      c += s[u] ? to_sink[u] : to_source[u];
    }
    for(std::size_t p = 0; p < pairs.size(); ++p) {
      const std::size_t u = pairs[p].first, v = pairs[p].second;
      if(s[u] && !s[v])
        c += capacity[p].first;
      if(s[v] && !s[u])
        c += capacity[p].second;
    }
    return c;
  }

  double brute_force() const
  {
    double best = std::numeric_limits<double>::infinity();
    std::vector<bool> s(n);
    for(std::uint32_t mask = 0; mask < (1u << n); ++mask) {
      for(std::size_t u = 0; u < n; ++u)
        s[u] = (mask >> u) & 1u;
      best = (std::min)(best, cost(s));
    }
    return best;
  }

  void randomize_capacities(SAI::Procedural_random& rng, bool with_constraints)
  {
    capacity.resize(pairs.size());
    for(auto& c : capacity) {
      c.first = rng.uniform() < 0.2 ? 0.0 : rng.uniform(0, 2);
      c.second = rng.uniform() < 0.2 ? 0.0 : rng.uniform(0, 2);
    }
    to_source.assign(n, 0.0);
    to_sink.assign(n, 0.0);
    constraint.assign(n, SAI::Terminal_min_cut::FREE);
    for(std::size_t u = 0; u < n; ++u) {
      if(rng.uniform() < 0.6)
        to_source[u] = rng.uniform(0, 3);
      if(rng.uniform() < 0.6)
        to_sink[u] = rng.uniform(0, 3);
      if(with_constraints) {
        const double r = rng.uniform();
        constraint[u] = r < 0.15 ? SAI::Terminal_min_cut::SOURCE
                                 : (r < 0.3 ? SAI::Terminal_min_cut::SINK : SAI::Terminal_min_cut::FREE);
      }
    }
  }

  void load(SAI::Terminal_min_cut& solver) const
  {
    for(std::size_t p = 0; p < pairs.size(); ++p)
      solver.set_edge_capacity(p, capacity[p].first, capacity[p].second);
    for(std::size_t u = 0; u < n; ++u) {
      solver.set_terminal_capacity(u, to_source[u], to_sink[u]);
      solver.constrain(u, constraint[u]);
    }
  }

  void check(SAI::Terminal_min_cut& solver, const std::string& what) const
  {
    const double flow = solver.solve();
    const double best = brute_force();
    EXPECT_NEAR(flow, best, 1e-9 * (1 + best)) << what;
    std::vector<bool> side(n);
    for(std::size_t u = 0; u < n; ++u)
      side[u] = solver.is_source_side(u);
    EXPECT_NEAR(cost(side), best, 1e-9 * (1 + best)) << what << ": the returned sides realize the cut";
  }
};

TEST(MinCut, MatchesBruteForceOnRandomGraphsWithReuse)
{
  for(std::uint64_t seed = 1; seed <= 40; ++seed) {
    SAI::Procedural_random rng(seed);
    Cut_problem problem;
    problem.n = 2 + rng.index(9); // 2..10 nodes
    for(std::size_t u = 0; u < problem.n; ++u)
      for(std::size_t v = u + 1; v < problem.n; ++v)
        if(rng.uniform() < 0.45)
          problem.pairs.emplace_back(rng.uniform() < 0.5 ? std::make_pair(u, v) : std::make_pair(v, u));
    SAI::Terminal_min_cut solver(problem.n);
    for(const auto& p : problem.pairs)
      solver.add_edge(p.first, p.second, 0.0);
    // The same topology solved several times with new capacities and constraints.
    for(int round = 0; round < 6; ++round) {
      problem.randomize_capacities(rng, round % 2 == 1);
      problem.load(solver);
      problem.check(solver, "seed " + std::to_string(seed) + " round " + std::to_string(round));
    }
    // Removing all terminals and constraints: the empty cut is free.
    solver.clear_terminals();
    EXPECT_EQ(solver.solve(), 0.0);
  }
}

TEST(MinCut, ConstraintsAddedAfterASolveAugmentTheFlow)
{
  // Solved without constraints, then constraints added two at a time (only capacities that
  // grow): the re-solve by augmentation matches brute force every time, and a constraint that
  // contradicts an earlier one falls back to a full solve that matches too.
  for(std::uint64_t seed = 1; seed <= 40; ++seed) {
    SAI::Procedural_random rng(100 + seed);
    Cut_problem problem;
    problem.n = 3 + rng.index(8); // 3..10 nodes
    for(std::size_t u = 0; u < problem.n; ++u)
      for(std::size_t v = u + 1; v < problem.n; ++v)
        if(rng.uniform() < 0.5)
          problem.pairs.emplace_back(u, v);
    problem.randomize_capacities(rng, false);
    SAI::Terminal_min_cut solver(problem.n);
    for(std::size_t p = 0; p < problem.pairs.size(); ++p)
      solver.add_edge(problem.pairs[p].first, problem.pairs[p].second, problem.capacity[p].first,
                      problem.capacity[p].second);
    for(std::size_t u = 0; u < problem.n; ++u)
      solver.set_terminal_capacity(u, problem.to_source[u], problem.to_sink[u]);
    problem.check(solver, "seed " + std::to_string(seed) + " unconstrained");
    for(int round = 0; round < 3; ++round) {
      std::vector<std::pair<std::size_t, SAI::Terminal_min_cut::Side>> added;
      for(int k = 0; k < 2; ++k) {
        const std::size_t u = rng.index(problem.n);
        const SAI::Terminal_min_cut::Side side =
          rng.uniform() < 0.5 ? SAI::Terminal_min_cut::SOURCE : SAI::Terminal_min_cut::SINK;
        added.emplace_back(u, side);
        problem.constraint[u] = side;
      }
      const double value = solver.constrain_and_resolve(added);
      const double best = problem.brute_force();
      const std::string what = "seed " + std::to_string(seed) + " round " + std::to_string(round);
      EXPECT_NEAR(value, best, 1e-9 * (1 + best)) << what;
      std::vector<bool> side(problem.n);
      for(std::size_t u = 0; u < problem.n; ++u)
        side[u] = solver.is_source_side(u);
      EXPECT_NEAR(problem.cost(side), best, 1e-9 * (1 + best)) << what << ": the sides realize the cut";
    }
  }
}

TEST(MinCut, ChangesBetweenSolvesAreTakenIntoAccount)
{
  // 0 - 1 - 2 in a chain; 0 wants the source side, 2 the sink side.
  SAI::Terminal_min_cut solver(3);
  solver.add_edge(0, 1, 1.0);
  solver.add_edge(1, 2, 2.0);
  solver.set_terminal_capacity(0, 10, 0);
  solver.set_terminal_capacity(2, 0, 10);
  EXPECT_NEAR(solver.solve(), 1.0, 1e-12); // cut 0-1
  EXPECT_FALSE(solver.is_source_side(1));
  // An edge added after the solve: the graph is rebuilt (0-2 of 0.5 now crosses every cut).
  solver.add_edge(0, 2, 0.5);
  EXPECT_NEAR(solver.solve(), 1.5, 1e-12);
  // A capacity lowered, then a constraint: the re-solve starts again (an augmentation of the
  // old flow would be wrong); with 1 on the source side the cut goes through the cheap 1-2 edge.
  solver.set_edge_capacity(1, 0.1, 0.1);
  EXPECT_NEAR(solver.constrain_and_resolve({{std::size_t(1), SAI::Terminal_min_cut::SOURCE}}), 0.6, 1e-12);
  EXPECT_TRUE(solver.is_source_side(1));
  // A solve that throws (a negative capacity) leaves nothing to augment: the next call solves.
  solver.set_edge_capacity(0, -1.0, 1.0);
  EXPECT_THROW(solver.solve(), SA::Bad_input);
  solver.set_edge_capacity(0, 1.0, 1.0);
  EXPECT_NEAR(solver.constrain_and_resolve({{std::size_t(0), SAI::Terminal_min_cut::SOURCE}}), 0.6, 1e-12);
  EXPECT_TRUE(solver.is_source_side(1));
  EXPECT_FALSE(solver.is_source_side(2));
}

TEST(MinCut, HardConstraintsWinOverExpensiveCuts)
{
  // A chain 0-1-2-3 with expensive links; node 0 prefers the sink strongly and node 3 the source,
  // but the constraints put 0 on the source side and 3 on the sink side.
  SAI::Terminal_min_cut solver(4);
  const double link[3] = {5, 1.5, 7};
  for(std::size_t u = 0; u + 1 < 4; ++u)
    solver.add_edge(u, u + 1, link[u]);
  solver.set_terminal_capacity(0, 0, 100);
  solver.set_terminal_capacity(3, 100, 0);
  solver.constrain(0, SAI::Terminal_min_cut::SOURCE);
  solver.constrain(3, SAI::Terminal_min_cut::SINK);
  const double flow = solver.solve();
  EXPECT_TRUE(solver.is_source_side(0));
  EXPECT_FALSE(solver.is_source_side(3));
  // The cheapest way: cut the middle link (1.5), plus the terminal arcs 0->t and s->3.
  EXPECT_NEAR(flow, 200 + 1.5, 1e-9);
  EXPECT_TRUE(solver.is_source_side(1));
  EXPECT_FALSE(solver.is_source_side(2));

  // Reversed constraints on the same solver.
  solver.constrain(0, SAI::Terminal_min_cut::SINK);
  solver.constrain(3, SAI::Terminal_min_cut::SOURCE);
  solver.set_terminal_capacity(0, 0, 0);
  solver.set_terminal_capacity(3, 0, 0);
  EXPECT_NEAR(solver.solve(), 1.5, 1e-9);
  EXPECT_FALSE(solver.is_source_side(0));
  EXPECT_FALSE(solver.is_source_side(1));
  EXPECT_TRUE(solver.is_source_side(2));
  EXPECT_TRUE(solver.is_source_side(3));
}

TEST(MinCut, AsymmetricCapacitiesAndReset)
{
  // Two nodes, source prefers 0, sink prefers 1: the arc 0->1 is cut, its reverse is not.
  SAI::Terminal_min_cut solver(2);
  solver.add_edge(0, 1, 0.25, 9.0);
  solver.set_terminal_capacity(0, 10, 0);
  solver.set_terminal_capacity(1, 0, 10);
  EXPECT_NEAR(solver.solve(), 0.25, 1e-12);
  EXPECT_TRUE(solver.is_source_side(0));
  EXPECT_FALSE(solver.is_source_side(1));
  // The other way around the reverse capacity counts.
  solver.set_terminal_capacity(0, 0, 10);
  solver.set_terminal_capacity(1, 10, 0);
  EXPECT_NEAR(solver.solve(), 9.0, 1e-12);
  EXPECT_TRUE(solver.is_source_side(1));
  EXPECT_FALSE(solver.is_source_side(0));

  // Reset to another graph: three isolated nodes choose their cheaper side.
  solver.reset(3);
  EXPECT_EQ(solver.number_of_nodes(), 3u);
  solver.set_terminal_capacity(0, 1, 2); // sink side costs 1, source side costs 2 -> sink
  solver.set_terminal_capacity(1, 3, 1); // -> source
  solver.set_terminal_capacity(2, 0, 0);
  EXPECT_NEAR(solver.solve(), 2.0, 1e-12);
  EXPECT_FALSE(solver.is_source_side(0));
  EXPECT_TRUE(solver.is_source_side(1));
}

TEST(MinCut, RejectsBadCapacities)
{
  SAI::Terminal_min_cut solver(2);
  solver.add_edge(0, 1, -1.0, 1.0);
  EXPECT_THROW(solver.solve(), SA::Bad_input);
  solver.set_edge_capacity(0, 1.0, 1.0);
  solver.set_terminal_capacity(1, std::numeric_limits<double>::quiet_NaN(), 0);
  EXPECT_THROW(solver.solve(), SA::Bad_input);
  solver.set_terminal_capacity(1, std::numeric_limits<double>::infinity(), 0);
  EXPECT_THROW(solver.solve(), SA::Bad_input);
  solver.set_terminal_capacity(1, 1, 0);
  EXPECT_NO_THROW(solver.solve());
}

// ---------------------------------------------------------------------------------------------
// Normalized-cut clustering

struct Small_graph
{
  std::vector<double> size;
  std::vector<std::uint32_t> source, target;
  std::vector<double> weight;
  void edge(std::uint32_t u, std::uint32_t v, double w)
  {
    source.push_back(u);
    target.push_back(v);
    weight.push_back(w);
  }
};

// Two 4-cliques (0..3 and 4..7) joined by the weak edge 3-4.
Small_graph two_cliques()
{
  Small_graph g;
  g.size.assign(8, 1.0);
  for(std::uint32_t base : {0u, 4u})
    for(std::uint32_t u = 0; u < 4; ++u)
      for(std::uint32_t v = u + 1; v < 4; ++v)
        g.edge(base + u, base + v, 1.0);
  g.edge(3, 4, 0.01);
  return g;
}

Small_graph random_grid(std::size_t side, std::uint64_t seed)
{
  SAI::Procedural_random rng(seed);
  Small_graph g;
  for(std::size_t i = 0; i < side * side; ++i)
    g.size.push_back(rng.uniform(0.5, 1.5));
  for(std::uint32_t r = 0; r < side; ++r)
    for(std::uint32_t c = 0; c < side; ++c) {
      const std::uint32_t u = r * std::uint32_t(side) + c;
      if(c + 1 < side)
        g.edge(u, u + 1, rng.uniform(0.01, 1.0));
      if(r + 1 < side)
        g.edge(u, u + std::uint32_t(side), rng.uniform(0.01, 1.0));
    }
  return g;
}

TEST(NormalizedCutClustering, TwoCliquesSplitAtTheWeakEdge)
{
  const Small_graph g = two_cliques();
  SAI::Normalized_cut_clustering c(g.size, g.source, g.target, g.weight);
  EXPECT_EQ(c.number_of_clusters(), 8u);
  c.run(2);
  EXPECT_EQ(c.number_of_clusters(), 2u);
  EXPECT_EQ(c.merges().size(), 6u);
  const std::vector<std::size_t> labels = c.labels();
  for(std::size_t i = 0; i < 8; ++i)
    EXPECT_EQ(labels[i], i < 4 ? 0u : 1u);
  const auto r0 = c.find(0), r1 = c.find(7);
  EXPECT_NEAR(c.cluster_cut(r0), 0.01, 1e-12);
  EXPECT_NEAR(c.cluster_size(r0) + c.cluster_size(r1), 8.0, 1e-12);
  ASSERT_EQ(c.neighbors(r0).size(), 1u);
  EXPECT_EQ(c.neighbors(r0)[0].first, r1);
  EXPECT_NEAR(c.neighbors(r0)[0].second, 0.01, 1e-12);
  // Then everything merges into one.
  c.run(1);
  EXPECT_EQ(c.number_of_clusters(), 1u);
  EXPECT_EQ(c.labels(), std::vector<std::size_t>(8, 0));
}

// Reference greedy: recompute every adjacent pair's change of J at every step.
std::vector<std::vector<std::size_t>> reference_greedy(const Small_graph& g)
{
  const std::size_t n = g.size.size();
  std::vector<std::size_t> label(n);
  std::iota(label.begin(), label.end(), std::size_t(0));
  std::vector<std::vector<std::size_t>> levels; // levels[k] = partition with n - k clusters
  levels.push_back(label);
  while(true) {
    std::map<std::size_t, double> size, cut;
    std::map<std::pair<std::size_t, std::size_t>, double> between;
    for(std::size_t i = 0; i < n; ++i)
      size[label[i]] += g.size[i];
    for(std::size_t e = 0; e < g.source.size(); ++e) {
      std::size_t a = label[g.source[e]], b = label[g.target[e]];
      if(a == b)
        continue;
      cut[a] += g.weight[e];
      cut[b] += g.weight[e];
      between[{(std::min)(a, b), (std::max)(a, b)}] += g.weight[e];
    }
    double best = std::numeric_limits<double>::infinity();
    std::pair<std::size_t, std::size_t> best_pair;
    for(const auto& p : between) {
      const std::size_t a = p.first.first, b = p.first.second;
      const double d = (cut[a] + cut[b] - 2 * p.second) / (size[a] + size[b]) - cut[a] / size[a] -
                       cut[b] / size[b];
      if(d < best) {
        best = d;
        best_pair = p.first;
      }
    }
    if(between.empty())
      break;
    for(auto& l : label)
      if(l == best_pair.second)
        l = best_pair.first;
    levels.push_back(label);
  }
  return levels;
}

TEST(NormalizedCutClustering, MatchesReferenceGreedyAtEveryLevel)
{
  for(std::uint64_t seed : {3u, 4u, 5u}) {
    const Small_graph g = random_grid(4, seed); // 16 nodes, random weights: no ties
    const auto levels = reference_greedy(g);
    ASSERT_EQ(levels.size(), 16u);
    for(std::size_t k = 1; k <= 16; ++k) {
      SAI::Normalized_cut_clustering c(g.size, g.source, g.target, g.weight);
      c.run(k);
      EXPECT_EQ(c.number_of_clusters(), k);
      EXPECT_EQ(SAI::rand_index(c.labels(), levels[16 - k]), 1.0)
        << "seed " << seed << ", " << k << " clusters";
    }
    // The recorded change of J of the first merge is the smallest over all edges.
    SAI::Normalized_cut_clustering c(g.size, g.source, g.target, g.weight);
    double best = std::numeric_limits<double>::infinity();
    for(std::size_t e = 0; e < g.source.size(); ++e)
      best = (std::min)(best, c.delta(g.source[e], g.target[e], g.weight[e]));
    c.run(15);
    ASSERT_EQ(c.merges().size(), 1u);
    EXPECT_DOUBLE_EQ(c.merges()[0].delta, best);
  }
}

TEST(NormalizedCutClustering, CanMergeConstraintIsHonoured)
{
  // A path 0-1-...-9; nodes 0 and 9 must not end in the same cluster (cannot-link tracked through
  // on_merge), and node 5 must stay alone.
  Small_graph g;
  g.size.assign(10, 1.0);
  for(std::uint32_t u = 0; u + 1 < 10; ++u)
    g.edge(u, u + 1, 1.0);
  SAI::Normalized_cut_clustering c(g.size, g.source, g.target, g.weight);
  std::vector<char> has0(10, 0), has9(10, 0);
  has0[0] = 1;
  has9[9] = 1;
  std::size_t calls = 0;
  auto can_merge = [&](std::uint32_t a, std::uint32_t b) {
    EXPECT_TRUE(c.is_cluster(a));
    EXPECT_TRUE(c.is_cluster(b));
    if(a == 5 || b == 5)
      return false;
    return !((has0[a] && has9[b]) || (has9[a] && has0[b]));
  };
  auto on_merge = [&](std::uint32_t survivor, std::uint32_t absorbed) {
    ++calls;
    EXPECT_TRUE(c.is_cluster(survivor));
    EXPECT_FALSE(c.is_cluster(absorbed));
    has0[survivor] = has0[survivor] || has0[absorbed];
    has9[survivor] = has9[survivor] || has9[absorbed];
  };
  c.run(1, can_merge, on_merge);
  // Node 5 alone cuts the path: {0..4}, {5}, {6..9}.
  EXPECT_EQ(c.number_of_clusters(), 3u);
  EXPECT_EQ(calls, 7u);
  EXPECT_EQ(c.merges().size(), 7u);
  EXPECT_NE(c.find(0), c.find(9));
  EXPECT_EQ(c.find(5), 5u);
  for(std::uint32_t u = 1; u < 5; ++u)
    EXPECT_EQ(c.find(u), c.find(0));
  for(std::uint32_t u = 6; u < 9; ++u)
    EXPECT_EQ(c.find(u), c.find(9));

  // Without node 5's constraint, the cannot-link alone stops at 2 clusters.
  SAI::Normalized_cut_clustering d(g.size, g.source, g.target, g.weight);
  std::fill(has0.begin(), has0.end(), 0);
  std::fill(has9.begin(), has9.end(), 0);
  has0[0] = has9[9] = 1;
  d.run(1,
        [&](std::uint32_t a, std::uint32_t b) { return !((has0[a] && has9[b]) || (has9[a] && has0[b])); },
        [&](std::uint32_t s, std::uint32_t t) {
          has0[s] = has0[s] || has0[t];
          has9[s] = has9[s] || has9[t];
        });
  EXPECT_EQ(d.number_of_clusters(), 2u);
  EXPECT_NE(d.find(0), d.find(9));
}

TEST(NormalizedCutClustering, RandomizedChoiceDependsOnlyOnTheSeed)
{
  const Small_graph g = random_grid(12, 17);
  auto run = [&](double randomness, unsigned seed) {
    SAI::Normalized_cut_clustering c(g.size, g.source, g.target, g.weight);
    c.run(6, {}, {}, randomness, seed);
    EXPECT_EQ(c.number_of_clusters(), 6u);
    return c.labels();
  };
  const auto a = run(1.0, 5);
  EXPECT_EQ(run(1.0, 5), a) << "same seed, same result";
  std::set<std::vector<std::size_t>> distinct;
  for(unsigned seed = 1; seed <= 8; ++seed)
    distinct.insert(run(1.0, seed));
  EXPECT_GE(distinct.size(), 3u) << "different seeds give different clusterings";
  // Without randomness the seed does not matter, and the result is the greedy one.
  const auto greedy = run(0.0, 1);
  EXPECT_EQ(run(0.0, 99), greedy);
  // A tiny randomness keeps the greedy choice when the changes of J are well apart.
  const Small_graph cliques = two_cliques();
  SAI::Normalized_cut_clustering c(cliques.size, cliques.source, cliques.target, cliques.weight);
  c.run(2, {}, {}, 1e-3, 42);
  EXPECT_NE(c.find(0), c.find(7));
}

TEST(NormalizedCutClustering, MergeGroupsActAsMustLink)
{
  // A path 0..9 whose cheapest edges are 1-2, 3-4, 5-6, 7-8 (the pairs' boundaries), grouped in
  // pairs {0,1}, {2,3}, ... by labels: the pairs must never be split.
  Small_graph g;
  g.size.assign(10, 1.0);
  for(std::uint32_t u = 0; u + 1 < 10; ++u)
    g.edge(u, u + 1, u % 2 == 1 ? 0.05 : 1.0);
  SAI::Normalized_cut_clustering c(g.size, g.source, g.target, g.weight);
  std::vector<int> groups(10);
  for(std::size_t i = 0; i < 10; ++i)
    groups[i] = 100 - int(i / 2); // arbitrary label values
  c.merge_groups(groups);
  EXPECT_EQ(c.number_of_clusters(), 5u);
  EXPECT_EQ(c.merges().size(), 5u);
  for(std::uint32_t i = 0; i < 10; i += 2) {
    EXPECT_EQ(c.find(i), c.find(i + 1));
    EXPECT_NEAR(c.cluster_size(c.find(i)), 2.0, 1e-12);
  }
  c.run(2);
  EXPECT_EQ(c.number_of_clusters(), 2u);
  const auto labels = c.labels();
  for(std::size_t i = 0; i < 10; i += 2)
    EXPECT_EQ(labels[i], labels[i + 1]);
  // The two clusters are contiguous runs of pairs.
  std::size_t changes = 0;
  for(std::size_t i = 0; i + 1 < 10; ++i)
    changes += labels[i] != labels[i + 1] ? 1 : 0;
  EXPECT_EQ(changes, 1u);
}

TEST(NormalizedCutClustering, SmallClustersMergeFirst)
{
  // A and B (size 1) joined by a strong edge, a speck T (tiny size) hanging on A by a near-zero
  // edge. Plain greedy merges A and B and leaves the speck alone; with small_size the speck goes
  // first.
  Small_graph g;
  g.size = {1.0, 1.0, 1e-6};
  g.edge(0, 1, 1.0);
  g.edge(0, 2, 1e-9);
  SAI::Normalized_cut_clustering plain(g.size, g.source, g.target, g.weight);
  plain.run(2);
  EXPECT_EQ(plain.find(0), plain.find(1));
  EXPECT_NE(plain.find(2), plain.find(0));
  SAI::Normalized_cut_clustering small(g.size, g.source, g.target, g.weight);
  small.run(2, {}, {}, 0.0, 0, 1e-3);
  EXPECT_EQ(small.find(2), small.find(0));
  EXPECT_NE(small.find(0), small.find(1));
}

TEST(NormalizedCutClustering, DisconnectedGraphStopsWhenNoPairIsLeft)
{
  Small_graph g;
  g.size.assign(4, 1.0);
  g.edge(0, 1, 1.0);
  g.edge(2, 3, 1.0);
  SAI::Normalized_cut_clustering c(g.size, g.source, g.target, g.weight);
  c.run(1);
  EXPECT_EQ(c.number_of_clusters(), 2u);
  EXPECT_EQ(c.labels(), (std::vector<std::size_t>{0, 0, 1, 1}));
}

// ---------------------------------------------------------------------------------------------
// Partition refinement

TEST(PartitionRefinement, NeverIncreasesTheNormalizedCut)
{
  for(std::uint64_t seed : {7u, 8u, 9u}) {
    const Small_graph g = random_grid(10, seed);
    SAI::Normalized_cut_clustering c(g.size, g.source, g.target, g.weight);
    c.run(4);
    std::vector<std::size_t> labels = c.labels();
    const double before = normalized_cut(g.size, g.source, g.target, g.weight, labels);
    SAI::multilevel_refinement(g.size, g.source, g.target, g.weight, c.merges(), labels);
    const double after = normalized_cut(g.size, g.source, g.target, g.weight, labels);
    EXPECT_LE(after, before + 1e-12) << "seed " << seed;
    std::set<std::size_t> used(labels.begin(), labels.end());
    EXPECT_EQ(used.size(), 4u) << "no segment disappears";
  }
  // A path whose greedy boundary is off by one node gets straightened: 0-1-2-3 | 4-5 with the
  // cheap edge between 2 and 3.
  Small_graph p;
  p.size.assign(6, 1.0);
  const double w[5] = {1, 1, 0.01, 1, 1};
  for(std::uint32_t u = 0; u < 5; ++u)
    p.edge(u, u + 1, w[u]);
  std::vector<std::size_t> labels = {0, 0, 0, 0, 1, 1};
  SAI::Weighted_graph q = SAI::quotient_graph(p.size, p.source, p.target, p.weight,
                                              {0, 1, 2, 3, 4, 5}, 6);
  std::vector<std::size_t> segment = labels;
  EXPECT_GE(SAI::move_units(q, segment, 2, 8), 1u);
  EXPECT_EQ(segment, (std::vector<std::size_t>{0, 0, 0, 1, 1, 1}));
}

// ---------------------------------------------------------------------------------------------
// Component links

struct Linked_graph
{
  SAI::Labelled_triangle_mesh lm;
  SAI::Dual_graph g;
  std::vector<std::uint32_t> component; // before linking
  std::size_t mesh_edges = 0;           // graph edges before linking
  double mean_cut = 0;
};

Linked_graph boxes_graph(std::size_t n, double gap, double cell)
{
  Linked_graph r;
  r.lm = SAI::mesh_procedural_shape(SAI::separate_boxes(n, gap), cell);
  const Mesh m = to_surface_mesh(r.lm);
  build_graph(m, 10, r.g);
  SAI::graph_components(r.g, r.component);
  r.mesh_edges = r.g.number_of_edges();
  double sum = 0;
  for(double c : r.g.cut_cost)
    sum += c;
  r.mean_cut = sum / double(r.mesh_edges);
  return r;
}

void expect_link_costs(const Linked_graph& r, const SAI::Component_link_options& o, std::size_t e)
{
  const double D = r.g.bbox_diagonal;
  const double d = (r.g.node_position[r.g.edge_source[e]] - r.g.node_position[r.g.edge_target[e]]).length();
  const double d_eps = o.epsilon * D;
  const double d1 = 1.2 * (d + d_eps);
  const double d2 = d1 / d_eps;
  EXPECT_EQ(r.g.mesh_edge[e], SAI::Dual_graph::no_mesh_edge);
  EXPECT_EQ(r.g.edge_length[e], 0.0);
  EXPECT_NEAR(r.g.traversal_cost[e], d1, 1e-12 * d1);
  const double cut = o.factor * r.mean_cut / (1 + d2);
  EXPECT_NEAR(r.g.cut_cost[e], cut, 1e-9 * cut);
  EXPECT_NE(r.component[r.g.edge_source[e]], r.component[r.g.edge_target[e]]);
}

TEST(ComponentLinks, FarComponentsAreJoinedByASpanningTree)
{
  Linked_graph r = boxes_graph(3, 3.0, 0.15);
  std::vector<std::uint32_t> comp;
  ASSERT_EQ(SAI::graph_components(r.g, comp), 3u);
  // The components are the boxes.
  ASSERT_EQ(SAI::rand_index(comp, r.lm.labels), 1.0);
  const SAI::Component_link_options options;
  // The gap (3) is more than 0.1 of the diagonal: no proximity link, only the tree.
  ASSERT_GT(3.0, options.link_distance * r.g.bbox_diagonal);
  EXPECT_EQ(SAI::add_component_links(r.g, options), 3u);
  EXPECT_EQ(SAI::graph_components(r.g, comp), 1u);
  ASSERT_EQ(r.g.number_of_edges(), r.mesh_edges + 2);
  std::set<std::pair<std::uint32_t, std::uint32_t>> joined;
  for(std::size_t e = r.mesh_edges; e < r.g.number_of_edges(); ++e) {
    expect_link_costs(r, options, e);
    const auto a = std::uint32_t(r.lm.labels[r.g.edge_source[e]]);
    const auto b = std::uint32_t(r.lm.labels[r.g.edge_target[e]]);
    joined.insert({(std::min)(a, b), (std::max)(a, b)});
    // The link spans the gap between neighbouring boxes (3), never a whole box (about 1 wide).
    const double d = (r.g.node_position[r.g.edge_source[e]] - r.g.node_position[r.g.edge_target[e]]).length();
    EXPECT_GT(d, 3.0 - 0.05);
    EXPECT_LT(d, 3.0 + 1.0);
  }
  EXPECT_EQ(joined, (std::set<std::pair<std::uint32_t, std::uint32_t>>{{0, 1}, {1, 2}}));
  // The adjacency was rebuilt with the links.
  EXPECT_EQ(r.g.first_arc.back(), 2 * r.g.number_of_edges());
}

TEST(ComponentLinks, CloseComponentsGetProximityLinks)
{
  Linked_graph r = boxes_graph(2, 0.1, 0.12);
  const SAI::Component_link_options options;
  const double radius = options.link_distance * r.g.bbox_diagonal;
  ASSERT_LT(0.1, radius);
  EXPECT_EQ(SAI::add_component_links(r.g, options), 2u);
  std::vector<std::uint32_t> comp;
  EXPECT_EQ(SAI::graph_components(r.g, comp), 1u);
  std::set<std::pair<std::uint32_t, std::uint32_t>> links;
  for(std::size_t e = r.mesh_edges; e < r.g.number_of_edges(); ++e) {
    expect_link_costs(r, options, e);
    const double d = (r.g.node_position[r.g.edge_source[e]] - r.g.node_position[r.g.edge_target[e]]).length();
    EXPECT_LT(d, radius);
    const std::uint32_t a = r.g.edge_source[e], b = r.g.edge_target[e];
    EXPECT_TRUE(links.insert({(std::min)(a, b), (std::max)(a, b)}).second) << "no duplicate link";
  }
  // Brute force: every face closer than the radius to the other box is linked to its nearest
  // face there.
  const std::size_t n = r.g.number_of_nodes();
  std::size_t expected_faces = 0;
  for(std::uint32_t f = 0; f < n; ++f) {
    double best = std::numeric_limits<double>::infinity();
    std::uint32_t nearest = 0;
    for(std::uint32_t h = 0; h < n; ++h)
      if(r.component[h] != r.component[f]) {
        const double d = (r.g.node_position[f] - r.g.node_position[h]).squared_length();
        if(d < best) {
          best = d;
          nearest = h;
        }
      }
    if(best < radius * radius) {
      ++expected_faces;
      EXPECT_EQ(links.count({(std::min)(f, nearest), (std::max)(f, nearest)}), 1u) << "face " << f;
    }
  }
  EXPECT_GT(expected_faces, 100u);
  EXPECT_LE(links.size(), expected_faces);
  EXPECT_GE(2 * links.size(), expected_faces);

  // Links are much cheaper to cut than mesh edges.
  for(std::size_t e = r.mesh_edges; e < r.g.number_of_edges(); ++e)
    EXPECT_LT(r.g.cut_cost[e], 0.01 * r.mean_cut);
}

TEST(ComponentLinks, OptionsChangeDistanceAndCost)
{
  // Without proximity links, two close boxes get one spanning link.
  Linked_graph r = boxes_graph(2, 0.1, 0.12);
  SAI::Component_link_options options;
  options.link_distance = 0;
  options.factor = 0.5;
  options.epsilon = 0.02;
  EXPECT_EQ(SAI::add_component_links(r.g, options), 2u);
  ASSERT_EQ(r.g.number_of_edges(), r.mesh_edges + 1);
  expect_link_costs(r, options, r.mesh_edges);

  // One component: nothing to do.
  const Mesh cube = unit_cube();
  SAI::Dual_graph g;
  build_graph(cube, 10, g);
  EXPECT_EQ(SAI::add_component_links(g, SAI::Component_link_options()), 1u);
  EXPECT_EQ(g.number_of_edges(), 18u);
}

TEST(PointTree, NearestMatchesBruteForce)
{
  SAI::Procedural_random rng(3);
  std::vector<Vector_3d> points;
  std::vector<std::uint32_t> ids;
  for(std::uint32_t i = 0; i < 500; ++i) {
    points.emplace_back(rng.uniform(), rng.uniform(), rng.uniform());
    ids.push_back(1000 + i);
  }
  const SAI::Point_tree tree(points, ids);
  for(int q = 0; q < 200; ++q) {
    const Vector_3d p(rng.uniform(-0.2, 1.2), rng.uniform(-0.2, 1.2), rng.uniform(-0.2, 1.2));
    double best = std::numeric_limits<double>::infinity();
    std::uint32_t best_i = 0;
    for(std::uint32_t i = 0; i < points.size(); ++i)
      if((points[i] - p).squared_length() < best) {
        best = (points[i] - p).squared_length();
        best_i = i;
      }
    std::uint32_t id = 0;
    double d2 = 0;
    ASSERT_TRUE(tree.nearest(p, std::numeric_limits<double>::infinity(), id, d2));
    EXPECT_EQ(id, ids[best_i]);
    EXPECT_EQ(d2, best);
    // With a radius below the nearest distance there is nothing.
    EXPECT_FALSE(tree.nearest(p, best * 0.99, id, d2));
  }
  std::uint32_t id = 0;
  double d2 = 0;
  EXPECT_FALSE(SAI::Point_tree().nearest(Vector_3d(), 1.0, id, d2)) << "an empty tree has no nearest";
}

TEST(PointTree, KNearestMatchesBruteForce)
{
  SAI::Procedural_random rng(5);
  std::vector<Vector_3d> points;
  std::vector<std::uint32_t> ids;
  for(std::uint32_t i = 0; i < 300; ++i) {
    points.emplace_back(rng.uniform(), rng.uniform(), rng.uniform());
    ids.push_back(7 * i + 1);
  }
  const SAI::Point_tree tree(points, ids);
  std::vector<std::pair<double, std::uint32_t>> result;
  for(std::size_t k : {1u, 5u, 17u, 400u}) {
    for(int q = 0; q < 50; ++q) {
      const Vector_3d p(rng.uniform(-0.2, 1.2), rng.uniform(-0.2, 1.2), rng.uniform(-0.2, 1.2));
      std::vector<std::pair<double, std::uint32_t>> expected;
      for(std::uint32_t i = 0; i < points.size(); ++i)
        expected.emplace_back((points[i] - p).squared_length(), ids[i]);
      std::sort(expected.begin(), expected.end());
      expected.resize((std::min)(k, expected.size()));
      tree.k_nearest(p, k, result);
      ASSERT_EQ(result.size(), expected.size());
      for(std::size_t j = 0; j < expected.size(); ++j) {
        EXPECT_EQ(result[j].first, expected[j].first) << "k " << k << " rank " << j;
        EXPECT_EQ(result[j].second, expected[j].second) << "k " << k << " rank " << j;
      }
    }
  }
  SAI::Point_tree().k_nearest(Vector_3d(), 3, result);
  EXPECT_TRUE(result.empty());
}

// Boxes (segments) around random points: the nearest segment through the hierarchy is the one a
// brute-force scan finds, before and after the segments move and the boxes are refitted.
TEST(Bvh, NearestMatchesBruteForceAfterRefit)
{
  SAI::Procedural_random rng(7);
  const std::size_t n = 700;
  std::vector<Vector_3d> a(n), b(n);
  for(std::size_t i = 0; i < n; ++i) {
    a[i] = Vector_3d(rng.uniform(), rng.uniform(), rng.uniform());
    b[i] = a[i] + Vector_3d(rng.uniform(-0.05, 0.05), rng.uniform(-0.05, 0.05), rng.uniform(-0.05, 0.05));
  }
  // The squared distance from q to segment i.
  const auto distance = [&](std::size_t i, const Vector_3d& q) {
    const Vector_3d d = b[i] - a[i];
    const double t = (std::max)(0.0, (std::min)(1.0, SAI::dot(q - a[i], d) / d.squared_length()));
    return (a[i] + d * t - q).squared_length();
  };
  const auto box_of = [&](std::uint32_t i) {
    SAI::Bvh::Box box;
    box.extend(a[i]);
    box.extend(b[i]);
    return box;
  };
  std::vector<Vector_3d> centers(n);
  for(std::size_t i = 0; i < n; ++i)
    centers[i] = (a[i] + b[i]) * 0.5;
  SAI::Bvh bvh(centers, box_of);
  EXPECT_EQ(bvh.size(), n);
  for(int round = 0; round < 2; ++round) {
    if(round == 1) { // every segment moves (up to a fifth of the cube): the tree no longer fits well
      for(std::size_t i = 0; i < n; ++i) {
        const Vector_3d m(rng.uniform(-0.2, 0.2), rng.uniform(-0.2, 0.2), rng.uniform(-0.2, 0.2));
        a[i] += m;
        b[i] += m;
      }
      bvh.refit(box_of);
    }
    for(int k = 0; k < 300; ++k) {
      const Vector_3d q(rng.uniform(-0.3, 1.3), rng.uniform(-0.3, 1.3), rng.uniform(-0.3, 1.3));
      double expected = std::numeric_limits<double>::infinity();
      for(std::size_t i = 0; i < n; ++i)
        expected = (std::min)(expected, distance(i, q));
      std::size_t visited = 0;
      const double found = bvh.nearest(q, std::numeric_limits<double>::infinity(), [&](std::uint32_t j, double& best) {
        ++visited;
        best = (std::min)(best, distance(bvh.item(j), q));
      });
      EXPECT_EQ(found, expected) << "round " << round << " query " << k;
      EXPECT_LT(visited, n) << "the boxes prune";
      // A bound below the nearest distance finds nothing closer.
      EXPECT_EQ(bvh.nearest(q, 0.5 * expected, [&](std::uint32_t j, double& best) {
                  best = (std::min)(best, distance(bvh.item(j), q));
                }),
                0.5 * expected);
    }
  }
  EXPECT_TRUE(SAI::Bvh().empty());
  EXPECT_EQ(SAI::Bvh().nearest(Vector_3d(), 1.0, [](std::uint32_t, double&) {}), 1.0);
}

// ---------------------------------------------------------------------------------------------
// Mesh checks

TEST(MeshChecks, RefuseEmptyPolygonalAndNonFiniteMeshes)
{
  const SAI::Point_to_vector<Kernel> to_vector{};
  Mesh empty;
  try {
    SAI::check_triangle_mesh(empty, get(CGAL::vertex_point, empty), to_vector, "who");
    FAIL() << "no exception";
  } catch(const SA::Bad_input& e) {
    EXPECT_NE(std::string(e.what()).find("who"), std::string::npos);
    EXPECT_NE(std::string(e.what()).find("no faces"), std::string::npos);
  }
  Mesh quad = make_mesh({Point(0, 0, 0), Point(1, 0, 0), Point(1, 1, 0), Point(0, 1, 0)}, {{0, 1, 2, 3}});
  EXPECT_THROW(SAI::check_triangle_mesh(quad, get(CGAL::vertex_point, quad), to_vector, "who"), SA::Bad_input);
  Mesh cube = unit_cube();
  EXPECT_NO_THROW(SAI::check_triangle_mesh(cube, get(CGAL::vertex_point, cube), to_vector, "who"));
  cube.point(*vertices(cube).begin()) = Point(std::numeric_limits<double>::quiet_NaN(), 0, 0);
  try {
    SAI::check_triangle_mesh(cube, get(CGAL::vertex_point, cube), to_vector, "who");
    FAIL() << "no exception";
  } catch(const SA::Bad_input& e) {
    EXPECT_NE(std::string(e.what()).find("finite"), std::string::npos);
  }
  // A non-finite vertex that no face uses is not looked at.
  Mesh tetra = unit_cube();
  tetra.add_vertex(Point(std::numeric_limits<double>::infinity(), 0, 0));
  EXPECT_NO_THROW(SAI::check_triangle_mesh(tetra, get(CGAL::vertex_point, tetra), to_vector, "who"));
}

// ---------------------------------------------------------------------------------------------
// JSON

TEST(Json, DumpsObjectsArraysAndEscapes)
{
  SAI::Json j = SAI::Json::object();
  j["name"] = "a\"b\\c\nd\te\x01";
  j["count"] = 3;
  j["size"] = std::size_t(12);
  j["ratio"] = 0.5;
  j["whole"] = 2.0;
  j["huge"] = 1e20;
  j["third"] = 1.0 / 3.0;
  j["nan"] = std::numeric_limits<double>::quiet_NaN();
  j["flag"] = true;
  j["none"] = nullptr;
  j["list"] = std::vector<int>{1, 2, 3};
  j["empty"] = SAI::Json::array();
  j["nested"]["inner"] = false;
  j["nested"]["inner"] = "again"; // the same member, replaced
  SAI::Json rows = SAI::Json::array();
  SAI::Json row;
  row["k"] = -4;
  rows.push_back(row);
  rows.push_back(SAI::Json::object());
  j["rows"] = rows;

  EXPECT_EQ(j.dump(0),
            "{\"name\":\"a\\\"b\\\\c\\nd\\te\\u0001\",\"count\":3,\"size\":12,\"ratio\":0.5,"
            "\"whole\":2,\"huge\":1e+20,\"third\":0.3333333333,\"nan\":null,\"flag\":true,"
            "\"none\":null,\"list\":[1, 2, 3],\"empty\":[],\"nested\":{\"inner\":\"again\"},"
            "\"rows\":[{\"k\":-4},{}]}");

  SAI::Json small = SAI::Json::object();
  small["a"] = 1;
  small["b"]["c"] = std::vector<double>{0.25};
  small["d"] = SAI::Json::array();
  small["d"].push_back(SAI::Json::object());
  small["d"].push_back(SAI::Json(std::vector<int>{}));
  EXPECT_EQ(small.dump(2),
            "{\n"
            "  \"a\": 1,\n"
            "  \"b\": {\n"
            "    \"c\": [0.25]\n"
            "  },\n"
            "  \"d\": [\n"
            "    {},\n"
            "    []\n"
            "  ]\n"
            "}");
  EXPECT_EQ(SAI::Json().dump(), "null");
  EXPECT_EQ(SAI::Json(-7LL).dump(), "-7");
}

// ---------------------------------------------------------------------------------------------
// Procedural shapes

void expect_closed_manifold(const SAI::Labelled_triangle_mesh& lm, std::size_t components)
{
  ASSERT_EQ(lm.labels.size(), lm.triangles.size());
  Mesh m;
  ASSERT_NO_THROW(SAI::fill_polygon_mesh(lm, m));
  EXPECT_EQ(num_faces(m), lm.triangles.size());
  EXPECT_TRUE(m.is_valid(false));
  EXPECT_TRUE(CGAL::is_closed(m));
  EXPECT_TRUE(CGAL::is_triangle_mesh(m));
  EXPECT_EQ(SAI::number_of_components(lm), components);
  EXPECT_TRUE(PMP::is_outward_oriented(m));
  EXPECT_GT(PMP::volume(m), 0.0);
  // Every vertex is used and no triangle repeats a vertex.
  std::vector<char> used(lm.points.size(), 0);
  for(const auto& t : lm.triangles) {
    EXPECT_TRUE(t[0] != t[1] && t[1] != t[2] && t[0] != t[2]);
    for(std::size_t v : t)
      used[v] = 1;
  }
  EXPECT_EQ(std::count(used.begin(), used.end(), 0), 0);
}

TEST(ProceduralShapes, ClosedManifoldsWithEveryPartLabelled)
{
  struct Case
  {
    const char* name;
    SAI::Procedural_shape shape;
    double cell;
    std::size_t components;
  };
  const std::vector<Case> cases = {{"chain", SAI::three_sphere_chain(), 0.2, 1},
                                   {"chain seed 3", SAI::three_sphere_chain(3), 0.2, 1},
                                   {"body", SAI::body_with_limbs(), 0.15, 1},
                                   {"body with head", SAI::body_with_limbs(2, true), 0.15, 1},
                                   {"star", SAI::star(6), 0.17, 1},
                                   {"star 9", SAI::star(9, 4), 0.17, 1},
                                   {"boxes", SAI::separate_boxes(4), 0.15, 4}};
  const std::vector<std::size_t> labels = {3, 3, 5, 6, 7, 10, 4};
  for(std::size_t c = 0; c < cases.size(); ++c) {
    SCOPED_TRACE(cases[c].name);
    const SAI::Labelled_triangle_mesh lm = SAI::mesh_procedural_shape(cases[c].shape, cases[c].cell);
    EXPECT_EQ(lm.number_of_labels, labels[c]);
    EXPECT_GT(lm.number_of_faces(), 1000u);
    EXPECT_LT(lm.number_of_faces(), 20000u);
    expect_closed_manifold(lm, cases[c].components);
    std::vector<std::size_t> count(lm.number_of_labels, 0);
    for(std::size_t l : lm.labels) {
      ASSERT_LT(l, lm.number_of_labels);
      ++count[l];
    }
    for(std::size_t l = 0; l < count.size(); ++l)
      EXPECT_GT(count[l], 50u) << "label " << l;
    // The surface lies on the zero set of the field (within a fraction of a cell).
    for(const auto& p : lm.points)
      EXPECT_LT(std::abs(cases[c].shape.field(Vector_3d(p[0], p[1], p[2]))), 0.5 * cases[c].cell);
  }
}

TEST(ProceduralShapes, SphereAreaAndVolumeConverge)
{
  SAI::Procedural_shape s;
  s.add(SAI::Shape_primitive::sphere(Vector_3d(0.3, -0.2, 0.1), 1.0, 0));
  const SAI::Labelled_triangle_mesh lm = SAI::mesh_procedural_shape(s, 0.1);
  const Mesh m = to_surface_mesh(lm);
  EXPECT_NEAR(PMP::volume(m), 4.0 / 3.0 * CGAL_PI, 0.02 * 4.0 / 3.0 * CGAL_PI);
  EXPECT_NEAR(PMP::area(m), 4 * CGAL_PI, 0.03 * 4 * CGAL_PI);
  // Primitive distances.
  EXPECT_NEAR(SAI::Shape_primitive::capsule(Vector_3d(0, 0, 0), Vector_3d(2, 0, 0), 0.5, 0)
                .distance(Vector_3d(1, 1, 0)), 0.5, 1e-12);
  EXPECT_NEAR(SAI::Shape_primitive::box(Vector_3d(0, 0, 0), Vector_3d(1, 2, 3), 0)
                .distance(Vector_3d(0, 0, 0)), -1.0, 1e-12);
  EXPECT_NEAR(SAI::Shape_primitive::box(Vector_3d(0, 0, 0), Vector_3d(1, 1, 1), 0, 0.25)
                .distance(Vector_3d(2, 2, 0)), std::sqrt(2 * 1.25 * 1.25) - 0.25, 1e-12);
  EXPECT_NEAR(SAI::Shape_primitive::cylinder(Vector_3d(0, 0, 0), Vector_3d(0, 0, 2), 1, 0)
                .distance(Vector_3d(0, 0, 3)), 1.0, 1e-12);
  EXPECT_NEAR(SAI::Shape_primitive::cylinder(Vector_3d(0, 0, 0), Vector_3d(0, 0, 2), 1, 0)
                .distance(Vector_3d(3, 0, 1)), 2.0, 1e-12);
}

TEST(ProceduralShapes, DeterministicTransformsAndShuffles)
{
  const SAI::Labelled_triangle_mesh a = SAI::mesh_procedural_shape(SAI::body_with_limbs(5), 0.15);
  const SAI::Labelled_triangle_mesh b = SAI::mesh_procedural_shape(SAI::body_with_limbs(5), 0.15);
  EXPECT_EQ(a.points, b.points);
  EXPECT_EQ(a.triangles, b.triangles);
  EXPECT_EQ(a.labels, b.labels);
  const SAI::Labelled_triangle_mesh c = SAI::mesh_procedural_shape(SAI::body_with_limbs(6), 0.15);
  EXPECT_NE(a.points, c.points) << "another seed, another shape";

  // Rigid transform: areas and labels are kept, the rotation is orthonormal.
  SAI::Labelled_triangle_mesh t = a;
  const auto transform = SAI::Rigid_transform::from_axis_angle(Vector_3d(1, 2, 3), 0.7, Vector_3d(5, -1, 2));
  SAI::transform_points(t, transform);
  for(int i = 0; i < 3; ++i)
    for(int j = 0; j < 3; ++j)
      EXPECT_NEAR(SAI::dot(transform.rotation[i], transform.rotation[j]), i == j ? 1.0 : 0.0, 1e-12);
  EXPECT_NEAR(SAI::dot(SAI::cross(transform.rotation[0], transform.rotation[1]), transform.rotation[2]), 1.0, 1e-12);
  for(std::size_t f = 0; f < a.number_of_faces(); f += 97)
    EXPECT_NEAR(t.area(f), a.area(f), 1e-12);
  expect_closed_manifold(t, 1);

  // Shuffle: a permutation, same labels per triangle, reproducible from the seed.
  SAI::Labelled_triangle_mesh s = a;
  const std::vector<std::size_t> order = SAI::shuffle_faces(s, 21, true);
  std::vector<std::size_t> sorted = order;
  std::sort(sorted.begin(), sorted.end());
  for(std::size_t i = 0; i < sorted.size(); ++i)
    ASSERT_EQ(sorted[i], i);
  std::size_t moved = 0;
  for(std::size_t i = 0; i < order.size(); ++i) {
    moved += order[i] != i ? 1 : 0;
    EXPECT_EQ(s.labels[i], a.labels[order[i]]);
    std::array<std::size_t, 3> x = s.triangles[i], y = a.triangles[order[i]];
    // Same oriented triangle, possibly another first corner.
    std::rotate(x.begin(), std::min_element(x.begin(), x.end()), x.end());
    std::rotate(y.begin(), std::min_element(y.begin(), y.end()), y.end());
    EXPECT_EQ(x, y);
  }
  EXPECT_GT(moved, order.size() / 2);
  SAI::Labelled_triangle_mesh s2 = a;
  EXPECT_EQ(SAI::shuffle_faces(s2, 21, true), order);
  EXPECT_EQ(s2.triangles, s.triangles);
  expect_closed_manifold(s, 1);
}

TEST(ProceduralShapes, PartitionAgreementMeasures)
{
  const std::vector<int> a = {0, 0, 0, 1, 1, 2};
  EXPECT_EQ(SAI::rand_index(a, a), 1.0);
  EXPECT_EQ(SAI::rand_index(a, std::vector<int>{5, 5, 5, 3, 3, 9}), 1.0); // relabelled
  EXPECT_EQ(SAI::matched_overlap(a, std::vector<int>{5, 5, 5, 3, 3, 9}), 1.0);
  // 15 pairs; {0,0,0,1,1,2} vs all-in-one: agree on the 3 + 1 same pairs: 4/15.
  EXPECT_NEAR(SAI::rand_index(a, std::vector<int>(6, 0)), 4.0 / 15.0, 1e-15);
  EXPECT_NEAR(SAI::matched_overlap(a, std::vector<int>(6, 0)), 3.0 / 6.0, 1e-15);
  // Moving one item: pairs (item 2 with 0, 1, 3, 4) change: 11/15.
  EXPECT_NEAR(SAI::rand_index(a, std::vector<int>{0, 0, 1, 1, 1, 2}), 11.0 / 15.0, 1e-15);
  EXPECT_NEAR(SAI::matched_overlap(a, std::vector<int>{0, 0, 1, 1, 1, 2}), 5.0 / 6.0, 1e-15);
  // Weights.
  const std::vector<double> w = {1, 1, 1, 1, 1, 5};
  EXPECT_NEAR(SAI::matched_overlap(a, std::vector<int>{0, 0, 1, 1, 1, 2}, &w), 9.0 / 10.0, 1e-15);
  EXPECT_EQ(SAI::rand_index(a, a, &w), 1.0);
  EXPECT_THROW(SAI::rand_index(a, std::vector<int>{0}), std::invalid_argument);
}

// ---------------------------------------------------------------------------------------------
// Boykov-Kolmogorov max-flow between two nodes, shortest paths, induced subgraphs

// A directed graph in compressed rows where every arc has a reverse arc (its own capacity).
struct Arc_graph
{
  std::size_t n = 0;
  std::vector<std::size_t> first;
  std::vector<std::uint32_t> target, reverse, tail;

  // Undirected pairs, each giving the arcs u->v and v->u.
  Arc_graph(std::size_t nodes, const std::vector<std::pair<std::uint32_t, std::uint32_t>>& pairs) : n(nodes)
  {
    std::vector<std::vector<std::pair<std::uint32_t, std::size_t>>> out(n); // (target, slot)
    for(std::size_t p = 0; p < pairs.size(); ++p) {
      out[pairs[p].first].emplace_back(pairs[p].second, 2 * p);
      out[pairs[p].second].emplace_back(pairs[p].first, 2 * p + 1);
    }
    std::vector<std::uint32_t> arc_of_slot(2 * pairs.size());
    first.assign(1, 0);
    for(std::uint32_t u = 0; u < n; ++u) {
      for(const auto& a : out[u]) {
        arc_of_slot[a.second] = static_cast<std::uint32_t>(target.size());
        target.push_back(a.first);
        tail.push_back(u);
      }
      first.push_back(target.size());
    }
    reverse.resize(target.size());
    for(std::size_t p = 0; p < pairs.size(); ++p) {
      reverse[arc_of_slot[2 * p]] = arc_of_slot[2 * p + 1];
      reverse[arc_of_slot[2 * p + 1]] = arc_of_slot[2 * p];
    }
  }

  // Capacity of the arcs leaving the node set `side` (true) to the rest.
  double cut(const std::vector<double>& capacity, const std::vector<bool>& side) const
  {
    double c = 0;
    for(std::size_t a = 0; a < target.size(); ++a)
      if(side[tail[a]] && !side[target[a]])
        c += capacity[a];
    return c;
  }
};

TEST(MaxFlow, MatchesBruteForceOnRandomDirectedGraphs)
{
  SAI::Bk_max_flow::Workspace w; // reused across problems of different sizes
  for(std::uint64_t seed = 1; seed <= 300; ++seed) {
    SAI::Procedural_random rng(seed);
    const std::size_t n = 2 + rng.index(10); // 2..11 nodes
    std::vector<std::pair<std::uint32_t, std::uint32_t>> pairs;
    for(std::uint32_t u = 0; u < n; ++u)
      for(std::uint32_t v = u + 1; v < n; ++v)
        if(rng.uniform() < 0.5)
          pairs.emplace_back(u, v);
    const Arc_graph g(n, pairs);
    std::vector<double> capacity(g.target.size());
    for(double& c : capacity) // zeros, ties and one-way arcs included
      c = rng.uniform() < 0.25 ? 0.0 : double(1 + rng.index(6));
    const std::uint32_t s = static_cast<std::uint32_t>(rng.index(n));
    std::uint32_t t = static_cast<std::uint32_t>(rng.index(n));
    if(t == s)
      t = static_cast<std::uint32_t>((s + 1) % n);
    SAI::Bk_max_flow flow(g.first, g.target, g.reverse);
    const double value = flow.solve(capacity, s, t, w);
    double best = std::numeric_limits<double>::infinity();
    std::vector<bool> side(n);
    for(std::uint32_t mask = 0; mask < (1u << n); ++mask) {
      if(!((mask >> s) & 1u) || ((mask >> t) & 1u))
        continue;
      for(std::size_t u = 0; u < n; ++u)
        side[u] = (mask >> u) & 1u;
      best = (std::min)(best, g.cut(capacity, side));
    }
    ASSERT_EQ(value, best) << "seed " << seed; // integer capacities: exact
    for(std::size_t u = 0; u < n; ++u)
      side[u] = SAI::Bk_max_flow::is_source_side(w, u);
    EXPECT_TRUE(side[s]);
    EXPECT_FALSE(side[t]);
    EXPECT_EQ(g.cut(capacity, side), best) << "seed " << seed << ": the sides realize the minimum";

    // Larger capacities: the flow continues from the last one and reaches the new maximum.
    std::vector<double> larger(capacity);
    for(double& c : larger)
      c += rng.uniform() < 0.5 ? 0.0 : double(rng.index(4));
    const double added = flow.solve_with_larger_capacities(capacity, larger, s, t, w);
    double best_larger = std::numeric_limits<double>::infinity();
    for(std::uint32_t mask = 0; mask < (1u << n); ++mask) {
      if(!((mask >> s) & 1u) || ((mask >> t) & 1u))
        continue;
      for(std::size_t u = 0; u < n; ++u)
        side[u] = (mask >> u) & 1u;
      best_larger = (std::min)(best_larger, g.cut(larger, side));
    }
    ASSERT_EQ(value + added, best_larger) << "seed " << seed;
    for(std::size_t u = 0; u < n; ++u)
      side[u] = SAI::Bk_max_flow::is_source_side(w, u);
    EXPECT_EQ(g.cut(larger, side), best_larger) << "seed " << seed;
  }
}

// The maximum flow from s to t of an undirected graph (capacity c both ways) by Boost's
// push-relabel: a reference computed by another algorithm and another implementation.
double boost_push_relabel_flow(std::size_t n, const std::vector<std::uint32_t>& from, const std::vector<std::uint32_t>& to,
                               const std::vector<double>& capacity, std::size_t s, std::size_t t)
{
  typedef boost::adjacency_list_traits<boost::vecS, boost::vecS, boost::directedS> Traits;
  typedef boost::adjacency_list<
    boost::vecS, boost::vecS, boost::directedS, boost::no_property,
    boost::property<boost::edge_capacity_t, double,
                    boost::property<boost::edge_residual_capacity_t, double,
                                    boost::property<boost::edge_reverse_t, Traits::edge_descriptor>>>>
    Graph;
  Graph g(n);
  auto cap = get(boost::edge_capacity, g);
  auto rev = get(boost::edge_reverse, g);
  for(std::size_t e = 0; e < from.size(); ++e) {
    const auto a = boost::add_edge(from[e], to[e], g).first, b = boost::add_edge(to[e], from[e], g).first;
    cap[a] = cap[b] = capacity[e];
    rev[a] = b, rev[b] = a;
  }
  return boost::push_relabel_max_flow(g, boost::vertex(s, g), boost::vertex(t, g));
}

TEST(MaxFlow, AgreesWithBoostOnAMeshDualGraph)
{
  // Many cuts on the dual graph of a real shape, with random capacities: the flow value of our
  // solver equals the one of Boost's push-relabel, and its sides realize it.
  const SAI::Labelled_triangle_mesh lm = SAI::mesh_procedural_shape(SAI::three_sphere_chain(), 0.3);
  Mesh m;
  SAI::fill_polygon_mesh(lm, m);
  SAI::Dual_graph g;
  SAI::build_dual_graph(m, get(CGAL::vertex_point, m), get(CGAL::face_index, m), 10.0, g);
  SAI::Dual_graph_min_cut ours(g);
  SAI::Dual_graph_min_cut::Workspace w;
  SAI::Procedural_random rng(11);
  std::vector<double> capacity(g.number_of_edges());
  for(int round = 0; round < 25; ++round) {
    for(double& c : capacity)
      c = round % 2 == 0 ? rng.uniform(0, 1) : std::pow(rng.uniform(), 8.0);
    const std::size_t s = rng.index(g.number_of_nodes());
    std::size_t t = rng.index(g.number_of_nodes());
    if(t == s)
      t = (s + 1) % g.number_of_nodes();
    const double expected = boost_push_relabel_flow(g.number_of_nodes(), g.edge_source, g.edge_target, capacity, s, t);
    const double value = ours.solve(capacity, s, t, w);
    EXPECT_NEAR(value, expected, 1e-9 * (1 + expected)) << "round " << round;
    double across = 0;
    for(std::size_t e = 0; e < g.number_of_edges(); ++e)
      if(SAI::Dual_graph_min_cut::is_source_side(w, g.edge_source[e]) !=
         SAI::Dual_graph_min_cut::is_source_side(w, g.edge_target[e]))
        across += capacity[e];
    EXPECT_NEAR(across, value, 1e-9 * (1 + value)) << "round " << round;
    EXPECT_TRUE(SAI::Dual_graph_min_cut::is_source_side(w, s));
    EXPECT_FALSE(SAI::Dual_graph_min_cut::is_source_side(w, t));
  }
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

TEST(ShortestPaths, MatchBellmanFordWithLabelsAndRegions)
{
  SAI::Graph_shortest_paths paths; // reused across graphs and runs
  for(std::uint64_t seed = 1; seed <= 60; ++seed) {
    SAI::Procedural_random rng(seed);
    const std::size_t n = 1 + rng.index(40);
    std::vector<std::pair<std::uint32_t, std::uint32_t>> edges;
    std::vector<double> length;
    for(std::uint32_t u = 0; u < n; ++u)
      for(std::uint32_t v = u + 1; v < n; ++v)
        if(rng.uniform() < 3.0 / double(n)) {
          edges.emplace_back(u, v);
          length.push_back(rng.uniform() < 0.1 ? 0.0 : double(rng.index(5)) + rng.uniform());
        }
    const SAI::Dual_graph g = graph_of(n, edges, length);
    std::vector<std::uint32_t> sources, labels;
    for(std::size_t k = 0, count = 1 + rng.index(3); k < count; ++k) {
      sources.push_back(static_cast<std::uint32_t>(rng.index(n)));
      labels.push_back(static_cast<std::uint32_t>(10 + k));
    }
    std::vector<char> region(n);
    for(char& r : region)
      r = rng.uniform() < 0.8 ? 1 : 0;
    for(int restricted = 0; restricted < 2; ++restricted) {
      auto allowed = [&](std::uint32_t i) { return restricted == 0 || region[i] == 1; };
      // Bellman-Ford reference.
      std::vector<double> d(n, std::numeric_limits<double>::infinity());
      for(std::uint32_t s : sources)
        if(allowed(s))
          d[s] = 0;
      for(std::size_t pass = 0; pass < n; ++pass)
        for(std::size_t e = 0; e < edges.size(); ++e) {
          const std::uint32_t u = edges[e].first, v = edges[e].second;
          if(!allowed(u) || !allowed(v))
            continue;
          d[v] = (std::min)(d[v], d[u] + length[e]);
          d[u] = (std::min)(d[u], d[v] + length[e]);
        }
      paths.run_within(g, length, sources, labels, {}, allowed);
      std::set<std::uint32_t> settled(paths.settled().begin(), paths.settled().end());
      EXPECT_EQ(settled.size(), paths.settled().size()) << "a node settled twice";
      for(std::uint32_t i = 0; i < n; ++i) {
        ASSERT_EQ(paths.distance(i), d[i]) << "seed " << seed << " node " << i;
        EXPECT_EQ(settled.count(i) == 1, std::isfinite(d[i]));
        if(!std::isfinite(d[i])) {
          EXPECT_EQ(paths.label(i), SAI::Graph_shortest_paths::no_label);
          continue;
        }
        // The label is the one of a source at that distance along some path: some source k
        // with the label has d(k, i) == d[i]; check it is one of the labels, and that a node and
        // a neighbour on a shortest path share labels consistently (nearest source wins).
        EXPECT_GE(paths.label(i), 10u);
        EXPECT_LT(paths.label(i), 10u + sources.size());
      }
      // Settled in non-decreasing distance.
      for(std::size_t k = 1; k < paths.settled().size(); ++k)
        EXPECT_LE(paths.distance(paths.settled()[k - 1]), paths.distance(paths.settled()[k]));
    }
  }
}

TEST(ShortestPaths, LabelsFormAVoronoiPartition)
{
  // A path graph 0 - 1 - ... - 9 with unit lengths, sources at 1 (label 0) and 8 (label 1).
  std::vector<std::pair<std::uint32_t, std::uint32_t>> edges;
  for(std::uint32_t i = 0; i + 1 < 10; ++i)
    edges.emplace_back(i, i + 1);
  const SAI::Dual_graph g = graph_of(10, edges, std::vector<double>(9, 1.0));
  SAI::Graph_shortest_paths paths;
  paths.run(g, std::vector<double>(9, 1.0), {1, 8}, {0, 1});
  for(std::uint32_t i = 0; i < 10; ++i)
    EXPECT_EQ(paths.label(i), i < 5 ? 0u : 1u) << i; // 4 and 5 are closer to 1 and 8 resp.
  EXPECT_EQ(paths.distance(0), 1.0);
  EXPECT_EQ(paths.distance(9), 1.0);
  // Offsets: a source that starts later loses ground.
  paths.run(g, std::vector<double>(9, 1.0), {1, 8}, {0, 1}, {0.0, 2.0});
  EXPECT_EQ(paths.label(5), 0u); // 4 from node 1, 2 + 3 from node 8
  EXPECT_EQ(paths.distance(5), 4.0);
  EXPECT_EQ(paths.label(6), 1u); // 5 from node 1, 2 + 2 from node 8
  EXPECT_EQ(paths.distance(6), 4.0);
}

TEST(DualGraph, InducedSubgraphKeepsInternalEdgesAndMeshEdges)
{
  // 0 - 1 - 2 - 3 and 1 - 3.
  const SAI::Dual_graph g = graph_of(4, {{0, 1}, {1, 2}, {2, 3}, {1, 3}}, {1, 2, 3, 4});
  SAI::Dual_graph sub;
  std::vector<std::uint32_t> parent;
  SAI::induced_subgraph(g, {1, 2, 3}, sub, parent);
  EXPECT_EQ(sub.number_of_nodes(), 3u);
  ASSERT_EQ(sub.number_of_edges(), 3u);
  EXPECT_EQ(parent, (std::vector<std::uint32_t>{1, 2, 3}));
  for(std::size_t e = 0; e < 3; ++e) {
    EXPECT_EQ(sub.mesh_edge[e], g.mesh_edge[parent[e]]);
    EXPECT_EQ(sub.traversal_cost[e], g.traversal_cost[parent[e]]);
  }
  EXPECT_EQ(sub.edge_source[0], 0u); // old node 1
  EXPECT_EQ(sub.edge_target[0], 1u); // old node 2
  EXPECT_EQ(sub.first_arc.back(), 6u);
}

} // namespace
