// The weighted dual graph of a mesh and its induced subgraphs.
// Part of test_shape_analysis_core (one translation unit: see test/CMakeLists.txt).

#include "test_core_fixtures.h"

#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Polygon_mesh_processing/orientation.h>
#include <CGAL/Shape_analysis/internal/Min_cut.h>

#include <limits>
#include <set>

namespace {

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
  const SAS::Labelled_triangle_mesh lm =
    SAS::mesh_procedural_shape(SAS::three_sphere_chain(), 0.2);
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
