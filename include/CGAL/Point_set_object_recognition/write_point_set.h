// Copyright (c) 2026 CGAL Global Shape Analysis contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_POINT_SET_OBJECT_RECOGNITION_WRITE_POINT_SET_H
#define CGAL_POINT_SET_OBJECT_RECOGNITION_WRITE_POINT_SET_H

/// \file write_point_set.h
/// Writing of point sets with their properties as LAS (the counterpart of `read_point_set()`'s
/// LAS reader, without LASlib).

#include <CGAL/Point_set_object_recognition/internal/Las_writer.h>
#include <CGAL/Shape_analysis/Bad_input.h>
#include <CGAL/Shape_analysis/parameters.h>

#include <CGAL/Point_set_3.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <cstdint>
#include <ostream>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Point_set_object_recognition {

/// The named parameters of this package (this project's, and CGAL's usable in the same chain).
namespace parameters = CGAL::Shape_analysis::parameters;
using CGAL::Shape_analysis::Bad_input;

/*!
\ingroup PkgPointSetObjectRecognitionRef
The options of `write_las_point_set()`: each member is the named parameter of the same name,
initialized to its default.
*/
struct Write_las_point_set_options
{
  /// the local origin added back to every point (finite): the `Point_set_read_result::offset` of
  /// `read_point_set()`, so that the file has the coordinates read
  std::array<double, 3> local_origin{{0, 0, 0}};
  /// the names of classification codes, (code 0 to 255, name) pairs, written in the file's
  /// Classification Lookup record (a name keeps its first 15 characters)
  std::vector<std::pair<unsigned, std::string>> class_names;
  /// the scale, offset and coordinate system records of the file (those of the LAS file the
  /// points were read from: `Point_set_read_result::las_georeference`); none: millimetres from
  /// an offset on a 100 m grid, no coordinate system record
  std::optional<Las_georeference> las_georeference;
};

/*!
\ingroup PkgPointSetObjectRecognitionRef
The options that `write_las_point_set()` reads from the named parameters `np`, the defaults of
`Write_las_point_set_options` for the others (not checked here).
\tparam NamedParameters a sequence of named parameters
\param np the named parameters of `write_las_point_set()`
\returns the options
*/
template <typename NamedParameters = parameters::Default_named_parameters>
Write_las_point_set_options write_las_point_set_options(const NamedParameters& np = parameters::default_values())
{
  using CGAL::Shape_analysis::internal::parameter_value;
  namespace snp = CGAL::Shape_analysis::internal_np;
  Write_las_point_set_options o;
  o.local_origin = parameter_value(np, snp::local_origin_tag, o.local_origin);
  o.class_names = parameter_value(np, snp::class_names_tag, o.class_names);
  o.las_georeference = parameter_value(np, snp::las_georeference_tag, o.las_georeference);
  return o;
}

/// \cond SKIP_IN_MANUAL
namespace internal {

// The options of `np`, checked; the file's scale and offsets: those of its `las_georeference`,
// else millimetres and per axis the smallest coordinate written (local origin added) rounded down
// to a multiple of 100 m.
template <typename Point, typename NamedParameters>
Write_las_point_set_options checked_las_options(const CGAL::Point_set_3<Point>& points, const NamedParameters& np,
                                                std::array<double, 3>& offset, std::array<double, 3>& scale)
{
  const Write_las_point_set_options o = write_las_point_set_options(np);
  for(double c : o.local_origin)
    if(!std::isfinite(c))
      throw Bad_input("write_las_point_set: the local origin must be finite");
  for(const auto& name : o.class_names)
    if(name.first > 255)
      throw Bad_input("write_las_point_set: class code " + std::to_string(name.first) + " is above 255");
  scale = {{0.001, 0.001, 0.001}};
  if(o.las_georeference) {
    for(int c = 0; c < 3; ++c)
      if(!(o.las_georeference->scale[c] > 0) || !std::isfinite(o.las_georeference->scale[c]) ||
         !std::isfinite(o.las_georeference->offset[c]))
        throw Bad_input("write_las_point_set: the georeference's scale must be positive, its scale and offset finite");
    for(const Las_georeference::Record& r : o.las_georeference->crs_records)
      if(r.data.size() > 65535)
        throw Bad_input("write_las_point_set: a coordinate system record of more than 65,535 bytes");
    scale = o.las_georeference->scale;
  }
  offset = {{0, 0, 0}};
  bool first = true;
  for(typename CGAL::Point_set_3<Point>::Index i : points) {
    const Point& p = points.point(i);
    const double xyz[3] = {CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z())};
    for(int c = 0; c < 3; ++c) {
      if(!std::isfinite(xyz[c]))
        throw Bad_input("write_las_point_set: a coordinate is not finite");
      offset[c] = first ? xyz[c] : (std::min)(offset[c], xyz[c]);
    }
    first = false;
  }
  for(int c = 0; c < 3; ++c)
    offset[c] = std::floor((offset[c] + o.local_origin[c]) / 100) * 100;
  if(o.las_georeference)
    offset = o.las_georeference->offset;
  return o;
}

