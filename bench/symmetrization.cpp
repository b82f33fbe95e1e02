// Copyright (c) 2026 CGAL Global Shape Analysis contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later

// Symmetrization: time, symmetry error and distortion, beside the naive baseline that moves each
// vertex halfway to the image of its mirror point.
//
//   bench_symmetrization [--data DIR] [--meshes camel,cow,...] [--repeats 5] [--no-large]
//                        [--large-repeats 1] [--threads 0] [--several a.off,b.off] [--planes 4]
//                        [--output FILE]
//
//   - CGAL's meshes (camel, cow, triceratops, homer, head, man): the best detected plane
//     (detection timed apart), then symmetrize();
//   - a procedural blob of 1,152 vertices whose connectivity is symmetric, bent by a smooth
//     asymmetric warp (the thesis: about 4 s for a mesh of about 1,200 vertices), median time of
//     --repeats runs;
//   - man.off Loop-subdivided twice with CGAL (279,890 vertices; the thesis: 10 minutes for
//     240,000 vertices), unless --no-large;
//   - each mesh of --several: its --planes best detected planes (seed 1) symmetrized at once, as
//     detected and regularized by regularize_symmetries() (angles between the planes, error,
//     distortion, time of each).
// Symmetry error: RMS over the vertices of the distance from a vertex's mirror image to the
// surface, relative to the bounding-box diagonal. Distortion: RMS relative change of the edge
// lengths ("distortion") and of the edge vectors ("edge_vector_distortion"). Each mesh is also
// symmetrized without the isometric refinement ("no_refinement": target_symmetry_error 0), with
// the default final_symmetry_weight and with 10^4 (less asymmetry, more distortion where the two
// sides have no matching vertices). Equal-error comparisons (not on the subdivided man): the naive
// move repeated until it is as symmetric as our result ("naive_repeated_to_our_error"), and our
// result stopped at the error of one naive pass ("ours_at_naive_error"). The subdivided man's
// time is the median of --large-repeats runs (the smallest is "seconds_min").
// JSON to stdout and to FILE; progress to stderr.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Subdivision_method_3/subdivision_methods_3.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>

#include <CGAL/Surface_mesh_symmetrization/detect_reflective_symmetries.h>
#include <CGAL/Surface_mesh_symmetrization/regularize_symmetries.h>
#include <Shape_analysis_support/Procedural_symmetric_shapes.h>
#include <Shape_analysis_support/Symmetry_metrics.h>
#include <CGAL/Surface_mesh_symmetrization/symmetrize.h>
#include "symmetry_bench.h"

#include <algorithm>
#include <chrono>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

