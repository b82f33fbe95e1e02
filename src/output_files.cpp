// Copyright (c) 2026 CGAL Global Shape Analysis contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later

// Output_files: the outputs of a run written as one set.
//
// Each output is first written to a temporary file beside its target ("<target>.tmp-<pid>-" and six
// random characters).
// commit() then, with every output folder locked (flock, in sorted order, so that two runs commit
// one after the other):
//  1. completes or discards what an interrupted run left in these folders (below);
//  2. copies the outputs that go to special files (a device, a pipe): the step that can still fail;
//  3. writes a journal, the list of the renames to do, into every output folder: a copy is written
//     under a ".part-" name and renamed into place, and the set is decided once every copy is there;
//  4. renames the temporary files onto their targets;
//  5. removes the journal's copies.
// A run killed at any moment (SIGKILL included) thus leaves the previous outputs, or the new set
// decided by its journal, which the next run writing into any of those folders completes before
// its own commit: a journal whose copies are all there is done to the end (renames of the
// temporary files that still exist), one with a copy missing is discarded with its temporary
// files. Temporary files of processes that no longer exist are removed then too.

#include "cli_common.h"

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstdlib>
#include <cstring>
#include <fcntl.h>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

namespace shape_analysis_cli {

namespace fs = std::filesystem;

namespace {

// Temporary files to remove if the run is interrupted (SIGINT, SIGTERM, SIGHUP): plain buffers,
// so that the signal handler only reads memory and calls unlink().
constexpr std::size_t max_temporaries = 4096; // coseg stages two outputs per mesh
char temporary_names[max_temporaries][4096];
volatile std::sig_atomic_t temporary_count = 0;

extern "C" void remove_temporaries_and_exit(int signal_number)
{
  for(std::sig_atomic_t i = 0; i < temporary_count; ++i)
    if(temporary_names[i][0] != '\0')
      ::unlink(temporary_names[i]);
  ::_exit(128 + signal_number);
}

void track_temporary(const std::string& name)
{
  static bool installed = false;
  if(!installed) {
    std::signal(SIGINT, remove_temporaries_and_exit);
    std::signal(SIGTERM, remove_temporaries_and_exit);
    std::signal(SIGHUP, remove_temporaries_and_exit);
    installed = true;
  }
  if(temporary_count < std::sig_atomic_t(max_temporaries) && name.size() < sizeof(temporary_names[0])) {
    std::memcpy(temporary_names[temporary_count], name.c_str(), name.size() + 1);
    temporary_count = temporary_count + 1;
  }
}

void untrack_temporaries()
{
  for(std::sig_atomic_t i = 0; i < temporary_count; ++i)
    temporary_names[i][0] = '\0';
}

// The path an output really goes to: symbolic links followed, made absolute.
std::string resolved(const std::string& path)
{
  std::error_code ec;
  fs::path p = fs::weakly_canonical(fs::absolute(path, ec), ec);
  return ec ? fs::absolute(path).lexically_normal().string() : p.string();
}

// For the interruption test: SHAPE_ANALYSIS_COMMIT_STEP_DELAY microseconds slept after each step
// of a commit (each journal copy, rename, removal), so that a test can kill a run in the middle.
void after_step()
{
  static const long delay = [] {
    const char* value = std::getenv("SHAPE_ANALYSIS_COMMIT_STEP_DELAY");
    return value ? std::strtol(value, nullptr, 10) : 0L;
  }();
  if(delay > 0)
    ::usleep(useconds_t(std::min(delay, 10000000L)));
}

const std::string journal_prefix = ".shape_analysis-journal-";
const std::string journal_part_prefix = ".shape_analysis-journal.part-";
const std::string journal_magic = "shape_analysis journal 1";
const std::string mkstemp_template(6, 'X'); // the end of a name that mkstemp() makes unique

// The process that wrote the temporary file `name` ("<target>.tmp-<pid>-" and six characters),
// when it is one.
bool temporary_owner(const std::string& name, long& pid)
{
  const std::size_t at = name.rfind(".tmp-");
  if(at == std::string::npos || name.size() < at + 5 + 1 + 7)
    return false;
  const std::string rest = name.substr(at + 5);
  const std::size_t dash = rest.find('-');
  if(dash == 0 || dash == std::string::npos || rest.size() != dash + 7 ||
     rest.find_first_not_of("0123456789") != dash)
    return false;
  pid = std::strtol(rest.c_str(), nullptr, 10);
  return pid > 0;
}

bool process_is_gone(long pid) { return ::kill(pid_t(pid), 0) != 0 && errno == ESRCH; }

struct Journal
{
  std::vector<std::string> copies;                           // the journal's files
  std::vector<std::pair<std::string, std::string>> renames; // (temporary, target)
};

// A journal is NUL-separated: magic, number of copies, the copies, number of renames, pairs.
std::string journal_text(const Journal& j)
{
  std::string text = journal_magic + '\0' + std::to_string(j.copies.size()) + '\0';
  for(const std::string& c : j.copies)
    text += c + '\0';
  text += std::to_string(j.renames.size()) + '\0';
  for(const auto& r : j.renames)
    text += r.first + '\0' + r.second + '\0';
  return text;
}

bool read_journal(const std::string& path, Journal& j)
{
  std::ifstream in(path, std::ios::binary);
  std::vector<std::string> tokens;
  std::string token;
  while(std::getline(in, token, '\0'))
    tokens.push_back(token);
  std::size_t next = 0;
  auto count = [&](std::size_t& n) {
    if(next >= tokens.size() || tokens[next].empty() ||
       tokens[next].find_first_not_of("0123456789") != std::string::npos || tokens[next].size() > 9)
      return false;
    n = std::stoul(tokens[next++]);
    return true;
  };
  std::size_t copies = 0, renames = 0;
  if(tokens.empty() || tokens[next++] != journal_magic || !count(copies) || tokens.size() < next + copies)
    return false;
  j.copies.assign(tokens.begin() + long(next), tokens.begin() + long(next + copies));
  next += copies;
  if(!count(renames) || tokens.size() != next + 2 * renames)
    return false;
  for(std::size_t i = 0; i < renames; ++i, next += 2)
    j.renames.emplace_back(tokens[next], tokens[next + 1]);
  return true;
}

std::vector<std::string> files_starting_with(const std::string& dir, const std::string& prefix)
{
  std::vector<std::string> found;
  std::error_code ec;
  for(fs::directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec)) {
    const std::string name = it->path().filename().string();
    if(name.compare(0, prefix.size(), prefix) == 0)
      found.push_back(it->path().string());
  }
  std::sort(found.begin(), found.end());
  return found;
}

std::string folder_of(const std::string& path) { return fs::path(path).parent_path().string(); }

// Exclusive locks on folders, taken in sorted order (no deadlock between runs), released together.
class Folder_locks
{
public:
  Folder_locks() = default;
  Folder_locks(const Folder_locks&) = delete;
  Folder_locks& operator=(const Folder_locks&) = delete;
  ~Folder_locks() { release(); }

