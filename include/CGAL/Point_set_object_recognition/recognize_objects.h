// Copyright (c) 2026 CGAL Global Shape Analysis contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_POINT_SET_OBJECT_RECOGNITION_RECOGNIZE_OBJECTS_H
#define CGAL_POINT_SET_OBJECT_RECOGNITION_RECOGNIZE_OBJECTS_H

/// \file recognize_objects.h
/// The whole chain (background removal, localization, segmentation) on a scan of any size, tile
/// by tile: each tile is processed with the points of a margin around it, so that the memory of
/// the grids and graphs is that of one tile.

#include <CGAL/Point_set_3.h>

#include <CGAL/Point_set_object_recognition/recognize_tile.h>
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

/// \cond SKIP_IN_MANUAL
namespace internal {

// The points by tile (a counting sort; within a tile, in input order): those that tile t owns
// are order[first[t]] to order[first[t + 1] - 1].
template <typename PointAt>
void sort_by_tile(std::size_t n, const PointAt& point, const Tile_plan& plan, std::vector<std::uint32_t>& first,
                  std::vector<std::uint32_t>& order)
{
  const std::size_t tiles = plan.number_of_tiles();
  first.assign(tiles + 1, 0);
  order.assign(n, 0);
  std::vector<std::uint32_t> tile_of(n);
  for(std::size_t i = 0; i < n; ++i) {
    const P3 q = point(i);
    ++first[(tile_of[i] = std::uint32_t(plan.tile_of(q[0], q[1]))) + 1];
  }
  for(std::size_t t = 0; t < tiles; ++t)
    first[t + 1] += first[t];
  std::vector<std::uint32_t> fill(first.begin(), first.end() - 1);
  for(std::size_t i = 0; i < n; ++i)
    order[fill[tile_of[i]]++] = std::uint32_t(i);
}

// The points that tile t holds (Tile_plan::holds()), in input order.
template <typename PointAt>
std::vector<std::uint32_t> tile_points(std::size_t t, const Tile_plan& plan, const std::vector<std::uint32_t>& first,
                                       const std::vector<std::uint32_t>& order, const PointAt& point)
{
  const long tx = long(t % plan.columns), ty = long(t / plan.columns), reach = plan.reach();
  std::vector<std::uint32_t> local;
  for(long j = (std::max)(0L, ty - reach); j <= (std::min)(long(plan.rows) - 1, ty + reach); ++j)
    for(long i = (std::max)(0L, tx - reach); i <= (std::min)(long(plan.columns) - 1, tx + reach); ++i) {
      const std::size_t u = std::size_t(j) * plan.columns + std::size_t(i);
      for(std::uint32_t k = first[u]; k < first[u + 1]; ++k) {
        const P3 a = point(order[k]);
        if(u == t || plan.holds(t, a[0], a[1]))
          local.push_back(order[k]);
      }
    }
  std::sort(local.begin(), local.end());
  return local;
}

// The results of the tiles merged in the order of the tiles (their objects' points as input
// indices): a point segmented by several objects goes to the one whose location is horizontally
// nearest (the first on a tie); an object holds no point that its own tile calls ground.
template <typename PointAt>
void merge_tiles(std::vector<Tile_recognition>& outputs, const PointAt& point, Object_recognition_result& r)
{
  for(Tile_recognition& out : outputs) {
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
    out = Tile_recognition();
  }
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
  const Tile_plan plan = plan_of_points(n, point, o, "recognize_objects");
  std::vector<std::uint32_t> first, order;
  sort_by_tile(n, point, plan, first, order);

  Object_recognition_result r;
  r.object_of_point.assign(n, Object_recognition_result::no_object);
  r.kind.assign(n, Point_kind::GROUND);
  // The tiles run in parallel (each with its own buffers, freed when it ends, and its stages with
  // `number_of_threads`); their results are merged in the order of the tiles, so that the result
  // does not depend on the number of threads.
  const std::vector<std::size_t> busy = plan.tiles_with_points();
  std::vector<Tile_recognition> outputs(busy.size());
  CGAL::Shape_analysis::internal::Parallel_workspaces<char> parallel(o.number_of_threads);
  parallel.for_each(0, busy.size(), [&](std::size_t b, char&) {
    const std::size_t t = busy[b];
    const std::vector<std::uint32_t> local = tile_points(t, plan, first, order, point);
    std::vector<P3> q(local.size());
    for(std::size_t k = 0; k < local.size(); ++k)
      q[k] = point(local[k]);
    Tile_recognition& out = outputs[b] = recognize_tile_points(plan, t, q, o);
    for(std::size_t k = 0; k < local.size(); ++k) // the kinds of its own points (no other tile writes them)
      if(plan.tile_of(q[k][0], q[k][1]) == t)
        r.kind[local[k]] = out.kind[k];
    out.kind.clear();
    for(Object_segmentation& object : out.objects) {
      for(std::size_t& i : object.points)
        i = local[i]; // increasing, as `local` is
      if(object.seed != Object_segmentation::no_point)
        object.seed = local[object.seed];
    }
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
    return coordinates(get(point_map, *(begin + std::ptrdiff_t(i))));
  }, o);
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
