// Copyright (c) 2026 CGAL Global Shape Analysis contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// One run at a time in a work folder of `points recognize --work-dir` (recognition_tiles.h).

#include "recognition_tiles.h"

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

namespace shape_analysis_cli {

Folder_lock::~Folder_lock()
{
  if(m_fd >= 0)
    ::close(m_fd);
}

void Folder_lock::take(const std::string& file, const std::string& folder)
{
  m_fd = ::open(file.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
  if(m_fd < 0)
    throw Cli_error("--work-dir " + folder + ": cannot create its lock file");
  if(::flock(m_fd, LOCK_EX | LOCK_NB) != 0)
    throw Cli_error("--work-dir " + folder + ": another run is using this folder");
}

} // namespace shape_analysis_cli
