// Copyright (c) 2026 CGAL Global Shape Analysis contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later

// shape_analysis coseg IN1 IN2 ... --segments K --oversegments k --output-dir DIR --report R.json
//   [--known MESH=FILE.seg ...] [--prior MESH=FILE.seg ...] [--merge-repeated]
// shape_analysis coseg IN --symmetry-plane a,b,c,d | --symmetric --output-dir DIR

#include "cli_common.h"

#include <CGAL/Consistent_segmentation/Consistent_segmentation_options.h>
#include <CGAL/Consistent_segmentation/consistent_segmentation.h>
#include <CGAL/Consistent_segmentation/merge_repeated_segments.h>
#include <CGAL/Surface_mesh_symmetrization/detect_reflective_symmetries.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <map>
#include <memory>
#include <set>
#include <sstream>

namespace shape_analysis_cli {

namespace {

namespace fs = std::filesystem;
namespace CS = CGAL::Consistent_segmentation;

// The files and switches of the command; the segmentation's options with the library's defaults.
struct Coseg_command_options
{
  std::vector<std::string> inputs;
  std::string output_dir, report, symmetry_plane;
  std::vector<std::string> known, prior; // MESH=FILE.seg
  bool symmetric = false;                 // --symmetry-plane or --symmetric given
  bool detect_plane = false;              // --symmetric: the plane detected
  CS::Consistent_segmentation_options coseg;
  bool no_refinement = false;
  bool merge_repeated = false;            // --merge-repeated: merge_repeated_segments() after
  bool quiet = false;
  bool verbose = false;
};

// Known labels are segment ids of the result: a bound keeps the result's tables (one entry per id
// up to the largest) small.
constexpr long long largest_known_label = (1LL << 20) - 1; // as the library

// The plane a x + b y + c z + d = 0 of "a,b,c,d".
std::array<double, 4> parse_plane(const std::string& text)
{
  std::array<double, 4> plane{};
  std::stringstream in(text);
  std::string field;
  std::size_t count = 0;
  bool ok = true;
  while(ok && std::getline(in, field, ',')) {
    std::size_t used = 0;
    double v = 0;
    try {
      v = std::stod(field, &used);
    } catch(const std::exception&) {
      ok = false;
      break;
    }
    ok = count < 4 && field.find_first_not_of(" \t", used) == std::string::npos && std::isfinite(v);
    if(ok)
      plane[count++] = v;
  }
  if(!ok || count != 4 || (!text.empty() && text.back() == ','))
    throw Usage_error("--symmetry-plane expects four finite numbers a,b,c,d (the plane "
                      "a x + b y + c z + d = 0), got '" + text + "'");
  return plane;
}

// The index of the input that `name` designates: the path as given, the same file, its file name
// or its file name without extension; `inputs.size()` when none.
std::size_t find_input(const std::vector<std::string>& inputs, const std::string& name)
{
  for(std::size_t i = 0; i < inputs.size(); ++i) {
    const fs::path p(inputs[i]);
    if(name == inputs[i] || name == p.filename().string() || name == p.stem().string())
      return i;
  }
  std::error_code ec;
  if(fs::exists(name, ec))
    for(std::size_t i = 0; i < inputs.size(); ++i)
      if(fs::equivalent(name, inputs[i], ec))
        return i;
  return inputs.size();
}

// Per input: the label file given by `--option MESH=FILE` (empty when none).
std::vector<std::string> label_files(const std::vector<std::string>& inputs,
                                     const std::vector<std::string>& specs,
                                     const std::string& option)
{
  std::vector<std::string> files(inputs.size());
  for(const std::string& spec : specs) {
    // MESH may hold '=': the first split whose left side names an input.
    std::size_t index = inputs.size(), split = std::string::npos;
    for(std::size_t at = spec.find('='); at != std::string::npos; at = spec.find('=', at + 1)) {
      index = find_input(inputs, spec.substr(0, at));
      if(index < inputs.size()) {
        split = at;
        break;
      }
    }
    if(spec.find('=') == std::string::npos || spec.back() == '=')
      throw Usage_error(option + " expects MESH=FILE.seg, got '" + spec + "'");
    if(split == std::string::npos)
      throw Usage_error(option + " '" + spec + "': '" + spec.substr(0, spec.find('=')) +
                        "' is none of the input meshes (give its path or its file name)");
    if(!files[index].empty())
      throw Usage_error("two " + option + " files for '" + inputs[index] + "': '" + files[index] +
                        "' and '" + spec.substr(split + 1) + "'");
    files[index] = spec.substr(split + 1);
  }
  return files;
}

// Labels per face of `input.mesh` (by face index) from a label file per input face; faces left
// out of the mesh keep theirs in `per_input`.
std::vector<long long> read_face_labels(const std::string& file, const std::string& mesh_path,
                                        const Input_mesh& input, bool known,
                                        std::vector<long long>& per_input)
{
  per_input = read_labels(file);
  const std::size_t n = input.number_of_input_faces();
  if(per_input.size() != n)
    throw Cli_error("'" + file + "' has " + std::to_string(per_input.size()) + " labels but '" +
                    mesh_path + "' has " + std::to_string(n) + " faces");
  if(known)
    for(std::size_t i = 0; i < n; ++i)
      if(per_input[i] > largest_known_label)
        throw Cli_error("'" + file + "': the label of face " + std::to_string(i) + " (" +
                        std::to_string(per_input[i]) + ") is larger than " +
                        std::to_string(largest_known_label) + " (-1 marks an unknown face)");
  std::vector<long long> labels(num_faces(input.mesh), known ? -1 : 0);
  for(std::size_t i = 0; i < n; ++i)
    if(input.mesh_face[i] != Input_mesh::left_out)
      labels[input.mesh_face[i]] = per_input[i];
  return labels;
}

// Removes the directories that a failed run created (when empty).
struct Created_directories
{
  std::vector<fs::path> paths; // outermost first
  bool keep = false;
  ~Created_directories()
  {
    if(keep)
      return;
    for(auto it = paths.rbegin(); it != paths.rend(); ++it) {
      std::error_code ec;
      fs::remove(*it, ec); // only removes an empty directory
    }
  }
};

void create_output_directory(const std::string& dir, Created_directories& created)
{
  std::error_code ec;
  const fs::path target = fs::absolute(dir, ec).lexically_normal();
  if(fs::is_directory(target, ec))
    return;
  if(fs::exists(target, ec))
    throw Cli_error("cannot create the output directory '" + dir + "': a file of that name exists");
  std::vector<fs::path> missing;
  for(fs::path p = target; !p.empty() && !fs::exists(p, ec); p = p.parent_path()) {
    missing.push_back(p);
    if(p == p.parent_path())
      break;
  }
  for(auto it = missing.rbegin(); it != missing.rend(); ++it) {
    if(!fs::create_directory(*it, ec) || ec)
      throw Cli_error("cannot create the output directory '" + dir + "': " +
                      (ec ? ec.message() : std::string("cannot create '" + it->string() + "'")));
    created.paths.push_back(*it);
  }
}

int run_coseg(const Coseg_command_options& o)
{
  Stopwatch total;
  Progress progress("coseg", o.quiet, o.verbose);
  const std::size_t m = o.inputs.size();
  const bool symmetric = o.symmetric;

  // The command line as a whole, before any work.
  if(m == 0)
    throw Usage_error("no input mesh");
  std::array<double, 4> plane{};
  if(symmetric) {
    const std::string option = o.detect_plane ? "--symmetric" : "--symmetry-plane";
    if(m != 1)
      throw Usage_error(option + " segments one mesh, got " + std::to_string(m) + " input meshes");
    if(!o.known.empty())
      throw Usage_error("--known cannot be used with " + option);
    if(!o.detect_plane)
      plane = parse_plane(o.symmetry_plane);
  }
  std::vector<std::string> stems(m);
  {
    std::map<std::string, std::size_t> by_stem;
    for(std::size_t i = 0; i < m; ++i) {
      stems[i] = fs::path(o.inputs[i]).stem().string();
      if(stems[i].empty() || stems[i] == "." || stems[i] == "..")
        throw Usage_error("'" + o.inputs[i] + "' is not a mesh file name");
      const auto it = by_stem.emplace(stems[i], i);
      if(!it.second)
        throw Usage_error("'" + o.inputs[it.first->second] + "' and '" + o.inputs[i] +
                          "' would both be written as '" + stems[i] +
                          "' in the output directory: rename one of them");
    }
  }
  const std::vector<std::string> known_files = label_files(o.inputs, o.known, "--known");
  const std::vector<std::string> prior_files = label_files(o.inputs, o.prior, "--prior");
  bool any_known = false, any_prior = false;
  for(std::size_t i = 0; i < m; ++i) {
    any_known = any_known || !known_files[i].empty();
    any_prior = any_prior || !prior_files[i].empty();
  }

  // Every output location, before any work; the directory is created (and removed again if the
  // run fails).
  Created_directories created;
  create_output_directory(o.output_dir, created);
  Output_files outputs;
  for(std::size_t i = 0; i < m; ++i) {
    outputs.add_input(o.inputs[i]);
    if(!known_files[i].empty())
      outputs.add_input(known_files[i]);
    if(!prior_files[i].empty())
      outputs.add_input(prior_files[i]);
  }
  std::vector<std::string> seg_paths(m), ply_paths(m);
  for(std::size_t i = 0; i < m; ++i) {
    seg_paths[i] = (fs::path(o.output_dir) / (stems[i] + ".seg")).string();
    ply_paths[i] = (fs::path(o.output_dir) / (stems[i] + ".ply")).string();
    outputs.add_output(seg_paths[i], "labels");
    outputs.add_output(ply_paths[i], "coloured mesh", {".ply"});
  }
  outputs.add_optional_output(o.report, "report", {".json"});

  // Meshes and label files.
  std::vector<Input_mesh> inputs(m);
  double read_seconds = 0;
  std::size_t total_faces = 0;
  for(std::size_t i = 0; i < m; ++i) {
    double seconds = 0;
    inputs[i] = read_input_mesh(o.inputs[i], progress, seconds);
    read_seconds += seconds;
    total_faces += inputs[i].number_of_input_faces();
  }
  std::vector<std::vector<long long>> known(m), prior(m), known_per_input(m);
  for(std::size_t i = 0; i < m; ++i) {
    std::vector<long long> per_input;
    if(any_known) // every mesh gets a map; -1 everywhere without a file
      known[i] = known_files[i].empty() ? std::vector<long long>(num_faces(inputs[i].mesh), -1)
                                        : read_face_labels(known_files[i], o.inputs[i], inputs[i],
                                                           true, known_per_input[i]);
    if(any_prior)
      prior[i] = prior_files[i].empty()
                   ? std::vector<long long>(num_faces(inputs[i].mesh), 0)
                   : read_face_labels(prior_files[i], o.inputs[i], inputs[i], false, per_input);
  }

  // The segmentation.
  std::vector<Mesh> meshes;
  meshes.reserve(m);
  std::vector<Mesh::Property_map<Mesh::Face_index, std::size_t>> segment_maps;
  for(std::size_t i = 0; i < m; ++i) {
    meshes.push_back(std::move(inputs[i].mesh)); // input_labels() below needs only the face order
    segment_maps.push_back(
      meshes.back().add_property_map<Mesh::Face_index, std::size_t>("f:segment", 0).first);
  }
  typedef decltype(CGAL::make_property_map(known[0])) Label_map;
  std::vector<Label_map> known_maps, prior_maps;
  for(std::size_t i = 0; i < m; ++i) {
    if(any_known)
      known_maps.push_back(CGAL::make_property_map(known[i])); // indexed by face index
    if(any_prior)
      prior_maps.push_back(CGAL::make_property_map(prior[i]));
  }

  const CS::Consistent_segmentation_options& co = o.coseg;
  const bool boundary_refinement = co.boundary_refinement && !o.no_refinement;
  if(symmetric)
    progress.stage("segmenting " + std::to_string(num_faces(meshes[0])) +
                   " faces symmetrically into " + count_in_words(co.number_of_segments) + " segments");
  else
    progress.stage("segmenting " + std::to_string(m) + " meshes consistently into " +
                   count_in_words(co.number_of_segments) + " segments (" +
                   std::to_string(co.number_of_oversegments) + " over-segments each)");
  std::function<void(double)> on_progress = [&](double f) { progress.fraction(f); };
  const auto np = CS::parameters::number_of_segments(co.number_of_segments)
                    .number_of_oversegments(co.number_of_oversegments)
                    .adjacency_exponent(co.adjacency_exponent)
                    .number_of_points(co.number_of_points)
                    .number_of_partners(co.number_of_partners)
                    .number_of_runs(co.number_of_runs)
                    .normal_threshold(co.normal_threshold)
                    .correspondence_distance(co.correspondence_distance)
                    .concavity_exponent(co.concavity_exponent)
                    .prior_boundary_factor(co.prior_boundary_factor)
                    .component_link_distance(co.component_link_distance)
                    .component_link_factor(co.component_link_factor)
                    .boundary_refinement(boundary_refinement)
                    .random_seed(co.random_seed)
                    .number_of_threads(co.number_of_threads)
                    .progress_callback(on_progress);
  Stopwatch segmenting;
  CS::Consistent_segmentation_result r;
  double detection_seconds = 0, detected_support = 1;
  std::vector<double> face_support; // of the detected plane, per face in the order of faces(): empty, all 1
  if(o.detect_plane) { // the best reflective plane of the mesh
    progress.stage("detecting the symmetry plane");
    Stopwatch detecting;
    std::vector<CGAL::Surface_mesh_symmetrization::Symmetry<Kernel>> found;
    CGAL::Surface_mesh_symmetrization::detect_reflective_symmetries(
      meshes[0], std::back_inserter(found),
      CGAL::Surface_mesh_symmetrization::parameters::maximum_number_of_symmetries(1)
        .random_seed(co.random_seed)
        .number_of_threads(co.number_of_threads));
    if(found.empty())
      throw Cli_error("no reflective symmetry found (give the plane with --symmetry-plane a,b,c,d)");
    const auto& q = found.front().plane;
    plane = {{CGAL::to_double(q.a()), CGAL::to_double(q.b()), CGAL::to_double(q.c()), CGAL::to_double(q.d())}};
    detected_support = found.front().support_fraction;
    face_support = found.front().support;
    detection_seconds = detecting.seconds();
    progress.stage("segmenting " + std::to_string(num_faces(meshes[0])) + " faces symmetrically into " +
                   count_in_words(co.number_of_segments) + " segments");
  }
  if(symmetric) {
    const Kernel::Plane_3 p(plane[0], plane[1], plane[2], plane[3]);
    // The mirror links weighted by the detected plane's support (a partial symmetry).
    auto support = meshes[0].add_property_map<Mesh::Face_index, double>("f:symmetry_support", 1.0).first;
    if(!face_support.empty()) {
      std::size_t k = 0;
      for(Mesh::Face_index f : faces(meshes[0]))
        support[f] = face_support[k++];
    }
    const auto sp = np.symmetry_support_map(support);
    if(any_prior)
      r = CS::symmetric_segmentation(meshes[0], p, segment_maps[0], sp.prior_segment_map(prior_maps[0]));
    else
      r = CS::symmetric_segmentation(meshes[0], p, segment_maps[0], sp);
  } else if(any_known && any_prior)
    r = CS::consistent_segmentation(
      meshes, segment_maps, np.known_segment_maps(known_maps).prior_segment_maps(prior_maps));
  else if(any_known)
    r = CS::consistent_segmentation(meshes, segment_maps, np.known_segment_maps(known_maps));
  else if(any_prior)
    r = CS::consistent_segmentation(meshes, segment_maps, np.prior_segment_maps(prior_maps));
  else
    r = CS::consistent_segmentation(meshes, segment_maps, np);
  // Parts repeated within the meshes (legs): one id per kind of part.
  std::size_t merged_ids = 0;
  const CS::Merge_repeated_segments_options merge_options;
  if(o.merge_repeated) {
    progress.stage("merging the ids of repeated parts");
    merged_ids = CS::merge_repeated_segments(
      meshes, segment_maps, r, CS::parameters::random_seed(co.random_seed).number_of_threads(co.number_of_threads));
  }
  const double segment_seconds = segmenting.seconds();
  progress.done();

  // Labels per input face. A face left out of the surface (no area, or a repeat) takes the label
  // of its neighbour, or its own known label when that label is the id of a segment.
  std::vector<std::vector<std::size_t>> labels(m);
  std::vector<std::set<std::size_t>> present(m);
  for(std::size_t i = 0; i < m; ++i) {
    std::vector<std::size_t> mesh_labels;
    mesh_labels.reserve(num_faces(meshes[i]));
    for(auto f : faces(meshes[i]))
      mesh_labels.push_back(segment_maps[i][f]);
    labels[i] = inputs[i].input_labels(mesh_labels);
    if(!known_per_input[i].empty())
      for(std::size_t f = 0; f < labels[i].size(); ++f)
        if(inputs[i].mesh_face[f] == Input_mesh::left_out && known_per_input[i][f] >= 0) {
          const std::size_t l = static_cast<std::size_t>(known_per_input[i][f]);
          if(l < r.number_of_segments && r.segment_label[l] == known_per_input[i][f])
            labels[i][f] = l;
        }
    present[i].insert(labels[i].begin(), labels[i].end());
  }
  for(std::size_t i = 0; i < m; ++i)
    stage_segmentation(outputs, progress, inputs[i], labels[i], ply_paths[i], seg_paths[i]);
  if(!o.report.empty()) {
    Json report = Json::object();
    report["command"] = "coseg";
    report["mode"] = symmetric ? "symmetric" : "consistent";
    Json meshes_report = Json::array();
    for(std::size_t i = 0; i < m; ++i) {
      Json entry = Json::object();
      add_input_report(entry, "", o.inputs[i], inputs[i]);
      entry["known"] = known_files[i].empty() ? Json() : Json(known_files[i]);
      entry["prior"] = prior_files[i].empty() ? Json() : Json(prior_files[i]);
      entry["segments"] = std::vector<std::size_t>(present[i].begin(), present[i].end());
      entry["labels"] = seg_paths[i];
      entry["mesh"] = ply_paths[i];
      meshes_report.push_back(entry);
    }
    report["meshes"] = meshes_report;
    // The options as the library's named parameters.
    Json parameters = Json::object();
    parameters["number_of_segments"] = co.number_of_segments;
    parameters["number_of_oversegments"] = co.number_of_oversegments;
    parameters["number_of_points"] = co.number_of_points;
    parameters["number_of_partners"] = co.number_of_partners;
    parameters["number_of_runs"] = co.number_of_runs;
    parameters["adjacency_exponent"] = co.adjacency_exponent;
    parameters["normal_threshold"] = co.normal_threshold;
    parameters["correspondence_distance"] = co.correspondence_distance;
    parameters["concavity_exponent"] = co.concavity_exponent;
    parameters["prior_boundary_factor"] = co.prior_boundary_factor;
    parameters["component_link_distance"] = co.component_link_distance;
    parameters["component_link_factor"] = co.component_link_factor;
    parameters["boundary_refinement"] = boundary_refinement;
    parameters["random_seed"] = co.random_seed;
    parameters["number_of_threads"] = co.number_of_threads;
    parameters["symmetry_plane"] =
      symmetric ? Json(std::vector<double>(plane.begin(), plane.end())) : Json();
    report["plane_detected"] = o.detect_plane;
    if(o.detect_plane) {
      report["plane_support"] = detected_support;
      report["seconds_detection"] = detection_seconds;
    }
    report["parameters"] = parameters;
    Json merged = Json();
    if(o.merge_repeated) {
      merged = Json::object();
      merged["duplicate_tolerance"] = merge_options.duplicate_tolerance;
      merged["ids_merged"] = merged_ids;
    }
    report["merge_repeated"] = merged;
    report["segments"] = r.number_of_segments;
    report["meshes_of_segment"] = r.meshes_of_segment;
    report["segment_area"] = r.segment_area;
    report["segment_label"] = r.segment_label;
    report["oversegments"] = r.number_of_oversegments;
    report["aligned_pairs"] = r.number_of_aligned_pairs;
    report["correspondences"] = r.number_of_correspondences;
    report["mean_alignment_rms"] = r.mean_alignment_rms;
    report["runs"] = r.number_of_runs;
    report["chosen_run"] = r.chosen_run;
    report["run_disagreement"] = r.run_disagreement;
    stage_report(outputs, o.report, report, segment_seconds, read_seconds, total.seconds(),
                 {{"directory", o.output_dir}});
  }
  outputs.commit();
  created.keep = true;

  for(std::size_t i = 0; i < m; ++i)
    std::cout << o.inputs[i] << ": " << inputs[i].number_of_input_faces() << " faces, "
              << present[i].size() << " segments -> " << seg_paths[i] << ", " << ply_paths[i]
              << "\n";
  std::cout << m << (m == 1 ? " mesh, " : " meshes, ") << total_faces << " faces, "
            << r.number_of_segments << " segments in " << segment_seconds << " s\n";
  return 0;
}

} // namespace

void add_coseg_command(CLI::App& app, std::function<int()>& run,
                       const CS::Consistent_segmentation_options& defaults)
{
  auto options = std::make_shared<Coseg_command_options>();
  options->coseg = defaults;
  CS::Consistent_segmentation_options& co = options->coseg;
  CLI::App* cmd = app.add_subcommand(
    "coseg",
    "Segment a set of triangle meshes consistently (the same segment id for the same part in "
    "every mesh), transfer known labels to the other faces, or segment one mesh symmetrically.");
  cmd->add_option("inputs", options->inputs, "Input triangle meshes (.off, .ply, .obj, .stl)")
    ->required();
  cmd->add_option("-o,--output-dir", options->output_dir,
                  "Directory (created if missing) for NAME.seg (segment id per input face) and "
                  "NAME.ply (coloured by segment id, the same colours in every mesh) per input")
    ->required();
  cmd->add_option("--report", options->report,
                  "JSON report (inputs, parameters, seconds, segments per mesh, correspondences)");
  cmd->add_option("-k,--segments", co.number_of_segments,
                  "Number of segments over the whole set, or auto: the median over the meshes of the "
                  "number `segment -k auto` chooses for each (the report's number_of_segments is then 0)")
    ->default_str(count_or_auto(co.number_of_segments))
    ->transform(positive_count_or_auto);
  cmd->add_option("--oversegments", co.number_of_oversegments,
                  "Number of segments of each mesh before the joint merging")
    ->capture_default_str()
    ->check(positive_count);
  cmd->add_option("--known", options->known,
                  "MESH=FILE.seg: known labels of a mesh (MESH: its path or file name; one "
                  "label per input face, -1 for unknown), kept and transferred (repeatable)")
    ->allow_extra_args(false);
  cmd->add_option("--prior", options->prior,
                  "MESH=FILE.seg: a prior segmentation whose boundaries are cheaper to cut "
                  "(repeatable)")
    ->allow_extra_args(false);
  CLI::Option* plane = cmd->add_option("--symmetry-plane", options->symmetry_plane,
                                       "a,b,c,d: segment the one input mesh symmetrically about "
                                       "the plane a x + b y + c z + d = 0");
  cmd->add_option("--points", co.number_of_points,
                  "Number of points sampled on each mesh for the correspondences (>= 10)")
    ->capture_default_str();
  cmd->add_option("--partners", co.number_of_partners,
                  "Number of best-aligned partners whose correspondences each mesh keeps (twice "
                  "as many are aligned in large sets; 0: every pair)")
    ->capture_default_str();
  cmd->add_option("--runs", co.number_of_runs,
                  "Number of runs of the alignments and merging, each with its own sample points, "
                  "in [1, 1000]; the run that agrees most with the others is kept (use 3 or more)")
    ->capture_default_str();
  cmd->add_option("--adjacency-exponent", co.adjacency_exponent,
                  "Weight in [0, 1] of the mesh edges against the correspondences")
    ->capture_default_str();
  cmd->add_option("--normal-threshold", co.normal_threshold,
                  "Least dot product of the normals of two corresponding points, in [-1, 1]")
    ->capture_default_str();
  cmd->add_option("--correspondence-distance", co.correspondence_distance,
                  "Largest distance of two corresponding points, as a fraction of the bounding-box "
                  "diagonal")
    ->capture_default_str();
  cmd->add_option("--concavity-exponent", co.concavity_exponent,
                  "Exponent alpha of the concavity weight min((theta/pi)^alpha, 1)")
    ->capture_default_str();
  cmd->add_option("--prior-factor", co.prior_boundary_factor,
                  "Cut-cost divisor on prior boundaries (>= 1)")
    ->capture_default_str();
  cmd->add_option("--link-distance", co.component_link_distance,
                  "Link faces of different components of a mesh closer than this fraction of its "
                  "bounding-box diagonal")
    ->capture_default_str();
  cmd->add_option("--link-factor", co.component_link_factor,
                  "Cost of a component link relative to the mean edge cut cost")
    ->capture_default_str();
  cmd->add_flag("--no-refinement", options->no_refinement, "Skip the boundary refinement");
  cmd->add_flag("--merge-repeated", options->merge_repeated,
                "Then give one id to the segments that are copies of one part within the meshes "
                "(the legs of a chair, its armrests; merge_repeated_segments())");
  cmd->add_option("--seed", co.random_seed, "Random seed (same seed, same result)")->capture_default_str();
  cmd->add_option("--threads", co.number_of_threads, "Largest number of threads (0: all cores)")
    ->capture_default_str();
  cmd->add_flag("-q,--quiet", options->quiet, "No progress on stderr");
  cmd->add_flag("-v,--verbose", options->verbose,
                "Progress on stderr even when it is not a terminal");
  CLI::Option* detect = cmd->add_flag("--symmetric", options->detect_plane,
                                      "Segment the one input mesh symmetrically about its best detected "
                                      "reflective plane (the report has it), the mirror links weighted by "
                                      "the plane's per-face support");
  cmd->callback([options, plane, detect, &run]() {
    if(plane->count() > 0 && detect->count() > 0)
      throw CLI::ValidationError("--symmetric", "give either --symmetric or --symmetry-plane, not both");
    options->symmetric = plane->count() > 0 || options->detect_plane;
    run = [options]() { return run_coseg(*options); };
  });
}

} // namespace shape_analysis_cli
