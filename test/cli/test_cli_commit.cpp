// Copyright (c) 2026 CGAL Global Shape Analysis contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later

// The outputs of a run are one set: two runs writing the same outputs at once never mix theirs,
// and a run killed (SIGKILL) at any moment leaves the previous set or the complete new one (once
// the next run in the folder has finished an interrupted commit). The tool is run as a process:
// `segment` on elephant.off writes a PLY, a .seg and a report; -k 3 and -k 5 give two sets that
// differ in every file.

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <csignal>
#include <cstdlib>
#include <fcntl.h>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iostream>
#include <iterator>
#include <random>
#include <spawn.h>
#include <string>
#include <sys/wait.h>
#include <thread>
#include <unistd.h>
#include <vector>

#include "tool_process.h"

namespace {

namespace fs = std::filesystem;
using namespace tool_process;

const std::string mesh = std::string(SHAPE_ANALYSIS_DATA_DIR) + "/elephant.off";

// `segment` with k segments writing out.ply, out.seg and out.json in `dir`.
pid_t start_segment(const fs::path& dir, int k, long delay)
{
  return start_tool({"segment", mesh, "-k", std::to_string(k), "-q", "-o", (dir / "out.ply").string(),
                     "--seg", (dir / "out.seg").string(), "--report", (dir / "out.json").string()},
                    delay);
}

// The three outputs of one run.
struct Output_set
{
  std::string ply, seg, segments; // segments: the report's "segments" line
  bool operator==(const Output_set& o) const { return ply == o.ply && seg == o.seg && segments == o.segments; }
};

Output_set read_set(const fs::path& dir)
{
  Output_set s{read_file(dir / "out.ply"), read_file(dir / "out.seg"), ""};
  const std::string report = read_file(dir / "out.json");
  const std::size_t at = report.find("\"segments\":");
  if(at != std::string::npos)
    s.segments = report.substr(at, report.find('\n', at) - at);
  return s;
}

Output_set reference_set(const fs::path& dir, int k)
{
  fs::create_directories(dir);
  const int status = wait_for(start_segment(dir, k, 0));
  EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0);
  return read_set(dir);
}

// Files the commit machinery leaves while a set is not complete: temporary files and journals.
std::vector<std::string> leftovers(const fs::path& dir)
{
  std::vector<std::string> found;
  for(const auto& entry : fs::directory_iterator(dir)) {
    const std::string name = entry.path().filename().string();
    if(name.find(".tmp-") != std::string::npos || name.rfind(".shape_analysis-journal", 0) == 0)
      found.push_back(name);
  }
  return found;
}

bool has_journal(const fs::path& dir)
{
  for(const auto& entry : fs::directory_iterator(dir))
    if(entry.path().filename().string().rfind(".shape_analysis-journal-", 0) == 0)
      return true;
  return false;
}

class CommitTest : public ::testing::Test
{
protected:
  void SetUp() override
  {
    root = fs::temp_directory_path() / ("shape_analysis_commit_" + std::to_string(::getpid()));
    fs::remove_all(root);
    three = reference_set(root / "three", 3);
    five = reference_set(root / "five", 5);
    ASSERT_FALSE(three.ply.empty());
    ASSERT_FALSE(three.segments.empty());
    ASSERT_NE(three.ply, five.ply);
    ASSERT_NE(three.seg, five.seg);
    ASSERT_NE(three.segments, five.segments);
    work = root / "work";
    fs::create_directories(work);
  }
  void TearDown() override { fs::remove_all(root); }

  fs::path root, work;
  Output_set three, five;
};

TEST_F(CommitTest, ConcurrentRunsNeverMixTheirOutputs)
{
  // A pause after each step of a commit (3 renames, journal copies) makes the commits overlap.
  int threes = 0, fives = 0;
  for(int round = 0; round < 8; ++round) {
    const pid_t a = start_segment(work, 3, 20000);
    const pid_t b = start_segment(work, 5, 20000);
    ASSERT_GT(a, 0);
    ASSERT_GT(b, 0);
    const int sa = wait_for(a), sb = wait_for(b);
    ASSERT_TRUE(WIFEXITED(sa) && WEXITSTATUS(sa) == 0);
    ASSERT_TRUE(WIFEXITED(sb) && WEXITSTATUS(sb) == 0);
    const Output_set now = read_set(work);
    ASSERT_TRUE(now == three || now == five) << "round " << round << ": the outputs of two runs mixed";
    (now == three ? threes : fives) += 1;
    EXPECT_TRUE(leftovers(work).empty());
  }
  EXPECT_EQ(threes + fives, 8);
}

TEST_F(CommitTest, KilledRunsLeaveTheOldOrTheNewSet)
{
  const long delay = 30000; // microseconds after each commit step: the commit takes ~0.2 s
  std::mt19937 random(7);
  int old_kept = 0, new_complete = 0, finished_by_next_run = 0;
  fs::copy_file(root / "three" / "out.ply", work / "out.ply");
  fs::copy_file(root / "three" / "out.seg", work / "out.seg");
  fs::copy_file(root / "three" / "out.json", work / "out.json");
  Output_set before = three;
  for(int round = 0; round < 24; ++round) {
    const bool to_five = before == three;
    const Output_set& after = to_five ? five : three;
    const pid_t pid = start_segment(work, to_five ? 5 : 3, delay);
    ASSERT_GT(pid, 0);
    // Kill it while it writes its temporary files, at a random moment, or at a random moment of
    // its commit (from the first journal copy on).
    const auto start = std::chrono::steady_clock::now();
    const auto wait_until = [&](const std::function<bool()>& seen) {
      while(!seen() && std::chrono::steady_clock::now() - start < std::chrono::seconds(20))
        std::this_thread::sleep_for(std::chrono::microseconds(200));
    };
    if(round % 3 == 0)
      wait_until([&] { return !leftovers(work).empty(); });
    else if(round % 3 == 1)
      std::this_thread::sleep_for(std::chrono::microseconds(std::uniform_int_distribution<long>(0, 100000)(random)));
    else {
      wait_until([&] { return has_journal(work); });
      std::this_thread::sleep_for(std::chrono::microseconds(std::uniform_int_distribution<long>(0, 5 * delay)(random)));
    }
    ::kill(pid, SIGKILL);
    wait_for(pid);
    const bool interrupted_commit = has_journal(work);
    if(!interrupted_commit) {
      const Output_set now = read_set(work);
      ASSERT_TRUE(now == before || now == after) << "round " << round << ": a mixed set and no journal";
    }
    // The next run writing into the folder (another output) finishes what the killed run left.
    const int status =
      wait_for(start_tool({"segment", mesh, "-k", "2", "-q", "--seg", (work / "other.seg").string()}, 0));
    ASSERT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0);
    const Output_set now = read_set(work);
    ASSERT_TRUE(now == before || now == after) << "round " << round << ": a mixed set after the next run";
    const std::vector<std::string> left = leftovers(work);
    ASSERT_TRUE(left.empty()) << "round " << round << ": " << left.front() << " left behind";
    if(now == before)
      ++old_kept;
    else if(interrupted_commit)
      ++finished_by_next_run;
    else
      ++new_complete;
    before = now;
  }
  // Kills landed before (the temporary files of the killed runs were removed by the next runs),
  // during and after the decision of a commit.
  EXPECT_GE(old_kept, 8);
  EXPECT_GT(finished_by_next_run, 0);
  std::cout << "old set kept " << old_kept << ", new set complete " << new_complete
            << ", new set finished by the next run " << finished_by_next_run << "\n";
}

} // namespace
