// Copyright (c) 2026 CGAL Global Shape Analysis contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_CONSISTENT_SEGMENTATION_CONSISTENT_SEGMENTATION_OPTIONS_H
#define CGAL_CONSISTENT_SEGMENTATION_CONSISTENT_SEGMENTATION_OPTIONS_H

/// \file Consistent_segmentation_options.h

#include <CGAL/Consistent_segmentation/Hierarchical_segmentation_options.h>
#include <CGAL/Shape_analysis/parameters.h>

#include <cstddef>
#include <cstdint>

namespace CGAL {
namespace Consistent_segmentation {

/*!
\ingroup PkgConsistentSegmentationRef

The options of `consistent_segmentation()` and `symmetric_segmentation()`: each member is the
named parameter of the same name, initialized to its default. The options of the first stage (the
over-segmentation of each mesh: `concavity_exponent`, `prior_boundary_factor`,
`component_link_distance`, `component_link_factor`, `boundary_refinement`) and
`number_of_segments` and `progress_callback` are those of `hierarchical_segmentation()`, with the
same defaults except `number_of_segments`; here `number_of_segments` counts the segments over the
whole set (0 by default: chosen, see `consistent_segmentation()`), and
`progress_callback` reports the progress of the whole computation. This struct is where the
defaults are written; the manual, `consistent_segmentation_options()` and the
`shape_analysis coseg` command take them from here.
*/
struct Consistent_segmentation_options : Hierarchical_segmentation_options
{
  /// The defaults of `Hierarchical_segmentation_options`, except `number_of_segments`: 0, the
  /// number chosen from the meshes' own (on the sets of the Princeton Segmentation Benchmark's
  /// development subset, within 0.02 of the Rand Index error that the human counts give; see the
  /// manual).
  Consistent_segmentation_options() { number_of_segments = 0; }

  /// the number of segments of each mesh after the first stage (at least 1)
  std::size_t number_of_oversegments = 20;
  /// the exponent \f$\alpha\f$ of the adjacency term of \f$E = E_{adj}^{\alpha}
  /// E_{corr}^{1-\alpha}\f$ (0: only the correspondences count; 1: only the mesh edges), in [0, 1]
  double adjacency_exponent = 0.1;
  /// the number of points sampled on each mesh for the alignments and the correspondences, from
  /// 10 to 10,000,000
  std::size_t number_of_points = 1000;
  /// two samples correspond only when the dot product of their normals, after alignment, is above
  /// this; in [-1, 1)
  double normal_threshold = 0.3;
  /// two samples correspond only when, after alignment, they are closer than this fraction of the
  /// bounding-box diagonal of the mesh of the second one (finite, positive)
  double correspondence_distance = 0.2;
  /// the number of best-aligned partners whose correspondences each mesh keeps; in sets of more
  /// than 2 `number_of_partners` + 1 meshes, each mesh is aligned only with the
  /// 2 `number_of_partners` meshes of most similar shape distribution; 0 aligns and keeps every
  /// pair (not used by `symmetric_segmentation()`)
  std::size_t number_of_partners = 4;
  /// the number of runs of what follows the over-segmentation (sampling, alignments,
  /// correspondences, merging), each with its own sample points, from 1 to 1,000; the result is the
  /// run whose segmentation agrees most with the others' (of two runs, the first; see
  /// `consistent_segmentation()`)
  std::size_t number_of_runs = 6;
  /// the seed of the random numbers (sample points)
  std::uint64_t random_seed = 0;
  /// the largest number of threads used (with TBB); 0 for all cores. The result does not depend
  /// on it
  std::size_t number_of_threads = 0;
};

/*!
\ingroup PkgConsistentSegmentationRef

The options that `consistent_segmentation()` and `symmetric_segmentation()` read from the named
parameters `np`: the value of each named parameter given, the default of
`Consistent_segmentation_options` for the others. The values are not checked here; the functions
check them. Named parameters that are not options (property maps, traits) are ignored.

\tparam NamedParameters a sequence of named parameters
\param np the named parameters, as given to the function whose options these are
\returns the options, each from its named parameter or its default
*/
template <typename NamedParameters = parameters::Default_named_parameters>
Consistent_segmentation_options
consistent_segmentation_options(const NamedParameters& np = parameters::default_values())
{
  using CGAL::Shape_analysis::internal::parameter_value;
  namespace snp = CGAL::Shape_analysis::internal_np;
  Consistent_segmentation_options o;
  internal::read_hierarchical_segmentation_options(np, o);
  o.number_of_oversegments = parameter_value(np, snp::number_of_oversegments_tag, o.number_of_oversegments);
  o.adjacency_exponent = parameter_value(np, snp::adjacency_exponent_tag, o.adjacency_exponent);
  o.number_of_points = parameter_value(np, snp::number_of_points_tag, o.number_of_points);
  o.normal_threshold = parameter_value(np, snp::normal_threshold_tag, o.normal_threshold);
  o.correspondence_distance = parameter_value(np, snp::correspondence_distance_tag, o.correspondence_distance);
  o.number_of_partners = parameter_value(np, snp::number_of_partners_tag, o.number_of_partners);
  o.number_of_runs = parameter_value(np, snp::number_of_runs_tag, o.number_of_runs);
  o.random_seed = parameter_value(np, CGAL::internal_np::random_seed, o.random_seed);
  o.number_of_threads = parameter_value(np, snp::number_of_threads_tag, o.number_of_threads);
  return o;
}

} // namespace Consistent_segmentation
} // namespace CGAL

#endif // CGAL_CONSISTENT_SEGMENTATION_CONSISTENT_SEGMENTATION_OPTIONS_H
