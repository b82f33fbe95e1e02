// Copyright (c) 2026 CGAL Global Shape Analysis contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_RANDOMIZED_CUTS_SAMPLING_METHOD_H
#define CGAL_RANDOMIZED_CUTS_SAMPLING_METHOD_H

/// \file Sampling_method.h

namespace CGAL {
namespace Randomized_cuts {

/*!
\ingroup PkgRandomizedCutsRef

The ways `partition_function()` draws random segmentations of a mesh (named parameter
`sampling_method`).
*/
enum Sampling_method : int
{
  /// A minimum cut between two random faces, with cuts near either face made expensive so that
  /// both sides are parts of a reasonable size. Each sample is one cut into two sides (the default
  /// of the functions that need cuts).
  MIN_CUT = 0,
  /// K-means clustering from random seed faces under traversal distances; each seed moves to the
  /// face of its segment furthest from the segment's boundary until the seeds stop moving (at most
  /// 30 rounds).
  K_MEANS = 1,
  /// Randomized hierarchical clustering under the area-normalized cut: each merge is drawn at
  /// random, better merges being much more likely (with probability about proportional to the
  /// gain raised to 1/`randomness`). Each run contributes its segmentations into 2, 3, ...,
  /// `number_of_clusters` segments (the default of `partition_function()`).
  HIERARCHICAL = 2
};

} // namespace Randomized_cuts
} // namespace CGAL

#endif // CGAL_RANDOMIZED_CUTS_SAMPLING_METHOD_H
