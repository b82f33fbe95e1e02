// Copyright (c) 2026 CGAL Global Shape Analysis contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_POINT_SET_OBJECT_RECOGNITION_INTERNAL_LAS_WRITER_H
#define CGAL_POINT_SET_OBJECT_RECOGNITION_INTERNAL_LAS_WRITER_H

// Writing of uncompressed ASPRS LAS files (see Las_io.h for the layout): the point set's standard
// attributes in the fields of the format, its other properties as described extra bytes, class
// names in a Classification Lookup record.

#include <CGAL/Point_set_object_recognition/internal/Binary_io.h>
#include <CGAL/Point_set_object_recognition/internal/Las_io.h>
#include <CGAL/Shape_analysis/Bad_input.h>

#include <CGAL/Point_set_3.h>
#include <CGAL/number_utils.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <functional>
#include <limits>
#include <memory>
#include <ostream>
#include <string>
#include <typeindex>
#include <typeinfo>
#include <utility>
#include <vector>

namespace CGAL {
namespace Point_set_object_recognition {
namespace internal {

// A property of the point set written in the extra bytes of the records: its name (at most 32
// bytes), data type (as Las_extra_bytes) and its value at a point.
template <typename Point_set>
struct Las_extra_field
{
  std::string name;
  unsigned data_type = 0;
  std::function<double(typename Point_set::Index)> value;
};

// The properties of `points` that no field of the formats holds: those of the arithmetic types
// below, but for the point and the standard attributes (see write_las()).
template <typename Point_set>
std::vector<Las_extra_field<Point_set>> las_extra_fields(const Point_set& points)
{
  std::vector<Las_extra_field<Point_set>> fields;
  const auto standard = [](const std::string& name, const std::type_index& type) {
    if(name == "intensity" || name == "red" || name == "green" || name == "blue")
      return type == typeid(unsigned short);
    if(name == "classification" || name == "return_number" || name == "number_of_returns")
      return type == typeid(unsigned char);
    return name == "gps_time" && type == typeid(double);
  };
  for(const auto& property : points.properties_and_types()) {
    const std::string& name = property.first;
    if(standard(name, property.second) || name == "point" || name == "normal" || name == "index")
      continue;
    Las_extra_field<Point_set> f;
    f.name = name.substr(0, 32);
    const auto take = [&](auto tag, unsigned data_type) {
      typedef decltype(tag) T;
      if(f.data_type != 0 || property.second != typeid(T))
        return;
      const auto map = points.template property_map<T>(name).first;
      f.data_type = data_type;
      f.value = [map](typename Point_set::Index i) { return static_cast<double>(map[i]); };
    };
    take((unsigned char)0, 1), take((signed char)0, 2), take(char(0), 2), take((unsigned short)0, 3);
    take(short(0), 4), take(0u, 5), take(0, 6), take(0.f, 9), take(0., 10);
    const auto same = [&](const Las_extra_field<Point_set>& g) { return g.name == f.name; };
    if(f.data_type != 0 && std::find_if(fields.begin(), fields.end(), same) == fields.end())
      fields.push_back(std::move(f));
  }
  return fields;
}

// The attributes that write_las() stores, from the properties of the point set (`second`:
// whether it has them).
template <typename Point_set>
struct Las_attributes
{
  template <typename T> using Map = std::pair<typename Point_set::template Property_map<T>, bool>;

private:
  const Point_set& points_of_extras; // (first: `extras` reads it)

public:

  explicit Las_attributes(const Point_set& points)
    : points_of_extras(points), intensity(points.template property_map<unsigned short>("intensity")),
      classification(points.template property_map<unsigned char>("classification")),
      return_number(points.template property_map<unsigned char>("return_number")),
      number_of_returns(points.template property_map<unsigned char>("number_of_returns")),
      gps_time(points.template property_map<double>("gps_time")),
      red(points.template property_map<unsigned short>("red")),
      green(points.template property_map<unsigned short>("green")),
      blue(points.template property_map<unsigned short>("blue"))
  {}

