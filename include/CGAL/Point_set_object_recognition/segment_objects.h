// Copyright (c) 2026 CGAL Global Shape Analysis contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_POINT_SET_OBJECT_RECOGNITION_SEGMENT_OBJECTS_H
#define CGAL_POINT_SET_OBJECT_RECOGNITION_SEGMENT_OBJECTS_H

/// \file segment_objects.h
/// Segmentation of objects from their locations (all points within a radius, connected
/// components, min-cut with a fixed or an automatic background radius), interactive min-cut
/// segmentation, and the evaluation of segmentations against known objects.

#include <CGAL/Point_set_3.h>
#include <CGAL/property_map.h>

#include <CGAL/Point_set_object_recognition/Segment_objects_options.h>
#include <CGAL/Point_set_object_recognition/internal/Interactive_min_cut.h>
#include <CGAL/Point_set_object_recognition/internal/Object_segmentation.h>
#include <CGAL/Point_set_object_recognition/internal/Voxel_grid.h>
#include <CGAL/Point_set_object_recognition/locate_objects.h>
#include <CGAL/Point_set_object_recognition/remove_background.h>
#include <CGAL/Shape_analysis/Bad_input.h>
#include <CGAL/Shape_analysis/internal/Parallel.h>
#include <CGAL/Shape_analysis/parameters.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <functional>
#include <iomanip>
#include <map>
#include <memory>
#include <ostream>
#include <string>
#include <unordered_map>
#include <vector>

namespace CGAL {
namespace Point_set_object_recognition {

using CGAL::Shape_analysis::Bad_input;

/// \ingroup PkgPointSetObjectRecognitionRef
/// The segmentation of one object (`segment_object()`, `segment_objects()`, `Interactive_segmenter`).
struct Object_segmentation
{
  std::vector<std::size_t> points; ///< the indices of its points (the foreground), increasing
  double radius = 0;   ///< the background radius used, in metres
  /// The cut cost (min-cut methods, 0 otherwise): the weight of the graph edges between the
  /// foreground and the background, divided by the mean number of points of the foreground's
  /// graph nodes (with one point per node: the sum of the Gaussian weights of the edges cut).
  double cut_cost = 0;
  double seconds = 0;  ///< the time this segmentation took
  /// The index of the point that seeds the hard foreground (nearest to the vertical segment from
  /// the location up to `foreground_height`), `no_point` when no point lies near the location.
  std::size_t seed = no_point;
  static constexpr std::size_t no_point = std::size_t(-1); ///< see `seed`
};

/// \ingroup PkgPointSetObjectRecognitionRef
/// The result of `segment_objects()`.
struct Segmentation_result
{
  std::vector<Object_segmentation> objects; ///< one per location, in the order of the locations
  /// Per point, the location whose object holds it (when several do: the one horizontally
  /// nearest to the point, the first at equal distances), or `no_object`.
  std::vector<std::size_t> object_of_point;
  static constexpr std::size_t no_object = std::size_t(-1); ///< see `object_of_point`
  double preparation_seconds = 0; ///< building the graph shared by the objects
  double seconds = 0;             ///< the whole call
};

/// \ingroup PkgPointSetObjectRecognitionRef
/// Precision and recall of the segmentation of one object (`evaluate_segmentations()`).
struct Object_segmentation_score
{
  std::size_t object = 0;    ///< the index of the segmentation (the location)
  int instance = 0;          ///< the true object matched: the one with most points in the segmentation
  int object_class = 0;      ///< its class
  std::size_t segmented_points = 0, true_points = 0, correct_points = 0; ///< counts (ignored points excluded)
  double precision = 0;      ///< correct / segmented points
  double recall = 0;         ///< correct / true points
};

/// \ingroup PkgPointSetObjectRecognitionRef
/// Mean precision and recall of the segmentations of the objects of one class.
struct Class_segmentation_score
{
  int object_class = 0;       ///< the class
  std::size_t objects = 0;    ///< the segmentations matched to objects of the class
  double precision = 0, recall = 0; ///< means over those segmentations
};

/// \ingroup PkgPointSetObjectRecognitionRef
/// The evaluation of segmentations against known objects (`evaluate_segmentations()`), as the
/// thesis' table 4.2.
struct Segmentation_evaluation
{
  std::vector<Object_segmentation_score> objects; ///< the segmentations matched to a true object
  std::vector<Class_segmentation_score> classes;  ///< by increasing class
  std::size_t unmatched = 0;  ///< segmentations holding no point of any true object
  double precision = 0, recall = 0; ///< means over all matched segmentations (1 when there is none)
};

/// \cond SKIP_IN_MANUAL
namespace internal {

// The options of `np`, checked (Bad_input from `who`).
template <typename NamedParameters>
Segment_objects_options checked_segmentation_options(const NamedParameters& np, const std::string& who)
{
  const Segment_objects_options o = segment_objects_options(np);
  check_segmentation_options(o, who);
  return o;
}

inline P3 location_position(const Object_location& l) { return l.position; }
template <typename T> P3 location_position(const std::array<T, 3>& l) { return {double(l[0]), double(l[1]), double(l[2])}; }

template <typename LocationRange>
std::vector<P3> location_positions(const LocationRange& locations)
{
  std::vector<P3> r;
  for(const auto& l : locations)
    r.push_back(location_position(l));
  return r;
}

inline Object_segmentation to_public(Segmentation_output&& s)
{
  Object_segmentation r;
  r.points = std::move(s.points);
  r.radius = s.radius;
  r.cut_cost = s.cut;
  r.seconds = s.seconds;
  r.seed = s.seed == std::size_t(-1) ? Object_segmentation::no_point : s.seed;
  return r;
}

// Whether the segmentation `o` needs the graph of the index.
inline bool uses_graph(const Segmentation_options& o)
{
  return o.segmentation_method == Segmentation_method::MIN_CUT ||
         o.segmentation_method == Segmentation_method::MIN_CUT_AUTOMATIC_RADIUS;
}

inline const std::vector<P3>& nonempty_points(const std::vector<P3>& p)
{
  if(p.empty())
    throw Bad_input("segment_objects: the point cloud is empty");
  return p;
}

// The columns of the points and the graph index around a set of locations, built once and shared
// by several segmentations of the objects there: those whose methods and radii look no farther
// than `reach` and whose graph options (neighbours, cells, threads) are those of `graph_options`.
class Object_segmenter
{
public:
  Object_segmenter(const std::vector<P3>& p, const std::vector<P3>& locations, const Segmentation_options& graph_options,
                   double reach, bool with_graph)
    : m_start(std::chrono::steady_clock::now()), m_options(graph_options), m_columns(nonempty_points(p)),
      m_index((m_columns.check(locations), m_columns), locations, reach, m_options, with_graph),
      m_reach(reach), m_graph(with_graph)
  {
    m_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - m_start).count();
  }
  Object_segmenter(const Object_segmenter&) = delete;
  Object_segmenter& operator=(const Object_segmenter&) = delete;

