// Copyright (c) 2026 CGAL Global Shape Analysis contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later

// Scanned procedural streets: time to generate and scan them, time to remove their background
// and to locate the objects by the four methods (connected components, mean shift, height image,
// normalized cut), and how well both do against the points' known classes and the objects' known
// locations (within 1 m).
//
//   bench_background_removal [--points 100000,1000000,10000000] [--seeds 1] [--threads 0]
//                            [--output FILE]
//
// Each size is a street of 400 m per million points (at least 100 m), for each seed. Figures:
// the fraction of ground and building points removed, of object points kept and of background
// points kept, and the objects (hit by the scanner) that keep at least half of their points; per
// localization method its seconds, the throughput of background removal plus localization in
// points of the scan per second, precision (against every true object) and recall (against the
// objects with at least 10 scanned points; `recall_all_objects` against all of them).
// JSON to stdout and to FILE; progress to stderr.

#include "bench_util.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <Shape_analysis_support/Urban_scan.h>
#include <CGAL/Point_set_object_recognition/locate_objects.h>
#include <CGAL/Point_set_object_recognition/remove_background.h>
#include <Shape_analysis_support/Json.h>

#include <algorithm>
#include <chrono>
#include <fstream>
#include <iostream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

namespace {

typedef CGAL::Exact_predicates_inexact_constructions_kernel::Point_3 Point;
namespace PSOR = CGAL::Point_set_object_recognition;
namespace SAS = CGAL::Shape_analysis_support;
typedef SAS::Json Json;

using bench_util::seconds_since;

} // namespace

