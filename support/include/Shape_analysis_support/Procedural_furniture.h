// Copyright (c) 2026 CGAL Global Shape Analysis contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef SHAPE_ANALYSIS_SUPPORT_PROCEDURAL_FURNITURE_H
#define SHAPE_ANALYSIS_SUPPORT_PROCEDURAL_FURNITURE_H

// Procedural sets of chairs and tables with known part labels, for the tests and benchmarks of
// consistent co-segmentation. Like the furniture models of shape repositories, every piece is a
// closed box of its own (a seat, a back, four legs, armrests with their supports): a model is a
// soup of several connected components that touch or pass through each other, never welded.
// Proportions, leg shapes, back tilt and the presence of armrests vary from model to model; an
// optional random similarity (rotation about any axis, scale, translation) puts each model in a
// pose of its own. Deterministic for a seed, on every platform.
//
// Part labels: SEAT (the seat of a chair, the top of a table), BACK, LEG, ARMREST. Every triangle
// also carries the index of its piece (`piece`), so that finer, per-piece agreement can be
// measured.

#include <Shape_analysis_support/Procedural_shapes.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <map>
#include <string>
#include <tuple>
#include <vector>

namespace CGAL {
namespace Shape_analysis_support {

enum Furniture_part : std::size_t { SEAT = 0, BACK = 1, LEG = 2, ARMREST = 3 };

inline const char* furniture_part_name(std::size_t label)
{
  static const char* names[] = {"seat", "back", "leg", "armrest"};
  return label < 4 ? names[label] : "unknown";
}

struct Furniture_model
{
  Labelled_triangle_mesh mesh;  // labels: Furniture_part
  std::vector<std::size_t> piece; // per triangle: the box it belongs to
  std::size_t number_of_pieces = 0;
  bool has_back = false;
  bool has_armrests = false;
};

namespace procedural_detail {

// Appends to `model` a closed box, outward oriented, with center `c`, half extents `h` along the
// orthonormal axes `axes` (rows), its faces cut into squares of about `edge` (at least one cell
// per side), every triangle labelled `label`.
inline void add_box(Furniture_model& model, const Vector_3d& c, const Vector_3d& h,
                    const std::array<Vector_3d, 3>& axes, double edge, std::size_t label)
{
  Labelled_triangle_mesh& m = model.mesh;
  const std::size_t piece = model.number_of_pieces++;
  std::array<int, 3> n;
  for(int a = 0; a < 3; ++a)
    n[std::size_t(a)] = (std::max)(1, int(std::lround(2 * h[a] / edge)));
  std::map<std::tuple<int, int, int>, std::size_t> index;
  auto vertex = [&](int i, int j, int k) {
    const auto key = std::make_tuple(i, j, k);
    auto it = index.find(key);
    if(it != index.end())
      return it->second;
    const Vector_3d local(h.x * (2.0 * i / n[0] - 1), h.y * (2.0 * j / n[1] - 1),
                          h.z * (2.0 * k / n[2] - 1));
    const Vector_3d p = c + axes[0] * local.x + axes[1] * local.y + axes[2] * local.z;
    m.points.push_back({p.x, p.y, p.z});
    index.emplace(key, m.points.size() - 1);
    return m.points.size() - 1;
  };
  // For each axis a and side s, the two other axes (u, v) in the order that makes u x v point
  // along +a; the -a side takes them the other way round.
  for(int a = 0; a < 3; ++a)
    for(int side = 0; side < 2; ++side) {
      int u = (a + 1) % 3, v = (a + 2) % 3;
      if(side == 0)
        std::swap(u, v);
      for(int p = 0; p < n[std::size_t(u)]; ++p)
        for(int q = 0; q < n[std::size_t(v)]; ++q) {
          auto corner = [&](int du, int dv) {
            std::array<int, 3> g;
            g[std::size_t(a)] = side == 0 ? 0 : n[std::size_t(a)];
            g[std::size_t(u)] = p + du;
            g[std::size_t(v)] = q + dv;
            return vertex(g[0], g[1], g[2]);
          };
          const std::size_t v00 = corner(0, 0), v10 = corner(1, 0), v11 = corner(1, 1),
                            v01 = corner(0, 1);
          m.triangles.push_back({v00, v10, v11});
          m.triangles.push_back({v00, v11, v01});
          m.labels.push_back(label);
          m.labels.push_back(label);
          model.piece.push_back(piece);
          model.piece.push_back(piece);
        }
    }
  m.number_of_labels = (std::max)(m.number_of_labels, label + 1);
}

inline std::array<Vector_3d, 3> standard_axes()
{
  return {{Vector_3d(1, 0, 0), Vector_3d(0, 1, 0), Vector_3d(0, 0, 1)}};
}

// Axes of a box tilted by `angle` about the x axis (y and z turn).
inline std::array<Vector_3d, 3> tilted_axes(double angle)
{
  const double c = std::cos(angle), s = std::sin(angle);
  return {{Vector_3d(1, 0, 0), Vector_3d(0, c, s), Vector_3d(0, -s, c)}};
}

// A uniformly random rotation (a random unit quaternion).
inline Rigid_transform random_rotation(Procedural_random& rng, const Vector_3d& translation)
{
  double q[4];
  double norm = 0;
  do {
    norm = 0;
    for(double& x : q) {
      x = rng.uniform(-1, 1);
      norm += x * x;
    }
  } while(norm > 1 || norm < 1e-6);
  norm = std::sqrt(norm);
  for(double& x : q)
    x /= norm;
  const double w = q[0], x = q[1], y = q[2], z = q[3];
  Rigid_transform t;
  t.rotation[0] = Vector_3d(1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w));
  t.rotation[1] = Vector_3d(2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w));
  t.rotation[2] = Vector_3d(2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y));
  t.translation = translation;
  return t;
}