  const std::set<std::string>& folders() const { return m_folders; }

  void lock(const std::set<std::string>& folders)
  {
    release();
    m_folders = folders;
    for(const std::string& d : folders) {
      const int fd = ::open(d.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
      if(fd < 0)
        continue;
      m_fds.push_back(fd);
      while(::flock(fd, LOCK_EX) != 0 && errno == EINTR) {
      }
    }
  }

  void release()
  {
    for(int fd : m_fds)
      ::close(fd); // (releases the lock)
    m_fds.clear();
  }

private:
  std::set<std::string> m_folders;
  std::vector<int> m_fds;
};

// Completes (every copy present) or discards (a copy missing) a journal left by a killed run.
void finish_journal(const Journal& j)
{
  const bool decided = std::all_of(j.copies.begin(), j.copies.end(), [](const std::string& c) {
    std::error_code ec;
    return fs::exists(c, ec);
  });
  for(const auto& r : j.renames) {
    std::error_code ec;
    if(decided)
      fs::rename(r.first, r.second, ec); // (done already when the temporary file is gone)
    else
      fs::remove(r.first, ec);
  }
  for(const std::string& c : j.copies) {
    std::error_code ec;
    fs::remove(c, ec);
  }
}

// With `locks` held on the output folders: finishes the journals found there (locking the other
// folders they name too), then removes journal parts and temporary files of processes gone.
void recover(Folder_locks& locks)
{
  for(;;) {
    std::vector<Journal> journals;
    std::set<std::string> needed = locks.folders();
    for(const std::string& d : locks.folders())
      for(const std::string& path : files_starting_with(d, journal_prefix)) {
        Journal j;
        if(!read_journal(path, j)) { // (not written by this tool: a journal is renamed in whole)
          std::error_code ec;
          fs::remove(path, ec);
          continue;
        }
        for(const std::string& c : j.copies)
          needed.insert(folder_of(c));
        for(const auto& r : j.renames)
          needed.insert(folder_of(r.second));
        journals.push_back(std::move(j));
      }
    if(needed != locks.folders()) { // lock them all, in order, and look again
      locks.lock(needed);
      continue;
    }
    for(const Journal& j : journals)
      finish_journal(j);
    break;
  }
  // Journal parts (their writer held this folder's lock: it is gone) and temporary files of
  // processes that no longer exist.
  for(const std::string& d : locks.folders()) {
    std::vector<fs::path> left_over;
    std::error_code ec;
    for(fs::directory_iterator it(d, ec), end; !ec && it != end; it.increment(ec)) {
      const std::string name = it->path().filename().string();
      long pid = 0;
      if(name.compare(0, journal_part_prefix.size(), journal_part_prefix) == 0 ||
         (temporary_owner(name, pid) && pid != long(::getpid()) && process_is_gone(pid)))
        left_over.push_back(it->path());
    }
    for(const fs::path& p : left_over)
      fs::remove(p, ec);
  }
}

// Writes a copy of the journal at `path` through a part file renamed into place.
void write_journal_copy(const std::string& path, const std::string& text)
{
  std::string pattern = (fs::path(path).parent_path() / (journal_part_prefix + mkstemp_template)).string();
  const int fd = ::mkstemp(pattern.data());
  if(fd < 0)
    throw Cli_error("cannot write the outputs' journal in '" + folder_of(path) + "': " + std::strerror(errno));
  std::size_t written = 0;
  while(written < text.size()) {
    const ssize_t n = ::write(fd, text.data() + written, text.size() - written);
    if(n < 0 && errno == EINTR)
      continue;
    if(n <= 0) {
      const int error = errno;
      ::close(fd);
      ::unlink(pattern.c_str());
      throw Cli_error("cannot write the outputs' journal in '" + folder_of(path) + "': " + std::strerror(error));
    }
    written += std::size_t(n);
  }
  ::close(fd);
  if(::rename(pattern.c_str(), path.c_str()) != 0) {
    const int error = errno;
    ::unlink(pattern.c_str());
    throw Cli_error("cannot write the outputs' journal in '" + folder_of(path) + "': " + std::strerror(error));
  }
}

// Blocks SIGINT, SIGTERM and SIGHUP while in scope: once a journal is written the handler must not
// remove the temporary files it names.
class Signals_held
{
public:
  Signals_held()
  {
    sigset_t held;
    sigemptyset(&held);
    sigaddset(&held, SIGINT);
    sigaddset(&held, SIGTERM);
    sigaddset(&held, SIGHUP);
    ::sigprocmask(SIG_BLOCK, &held, &m_previous);
  }
  ~Signals_held() { ::sigprocmask(SIG_SETMASK, &m_previous, nullptr); }

private:
  sigset_t m_previous;
};

} // namespace

Output_files::~Output_files()
{
  if(!m_committed)
    for(const auto& s : m_staged) {
      std::error_code ec;
      fs::remove(s.temporary, ec);
    }
  untrack_temporaries();
}

void Output_files::add_input(const std::string& path)
{
  m_inputs.emplace_back(resolved(path), path);
}

void Output_files::add_output(const std::string& path, const std::string& what,
                              std::initializer_list<const char*> extensions)
{
  if(path.empty())
    throw Usage_error("the " + what + " is given an empty file name");
  const std::string target = resolved(path);
  for(const auto& in : m_inputs)
    if(in.first == target)
      throw Usage_error("the " + what + " '" + path + "' would overwrite the input '" + in.second + "'");
  for(const auto& out : m_outputs)
    if(out.first == target)
      throw Usage_error("'" + path + "' is given for two outputs");
  std::error_code ec;
  if(fs::is_directory(target, ec))
    throw Cli_error("cannot write the " + what + " '" + path + "': it is a directory");
  const bool special = fs::exists(target, ec) && !fs::is_regular_file(target, ec);
  if(!special && extensions.size() > 0) // (/dev/null, /dev/stdout: any name)
    require_extension(path, extensions, what);
  const fs::path dir = fs::path(target).parent_path();
  if(!fs::is_directory(dir, ec))
    throw Cli_error("cannot write the " + what + " '" + path + "': directory '" + dir.string() +
                    "' does not exist");
  if(special ? ::access(target.c_str(), W_OK) != 0 : ::access(dir.c_str(), W_OK) != 0)
    throw Cli_error("cannot write the " + what + " '" + path + "': " + std::strerror(errno));
  m_outputs.emplace_back(target, path);
}

std::string Output_files::new_temporary(const std::string& path, bool& special)
{
  std::string target = resolved(path);
  std::error_code ec;
  special = fs::exists(target, ec) && !fs::is_regular_file(target, ec);
  // The temporary file: beside the target (same file system, so that rename() is atomic), named
  // after this process (so that a later run can tell it is left over), or in the temporary
  // directory for a special file.
  std::string pattern = special ? (fs::temp_directory_path(ec) / ("shape_analysis." + mkstemp_template)).string()
                                : target + ".tmp-" + std::to_string(::getpid()) + "-" + mkstemp_template;
  std::vector<char> name(pattern.begin(), pattern.end());
  name.push_back('\0');
  const int fd = ::mkstemp(name.data());
  if(fd < 0)
    throw Cli_error("cannot write '" + path + "': " + std::strerror(errno));
  // mkstemp() creates the file readable by its owner only; outputs get the usual permissions.
  const mode_t mask = ::umask(0);
  ::umask(mask);
  ::fchmod(fd, 0666 & ~mask);
  ::close(fd);
  const std::string temporary(name.data());
  track_temporary(temporary);
  m_staged.push_back(Staged{temporary, target, path, special});
  return temporary;
}

void Output_files::stage(const std::string& path, bool binary,
                         const std::function<void(std::ostream&)>& writer)
{
  bool special = false;
  const std::string temporary = new_temporary(path, special);
  std::ofstream out(temporary, binary ? std::ios::binary | std::ios::trunc : std::ios::trunc);
  if(!out)
    throw Cli_error("cannot write '" + path + "'");
  writer(out);
  out.flush();
  if(!out)
    throw Cli_error("error while writing '" + path + "' (disk full?)");
}

void Output_files::stage_file(const std::string& path, const std::function<void(const std::string&)>& writer)
{
  bool special = false;
  writer(new_temporary(path, special)); // (for a special target, a file of the temporary directory)
}

void Output_files::commit()
{
  Journal journal;
  std::set<std::string> folders;
  for(const auto& s : m_staged)
    if(!s.special) {
      journal.renames.emplace_back(s.temporary, s.target);
      folders.insert(folder_of(s.target));
    }
  Folder_locks locks;
  locks.lock(folders);
  recover(locks);
  // Special files (a device, a pipe) first: they are the ones that can still fail (a full
  // device), and the regular files are renamed only once all of them took their content, so
  // that a failure leaves none of the new set.
  for(const auto& s : m_staged) {
    if(!s.special)
      continue;
    std::ifstream in(s.temporary, std::ios::binary);
    errno = 0;
    std::ofstream out(s.target, std::ios::binary);
    if(!out || !(out << in.rdbuf()) || !out.flush())
      throw Cli_error("cannot write '" + s.shown + "'" + (errno ? std::string(": ") + std::strerror(errno) : ""));
    std::error_code ec;
    fs::remove(s.temporary, ec);
  }
  Signals_held held;
  if(journal.renames.size() > 1) { // (one rename is atomic by itself)
    const std::string name = journal_prefix + std::to_string(::getpid()) + "-" +
      std::to_string(std::chrono::steady_clock::now().time_since_epoch().count());
    for(const std::string& d : folders)
      journal.copies.push_back((fs::path(d) / name).string());
    const std::string text = journal_text(journal);
    for(std::size_t i = 0; i < journal.copies.size(); ++i) {
      try {
        write_journal_copy(journal.copies[i], text);
      } catch(const Cli_error&) {
        for(std::size_t k = 0; k < i; ++k) { // (the set is not decided: the old outputs stay)
          std::error_code ec;
          fs::remove(journal.copies[k], ec);
        }
        throw;
      }
      after_step();
    }
  }
  for(const auto& r : journal.renames) {
    std::error_code ec;
    fs::rename(r.first, r.second, ec);
    if(ec) { // (the target became a folder since add_output): the rest is not written
      const std::string reason = ec.message();
      for(const std::string& copy : journal.copies)
        fs::remove(copy, ec);
      throw Cli_error("cannot write '" + r.second + "': " + reason);
    }
    after_step();
  }
  for(const std::string& copy : journal.copies) {
    std::error_code ec;
    fs::remove(copy, ec);
    after_step();
  }
  m_committed = true;
}

} // namespace shape_analysis_cli
