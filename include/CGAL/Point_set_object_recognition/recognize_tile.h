// Copyright (c) 2026 CGAL Global Shape Analysis contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_POINT_SET_OBJECT_RECOGNITION_RECOGNIZE_TILE_H
#define CGAL_POINT_SET_OBJECT_RECOGNITION_RECOGNIZE_TILE_H

/// \file recognize_tile.h
/// The tiles of a scene and the recognition of one tile: what `recognize_objects()` does tile by
/// tile, for engines of their own (out of core, on a cluster) to drive.

#include <CGAL/Bbox_2.h>
#include <CGAL/Point_set_3.h>

#include <CGAL/Point_set_object_recognition/extract_object_features.h>
#include <CGAL/Point_set_object_recognition/locate_objects.h>
#include <CGAL/Point_set_object_recognition/remove_background.h>
#include <CGAL/Point_set_object_recognition/segment_objects.h>
#include <CGAL/Shape_analysis/Bad_input.h>
#include <CGAL/Shape_analysis/parameters.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <functional>
#include <iterator>
#include <memory>
#include <optional>
#include <string>
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

// Checks the tile options of `r` (Bad_input naming `who`).
inline void check_tile_options(const Recognize_objects_options& r, const std::string& who)
{
  if(r.tile_origin && (!std::isfinite((*r.tile_origin)[0]) || !std::isfinite((*r.tile_origin)[1])))
    throw Bad_input(who + ": tile_origin must be finite");
  if(!(r.tile_size > 0) || !std::isfinite(r.tile_size))
    throw Bad_input(who + ": tile_size must be a positive number");
  if(!(r.tile_margin >= 0) || !std::isfinite(r.tile_margin))
    throw Bad_input(who + ": tile_margin must be zero or a positive number");
}

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
  check_tile_options(r, "recognize_objects");
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

// The options of recognize_objects() from its named parameters, with the classifier given as
// `object_classifier` (a model of ObjectClassifier; copied, its models share their trained data).
template <typename NamedParameters>
Recognition_options recognition_options_of(const NamedParameters& np, const Recognize_objects_options& r)
{
  Recognition_options o = recognition_options(r);
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


template <typename NamedParameters>
Recognition_options recognition_options_of(const NamedParameters& np)
{
  return recognition_options_of(np, recognize_objects_options(np));
}

} // namespace internal
/// \endcond

/*!
\ingroup PkgPointSetObjectRecognitionRef

The tiles of a scene, as `recognize_objects()` cuts it: squares of side `tile_size` in the
horizontal plane, tile `t` at column `t % columns` and row `t / columns` from `origin`, each
processed with the points within `tile_margin` of it. The plan is what an engine of its own (out
of core, on a cluster) needs to drive `recognize_tile()`: which tile owns a point, which tiles
must see it, which tile keeps a location. `plan_tiles()` makes one.
*/
struct Tile_plan
{
  std::array<double, 2> origin{{0, 0}}; ///< the lower corner of tile 0
  double tile_size = 100;               ///< the side of the tiles, in metres
  double tile_margin = 10;              ///< the width of the band of points around a tile that it sees
  std::size_t columns = 1;              ///< tiles along x
  std::size_t rows = 1;                 ///< tiles along y
  /// Per tile, the points it owns (`tile_of()`); filled by `add_point()` (`plan_tiles()` of a
  /// range does it). `owner_of_location()` reads it.
  std::vector<std::size_t> number_of_points;

  /// \returns the number of tiles, `columns * rows`
  std::size_t number_of_tiles() const { return columns * rows; }

  /// The tile that owns a point: the square that holds it, a point outside the grid (or not
  /// finite) going to the nearest tile along each axis.
  /// \param x,y the point's horizontal coordinates
  /// \returns the tile, below `number_of_tiles()`
  std::size_t tile_of(double x, double y) const { return row(y) * columns + column(x); }