// Scales `model` by a random factor in [0.7, 1.4], then turns it by a random rotation and moves it.
inline void apply_random_pose(Furniture_model& model, Procedural_random& rng)
{
  const double scale = std::exp(rng.uniform(std::log(0.7), std::log(1.4)));
  for(auto& p : model.mesh.points)
    for(double& x : p)
      x *= scale;
  transform_points(model.mesh,
                   random_rotation(rng, Vector_3d(rng.uniform(-2, 2), rng.uniform(-2, 2), rng.uniform(-2, 2))));
}

} // namespace procedural_detail

struct Furniture_options
{
  // Target edge length of the box faces, in the model's units (a chair seat is about 0.5 wide):
  // 0.045 gives about 2,050 triangles per chair, 0.042 about 2,300.
  double edge_length = 0.045;
  // Probability that a chair has armrests.
  double armrest_probability = 0.5;
  // Whether each model is moved by a random rotation, a scale in [0.7, 1.4] and a translation.
  bool random_pose = false;
};

// One chair: a seat on four legs, a back (possibly tilted) and, with some probability, two
// armrests on vertical supports. Model `index` of the set seeded by `seed`.
inline Furniture_model procedural_chair(std::uint64_t seed, std::size_t index,
                                        const Furniture_options& o = Furniture_options())
{
  using namespace procedural_detail;
  Procedural_random rng(seed, index);
  Furniture_model model;
  const double e = o.edge_length;
  const auto axes = standard_axes();
  const double width = rng.uniform(0.42, 0.6), depth = rng.uniform(0.4, 0.55);
  const double thickness = rng.uniform(0.04, 0.08), height = rng.uniform(0.4, 0.5);
  const double leg = rng.uniform(0.03, 0.055), inset = rng.uniform(0.0, 0.04);
  const bool splayed = rng.uniform() < 0.3;
  // Seat: x across, y front (-) to back (+), z up.
  add_box(model, Vector_3d(0, 0, height + thickness / 2), Vector_3d(width / 2, depth / 2, thickness / 2),
          axes, e, SEAT);
  for(int sx = -1; sx <= 1; sx += 2)
    for(int sy = -1; sy <= 1; sy += 2) {
      const double x = sx * (width / 2 - leg - inset), y = sy * (depth / 2 - leg - inset);
      if(splayed) {
        // A leg leaning outwards along y, from the seat's corner to the floor.
        const double lean = 0.12 * sy;
        const double len = std::sqrt(height * height + (height * lean) * (height * lean));
        const auto a = tilted_axes(std::atan(lean));
        add_box(model, Vector_3d(x, y + height * lean / 2, height / 2 + thickness * 0.2),
                Vector_3d(leg, leg, len / 2), a, e, LEG);
      } else
        add_box(model, Vector_3d(x, y, height / 2 + thickness * 0.2), Vector_3d(leg, leg, height / 2),
                axes, e, LEG);
    }
  // Back: above the seat's rear edge, tilted backwards.
  const double back_height = rng.uniform(0.35, 0.55), back_thickness = rng.uniform(0.03, 0.05);
  const double tilt = rng.uniform(0.0, 0.25);
  const auto back_axes = tilted_axes(-tilt);
  const Vector_3d back_center(0, depth / 2 - back_thickness / 2 + std::sin(tilt) * back_height / 2,
                              height + thickness * 0.5 + std::cos(tilt) * back_height / 2);
  add_box(model, back_center, Vector_3d(width / 2, back_thickness / 2, back_height / 2), back_axes, e, BACK);
  model.has_back = true;
  if(rng.uniform() < o.armrest_probability) {
    model.has_armrests = true;
    const double arm_height = rng.uniform(0.18, 0.26), arm = rng.uniform(0.025, 0.04);
    for(int sx = -1; sx <= 1; sx += 2) {
      const double x = sx * (width / 2 + arm);
      // The rest, front to back, and its vertical support at the front.
      add_box(model, Vector_3d(x, 0.05, height + thickness + arm_height),
              Vector_3d(arm, depth * 0.42, arm * 0.8), axes, e, ARMREST);
      add_box(model, Vector_3d(x, -depth * 0.3, height + thickness + arm_height / 2),
              Vector_3d(arm * 0.8, arm * 0.8, arm_height / 2), axes, e, ARMREST);
    }
  }
  if(o.random_pose)
    apply_random_pose(model, rng);
  return model;
}

