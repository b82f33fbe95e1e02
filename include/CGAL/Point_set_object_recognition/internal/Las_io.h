// Copyright (c) 2026 CGAL Global Shape Analysis contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_POINT_SET_OBJECT_RECOGNITION_INTERNAL_LAS_IO_H
#define CGAL_POINT_SET_OBJECT_RECOGNITION_INTERNAL_LAS_IO_H

// Reading of uncompressed ASPRS LAS files (versions 1.0 to 1.4, point data formats 0 to 10),
// without LASlib (Debian's CGAL is built without it); the writer is in Las_writer.h.
//
// A file is the public header block, variable length records (skipped: the point data starts at
// the header's "offset to point data"), the point records, and in 1.3/1.4 optional waveform data
// or extended variable length records after them. A record starts with X, Y, Z as int32
// (coordinate = integer * scale + offset) and the intensity (uint16); formats 0-5 pack the return
// number and the number of returns in 3 bits each of byte 14 and the classification in the low 5
// bits of byte 15; formats 6-10 use 4 bits each in byte 14 and a whole byte 16 for the
// classification. GPS time (double) and RGB (3 x uint16) follow where the format has them.
// Records may be longer than their format: the "extra bytes" that an Extra Bytes VLR (user id
// "LASF_Spec", record id 4; 192-byte descriptors: data type, options, name, ..., scale, offset)
// describes are read as attributes; undescribed ones are skipped.

#include <CGAL/Point_set_object_recognition/Las_georeference.h>
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
  std::uint16_t global_encoding = 0;
  std::uint64_t start_of_evlrs = 0;  // LAS 1.4: the extended VLRs after the points (0: none)
  std::uint32_t number_of_evlrs = 0;
};

// An attribute stored in the extra bytes of the records: its name, data type (1 to 10: unsigned
// and signed 8, 16, 32, 64-bit integers, then float and double), byte offset in the record,
// scale and offset (value = stored * scale + offset when `scaled`), and its values.
struct Las_extra_bytes
{
  std::string name;
  unsigned data_type = 0;
  std::size_t offset = 0;
  double scale = 1, add = 0;
  bool scaled = false;
  std::vector<double> values;
};

// The size of an extra-bytes data type (1 to 10), 0 for the others.
inline std::size_t las_extra_size(unsigned data_type)
{
  static const std::size_t sizes[11] = {0, 1, 1, 2, 2, 4, 4, 8, 8, 4, 8};
  return data_type <= 10 ? sizes[data_type] : 0;
}

// The value of type `data_type` (1 to 10) at p.
inline double las_extra_value(const unsigned char* p, unsigned data_type)
{
  switch(data_type) {
  case 1: return p[0];
  case 2: return static_cast<signed char>(p[0]);
  case 3: return le_u16(p);
  case 4: return static_cast<std::int16_t>(le_u16(p));
  case 5: return le_u32(p);
  case 6: return le_i32(p);
  case 7: return static_cast<double>(le_u64(p));
  case 8: return static_cast<double>(static_cast<std::int64_t>(le_u64(p)));
  case 9: return le_f32(p);
  default: return le_f64(p);
  }
}

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
  std::vector<Las_extra_bytes> extras; // the described extra bytes, in record order
  Las_georeference georeference;       // scale, offset and CRS records of the header
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
  hd.global_encoding = le_u16(h + 6);
  if(hd.version_minor >= 4 && hd.header_size >= 375) {
    hd.start_of_evlrs = le_u64(h + 235);
    hd.number_of_evlrs = le_u32(h + 243);
  }
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
  for(Las_extra_bytes& e : data.extras)
    e.values.resize(count);

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
      for(Las_extra_bytes& e : data.extras) {
        const double v = las_extra_value(p + e.offset, e.data_type);
        e.values[i] = e.scaled ? v * e.scale + e.add : v;
      }
    }
    first += m;
  }
}

// The text of a fixed-size field of n bytes (up to its first 0).
inline std::string fixed_text(const unsigned char* p, std::size_t n)
{
  return std::string(reinterpret_cast<const char*>(p), reinterpret_cast<const char*>(std::find(p, p + n, 0)));
}

// Appends the coordinate system record `id` (its `length` bytes next in `in`) to `data.georeference`.
inline void read_las_crs_record(std::ifstream& in, std::uint16_t id, const std::string& description,
                                std::uint64_t length, Las_data& data, const std::string& filename)
{
  Las_georeference::Record r;
  r.record_id = id;
  r.description = description;
  r.data.resize(static_cast<std::size_t>(length));
  if(!in.read(reinterpret_cast<char*>(r.data.data()), static_cast<std::streamsize>(length)))
    throw las_error(filename, "cannot read the coordinate system record");
  data.georeference.crs_records.push_back(std::move(r));
}

