// Named parameters: our packs, CGAL's packs, and their mixtures.
// Part of test_shape_analysis_core (one translation unit: see test/CMakeLists.txt).

#include "test_core_fixtures.h"

#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Shape_analysis/parameters.h>

#include <functional>
#include <set>
#include <string>
#include <type_traits>

namespace {

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

} // namespace
