// Copyright (c) 2026 CGAL Global Shape Analysis contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later

// Running time of hierarchical_segmentation, side by side with CGAL's SDF segmentation (default
// parameters) measured in the same process.
//
//   bench_hierarchical_segmentation_speed [mesh.off] [--segments 10] [--repeats 10]
//                                         [--sdf-repeats 3] [--armadillo FILE] [--no-sdf]
//                                         [--output FILE]
//
// On the mesh (default: CGAL's camel.off, 19,536 faces): ours R times (default and with
// boundary_refinement(false)), SDF (sdf_values + segmentation_from_sdf_values) R' times; on
// armadillo.off (52,000 faces): ours R times. Each timing is the public call alone (building the
// dual graph included, reading the file excluded). Reports min and median seconds and the speed
// ratio SDF / ours. JSON to stdout and to FILE; progress to stderr.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/mesh_segmentation.h>
#include <CGAL/version.h>

#include <CGAL/Consistent_segmentation/hierarchical_segmentation.h>
#include <Shape_analysis_support/Json.h>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iostream>
#include <string>
#include <thread>
#include <vector>

namespace {

typedef CGAL::Exact_predicates_inexact_constructions_kernel Kernel;
typedef CGAL::Surface_mesh<Kernel::Point_3> Mesh;
typedef Mesh::Face_index Face;
namespace SAS = CGAL::Shape_analysis_support;
typedef SAS::Json Json;
namespace CS = CGAL::Consistent_segmentation;

struct Timings
{
  std::vector<double> seconds;
  std::size_t segments = 0;

