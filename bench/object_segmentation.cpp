// Copyright (c) 2026 CGAL Global Shape Analysis contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later

// Segmentation of objects from their locations on scanned procedural streets (ground removed):
// precision and recall per class and overall (the thesis' table 4.2: 86% and 93% for min-cut with
// the automatic radius), for the true locations and for the locations of locate_objects(); the
// time per object (median and 90th percentile, one thread; the thesis: 0.1 s per object) by the
// number of points within 5 m of the location (10,000 to 200,000 on the dense street); and, built
// with PCL (bench_object_segmentation_pcl), pcl::MinCutSegmentation on the same objects side by
// side: same seed point, same background radius, on the points within that radius plus 1 m.
//
//   bench_object_segmentation [--seeds 2,3] [--points 1000000] [--length 200]
//                             [--dense-points 4000000] [--dense-length 60] [--pcl-objects 60]
//                             [--threads 0] [--output FILE]
//                             [--background-weight B] [--sigma S] [--max-cut C] [--cell C]
//                             [--neighbors K] [--graph-size N]   (overrides of the defaults, to tune)
//
// The time per object excludes the graph shared by the objects of a call; the figures "with the
// shared graph" add its time shared out equally among the call's objects.
// Measured (seeds 2,3, --dense-points 4000000 --dense-length 60 --pcl-objects 60, 2 cores shared
// with other work): min-cut with the automatic radius 86.2% / 99.4% over 93 objects, 0.13 ms per
// object (median), 0.72 to 0.75 ms with the shared graph (0.027 to 0.030 s per street of 10^6
// points); on PCL's 110 objects PCL 80.4% / 85.6% in 15 to 16 ms, ours 86.7% / 99.5% in 0.17 ms
// (about 90 times faster; 0.80 to 0.85 ms and 18 to 19.5 times with the shared graph, from run to
// run).
//
// The defaults were tuned on seed 1 (--seeds 1); report on other seeds. JSON to stdout and FILE, progress and
// tables to stderr.

#include "bench_util.h"

#include <Shape_analysis_support/Scanned_objects.h>
#include <Shape_analysis_support/Segmentation_json.h>
#include <CGAL/Point_set_object_recognition/locate_objects.h>
#include <CGAL/Point_set_object_recognition/segment_objects.h>
#include <Shape_analysis_support/Json.h>

#ifdef SHAPE_ANALYSIS_BENCH_WITH_PCL
#include <pcl/point_cloud.h>
#include <pcl/point_types.h>
#include <pcl/search/kdtree.h>
#include <pcl/segmentation/min_cut_segmentation.h>
#endif

#include <algorithm>
#include <chrono>
#include <fstream>
#include <iostream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

namespace {

namespace PSOR = CGAL::Point_set_object_recognition;
namespace SAS = CGAL::Shape_analysis_support;
typedef SAS::Json Json;

double quantile(std::vector<double> v, double q)
{
  if(v.empty())
    return 0;
  std::sort(v.begin(), v.end());
  return v[std::size_t(q * double(v.size() - 1) + 0.5)];
}

std::string class_name(int c) { return SAS::object_class_name(c); }

Json evaluation_json(const PSOR::Segmentation_evaluation& e) { return SAS::segmentation_evaluation_json(e, class_name); }

// The parameters of a run: the library's defaults (Segment_objects_options), or the values given
// (negative / zero / -1: default).
struct Tuning
{
  double weight = -1, sigma = -1, max_cut = -1, cell = -1;
  std::size_t neighbors = 0, graph_size = std::size_t(-1);

