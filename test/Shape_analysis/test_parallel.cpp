// Work spread over threads: how many processors the process may use (a cgroup CPU quota narrows
// the hardware's), and that every item runs once on at most that many threads.
// Part of test_shape_analysis_core (one translation unit: see test/CMakeLists.txt).

#include "test_core_fixtures.h"

#include <CGAL/Shape_analysis/internal/Parallel.h>

#include <atomic>
#include <mutex>
#include <set>
#include <thread>
#include <vector>

namespace {

namespace SAP = CGAL::Shape_analysis::internal;

TEST(Parallel, CgroupQuotaIsRoundedUpToWholeProcessors)
{
  EXPECT_EQ(SAP::cgroup_quota_processors("200000", "100000"), 2u);
  EXPECT_EQ(SAP::cgroup_quota_processors("150000", "100000"), 2u);
  EXPECT_EQ(SAP::cgroup_quota_processors("50000", "100000"), 1u);
  EXPECT_EQ(SAP::cgroup_quota_processors("1000", "100000"), 1u);
  EXPECT_EQ(SAP::cgroup_v2_processors("400000 100000"), 4u);
  EXPECT_EQ(SAP::cgroup_v2_processors("250000 100000\n"), 3u);
}

TEST(Parallel, NoQuotaOrUnreadableTextIsNoLimit)
{
  EXPECT_EQ(SAP::cgroup_v2_processors("max 100000"), 0u);
  EXPECT_EQ(SAP::cgroup_v2_processors(""), 0u);
  EXPECT_EQ(SAP::cgroup_quota_processors("-1", "100000"), 0u); // v1: no quota
  EXPECT_EQ(SAP::cgroup_quota_processors("100000", "0"), 0u);
  EXPECT_EQ(SAP::cgroup_quota_processors("", "100000"), 0u);
  EXPECT_EQ(SAP::cgroup_quota_processors("1e308", "1e-308"), 0u);
}

TEST(Parallel, AvailableProcessorsAreAtMostTheHardwareAndTheQuota)
{
  const std::size_t n = CGAL::Shape_analysis::available_processors();
  EXPECT_GE(n, 1u);
  if(std::thread::hardware_concurrency() > 0)
    EXPECT_LE(n, std::size_t(std::thread::hardware_concurrency()));
  if(SAP::cgroup_processors() > 0)
    EXPECT_LE(n, SAP::cgroup_processors());
}

TEST(Parallel, EveryItemRunsOnceOnAtMostTheAvailableThreads)
{
  struct Workspace { std::size_t items = 0; };
  for(std::size_t threads : {std::size_t(0), std::size_t(1), std::size_t(3)}) {
    SAP::Parallel_workspaces<Workspace> workers(threads);
    std::vector<std::atomic<int>> runs(2000);
    std::mutex mutex;
    std::set<std::thread::id> ids;
    workers.for_each(0, runs.size(), [&](std::size_t i, Workspace& w) {
      ++runs[i];
      ++w.items;
      std::lock_guard<std::mutex> lock(mutex);
      ids.insert(std::this_thread::get_id());
    });
    for(const auto& r : runs)
      ASSERT_EQ(r.load(), 1);
    const std::size_t most = threads == 0 ? CGAL::Shape_analysis::available_processors() : threads;
    EXPECT_LE(ids.size(), most) << threads;
  }
}

} // namespace
