// Copyright (c) 2026 CGAL Global Shape Analysis contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Symmetric remeshing, decimation and simplification (issue 24), per mesh: the best detected
// plane (score, support fraction), symmetrize() (seconds), then
//   - symmetric_remeshing() of the symmetrized mesh to its face count: seconds, fractions of the
//     vertices, edges and faces with mirror partners (measured again from positions), faces, the
//     two-sided Hausdorff distance (support's mesh_distance, fixed seed; relative to the input's
//     bounding-box diagonal) to the symmetrized mesh and to the input, the mean normal deviation
//     (degrees) to the symmetrized mesh, and the same for the copy of one side (copy_one_side:
//     the positive side; copy_other_side: the negative one, with the plane reversed);
//   - symmetric_decimation() of the remeshed mesh to a fifth of the faces: seconds, fractions, faces;
//   - symmetric_simplification() of the input to a fifth with the residuals restored, beside CGAL's
//     Garland-Heckbert edge collapse (GarlandHeckbert_plane_policies) to the same face count:
//     seconds, Hausdorff distance and mean normal deviation to the input, and the distances' ratio.
// Meshes: CGAL's (--meshes, default cow, camel, armadillo) and the PSB subset in
// ../shared/data/psb (--psb DIR; --classes, --ids select; skipped when absent).
//   bench_symmetric_remeshing [--data DIR] [--meshes a,b] [--psb DIR] [--classes c,d] [--ids 1-8]
//       [--no-psb] [--no-simplification] [--threads N] [--target-error E] [--output FILE]
// (--target-error: symmetrize()'s target_symmetry_error, its default unless given)

#include "psb_io.h"

#include <CGAL/Surface_mesh_symmetrization/detect_reflective_symmetries.h>
#include <CGAL/Surface_mesh_symmetrization/symmetric_simplification.h>

#include <CGAL/Surface_mesh_simplification/edge_collapse.h>
#include <CGAL/Surface_mesh_simplification/Policies/Edge_collapse/Count_stop_predicate.h>
#include <CGAL/Surface_mesh_simplification/Policies/Edge_collapse/GarlandHeckbert_plane_policies.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>

#include <Shape_analysis_support/Mesh_distance.h>

#include <algorithm>
#include <chrono>
#include <iostream>
#include <string>
#include <vector>

