// Copyright (c) 2026 CGAL Global Shape Analysis contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later

// The documented chain of Point_set_object_recognition on real labelled LIDAR frames (vehicle
// scanners: KITTI and SemanticKITTI HDL-64E, nuScenes 32 beams, Argoverse 2 two stacked 32
// beams; ../shared/data/lidar, see its README): remove_background(), then
//  - segmentation: segment_objects() at the TRUE locations (defaults: min-cut, automatic radius)
//    on the points that are not ground (points_above_ground()), against the truth: the points
//    inside each labelled box, or each SemanticKITTI instance (cars, persons, two-wheelers; poles
//    and signs (classes 80, 81) grouped together by 0.5 m single linkage). A true location is the
//    box centre (x, y) at the bottom of the box, or for an instance the middle of its horizontal
//    extent at its lowest point. Precision |S n T| / |S| and recall |S n T| / |T|, pooled over
//    the objects (sums) and as means per object (the precision of an empty segment is left out of
//    the mean and counted in `empty`); `pooled_recall_above_ground` counts only the truth points
//    that remove_background() did not call ground (what the segmentation can reach);
//  - localization: locate_objects() on the foreground with its defaults (connected components)
//    and with the normalized cut: the fraction of true objects with a location within 2 m and
//    1 m (horizontally);
//  - recognition, leave one frame out: car, pedestrian, cyclist or bicycle, and pole, bollard or
//    sign (SemanticKITTI labels poles and signs together); a random forest trained on the other
//    frames classifies each frame's candidates (locate_objects()), scored by evaluate_recognition()
//    within 1 m and 2 m;
//  - seconds per stage; per object the fate of its points in remove_background(), the ground
//    error under it, the radius and cut chosen, whether the seed lies on it, and the vertical
//    spacing of its scan lines (nearest point steeply above or below); per frame the sensor
//    height (depth of the ground points 3 to 15 m around the origin), the point spacing by range
//    and, for SemanticKITTI, the agreement of the ground with the labelled ground.
// Objects with >= 20 points and all objects are reported separately (targets of the project:
// segmentation precision and recall >= 0.85, localization within 2 m >= 0.85).
//
//   bench_real_scans [--data DIR] [--frames kitti_000003,...] [--threads 0] [--no-objects]
//                    [--output FILE]
//     overrides of the defaults (same values for every frame; then a second run "override"):
//     remove_background: --ground-cell C --ground-threshold T --isolation-radius R
//                        --minimum-neighbors K --background-spacing S --maximum-extent E
//     locate_objects:    --locate-spacing S --minimum-cluster N --maximum-cluster-height H
//                        --ncut-cell C --ncut-threshold T
//     segment_objects:   --method automatic|min-cut|components|radius --background-radius R
//                        --foreground-height H --cell C --neighbors K --sigma S
//                        --background-weight B --graph-size N --minimum-foreground N
//                        --max-cut C --segment-spacing S
//
// Measured (2026-12-04, the 8 frames of the README; 95 objects >= 20 points, 201 in all;
// segmentation precision / recall pooled and mean per object, localization within 2 m):
//   defaults           >= 20: pooled 0.922 / 0.922, mean 0.875 / 0.868, located 0.916 (within
//                      1 m 0.621; normalized cut 0.916); all: pooled 0.864 / 0.919, mean
//                      0.664 / 0.788, located 0.557. By kind (>= 20, mean): cars 0.959 / 0.847,
//                      large vehicles 0.974 / 0.534 (located 1 of 6: remove_background() drops
//                      components longer than 12 m), persons 0.821 / 0.965, street furniture
//                      0.690 / 0.959.
//   before the ground fit stopped 0.3 m above its plane and the automatic radius reached 7 m:
//                      >= 20: pooled 0.898 / 0.609 (one 12 m bus, 30% of the true points, 18 of
//                      its 10,497 segmented), mean 0.845 / 0.797, located 0.926; of the points
//                      missed on the other objects, 86% were called ground.
//   --ground-cell 10 --neighbors 16 --sigma 0.3 (best uniform overrides before those changes):
//                      >= 20: pooled 0.943 / 0.631, mean 0.911 / 0.872, located 0.895 (0.571 on
//                      the hilly nuScenes frame).
//   recognition, leave one frame out (random forest trained on the other 7 frames at their
//                      candidates: within 2 m of a true object its class, farther than 2 m from
//                      any labelled object background), 84 objects of 4 classes, precision /
//                      recall within 1 m (2 m): car 0.458 / 0.200 (0.667 / 0.291), pedestrian
//                      - / 0 (5 objects), cyclist or bicycle 1 / 1 (3), pole, bollard or sign
//                      0.750 / 0.619 (0.950 / 0.714); all 0.617 / 0.321 (0.809 / 0.405).
//                      2026-12-05, KITTI's candidates in its camera's view only, classes
//                      balanced, column features: car 0.559 / 0.345 (0.824 / 0.509),
//                      pedestrian 0 / 0 (1 predicted), cyclist or bicycle 1 / 0.333, pole,
//                      bollard or sign 0.643 / 0.762 (0.857 / 0.905); all 0.594 / 0.429
//                      (0.828 / 0.571).
//   Seconds for all 8 frames: remove_background 0.16, locate_objects 0.03 (normalized cut 0.17),
//   segment_objects 0.11.
//
// The frames, the input of the segmentation and its scores are real_frames.h's (shared with
// bench_pcl_min_cut). JSON to stdout and FILE; progress and a table per frame to stderr.