  PSOR::Segmentation_result run(const SAS::Scanned_objects& s, const std::vector<std::array<double, 3>>& at,
                                PSOR::Segmentation_method method, double radius, std::size_t threads) const
  {
    const PSOR::Segment_objects_options d;
    const auto np = PSOR::parameters::segmentation_method(method)
                      .background_radius(radius)
                      .number_of_threads(threads)
                      .background_weight(weight >= 0 ? weight : d.background_weight)
                      .maximum_cut_cost(max_cut >= 0 ? max_cut : d.maximum_cut_cost)
                      .graph_cell_size(cell >= 0 ? cell : d.graph_cell_size)
                      .number_of_neighbors(neighbors > 0 ? neighbors : d.number_of_neighbors)
                      .maximum_graph_size(graph_size != std::size_t(-1) ? graph_size : d.maximum_graph_size);
    // Without a sigma, the library's default for the cell size.
    return sigma > 0 ? PSOR::segment_objects(s.points, at, np.edge_sigma(sigma)) : PSOR::segment_objects(s.points, at, np);
  }
};

SAS::Scanned_objects make_street(std::uint64_t seed, std::size_t points, double length, std::size_t threads)
{
  SAS::Urban_scene_options o;
  o.seed = seed;
  o.target_points = points;
  o.street_length = length;
  o.number_of_threads = threads;
  const SAS::Urban_scene scene = SAS::make_urban_scene(o);
  const SAS::Urban_scan scan = SAS::scan_urban_scene(scene, o);
  return SAS::scanned_objects(scene, scan);
}

#ifdef SHAPE_ANALYSIS_BENCH_WITH_PCL
// pcl::MinCutSegmentation of one object: the points within radius + 1 m of the location, the
// same seed point, the same background radius; PCL's defaults of its tutorial otherwise
// (sigma 0.25, 14 neighbours, source weight 0.8). Returns the indices (into s.points) and the
// seconds of extract().
std::vector<std::size_t> pcl_segment(const SAS::Scanned_objects& s, const std::array<double, 3>& at,
                                     std::size_t seed, double radius, double& seconds)
{
  pcl::PointCloud<pcl::PointXYZ>::Ptr cloud(new pcl::PointCloud<pcl::PointXYZ>);
  std::vector<std::size_t> index;
  for(std::size_t i = 0; i < s.points.size(); ++i)
    if(std::hypot(s.points[i].x() - at[0], s.points[i].y() - at[1]) <= radius + 1.0) {
      // PCL stores floats: coordinates relative to the location.
      cloud->push_back(pcl::PointXYZ(float(s.points[i].x() - at[0]), float(s.points[i].y() - at[1]),
                                     float(s.points[i].z() - at[2])));
      index.push_back(i);
    }
  std::vector<std::size_t> result;
  if(seed >= s.points.size())
    return result;
  const auto start = std::chrono::steady_clock::now();
  pcl::MinCutSegmentation<pcl::PointXYZ> seg;
  seg.setInputCloud(cloud);
  pcl::PointCloud<pcl::PointXYZ>::Ptr fg(new pcl::PointCloud<pcl::PointXYZ>);
  fg->push_back(pcl::PointXYZ(float(s.points[seed].x() - at[0]), float(s.points[seed].y() - at[1]),
                              float(s.points[seed].z() - at[2])));
  seg.setForegroundPoints(fg);
  seg.setSigma(0.25);
  seg.setRadius(radius);
  seg.setNumberOfNeighbours(14);
  seg.setSourceWeight(0.8);
  std::vector<pcl::PointIndices> clusters;
  seg.extract(clusters);
  seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  // Cluster 1 is the foreground.
  if(clusters.size() > 1)
    for(int k : clusters[1].indices)
      result.push_back(index[std::size_t(k)]);
  std::sort(result.begin(), result.end());
  return result;
}
#endif

} // namespace