  double min() const { return *std::min_element(seconds.begin(), seconds.end()); }
  double median() const
  {
    std::vector<double> s(seconds);
    std::sort(s.begin(), s.end());
    const std::size_t n = s.size();
    return n % 2 ? s[n / 2] : 0.5 * (s[n / 2 - 1] + s[n / 2]);
  }
  Json json() const
  {
    Json j = Json::object();
    j["runs"] = seconds.size();
    j["min_seconds"] = min();
    j["median_seconds"] = median();
    j["seconds"] = seconds;
    j["segments"] = segments;
    return j;
  }
};

// Runs `run` (which returns a segment count) `repeats` times, timing each call.
Timings time_runs(const std::string& what, std::size_t repeats,
                  const std::function<std::size_t()>& run)
{
  Timings t;
  for(std::size_t r = 0; r < repeats; ++r) {
    const auto start = std::chrono::steady_clock::now();
    t.segments = run();
    t.seconds.push_back(
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
    std::cerr << "  " << what << " run " << (r + 1) << "/" << repeats << ": " << t.seconds.back()
              << " s, " << t.segments << " segments" << std::endl;
  }
  return t;
}

std::size_t number_of_labels(const Mesh& mesh, Mesh::Property_map<Face, std::size_t> segment)
{
  std::vector<std::size_t> labels;
  labels.reserve(mesh.number_of_faces());
  for(Face f : faces(mesh))
    labels.push_back(segment[f]);
  std::sort(labels.begin(), labels.end());
  return static_cast<std::size_t>(std::unique(labels.begin(), labels.end()) - labels.begin());
}

Timings time_ours(Mesh& mesh, std::size_t k, bool refinement, std::size_t repeats,
                  const std::string& what)
{
  auto segment = mesh.add_property_map<Face, std::size_t>("f:ours", 0).first;
  Timings t = time_runs(what, repeats, [&]() {
    return CS::hierarchical_segmentation(
      mesh, segment, CS::parameters::number_of_segments(k).boundary_refinement(refinement));
  });
  t.segments = number_of_labels(mesh, segment);
  mesh.remove_property_map(segment);
  return t;
}

Timings time_sdf(Mesh& mesh, std::size_t repeats, const std::string& what)
{
  auto sdf = mesh.add_property_map<Face, double>("f:sdf", 0.0).first;
  auto segment = mesh.add_property_map<Face, std::size_t>("f:sdf_segment", 0).first;
  Timings t = time_runs(what, repeats, [&]() {
    CGAL::sdf_values(mesh, sdf);
    return CGAL::segmentation_from_sdf_values(mesh, sdf, segment);
  });
  t.segments = number_of_labels(mesh, segment);
  mesh.remove_property_map(segment);
  mesh.remove_property_map(sdf);
  return t;
}

bool read_mesh(const std::string& file, Mesh& mesh)
{
  return CGAL::IO::read_polygon_mesh(file, mesh) && !faces(mesh).empty();
}

void usage(const char* name)
{
  std::cerr << "usage: " << name
            << " [mesh.off] [--segments 10] [--repeats 10] [--sdf-repeats 3]"
               " [--armadillo FILE] [--no-sdf] [--output FILE]\n";
}

} // namespace

int main(int argc, char** argv)
{
  std::string mesh_file = std::string(SHAPE_ANALYSIS_DATA_DIR) + "/camel.off";
  std::string armadillo_file = std::string(SHAPE_ANALYSIS_DATA_DIR) + "/armadillo.off";
  std::size_t k = 10, repeats = 10, sdf_repeats = 3;
  bool with_sdf = true;
  std::string output;
  for(int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    auto value = [&]() -> std::string {
      if(i + 1 >= argc) {
        usage(argv[0]);
        std::exit(EXIT_FAILURE);
      }
      return argv[++i];
    };
    auto count = [&]() -> std::size_t {
      const std::string v = value();
      char* end = nullptr;
      const unsigned long c = std::strtoul(v.c_str(), &end, 10);
      if(end == v.c_str() || *end != '\0' || c == 0) {
        std::cerr << arg << " needs a positive integer, not " << v << '\n';
        std::exit(EXIT_FAILURE);
      }
      return c;
    };
    if(arg == "--segments")
      k = count();
    else if(arg == "--repeats")
      repeats = count();
    else if(arg == "--sdf-repeats")
      sdf_repeats = count();
    else if(arg == "--armadillo")
      armadillo_file = value();
    else if(arg == "--no-sdf")
      with_sdf = false;
    else if(arg == "--output")
      output = value();
    else if(arg == "--help" || arg == "-h") {
      usage(argv[0]);
      return EXIT_SUCCESS;
    } else if(!arg.empty() && arg[0] == '-') {
      std::cerr << "unknown argument " << arg << '\n';
      usage(argv[0]);
      return EXIT_FAILURE;
    } else
      mesh_file = arg;
  }

  Json report = Json::object();
  report["benchmark"] = "hierarchical_segmentation_speed";
  report["cgal_version"] = CGAL_VERSION_STR;
  report["hardware_threads"] = static_cast<unsigned long>(std::thread::hardware_concurrency());
  report["number_of_segments"] = k;
  report["timing"] = "steady_clock around the public call (dual graph built inside; file reading "
                     "excluded), sequential";

  try {
    Mesh mesh;
    if(!read_mesh(mesh_file, mesh)) {
      std::cerr << "cannot read " << mesh_file << '\n';
      return EXIT_FAILURE;
    }
    std::cerr << mesh_file << ": " << mesh.number_of_faces() << " faces\n";
    Json main_mesh = Json::object();
    main_mesh["file"] = mesh_file;
    main_mesh["faces"] = mesh.number_of_faces();
    const Timings ours = time_ours(mesh, k, true, repeats, "ours");
    main_mesh["ours"] = ours.json();
    const Timings ours_plain = time_ours(mesh, k, false, repeats, "ours boundary_refinement(false)");
    main_mesh["ours_without_boundary_refinement"] = ours_plain.json();
    main_mesh["boundary_refinement_cost_seconds"] = ours.median() - ours_plain.median();
    if(with_sdf) {
      const Timings sdf = time_sdf(mesh, sdf_repeats, "sdf");
      Json j = sdf.json();
      j["parameters"] = "CGAL::sdf_values + CGAL::segmentation_from_sdf_values, defaults "
                        "(5 clusters, smoothing lambda 0.26)";
      main_mesh["sdf"] = j;
      main_mesh["speed_ratio_sdf_over_ours_min"] = sdf.min() / ours.min();
      main_mesh["speed_ratio_sdf_over_ours_median"] = sdf.median() / ours.median();
      Json targets = Json::object();
      targets["ours_median_seconds_at_most"] = 0.15;
      targets["ours_median_met"] = ours.median() <= 0.15;
      targets["speed_ratio_at_least"] = 20.0;
      targets["speed_ratio_median_met"] = sdf.median() / ours.median() >= 20.0;
      main_mesh["targets"] = targets;
    }
    report["mesh"] = main_mesh;

    Mesh armadillo;
    if(!armadillo_file.empty() && read_mesh(armadillo_file, armadillo)) {
      std::cerr << armadillo_file << ": " << armadillo.number_of_faces() << " faces\n";
      Json a = Json::object();
      a["file"] = armadillo_file;
      a["faces"] = armadillo.number_of_faces();
      const Timings t = time_ours(armadillo, k, true, repeats, "armadillo ours");
      a["ours"] = t.json();
      const Timings t_plain =
        time_ours(armadillo, k, false, repeats, "armadillo ours boundary_refinement(false)");
      a["ours_without_boundary_refinement"] = t_plain.json();
      a["boundary_refinement_cost_seconds"] = t.median() - t_plain.median();
      report["armadillo"] = a;
    } else
      report["armadillo"] = Json("skipped: cannot read " + armadillo_file);
  } catch(const std::exception& e) {
    std::cerr << "error: " << e.what() << '\n';
    return EXIT_FAILURE;
  }

  const std::string text = SAS::to_text(report);
  std::cout << text << '\n';
  if(!output.empty()) {
    std::ofstream out(output);
    out << text << '\n';
    if(!out) {
      std::cerr << "cannot write " << output << '\n';
      return EXIT_FAILURE;
    }
  }
  return EXIT_SUCCESS;
}
