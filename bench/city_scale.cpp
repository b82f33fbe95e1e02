// Copyright (c) 2026 CGAL Global Shape Analysis contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later

// The whole chain (background removal, normalized-cut localization, min-cut segmentation with
// the automatic radius) on scanned procedural streets of 10^6 to 10^8 points, tile by tile with
// recognize_objects(): seconds, points per second, the tiles and the most points one tile was
// processed with, the peak resident memory of the call (the input included), localization
// precision and recall (within 1 m) and segmentation precision and recall against the generated
// truth (the points left out as ground left out, as `points evaluate` does; per segmentation, and
// with each point given to its nearest object), the same chain on the whole street as one tile, side by side, up to --whole-limit points.
//
//   bench_city_scale [--points 1000000,10000000] [--seed 6] [--tile-size 100] [--tile-margin 10]
//                    [--whole-limit 10000000] [--threads 0] [--output FILE]
//
// Each size is a street of 400 m per million points. The objects "seen" (for recall) are those
// with at least 50 scanned points. JSON to stdout and to FILE; progress to stderr.

#include "bench_util.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <Shape_analysis_support/Urban_scan.h>
#include <CGAL/Point_set_object_recognition/recognize_objects.h>
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

// The peak resident memory of this process since the last reset, in MiB (Linux; 0 elsewhere).
double peak_resident_mib()
{
  std::ifstream in("/proc/self/status");
  std::string line;
  while(std::getline(in, line))
    if(line.rfind("VmHWM:", 0) == 0)
      return std::stod(line.substr(6)) / 1024.0;
  return 0;
}
void reset_peak_resident() { std::ofstream("/proc/self/clear_refs") << "5"; }

} // namespace

