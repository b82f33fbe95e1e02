// Links between the connected components of a mesh's dual graph.
// Part of test_shape_analysis_core (one translation unit: see test/CMakeLists.txt).

#include "test_core_fixtures.h"

#include <CGAL/Shape_analysis/internal/Component_links.h>

#include <set>

namespace {

// ---------------------------------------------------------------------------------------------
// Component links

struct Linked_graph
{
  SAS::Labelled_triangle_mesh lm;
  SAI::Dual_graph g;
  std::vector<std::uint32_t> component; // before linking
  std::size_t mesh_edges = 0;           // graph edges before linking
  double mean_cut = 0;
};

Linked_graph boxes_graph(std::size_t n, double gap, double cell)
{
  Linked_graph r;
  r.lm = SAS::mesh_procedural_shape(SAS::separate_boxes(n, gap), cell);
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
  ASSERT_EQ(SAS::rand_index(comp, r.lm.labels), 1.0);
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

} // namespace
