// Copyright (c) 2026 CGAL Global Shape Analysis contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later

// Rand Index error of hierarchical_segmentation on the Princeton Segmentation Benchmark subset,
// side by side with CGAL's SDF segmentation (default parameters) run on the same meshes in the
// same process.
//
//   bench_hierarchical_segmentation_psb [--no-sdf] [--segments auto] [--classes Human,Cup,...]
//                                       [--ids 1,2,21-28] [--psb DIR] [--output FILE]
//
// Per mesh: K = the most frequent segment count of its human segmentations; ours gets K segments
// (with --segments auto: number_of_segments 0, the count chosen by the function),
// SDF its defaults (5 clusters, smoothing lambda 0.26). Times exclude file reading. Scores are
// averaged as the benchmark does: over the human segmentations of a mesh, then over the meshes of
// a class, then over classes. Runs sequentially so that timings are clean. JSON goes to stdout
// (and to FILE, rewritten after every mesh so that a long run can be watched); progress to stderr.

#include "psb_io.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/mesh_segmentation.h>

#include <CGAL/Consistent_segmentation/hierarchical_segmentation.h>
#include <Shape_analysis_support/Json.h>

#include <algorithm>
#include <cctype>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace {

using psb::Mesh;
using psb::lower;
using psb::parse_ids;
using psb::read_mesh;
using psb::split;
using psb::write_output;
typedef Mesh::Face_index Face;
namespace SAS = CGAL::Shape_analysis_support;
typedef SAS::Json Json;
namespace CS = CGAL::Consistent_segmentation;
namespace fs = std::filesystem;

using bench_util::seconds_since;

struct Method_result
{
  bool ok = false;
  std::string error;
  double seconds = 0;
  double rand_index_error = 0;
  std::size_t segments = 0;

  Json json() const
  {
    Json j = Json::object();
    if(!ok) {
      j["error"] = error;
      return j;
    }
    j["seconds"] = seconds;
    j["rand_index_error"] = rand_index_error;
    j["segments"] = segments;
    return j;
  }
};

// Mean of a method's figures over a set of meshes (only those where it succeeded).
struct Accumulator
{
  double rand_index_error = 0;
  double seconds = 0;
  double segments = 0;
  std::size_t count = 0;
  std::size_t failures = 0;

  void add(const Method_result& r)
  {
    if(!r.ok) {
      ++failures;
      return;
    }
    rand_index_error += r.rand_index_error;
    seconds += r.seconds;
    segments += double(r.segments);
    ++count;
  }

  Json json() const
  {
    Json j = Json::object();
    if(count > 0) {
      j["rand_index_error"] = rand_index_error / double(count);
      j["seconds"] = seconds / double(count);
      j["segments"] = segments / double(count);
    } else {
      j["rand_index_error"] = nullptr;
    }
    j["meshes"] = count;
    j["failures"] = failures;
    return j;
  }
};

void usage(const char* name)
{
  std::cerr << "usage: " << name
            << " [--no-sdf] [--segments auto] [--classes Human,Cup,...] [--ids 1,2,21-28] [--psb DIR]"
               " [--output FILE]\n";
}

} // namespace

