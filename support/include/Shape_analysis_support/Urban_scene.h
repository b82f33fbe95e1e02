// Copyright (c) 2026 CGAL Global Shape Analysis contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef SHAPE_ANALYSIS_SUPPORT_URBAN_SCENE_H
#define SHAPE_ANALYSIS_SUPPORT_URBAN_SCENE_H

// Ground-truth data for object recognition in city LIDAR: a procedural street scene (sloped
// ground with a two-lane road and raised sidewalks, buildings, trees and the small objects of
// the thesis' classes, with clutter) made of triangles, scanned by a simulated mobile LIDAR (two
// rotating line scanners tilted by +-30 degrees about the vertical, on a vehicle driving along the
// centre line) and optionally by an airborne pass (vertical rays on a regular grid); the scanning
// itself is in Urban_scan.h.
//
// Deterministic: the scene is drawn from streams seeded by (seed, k) and every scan line from its
// own stream seeded by (seed, line index), so that the points are identical for any thread count.
//
// Frame: x along the street (scanner path from x = 0 to street_length), y across (road centre at
// y = 0), z up. Objects stand on the sidewalks (|y| in [road_half_width, facade_y]) or, for cars,
// on the road next to the curb; buildings span |y| in [facade_y, back_y]. Road users (pedestrians,
// cyclists, cars in the lanes) and vegetation are off by default (Urban_road_users.h).

#include <CGAL/Shape_analysis/Bad_input.h>
#include <CGAL/Shape_analysis/internal/Random.h>

#include <CGAL/Bbox_3.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <ostream>
#include <string>
#include <vector>