int main(int argc, char** argv)
{
  std::vector<std::uint64_t> seeds = {2, 3};
  std::size_t points = 1000000, dense_points = 4000000, pcl_objects = 60, threads = 0;
  double length = 200, dense_length = 60;
  // Overrides of the segmentation's defaults (for tuning; the defaults when absent).
  double weight = -1, sigma = -1, max_cut = -1, cell = -1;
  std::size_t neighbors = 0, graph_size = std::size_t(-1);
  std::string output;
  for(int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if(i + 1 >= argc) {
      std::cerr << "usage: bench_object_segmentation [--seeds a,b] [--points N] [--length L] [--dense-points N] "
                   "[--dense-length L] [--pcl-objects N] [--threads N] [--output FILE]\n";
      return 2;
    }
    const std::string v = argv[++i];
    if(a == "--seeds") {
      seeds.clear();
      for(unsigned long long k : bench_util::split_numbers(v))
        seeds.push_back(k);
    } else if(a == "--points")
      points = std::stoul(v);
    else if(a == "--length")
      length = std::stod(v);
    else if(a == "--dense-points")
      dense_points = std::stoul(v);
    else if(a == "--dense-length")
      dense_length = std::stod(v);
    else if(a == "--pcl-objects")
      pcl_objects = std::stoul(v);
    else if(a == "--threads")
      threads = std::stoul(v);
    else if(a == "--background-weight")
      weight = std::stod(v);
    else if(a == "--sigma")
      sigma = std::stod(v);
    else if(a == "--max-cut")
      max_cut = std::stod(v);
    else if(a == "--cell")
      cell = std::stod(v);
    else if(a == "--neighbors")
      neighbors = std::stoul(v);
    else if(a == "--graph-size")
      graph_size = std::stoul(v);
    else if(a == "--output")
      output = v;
    else {
      std::cerr << "unknown option " << a << "\n";
      return 2;
    }
  }

  Tuning tuning;
  tuning.weight = weight, tuning.sigma = sigma, tuning.max_cut = max_cut, tuning.cell = cell;
  tuning.neighbors = neighbors, tuning.graph_size = graph_size;
  Json runs = Json::array();
  // Pooled over the seeds: per-object scores of min-cut with the automatic radius.
  std::vector<PSOR::Object_segmentation> pooled_segmentations;
  std::vector<int> pooled_instance;
  std::map<int, int> pooled_classes;
  int instance_offset = 0;
  std::size_t point_offset = 0;
  std::vector<double> pooled_ms, pooled_amortized_ms;
#ifdef SHAPE_ANALYSIS_BENCH_WITH_PCL
  std::vector<PSOR::Object_segmentation> ours_pcl_objects, pcl_segmentations;
  std::vector<double> ours_pcl_ms, ours_pcl_amortized_ms, pcl_ms;
  std::vector<int> pcl_instance;
  std::map<int, int> pcl_classes;
  std::size_t pcl_offset = 0;
#endif

  struct Street { std::uint64_t seed; std::size_t points; double length; bool dense; };
  std::vector<Street> streets;
  for(std::uint64_t s : seeds)
    streets.push_back({s, points, length, false});
  if(dense_points > 0)
    streets.push_back({seeds.empty() ? 2 : seeds.front(), dense_points, dense_length, true});

  for(const Street& st : streets) {
    std::cerr << "seed " << st.seed << ", " << st.points << " points, street of " << st.length << " m...\n";
    const SAS::Scanned_objects s = make_street(st.seed, st.points, st.length, threads);
    Json run = Json::object();
    run["seed"] = st.seed;
    run["scan_points"] = s.scan_points;
    run["points_above_ground"] = s.points.size();
    run["objects_seen"] = s.locations.size();
    run["dense"] = st.dense;

    // Points within 5 m of each location (the largest automatic radius).
    std::vector<std::size_t> within(s.locations.size(), 0);
    for(std::size_t k = 0; k < s.locations.size(); ++k)
      for(const auto& p : s.points)
        within[k] += std::hypot(p.x() - s.locations[k][0], p.y() - s.locations[k][1]) <= 5.0;

    Json methods = Json::array();
    struct Method { std::string name; PSOR::Segmentation_method method; double radius; };
    const std::vector<Method> all_methods = {
      {"min-cut, automatic radius", PSOR::Segmentation_method::MIN_CUT_AUTOMATIC_RADIUS, 2},
      {"min-cut, radius 2 m", PSOR::Segmentation_method::MIN_CUT, 2},
      {"connected components (0.3 m) within 2 m", PSOR::Segmentation_method::CONNECTED_COMPONENTS, 2},
      {"all points within 1 m", PSOR::Segmentation_method::ALL_WITHIN_RADIUS, 1}};
    PSOR::Segmentation_result automatic;
    for(const Method& m : all_methods) {
      if(st.dense && m.method != PSOR::Segmentation_method::MIN_CUT_AUTOMATIC_RADIUS)
        continue;
      // One thread: the time per object is that of one core.
      const PSOR::Segmentation_result r = tuning.run(s, s.locations, m.method, m.radius, 1);
      const PSOR::Segmentation_evaluation e = PSOR::evaluate_segmentations(r.objects, s.instance, s.class_of_instance);
      std::vector<double> ms;
      for(const auto& o : r.objects)
        ms.push_back(1000 * o.seconds);
      Json j = evaluation_json(e);
      j["method"] = m.name;
      j["milliseconds_per_object_median"] = quantile(ms, 0.5);
      j["milliseconds_per_object_p90"] = quantile(ms, 0.9);
      j["seconds_preparation"] = r.preparation_seconds;
      j["seconds"] = r.seconds;
      methods.push_back(j);
      std::cerr << "  " << m.name << ": precision " << e.precision << ", recall " << e.recall << ", "
                << quantile(ms, 0.5) << " ms per object (median), " << quantile(ms, 0.9) << " (p90), preparation "
                << r.preparation_seconds << " s\n";
      if(m.method == PSOR::Segmentation_method::MIN_CUT_AUTOMATIC_RADIUS) {
        PSOR::print_segmentation_table(std::cerr, e, class_name);
        automatic = r;
      }
    }
    run["true_locations"] = methods;

    // Time by the number of points within 5 m.
    Json bins = Json::array();
    const std::vector<std::pair<std::size_t, std::size_t>> ranges = {
      {0, 10000}, {10000, 50000}, {50000, 100000}, {100000, 200000}, {200000, 100000000}};
    for(const auto& rg : ranges) {
      std::vector<double> ms;
      for(std::size_t k = 0; k < s.locations.size(); ++k)
        if(within[k] >= rg.first && within[k] < rg.second)
          ms.push_back(1000 * automatic.objects[k].seconds);
      if(ms.empty())
        continue;
      Json b = Json::object();
      b["points_within_5m_from"] = rg.first;
      b["points_within_5m_to"] = rg.second;
      b["objects"] = ms.size();
      b["milliseconds_median"] = quantile(ms, 0.5);
      b["milliseconds_p90"] = quantile(ms, 0.9);
      bins.push_back(b);
      std::cerr << "  " << rg.first << "-" << rg.second << " points within 5 m: " << ms.size() << " objects, "
                << quantile(ms, 0.5) << " ms median, " << quantile(ms, 0.9) << " ms p90\n";
    }
    run["time_by_points_within_5m"] = bins;
    // With all threads: the whole street.
    {
      const PSOR::Segmentation_result r =
        tuning.run(s, s.locations, PSOR::Segmentation_method::MIN_CUT_AUTOMATIC_RADIUS, 2, threads);
      run["seconds_all_objects_all_threads"] = r.seconds;
    }

    if(!st.dense) {
      for(std::size_t k = 0; k < automatic.objects.size(); ++k) {
        PSOR::Object_segmentation o = automatic.objects[k];
        for(std::size_t& q : o.points)
          q += point_offset;
        pooled_segmentations.push_back(o);
        pooled_ms.push_back(1000 * o.seconds);
        pooled_amortized_ms.push_back(1000 * (o.seconds + automatic.preparation_seconds / double(automatic.objects.size())));
      }
      for(int i : s.instance)
        pooled_instance.push_back(i > 0 ? i + instance_offset : i);
      for(const auto& c : s.class_of_instance)
        pooled_classes[c.first + instance_offset] = c.second;
      point_offset += s.points.size();
      instance_offset += 100000;

      // Locations found by locate_objects() among the foreground of remove_background().
      std::vector<SAS::Scanned_objects::Point> foreground;
      {
        const PSOR::Background_removal_result b = PSOR::remove_background(s.points);
        for(std::size_t i : b.foreground)
          foreground.push_back(s.points[i]);
      }
      const PSOR::Localization_result l = PSOR::locate_objects(foreground);
      std::vector<std::array<double, 2>> truth;
      for(const auto& t : s.locations)
        truth.push_back({t[0], t[1]});
      const PSOR::Localization_evaluation le = PSOR::evaluate_locations(l.locations, truth, 1.0);
      std::vector<std::array<double, 3>> found;
      for(const auto& q : l.locations)
        found.push_back(q.position);
      const PSOR::Segmentation_result r =
        tuning.run(s, found, PSOR::Segmentation_method::MIN_CUT_AUTOMATIC_RADIUS, 2, threads);
      const PSOR::Segmentation_evaluation e = PSOR::evaluate_segmentations(r.objects, s.instance, s.class_of_instance);
      Json j = evaluation_json(e);
      j["locations"] = l.locations.size();
      j["localization_precision"] = le.precision;
      j["localization_recall"] = le.recall;
      run["found_locations"] = j;
      std::cerr << "  locate_objects: " << l.locations.size() << " locations (precision " << le.precision
                << ", recall " << le.recall << "); min-cut automatic: precision " << e.precision << ", recall "
                << e.recall << " over " << e.objects.size() << " matched\n";
    }

#ifdef SHAPE_ANALYSIS_BENCH_WITH_PCL
    // PCL on the same objects (the first pcl_objects of the street).
    for(std::size_t k = 0; k < s.locations.size() && k < pcl_objects; ++k) {
      const PSOR::Object_segmentation& ours = automatic.objects[k];
      double seconds = 0;
      PSOR::Object_segmentation theirs;
      theirs.points = pcl_segment(s, s.locations[k], ours.seed, ours.radius, seconds);
      theirs.seconds = seconds;
      PSOR::Object_segmentation mine = ours;
      for(std::size_t& q : theirs.points)
        q += pcl_offset;
      for(std::size_t& q : mine.points)
        q += pcl_offset;
      pcl_segmentations.push_back(theirs);
      ours_pcl_objects.push_back(mine);
      pcl_ms.push_back(1000 * seconds);
      ours_pcl_ms.push_back(1000 * ours.seconds);
      // With the graph shared by the street's objects (built once per call) shared out equally.
      ours_pcl_amortized_ms.push_back(1000 * (ours.seconds + automatic.preparation_seconds /
                                                                 double((std::max)(std::size_t(1), automatic.objects.size()))));
    }
    const int pcl_shift = int(&st - &streets[0]) * 100000;
    for(int i : s.instance)
      pcl_instance.push_back(i > 0 ? i + pcl_shift : i);
    for(const auto& c : s.class_of_instance)
      pcl_classes[c.first + pcl_shift] = c.second;
    pcl_offset += s.points.size();
#endif
    runs.push_back(run);
  }

  Json result = Json::object();
  result["benchmark"] = "object_segmentation";
  result["threads"] = threads;
  result["runs"] = runs;
  {
    const PSOR::Segmentation_evaluation e =
      PSOR::evaluate_segmentations(pooled_segmentations, pooled_instance, pooled_classes);
    Json j = evaluation_json(e);
    j["milliseconds_per_object_median"] = quantile(pooled_ms, 0.5);
    j["milliseconds_per_object_p90"] = quantile(pooled_ms, 0.9);
    j["milliseconds_per_object_with_graph_median"] = quantile(pooled_amortized_ms, 0.5);
    j["thesis_precision"] = 0.86;
    j["thesis_recall"] = 0.93;
    j["thesis_seconds_per_object"] = 0.1;
    result["min_cut_automatic_radius_all_seeds"] = j;
    std::cerr << "all seeds, min-cut with the automatic radius, true locations:\n";
    PSOR::print_segmentation_table(std::cerr, e, class_name);
    std::cerr << "median " << quantile(pooled_ms, 0.5) << " ms per object, p90 " << quantile(pooled_ms, 0.9)
              << "; with the shared graph's time shared out: median " << quantile(pooled_amortized_ms, 0.5) << " ms\n";
  }
#ifdef SHAPE_ANALYSIS_BENCH_WITH_PCL
  {
    const std::map<int, int>& classes = pcl_classes;
    const PSOR::Segmentation_evaluation eo = PSOR::evaluate_segmentations(ours_pcl_objects, pcl_instance, classes);
    const PSOR::Segmentation_evaluation ep = PSOR::evaluate_segmentations(pcl_segmentations, pcl_instance, classes);
    Json j = Json::object();
    j["objects"] = pcl_segmentations.size();
    j["ours"] = evaluation_json(eo);
    j["ours"]["milliseconds_per_object_median"] = quantile(ours_pcl_ms, 0.5);
    j["pcl"] = evaluation_json(ep);
    j["pcl"]["milliseconds_per_object_median"] = quantile(pcl_ms, 0.5);
    const double speedup = quantile(pcl_ms, 0.5) / (std::max)(1e-9, quantile(ours_pcl_ms, 0.5));
    j["median_speedup"] = speedup;
    j["ours"]["milliseconds_per_object_with_graph_median"] = quantile(ours_pcl_amortized_ms, 0.5);
    const double amortized_speedup = quantile(pcl_ms, 0.5) / (std::max)(1e-9, quantile(ours_pcl_amortized_ms, 0.5));
    j["median_speedup_with_graph"] = amortized_speedup;
    result["pcl_min_cut_segmentation"] = j;
    std::cerr << "PCL MinCutSegmentation on " << pcl_segmentations.size() << " objects: precision " << ep.precision
              << ", recall " << ep.recall << ", " << quantile(pcl_ms, 0.5) << " ms median; ours: precision "
              << eo.precision << ", recall " << eo.recall << ", " << quantile(ours_pcl_ms, 0.5)
              << " ms median; speed-up " << speedup << "; with the shared graph's time shared out: "
              << quantile(ours_pcl_amortized_ms, 0.5) << " ms median, speed-up " << amortized_speedup << "\n";
  }
#endif
  const std::string text = SAS::to_text(result);
  std::cout << text << std::endl;
  if(!output.empty())
    std::ofstream(output) << text << std::endl;
  return 0;
}