// The CRS records among the extended VLRs of the LAS 1.4 file `in` (after its points), appended
// to `data.georeference`; a record too large for a VLR (64 KiB) is an error, as the file could not
// be written again with it.
inline void read_las_crs_evlrs(std::ifstream& in, Las_data& data, const std::string& filename)
{
  const Las_header& hd = data.header;
  if(hd.number_of_evlrs == 0 || hd.start_of_evlrs == 0)
    return;
  const std::uint64_t size = file_size(in);
  std::uint64_t at = hd.start_of_evlrs;
  for(std::uint32_t v = 0; v < hd.number_of_evlrs; ++v) {
    unsigned char h[60];
    in.clear();
    in.seekg(static_cast<std::streamoff>(at));
    if(at > size || size - at < 60 || !in.read(reinterpret_cast<char*>(h), 60))
      throw las_error(filename, "extended variable length record " + std::to_string(v) + " runs past the end");
    const std::uint64_t length = le_u64(h + 20);
    if(length > size - at - 60)
      throw las_error(filename, "extended variable length record " + std::to_string(v) + " runs past the end");
    if(fixed_text(h + 2, 16) == "LASF_Projection") {
      if(length > 65535)
        throw las_error(filename, "a coordinate system record of " + std::to_string(length) +
                                      " bytes (at most 65,535 are kept)");
      read_las_crs_record(in, le_u16(h + 18), fixed_text(h + 28, 32), length, data, filename);
    }
    at += 60 + length;
  }
  in.clear();
}

// What the reader takes from the variable length records of the file (`in`): the extra bytes that
// its Extra Bytes VLR describes, in `data.extras`, and its scale, offset and CRS records (VLRs and
// extended VLRs), in `data.georeference`; the other records are skipped.
inline void read_las_vlrs(std::ifstream& in, Las_data& data, const std::string& filename)
{
  const Las_header& hd = data.header;
  std::uint64_t at = hd.header_size;
  for(std::uint32_t v = 0; v < hd.number_of_vlrs; ++v) {
    unsigned char h[54];
    in.seekg(static_cast<std::streamoff>(at));
    if(at + 54 > hd.offset_to_point_data || !in.read(reinterpret_cast<char*>(h), 54))
      throw las_error(filename, "variable length record " + std::to_string(v) + " runs into the point data");
    const std::uint64_t length = le_u16(h + 20);
    if(at + 54 + length > hd.offset_to_point_data)
      throw las_error(filename, "variable length record " + std::to_string(v) + " runs into the point data");
    const std::string user = fixed_text(h + 2, 16);
    if(user == "LASF_Spec" && le_u16(h + 18) == 4) {
      std::vector<unsigned char> d(static_cast<std::size_t>(length));
      if(!in.read(reinterpret_cast<char*>(d.data()), static_cast<std::streamsize>(length)))
        throw las_error(filename, "cannot read the extra bytes record");
      std::size_t offset = las_layout(hd.point_format).size;
      for(std::size_t k = 0; k + 192 <= d.size(); k += 192) {
        const unsigned char* e = d.data() + k;
        const unsigned type = e[2], options = e[3];
        const std::size_t size = type == 0 ? options : las_extra_size(type);
        if(size == 0)
          throw las_error(filename, "extra bytes of data type " + std::to_string(type) + " (1 to 10 are read)");
        if(offset + size > hd.record_length)
          throw las_error(filename, "the extra bytes described run past the point record length " +
                                        std::to_string(hd.record_length));
        if(type != 0) {
          Las_extra_bytes x;
          x.name = fixed_text(e + 4, 32);
          x.data_type = type, x.offset = offset;
          x.scaled = (options & 24) != 0;
          x.scale = (options & 8) ? le_f64(e + 112) : 1.0;
          x.add = (options & 16) ? le_f64(e + 136) : 0.0;
          data.extras.push_back(std::move(x));
        }
        offset += size;
      }
    } else if(user == "LASF_Projection") {
      read_las_crs_record(in, le_u16(h + 18), fixed_text(h + 22, 32), length, data, filename);
    }
    at += 54 + length;
  }
  read_las_crs_evlrs(in, data, filename);
  data.georeference.scale = hd.scale;
  data.georeference.offset = hd.offset;
  data.georeference.wkt = (hd.global_encoding & 0x10) != 0;
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
  read_las_vlrs(in, data, filename);
  read_las_records(in, data, filename);
  return data;
}

} // namespace internal
} // namespace Point_set_object_recognition
} // namespace CGAL

#endif // CGAL_POINT_SET_OBJECT_RECOGNITION_INTERNAL_LAS_IO_H
