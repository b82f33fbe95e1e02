// Copyright (c) 2026 CGAL Global Shape Analysis contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later

// shape_analysis symmetry detect IN [--rotational] --report R.json [--output SUPPORT.ply]
// shape_analysis symmetry symmetrize IN [--plane a,b,c,d] --output OUT.off --map MAP.txt --report R.json
// shape_analysis symmetry enhance IN --amount t [--plane a,b,c,d | --symmetric SYM.off] --output OUT.off
// shape_analysis symmetry transfer IN [--colors IN_COLORS.ply] [--plane a,b,c,d] --output OUT.ply
// (remesh and decimate: symmetry_remesh_command.cpp)

#include "cli_common.h"
#include "symmetry_files.h"

#include <CGAL/Surface_mesh_symmetrization/detect_reflective_symmetries.h>
#include <CGAL/Surface_mesh_symmetrization/detect_rotational_symmetries.h>
#include <CGAL/Surface_mesh_symmetrization/symmetrize.h>
#include <CGAL/Surface_mesh_symmetrization/transfer_vertex_attribute.h>

#include <CGAL/IO/PLY.h>
#include <CGAL/IO/polygon_soup_io.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <map>
#include <memory>
#include <sstream>

namespace shape_analysis_cli {

namespace {

struct Detect_options : Common_options
{
  std::string output_ply;
  bool rotational = false;
  bool minimum_support_given = false; // (the rotations' default differs from the planes')
  SMS::Detect_rotational_symmetries_options rotation;
};

struct Enhance_options : Symmetrize_command_options
{
  double amount = 1;
  std::string symmetric;
};

struct Transfer_options : Common_options
{
  std::string colors, output_ply, symmetric;
  SMS::Transfer_vertex_attribute_options transfer;
};

// The names of --mode and --from.
const std::map<std::string, SMS::Transfer_mode> transfer_modes{{"copy", SMS::Transfer_mode::COPY},
                                                               {"blend", SMS::Transfer_mode::BLEND}};
const std::map<std::string, int> source_sides{{"positive", 1}, {"negative", -1}};

template <typename Value>
std::string name_of(const std::map<std::string, Value>& names, Value value)
{
  for(const auto& n : names)
    if(n.second == value)
      return n.first;
  return std::string();
}

// `symmetry detect`: the planes, or with --rotational the axes (their orders), with their scores
// and supports.
int run_detect(const Detect_options& o)
{
  Stopwatch total;
  Progress progress("symmetry detect", o.quiet, o.verbose);
  Output_files outputs;
  outputs.add_input(o.input);
  if(!o.output_ply.empty())
    outputs.add_output(o.output_ply, "support mesh", {".ply"});
  outputs.add_optional_output(o.report, "report", {".json"});
  double read_seconds = 0;
  const Input_mesh input = read_input_mesh(o.input, progress, read_seconds);
  const std::string kind = o.rotational ? "rotational" : "reflective";
  progress.stage("detecting " + kind + " symmetries of " + std::to_string(num_faces(input.mesh)) + " faces");
  // The options as the library's named parameters (a rotation's minimum support has its own default).
  SMS::Detect_reflective_symmetries_options d = o.detection;
  if(o.rotational && !o.minimum_support_given)
    d.minimum_support = o.rotation.minimum_support;
  Json parameters = Json::object();
  parameters["number_of_samples"] = d.number_of_samples;
  parameters["random_seed"] = d.random_seed;
  parameters["maximum_number_of_symmetries"] = d.maximum_number_of_symmetries;
  if(o.rotational)
    parameters["maximum_order"] = o.rotation.maximum_order;
  parameters["minimum_support"] = d.minimum_support;
  parameters["support_tolerance"] = d.support_tolerance;
  parameters["number_of_threads"] = d.number_of_threads;
  const auto np = SMS::parameters::number_of_samples(d.number_of_samples)
                    .random_seed(d.random_seed)
                    .number_of_threads(d.number_of_threads)
                    .maximum_number_of_symmetries(d.maximum_number_of_symmetries)
                    .minimum_support(d.minimum_support)
                    .support_tolerance(d.support_tolerance);
  Stopwatch watch;
  Json found = Json::array();         // per symmetry, its report entry
  std::vector<std::string> lines;     // and its line on stdout
  std::vector<double> best_support;   // per face, of the best one
  if(o.rotational) {
    std::vector<SMS::Rotational_symmetry<Kernel>> r;
    SMS::detect_rotational_symmetries(input.mesh, std::back_inserter(r), np.maximum_order(o.rotation.maximum_order));
    for(const auto& x : r) {
      const std::string order = x.order == 0 ? std::string("revolution") : std::to_string(x.order) + "-fold";
      Json j = Json::object();
      j["axis"] = Json::array({x.axis.x(), x.axis.y(), x.axis.z()});
      j["point"] = Json::array({x.point.x(), x.point.y(), x.point.z()});
      j["order"] = x.order; // 0: a surface of revolution
      j["kind"] = order;
      j["score"] = x.score;
      j["support"] = x.support_fraction;
      found.push_back(j);
      std::ostringstream line;
      line << order << " about the axis through " << x.point << " along " << x.axis << "  score " << x.score
           << "  support " << x.support_fraction;
      lines.push_back(line.str());
    }
    if(!r.empty())
      best_support = r.front().support;
  } else {
    std::vector<Symmetry> r;
    SMS::detect_reflective_symmetries(input.mesh, std::back_inserter(r), np);
    for(const Symmetry& x : r) {
      Json j = plane_json(x);
      j["score"] = x.score;
      j["support"] = x.support_fraction;
      found.push_back(j);
      std::ostringstream line;
      line << "plane " << plane_text(x) << "  score " << x.score << "  support " << x.support_fraction;
      lines.push_back(line.str());
    }
    if(!r.empty())
      best_support = r.front().support;
  }
  const double seconds = watch.seconds();
  progress.done();
  if(!o.output_ply.empty()) {
    if(found.empty())
      throw Cli_error("no " + kind + " symmetry found: no support mesh to write");
    progress.stage("writing " + o.output_ply);
    const std::vector<double> support = per_input_face(input, best_support, 0.0);
    outputs.stage(o.output_ply, true, [&](std::ostream& out) {
      write_support_ply(out, input.points, input.triangles, support);
    });
  }
  if(!o.report.empty()) {
    Json report = input_report("symmetry detect", o.input, input);
    report["parameters"] = parameters;
    report[o.rotational ? "rotations" : "planes"] = found;
    stage_report(outputs, o.report, report, seconds, read_seconds, total.seconds(),
                 {{"support_mesh", o.output_ply}});
  }
  outputs.commit();
  std::cout << o.input << ": " << found.size() << " " << kind << " symmetr" << (found.size() == 1 ? "y" : "ies")
            << " in " << seconds << " s\n";
  for(const std::string& line : lines)
    std::cout << "  " << line << '\n';
  return 0;
}

int run_symmetrize(const Symmetrize_command_options& o)
{
  Stopwatch total;
  Progress progress("symmetry symmetrize", o.quiet, o.verbose);
  Output_files outputs;
  outputs.add_input(o.input);
  check_symmetry_options(o); // a bad plane or turn costs nothing
  if(!o.output_off.empty()) {
    outputs.add_output(o.output_off, "symmetrized mesh", {".off"});
  }
  outputs.add_optional_output(o.map, "symmetric map");
  outputs.add_optional_output(o.report, "report", {".json"});
  double read_seconds = 0;
  Input_mesh input = read_input_mesh(o.input, progress, read_seconds);
  Stopwatch watch;
  Symmetry symmetry;
  double detect_seconds = 0;
  bool detected = false;
  Used_symmetries used;
  const auto r = symmetrize_input(o, input, progress, symmetry, detect_seconds, detected, &used);
  const double seconds = watch.seconds();
  const std::vector<Point_3> points = moved_points(input, input.mesh);
  if(!o.output_off.empty()) {
    progress.stage("writing " + o.output_off);
    outputs.stage(o.output_off, false, [&](std::ostream& out) { write_off(out, points, input.triangles); });
  }
  if(!o.map.empty()) {
    progress.stage("writing " + o.map);
    outputs.stage(o.map, false, [&](std::ostream& out) { write_map(out, input, input.mesh, r.symmetric_map.front()); });
  }
  if(!o.report.empty()) {
    Json report = input_report("symmetry symmetrize", o.input, input);
    report["parameters"] = symmetrization_parameters(o);
    add_symmetrization_report(report, r, symmetry, detected, detect_seconds, used);
    stage_report(outputs, o.report, report, seconds, read_seconds, total.seconds(),
                 {{"mesh", o.output_off}, {"map", o.map}});
  }
  outputs.commit();
  std::cout << o.input << ": symmetry error " << r.symmetry_error_before << " -> " << r.symmetry_error_after
            << " (of the bounding-box diagonal), distortion " << r.distortion << ", " << seconds << " s\n";
  return 0;
}

int run_enhance(const Enhance_options& o)
{
  Stopwatch total;
  Progress progress("symmetry enhance", o.quiet, o.verbose);
  Output_files outputs;
  outputs.add_input(o.input);
  if(!std::isfinite(o.amount))
    throw Usage_error("--amount must be a finite number");
  check_symmetry_options(o);
  if(!o.symmetric.empty()) {
    outputs.add_input(o.symmetric);
    if(!o.plane.empty() || o.rotation_requested)
      throw Usage_error("give either --symmetric or --plane / --rotation, not both");
  }
  outputs.add_output(o.output_off, "enhanced mesh", {".off"});
  outputs.add_optional_output(o.report, "report", {".json"});
  double read_seconds = 0;
  Input_mesh input = read_input_mesh(o.input, progress, read_seconds);
  Stopwatch watch;
  std::vector<Point_3> symmetric, original = input.points;
  Json report = input_report("symmetry enhance", o.input, input);
  if(!o.symmetric.empty()) {
    // A symmetrized version given: the residuals are the differences, nothing to solve.
    double more = 0;
    const Input_mesh sym = read_input_mesh(o.symmetric, progress, more);
    read_seconds += more;
    if(sym.points.size() != input.points.size() || sym.triangles != input.triangles)
      throw Cli_error("'" + o.symmetric + "' does not have the vertices and faces of '" + o.input + "'");
    symmetric = sym.points;
  } else {
    Symmetry symmetry;
    double detect_seconds = 0;
    bool detected = false;
    Used_symmetries used;
    const auto r = symmetrize_input(o, input, progress, symmetry, detect_seconds, detected, &used);
    symmetric = moved_points(input, input.mesh);
    report["parameters"] = symmetrization_parameters(o);
    add_symmetrization_report(report, r, symmetry, detected, detect_seconds, used);
  }
  std::vector<Point_3> enhanced(original.size());
  for(std::size_t i = 0; i < original.size(); ++i)
    enhanced[i] = symmetric[i] + (original[i] - symmetric[i]) * (1 - o.amount);
  const double seconds = watch.seconds();
  progress.stage("writing " + o.output_off);
  outputs.stage(o.output_off, false, [&](std::ostream& out) { write_off(out, enhanced, input.triangles); });
  if(!o.report.empty()) {
    report["amount"] = o.amount;
    stage_report(outputs, o.report, report, seconds, read_seconds, total.seconds(), {{"mesh", o.output_off}});
  }
  outputs.commit();
  std::cout << o.input << ": amount " << o.amount << " written to " << o.output_off << " in " << seconds << " s\n";
  return 0;
}

std::vector<CGAL::IO::Color> read_vertex_colours(const std::string& path, std::size_t expected,
                                                 std::size_t merged)
{
  check_input_file(path);
  if(lower_extension(path) != ".ply")
    throw Cli_error("the vertex colours are read from a PLY file, not '" + path +
                    "': give the input as .ply or the colours with --colors FILE.ply");
  std::vector<Point_3> points;
  std::vector<std::vector<std::size_t>> polygons;
  std::vector<CGAL::IO::Color> colours, face_colours;
  bool ok = false;
  try {
    // (CGAL reads face and vertex colours through iterators of one type.)
    ok = CGAL::IO::read_PLY(path, points, polygons,
                            CGAL::parameters::vertex_color_output_iterator(std::back_inserter(colours))
                              .face_color_output_iterator(std::back_inserter(face_colours))
                              .verbose(false));
  } catch(const std::exception&) {
    ok = false;
  }
  if(!ok)
    throw Cli_error("cannot read '" + path + "': not a valid PLY file");
  if(colours.size() != points.size() || colours.empty())
    throw Cli_error("'" + path + "' has no vertex colours (red, green, blue)");
  if(points.size() != expected && points.size() != merged)
    throw Cli_error("'" + path + "' has " + std::to_string(points.size()) + " vertices, the mesh " +
                    std::to_string(expected));
  return colours;
}

int run_transfer(const Transfer_options& o)
{
  Stopwatch total;
  Progress progress("symmetry transfer", o.quiet, o.verbose);
  Output_files outputs;
  const std::string colour_file = o.colors.empty() ? o.input : o.colors;
  outputs.add_input(o.input);
  outputs.add_input(colour_file);
  if(!o.plane.empty())
    parse_plane(o.plane);
  if(!o.symmetric.empty())
    outputs.add_input(o.symmetric);
  outputs.add_output(o.output_ply, "coloured mesh", {".ply"});
  outputs.add_optional_output(o.report, "report", {".json"});
  double read_seconds = 0;
  const Input_mesh input = read_input_mesh(o.input, progress, read_seconds);
  // The file's vertex count (before duplicate points were merged).
  std::size_t file_vertices = 0;
  for(std::size_t i : input.input_index)
    file_vertices = (std::max)(file_vertices, i + 1);
  {
    std::vector<Point_3> p;
    std::vector<std::vector<std::size_t>> f;
    if(CGAL::IO::read_polygon_soup(o.input, p, f, CGAL::parameters::verbose(false)))
      file_vertices = p.size();
  }
  Stopwatch read_colours;
  // Colours per vertex of the file, or per point once duplicates are merged (as the tool writes).
  const std::vector<CGAL::IO::Color> read = read_vertex_colours(colour_file, file_vertices, input.points.size());
  std::vector<CGAL::IO::Color> file_colours = read;
  if(read.size() != file_vertices) { // per merged point: spread to the file's vertices
    file_colours.assign(file_vertices, CGAL::IO::Color());
    for(std::size_t p = 0; p < input.points.size(); ++p)
      file_colours[input.input_index[p]] = read[p];
  }
  read_seconds += read_colours.seconds();
  Stopwatch watch;
  Symmetry symmetry;
  double detect_seconds = 0;
  bool detected = false;
  // With --symmetric: the symmetric map of the symmetrized mesh (the input's vertices and faces),
  // whose plane is detected there when not given.
  std::vector<SMS::Mirror_point> map;
  if(!o.symmetric.empty()) {
    double more = 0;
    const Input_mesh sym = read_input_mesh(o.symmetric, progress, more);
    read_seconds += more;
    if(sym.points.size() != input.points.size() || sym.triangles != input.triangles)
      throw Cli_error("'" + o.symmetric + "' does not have the vertices and faces of '" + o.input + "'");
    symmetry = symmetry_of(o, sym.mesh, progress, detect_seconds, detected);
    progress.stage("computing the symmetric map of " + o.symmetric);
    map = SMS::compute_symmetric_map(sym.mesh, symmetry,
                                     SMS::parameters::number_of_threads(o.detection.number_of_threads));
  } else
    symmetry = symmetry_of(o, input.mesh, progress, detect_seconds, detected);
  // Colours of the mesh's vertices, through the points.
  Mesh mesh = input.mesh;
  auto colour = mesh.add_property_map<Mesh::Vertex_index, CGAL::IO::Color>("v:transfer_colour").first;
  for(Mesh::Vertex_index v : mesh.vertices())
    colour[v] = file_colours[input.input_index[input.vertex_point[v]]];
  const SMS::Transfer_vertex_attribute_options& to = o.transfer;
  const bool copy = to.transfer_mode == SMS::Transfer_mode::COPY;
  const std::string from = name_of(source_sides, to.source_side);
  progress.stage(std::string(copy ? "copying" : "blending") + " vertex colours across the plane " +
                 plane_text(symmetry));
  const auto np = SMS::parameters::transfer_mode(to.transfer_mode)
                    .source_side(to.source_side)
                    .number_of_threads(o.detection.number_of_threads);
  if(map.empty())
    SMS::transfer_vertex_attribute(mesh, symmetry, colour, np);
  else
    SMS::transfer_vertex_attribute(mesh, symmetry, colour, np.symmetric_map(map));
  std::vector<CGAL::IO::Color> colours(input.points.size());
  for(std::size_t p = 0; p < input.points.size(); ++p)
    colours[p] = file_colours[input.input_index[p]];
  std::size_t changed = 0;
  for(Mesh::Vertex_index v : mesh.vertices()) {
    const std::size_t p = input.vertex_point[v];
    if(colour[v] != colours[p])
      ++changed;
    colours[p] = colour[v];
  }
  const double seconds = watch.seconds();
  progress.stage("writing " + o.output_ply);
  outputs.stage(o.output_ply, true, [&](std::ostream& out) {
    write_vertex_coloured_ply(out, input.points, input.triangles, colours);
  });
  if(!o.report.empty()) {
    Json report = input_report("symmetry transfer", o.input, input);
    report["colors"] = colour_file;
    // The options as the library's named parameters.
    Json parameters = Json::object();
    parameters["transfer_mode"] = name_of(transfer_modes, to.transfer_mode);
    parameters["source_side"] = to.source_side;
    parameters["number_of_threads"] = o.detection.number_of_threads;
    report["parameters"] = parameters;
    report["plane"] = plane_json(symmetry);
    report["plane_detected"] = detected;
    report["symmetric"] = o.symmetric.empty() ? Json() : Json(o.symmetric);
    report["seconds_detection"] = detect_seconds;
    report["vertices_changed"] = changed;
    stage_report(outputs, o.report, report, seconds, read_seconds, total.seconds(), {{"mesh", o.output_ply}});
  }
  outputs.commit();
  std::cout << o.input << ": colours " << (copy ? "copied from the " + from + " side" : std::string("blended"))
            << " across the plane " << plane_text(symmetry) << " in " << seconds << " s\n";
  return 0;
}

} // namespace

void add_symmetry_command(CLI::App& app, std::function<int()>& run)
{
  CLI::App* symmetry = app.add_subcommand(
    "symmetry", "Reflective symmetries of a triangle mesh: detect, symmetrize, enhance, transfer attributes, "
                "remesh and decimate symmetrically.");
  symmetry->require_subcommand(1);

  auto d = std::make_shared<Detect_options>();
  CLI::App* detect = symmetry->add_subcommand(
    "detect", "Detect the planar reflective symmetries (global and partial), or with --rotational the "
              "rotational ones (k-fold axes, surfaces of revolution), best first.");
  add_common_options(detect, *d, false);
  detect->add_option("--report", d->report,
                     "JSON report: planes (unit normal n and offset d of n.x = d, coefficients "
                     "a,b,c,d, score, support), seconds");
  detect->add_option("-o,--output", d->output_ply,
                     "The mesh with each face coloured by its support for the best plane (.ply, "
                     "float face property 'support')");
  detect->add_option("--max-symmetries", d->detection.maximum_number_of_symmetries,
                     "Largest number of planes reported")
    ->capture_default_str();
  detect->add_option("--min-support", d->detection.minimum_support,
                     "Smallest support fraction of a plane, in [0, 1] (of a rotation: default " +
                       Json(d->rotation.minimum_support).dump() + ")")
    ->capture_default_str();
  detect->add_flag("--rotational", d->rotational,
                   "Detect rotational symmetries instead of planes: the report's 'rotations' (axis, "
                   "point, order: k of a k-fold symmetry or 0 for a surface of revolution, score, support)");
  detect->add_option("--max-order", d->rotation.maximum_order, "With --rotational: the largest order k tried (2 to 360)")
    ->capture_default_str();
  detect->callback([d, detect, &run]() {
    d->minimum_support_given = detect->count("--min-support") > 0;
    if(!d->rotational && detect->count("--max-order") > 0)
      throw CLI::ValidationError("--max-order", "needs --rotational");
    run = [d]() { return run_detect(*d); };
  });

  auto s = std::make_shared<Symmetrize_command_options>();
  CLI::App* sym = symmetry->add_subcommand(
    "symmetrize", "Warp the mesh (same vertices and faces) to be symmetric about a plane (or under a turn, "
                  "--rotation), "
                  "changing its shape as little as possible.");
  add_common_options(sym, *s, true);
  sym->add_option("-o,--output", s->output_off, "The symmetrized mesh (.off; the input's vertices and faces, in order)");
  sym->add_option("--map", s->map,
                  "The symmetric map: per vertex, the face and barycentric coordinates of its mirror point (text)");
  sym->add_option("--report", s->report,
                  "JSON report: plane, symmetry_error_before, symmetry_error_after, distortion, seconds");
  sym->add_option("--iterations", s->symmetrization.number_of_iterations, "Steps of alpha from 0 to 1 on the coarsest level (>= 1)")
    ->capture_default_str();
  sym->add_option("--levels", s->symmetrization.number_of_levels, "Levels of the multiresolution hierarchy (0: automatic, 1: none)")
    ->capture_default_str();
  sym->add_option("--final-weight", s->symmetrization.final_symmetry_weight,
                  "Weight of symmetry against shape in the last steps (> 0): larger, less asymmetry and more "
                  "distortion where the two sides have no matching vertices")
    ->capture_default_str();
  sym->add_option("--target-error", s->symmetrization.target_symmetry_error,
                  "RMS symmetry error (fraction of the diagonal) at which the isometric refinement stops "
                  "(0: no refinement); smaller, more symmetric and more distorted")
    ->capture_default_str();
  add_rotation_option(sym, *s);
  add_several_planes_option(sym, *s);
  sym->callback([s, sym, &run]() {
    note_rotation_option(sym, *s);
    run = [s]() { return run_symmetrize(*s); };
  });

  auto e = std::make_shared<Enhance_options>();
  CLI::App* enhance = symmetry->add_subcommand(
    "enhance", "Move the mesh between or beyond its symmetric and its input shape: amount 1 is "
               "symmetric, 0 the input, below 0 exaggerates the asymmetries.");
  add_common_options(enhance, *e, true);
  enhance->add_option("--amount", e->amount, "The amount t (position = symmetric + (1 - t) residual)")->required();
  enhance->add_option("-o,--output", e->output_off, "The enhanced mesh (.off)")->required();
  enhance->add_option("--symmetric", e->symmetric,
                      "The symmetrized mesh written by 'symmetry symmetrize' (no solve: instant)");
  enhance->add_option("--report", e->report, "JSON report");
  SMS::Symmetrize_options& es = e->symmetrization;
  enhance->add_option("--iterations", es.number_of_iterations, "As for symmetrize")->capture_default_str();
  enhance->add_option("--levels", es.number_of_levels, "As for symmetrize")->capture_default_str();
  enhance->add_option("--final-weight", es.final_symmetry_weight, "As for symmetrize")->capture_default_str();
  enhance->add_option("--target-error", es.target_symmetry_error, "As for symmetrize")->capture_default_str();
  add_rotation_option(enhance, *e);
  add_several_planes_option(enhance, *e);
  enhance->callback([e, enhance, &run]() {
    note_rotation_option(enhance, *e);
    run = [e]() { return run_enhance(*e); };
  });

  auto t = std::make_shared<Transfer_options>();
  CLI::App* transfer = symmetry->add_subcommand(
    "transfer", "Transfer vertex colours from one side of the symmetry plane to the other "
                "(or blend both sides) through the symmetric map.");
  add_common_options(transfer, *t, true);
  transfer->add_option("--colors", t->colors,
                       "PLY with the vertex colours, the same vertices as IN in the same order (default: IN)");
  transfer->add_option("-o,--output", t->output_ply, "The mesh with the transferred vertex colours (.ply)")->required();
  // Bound to the library's options by name (the defaults shown are the library's).
  transfer->add_option("--mode", t->transfer.transfer_mode,
                       "copy (one side onto the other) or blend (both sides, symmetric)")
    ->type_name("TEXT")
    ->transform(CLI::CheckedTransformer(transfer_modes).description("{copy,blend}"))
    ->default_str(name_of(transfer_modes, t->transfer.transfer_mode));
  transfer->add_option("--from", t->transfer.source_side,
                       "copy: the side copied, positive (where the plane's normal points) or negative")
    ->type_name("TEXT")
    ->transform(CLI::CheckedTransformer(source_sides).description("{positive,negative}"))
    ->default_str(name_of(source_sides, t->transfer.source_side));
  transfer->add_option("--report", t->report, "JSON report");
  transfer->add_option("--symmetric", t->symmetric,
                       "The symmetrized mesh written by 'symmetry symmetrize' (the input's vertices and faces): "
                       "the colours go through its symmetric map, whose mirror points are those of a "
                       "symmetric surface, instead of the input's (its plane detected there when not given)");
  transfer->callback([t, &run]() { run = [t]() { return run_transfer(*t); }; });

  add_symmetry_remesh_commands(symmetry, run);
}

} // namespace shape_analysis_cli
