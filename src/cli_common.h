// Copyright (c) 2026 CGAL Global Shape Analysis contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef SHAPE_ANALYSIS_CLI_COMMON_H
#define SHAPE_ANALYSIS_CLI_COMMON_H

// Shared pieces of the `shape_analysis` subcommands: reading meshes with their face order kept,
// writing outputs atomically (all or nothing), colours, reports, progress.

#include <CGAL/Consistent_segmentation/Consistent_segmentation_options.h>
#include <CGAL/Consistent_segmentation/Hierarchical_segmentation_options.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <Shape_analysis_support/Json.h>

#include <CLI/CLI.hpp>

#include <array>
#include <chrono>
#include <functional>
#include <initializer_list>
#include <stdexcept>
#include <string>
#include <vector>
namespace SAS = CGAL::Shape_analysis_support;

namespace CGAL {
namespace Point_set_object_recognition {
enum class Localization_method;
} // namespace Point_set_object_recognition
} // namespace CGAL

namespace shape_analysis_cli {

typedef CGAL::Exact_predicates_inexact_constructions_kernel Kernel;
typedef Kernel::Point_3 Point_3;
typedef CGAL::Surface_mesh<Point_3> Mesh;
using SAS::Json;

// An error the tool reports in one line and exits non-zero for (1: the job failed).
struct Cli_error : std::runtime_error
{
  explicit Cli_error(const std::string& what) : std::runtime_error(what) {}
};

// A command line that cannot work as given (exit code 2), found after parsing.
struct Usage_error : Cli_error
{
  explicit Usage_error(const std::string& what) : Cli_error(what) {}
};

// A triangle mesh read from a file, with what is needed to answer per input face.
struct Input_mesh
{
  Mesh mesh;                                    // the faces that form a surface
  std::vector<Point_3> points;                  // the file's points, exact duplicates merged
  std::vector<std::array<std::size_t, 3>> triangles; // every input face, in the file's order
  std::vector<std::size_t> mesh_face;           // per input face: its face in `mesh`, or `left_out`
  std::size_t merged_points = 0;                // duplicate points merged
  std::size_t left_out_faces = 0;               // degenerate or repeated faces left out of `mesh`
  std::vector<std::size_t> input_index;         // per point: the smallest index of the file's
                                                // vertices at that position
  std::vector<std::size_t> vertex_point;        // per vertex of `mesh` (by index): its point

  static constexpr std::size_t left_out = static_cast<std::size_t>(-1);

  std::size_t number_of_input_faces() const { return triangles.size(); }

  // Labels per input face from labels per face of `mesh` (in the order of faces(mesh)): a face
  // left out takes the label of the face of `mesh` sharing most of its vertices (label 0 when
  // none does).
  std::vector<std::size_t> input_labels(const std::vector<std::size_t>& mesh_labels) const;
};

// Reads a triangle mesh (OFF, PLY, OBJ, STL). Exact duplicate points are merged; a face that
// repeats a vertex, or repeats another face, is left out of the surface (and labelled like its
// neighbour by `input_labels`); a non-manifold or badly oriented soup is repaired by orienting it.
// Throws Cli_error with the reason when the file cannot be used.
Input_mesh read_triangle_mesh(const std::string& path);

// Reads one integer label per line (the Princeton Segmentation Benchmark's .seg format).
std::vector<long long> read_labels(const std::string& path);

// Output files written all-or-nothing. Each is first written to a temporary file beside its
// (link-resolved) target; commit() renames them all; without commit() (an error happened) they
// are removed. An existing target that is not a regular file (/dev/null, a pipe) is written to
// directly at commit time.
class Output_files
{
public:
  Output_files() = default;
  Output_files(const Output_files&) = delete;
  Output_files& operator=(const Output_files&) = delete;
  ~Output_files();

