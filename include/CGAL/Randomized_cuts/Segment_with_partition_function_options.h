// Copyright (c) 2026 CGAL Global Shape Analysis contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_RANDOMIZED_CUTS_SEGMENT_WITH_PARTITION_FUNCTION_OPTIONS_H
#define CGAL_RANDOMIZED_CUTS_SEGMENT_WITH_PARTITION_FUNCTION_OPTIONS_H

/// \file Segment_with_partition_function_options.h

#include <CGAL/Randomized_cuts/Partition_function_options.h>

#include <cstddef>

namespace CGAL {
namespace Randomized_cuts {

/*!
\ingroup PkgRandomizedCutsRef

The options of `segment_with_partition_function()`: those of the partition functions it samples
(`Partition_function_options`) and those of the segmentation; each member is the named parameter
of the same name, initialized to its default. The `shape_analysis partition-segment` command
takes its defaults from here.
*/
struct Segment_with_partition_function_options : Partition_function_options
{
  /// The defaults of `Partition_function_options`, except `sampling_method`: `MIN_CUT`, the only
  /// sampler whose samples are cuts.
  Segment_with_partition_function_options() { sampling_method = MIN_CUT; }

  /// the number of segments to produce, at most the number of faces; 0, the default, chooses it
  /// (see `segment_with_partition_function()`; on the Princeton Segmentation Benchmark's
  /// development subset, within 0.02 of the Rand Index error that the human counts give)
  std::size_t number_of_segments = 0;
  /// whether single faces are moved between segments at the end while the normalized cut
  /// decreases
  bool boundary_refinement = true;
};

/*!
\ingroup PkgRandomizedCutsRef

The options that `segment_with_partition_function()` reads from the named parameters `np`: the
value of each named parameter given, the default of `Segment_with_partition_function_options` for
the others. The values are not checked here; `segment_with_partition_function()` checks them.
Named parameters that are not options (property maps, traits) are ignored.

\tparam NamedParameters a sequence of named parameters
\param np the named parameters, as given to the function whose options these are
\returns the options, each from its named parameter or its default
*/
template <typename NamedParameters = parameters::Default_named_parameters>
Segment_with_partition_function_options
segment_with_partition_function_options(const NamedParameters& np = parameters::default_values())
{
  using CGAL::Shape_analysis::internal::parameter_value;
  namespace snp = CGAL::Shape_analysis::internal_np;
  Segment_with_partition_function_options o;
  internal::read_partition_function_options(np, o);
  o.number_of_segments = parameter_value(np, snp::number_of_segments_tag, o.number_of_segments);
  o.boundary_refinement = parameter_value(np, snp::boundary_refinement_tag, o.boundary_refinement);
  return o;
}

} // namespace Randomized_cuts
} // namespace CGAL

#endif // CGAL_RANDOMIZED_CUTS_SEGMENT_WITH_PARTITION_FUNCTION_OPTIONS_H
