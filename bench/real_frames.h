// Copyright (c) 2026 CGAL Global Shape Analysis contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_SHAPE_ANALYSIS_BENCH_REAL_FRAMES_H
#define CGAL_SHAPE_ANALYSIS_BENCH_REAL_FRAMES_H

// The real labelled LIDAR frames of ../shared/data/lidar (see its README) as the benchmarks read
// and score them (bench_real_scans, bench_pcl_min_cut):
//  - a frame: its points (`*.bin`) and its true objects: the points inside each labelled box
//    (`*.boxes.csv`), or each SemanticKITTI instance (`*.label`: cars, persons, two-wheelers;
//    poles and signs (classes 80, 81) grouped together by 0.5 m single linkage). A true location
//    is the box centre (x, y) at the bottom of the box, or for an instance the middle of its
//    horizontal extent at its lowest point;
//  - what a segmentation is given: the points remove_background() leaves above the ground
//    (points_above_ground()) and the true locations within their horizontal box;
//  - how a segmentation is scored: precision |S n T| / |S| and recall |S n T| / |T| against the
//    true object's points T, pooled over the objects (sums) and as means per object (the
//    precision of an empty segment is left out of the mean and counted in `empty`).

#include "bench_util.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Point_set_3.h>

#include <CGAL/Point_set_object_recognition/read_point_set.h>
#include <CGAL/Point_set_object_recognition/remove_background.h>
#include <CGAL/Point_set_object_recognition/segment_objects.h> // points_above_ground()

#include <algorithm>
#include <array>
#include <chrono>
#include <cctype>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <map>
#include <numeric>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#ifndef SHAPE_ANALYSIS_LIDAR_DIR
#define SHAPE_ANALYSIS_LIDAR_DIR "../shared/data/lidar"
#endif

