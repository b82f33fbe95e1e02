// Copyright (c) 2026 CGAL Global Shape Analysis contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later

// shape_analysis: the command-line tool of CGAL Global Shape Analysis (src/command_line.cpp).
// Exit codes: 0 success, 1 the job failed (bad input, unreadable file...), 2 bad command line.

#include "cli_common.h"
#include "ranks.h"

int main(int argc, char** argv)
{
  // Under mpirun, the ranks of the job (MPI_Init); `points recognize --work-dir` shares its work.
  shape_analysis_cli::Ranks::initialize(argc, argv);
  const int status = shape_analysis_cli::run_command_line(argc, argv, true);
  shape_analysis_cli::Ranks::finalize();
  return status;
}