#include "real_frames.h"

#include <CGAL/Point_set_object_recognition/Object_classifiers.h>
#include <CGAL/Point_set_object_recognition/locate_objects.h>
#include <CGAL/Point_set_object_recognition/remove_background.h>
#include <CGAL/Point_set_object_recognition/segment_objects.h>
#include <CGAL/Point_set_object_recognition/train_object_classifier.h>
#include <Shape_analysis_support/Json.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <limits>
#include <string>
#include <unordered_map>
#include <vector>

namespace {

namespace PSOR = CGAL::Point_set_object_recognition;
namespace SAS = CGAL::Shape_analysis_support;
typedef SAS::Json Json;
using bench_util::seconds_since;
using real_frames::Frame;
using real_frames::Point;
using real_frames::Truth;
using real_frames::class_group;

double median(std::vector<double> v)
{
  if(v.empty())
    return std::numeric_limits<double>::quiet_NaN();
  std::nth_element(v.begin(), v.begin() + long(v.size() / 2), v.end());
  return v[v.size() / 2];
}

// ------------------------------------------------------------------------------------------
// Point spacing

// Per query point, the horizontal distance to its nearest neighbour (`along`: the spacing along a
// scan line) and the distance to its nearest neighbour steeply above or below it (|dz| at least
// twice the horizontal distance: the next scan line on an upright surface), both up to 1.5 m
// (NaN beyond), among `pool`.
class Spacing_grid
{
public:
  Spacing_grid(const std::vector<Point>& p, const std::vector<std::size_t>& pool) : m_p(p)
  {
    for(std::size_t i : pool)
      m_cells[key(p[i].x(), p[i].y(), p[i].z())].push_back(i);
  }

  void query(std::size_t i, double& along, double& across) const
  {
    const Point& q = m_p[i];
    const long ci = cell(q.x()), cj = cell(q.y()), ck = cell(q.z());
    double a2 = reach * reach, s2 = reach * reach;
    bool found_a = false, found_s = false;
    for(long dk = -3; dk <= 3; ++dk)
      for(long dj = -3; dj <= 3; ++dj)
        for(long di = -3; di <= 3; ++di) {
          const auto it = m_cells.find(pack(ci + di, cj + dj, ck + dk));
          if(it == m_cells.end())
            continue;
          for(std::size_t j : it->second) {
            if(j == i)
              continue;
            const double dx = m_p[j].x() - q.x(), dy = m_p[j].y() - q.y(), dz = m_p[j].z() - q.z();
            const double h2 = dx * dx + dy * dy, d2 = h2 + dz * dz;
            if(d2 < a2 && d2 > 1e-8)
              a2 = d2, found_a = true;
            if(dz * dz >= 4 * h2 && d2 < s2 && std::abs(dz) > 0.01)
              s2 = d2, found_s = true;
          }
        }
    along = found_a ? std::sqrt(a2) : std::numeric_limits<double>::quiet_NaN();
    across = found_s ? std::sqrt(s2) : std::numeric_limits<double>::quiet_NaN();
  }

private:
  static constexpr double side = 0.5, reach = 1.5;
  static long cell(double v) { return long(std::floor(v / side)); }
  static std::uint64_t pack(long i, long j, long k)
  {
    return (std::uint64_t(i + (1 << 20)) & 0x1FFFFF) | ((std::uint64_t(j + (1 << 20)) & 0x1FFFFF) << 21) |
           ((std::uint64_t(k + (1 << 20)) & 0x1FFFFF) << 42);
  }
  std::uint64_t key(double x, double y, double z) const { return pack(cell(x), cell(y), cell(z)); }

