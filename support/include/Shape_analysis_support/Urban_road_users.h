// Copyright (c) 2026 CGAL Global Shape Analysis contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef SHAPE_ANALYSIS_SUPPORT_URBAN_ROAD_USERS_H
#define SHAPE_ANALYSIS_SUPPORT_URBAN_ROAD_USERS_H

// Road users and vegetation of the procedural street (Urban_scene.h), for the regime of a rotating
// sensor on a car: pedestrians (walking or standing, 1.5-1.9 m), cyclists (a rider on a bicycle
// 1.65-1.85 m long, or a parked bicycle), cars in the driving lanes, and, as background,
// vegetation (hedges, bushes, low shrubs; irregular tree crowns). All of it is off by default
// (Urban_scene_options' densities are 0), and then nothing here draws a random number: the
// default scene is the thesis' street, bit for bit.
//
// Each kind draws from its own streams, one per placement attempt, seeded from (seed, 2^40 + k)
// and the attempt's index: turning one density on or up does not move the others' attempts.
// Shapes are triangles in their own frame (origin on the ground, local +x forwards for road
// users), placed by the scene's Builder, which refuses what would cut into an already placed
// shape; road users come last and take the room that is left.

#include <Shape_analysis_support/Urban_scene.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <vector>

namespace CGAL {
namespace Shape_analysis_support {
namespace urban_detail {

constexpr double road_users_pi = 3.14159265358979323846;

// An ellipsoid (centre c, radii r) whose radius varies smoothly with the direction (three random
// harmonics of relative amplitude up to `amp`) and a little from vertex to vertex: the outline
// of foliage. Closed, like Shape::ellipsoid; one part; raised if needed so that it stays above
// `floor`.
inline void lumpy_ellipsoid(Shape& s, const V3& c, const V3& r, double amp, Rng& rng, int nu = 16, int nv = 9,
                            double floor = -1e300)
{
  const double pi = road_users_pi;
  double a[3], p[3], q[3];
  int m[3], n[3];
  for(int k = 0; k < 3; ++k) {
    a[k] = amp * rng.uniform(0.3, 1.);
    m[k] = 1 + int(rng.index(4)), n[k] = 1 + int(rng.index(3));
    p[k] = rng.uniform(0., 2 * pi), q[k] = rng.uniform(0., 2 * pi);
  }
  std::vector<V3> v(std::size_t(nu) * std::size_t(nv + 1));
  for(int j = 0; j <= nv; ++j)
    for(int i = 0; i < nu; ++i) {
      const double th = pi * j / nv, phi = 2 * pi * i / nu;
      double f = 1.;
      for(int k = 0; k < 3; ++k)
        f += std::sin(th) * a[k] * std::cos(m[k] * phi + p[k]) * std::cos(n[k] * th + q[k]);
      if(j > 0 && j < nv)
        f += 0.25 * amp * rng.uniform(-1., 1.);
      v[std::size_t(j) * nu + i] = {c[0] + r[0] * f * std::sin(th) * std::cos(phi),
                                    c[1] + r[1] * f * std::sin(th) * std::sin(phi), c[2] + r[2] * f * std::cos(th)};
    }
  double lowest = 1e300;
  for(const V3& p : v)
    lowest = (std::min)(lowest, p[2]);
  if(lowest < floor)
    for(V3& p : v)
      p[2] += floor - lowest;
  const std::size_t first = s.tris.size();
  auto at = [&](int i, int j) { return v[std::size_t(j) * nu + std::size_t(i % nu)]; };
  for(int i = 0; i < nu; ++i)
    for(int j = 0; j < nv; ++j) {
      if(j > 0)
        s.tri(at(i, j), at(i + 1, j), at(i + 1, j + 1));
      if(j + 1 < nv)
        s.tri(at(i, j), at(i + 1, j + 1), at(i, j + 1));
    }
  s.close_part(first);
}

// A tree with a trunk, two to four branches and an irregular crown of three to six lumpy blobs;
// the crown starts 2.3 m or more above the ground (pedestrians and cyclists pass under it).
inline Shape make_irregular_tree_shape(Rng& rng)
{
  Shape s;
  const double pi = road_users_pi;
  const double trunk = rng.uniform(2.6, 4.2), rt = rng.uniform(0.12, 0.25);
  const double crown = rng.uniform(1.4, 2.6), rise = rng.uniform(1.5, 2.8);
  const V3 top = {rng.uniform(-0.15, 0.15), rng.uniform(-0.15, 0.15), trunk + 0.4 * rise};
  s.cylinder({0, 0, -0.05}, top, rt, 10);
  const int blobs = 3 + int(rng.index(4));
  for(int k = 0; k < blobs; ++k) {
    const double ang = 2 * pi * (k + rng.uniform(-0.3, 0.3)) / blobs;
    const double d = k == 0 ? 0. : crown * rng.uniform(0.3, 0.6);
    const double rb = crown * rng.uniform(0.5, 0.75), rzb = rise * rng.uniform(0.45, 0.7);
    const V3 c = {d * std::cos(ang), d * std::sin(ang), (std::max)(trunk + rzb, top[2] + rng.uniform(-0.3, 0.9))};
    if(k > 0)
      s.cylinder(top, {c[0] * 0.8, c[1] * 0.8, c[2] - 0.3 * rzb}, rt * 0.45, 6);
    lumpy_ellipsoid(s, c, {rb, rb * rng.uniform(0.8, 1.), rzb}, 0.2, rng, 18, 10, 2.3);
  }
  return s;
}

// A hedge (or a strip of low shrubs): overlapping lumpy blobs along local x over `length`, of
// depth `d` and height `h` above the ground; `dz(dx)` is the ground's rise at dx along the hedge.
inline Shape make_hedge_shape(Rng& rng, double length, double d, double h, double amp,
                              const std::function<double(double)>& dz)
{
  Shape s;
  const int n = (std::max)(2, int(std::ceil(length / 0.45)));
  for(int k = 0; k < n; ++k) {
    const double x = -length / 2 + 0.5 + (length - 1.) * k / (n - 1);
    const double hk = h * rng.uniform(0.9, 1.06), rz = 0.6 * hk;
    lumpy_ellipsoid(s, {x, rng.uniform(-0.04, 0.04), dz(x) + hk - rz}, {0.75, d / 2, rz}, amp, rng, 12, 7);
  }
  return s;
}

// A bush: one to three lumpy blobs, about `r` in radius and `h` high.
inline Shape make_bush_shape(Rng& rng, double r, double h)
{
  Shape s;
  const int n = 1 + int(rng.index(3));
  for(int k = 0; k < n; ++k) {
    const double rk = k == 0 ? r : r * rng.uniform(0.5, 0.75), hk = k == 0 ? h : h * rng.uniform(0.55, 0.85);
    const double ox = k == 0 ? 0. : rng.uniform(-0.45, 0.45) * r, oy = k == 0 ? 0. : rng.uniform(-0.3, 0.3) * r;
    lumpy_ellipsoid(s, {ox, oy, 0.4 * hk}, {rk, rk * rng.uniform(0.8, 1.), 0.6 * hk}, 0.18, rng, 14, 8);
  }
  return s;
}

// A pedestrian of stature 1.5-1.9 m (proportions of adult anthropometry: hips at 0.53, shoulders
// at 0.82, chin at 0.87 of the stature) facing local +x: feet, legs in stride (or standing),
// pelvis, torso, arms swinging against the legs, neck, head; sometimes a backpack or a bag.
inline Shape make_pedestrian_shape(Rng& rng, bool walking)
{
  Shape s;
  auto u = [&](double lo, double hi) { return rng.uniform(lo, hi); };
  const double H = u(1.5, 1.9), k = H / 1.75, girth = u(0.85, 1.2);
  const double a = walking ? u(0.18, 0.42) : u(0., 0.05); // half the angle between the legs
  const double front = rng.uniform() < 0.5 ? 1. : -1.;    // side of the leg in front
  const double ankle = 0.039 * H, leg = 0.491 * H, hip = ankle + leg * std::cos(a);
  const double shoulder = hip + 0.288 * H, hw = 0.085 * k * girth;
  for(int side = -1; side <= 1; side += 2) {
    const double swing = side * front * a;
    const V3 h = {0, side * hw, hip}, f = {leg * std::sin(swing), side * (hw + 0.01), ankle};
    const V3 knee = {(h[0] + f[0]) / 2 + (swing < 0 ? 0.03 : 0.), side * hw, (h[2] + f[2]) / 2};
    s.cylinder(h, knee, 0.068 * k * girth, 8);
    s.cylinder(knee, f, 0.048 * k, 8);
    s.aabox(f[0] - 0.07 * k, f[1] - 0.05 * k, -0.03, f[0] + 0.19 * k, f[1] + 0.05 * k, ankle + 0.03);
  }
  const double tw = u(0.15, 0.19) * k * girth, td = u(0.1, 0.13) * k * girth;
  s.aabox(-td * 0.9, -hw - 0.07 * k, hip - 0.06, td * 0.9, hw + 0.07 * k, hip + 0.1);
  s.ellipsoid({0, 0, (hip + shoulder) / 2 + 0.03}, {td, tw, (shoulder - hip) / 2 + 0.01}, 12, 7);
  const double arm = 0.36 * H;
  for(int side = -1; side <= 1; side += 2) {
    const double b = walking ? -side * front * u(0.12, 0.4) : u(-0.05, 0.1);
    const V3 sh = {0, side * (tw - 0.02), shoulder - 0.03};
    const V3 el = {sh[0] + 0.5 * arm * std::sin(b), side * (tw + 0.01), sh[2] - 0.5 * arm * std::cos(b)};
    const V3 hand = {sh[0] + arm * std::sin(b * 1.3), side * (tw + 0.03), sh[2] - arm * std::cos(b * 1.3)};
    s.cylinder(sh, el, 0.045 * k, 8);
    s.cylinder(el, hand, 0.037 * k, 8);
    if(side == 1 && rng.uniform() < 0.15) // a bag in the hand
      s.aabox(hand[0] - 0.17, hand[1], hand[2] - 0.3, hand[0] + 0.17, hand[1] + 0.12, hand[2] - 0.02);
  }
  s.cylinder({0, 0, shoulder - 0.05}, {0, 0, 0.9 * H + hip - ankle - leg}, 0.05 * k, 8);
  const double head = 0.935 * H + hip - ankle - leg;
  s.ellipsoid({0.01, 0, head}, {0.095 * k, 0.08 * k, 0.066 * H}, 10, 6);
  if(rng.uniform() < 0.2) // a backpack
    s.aabox(-td - 0.18, -0.15, shoulder - 0.45, -td + 0.01, 0.15, shoulder - 0.04);
  return s;
}

// A wheel (tyre) of radius r in the plane y = y0 of local x-z, centred at x0: a ring of thin tubes.
inline void wheel(Shape& s, double x0, double y0, double r, double tube)
{
  const int n = 16;
  for(int i = 0; i < n; ++i) {
    const double t0 = 2 * road_users_pi * i / n, t1 = 2 * road_users_pi * (i + 1) / n;
    s.cylinder({x0 + r * std::cos(t0), y0, r + r * std::sin(t0)}, {x0 + r * std::cos(t1), y0, r + r * std::sin(t1)},
               tube, 6);
  }
  s.cylinder({x0, y0 - 0.05, r}, {x0, y0 + 0.05, r}, 0.03, 6); // hub
}

// The knee of a leg from hip h to foot f (thigh t, shin l) in the plane of the bicycle, forwards.
inline V3 knee_between(const V3& h, const V3& f, double t, double l)
{
  const double dx = f[0] - h[0], dz = f[2] - h[2], d = std::sqrt(dx * dx + dz * dz);
  const double along = (std::min)(t, (t * t - l * l + d * d) / (2 * d));
  const double up = std::sqrt((std::max)(0., t * t - along * along));
  return {h[0] + dx / d * along - dz / d * up, h[1], h[2] + dz / d * along + dx / d * up};
}

// A bicycle facing local +x (wheels 26-28", wheelbase 1-1.1 m: 1.65-1.85 m long), centred between
// its axles; with `ridden`, a rider (stature 1.6-1.9 m) leaning forwards, feet on the pedals.
inline Shape make_cyclist_shape(Rng& rng, bool ridden)
{
  Shape s;
  auto u = [&](double lo, double hi) { return rng.uniform(lo, hi); };
  const double rw = u(0.33, 0.36), wb = u(1.0, 1.1), tube = u(0.016, 0.024);
  const double H = u(1.6, 1.9), thigh = 0.245 * H, shin = 0.25 * H, crank = 0.17;
  wheel(s, -wb / 2, 0, rw, 0.022);
  wheel(s, wb / 2, 0, rw, 0.022);
  const V3 rear = {-wb / 2, 0, rw}, front = {wb / 2, 0, rw}, bb = {-wb / 2 + 0.42, 0, rw - 0.05};
  const double seat = 0.96 * (thigh + shin) - 0.95 * crank - 0.06, tilt = 0.3;
  const V3 saddle = {bb[0] - seat * std::sin(tilt), 0, bb[2] + seat * std::cos(tilt)};
  const V3 clamp = {bb[0] - 0.55 * std::sin(tilt), 0, bb[2] + 0.55 * std::cos(tilt)};
  const V3 head_lo = {wb / 2 - 0.2, 0, rw + 0.33}, head_hi = {wb / 2 - 0.24, 0, rw + 0.5};
  s.cylinder(rear, bb, tube, 6);
  s.cylinder(rear, clamp, tube, 6);
  s.cylinder(bb, saddle, tube * 1.2, 6);
  s.cylinder(bb, head_lo, tube * 1.4, 6);
  s.cylinder(clamp, head_hi, tube * 1.2, 6);
  s.cylinder(head_lo, head_hi, tube * 1.5, 6);
  s.cylinder(front, head_lo, tube, 6);
  const double bar_w = u(0.55, 0.68), bar_z = (std::max)(head_hi[2] + 0.08, saddle[2] + u(-0.08, 0.06));
  const V3 bar = {head_hi[0] - 0.06, 0, bar_z};
  s.cylinder(head_hi, bar, tube, 6);
  s.cylinder({bar[0], -bar_w / 2, bar_z}, {bar[0], bar_w / 2, bar_z}, tube, 6);
  s.aabox(saddle[0] - 0.16, -0.07, saddle[2], saddle[0] + 0.11, 0.07, saddle[2] + 0.06);
  if(rng.uniform() < 0.3) // a basket or a rack bag
    s.aabox(bar[0] + 0.05, -0.17, bar_z - 0.3, bar[0] + 0.38, 0.17, bar_z - 0.02);
  const double phase = u(0., 2 * road_users_pi);
  for(int side = -1; side <= 1; side += 2) {
    const double ph = phase + (side > 0 ? road_users_pi : 0.);
    const V3 pedal = {bb[0] + crank * std::cos(ph), side * 0.15, bb[2] + crank * std::sin(ph)};
    s.cylinder({bb[0], side * 0.04, bb[2]}, pedal, 0.015, 6);
    if(!ridden)
      continue;
    const V3 hp = {saddle[0], side * 0.1, saddle[2] + 0.1};
    const V3 knee = knee_between(hp, pedal, thigh, shin);
    s.cylinder(hp, knee, 0.066 * H / 1.75, 8);
    s.cylinder(knee, pedal, 0.048 * H / 1.75, 8);
  }
  if(!ridden)
    return s;
  const double lean = u(0.4, 0.85), torso = 0.3 * H;
  const V3 hip = {saddle[0] + 0.02, 0, saddle[2] + 0.12};
  const V3 sh = {hip[0] + torso * std::sin(lean), 0, hip[2] + torso * std::cos(lean)};
  s.cylinder(hip, sh, u(0.13, 0.17) * H / 1.75, 10);
  const V3 head = {sh[0] + 0.1 + 0.06 * std::sin(lean), 0, sh[2] + 0.19 * H / 1.75};
  s.cylinder(sh, head, 0.05, 8);
  s.ellipsoid(head, {0.11, 0.09, 0.115 * H / 1.75}, 10, 6);
  for(int side = -1; side <= 1; side += 2) {
    const V3 a = {sh[0], side * 0.18, sh[2] - 0.04}, g = {bar[0], side * (bar_w / 2 - 0.06), bar_z};
    const V3 el = {(a[0] + g[0]) / 2 - 0.03, side * 0.24, (a[2] + g[2]) / 2 + 0.02};
    s.cylinder(a, el, 0.045, 8);
    s.cylinder(el, g, 0.037, 8);
  }
  return s;
}

// The stream of placement attempt `i` of kind `k` (4: vegetation, 5: pedestrians, 6: riding
// cyclists, 7: lane cars, 8: parked bicycles).
inline Rng attempt_stream(std::uint64_t seed, std::uint64_t k, std::size_t i)
{
  return Rng(Rng(seed, (std::uint64_t(1) << 40) + k).next(), i);
}

// Undo of a group of placements.
struct Builder_mark { std::size_t parts, triangles, objects; };
inline Builder_mark mark(const Builder& bd)
{
  return {bd.parts.size(), bd.scene.triangles.size(), bd.scene.objects.size()};
}
inline void undo(Builder& bd, const Builder_mark& m)
{
  bd.parts.resize(m.parts);
  bd.scene.triangles.resize(m.triangles), bd.scene.triangle_instance.resize(m.triangles);
  bd.scene.triangle_class.resize(m.triangles);
  bd.scene.objects.resize(m.objects);
}

struct Placement { Shape shape; double x, y, heading; int cls; };

// Places all of `g` on the ground (objects with ids from next_id on) or none of them.
inline bool place_all(Builder& bd, const std::vector<Placement>& g, int& next_id)
{
  const Builder_mark m = mark(bd);
  int id = next_id;
  for(const Placement& p : g)
    if(!bd.place(p.shape, p.x, p.y, bd.scene.ground_height(p.x, p.y), p.heading, id++, p.cls)) {
      undo(bd, m);
      return false;
    }
  next_id = id;
  return true;
}

inline void check_road_user_options(const Urban_scene_options& o)
{
  for(double d : {o.pedestrians_per_100m, o.cyclists_per_100m, o.lane_cars_per_100m, o.vegetation_per_100m})
    if(!(d >= 0. && d <= 100.))
      throw CGAL::Shape_analysis::Bad_input("Urban scene: pedestrians, cyclists, lane cars and vegetation per "
                                            "100 m must be in [0, 100]");
}

// Hedges along the facades, bushes at the facades or the curbs, strips of low shrubs along the
// curbs, where there is room (background: class VEGETATION, instance 0).
inline void add_vegetation(Builder& bd, const Urban_scene_options& o)
{
  const std::size_t n = std::size_t(std::llround(o.vegetation_per_100m * o.street_length / 100.));
  if(n == 0)
    return;
  Urban_scene& sc = bd.scene;
  const double R = sc.road_half_width, F = sc.facade_y, L = o.street_length;
  for(std::size_t k = 0, attempt = 0; k < n && attempt < 30 * n; ++attempt) {
    Rng rng = attempt_stream(o.seed, 4, attempt);
    const int side = rng.uniform() < 0.5 ? -1 : 1;
    const double r = rng.uniform(), x = rng.uniform(0., L);
    double y;
    Shape s;
    if(r < 0.55) {
      const bool hedge = r < 0.35;
      const double len = hedge ? rng.uniform(2., 8.) : rng.uniform(1.5, 5.);
      const double d = hedge ? rng.uniform(0.6, 1.1) : rng.uniform(0.7, 1.2);
      const double h = hedge ? rng.uniform(0.7, 1.5) : rng.uniform(0.25, 0.5);
      const double amp = hedge ? 0.08 : 0.2; // lumps reach at most 1 + 3.25 amp times the radius
      y = side * (hedge ? F - d / 2 * (1 + 3.3 * amp) - 0.02 : R + 0.25 + d / 2);
      const double z0 = sc.ground_height(x, y);
      s = make_hedge_shape(rng, len, d, h, amp,
                           [&](double dx) { return sc.ground_height(x + dx, y) - z0; });
    } else {
      const double rb = rng.uniform(0.35, 0.8), h = rng.uniform(0.5, 1.6);
      y = side * (rng.uniform() < 0.5 ? F - 1.6 * rb - 0.02 : R + 0.35 + rb);
      s = make_bush_shape(rng, rb, h);
    }
    if(bd.place(s, x, y, sc.ground_height(x, y), 0., 0, VEGETATION))
      ++k;
  }
}

// Pedestrians: on the sidewalks, walking along the street (alone or in pairs) or standing, or
// crossing the road.
inline void add_pedestrians(Builder& bd, const Urban_scene_options& o, std::size_t n, int& next_id)
{
  const Urban_scene& sc = bd.scene;
  const double R = sc.road_half_width, F = sc.facade_y, L = o.street_length, pi = road_users_pi;
  for(std::size_t k = 0, attempt = 0; k < n && attempt < 30 * n; ++attempt) {
    Rng rng = attempt_stream(o.seed, 5, attempt);
    std::vector<Placement> g;
    const double x = rng.uniform(1., L - 1.);
    if(rng.uniform() < 0.2) { // crossing
      const double heading = (rng.uniform() < 0.5 ? 0.5 : -0.5) * pi + rng.uniform(-0.15, 0.15);
      g.push_back({make_pedestrian_shape(rng, true), x, rng.uniform(-R + 0.5, R - 0.5), heading, PEDESTRIAN});
    } else {
      const int side = rng.uniform() < 0.5 ? -1 : 1;
      const bool walking = rng.uniform() < 0.75;
      const double heading = walking ? (rng.uniform() < 0.5 ? 0. : pi) + rng.uniform(-0.25, 0.25)
                                     : rng.uniform(0., 2 * pi);
      const double y = side * rng.uniform(R + 0.45, F - 0.45);
      g.push_back({make_pedestrian_shape(rng, walking), x, y, heading, PEDESTRIAN});
      if(rng.uniform() < 0.25 && k + 2 <= n) { // a companion at the side, a little ahead or behind
        const double d = rng.uniform(0.6, 0.8) * (rng.uniform() < 0.5 ? -1 : 1), e = rng.uniform(-0.25, 0.25);
        const double c = std::cos(heading), sn = std::sin(heading);
        g.push_back({make_pedestrian_shape(rng, walking), x + c * e - sn * d, y + sn * e + c * d,
                     heading + rng.uniform(-0.1, 0.1), PEDESTRIAN});
      }
    }
    if(place_all(bd, g, next_id))
      k += g.size();
  }
}

// Cyclists: seven in ten ride along the outer edge of the lanes; the others are parked bicycles,
// against the facades or in racks of two to four across the sidewalk near the curb.
inline void add_cyclists(Builder& bd, const Urban_scene_options& o, std::size_t n, int& next_id)
{
  const Urban_scene& sc = bd.scene;
  const double R = sc.road_half_width, F = sc.facade_y, L = o.street_length, pi = road_users_pi;
  const std::size_t riders = std::size_t(std::llround(0.7 * double(n)));
  for(std::size_t k = 0, attempt = 0; k < riders && attempt < 30 * riders; ++attempt) {
    Rng rng = attempt_stream(o.seed, 6, attempt);
    const double x = rng.uniform(1.5, L - 1.5);
    const int side = rng.uniform() < 0.5 ? -1 : 1;
    const double heading = (side < 0 ? 0. : pi) + rng.uniform(-0.06, 0.06);
    const std::vector<Placement> g = {
      {make_cyclist_shape(rng, true), x, side * (3.5 - rng.uniform(0.35, 0.7)), heading, CYCLIST}};
    k += place_all(bd, g, next_id) ? 1 : 0;
  }
  const std::size_t parked = n - riders;
  for(std::size_t k = 0, attempt = 0; k < parked && attempt < 30 * parked; ++attempt) {
    Rng rng = attempt_stream(o.seed, 8, attempt);
    std::vector<Placement> g;
    const double x = rng.uniform(1.5, L - 1.5);
    const int side = rng.uniform() < 0.5 ? -1 : 1;
    if(rng.uniform() < 0.4 || k + 2 > parked)
      g.push_back({make_cyclist_shape(rng, false), x, side * (F - 0.4), rng.uniform() < 0.5 ? 0. : pi, CYCLIST});
    else {
      const std::size_t m = (std::min)(parked - k, std::size_t(2 + rng.index(3)));
      const double step = rng.uniform(0.7, 0.85), y = side * (R + 1.2 + rng.uniform(0., 0.3));
      for(std::size_t i = 0; i < m; ++i)
        g.push_back({make_cyclist_shape(rng, false), x + double(i) * step, y,
                     (rng.uniform() < 0.5 ? 0.5 : -0.5) * pi + rng.uniform(-0.05, 0.05), CYCLIST});
    }
    if(place_all(bd, g, next_id))
      k += g.size();
  }
}

// Cars driving in both lanes.
inline void add_lane_cars(Builder& bd, const Urban_scene_options& o, std::size_t n, int& next_id)
{
  const double L = o.street_length, pi = road_users_pi;
  for(std::size_t k = 0, attempt = 0; k < n && attempt < 30 * n; ++attempt) {
    Rng rng = attempt_stream(o.seed, 7, attempt);
    const int side = rng.uniform() < 0.5 ? -1 : 1;
    std::vector<Placement> g;
    g.push_back({make_object_shape(CAR, rng), rng.uniform(2.5, L - 2.5), side * (1.75 + rng.uniform(-0.25, 0.25)),
                 (side < 0 ? 0. : pi) + rng.uniform(-0.02, 0.02), CAR});
    if(place_all(bd, g, next_id))
      ++k;
  }
}

// Road users, after everything else (they take the room that is left), kept off the scanner's
// path: for the rotating sensor, 3.5 m before and after each of its positions in its lane; for
// the profile scanners, the centre line (|y| < 0.5 m).
inline void add_road_users(Builder& bd, const Urban_scene_options& o, int& next_id)
{
  const double L = o.street_length;
  auto count = [&](double per_100m) { return std::size_t(std::llround(per_100m * L / 100.)); };
  const std::size_t pedestrians = count(o.pedestrians_per_100m), cyclists = count(o.cyclists_per_100m);
  const std::size_t cars = count(o.lane_cars_per_100m);
  if(pedestrians + cyclists + cars == 0)
    return;
  const double x0 = -bd.scene.margin, x1 = L + bd.scene.margin;
  auto keep_out = [&](double xa, double xb, double ya, double yb) {
    bd.parts.push_back({Box{{xa, ya, -1e4}, {xb, yb, 1e4}}, -1});
  };
  if(!o.rotating_sensor)
    keep_out(x0, x1, -0.5, 0.5);
  else if(!(o.sweep_spacing >= 7.))
    keep_out(x0, x1, o.lane_offset - 1.1, o.lane_offset + 1.1);
  else // the sweeps of scan_rotating()
    for(std::size_t i = 0, sweeps = (std::max)(std::size_t(1), std::size_t(L / o.sweep_spacing)); i < sweeps; ++i) {
      const double x = (double(i) + 0.5) * o.sweep_spacing;
      keep_out(x - 3.5, x + 3.5, o.lane_offset - 1.1, o.lane_offset + 1.1);
    }
  add_lane_cars(bd, o, cars, next_id);
  add_cyclists(bd, o, cyclists, next_id);
  add_pedestrians(bd, o, pedestrians, next_id);
  bd.parts.erase(std::remove_if(bd.parts.begin(), bd.parts.end(),
                                [](const std::pair<Box, int>& p) { return p.second < 0; }),
                 bd.parts.end());
}

} // namespace urban_detail
} // namespace Shape_analysis_support
} // namespace CGAL

#endif // SHAPE_ANALYSIS_SUPPORT_URBAN_ROAD_USERS_H