namespace CGAL {
namespace Shape_analysis_support {

// Kinds of surfaces: background (ground, building, tree, vegetation: bushes, hedges, shrubs) and
// the object classes: the 16 of the thesis, then the road users PEDESTRIAN and CYCLIST (a person
// on a bicycle, or a parked bicycle: the real data's "cyclist or bicycle").
enum Object_class : int {
  BACKGROUND = 0, GROUND = 1, BUILDING = 2, TREE = 3, VEGETATION = 4,
  SHORT_POST = 10, TALL_POST, LAMP_POST, LIGHT_STANDARD, SIGN, TRAFFIC_LIGHT, CAR, FIRE_HYDRANT,
  TRASH_CAN, NEWSPAPER_BOX, PARKING_METER, MAILING_BOX, RECYCLE_BIN, ADVERTISING_CYLINDER,
  TRAFFIC_CONTROL_BOX, A_FRAME_SIGN, PEDESTRIAN, CYCLIST
};
constexpr int first_object_class = SHORT_POST;
constexpr int last_object_class = CYCLIST;
constexpr int number_of_object_classes = last_object_class - first_object_class + 1;
// The thesis' classes (SHORT_POST to A_FRAME_SIGN): the street furniture of the default scene.
constexpr int number_of_thesis_classes = A_FRAME_SIGN - SHORT_POST + 1;

inline bool is_object_class(int c) { return c >= first_object_class && c <= last_object_class; }

inline const char* object_class_name(int c)
{
  static const char* const objects[] = {
    "short post", "tall post", "lamp post", "light standard", "sign", "traffic light", "car",
    "fire hydrant", "trash can", "newspaper box", "parking meter", "mailing box", "recycle bin",
    "advertising cylinder", "traffic control box", "A-frame sign", "pedestrian", "cyclist"};
  static_assert(sizeof(objects) / sizeof(objects[0]) == number_of_object_classes, "one name per class");
  static const char* const background[] = {"background", "ground", "building", "tree", "vegetation"};
  if(c >= 0 && c <= VEGETATION)
    return background[c];
  if(is_object_class(c))
    return objects[c - first_object_class];
  return "unknown";
}

struct Urban_scene_options
{
  std::uint64_t seed = 1;
  double street_length = 200.;      // m, scanner path length along x
  std::size_t objects_per_100m = 30; // objects of the thesis' classes, both sides together
  double tree_probability = 0.7;     // per tree slot (every 10-18 m on each side)
  // Road users and vegetation (Urban_road_users.h), none by default. Pedestrians walk or stand on
  // the sidewalks (a quarter in pairs) or cross the road (one in five); cyclists ride along the
  // outer edge of the lanes (seven in ten) or are parked bicycles on the sidewalks, alone against
  // a wall or in racks; cars drive in both lanes. Nothing is put within 3.5 m (along the street)
  // of the rotating sensor's positions in its lane, nor across the profile scanners' path.
  double pedestrians_per_100m = 0.;
  double cyclists_per_100m = 0.;
  double lane_cars_per_100m = 0.;  // cars in the driving lanes (parked cars are objects_per_100m's)
  double vegetation_per_100m = 0.; // hedges, bushes and low shrubs; > 0 also makes trees irregular
  // Mobile scanner.
  std::size_t target_points = 1000000; // mobile points wanted (roughly); 0: use the two below
  double profile_spacing = 0.05;       // m of travel between scan lines (if target_points == 0)
  double angular_step = 0.005;         // rad between rays of a line (if target_points == 0)
  double isotropic_range = 10.;        // with target_points: angular_step = spacing / this
  double scanner_height = 2.;          // m above the road
  double max_range = 60.;              // m
  double range_noise = 0.015;          // m, standard deviation of the Gaussian range error
  // Rotating multi-beam sensor (a Velodyne on a car in the right lane) instead of the two profile
  // scanners: one full turn every `sweep_spacing` metres of travel, `beams` lasers at elevations
  // spread evenly over [lowest_elevation, highest_elevation], a firing every `azimuth_step`;
  // target_points is then ignored (the sweeps set the density), scanner_height and max_range
  // still apply. The lasers' defaults are an HDL-64E's (KITTI's sensor, 1.73 m above the road).
  bool rotating_sensor = false;
  std::size_t beams = 64;
  double lowest_elevation = -24.8;  // degrees
  double highest_elevation = 2.0;   // degrees
  double azimuth_step = 0.17;       // degrees
  double sweep_spacing = 10.;       // m
  double lane_offset = -2.;         // y of the sensor's path
  // Airborne pass (added to the mobile points).
  bool airborne = false;
  double airborne_spacing = 0.5; // m, grid step
  double airborne_height = 500.; // m
  std::size_t number_of_threads = 0; // 0: TBB's choice
};

// One object of the ground truth. (x, y, z): location at ground level.
struct Urban_object
{
  int id = 0; // 1, 2, ...
  int object_class = 0;
  double x = 0, y = 0, z = 0;
  double height = 0;
  CGAL::Bbox_3 bbox; // of its triangles
};

struct Urban_scene
{
  typedef CGAL::Epick K;
  // Street geometry (m).
  double road_half_width = 5.5; // two 3.5 m lanes plus parking strips
  double facade_y = 10.;        // sidewalk from road_half_width to facade_y
  double back_y = 24.;          // buildings from facade_y to back_y
  double curb_height = 0.15;
  double margin = 30.;          // ground and buildings extend this far beyond the path ends
  double street_length = 200.;
  std::vector<K::Triangle_3> triangles;
  std::vector<int> triangle_instance; // object id, 0 for background
  std::vector<int> triangle_class;
  std::vector<Urban_object> objects;
  std::vector<CGAL::Bbox_3> buildings;

