// Copyright (c) 2026 CGAL Global Shape Analysis contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later

// shape_analysis segment IN --segments K --output OUT.ply --seg OUT.seg --report R.json

#include "cli_common.h"

#include <CGAL/Consistent_segmentation/hierarchical_segmentation.h>

#include <iostream>
#include <memory>

namespace shape_analysis_cli {

namespace {

struct Segment_options
{
  std::string input;
  std::size_t segments = 8;
  std::string output_ply, output_seg, report, prior;
  double concavity_exponent = 10;
  double prior_factor = 10;
  double link_distance = 0.1;
  double link_factor = 0.01;
  bool no_refinement = false;
  bool quiet = false;
  bool verbose = false;
};

int run_segment(const Segment_options& o)
{
  namespace CS = CGAL::Consistent_segmentation;
  Stopwatch total;
  Progress progress("segment", o.quiet, o.verbose);

  // Check every output location before any work, so that a bad path costs nothing.
  Output_files outputs;
  outputs.add_input(o.input);
  if(!o.prior.empty())
    outputs.add_input(o.prior);
  if(!o.output_ply.empty())
    outputs.add_output(o.output_ply, "coloured mesh");
  if(!o.output_seg.empty())
    outputs.add_output(o.output_seg, "labels");
  if(!o.report.empty())
    outputs.add_output(o.report, "report");

  progress.stage("reading " + o.input);
  Stopwatch reading;
  Input_mesh input = read_triangle_mesh(o.input);
  Mesh& mesh = input.mesh;
  const double read_seconds = reading.seconds();
  const std::size_t n = input.number_of_input_faces();
  if(input.merged_points > 0 || input.left_out_faces > 0)
    progress.stage("merged " + std::to_string(input.merged_points) + " duplicate points; left " +
                   std::to_string(input.left_out_faces) + " degenerate or repeated faces out");

  std::vector<long long> prior;
  if(!o.prior.empty()) {
    const std::vector<long long> prior_per_input = read_labels(o.prior);
    if(prior_per_input.size() != n)
      throw Cli_error("'" + o.prior + "' has " + std::to_string(prior_per_input.size()) +
                      " labels but '" + o.input + "' has " + std::to_string(n) + " faces");
    prior.assign(num_faces(mesh), 0);
    for(std::size_t i = 0; i < n; ++i)
      if(input.mesh_face[i] != Input_mesh::left_out)
        prior[input.mesh_face[i]] = prior_per_input[i];
  }

  progress.stage("segmenting " + std::to_string(num_faces(mesh)) + " faces into " +
                 std::to_string(o.segments) + " segments");
  auto segment_map = mesh.add_property_map<Mesh::Face_index, std::size_t>("f:segment", 0).first;
  std::function<void(double)> on_progress = [&](double f) { progress.fraction(f); };
  const auto np = CS::parameters::number_of_segments(o.segments)
                    .concavity_exponent(o.concavity_exponent)
                    .prior_boundary_factor(o.prior_factor)
                    .component_link_distance(o.link_distance)
                    .component_link_factor(o.link_factor)
                    .boundary_refinement(!o.no_refinement)
                    .progress_callback(on_progress);
  Stopwatch segmenting;
  std::size_t k = 0;
  if(prior.empty())
    k = CS::hierarchical_segmentation(mesh, segment_map, np);
  else {
    auto prior_map = CGAL::make_property_map(prior); // indexed by face index
    k = CS::hierarchical_segmentation(mesh, segment_map, np.prior_segment_map(prior_map));
  }
  const double segment_seconds = segmenting.seconds();
  progress.done();

  std::vector<std::size_t> mesh_labels;
  mesh_labels.reserve(num_faces(mesh));
  for(auto f : faces(mesh))
    mesh_labels.push_back(segment_map[f]);
  const std::vector<std::size_t> labels = input.input_labels(mesh_labels);
  std::vector<double> areas(k, 0.0);
  std::vector<std::size_t> counts(k, 0);
  for(std::size_t i = 0; i < n; ++i) {
    const auto& t = input.triangles[i];
    const Point_3& a = input.points[t[0]];
    const Point_3& b = input.points[t[1]];
    const Point_3& c = input.points[t[2]];
    areas[labels[i]] += std::sqrt(CGAL::to_double(CGAL::squared_area(a, b, c)));
    ++counts[labels[i]];
  }

  if(!o.output_ply.empty()) {
    progress.stage("writing " + o.output_ply);
    outputs.stage(o.output_ply, true, [&](std::ostream& out) {
      write_labelled_ply(out, input.points, input.triangles, labels);
    });
  }
  if(!o.output_seg.empty()) {
    progress.stage("writing " + o.output_seg);
    outputs.stage(o.output_seg, false, [&](std::ostream& out) { write_labels(out, labels); });
  }
  if(!o.report.empty()) {
    Json report = Json::object();
    report["command"] = "segment";
    report["input"] = o.input;
    report["faces"] = n;
    report["vertices"] = input.points.size();
    report["merged_duplicate_points"] = input.merged_points;
    report["left_out_faces"] = input.left_out_faces;
    report["segments"] = k;
    Json parameters = Json::object();
    parameters["segments"] = o.segments;
    parameters["concavity_exponent"] = o.concavity_exponent;
    parameters["prior"] = o.prior.empty() ? Json() : Json(o.prior);
    parameters["prior_factor"] = o.prior_factor;
    parameters["link_distance"] = o.link_distance;
    parameters["link_factor"] = o.link_factor;
    parameters["boundary_refinement"] = !o.no_refinement;
    report["parameters"] = parameters;
    report["seconds"] = segment_seconds;
    report["seconds_reading"] = read_seconds;
    report["seconds_total"] = total.seconds();
    report["segment_faces"] = counts;
    report["segment_areas"] = areas;
    Json outputs_json = Json::object();
    outputs_json["mesh"] = o.output_ply.empty() ? Json() : Json(o.output_ply);
    outputs_json["labels"] = o.output_seg.empty() ? Json() : Json(o.output_seg);
    report["outputs"] = outputs_json;
    outputs.stage(o.report, false, [&](std::ostream& out) { out << report.dump() << '\n'; });
  }
  outputs.commit();

  std::cout << o.input << ": " << n << " faces, " << k << " segments in " << segment_seconds
            << " s\n";
  return 0;
}

} // namespace

void add_segment_command(CLI::App& app, std::function<int()>& run)
{
  auto options = std::make_shared<Segment_options>();
  CLI::App* cmd = app.add_subcommand(
    "segment", "Segment a triangle mesh into parts (hierarchical area-normalized cut).");
  cmd->add_option("input", options->input, "Input triangle mesh (.off, .ply, .obj, .stl)")->required();
  cmd->add_option("-k,--segments", options->segments, "Number of segments")
    ->capture_default_str()
    ->check(CLI::PositiveNumber);
  cmd->add_option("-o,--output", options->output_ply,
                  "Coloured mesh (.ply, one colour and an integer 'segment' per face)");
  cmd->add_option("--seg", options->output_seg,
                  "Segment id per face, one per line, in the input's face order");
  cmd->add_option("--report", options->report, "JSON report (inputs, parameters, seconds, figures)");
  cmd->add_option("--prior", options->prior,
                  "Prior segmentation (.seg) whose boundaries are cheaper to cut");
  cmd->add_option("--prior-factor", options->prior_factor,
                  "Cut-cost divisor on prior boundaries (>= 1)")
    ->capture_default_str();
  cmd->add_option("--concavity-exponent", options->concavity_exponent,
                  "Exponent alpha of the concavity weight min((theta/pi)^alpha, 1)")
    ->capture_default_str();
  cmd->add_option("--link-distance", options->link_distance,
                  "Link faces of different components closer than this fraction of the bounding-box diagonal")
    ->capture_default_str();
  cmd->add_option("--link-factor", options->link_factor,
                  "Cost of a component link relative to the mean edge cut cost")
    ->capture_default_str();
  cmd->add_flag("--no-refinement", options->no_refinement, "Skip the boundary refinement");
  cmd->add_flag("-q,--quiet", options->quiet, "No progress on stderr");
  cmd->add_flag("-v,--verbose", options->verbose,
                "Progress on stderr even when it is not a terminal");
  cmd->callback([options, &run]() { run = [options]() { return run_segment(*options); }; });
}

} // namespace shape_analysis_cli
