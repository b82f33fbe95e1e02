// Copyright (c) 2026 CGAL Global Shape Analysis contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef SHAPE_ANALYSIS_RANKS_H
#define SHAPE_ANALYSIS_RANKS_H

// The processes of a run: one, or the ranks of an Open MPI job (`mpirun -np N shape_analysis
// ...`, when the tool is built with MPI). Everything here is collective (every rank calls it, in
// the same order) but `Counter::next()`; with one process it costs nothing.

#include <cstdint>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

namespace shape_analysis_cli {

class Ranks
{
public:
  // The run's processes: MPI_Init_thread when the process was started by mpirun (its
  // environment says so) and the tool has MPI; one process otherwise. Called once, by main().
  static void initialize(int& argc, char**& argv);
  // MPI_Finalize when MPI was initialized.
  static void finalize();
  static const Ranks& world();

  int size() const { return m_size; }
  int rank() const { return m_rank; }

  void barrier() const;
  // Per position, the smallest (lo) and largest (hi) over the ranks, in place.
  void min_max(std::vector<double>& lo, std::vector<double>& hi) const;
  // Per position, the sum over the ranks, in place.
  void sum(std::vector<std::uint64_t>& v) const;
  // `error` is this rank's ("" for none); returns the error of the lowest rank that has one,
  // with its rank when there are several ranks, or "" on every rank.
  std::string first_error(const std::string& error) const;
  // Rank 0's `s` on every rank.
  std::string broadcast(const std::string& s) const;

  // A counter shared by the ranks (and the threads of each): next() returns 0, 1, 2... once each.
  class Counter
  {
  public:
    explicit Counter(const Ranks& ranks); // collective
    ~Counter();                           // collective
    std::uint64_t next();

  private:
    struct State;
    std::unique_ptr<State> m_state;
    std::mutex m_mutex;
  };

private:
  int m_size = 1, m_rank = 0;
  bool m_mpi = false;
};

} // namespace shape_analysis_cli

#endif // SHAPE_ANALYSIS_RANKS_H