  /// \param t a tile, below `number_of_tiles()`
  /// \returns the square of tile `t` (`Scene_tile::min`, `Scene_tile::max`; its counts and time 0)
  Scene_tile tile(std::size_t t) const
  {
    Scene_tile s;
    s.min = {{origin[0] + double(t % columns) * tile_size, origin[1] + double(t / columns) * tile_size}};
    s.max = {{s.min[0] + tile_size, s.min[1] + tile_size}};
    return s;
  }

  /// Whether a tile is processed with a point: it owns it, or the point lies within
  /// `tile_margin` of its square (horizontally, along each axis).
  /// \param t a tile, below `number_of_tiles()`
  /// \param x,y the point's horizontal coordinates
  /// \returns whether tile `t` holds the point
  bool holds(std::size_t t, double x, double y) const
  {
    const std::size_t own = tile_of(x, y);
    if(own == t)
      return true;
    const long dx = long(t % columns) - long(own % columns), dy = long(t / columns) - long(own / columns);
    if(std::abs(dx) > reach() || std::abs(dy) > reach())
      return false;
    const Scene_tile s = tile(t);
    return x >= s.min[0] - tile_margin && x <= s.max[0] + tile_margin && y >= s.min[1] - tile_margin &&
           y <= s.max[1] + tile_margin;
  }

  /// Calls `f(t)` for every tile `t` that `holds()` a point, in increasing order.
  /// \tparam F a callable taking a `std::size_t`
  /// \param x,y the point's horizontal coordinates
  /// \param f called with each tile
  template <typename F>
  void for_each_tile_holding(double x, double y, const F& f) const
  {
    const std::size_t own = tile_of(x, y);
    const long cx = long(own % columns), cy = long(own / columns), r = reach();
    // Most points lie farther than the margin from their square's sides (with room for the
    // rounding of the neighbours' sides): their tile alone holds them.
    const double x0 = origin[0] + double(cx) * tile_size, y0 = origin[1] + double(cy) * tile_size;
    const double room = tile_margin + 1e-9 * (std::abs(x) + std::abs(y) + tile_size);
    if(x - x0 > room && x0 + tile_size - x > room && y - y0 > room && y0 + tile_size - y > room) {
      f(own);
      return;
    }
    for(long j = (std::max)(0L, cy - r); j <= (std::min)(long(rows) - 1, cy + r); ++j)
      for(long i = (std::max)(0L, cx - r); i <= (std::min)(long(columns) - 1, cx + r); ++i) {
        const std::size_t t = std::size_t(j) * columns + std::size_t(i);
        if(holds(t, x, y))
          f(t);
      }
  }

  /// The tile that keeps a location: the one that owns its position if that tile owns points,
  /// or else the first of its eight neighbours (row by row) that does.
  /// \param x,y the location's horizontal coordinates
  /// \returns the tile, or `number_of_tiles()` when no tile around owns points
  std::size_t owner_of_location(double x, double y) const
  {
    const std::size_t cx = column(x), cy = row(y), own = cy * columns + cx;
    if(own < number_of_points.size() && number_of_points[own] > 0)
      return own;
    for(std::size_t j = cy > 0 ? cy - 1 : 0; j <= (std::min)(rows - 1, cy + 1); ++j)
      for(std::size_t i = cx > 0 ? cx - 1 : 0; i <= (std::min)(columns - 1, cx + 1); ++i) {
        const std::size_t t = j * columns + i;
        if(t < number_of_points.size() && number_of_points[t] > 0)
          return t;
      }
    return number_of_tiles();
  }

  /// Counts a point in `number_of_points` (of the tile that owns it).
  /// \param x,y the point's horizontal coordinates
  void add_point(double x, double y) { ++number_of_points[tile_of(x, y)]; }

  /// \returns the tiles that own points, in increasing order: those `recognize_objects()` processes
  std::vector<std::size_t> tiles_with_points() const
  {
    std::vector<std::size_t> busy;
    for(std::size_t t = 0; t < number_of_points.size(); ++t)
      if(number_of_points[t] > 0)
        busy.push_back(t);
    return busy;
  }