  // Declares an input file: no output may be written over it.
  void add_input(const std::string& path);
  // Declares an output before any work: checks that it has one of `extensions` (when given,
  // case-insensitive, e.g. {".ply", ".las"}), that its directory exists and is writable and that
  // it is neither an input nor another output. Throws Cli_error / Usage_error otherwise.
  void add_output(const std::string& path, const std::string& what,
                  std::initializer_list<const char*> extensions = {});
  // The same for an output that was not asked for when `path` is empty (then nothing happens).
  void add_optional_output(const std::string& path, const std::string& what,
                           std::initializer_list<const char*> extensions = {})
  {
    if(!path.empty())
      add_output(path, what, extensions);
  }

  // Writes the content produced by `writer` into a temporary file for the declared `path`.
  void stage(const std::string& path, bool binary, const std::function<void(std::ostream&)>& writer);
  // The same, `writer` given the temporary file's name to write it itself (e.g. from several
  // processes of one machine: for a target that is not a regular file, the temporary file is in
  // the temporary directory).
  void stage_file(const std::string& path, const std::function<void(const std::string& temporary)>& writer);
  void commit();

private:
  struct Staged
  {
    std::string temporary, target, shown;
    bool special;
  };
  std::vector<std::pair<std::string, std::string>> m_inputs;  // (resolved, as given)
  std::vector<std::pair<std::string, std::string>> m_outputs; // (resolved, as given)
  std::vector<Staged> m_staged;
  bool m_committed = false;
  // A new temporary file for the declared `path`, staged (`special`: the target is not a regular file).
  std::string new_temporary(const std::string& path, bool& special);
};

// Distinct colours for labels 0, 1, 2, ... (golden-angle hues).
std::array<unsigned char, 3> label_colour(std::size_t label);

// Binary PLY of a triangle soup, coordinates in double precision, faces in the given order, with
// a colour per face and one scalar face property named `property` (int or float).
void write_face_ply(std::ostream& out, const std::vector<Point_3>& points,
                    const std::vector<std::array<std::size_t, 3>>& triangles,
                    const std::function<std::array<unsigned char, 3>(std::size_t)>& colour,
                    const std::string& property, bool integer_property,
                    const std::function<double(std::size_t)>& value);

// Binary PLY of a triangle soup with per-face colours from `labels` and an integer face
// property `segment`; coordinates in double precision; faces in the given order.
void write_labelled_ply(std::ostream& out, const std::vector<Point_3>& points,
                        const std::vector<std::array<std::size_t, 3>>& triangles,
                        const std::vector<std::size_t>& labels);

// OFF of a triangle soup, coordinates with every digit of a double; faces in the given order.
void write_off(std::ostream& out, const std::vector<Point_3>& points,
               const std::vector<std::array<std::size_t, 3>>& triangles);

// The diagonal of the bounding box of `points` (0 when empty).
double bounding_box_diagonal(const std::vector<Point_3>& points);

// Checks that the input `path` can be read: Cli_error "cannot read 'path': no such file", "...: it
// is a directory", "...: not a regular file" (a device or a pipe: the readers need a file) or
// "...: permission denied".
void check_input_file(const std::string& path);

// The whole command line: parses it, checks its values and, with `execute`, runs the job;
// messages on stderr; returns the exit code (0, 1 the job failed, 2 bad command line). Without
// `execute` (the fuzzer of the option parsing), 0 when the command line is accepted.
int run_command_line(int argc, char** argv, bool execute);

// The finite number of a cell; throws Cli_error `where` + why otherwise.
double finite_number(const std::string& cell, const std::string& where);

// A count option's check: a whole number >= 1, else "must be a positive whole number (got x)"
// (CLI11's PositiveNumber names the largest double in its message).
extern const CLI::Validator positive_count;
// The same, or the word "auto", which becomes 0 (the library's "choose it").
extern const CLI::Validator positive_count_or_auto;
// A number of segments as such an option reads it: "auto" for 0, else the number (help defaults).
std::string count_or_auto(std::size_t k);
// The same in a progress line: "an automatic number of" for 0.
std::string count_in_words(std::size_t k);

// The extension of `path`, lower case (".ply").
std::string lower_extension(const std::string& path);

// Checks that `path` ends with one of `extensions` (case-insensitive, e.g. {".ply", ".las"});
// Usage_error naming `what` and the formats otherwise ("the coloured mesh is written as PLY: name
// it '.ply' (got 'parts.off')").
void require_extension(const std::string& path, std::initializer_list<const char*> extensions, const std::string& what);

// One label per line.
void write_labels(std::ostream& out, const std::vector<std::size_t>& labels);

// Reads the input mesh of a subcommand, with a progress note on what was repaired.
class Progress;
Input_mesh read_input_mesh(const std::string& path, Progress& progress, double& read_seconds);

// Labels per input face from the face labels of `input.mesh` in a property map.
std::vector<std::size_t>
labels_per_input_face(const Input_mesh& input,
                      const Mesh::Property_map<Mesh::Face_index, std::size_t>& mesh_labels);

// Stages the outputs of a segmentation: the coloured mesh (`ply`) and the label file (`seg`);
// an empty path is skipped.
void stage_segmentation(Output_files& outputs, Progress& progress, const Input_mesh& input,
                        const std::vector<std::size_t>& labels, const std::string& ply,
                        const std::string& seg);

// The start of a JSON report: the command and what the input mesh (`prefix` names it in
// reports with several inputs) is made of.
Json input_report(const std::string& command, const std::string& path, const Input_mesh& input);
void add_input_report(Json& report, const std::string& prefix, const std::string& path,
                      const Input_mesh& input);

// Adds "seconds", "seconds_reading", "seconds_total" and "outputs" (name -> path or null) and
// stages the report at `path`.
void stage_report(Output_files& outputs, const std::string& path, Json report, double seconds,
                  double read_seconds, double total_seconds,
                  const std::vector<std::pair<std::string, std::string>>& named_outputs);

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
// `defaults`: the library's own unless a test gives others (to show the tool follows them).
void add_segment_command(CLI::App& app, std::function<int()>& run,
                         const CGAL::Consistent_segmentation::Hierarchical_segmentation_options& defaults = {});
void add_register_command(CLI::App& app, std::function<int()>& run);
void add_deform_command(CLI::App& app, std::function<int()>& run); // (register_command.cpp)
void add_partition_commands(CLI::App& app, std::function<int()>& run); // partition, partition-segment
void add_coseg_command(CLI::App& app, std::function<int()>& run,
                       const CGAL::Consistent_segmentation::Consistent_segmentation_options& defaults = {});
void add_symmetry_command(CLI::App& app, std::function<int()>& run); // symmetry detect|symmetrize|enhance|transfer|remesh|decimate
void add_points_command(CLI::App& app, std::function<int()>& run);   // points scene|background
void add_points_segment_commands(CLI::App* points, std::function<int()>& run); // points segment|evaluate

// An object of a ground-truth file written by `points generate --truth` (or `points scene
// --objects`).
struct Truth_object
{
  int id = 0, object_class = 0;
  std::string name;                           // "class", empty when the file does not say
  std::array<double, 3> location{{0, 0, 0}};  // z is 0 when the file gives only (x, y)
  long scanned_points = -1;                   // -1 when the file does not say
};
// The objects of such a file (a JSON array of objects with "id", "class", "class_id",
// "location": [x, y, z] and "scanned_points"; only "location" is required). An empty array gives
// no object; throws Cli_error on a file that cannot be read or an object without a location.
std::vector<Truth_object> read_truth_objects(const std::string& path);

// The localization method of a command-line name: nc, meanshift (mean-shift), image, cc (the
// default for any other name; CLI11 checks the names).
CGAL::Point_set_object_recognition::Localization_method localization_method(const std::string& name);

// locations.csv: a header line `x,y,z`, then one location per line (17 significant digits).
void write_locations_csv(std::ostream& out, const std::vector<std::array<double, 3>>& locations);

} // namespace shape_analysis_cli

#endif // SHAPE_ANALYSIS_CLI_COMMON_H