  Map<unsigned short> intensity;
  Map<unsigned char> classification, return_number, number_of_returns;
  Map<double> gps_time;
  Map<unsigned short> red, green, blue;
  std::vector<Las_extra_field<Point_set>> extras = las_extra_fields(points_of_extras);
};

// The integer coordinates of the points (x, y, z of each), their bounding box as stored and
// their counts by return (write_las()).
template <typename Point>
void las_integer_coordinates(const CGAL::Point_set_3<Point>& points, const Las_attributes<CGAL::Point_set_3<Point>>& a,
                             const std::array<double, 3>& scale, const std::array<double, 3>& offset,
                             const std::array<double, 3>& origin, unsigned point_format, const std::string& who,
                             std::vector<std::int32_t>& q, std::array<double, 3>& lo, std::array<double, 3>& hi,
                             std::uint64_t (&by_return)[15])
{
  typedef CGAL::Shape_analysis::Bad_input Bad_input;
  const bool extended = las_layout(point_format).extended;
  const unsigned max_return = extended ? 15 : 7;
  q.assign(3 * points.size(), 0);
  std::size_t k = 0;
  for(typename CGAL::Point_set_3<Point>::Index i : points) {
    const Point& p = points.point(i);
    const double w[3] = {CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z())};
    for(int c = 0; c < 3; ++c) {
      const double v = std::round((w[c] + origin[c] - offset[c]) / scale[c]);
      if(!(v >= std::numeric_limits<std::int32_t>::min() && v <= std::numeric_limits<std::int32_t>::max()))
        throw Bad_input(who + "point " + std::to_string(k) +
                        " does not fit in 32-bit integers with this scale and offset");
      q[3 * k + c] = static_cast<std::int32_t>(v);
      const double stored = q[3 * k + c] * scale[c] + offset[c];
      lo[c] = k == 0 ? stored : std::min(lo[c], stored);
      hi[c] = k == 0 ? stored : std::max(hi[c], stored);
    }
    const unsigned r = a.return_number.second ? a.return_number.first[i] : 1;
    const unsigned nr = a.number_of_returns.second ? a.number_of_returns.first[i] : 1;
    if(r > max_return || nr > max_return)
      throw Bad_input(who + "a return number above " + std::to_string(max_return) + " does not fit format " +
                      std::to_string(point_format));
    if(!extended && a.classification.second && a.classification.first[i] > 31)
      throw Bad_input(who + "a classification above 31 does not fit format " + std::to_string(point_format) +
                      " (use format 6)");
    if(r >= 1)
      ++by_return[r - 1];
    ++k;
  }
}

// The public header block of a LAS file of n points (write_las()), followed by `vlrs` (their
// number and bytes), records of `record_length` bytes.
inline void las_header_block(Le_buffer& b, unsigned point_format, std::size_t n, const std::uint64_t (&by_return)[15],
                             const std::array<double, 3>& scale, const std::array<double, 3>& offset,
                             const std::array<double, 3>& lo, const std::array<double, 3>& hi,
                             std::size_t record_length, const std::pair<std::uint32_t, std::size_t>& vlrs,
                             bool wkt = true)
{
  const Las_format_layout& layout = las_layout(point_format);
  const bool extended = layout.extended;
  const unsigned header_size = extended ? 375 : 227;
  b.text("LASF", 4);
  b.u16(0);                    // file source id
  b.u16(extended && wkt ? 0x10 : 0);  // global encoding (WKT bit, of formats 6-10)
  b.zeros(16);                 // project GUID
  b.u8(1);
  b.u8(extended ? 4 : 2);
  b.text("CGAL Global Shape Analysis", 32);
  b.text("Point_set_object_recognition", 32);
  b.u16(0);  // creation day (left 0: the output depends on the points only)
  b.u16(0);  // creation year
  b.u16(header_size);
  b.u32(static_cast<std::uint32_t>(header_size + vlrs.second));  // offset to point data
  b.u32(vlrs.first);
  b.u8(point_format);
  b.u16(static_cast<unsigned>(record_length));
  b.u32(extended ? 0 : static_cast<std::uint32_t>(n));
  for(int r = 0; r < 5; ++r)
    b.u32(extended ? 0 : static_cast<std::uint32_t>(by_return[r]));
  for(int c = 0; c < 3; ++c)
    b.f64(scale[c]);
  for(int c = 0; c < 3; ++c)
    b.f64(offset[c]);
  for(int c = 0; c < 3; ++c) {
    b.f64(hi[c]);
    b.f64(lo[c]);
  }
  if(extended) {
    b.u64(0);  // start of waveform data
    b.u64(0);  // start of the first extended VLR
    b.u32(0);  // number of extended VLRs
    b.u64(n);
    for(int r = 0; r < 15; ++r)
      b.u64(by_return[r]);
  }
}

// The point record of point i (integer coordinates `q`) in point data format `point_format`.
template <typename Point_set>
void append_las_record(Le_buffer& b, const Las_attributes<Point_set>& a, typename Point_set::Index i,
                       const std::int32_t* q, unsigned point_format)
{
  const Las_format_layout& layout = las_layout(point_format);
  for(int c = 0; c < 3; ++c)
    b.i32(q[c]);
  b.u16(a.intensity.second ? a.intensity.first[i] : 0);
  const unsigned r = a.return_number.second ? a.return_number.first[i] : 1;
  const unsigned nr = a.number_of_returns.second ? a.number_of_returns.first[i] : 1;
  const unsigned cls = a.classification.second ? a.classification.first[i] : 0;
  if(layout.extended) {
    b.u8(r | (nr << 4));
    b.u8(0);  // classification flags, scanner channel, scan direction, edge of flight line
    b.u8(cls);
    b.u8(0);   // user data
    b.u16(0);  // scan angle
    b.u16(0);  // point source id
  } else {
    b.u8(r | (nr << 3));
    b.u8(cls);
    b.u8(0);   // scan angle rank
    b.u8(0);   // user data
    b.u16(0);  // point source id
  }
  if(layout.gps_time >= 0)
    b.f64(a.gps_time.second ? a.gps_time.first[i] : 0.);
  if(layout.rgb >= 0) {
    b.u16(a.red.second ? a.red.first[i] : 0);
    b.u16(a.green.second ? a.green.first[i] : 0);
    b.u16(a.blue.second ? a.blue.first[i] : 0);
  }
  if(point_format == 8)
    b.u16(0);  // near infrared
  for(const auto& e : a.extras) {
    const double v = e.value(i);
    switch(e.data_type) {
    case 1: case 2: b.u8(static_cast<unsigned>(static_cast<int>(v)) & 0xff); break;
    case 3: case 4: b.u16(static_cast<unsigned>(static_cast<int>(v)) & 0xffff); break;
    case 5: b.u32(static_cast<std::uint32_t>(v)); break;
    case 6: b.i32(static_cast<std::int32_t>(v)); break;
    case 9: b.f32(static_cast<float>(v)); break;
    default: b.f64(v);
    }
  }
}

// A variable length record (of the LAS specification's own user id unless `user` is given).
inline void las_vlr(Le_buffer& b, unsigned record_id, const Le_buffer& payload, const std::string& description,
                    const std::string& user = "LASF_Spec")
{
  b.u16(0);
  b.text(user, 16);
  b.u16(record_id);
  b.u16(static_cast<unsigned>(payload.bytes.size()));
  b.text(description, 32);
  b.bytes.insert(b.bytes.end(), payload.bytes.begin(), payload.bytes.end());
}

// The VLRs of write_las(): the Extra Bytes record describing `extras`, the Classification Lookup
// record naming the classes, the coordinate system records of `geo` (if any); their number.
template <typename Field>
std::uint32_t las_vlrs(Le_buffer& b, const std::vector<Field>& extras,
                       const std::vector<std::pair<unsigned, std::string>>& class_names, const std::string& who,
                       const Las_georeference* geo = nullptr)
{
  std::uint32_t count = 0;
  if(!extras.empty()) {
    if(extras.size() > 341)
      throw CGAL::Shape_analysis::Bad_input(who + "more than 341 extra attributes do not fit one Extra Bytes record");
    Le_buffer d;
    for(const Field& e : extras) {
      d.zeros(2);
      d.u8(e.data_type);
      d.u8(0); // options: no no-data value, min, max, scale nor offset
      d.text(e.name, 32);
      d.zeros(4 + 3 * 24 + 2 * 24); // unused, no data, min, max, scale, offset
      d.text("", 32);
    }
    las_vlr(b, 4, d, "Extra bytes");
    ++count;
  }
  if(!class_names.empty()) {
    Le_buffer d;
    for(unsigned c = 0; c < 256; ++c) {
      std::string name;
      for(const auto& n : class_names)
        if(n.first == c)
          name = n.second.substr(0, 15);
      d.u8(c);
      d.text(name, 15);
    }
    las_vlr(b, 0, d, "Classification lookup");
    ++count;
  }
  for(std::size_t r = 0; geo && r < geo->crs_records.size(); ++r) {
    const Las_georeference::Record& record = geo->crs_records[r];
    if(record.data.size() > 65535)
      throw CGAL::Shape_analysis::Bad_input(who + "a coordinate system record of more than 65,535 bytes");
    Le_buffer d;
    d.bytes = record.data;
    las_vlr(b, record.record_id, d, record.description, "LASF_Projection");
    ++count;
  }
  return count;
}

// Whether a file written with `geo` declares a WKT coordinate system (global encoding bit 4):
// without CRS records, or when they are WKT.
inline bool las_wkt(const Las_georeference* geo)
{
  return geo == nullptr || geo->crs_records.empty() || geo->wkt;
}

// Writes `points` as an uncompressed LAS file to `sink` (called with consecutive byte blocks):
// point data formats 0-3 as LAS 1.2, 6-8 as LAS 1.4 (with the 64-bit point count, legacy counts
// 0). A point p is stored as the integers round((p + origin - offset) / scale): `origin` is the
// local origin that `read_point_set()` subtracted, added back here. Attributes come from the
// properties "intensity" (unsigned short), "classification", "return_number",
// "number_of_returns" (unsigned char), "gps_time" (double), "red", "green", "blue" (unsigned
// short) when the point set has them with these types; otherwise 0 (1 for the return number and
// number of returns). Every other property of an arithmetic type (unsigned char, signed char,
// char, unsigned short, short, unsigned int, int, float, double) is an extra attribute after the
// format's fields, described by an Extra Bytes VLR under its name (its first 32 bytes), as
// CloudCompare and PDAL read them. `class_names` (class code, name of at most 15 characters)
// fill a Classification Lookup VLR. Throws Bad_input for an unsupported format, a scale that is
// not positive, a coordinate that does not fit in 32 bits with this scale and offset, or an
// attribute too large for the format.
template <typename Point, typename Sink>
void write_las_to(const Sink& sink, const CGAL::Point_set_3<Point>& points, const std::array<double, 3>& scale,
                  const std::array<double, 3>& offset, unsigned point_format, const std::array<double, 3>& origin,
                  const std::vector<std::pair<unsigned, std::string>>& class_names, const std::string& who,
                  const Las_georeference* geo = nullptr)
{
  typedef CGAL::Shape_analysis::Bad_input Bad_input;
  typedef CGAL::Point_set_3<Point> Point_set;
  if(!(point_format <= 3 || (point_format >= 6 && point_format <= 8)))
    throw Bad_input(who + "point data format " + std::to_string(point_format) +
                    " is not written (0-3 and 6-8 are)");
  for(int c = 0; c < 3; ++c)
    if(!(scale[c] > 0) || !std::isfinite(scale[c]) || !std::isfinite(offset[c]) || !std::isfinite(origin[c]))
      throw Bad_input(who + "the scale must be positive, the scale, offset and origin finite");
  const std::size_t n = points.size();
  if(!las_layout(point_format).extended && n > std::numeric_limits<std::uint32_t>::max())
    throw Bad_input(who + "too many points for LAS 1.2 (use point format 6)");
  const Las_attributes<Point_set> attributes(points);

  // Integer coordinates, bounding box and counts by return, then the header, the VLRs and the records.
  std::vector<std::int32_t> q;
  std::array<double, 3> lo{{0, 0, 0}}, hi{{0, 0, 0}};
  std::uint64_t by_return[15] = {0};
  las_integer_coordinates(points, attributes, scale, offset, origin, point_format, who, q, lo, hi, by_return);
  Le_buffer vlrs;
  const std::uint32_t number_of_vlrs = las_vlrs(vlrs, attributes.extras, class_names, who, geo);
  std::size_t record_length = las_layout(point_format).size;
  for(const auto& e : attributes.extras)
    record_length += las_extra_size(e.data_type);
  Le_buffer b;
  las_header_block(b, point_format, n, by_return, scale, offset, lo, hi, record_length,
                   {number_of_vlrs, vlrs.bytes.size()}, las_wkt(geo));
  b.bytes.insert(b.bytes.end(), vlrs.bytes.begin(), vlrs.bytes.end());
  sink(b.bytes);
  b.bytes.clear();
  std::size_t k = 0;
  for(typename Point_set::Index i : points) {
    append_las_record(b, attributes, i, q.data() + 3 * k, point_format);
    if(b.bytes.size() >= (1 << 20)) {
      sink(b.bytes);
      b.bytes.clear();
    }
    ++k;
  }
  sink(b.bytes);
}

// write_las_to() into the file `filename`, written under a temporary name then renamed (nothing
// is left on failure).
template <typename Point>
void write_las(const std::string& filename, const CGAL::Point_set_3<Point>& points,
               const std::array<double, 3>& scale, const std::array<double, 3>& offset,
               unsigned point_format = 3, const std::array<double, 3>& origin = {{0, 0, 0}},
               const std::vector<std::pair<unsigned, std::string>>& class_names = {},
               const Las_georeference* geo = nullptr)
{
  const std::string who = filename + ": write_las: ";
  std::unique_ptr<Atomic_output_file> out;
  write_las_to([&](const std::vector<unsigned char>& bytes) {
                 if(!out)
                   out.reset(new Atomic_output_file(filename));
                 out->write(bytes);
               },
               points, scale, offset, point_format, origin, class_names, who, geo);
  out->commit();
}

// write_las_to() into the stream `out` (binary).
template <typename Point>
void write_las(std::ostream& out, const CGAL::Point_set_3<Point>& points, const std::array<double, 3>& scale,
               const std::array<double, 3>& offset, unsigned point_format, const std::array<double, 3>& origin,
               const std::vector<std::pair<unsigned, std::string>>& class_names = {},
               const Las_georeference* geo = nullptr)
{
  write_las_to([&](const std::vector<unsigned char>& bytes) {
                 out.write(reinterpret_cast<const char*>(bytes.data()), static_cast<std::streamsize>(bytes.size()));
               },
               points, scale, offset, point_format, origin, class_names, "write_las: ", geo);
}

} // namespace internal
} // namespace Point_set_object_recognition
} // namespace CGAL

#endif // CGAL_POINT_SET_OBJECT_RECOGNITION_INTERNAL_LAS_WRITER_H