  const std::vector<Point>& m_p;
  std::unordered_map<std::uint64_t, std::vector<std::size_t>> m_cells;
};

double horizontal_range(const std::array<double, 3>& l) { return std::hypot(l[0], l[1]); }

// Per range band (metres from the sensor), the median spacings of the points above the ground.
Json spacing_by_range(const std::vector<Point>& p, const std::vector<std::size_t>& above)
{
  const Spacing_grid grid(p, above);
  const std::vector<double> bands = {0, 10, 20, 30, 50, 1000};
  std::vector<std::vector<double>> along(bands.size() - 1), across(bands.size() - 1);
  std::vector<std::size_t> asked(bands.size() - 1, 0);
  for(std::size_t k = 0; k < above.size(); k += 5) {
    const std::size_t i = above[k];
    const double r = std::hypot(p[i].x(), p[i].y());
    const std::size_t b = std::size_t(std::upper_bound(bands.begin(), bands.end(), r) - bands.begin()) - 1;
    if(b >= along.size())
      continue;
    double a, s;
    grid.query(i, a, s);
    ++asked[b];
    if(!std::isnan(a))
      along[b].push_back(a);
    if(!std::isnan(s))
      across[b].push_back(s);
  }
  Json j = Json::array();
  for(std::size_t b = 0; b + 1 < bands.size(); ++b) {
    Json e = Json::object();
    e["range_from"] = bands[b];
    e["range_to"] = bands[b + 1];
    e["points_sampled"] = asked[b];
    e["nearest_neighbor_median"] = median(along[b]);
    e["line_spacing_median"] = median(across[b]);
    e["no_line_within_1_5m"] = asked[b] ? 1.0 - double(across[b].size()) / double(asked[b]) : 0.0;
    j.push_back(e);
  }
  return j;
}

// The median spacing of the scan lines over the object's own points (NaN when none has a point
// steeply above or below within 1.5 m).
double object_line_spacing(const std::vector<Point>& p, const std::vector<std::size_t>& points)
{
  const Spacing_grid grid(p, points);
  std::vector<double> across;
  const std::size_t step = std::max<std::size_t>(1, points.size() / 400);
  for(std::size_t k = 0; k < points.size(); k += step) {
    double a, s;
    grid.query(points[k], a, s);
    if(!std::isnan(s))
      across.push_back(s);
  }
  return median(across);
}

// ------------------------------------------------------------------------------------------
// The pipeline

struct Settings
{
  PSOR::Remove_background_options background;
  PSOR::Locate_objects_options localization;
  PSOR::Segment_objects_options segmentation;
};

PSOR::Background_removal_result remove(const std::vector<Point>& p, const PSOR::Remove_background_options& o)
{
  return PSOR::remove_background(p, PSOR::parameters::ground_cell_size(o.ground_cell_size)
                                      .ground_threshold(o.ground_threshold)
                                      .isolation_radius(o.isolation_radius)
                                      .minimum_neighbors(o.minimum_neighbors)
                                      .component_spacing(o.component_spacing)
                                      .maximum_component_extent(o.maximum_component_extent));
}

PSOR::Localization_result locate(const std::vector<Point>& p, const PSOR::Locate_objects_options& o,
                                 PSOR::Localization_method method)
{
  return PSOR::locate_objects(p, PSOR::parameters::localization_method(method)
                                   .mean_shift_radius(o.mean_shift_radius)
                                   .component_spacing(o.component_spacing)
                                   .localization_cell_size(o.localization_cell_size)
                                   .normalized_cut_threshold(o.normalized_cut_threshold)
                                   .height_image_sigma(o.height_image_sigma)
                                   .height_image_threshold(o.height_image_threshold)
                                   .number_of_threads(o.number_of_threads)
                                   .minimum_cluster_size(o.minimum_cluster_size)
                                   .maximum_cluster_height(o.maximum_cluster_height));
}

PSOR::Segmentation_result segment(const std::vector<Point>& p, const std::vector<std::array<double, 3>>& at,
                                  const PSOR::Segment_objects_options& o)
{
  return PSOR::segment_objects(p, at, PSOR::parameters::segmentation_method(o.segmentation_method)
                                        .background_radius(o.background_radius)
                                        .foreground_height(o.foreground_height)
                                        .graph_cell_size(o.graph_cell_size)
                                        .number_of_neighbors(o.number_of_neighbors)
                                        .edge_sigma(o.edge_sigma)
                                        .background_weight(o.background_weight)
                                        .maximum_graph_size(o.maximum_graph_size)
                                        .minimum_foreground_size(o.minimum_foreground_size)
                                        .maximum_cut_cost(o.maximum_cut_cost)
                                        .component_spacing(o.component_spacing)
                                        .number_of_threads(o.number_of_threads));
}

std::string method_name(PSOR::Segmentation_method m)
{
  switch(m) {
  case PSOR::Segmentation_method::ALL_WITHIN_RADIUS: return "radius";
  case PSOR::Segmentation_method::CONNECTED_COMPONENTS: return "components";
  case PSOR::Segmentation_method::MIN_CUT: return "min-cut";
  default: return "automatic";
  }
}

Json settings_json(const Settings& s)
{
  Json j = Json::object();
  const auto& b = s.background;
  j["remove_background"] = {{"ground_cell_size", b.ground_cell_size}, {"ground_threshold", b.ground_threshold},
                            {"isolation_radius", b.isolation_radius}, {"minimum_neighbors", b.minimum_neighbors},
                            {"component_spacing", b.component_spacing},
                            {"maximum_component_extent", b.maximum_component_extent}};
  const auto& l = s.localization;
  j["locate_objects"] = {{"component_spacing", l.component_spacing}, {"minimum_cluster_size", l.minimum_cluster_size},
                         {"maximum_cluster_height", l.maximum_cluster_height},
                         {"localization_cell_size", l.localization_cell_size},
                         {"normalized_cut_threshold", l.normalized_cut_threshold}};
  const auto& g = s.segmentation;
  j["segment_objects"] = {{"segmentation_method", method_name(g.segmentation_method)},
                          {"background_radius", g.background_radius},
                          {"foreground_height", g.foreground_height},
                          {"graph_cell_size", g.graph_cell_size},
                          {"number_of_neighbors", g.number_of_neighbors},
                          {"edge_sigma", g.edge_sigma ? Json(*g.edge_sigma) : Json("default")},
                          {"background_weight", g.background_weight},
                          {"maximum_graph_size", g.maximum_graph_size},
                          {"minimum_foreground_size", g.minimum_foreground_size},
                          {"maximum_cut_cost", g.maximum_cut_cost},
                          {"component_spacing", g.component_spacing}};
  return j;
}

// What became of one true object.
struct Object_outcome
{
  std::string frame, object_class;
  std::array<double, 3> location{{0, 0, 0}};
  std::size_t truth = 0, ground = 0, isolated = 0, large = 0, foreground = 0;
  double ground_error = 0, line_spacing = 0;
  bool segmented = false; // false: the location lies outside the points above the ground
  std::size_t segment = 0, correct = 0;
  double radius = 0, cut_cost = 0;
  bool seed_on_object = false;
  double located = 0, located_ncut = 0; // the horizontal distance to the nearest location
};

struct Stage_seconds
{
  double background = 0, locate = 0, locate_ncut = 0, segment = 0, segment_preparation = 0;
};

// SemanticKITTI: how remove_background()'s ground agrees with the labelled ground (road,
// parking, sidewalk, other ground, lane marking, terrain) and objects (movable, poles, signs).
Json ground_by_labels(const std::vector<std::uint32_t>& label, const PSOR::Background_removal_result& bg)
{
  std::size_t ground = 0, ground_kept = 0, objects = 0, objects_ground = 0, vehicle = 0, vehicle_ground = 0;
  for(std::size_t i = 0; i < label.size(); ++i) {
    const unsigned c = label[i] & 0xFFFFu;
    const bool is_ground = bg.kind[i] == PSOR::Point_kind::GROUND;
    if(c == 40 || c == 44 || c == 48 || c == 49 || c == 60 || c == 72)
      ++ground, ground_kept += is_ground ? 0 : 1;
    else if((c >= 10 && c <= 32) || (c >= 252 && c <= 259) || c == 80 || c == 81) {
      ++objects, objects_ground += is_ground ? 1 : 0;
      if(c == 10 || c == 252)
        ++vehicle, vehicle_ground += is_ground ? 1 : 0;
    }
  }
  const auto ratio = [](std::size_t a, std::size_t b) { return b ? double(a) / double(b) : 0.0; };
  return {{"ground_points_not_called_ground", ratio(ground_kept, ground)},
          {"object_points_called_ground", ratio(objects_ground, objects)},
          {"car_points_called_ground", ratio(vehicle_ground, vehicle)}};
}

double nearest_location(const std::vector<PSOR::Object_location>& found, const std::array<double, 3>& at)
{
  double d = std::numeric_limits<double>::infinity();
  for(const PSOR::Object_location& l : found)
    d = std::min(d, std::hypot(l.position[0] - at[0], l.position[1] - at[1]));
  return d;
}

// The chain on one frame.
std::vector<Object_outcome> run_frame(const Frame& f, const Settings& s, const std::vector<double>& line_spacing,
                                      Stage_seconds& t, Json& scan, std::size_t& locations,
                                      std::size_t& locations_ncut)
{
  const std::vector<Point>& p = f.points;
  auto start = std::chrono::steady_clock::now();
  const PSOR::Background_removal_result bg = remove(p, s.background);
  t.background = seconds_since(start);
  std::vector<Point> fg;
  for(std::size_t i : bg.foreground)
    fg.push_back(p[i]);
  start = std::chrono::steady_clock::now();
  const PSOR::Localization_result cc = locate(fg, s.localization, PSOR::Localization_method::CONNECTED_COMPONENTS);
  t.locate = seconds_since(start);
  start = std::chrono::steady_clock::now();
  const PSOR::Localization_result nc = locate(fg, s.localization, PSOR::Localization_method::NORMALIZED_CUT);
  t.locate_ncut = seconds_since(start);
  locations = cc.locations.size(), locations_ncut = nc.locations.size();

  const real_frames::Segmentation_input in = real_frames::segmentation_input(f, bg);
  const std::vector<std::size_t>& above = in.above;
  const std::vector<std::size_t>& asked = in.asked; // objects segmented, in the order of in.at
  start = std::chrono::steady_clock::now();
  const PSOR::Segmentation_result seg = segment(in.points, in.at, s.segmentation);
  t.segment = seconds_since(start);
  t.segment_preparation = seg.preparation_seconds;

  std::vector<Object_outcome> out(f.objects.size());
  for(std::size_t k = 0; k < f.objects.size(); ++k) {
    const Truth& truth = f.objects[k];
    Object_outcome& o = out[k];
    o.frame = f.name, o.object_class = truth.object_class, o.location = truth.location;
    o.truth = truth.points.size();
    for(std::size_t i : truth.points)
      switch(bg.kind[i]) {
      case PSOR::Point_kind::GROUND: ++o.ground; break;
      case PSOR::Point_kind::ISOLATED: ++o.isolated; break;
      case PSOR::Point_kind::LARGE_COMPONENT: ++o.large; break;
      default: ++o.foreground;
      }
    o.ground_error = bg.ground.height(truth.location[0], truth.location[1]) - truth.location[2];
    o.line_spacing = line_spacing[k];
    o.located = nearest_location(cc.locations, truth.location);
    o.located_ncut = nearest_location(nc.locations, truth.location);
  }
  for(std::size_t a = 0; a < asked.size(); ++a) {
    const PSOR::Object_segmentation& os = seg.objects[a];
    Object_outcome& o = out[asked[a]];
    const std::vector<std::size_t>& truth = f.objects[asked[a]].points;
    o.segmented = true;
    o.segment = os.points.size();
    o.radius = os.radius, o.cut_cost = os.cut_cost;
    o.correct = real_frames::correct_points(os.points, above, truth);
    o.seed_on_object = os.seed != PSOR::Object_segmentation::no_point &&
                       std::binary_search(truth.begin(), truth.end(), above[os.seed]);
  }

  scan["points"] = p.size();
  scan["ground_points"] = bg.number_of_ground_points;
  scan["foreground_points"] = bg.foreground.size();
  // The sensor is at the origin: its height is that of the ground points 3 to 15 m around it.
  std::vector<double> near_ground;
  for(std::size_t i = 0; i < p.size(); ++i) {
    const double r = std::hypot(p[i].x(), p[i].y());
    if(bg.kind[i] == PSOR::Point_kind::GROUND && r > 3 && r < 15)
      near_ground.push_back(-p[i].z());
  }
  scan["sensor_height_estimate"] = median(near_ground);
  if(!f.label.empty())
    scan["ground_by_labels"] = ground_by_labels(f.label, bg);
  scan["spacing_by_range"] = spacing_by_range(p, above);
  return out;
}

// ------------------------------------------------------------------------------------------
// Figures

Json summary(const std::vector<const Object_outcome*>& objects, std::size_t locations, std::size_t locations_ncut)
{
  std::size_t reachable = 0, n2 = 0, n1 = 0, c2 = 0, c1 = 0, ground = 0, isolated = 0, large = 0, seed_on = 0;
  std::vector<real_frames::Segmentation_count> counts;
  for(const Object_outcome* o : objects) {
    counts.push_back({o->truth, o->segment, o->correct});
    reachable += o->truth - o->ground, ground += o->ground, isolated += o->isolated, large += o->large;
    seed_on += o->seed_on_object ? 1 : 0;
    n2 += o->located <= 2.0, n1 += o->located <= 1.0;
    c2 += o->located_ncut <= 2.0, c1 += o->located_ncut <= 1.0;
  }
  const real_frames::Segmentation_scores sc = real_frames::segmentation_scores(counts);
  const std::size_t truth = sc.truth;
  const double n = double(std::max<std::size_t>(1, objects.size()));
  const auto ratio = [](std::size_t a, std::size_t b) { return b ? double(a) / double(b) : 0.0; };
  Json j = Json::object();
  j["objects"] = objects.size();
  j["truth_points"] = truth;
  const double pp = sc.pooled_precision, pr = sc.pooled_recall, mp = sc.mean_precision, mr = sc.mean_recall;
  j["segmentation"] = {{"pooled_precision", pp},
                       {"pooled_recall", pr},
                       {"mean_precision", mp},
                       {"mean_recall", mr},
                       {"pooled_recall_above_ground", ratio(sc.correct, reachable)},
                       {"empty", sc.empty},
                       {"seed_on_object", seed_on},
                       {"truth_points_ground", ratio(ground, truth)},
                       {"truth_points_isolated", ratio(isolated, truth)},
                       {"truth_points_large_component", ratio(large, truth)},
                       {"meets_target_pooled", pp >= 0.85 && pr >= 0.85},
                       {"meets_target_mean", mp >= 0.85 && mr >= 0.85}};
  j["localization"] = {{"locations", locations},
                       {"within_2m", n2},
                       {"within_1m", n1},
                       {"fraction_within_2m", double(n2) / n},
                       {"fraction_within_1m", double(n1) / n},
                       {"meets_target", double(n2) / n >= 0.85}};
  j["localization_normalized_cut"] = {{"locations", locations_ncut},
                                      {"within_2m", c2},
                                      {"within_1m", c1},
                                      {"fraction_within_2m", double(c2) / n},
                                      {"fraction_within_1m", double(c1) / n},
                                      {"meets_target", double(c2) / n >= 0.85}};
  return j;
}

Json object_json(const Object_outcome& o)
{
  const auto finite = [](double v) { return std::isfinite(v) ? Json(v) : Json(nullptr); };
  Json j = Json::object();
  j["class"] = o.object_class;
  j["location"] = o.location;
  j["range"] = horizontal_range(o.location);
  j["points"] = o.truth;
  j["points_ground"] = o.ground;
  j["points_isolated"] = o.isolated;
  j["points_large_component"] = o.large;
  j["ground_error"] = o.ground_error;
  j["line_spacing"] = finite(o.line_spacing);
  j["segmented"] = o.segmented;
  j["segment_points"] = o.segment;
  j["correct_points"] = o.correct;
  j["precision"] = o.segment ? Json(double(o.correct) / double(o.segment)) : Json(nullptr);
  j["recall"] = o.truth ? double(o.correct) / double(o.truth) : 0.0;
  j["radius"] = o.radius;
  j["cut_cost"] = o.cut_cost;
  j["seed_on_object"] = o.seed_on_object;
  j["nearest_location"] = finite(o.located);
  j["nearest_location_normalized_cut"] = finite(o.located_ncut);
  return j;
}

std::vector<const Object_outcome*> select(const std::vector<Object_outcome>& all, std::size_t minimum,
                                          const std::string& group = "")
{
  std::vector<const Object_outcome*> r;
  for(const Object_outcome& o : all)
    if(o.truth >= minimum && (group.empty() || class_group(o.object_class) == group))
      r.push_back(&o);
  return r;
}

void print_line(const std::string& what, const Json& s)
{
  const Json& g = s["segmentation"];
  const Json& l = s["localization"];
  const Json& c = s["localization_normalized_cut"];
  std::cerr << std::fixed << std::setprecision(3) << "  " << std::left << std::setw(28) << what << std::right
            << std::setw(4) << s["objects"].get<std::size_t>() << " objects  seg P/R pooled "
            << g["pooled_precision"].get<double>() << "/" << g["pooled_recall"].get<double>() << "  mean "
            << g["mean_precision"].get<double>() << "/" << g["mean_recall"].get<double>() << "  loc<2m "
            << l["fraction_within_2m"].get<double>() << " (<1m " << l["fraction_within_1m"].get<double>()
            << ")  ncut<2m " << c["fraction_within_2m"].get<double>() << " (<1m "
            << c["fraction_within_1m"].get<double>() << ")\n";
}

// All frames with one setting.
Json run(const std::vector<Frame>& frames, const std::vector<std::vector<double>>& spacing, const Settings& s,
         const std::string& name, bool with_objects)
{
  std::cerr << "run \"" << name << "\":\n";
  Json j = Json::object();
  j["name"] = name;
  j["parameters"] = settings_json(s);
  Json fj = Json::array();
  std::vector<Object_outcome> all;
  std::size_t locations = 0, locations_ncut = 0;
  Stage_seconds total;
  for(std::size_t k = 0; k < frames.size(); ++k) {
    Stage_seconds t;
    Json scan = Json::object();
    std::size_t nl = 0, nn = 0;
    const std::vector<Object_outcome> out = run_frame(frames[k], s, spacing[k], t, scan, nl, nn);
    locations += nl, locations_ncut += nn;
    total.background += t.background, total.locate += t.locate, total.locate_ncut += t.locate_ncut;
    total.segment += t.segment, total.segment_preparation += t.segment_preparation;
    Json e = Json::object();
    e["frame"] = frames[k].name;
    e["scan"] = scan;
    e["seconds"] = {{"read", frames[k].read_seconds}, {"remove_background", t.background},
                    {"locate_objects", t.locate}, {"locate_objects_normalized_cut", t.locate_ncut},
                    {"segment_objects", t.segment}, {"segment_objects_preparation", t.segment_preparation}};
    e["objects_20_points"] = summary(select(out, 20), nl, nn);
    e["all_objects"] = summary(select(out, 0), nl, nn);
    print_line(frames[k].name + " (>=20 pts)", e["objects_20_points"]);
    if(with_objects) {
      Json oj = Json::array();
      for(const Object_outcome& o : out)
        oj.push_back(object_json(o));
      e["objects"] = oj;
    }
    fj.push_back(e);
    all.insert(all.end(), out.begin(), out.end());
  }
  j["frames"] = fj;
  Json totals = Json::object();
  totals["objects_20_points"] = summary(select(all, 20), locations, locations_ncut);
  totals["all_objects"] = summary(select(all, 0), locations, locations_ncut);
  Json groups = Json::object();
  for(const char* g : {"car", "large vehicle", "person", "two-wheeler", "street furniture"})
    if(!select(all, 20, g).empty()) {
      groups[g] = summary(select(all, 20, g), locations, locations_ncut);
      groups[g]["localization"].erase("locations");
      groups[g]["localization_normalized_cut"].erase("locations");
      print_line(std::string("  ") + g + " (>=20 points)", groups[g]);
    }
  totals["objects_20_points_by_kind"] = groups;
  totals["seconds"] = {{"remove_background", total.background}, {"locate_objects", total.locate},
                       {"locate_objects_normalized_cut", total.locate_ncut}, {"segment_objects", total.segment},
                       {"segment_objects_preparation", total.segment_preparation}};
  print_line("TOTAL (>=20 points)", totals["objects_20_points"]);
  print_line("TOTAL (all)", totals["all_objects"]);
  j["totals"] = totals;
  return j;
}

// ------------------------------------------------------------------------------------------
// Recognition, leave one frame out

// The classes recognized on the real frames; -1: not one of them. SemanticKITTI labels poles and
// signs together, so they are one class here.
const char* const recognition_classes[] = {"car", "pedestrian", "cyclist or bicycle", "pole, bollard or sign"};

int recognition_class(std::string c)
{
  std::transform(c.begin(), c.end(), c.begin(), [](unsigned char x) { return char(std::tolower(x)); });
  const auto has = [&](const char* w) { return c.find(w) != std::string::npos; };
  if(has("bicycl") || has("cyclist"))
    return 2;
  if(has("pedestrian") || has("person"))
    return 1;
  if(c == "car" || c == "moving-car" || c == "regular_vehicle")
    return 0;
  if(has("pole") || has("bollard") || has("sign"))
    return 3;
  return -1;
}

// Whether a place of a frame lies where its objects are labelled: KITTI's object frames label the
// camera's field of view only (about 90 degrees ahead, x forward), the other sets all around.
// Candidates elsewhere are neither background examples nor scored predictions: an unlabelled car
// behind the sensor would otherwise teach "background" from a car.
bool labelled_place(const std::string& frame, const std::array<double, 3>& at)
{
  if(frame.compare(0, 6, "kitti_") == 0)
    return at[0] > 0 && std::abs(at[1]) <= at[0];
  return true;
}

// Per frame: the features at its true objects of the four classes (>= 20 points) and at the
// candidates of locate_objects() away from every labelled object (background); then, for each
// frame, a random forest trained on the others classifies its candidates, scored within 1 m.
Json recognition_leave_one_frame_out(const std::vector<Frame>& frames)
{
  const std::size_t classes = 4;
  struct Data
  {
    std::vector<std::vector<double>> rows;
    std::vector<std::size_t> labels;
    std::vector<PSOR::Labelled_location> truth;
    std::vector<std::array<double, 3>> candidates;
    std::vector<std::vector<double>> candidate_rows;
  };
  std::vector<Data> data(frames.size());
  for(std::size_t k = 0; k < frames.size(); ++k) {
    const Frame& f = frames[k];
    const PSOR::Background_removal_result bg = PSOR::remove_background(f.points);
    std::vector<Point> above, fg;
    for(std::size_t i : PSOR::points_above_ground(bg))
      above.push_back(f.points[i]);
    for(std::size_t i : bg.foreground)
      fg.push_back(f.points[i]);
    Data& d = data[k];
    for(const PSOR::Object_location& l : PSOR::locate_objects(fg).locations)
      if(labelled_place(f.name, l.position))
        d.candidates.push_back(l.position);
    // Training examples at the candidates, as the test sees objects: a candidate within 2 m of a
    // true object of the four classes takes its class (the nearest), one farther than 2 m from
    // every labelled object is background, the others are left out.
    std::vector<std::array<double, 3>> at;
    for(const Truth& t : f.objects) {
      const int c = recognition_class(t.object_class);
      if(c >= 0 && t.points.size() >= 20) {
        PSOR::Labelled_location l;
        l.position = t.location, l.label = std::size_t(c);
        d.truth.push_back(l);
      }
    }
    for(const auto& c : d.candidates) {
      double nearest_any = 1e300, nearest = 1e300;
      std::size_t label = classes;
      for(const Truth& t : f.objects) {
        const double r = std::hypot(c[0] - t.location[0], c[1] - t.location[1]);
        nearest_any = std::min(nearest_any, r);
        const int k = recognition_class(t.object_class);
        if(k >= 0 && t.points.size() >= 20 && r < nearest)
          nearest = r, label = std::size_t(k);
      }
      if(nearest <= 2.0)
        at.push_back(c), d.labels.push_back(label);
      else if(nearest_any > 2.0)
        at.push_back(c), d.labels.push_back(classes);
    }
    if(!at.empty())
      d.rows = PSOR::extract_object_features(above, at).values;
    if(!d.candidates.empty())
      d.candidate_rows = PSOR::extract_object_features(above, d.candidates).values;
  }
  std::vector<PSOR::Class_recognition_score> sum(classes + 1), sum2(classes + 1); // within 1 m, 2 m
  Json per_frame = Json::array();
  for(std::size_t k = 0; k < frames.size(); ++k) {
    std::vector<std::vector<double>> rows;
    std::vector<std::size_t> labels;
    for(std::size_t j = 0; j < frames.size(); ++j)
      if(j != k) {
        rows.insert(rows.end(), data[j].rows.begin(), data[j].rows.end());
        labels.insert(labels.end(), data[j].labels.begin(), data[j].labels.end());
      }
    PSOR::Random_forest_object_classifier forest;
    // Balanced classes: each object example repeated so that every class has about as many as
    // the background (recall of all classes within 2 m 0.49 -> 0.57, precision 0.87 both ways,
    // before the column features; with them 0.83 / 0.57).
    std::vector<std::size_t> count(classes + 1, 0);
    for(std::size_t l : labels)
      ++count[l];
    const std::size_t n = rows.size();
    for(std::size_t i = 0; i < n; ++i)
      if(labels[i] < classes)
        for(std::size_t c = 1; c < count[classes] / count[labels[i]]; ++c)
          rows.push_back(rows[i]), labels.push_back(labels[i]);
    forest.train(rows, labels, classes + 1);
    std::vector<PSOR::Labelled_location> predicted(data[k].candidates.size());
    for(std::size_t c = 0; c < predicted.size(); ++c) {
      predicted[c].position = data[k].candidates[c];
      predicted[c].label = forest.predict(data[k].candidate_rows[c], predicted[c].confidence);
    }
    const auto s = PSOR::evaluate_recognition(predicted, data[k].truth, classes);
    const auto s2 = PSOR::evaluate_recognition(predicted, data[k].truth, classes, 2.0);
    for(std::size_t c = 0; c <= classes; ++c) {
      sum[c].predicted += s[c].predicted, sum[c].correct += s[c].correct;
      sum[c].objects += s[c].objects, sum[c].found += s[c].found;
      sum2[c].predicted += s2[c].predicted, sum2[c].correct += s2[c].correct;
      sum2[c].objects += s2[c].objects, sum2[c].found += s2[c].found;
    }
    per_frame.push_back({{"frame", frames[k].name}, {"objects", s[classes].objects}, {"predicted", s[classes].predicted},
                         {"precision", s[classes].precision}, {"recall", s[classes].recall}});
  }
  Json j;
  j["classifier"] = "random forest (50 trees, seed 0), trained on the other frames, classes balanced by repetition";
  j["frames"] = per_frame;
  std::cerr << "recognition, leave one frame out (random forest; objects >= 20 points):\n";
  for(std::size_t c = 0; c <= classes; ++c) {
    const std::string name = c < classes ? recognition_classes[c] : "all";
    for(auto* x : {&sum[c], &sum2[c]}) {
      x->precision = x->predicted == 0 ? 1.0 : double(x->correct) / double(x->predicted);
      x->recall = x->objects == 0 ? 1.0 : double(x->found) / double(x->objects);
      j[x == &sum[c] ? "classes_within_1m" : "classes_within_2m"][name] = {
          {"objects", x->objects}, {"found", x->found}, {"predicted", x->predicted},
          {"correct", x->correct}, {"precision", x->precision}, {"recall", x->recall}};
    }
    std::cerr << "  " << std::left << std::setw(24) << name << " P/R within 1 m " << std::fixed << std::setprecision(3)
              << sum[c].precision << " / " << sum[c].recall << ", within 2 m " << sum2[c].precision << " / "
              << sum2[c].recall << " (" << sum[c].objects << " objects, " << sum[c].predicted << " predicted)\n";
  }
  return j;
}

bool parse_method(const std::string& v, PSOR::Segmentation_method& m)
{
  if(v == "automatic")
    m = PSOR::Segmentation_method::MIN_CUT_AUTOMATIC_RADIUS;
  else if(v == "min-cut")
    m = PSOR::Segmentation_method::MIN_CUT;
  else if(v == "components")
    m = PSOR::Segmentation_method::CONNECTED_COMPONENTS;
  else if(v == "radius")
    m = PSOR::Segmentation_method::ALL_WITHIN_RADIUS;
  else
    return false;
  return true;
}

} // namespace

