// Copyright (c) 2026 CGAL Global Shape Analysis contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_POINT_SET_OBJECT_RECOGNITION_EXTRACT_OBJECT_FEATURES_H
#define CGAL_POINT_SET_OBJECT_RECOGNITION_EXTRACT_OBJECT_FEATURES_H

/// \file extract_object_features.h
/// Features of candidate objects, for their classification (thesis section 4.4.1): shape
/// features of three segmentations of each object and a spin image around its location.

#include <CGAL/Point_set_object_recognition/internal/Horizontal_buckets.h>
#include <CGAL/Point_set_object_recognition/segment_objects.h>
#include <CGAL/Shape_analysis/Bad_input.h>
#include <CGAL/Shape_analysis/internal/Parallel.h>
#include <CGAL/Shape_analysis/parameters.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <memory>
#include <string>
#include <unordered_map>
#include <vector>

namespace CGAL {
namespace Point_set_object_recognition {

/// \ingroup PkgPointSetObjectRecognitionRef
/// The options of `extract_object_features()`, one member per named parameter, initialized to its
/// default (filled by `extract_object_features_options()`).
struct Extract_object_features_options
{
  /// The radius of the spin image (metres): it covers the points within that distance of the
  /// location's vertical axis, from the location up to twice that height. The thesis' 2 m.
  double spin_image_radius = 2.0;
};

/// \ingroup PkgPointSetObjectRecognitionRef
/// The features of a set of locations: one row per location, one column per feature.
struct Object_features
{
  /// the names of the columns, e.g. `automatic.volume`, `spin.2.7` (see `extract_object_features()`)
  std::vector<std::string> names;
  std::vector<std::vector<double>> values; ///< per location, its features in the order of `names`
};

/// \ingroup PkgPointSetObjectRecognitionRef
/// The options that the named parameters `np` of `extract_object_features()` set, the others at
/// their defaults.
/// \tparam NamedParameters a sequence of named parameters
/// \param np the named parameters of `extract_object_features()`
/// \returns the options
template <typename NamedParameters = parameters::Default_named_parameters>
Extract_object_features_options extract_object_features_options(const NamedParameters& np = parameters::default_values())
{
  using CGAL::Shape_analysis::internal::parameter_value;
  namespace snp = CGAL::Shape_analysis::internal_np;
  Extract_object_features_options o;
  o.spin_image_radius = parameter_value(np, snp::spin_image_radius_tag, o.spin_image_radius);
  return o;
}

namespace internal {

// The spin image: 5 bins of radius / 5 from the axis, 10 of radius / 5 in height.
constexpr int spin_radial_bins = 5, spin_height_bins = 10;
// The side of the columns whose heights add up to the volume (metres).
constexpr double volume_cell = 0.2;

// The six shape features of the points `members` of an object based at `at`: their number, the
// volume under them (columns of volume_cell along the principal horizontal directions from the
// smallest coordinates, each from the base to its highest point), the mean and the standard deviation of their heights above the
// base, and their standard deviations along the two principal horizontal directions (largest
// first).
inline std::array<double, 6> shape_features(const std::vector<P3>& p, const std::vector<std::size_t>& members,
                                            const P3& at)
{
  std::array<double, 6> f{{double(members.size()), 0, 0, 0, 0, 0}};
  if(members.empty())
    return f;
  double sum = 0, sum2 = 0, mx = 0, my = 0;
  for(std::size_t i : members) {
    const double h = p[i][2] - at[2];
    sum += h, sum2 += h * h, mx += p[i][0], my += p[i][1];
  }
  const double n = double(members.size());
  f[2] = sum / n;
  f[3] = std::sqrt((std::max)(0.0, sum2 / n - f[2] * f[2]));
  mx /= n, my /= n;
  double cxx = 0, cxy = 0, cyy = 0;
  for(std::size_t i : members) {
    const double dx = p[i][0] - mx, dy = p[i][1] - my;
    cxx += dx * dx, cxy += dx * dy, cyy += dy * dy;
  }
  cxx /= n, cxy /= n, cyy /= n;
  const double mean = 0.5 * (cxx + cyy), spread = std::sqrt(0.25 * (cxx - cyy) * (cxx - cyy) + cxy * cxy);
  f[4] = std::sqrt((std::max)(0.0, mean + spread));
  f[5] = std::sqrt((std::max)(0.0, mean - spread));
  // The major direction (angle of the covariance's first eigenvector), then columns along it.
  const double angle = 0.5 * std::atan2(2 * cxy, cxx - cyy), ux = std::cos(angle), uy = std::sin(angle);
  // The columns start at the smallest coordinates along those directions.
  double u0 = std::numeric_limits<double>::infinity(), v0 = u0, u1 = -u0, v1 = -u0;
  for(std::size_t i : members) {
    const double dx = p[i][0] - mx, dy = p[i][1] - my, u = dx * ux + dy * uy, v = dy * ux - dx * uy;
    u0 = (std::min)(u0, u), v0 = (std::min)(v0, v), u1 = (std::max)(u1, u), v1 = (std::max)(v1, v);
  }
  const auto cell = [](double v) { return std::uint64_t(std::int64_t(v / volume_cell)); };
  const std::uint64_t nu = cell(u1 - u0) + 1, nv = cell(v1 - v0) + 1;
  const auto column = [&](std::size_t i) {
    const double dx = p[i][0] - mx, dy = p[i][1] - my;
    return std::make_pair(cell(dx * ux + dy * uy - u0), cell(dy * ux - dx * uy - v0));
  };
  if(nu * nv <= 4 * members.size() + 4096) { // a dense grid of columns: each its highest point
    std::vector<double> top(std::size_t(nu * nv), -std::numeric_limits<double>::infinity());
    for(std::size_t i : members) {
      const auto c = column(i);
      double& t = top[std::size_t(c.first * nv + c.second)];
      t = (std::max)(t, p[i][2] - at[2]);
    }
    for(double t : top)
      f[1] += volume_cell * volume_cell * (std::max)(0.0, t);
    return f;
  }
  std::unordered_map<std::uint64_t, double> top; // a sparse one: column -> highest point
  for(std::size_t i : members) {
    const auto c = column(i);
    auto it = top.emplace(c.first | (c.second << 32), p[i][2] - at[2]).first;
    it->second = (std::max)(it->second, p[i][2] - at[2]);
  }
  for(const auto& c : top)
    f[1] += volume_cell * volume_cell * (std::max)(0.0, c.second);
  return f;
}

// The spin image of the points around `at` (axis vertical through it): the fraction of the
// points of the cylinder (radius r, height 2 r above the base) in each of the bins, by distance
// to the axis then by height; all 0 when the cylinder is empty.
inline std::vector<double> spin_image(const std::vector<P3>& p, const Horizontal_buckets& cells, const P3& at, double r)
{
  std::vector<double> image(std::size_t(spin_radial_bins * spin_height_bins), 0.0);
  const double bin = r / spin_radial_bins;
  double count = 0;
  cells.around(at[0], at[1], r, [&](std::size_t i) {
    const double a = std::hypot(p[i][0] - at[0], p[i][1] - at[1]), h = p[i][2] - at[2];
    if(!(a < r) || h < 0 || !(h < 2 * r))
      return;
    const int ia = (std::min)(spin_radial_bins - 1, int(a / bin)), ih = (std::min)(spin_height_bins - 1, int(h / bin));
    image[std::size_t(ia * spin_height_bins + ih)] += 1;
    count += 1;
  });
  if(count > 0)
    for(double& v : image)
      v /= count;
  return image;
}

// The column features of the points around `at`, needing no segmentation: the height above the
// base of the highest point within 0.5, 1 and 2 m of the vertical axis through it, the area of
// the cells of 0.2 m holding points within 1 m, and the 90th percentile of their heights (0
// without points).
constexpr double column_cell = 0.2;
inline std::array<double, 5> column_features(const std::vector<P3>& p, const Horizontal_buckets& cells, const P3& at)
{
  std::array<double, 5> f{{0, 0, 0, 0, 0}};
  std::vector<double> heights;
  std::vector<std::uint64_t> occupied;
  cells.around(at[0], at[1], 2.0, [&](std::size_t i) {
    const double a = std::hypot(p[i][0] - at[0], p[i][1] - at[1]), h = p[i][2] - at[2];
    if(!(a <= 2.0))
      return;
    f[2] = (std::max)(f[2], h);
    if(a <= 1.0) {
      f[1] = (std::max)(f[1], h);
      heights.push_back(h);
      const auto index = [&](double v, double o) {
        return std::uint64_t(std::int64_t(std::floor((v - o) / column_cell + 0.5)) + 16); // a cell centred on `at`
      };
      occupied.push_back(index(p[i][0], at[0]) | (index(p[i][1], at[1]) << 32));
    }
    if(a <= 0.5)
      f[0] = (std::max)(f[0], h);
  });
  std::sort(occupied.begin(), occupied.end());
  f[3] = double(std::unique(occupied.begin(), occupied.end()) - occupied.begin()) * column_cell * column_cell;
  if(!heights.empty()) {
    const auto k = heights.begin() + std::ptrdiff_t(0.9 * double(heights.size() - 1));
    std::nth_element(heights.begin(), k, heights.end());
    f[4] = (std::max)(0.0, *k);
  }
  return f;
}

// The two other segmentations of the features: the min-cut at 4 m, all points within 2 m.
inline std::array<Segment_objects_options, 2> other_feature_segmentations(const Segment_objects_options& automatic)
{
  std::array<Segment_objects_options, 2> o{{automatic, automatic}};
  o[0].segmentation_method = Segmentation_method::MIN_CUT;
  o[0].background_radius = 4.0;
  o[1].segmentation_method = Segmentation_method::ALL_WITHIN_RADIUS;
  o[1].background_radius = 2.0;
  return o;
}

// Whether one segmenter built for the `automatic` segmentation serves the two others too (it
// does with the default, the automatic radius, which looks farther than the min-cut at 4 m);
// then the objects of `automatic` are exactly those of its own segment_objects().
inline bool features_share_segmenter(const Segment_objects_options& automatic)
{
  return uses_graph(automatic) &&
         segmentation_reach(automatic) >= segmentation_reach(other_feature_segmentations(automatic)[0]);
}

// The segmenter of the features' segmentations (see features_share_segmenter()).
inline std::unique_ptr<Object_segmenter> feature_segmenter(const std::vector<P3>& p, const std::vector<P3>& at,
                                                           const Segment_objects_options& automatic)
{
  const double reach = features_share_segmenter(automatic)
                         ? segmentation_reach(automatic)
                         : segmentation_reach(other_feature_segmentations(automatic)[0]);
  return std::unique_ptr<Object_segmenter>(new Object_segmenter(p, at, automatic, reach, true));
}

// The features of the objects based at `at` among the points `p` (see extract_object_features()):
// `automatic` the options of the first segmentation, whose result may be given (`computed`, one
// object per location) rather than computed again; `segmenter` the feature_segmenter() of `p`
// and `at` when the caller has it.
inline Object_features object_features(const std::vector<P3>& p, const std::vector<P3>& at,
                                       const Segment_objects_options& automatic, double spin_image_radius,
                                       const std::vector<Object_segmentation>* computed = nullptr,
                                       const Object_segmenter* segmenter = nullptr)
{
  std::unique_ptr<Object_segmenter> own;
  if(!segmenter) {
    own = feature_segmenter(p, at, automatic);
    segmenter = own.get();
  }
  const std::array<Segment_objects_options, 2> others = other_feature_segmentations(automatic);
  std::vector<std::vector<Object_segmentation>> segmentations;
  if(computed)
    segmentations.push_back(*computed);
  else if(features_share_segmenter(automatic))
    segmentations.push_back(segmenter->segment(at, automatic).objects);
  else
    segmentations.push_back(segment_objects(p, at, automatic).objects);
  for(const Segment_objects_options& o : others)
    segmentations.push_back(segmenter->segment(at, o).objects);

  Object_features r;
  const char* shape_names[] = {"points", "volume", "mean_height", "height_deviation", "major_deviation",
                               "minor_deviation"};
  for(const char* kind : {"automatic.", "min_cut_4m.", "within_2m."})
    for(const char* name : shape_names)
      r.names.push_back(std::string(kind) + name);
  for(int i = 0; i < spin_radial_bins; ++i)
    for(int j = 0; j < spin_height_bins; ++j)
      r.names.push_back("spin." + std::to_string(i) + "." + std::to_string(j));
  for(const char* name : {"top_0.5m", "top_1m", "top_2m", "area_1m", "height_90_1m"})
    r.names.push_back(std::string("column.") + name);
  const Horizontal_buckets cells(p, (std::max)(spin_image_radius, 2.0));
  r.values.resize(at.size());
  CGAL::Shape_analysis::internal::Parallel_workspaces<char> parallel(automatic.number_of_threads);
  parallel.for_each(0, at.size(), [&](std::size_t l, char&) { // rows apart: the same for any number of threads
    std::vector<double>& row = r.values[l];
    for(const std::vector<Object_segmentation>& s : segmentations) {
      const std::array<double, 6> f = shape_features(p, s[l].points, at[l]);
      row.insert(row.end(), f.begin(), f.end());
    }
    const std::vector<double> spin = spin_image(p, cells, at[l], spin_image_radius);
    row.insert(row.end(), spin.begin(), spin.end());
    const std::array<double, 5> column = column_features(p, cells, at[l]);
    row.insert(row.end(), column.begin(), column.end());
  });
  return r;
}

} // namespace internal

/*!
\ingroup PkgPointSetObjectRecognitionRef
Computes the features of the objects at `locations` that `recognize_objects()` classifies
(thesis section 4.4.1). Each location is the base of a candidate object (as for
`segment_objects()`: its horizontal position and the ground height under it). Its row holds, in
the order of `Object_features::names`:

- for each of three segmentations of the object, six shape features: the number of points; the
  volume under them (the points binned in vertical columns of 0.2 m along their principal
  horizontal directions, each column from the base up to its highest point); the mean and the standard deviation of their heights above the base; the
  standard deviations of their positions along the two principal horizontal directions, the
  larger first. The segmentations, named by the prefix of their columns, are `automatic.` (the
  one `segment_objects()` makes with the named parameters given, by default the minimum cut with
  the automatic radius), `min_cut_4m.` (the minimum cut with a background radius of 4 m) and
  `within_2m.` (every point within 2 m of the location, horizontally);
- the spin image `spin.i.j` of the points around the location, about the vertical axis through
  it: the fraction of the points within `spin_image_radius` of the axis and less than twice that
  above the base whose distance to the axis falls in bin `i` (0 to 4) and whose height falls in
  bin `j` (0 to 9), bins of a fifth of the radius;
- the column features, which need no segmentation either: `column.top_0.5m`, `column.top_1m` and
  `column.top_2m`, the height above the base of the highest point within 0.5, 1 and 2 m of the
  location's vertical axis; `column.area_1m`, the area of the cells of 0.2 m (on a grid centred
  on the location) holding points within 1 m; `column.height_90_1m`, the 90th percentile of the
  heights of those points (all 0 when no point lies around). They tell apart objects of similar
  sizes but different profiles (a trash can from a mailing box): with them, the SVM recognized
  0.89 / 0.82 of a generated street's objects from the shape features, against 0.84 / 0.76.

The features do not change when the scene is translated, nor, but for the binning of the volume
(whose columns follow the principal directions), when it turns about a vertical axis. The shape
features are 0 for an empty segmentation, the spin image 0 when no point lies around.

\tparam PointRange a model of `ConstRange` whose iterator type is `RandomAccessIterator`
\tparam LocationRange a range of `Object_location` or of `std::array<double, 3>`
\tparam NamedParameters a sequence of named parameters
\param points the points, without the ground (as for `segment_objects()`)
\param locations the bases of the objects
\param np the named parameters of `segment_objects()` (for the `automatic.` segmentation and,
          but for the method and the radius, the two others), and:

\cgalNamedParamsBegin
  \cgalParamNBegin{spin_image_radius}
    \cgalParamDescription{the radius of the spin image, in metres (its height is twice that)}
    \cgalParamType{`double`}
    \cgalParamDefault{`Extract_object_features_options::spin_image_radius`}
  \cgalParamNEnd
\cgalNamedParamsEnd

\returns the names of the features and one row per location, in the order of the locations

\throws CGAL::Shape_analysis::Bad_input as `segment_objects()`, or if `spin_image_radius` is not
        positive and finite
*/
template <typename PointRange, typename LocationRange, typename NamedParameters = parameters::Default_named_parameters>
Object_features extract_object_features(const PointRange& points, const LocationRange& locations,
                                        const NamedParameters& np = parameters::default_values())
{
  const Extract_object_features_options fo = extract_object_features_options(np);
  if(!(fo.spin_image_radius > 0) || !std::isfinite(fo.spin_image_radius))
    throw Bad_input("extract_object_features: spin_image_radius must be positive and finite");
  const Segment_objects_options automatic = internal::checked_segmentation_options(np, "extract_object_features");
  return internal::object_features(internal::point_arrays(points, np), internal::location_positions(locations), automatic,
                                   fo.spin_image_radius);
}

} // namespace Point_set_object_recognition
} // namespace CGAL

#endif // CGAL_POINT_SET_OBJECT_RECOGNITION_EXTRACT_OBJECT_FEATURES_H
