// Copyright (c) 2026 CGAL Global Shape Analysis contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later

// shape_analysis segment IN --segments K --output OUT.ply --seg OUT.seg --report R.json

#include "cli_common.h"

#include <CGAL/Consistent_segmentation/hierarchical_segmentation.h>

#include <iostream>
#include <memory>

namespace shape_analysis_cli {

namespace {

namespace CS = CGAL::Consistent_segmentation;

// The files and switches of the command; the segmentation's options with the library's defaults.
struct Segment_options
{
  std::string input;
  std::string output_ply, output_seg, report, prior;
  CS::Hierarchical_segmentation_options segmentation;
  bool no_refinement = false;
  bool quiet = false;
  bool verbose = false;
};

int run_segment(const Segment_options& o)
{
  Stopwatch total;
  Progress progress("segment", o.quiet, o.verbose);

  // Check every output location before any work, so that a bad path costs nothing.
  Output_files outputs;
  outputs.add_input(o.input);
  if(!o.prior.empty())
    outputs.add_input(o.prior);
  outputs.add_optional_output(o.output_ply, "coloured mesh", {".ply"});
  outputs.add_optional_output(o.output_seg, "labels");
  outputs.add_optional_output(o.report, "report", {".json"});

  double read_seconds = 0;
  Input_mesh input = read_input_mesh(o.input, progress, read_seconds);
  Mesh& mesh = input.mesh;
  const std::size_t n = input.number_of_input_faces();

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
                 count_in_words(o.segmentation.number_of_segments) + " segments");
  auto segment_map = mesh.add_property_map<Mesh::Face_index, std::size_t>("f:segment", 0).first;
  std::function<void(double)> on_progress = [&](double f) { progress.fraction(f); };
  const CS::Hierarchical_segmentation_options& so = o.segmentation;
  const auto np = CS::parameters::number_of_segments(so.number_of_segments)
                    .concavity_exponent(so.concavity_exponent)
                    .prior_boundary_factor(so.prior_boundary_factor)
                    .component_link_distance(so.component_link_distance)
                    .component_link_factor(so.component_link_factor)
                    .boundary_refinement(so.boundary_refinement && !o.no_refinement)
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

  const std::vector<std::size_t> labels = labels_per_input_face(input, segment_map);
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

  stage_segmentation(outputs, progress, input, labels, o.output_ply, o.output_seg);
  if(!o.report.empty()) {
    Json report = input_report("segment", o.input, input);
    report["segments"] = k;
    // The options as the library's named parameters.
    Json parameters = Json::object();
    parameters["number_of_segments"] = o.segmentation.number_of_segments;
    parameters["concavity_exponent"] = o.segmentation.concavity_exponent;
    parameters["prior"] = o.prior.empty() ? Json() : Json(o.prior);
    parameters["prior_boundary_factor"] = o.segmentation.prior_boundary_factor;
    parameters["component_link_distance"] = o.segmentation.component_link_distance;
    parameters["component_link_factor"] = o.segmentation.component_link_factor;
    parameters["boundary_refinement"] = o.segmentation.boundary_refinement && !o.no_refinement;
    report["parameters"] = parameters;
    report["segment_faces"] = counts;
    report["segment_areas"] = areas;
    stage_report(outputs, o.report, report, segment_seconds, read_seconds, total.seconds(),
                 {{"mesh", o.output_ply}, {"labels", o.output_seg}});
  }
  outputs.commit();

  std::cout << o.input << ": " << n << " faces, " << k << " segments in " << segment_seconds
            << " s\n";
  return 0;
}

} // namespace

void add_segment_command(CLI::App& app, std::function<int()>& run,
                         const CS::Hierarchical_segmentation_options& defaults)
{
  auto options = std::make_shared<Segment_options>();
  options->segmentation = defaults;
  CS::Hierarchical_segmentation_options& so = options->segmentation;
  CLI::App* cmd = app.add_subcommand(
    "segment", "Segment a triangle mesh into parts (hierarchical area-normalized cut).");
  cmd->add_option("input", options->input, "Input triangle mesh (.off, .ply, .obj, .stl)")->required();
  cmd->add_option("-k,--segments", so.number_of_segments,
                  "Number of segments, or auto: chosen from 2 to 12, the number whose boundaries run most "
                  "along concave creases (the report's number_of_segments is then 0, its segments the "
                  "number chosen)")
    ->capture_default_str()
    ->transform(positive_count_or_auto);
  cmd->add_option("-o,--output", options->output_ply,
                  "Coloured mesh (.ply, one colour and an integer 'segment' per face)");
  cmd->add_option("--seg", options->output_seg,
                  "Segment id per face, one per line, in the input's face order");
  cmd->add_option("--report", options->report, "JSON report (inputs, parameters, seconds, figures)");
  cmd->add_option("--prior", options->prior,
                  "Prior segmentation (.seg) whose boundaries are cheaper to cut");
  cmd->add_option("--prior-factor", so.prior_boundary_factor,
                  "Cut-cost divisor on prior boundaries (>= 1)")
    ->capture_default_str();
  cmd->add_option("--concavity-exponent", so.concavity_exponent,
                  "Exponent alpha of the concavity weight min((theta/pi)^alpha, 1)")
    ->capture_default_str();
  cmd->add_option("--link-distance", so.component_link_distance,
                  "Link faces of different components closer than this fraction of the bounding-box diagonal")
    ->capture_default_str();
  cmd->add_option("--link-factor", so.component_link_factor,
                  "Cost of a component link relative to the mean edge cut cost")
    ->capture_default_str();
  cmd->add_flag("--no-refinement", options->no_refinement, "Skip the boundary refinement");
  cmd->add_flag("-q,--quiet", options->quiet, "No progress on stderr");
  cmd->add_flag("-v,--verbose", options->verbose,
                "Progress on stderr even when it is not a terminal");
  cmd->callback([options, &run]() { run = [options]() { return run_segment(*options); }; });
}

} // namespace shape_analysis_cli