int main(int argc, char** argv)
{
  std::string data = SHAPE_ANALYSIS_LIDAR_DIR, output;
  std::vector<std::string> only;
  std::size_t threads = 0;
  bool with_objects = true, overridden = false;
  Settings o;
  const char* usage = "usage: bench_real_scans [--data DIR] [--frames a,b] [--threads N] [--no-objects] "
                      "[--output FILE] [overrides, see the source's first comment]\n";
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
    auto& b = o.background;
    auto& l = o.localization;
    auto& g = o.segmentation;
    bool tuning = true;
    if(a == "--data")
      data = v, tuning = false;
    else if(a == "--frames")
      only = bench_util::split(v), tuning = false;
    else if(a == "--threads")
      threads = std::stoul(v), tuning = false;
    else if(a == "--output")
      output = v, tuning = false;
    else if(a == "--ground-cell")
      b.ground_cell_size = std::stod(v);
    else if(a == "--ground-threshold")
      b.ground_threshold = std::stod(v);
    else if(a == "--isolation-radius")
      b.isolation_radius = std::stod(v);
    else if(a == "--minimum-neighbors")
      b.minimum_neighbors = std::stoul(v);
    else if(a == "--background-spacing")
      b.component_spacing = std::stod(v);
    else if(a == "--maximum-extent")
      b.maximum_component_extent = std::stod(v);
    else if(a == "--locate-spacing")
      l.component_spacing = std::stod(v);
    else if(a == "--minimum-cluster")
      l.minimum_cluster_size = std::stoul(v);
    else if(a == "--maximum-cluster-height")
      l.maximum_cluster_height = std::stod(v);
    else if(a == "--ncut-cell")
      l.localization_cell_size = std::stod(v);
    else if(a == "--ncut-threshold")
      l.normalized_cut_threshold = std::stod(v);
    else if(a == "--method") {
      if(!parse_method(v, g.segmentation_method)) {
        std::cerr << "unknown method " << v << "\n";
        return 2;
      }
    } else if(a == "--background-radius")
      g.background_radius = std::stod(v);
    else if(a == "--foreground-height")
      g.foreground_height = std::stod(v);
    else if(a == "--cell")
      g.graph_cell_size = std::stod(v);
    else if(a == "--neighbors")
      g.number_of_neighbors = std::stoul(v);
    else if(a == "--sigma")
      g.edge_sigma = std::stod(v);
    else if(a == "--background-weight")
      g.background_weight = std::stod(v);
    else if(a == "--graph-size")
      g.maximum_graph_size = std::stoul(v);
    else if(a == "--minimum-foreground")
      g.minimum_foreground_size = std::stoul(v);
    else if(a == "--max-cut")
      g.maximum_cut_cost = std::stod(v);
    else if(a == "--segment-spacing")
      g.component_spacing = std::stod(v);
    else {
      std::cerr << "unknown option " << a << "\n" << usage;
      return 2;
    }
    overridden = overridden || tuning;
  }
  o.localization.number_of_threads = o.segmentation.number_of_threads = threads;

  Json result = Json::object();
  result["benchmark"] = "real_scans";
  result["data"] = data;
  const std::filesystem::path dir(data);
  const std::vector<std::string> names = real_frames::frame_names(dir, only);
  if(names.empty()) {
    result["skipped"] = "no *.bin frame in " + data;
    std::cout << SAS::to_text(result) << std::endl;
    return 0;
  }

  std::vector<Frame> frames;
  std::vector<std::vector<double>> spacing;
  for(const std::string& name : names) {
    frames.push_back(real_frames::read_frame(dir, name));
    const Frame& f = frames.back();
    std::size_t mismatched = 0;
    std::vector<double> s;
    for(const Truth& t : f.objects) {
      mismatched += t.listed_points >= 0 && std::size_t(t.listed_points) != t.points.size();
      s.push_back(object_line_spacing(f.points, t.points));
    }
    spacing.push_back(s);
    std::cerr << name << ": " << f.points.size() << " points, " << f.objects.size() << " objects"
              << (mismatched ? ", " + std::to_string(mismatched) + " boxes whose point count differs from the file's" : "")
              << "\n";
  }

  Json runs = Json::array();
  runs.push_back(run(frames, spacing, Settings{PSOR::Remove_background_options(), [&] {
                       PSOR::Locate_objects_options l;
                       l.number_of_threads = threads;
                       return l;
                     }(), [&] {
                       PSOR::Segment_objects_options g;
                       g.number_of_threads = threads;
                       return g;
                     }()}, "default", with_objects));
  if(overridden)
    runs.push_back(run(frames, spacing, o, "override", with_objects));
  result["runs"] = runs;
  result["recognition_leave_one_frame_out"] = recognition_leave_one_frame_out(frames);
  const std::string text = SAS::to_text(result);
  std::cout << text << std::endl;
  if(!output.empty())
    std::ofstream(output) << text << std::endl;
  return 0;
}