  // Whether it can segment with `o` (same graph options assumed).
  bool serves(const Segmentation_options& o) const
  {
    return segmentation_reach(o) <= m_reach && (m_graph || !uses_graph(o));
  }

  // The objects at `locations` (those given at construction) by the segmentation `o`.
  Segmentation_result segment(const std::vector<P3>& locations, const Segmentation_options& o) const
  {
    const auto start = std::chrono::steady_clock::now();
    Segmentation_result r;
    r.preparation_seconds = m_seconds;
    std::vector<Segmentation_output> out(locations.size());
    CGAL::Shape_analysis::internal::Parallel_workspaces<Segmentation_workspace> parallel(o.number_of_threads);
    parallel.for_each(0, locations.size(), [&](std::size_t k, Segmentation_workspace& w) {
      out[k] = segment_one(m_index, locations[k], o, w);
    });
    claim_points(m_columns.points(), locations, out, r.object_of_point);
    for(Segmentation_output& s : out)
      r.objects.push_back(to_public(std::move(s)));
    r.seconds = m_seconds + std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return r;
  }

private:
  std::chrono::steady_clock::time_point m_start;
  Segmentation_options m_options; // the index keeps a reference to it
  Point_columns m_columns;
  Segmentation_index m_index;
  double m_reach = 0, m_seconds = 0;
  bool m_graph = false;
};

inline Segmentation_result segment_objects(const std::vector<P3>& p, const std::vector<P3>& locations,
                                           const Segmentation_options& o)
{
  return Object_segmenter(p, locations, o, segmentation_reach(o), uses_graph(o)).segment(locations, o);
}

} // namespace internal
/// \endcond

/*!
\ingroup PkgPointSetObjectRecognitionRef

Segments the objects at the given locations from the points around them, as
\cgalCite{Golovinskiy2010} (section 4.3.3) and \cgalCite{GolovinskiyFunkhouser2009mincut} do.
Each location (metres, \f$z\f$ up) gives the base of an object: its horizontal position and
the height of the ground under it (what `locate_objects()` returns). The hard foreground is
described below (`foreground_height`: the thesis' 1.2 m). By `segmentation_method`:
- `Segmentation_method::ALL_WITHIN_RADIUS`: every point within `background_radius` of the
  location in the horizontal plane;
- `Segmentation_method::CONNECTED_COMPONENTS`: among those, the points connected to the hard
  foreground (touching voxels of side `component_spacing`);
- `Segmentation_method::MIN_CUT`: a minimum s-t cut of a k-nearest-neighbour graph. Its nodes
  are the cells of side `graph_cell_size` holding points, weighted by their point counts
  (with `graph_cell_size(0)`, the points themselves); each node is joined to its
  `number_of_neighbors` nearest nodes (with cells: among the nodes up to three cells away) by an
  edge of weight \f$ e^{-(d/\sigma)^2} \min(n_a, n_b) \f$, \f$ d \f$ the distance of their
  centroids, \f$ \sigma \f$ = `edge_sigma`, \f$ n \f$ the point counts. The data term of a node of
  \f$ n \f$ points at horizontal distance \f$ r \f$ from the location is two linear ramps: a
  reward for being foreground of \f$ n \beta (1 - r / R) \f$ within the background radius
  \f$ R \f$ = `background_radius` (\f$ \beta \f$ = `background_weight`), then a penalty for being
  foreground rising from 0 at \f$ R \f$ to \f$ 10 n \beta \f$ at \f$ R \f$ + 1 m; the nodes farther
  away are the hard background (edges to them count in the penalty). The hard foreground (with
  cells, its node and the three nodes nearest to it) is bound to the source. The foreground is the
  part of the source side connected to the hard foreground. When the graph has more than
  `maximum_graph_size` nodes, it is contracted first (nodes joined by their heaviest edge are
  merged, round after round, until about that many remain), which bounds the time per object.
- `Segmentation_method::MIN_CUT_AUTOMATIC_RADIUS`: the same cut with
  \f$ R \f$ = 1, 2, ..., 7 m in turn, keeping the first whose foreground has more than
  `minimum_foreground_size` points and a cut cost (see `Object_segmentation::cut_cost`)
  under `maximum_cut_cost`. When none qualifies, the smallest radius whose foreground is
  big enough is kept (a larger one without a clean cut only takes more of what the object
  touches), else 7 m.

The hard foreground is the point nearest to the vertical segment from the location up to
`foreground_height` (the thesis takes the point nearest to the segment's top; the segment keeps an
object that stands against a wall from being seeded on the wall) and its three nearest neighbours.

<b>Walls.</b> For the min-cut methods, the points of walls are found first and left out of the
graph (they never join an object, and never seed one), so that an object flush against a facade
is cut along its contact instead of through it: the columns of 0.2 m holding points over more
than 3.5 m of height whose high points (2 m above the column's lowest) spread horizontally over
more than 0.2 m within 0.5 m (a pole does not) mark, in 2.5 cm cells stacking at least three such
points over a metre or more (a tree's crown does not), the wall; every point within a cell of
those cells, down to the ground, is the wall's.

<b>The ground.</b> The points should not hold the ground: the ground touches every object, so a
cut would have to go through it, and a disc of ground around the base would cost the cut less
than its edges. Remove it first with `remove_background()` and keep the points that are not
`Point_kind::GROUND` (`points_above_ground()`); keep the buildings and the large components: the
cut is what separates an object from the wall it stands against.

The objects are segmented independently (in parallel with TBB, with identical results for any
number of threads) from one graph built for all of them.

\tparam PointRange a model of `ConstRange` whose iterator type is `RandomAccessIterator`
\tparam LocationRange a range of `Object_location` or of `std::array<double, 3>` (x, y, z of the base)
\tparam NamedParameters a sequence of named parameters

\param points the points, without the ground
\param locations the locations of the objects, inside the horizontal bounding box of the points
\param np an optional sequence of named parameters among the ones listed below

\cgalNamedParamsBegin
  \cgalParamNBegin{point_map}
    \cgalParamDescription{a property map associating points to the elements of `points`}
    \cgalParamType{a model of `ReadablePropertyMap` whose value type is a point of a \cgal kernel}
    \cgalParamDefault{`CGAL::Identity_property_map`}
  \cgalParamNEnd
  \cgalParamNBegin{segmentation_method}
    \cgalParamDescription{how the objects are segmented}
    \cgalParamType{`Segmentation_method`}
    \cgalParamDefault{`Segment_objects_options::segmentation_method`}
  \cgalParamNEnd
  \cgalParamNBegin{background_radius}
    \cgalParamDescription{the background radius of `MIN_CUT`, the radius of `ALL_WITHIN_RADIUS` and `CONNECTED_COMPONENTS`, in metres}
    \cgalParamType{`double`}
    \cgalParamDefault{`Segment_objects_options::background_radius`}
    \cgalParamExtra{must be positive}
  \cgalParamNEnd
  \cgalParamNBegin{foreground_height}
    \cgalParamDescription{the height of the hard foreground above the location, in metres}
    \cgalParamType{`double`}
    \cgalParamDefault{`Segment_objects_options::foreground_height`}
  \cgalParamNEnd
  \cgalParamNBegin{graph_cell_size}
    \cgalParamDescription{the side of the cells that are the nodes of the graph, in metres; 0 makes every point a node}
    \cgalParamType{`double`}
    \cgalParamDefault{`Segment_objects_options::graph_cell_size`}
  \cgalParamNEnd
  \cgalParamNBegin{number_of_neighbors}
    \cgalParamDescription{the number of nearest nodes each node is joined to}
    \cgalParamType{`std::size_t`}
    \cgalParamDefault{`Segment_objects_options::number_of_neighbors`}
    \cgalParamExtra{between 1 and 64}
  \cgalParamNEnd
  \cgalParamNBegin{edge_sigma}
    \cgalParamDescription{the length scale \f$ \sigma \f$ of the edge weights, in metres}
    \cgalParamType{`double`}
    \cgalParamDefault{`Segment_objects_options::edge_sigma`: none, that is 4 `graph_cell_size`, or 0.2 m when it is 0}
    \cgalParamExtra{must be positive}
  \cgalParamNEnd
  \cgalParamNBegin{background_weight}
    \cgalParamDescription{the scale \f$ \beta \f$ of the data term: a point at the location is
      rewarded by \f$ \beta \f$ for being foreground, a point at the background radius plus 1 m is
      penalised by \f$ 10 \beta \f$}
    \cgalParamType{`double`}
    \cgalParamDefault{`Segment_objects_options::background_weight`}
  \cgalParamNEnd
  \cgalParamNBegin{maximum_graph_size}
    \cgalParamDescription{larger graphs are contracted to about this many nodes (0: never)}
    \cgalParamType{`std::size_t`}
    \cgalParamDefault{`Segment_objects_options::maximum_graph_size`}
  \cgalParamNEnd
  \cgalParamNBegin{minimum_foreground_size}
    \cgalParamDescription{the automatic radius wants more foreground points than this}
    \cgalParamType{`std::size_t`}
    \cgalParamDefault{`Segment_objects_options::minimum_foreground_size`}
  \cgalParamNEnd
  \cgalParamNBegin{maximum_cut_cost}
    \cgalParamDescription{the automatic radius wants a cut cost under this}
    \cgalParamType{`double`}
    \cgalParamDefault{`Segment_objects_options::maximum_cut_cost`}
  \cgalParamNEnd
  \cgalParamNBegin{component_spacing}
    \cgalParamDescription{the side of the voxels of `CONNECTED_COMPONENTS`, in metres}
    \cgalParamType{`double`}
    \cgalParamDefault{`Segment_objects_options::component_spacing`}
    \cgalParamExtra{must be positive; a parameter of its own, as in `locate_objects()`, finer by
      default than the `component_spacing` of `remove_background()`
      (`Remove_background_options::component_spacing`)}
  \cgalParamNEnd
  \cgalParamNBegin{number_of_threads}
    \cgalParamDescription{the largest number of threads (0: TBB's choice); results do not depend on it}
    \cgalParamType{`std::size_t`}
    \cgalParamDefault{`Segment_objects_options::number_of_threads`}
  \cgalParamNEnd
\cgalNamedParamsEnd

\returns one `Object_segmentation` per location and the object of every point

\throws CGAL::Shape_analysis::Bad_input if the cloud is empty, a coordinate is not finite, a
        location lies outside the horizontal bounding box of the points, or a parameter is out of
        its range
*/
template <typename PointRange, typename LocationRange, typename NamedParameters = parameters::Default_named_parameters>
Segmentation_result segment_objects(const PointRange& points, const LocationRange& locations,
                                    const NamedParameters& np = parameters::default_values())
{
  const Segment_objects_options o = internal::checked_segmentation_options(np, "segment_objects");
  return internal::segment_objects(internal::point_arrays(points, np), internal::location_positions(locations), o);
}

/// \ingroup PkgPointSetObjectRecognitionRef
/// `segment_objects()` of the points of a `CGAL::Point_set_3` (its point map).
/// \tparam Point the point type of the point set
/// \tparam Vector the normal type of the point set
/// \tparam LocationRange a range of `Object_location` or of `std::array<double, 3>`
/// \tparam NamedParameters a sequence of named parameters
/// \param point_set the points, without the ground
/// \param locations the locations of the objects
/// \param np the same named parameters as the other overload, but `point_map`
/// \returns as the other overload; point indices follow the point set's iteration order
template <typename Point, typename Vector, typename LocationRange,
          typename NamedParameters = parameters::Default_named_parameters>
Segmentation_result segment_objects(const CGAL::Point_set_3<Point, Vector>& point_set, const LocationRange& locations,
                                    const NamedParameters& np = parameters::default_values())
{
  return segment_objects(internal::points_of(point_set), locations, np);
}

/// \ingroup PkgPointSetObjectRecognitionRef
/// Segments one object: `segment_objects()` with one location.
/// \tparam PointRange a model of `ConstRange` whose iterator type is `RandomAccessIterator`
/// \tparam NamedParameters a sequence of named parameters
/// \param points the points, without the ground
/// \param location the base of the object (x, y, z)
/// \param np the named parameters of `segment_objects()`
/// \returns the object's segmentation
/// \throws CGAL::Shape_analysis::Bad_input as `segment_objects()`
template <typename PointRange, typename NamedParameters = parameters::Default_named_parameters>
Object_segmentation segment_object(const PointRange& points, const std::array<double, 3>& location,
                                   const NamedParameters& np = parameters::default_values())
{
  return std::move(segment_objects(points, std::vector<std::array<double, 3>>{location}, np).objects.front());
}

/// \ingroup PkgPointSetObjectRecognitionRef
/// The indices of the points that `remove_background()` did not find to be ground (the
/// foreground, isolated points and large components), increasing: the points to segment.
/// \param background the result of `remove_background()`
/// \returns the indices of the points that are not `Point_kind::GROUND`
inline std::vector<std::size_t> points_above_ground(const Background_removal_result& background)
{
  std::vector<std::size_t> r;
  for(std::size_t i = 0; i < background.kind.size(); ++i)
    if(background.kind[i] != Point_kind::GROUND)
      r.push_back(i);
  return r;
}

/*!
\ingroup PkgPointSetObjectRecognitionRef

Min-cut segmentation of one object that a user corrects: each foreground or background
constraint (a point that must or must not belong to the object) is added to the graph and the cut
is solved again by augmenting the last flow (a constraint only raises capacities), without
rebuilding the graph.

The segmenter chooses its background radius at construction (the automatic radius of
`segment_objects()`, or `background_radius` with `Segmentation_method::MIN_CUT`), then keeps that
graph, uncontracted. Constraints are always honoured: a point constrained to the foreground is in
`segmentation().points`, one constrained to the background is not (the last constraint on a point
wins). A constraint binds the graph node of its point (with cells, the other points of the cell
follow it) unless the points of that node carry opposite constraints; then the node is free and
only the constrained points are forced.

The segmenter refers to its own copy of the points; it is neither copied nor moved.
*/
class Interactive_segmenter
{
public:
  /// Builds the graph around `location` and computes the first segmentation.
  /// \tparam PointRange a model of `ConstRange` whose iterator type is `RandomAccessIterator`
  /// \tparam NamedParameters a sequence of named parameters
  /// \param points the points, without the ground
  /// \param location the base of the object
  /// \param np the named parameters of `segment_objects()` (a min-cut method)
  /// \throws CGAL::Shape_analysis::Bad_input as `segment_objects()`, and for a method that is not a min-cut
  template <typename PointRange, typename NamedParameters = parameters::Default_named_parameters>
  Interactive_segmenter(const PointRange& points, const std::array<double, 3>& location,
                        const NamedParameters& np = parameters::default_values())
    : m_impl(internal::point_arrays(points, np), internal::checked_segmentation_options(np, "Interactive_segmenter"),
             internal::P3{{location[0], location[1], location[2]}})
  {}

