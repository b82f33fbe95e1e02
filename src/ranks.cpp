// Copyright (c) 2026 CGAL Global Shape Analysis contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The processes of a run (ranks.h): Open MPI's when the tool is built with it
// (SHAPE_ANALYSIS_WITH_MPI) and started by mpirun, one process otherwise.

#include "ranks.h"

#include <algorithm>
#include <cstdlib>
#include <iostream>

#ifdef SHAPE_ANALYSIS_WITH_MPI
#include <mpi.h>
#endif

namespace shape_analysis_cli {

namespace {

Ranks& the_world()
{
  static Ranks world;
  return world;
}

// Whether a launcher (mpirun, srun) started this process as one of several.
bool started_by_launcher()
{
  for(const char* v : {"OMPI_COMM_WORLD_SIZE", "PMIX_RANK", "PMI_SIZE"})
    if(std::getenv(v))
      return true;
  return false;
}

} // namespace

const Ranks& Ranks::world() { return the_world(); }

#ifdef SHAPE_ANALYSIS_WITH_MPI

void Ranks::initialize(int& argc, char**& argv)
{
  if(!started_by_launcher())
    return;
  // The ranks exchange little (a counter, a few sums and broadcasts): Open MPI's ob1 messaging
  // layer starts in a third of the time of UCX, its default when UCX is installed (measured: 0.1 s
  // against 0.3 s for 2 ranks). A choice of the user's (OMPI_MCA_pml) is kept.
  ::setenv("OMPI_MCA_pml", "ob1", 0);
  int provided = 0;
  MPI_Init_thread(&argc, &argv, MPI_THREAD_SERIALIZED, &provided);
  Ranks& w = the_world();
  w.m_mpi = true;
  MPI_Comm_size(MPI_COMM_WORLD, &w.m_size);
  MPI_Comm_rank(MPI_COMM_WORLD, &w.m_rank);
}

void Ranks::finalize()
{
  if(the_world().m_mpi)
    MPI_Finalize();
}

void Ranks::barrier() const
{
  if(m_mpi)
    MPI_Barrier(MPI_COMM_WORLD);
}

void Ranks::min_max(std::vector<double>& lo, std::vector<double>& hi) const
{
  if(!m_mpi)
    return;
  MPI_Allreduce(MPI_IN_PLACE, lo.data(), int(lo.size()), MPI_DOUBLE, MPI_MIN, MPI_COMM_WORLD);
  MPI_Allreduce(MPI_IN_PLACE, hi.data(), int(hi.size()), MPI_DOUBLE, MPI_MAX, MPI_COMM_WORLD);
}

void Ranks::sum(std::vector<std::uint64_t>& v) const
{
  if(!m_mpi)
    return;
  // In slices: MPI counts are int.
  const std::size_t slice = std::size_t(1) << 28;
  for(std::size_t at = 0; at < v.size(); at += slice)
    MPI_Allreduce(MPI_IN_PLACE, v.data() + at, int(std::min(slice, v.size() - at)), MPI_UINT64_T, MPI_SUM,
                  MPI_COMM_WORLD);
}

std::string Ranks::first_error(const std::string& error) const
{
  if(!m_mpi)
    return error;
  int failing = error.empty() ? m_size : m_rank;
  MPI_Allreduce(MPI_IN_PLACE, &failing, 1, MPI_INT, MPI_MIN, MPI_COMM_WORLD);
  if(failing == m_size)
    return std::string();
  std::string text = failing == m_rank ? error : std::string();
  int length = int(text.size());
  MPI_Bcast(&length, 1, MPI_INT, failing, MPI_COMM_WORLD);
  text.resize(std::size_t(length));
  MPI_Bcast(text.data(), length, MPI_CHAR, failing, MPI_COMM_WORLD);
  return m_size > 1 ? "rank " + std::to_string(failing) + ": " + text : text;
}

std::string Ranks::broadcast(const std::string& s) const
{
  if(!m_mpi)
    return s;
  std::string text = s;
  int length = int(text.size());
  MPI_Bcast(&length, 1, MPI_INT, 0, MPI_COMM_WORLD);
  text.resize(std::size_t(length));
  MPI_Bcast(text.data(), length, MPI_CHAR, 0, MPI_COMM_WORLD);
  return text;
}

struct Ranks::Counter::State
{
  bool mpi = false;
  std::uint64_t local = 0;
  std::uint64_t value = 0; // rank 0's, in the window
  MPI_Win window;
};

Ranks::Counter::Counter(const Ranks& ranks) : m_state(new State)
{
  m_state->mpi = ranks.m_mpi;
  if(m_state->mpi)
    MPI_Win_create(ranks.m_rank == 0 ? &m_state->value : nullptr, ranks.m_rank == 0 ? MPI_Aint(sizeof(std::uint64_t)) : 0,
                   int(sizeof(std::uint64_t)), MPI_INFO_NULL, MPI_COMM_WORLD, &m_state->window);
}

Ranks::Counter::~Counter()
{
  if(m_state->mpi) {
    MPI_Barrier(MPI_COMM_WORLD);
    MPI_Win_free(&m_state->window);
  }
}

std::uint64_t Ranks::Counter::next()
{
  std::lock_guard<std::mutex> lock(m_mutex);
  if(!m_state->mpi)
    return m_state->local++;
  const std::uint64_t one = 1;
  std::uint64_t previous = 0;
  MPI_Win_lock(MPI_LOCK_SHARED, 0, 0, m_state->window);
  MPI_Fetch_and_op(&one, &previous, MPI_UINT64_T, 0, 0, MPI_SUM, m_state->window);
  MPI_Win_unlock(0, m_state->window);
  return previous;
}

#else // one process

void Ranks::initialize(int&, char**&)
{
  // Started by mpirun as one of several: each would run the whole job. Refused (by the first).
  const char* size = std::getenv("OMPI_COMM_WORLD_SIZE");
  if(size && std::atoi(size) > 1) {
    const char* rank = std::getenv("OMPI_COMM_WORLD_RANK");
    if(!rank || std::atoi(rank) == 0)
      std::cerr << "shape_analysis: error: this shape_analysis was built without MPI: run it without mpirun"
                << std::endl;
    std::exit(2);
  }
}
void Ranks::finalize() {}
void Ranks::barrier() const {}
void Ranks::min_max(std::vector<double>&, std::vector<double>&) const {}
void Ranks::sum(std::vector<std::uint64_t>&) const {}
std::string Ranks::first_error(const std::string& error) const { return error; }
std::string Ranks::broadcast(const std::string& s) const { return s; }

struct Ranks::Counter::State
{
  std::uint64_t local = 0;
};
Ranks::Counter::Counter(const Ranks&) : m_state(new State) {}
Ranks::Counter::~Counter() = default;
std::uint64_t Ranks::Counter::next()
{
  std::lock_guard<std::mutex> lock(m_mutex);
  return m_state->local++;
}

#endif

} // namespace shape_analysis_cli