namespace {

using namespace symmetry_bench;
namespace SY = CGAL::Surface_mesh_symmetrization;
namespace SAS = CGAL::Shape_analysis_support;
typedef SY::Symmetry<Kernel> Symmetry;
typedef SAS::Symmetry_metrics<Point> Metrics;
typedef Metrics::Vector_3d Vector_3d;

double median(std::vector<double> s)
{
  std::sort(s.begin(), s.end());
  return s.empty() ? 0.0 : (s.size() % 2 ? s[s.size() / 2] : 0.5 * (s[s.size() / 2 - 1] + s[s.size() / 2]));
}

// Symmetrizes a copy of `mesh` `repeats` times about `symmetry`; the figures of the last run and
// the naive baseline's.
Json run(const std::string& name, const Mesh& mesh, const Symmetry& symmetry, std::size_t repeats,
         std::size_t threads, bool equal_error = true)
{
  std::vector<double> seconds;
  SY::Symmetrization_result<Kernel> r;
  Mesh result;
  for(std::size_t k = 0; k < repeats; ++k) {
    result = mesh;
    const auto start = std::chrono::steady_clock::now();
    r = SY::symmetrize(result, std::vector<Symmetry>{symmetry}, SY::parameters::number_of_threads(threads));
    seconds.push_back(seconds_since(start));
  }
  const Metrics metrics(mesh);
  const std::vector<Vector_3d>& input = metrics.points();
  const auto naive_start = std::chrono::steady_clock::now();
  const std::vector<Vector_3d> naive = metrics.naive_symmetrization(input, symmetry, threads);
  const double naive_seconds = seconds_since(naive_start);
  Json j = Json::object();
  j["mesh"] = name;
  j["vertices"] = num_vertices(mesh);
  j["faces"] = num_faces(mesh);
  j["seconds"] = median(seconds);
  j["seconds_min"] = *std::min_element(seconds.begin(), seconds.end());
  j["repeats"] = repeats;
  j["levels"] = Json(r.level_sizes);
  j["solves"] = r.symmetry_errors.size();
  j["symmetry_error_before"] = r.symmetry_error_before;
  j["symmetry_error_after"] = r.symmetry_error_after;
  j["distortion"] = r.distortion;
  j["edge_vector_distortion"] = metrics.edge_vector_distortion(input, Metrics::positions_of(result));
  const double naive_error = metrics.symmetry_error(naive, symmetry, threads);
  const double naive_distortion = metrics.edge_distortion(input, naive);
  Json b = Json::object();
  b["seconds"] = naive_seconds;
  b["symmetry_error_after"] = naive_error;
  b["distortion"] = naive_distortion;
  b["edge_vector_distortion"] = metrics.edge_vector_distortion(input, naive);
  j["naive_halfway"] = b;
  // Equal-error comparisons: the naive move repeated (each pass from the mirror points of the
  // last) until it is as symmetric as our result, and our result stopped at the error of one
  // naive pass.
  if(equal_error) {
    Json it = Json::object();
    std::size_t passes = 0;
    double e = naive_error;
    std::vector<Vector_3d> repeated = naive;
    for(passes = 1; passes < 100 && e > r.symmetry_error_after; ++passes) {
      repeated = metrics.naive_symmetrization(repeated, symmetry, threads);
      e = metrics.symmetry_error(repeated, symmetry, threads);
    }
    it["passes"] = passes;
    it["symmetry_error_after"] = e;
    it["distortion"] = metrics.edge_distortion(input, repeated);
    j["naive_repeated_to_our_error"] = it;
    Mesh stopped = mesh;
    const auto rs = SY::symmetrize(stopped, std::vector<Symmetry>{symmetry},
                                   SY::parameters::number_of_threads(threads).target_symmetry_error(naive_error));
    Json at = Json::object();
    at["target_symmetry_error"] = naive_error;
    at["symmetry_error_after"] = rs.symmetry_error_after;
    at["distortion"] = rs.distortion;
    j["ours_at_naive_error"] = at;
    std::cerr << "    equal error: naive repeated " << passes << " times: error " << e << ", distortion "
              << it["distortion"].dump() << "; ours at the naive error: error " << rs.symmetry_error_after
              << ", distortion " << rs.distortion << "\n";
  }
  // Without the isometric refinement (target 0), with the default and with a larger final
  // symmetry weight (10^4: less asymmetry, more distortion).
  for(const double weight : {100.0, 1e4}) {
    Mesh tight = mesh;
    const auto start = std::chrono::steady_clock::now();
    const auto rt = SY::symmetrize(
      tight, std::vector<Symmetry>{symmetry},
      SY::parameters::number_of_threads(threads).final_symmetry_weight(weight).target_symmetry_error(0.0));
    Json t = Json::object();
    t["final_symmetry_weight"] = weight;
    t["target_symmetry_error"] = 0;
    t["seconds"] = seconds_since(start);
    t["symmetry_error_after"] = rt.symmetry_error_after;
    t["distortion"] = rt.distortion;
    j[weight == 100.0 ? "no_refinement" : "no_refinement_final_weight_1e4"] = t;
    std::cerr << "    no refinement, final weight " << weight << ": error " << rt.symmetry_error_after
              << ", distortion " << rt.distortion << ", " << t["seconds"].dump() << " s\n";
  }
  std::cerr << "  " << name << ": " << num_vertices(mesh) << " vertices, " << median(seconds) << " s, error "
            << r.symmetry_error_before << " -> " << r.symmetry_error_after << " (naive "
            << naive_error << "), distortion " << r.distortion << " (naive " << naive_distortion << ")\n";
  return j;
}

Symmetry best_plane(const Mesh& m, std::size_t threads, double& seconds)
{
  const auto start = std::chrono::steady_clock::now();
  std::vector<Symmetry> found;
  SY::detect_reflective_symmetries(m, std::back_inserter(found),
                                   SY::parameters::maximum_number_of_symmetries(1).number_of_threads(threads));
  seconds = seconds_since(start);
  if(found.empty())
    throw std::runtime_error("no plane found");
  return found.front();
}

// Several detected planes symmetrized at once, as detected and regularized (regularize_symmetries()):
// the angles between them, and symmetrize()'s error, distortion and time for each set.
Json several_planes(const std::string& path, std::size_t planes, std::size_t threads)
{
  Mesh m;
  if(!CGAL::IO::read_polygon_mesh(path, m) || faces(m).empty())
    throw std::runtime_error("cannot read " + path);
  std::vector<Symmetry> found;
  SY::detect_reflective_symmetries(m, std::back_inserter(found), SY::parameters::maximum_number_of_symmetries(planes)
                                                                   .random_seed(1)
                                                                   .number_of_threads(threads));
  const std::vector<Symmetry> regular = SY::regularize_symmetries(m, found);
  const auto angles = [](const std::vector<Symmetry>& set) {
    Json a = Json::array();
    for(std::size_t i = 0; i < set.size(); ++i)
      for(std::size_t j = i + 1; j < set.size(); ++j) {
        const Kernel::Vector_3 n = set[i].plane.orthogonal_vector(), k = set[j].plane.orthogonal_vector();
        const double c = std::abs(n * k) / std::sqrt(n.squared_length() * k.squared_length());
        a.push_back(std::acos((std::min)(1.0, c)) * 180 / 3.14159265358979323846);
      }
    return a;
  };
  Json j;
  j["mesh"] = path;
  j["vertices"] = num_vertices(m);
  for(const auto& [name, set] : {std::make_pair("detected", found), std::make_pair("regularized", regular)}) {
    Mesh copy = m;
    const auto start = std::chrono::steady_clock::now();
    const auto r = SY::symmetrize(copy, set, SY::parameters::number_of_threads(threads));
    Json k;
    k["planes"] = set.size();
    k["angles_degrees"] = angles(set);
    k["seconds"] = seconds_since(start);
    k["symmetry_error_before"] = r.symmetry_error_before;
    k["symmetry_error_after"] = r.symmetry_error_after;
    k["distortion"] = r.distortion;
    j[name] = k;
    std::cerr << path << " " << name << ": error " << r.symmetry_error_after << ", distortion " << r.distortion << "\n";
  }
  return j;
}

} // namespace