  /// \returns how many tiles away along an axis the points that a tile holds can be owned (at least 1)
  long reach() const
  {
    return long((std::min)(std::floor(tile_margin / tile_size) + 1, double((std::max)(columns, rows))));
  }

private:
  std::size_t column(double x) const { return clamped((x - origin[0]) / tile_size, columns); }
  std::size_t row(double y) const { return clamped((y - origin[1]) / tile_size, rows); }
  // floor(v) clamped to [0, n - 1] before the conversion (no overflow; NaN to 0).
  static std::size_t clamped(double v, std::size_t n)
  {
    const double f = std::floor(v);
    return f >= double(n - 1) ? n - 1 : (f > 0 ? std::size_t(f) : 0);
  }
};

/// \ingroup PkgPointSetObjectRecognitionRef
/// What `recognize_tile()` found in one tile.
struct Tile_recognition
{
  Scene_tile tile; ///< the tile's square, the points it was processed with, its locations and time
  /// the locations that the tile keeps (`Tile_plan::owner_of_location()`), in the order found
  std::vector<Object_location> locations;
  /// one per location: its object, as indices into the points given to `recognize_tile()`
  std::vector<Object_segmentation> objects;
  /// per point given, what the tile's background removal made of it (final for the points the
  /// tile owns; a point of the margin keeps the kind its own tile gives it)
  std::vector<Point_kind> kind;
  std::vector<std::size_t> labels;          ///< with an `object_classifier`: per location, its class
  std::vector<double> confidences;          ///< with an `object_classifier`: per location, the confidence
  std::vector<std::vector<double>> features; ///< with an `object_classifier`: per location, its features
};

/// \cond SKIP_IN_MANUAL
namespace internal {

// The plan of the tiles over the horizontal box [lo, hi] (its counts zero).
inline Tile_plan tile_plan(const std::array<double, 2>& lo, const std::array<double, 2>& hi,
                           const Recognize_objects_options& r, const std::string& who)
{
  check_tile_options(r, who);
  for(int c = 0; c < 2; ++c)
    if(!std::isfinite(lo[c]) || !std::isfinite(hi[c]) || lo[c] > hi[c])
      throw Bad_input(who + ": the box of the scene must be finite and not empty");
  // The tiles start at the corner of the box, or on the grid of the given origin (so that
  // separate runs on parts of a scene have the same tiles).
  Tile_plan plan;
  plan.origin = lo;
  if(r.tile_origin)
    for(int c = 0; c < 2; ++c)
      plan.origin[c] = (*r.tile_origin)[c] + std::floor((lo[c] - (*r.tile_origin)[c]) / r.tile_size) * r.tile_size;
  plan.tile_size = r.tile_size;
  plan.tile_margin = r.tile_margin;
  const double nx = std::floor((hi[0] - plan.origin[0]) / r.tile_size) + 1,
               ny = std::floor((hi[1] - plan.origin[1]) / r.tile_size) + 1;
  if(!(nx * ny <= 1e8))
    throw Bad_input(who + ": more than 10^8 tiles (use a larger tile_size)");
  plan.columns = std::size_t(nx), plan.rows = std::size_t(ny);
  plan.number_of_points.assign(plan.number_of_tiles(), 0);
  return plan;
}

// The plan of the n points `point(i)`, counted; Bad_input for a coordinate that is not finite.
template <typename PointAt>
Tile_plan plan_of_points(std::size_t n, const PointAt& point, const Recognize_objects_options& r,
                         const std::string& who)
{
  if(n == 0)
    throw Bad_input(who + ": the point cloud is empty");
  const P3 first = point(0);
  std::array<double, 2> lo{{first[0], first[1]}}, hi = lo;
  for(std::size_t i = 0; i < n; ++i) {
    const P3 q = point(i);
    if(!std::isfinite(q[0]) || !std::isfinite(q[1]) || !std::isfinite(q[2]))
      throw Bad_input(who + ": a coordinate is not finite");
    lo[0] = (std::min)(lo[0], q[0]), lo[1] = (std::min)(lo[1], q[1]);
    hi[0] = (std::max)(hi[0], q[0]), hi[1] = (std::max)(hi[1], q[1]);
  }
  Tile_plan plan = tile_plan(lo, hi, r, who);
  for(std::size_t i = 0; i < n; ++i) {
    const P3 q = point(i);
    plan.add_point(q[0], q[1]);
  }
  return plan;
}

// The coordinates of a point of a CGAL kernel.
template <typename Point>
P3 coordinates(const Point& q)
{
  return P3{{CGAL::to_double(q.x()), CGAL::to_double(q.y()), CGAL::to_double(q.z())}};
}

// Tile t of `plan` on the points `q` that it holds: background removal, the locations it keeps,
// their objects (indices into q) and, with a classifier, their classes.
inline Tile_recognition recognize_tile_points(const Tile_plan& plan, std::size_t t, const std::vector<P3>& q,
                                              const Recognition_options& o)
{
  const auto start = std::chrono::steady_clock::now();
  Tile_recognition out;
  out.tile = plan.tile(t);
  out.tile.number_of_points = q.size();
  Background_removal_result background = internal::remove_background(q, o.background);
  std::vector<P3> foreground(background.foreground.size());
  for(std::size_t k = 0; k < foreground.size(); ++k)
    foreground[k] = q[background.foreground[k]];
  if(!foreground.empty()) {
    const Localization_result found = internal::locate_objects(foreground, o.localization);
    std::vector<P3> own;
    for(const Object_location& l : found.locations)
      if(plan.owner_of_location(l.position[0], l.position[1]) == t) {
        out.locations.push_back(l);
        own.push_back(l.position);
      }
    out.tile.number_of_locations = own.size();
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
          i = above[i]; // increasing, as `above` is
        if(object.seed != Object_segmentation::no_point)
          object.seed = above[object.seed];
      }
      out.objects = std::move(s.objects);
    }
  }
  out.kind = std::move(background.kind);
  out.tile.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return out;
}

} // namespace internal
/// \endcond

