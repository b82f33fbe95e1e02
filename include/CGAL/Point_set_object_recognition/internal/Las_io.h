// Copyright (c) 2026 CGAL Global Shape Analysis contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_POINT_SET_OBJECT_RECOGNITION_INTERNAL_LAS_IO_H
#define CGAL_POINT_SET_OBJECT_RECOGNITION_INTERNAL_LAS_IO_H

// Reading and writing of uncompressed ASPRS LAS files (versions 1.0 to 1.4, point data formats 0
// to 10), without LASlib (Debian's CGAL is built without it).
//
// A file is the public header block, variable length records (skipped: the point data starts at
// the header's "offset to point data"), the point records, and in 1.3/1.4 optional waveform data
// or extended variable length records after them. A record starts with X, Y, Z as int32
// (coordinate = integer * scale + offset) and the intensity (uint16); formats 0-5 pack the return
// number and the number of returns in 3 bits each of byte 14 and the classification in the low 5
// bits of byte 15; formats 6-10 use 4 bits each in byte 14 and a whole byte 16 for the
// classification. GPS time (double) and RGB (3 x uint16) follow where the format has them.
// Records may be longer than their format (extra bytes), which are skipped.

#include <CGAL/Point_set_object_recognition/internal/Binary_io.h>
#include <CGAL/Shape_analysis/Bad_input.h>