// One table: a top (label SEAT) on four legs, or on a central pedestal (label LEG) with a foot.
inline Furniture_model procedural_table(std::uint64_t seed, std::size_t index,
                                        const Furniture_options& o = Furniture_options())
{
  using namespace procedural_detail;
  Procedural_random rng(seed ^ 0x7461626C65ull, index);
  Furniture_model model;
  const double e = o.edge_length * 1.5;
  const auto axes = standard_axes();
  const double width = rng.uniform(0.8, 1.6), depth = rng.uniform(0.6, 0.9);
  const double thickness = rng.uniform(0.03, 0.06), height = rng.uniform(0.68, 0.78);
  add_box(model, Vector_3d(0, 0, height + thickness / 2), Vector_3d(width / 2, depth / 2, thickness / 2),
          axes, e, SEAT);
  if(rng.uniform() < 0.75) {
    const double leg = rng.uniform(0.03, 0.06), inset = rng.uniform(0.02, 0.1);
    for(int sx = -1; sx <= 1; sx += 2)
      for(int sy = -1; sy <= 1; sy += 2)
        add_box(model,
                Vector_3d(sx * (width / 2 - leg - inset), sy * (depth / 2 - leg - inset), height / 2 + 0.005),
                Vector_3d(leg, leg, height / 2), axes, e, LEG);
  } else {
    const double post = rng.uniform(0.05, 0.09);
    add_box(model, Vector_3d(0, 0, height / 2 + 0.005), Vector_3d(post, post, height / 2), axes, e, LEG);
    add_box(model, Vector_3d(0, 0, 0.02), Vector_3d(depth * 0.35, depth * 0.35, 0.02), axes, e, LEG);
  }
  if(o.random_pose)
    apply_random_pose(model, rng);
  return model;
}

// `n` models made by `make(seed, index, o)` (models 0 .. n-1 of the set seeded by `seed`).
template <typename Make>
std::vector<Furniture_model> furniture_set(std::size_t n, std::uint64_t seed, const Furniture_options& o,
                                           const Make& make)
{
  std::vector<Furniture_model> set;
  set.reserve(n);
  for(std::size_t i = 0; i < n; ++i)
    set.push_back(make(seed, i, o));
  return set;
}

// `n` chairs.
inline std::vector<Furniture_model> procedural_chair_set(std::size_t n, std::uint64_t seed,
                                                         const Furniture_options& o = Furniture_options())
{
  return furniture_set(n, seed, o, procedural_chair);
}

// `n` tables.
inline std::vector<Furniture_model> procedural_table_set(std::size_t n, std::uint64_t seed,
                                                         const Furniture_options& o = Furniture_options())
{
  return furniture_set(n, seed, o, procedural_table);
}

// The accuracy of a consistent segmentation of a furniture set: every segment id is matched, once
// for the whole set, to the part label that covers most of its area over all models (several ids
// may match one label: a split part is not an error, a mixed segment is); returns the fraction of
// the total area (each model's area counting as 1) whose label is the one its id is matched to.
// `ids[i][f]` is the segment id of triangle f of model i.
inline double furniture_label_accuracy(const std::vector<Furniture_model>& models,
                                       const std::vector<std::vector<std::size_t>>& ids)
{
  std::map<std::size_t, std::map<std::size_t, double>> overlap; // id -> label -> area
  for(std::size_t i = 0; i < models.size(); ++i) {
    const Labelled_triangle_mesh& m = models[i].mesh;
    double total = 0;
    for(std::size_t f = 0; f < m.number_of_faces(); ++f)
      total += m.area(f);
    if(!(total > 0))
      continue;
    for(std::size_t f = 0; f < m.number_of_faces(); ++f)
      overlap[ids[i][f]][m.labels[f]] += m.area(f) / total;
  }
  double right = 0, all = 0;
  for(const auto& kv : overlap) {
    double best = 0;
    for(const auto& lv : kv.second) {
      best = (std::max)(best, lv.second);
      all += lv.second;
    }
    right += best;
  }
  return all > 0 ? right / all : 0.0;
}

} // namespace Shape_analysis_support
} // namespace CGAL

#endif // SHAPE_ANALYSIS_SUPPORT_PROCEDURAL_FURNITURE_H
