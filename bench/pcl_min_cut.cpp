// Copyright (c) 2026 CGAL Global Shape Analysis contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later

// PCL's pcl::MinCutSegmentation beside segment_objects() on the real labelled LIDAR frames of
// bench_real_scans (../shared/data/lidar; issue 23), on identical inputs: per frame,
// remove_background() and points_above_ground() with their defaults, then for each true object
// with >= 20 points (the objects bench_real_scans reports as ">= 20") at its true location (the
// box centre (x, y) at the bottom of the box; for a SemanticKITTI instance the middle of its
// horizontal extent at its lowest point):
//  - ours: segment_objects() with its defaults (min-cut, automatic radius), all the frame's
//    locations in one call as bench_real_scans makes it (the same figures);
//  - pcl_fixed_radius: pcl::MinCutSegmentation with its tutorial's parameters for a car (radius
//    3.0433856 m, sigma 0.25, 14 neighbours, source weight 0.8), the foreground point at the
//    true location;
//  - pcl_our_radius: the same with the radius R segment_objects() chose for the object;
//  - pcl_matched_radius: the same with the radius R / source weight, at which PCL's data term
//    turns from foreground to background at R, as ours does (ours rewards the foreground up to
//    R; PCL's sink weight d / radius passes its source weight 0.8 at 0.8 radius).
// PCL's input is the points above the ground within the radius plus 3 m (--margin) horizontally
// of the location (PCL builds its graph on the whole cloud it is given). PCL 1.13 uses only the
// horizontal position of a foreground point: a point's sink weight is its horizontal distance to
// the nearest foreground point divided by the radius, its source weight the constant source
// weight, so the height of the location does not matter to it (and no point is forced into the
// foreground). Scores are real_frames.h's (bench_real_scans'): precision and recall of the
// segment against the points inside the box (or of the instance), pooled and mean per object,
// per frame and in total and by kind. Seconds per object: ours excludes the graph that
// segment_objects() shares among a call's locations (`with_shared_graph` adds its share); PCL's
// include cropping its cloud.
//
//   bench_pcl_min_cut [--data DIR] [--frames a,b] [--minimum-points 20] [--radius 3.0433856]
//                     [--sigma 0.25] [--neighbors 14] [--source-weight 0.8] [--margin 3]
//                     [--no-objects] [--output FILE]
//
// Measured (2026-12-05, PCL 1.13.0, the 8 frames, 95 objects >= 20 points, 2 shared cores;
// precision / recall pooled, mean per object, milliseconds per object (mean)):
//   ours                       0.922 / 0.922, 0.875 / 0.868, 0.8 (1.3 with the shared graph)
//   PCL radius 3.04 m          0.602 / 0.642, 0.725 / 0.865, 24 (2 empty segments)
//   PCL radius R (ours)        0.693 / 0.415, 0.792 / 0.654, 17
//   PCL radius R / 0.8         0.752 / 0.914, 0.757 / 0.884, 19
// (PCL's best, R / 0.8, by kind, mean: cars 0.793 / 0.836 (ours 0.959 / 0.847), persons
// 0.741 / 0.963 (0.821 / 0.965), street furniture 0.673 / 0.944 (0.690 / 0.959).)
//
// JSON to stdout and FILE; a table per frame, ours beside PCL, to stderr.

#include "real_frames.h"

#include <CGAL/Point_set_object_recognition/remove_background.h>
#include <CGAL/Point_set_object_recognition/segment_objects.h>
#include <Shape_analysis_support/Json.h>

#include <pcl/pcl_config.h>
#include <pcl/point_cloud.h>
#include <pcl/point_types.h>
#include <pcl/search/kdtree.h>
#include <pcl/segmentation/min_cut_segmentation.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cstddef>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