// Point format 7 when the point set has 16-bit colours, else 6.
template <typename Point>
unsigned las_point_format(const CGAL::Point_set_3<Point>& points)
{
  return points.template has_property_map<unsigned short>("red") ? 7 : 6;
}

} // namespace internal
/// \endcond

/*!
\ingroup PkgPointSetObjectRecognitionRef

Writes `points` to `os` (binary) as an uncompressed ASPRS LAS 1.4 file, point data format 7
when the point set has `red`, `green` and `blue` properties of type `unsigned short`, else 6.
Coordinates are stored in millimetres from an offset on a 100 m grid (per axis the smallest
coordinate, rounded down), after `local_origin` is added back, or with the scale and offset of
`las_georeference`, whose coordinate system records are written too. The properties `intensity`
(`unsigned short`), `classification`, `return_number`, `number_of_returns` (`unsigned char`),
`gps_time` (`double`) and the colours fill the fields of the format (0, or 1 for the return
number and the number of returns, when absent: what `read_point_set()` creates from a LAS file);
every other property of an arithmetic type (`unsigned char`, `signed char`, `char`,
`unsigned short`, `short`, `unsigned int`, `int`, `float`, `double`) is written after them as
"extra bytes" under its name (its first 32 characters), described by an Extra Bytes record as
LAS 1.4 specifies: CloudCompare and PDAL show them as scalar fields, and `read_point_set()`
reads them back as properties. Properties of other types (normals among them) are not written.

\tparam Point the point type of the point set
\tparam NamedParameters a sequence of named parameters
\param os the output stream, opened in binary mode
\param points the points and their properties
\param np an optional sequence of named parameters among the ones listed below

\cgalNamedParamsBegin
  \cgalParamNBegin{local_origin}
    \cgalParamDescription{the local origin added back to the points, as `std::array<double, 3>`}
    \cgalParamType{`std::array<double, 3>`}
    \cgalParamDefault{`{0, 0, 0}`}
  \cgalParamNEnd
  \cgalParamNBegin{class_names}
    \cgalParamDescription{names of classification codes written in the Classification Lookup
                          record, as (code, name) pairs}
    \cgalParamType{`std::vector<std::pair<unsigned, std::string>>`}
    \cgalParamDefault{none (no record)}
  \cgalParamNEnd
  \cgalParamNBegin{las_georeference}
    \cgalParamDescription{the scale and offset of the integer coordinates and the coordinate system
                          records (written as VLRs of user id `LASF_Projection`) of the file: those
                          of the LAS file read (`Point_set_read_result::las_georeference`), so that
                          its points keep their stored integers and its coordinate system}
    \cgalParamType{`Las_georeference`}
    \cgalParamDefault{none: millimetres from an offset on a 100 m grid, no coordinate system record}
  \cgalParamNEnd
\cgalNamedParamsEnd

\throws CGAL::Shape_analysis::Bad_input if a coordinate or the local origin is not finite, a
        point does not fit 32-bit integers with the scale and offset (2,147 km from the offset in
        millimetres), the georeference's scale is not positive or a record is above 64 KiB, a class code is above 255, a return number
        is above 15, more than 341 properties are to be written as extra bytes, or the stream
        fails; nothing is written to `os` before the checks pass
*/
template <typename Point, typename NamedParameters = parameters::Default_named_parameters>
void write_las_point_set(std::ostream& os, const CGAL::Point_set_3<Point>& points,
                         const NamedParameters& np = parameters::default_values())
{
  std::array<double, 3> offset, scale;
  const Write_las_point_set_options o = internal::checked_las_options(points, np, offset, scale);
  internal::write_las(os, points, scale, offset, internal::las_point_format(points), o.local_origin, o.class_names,
                      o.las_georeference ? &*o.las_georeference : nullptr);
  if(!os)
    throw Bad_input("write_las_point_set: cannot write the stream");
}