int main(int argc, char** argv)
{
  std::string data = SHAPE_ANALYSIS_DATA_DIR, output;
  std::vector<std::string> names = {"camel", "cow", "triceratops", "homer", "head", "man"};
  std::vector<std::string> several;
  std::size_t repeats = 5, repeats_large = 1, threads = 0, planes = 4;
  bool large = true;
  for(Arguments args(argc, argv); args.next();) {
    const std::string a = args.flag();
    if(a == "--data")
      data = args.value();
    else if(a == "--meshes")
      names = split(args.value());
    else if(a == "--repeats")
      repeats = std::max<std::size_t>(1, std::stoul(args.value()));
    else if(a == "--large-repeats")
      repeats_large = std::max<std::size_t>(1, std::stoul(args.value()));
    else if(a == "--threads")
      threads = std::stoul(args.value());
    else if(a == "--no-large")
      large = false;
    else if(a == "--several")
      several = split(args.value());
    else if(a == "--planes")
      planes = std::max<std::size_t>(2, std::stoul(args.value()));
    else if(a == "--output")
      output = args.value();
    else {
      std::cerr << "usage: bench_symmetrization [--data DIR] [--meshes a,b] [--repeats N] [--no-large] "
                   "[--large-repeats N] [--threads N] [--several a.off,b.off] [--planes N] [--output FILE]\n";
      return 2;
    }
  }
  Json result = Json::object();
  result["benchmark"] = "symmetrization";
  result["threads"] = threads;

  // The procedural blob: about 1,200 vertices, symmetric connectivity, warped.
  {
    std::cerr << "procedural blob (1,152 vertices), warp 0.005:\n";
    SAS::Procedural_mesh blob = SAS::symmetric_blob(24, 50);
    for(auto& p : blob.points)
      p = SAS::asymmetric_warp(p, 0.005);
    Mesh m;
    std::vector<Mesh::Vertex_index> v;
    for(const auto& p : blob.points)
      v.push_back(m.add_vertex(Point(p[0], p[1], p[2])));
    for(const auto& t : blob.triangles)
      m.add_face(v[t[0]], v[t[1]], v[t[2]]);
    Json j = run("warped_blob_1152", m, SY::reflective_symmetry<Kernel>(Kernel::Plane_3(0, 1, 0, 0)), repeats, threads);
    j["thesis_seconds"] = 4.0;
    j["target_seconds"] = 0.2;
    result["small"] = j;
  }

  Json meshes = Json::array();
  for(const std::string& name : names) {
    Mesh m;
    const std::string path = data + "/" + name + ".off";
    if(!CGAL::IO::read_polygon_mesh(path, m) || faces(m).empty()) {
      std::cerr << "cannot read " << path << "\n";
      return 1;
    }
    double detection = 0;
    const Symmetry s = best_plane(m, threads, detection);
    Json j = run(name, m, s, 1, threads);
    j["detection_seconds"] = detection;
    meshes.push_back(j);
  }
  result["meshes"] = meshes;

  Json sets = Json::array();
  for(const std::string& path : several)
    sets.push_back(several_planes(path, planes, threads));
  result["several_planes"] = sets;

  if(large) {
    Mesh m;
    const std::string path = data + "/man.off";
    if(!CGAL::IO::read_polygon_mesh(path, m)) {
      std::cerr << "cannot read " << path << "\n";
      return 1;
    }
    const auto start = std::chrono::steady_clock::now();
    CGAL::Subdivision_method_3::Loop_subdivision(m, CGAL::parameters::number_of_iterations(2));
    std::cerr << "man.off Loop-subdivided twice (" << num_vertices(m) << " vertices, " << seconds_since(start) << " s):\n";
    double detection = 0;
    const Symmetry s = best_plane(m, threads, detection);
    Json j = run("man_loop2", m, s, repeats_large, threads, false);
    j["detection_seconds"] = detection;
    j["thesis_seconds"] = 600.0;
    j["thesis_vertices"] = 240000;
    j["target_seconds"] = 30.0;
    result["large"] = j;
  }
  write_report(result, output);
  return 0;
}
