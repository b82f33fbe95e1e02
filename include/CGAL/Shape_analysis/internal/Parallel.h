// Copyright (c) 2026 CGAL Global Shape Analysis contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_SHAPE_ANALYSIS_INTERNAL_PARALLEL_H
#define CGAL_SHAPE_ANALYSIS_INTERNAL_PARALLEL_H

// Independent work items (samples, meshes, tiles) spread over threads with TBB when CGAL is linked
// with it, one after the other otherwise. Each thread gets its own workspace (buffers reused from
// item to item). Items must not depend on which thread or workspace runs them: results are then
// identical for any number of threads.

#include <CGAL/Shape_analysis/available_processors.h>

#include <algorithm>
#include <cstddef>
#include <memory>

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/blocked_range.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>
#endif

namespace CGAL {
namespace Shape_analysis {
namespace internal {

// Whether work can run on several threads in this build.
constexpr bool parallel_available()
{
#ifdef CGAL_LINKED_WITH_TBB
  return true;
#else
  return false;
#endif
}

template <typename Workspace>
class Parallel_workspaces
{
public:
  // `threads`: 0 for one per processor the process may use (available_processors()), 1 to run
  // on the calling thread only, n for at most n threads.
  explicit Parallel_workspaces(std::size_t threads = 0) : m_threads(threads) {}

  // Calls body(i, workspace) for every i in [begin, end).
  template <typename Body>
  void for_each(std::size_t begin, std::size_t end, const Body& body)
  {
    if(begin >= end)
      return;
#ifdef CGAL_LINKED_WITH_TBB
    const std::size_t threads = m_threads == 0 ? Shape_analysis::available_processors() : m_threads;
    if(threads != 1 && end - begin > 1) {
      auto loop = [&]() {
        tbb::parallel_for(tbb::blocked_range<std::size_t>(begin, end, 1),
                          [&](const tbb::blocked_range<std::size_t>& range) {
                            Workspace& w = m_workspaces.local();
                            for(std::size_t i = range.begin(); i != range.end(); ++i)
                              body(i, w);
                          });
      };
      if(m_threads == 0 && int(threads) >= tbb::this_task_arena::max_concurrency())
        loop();
      else {
        tbb::task_arena arena(static_cast<int>((std::min)(threads, std::size_t(1) << 16)));
        arena.execute(loop);
      }
      return;
    }
#endif
    Workspace& w = local();
    for(std::size_t i = begin; i < end; ++i)
      body(i, w);
  }

  // The calling thread's workspace.
  Workspace& local()
  {
#ifdef CGAL_LINKED_WITH_TBB
    return m_workspaces.local();
#else
    if(!m_single)
      m_single = std::make_unique<Workspace>();
    return *m_single;
#endif
  }

private:
  std::size_t m_threads;
#ifdef CGAL_LINKED_WITH_TBB
  tbb::enumerable_thread_specific<Workspace> m_workspaces;
#else
  std::unique_ptr<Workspace> m_single;
#endif
};

} // namespace internal
} // namespace Shape_analysis
} // namespace CGAL

#endif // CGAL_SHAPE_ANALYSIS_INTERNAL_PARALLEL_H
