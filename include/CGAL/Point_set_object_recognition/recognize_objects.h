// Copyright (c) 2026 CGAL Global Shape Analysis contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_POINT_SET_OBJECT_RECOGNITION_RECOGNIZE_OBJECTS_H
#define CGAL_POINT_SET_OBJECT_RECOGNITION_RECOGNIZE_OBJECTS_H

/// \file recognize_objects.h
/// The whole chain (background removal, localization, segmentation) on a scan of any size, tile
/// by tile: each tile is processed with the points of a margin around it, so that the memory of
/// the grids and graphs is that of one tile.

#include <CGAL/Point_set_3.h>

#include <CGAL/Point_set_object_recognition/extract_object_features.h>
#include <CGAL/Point_set_object_recognition/locate_objects.h>
#include <CGAL/Point_set_object_recognition/remove_background.h>
#include <CGAL/Point_set_object_recognition/segment_objects.h>
#include <CGAL/Shape_analysis/Bad_input.h>
#include <CGAL/Shape_analysis/internal/Parallel.h>
#include <CGAL/Shape_analysis/parameters.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <functional>
#include <iterator>
#include <limits>
#include <memory>
#include <optional>
#include <type_traits>
#include <vector>

namespace CGAL {
namespace Point_set_object_recognition {

/// \ingroup PkgPointSetObjectRecognitionRef
/// A square tile of the horizontal plane processed by `recognize_objects()`.
struct Scene_tile
{
  /// its own part of the plane: the points with `min[0] <= x < max[0]` and `min[1] <= y < max[1]`
  /// (the last row and column may hold points rounded onto their upper border)
  std::array<double, 2> min{{0, 0}}, max{{0, 0}};
  std::size_t number_of_points = 0;    ///< the points it was processed with: its own and its margin's
  std::size_t number_of_locations = 0; ///< the locations found in its own part
  double seconds = 0;                  ///< the time its processing took
};

/// \ingroup PkgPointSetObjectRecognitionRef
/// The result of `recognize_objects()`.
struct Object_recognition_result
{
  std::vector<Object_location> locations;   ///< the objects found, tile after tile
  std::vector<Object_segmentation> objects; ///< one per location; point indices into the input
  /// Per input point, the location whose object holds it (when several do: the one horizontally
  /// nearest to the point, the first at equal distances), or `no_object`.
  std::vector<std::size_t> object_of_point;
  static constexpr std::size_t no_object = std::size_t(-1); ///< see `object_of_point`
  /// Per input point, what the background removal of its own tile made of it.
  std::vector<Point_kind> kind;
  /// With an `object_classifier`: per location, its class (the classifier's; with one trained by
  /// `train_object_classifier()`, the number of classes means background); empty otherwise.
  std::vector<std::size_t> labels;
  std::vector<double> confidences; ///< per location, the classifier's confidence in its label
  /// With an `object_classifier`: per location, the features it was classified from (a row of
  /// `extract_object_features()`, e.g. to add context features and classify again); else empty.
  std::vector<std::vector<double>> features;
  std::vector<Scene_tile> tiles;   ///< the tiles that hold points, in the order processed
  std::size_t largest_tile = 0;    ///< the most points a tile was processed with
  double seconds = 0;              ///< the whole call
};

/*!
\ingroup PkgPointSetObjectRecognitionRef

The options of `recognize_objects()`: each member is the named parameter of the same name,
initialized to its default. This struct is where the defaults are written; the manual,
`recognize_objects_options()` and the `shape_analysis points recognize` command take them from
here. The segmentation's defaults are those of `segment_objects()` (`Segment_objects_options`);
the localization's method has a default of its own (the thesis' method, rather than the faster
default of `locate_objects()`). The other parameters of the three stages take the defaults of
`Remove_background_options`, `Locate_objects_options` and `Segment_objects_options`.
*/
struct Recognize_objects_options
{
  /// the side of the tiles, in metres (positive)
  double tile_size = 100;
  /// the width of the band around a tile whose points it is processed with, in metres (zero or
  /// positive)
  double tile_margin = 10;
  /// a corner (x, y) of the grid of tiles (finite); none: the lower corner of the points'
  /// horizontal bounding box
  std::optional<std::array<double, 2>> tile_origin;
  /// how `locate_objects()` groups the foreground points
  Localization_method localization_method = Localization_method::NORMALIZED_CUT;
  /// how `segment_objects()` separates each object
  Segmentation_method segmentation_method = Segment_objects_options().segmentation_method;
  /// the background radius of the segmentation methods other than the automatic one, in metres
  /// (positive)
  double background_radius = Segment_objects_options().background_radius;
  /// the largest number of threads of the loop over the tiles and of each stage within a tile
  /// (0: TBB's choice)
  std::size_t number_of_threads = 0;
};

/*!
\ingroup PkgPointSetObjectRecognitionRef

The options that `recognize_objects()` reads from the named parameters `np`: the value of each
named parameter given, the default of `Recognize_objects_options` for the others. The values are
not checked here; `recognize_objects()` checks them. Named parameters that are not options
(property maps) are ignored.

\tparam NamedParameters a sequence of named parameters
\param np the named parameters of `recognize_objects()`
\returns the options
*/
template <typename NamedParameters = parameters::Default_named_parameters>
Recognize_objects_options recognize_objects_options(const NamedParameters& np = parameters::default_values())
{
  using CGAL::Shape_analysis::internal::parameter_value;
  namespace snp = CGAL::Shape_analysis::internal_np;
  Recognize_objects_options o;
  o.tile_size = parameter_value(np, snp::tile_size_tag, o.tile_size);
  o.tile_margin = parameter_value(np, snp::tile_margin_tag, o.tile_margin);
  o.tile_origin = parameter_value(np, snp::tile_origin_tag, o.tile_origin);
  o.localization_method = parameter_value(np, snp::localization_method_tag, o.localization_method);
  o.segmentation_method = parameter_value(np, snp::segmentation_method_tag, o.segmentation_method);
  o.background_radius = parameter_value(np, snp::background_radius_tag, o.background_radius);
  o.number_of_threads = parameter_value(np, snp::number_of_threads_tag, o.number_of_threads);
  return o;
}

/// \cond SKIP_IN_MANUAL
namespace internal {

// The options of recognize_objects() and those of its three stages within a tile.
struct Recognition_options : Recognize_objects_options
{
  Remove_background_options background;
  Locate_objects_options localization;
  Segment_objects_options segmentation;
  // With a classifier: the label and confidence of features (one row), else empty.
  std::function<std::size_t(const std::vector<double>&, double&)> classify;
};

// The options of the stages from those of recognize_objects(), checked (Bad_input).
inline Recognition_options recognition_options(const Recognize_objects_options& r)
{
  if(r.tile_origin && (!std::isfinite((*r.tile_origin)[0]) || !std::isfinite((*r.tile_origin)[1])))
    throw Bad_input("recognize_objects: tile_origin must be finite");
  if(!(r.tile_size > 0) || !std::isfinite(r.tile_size))
    throw Bad_input("recognize_objects: tile_size must be a positive number");
  if(!(r.tile_margin >= 0) || !std::isfinite(r.tile_margin))
    throw Bad_input("recognize_objects: tile_margin must be zero or a positive number");
  Recognition_options o;
  static_cast<Recognize_objects_options&>(o) = r;
  o.localization.localization_method = r.localization_method;
  o.localization.number_of_threads = r.number_of_threads;
  o.segmentation.segmentation_method = r.segmentation_method;
  o.segmentation.background_radius = r.background_radius;
  o.segmentation.number_of_threads = r.number_of_threads;
  check_segmentation_options(o.segmentation, "recognize_objects");
  return o;
}

// Tiles of side `side` from `lo`, `n` of them along each axis (clamped: a
// coordinate rounded out of the grid belongs to the nearest tile).
struct Tile_grid
{
  std::array<double, 2> lo{{0, 0}};
  double side = 1;
  long nx = 1, ny = 1;

