// Copyright (c) 2026 CGAL Global Shape Analysis contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_SHAPE_ANALYSIS_PARAMETERS_H
#define CGAL_SHAPE_ANALYSIS_PARAMETERS_H

/// \file parameters.h
/// Named parameters of the Global Shape Analysis packages, usable in one chain with CGAL's own.

#include <CGAL/Named_function_parameters.h>
#include <CGAL/boost/graph/named_params_helper.h>

#include <functional>
#include <type_traits>

namespace CGAL {
namespace Shape_analysis {

/// Tags of the named parameters this project adds to CGAL's list.
namespace internal_np {

// X(tag type, tag value, member/starter function name)
#define CGAL_SHAPE_ANALYSIS_NAMED_PARAMETER_LIST(X)                                  \
  X(number_of_segments_t, number_of_segments_tag, number_of_segments)                \
  X(concavity_exponent_t, concavity_exponent_tag, concavity_exponent)                \
  X(prior_segment_map_t, prior_segment_map_tag, prior_segment_map)                   \
  X(prior_boundary_factor_t, prior_boundary_factor_tag, prior_boundary_factor)       \
  X(component_link_distance_t, component_link_distance_tag, component_link_distance) \
  X(component_link_factor_t, component_link_factor_tag, component_link_factor)       \
  X(boundary_refinement_t, boundary_refinement_tag, boundary_refinement)             \
  X(progress_callback_t, progress_callback_tag, progress_callback)                   \
  X(sampling_method_t, sampling_method_tag, sampling_method)                         \
  X(part_size_t, part_size_tag, part_size)                                           \
  X(part_sizes_t, part_sizes_tag, part_sizes)                                        \
  X(number_of_clusters_t, number_of_clusters_tag, number_of_clusters)                \
  X(randomness_t, randomness_tag, randomness)                                        \
  X(convergence_tolerance_t, convergence_tolerance_tag, convergence_tolerance)       \
  X(score_weighting_t, score_weighting_tag, score_weighting)                         \
  X(number_of_threads_t, number_of_threads_tag, number_of_threads)                   \
  X(number_of_cuts_t, number_of_cuts_tag, number_of_cuts)                            \
  X(duplicate_tolerance_t, duplicate_tolerance_tag, duplicate_tolerance)             \
  X(edge_value_map_t, edge_value_map_tag, edge_value_map)                            \
  X(flexible_weight_t, flexible_weight_tag, flexible_weight)                         \
  X(stiffness_exponent_t, stiffness_exponent_tag, stiffness_exponent)                \
  X(value_scale_t, value_scale_tag, value_scale)                                     \
  X(number_of_points_t, number_of_points_tag, number_of_points)                      \
  X(partition_weighting_t, partition_weighting_tag, partition_weighting)             \
  X(spread_rings_t, spread_rings_tag, spread_rings)                                   \
  X(number_of_oversegments_t, number_of_oversegments_tag, number_of_oversegments)    \
  X(adjacency_exponent_t, adjacency_exponent_tag, adjacency_exponent)                \
  X(number_of_partners_t, number_of_partners_tag, number_of_partners)                \
  X(number_of_runs_t, number_of_runs_tag, number_of_runs)                            \
  X(normal_threshold_t, normal_threshold_tag, normal_threshold)                      \
  X(correspondence_distance_t, correspondence_distance_tag, correspondence_distance) \
  X(vertex_point_maps_t, vertex_point_maps_tag, vertex_point_maps)                   \
  X(known_segment_maps_t, known_segment_maps_tag, known_segment_maps)                \
  X(prior_segment_maps_t, prior_segment_maps_tag, prior_segment_maps)                   \
  X(maximum_number_of_symmetries_t, maximum_number_of_symmetries_tag, maximum_number_of_symmetries) \
  X(minimum_support_t, minimum_support_tag, minimum_support)                         \
  X(maximum_order_t, maximum_order_tag, maximum_order)                               \
  X(support_tolerance_t, support_tolerance_tag, support_tolerance)                   \
  X(support_weighting_t, support_weighting_tag, support_weighting)                   \
  X(shape_weight_t, shape_weight_tag, shape_weight)                                  \
  X(displacement_weight_t, displacement_weight_tag, displacement_weight)             \
  X(number_of_levels_t, number_of_levels_tag, number_of_levels)                      \
  X(coarsest_level_size_t, coarsest_level_size_tag, coarsest_level_size)             \
  X(symmetry_tolerance_t, symmetry_tolerance_tag, symmetry_tolerance)                \
  X(final_symmetry_weight_t, final_symmetry_weight_tag, final_symmetry_weight)       \
  X(target_symmetry_error_t, target_symmetry_error_tag, target_symmetry_error)       \
  X(transfer_mode_t, transfer_mode_tag, transfer_mode)                               \
  X(source_side_t, source_side_tag, source_side)                                     \
  X(symmetric_map_t, symmetric_map_tag, symmetric_map)                               \
  X(symmetry_support_map_t, symmetry_support_map_tag, symmetry_support_map)          \
  X(number_of_faces_t, number_of_faces_tag, number_of_faces)                         \
  X(maximum_error_t, maximum_error_tag, maximum_error)                               \
  X(pairing_tolerance_t, pairing_tolerance_tag, pairing_tolerance)                   \
  X(restore_residuals_t, restore_residuals_tag, restore_residuals)                   \
  X(copy_one_side_t, copy_one_side_tag, copy_one_side)                               \
  X(ground_cell_size_t, ground_cell_size_tag, ground_cell_size)                      \
  X(ground_threshold_t, ground_threshold_tag, ground_threshold)                      \
  X(isolation_radius_t, isolation_radius_tag, isolation_radius)                      \
  X(minimum_neighbors_t, minimum_neighbors_tag, minimum_neighbors)                   \
  X(component_spacing_t, component_spacing_tag, component_spacing)                   \
  X(maximum_component_extent_t, maximum_component_extent_tag, maximum_component_extent) \
  X(minimum_cluster_size_t, minimum_cluster_size_tag, minimum_cluster_size)          \
  X(maximum_cluster_height_t, maximum_cluster_height_tag, maximum_cluster_height)    \
  X(localization_method_t, localization_method_tag, localization_method)             \
  X(mean_shift_radius_t, mean_shift_radius_tag, mean_shift_radius)                   \
  X(localization_cell_size_t, localization_cell_size_tag, localization_cell_size)    \
  X(normalized_cut_threshold_t, normalized_cut_threshold_tag, normalized_cut_threshold) \
  X(height_image_sigma_t, height_image_sigma_tag, height_image_sigma)                \
  X(height_image_threshold_t, height_image_threshold_tag, height_image_threshold)    \
  X(local_origin_t, local_origin_tag, local_origin)                                  \
  X(shift_to_local_origin_t, shift_to_local_origin_tag, shift_to_local_origin) \
  X(class_names_t, class_names_tag, class_names)                                     \
  X(las_georeference_t, las_georeference_tag, las_georeference)                      \
  X(segmentation_method_t, segmentation_method_tag, segmentation_method)             \
  X(background_radius_t, background_radius_tag, background_radius)                   \
  X(foreground_height_t, foreground_height_tag, foreground_height)                   \
  X(number_of_neighbors_t, number_of_neighbors_tag, number_of_neighbors)             \
  X(edge_sigma_t, edge_sigma_tag, edge_sigma)                                        \
  X(background_weight_t, background_weight_tag, background_weight)                   \
  X(graph_cell_size_t, graph_cell_size_tag, graph_cell_size)                         \
  X(maximum_graph_size_t, maximum_graph_size_tag, maximum_graph_size)                \
  X(minimum_foreground_size_t, minimum_foreground_size_tag, minimum_foreground_size) \
  X(maximum_cut_cost_t, maximum_cut_cost_tag, maximum_cut_cost)                     \
  X(tile_size_t, tile_size_tag, tile_size)                                           \
  X(tile_margin_t, tile_margin_tag, tile_margin)                                     \
  X(tile_origin_t, tile_origin_tag, tile_origin)                                     \
  X(spin_image_radius_t, spin_image_radius_tag, spin_image_radius)                   \
  X(object_classifier_t, object_classifier_tag, object_classifier)

#define CGAL_SHAPE_ANALYSIS_DECLARE_TAG(X, Y, Z) enum X { Y };
CGAL_SHAPE_ANALYSIS_NAMED_PARAMETER_LIST(CGAL_SHAPE_ANALYSIS_DECLARE_TAG)
#undef CGAL_SHAPE_ANALYSIS_DECLARE_TAG

} // namespace internal_np

/// \ingroup PkgShapeAnalysisCore
/// A named-parameter pack that behaves like `CGAL::Named_function_parameters` (CGAL's functions
/// accept it, `CGAL::parameters::choose_parameter()` reads it) and whose member functions also
/// offer the parameters of this project, so that one chain can mix both kinds:
/// `parameters::number_of_segments(8).vertex_point_map(vpm).random_seed(3)`.
template <typename T, typename Tag, typename Base = CGAL::internal_np::No_property>
struct Named_parameters : CGAL::Named_function_parameters<T, Tag, Base>
{
  typedef CGAL::Named_function_parameters<T, Tag, Base> Cgal_pack;
  typedef Named_parameters<T, Tag, Base> self;