int main(int argc, char** argv)
{
  bool with_sdf = true, automatic = false;
  std::set<std::string> classes; // lower case
  std::set<int> ids;
  std::string output;
  fs::path psb_dir = SHAPE_ANALYSIS_PSB_DIR;
  for(int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    auto value = [&]() -> std::string {
      if(i + 1 >= argc) {
        usage(argv[0]);
        std::exit(EXIT_FAILURE);
      }
      return argv[++i];
    };
    if(arg == "--no-sdf")
      with_sdf = false;
    else if(arg == "--segments") {
      if(value() != "auto") {
        usage(argv[0]);
        return EXIT_FAILURE;
      }
      automatic = true;
    }
    else if(arg == "--classes")
      for(const std::string& c : split(value()))
        classes.insert(lower(c));
    else if(arg == "--ids") {
      if(!parse_ids(value(), ids)) {
        usage(argv[0]);
        return EXIT_FAILURE;
      }
    } else if(arg == "--output")
      output = value();
    else if(arg == "--psb")
      psb_dir = value();
    else if(arg == "--help" || arg == "-h") {
      usage(argv[0]);
      return EXIT_SUCCESS;
    } else {
      std::cerr << "unknown argument " << arg << '\n';
      usage(argv[0]);
      return EXIT_FAILURE;
    }
  }

  Json report = Json::object();
  report["benchmark"] = "hierarchical_segmentation_psb";
  report["psb_dir"] = psb_dir.string();
  report["metric"] = "Rand Index error (1 - RI), mean over human segmentations, then meshes of a "
                     "class, then classes";
  report["ours"] = std::string("CGAL::Consistent_segmentation::hierarchical_segmentation, ") +
                   (automatic ? "number_of_segments = 0 (chosen by the function)"
                              : "number_of_segments = most frequent human segment count") +
                   ", other parameters default";
  report["sdf"] = with_sdf ? Json("CGAL::sdf_values + CGAL::segmentation_from_sdf_values, "
                                  "default parameters (5 clusters, smoothing lambda 0.26)")
                           : Json("skipped (--no-sdf)");

  std::vector<psb::Mesh_entry> meshes = psb::select_meshes(psb_dir, classes, ids);
  if(meshes.empty()) {
    report["skipped"] = "no PSB mesh with segmentations matches the selection in " + psb_dir.string();
    std::cout << SAS::to_text(report) << '\n';
    write_output(output, report);
    return EXIT_SUCCESS;
  }

  struct Row
  {
    std::string mesh_class;
    Method_result ours, sdf;
  };
  std::vector<Row> rows;
  std::vector<std::string> class_order;
  Json per_mesh = Json::array();
  std::size_t total_faces = 0;
  double total_ours = 0, total_sdf = 0;
  std::size_t ours_better = 0, sdf_better = 0, compared = 0;

  auto summarize = [&](bool complete) {
    std::map<std::string, std::pair<Accumulator, Accumulator>> by_class;
    std::map<std::string, std::size_t> class_meshes;
    Accumulator all_ours, all_sdf;
    for(const Row& r : rows) {
      by_class[r.mesh_class].first.add(r.ours);
      ++class_meshes[r.mesh_class];
      all_ours.add(r.ours);
      if(with_sdf) {
        by_class[r.mesh_class].second.add(r.sdf);
        all_sdf.add(r.sdf);
      }
    }
    Json per_class = Json::object();
    double sum_ours = 0, sum_sdf = 0;
    std::size_t n_ours = 0, n_sdf = 0;
    for(const std::string& c : class_order) {
      const auto& acc = by_class[c];
      Json j = Json::object();
      j["meshes"] = class_meshes[c];
      j["ours"] = acc.first.json();
      if(acc.first.count > 0) {
        sum_ours += acc.first.rand_index_error / double(acc.first.count);
        ++n_ours;
      }
      if(with_sdf) {
        j["sdf"] = acc.second.json();
        if(acc.second.count > 0) {
          sum_sdf += acc.second.rand_index_error / double(acc.second.count);
          ++n_sdf;
        }
      }
      per_class[c] = j;
    }
    Json overall = Json::object();
    overall["classes"] = class_order.size();
    overall["ours_rand_index_error"] = n_ours > 0 ? Json(sum_ours / double(n_ours)) : Json();
    if(with_sdf)
      overall["sdf_rand_index_error"] = n_sdf > 0 ? Json(sum_sdf / double(n_sdf)) : Json();
    overall["ours_mean_over_meshes"] = all_ours.json();
    if(with_sdf)
      overall["sdf_mean_over_meshes"] = all_sdf.json();

    Json totals = Json::object();
    totals["meshes"] = rows.size();
    totals["faces"] = total_faces;
    totals["ours_seconds"] = total_ours;
    totals["ours_failures"] = all_ours.failures;
    if(with_sdf) {
      totals["sdf_seconds"] = total_sdf;
      totals["sdf_failures"] = all_sdf.failures;
      totals["speed_ratio_sdf_over_ours"] = total_ours > 0 ? Json(total_sdf / total_ours) : Json();
      totals["meshes_compared"] = compared;
      totals["meshes_ours_lower_error"] = ours_better;
      totals["meshes_sdf_lower_error"] = sdf_better;
    }

    Json out = report;
    out["complete"] = complete;
    out["per_mesh"] = per_mesh;
    out["per_class"] = per_class;
    out["overall"] = overall;
    out["totals"] = totals;
    return out;
  };

  std::size_t index = 0;
  for(const psb::Mesh_entry& entry : meshes) {
    ++index;
    Row row;
    row.mesh_class = entry.mesh_class;
    if(std::find(class_order.begin(), class_order.end(), entry.mesh_class) == class_order.end())
      class_order.push_back(entry.mesh_class);
    const std::size_t k = psb::mode_segment_count(entry);

    Json j = Json::object();
    j["id"] = entry.id;
    j["class"] = entry.mesh_class;

    Mesh mesh;
    std::string note;
    std::string failure;
    if(!read_mesh(entry.off, mesh, note))
      failure = "cannot read " + entry.off.string();
    else if(mesh.number_of_faces() != entry.human.front().size())
      failure = "the mesh has " + std::to_string(mesh.number_of_faces()) +
                " faces, its segmentations " + std::to_string(entry.human.front().size());
    const std::size_t n = mesh.number_of_faces();
    j["faces"] = n;
    j["k"] = k;
    j["human_segmentations"] = entry.human.size();
    if(!note.empty())
      j["note"] = note;
    if(!failure.empty()) {
      row.ours.error = row.sdf.error = failure;
      std::cerr << "[" << index << "/" << meshes.size() << "] " << entry.id << ": " << failure
                << '\n';
    } else {
      total_faces += n;
      std::vector<std::size_t> labels(n, 0);

      // Ours.
      {
        auto segment = mesh.add_property_map<Face, std::size_t>("f:ours", 0).first;
        try {
          const auto start = std::chrono::steady_clock::now();
          row.ours.segments =
            CS::hierarchical_segmentation(mesh, segment, CS::parameters::number_of_segments(automatic ? 0 : k));
          row.ours.seconds = seconds_since(start);
          for(Face f : faces(mesh))
            labels[f.idx()] = segment[f];
          row.ours.rand_index_error = psb::mean_rand_index_error(entry, labels);
          row.ours.segments = psb::number_of_labels(labels);
          row.ours.ok = true;
          total_ours += row.ours.seconds;
        } catch(const std::exception& e) {
          row.ours.error = e.what();
        }
        mesh.remove_property_map(segment);
      }

      // CGAL's SDF segmentation, default parameters.
      if(with_sdf) {
        auto sdf = mesh.add_property_map<Face, double>("f:sdf", 0.0).first;
        auto segment = mesh.add_property_map<Face, std::size_t>("f:sdf_segment", 0).first;
        try {
          const auto start = std::chrono::steady_clock::now();
          CGAL::sdf_values(mesh, sdf);
          CGAL::segmentation_from_sdf_values(mesh, sdf, segment);
          row.sdf.seconds = seconds_since(start);
          for(Face f : faces(mesh))
            labels[f.idx()] = segment[f];
          row.sdf.rand_index_error = psb::mean_rand_index_error(entry, labels);
          row.sdf.segments = psb::number_of_labels(labels);
          row.sdf.ok = true;
          total_sdf += row.sdf.seconds;
        } catch(const std::exception& e) {
          row.sdf.error = e.what();
        }
        mesh.remove_property_map(segment);
        mesh.remove_property_map(sdf);
      }

      std::cerr << "[" << index << "/" << meshes.size() << "] " << entry.id << " "
                << entry.mesh_class << " faces=" << n << " k=" << k;
      if(row.ours.ok)
        std::cerr << " ours: " << row.ours.seconds << " s, RI err " << row.ours.rand_index_error
                  << ", " << row.ours.segments << " seg";
      else
        std::cerr << " ours FAILED: " << row.ours.error;
      if(with_sdf) {
        if(row.sdf.ok)
          std::cerr << " | sdf: " << row.sdf.seconds << " s, RI err " << row.sdf.rand_index_error
                    << ", " << row.sdf.segments << " seg";
        else
          std::cerr << " | sdf FAILED: " << row.sdf.error;
      }
      std::cerr << std::endl;
    }

    j["ours"] = row.ours.json();
    if(with_sdf) {
      j["sdf"] = row.sdf.json();
      if(row.ours.ok && row.sdf.ok) {
        ++compared;
        if(row.ours.rand_index_error < row.sdf.rand_index_error)
          ++ours_better;
        else if(row.sdf.rand_index_error < row.ours.rand_index_error)
          ++sdf_better;
      }
    }
    per_mesh.push_back(j);
    rows.push_back(row);
    write_output(output, summarize(false));
  }

  const Json final_report = summarize(true);
  std::cout << SAS::to_text(final_report) << '\n';
  write_output(output, final_report);
  return EXIT_SUCCESS;
}
