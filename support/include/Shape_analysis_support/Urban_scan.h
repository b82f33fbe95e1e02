// Copyright (c) 2026 CGAL Global Shape Analysis contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef SHAPE_ANALYSIS_SUPPORT_URBAN_SCAN_H
#define SHAPE_ANALYSIS_SUPPORT_URBAN_SCAN_H

// The simulated LIDAR of the procedural street (Urban_scene.h): rays cast with CGAL's AABB tree, so
// occlusion and range-dependent density follow from the geometry; every scan line draws from its
// own stream seeded by (seed, line index), so the points are identical for any thread count.

#include <Shape_analysis_support/Urban_scene.h>
#include <CGAL/Shape_analysis/internal/Parallel.h>

#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/AABB_triangle_primitive.h>
#include <CGAL/Point_set_3.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace CGAL {
namespace Shape_analysis_support {

namespace urban_detail {

typedef Urban_scene::K K;
typedef std::vector<K::Triangle_3>::const_iterator Tri_iterator;
typedef CGAL::AABB_triangle_primitive<K, Tri_iterator> Primitive;
typedef CGAL::AABB_tree<CGAL::AABB_traits<K, Primitive>> Tree;

inline double gaussian(Rng& r)
{
  double u1 = 1. - r.uniform(), u2 = r.uniform();
  return std::sqrt(-2. * std::log(u1)) * std::cos(6.283185307179586 * u2);
}

inline float reflectivity(int c)
{
  switch(c) {
  case GROUND: return 0.25f;
  case BUILDING: return 0.45f;
  case TREE: return 0.35f;
  case SIGN: return 0.95f;
  case CAR: return 0.6f;
  case VEGETATION: return 0.4f;
  case PEDESTRIAN: return 0.3f;
  case CYCLIST: return 0.4f;
  default: return 0.5f;
  }
}

// Casts one ray; appends the noisy hit (if any, within max_range) to `out`.
inline void cast(const Tree& tree, const Urban_scene& sc, const K::Point_3& o, const K::Vector_3& d,
                 double max_range, double sigma, bool airborne, Rng& rng, std::vector<Urban_scan_point>& out)
{
  auto hit = tree.first_intersection(K::Ray_3(o, d));
  double noise = gaussian(rng); // drawn for every ray: the stream does not depend on hits
  if(!hit)
    return;
  const K::Point_3* p = boost::get<K::Point_3>(&hit->first);
  K::Point_3 q;
  if(p)
    q = *p;
  else { // ray in the plane of the triangle: nearer end of the overlap
    const K::Segment_3& s = boost::get<K::Segment_3>(hit->first);
    q = CGAL::squared_distance(o, s.source()) < CGAL::squared_distance(o, s.target()) ? s.source() : s.target();
  }
  double t = std::sqrt(CGAL::squared_distance(o, q));
  if(t > max_range)
    return;
  std::size_t f = std::size_t(hit->second - sc.triangles.begin());
  const K::Triangle_3& tr = sc.triangles[f];
  K::Vector_3 n = CGAL::cross_product(tr[1] - tr[0], tr[2] - tr[0]);
  double cosi = std::abs(n * d) / std::sqrt(n.squared_length() * d.squared_length());
  double dl = std::sqrt(d.squared_length());
  double s = (t + sigma * noise) / dl;
  Urban_scan_point sp;
  sp.x = o.x() + d.x() * s, sp.y = o.y() + d.y() * s, sp.z = o.z() + d.z() * s;
  sp.instance = sc.triangle_instance[f];
  sp.label = sc.triangle_class[f];
  double I = reflectivity(sp.label) * (0.3 + 0.7 * cosi) / (1. + (airborne ? 0. : t / 40.));
  sp.intensity = float((std::min)(1., (std::max)(0., I + 0.02 * gaussian(rng))));
  sp.airborne = airborne;
  out.push_back(sp);
}

} // namespace urban_detail

// Sweeps of the rotating multi-beam sensor along the street (see Urban_scene_options): sweep i at
// x = (i + 0.5) sweep_spacing, y = lane_offset, each laser firing every azimuth_step from a phase
// of its own; every sweep draws from its own stream.
inline Urban_scan scan_rotating(const Urban_scene& sc, const Urban_scene_options& o, const urban_detail::Tree& tree)
{
  using namespace urban_detail;
  const double degree = 3.14159265358979323846 / 180;
  if(o.beams < 1 || o.beams > 1024 || !(o.lowest_elevation >= -90 && o.lowest_elevation <= o.highest_elevation &&
                                        o.highest_elevation <= 90) ||
     !(o.azimuth_step >= 0.01 && o.azimuth_step <= 90) || !(o.sweep_spacing >= 0.1) || !std::isfinite(o.lane_offset))
    throw CGAL::Shape_analysis::Bad_input("Urban scene: rotating sensor parameter out of range (beams in [1, 1024], "
                                          "elevations in [-90, 90] increasing, azimuth_step in [0.01, 90] degrees, "
                                          "sweep_spacing >= 0.1 m)");
  const std::size_t sweeps = (std::max)(std::size_t(1), std::size_t(sc.street_length / o.sweep_spacing));
  const std::size_t firings = std::size_t(std::ceil(360 / o.azimuth_step));
  std::vector<std::vector<Urban_scan_point>> out(sweeps);
  CGAL::Shape_analysis::internal::Parallel_workspaces<char> parallel(o.number_of_threads);
  parallel.for_each(0, sweeps, [&](std::size_t i, char&) {
    Rng rng(o.seed, i);
    const double x = (double(i) + 0.5) * o.sweep_spacing;
    const K::Point_3 origin(x, o.lane_offset, Urban_scene::terrain(x, o.lane_offset) + o.scanner_height);
    for(std::size_t b = 0; b < o.beams; ++b) {
      const double e = (o.beams == 1 ? o.lowest_elevation
                                     : o.lowest_elevation + (o.highest_elevation - o.lowest_elevation) * double(b) /
                                                                double(o.beams - 1)) * degree;
      const double phase = rng.uniform();
      for(std::size_t j = 0; j < firings; ++j) {
        const double a = (double(j) + phase) * o.azimuth_step * degree;
        const K::Vector_3 d(std::cos(e) * std::cos(a), std::cos(e) * std::sin(a), std::sin(e));
        cast(tree, sc, origin, d, o.max_range, o.range_noise, false, rng, out[i]);
      }
    }
  });
  Urban_scan scan;
  scan.scan_lines = sweeps, scan.profile_spacing = o.sweep_spacing, scan.angular_step = o.azimuth_step * degree;
  for(auto& s : out) {
    scan.points.insert(scan.points.end(), s.begin(), s.end());
    std::vector<Urban_scan_point>().swap(s);
  }
  scan.mobile_points = scan.points.size();
  return scan;
}

// Scans `sc` with the mobile scanner (and the airborne pass if asked) described by `o`.
inline Urban_scan scan_urban_scene(const Urban_scene& sc, const Urban_scene_options& o)
{
  using namespace urban_detail;
  if(!(o.range_noise >= 0. && o.range_noise < 1.) || !(o.max_range > 0. && o.max_range < 1e4) ||
     !(o.isotropic_range > 0.) || !std::isfinite(o.scanner_height) || o.target_points > 1000000000 ||
     (o.airborne && !(o.airborne_spacing >= 0.01 && o.airborne_height > 0. && o.airborne_height < 1e5)))
    throw CGAL::Shape_analysis::Bad_input("Urban scene: scanner parameter out of range (range_noise "
                                          "in [0, 1), max_range in (0, 1e4), target_points <= 1e9, "
                                          "airborne_spacing >= 0.01)");
  Tree tree(sc.triangles.begin(), sc.triangles.end());
  tree.build();
  if(o.rotating_sensor) {
    if(o.airborne)
      throw CGAL::Shape_analysis::Bad_input("Urban scene: the rotating sensor has no airborne pass");
    return scan_rotating(sc, o, tree);
  }
  const double L = sc.street_length, pi = 3.14159265358979323846;
  const double tilt = pi / 6.;
  typedef std::vector<Urban_scan_point> Line;

  // Scan line i: scanner (i even: +tilt, odd: -tilt) at x = (i + 0.5) * dx.
  auto scan_line = [&](std::size_t i, double dx, double dth, double sigma, Rng rng, Line& out) {
    double x = (double(i) + 0.5) * dx;
    K::Point_3 org(x, 0., Urban_scene::terrain(x, 0.) + o.scanner_height);
    double a = (i % 2 == 0) ? tilt : -tilt, ca = std::cos(a), sa = std::sin(a);
    std::size_t m = std::size_t(std::ceil(2 * pi / dth));
    double phase = rng.uniform();
    for(std::size_t j = 0; j < m; ++j) {
      double th = (double(j) + phase) * (2 * pi / double(m));
      K::Vector_3 d(-sa * std::cos(th), ca * std::cos(th), std::sin(th));
      cast(tree, sc, org, d, o.max_range, sigma, false, rng, out);
    }
  };

  double dx = o.profile_spacing, dth = o.angular_step;
  if(o.target_points > 0) {
    // Pilot: a few noiseless lines at a first guess (half the rays hit), then the spacing for
    // which the hits per length meet the target (rays per line ~ 1/dth, dth = dx / rho).
    const double rho = o.isotropic_range;
    double dx0 = std::sqrt(0.5 * 2 * pi * rho * L / double(o.target_points));
    double dth0 = dx0 / rho;
    std::size_t lines0 = std::size_t(L / dx0), pilot = (std::min<std::size_t>)(lines0, 64);
    Line tmp;
    std::size_t hits = 0;
    for(std::size_t k = 0; k < pilot; ++k) {
      tmp.clear();
      std::size_t i = (k * lines0) / pilot;
      scan_line(i, dx0, dth0, 0., Rng(o.seed, i), tmp);
      hits += tmp.size();
    }
    double per_line = double(hits) / double((std::max<std::size_t>)(pilot, 1));
    dx = std::sqrt(L * per_line * dth0 * rho / double(o.target_points));
    dth = dx / rho;
  }
  if(!(dx >= 1e-4 && dth >= 1e-5 && dth < 1.))
    throw CGAL::Shape_analysis::Bad_input("Urban scene: profile_spacing must be >= 1e-4 m and "
                                          "angular_step in [1e-5, 1) rad");
  const std::size_t lines = std::size_t(L / dx);
  std::size_t n_air = 0, ax = 0, ay = 0;
  if(o.airborne) {
    ax = std::size_t(L / o.airborne_spacing) + 1;
    ay = std::size_t(2 * sc.back_y / o.airborne_spacing) + 1;
    n_air = ax;
  }
  std::vector<Line> out(lines + n_air);
  CGAL::Shape_analysis::internal::Parallel_workspaces<char> parallel(o.number_of_threads);
  parallel.for_each(0, lines + n_air, [&](std::size_t i, char&) {
    Rng rng(o.seed, i);
    if(i < lines)
      scan_line(i, dx, dth, o.range_noise, rng, out[i]);
    else { // airborne row: one x, all y
      double x = double(i - lines) * o.airborne_spacing;
      for(std::size_t j = 0; j < ay; ++j) {
        double y = -sc.back_y + double(j) * o.airborne_spacing;
        cast(tree, sc, K::Point_3(x, y, o.airborne_height), K::Vector_3(0, 0, -1), 1e300,
             o.range_noise, true, rng, out[i]);
      }
    }
  });
  Urban_scan scan;
  scan.scan_lines = lines, scan.profile_spacing = dx, scan.angular_step = dth;
  std::size_t total = 0;
  for(std::size_t i = 0; i < out.size(); ++i) {
    total += out[i].size();
    if(i + 1 == lines)
      scan.mobile_points = total;
  }
  scan.points.reserve(total);
  for(Line& l : out) {
    scan.points.insert(scan.points.end(), l.begin(), l.end());
    Line().swap(l);
  }
  return scan;
}

// Copies the scan into `ps` (cleared first) with int properties "instance" and "label" and,
// if asked, a float property "intensity".
template <typename Point>
void fill_point_set(const Urban_scan& scan, CGAL::Point_set_3<Point>& ps, bool with_intensity = true)
{
  ps.clear();
  ps.reserve(scan.points.size());
  auto inst = ps.template add_property_map<int>("instance", 0).first;
  auto label = ps.template add_property_map<int>("label", 0).first;
  typename CGAL::Point_set_3<Point>::template Property_map<float> inten;
  if(with_intensity)
    inten = ps.template add_property_map<float>("intensity", 0.f).first;
  for(const Urban_scan_point& p : scan.points) {
    auto it = ps.insert(Point(p.x, p.y, p.z));
    inst[*it] = p.instance;
    label[*it] = p.label;
    if(with_intensity)
      inten[*it] = p.intensity;
  }
}

// The ground-truth objects, one a line: id, class id, x, y, z, height, class name.

} // namespace Shape_analysis_support
} // namespace CGAL

#endif // SHAPE_ANALYSIS_SUPPORT_URBAN_SCAN_H
