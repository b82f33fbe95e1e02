// Copyright (c) 2026 CGAL Global Shape Analysis contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_SHAPE_ANALYSIS_INTERNAL_RANDOM_H
#define CGAL_SHAPE_ANALYSIS_INTERNAL_RANDOM_H

// Random numbers identical on every platform and standard library (splitmix64; no
// std::distribution). Randomized algorithms draw sample i from `Random_stream(seed, i)`, its own
// stream, so that their results do not depend on how samples are spread over threads.

#include <cstdint>
#include <cstddef>

namespace CGAL {
namespace Shape_analysis {
namespace internal {

class Random_stream
{
public:
  explicit Random_stream(std::uint64_t seed = 0) : m_state(seed) {}
  // The stream of sample `index` of a run seeded with `seed`.
  Random_stream(std::uint64_t seed, std::uint64_t index)
    : m_state(mix(mix(seed ^ 0x6A09E667F3BCC909ull) + index))
  {}

  static std::uint64_t mix(std::uint64_t z)
  {
    z += 0x9E3779B97F4A7C15ull;
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
  }

  std::uint64_t next()
  {
    std::uint64_t z = (m_state += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
  }

  // Uniform in [0, 1).
  double uniform() { return double(next() >> 11) * (1.0 / 9007199254740992.0); }
  // Uniform in [lo, hi).
  double uniform(double lo, double hi) { return lo + (hi - lo) * uniform(); }
  // Uniform integer in [0, n), n > 0.
  std::size_t index(std::size_t n) { return static_cast<std::size_t>(next() % std::uint64_t(n)); }

private:
  std::uint64_t m_state;
};

} // namespace internal
} // namespace Shape_analysis
} // namespace CGAL

#endif // CGAL_SHAPE_ANALYSIS_INTERNAL_RANDOM_H
