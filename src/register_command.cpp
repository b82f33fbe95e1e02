// Copyright (c) 2026 CGAL Global Shape Analysis contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later

// shape_analysis register SOURCE TARGET --output SOURCE_aligned.off --report R.json
// shape_analysis deform IN --handles H.txt [--fixed F.txt] [--edge-values V.txt] --output OUT.off

#include "cli_common.h"

#include <CGAL/Randomized_cuts/partition_aware_deformation.h>
#include <CGAL/Randomized_cuts/partition_function.h>
#include <CGAL/Randomized_cuts/register_meshes.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <fstream>
#include <limits>
#include <map>
#include <memory>
#include <sstream>

namespace shape_analysis_cli {

namespace {

namespace RC = CGAL::Randomized_cuts;

// The files and switches of the command; the registration's options with the library's defaults.
struct Register_options
{
  std::string source, target, output_off, report;
  RC::Register_meshes_options registration;
  bool no_partition_weighting = false;
  bool quiet = false;
  bool verbose = false;
};

int run_register(const Register_options& o)
{
  Stopwatch total;
  Progress progress("register", o.quiet, o.verbose);
  const RC::Register_meshes_options& ro = o.registration;
  const bool weighting = ro.partition_weighting && !o.no_partition_weighting;

  // Check every output location before any work, so that a bad path costs nothing.
  Output_files outputs;
  outputs.add_input(o.source);
  outputs.add_input(o.target);
  if(!o.output_off.empty()) {
    outputs.add_output(o.output_off, "aligned mesh", {".off"});
  }
  outputs.add_optional_output(o.report, "report", {".json"});

  double read_source = 0, read_target = 0;
  const Input_mesh source = read_input_mesh(o.source, progress, read_source);
  const Input_mesh target = read_input_mesh(o.target, progress, read_target);
  const double read_seconds = read_source + read_target;

  progress.stage(std::string("registering ") + std::to_string(num_faces(source.mesh)) + " onto " +
                 std::to_string(num_faces(target.mesh)) + " faces" +
                 (!weighting ? " (uniform sampling)"
                             : " (partition functions of " + std::to_string(ro.number_of_samples) +
                                 " samples)"));
  std::function<void(double)> on_progress = [&](double f) { progress.fraction(f); };
  const auto np = RC::parameters::number_of_points(ro.number_of_points)
                    .number_of_samples(ro.number_of_samples)
                    .number_of_iterations(ro.number_of_iterations)
                    .overlap(ro.overlap)
                    .random_seed(ro.random_seed)
                    .number_of_threads(ro.number_of_threads)
                    .partition_weighting(weighting)
                    .progress_callback(on_progress);
  Stopwatch registering;
  const RC::Registration_result<Kernel> r = RC::register_meshes(source.mesh, target.mesh, np);
  const double register_seconds = registering.seconds();
  progress.done();

  const double diagonal = bounding_box_diagonal(target.points);
  const double relative_rms = diagonal > 0 ? r.rms_distance / diagonal : 0.0;

  if(!o.output_off.empty()) {
    progress.stage("writing " + o.output_off);
    std::vector<Point_3> moved;
    moved.reserve(source.points.size());
    for(const Point_3& p : source.points)
      moved.push_back(r.transformation.transform(p));
    outputs.stage(o.output_off, false,
                  [&](std::ostream& out) { write_off(out, moved, source.triangles); });
  }
  if(!o.report.empty()) {
    Json report = Json::object();
    report["command"] = "register";
    add_input_report(report, "source", o.source, source);
    add_input_report(report, "target", o.target, target);
    // The options as the library's named parameters.
    Json parameters = Json::object();
    parameters["number_of_points"] = ro.number_of_points;
    parameters["number_of_samples"] = ro.number_of_samples;
    parameters["number_of_iterations"] = ro.number_of_iterations;
    parameters["overlap"] = ro.overlap;
    parameters["random_seed"] = ro.random_seed;
    parameters["number_of_threads"] = ro.number_of_threads;
    parameters["partition_weighting"] = weighting;
    report["parameters"] = parameters;
    report["rms_distance"] = r.rms_distance;
    report["rms_distance_relative_to_target_diagonal"] = relative_rms;
    report["initial_rms_distance"] = r.initial_rms_distance;
    report["scale"] = r.scale;
    Json matrix = Json::array();
    for(int i = 0; i < 4; ++i) {
      std::vector<double> row;
      for(int j = 0; j < 4; ++j)
        row.push_back(i < 3 ? CGAL::to_double(r.transformation.m(i, j)) : (j == 3 ? 1.0 : 0.0));
      matrix.push_back(Json(row));
    }
    report["matrix"] = matrix;
    report["restarts"] = r.number_of_restarts;
    report["best_restart"] = r.best_restart;
    report["iterations"] = r.number_of_iterations;
    report["converged"] = r.converged;
    stage_report(outputs, o.report, report, register_seconds, read_seconds, total.seconds(),
                 {{"mesh", o.output_off}});
  }
  outputs.commit();

  std::cout << o.source << " onto " << o.target << ": scale " << r.scale << ", RMS distance "
            << r.rms_distance << " (" << 100 * relative_rms
            << "% of the target's bounding-box diagonal) in " << register_seconds << " s\n";
  return 0;
}

// The files and switches of `deform`; the library's options with its defaults.
struct Deform_options
{
  std::string input, handles, fixed, edge_values, output_off, report;
  RC::Partition_aware_deformation_options deformation;
  RC::Partition_function_options sampling;
  bool quiet = false;
  bool verbose = false;
};

// The lines of a text file as numbers, `count` per line (blank lines skipped); Cli_error naming
// the file and line otherwise.
std::vector<std::vector<double>> read_number_lines(const std::string& path, std::size_t count, const std::string& what)
{
  std::ifstream in(path);
  if(!in)
    throw Cli_error("cannot open " + what + " '" + path + "'");
  std::vector<std::vector<double>> lines;
  std::string line;
  for(std::size_t number = 1; std::getline(in, line); ++number) {
    std::istringstream ss(line);
    std::vector<double> v;
    std::string word;
    while(ss >> word)
      v.push_back(finite_number(word, path + ": line " + std::to_string(number) + ": "));
    if(v.empty())
      continue;
    if(v.size() != count)
      throw Cli_error(path + ": line " + std::to_string(number) + ": " + std::to_string(count) + " numbers expected (" +
                      what + "), got " + std::to_string(v.size()));
    lines.push_back(v);
  }
  return lines;
}

// The vertices of `input.mesh` by the file's vertex index (a vertex that repeats an earlier
// one's position has none: its point is the earlier one's).
std::map<std::size_t, Mesh::Vertex_index> vertices_by_file_index(const Input_mesh& input)
{
  std::map<std::size_t, Mesh::Vertex_index> result;
  for(Mesh::Vertex_index v : input.mesh.vertices()) {
    const std::size_t i = input.input_index[input.vertex_point[v]];
    if(result.count(i) == 0)
      result[i] = v;
  }
  return result;
}

// The vertex of the file's vertex index `x` (a number read from `path`).
Mesh::Vertex_index vertex_of(const std::map<std::size_t, Mesh::Vertex_index>& vertices, double x, const std::string& path)
{
  const auto it = x >= 0 && x == std::floor(x) && x < 1e18 ? vertices.find(std::size_t(x)) : vertices.end();
  if(it == vertices.end())
    throw Cli_error(path + ": " + (x == std::floor(x) && std::abs(x) < 1e15 ? std::to_string((long long)x) : Json(x).dump()) +
                    " is not the index of a vertex on a face (nor of the first of vertices at one position)");
  return it->second;
}

int run_deform(const Deform_options& o)
{
  Stopwatch total;
  Progress progress("deform", o.quiet, o.verbose);
  Output_files outputs;
  outputs.add_input(o.input);
  outputs.add_input(o.handles);
  if(!o.fixed.empty())
    outputs.add_input(o.fixed);
  if(!o.edge_values.empty())
    outputs.add_input(o.edge_values);
  outputs.add_output(o.output_off, "deformed mesh", {".off"});
  outputs.add_optional_output(o.report, "report", {".json"});
  double read_seconds = 0;
  Input_mesh input = read_input_mesh(o.input, progress, read_seconds);
  Mesh& mesh = input.mesh;
  const std::map<std::size_t, Mesh::Vertex_index> by_index = vertices_by_file_index(input);

  Stopwatch reading;
  std::vector<Mesh::Vertex_index> controls, fixed;
  std::vector<Point_3> targets;
  for(const auto& l : read_number_lines(o.handles, 4, "a vertex index and its target x y z")) {
    controls.push_back(vertex_of(by_index, l[0], o.handles));
    targets.emplace_back(l[1], l[2], l[3]);
  }
  if(controls.empty())
    throw Cli_error(o.handles + ": no handle (lines 'vertex x y z')");
  if(!o.fixed.empty())
    for(const auto& l : read_number_lines(o.fixed, 1, "a vertex index"))
      fixed.push_back(vertex_of(by_index, l[0], o.fixed));
  std::vector<double> values(num_edges(mesh), 0.0);
  bool computed = o.edge_values.empty();
  if(!computed) { // 'i j value' lines, as `partition --edge-values` writes them
    std::map<std::pair<std::size_t, std::size_t>, double> by_pair;
    for(const auto& l : read_number_lines(o.edge_values, 3, "'i j value'")) {
      const Mesh::Vertex_index a = vertex_of(by_index, l[0], o.edge_values);
      const Mesh::Vertex_index b = vertex_of(by_index, l[1], o.edge_values);
      by_pair[{(std::min)(a.idx(), b.idx()), (std::max)(a.idx(), b.idx())}] = l[2];
    }
    for(Mesh::Edge_index e : edges(mesh)) {
      const std::size_t a = source(halfedge(e, mesh), mesh).idx(), b = target(halfedge(e, mesh), mesh).idx();
      const auto it = by_pair.find({(std::min)(a, b), (std::max)(a, b)});
      if(it == by_pair.end()) {
        const auto index = [&](std::size_t v) { return input.input_index[input.vertex_point[Mesh::Vertex_index(Mesh::size_type(v))]]; };
        throw Cli_error(o.edge_values + ": no value for the edge of vertices " + std::to_string(index(a)) + " and " +
                        std::to_string(index(b)));
      }
      values[e.idx()] = it->second;
    }
  }
  read_seconds += reading.seconds();

  Stopwatch working;
  std::function<void(double)> on_progress = [&](double f) { progress.fraction(f); };
  const RC::Partition_function_options& so = o.sampling;
  if(computed) {
    progress.stage("sampling the partition function (" + std::to_string(so.number_of_samples) + " segmentations)");
    RC::partition_function(mesh, CGAL::make_property_map(values),
                           RC::parameters::sampling_method(RC::MIN_CUT) // the joints, not every boundary
                             .number_of_samples(so.number_of_samples)
                             .random_seed(so.random_seed)
                             .number_of_threads(so.number_of_threads)
                             .progress_callback(on_progress));
    progress.done();
  }
  progress.stage("deforming " + std::to_string(num_vertices(mesh)) + " vertices, " + std::to_string(controls.size()) +
                 " handles");
  const RC::Partition_aware_deformation_options& d = o.deformation;
  auto np = RC::parameters::number_of_iterations(d.number_of_iterations)
              .convergence_tolerance(d.convergence_tolerance)
              .flexible_weight(d.flexible_weight)
              .stiffness_exponent(d.stiffness_exponent)
              .spread_rings(d.spread_rings);
  const RC::Partition_aware_deformation_result r =
    d.value_scale ? RC::partition_aware_deformation(mesh, CGAL::make_property_map(values), controls, targets, fixed,
                                                    np.value_scale(*d.value_scale))
                  : RC::partition_aware_deformation(mesh, CGAL::make_property_map(values), controls, targets, fixed, np);
  progress.done();
  const double seconds = working.seconds();

  std::vector<Point_3> points = input.points;
  for(Mesh::Vertex_index v : mesh.vertices())
    points[input.vertex_point[v]] = mesh.point(v);
  progress.stage("writing " + o.output_off);
  outputs.stage(o.output_off, false, [&](std::ostream& out) { write_off(out, points, input.triangles); });
  if(!o.report.empty()) {
    Json report = input_report("deform", o.input, input);
    Json parameters = Json::object();
    parameters["number_of_iterations"] = d.number_of_iterations;
    parameters["convergence_tolerance"] = d.convergence_tolerance;
    parameters["flexible_weight"] = d.flexible_weight;
    parameters["stiffness_exponent"] = d.stiffness_exponent;
    parameters["value_scale"] = d.value_scale ? Json(*d.value_scale) : Json();
    parameters["spread_rings"] = d.spread_rings;
    report["parameters"] = parameters;
    report["handles"] = controls.size();
    report["fixed"] = fixed.size();
    report["partition_function"] = computed ? Json("computed") : Json(o.edge_values);
    report["number_of_samples"] = computed ? Json(so.number_of_samples) : Json();
    report["iterations"] = r.number_of_iterations;
    report["converged"] = r.converged;
    report["largest_displacement"] = r.largest_displacement;
    stage_report(outputs, o.report, report, seconds, read_seconds, total.seconds(), {{"mesh", o.output_off}});
  }
  outputs.commit();
  std::cout << o.input << ": " << controls.size() << " handles moved, " << r.number_of_iterations << " iterations"
            << (r.converged ? " (converged)" : "") << " in " << seconds << " s\n";
  return 0;
}

} // namespace

void add_deform_command(CLI::App& app, std::function<int()>& run)
{
  auto o = std::make_shared<Deform_options>();
  RC::Partition_aware_deformation_options& d = o->deformation;
  CLI::App* cmd = app.add_subcommand(
    "deform", "Deform a triangle mesh as rigidly as possible, bending where the partition function puts part "
              "boundaries: handle vertices go to their targets, fixed ones stay.");
  cmd->add_option("input", o->input, "Triangle mesh (.off, .ply, .obj, .stl)")->required();
  cmd->add_option("--handles", o->handles, "Text file, one line 'vertex x y z' per handle (the file's vertex index)")
    ->required();
  cmd->add_option("--fixed", o->fixed, "Text file, one vertex index per line: vertices kept in place");
  cmd->add_option("--edge-values", o->edge_values,
                  "The partition function as 'partition --edge-values' writes it ('i j value' per edge); "
                  "computed when absent");
  cmd->add_option("-o,--output", o->output_off, "The deformed mesh (.off; the input's vertices and faces)")->required();
  cmd->add_option("--report", o->report, "JSON report (inputs, parameters, iterations, seconds)");
  cmd->add_option("-n,--samples", o->sampling.number_of_samples,
                  "Without --edge-values: segmentations sampled for the partition function")
    ->capture_default_str()
    ->check(positive_count);
  cmd->add_option("--seed", o->sampling.random_seed, "Without --edge-values: random seed")->capture_default_str();
  cmd->add_option("--threads", o->sampling.number_of_threads, "Threads of the sampling (0: all cores)")
    ->capture_default_str();
  cmd->add_option("--iterations", d.number_of_iterations, "Largest number of as-rigid-as-possible iterations")
    ->capture_default_str()
    ->check(positive_count);
  cmd->add_option("--tolerance", d.convergence_tolerance,
                  "Stop when no vertex moves more than this fraction of the diagonal in an iteration")
    ->capture_default_str();
  cmd->add_option("--flexible-weight", d.flexible_weight, "Stiffness factor of an edge on a part boundary, in (0, 1]")
    ->capture_default_str();
  cmd->add_option("--stiffness-exponent", d.stiffness_exponent, "Exponent of the stiffness factor (> 0)")
    ->capture_default_str();
  cmd->add_option("--value-scale", d.value_scale,
                  "Partition-function value from which an edge is fully flexible, in (0, 1] (default: half "
                  "the largest value)");
  cmd->add_option("--spread-rings", d.spread_rings, "Rings over which the values are spread (0 to 4)")
    ->capture_default_str();
  cmd->add_flag("-q,--quiet", o->quiet, "No progress on stderr");
  cmd->add_flag("-v,--verbose", o->verbose, "Progress on stderr even when it is not a terminal");
  cmd->callback([o, &run]() { run = [o]() { return run_deform(*o); }; });
}

void add_register_command(CLI::App& app, std::function<int()>& run)
{
  auto options = std::make_shared<Register_options>();
  RC::Register_meshes_options& ro = options->registration;
  CLI::App* cmd = app.add_subcommand(
    "register",
    "Register two triangle meshes: the similarity transform (rotation, scale, translation) that "
    "maps SOURCE onto TARGET (samples weighted by the partition function, ICP with restarts).");
  cmd->add_option("source", options->source, "Mesh to move (.off, .ply, .obj, .stl)")->required();
  cmd->add_option("target", options->target, "Mesh to move onto (.off, .ply, .obj, .stl)")->required();
  cmd->add_option("-o,--output", options->output_off,
                  "SOURCE moved onto TARGET (.off; the input's vertices and faces, in order)");
  cmd->add_option("--report", options->report,
                  "JSON report (inputs, parameters, seconds, RMS distance, scale, 4x4 matrix)");
  cmd->add_option("--points", ro.number_of_points, "Number of points sampled on each mesh (>= 10)")
    ->capture_default_str()
    ->check(positive_count);
  cmd->add_option("-n,--samples", ro.number_of_samples,
                  "Number of segmentations sampled for each partition function")
    ->capture_default_str()
    ->check(positive_count);
  cmd->add_option("--iterations", ro.number_of_iterations, "Largest number of ICP iterations per restart")
    ->capture_default_str();
  cmd->add_option("--overlap", ro.overlap,
                  "Fraction of the closest point pairs kept by ICP, in (0, 1]")
    ->capture_default_str();
  cmd->add_option("--seed", ro.random_seed, "Random seed (same seed, same result)")->capture_default_str();
  cmd->add_option("--threads", ro.number_of_threads, "Largest number of threads (0: all cores)")
    ->capture_default_str();
  cmd->add_flag("--no-partition-weighting", options->no_partition_weighting,
                "Sample points uniformly by area (no partition function)");
  cmd->add_flag("-q,--quiet", options->quiet, "No progress on stderr");
  cmd->add_flag("-v,--verbose", options->verbose,
                "Progress on stderr even when it is not a terminal");
  cmd->callback([options, &run]() { run = [options]() { return run_register(*options); }; });
}

} // namespace shape_analysis_cli