/*!
\ingroup PkgPointSetObjectRecognitionRef

The plan of the tiles of a scene whose points lie in the horizontal box `box`, as
`recognize_objects()` makes it, with no point counted yet: call `Tile_plan::add_point()` for every
point of the scene (e.g. in a streaming pass over its files) before `recognize_tile()`.

\tparam NamedParameters a sequence of named parameters
\param box the horizontal bounding box of the scene's points (finite, not empty)
\param np an optional sequence of named parameters among `tile_size`, `tile_margin` and
          `tile_origin`, as for `recognize_objects()`; the others are ignored
\returns the plan, its counts zero
\throws CGAL::Shape_analysis::Bad_input if a parameter is out of its range, the box is not finite
        or empty, or the scene would have more than \f$10^8\f$ tiles
*/
template <typename NamedParameters = parameters::Default_named_parameters>
Tile_plan plan_tiles(const CGAL::Bbox_2& box, const NamedParameters& np = parameters::default_values())
{
  return internal::tile_plan({{box.xmin(), box.ymin()}}, {{box.xmax(), box.ymax()}}, recognize_objects_options(np),
                             "plan_tiles");
}

/*!
\ingroup PkgPointSetObjectRecognitionRef

The plan of the tiles of the scene `points`, as `recognize_objects()` makes it, its points counted.

\tparam PointRange a model of `ConstRange` whose iterator type is `RandomAccessIterator`
\tparam NamedParameters a sequence of named parameters
\param points the whole scan
\param np an optional sequence of named parameters among `point_map`, `tile_size`, `tile_margin`
          and `tile_origin`, as for `recognize_objects()`; the others are ignored
\returns the plan
\throws CGAL::Shape_analysis::Bad_input if the range is empty, a coordinate is not finite, a
        parameter is out of its range, or the scene would have more than \f$10^8\f$ tiles
*/
template <typename PointRange, typename NamedParameters = parameters::Default_named_parameters>
Tile_plan plan_tiles(const PointRange& points, const NamedParameters& np = parameters::default_values())
{
  typedef typename std::iterator_traits<typename PointRange::const_iterator>::value_type Value;
  const auto point_map = CGAL::parameters::choose_parameter(
    CGAL::parameters::get_parameter(np, CGAL::internal_np::point_map), CGAL::Identity_property_map<Value>());
  const auto begin = std::begin(points);
  return internal::plan_of_points(
    std::size_t(std::distance(begin, std::end(points))),
    [&](std::size_t i) { return internal::coordinates(get(point_map, *(begin + std::ptrdiff_t(i)))); },
    recognize_objects_options(np), "plan_tiles");
}