#include <CGAL/Point_set_3.h>
#include <CGAL/number_utils.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <limits>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Point_set_object_recognition {
namespace internal {

// Size of the records of a point data format, byte offsets of its GPS time and RGB fields (-1 if
// absent), and whether it is one of the formats 6-10 of LAS 1.4.
struct Las_format_layout
{
  std::size_t size;
  int gps_time;
  int rgb;
  bool extended;
};

// The layout of point data format `format`, at most 10.
inline const Las_format_layout& las_layout(unsigned format)
{
  static const Las_format_layout layouts[11] = {
    {20, -1, -1, false}, {28, 20, -1, false}, {26, -1, 20, false}, {34, 20, 28, false},
    {57, 20, -1, false}, {63, 20, 28, false}, {30, 22, -1, true},  {36, 22, 30, true},
    {38, 22, 30, true},  {59, 22, -1, true},  {67, 22, 30, true}};
  return layouts[format];
}

// The fields of the public header block that the reader uses.
struct Las_header
{
  unsigned version_major = 1, version_minor = 2;
  std::uint16_t header_size = 0;
  std::uint32_t offset_to_point_data = 0;
  std::uint32_t number_of_vlrs = 0;
  unsigned point_format = 0;
  std::uint16_t record_length = 0;
  std::uint64_t number_of_points = 0;
  std::array<double, 3> scale{{1, 1, 1}}, offset{{0, 0, 0}}, min{{0, 0, 0}}, max{{0, 0, 0}};
};

// The content of a LAS file: coordinates (x, y, z of each point, in file units, computed in
// double) and per-point attributes; `gps_time` and the colours are empty when the format has none.
struct Las_data
{
  Las_header header;
  std::vector<double> xyz;
  std::vector<std::uint16_t> intensity;
  std::vector<unsigned char> classification, return_number, number_of_returns;
  std::vector<double> gps_time;
  std::vector<std::uint16_t> red, green, blue;
};

// The error about the LAS file `filename`.
inline CGAL::Shape_analysis::Bad_input las_error(const std::string& filename, const std::string& what)
{
  return CGAL::Shape_analysis::Bad_input(filename + ": " + what);
}

// The fields of the public header block `h` that the reader uses, unchecked (the point data
// format stays 0); its point data format byte and its legacy 32-bit point count.
inline Las_header las_header_fields(const unsigned char* h, unsigned& format_byte, std::uint32_t& legacy_count)
{
  Las_header hd;
  hd.version_major = h[24];
  hd.version_minor = h[25];
  hd.header_size = le_u16(h + 94);
  hd.offset_to_point_data = le_u32(h + 96);
  hd.number_of_vlrs = le_u32(h + 100);
  format_byte = h[104];
  hd.record_length = le_u16(h + 105);
  legacy_count = le_u32(h + 107);
  for(int c = 0; c < 3; ++c) {
    hd.scale[c] = le_f64(h + 131 + 8 * c);
    hd.offset[c] = le_f64(h + 155 + 8 * c);
    hd.max[c] = le_f64(h + 179 + 16 * c);
    hd.min[c] = le_f64(h + 187 + 16 * c);
  }
  return hd;
}

// Checks the header `hd` of the file `filename` of `size` bytes, whose point data format byte is
// `format_byte`, and sets its point data format.
inline void check_las_header(Las_header& hd, unsigned format_byte, std::uint64_t size, const std::string& filename)
{
  if(hd.version_major != 1 || hd.version_minor > 4)
    throw las_error(filename, "unsupported LAS version " + std::to_string(hd.version_major) + "." +
                                  std::to_string(hd.version_minor) + " (1.0 to 1.4 are read)");
  if((format_byte & 0xC0) != 0)
    throw las_error(filename, "compressed LAZ is not supported; decompress it with laszip");
  if(format_byte > 10)
    throw las_error(filename, "unknown LAS point data format " + std::to_string(format_byte));
  hd.point_format = format_byte;
  if(hd.header_size < 227 || hd.header_size > size)
    throw las_error(filename, "invalid LAS header size " + std::to_string(hd.header_size));
  if(hd.version_minor >= 4 && hd.header_size < 375)
    throw las_error(filename, "LAS 1.4 header of " + std::to_string(hd.header_size) + " bytes (375 expected)");
  if(hd.offset_to_point_data < hd.header_size || hd.offset_to_point_data > size)
    throw las_error(filename, "invalid offset to point data " + std::to_string(hd.offset_to_point_data) +
                                  " (header of " + std::to_string(hd.header_size) + " bytes, file of " +
                                  std::to_string(size) + " bytes)");
  const Las_format_layout& layout = las_layout(hd.point_format);
  if(hd.record_length < layout.size)
    throw las_error(filename, "point record length " + std::to_string(hd.record_length) + " is smaller than the " +
                                  std::to_string(layout.size) + " bytes of point data format " +
                                  std::to_string(hd.point_format));
  for(int c = 0; c < 3; ++c)
    if(!std::isfinite(hd.scale[c]) || hd.scale[c] == 0 || !std::isfinite(hd.offset[c]))
      throw las_error(filename, "invalid scale factor or offset in the LAS header");
}

// Sets the number of points of the header `hd` (read from the header block `h`, with its legacy
// count) and checks it against the size of the file.
inline void set_las_point_count(Las_header& hd, const unsigned char* h, std::uint32_t legacy_count, std::uint64_t size,
                                const std::string& filename)
{
  // LAS 1.4 holds the count in 64 bits; the legacy 32-bit field is 0 for formats 6-10.
  hd.number_of_points = legacy_count;
  if(hd.version_minor >= 4) {
    const std::uint64_t count = le_u64(h + 247);
    if(count != 0 || legacy_count == 0)
      hd.number_of_points = count;
  }
  const std::uint64_t n = hd.number_of_points, length = hd.record_length;
  const std::uint64_t data_bytes = size - hd.offset_to_point_data;
  if(n > data_bytes / length)
    throw las_error(filename, "truncated point data: the header announces " + std::to_string(n) + " points of " +
                                  std::to_string(length) + " bytes but only " + std::to_string(data_bytes) +
                                  " bytes follow");
  const std::uint64_t data_end = hd.offset_to_point_data + n * length;
  if(size > data_end) {
    // Only waveform data (1.3) or extended variable length records (1.4) may follow the points.
    const std::uint64_t waveform = hd.version_minor >= 3 ? le_u64(h + 227) : 0;
    const bool evlrs = hd.version_minor >= 4 && le_u32(h + 243) > 0 && le_u64(h + 235) >= data_end;
    if(!(waveform >= data_end || evlrs))
      throw las_error(filename, "the file size (" + std::to_string(size) + " bytes) does not match the point count: " +
                                    std::to_string(n) + " points of " + std::to_string(length) +
                                    " bytes end at byte " + std::to_string(data_end));
  }
}

// Reads the point records that the header of `data` announces from `in` into `data`.
inline void read_las_records(std::ifstream& in, Las_data& data, const std::string& filename)
{
  const Las_header& hd = data.header;
  const Las_format_layout& layout = las_layout(hd.point_format);
  const std::uint64_t length = hd.record_length;
  const std::size_t count = static_cast<std::size_t>(hd.number_of_points);
  data.xyz.resize(3 * count);
  data.intensity.resize(count);
  data.classification.resize(count);
  data.return_number.resize(count);
  data.number_of_returns.resize(count);
  if(layout.gps_time >= 0)
    data.gps_time.resize(count);
  if(layout.rgb >= 0) {
    data.red.resize(count);
    data.green.resize(count);
    data.blue.resize(count);
  }

  in.seekg(static_cast<std::streamoff>(hd.offset_to_point_data));
  const std::size_t chunk = 1 << 16;
  std::vector<unsigned char> buffer(std::min(chunk, std::max<std::size_t>(count, 1)) * length);
  for(std::size_t first = 0; first < count;) {
    const std::size_t m = std::min(chunk, count - first);
    if(!in.read(reinterpret_cast<char*>(buffer.data()), static_cast<std::streamsize>(m * length)))
      throw las_error(filename, "cannot read the point data");
    for(std::size_t k = 0; k < m; ++k) {
      const unsigned char* p = buffer.data() + k * length;
      const std::size_t i = first + k;
      for(int c = 0; c < 3; ++c)
        data.xyz[3 * i + c] = le_i32(p + 4 * c) * hd.scale[c] + hd.offset[c];
      data.intensity[i] = le_u16(p + 12);
      if(layout.extended) {
        data.return_number[i] = p[14] & 15;
        data.number_of_returns[i] = p[14] >> 4;
        data.classification[i] = p[16];
      } else {
        data.return_number[i] = p[14] & 7;
        data.number_of_returns[i] = (p[14] >> 3) & 7;
        data.classification[i] = p[15] & 31;
      }
      if(layout.gps_time >= 0)
        data.gps_time[i] = le_f64(p + layout.gps_time);
      if(layout.rgb >= 0) {
        data.red[i] = le_u16(p + layout.rgb);
        data.green[i] = le_u16(p + layout.rgb + 2);
        data.blue[i] = le_u16(p + layout.rgb + 4);
      }
    }
    first += m;
  }
}

// Reads the uncompressed LAS file `filename`; throws Bad_input with a one-line message on a file
// it cannot read (missing, truncated, not LAS, compressed LAZ, unknown format, inconsistent sizes).
inline Las_data read_las(const std::string& filename)
{
  std::ifstream in;
  open_for_reading(in, filename);
  const std::uint64_t size = file_size(in);
  if(size == 0)
    throw las_error(filename, "the file is empty");

  unsigned char h[375] = {0};
  const std::size_t available = static_cast<std::size_t>(std::min<std::uint64_t>(size, 375));
  if(!in.read(reinterpret_cast<char*>(h), static_cast<std::streamsize>(available)))
    throw las_error(filename, "cannot read the LAS header");
  if(available < 4 || std::memcmp(h, "LASF", 4) != 0)
    throw las_error(filename, "not a LAS file (no \"LASF\" signature)");
  if(size < 227)
    throw las_error(filename, "truncated LAS header (" + std::to_string(size) + " bytes, at least 227 expected)");

  Las_data data;
  unsigned format_byte = 0;
  std::uint32_t legacy_count = 0;
  data.header = las_header_fields(h, format_byte, legacy_count);
  check_las_header(data.header, format_byte, size, filename);
  set_las_point_count(data.header, h, legacy_count, size, filename);
  read_las_records(in, data, filename);
  return data;
}

// The attributes that write_las() stores, from the properties of the point set (`second`:
// whether it has them).
template <typename Point_set>
struct Las_attributes
{
  template <typename T> using Map = std::pair<typename Point_set::template Property_map<T>, bool>;