namespace {

namespace PSOR = CGAL::Point_set_object_recognition;
namespace SAS = CGAL::Shape_analysis_support;
typedef SAS::Json Json;
using bench_util::seconds_since;
using real_frames::Frame;
using real_frames::Point;
using real_frames::Segmentation_count;

struct Pcl_parameters
{
  double radius = 3.0433856; // PCL's tutorial (a car)
  double sigma = 0.25;
  int neighbours = 14;
  double source_weight = 0.8;
  double margin = 3.0; // the cloud: the points within radius + margin (horizontally)
};

struct Pcl_segment
{
  std::vector<std::size_t> points; // indices into the points given, increasing
  std::size_t cloud = 0;           // the points of PCL's cloud
  double seconds = 0;
};

// pcl::MinCutSegmentation of the object at `at` among `p` with the background radius `radius`.
Pcl_segment pcl_min_cut(const std::vector<Point>& p, const std::array<double, 3>& at, double radius,
                        const Pcl_parameters& o)
{
  const auto start = std::chrono::steady_clock::now();
  Pcl_segment r;
  pcl::PointCloud<pcl::PointXYZ>::Ptr cloud(new pcl::PointCloud<pcl::PointXYZ>);
  std::vector<std::size_t> index;
  const double reach = radius + o.margin;
  for(std::size_t i = 0; i < p.size(); ++i) {
    const double dx = p[i].x() - at[0], dy = p[i].y() - at[1];
    if(dx * dx + dy * dy <= reach * reach) {
      // PCL stores floats: coordinates relative to the location.
      cloud->push_back(pcl::PointXYZ(float(dx), float(dy), float(p[i].z() - at[2])));
      index.push_back(i);
    }
  }
  r.cloud = cloud->size();
  if(!cloud->empty()) {
    pcl::MinCutSegmentation<pcl::PointXYZ> seg;
    seg.setInputCloud(cloud);
    pcl::PointCloud<pcl::PointXYZ>::Ptr foreground(new pcl::PointCloud<pcl::PointXYZ>);
    foreground->push_back(pcl::PointXYZ(0.f, 0.f, 0.f)); // the location
    seg.setForegroundPoints(foreground);
    seg.setSigma(o.sigma);
    seg.setRadius(radius);
    seg.setNumberOfNeighbours(o.neighbours);
    seg.setSourceWeight(o.source_weight);
    std::vector<pcl::PointIndices> clusters;
    seg.extract(clusters);
    if(clusters.size() > 1) // clusters[1]: the foreground
      for(const auto k : clusters[1].indices)
        r.points.push_back(index[std::size_t(k)]);
    std::sort(r.points.begin(), r.points.end());
  }
  r.seconds = seconds_since(start);
  return r;
}

const std::size_t methods = 4;
const char* const method_names[methods] = {"ours", "pcl_fixed_radius", "pcl_our_radius", "pcl_matched_radius"};

// One true object, segmented by the three methods.
struct Object_row
{
  std::string frame, object_class;
  std::array<double, 3> location{{0, 0, 0}};
  bool segmented = false; // false: the location lies outside the box of the points above the ground
  double our_radius = 0;
  double our_shared_seconds = 0; // its share of the graph segment_objects() shares among the call's locations
  std::array<Segmentation_count, methods> count{};
  std::array<double, methods> seconds{};
  std::array<std::size_t, methods> cloud{}; // PCL's input points (0 for ours)
};

double median(std::vector<double> v)
{
  if(v.empty())
    return 0;
  std::nth_element(v.begin(), v.begin() + long(v.size() / 2), v.end());
  return v[v.size() / 2];
}

Json method_json(const std::vector<const Object_row*>& rows, std::size_t m)
{
  std::vector<Segmentation_count> counts;
  std::vector<double> seconds;
  double total = 0, shared = 0;
  for(const Object_row* r : rows) {
    counts.push_back(r->count[m]);
    seconds.push_back(r->seconds[m]);
    total += r->seconds[m], shared += r->our_shared_seconds;
  }
  const real_frames::Segmentation_scores s = real_frames::segmentation_scores(counts);
  const double n = double(std::max<std::size_t>(1, rows.size()));
  Json j = {{"objects", s.objects},
            {"truth_points", s.truth},
            {"segment_points", s.segment},
            {"correct_points", s.correct},
            {"pooled_precision", s.pooled_precision},
            {"pooled_recall", s.pooled_recall},
            {"mean_precision", s.mean_precision},
            {"mean_recall", s.mean_recall},
            {"empty", s.empty},
            {"seconds", total},
            {"seconds_per_object_mean", total / n},
            {"seconds_per_object_median", median(seconds)}};
  if(m == 0)
    j["seconds_per_object_mean_with_shared_graph"] = (total + shared) / n;
  return j;
}

Json methods_json(const std::vector<const Object_row*>& rows)
{
  Json j = Json::object();
  for(std::size_t m = 0; m < methods; ++m)
    j[method_names[m]] = method_json(rows, m);
  return j;
}

void print_header(const Pcl_parameters& o)
{
  std::ostringstream fixed, matched;
  fixed << "PCL, radius " << std::setprecision(3) << o.radius << " m";
  matched << "PCL, radius ours / " << o.source_weight;
  const std::string titles[methods] = {"ours (automatic radius R)", fixed.str(), "PCL, radius R (ours)", matched.str()};
  std::cerr << std::left << std::setw(31) << "";
  for(const std::string& t : titles)
    std::cerr << " | " << std::setw(31) << t;
  std::cerr << "\n" << std::setw(26) << "frame" << std::setw(5) << "objs";
  for(std::size_t m = 0; m < methods; ++m)
    std::cerr << " | " << std::setw(31) << "P/R pooled  P/R mean     ms/obj";
  std::cerr << "\n";
}

void print_row(const std::string& what, const Json& j)
{
  std::cerr << std::left << std::setw(26) << what << std::right << std::setw(4) << j["ours"]["objects"].get<std::size_t>()
            << " " << std::fixed;
  for(std::size_t m = 0; m < methods; ++m) {
    const Json& e = j[method_names[m]];
    std::cerr << " | " << std::setprecision(3) << e["pooled_precision"].get<double>() << "/"
              << e["pooled_recall"].get<double>() << "  " << e["mean_precision"].get<double>() << "/"
              << e["mean_recall"].get<double>() << std::setw(7) << std::setprecision(2)
              << 1000 * e["seconds_per_object_mean"].get<double>();
  }
  std::cerr << "\n";
}

Json object_json(const Object_row& r)
{
  Json j = {{"class", r.object_class}, {"location", r.location}, {"points", r.count[0].truth},
            {"segmented", r.segmented}, {"our_radius", r.our_radius}};
  for(std::size_t m = 0; m < methods; ++m) {
    const Segmentation_count& c = r.count[m];
    Json e = {{"segment_points", c.segment},
              {"correct_points", c.correct},
              {"precision", c.segment ? Json(double(c.correct) / double(c.segment)) : Json(nullptr)},
              {"recall", c.truth ? double(c.correct) / double(c.truth) : 0.0},
              {"seconds", r.seconds[m]}};
    if(m > 0)
      e["cloud_points"] = r.cloud[m];
    j[method_names[m]] = e;
  }
  return j;
}

// The objects of one frame with at least `minimum` points, segmented by the three methods.
std::vector<Object_row> run_frame(const Frame& f, std::size_t minimum, const Pcl_parameters& o)
{
  const PSOR::Background_removal_result bg = PSOR::remove_background(f.points);
  const real_frames::Segmentation_input in = real_frames::segmentation_input(f, bg);
  const PSOR::Segmentation_result seg = PSOR::segment_objects(in.points, in.at);
  const double shared = seg.preparation_seconds / double(std::max<std::size_t>(1, in.at.size()));
  std::vector<Object_row> rows;
  for(std::size_t k = 0; k < f.objects.size(); ++k) {
    const real_frames::Truth& t = f.objects[k];
    if(t.points.size() < minimum)
      continue;
    Object_row r;
    r.frame = f.name, r.object_class = t.object_class, r.location = t.location;
    for(Segmentation_count& c : r.count)
      c.truth = t.points.size();
    const auto a = std::size_t(std::find(in.asked.begin(), in.asked.end(), k) - in.asked.begin());
    if(a < in.asked.size()) {
      r.segmented = true;
      const PSOR::Object_segmentation& os = seg.objects[a];
      r.our_radius = os.radius, r.our_shared_seconds = shared;
      r.count[0].segment = os.points.size();
      r.count[0].correct = real_frames::correct_points(os.points, in.above, t.points);
      r.seconds[0] = os.seconds;
      const double ours = os.radius > 0 ? os.radius : o.radius;
      const double radii[methods] = {0, o.radius, ours, ours / o.source_weight};
      for(std::size_t m = 1; m < methods; ++m) {
        const Pcl_segment ps = pcl_min_cut(in.points, t.location, radii[m], o);
        r.count[m].segment = ps.points.size();
        r.count[m].correct = real_frames::correct_points(ps.points, in.above, t.points);
        r.seconds[m] = ps.seconds, r.cloud[m] = ps.cloud;
      }
    }
    rows.push_back(r);
  }
  return rows;
}

std::vector<const Object_row*> pointers(const std::vector<Object_row>& rows, const std::string& group = "")
{
  std::vector<const Object_row*> r;
  for(const Object_row& o : rows)
    if(group.empty() || real_frames::class_group(o.object_class) == group)
      r.push_back(&o);
  return r;
}

} // namespace

