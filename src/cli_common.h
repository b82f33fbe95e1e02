// Copyright (c) 2026 CGAL Global Shape Analysis contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef SHAPE_ANALYSIS_CLI_COMMON_H
#define SHAPE_ANALYSIS_CLI_COMMON_H

// Shared pieces of the `shape_analysis` subcommands: reading meshes with their face order kept,
// writing outputs atomically (all or nothing), colours, reports, progress.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Shape_analysis/internal/Json.h>

#include <CLI/CLI.hpp>

#include <array>
#include <chrono>
#include <functional>
#include <stdexcept>
#include <string>
#include <vector>

namespace shape_analysis_cli {

typedef CGAL::Exact_predicates_inexact_constructions_kernel Kernel;
typedef Kernel::Point_3 Point_3;
typedef CGAL::Surface_mesh<Point_3> Mesh;
using CGAL::Shape_analysis::internal::Json;

// An error the tool reports in one line and exits non-zero for.
struct Cli_error : std::runtime_error
{
  explicit Cli_error(const std::string& what) : std::runtime_error(what) {}
};

// Reads a triangle mesh (OFF, PLY, OBJ, STL). Face i of the result is face i of the file.
// Throws Cli_error with the reason when the file cannot be used.
Mesh read_triangle_mesh(const std::string& path);

// Reads one integer label per line (the Princeton Segmentation Benchmark's .seg format).
std::vector<long long> read_labels(const std::string& path);

// Output files written all-or-nothing: each is first written to a temporary file beside its
// target; commit() renames them all; without commit() (an error happened) they are removed.
class Output_files
{
public:
  Output_files() = default;
  Output_files(const Output_files&) = delete;
  Output_files& operator=(const Output_files&) = delete;
  ~Output_files();

  // Checks early that `path` can be written (its directory exists); throws Cli_error otherwise.
  static void check_writable(const std::string& path, const std::string& what);

  // Writes the content produced by `writer` into a temporary file for `path`.
  void stage(const std::string& path, bool binary, const std::function<void(std::ostream&)>& writer);
  void commit();

private:
  std::vector<std::pair<std::string, std::string>> m_staged; // (temporary, final)
  bool m_committed = false;
};

// Distinct colours for labels 0, 1, 2, ... (golden-angle hues).
std::array<unsigned char, 3> label_colour(std::size_t label);

// Binary PLY of the mesh with per-face colours from `labels` and an integer face property
// `segment`. Vertices and faces in the mesh's order.
void write_labelled_ply(std::ostream& out, const Mesh& mesh, const std::vector<std::size_t>& labels);

// One label per line.
void write_labels(std::ostream& out, const std::vector<std::size_t>& labels);

// Progress on stderr when it is a terminal (stage lines and a percentage), or on request
// (`verbose`: stage lines even when stderr is a file or a pipe); nothing with `quiet`.
class Progress
{
public:
  Progress(std::string command, bool quiet, bool verbose);
  void stage(const std::string& message);
  void fraction(double f);
  void done();

private:
  std::string m_command;
  bool m_quiet;
  bool m_tty;
  int m_last_percent = -1;
};

class Stopwatch
{
public:
  Stopwatch() : m_start(std::chrono::steady_clock::now()) {}
  double seconds() const
  {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - m_start).count();
  }

private:
  std::chrono::steady_clock::time_point m_start;
};

// Registration of the subcommands (one translation unit each).
void add_segment_command(CLI::App& app, std::function<int()>& run);

} // namespace shape_analysis_cli

#endif // SHAPE_ANALYSIS_CLI_COMMON_H
