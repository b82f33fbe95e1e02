// Copyright (c) 2026 CGAL Global Shape Analysis contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later

// shape_analysis partition IN --method mincut|kmeans|hierarchical --samples N --seed S
//     --part-size s --output OUT.ply --edge-values OUT.txt --report R.json
//     [--cuts CUTS.json [--max-cuts N] | --scales s1,s2,...]
// shape_analysis partition-segment IN --segments K --seg OUT.seg --output OUT.ply --report R.json
// Every default is the library's (its options structs); the reports echo the options under the
// named parameters' names.

#include "cli_common.h"

#include <CGAL/Randomized_cuts/Partition_function_options.h>
#include <CGAL/Randomized_cuts/Segment_with_partition_function_options.h>
#include <CGAL/Randomized_cuts/most_consistent_cuts.h>
#include <CGAL/Randomized_cuts/partition_function.h>
#include <CGAL/Randomized_cuts/segment_with_partition_function.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <iostream>
#include <map>
#include <memory>
#include <sstream>

namespace shape_analysis_cli {

namespace {

namespace RC = CGAL::Randomized_cuts;

// The files and switches of the subcommands; the library's options with the library's defaults.
struct Command_options
{
  bool quiet = false;
  bool verbose = false;
};

struct Partition_options : Command_options
{
  std::string input, output_ply, edge_values, report, cuts;
  RC::Partition_function_options sampling;
  std::size_t maximum_cuts = 20;
  std::vector<double> scales; // --scales: multiscale_partition_function()'s part_sizes
};

struct Partition_segment_options : Command_options
{
  std::string input, output_ply, output_seg, report;
  RC::Segment_with_partition_function_options segmentation;
  bool no_refinement = false;
};

// The names of the samplers on the command line.
const std::map<std::string, RC::Sampling_method> method_names{
  {"mincut", RC::MIN_CUT}, {"kmeans", RC::K_MEANS}, {"hierarchical", RC::HIERARCHICAL}};

std::string method_name(RC::Sampling_method method)
{
  for(const auto& m : method_names)
    if(m.second == method)
      return m.first;
  return std::to_string(int(method));
}

void add_sampling_options(CLI::App* cmd, RC::Partition_function_options& so, Command_options& o,
                          bool with_method)
{
  if(with_method)
    cmd->add_option("--method", so.sampling_method, "Sampler: mincut, kmeans or hierarchical")
      ->type_name("TEXT")
      ->transform(CLI::Validator(
        [](std::string& name) -> std::string {
          const auto m = method_names.find(name);
          if(m == method_names.end())
            return name + " not in {mincut,kmeans,hierarchical}";
          name = std::to_string(int(m->second)); // parsed into the enum
          return std::string();
        },
        "{mincut,kmeans,hierarchical}"))
      ->default_str(method_name(so.sampling_method) +
                    (so.sampling_method == RC::MIN_CUT ? "" : "; mincut with --cuts, --scales or --part-size"));
  cmd->add_option("-n,--samples", so.number_of_samples, "Number of sampled segmentations")
    ->capture_default_str()
    ->check(positive_count);
  cmd->add_option("--seed", so.random_seed, "Random seed (same seed, same result)")->capture_default_str();
  cmd->add_option("--part-size", so.part_size,
                  "mincut: part size s of the penalty near the two sampled faces, in (0, 1/6]")
    ->capture_default_str();
  if(with_method) {
    cmd->add_option("--clusters", so.number_of_clusters,
                    "kmeans: number of seeds; hierarchical: largest number of segments")
      ->capture_default_str();
    cmd->add_option("--randomness", so.randomness, "hierarchical: randomness r of the merges")
      ->capture_default_str();
  }
  cmd->add_option("--tolerance", so.convergence_tolerance,
                  "Stop when no edge value changes by more than this over a batch of 64 samples (0: off)")
    ->capture_default_str();
  cmd->add_flag("--score-weighting", so.score_weighting,
                "Weight each sample by 1 / its normalized cut (clean cuts count more)");
  cmd->add_option("--threads", so.number_of_threads, "Threads (0: all cores); the result does not depend on it")
    ->capture_default_str();
  cmd->add_option("--concavity-exponent", so.concavity_exponent,
                  "Exponent alpha of the concavity weight min((theta/pi)^alpha, 1)")
    ->capture_default_str();
  cmd->add_flag("-q,--quiet", o.quiet, "No progress on stderr");
  cmd->add_flag("-v,--verbose", o.verbose, "Progress on stderr even when it is not a terminal");
}

// The options the command line sets, under the library's named-parameter names.
Json sampling_json(const RC::Partition_function_options& so, bool with_method)
{
  Json p = Json::object();
  if(with_method)
    p["sampling_method"] = method_name(so.sampling_method);
  p["number_of_samples"] = so.number_of_samples;
  p["random_seed"] = so.random_seed;
  p["part_size"] = so.part_size;
  if(with_method) {
    p["number_of_clusters"] = so.number_of_clusters;
    p["randomness"] = so.randomness;
  }
  p["convergence_tolerance"] = so.convergence_tolerance;
  p["score_weighting"] = so.score_weighting;
  p["number_of_threads"] = so.number_of_threads;
  p["concavity_exponent"] = so.concavity_exponent;
  return p;
}

// Light grey (value 0) through yellow and orange to dark red (value 1).
std::array<unsigned char, 3> ramp(double t)
{
  t = std::clamp(t, 0.0, 1.0);
  static const double stops[4][3] = {{235, 235, 230}, {250, 215, 80}, {235, 110, 30}, {150, 0, 20}};
  const double x = t * 3.0;
  const int i = (std::min)(2, static_cast<int>(x));
  const double f = x - i;
  std::array<unsigned char, 3> c;
  for(int k = 0; k < 3; ++k)
    c[std::size_t(k)] = static_cast<unsigned char>(std::lround(stops[i][k] + f * (stops[i + 1][k] - stops[i][k])));
  return c;
}

template <typename T>
void put_binary(std::ostream& out, T value)
{
  out.write(reinterpret_cast<const char*>(&value), sizeof(T)); // little-endian hosts
}

// Binary PLY: the input's points with a colour (ramp of the vertex value divided by the largest
// edge value) and a `quality` scalar (the largest value of the vertex's edges); its faces in
// the input order; an `edge` element with each surface edge's two vertices and `value`.
void write_partition_ply(std::ostream& out, const Input_mesh& input,
                         const std::vector<std::array<std::size_t, 2>>& edge_points,
                         const std::vector<double>& edge_value)
{
  const std::size_t np = input.points.size();
  std::vector<double> vertex_value(np, 0.0);
  double largest = 0;
  for(std::size_t e = 0; e < edge_points.size(); ++e) {
    for(std::size_t p : edge_points[e])
      vertex_value[p] = (std::max)(vertex_value[p], edge_value[e]);
    largest = (std::max)(largest, edge_value[e]);
  }
  out << "ply\nformat binary_little_endian 1.0\n"
      << "comment written by shape_analysis partition (CGAL Global Shape Analysis)\n"
      << "comment vertex quality: largest partition-function value of the vertex's edges\n"
      << "comment colours: the quality divided by the largest edge value (" << largest << ")\n"
      << "element vertex " << np << "\n"
      << "property double x\nproperty double y\nproperty double z\n"
      << "property uchar red\nproperty uchar green\nproperty uchar blue\n"
      << "property float quality\n"
      << "element face " << input.triangles.size() << "\n"
      << "property list uchar int vertex_indices\n"
      << "element edge " << edge_points.size() << "\n"
      << "property int vertex1\nproperty int vertex2\nproperty float value\n"
      << "end_header\n";
  for(std::size_t p = 0; p < np; ++p) {
    put_binary(out, CGAL::to_double(input.points[p].x()));
    put_binary(out, CGAL::to_double(input.points[p].y()));
    put_binary(out, CGAL::to_double(input.points[p].z()));
    const auto c = ramp(largest > 0 ? vertex_value[p] / largest : 0.0);
    out.write(reinterpret_cast<const char*>(c.data()), 3);
    put_binary(out, static_cast<float>(vertex_value[p]));
  }
  for(const auto& t : input.triangles) {
    put_binary(out, static_cast<unsigned char>(3));
    for(std::size_t v : t)
      put_binary(out, static_cast<std::int32_t>(v));
  }
  for(std::size_t e = 0; e < edge_points.size(); ++e) {
    put_binary(out, static_cast<std::int32_t>(edge_points[e][0]));
    put_binary(out, static_cast<std::int32_t>(edge_points[e][1]));
    put_binary(out, static_cast<float>(edge_value[e]));
  }
}

// The cuts as JSON, by decreasing consistency: per cut its rank, consistency, normalized cut,
// length, samples, sample index, the edges it crosses (pairs i < j of the file's vertex indices,
// sorted) and, for min-cut samples, the faces of its smaller side (the file's face indices, sorted).
Json cuts_json(const Input_mesh& input, const std::vector<RC::Cut<Mesh>>& cuts)
{
  const Mesh& mesh = input.mesh;
  std::vector<std::size_t> input_face(num_faces(mesh), 0);
  for(std::size_t i = input.triangles.size(); i-- > 0;) // (the first input face of a mesh face)
    if(input.mesh_face[i] != Input_mesh::left_out)
      input_face[input.mesh_face[i]] = i;
  Json list = Json::array();
  for(std::size_t k = 0; k < cuts.size(); ++k) {
    const RC::Cut<Mesh>& c = cuts[k];
    std::vector<std::array<std::size_t, 2>> edges;
    for(Mesh::Edge_index e : c.edges) {
      const Mesh::Halfedge_index h = halfedge(e, mesh);
      std::size_t i = input.input_index[input.vertex_point[source(h, mesh)]];
      std::size_t j = input.input_index[input.vertex_point[target(h, mesh)]];
      edges.push_back({{(std::min)(i, j), (std::max)(i, j)}});
    }
    std::sort(edges.begin(), edges.end());
    std::vector<std::size_t> side;
    for(Mesh::Face_index f : c.smaller_side)
      side.push_back(input_face[f]);
    std::sort(side.begin(), side.end());
    Json j = Json::object();
    j["rank"] = k;
    j["consistency"] = c.consistency;
    j["normalized_cut"] = c.normalized_cut;
    j["length"] = c.length;
    j["samples"] = c.number_of_samples;
    j["sample_index"] = c.sample_index;
    j["edges"] = Json(edges);
    j["smaller_side_faces"] = Json(side);
    list.push_back(j);
  }
  Json root = Json::object();
  root["cuts"] = list;
  return root;
}

int run_partition(const Partition_options& o)
{
  Stopwatch total;
  Progress progress("partition", o.quiet, o.verbose);
  Output_files outputs;
  outputs.add_input(o.input);
  outputs.add_optional_output(o.output_ply, "coloured mesh", {".ply"});
  outputs.add_optional_output(o.edge_values, "edge values");
  outputs.add_optional_output(o.cuts, "cuts", {".json"});
  outputs.add_optional_output(o.report, "report", {".json"});

  double read_seconds = 0;
  Input_mesh input = read_input_mesh(o.input, progress, read_seconds);
  Mesh& mesh = input.mesh;

  const RC::Partition_function_options& so = o.sampling;
  progress.stage("sampling " + std::to_string(so.number_of_samples) + " " + method_name(so.sampling_method) +
                 " segmentations of " +
                 std::to_string(num_faces(mesh)) + " faces");
  std::vector<double> values(num_edges(mesh), 0.0);
  std::function<void(double)> on_progress = [&](double f) { progress.fraction(f); };
  Stopwatch sampling;
  const auto np = RC::parameters::sampling_method(so.sampling_method)
                    .number_of_samples(so.number_of_samples)
                    .random_seed(so.random_seed)
                    .part_size(so.part_size)
                    .number_of_clusters(so.number_of_clusters)
                    .randomness(so.randomness)
                    .convergence_tolerance(so.convergence_tolerance)
                    .score_weighting(so.score_weighting)
                    .number_of_threads(so.number_of_threads)
                    .concavity_exponent(so.concavity_exponent)
                    .progress_callback(on_progress);
  RC::Partition_function_result r;
  std::vector<RC::Cut<Mesh>> cuts;
  std::vector<std::vector<double>> scale_values; // with --scales: per edge, one value per part size
  if(!o.scales.empty()) { // the largest over the scales goes to `values`
    scale_values.assign(num_edges(mesh), std::vector<double>());
    r = RC::multiscale_partition_function(mesh, CGAL::make_property_map(scale_values), np.part_sizes(o.scales));
    for(std::size_t e = 0; e < values.size(); ++e)
      for(double v : scale_values[e])
        values[e] = (std::max)(values[e], v);
  } else if(o.cuts.empty())
    r = RC::partition_function(mesh, CGAL::make_property_map(values), np);
  else { // the same samples, kept: their distinct cuts and the values they were ranked with
    cuts = RC::most_consistent_cuts(mesh, np.edge_value_map(CGAL::make_property_map(values)));
    for(const RC::Cut<Mesh>& c : cuts)
      r.number_of_samples += c.number_of_samples;
    if(cuts.size() > o.maximum_cuts)
      cuts.resize(o.maximum_cuts);
  }
  const double seconds = sampling.seconds();
  progress.done();

  // Edges by the input's points; values in the order of edges(mesh).
  std::vector<std::array<std::size_t, 2>> edge_points;
  std::vector<double> edge_value;
  edge_points.reserve(num_edges(mesh));
  double largest = 0, sum = 0;
  for(Mesh::Edge_index e : edges(mesh)) {
    const Mesh::Halfedge_index h = halfedge(e, mesh);
    edge_points.push_back({input.vertex_point[source(h, mesh)], input.vertex_point[target(h, mesh)]});
    edge_value.push_back(values[e]);
    largest = (std::max)(largest, values[e]);
    sum += values[e];
  }

  if(!o.output_ply.empty()) {
    progress.stage("writing " + o.output_ply);
    outputs.stage(o.output_ply, true,
                  [&](std::ostream& out) { write_partition_ply(out, input, edge_points, edge_value); });
  }
  if(!o.cuts.empty()) {
    progress.stage("writing " + o.cuts);
    outputs.stage(o.cuts, false, [&](std::ostream& out) { out << cuts_json(input, cuts).dump(1) << '\n'; });
  }
  if(!o.edge_values.empty()) {
    progress.stage("writing " + o.edge_values);
    outputs.stage(o.edge_values, false, [&](std::ostream& out) {
      // i j value, i < j the file's vertex indices, one line per edge of the surface, sorted
      // (with --scales: i j and one value per part size).
      std::vector<std::pair<std::array<std::size_t, 2>, std::vector<double>>> lines;
      lines.reserve(edge_points.size());
      std::size_t e = 0;
      for(Mesh::Edge_index edge : edges(mesh)) {
        std::size_t i = input.input_index[edge_points[e][0]], j = input.input_index[edge_points[e][1]];
        if(i > j)
          std::swap(i, j);
        lines.push_back({{i, j}, scale_values.empty() ? std::vector<double>{edge_value[e]} : scale_values[edge]});
        ++e;
      }
      std::sort(lines.begin(), lines.end());
      std::ostringstream buffer;
      buffer << std::setprecision(9);
      for(std::size_t k = 0; k < lines.size(); ++k) {
        // A non-manifold edge of the file, split into several edges of the surface: one line,
        // with the largest of their values (the last after sorting).
        if(k + 1 < lines.size() && lines[k + 1].first == lines[k].first)
          continue;
        buffer << lines[k].first[0] << ' ' << lines[k].first[1];
        for(double v : lines[k].second)
          buffer << ' ' << v;
        buffer << '\n';
      }
      out << buffer.str();
    });
  }
  if(!o.report.empty()) {
    Json report = input_report("partition", o.input, input);
    report["edges"] = edge_points.size();
    report["parameters"] = sampling_json(o.sampling, true);
    if(!o.scales.empty()) { // multiscale_partition_function()'s part_sizes instead of part_size
      report["parameters"]["part_sizes"] = Json(o.scales);
      report["parameters"]["part_size"] = Json();
    }
    report["samples_drawn"] = r.number_of_samples;
    if(!o.scales.empty()) { // per part size: the largest and mean values
      Json per_scale = Json::array();
      for(std::size_t k = 0; k < o.scales.size(); ++k) {
        double scale_largest = 0, scale_sum = 0;
        for(const auto& v : scale_values)
          scale_largest = (std::max)(scale_largest, v[k]), scale_sum += v[k];
        Json j = Json::object();
        j["part_size"] = o.scales[k];
        j["largest_value"] = scale_largest;
        j["mean_value"] = scale_values.empty() ? 0.0 : scale_sum / double(scale_values.size());
        per_scale.push_back(j);
      }
      report["scales"] = per_scale;
    }
    if(!o.cuts.empty()) {
      report["cuts"] = cuts.size();
      report["most_consistent_cut"] = cuts.empty() ? Json() : Json(cuts.front().consistency);
    }
    report["converged"] = o.cuts.empty() ? Json(r.converged) : Json(); // (not told with --cuts)
    report["largest_change"] = o.cuts.empty() ? Json(r.largest_change) : Json();
    report["largest_value"] = largest;
    report["mean_value"] = edge_points.empty() ? 0.0 : sum / double(edge_points.size());
    report["seconds_per_sample"] = r.number_of_samples > 0 ? seconds / double(r.number_of_samples) : 0.0;
    stage_report(outputs, o.report, report, seconds, read_seconds, total.seconds(),
                 {{"mesh", o.output_ply}, {"edge_values", o.edge_values}, {"cuts", o.cuts}});
  }
  outputs.commit();
  if(!o.cuts.empty())
    std::cout << o.input << ": " << cuts.size() << " most consistent cuts"
              << (cuts.empty() ? std::string() : ", the first of consistency " + std::to_string(cuts.front().consistency))
              << '\n';
  std::cout << o.input << ": " << num_faces(mesh) << " faces, " << r.number_of_samples
            << " samples in " << seconds << " s; largest edge value " << largest << "\n";
  return 0;
}

int run_partition_segment(const Partition_segment_options& o)
{
  Stopwatch total;
  Progress progress("partition-segment", o.quiet, o.verbose);
  Output_files outputs;
  outputs.add_input(o.input);
  outputs.add_optional_output(o.output_ply, "coloured mesh", {".ply"});
  outputs.add_optional_output(o.output_seg, "labels");
  outputs.add_optional_output(o.report, "report", {".json"});

  double read_seconds = 0;
  Input_mesh input = read_input_mesh(o.input, progress, read_seconds);
  Mesh& mesh = input.mesh;
  const std::size_t n = input.number_of_input_faces();

  const RC::Segment_with_partition_function_options& so = o.segmentation;
  const bool refinement = so.boundary_refinement && !o.no_refinement;
  progress.stage("segmenting " + std::to_string(num_faces(mesh)) + " faces into " +
                 count_in_words(so.number_of_segments) + " segments with the partition function");
  auto segment_map = mesh.add_property_map<Mesh::Face_index, std::size_t>("f:segment", 0).first;
  std::function<void(double)> on_progress = [&](double f) { progress.fraction(f); };
  Stopwatch segmenting;
  const std::size_t k = RC::segment_with_partition_function(
    mesh, segment_map,
    RC::parameters::number_of_segments(so.number_of_segments)
      .number_of_samples(so.number_of_samples)
      .random_seed(so.random_seed)
      .part_size(so.part_size)
      .convergence_tolerance(so.convergence_tolerance)
      .score_weighting(so.score_weighting)
      .number_of_threads(so.number_of_threads)
      .concavity_exponent(so.concavity_exponent)
      .boundary_refinement(refinement)
      .progress_callback(on_progress));
  const double seconds = segmenting.seconds();
  progress.done();

  const std::vector<std::size_t> labels = labels_per_input_face(input, segment_map);
  std::vector<std::size_t> counts(k, 0);
  for(std::size_t l : labels)
    ++counts[l];
  stage_segmentation(outputs, progress, input, labels, o.output_ply, o.output_seg);
  if(!o.report.empty()) {
    Json report = input_report("partition-segment", o.input, input);
    report["segments"] = k;
    Json parameters = sampling_json(so, false);
    parameters["number_of_segments"] = so.number_of_segments;
    parameters["boundary_refinement"] = refinement;
    report["parameters"] = parameters;
    report["segment_faces"] = counts;
    stage_report(outputs, o.report, report, seconds, read_seconds, total.seconds(),
                 {{"mesh", o.output_ply}, {"labels", o.output_seg}});
  }
  outputs.commit();
  std::cout << o.input << ": " << n << " faces, " << k << " segments in " << seconds << " s\n";
  return 0;
}

} // namespace

void add_partition_commands(CLI::App& app, std::function<int()>& run)
{
  {
    auto o = std::make_shared<Partition_options>();
    CLI::App* cmd = app.add_subcommand(
      "partition",
      "Partition function: how often random segmentations cut each edge (high on part boundaries).");
    cmd->add_option("input", o->input, "Input triangle mesh (.off, .ply, .obj, .stl)")->required();
    cmd->add_option("-o,--output", o->output_ply,
                    "Coloured mesh (.ply: vertex colours and 'quality', edges with 'value')");
    cmd->add_option("--edge-values", o->edge_values,
                    "Text file, one line per edge: 'i j value', i < j the input's vertex indices");
    cmd->add_option("--report", o->report, "JSON report (inputs, parameters, seconds, figures)");
    cmd->add_option("--cuts", o->cuts,
                    "JSON file of the samples' distinct cuts, the most consistent first: consistency, "
                    "normalized_cut, length, samples, the edges crossed (vertex index pairs) and the "
                    "faces of the smaller side (mincut)");
    cmd->add_option("--max-cuts", o->maximum_cuts, "With --cuts: the largest number of cuts written")
      ->capture_default_str()
      ->check(positive_count);
    cmd->add_option("--scales", o->scales,
                    "mincut: several part sizes at once (multiscale partition function), comma-separated: "
                    "--edge-values gets one value per part size, the mesh and report the largest")
      ->delimiter(',');
    add_sampling_options(cmd, o->sampling, *o, true);
    cmd->callback([o, cmd, &run]() {
      // Without --method, what needs single cuts (the list of cuts, part sizes) samples min-cuts,
      // as the library's most_consistent_cuts() and multiscale_partition_function() do.
      if(cmd->count("--method") == 0 &&
         (!o->cuts.empty() || !o->scales.empty() || cmd->count("--part-size") > 0)) {
        if(cmd->count("--clusters") > 0 || cmd->count("--randomness") > 0)
          throw CLI::ValidationError("--method", "give it: --clusters and --randomness are the hierarchical or "
                                                 "kmeans sampler's, --cuts, --scales and --part-size imply mincut");
        o->sampling.sampling_method = RC::MIN_CUT;
      }
      if(o->cuts.empty() && cmd->count("--max-cuts") > 0)
        throw CLI::ValidationError("--max-cuts", "needs --cuts");
      if(!o->scales.empty() && !o->cuts.empty())
        throw CLI::ValidationError("--scales", "give either --scales or --cuts, not both");
      if(!o->scales.empty() && o->sampling.sampling_method != RC::MIN_CUT)
        throw CLI::ValidationError("--scales", "needs the mincut sampler");
      if(!o->scales.empty() && cmd->count("--part-size") > 0)
        throw CLI::ValidationError("--scales", "give either --scales or --part-size, not both");
      run = [o]() { return run_partition(*o); };
    });
  }
  {
    auto o = std::make_shared<Partition_segment_options>();
    CLI::App* cmd = app.add_subcommand(
      "partition-segment",
      "Segment a triangle mesh along its most consistent cuts (partition function, min-cut sampling).");
    cmd->add_option("input", o->input, "Input triangle mesh (.off, .ply, .obj, .stl)")->required();
    cmd->add_option("-k,--segments", o->segmentation.number_of_segments,
                    "Number of segments, or auto: the splits go on while the next cut follows concave creases, "
                    "4 to 12 segments (the report's number_of_segments is then 0, its segments the number chosen)")
      ->default_str(count_or_auto(o->segmentation.number_of_segments))
      ->transform(positive_count_or_auto);
    cmd->add_option("-o,--output", o->output_ply,
                    "Coloured mesh (.ply, one colour and an integer 'segment' per face)");
    cmd->add_option("--seg", o->output_seg,
                    "Segment id per face, one per line, in the input's face order");
    cmd->add_option("--report", o->report, "JSON report (inputs, parameters, seconds, figures)");
    cmd->add_flag("--no-refinement", o->no_refinement, "Skip the final boundary refinement");
    add_sampling_options(cmd, o->segmentation, *o, false);
    cmd->callback([o, &run]() { run = [o]() { return run_partition_segment(*o); }; });
  }
}

} // namespace shape_analysis_cli