int main(int argc, char** argv)
{
  std::vector<std::size_t> sizes = {1000000, 10000000};
  std::uint64_t seed = 6;
  std::size_t threads = 0, whole_limit = 10000000;
  double tile = 100, margin = 10;
  std::string output;
  for(int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if(i + 1 >= argc) {
      std::cerr << "usage: bench_city_scale [--points a,b,...] [--seed S] [--tile-size T] [--tile-margin M] "
                   "[--whole-limit N] [--threads N] [--output FILE]\n";
      return 2;
    }
    const std::string v = argv[++i];
    if(a == "--points") {
      sizes.clear();
      for(unsigned long long k : bench_util::split_numbers(v))
        sizes.push_back(std::size_t(k));
    } else if(a == "--seed")
      seed = std::stoull(v);
    else if(a == "--tile-size")
      tile = std::stod(v);
    else if(a == "--tile-margin")
      margin = std::stod(v);
    else if(a == "--whole-limit")
      whole_limit = std::stoul(v);
    else if(a == "--threads")
      threads = std::stoul(v);
    else if(a == "--output")
      output = v;
    else {
      std::cerr << "unknown option " << a << "\n";
      return 2;
    }
  }
  Json runs = Json::array();
  for(std::size_t n : sizes) {
    SAS::Urban_scene_options o;
    o.seed = seed;
    o.target_points = n;
    o.street_length = (std::max)(100.0, 400.0 * double(n) / 1e6);
    o.number_of_threads = threads;
    std::cerr << n << " points, street of " << o.street_length << " m, seed " << seed << "...\n";
    const auto t0 = std::chrono::steady_clock::now();
    std::vector<Point> points;
    std::vector<int> instance;
    std::map<int, int> class_of_instance;
    std::vector<std::array<double, 2>> truth, seen;
    {
      const SAS::Urban_scene scene = SAS::make_urban_scene(o);
      const SAS::Urban_scan scan = SAS::scan_urban_scene(scene, o);
      points.reserve(scan.points.size());
      instance.reserve(scan.points.size());
      std::map<int, std::size_t> count;
      for(const auto& p : scan.points) {
        points.emplace_back(p.x, p.y, p.z);
        instance.push_back(p.instance);
        if(p.instance > 0) {
          class_of_instance[p.instance] = p.label;
          ++count[p.instance];
        }
      }
      for(const auto& b : scene.objects) {
        truth.push_back({b.x, b.y});
        const auto it = count.find(b.id);
        if(it != count.end() && it->second >= 50)
          seen.push_back({b.x, b.y});
      }
    }
    const double generation = seconds_since(t0);
    std::cerr << "  generated " << points.size() << " points in " << generation << " s\n";
    Json j = Json::object();
    j["points"] = points.size();
    j["street_length"] = o.street_length;
    j["objects"] = truth.size();
    j["objects_seen"] = seen.size();
    j["seconds_generation"] = generation;
    Json chains = Json::array();
    for(const bool whole : {false, true}) {
      if(whole && points.size() > whole_limit)
        continue;
      reset_peak_resident();
      const double before = peak_resident_mib();
      const PSOR::Object_recognition_result r = PSOR::recognize_objects(
        points, PSOR::parameters::tile_size(whole ? 1e9 : tile).tile_margin(margin).number_of_threads(threads));
      const double peak = peak_resident_mib();
      const PSOR::Localization_evaluation le = PSOR::evaluate_locations(r.locations, truth, 1.0);
      const PSOR::Localization_evaluation lv = PSOR::evaluate_locations(r.locations, seen, 1.0);
      // As `points evaluate`: the points left out as ground are left out of the evaluation.
      std::vector<int> kept_instance = instance;
      for(std::size_t i = 0; i < kept_instance.size(); ++i)
        if(r.kind[i] == PSOR::Point_kind::GROUND)
          kept_instance[i] = -1;
      const PSOR::Segmentation_evaluation se = PSOR::evaluate_segmentations(r.objects, kept_instance, class_of_instance);
      const PSOR::Segmentation_evaluation sl = PSOR::evaluate_labelling(r.object_of_point, kept_instance, class_of_instance);
      Json c = Json::object();
      c["tiling"] = whole ? "one tile" : "tiles";
      c["tile_size"] = whole ? 0.0 : tile;
      c["tile_margin"] = margin;
      c["tiles"] = r.tiles.size();
      c["largest_tile_points"] = r.largest_tile;
      c["seconds"] = r.seconds;
      c["points_per_second"] = double(points.size()) / r.seconds;
      c["resident_mib_before"] = before;
      c["peak_resident_mib"] = peak;
      c["locations"] = r.locations.size();
      c["localization_precision"] = le.precision;
      c["localization_recall"] = lv.recall;
      c["segmentation_precision"] = se.precision;
      c["segmentation_recall"] = se.recall;
      c["segmentations_matched"] = se.objects.size();
      c["labelling_precision"] = sl.precision;
      c["labelling_recall"] = sl.recall;
      chains.push_back(c);
      std::cerr << "  " << (whole ? "one tile" : "tiles") << ": " << r.tiles.size() << " tiles (largest "
                << r.largest_tile << " points), " << r.seconds << " s, " << double(points.size()) / r.seconds
                << " points/s, peak memory " << peak << " MiB (" << before << " before); " << r.locations.size()
                << " locations, precision " << le.precision << ", recall " << lv.recall << " (" << seen.size()
                << " objects seen); segmentation " << se.precision << " / " << se.recall << " over "
                << se.objects.size() << " (each point to its nearest object: " << sl.precision << " / " << sl.recall
                << ")\n";
    }
    j["chains"] = chains;
    runs.push_back(j);
  }
  Json result = Json::object();
  result["benchmark"] = "city_scale";
  result["seed"] = seed;
  result["threads"] = threads;
  result["runs"] = runs;
  const std::string text = SAS::to_text(result);
  std::cout << text << std::endl;
  if(!output.empty())
    std::ofstream(output) << text << std::endl;
  return 0;
}
