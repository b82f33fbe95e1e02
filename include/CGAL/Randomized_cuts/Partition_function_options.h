// Copyright (c) 2026 CGAL Global Shape Analysis contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_RANDOMIZED_CUTS_PARTITION_FUNCTION_OPTIONS_H
#define CGAL_RANDOMIZED_CUTS_PARTITION_FUNCTION_OPTIONS_H

/// \file Partition_function_options.h

#include <CGAL/Randomized_cuts/Sampling_method.h>
#include <CGAL/Shape_analysis/defaults.h>
#include <CGAL/Shape_analysis/parameters.h>

#include <cstddef>
#include <cstdint>
#include <functional>
#include <type_traits>

namespace CGAL {
namespace Randomized_cuts {

/// The named parameters of this package (this project's, and CGAL's usable in the same chain).
namespace parameters = CGAL::Shape_analysis::parameters;

/*!
\ingroup PkgRandomizedCutsRef

The options of `partition_function()`: each member is the named parameter of the same name,
initialized to its default. The other functions of the package that sample the partition function
(`multiscale_partition_function()`, `most_consistent_cuts()`, `segment_with_partition_function()`,
`register_meshes()`) take these options too, in options structs derived from this one. This struct
is where the defaults are written; the manual, `partition_function_options()` and the
`shape_analysis partition` command take them from here.
*/
struct Partition_function_options
{
  /// how segmentations are sampled: `HIERARCHICAL`, whose values say best where people draw part
  /// boundaries (see the manual's section on boundary prediction); the functions that need each
  /// sample to be one cut (`segment_with_partition_function()`, `most_consistent_cuts()`,
  /// `multiscale_partition_function()`) and `register_meshes()` default to `MIN_CUT` in their own
  /// options structs
  Sampling_method sampling_method = HIERARCHICAL;
  /// the number of segmentations to sample (at least 1)
  std::size_t number_of_samples = 400;
  /// stop early, after a batch of samples, when no edge value changed by more than this over the
  /// batch; 0 draws every sample (at least 0)
  double convergence_tolerance = 0;
  /// the seed of the random numbers
  std::uint64_t random_seed = 0;
  /// `MIN_CUT`: the part size \f$s\f$ of the penalty near the source and sink faces, as a fraction
  /// of the relative distance (in \f$(0, 1/6]\f$); given without `sampling_method`, it selects
  /// `MIN_CUT`
  double part_size = 0.05;
  /// `K_MEANS`: the number of seeds; `HIERARCHICAL`: the largest number of segments of the
  /// segmentations a run contributes (at least 2)
  std::size_t number_of_clusters = 10;
  /// `HIERARCHICAL`: the randomness \f$r\f$ of the merge choice, smaller is closer to the
  /// deterministic clustering (positive)
  double randomness = 0.02;
  /// whether each sampled segmentation counts with weight \f$1/J\f$ rather than 1
  bool score_weighting = false;
  /// the largest number of threads used (with TBB); 0 for all cores
  std::size_t number_of_threads = 0;
  /// the exponent \f$\alpha\f$ of the concavity weight \f$\min((\theta/\pi)^\alpha, 1)\f$ (at
  /// least 0)
  double concavity_exponent = CGAL::Shape_analysis::default_concavity_exponent;
  /// faces of different connected components closer than this fraction of the bounding-box
  /// diagonal are linked (at least 0)
  double component_link_distance = CGAL::Shape_analysis::default_component_link_distance;
  /// the cut cost of a link between components, relative to the mean cut cost of the mesh edges
  /// (positive)
  double component_link_factor = CGAL::Shape_analysis::default_component_link_factor;
  /// called after every batch of samples with the fraction drawn; none by default
  std::function<void(double)> progress_callback;
};

/// \cond SKIP_IN_MANUAL
namespace internal {

// Sets the members of `o` whose named parameters `np` gives (the others keep their values: the
// defaults of `o`'s own type, which may be an options struct derived from this one).
template <typename NamedParameters>
void read_partition_function_options(const NamedParameters& np, Partition_function_options& o)
{
  using CGAL::Shape_analysis::internal::parameter_value;
  using CGAL::parameters::get_parameter;
  namespace snp = CGAL::Shape_analysis::internal_np;
  namespace cnp = CGAL::internal_np;
  o.sampling_method = parameter_value(np, snp::sampling_method_tag, o.sampling_method);
  // A part size is the min-cut sampler's: given without a sampler, it selects MIN_CUT.
  constexpr bool has_method = !std::is_same<decltype(get_parameter(np, snp::sampling_method_tag)),
                                            CGAL::internal_np::Param_not_found>::value;
  constexpr bool has_part_size = !std::is_same<decltype(get_parameter(np, snp::part_size_tag)),
                                               CGAL::internal_np::Param_not_found>::value;
  if constexpr(has_part_size && !has_method)
    o.sampling_method = MIN_CUT;
  o.number_of_samples = parameter_value(np, cnp::number_of_samples, o.number_of_samples);
  o.convergence_tolerance = parameter_value(np, snp::convergence_tolerance_tag, o.convergence_tolerance);
  o.random_seed = parameter_value(np, cnp::random_seed, o.random_seed);
  o.part_size = parameter_value(np, snp::part_size_tag, o.part_size);
  o.number_of_clusters = parameter_value(np, snp::number_of_clusters_tag, o.number_of_clusters);
  o.randomness = parameter_value(np, snp::randomness_tag, o.randomness);
  o.score_weighting = parameter_value(np, snp::score_weighting_tag, o.score_weighting);
  o.number_of_threads = parameter_value(np, snp::number_of_threads_tag, o.number_of_threads);
  o.concavity_exponent = parameter_value(np, snp::concavity_exponent_tag, o.concavity_exponent);
  o.component_link_distance =
    parameter_value(np, snp::component_link_distance_tag, o.component_link_distance);
  o.component_link_factor = parameter_value(np, snp::component_link_factor_tag, o.component_link_factor);
  o.progress_callback = parameter_value(np, snp::progress_callback_tag, o.progress_callback);
}

} // namespace internal
/// \endcond

/*!
\ingroup PkgRandomizedCutsRef

The options that `partition_function()` reads from the named parameters `np`: the value of each
named parameter given, the default of `Partition_function_options` for the others. The values are
not checked here; `partition_function()` checks them. Named parameters that are not options
(property maps, traits) are ignored.

\tparam NamedParameters a sequence of named parameters
\param np the named parameters, as given to the function whose options these are
\returns the options, each from its named parameter or its default
*/
template <typename NamedParameters = parameters::Default_named_parameters>
Partition_function_options
partition_function_options(const NamedParameters& np = parameters::default_values())
{
  Partition_function_options o;
  internal::read_partition_function_options(np, o);
  return o;
}

} // namespace Randomized_cuts
} // namespace CGAL

#endif // CGAL_RANDOMIZED_CUTS_PARTITION_FUNCTION_OPTIONS_H