  long column(double x) const { return clamped((x - lo[0]) / side, nx); }
  long row(double y) const { return clamped((y - lo[1]) / side, ny); }
  // floor(t) clamped to [0, n - 1] before the conversion (no overflow, NaN to 0).
  static long clamped(double t, long n)
  {
    const double f = std::floor(t);
    return f >= double(n - 1) ? n - 1 : (f > 0 ? long(f) : 0L);
  }
  std::size_t tile(double x, double y) const { return std::size_t(row(y) * nx + column(x)); }
};

// What one tile found: its locations and their objects (point indices in the input).
struct Tile_output
{
  Scene_tile tile;
  std::vector<Object_location> locations;
  std::vector<Object_segmentation> objects;
  std::vector<std::size_t> labels;
  std::vector<double> confidences;
  std::vector<std::vector<double>> features;
};

// The tiles of the scene of the n points `point(i)`; Bad_input for a coordinate that is not finite
// or too many tiles.
template <typename PointAt>
Tile_grid scene_tiles(std::size_t n, const PointAt& point, const Recognition_options& o)
{
  std::array<double, 2> lo{{point(0)[0], point(0)[1]}}, hi = lo;
  for(std::size_t i = 0; i < n; ++i) {
    const P3 q = point(i);
    if(!std::isfinite(q[0]) || !std::isfinite(q[1]) || !std::isfinite(q[2]))
      throw Bad_input("recognize_objects: a coordinate is not finite");
    lo[0] = (std::min)(lo[0], q[0]), lo[1] = (std::min)(lo[1], q[1]);
    hi[0] = (std::max)(hi[0], q[0]), hi[1] = (std::max)(hi[1], q[1]);
  }
  // The tiles start at the corner of the bounding box, or on the grid of the given origin (so that
  // separate runs on parts of a scene have the same tiles).
  Tile_grid grid;
  grid.lo = lo;
  if(o.tile_origin)
    for(int c = 0; c < 2; ++c)
      grid.lo[c] = (*o.tile_origin)[c] + std::floor((lo[c] - (*o.tile_origin)[c]) / o.tile_size) * o.tile_size;
  grid.side = o.tile_size;
  const double nx = std::floor((hi[0] - grid.lo[0]) / o.tile_size) + 1,
               ny = std::floor((hi[1] - grid.lo[1]) / o.tile_size) + 1;
  if(!(nx * ny <= 1e8))
    throw Bad_input("recognize_objects: more than 10^8 tiles (use a larger tile_size)");
  grid.nx = long(nx), grid.ny = long(ny);
  return grid;
}

// The points by tile (a counting sort; within a tile, in input order): those of tile t are
// order[first[t]] to order[first[t + 1] - 1].
template <typename PointAt>
void sort_by_tile(std::size_t n, const PointAt& point, const Tile_grid& grid, std::vector<std::uint32_t>& first,
                  std::vector<std::uint32_t>& order)
{
  const std::size_t tiles = std::size_t(grid.nx * grid.ny);
  first.assign(tiles + 1, 0);
  order.assign(n, 0);
  std::vector<std::uint32_t> tile_of(n);
  for(std::size_t i = 0; i < n; ++i) {
    const P3 q = point(i);
    ++first[(tile_of[i] = std::uint32_t(grid.tile(q[0], q[1]))) + 1];
  }
  for(std::size_t t = 0; t < tiles; ++t)
    first[t + 1] += first[t];
  std::vector<std::uint32_t> fill(first.begin(), first.end() - 1);
  for(std::size_t i = 0; i < n; ++i)
    order[fill[tile_of[i]]++] = std::uint32_t(i);
}

// The tile that keeps a location: the one holding it or, when that one holds no point (a
// location over a hole of the scan), the first of its neighbours that holds some; the number of
// tiles for none.
inline std::size_t location_owner(const Tile_grid& grid, const std::vector<std::uint32_t>& first, const P3& l)
{
  const long cx = grid.column(l[0]), cy = grid.row(l[1]);
  const std::size_t u = std::size_t(cy * grid.nx + cx);
  if(first[u] != first[u + 1])
    return u;
  for(long j = (std::max)(0L, cy - 1); j <= (std::min)(grid.ny - 1, cy + 1); ++j)
    for(long i = (std::max)(0L, cx - 1); i <= (std::min)(grid.nx - 1, cx + 1); ++i) {
      const std::size_t v = std::size_t(j * grid.nx + i);
      if(first[v] != first[v + 1])
        return v;
    }
  return first.size() - 1; // none
}

// The points of tile t and those of its margin (in the tiles up to `reach` away), in input order.
template <typename PointAt>
std::vector<std::uint32_t> tile_points(std::size_t t, const Scene_tile& tile, long reach, const Tile_grid& grid,
                                       const std::vector<std::uint32_t>& first, const std::vector<std::uint32_t>& order,
                                       const PointAt& point, double margin)
{
  const long tx = long(t % std::size_t(grid.nx)), ty = long(t / std::size_t(grid.nx));
  std::vector<std::uint32_t> local;
  for(long j = (std::max)(0L, ty - reach); j <= (std::min)(grid.ny - 1, ty + reach); ++j)
    for(long i = (std::max)(0L, tx - reach); i <= (std::min)(grid.nx - 1, tx + reach); ++i) {
      const std::size_t u = std::size_t(j * grid.nx + i);
      for(std::uint32_t k = first[u]; k < first[u + 1]; ++k) {
        if(u == t) { // its own points (whatever the rounding)
          local.push_back(order[k]);
          continue;
        }
        const P3 a = point(order[k]);
        if(a[0] >= tile.min[0] - margin && a[0] <= tile.max[0] + margin && a[1] >= tile.min[1] - margin &&
           a[1] <= tile.max[1] + margin)
          local.push_back(order[k]);
      }
    }
  std::sort(local.begin(), local.end());
  return local;
}

// Tile t on its own: the background removal of its points and those of its margin (the kinds of
// its own points into `kind`), the locations that fall in it, their objects.
template <typename PointAt>
void process_tile(std::size_t t, long reach, const Tile_grid& grid, const std::vector<std::uint32_t>& first,
                  const std::vector<std::uint32_t>& order, const PointAt& point, const Recognition_options& o,
                  std::vector<Point_kind>& kind, Tile_output& out)
{
  const long tx = long(t % std::size_t(grid.nx)), ty = long(t / std::size_t(grid.nx));
  const auto tile_start = std::chrono::steady_clock::now();
  Scene_tile& tile = out.tile;
  tile.min = {{grid.lo[0] + double(tx) * o.tile_size, grid.lo[1] + double(ty) * o.tile_size}};
  tile.max = {{tile.min[0] + o.tile_size, tile.min[1] + o.tile_size}};
  const std::vector<std::uint32_t> local = tile_points(t, tile, reach, grid, first, order, point, o.tile_margin);
  std::vector<P3> q(local.size());
  for(std::size_t k = 0; k < local.size(); ++k)
    q[k] = point(local[k]);
  tile.number_of_points = local.size();

  const Background_removal_result background = internal::remove_background(q, o.background);
  // The kinds of its own points (no other tile writes them).
  for(std::size_t k = 0; k < local.size(); ++k)
    if(grid.tile(q[k][0], q[k][1]) == t)
      kind[local[k]] = background.kind[k];
  std::vector<P3> foreground(background.foreground.size());
  for(std::size_t k = 0; k < foreground.size(); ++k)
    foreground[k] = q[background.foreground[k]];
  const Localization_result found = internal::locate_objects(foreground, o.localization);
  std::vector<P3> own;
  for(const Object_location& l : found.locations)
    if(location_owner(grid, first, l.position) == t) {
      out.locations.push_back(l);
      own.push_back(l.position);
    }
  tile.number_of_locations = own.size();
  if(!own.empty()) {
    const std::vector<std::size_t> above = points_above_ground(background);
    std::vector<P3> kept(above.size());
    for(std::size_t k = 0; k < above.size(); ++k)
      kept[k] = q[above[k]];
    // With a classifier, the segmenter of the features serves this segmentation when it can.
    std::unique_ptr<Object_segmenter> shared;
    if(o.classify && features_share_segmenter(o.segmentation))
      shared = feature_segmenter(kept, own, o.segmentation);
    Segmentation_result s = shared ? shared->segment(own, o.segmentation) : segment_objects(kept, own, o.segmentation);
    if(o.classify) { // the features of the tile's objects among its own points, this segmentation reused
      Object_features f = object_features(kept, own, o.segmentation, Extract_object_features_options().spin_image_radius,
                                          &s.objects, shared.get());
      out.labels.resize(own.size());
      out.confidences.resize(own.size());
      for(std::size_t k = 0; k < own.size(); ++k)
        out.labels[k] = o.classify(f.values[k], out.confidences[k]);
      out.features = std::move(f.values);
    }
    for(Object_segmentation& object : s.objects) {
      for(std::size_t& i : object.points)
        i = local[above[i]]; // increasing, as `above` and `local` are
      if(object.seed != Object_segmentation::no_point)
        object.seed = local[above[object.seed]];
    }
    out.objects = std::move(s.objects);
  }
  tile.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - tile_start).count();
}

// The outputs of the tiles merged in the order of the tiles: a point segmented by several
// objects goes to the one whose location is horizontally nearest (the first on a tie).
template <typename PointAt>
void merge_tiles(std::vector<Tile_output>& outputs, const PointAt& point, Object_recognition_result& r)
{
  for(Tile_output& out : outputs) {
    r.largest_tile = (std::max)(r.largest_tile, out.tile.number_of_points);
    // One object per location (segment_objects()): object k is that of location k.
    for(std::size_t k = 0; k < out.locations.size(); ++k) {
      const std::size_t id = r.objects.size();
      r.locations.push_back(out.locations[k]);
      const P3& at = r.locations[id].position;
      for(std::size_t i : out.objects[k].points) {
        std::size_t& claim = r.object_of_point[i];
        const P3 a = point(i);
        if(claim == Object_recognition_result::no_object ||
           horizontal_distance(a, at) < horizontal_distance(a, r.locations[claim].position))
          claim = id;
      }
      r.objects.push_back(std::move(out.objects[k]));
    }
    r.labels.insert(r.labels.end(), out.labels.begin(), out.labels.end());
    r.confidences.insert(r.confidences.end(), out.confidences.begin(), out.confidences.end());
    r.features.insert(r.features.end(), std::make_move_iterator(out.features.begin()),
                      std::make_move_iterator(out.features.end()));
    r.tiles.push_back(out.tile);
    out = Tile_output();
  }
  // A point of a margin segmented by one tile may be ground for its own tile: an object holds no
  // ground point.
  for(std::size_t id = 0; id < r.objects.size(); ++id) {
    std::vector<std::size_t>& points = r.objects[id].points;
    points.erase(std::remove_if(points.begin(), points.end(),
                                [&](std::size_t i) {
                                  if(r.kind[i] != Point_kind::GROUND)
                                    return false;
                                  r.object_of_point[i] = Object_recognition_result::no_object;
                                  return true;
                                }),
                 points.end());
  }
}

// `point(i)` gives the coordinates of point i < n, read as the tiles need them (no copy of the
// whole cloud).
template <typename PointAt>
Object_recognition_result recognize_objects(std::size_t n, const PointAt& point, const Recognition_options& o)
{
  const auto start = std::chrono::steady_clock::now();
  if(n == 0)
    throw Bad_input("recognize_objects: the point cloud is empty");
  if(n >= std::size_t(std::numeric_limits<std::uint32_t>::max()))
    throw Bad_input("recognize_objects: too many points (at most 2^32 - 2)");
  const Tile_grid grid = scene_tiles(n, point, o);
  const std::size_t tiles = std::size_t(grid.nx * grid.ny);
  std::vector<std::uint32_t> first, order;
  sort_by_tile(n, point, grid, first, order);

  Object_recognition_result r;
  r.object_of_point.assign(n, Object_recognition_result::no_object);
  r.kind.assign(n, Point_kind::GROUND);
  // The tiles whose points can lie within the margin (bounded by the grid: any margin is valid).
  const long reach = long((std::min)(std::floor(o.tile_margin / o.tile_size) + 1, double((std::max)(grid.nx, grid.ny))));
  // The tiles run in parallel (each with its own buffers, freed when it ends, and its stages with
  // `number_of_threads`); their locations and objects are merged in the order of the tiles, so
  // that the result does not depend on the number of threads.
  std::vector<std::size_t> busy; // the tiles that hold points
  for(std::size_t t = 0; t < tiles; ++t)
    if(first[t] != first[t + 1])
      busy.push_back(t);
  std::vector<Tile_output> outputs(busy.size());
  CGAL::Shape_analysis::internal::Parallel_workspaces<char> parallel(o.number_of_threads);
  parallel.for_each(0, busy.size(), [&](std::size_t b, char&) {
    process_tile(busy[b], reach, grid, first, order, point, o, r.kind, outputs[b]);
  });
  merge_tiles(outputs, point, r);
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return r;
}

// recognize_objects() of a random-access range read through `point_map`, in place.
template <typename PointRange, typename PointMap>
Object_recognition_result recognize_objects_of_range(const PointRange& points, const PointMap& point_map,
                                                     const Recognition_options& o)
{
  const auto begin = std::begin(points);
  return recognize_objects(std::size_t(std::distance(begin, std::end(points))), [&](std::size_t i) {
    const auto& q = get(point_map, *(begin + std::ptrdiff_t(i)));
    return P3{{CGAL::to_double(q.x()), CGAL::to_double(q.y()), CGAL::to_double(q.z())}};
  }, o);
}

// The options of recognize_objects() from its named parameters, with the classifier given as
// `object_classifier` (a model of ObjectClassifier; copied, its models share their trained data).
template <typename NamedParameters>
Recognition_options recognition_options_of(const NamedParameters& np)
{
  Recognition_options o = recognition_options(recognize_objects_options(np));
  const auto& classifier =
      CGAL::parameters::get_parameter_reference(np, CGAL::Shape_analysis::internal_np::object_classifier_tag);
  typedef std::decay_t<decltype(classifier)> Classifier;
  if constexpr(!std::is_same<Classifier, CGAL::internal_np::Param_not_found>::value) {
    if(!classifier.is_trained())
      throw Bad_input("recognize_objects: the object_classifier is not trained");
    o.classify = [c = classifier](const std::vector<double>& f, double& confidence) { return c.predict(f, confidence); };
  }
  return o;
}

} // namespace internal
/// \endcond

/*!
\ingroup PkgPointSetObjectRecognitionRef

Finds and segments the objects of a scanned scene of any size: `remove_background()`, then
`locate_objects()` among the foreground, then `segment_objects()` of the located objects among the
points above the ground, as \cgalCite{Golovinskiy2010} (chapter 4) chains them, tile by tile.

The horizontal plane is cut into squares of side `tile_size` from the corner of the points'
bounding box (or on the grid through `tile_origin`). Each square that holds points (a tile) is processed on its own points and on those within `tile_margin` of it,
and keeps the locations that fall in it (a location over a square without points goes to the
first neighbouring tile). An object across a border is then found by the tile that holds its
location, with all its surroundings when the margin is wider than the object plus the reach of the
segmentation (the largest background radius plus 2 m: 9 m for the automatic radius); since each
tile locates objects in its own view, an object right at a border can still, rarely, be located
on both sides or on neither. A point keeps the kind (`Point_kind`) that its own tile gives it,
and an object keeps none of the points its own tiles find to be ground. The grids and graphs are
those of the tiles being processed, at most `number_of_threads` of them at a time (each with its
stages' threads inside): their memory does not grow with the scene, only the per-point results
do; and localization by normalized cuts, whose time grows faster than the number of points, is
applied to tiles of bounded size. The locations and objects of the tiles are merged in the
order of the tiles, so the results are the same for any number of threads. Since a tile depends only on the points
within its margin, separate processes (on a cluster) can each be given the points of a band of
whole tiles plus those within `tile_margin` of it, with one `tile_origin` for all, and keep the
tiles of their band: those tiles come out as in a single run with that origin (the points in the
same relative order).

\tparam PointRange a model of `ConstRange` whose iterator type is `RandomAccessIterator`
\tparam NamedParameters a sequence of named parameters

\param points the whole scan (ground included), metres, \f$z\f$ up
\param np an optional sequence of named parameters among the ones listed below

\cgalNamedParamsBegin
  \cgalParamNBegin{point_map}
    \cgalParamDescription{a property map associating points to the elements of `points`}
    \cgalParamType{a model of `ReadablePropertyMap` whose value type is a point of a \cgal kernel}
    \cgalParamDefault{`CGAL::Identity_property_map`}
  \cgalParamNEnd
  \cgalParamNBegin{tile_size}
    \cgalParamDescription{the side of the tiles, in metres}
    \cgalParamType{`double`}
    \cgalParamDefault{`Recognize_objects_options::tile_size`}
    \cgalParamExtra{must be positive; the whole scene is one tile when it is larger than the scene}
  \cgalParamNEnd
  \cgalParamNBegin{tile_margin}
    \cgalParamDescription{the width of the band around a tile whose points it is processed with, in metres}
    \cgalParamType{`double`}
    \cgalParamDefault{`Recognize_objects_options::tile_margin`}
    \cgalParamExtra{must be zero or positive; below the segmentation's reach (9 m), objects near a
      border lose their surroundings; below the background removal's `maximum_component_extent`,
      a building that only pokes into the margin may be kept as foreground there (it
      does not change the tile's own points' kinds, only what its localization sees)}
  \cgalParamNEnd
  \cgalParamNBegin{tile_origin}
    \cgalParamDescription{a corner of the grid of tiles (x, y): the tiles are the squares of side
      `tile_size` whose corners are this point plus multiples of `tile_size`}
    \cgalParamType{`std::array<double, 2>`}
    \cgalParamDefault{`Recognize_objects_options::tile_origin`: none, that is the lower corner of
      the points' horizontal bounding box}
    \cgalParamExtra{must be finite}
  \cgalParamNEnd
  \cgalParamNBegin{localization_method}
    \cgalParamDescription{how `locate_objects()` groups the foreground points}
    \cgalParamType{`Localization_method`}
    \cgalParamDefault{`Recognize_objects_options::localization_method`}
  \cgalParamNEnd
  \cgalParamNBegin{segmentation_method}
    \cgalParamDescription{how `segment_objects()` separates each object}
    \cgalParamType{`Segmentation_method`}
    \cgalParamDefault{`Recognize_objects_options::segmentation_method`}
  \cgalParamNEnd
  \cgalParamNBegin{background_radius}
    \cgalParamDescription{the background radius of the segmentation methods other than the automatic one, in metres}
    \cgalParamType{`double`}
    \cgalParamDefault{`Recognize_objects_options::background_radius`}
    \cgalParamExtra{must be positive}
  \cgalParamNEnd
  \cgalParamNBegin{object_classifier}
    \cgalParamDescription{a trained classifier (a model of the `ObjectClassifier` concept, e.g. one
      trained by `train_object_classifier()`); each object then gets the class it predicts from
      the features of `extract_object_features()` (with the segmentation's options and the default
      spin image), computed within the object's tile, in `Object_recognition_result::labels` and
      `Object_recognition_result::confidences`}
    \cgalParamType{a model of `ObjectClassifier`}
    \cgalParamDefault{none: the objects are not classified}
    \cgalParamExtra{must be trained}
  \cgalParamNEnd
  \cgalParamNBegin{number_of_threads}
    \cgalParamDescription{the largest number of threads of the loop over the tiles and of each stage
      within a tile (0: TBB's choice); the results do not depend on it}
    \cgalParamType{`std::size_t`}
    \cgalParamDefault{`Recognize_objects_options::number_of_threads`}
  \cgalParamNEnd
\cgalNamedParamsEnd

The other parameters of the three stages take the defaults of `Remove_background_options`,
`Locate_objects_options` and `Segment_objects_options`.

\returns the locations, one segmentation per location, the object and the kind of every point,
         the tiles with their sizes and times, and, with a classifier, the class of every location

\throws CGAL::Shape_analysis::Bad_input if the cloud is empty or holds \f$2^{32} - 1\f$ points or
        more, a coordinate is not finite, a parameter is out of its range, the scene would have
        more than \f$10^8\f$ tiles, a stage rejects a tile (as `remove_background()`,
        `locate_objects()` and `segment_objects()` do: a tile too tall for their grids), or the
        classifier is not trained or was trained on features of another dimension
*/
template <typename PointRange, typename NamedParameters = parameters::Default_named_parameters>
Object_recognition_result recognize_objects(const PointRange& points,
                                            const NamedParameters& np = parameters::default_values())
{
  typedef typename std::iterator_traits<typename PointRange::const_iterator>::value_type Value;
  const auto point_map = CGAL::parameters::choose_parameter(
    CGAL::parameters::get_parameter(np, CGAL::internal_np::point_map), CGAL::Identity_property_map<Value>());
  return internal::recognize_objects_of_range(points, point_map, internal::recognition_options_of(np));
}

/// \ingroup PkgPointSetObjectRecognitionRef
/// `recognize_objects()` of the points of a `CGAL::Point_set_3` (its point map).
/// \tparam Point the point type of the point set
/// \tparam Vector the normal type of the point set
/// \tparam NamedParameters a sequence of named parameters
/// \param point_set the whole scan
/// \param np the same named parameters as the other overload, but `point_map`
/// \returns as the other overload; point indices follow the point set's iteration order
template <typename Point, typename Vector, typename NamedParameters = parameters::Default_named_parameters>
Object_recognition_result recognize_objects(const CGAL::Point_set_3<Point, Vector>& point_set,
                                            const NamedParameters& np = parameters::default_values())
{
  return internal::recognize_objects_of_range(point_set, point_set.point_map(), internal::recognition_options_of(np));
}

} // namespace Point_set_object_recognition
} // namespace CGAL

#endif // CGAL_POINT_SET_OBJECT_RECOGNITION_RECOGNIZE_OBJECTS_H