  Interactive_segmenter(const Interactive_segmenter&) = delete;
  Interactive_segmenter& operator=(const Interactive_segmenter&) = delete;

  /// The current segmentation.
  /// \returns the segmentation of the last solve (its `cut_cost` and `seconds` included)
  const Object_segmentation& segmentation() const { return m_impl.segmentation(); }

  /// Constrains point `i` to the foreground and solves again.
  /// \param i the index of a point
  /// \returns the new segmentation
  /// \throws CGAL::Shape_analysis::Bad_input if `i` is not a point, or lies outside the graph
  ///         (beyond the background radius plus 1 m): it cannot be joined to the object
  const Object_segmentation& add_foreground(std::size_t i) { return add(i, true); }

  /// Constrains point `i` to the background and solves again.
  /// \param i the index of a point
  /// \returns the new segmentation
  /// \throws CGAL::Shape_analysis::Bad_input if `i` is not a point
  const Object_segmentation& add_background(std::size_t i) { return add(i, false); }

  /// The number of points constrained so far.
  /// \returns the number of foreground and background constraints added
  std::size_t number_of_constraints() const { return m_impl.number_of_constraints(); }

private:
  const Object_segmentation& add(std::size_t i, bool foreground) { return m_impl.add(i, foreground); }

  internal::Interactive_min_cut<Object_segmentation> m_impl;
};

/*!
\ingroup PkgPointSetObjectRecognitionRef

Evaluates segmentations against the true objects of the points, as \cgalCite{Golovinskiy2010}
does (section 4.4.2, table 4.2): each segmentation is matched to the true object with most
points in it; its precision is the fraction of its points that belong to that object, its recall
the fraction of that object's points it holds. Points whose instance is negative (for example the
ground removed before segmenting) are ignored on both sides. Per class and overall, precision and
recall are means over the matched segmentations (every object counts the same, whatever its
size); segmentations without any point of a true object are counted in `unmatched`.

\tparam InstanceRange a range of `int`: per point, its true object (0 for the background, negative
        for a point to ignore)
\param segmentations the segmentations (independent: a point may be in several)
\param instance_of_point the true object of every point
\param class_of_instance the class of every true object (instances missing from it have class 0)
\returns the scores per segmentation, per class and overall
\throws CGAL::Shape_analysis::Bad_input if a segmentation holds a point index out of range
*/
template <typename InstanceRange>
Segmentation_evaluation evaluate_segmentations(const std::vector<Object_segmentation>& segmentations,
                                               const InstanceRange& instance_of_point,
                                               const std::map<int, int>& class_of_instance)
{
  const std::vector<int> instance(std::begin(instance_of_point), std::end(instance_of_point));
  std::map<int, std::size_t> size;
  for(int i : instance)
    if(i > 0)
      ++size[i];
  Segmentation_evaluation e;
  std::map<int, std::array<double, 3>> by_class; // count, sum of precision, sum of recall
  std::map<int, std::size_t> in;
  for(std::size_t k = 0; k < segmentations.size(); ++k) {
    in.clear();
    std::size_t counted = 0;
    for(std::size_t q : segmentations[k].points) {
      if(q >= instance.size())
        throw Bad_input("evaluate_segmentations: a point index is out of range");
      if(instance[q] < 0)
        continue;
      ++counted;
      if(instance[q] > 0)
        ++in[instance[q]];
    }
    int best = 0;
    std::size_t best_n = 0;
    for(const auto& c : in)
      if(c.second > best_n)
        best_n = c.second, best = c.first;
    if(best == 0) {
      ++e.unmatched;
      continue;
    }
    Object_segmentation_score s;
    s.object = k;
    s.instance = best;
    const auto cls = class_of_instance.find(best);
    s.object_class = cls == class_of_instance.end() ? 0 : cls->second;
    s.segmented_points = counted;
    s.true_points = size[best];
    s.correct_points = best_n;
    s.precision = double(best_n) / double(counted);
    s.recall = double(best_n) / double(s.true_points);
    auto& acc = by_class[s.object_class];
    acc[0] += 1, acc[1] += s.precision, acc[2] += s.recall;
    e.precision += s.precision;
    e.recall += s.recall;
    e.objects.push_back(s);
  }
  for(const auto& c : by_class) {
    Class_segmentation_score s;
    s.object_class = c.first;
    s.objects = std::size_t(c.second[0]);
    s.precision = c.second[1] / c.second[0];
    s.recall = c.second[2] / c.second[0];
    e.classes.push_back(s);
  }
  e.precision = e.objects.empty() ? 1.0 : e.precision / double(e.objects.size());
  e.recall = e.objects.empty() ? 1.0 : e.recall / double(e.objects.size());
  return e;
}

/// \ingroup PkgPointSetObjectRecognitionRef
/// `evaluate_segmentations()` of a labelling: per point the segmentation holding it (0, 1, ...)
/// or a negative value (or `Segmentation_result::no_object`) for none.
/// \tparam ObjectRange a range of integers: per point, its segmentation
/// \tparam InstanceRange a range of `int`: per point, its true object
/// \param object_of_point the segmentation of every point (for example `Segmentation_result::object_of_point`)
/// \param instance_of_point the true object of every point
/// \param class_of_instance the class of every true object
/// \returns as the other overload, segmentations numbered by their labels
/// \throws CGAL::Shape_analysis::Bad_input if the two ranges differ in size
template <typename ObjectRange, typename InstanceRange>
Segmentation_evaluation evaluate_labelling(const ObjectRange& object_of_point, const InstanceRange& instance_of_point,
                                           const std::map<int, int>& class_of_instance)
{
  std::vector<Object_segmentation> s;
  std::size_t i = 0;
  for(const auto& o : object_of_point) {
    const long long label = (long long)(o);
    if(label >= 0 && std::size_t(label) != Segmentation_result::no_object) {
      if(std::size_t(label) >= s.size())
        s.resize(std::size_t(label) + 1);
      s[std::size_t(label)].points.push_back(i);
    }
    ++i;
  }
  if(i != std::size_t(std::distance(std::begin(instance_of_point), std::end(instance_of_point))))
    throw Bad_input("evaluate_labelling: the labels and the instances differ in size");
  return evaluate_segmentations(s, instance_of_point, class_of_instance);
}

/// \ingroup PkgPointSetObjectRecognitionRef
/// Prints an evaluation as the thesis' table 4.2: one line per class (name, objects, precision,
/// recall in percent), then the overall line.
/// \param os the stream
/// \param e the evaluation
/// \param class_name the name of a class
inline void print_segmentation_table(std::ostream& os, const Segmentation_evaluation& e,
                                     const std::function<std::string(int)>& class_name)
{
  const auto flags = os.flags();
  const auto precision = os.precision();
  os << std::left << std::setw(24) << "class" << std::right << std::setw(8) << "objects" << std::setw(11)
     << "precision" << std::setw(8) << "recall" << "\n";
  os << std::fixed << std::setprecision(1);
  for(const Class_segmentation_score& c : e.classes)
    os << std::left << std::setw(24) << class_name(c.object_class) << std::right << std::setw(8) << c.objects
       << std::setw(10) << 100 * c.precision << "%" << std::setw(7) << 100 * c.recall << "%\n";
  os << std::left << std::setw(24) << "all" << std::right << std::setw(8) << e.objects.size() << std::setw(10)
     << 100 * e.precision << "%" << std::setw(7) << 100 * e.recall << "%\n";
  os.flags(flags);
  os.precision(precision);
}

} // namespace Point_set_object_recognition
} // namespace CGAL

#endif // CGAL_POINT_SET_OBJECT_RECOGNITION_SEGMENT_OBJECTS_H