int main(int argc, char** argv)
{
  std::string data = SHAPE_ANALYSIS_LIDAR_DIR, output;
  std::vector<std::string> only;
  std::size_t minimum = 20;
  bool with_objects = true;
  Pcl_parameters o;
  const char* usage = "usage: bench_pcl_min_cut [--data DIR] [--frames a,b] [--minimum-points 20] [--radius R] "
                      "[--sigma S] [--neighbors K] [--source-weight W] [--margin M] [--no-objects] [--output FILE]\n";
  for(int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if(a == "--no-objects") {
      with_objects = false;
      continue;
    }
    if(a == "--help" || i + 1 >= argc) {
      std::cerr << usage;
      return a == "--help" ? 0 : 2;
    }
    const std::string v = argv[++i];
    if(a == "--data")
      data = v;
    else if(a == "--frames")
      only = bench_util::split(v);
    else if(a == "--minimum-points")
      minimum = std::stoul(v);
    else if(a == "--radius")
      o.radius = std::stod(v);
    else if(a == "--sigma")
      o.sigma = std::stod(v);
    else if(a == "--neighbors")
      o.neighbours = std::stoi(v);
    else if(a == "--source-weight")
      o.source_weight = std::stod(v);
    else if(a == "--margin")
      o.margin = std::stod(v);
    else if(a == "--output")
      output = v;
    else {
      std::cerr << "unknown option " << a << "\n" << usage;
      return 2;
    }
  }

  Json result = Json::object();
  result["benchmark"] = "pcl_min_cut";
  result["data"] = data;
  result["pcl_version"] = PCL_VERSION_PRETTY;
  const std::filesystem::path dir(data);
  const std::vector<std::string> names = real_frames::frame_names(dir, only);
  if(names.empty()) {
    result["skipped"] = "no *.bin frame in " + data;
    std::cout << SAS::to_text(result) << std::endl;
    return 0;
  }
  result["minimum_points"] = minimum;
  result["location"] = "the true location: box centre (x, y) at the bottom of the box, for an instance the middle "
                       "of its horizontal extent at its lowest point (PCL uses only its horizontal position)";
  result["ours"] = "segment_objects() with its defaults (min-cut, automatic radius), all the frame's locations in one call";
  result["pcl"] = {{"radius_fixed", o.radius},
                   {"radius_ours", "the radius R segment_objects() chose for the object"},
                   {"radius_matched", "R / source_weight: PCL's data term turns at R, as ours does"},
                   {"sigma", o.sigma}, {"number_of_neighbours", o.neighbours}, {"source_weight", o.source_weight},
                   {"cloud", "the points above the ground within radius + margin horizontally"}, {"margin", o.margin}};

  print_header(o);
  std::vector<Object_row> all;
  Json frames = Json::array();
  for(const std::string& name : names) {
    const Frame f = real_frames::read_frame(dir, name);
    const std::vector<Object_row> rows = run_frame(f, minimum, o);
    Json e = {{"frame", name}, {"points", f.points.size()}, {"methods", methods_json(pointers(rows))}};
    print_row(name, e["methods"]);
    if(with_objects) {
      Json oj = Json::array();
      for(const Object_row& r : rows)
        oj.push_back(object_json(r));
      e["objects"] = oj;
    }
    frames.push_back(e);
    all.insert(all.end(), rows.begin(), rows.end());
  }
  result["frames"] = frames;
  Json totals = methods_json(pointers(all));
  print_row("TOTAL", totals);
  Json kinds = Json::object();
  for(const char* g : {"car", "large vehicle", "person", "two-wheeler", "street furniture"})
    if(!pointers(all, g).empty()) {
      kinds[g] = methods_json(pointers(all, g));
      print_row(std::string("  ") + g, kinds[g]);
    }
  result["totals"] = totals;
  result["totals_by_kind"] = kinds;
  const std::string text = SAS::to_text(result);
  std::cout << text << std::endl;
  if(!output.empty())
    std::ofstream(output) << text << std::endl;
  return 0;
}