  // Smooth terrain (road level) and ground height including the curb step of the sidewalks.
  static double terrain(double x, double y)
  {
    const double pi = 3.14159265358979323846;
    return 0.02 * x + 0.25 * std::sin(2 * pi * x / 130.) + 0.004 * y +
           0.08 * std::sin(2 * pi * y / 50. + x / 70.);
  }
  double ground_height(double x, double y) const
  {
    return terrain(x, y) + (std::abs(y) > road_half_width ? curb_height : 0.);
  }
};

struct Urban_scan_point
{
  double x, y, z;
  int instance;    // object id, 0 for background
  int label;       // Object_class
  float intensity; // in [0, 1]
  bool airborne;
};

struct Urban_scan
{
  std::vector<Urban_scan_point> points; // mobile points by scan line, then airborne points
  std::size_t mobile_points = 0;
  std::size_t scan_lines = 0;  // profile lines, or sweeps of the rotating sensor
  double profile_spacing = 0, angular_step = 0;
};

namespace urban_detail {

typedef std::array<double, 3> V3;
struct Box { double lo[3], hi[3]; };

inline Box empty_box() { return Box{{1e300, 1e300, 1e300}, {-1e300, -1e300, -1e300}}; }
inline void grow(Box& b, const V3& p)
{
  for(int i = 0; i < 3; ++i) {
    b.lo[i] = (std::min)(b.lo[i], p[i]);
    b.hi[i] = (std::max)(b.hi[i], p[i]);
  }
}
inline bool overlap(const Box& a, const Box& b, double tol)
{
  for(int i = 0; i < 3; ++i)
    if(a.hi[i] - tol <= b.lo[i] || b.hi[i] - tol <= a.lo[i])
      return false;
  return true;
}

inline V3 add(const V3& a, const V3& b) { return {a[0] + b[0], a[1] + b[1], a[2] + b[2]}; }
inline V3 mul(const V3& a, double s) { return {a[0] * s, a[1] * s, a[2] * s}; }
inline V3 cross(const V3& a, const V3& b)
{
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
inline V3 unit(const V3& a)
{
  double l = std::sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]);
  return mul(a, 1. / l);
}

// A shape in its own frame (origin at ground level, local +y towards the road), as triangles and
// one bounding box per primitive (used to keep objects from interpenetrating).
struct Shape
{
  std::vector<std::array<V3, 3>> tris;
  std::vector<Box> parts;
  void tri(const V3& a, const V3& b, const V3& c) { tris.push_back({a, b, c}); }
  void close_part(std::size_t first)
  {
    Box b = empty_box();
    for(std::size_t i = first; i < tris.size(); ++i)
      for(const V3& p : tris[i])
        grow(b, p);
    parts.push_back(b);
  }
  // Box centred at c with axes u, v, w (unit, orthogonal) and half sizes h.
  void box(const V3& c, const V3& h, const V3& u = {1, 0, 0}, const V3& v = {0, 1, 0},
           const V3& w = {0, 0, 1})
  {
    std::size_t first = tris.size();
    V3 p[8];
    for(int i = 0; i < 8; ++i)
      p[i] = add(add(add(c, mul(u, (i & 1) ? h[0] : -h[0])), mul(v, (i & 2) ? h[1] : -h[1])),
                 mul(w, (i & 4) ? h[2] : -h[2]));
    static const int q[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4},
                                {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
    for(const auto& f : q) {
      tri(p[f[0]], p[f[1]], p[f[2]]);
      tri(p[f[0]], p[f[2]], p[f[3]]);
    }
    close_part(first);
  }
  void aabox(double x0, double y0, double z0, double x1, double y1, double z1)
  {
    box({(x0 + x1) / 2, (y0 + y1) / 2, (z0 + z1) / 2}, {(x1 - x0) / 2, (y1 - y0) / 2, (z1 - z0) / 2});
  }
  // Capped cylinder from a to b.
  void cylinder(const V3& a, const V3& b, double r, int n = 12)
  {
    std::size_t first = tris.size();
    V3 axis = unit({b[0] - a[0], b[1] - a[1], b[2] - a[2]});
    V3 e1 = unit(cross(axis, std::abs(axis[2]) < 0.9 ? V3{0, 0, 1} : V3{1, 0, 0}));
    V3 e2 = cross(axis, e1);
    const double pi = 3.14159265358979323846;
    for(int i = 0; i < n; ++i) {
      double t0 = 2 * pi * i / n, t1 = 2 * pi * (i + 1) / n;
      V3 d0 = add(mul(e1, r * std::cos(t0)), mul(e2, r * std::sin(t0)));
      V3 d1 = add(mul(e1, r * std::cos(t1)), mul(e2, r * std::sin(t1)));
      V3 a0 = add(a, d0), a1 = add(a, d1), b0 = add(b, d0), b1 = add(b, d1);
      tri(a0, a1, b1);
      tri(a0, b1, b0);
      tri(a, a1, a0);
      tri(b, b0, b1);
    }
    close_part(first);
  }
  void post(double x, double y, double z0, double z1, double r, int n = 12)
  {
    cylinder({x, y, z0}, {x, y, z1}, r, n);
  }
  void ellipsoid(const V3& c, const V3& r, int nu = 14, int nv = 8)
  {
    std::size_t first = tris.size();
    const double pi = 3.14159265358979323846;
    auto at = [&](int i, int j) {
      double phi = 2 * pi * i / nu, th = pi * j / nv;
      return V3{c[0] + r[0] * std::sin(th) * std::cos(phi), c[1] + r[1] * std::sin(th) * std::sin(phi),
                c[2] + r[2] * std::cos(th)};
    };
    for(int i = 0; i < nu; ++i)
      for(int j = 0; j < nv; ++j) {
        if(j > 0)
          tri(at(i, j), at(i + 1, j), at(i + 1, j + 1));
        if(j + 1 < nv)
          tri(at(i, j), at(i + 1, j + 1), at(i, j + 1));
      }
    close_part(first);
  }
  Box bounds(double below_z = 1e300) const
  {
    Box b = empty_box();
    for(const Box& p : parts)
      if(p.lo[2] < below_z) {
        grow(b, {p.lo[0], p.lo[1], p.lo[2]});
        grow(b, {p.hi[0], p.hi[1], p.hi[2]});
      }
    return b;
  }
};

typedef CGAL::Shape_analysis::internal::Random_stream Rng;

// The object of class `c` in its own frame, with realistic dimensions and some variation.
inline Shape make_object_shape(int c, Rng& rng)
{
  Shape s;
  const double b = -0.05; // bases sink a little into the (sloped) ground
  auto u = [&](double lo, double hi) { return rng.uniform(lo, hi); };
  switch(c) {
  case SHORT_POST: {
    double h = u(0.8, 1.1), r = u(0.08, 0.13);
    s.post(0, 0, b, h, r);
    if(rng.uniform() < 0.5)
      s.post(0, 0, h, h + 0.06, r * 1.25);
    break;
  }
  case TALL_POST:
    s.post(0, 0, b, u(2.2, 2.8), u(0.04, 0.07));
    break;
  case LAMP_POST: {
    double h = u(5., 8.), arm = u(1.2, 2.2);
    s.post(0, 0, b, h, u(0.09, 0.13));
    s.cylinder({0, 0, h - 0.15}, {0, arm, h - 0.05}, 0.045, 8);
    s.aabox(-0.18, arm - 0.05, h - 0.35, 0.18, arm + 0.55, h - 0.1);
    break;
  }
  case LIGHT_STANDARD: {
    double h = u(9., 11.), arm = u(2.5, 3.5);
    s.post(0, 0, b, h, u(0.15, 0.2));
    s.cylinder({0, 0, h - 0.2}, {0, arm, h}, 0.06, 8);
    s.aabox(-0.25, arm - 0.1, h - 0.35, 0.25, arm + 0.8, h - 0.05);
    break;
  }
  case SIGN: {
    double h = u(2.1, 2.6), w = u(0.45, 0.9), t = u(0.45, 0.9);
    s.post(0, 0, b, h, 0.035, 8);
    if(rng.uniform() < 0.5)
      s.aabox(-w / 2, 0.04, h - t, w / 2, 0.07, h + 0.05);
    else
      s.cylinder({0, 0.04, h - w / 2}, {0, 0.07, h - w / 2}, w / 2, 16);
    break;
  }
  case TRAFFIC_LIGHT: {
    double h = u(3., 4.2);
    s.post(0, 0, b, h, u(0.08, 0.12));
    s.aabox(-0.18, 0.1, h - 0.4, 0.18, 0.4, h + 0.65);
    if(rng.uniform() < 0.4) {
      double arm = u(3., 4.5);
      s.cylinder({0, 0, h - 0.3}, {0, arm, h - 0.3}, 0.07, 8);
      s.aabox(-0.18, arm - 0.3, h - 1.3, 0.18, arm, h - 0.35);
    }
    break;
  }
  case CAR: {
    double l = u(4.1, 4.9), w = u(1.7, 1.9), hb = u(0.7, 0.9), hc = u(0.5, 0.65);
    double wr = u(0.3, 0.35);
    s.aabox(-l / 2, -w / 2, wr * 0.9, l / 2, w / 2, wr * 0.9 + hb);
    double cl = l * u(0.5, 0.6), cx = u(-0.3, 0.1);
    s.aabox(cx - cl / 2, -w / 2 + 0.08, wr * 0.9 + hb, cx + cl / 2, w / 2 - 0.08, wr * 0.9 + hb + hc);
    for(int i = 0; i < 4; ++i) {
      double x = (i & 1 ? 1 : -1) * (l / 2 - 0.8), y = (i & 2 ? 1 : -1) * (w / 2 - 0.12);
      s.cylinder({x, y - 0.11, wr - 0.03}, {x, y + 0.11, wr - 0.03}, wr, 12);
    }
    break;
  }
  case FIRE_HYDRANT: {
    double h = u(0.55, 0.75);
    s.post(0, 0, b, h, 0.14, 12);
    s.post(0, 0, h, h + 0.1, 0.09, 10);
    s.cylinder({-0.24, 0, h * 0.65}, {0.24, 0, h * 0.65}, 0.05, 8);
    s.cylinder({0, 0, h * 0.6}, {0, 0.22, h * 0.6}, 0.065, 8);
    break;
  }
  case TRASH_CAN:
    s.post(0, 0, b, u(0.85, 1.05), u(0.26, 0.33), 14);
    break;
  case NEWSPAPER_BOX: {
    double w = u(0.42, 0.55), d = u(0.4, 0.5), h = u(0.95, 1.2);
    s.aabox(-w / 2, -d / 2, 0.25, w / 2, d / 2, h);
    s.aabox(-w / 2 + 0.03, -d / 2 + 0.03, b, w / 2 - 0.03, d / 2 - 0.03, 0.25);
    break;
  }
  case PARKING_METER: {
    double h = u(1.0, 1.2);
    s.post(0, 0, b, h, 0.035, 8);
    s.aabox(-0.11, -0.08, h, 0.11, 0.08, h + u(0.3, 0.4));
    break;
  }
  case MAILING_BOX: {
    double w = u(0.45, 0.55), d = u(0.45, 0.55), h = u(0.9, 1.05);
    s.aabox(-w / 2, -d / 2, b, w / 2, d / 2, h);
    s.cylinder({0, -d / 2, h}, {0, d / 2, h}, w / 2, 12);
    break;
  }
  case RECYCLE_BIN: {
    double w = u(0.6, 0.8), d = u(0.55, 0.7), h = u(0.95, 1.15);
    s.aabox(-w / 2, -d / 2, b, w / 2, d / 2, h);
    s.aabox(-w / 2 - 0.02, -d / 2 - 0.02, h, w / 2 + 0.02, d / 2 + 0.02, h + 0.06);
    break;
  }
  case ADVERTISING_CYLINDER: {
    double r = u(0.55, 0.65), h = u(2.7, 3.2);
    s.post(0, 0, b, h, r, 20);
    s.post(0, 0, h, h + 0.15, r + 0.1, 20);
    break;
  }
  case TRAFFIC_CONTROL_BOX: {
    double w = u(0.8, 1.2), d = u(0.4, 0.6), h = u(1.1, 1.5);
    s.aabox(-w / 2, -d / 2, b, w / 2, d / 2, h);
    break;
  }
  default: { // A-frame sign: two boards leaning on each other
    double w = u(0.55, 0.7), h = u(0.8, 1.0), a = u(0.22, 0.3), t = 0.012;
    double l = h / std::cos(a);
    for(int k = -1; k <= 1; k += 2) {
      V3 v = {0, std::cos(a), k * std::sin(a)}, ww = {0, -k * std::sin(a), std::cos(a)};
      s.box({0, k * (h / 2) * std::tan(a), h / 2 - 0.02}, {w / 2, t, l / 2}, {1, 0, 0}, v, ww);
    }
    break;
  }
  }
  return s;
}

inline Shape make_tree_shape(Rng& rng)
{
  Shape s;
  double trunk = rng.uniform(2.5, 4.), rt = rng.uniform(0.12, 0.22);
  double rc = rng.uniform(1.6, 2.4), rz = rng.uniform(1.8, 3.);
  s.post(0, 0, -0.05, trunk + rz * 0.4, rt, 10);
  s.ellipsoid({0, 0, trunk + rz}, {rc, rc * rng.uniform(0.85, 1.), rz});
  return s;
}

// Scene under construction: appends placed shapes and checks collisions.
struct Builder
{
  Urban_scene& scene;
  std::vector<std::pair<Box, int>> parts; // world boxes of placed parts, with owner

