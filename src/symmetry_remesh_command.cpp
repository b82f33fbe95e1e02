// Copyright (c) 2026 CGAL Global Shape Analysis contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later

// shape_analysis symmetry remesh IN [--plane a,b,c,d] [--faces N] [--copy-one-side] --output OUT.off [--report R.json]
// shape_analysis symmetry decimate IN [--plane a,b,c,d] --faces N [--restore] --output OUT.off [--report R.json]

#include "cli_common.h"
#include "symmetry_files.h"

#include <CGAL/Surface_mesh_symmetrization/compute_symmetric_map.h>
#include <CGAL/Surface_mesh_symmetrization/symmetric_simplification.h>

#include <cmath>
#include <iostream>
#include <memory>
#include <string>

namespace shape_analysis_cli {

namespace {

struct Remesh_options : Symmetrize_command_options
{
  std::size_t faces = 0; // remesh: 0 for the input's
  bool copy_one_side = false;
  bool restore = false;
};

// The vertices and faces of `mesh` as OFF.
void write_mesh_off(std::ostream& out, const Mesh& mesh)
{
  std::vector<Point_3> points;
  std::vector<std::size_t> index(mesh.number_of_vertices() + mesh.number_of_removed_vertices(), 0);
  for(Mesh::Vertex_index v : mesh.vertices()) {
    index[v.idx()] = points.size();
    points.push_back(mesh.point(v));
  }
  std::vector<std::array<std::size_t, 3>> triangles;
  for(Mesh::Face_index f : mesh.faces()) {
    const Mesh::Halfedge_index h = mesh.halfedge(f);
    triangles.push_back({{index[mesh.source(h).idx()], index[mesh.target(h).idx()],
                          index[mesh.target(mesh.next(h)).idx()]}});
  }
  write_off(out, points, triangles);
}

void add_connectivity(Json& report, const SMS::Symmetric_connectivity& c)
{
  report["paired_vertices"] = c.paired_vertices;
  report["symmetric_edges"] = c.symmetric_edges;
  report["symmetric_faces"] = c.symmetric_faces;
}

Json connectivity_json(const SMS::Symmetric_connectivity& c)
{
  Json j = Json::object();
  add_connectivity(j, c);
  return j;
}

// The RMS distance of the vertices to the surface's mirror image, relative to the bounding-box
// diagonal (what symmetrize() reports as its error).
double symmetry_error(const Mesh& mesh, const Symmetry& s)
{
  const std::vector<SMS::Mirror_point> map = SMS::compute_symmetric_map(mesh, s);
  const CGAL::Bbox_3 box = CGAL::bbox_3(mesh.points().begin(), mesh.points().end());
  const double diagonal = std::sqrt(CGAL::square(box.xmax() - box.xmin()) + CGAL::square(box.ymax() - box.ymin()) +
                                    CGAL::square(box.zmax() - box.zmin()));
  double sum = 0;
  for(const SMS::Mirror_point& m : map)
    sum += m.found ? m.distance * m.distance : diagonal * diagonal;
  return map.empty() || !(diagonal > 0) ? 0.0 : std::sqrt(sum / double(map.size())) / diagonal;
}

// Reads the input and finds the plane; checks the output paths first (a bad command line costs
// nothing).
Input_mesh prepare(const Remesh_options& o, Output_files& outputs, Progress& progress, double& read_seconds,
                   Symmetry& symmetry, double& detect_seconds, bool& detected)
{
  outputs.add_input(o.input);
  if(!o.plane.empty())
    parse_plane(o.plane);
  outputs.add_output(o.output_off, "output mesh", {".off"});
  outputs.add_optional_output(o.report, "report", {".json"});
  Input_mesh input = read_input_mesh(o.input, progress, read_seconds);
  symmetry = symmetry_of(o, input.mesh, progress, detect_seconds, detected);
  return input;
}

void finish(const Remesh_options& o, Output_files& outputs, Progress& progress, const Mesh& mesh, Json report,
            double seconds, double read_seconds, double total)
{
  progress.stage("writing " + o.output_off);
  outputs.stage(o.output_off, false, [&](std::ostream& out) { write_mesh_off(out, mesh); });
  if(!o.report.empty())
    stage_report(outputs, o.report, report, seconds, read_seconds, total, {{"mesh", o.output_off}});
  outputs.commit();
}

int run_remesh(const Remesh_options& o)
{
  Stopwatch total;
  Progress progress("symmetry remesh", o.quiet, o.verbose);
  Output_files outputs;
  double read_seconds = 0, detect_seconds = 0;
  bool detected = false;
  Symmetry symmetry;
  Input_mesh input = prepare(o, outputs, progress, read_seconds, symmetry, detect_seconds, detected);
  Stopwatch watch;
  Json report = input_report("symmetry remesh", o.input, input);
  const double error = symmetry_error(input.mesh, symmetry);
  const bool symmetrized = error > o.symmetrization.target_symmetry_error;
  if(symmetrized) { // the surface first
    Symmetrize_command_options so = o;
    so.plane = plane_text(symmetry);
    double unused = 0;
    bool unused_detected = false;
    const auto s = symmetrize_input(so, input, progress, symmetry, unused, unused_detected);
    add_symmetrization_report(report, s, symmetry, detected, detect_seconds);
  } else {
    report["plane"] = plane_json(symmetry);
    report["plane_detected"] = detected;
    report["seconds_detection"] = detect_seconds;
  }
  report["symmetrized"] = symmetrized;
  report["surface_symmetry_error"] = error;
  progress.stage("remeshing " + std::to_string(num_faces(input.mesh)) + " faces symmetrically");
  const SMS::Symmetric_remeshing_result r = SMS::symmetric_remeshing(
    input.mesh, symmetry, SMS::parameters::number_of_faces(o.faces).copy_one_side(o.copy_one_side));
  const double seconds = watch.seconds();
  add_connectivity(report, r.after);
  report["connectivity_before"] = connectivity_json(r.before);
  report["faces_before"] = r.faces_before;
  report["faces"] = r.faces;
  report["meta_mesh_faces"] = r.meta_mesh_faces;
  report["mirror_points"] = r.mirror_points;
  report["flips"] = r.flips;
  report["overlaid_regions"] = r.overlaid_regions;
  report["overlay_points"] = r.overlay_points;
  report["copied_faces"] = r.copied_faces;
  report["copied_whole_side"] = r.copied_whole_side;
  finish(o, outputs, progress, input.mesh, report, seconds, read_seconds, total.seconds());
  std::cout << o.input << ": " << r.faces << " faces, " << 100 * r.after.symmetric_edges << "% of the edges mirrored (input "
            << 100 * r.before.symmetric_edges << "%), " << seconds << " s\n";
  return 0;
}

int run_decimate(const Remesh_options& o)
{
  Stopwatch total;
  Progress progress("symmetry decimate", o.quiet, o.verbose);
  Output_files outputs;
  double read_seconds = 0, detect_seconds = 0;
  bool detected = false;
  Symmetry symmetry;
  Input_mesh input = prepare(o, outputs, progress, read_seconds, symmetry, detect_seconds, detected);
  Stopwatch watch;
  Json report = input_report("symmetry decimate", o.input, input);
  report["plane"] = plane_json(symmetry);
  report["plane_detected"] = detected;
  report["seconds_detection"] = detect_seconds;
  report["faces_before"] = num_faces(input.mesh);
  const SMS::Symmetric_connectivity c = SMS::measure_symmetric_connectivity(input.mesh, symmetry);
  report["connectivity_before"] = connectivity_json(c);
  const bool direct = !o.restore && c.paired_vertices == 1 && c.symmetric_edges == 1;
  progress.stage(direct ? "decimating symmetrically" : "symmetrizing, remeshing and decimating");
  SMS::Symmetric_connectivity after;
  std::size_t faces = 0;
  if(direct) {
    const SMS::Symmetric_decimation_result r =
      SMS::symmetric_decimation(input.mesh, symmetry, SMS::parameters::number_of_faces(o.faces));
    after = r.after, faces = r.faces;
  } else {
    const SMS::Symmetrize_options& so = o.symmetrization;
    const SMS::Symmetric_simplification_result r = SMS::symmetric_simplification(
      input.mesh, symmetry,
      SMS::parameters::number_of_faces(o.faces)
        .restore_residuals(o.restore)
        .number_of_levels(so.number_of_levels)
        .final_symmetry_weight(so.final_symmetry_weight)
        .target_symmetry_error(so.target_symmetry_error)
        .number_of_threads(o.detection.number_of_threads));
    after = r.remeshing.after, faces = r.faces;
    report["symmetry_error_before"] = r.symmetry_error_before;
    report["symmetry_error_after"] = r.symmetry_error_after;
    report["mirror_points"] = r.remeshing.mirror_points;
    report["copied_faces"] = r.remeshing.copied_faces;
    report["restore_flips"] = r.restore_flips;
    if(o.restore)
      report["copied_side"] = r.copied_side;
  }
  const double seconds = watch.seconds();
  report["remeshed"] = !direct;
  report["restored"] = o.restore;
  report["faces"] = faces;
  add_connectivity(report, after); // by the pairs: with --restore the positions are not mirrored
  finish(o, outputs, progress, input.mesh, report, seconds, read_seconds, total.seconds());
  std::cout << o.input << ": " << faces << " faces, " << 100 * after.symmetric_edges << "% of the edges mirrored"
            << (o.restore ? ", on the input's surface" : ", symmetric") << ", " << seconds << " s\n";
  return 0;
}


} // namespace

void add_symmetry_remesh_commands(CLI::App* symmetry, std::function<int()>& run)
{
  auto r = std::make_shared<Remesh_options>();
  CLI::App* remesh = symmetry->add_subcommand(
    "remesh", "Remesh so that the connectivity mirrors itself across the plane (every vertex, edge and face "
              "has a mirror image); symmetrizes the surface first when it is not symmetric.");
  add_common_options(remesh, *r, true);
  remesh->add_option("-o,--output", r->output_off, "The remeshed mesh (.off)")->required();
  remesh->add_option("--faces", r->faces, "Faces of the result (default: the input's)")->check(positive_count);
  remesh->add_flag("--copy-one-side", r->copy_one_side,
                   "Cut at the plane and copy the positive side across it instead (the simple alternative)");
  remesh->add_option("--report", r->report,
                     "JSON report: plane, symmetrized, paired_vertices, symmetric_edges, symmetric_faces "
                     "(fractions), faces, mirror_points, flips, overlaid_regions, overlay_points, copied_faces, "
                     "seconds");
  remesh->callback([r, &run]() { run = [r]() { return run_remesh(*r); }; });

  auto d = std::make_shared<Remesh_options>();
  CLI::App* decimate = symmetry->add_subcommand(
    "decimate", "Decimate keeping the connectivity symmetric (remeshing first when it is not); with --restore "
                "the result lies on the input's asymmetric surface, otherwise it is symmetric.");
  add_common_options(decimate, *d, true);
  decimate->add_option("-o,--output", d->output_off, "The decimated mesh (.off)")->required();
  decimate->add_option("--faces", d->faces, "Faces of the result (at most the input's)")
    ->required()
    ->check(positive_count);
  decimate->add_flag("--restore", d->restore, "Move the result back onto the input's surface (its asymmetries)");
  decimate->add_option("--report", d->report,
                       "JSON report: plane, faces, paired_vertices, symmetric_edges, symmetric_faces (fractions, "
                       "by the pairs), remeshed, restored, seconds");
  decimate->callback([d, &run]() { run = [d]() { return run_decimate(*d); }; });
}

} // namespace shape_analysis_cli
