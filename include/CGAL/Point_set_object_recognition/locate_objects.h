// Copyright (c) 2026 CGAL Global Shape Analysis contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_POINT_SET_OBJECT_RECOGNITION_LOCATE_OBJECTS_H
#define CGAL_POINT_SET_OBJECT_RECOGNITION_LOCATE_OBJECTS_H

/// \file locate_objects.h
/// Localization of small objects among the foreground points of a scan, and its evaluation
/// against known locations.

#include <CGAL/Point_set_3.h>
#include <CGAL/property_map.h>

#include <CGAL/Point_set_object_recognition/internal/Localization.h>
#include <CGAL/Point_set_object_recognition/internal/Voxel_grid.h>
#include <CGAL/Shape_analysis/Bad_input.h>
#include <CGAL/Shape_analysis/parameters.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <tuple>
#include <unordered_map>
#include <vector>

namespace CGAL {
namespace Point_set_object_recognition {

namespace parameters = CGAL::Shape_analysis::parameters;
using CGAL::Shape_analysis::Bad_input;

/// \ingroup PkgPointSetObjectRecognitionRef
/// How `locate_objects()` groups the points into potential objects.
enum class Localization_method {
  CONNECTED_COMPONENTS, ///< touching voxels of side `component_spacing`
  MEAN_SHIFT,           ///< modes of the horizontal point density, flat kernel of `mean_shift_radius`
  HEIGHT_IMAGE,         ///< blobs of a height image filtered by a difference of Gaussians
  NORMALIZED_CUT        ///< agglomerative normalized-cut clustering of a nearest-neighbour graph
};

/// \ingroup PkgPointSetObjectRecognitionRef
/// A potential object found by `locate_objects()`.
struct Object_location
{
  /// the mean \f$(x, y)\f$ of the points of its foot (less than 1 m above its lowest point) and
  /// the \f$z\f$ of its lowest point
  std::array<double, 3> position{{0, 0, 0}};
  std::size_t number_of_points = 0;           ///< the points of its cluster
  double height = 0;                          ///< the vertical extent of its cluster
};

/// \ingroup PkgPointSetObjectRecognitionRef
/// The result of `locate_objects()`.
struct Localization_result
{
  std::vector<Object_location> locations; ///< sorted by \f$x\f$, then \f$y\f$
  /// Per point, the index of its location in `locations`, or `no_location` for a point of a
  /// cluster that was rejected.
  std::vector<std::size_t> location_of_point;
  static constexpr std::size_t no_location = std::size_t(-1); ///< see `location_of_point`
  std::size_t number_of_clusters = 0;      ///< before the rejection of too small, too high and floating ones
};

/// \ingroup PkgPointSetObjectRecognitionRef
/// Precision and recall of locations against the true ones (`evaluate_locations()`).
struct Localization_evaluation
{
  std::size_t correct_locations = 0; ///< locations within the radius of a true object
  std::size_t found_objects = 0;     ///< true objects within the radius of a location
  std::size_t number_of_locations = 0;
  std::size_t number_of_objects = 0;
  double precision = 0; ///< correct locations / locations (1 when there is none)
  double recall = 0;    ///< found objects / objects (1 when there is none)
};

/*!
\ingroup PkgPointSetObjectRecognitionRef

The options of `locate_objects()`: each member is the named parameter of the same name,
initialized to its default. This struct is where the defaults are written; the manual,
`locate_objects_options()` and the `shape_analysis points locate` command take them from here.

`component_spacing` here (as in `segment_objects()`) groups the foreground points into objects; it
is not the `component_spacing` of `remove_background()`
(`Remove_background_options::component_spacing`), whose voxels are coarser.
*/
struct Locate_objects_options
{
  /// how the points are grouped into clusters
  Localization_method localization_method = Localization_method::CONNECTED_COMPONENTS;
  /// the radius of the flat kernel of the mean shift, in metres (positive)
  double mean_shift_radius = 2;
  /// the side of the voxels whose contact makes clusters (connected components), in metres
  /// (positive)
  double component_spacing = 0.3;
  /// the side of the voxels of the normalized cut and of the cells of the height image, in metres
  /// (positive)
  double localization_cell_size = 0.15;
  /// two clusters merge only if the normalized cut between them is at least this (non-negative)
  double normalized_cut_threshold = 0.002;
  /// the standard deviation of the smaller Gaussian of the difference of Gaussians, in metres
  /// (positive)
  double height_image_sigma = 0.2;
  /// the response of the difference of Gaussians above which a cell belongs to an object, in
  /// metres (finite)
  double height_image_threshold = 0.02;
  /// the largest number of threads (0: TBB's choice, 1: the calling thread only)
  std::size_t number_of_threads = 0;
  /// clusters with fewer points are rejected
  std::size_t minimum_cluster_size = 10;
  /// clusters with a larger vertical extent are rejected, in metres (positive)
  double maximum_cluster_height = 12;
};

/*!
\ingroup PkgPointSetObjectRecognitionRef

The options that `locate_objects()` reads from the named parameters `np`: the value of each named
parameter given, the default of `Locate_objects_options` for the others. The values are not
checked here; `locate_objects()` checks them. Named parameters that are not options (property
maps) are ignored.

\tparam NamedParameters a sequence of named parameters
\param np the named parameters of `locate_objects()`
\returns the options
*/
template <typename NamedParameters = parameters::Default_named_parameters>
Locate_objects_options locate_objects_options(const NamedParameters& np = parameters::default_values())
{
  using CGAL::Shape_analysis::internal::parameter_value;
  namespace snp = CGAL::Shape_analysis::internal_np;
  Locate_objects_options o;
  o.localization_method = parameter_value(np, snp::localization_method_tag, o.localization_method);
  o.mean_shift_radius = parameter_value(np, snp::mean_shift_radius_tag, o.mean_shift_radius);
  o.component_spacing = parameter_value(np, snp::component_spacing_tag, o.component_spacing);
  o.localization_cell_size = parameter_value(np, snp::localization_cell_size_tag, o.localization_cell_size);
  o.normalized_cut_threshold = parameter_value(np, snp::normalized_cut_threshold_tag, o.normalized_cut_threshold);
  o.height_image_sigma = parameter_value(np, snp::height_image_sigma_tag, o.height_image_sigma);
  o.height_image_threshold = parameter_value(np, snp::height_image_threshold_tag, o.height_image_threshold);
  o.number_of_threads = parameter_value(np, snp::number_of_threads_tag, o.number_of_threads);
  o.minimum_cluster_size = parameter_value(np, snp::minimum_cluster_size_tag, o.minimum_cluster_size);
  o.maximum_cluster_height = parameter_value(np, snp::maximum_cluster_height_tag, o.maximum_cluster_height);
  return o;
}

/// \cond SKIP_IN_MANUAL
namespace internal {

typedef Locate_objects_options Localization_options;

// Above this, a cluster's points are not its foot (metres above its lowest point).
constexpr double foot_height = 1.0;
// A cluster whose lowest point stands more than `floating_height` above the lowest foreground
// point within `floating_radius` of its location floats (the head of a lamp post, a tree crown).
constexpr double floating_height = 2.0, floating_radius = 3.0;

// Per point its cluster by the method of `o` (`no_component` for none); their number.
inline std::vector<std::uint32_t> clusters_by_method(const std::vector<std::array<double, 3>>& p,
                                                     const Localization_options& o, const std::array<double, 3>& lo,
                                                     const std::array<double, 3>& hi, std::size_t& clusters)
{
  switch(o.localization_method) {
  case Localization_method::MEAN_SHIFT:
    return mean_shift_clusters(p, o.mean_shift_radius, lo, clusters);
  case Localization_method::HEIGHT_IMAGE:
    return height_image_clusters(p, o.localization_cell_size, o.height_image_sigma, o.height_image_threshold, lo, hi, clusters);
  case Localization_method::NORMALIZED_CUT:
    return normalized_cut_clusters(p, o.localization_cell_size, o.normalized_cut_threshold, lo, o.number_of_threads, clusters);
  default:
    return voxel_components(p, std::vector<char>(p.size(), 1), o.component_spacing, lo, clusters);
  }
}

// The locations of the clusters that are large enough, not too tall and not floating, each with
// its cluster, by increasing cluster.
inline std::vector<std::pair<Object_location, std::size_t>>
cluster_locations(const std::vector<std::array<double, 3>>& p, const std::vector<std::uint32_t>& cluster,
                  std::size_t clusters, const std::array<double, 3>& lo, const Localization_options& o)
{
  // Per cluster: count, lowest and highest z; then the mean (x, y) of its foot.
  std::vector<std::size_t> count(clusters, 0), foot(clusters, 0);
  std::vector<std::array<double, 2>> z(clusters, {std::numeric_limits<double>::infinity(),
                                                  -std::numeric_limits<double>::infinity()});
  std::vector<std::array<double, 2>> xy(clusters, {0, 0});
  for(std::size_t i = 0; i < p.size(); ++i) {
    if(cluster[i] == no_component)
      continue;
    auto& a = z[cluster[i]];
    ++count[cluster[i]];
    a[0] = (std::min)(a[0], p[i][2]), a[1] = (std::max)(a[1], p[i][2]);
  }
  for(std::size_t i = 0; i < p.size(); ++i) {
    const std::uint32_t c = cluster[i];
    if(c == no_component || p[i][2] > z[c][0] + foot_height)
      continue;
    ++foot[c];
    xy[c][0] += p[i][0] - lo[0], xy[c][1] += p[i][1] - lo[1];
  }
  // The lowest foreground point per square of side floating_radius (for the floating test).
  std::unordered_map<std::uint64_t, double> lowest;
  for(const auto& q : p) {
    auto it = lowest.emplace(voxel_key(q[0], q[1], lo[2], floating_radius, lo), q[2]).first;
    it->second = (std::min)(it->second, q[2]);
  }
  std::vector<std::pair<Object_location, std::size_t>> kept;
  for(std::size_t c = 0; c < clusters; ++c) {
    const double height = z[c][1] - z[c][0];
    if(count[c] < o.minimum_cluster_size || height > o.maximum_cluster_height)
      continue;
    Object_location l;
    l.position = {lo[0] + xy[c][0] / double(foot[c]), lo[1] + xy[c][1] / double(foot[c]), z[c][0]};
    double ground = std::numeric_limits<double>::infinity();
    const std::uint64_t key = voxel_key(l.position[0], l.position[1], lo[2], floating_radius, lo);
    for(int dj = -1; dj <= 1; ++dj)
      for(int di = -1; di <= 1; ++di) {
        const auto it = lowest.find(voxel_neighbor(key, di, dj, 0));
        if(it != lowest.end())
          ground = (std::min)(ground, it->second);
      }
    if(z[c][0] > ground + floating_height)
      continue;
    l.number_of_points = count[c];
    l.height = height;
    kept.emplace_back(l, c);
  }
  return kept;
}

inline Localization_result locate_objects(const std::vector<std::array<double, 3>>& p, const Localization_options& o)
{
  Localization_result r;
  r.location_of_point.assign(p.size(), Localization_result::no_location);
  if(p.empty())
    return r;
  std::array<double, 3> lo, hi;
  double voxel = o.component_spacing;
  if(o.localization_method == Localization_method::MEAN_SHIFT)
    voxel = o.mean_shift_radius / 2;
  else if(o.localization_method == Localization_method::HEIGHT_IMAGE || o.localization_method == Localization_method::NORMALIZED_CUT)
    voxel = o.localization_cell_size;
  checked_bounds(p, (std::min)(voxel, floating_radius), "locate_objects", lo, hi);
  std::size_t clusters = 0;
  const std::vector<std::uint32_t> cluster = clusters_by_method(p, o, lo, hi, clusters);
  r.number_of_clusters = clusters;
  std::vector<std::pair<Object_location, std::size_t>> kept = cluster_locations(p, cluster, clusters, lo, o);
  std::sort(kept.begin(), kept.end(), [](const auto& a, const auto& b) {
    return std::tie(a.first.position[0], a.first.position[1]) < std::tie(b.first.position[0], b.first.position[1]);
  });
  std::vector<std::size_t> location_of_cluster(clusters, Localization_result::no_location);
  for(std::size_t k = 0; k < kept.size(); ++k) {
    r.locations.push_back(kept[k].first);
    location_of_cluster[kept[k].second] = k;
  }
  for(std::size_t i = 0; i < p.size(); ++i)
    if(cluster[i] != no_component)
      r.location_of_point[i] = location_of_cluster[cluster[i]];
  return r;
}

} // namespace internal
/// \endcond

/*!
\ingroup PkgPointSetObjectRecognitionRef

Locates potential objects among the foreground points of a scan (what `remove_background()`
keeps), in the manner of \cgalCite{Golovinskiy2010} (section 4.3.2). The points are grouped into
clusters by the `localization_method`:
- `Localization_method::CONNECTED_COMPONENTS`: touching voxels of side `component_spacing`
  (by a face, an edge or a corner). Objects that touch each other give one cluster;
- `Localization_method::MEAN_SHIFT`: every square of side `mean_shift_radius` / 2 holding points
  starts at the mean of its points and climbs to a mode of the horizontal point density (mean of
  the points within `mean_shift_radius`); squares whose modes are closer than half the radius
  form one cluster. Nearby objects (a post beside a trash can) are merged, a long one (a car seen
  in pieces) is kept whole;
- `Localization_method::HEIGHT_IMAGE`: an image of cells of side `localization_cell_size` in
  \f$(x, y)\f$ holds the height of each cell's highest point above the lowest point within 1.5 m
  (the foot of the foreground nearby); the image is filtered by the difference of two Gaussians of
  standard deviations `height_image_sigma` and three times that, which responds to blobs of about
  the object's size; the cells whose response exceeds `height_image_threshold` form 8-connected
  components, each a cluster of the points of its cells (points elsewhere are in no cluster);
- `Localization_method::NORMALIZED_CUT`: the points are downsampled to voxels of side
  `localization_cell_size`; the voxels' centroids are joined to their 4 nearest neighbours by
  edges of weight \f$\exp(-d^2 / 2 s^2)\f$ (\f$d\f$ their distance, \f$s\f$ the voxel side, the
  point spacing after downsampling), the closest voxels of disconnected components of that graph
  within 5 voxels are linked with the same weight, and clusters (starting from single voxels)
  merge greedily, the pair that lowers \f$\sum_S cut(S) / |S|\f$ the most first, as long as the
  normalized cut between the two, \f$w(S, T) (1/|S| + 1/|T|)\f$ (sizes in voxels), is at least
  `normalized_cut_threshold`. Pieces of one object separated by occlusion are joined; objects
  that touch each other give one cluster.

Clusters of fewer than `minimum_cluster_size` points (debris, remains of the ground), clusters
taller than `maximum_cluster_height` (remains of buildings, tall trees) and floating clusters
(whose lowest point stands more than 2 m above the lowest foreground point within about 3 m: the
head of a lamp post, a tree crown seen apart from its trunk) are rejected; each other cluster
gives one location: the mean \f$(x, y)\f$ of its foot (its points less than 1 m above its lowest
one), which for an object standing on the ground is where it stands even when an arm, a sign
board or a tree crown leans over, at the height of its lowest point.

Nearest-neighbour searches run on `number_of_threads` threads with TBB; the result is the same
for any number of threads.

\tparam PointRange a model of `ConstRange`
\tparam NamedParameters a sequence of named parameters

\param points the foreground points (metres, \f$z\f$ up)
\param np an optional sequence of named parameters among the ones listed below

\cgalNamedParamsBegin
  \cgalParamNBegin{point_map}
    \cgalParamDescription{a property map associating points to the elements of `points`}
    \cgalParamType{a model of `ReadablePropertyMap` whose value type is a point of a \cgal kernel}
    \cgalParamDefault{`CGAL::Identity_property_map`}
  \cgalParamNEnd
  \cgalParamNBegin{localization_method}
    \cgalParamDescription{how the points are grouped}
    \cgalParamType{`Localization_method`}
    \cgalParamDefault{`Locate_objects_options::localization_method`}
  \cgalParamNEnd
  \cgalParamNBegin{mean_shift_radius}
    \cgalParamDescription{the radius of the flat kernel of the mean shift, in metres (the thesis: 2 m)}
    \cgalParamType{`double`}
    \cgalParamDefault{`Locate_objects_options::mean_shift_radius`}
    \cgalParamExtra{must be positive}
  \cgalParamNEnd
  \cgalParamNBegin{component_spacing}
    \cgalParamDescription{the side of the voxels whose contact makes clusters (connected components), in metres}
    \cgalParamType{`double`}
    \cgalParamDefault{`Locate_objects_options::component_spacing`}
    \cgalParamExtra{must be positive; a parameter of its own, finer by default than the
      `component_spacing` of `remove_background()` (`Remove_background_options::component_spacing`)}
  \cgalParamNEnd
  \cgalParamNBegin{localization_cell_size}
    \cgalParamDescription{the side of the voxels of the normalized cut and of the cells of the height image, in metres}
    \cgalParamType{`double`}
    \cgalParamDefault{`Locate_objects_options::localization_cell_size`}
    \cgalParamExtra{must be positive; the height image may hold at most \f$2 \cdot 10^8\f$ cells}
  \cgalParamNEnd
  \cgalParamNBegin{normalized_cut_threshold}
    \cgalParamDescription{two clusters merge only if the normalized cut between them is at least this (larger: more, smaller clusters)}
    \cgalParamType{`double`}
    \cgalParamDefault{`Locate_objects_options::normalized_cut_threshold`}
    \cgalParamExtra{must be non-negative}
  \cgalParamNEnd
  \cgalParamNBegin{height_image_sigma}
    \cgalParamDescription{the standard deviation of the smaller Gaussian of the difference of Gaussians (the larger one is three times wider), in metres}
    \cgalParamType{`double`}
    \cgalParamDefault{`Locate_objects_options::height_image_sigma`}
    \cgalParamExtra{must be positive}
  \cgalParamNEnd
  \cgalParamNBegin{height_image_threshold}
    \cgalParamDescription{the response of the difference of Gaussians above which a cell belongs to an object, in metres}
    \cgalParamType{`double`}
    \cgalParamDefault{`Locate_objects_options::height_image_threshold`}
    \cgalParamExtra{must be finite}
  \cgalParamNEnd
  \cgalParamNBegin{number_of_threads}
    \cgalParamDescription{the largest number of threads (0: TBB's choice, 1: the calling thread only)}
    \cgalParamType{`std::size_t`}
    \cgalParamDefault{`Locate_objects_options::number_of_threads`}
  \cgalParamNEnd
  \cgalParamNBegin{minimum_cluster_size}
    \cgalParamDescription{clusters with fewer points are rejected}
    \cgalParamType{`std::size_t`}
    \cgalParamDefault{`Locate_objects_options::minimum_cluster_size`}
  \cgalParamNEnd
  \cgalParamNBegin{maximum_cluster_height}
    \cgalParamDescription{clusters with a larger vertical extent are rejected, in metres}
    \cgalParamType{`double`}
    \cgalParamDefault{`Locate_objects_options::maximum_cluster_height`}
    \cgalParamExtra{must be positive}
  \cgalParamNEnd
\cgalNamedParamsEnd

\returns the locations (sorted by \f$x\f$, then \f$y\f$) and the location of every point

\throws CGAL::Shape_analysis::Bad_input if a coordinate is not finite, a parameter is out of its
        range, the points spread over more than two million voxels along an axis, or the height
        image would have more than \f$2 \cdot 10^8\f$ cells (process the scene in tiles)
*/
template <typename PointRange, typename NamedParameters = parameters::Default_named_parameters>
Localization_result locate_objects(const PointRange& points, const NamedParameters& np = parameters::default_values())
{
  const Locate_objects_options o = locate_objects_options(np);
  const auto positive = [](double v) { return v > 0 && std::isfinite(v); };
  if(!positive(o.mean_shift_radius))
    throw Bad_input("locate_objects: mean_shift_radius must be a positive number");
  if(!positive(o.component_spacing))
    throw Bad_input("locate_objects: component_spacing must be a positive number");
  if(!positive(o.maximum_cluster_height))
    throw Bad_input("locate_objects: maximum_cluster_height must be a positive number");
  if(!positive(o.localization_cell_size))
    throw Bad_input("locate_objects: localization_cell_size must be a positive number");
  if(!(o.normalized_cut_threshold >= 0) || !std::isfinite(o.normalized_cut_threshold))
    throw Bad_input("locate_objects: normalized_cut_threshold must be a non-negative number");
  if(!positive(o.height_image_sigma))
    throw Bad_input("locate_objects: height_image_sigma must be a positive number");
  if(!std::isfinite(o.height_image_threshold))
    throw Bad_input("locate_objects: height_image_threshold must be a finite number");
  return internal::locate_objects(internal::point_arrays(points, np), o);
}

/// \ingroup PkgPointSetObjectRecognitionRef
/// `locate_objects()` of the points of a `CGAL::Point_set_3` (its point map).
/// \tparam Point the point type of the point set
/// \tparam Vector the normal type of the point set
/// \tparam NamedParameters a sequence of named parameters
/// \param point_set the foreground points
/// \param np the same named parameters as the other overload, but `point_map`
/// \returns as the other overload; point indices follow the point set's iteration order
template <typename Point, typename Vector, typename NamedParameters = parameters::Default_named_parameters>
Localization_result locate_objects(const CGAL::Point_set_3<Point, Vector>& point_set,
                                   const NamedParameters& np = parameters::default_values())
{
  return locate_objects(internal::points_of(point_set), np);
}

/*!
\ingroup PkgPointSetObjectRecognitionRef

Evaluates locations against the true locations of the objects in the horizontal plane, as in
\cgalCite{Golovinskiy2010} (section 4.4.1): a location is correct when a true object lies within
`radius` of it, and an object is found when a location lies within `radius` of it. Precision is
the fraction of the locations that are correct, recall the fraction of the objects found.

\tparam LocationRange a range of `Object_location`
\tparam TruthRange a range of `std::array<double, 2>` or `std::array<double, 3>` (\f$x, y\f$ first)

\param locations the locations found
\param objects the true locations
\param radius the largest horizontal distance of a match, in metres (the thesis: 1 m)

\returns the counts, precision and recall

\throws CGAL::Shape_analysis::Bad_input if `radius` is not positive or a coordinate is not finite
*/
template <typename LocationRange, typename TruthRange>
Localization_evaluation evaluate_locations(const LocationRange& locations, const TruthRange& objects,
                                           double radius = 1.0)
{
  if(!(radius > 0) || !std::isfinite(radius))
    throw Bad_input("evaluate_locations: radius must be a positive number");
  std::vector<std::array<double, 2>> a, b;
  for(const Object_location& l : locations)
    a.push_back({l.position[0], l.position[1]});
  for(const auto& o : objects)
    b.push_back({double(o[0]), double(o[1])});
  for(const auto& q : a)
    if(!std::isfinite(q[0]) || !std::isfinite(q[1]))
      throw Bad_input("evaluate_locations: a location is not finite");
  for(const auto& q : b)
    if(!std::isfinite(q[0]) || !std::isfinite(q[1]))
      throw Bad_input("evaluate_locations: an object location is not finite");
  // Objects sorted by x; for each location, the objects within the radius.
  std::vector<std::size_t> order(b.size());
  for(std::size_t j = 0; j < b.size(); ++j)
    order[j] = j;
  std::sort(order.begin(), order.end(), [&](std::size_t x, std::size_t y) { return b[x][0] < b[y][0]; });
  std::vector<char> found(b.size(), 0);
  Localization_evaluation e;
  for(std::size_t i = 0; i < a.size(); ++i) {
    bool correct = false;
    auto first = std::lower_bound(order.begin(), order.end(), a[i][0] - radius,
                                  [&](std::size_t j, double x) { return b[j][0] < x; });
    for(auto it = first; it != order.end() && b[*it][0] <= a[i][0] + radius; ++it)
      if(std::hypot(a[i][0] - b[*it][0], a[i][1] - b[*it][1]) <= radius) {
        correct = true;
        found[*it] = 1;
      }
    e.correct_locations += correct ? 1 : 0;
  }
  for(char f : found)
    e.found_objects += f ? 1 : 0;
  e.number_of_locations = a.size();
  e.number_of_objects = b.size();
  e.precision = a.empty() ? 1.0 : double(e.correct_locations) / double(a.size());
  e.recall = b.empty() ? 1.0 : double(e.found_objects) / double(b.size());
  return e;
}

} // namespace Point_set_object_recognition
} // namespace CGAL

#endif // CGAL_POINT_SET_OBJECT_RECOGNITION_LOCATE_OBJECTS_H
