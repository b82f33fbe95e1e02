// Copyright (c) 2026 CGAL Global Shape Analysis contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_SHAPE_ANALYSIS_AVAILABLE_PROCESSORS_H
#define CGAL_SHAPE_ANALYSIS_AVAILABLE_PROCESSORS_H

/// \file available_processors.h
/// How many threads the default `number_of_threads` (0) of the packages' functions runs.

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <fstream>
#include <sstream>
#include <string>
#include <thread>

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/info.h>
#endif

namespace CGAL {
namespace Shape_analysis {

/// \cond SKIP_IN_MANUAL
namespace internal {

// The processors granted by a Linux cgroup CPU quota, from the text of cgroup v2's `cpu.max`
// ("<quota> <period>" or "max <period>") or of v1's `cpu.cfs_quota_us` and `cpu.cfs_period_us`
// (a quota of -1 is none): the quota over the period, rounded up, at least 1; 0 for no quota or
// text that is not one.
inline std::size_t cgroup_quota_processors(const std::string& quota, const std::string& period)
{
  double q = 0, p = 0;
  std::istringstream qs(quota), ps(period);
  if(!(qs >> q) || !(ps >> p) || !(q > 0) || !(p > 0) || !std::isfinite(q / p))
    return 0;
  return (std::max)(std::size_t(1), std::size_t(std::ceil(q / p - 1e-9)));
}

inline std::size_t cgroup_v2_processors(const std::string& cpu_max)
{
  std::istringstream in(cpu_max);
  std::string quota, period;
  in >> quota >> period;
  return cgroup_quota_processors(quota, period);
}

// The smallest cgroup CPU quota over this process's cgroup and its ancestors (v2, then v1's cpu
// controller), in processors; 0 when there is none or on other systems.
inline std::size_t cgroup_processors()
{
#ifdef __linux__
  const auto read = [](const std::string& file) {
    std::ifstream in(file);
    std::string text;
    std::getline(in, text);
    return in ? text : std::string();
  };
  std::size_t least = 0;
  const auto take = [&least](std::size_t n) {
    if(n > 0 && (least == 0 || n < least))
      least = n;
  };
  // Each directory from the process's own cgroup up to the root of the hierarchy (inside a
  // container the path may name the host's hierarchy: the root is then the container's).
  const auto walk = [](std::string path, const auto& visit) {
    while(true) {
      visit(path);
      if(path.empty() || path == "/")
        break;
      const std::size_t slash = path.find_last_of('/');
      path = slash == std::string::npos || slash == 0 ? std::string("/") : path.substr(0, slash);
    }
  };
  std::ifstream cgroups("/proc/self/cgroup");
  std::string line;
  while(std::getline(cgroups, line)) {
    const std::size_t a = line.find(':'), b = a == std::string::npos ? a : line.find(':', a + 1);
    if(b == std::string::npos)
      continue;
    const std::string controllers = line.substr(a + 1, b - a - 1), path = line.substr(b + 1);
    if(line.compare(0, a, "0") == 0 && controllers.empty())
      walk(path, [&](const std::string& d) { take(cgroup_v2_processors(read("/sys/fs/cgroup" + d + "/cpu.max"))); });
    else if(("," + controllers + ",").find(",cpu,") != std::string::npos)
      for(const char* root : {"/sys/fs/cgroup/cpu", "/sys/fs/cgroup/cpu,cpuacct"})
        walk(path, [&](const std::string& d) {
          const std::string dir = std::string(root) + (d == "/" ? std::string() : d);
          take(cgroup_quota_processors(read(dir + "/cpu.cfs_quota_us"), read(dir + "/cpu.cfs_period_us")));
        });
  }
  return least;
#else
  return 0;
#endif
}

} // namespace internal
/// \endcond

/*!
\ingroup PkgShapeAnalysisCore
The number of processors this process may run on at once, which the functions of the packages use
as their number of threads when their named parameter `number_of_threads` is 0 (the default): the
processors of its affinity mask (as oneTBB counts them; without oneTBB, the hardware's), fewer
under a Linux cgroup CPU quota, which oneTBB 2021 does not read. A container started with
`--cpus 2` on a 64-core host, or a Kubernetes pod with a CPU limit of 2, gets 2: one thread per
processor of the host would have the quota throttle them, and multi-threaded work would run
several times slower than on one thread. The quota is the smallest over the process's cgroup and
its ancestors (cgroup v2's `cpu.max`, or v1's `cpu.cfs_quota_us` over `cpu.cfs_period_us`),
rounded up to whole processors. Read once, on the first call.
\returns at least 1
*/
inline std::size_t available_processors()
{
  static const std::size_t n = []() {
#ifdef CGAL_LINKED_WITH_TBB
    // The process's count, not the calling arena's (a first call inside a smaller arena).
    const std::size_t p = std::size_t((std::max)(1, tbb::info::default_concurrency()));
#else
    const std::size_t p = (std::max)(1u, std::thread::hardware_concurrency());
#endif
    const std::size_t q = internal::cgroup_processors();
    return q > 0 ? (std::min)(p, q) : p;
  }();
  return n;
}

} // namespace Shape_analysis
} // namespace CGAL

#endif // CGAL_SHAPE_ANALYSIS_AVAILABLE_PROCESSORS_H