  Named_parameters() : Cgal_pack() {}
  explicit Named_parameters(const T& v) : Cgal_pack(v) {}
  Named_parameters(const T& v, const Base& b) : Cgal_pack(v, b) {}

  // CGAL's own parameters, returning our pack so that the chain keeps our members.
#define CGAL_add_named_parameter(X, Y, Z)                                     \
  template <typename K>                                                     \
  Named_parameters<K, CGAL::internal_np::X, self> Z(const K& k) const       \
  {                                                                         \
    return Named_parameters<K, CGAL::internal_np::X, self>(k, *this);       \
  }
#include <CGAL/STL_Extension/internal/parameters_interface.h>
#undef CGAL_add_named_parameter

  // This project's parameters.
#define CGAL_SHAPE_ANALYSIS_MEMBER(X, Y, Z)                                   \
  template <typename K>                                                     \
  Named_parameters<K, internal_np::X, self> Z(const K& k) const             \
  {                                                                         \
    return Named_parameters<K, internal_np::X, self>(k, *this);             \
  }
  CGAL_SHAPE_ANALYSIS_NAMED_PARAMETER_LIST(CGAL_SHAPE_ANALYSIS_MEMBER)
#undef CGAL_SHAPE_ANALYSIS_MEMBER
};

namespace parameters {

using CGAL::parameters::choose_parameter;
using CGAL::parameters::get_parameter;
using CGAL::parameters::get_parameter_reference;
using CGAL::parameters::is_default_parameter;

/// The empty pack: all parameters take their default values.
typedef Named_parameters<bool, CGAL::internal_np::all_default_t> Default_named_parameters;

/// \ingroup PkgShapeAnalysisCore
/// The empty pack, start of a chain.
/// \returns a pack in which every parameter takes its default value
inline Default_named_parameters default_values() { return Default_named_parameters(); }

// Starters for CGAL's parameters (so that `parameters::vertex_point_map(vpm)` can continue with
// this project's members).
#define CGAL_add_named_parameter(X, Y, Z)                                     \
  template <typename K>                                                     \
  Named_parameters<K, CGAL::internal_np::X> Z(const K& k)                   \
  {                                                                         \
    return Named_parameters<K, CGAL::internal_np::X>(k);                    \
  }
#include <CGAL/STL_Extension/internal/parameters_interface.h>
#undef CGAL_add_named_parameter

// Starters for this project's parameters.
#define CGAL_SHAPE_ANALYSIS_STARTER(X, Y, Z)                                  \
  template <typename K>                                                     \
  Named_parameters<K, internal_np::X> Z(const K& k)                         \
  {                                                                         \
    return Named_parameters<K, internal_np::X>(k);                          \
  }
CGAL_SHAPE_ANALYSIS_NAMED_PARAMETER_LIST(CGAL_SHAPE_ANALYSIS_STARTER)
#undef CGAL_SHAPE_ANALYSIS_STARTER

/// Wraps a pack made by CGAL (for example `point_set.parameters()` or
/// `CGAL::parameters::vertex_point_map(vpm)`) into this project's pack type, so that the chain
/// can continue with this project's parameters: `extend(cgal_pack).number_of_segments(5)`.
/// \ingroup PkgShapeAnalysisCore
/// \param np a pack of named parameters made by \cgal
/// \returns the same parameters as a `CGAL::Shape_analysis::Named_parameters` pack
template <typename T, typename Tag>
Named_parameters<T, Tag>
extend(const CGAL::Named_function_parameters<T, Tag, CGAL::internal_np::No_property>& np)
{
  return Named_parameters<T, Tag>(np.v);
}

/// \cond SKIP_IN_MANUAL
template <typename T, typename Tag, typename Base>
auto extend(const CGAL::Named_function_parameters<T, Tag, Base>& np)
{
  auto base = extend(static_cast<const Base&>(np));
  return Named_parameters<T, Tag, decltype(base)>(np.v, base);
}
/// \endcond

} // namespace parameters

namespace internal {

// The value of a named parameter, or `default_value` when it is absent; converted to `Value`.
template <typename Value, typename NP, typename Tag>
Value parameter_value(const NP& np, Tag tag, const Value& default_value)
{
  return static_cast<Value>(
    CGAL::parameters::choose_parameter(CGAL::parameters::get_parameter(np, tag), default_value));
}

} // namespace internal

} // namespace Shape_analysis

// `Polygon_mesh_processing/measure.h` specializes `GetGeomTraits` for CGAL's pack so that an
// overload taking a face range is not picked for a pack; our pack needs the same treatment.
template <typename T, typename Tag, typename Base, typename NP>
class GetGeomTraits<Shape_analysis::Named_parameters<T, Tag, Base>, NP>
{
public:
  struct type {};
};

} // namespace CGAL

#endif // CGAL_SHAPE_ANALYSIS_PARAMETERS_H