/*!
\ingroup PkgPointSetObjectRecognitionRef

Finds and segments the objects of one tile of a plan, as `recognize_objects()` does with each tile:
`remove_background()` of the points the tile holds, `locate_objects()` among their foreground,
keeping the locations that the tile keeps (`Tile_plan::owner_of_location()`), and
`segment_objects()` of those among the points above the ground; with an `object_classifier`, each
object classified.

An engine of its own gets the results of `recognize_objects()` (for the same plan and options) by
calling this function for every tile that owns points, in any order and anywhere, with the points
that the tile holds (`Tile_plan::holds()`) in the scene's order, and merging the results in the
order of the tiles: the locations of tile after tile, the kind of each point from its own tile,
each point in the object of the horizontally nearest location among the objects that hold it
(the first in that order at equal distances) unless its own tile calls it ground.

\tparam PointRange a model of `ConstRange` whose iterator type is `RandomAccessIterator`
\tparam NamedParameters a sequence of named parameters
\param plan the plan of the scene, its points counted
\param tile the tile, below `plan.number_of_tiles()`
\param points the points that the tile holds: those it owns and those of its margin
\param np an optional sequence of named parameters among `point_map`, `localization_method`,
          `segmentation_method`, `background_radius`, `object_classifier` and
          `number_of_threads` (of the stages), as for `recognize_objects()`; the tiles are the plan's
\returns the tile's locations, their objects (indices into `points`), the kinds of the points
\throws CGAL::Shape_analysis::Bad_input if the tile is not one of the plan, the plan's counts are
        missing, a point is not finite or not held by the tile, the tile owns none of the points,
        a parameter is out of its range, a stage rejects the tile, or the classifier is not trained
*/
template <typename PointRange, typename NamedParameters = parameters::Default_named_parameters>
Tile_recognition recognize_tile(const Tile_plan& plan, std::size_t tile, const PointRange& points,
                                const NamedParameters& np = parameters::default_values())
{
  typedef typename std::iterator_traits<typename PointRange::const_iterator>::value_type Value;
  const auto point_map = CGAL::parameters::choose_parameter(
    CGAL::parameters::get_parameter(np, CGAL::internal_np::point_map), CGAL::Identity_property_map<Value>());
  Recognize_objects_options r = recognize_objects_options(np);
  r.tile_size = plan.tile_size, r.tile_margin = plan.tile_margin, r.tile_origin = std::nullopt;
  const internal::Recognition_options o = internal::recognition_options_of(np, r);
  if(plan.columns == 0 || plan.rows == 0 || tile >= plan.number_of_tiles())
    throw Bad_input("recognize_tile: the tile is not one of the plan's");
  if(plan.number_of_points.size() != plan.number_of_tiles())
    throw Bad_input("recognize_tile: the plan's points are not counted (Tile_plan::add_point)");
  std::vector<internal::P3> q;
  q.reserve(std::size_t(std::distance(std::begin(points), std::end(points))));
  bool owns = false;
  for(const auto& v : points) {
    const internal::P3 p = internal::coordinates(get(point_map, v));
    if(!std::isfinite(p[0]) || !std::isfinite(p[1]) || !std::isfinite(p[2]))
      throw Bad_input("recognize_tile: a coordinate is not finite");
    if(!plan.holds(tile, p[0], p[1]))
      throw Bad_input("recognize_tile: a point is not one that the tile holds");
    owns = owns || plan.tile_of(p[0], p[1]) == tile;
    q.push_back(p);
  }
  if(!owns || plan.number_of_points[tile] == 0)
    throw Bad_input("recognize_tile: the tile owns none of the points");
  return internal::recognize_tile_points(plan, tile, q, o);
}

} // namespace Point_set_object_recognition
} // namespace CGAL

#endif // CGAL_POINT_SET_OBJECT_RECOGNITION_RECOGNIZE_TILE_H