namespace {

namespace SY = CGAL::Surface_mesh_symmetrization;
namespace SMS = CGAL::Surface_mesh_simplification;
using psb::Kernel;
using psb::Mesh;
typedef SY::Symmetry<Kernel> Symmetry;
using bench_util::seconds_since;

double diagonal_of(const Mesh& m)
{
  const CGAL::Bbox_3 b = CGAL::bbox_3(m.points().begin(), m.points().end());
  return std::sqrt(CGAL::square(b.xmax() - b.xmin()) + CGAL::square(b.ymax() - b.ymin()) +
                   CGAL::square(b.zmax() - b.zmin()));
}

SAS::Json connectivity(const Mesh& m, const Symmetry& s)
{
  const SY::Symmetric_connectivity c = SY::measure_symmetric_connectivity(m, s);
  SAS::Json j = SAS::Json::object();
  j["paired_vertices"] = c.paired_vertices;
  j["symmetric_edges"] = c.symmetric_edges;
  j["symmetric_faces"] = c.symmetric_faces;
  return j;
}

// Remeshing (or the copy of one side) of the symmetrized mesh.
SAS::Json remesh(const Mesh& symmetrized, const Mesh& input, const Symmetry& s, double diagonal, bool copy)
{
  Mesh m = symmetrized;
  const auto start = std::chrono::steady_clock::now();
  const SY::Symmetric_remeshing_result r = SY::symmetric_remeshing(m, s, SY::parameters::copy_one_side(copy));
  SAS::Json j = connectivity(m, s);
  j["seconds"] = seconds_since(start);
  j["faces"] = r.faces;
  j["meta_mesh_faces"] = r.meta_mesh_faces;
  j["mirror_points"] = r.mirror_points;
  j["flips"] = r.flips;
  j["overlaid_regions"] = r.overlaid_regions;
  j["overlay_points"] = r.overlay_points;
  j["copied_faces"] = r.copied_faces;
  j["copied_whole_side"] = r.copied_whole_side;
  const SAS::Mesh_distance to_symmetrized = SAS::mesh_distance(m, symmetrized, diagonal);
  j["hausdorff_to_symmetrized"] = to_symmetrized.hausdorff;
  j["normal_deviation_to_symmetrized"] = to_symmetrized.normal_deviation;
  j["hausdorff_to_input"] = SAS::mesh_distance(m, input, diagonal).hausdorff;
  if(!copy) { // then a fifth of the faces
    const std::size_t target = r.faces_before / 5;
    const auto d_start = std::chrono::steady_clock::now();
    const SY::Symmetric_decimation_result d = SY::symmetric_decimation(m, s, SY::parameters::number_of_faces(target));
    SAS::Json dj = connectivity(m, s);
    dj["seconds"] = seconds_since(d_start);
    dj["faces"] = d.faces;
    dj["target_faces"] = target;
    j["decimation_to_a_fifth"] = dj;
  }
  return j;
}

// Symmetric simplification with restore beside CGAL's Garland-Heckbert collapse, to a fifth.
SAS::Json simplify(const Mesh& input, const Symmetry& s, double diagonal, std::size_t threads)
{
  const std::size_t target = num_faces(input) / 5;
  Mesh ours = input;
  auto start = std::chrono::steady_clock::now();
  const SY::Symmetric_simplification_result r =
    SY::symmetric_simplification(ours, s, SY::parameters::number_of_faces(target).number_of_threads(threads));
  SAS::Json j = SAS::Json::object();
  j["target_faces"] = target;
  j["seconds"] = seconds_since(start);
  j["faces"] = r.faces;
  j["symmetric_edges_by_pairs"] = r.remeshing.after.symmetric_edges;
  const SAS::Mesh_distance d = SAS::mesh_distance(ours, input, diagonal);
  j["hausdorff"] = d.hausdorff;
  j["normal_deviation"] = d.normal_deviation;
  Mesh gh = input;
  start = std::chrono::steady_clock::now();
  SMS::GarlandHeckbert_plane_policies<Mesh, Kernel> policies(gh);
  // (CGAL 5.5 stops on edges: a closed mesh has 1.5 edges per face.)
  SMS::edge_collapse(gh, SMS::Count_stop_predicate<Mesh>(target * 3 / 2),
                     CGAL::parameters::get_cost(policies.get_cost()).get_placement(policies.get_placement()));
  gh.collect_garbage();
  j["cgal_seconds"] = seconds_since(start);
  j["cgal_faces"] = num_faces(gh);
  const SAS::Mesh_distance dg = SAS::mesh_distance(gh, input, diagonal);
  j["cgal_hausdorff"] = dg.hausdorff;
  j["cgal_normal_deviation"] = dg.normal_deviation;
  j["hausdorff_ratio"] = j["hausdorff"].get<double>() / j["cgal_hausdorff"].get<double>();
  return j;
}

SAS::Json run(const std::string& name, const Mesh& input, bool simplification, std::size_t threads,
              double target_error)
{
  SAS::Json j = SAS::Json::object();
  j["mesh"] = name;
  j["faces"] = num_faces(input);
  std::vector<Symmetry> found;
  auto start = std::chrono::steady_clock::now();
  SY::detect_reflective_symmetries(input, std::back_inserter(found),
                                   SY::parameters::maximum_number_of_symmetries(1).number_of_threads(threads));
  j["detection_seconds"] = seconds_since(start);
  if(found.empty()) {
    j["plane"] = SAS::Json();
    return j;
  }
  const Symmetry& s = found.front();
  j["score"] = s.score;
  j["support_fraction"] = s.support_fraction;
  const double diagonal = diagonal_of(input);
  Mesh symmetrized = input;
  start = std::chrono::steady_clock::now();
  const auto sr = SY::symmetrize(symmetrized, std::vector<Symmetry>{s},
                                 SY::parameters::number_of_threads(threads).target_symmetry_error(target_error));
  j["symmetrize_seconds"] = seconds_since(start);
  j["symmetry_error_after"] = sr.symmetry_error_after;
  j["symmetrized_hausdorff_to_input"] = SAS::mesh_distance(symmetrized, input, diagonal).hausdorff;
  j["connectivity_after_symmetrize"] = connectivity(symmetrized, s);
  try {
    j["remeshing"] = remesh(symmetrized, input, s, diagonal, false);
    j["copy_one_side"] = remesh(symmetrized, input, s, diagonal, true);
    Symmetry reversed = s; // the same reflection, the other side copied
    reversed.plane = s.plane.opposite();
    j["copy_other_side"] = remesh(symmetrized, input, reversed, diagonal, true);
    if(simplification)
      j["simplification"] = simplify(input, s, diagonal, threads);
  } catch(const CGAL::Shape_analysis::Bad_input& e) {
    j["error"] = e.what();
  }
  std::cerr << name << ": " << SAS::to_text(j) << "\n";
  return j;
}

} // namespace