  // Places `s` at world (x, y, z) turned by `heading` about z. Returns false (and places nothing)
  // if it would cut into an already placed shape.
  bool place(const Shape& s, double x, double y, double z, double heading, int instance, int cls,
             bool check = true)
  {
    double c = std::cos(heading), sn = std::sin(heading);
    auto world = [&](const V3& p) { return V3{x + c * p[0] - sn * p[1], y + sn * p[0] + c * p[1], z + p[2]}; };
    std::vector<Box> wb;
    for(const Box& b : s.parts) {
      Box w = empty_box();
      for(int i = 0; i < 8; ++i)
        grow(w, world({(i & 1) ? b.hi[0] : b.lo[0], (i & 2) ? b.hi[1] : b.lo[1], (i & 4) ? b.hi[2] : b.lo[2]}));
      wb.push_back(w);
    }
    if(check)
      for(const Box& w : wb)
        for(const auto& p : parts)
          if(overlap(w, p.first, 0.005))
            return false;
    for(const Box& w : wb)
      parts.push_back({w, instance});
    Box all = empty_box();
    for(const auto& t : s.tris) {
      V3 a = world(t[0]), b = world(t[1]), d = world(t[2]);
      grow(all, a), grow(all, b), grow(all, d);
      scene.triangles.emplace_back(Urban_scene::K::Point_3(a[0], a[1], a[2]),
                                   Urban_scene::K::Point_3(b[0], b[1], b[2]),
                                   Urban_scene::K::Point_3(d[0], d[1], d[2]));
      scene.triangle_instance.push_back(instance);
      scene.triangle_class.push_back(cls);
    }
    if(instance > 0) {
      Urban_object o;
      o.id = instance, o.object_class = cls, o.x = x, o.y = y, o.z = z;
      o.height = all.hi[2] - z;
      o.bbox = CGAL::Bbox_3(all.lo[0], all.lo[1], all.lo[2], all.hi[0], all.hi[1], all.hi[2]);
      scene.objects.push_back(o);
    }
    return true;
  }
  void quad(const V3& a, const V3& b, const V3& c, const V3& d, int cls)
  {
    typedef Urban_scene::K::Point_3 P;
    for(int k = 0; k < 2; ++k) {
      const V3& q = k ? c : b;
      const V3& r = k ? d : c;
      scene.triangles.emplace_back(P(a[0], a[1], a[2]), P(q[0], q[1], q[2]), P(r[0], r[1], r[2]));
      scene.triangle_instance.push_back(0);
      scene.triangle_class.push_back(cls);
    }
  }
};

// In Urban_road_users.h (included at the end of this file).
inline Shape make_irregular_tree_shape(Rng& rng);
inline void add_vegetation(Builder& bd, const Urban_scene_options& o);
inline void add_road_users(Builder& bd, const Urban_scene_options& o, int& next_id);
inline void check_road_user_options(const Urban_scene_options& o);

} // namespace urban_detail

// Builds the street scene described by `o` (the scanner parameters are not used here, but for
// keeping road users off the scanner's path).
inline Urban_scene make_urban_scene(const Urban_scene_options& o)
{
  using namespace urban_detail;
  if(!(o.street_length > 1. && o.street_length <= 1e5))
    throw CGAL::Shape_analysis::Bad_input("Urban scene: street_length must be in (1, 1e5] m");
  if(o.objects_per_100m > 200)
    throw CGAL::Shape_analysis::Bad_input("Urban scene: objects_per_100m must be at most 200");
  check_road_user_options(o);
  Urban_scene sc;
  sc.street_length = o.street_length;
  Builder bd{sc, {}};
  const double L = o.street_length, R = sc.road_half_width, F = sc.facade_y, B = sc.back_y;
  const double x0 = -sc.margin, x1 = L + sc.margin;

  // Ground: road strip, curb faces, sidewalk strips (running under the buildings), ~1 m cells.
  const int nx = int(std::ceil(x1 - x0));
  auto ground_strip = [&](double ya, double yb, double dz) {
    int ny = (std::max)(1, int(std::ceil(std::abs(yb - ya))));
    for(int i = 0; i < nx; ++i)
      for(int j = 0; j < ny; ++j) {
        double xa = x0 + (x1 - x0) * i / nx, xb = x0 + (x1 - x0) * (i + 1) / nx;
        double y0 = ya + (yb - ya) * j / ny, y1 = ya + (yb - ya) * (j + 1) / ny;
        auto p = [&](double x, double y) { return V3{x, y, Urban_scene::terrain(x, y) + dz}; };
        bd.quad(p(xa, y0), p(xb, y0), p(xb, y1), p(xa, y1), GROUND);
      }
  };
  ground_strip(-R, R, 0.);
  ground_strip(R, B, sc.curb_height);
  ground_strip(-B, -R, sc.curb_height);
  for(int s = -1; s <= 1; s += 2)
    for(int i = 0; i < nx; ++i) {
      double xa = x0 + (x1 - x0) * i / nx, xb = x0 + (x1 - x0) * (i + 1) / nx, y = s * R;
      double za = Urban_scene::terrain(xa, y), zb = Urban_scene::terrain(xb, y);
      bd.quad({xa, y, za}, {xb, y, zb}, {xb, y, zb + sc.curb_height}, {xa, y, za + sc.curb_height}, GROUND);
    }

  // Buildings: boxes from the facade to the back line, 8-30 m wide, 6-25 m high, some gaps.
  Rng brng(o.seed, (std::uint64_t(1) << 40) + 1);
  for(int s = -1; s <= 1; s += 2) {
    double x = x0;
    while(x < x1) {
      double w = brng.uniform(8., 30.), h = brng.uniform(6., 25.);
      double xe = (std::min)(x + w, x1);
      double zmin = 1e300;
      for(double xx : {x, xe})
        for(double yy : {F, B})
          zmin = (std::min)(zmin, sc.ground_height(xx, s * yy));
      double zmax = sc.ground_height((x + xe) / 2, s * F) + h;
      Shape box;
      box.aabox(x, (std::min)(s * F, s * B), zmin - 0.5, xe, (std::max)(s * F, s * B), zmax);
      bd.place(box, 0, 0, 0, 0, 0, BUILDING, false);
      const Box& b = box.parts.back();
      sc.buildings.emplace_back(b.lo[0], b.lo[1], b.lo[2], b.hi[0], b.hi[1], b.hi[2]);
      x = xe + (brng.uniform() < 0.35 ? brng.uniform(0.8, 4.) : 0.);
    }
  }

  // Objects: classes drawn from bags (each bag holds every class, common ones several times),
  // placed at random along the street with some clutter groups.
  static const int bag_counts[number_of_thesis_classes] = {3, 2, 3, 1, 3, 1, 5, 1, 2, 2, 2, 1, 1, 1, 1, 1};
  std::vector<int> bag;
  Rng orng(o.seed, (std::uint64_t(1) << 40) + 2);
  auto next_class = [&]() {
    if(bag.empty()) {
      for(int c = 0; c < number_of_thesis_classes; ++c)
        for(int k = 0; k < bag_counts[c]; ++k)
          bag.push_back(first_object_class + c);
      for(std::size_t i = bag.size(); i > 1; --i)
        std::swap(bag[i - 1], bag[orng.index(i)]);
    }
    int c = bag.back();
    bag.pop_back();
    return c;
  };
  const std::size_t wanted = std::size_t(std::llround(double(o.objects_per_100m) * L / 100.));
  int next_id = 1;
  const double pi = 3.14159265358979323846;
  // A group: shapes placed side by side along local x (touching) at one distance from the curb.
  struct Member { Shape shape; int cls; double dx; };
  auto place_group = [&](std::vector<Member>& g, double x, int side, bool at_wall, double off) {
    double heading = side > 0 ? pi : 0.;
    Box front = empty_box();
    for(const Member& m : g) {
      Box b = m.shape.bounds(2.5);
      grow(front, {b.lo[0], b.lo[1], b.lo[2]});
      grow(front, {b.hi[0], b.hi[1], b.hi[2]});
    }
    if(at_wall)
      off = F - 0.01 - R + front.lo[1];
    else
      off = (std::max)(off, front.hi[1] + 0.08);
    double y = side * (R + off);
    std::size_t n_parts = bd.parts.size(), n_tris = sc.triangles.size(), n_obj = sc.objects.size();
    for(const Member& m : g) {
      double xx = x + std::cos(heading) * m.dx, yy = y + std::sin(heading) * m.dx;
      if(!bd.place(m.shape, xx, yy, sc.ground_height(xx, yy), heading, next_id, m.cls)) {
        bd.parts.resize(n_parts); // undo the group
        sc.triangles.resize(n_tris), sc.triangle_instance.resize(n_tris), sc.triangle_class.resize(n_tris);
        sc.objects.resize(n_obj);
        next_id -= int(&m - &g[0]);
        return false;
      }
      ++next_id;
    }
    return true;
  };
  for(std::size_t attempt = 0; sc.objects.size() < wanted && attempt < 20 * wanted + 20;) {
    int c = next_class();
    for(int tries = 0; tries < 20; ++tries, ++attempt) {
      double x = orng.uniform(1., L - 1.);
      int side = orng.uniform() < 0.5 ? -1 : 1;
      std::vector<Member> g;
      g.push_back({make_object_shape(c, orng), c, 0.});
      bool ok;
      if(c == CAR) {
        double heading = (orng.uniform() < 0.5 ? 0. : pi) + orng.uniform(-0.03, 0.03);
        double y = side * (R - 0.3 - g[0].shape.bounds().hi[1]);
        ok = bd.place(g[0].shape, x, y, Urban_scene::terrain(x, y), heading, next_id, CAR);
        if(ok)
          ++next_id;
      } else {
        bool at_wall = false;
        double off = orng.uniform(0.3, 0.9);
        double r = orng.uniform();
        auto gap = [&](const Shape& a, const Shape& b) {
          return a.bounds(2.5).hi[0] - b.bounds(2.5).lo[0] + orng.uniform(0.003, 0.02);
        };
        if(c == NEWSPAPER_BOX && r < 0.7) { // a row against a wall
          at_wall = true;
          int n = 2 + int(orng.index(3));
          for(int k = 1; k < n; ++k) {
            int ck = orng.uniform() < 0.2 ? MAILING_BOX : NEWSPAPER_BOX;
            Shape sh = make_object_shape(ck, orng);
            double dx = g.back().dx + gap(g.back().shape, sh);
            g.push_back({sh, ck, dx});
          }
        } else if(c == TRASH_CAN && r < 0.5) { // against a lamp post
          Shape lamp = make_object_shape(LAMP_POST, orng);
          double dx = gap(lamp, g[0].shape);
          g.insert(g.begin(), Member{lamp, LAMP_POST, 0.});
          g[1].dx = dx;
        } else if((c == MAILING_BOX || c == RECYCLE_BIN || c == TRAFFIC_CONTROL_BOX ||
                   c == A_FRAME_SIGN || c == ADVERTISING_CYLINDER || c == TRASH_CAN) && r < 0.5)
          at_wall = true;
        else if(c == PARKING_METER || c == FIRE_HYDRANT || c == SHORT_POST)
          off = orng.uniform(0.25, 0.6);
        ok = place_group(g, x, side, at_wall, off);
      }
      if(ok) {
        ++attempt;
        break;
      }
    }
  }

  // Trees along the curbs where there is room.
  Rng trng(o.seed, (std::uint64_t(1) << 40) + 3);
  for(int s = -1; s <= 1; s += 2)
    for(double x = trng.uniform(2., 12.); x < L; x += trng.uniform(10., 18.)) {
      Shape t = o.vegetation_per_100m > 0 ? make_irregular_tree_shape(trng) : make_tree_shape(trng);
      if(trng.uniform() >= o.tree_probability)
        continue;
      double y = s * (R + 1.5 + trng.uniform(-0.2, 0.2));
      bd.place(t, x, y, sc.ground_height(x, y), 0., 0, TREE);
    }
  add_vegetation(bd, o);
  add_road_users(bd, o, next_id);
  return sc;
}

inline void write_ground_truth(std::ostream& os, const std::vector<Urban_object>& objects)
{
  os << "# id class x y z height name\n";
  for(const Urban_object& b : objects)
    os << b.id << ' ' << b.object_class << ' ' << b.x << ' ' << b.y << ' ' << b.z << ' ' << b.height
       << ' ' << object_class_name(b.object_class) << '\n';
}

} // namespace Shape_analysis_support
} // namespace CGAL

#include <Shape_analysis_support/Urban_road_users.h>

#endif // SHAPE_ANALYSIS_SUPPORT_URBAN_SCENE_H
