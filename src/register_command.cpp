// Copyright (c) 2026 CGAL Global Shape Analysis contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later

// shape_analysis register SOURCE TARGET --output SOURCE_aligned.off --report R.json

#include "cli_common.h"

#include <CGAL/Randomized_cuts/register_meshes.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <limits>
#include <memory>

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

} // namespace

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
