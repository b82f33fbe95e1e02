// Copyright (c) 2026 CGAL Global Shape Analysis contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later

// The tool run as a process by the CLI's GoogleTest suites (CliCommit, CliTiles):
// SHAPE_ANALYSIS_TOOL is its path.

#ifndef SHAPE_ANALYSIS_TEST_TOOL_PROCESS_H
#define SHAPE_ANALYSIS_TEST_TOOL_PROCESS_H

#include <fcntl.h>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <spawn.h>
#include <string>
#include <sys/wait.h>
#include <unistd.h>
#include <vector>

extern char** environ;

namespace tool_process {

namespace fs = std::filesystem;

const std::string tool = SHAPE_ANALYSIS_TOOL;

inline std::string read_file(const fs::path& path)
{
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

// How to start a program (start_program()).
struct Launch
{
  std::vector<std::pair<std::string, std::string>> environment; // set (or replaced) for it
  std::string standard_error;                                   // its stderr to this file, unless empty
  bool own_group = false; // in a process group of its own (killpg(pid, ...) reaches its children)
};

// Starts `program` with `args` (its standard output discarded); -1 if it cannot start.
inline pid_t start_program(const std::string& program, std::vector<std::string> args, const Launch& launch = {})
{
  args.insert(args.begin(), program);
  std::vector<char*> argv;
  for(std::string& a : args)
    argv.push_back(a.data());
  argv.push_back(nullptr);
  std::vector<std::string> env_strings;
  for(char** e = environ; *e; ++e) {
    bool replaced = false;
    for(const auto& v : launch.environment)
      replaced = replaced || std::string(*e).rfind(v.first + "=", 0) == 0;
    if(!replaced)
      env_strings.emplace_back(*e);
  }
  for(const auto& v : launch.environment)
    env_strings.push_back(v.first + "=" + v.second);
  std::vector<char*> envp;
  for(std::string& e : env_strings)
    envp.push_back(e.data());
  envp.push_back(nullptr);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, 1, "/dev/null", O_WRONLY, 0);
  if(!launch.standard_error.empty())
    posix_spawn_file_actions_addopen(&actions, 2, launch.standard_error.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  posix_spawnattr_t attributes;
  posix_spawnattr_init(&attributes);
  if(launch.own_group) {
    posix_spawnattr_setflags(&attributes, POSIX_SPAWN_SETPGROUP);
    posix_spawnattr_setpgroup(&attributes, 0);
  }
  pid_t pid = -1;
  if(::posix_spawnp(&pid, program.c_str(), &actions, &attributes, argv.data(), envp.data()) != 0)
    pid = -1;
  posix_spawnattr_destroy(&attributes);
  posix_spawn_file_actions_destroy(&actions);
  return pid;
}

// Starts the tool with `args` (its standard output discarded), SHAPE_ANALYSIS_COMMIT_STEP_DELAY
// set to `delay` microseconds: the pause after each step of a commit.
inline pid_t start_tool(std::vector<std::string> args, long delay)
{
  Launch launch;
  launch.environment.emplace_back("SHAPE_ANALYSIS_COMMIT_STEP_DELAY", std::to_string(delay));
  return start_program(tool, std::move(args), launch);
}

inline int wait_for(pid_t pid)
{
  int status = 0;
  ::waitpid(pid, &status, 0);
  return status;
}

// Runs the tool to its end; whether it exited with 0.
inline bool run_tool(const std::vector<std::string>& args)
{
  const int status = wait_for(start_tool(args, 0));
  return WIFEXITED(status) && WEXITSTATUS(status) == 0;
}

} // namespace tool_process

#endif // SHAPE_ANALYSIS_TEST_TOOL_PROCESS_H