/*!
\ingroup PkgPointSetObjectRecognitionRef

Writes `points` to the file `filename` as `write_las_point_set()` does to a stream. The file is
written under a temporary name and renamed when complete: on failure no file is left.

\tparam Point the point type of the point set
\tparam NamedParameters a sequence of named parameters
\param filename the name of the LAS file
\param points the points and their properties
\param np the named parameters of `write_las_point_set()` (`local_origin`, `class_names`)

\throws CGAL::Shape_analysis::Bad_input as `write_las_point_set()`, or if the file cannot be written
*/
template <typename Point, typename NamedParameters = parameters::Default_named_parameters>
void write_las_point_set(const std::string& filename, const CGAL::Point_set_3<Point>& points,
                         const NamedParameters& np = parameters::default_values())
{
  std::array<double, 3> offset, scale;
  const Write_las_point_set_options o = internal::checked_las_options(points, np, offset, scale);
  internal::write_las(filename, points, scale, offset, internal::las_point_format(points), o.local_origin,
                      o.class_names, o.las_georeference ? &*o.las_georeference : nullptr);
}

/*!
\ingroup PkgPointSetObjectRecognitionRef

A LAS 1.4 file written a piece at a time, as `write_las_point_set()` writes the union of the
pieces, so that a scan larger than memory can be written (and by several processes, each with the
records of its own pieces at their places in the file). The pieces are point sets with the same
properties; the file's offset is that of the whole (its smallest coordinate rounded down to a
multiple of 100 m, local origin added), given at construction, or that of `las_georeference`. Write the header (`header()`, of
the `Summary` of every piece, merged) at the start of the file and the records of the pieces
(`records()`) after it, in order: record `i` of the file at byte `header().size() + i *
record_length()`.

\tparam Point the point type of the point sets
*/
template <typename Point>
class Las_point_set_pieces
{
public:
  /// What the header needs from the records written: their number, counts by return number,
  /// and the box of the coordinates as stored.
  struct Summary
  {
    std::uint64_t number_of_points = 0;            ///< the records
    std::array<std::uint64_t, 15> by_return{};      ///< per return number 1 to 15, the records
    std::array<double, 3> min{{0, 0, 0}};          ///< the smallest stored coordinates
    std::array<double, 3> max{{0, 0, 0}};          ///< the largest stored coordinates

    /// Adds the records of `other` to these (from another process, say).
    /// \param other what other records need
    void merge(const Summary& other)
    {
      for(int c = 0; c < 3; ++c) {
        min[c] = number_of_points == 0 ? other.min[c] : (other.number_of_points == 0 ? min[c] : (std::min)(min[c], other.min[c]));
        max[c] = number_of_points == 0 ? other.max[c] : (other.number_of_points == 0 ? max[c] : (std::max)(max[c], other.max[c]));
      }
      number_of_points += other.number_of_points;
      for(int r = 0; r < 15; ++r)
        by_return[r] += other.by_return[r];
    }
  };

