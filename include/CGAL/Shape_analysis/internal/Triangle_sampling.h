// Copyright (c) 2026 CGAL Global Shape Analysis contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_SHAPE_ANALYSIS_INTERNAL_TRIANGLE_SAMPLING_H
#define CGAL_SHAPE_ANALYSIS_INTERNAL_TRIANGLE_SAMPLING_H

// Random points on a set of triangles: a triangle is drawn with probability proportional to its
// weight (its area, or its area times an emphasis), then a point uniformly inside it. Shared by
// the registration of meshes and by the correspondences of consistent segmentation.

#include <CGAL/Shape_analysis/internal/Random.h>
#include <CGAL/Shape_analysis/internal/Vector_3d.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

namespace CGAL {
namespace Shape_analysis {
namespace internal {

class Weighted_triangle_sampler
{
public:
  // `weights[f]` >= 0, one per triangle, their sum > 0.
  explicit Weighted_triangle_sampler(const std::vector<double>& weights) : m_weights(weights)
  {
    m_cumulative.resize(weights.size());
    double total = 0;
    for(std::size_t f = 0; f < weights.size(); ++f) {
      total += weights[f];
      m_cumulative[f] = total;
    }
  }

  // A triangle drawn with probability proportional to its weight (never one of weight 0).
  std::size_t triangle(Random_stream& rng) const
  {
    const double u = rng.uniform() * m_cumulative.back();
    std::size_t f = std::size_t(std::upper_bound(m_cumulative.begin(), m_cumulative.end(), u) -
                                m_cumulative.begin());
    f = (std::min)(f, m_cumulative.size() - 1);
    while(f > 0 && m_weights[f] == 0)
      --f;
    return f;
  }

  // A point drawn uniformly in the triangle of corners `c`.
  static Vector_3d point_in(const std::array<Vector_3d, 3>& c, Random_stream& rng)
  {
    const double r1 = std::sqrt(rng.uniform()), r2 = rng.uniform();
    return c[0] * (1 - r1) + c[1] * (r1 * (1 - r2)) + c[2] * (r1 * r2);
  }

private:
  const std::vector<double>& m_weights;
  std::vector<double> m_cumulative;
};

} // namespace internal
} // namespace Shape_analysis
} // namespace CGAL

#endif // CGAL_SHAPE_ANALYSIS_INTERNAL_TRIANGLE_SAMPLING_H
