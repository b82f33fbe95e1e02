// Copyright (c) 2026 CGAL Global Shape Analysis contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_POINT_SET_OBJECT_RECOGNITION_READ_POINT_SET_H
#define CGAL_POINT_SET_OBJECT_RECOGNITION_READ_POINT_SET_H

/// \file read_point_set.h

#include <CGAL/Point_set_object_recognition/internal/Kitti_io.h>
#include <CGAL/Point_set_object_recognition/internal/Las_io.h>
#include <CGAL/Point_set_object_recognition/internal/Text_points_io.h>
#include <CGAL/Shape_analysis/Bad_input.h>
#include <CGAL/Shape_analysis/internal/Ply_header.h>
#include <CGAL/Shape_analysis/parameters.h>

#include <CGAL/Kernel_traits.h>
#include <CGAL/Point_set_3.h>
#include <CGAL/Point_set_3/IO/PLY.h>
#include <CGAL/number_utils.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <optional>
#include <string>
#include <vector>

namespace CGAL {
namespace Point_set_object_recognition {

/// The named parameters of this package (this project's, and CGAL's usable in the same chain).
namespace parameters = CGAL::Shape_analysis::parameters;
using CGAL::Shape_analysis::Bad_input;

/*!
\ingroup PkgPointSetObjectRecognitionRef
What `read_point_set()` read.
*/
struct Point_set_read_result
{
  /// The number of points read.
  std::size_t number_of_points = 0;
  /// The format of the file: `"ply"`, `"xyz"`, `"las"` or `"kitti"`.
  std::string format;
  /// The local origin subtracted from every point: a point of the file at \f$ (x, y, z) \f$ is at
  /// \f$ (x, y, z) - \f$ `offset` in the point set; `{0, 0, 0}` when nothing was shifted.
  std::array<double, 3> offset{{0, 0, 0}};
  /// The names of the properties created in the point set besides the points, in order
  /// (for example `"normal"`, `"intensity"`, `"classification"`, `"red"`).
  std::vector<std::string> property_names;
  /// For a LAS file, its scale, offset and coordinate system records: give them to
  /// `write_las_point_set()` (named parameter `las_georeference`) to write the points as they were
  /// stored; empty for the other formats.
  std::optional<Las_georeference> las_georeference;
};

/*!
\ingroup PkgPointSetObjectRecognitionRef

The options of `read_point_set()`: each member is the named parameter of the same name,
initialized to its default. This struct is where the defaults are written; the manual and
`read_point_set_options()` take them from here.
*/
struct Read_point_set_options
{
  /// whether the points are shifted to a local origin; `false` keeps the coordinates of the file
  bool shift_to_local_origin = true;
  /// the local origin subtracted from every point (finite); none: the automatic one (per axis, 0
  /// for coordinates below \f$ 10^5 \f$ in absolute value, else the minimum rounded down to a
  /// multiple of 100)
  std::optional<std::array<double, 3>> local_origin;
};

/*!
\ingroup PkgPointSetObjectRecognitionRef

The options that `read_point_set()` reads from the named parameters `np`: the value of each named
parameter given, the default of `Read_point_set_options` for the others. The values are not
checked here; `read_point_set()` checks them.

\tparam NamedParameters a sequence of named parameters
\param np the named parameters of `read_point_set()`
\returns the options
*/
template <typename NamedParameters = parameters::Default_named_parameters>
Read_point_set_options read_point_set_options(const NamedParameters& np = parameters::default_values())
{
  using CGAL::Shape_analysis::internal::parameter_value;
  namespace snp = CGAL::Shape_analysis::internal_np;
  Read_point_set_options o;
  o.shift_to_local_origin = parameter_value(np, snp::shift_to_local_origin_tag, o.shift_to_local_origin);
  o.local_origin = parameter_value(np, snp::local_origin_tag, o.local_origin);
  return o;
}

/// \cond SKIP_IN_MANUAL
namespace internal {

// The extension of `filename` with its dot, in lower case ("" if it has none).
inline std::string lowercase_extension(const std::string& filename)
{
  const std::size_t slash = filename.find_last_of("/\\");
  const std::size_t dot = filename.find_last_of('.');
  if(dot == std::string::npos || (slash != std::string::npos && dot < slash))
    return "";
  std::string e = filename.substr(dot);
  for(char& c : e)
    c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return e;
}

// The automatic local origin of points whose bounding box is [lo, hi]: per axis, 0 when the
// coordinates on that axis are all below 1e5 in absolute value, else the minimum rounded down to
// a multiple of 100.
inline std::array<double, 3> automatic_local_origin(const std::array<double, 3>& lo,
                                                    const std::array<double, 3>& hi)
{
  std::array<double, 3> o{{0, 0, 0}};
  for(int c = 0; c < 3; ++c)
    if(std::max(std::abs(lo[c]), std::abs(hi[c])) >= 1e5)
      o[c] = std::floor(lo[c] / 100) * 100;
  return o;
}

// Bounding box of points given as x, y, z triples; throws if a coordinate is not finite.
inline void bounding_box(const std::vector<double>& xyz, std::array<double, 3>& lo, std::array<double, 3>& hi)
{
  for(std::size_t i = 0; i < xyz.size(); ++i) {
    const double v = xyz[i];
    const int c = static_cast<int>(i % 3);
    if(!std::isfinite(v))
      throw Bad_input("point " + std::to_string(i / 3) + " has a coordinate that is not finite");
    lo[c] = i < 3 ? v : std::min(lo[c], v);
    hi[c] = i < 3 ? v : std::max(hi[c], v);
  }
}

// The origin to subtract: none, the one given, or the automatic one.
inline std::array<double, 3> choose_local_origin(const Read_point_set_options& o, const std::array<double, 3>& lo,
                                                 const std::array<double, 3>& hi)
{
  if(!o.shift_to_local_origin)
    return {{0, 0, 0}};
  return o.local_origin ? *o.local_origin : automatic_local_origin(lo, hi);
}

// Appends the points (x, y, z) - origin, the subtraction done in double.
template <typename Point>
void add_points(CGAL::Point_set_3<Point>& points, const std::vector<double>& xyz, const std::array<double, 3>& o)
{
  typedef typename CGAL::Kernel_traits<Point>::Kernel::FT FT;
  points.reserve(xyz.size() / 3);
  for(std::size_t i = 0; i + 2 < xyz.size(); i += 3)
    points.insert(Point(FT(xyz[i] - o[0]), FT(xyz[i + 1] - o[1]), FT(xyz[i + 2] - o[2])));
}

// Adds the property `name` with one value per point, in point order (nothing if `values` is empty).
template <typename Point, typename T>
void add_property(CGAL::Point_set_3<Point>& points, const std::string& name, const std::vector<T>& values)
{
  if(values.empty())
    return;
  auto pm = points.template add_property_map<T>(name, T()).first;
  std::size_t k = 0;
  for(typename CGAL::Point_set_3<Point>::Index i : points)
    pm[i] = values[k++];
}

// Adds the extra attribute `e` of a LAS file as a property of its name (unless the point set has
// one): unsigned char, unsigned short, unsigned int for the unsigned 8, 16 and 32-bit integers,
// int for the signed ones, double for the others and for scaled values.
template <typename Point>
void add_extra_property(CGAL::Point_set_3<Point>& points, const Las_extra_bytes& e)
{
  const std::vector<std::string> names = points.properties();
  if(e.name.empty() || std::find(names.begin(), names.end(), e.name) != names.end())
    return;
  const auto add = [&](auto tag) {
    typedef decltype(tag) T;
    auto pm = points.template add_property_map<T>(e.name, T()).first;
    std::size_t k = 0;
    for(typename CGAL::Point_set_3<Point>::Index i : points)
      pm[i] = static_cast<T>(e.values[k++]);
  };
  const unsigned t = e.scaled ? 10 : e.data_type;
  if(t == 1)
    add((unsigned char)0);
  else if(t == 3)
    add((unsigned short)0);
  else if(t == 5)
    add(0u);
  else if(t == 2 || t == 4 || t == 6)
    add(0);
  else
    add(0.0);
}

// Reads an XYZ file (read_xyz()), shifted to its local origin; normals when every line has them.
template <typename Point>
std::array<double, 3> read_xyz_points(const std::string& filename, CGAL::Point_set_3<Point>& points,
                                      const Read_point_set_options& options)
{
  typedef typename CGAL::Kernel_traits<Point>::Kernel::Vector_3 Vector;
  const Xyz_points d = read_xyz(filename);
  std::array<double, 3> lo{{0, 0, 0}}, hi{{0, 0, 0}};
  bounding_box(d.xyz, lo, hi);
  const std::array<double, 3> o = choose_local_origin(options, lo, hi);
  add_points(points, d.xyz, o);
  if(!d.normals.empty()) {
    points.add_normal_map();
    std::size_t k = 0;
    for(typename CGAL::Point_set_3<Point>::Index i : points) {
      points.normal(i) = Vector(d.normals[k], d.normals[k + 1], d.normals[k + 2]);
      k += 3;
    }
  }
  return o;
}

// Reads a PLY file with CGAL's reader, then shifts the points to their local origin.
template <typename Point>
std::array<double, 3> read_ply_points(const std::string& filename, CGAL::Point_set_3<Point>& points,
                                      const Read_point_set_options& options)
{
  typedef typename CGAL::Kernel_traits<Point>::Kernel::FT FT;
  if(!std::ifstream(filename))
    throw Bad_input(filename + ": cannot open the file for reading");
  CGAL::Shape_analysis::internal::read_ply_header(filename); // (throws without x, y, z)
  if(!CGAL::IO::read_PLY(filename, points)) {
    const std::string why = diagnose_ascii_ply(filename);
    throw Bad_input(why.empty() ? filename + ": cannot read the file as PLY" : why);
  }
  std::array<double, 3> lo{{0, 0, 0}}, hi{{0, 0, 0}};
  std::vector<double> xyz;
  xyz.reserve(3 * points.size());
  for(typename CGAL::Point_set_3<Point>::Index i : points) {
    const Point& p = points.point(i);
    xyz.insert(xyz.end(), {CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z())});
  }
  bounding_box(xyz, lo, hi);
  const std::array<double, 3> o = choose_local_origin(options, lo, hi);
  if(o[0] != 0 || o[1] != 0 || o[2] != 0) {
    std::size_t k = 0;
    for(typename CGAL::Point_set_3<Point>::Index i : points) {
      points.point(i) = Point(FT(xyz[k] - o[0]), FT(xyz[k + 1] - o[1]), FT(xyz[k + 2] - o[2]));
      k += 3;
    }
  }
  return o;
}

} // namespace internal
/// \endcond

/*!
\ingroup PkgPointSetObjectRecognitionRef

Reads a point cloud file into a point set, with its per-point properties, and shifts
georeferenced coordinates to a local origin without loss of precision.

The format is chosen by the extension of `filename`, in any case:
- `.ply`: \cgal's PLY reader (`CGAL::IO::read_PLY()`), ASCII or binary; normals become the normal
  map and every other vertex property becomes a property of the same name and type (for example
  `red`, `green`, `blue` as `unsigned char`, `label` as `int`).
- `.xyz`, `.pts`, `.txt`: one point a line, `x y z` or `x y z nx ny nz` (normals when every line
  has them; empty lines, lines starting with `#` and a first line holding only the number of
  points are skipped); a line of another shape or a value that is not a finite number is an
  error naming the line.
- `.las`: uncompressed ASPRS LAS 1.0 to 1.4, point data formats 0 to 10. Properties: `intensity`
  (`unsigned short`), `classification`, `return_number`, `number_of_returns` (`unsigned char`),
  and where the format has them `gps_time` (`double`; formats 1, 3-10) and `red`, `green`, `blue`
  (`unsigned short`; formats 2, 3, 5, 7, 8, 10). The extra bytes that an Extra Bytes record
  describes (as CloudCompare, PDAL and `shape_analysis points recognize --output .las` write
  them) become properties of their names: `unsigned char`, `unsigned short`, `unsigned int` for
  unsigned 8, 16 and 32-bit integers, `int` for signed ones, `double` for the others and for
  scaled values (a name the point set already has is skipped). Other variable length records are
  skipped. Compressed LAZ files are refused.
- `.bin`: KITTI velodyne scans, records of float32 `x`, `y`, `z`, `reflectance`, little-endian;
  property `reflectance` (`float`).

<b>Local origin.</b> Map projections (UTM: \f$ x \approx 5 \cdot 10^5 \f$,
\f$ y \approx 4 \cdot 10^6 \f$ m) leave few significant digits for local geometry, so the points
are shifted: the local origin is subtracted from the coordinates of the file in double precision
before the points are built (for LAS, from the scaled integers), so that a coordinate such as
500123.456 keeps its millimetres. The automatic origin is chosen per axis: 0 if all coordinates
on that axis are below \f$ 10^5 \f$ in absolute value (local or small data are not moved, and
heights stay heights), otherwise the minimum of the coordinates on that axis rounded down to a
multiple of 100. The origin used is returned in `Point_set_read_result::offset`; adding it back
gives the coordinates of the file.

\tparam Point a point type of a \cgal kernel (for example `CGAL::Epick::Point_3`)
\tparam NamedParameters a sequence of named parameters

\param filename the file to read
\param points receives the points and their properties; its former content and properties are
       removed (on failure it is left empty)
\param np an optional sequence of named parameters among the ones listed below

\cgalNamedParamsBegin
  \cgalParamNBegin{shift_to_local_origin}
    \cgalParamDescription{whether the points are shifted to a local origin; `false` keeps the
      coordinates of the file}
    \cgalParamType{`bool`}
    \cgalParamDefault{`Read_point_set_options::shift_to_local_origin`}
  \cgalParamNEnd
  \cgalParamNBegin{local_origin}
    \cgalParamDescription{the local origin subtracted from every point, instead of the automatic
      one described above}
    \cgalParamType{`std::array<double, 3>`}
    \cgalParamDefault{`Read_point_set_options::local_origin`: none, that is the automatic origin}
    \cgalParamExtra{must be finite; cannot be combined with `shift_to_local_origin(false)`}
  \cgalParamNEnd
\cgalNamedParamsEnd

\returns the number of points, the format, the local origin subtracted and the property names

\throws CGAL::Shape_analysis::Bad_input with a one-line message if the file cannot be opened or
        read, is a directory or a device, has an unknown extension, is compressed LAZ, is a PLY file whose vertices lack an
        x, y or z property, is truncated or inconsistent (LAS
        signature, version, point data format, record length, point count and file size), holds
        no points or a coordinate that is not finite, or if the parameters contradict each other
*/
template <typename Point, typename NamedParameters = parameters::Default_named_parameters>
Point_set_read_result read_point_set(const std::string& filename, CGAL::Point_set_3<Point>& points,
                                     const NamedParameters& np = parameters::default_values())
{
  const std::string who = "read_point_set: ";
  const Read_point_set_options options = read_point_set_options(np);
  if(options.local_origin) {
    const std::array<double, 3>& o = *options.local_origin;
    if(!std::isfinite(o[0]) || !std::isfinite(o[1]) || !std::isfinite(o[2]))
      throw Bad_input(who + "local_origin must be finite");
    if(!options.shift_to_local_origin)
      throw Bad_input(who + "local_origin is given but shift_to_local_origin is false");
  }

  const std::string ext = internal::lowercase_extension(filename);
  Point_set_read_result result;
  if(ext == ".ply")
    result.format = "ply";
  else if(ext == ".xyz" || ext == ".pts" || ext == ".txt")
    result.format = "xyz";
  else if(ext == ".las")
    result.format = "las";
  else if(ext == ".bin")
    result.format = "kitti";
  else if(ext == ".laz")
    throw Bad_input(who + filename + ": compressed LAZ is not supported; decompress it with laszip");
  else
    throw Bad_input(who + filename + ": unknown point-set file extension \"" + ext +
                    "\" (.ply, .xyz, .pts, .txt, .las and .bin are read)");

  points.clear();
  {
    // The readers need a regular file: a folder would read as empty, a device (/dev/zero) forever.
    std::error_code ec;
    if(std::filesystem::is_directory(filename, ec))
      throw Bad_input(who + filename + ": it is a directory");
    if(std::filesystem::exists(filename, ec) && !std::filesystem::is_regular_file(filename, ec))
      throw Bad_input(who + filename + ": not a regular file (a device or a pipe)");
  }
  try {
    std::array<double, 3> lo{{0, 0, 0}}, hi{{0, 0, 0}};
    if(result.format == "ply") {
      result.offset = internal::read_ply_points(filename, points, options);
    } else if(result.format == "xyz") {
      result.offset = internal::read_xyz_points(filename, points, options);
    } else if(result.format == "las") {
      const internal::Las_data d = internal::read_las(filename);
      internal::bounding_box(d.xyz, lo, hi);
      result.offset = internal::choose_local_origin(options, lo, hi);
      internal::add_points(points, d.xyz, result.offset);
      internal::add_property(points, "intensity", d.intensity);
      internal::add_property(points, "classification", d.classification);
      internal::add_property(points, "return_number", d.return_number);
      internal::add_property(points, "number_of_returns", d.number_of_returns);
      internal::add_property(points, "gps_time", d.gps_time);
      internal::add_property(points, "red", d.red);
      internal::add_property(points, "green", d.green);
      internal::add_property(points, "blue", d.blue);
      for(const internal::Las_extra_bytes& e : d.extras)
        internal::add_extra_property(points, e);
      result.las_georeference = d.georeference;
    } else {
      const internal::Kitti_data d = internal::read_kitti(filename);
      internal::bounding_box(d.xyz, lo, hi);
      result.offset = internal::choose_local_origin(options, lo, hi);
      internal::add_points(points, d.xyz, result.offset);
      internal::add_property(points, "reflectance", d.reflectance);
    }
    if(points.empty())
      throw Bad_input(filename + ": the file contains no points");
  } catch(const Bad_input& e) {
    points.clear();
    // The readers' messages start with the file name; the coordinate check's does not.
    const std::string what = e.what();
    throw Bad_input(who + (what.compare(0, filename.size(), filename) == 0 ? what : filename + ": " + what));
  }
  result.number_of_points = points.size();
  result.property_names = points.properties();
  return result;
}

} // namespace Point_set_object_recognition
} // namespace CGAL

#endif // CGAL_POINT_SET_OBJECT_RECOGNITION_READ_POINT_SET_H