  /// \param layout a point set with the properties of the pieces (its points are not written)
  /// \param lowest the smallest coordinates of all the pieces' points (each axis), to choose the
  ///        file's offset as `write_las_point_set()` does
  /// \param np an optional sequence of named parameters among `local_origin`, `class_names` and
  ///        `las_georeference`, as for `write_las_point_set()`
  /// \throws CGAL::Shape_analysis::Bad_input if `lowest`, the local origin or a class code is
  ///         not valid (as `write_las_point_set()`)
  template <typename NamedParameters = parameters::Default_named_parameters>
  Las_point_set_pieces(const CGAL::Point_set_3<Point>& layout, const std::array<double, 3>& lowest,
                       const NamedParameters& np = parameters::default_values())
    : m_layout(layout)
  {
    CGAL::Point_set_3<Point> one = layout;
    one.clear();
    one.insert(Point(lowest[0], lowest[1], lowest[2]));
    m_options = internal::checked_las_options(one, np, m_offset, m_scale);
    m_format = internal::las_point_format(layout);
    const internal::Las_attributes<CGAL::Point_set_3<Point>> attributes(layout);
    m_record = internal::las_layout(m_format).size;
    for(const auto& e : attributes.extras)
      m_record += internal::las_extra_size(e.data_type);
    internal::Le_buffer vlrs;
    m_vlrs_count = internal::las_vlrs(vlrs, attributes.extras, m_options.class_names, "write_las_point_set: ",
                                      m_options.las_georeference ? &*m_options.las_georeference : nullptr);
    m_vlrs = std::move(vlrs.bytes);
  }

  /// \returns the size of a point record in bytes
  std::size_t record_length() const { return m_record; }

  /// Appends the records of `piece` to `bytes` and returns what the header needs of them.
  /// \param piece points with the properties of the layout
  /// \param bytes the records, appended
  /// \returns their summary
  /// \throws CGAL::Shape_analysis::Bad_input as `write_las_point_set()` (a point too far from
  ///         the offset, a return number too large)
  Summary records(const CGAL::Point_set_3<Point>& piece, std::vector<unsigned char>& bytes) const
  {
    Summary s;
    const internal::Las_attributes<CGAL::Point_set_3<Point>> attributes(piece);
    if(attributes.extras.size() != internal::Las_attributes<CGAL::Point_set_3<Point>>(m_layout).extras.size())
      throw Bad_input("write_las_point_set: a piece has other properties than the layout");
    std::vector<std::int32_t> q;
    std::uint64_t by_return[15] = {0};
    internal::las_integer_coordinates(piece, attributes, m_scale, m_offset, m_options.local_origin,
                                      m_format, "write_las_point_set: ", q, s.min, s.max, by_return);
    s.number_of_points = piece.size();
    for(int r = 0; r < 15; ++r)
      s.by_return[std::size_t(r)] = by_return[r];
    internal::Le_buffer b;
    b.bytes.swap(bytes);
    std::size_t k = 0;
    for(typename CGAL::Point_set_3<Point>::Index i : piece)
      internal::append_las_record(b, attributes, i, q.data() + 3 * (k++), m_format);
    b.bytes.swap(bytes);
    return s;
  }

  /// \param all the summary of every record of the file (merged)
  /// \returns the header block and the variable length records, which start the file
  std::vector<unsigned char> header(const Summary& all) const
  {
    std::uint64_t by_return[15];
    for(int r = 0; r < 15; ++r)
      by_return[r] = all.by_return[std::size_t(r)];
    internal::Le_buffer b;
    internal::las_header_block(b, m_format, std::size_t(all.number_of_points), by_return, m_scale, m_offset, all.min,
                               all.max, m_record, {m_vlrs_count, m_vlrs.size()},
                               internal::las_wkt(m_options.las_georeference ? &*m_options.las_georeference : nullptr));
    b.bytes.insert(b.bytes.end(), m_vlrs.begin(), m_vlrs.end());
    return b.bytes;
  }

private:
  CGAL::Point_set_3<Point> m_layout;
  Write_las_point_set_options m_options;
  std::array<double, 3> m_offset{{0, 0, 0}};
  std::array<double, 3> m_scale{{0.001, 0.001, 0.001}};
  unsigned m_format = 6;
  std::size_t m_record = 0;
  std::uint32_t m_vlrs_count = 0;
  std::vector<unsigned char> m_vlrs;
};

} // namespace Point_set_object_recognition
} // namespace CGAL

#endif // CGAL_POINT_SET_OBJECT_RECOGNITION_WRITE_POINT_SET_H