  explicit Las_attributes(const Point_set& points)
    : intensity(points.template property_map<unsigned short>("intensity")),
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

// The public header block of a LAS file of n points (write_las()), without VLRs.
inline void las_header_block(Le_buffer& b, unsigned point_format, std::size_t n, const std::uint64_t (&by_return)[15],
                             const std::array<double, 3>& scale, const std::array<double, 3>& offset,
                             const std::array<double, 3>& lo, const std::array<double, 3>& hi)
{
  const Las_format_layout& layout = las_layout(point_format);
  const bool extended = layout.extended;
  const unsigned header_size = extended ? 375 : 227;
  b.text("LASF", 4);
  b.u16(0);                    // file source id
  b.u16(extended ? 0x10 : 0);  // global encoding (WKT bit, required with formats 6-10)
  b.zeros(16);                 // project GUID
  b.u8(1);
  b.u8(extended ? 4 : 2);
  b.text("CGAL Global Shape Analysis", 32);
  b.text("Point_set_object_recognition", 32);
  b.u16(0);  // creation day (left 0: the output depends on the points only)
  b.u16(0);  // creation year
  b.u16(header_size);
  b.u32(header_size);  // offset to point data: no VLRs
  b.u32(0);
  b.u8(point_format);
  b.u16(static_cast<unsigned>(layout.size));
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
}

// Writes `points` as an uncompressed LAS file: point data formats 0-3 as LAS 1.2, 6-8 as LAS 1.4
// (with the 64-bit point count, legacy counts 0). A point p is stored as the integers
// round((p + origin - offset) / scale): `origin` is the local origin that `read_point_set()`
// subtracted, added back here. Attributes come from the properties "intensity" (unsigned short),
// "classification", "return_number", "number_of_returns" (unsigned char), "gps_time" (double),
// "red", "green", "blue" (unsigned short) when the point set has them with these types; otherwise
// 0 (1 for the return number and number of returns). Written to a temporary file then renamed.
// Throws Bad_input for an unsupported format, a scale that is not positive, a coordinate that
// does not fit in 32 bits with this scale and offset, or an attribute too large for the format.
template <typename Point>
void write_las(const std::string& filename, const CGAL::Point_set_3<Point>& points,
               const std::array<double, 3>& scale, const std::array<double, 3>& offset,
               unsigned point_format = 3, const std::array<double, 3>& origin = {{0, 0, 0}})
{
  typedef CGAL::Shape_analysis::Bad_input Bad_input;
  typedef CGAL::Point_set_3<Point> Point_set;
  const std::string who = filename + ": write_las: ";
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

  // Integer coordinates, bounding box and counts by return, then the header, then the records.
  std::vector<std::int32_t> q;
  std::array<double, 3> lo{{0, 0, 0}}, hi{{0, 0, 0}};
  std::uint64_t by_return[15] = {0};
  las_integer_coordinates(points, attributes, scale, offset, origin, point_format, who, q, lo, hi, by_return);
  Le_buffer b;
  las_header_block(b, point_format, n, by_return, scale, offset, lo, hi);

  Atomic_output_file out(filename);
  out.write(b.bytes);
  b.bytes.clear();
  std::size_t k = 0;
  for(typename Point_set::Index i : points) {
    append_las_record(b, attributes, i, q.data() + 3 * k, point_format);
    if(b.bytes.size() >= (1 << 20)) {
      out.write(b.bytes);
      b.bytes.clear();
    }
    ++k;
  }
  out.write(b.bytes);
  out.commit();
}

} // namespace internal
} // namespace Point_set_object_recognition
} // namespace CGAL

#endif // CGAL_POINT_SET_OBJECT_RECOGNITION_INTERNAL_LAS_IO_H