int main(int argc, char** argv)
{
  std::vector<std::size_t> sizes = {100000, 1000000, 10000000};
  std::vector<std::uint64_t> seeds = {1};
  std::size_t threads = 0;
  std::string output;
  for(int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if(i + 1 >= argc) {
      std::cerr << "usage: bench_background_removal [--points a,b,...] [--seeds a,b,...] [--threads N] [--output FILE]\n";
      return 2;
    }
    const std::string v = argv[++i];
    if(a == "--points" || a == "--seeds") {
      std::vector<std::size_t> list;
      for(unsigned long long k : bench_util::split_numbers(v))
        list.push_back(std::size_t(k));
      if(a == "--points")
        sizes = list;
      else
        seeds.assign(list.begin(), list.end());
    } else if(a == "--threads")
      threads = std::stoul(v);
    else if(a == "--output")
      output = v;
    else {
      std::cerr << "unknown option " << a << "\n";
      return 2;
    }
  }
  Json runs = Json::array();
  for(std::uint64_t seed : seeds)
  for(std::size_t n : sizes) {
    SAS::Urban_scene_options o;
    o.seed = seed;
    o.target_points = n;
    o.street_length = (std::max)(100.0, 400.0 * double(n) / 1e6);
    o.number_of_threads = threads;
    std::cerr << n << " points, street of " << o.street_length << " m, seed " << seed << "...\n";
    const auto t0 = std::chrono::steady_clock::now();
    const SAS::Urban_scene scene = SAS::make_urban_scene(o);
    const SAS::Urban_scan scan = SAS::scan_urban_scene(scene, o);
    const double generation = seconds_since(t0);
    std::vector<Point> points;
    points.reserve(scan.points.size());
    for(const auto& p : scan.points)
      points.emplace_back(p.x, p.y, p.z);
    const auto t1 = std::chrono::steady_clock::now();
    const PSOR::Background_removal_result r = PSOR::remove_background(points);
    const double removal = seconds_since(t1);

    std::size_t ground = 0, ground_removed = 0, building = 0, building_removed = 0, object = 0,
                object_kept = 0, background = 0, background_kept = 0;
    std::map<int, std::pair<std::size_t, std::size_t>> per_object;
    for(std::size_t i = 0; i < scan.points.size(); ++i) {
      const auto& p = scan.points[i];
      const bool kept = r.kind[i] == PSOR::Point_kind::FOREGROUND;
      if(p.instance > 0) {
        ++object;
        object_kept += kept;
        auto& po = per_object[p.instance];
        ++po.first;
        po.second += kept;
        continue;
      }
      ++background;
      background_kept += kept;
      if(p.label == SAS::GROUND) {
        ++ground;
        ground_removed += !kept;
      } else if(p.label == SAS::BUILDING) {
        ++building;
        building_removed += !kept;
      }
    }
    std::size_t half_kept = 0;
    for(const auto& kv : per_object)
      half_kept += 2 * kv.second.second >= kv.second.first;
    Json j = Json::object();
    j["points"] = scan.points.size();
    j["seed"] = seed;
    j["street_length"] = o.street_length;
    j["objects"] = scene.objects.size();
    j["objects_hit"] = per_object.size();
    j["object_points"] = object;
    j["seconds_generation"] = generation;
    j["seconds_background_removal"] = removal;
    j["ground_removed"] = ground ? double(ground_removed) / double(ground) : 0.0;
    j["building_removed"] = building ? double(building_removed) / double(building) : 0.0;
    j["object_points_kept"] = object ? double(object_kept) / double(object) : 0.0;
    j["background_points_kept"] = background ? double(background_kept) / double(background) : 0.0;
    j["objects_keeping_half"] = half_kept;
    j["foreground_points"] = r.foreground.size();
    {
      std::vector<Point> foreground;
      for(std::size_t i : r.foreground)
        foreground.push_back(points[i]);
      std::vector<std::array<double, 2>> truth, visible;
      for(const auto& b : scene.objects) {
        truth.push_back({b.x, b.y});
        const auto it = per_object.find(b.id);
        if(it != per_object.end() && it->second.first >= 10)
          visible.push_back({b.x, b.y});
      }
      j["objects_with_10_points"] = visible.size();
      Json methods = Json::array();
      const std::pair<PSOR::Localization_method, const char*> all_methods[] = {
        {PSOR::Localization_method::CONNECTED_COMPONENTS, "connected components (0.3 m)"},
        {PSOR::Localization_method::MEAN_SHIFT, "mean shift (2 m)"},
        {PSOR::Localization_method::HEIGHT_IMAGE, "height image (0.15 m, DoG 0.2 m)"},
        {PSOR::Localization_method::NORMALIZED_CUT, "normalized cut (0.15 m voxels)"}};
      for(const auto& m : all_methods) {
        const auto t2 = std::chrono::steady_clock::now();
        const PSOR::Localization_result l = PSOR::locate_objects(
          foreground, PSOR::parameters::localization_method(m.first).number_of_threads(threads));
        const double seconds = seconds_since(t2);
        const PSOR::Localization_evaluation e = PSOR::evaluate_locations(l.locations, truth, 1.0);
        const PSOR::Localization_evaluation ev = PSOR::evaluate_locations(l.locations, visible, 1.0);
        Json jl = Json::object();
        jl["method"] = m.second;
        jl["seconds"] = seconds;
        jl["points_per_second_with_background_removal"] = double(scan.points.size()) / (removal + seconds);
        jl["locations"] = l.locations.size();
        jl["precision"] = e.precision;
        jl["recall"] = ev.recall;
        jl["recall_all_objects"] = e.recall;
        methods.push_back(jl);
        std::cerr << "  localization, " << m.second << ": " << l.locations.size() << " locations in " << seconds
                  << " s (" << double(scan.points.size()) / (removal + seconds)
                  << " points/s with the background removal), precision " << e.precision << ", recall "
                  << ev.recall << " (" << visible.size() << " objects with 10 points or more; " << e.recall
                  << " of all " << scene.objects.size() << ")\n";
      }
      j["localization"] = methods;
    }
    runs.push_back(j);
    std::cerr << "  " << scan.points.size() << " points: generated in " << generation << " s, background removed in "
              << removal << " s; object points kept " << j["object_points_kept"].dump() << ", background kept "
              << j["background_points_kept"].dump() << ", objects keeping half " << half_kept << "/"
              << per_object.size() << "\n";
  }
  Json result = Json::object();
  result["benchmark"] = "background_removal";
  result["threads"] = threads;
  result["runs"] = runs;
  const std::string text = SAS::to_text(result);
  std::cout << text << std::endl;
  if(!output.empty())
    std::ofstream(output) << text << std::endl;
  return 0;
}
