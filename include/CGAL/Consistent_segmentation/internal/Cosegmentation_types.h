// Copyright (c) 2026 CGAL Global Shape Analysis contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_CONSISTENT_SEGMENTATION_INTERNAL_COSEGMENTATION_TYPES_H
#define CGAL_CONSISTENT_SEGMENTATION_INTERNAL_COSEGMENTATION_TYPES_H

// The input, options and result of the co-segmentation (see Cosegmentation.h).

#include <CGAL/Consistent_segmentation/Consistent_segmentation_options.h>
#include <CGAL/Consistent_segmentation/internal/Segmentation_graph.h>
#include <CGAL/Shape_analysis/Bad_input.h>
#include <CGAL/Shape_analysis/internal/Dual_graph.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <functional>
#include <limits>
#include <string>
#include <vector>

namespace CGAL {
namespace Consistent_segmentation {
namespace internal {

namespace SAI = CGAL::Shape_analysis::internal;

// One mesh of the set, as its dual graph and the triangles of its faces.
struct Coseg_mesh
{
  SAI::Dual_graph graph;                                // no component links yet
  std::vector<std::array<SAI::Vector_3d, 3>> triangles; // per node, in graph units
  std::vector<long long> prior;                         // empty, or a prior segment per node
  std::vector<long long> known;                         // empty, or a label per node (-1: unknown)
  bool has_plane = false;                               // mirror correspondences within the mesh
  SAI::Vector_3d plane_normal;                          // unit, graph units
  double plane_offset = 0;                              // plane: n.x = offset
  std::vector<double> mirror_support;                   // empty (all 1), or per node in [0, 1]
};

typedef Consistent_segmentation_options Coseg_options;

// Every this many merges of the joint merging, single over-segments move to a neighbouring segment
// when that lowers the energy (if boundary_refinement).
constexpr std::size_t refinement_interval = 12;

struct Coseg_result
{
  std::vector<std::vector<std::size_t>> labels;          // per mesh, per node: segment id
  std::size_t number_of_segments = 0;
  std::vector<std::vector<std::size_t>> meshes_of_segment; // per segment: the meshes it occurs in
  std::vector<double> segment_area;                      // per segment: sum of the meshes' area fractions
  std::vector<long long> segment_label;                  // per segment: its known label, or -1
  std::size_t number_of_oversegments = 0;                // over all meshes
  std::size_t number_of_aligned_pairs = 0;
  std::size_t number_of_correspondences = 0;
  double mean_alignment_rms = 0;                         // relative to the target's sample diagonal
  std::size_t number_of_runs = 1;                        // of stages two and three
  std::size_t chosen_run = 0;                            // the one returned
  double run_disagreement = 0;                           // its mean Rand distance to the others
};

inline void check_coseg_options(const Coseg_options& o, const std::string& who)
{
  using CGAL::Shape_analysis::Bad_input;
  if(o.number_of_oversegments == 0)
    throw Bad_input(who + ": number_of_oversegments must be at least 1");
  if(!(o.adjacency_exponent >= 0 && o.adjacency_exponent <= 1))
    throw Bad_input(who + ": adjacency_exponent must be in [0, 1]");
  if(o.number_of_points < 10 || o.number_of_points > 10000000)
    throw Bad_input(who + ": number_of_points must be in [10, 10,000,000]");
  if(!(o.normal_threshold >= -1 && o.normal_threshold < 1))
    throw Bad_input(who + ": normal_threshold must be in [-1, 1)");
  if(!(o.correspondence_distance > 0) || !std::isfinite(o.correspondence_distance))
    throw Bad_input(who + ": correspondence_distance must be a finite number > 0");
  if(o.number_of_runs < 1 || o.number_of_runs > 1000)
    throw Bad_input(who + ": number_of_runs must be in [1, 1000]");
  check_options(o, (std::numeric_limits<std::size_t>::max)(), who, true); // 0: automatic
}

} // namespace internal
} // namespace Consistent_segmentation
} // namespace CGAL

#endif // CGAL_CONSISTENT_SEGMENTATION_INTERNAL_COSEGMENTATION_TYPES_H