int main(int argc, char** argv)
{
  std::string data = SHAPE_ANALYSIS_DATA_DIR, psb_dir = SHAPE_ANALYSIS_PSB_DIR, output;
  std::vector<std::string> names = {"cow", "camel", "armadillo"};
  std::set<std::string> classes;
  std::set<int> ids;
  bool with_psb = true, simplification = true;
  std::size_t threads = 0;
  double target_error = SY::Symmetrize_options().target_symmetry_error;
  for(int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    const bool has_value = i + 1 < argc;
    if(a == "--data" && has_value)
      data = argv[++i];
    else if(a == "--meshes" && has_value)
      names = bench_util::split(argv[++i]);
    else if(a == "--psb" && has_value)
      psb_dir = argv[++i];
    else if(a == "--classes" && has_value)
      for(const std::string& c : bench_util::split(argv[++i]))
        classes.insert(psb::lower(c));
    else if(a == "--ids" && has_value && psb::parse_ids(argv[i + 1], ids))
      ++i;
    else if(a == "--no-psb")
      with_psb = false;
    else if(a == "--no-simplification")
      simplification = false;
    else if(a == "--threads" && has_value)
      threads = std::stoul(argv[++i]);
    else if(a == "--target-error" && has_value)
      target_error = std::stod(argv[++i]);
    else if(a == "--output" && has_value)
      output = argv[++i];
    else {
      std::cerr << "usage: bench_symmetric_remeshing [--data DIR] [--meshes a,b] [--psb DIR] [--classes c,d] "
                   "[--ids 1-8] [--no-psb] [--no-simplification] [--threads N] [--target-error E] "
                   "[--output FILE]\n";
      return 2;
    }
  }
  SAS::Json report = SAS::Json::object();
  report["benchmark"] = "symmetric_remeshing";
  report["threads"] = threads;
  report["target_symmetry_error"] = target_error;
  SAS::Json cgal = SAS::Json::array();
  for(const std::string& name : names) {
    Mesh m;
    if(!CGAL::IO::read_polygon_mesh(data + "/" + name + ".off", m) || faces(m).empty()) {
      std::cerr << "cannot read " << data << "/" << name << ".off\n";
      return 1;
    }
    cgal.push_back(run(name, m, simplification, threads, target_error));
  }
  report["cgal_meshes"] = cgal;
  SAS::Json psb_meshes = SAS::Json::array();
  if(with_psb && std::filesystem::is_directory(psb_dir))
    for(const psb::Mesh_entry& e : psb::select_meshes(psb_dir, classes, ids)) {
      Mesh m;
      std::string note;
      if(!psb::read_mesh(e.off, m, note))
        continue;
      SAS::Json j = run(std::to_string(e.id), m, simplification, threads, target_error);
      j["class"] = e.mesh_class;
      psb_meshes.push_back(j);
    }
  report["psb_meshes"] = psb_meshes;
  std::cout << SAS::to_text(report) << std::endl;
  psb::write_output(output, report);
  return 0;
}