namespace real_frames {

typedef CGAL::Exact_predicates_inexact_constructions_kernel::Point_3 Point;

// ------------------------------------------------------------------------------------------
// Ground truth

struct Truth
{
  std::string object_class;
  std::array<double, 3> location{{0, 0, 0}}; // x, y, base z
  std::vector<std::size_t> points;           // increasing
  long listed_points = -1;                   // the box file's count (boxes only)
};

struct Frame
{
  std::string name;
  std::vector<Point> points;
  std::vector<Truth> objects;
  std::vector<std::uint32_t> label; // SemanticKITTI: per point its label (empty for the others)
  double read_seconds = 0;
};

inline std::vector<std::string> csv_fields(const std::string& line)
{
  std::vector<std::string> f;
  std::stringstream in(line);
  std::string item;
  while(std::getline(in, item, ','))
    f.push_back(item);
  return f;
}

// The boxes of `file` (class,x,y,z,length,width,height,yaw,points) and the points inside each.
inline void read_boxes(const std::string& file, Frame& frame)
{
  std::ifstream in(file);
  std::string line;
  std::getline(in, line); // header
  while(std::getline(in, line)) {
    const std::vector<std::string> f = csv_fields(line);
    if(f.size() < 9)
      continue;
    const double x = std::stod(f[1]), y = std::stod(f[2]), z = std::stod(f[3]);
    const double l = std::stod(f[4]), w = std::stod(f[5]), h = std::stod(f[6]), yaw = std::stod(f[7]);
    if(f[0] == "ignore") // nuScenes' box of a region to ignore, not an object
      continue;
    Truth t;
    t.object_class = f[0];
    t.location = {{x, y, z - h / 2}};
    t.listed_points = std::stol(f[8]);
    const double c = std::cos(yaw), s = std::sin(yaw);
    for(std::size_t i = 0; i < frame.points.size(); ++i) {
      const Point& p = frame.points[i];
      const double dx = p.x() - x, dy = p.y() - y;
      const double u = c * dx + s * dy, v = -s * dx + c * dy;
      if(std::abs(u) <= l / 2 && std::abs(v) <= w / 2 && std::abs(p.z() - z) <= h / 2)
        t.points.push_back(i);
    }
    frame.objects.push_back(std::move(t));
  }
}

inline std::string semantic_kitti_name(unsigned c)
{
  static const std::map<unsigned, std::string> names = {
    {10, "car"}, {11, "bicycle"}, {13, "bus"}, {15, "motorcycle"}, {16, "on-rails"}, {18, "truck"},
    {20, "other-vehicle"}, {30, "person"}, {31, "bicyclist"}, {32, "motorcyclist"}, {80, "pole/sign"},
    {252, "moving-car"}, {253, "moving-bicyclist"}, {254, "moving-person"}, {255, "moving-motorcyclist"},
    {256, "moving-on-rails"}, {257, "moving-bus"}, {258, "moving-truck"}, {259, "moving-other-vehicle"}};
  const auto it = names.find(c);
  return it == names.end() ? std::to_string(c) : it->second;
}

// The kind of a class of any of the datasets.
inline std::string class_group(std::string c)
{
  std::transform(c.begin(), c.end(), c.begin(), [](unsigned char x) { return char(std::tolower(x)); });
  const auto has = [&](const char* w) { return c.find(w) != std::string::npos; };
  if(has("pedestrian") || has("person") || has("cyclist"))
    return "person";
  if(has("bicycle") || has("motorcycle"))
    return "two-wheeler";
  if(has("bus") || has("truck") || has("large") || has("construction") || has("trailer"))
    return "large vehicle";
  if(has("car") || has("vehicle"))
    return "car";
  return "street furniture"; // poles, signs, bollards, cones, barriers
}

// The instance's location: the middle of its horizontal extent, at its lowest point.
inline void locate_instance(const std::vector<Point>& p, Truth& t)
{
  double x0 = 1e300, x1 = -1e300, y0 = 1e300, y1 = -1e300, z0 = 1e300;
  for(std::size_t i : t.points) {
    x0 = std::min(x0, p[i].x()), x1 = std::max(x1, p[i].x());
    y0 = std::min(y0, p[i].y()), y1 = std::max(y1, p[i].y());
    z0 = std::min(z0, p[i].z());
  }
  t.location = {{(x0 + x1) / 2, (y0 + y1) / 2, z0}};
}

// SemanticKITTI labels: the instances of the movable classes, and poles with signs (classes 80
// and 81 together) as groups linked by 0.5 m.
inline void read_labels(const std::string& file, Frame& frame)
{
  std::ifstream in(file, std::ios::binary);
  std::vector<std::uint32_t>& label = frame.label;
  label.resize(frame.points.size());
  in.read(reinterpret_cast<char*>(label.data()), std::streamsize(label.size() * 4));
  if(!in)
    throw std::runtime_error(file + ": fewer labels than points");
  std::map<std::uint32_t, Truth> instance;
  std::vector<std::size_t> poles;
  for(std::size_t i = 0; i < label.size(); ++i) {
    const unsigned c = label[i] & 0xFFFFu, id = label[i] >> 16;
    const bool movable = (c >= 10 && c <= 32) || (c >= 252 && c <= 259);
    if(movable && id != 0) {
      Truth& t = instance[label[i]];
      t.object_class = semantic_kitti_name(c);
      t.points.push_back(i);
    } else if(c == 80 || c == 81)
      poles.push_back(i);
  }
  for(auto& kv : instance) {
    locate_instance(frame.points, kv.second);
    frame.objects.push_back(std::move(kv.second));
  }
  // Single linkage of the pole and sign points (a few hundred: all pairs).
  std::vector<std::size_t> parent(poles.size());
  std::iota(parent.begin(), parent.end(), 0);
  const auto find = [&](std::size_t a) {
    while(parent[a] != a)
      a = parent[a] = parent[parent[a]];
    return a;
  };
  for(std::size_t a = 0; a < poles.size(); ++a)
    for(std::size_t b = a + 1; b < poles.size(); ++b)
      if(CGAL::squared_distance(frame.points[poles[a]], frame.points[poles[b]]) <= 0.25)
        parent[find(a)] = find(b);
  std::map<std::size_t, Truth> groups;
  for(std::size_t a = 0; a < poles.size(); ++a) {
    Truth& t = groups[find(a)];
    t.object_class = "pole/sign";
    t.points.push_back(poles[a]);
  }
  for(auto& kv : groups) {
    locate_instance(frame.points, kv.second);
    frame.objects.push_back(std::move(kv.second));
  }
}

inline Frame read_frame(const std::filesystem::path& dir, const std::string& name)
{
  namespace PSOR = CGAL::Point_set_object_recognition;
  const auto start = std::chrono::steady_clock::now();
  Frame f;
  f.name = name;
  CGAL::Point_set_3<Point> set;
  PSOR::read_point_set((dir / (name + ".bin")).string(), set, PSOR::parameters::shift_to_local_origin(false));
  f.points.reserve(set.size());
  for(auto i : set)
    f.points.push_back(set.point(i));
  if(std::filesystem::exists(dir / (name + ".boxes.csv")))
    read_boxes((dir / (name + ".boxes.csv")).string(), f);
  if(std::filesystem::exists(dir / (name + ".label")))
    read_labels((dir / (name + ".label")).string(), f);
  f.read_seconds = bench_util::seconds_since(start);
  return f;
}

// The names of the frames of `dir` (its `*.bin` files without the extension, sorted), only those
// of `only` unless it is empty; none when `dir` is not a directory.
inline std::vector<std::string> frame_names(const std::filesystem::path& dir, const std::vector<std::string>& only)
{
  std::vector<std::string> names;
  if(std::filesystem::is_directory(dir))
    for(const auto& e : std::filesystem::directory_iterator(dir))
      if(e.path().extension() == ".bin" &&
         (only.empty() || std::find(only.begin(), only.end(), e.path().stem().string()) != only.end()))
        names.push_back(e.path().stem().string());
  std::sort(names.begin(), names.end());
  return names;
}

// ------------------------------------------------------------------------------------------
// What a segmentation is given

struct Segmentation_input
{
  std::vector<std::size_t> above;           // the frame's points above the ground (points_above_ground())
  std::vector<Point> points;                // those points
  std::vector<std::array<double, 3>> at;    // the true locations within their horizontal box
  std::vector<std::size_t> asked;           // per location of `at`, its object of the frame
};

inline Segmentation_input segmentation_input(const Frame& f,
                                             const CGAL::Point_set_object_recognition::Background_removal_result& bg)
{
  Segmentation_input in;
  in.above = CGAL::Point_set_object_recognition::points_above_ground(bg);
  for(std::size_t i : in.above)
    in.points.push_back(f.points[i]);
  // segment_objects() wants locations within the horizontal box of its points.
  double x0 = 1e300, x1 = -1e300, y0 = 1e300, y1 = -1e300;
  for(const Point& q : in.points)
    x0 = std::min(x0, q.x()), x1 = std::max(x1, q.x()), y0 = std::min(y0, q.y()), y1 = std::max(y1, q.y());
  for(std::size_t k = 0; k < f.objects.size(); ++k) {
    const auto& l = f.objects[k].location;
    if(l[0] >= x0 && l[0] <= x1 && l[1] >= y0 && l[1] <= y1)
      in.at.push_back(l), in.asked.push_back(k);
  }
  return in;
}

// ------------------------------------------------------------------------------------------
// Scores

// The points of a segment (indices into Segmentation_input::points) that are the true object's
// (`truth`: indices into the frame, increasing).
inline std::size_t correct_points(const std::vector<std::size_t>& segment, const std::vector<std::size_t>& above,
                                  const std::vector<std::size_t>& truth)
{
  std::size_t correct = 0;
  for(std::size_t q : segment)
    correct += std::binary_search(truth.begin(), truth.end(), above[q]) ? 1 : 0;
  return correct;
}

// One object's counts: its true points, its segment's points and those of them that are true.
struct Segmentation_count
{
  std::size_t truth = 0, segment = 0, correct = 0;
};

struct Segmentation_scores
{
  std::size_t objects = 0, truth = 0, segment = 0, correct = 0, empty = 0;
  double pooled_precision = 0, pooled_recall = 0, mean_precision = 0, mean_recall = 0;
};

inline Segmentation_scores segmentation_scores(const std::vector<Segmentation_count>& counts)
{
  Segmentation_scores s;
  double sum_p = 0, sum_r = 0;
  std::size_t n_p = 0;
  for(const Segmentation_count& c : counts) {
    s.segment += c.segment, s.truth += c.truth, s.correct += c.correct;
    if(c.segment > 0)
      sum_p += double(c.correct) / double(c.segment), ++n_p;
    else
      ++s.empty;
    sum_r += c.truth ? double(c.correct) / double(c.truth) : 0.0;
  }
  s.objects = counts.size();
  const auto ratio = [](std::size_t a, std::size_t b) { return b ? double(a) / double(b) : 0.0; };
  s.pooled_precision = ratio(s.correct, s.segment), s.pooled_recall = ratio(s.correct, s.truth);
  s.mean_precision = n_p ? sum_p / double(n_p) : 0.0;
  s.mean_recall = sum_r / double(std::max<std::size_t>(1, counts.size()));
  return s;
}

} // namespace real_frames

#endif // CGAL_SHAPE_ANALYSIS_BENCH_REAL_FRAMES_H
