// Copyright (c) 2026 CGAL Global Shape Analysis contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_POINT_SET_OBJECT_RECOGNITION_POINT_SET_FILE_READER_H
#define CGAL_POINT_SET_OBJECT_RECOGNITION_POINT_SET_FILE_READER_H

/// \file Point_set_file_reader.h
/// Reading a scan piece by piece, for scans larger than memory.

#include <CGAL/Point_set_3.h>

#include <CGAL/Point_set_object_recognition/read_point_set.h>
#include <CGAL/Point_set_object_recognition/internal/Binary_io.h>
#include <CGAL/Point_set_object_recognition/internal/Las_io.h>
#include <CGAL/Shape_analysis/Bad_input.h>
#include <CGAL/Shape_analysis/internal/Ply_header.h>

#include <array>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <sstream>
#include <optional>
#include <string>
#include <vector>

namespace CGAL {
namespace Point_set_object_recognition {

/*!
\ingroup PkgPointSetObjectRecognitionRef

A scan file read piece by piece: any range of its points, in any order and from any number of
threads, with the same points and properties as `read_point_set()` gives them, so that a scan
larger than memory can be processed a piece at a time. The formats are those whose points are
records of one size: uncompressed LAS 1.0 to 1.4 (point data formats 0 to 10, extra bytes
included), binary little-endian PLY whose first element is the vertex element with scalar
properties only, and KITTI velodyne files (`.bin`). Other files (XYZ, ASCII PLY) are read whole
with `read_point_set()`.
*/
class Point_set_file_reader
{
public:
  /// Opens `filename` and reads its header.
  /// \param filename the scan (`.las`, `.ply` or `.bin`)
  /// \throws CGAL::Shape_analysis::Bad_input if the file cannot be opened, is not one of the
  ///         formats above (`readable()` tells beforehand), or its header is inconsistent with
  ///         its size
  explicit Point_set_file_reader(const std::string& filename) : m_filename(filename)
  {
    const std::string ext = internal::lowercase_extension(filename);
    if(ext == ".las")
      open_las();
    else if(ext == ".ply")
      open_ply();
    else if(ext == ".bin")
      open_kitti();
    else
      throw Bad_input(filename + ": a scan read in pieces must be LAS, binary PLY or KITTI (.las, .ply, .bin)");
    if(m_count == 0)
      throw Bad_input(filename + ": the file contains no points");
  }

  /// Whether `filename` is a file this class reads (by its extension and, for PLY, its header);
  /// never throws.
  /// \param filename the scan
  /// \returns whether the constructor would accept it
  static bool readable(const std::string& filename)
  {
    try {
      Point_set_file_reader r(filename);
      return true;
    } catch(const std::exception&) {
      return false;
    }
  }

  /// The local origin that `read_point_set()` subtracts by default from points whose bounding
  /// box is [`lo`, `hi`]: per axis, 0 when the coordinates are below \f$10^5\f$ in absolute
  /// value, else the minimum rounded down to a multiple of 100.
  /// \param lo,hi the bounding box of the coordinates as stored (`read_coordinates()`)
  /// \returns the origin
  static std::array<double, 3> automatic_local_origin(const std::array<double, 3>& lo, const std::array<double, 3>& hi)
  {
    return internal::automatic_local_origin(lo, hi);
  }

  /// \returns the file's name
  const std::string& filename() const { return m_filename; }
  /// \returns the format, as `Point_set_read_result::format`: "las", "ply" or "kitti"
  const std::string& format() const { return m_format; }
  /// \returns the number of points of the file
  std::uint64_t number_of_points() const { return m_count; }
  /// \returns for a LAS file, its scale, offset and coordinate system records (as
  ///          `Point_set_read_result::las_georeference`); empty for the other formats
  std::optional<Las_georeference> las_georeference() const
  {
    return m_format == "las" ? std::optional<Las_georeference>(m_las.georeference) : std::nullopt;
  }

  /// Reads the coordinates of the points `first` to `first + count - 1`, as stored (no origin
  /// subtracted), into `xyz` (x, y, z of each point; replaced).
  /// \param first the first point
  /// \param count the number of points
  /// \param xyz the coordinates
  /// \throws CGAL::Shape_analysis::Bad_input if the range is beyond the file's points or the
  ///         file cannot be read (changed since it was opened)
  void read_coordinates(std::uint64_t first, std::size_t count, std::vector<double>& xyz) const
  {
    std::vector<unsigned char> buffer;
    read_raw(first, count, buffer);
    xyz.resize(3 * count);
    for(std::size_t k = 0; k < count; ++k)
      decode_point(buffer.data() + k * m_record, &xyz[3 * k]);
  }

  /// \returns the size in bytes of a point's record in the file
  std::size_t record_length() const { return m_record; }

  /// Reads the records of the points `first` to `first + count - 1` as the file stores them (for
  /// a PLY file, the vertex element's bytes) into `bytes` (replaced).
  /// \param first the first point
  /// \param count the number of points
  /// \param bytes the records, `count * record_length()` bytes
  /// \throws CGAL::Shape_analysis::Bad_input as `read_coordinates()`
  void read_records(std::uint64_t first, std::size_t count, std::vector<unsigned char>& bytes) const
  {
    read_raw(first, count, bytes);
  }

  /// Reads the points `first` to `first + count - 1` with their properties into `points`
  /// (replaced), minus `origin`: the points and properties (names, types, order) that
  /// `read_point_set()` gives these points when it subtracts the same origin.
  /// \tparam Point the point type of the point set
  /// \tparam Vector the normal type of the point set
  /// \param first the first point
  /// \param count the number of points
  /// \param points the point set
  /// \param origin subtracted from the coordinates (the local origin of `read_point_set()`)
  /// \throws CGAL::Shape_analysis::Bad_input as `read_coordinates()`
  template <typename Point, typename Vector>
  void read(std::uint64_t first, std::size_t count, CGAL::Point_set_3<Point, Vector>& points,
            const std::array<double, 3>& origin = {{0, 0, 0}}) const
  {
    std::vector<unsigned char> buffer;
    read_raw(first, count, buffer);
    points.clear();
    std::vector<double> xyz(3 * count);
    for(std::size_t k = 0; k < count; ++k)
      decode_point(buffer.data() + k * m_record, &xyz[3 * k]);
    internal::add_points(points, xyz, origin);
    if(m_format == "las")
      las_properties(buffer, count, points);
    else if(m_format == "ply")
      ply_properties(buffer, count, points);
    else {
      std::vector<float> reflectance(count);
      for(std::size_t k = 0; k < count; ++k)
        reflectance[k] = internal::le_f32(buffer.data() + k * m_record + 12);
      internal::add_property(points, "reflectance", reflectance);
    }
  }

private:
  // A scalar property of a PLY vertex: name, type, byte offset in the record.
  struct Ply_property
  {
    std::string name, type;
    std::size_t offset;
  };

  void read_raw(std::uint64_t first, std::size_t count, std::vector<unsigned char>& buffer) const
  {
    if(first > m_count || count > m_count - first)
      throw Bad_input(m_filename + ": points " + std::to_string(first) + " to " + std::to_string(first + count) +
                      " are beyond its " + std::to_string(m_count) + " points");
    buffer.resize(count * m_record);
    if(count == 0)
      return;
    std::ifstream in;
    internal::open_for_reading(in, m_filename);
    in.seekg(std::streamoff(m_data + first * m_record));
    if(!in.read(reinterpret_cast<char*>(buffer.data()), std::streamsize(buffer.size())))
      throw Bad_input(m_filename + ": cannot read points " + std::to_string(first) + " to " +
                      std::to_string(first + count) + " (the file changed?)");
  }

  void decode_point(const unsigned char* p, double* xyz) const
  {
    if(m_format == "las") {
      for(int c = 0; c < 3; ++c)
        xyz[c] = internal::le_i32(p + 4 * c) * m_las.header.scale[c] + m_las.header.offset[c];
    } else if(m_format == "kitti") {
      for(int c = 0; c < 3; ++c)
        xyz[c] = internal::le_f32(p + 4 * c);
    } else {
      for(int c = 0; c < 3; ++c)
        xyz[c] = m_ply_double ? internal::le_f64(p + m_ply_xyz[c]) : internal::le_f32(p + m_ply_xyz[c]);
    }
  }

  void open_las()
  {
    m_format = "las";
    std::ifstream in;
    internal::open_for_reading(in, m_filename);
    const std::uint64_t size = internal::file_size(in);
    unsigned char h[375] = {0};
    const std::size_t available = std::size_t((std::min<std::uint64_t>)(size, 375));
    if(!in.read(reinterpret_cast<char*>(h), std::streamsize(available)) || available < 227 ||
       std::memcmp(h, "LASF", 4) != 0)
      throw Bad_input(m_filename + ": not a LAS file (no \"LASF\" signature or a truncated header)");
    unsigned format_byte = 0;
    std::uint32_t legacy_count = 0;
    m_las.header = internal::las_header_fields(h, format_byte, legacy_count);
    internal::check_las_header(m_las.header, format_byte, size, m_filename);
    internal::set_las_point_count(m_las.header, h, legacy_count, size, m_filename);
    internal::read_las_vlrs(in, m_las, m_filename);
    m_count = m_las.header.number_of_points;
    m_record = m_las.header.record_length;
    m_data = m_las.header.offset_to_point_data;
  }

  void open_kitti()
  {
    m_format = "kitti";
    std::ifstream in;
    internal::open_for_reading(in, m_filename);
    const std::uint64_t size = internal::file_size(in);
    if(size % 16 != 0)
      throw Bad_input(m_filename + ": the size of a KITTI velodyne file (" + std::to_string(size) +
                      " bytes) must be a multiple of 16 (float32 x, y, z, reflectance per point)");
    m_count = size / 16, m_record = 16, m_data = 0;
  }

  void open_ply()
  {
    m_format = "ply";
    const CGAL::Shape_analysis::internal::Ply_header checked =
      CGAL::Shape_analysis::internal::read_ply_header(m_filename); // every check of read_point_set()
    if(checked.format != "binary_little_endian")
      throw Bad_input(m_filename + ": a PLY file read in pieces must be binary_little_endian");
    std::ifstream in;
    internal::open_for_reading(in, m_filename);
    std::string line;
    bool first_element = true, in_vertex = false;
    while(std::getline(in, line)) {
      if(!line.empty() && line.back() == '\r')
        line.pop_back();
      std::istringstream words(line);
      std::string word, type, name;
      words >> word;
      if(word == "end_header")
        break;
      if(word == "element") {
        words >> name;
        if(first_element && name != "vertex")
          throw Bad_input(m_filename + ": a PLY file read in pieces must start with its vertex element");
        in_vertex = first_element;
        first_element = false;
      } else if(word == "property" && in_vertex) {
        words >> type >> name;
        if(type == "list")
          throw Bad_input(m_filename + ": a PLY file read in pieces has no list property in its vertex element");
        m_ply.push_back(Ply_property{name, canonical_type(type), m_record});
        m_record += CGAL::Shape_analysis::internal::type_size(type);
      }
    }
    m_data = std::uint64_t(in.tellg());
    for(const Ply_property& p : m_ply)
      for(int c = 0; c < 3; ++c)
        if(p.name == std::string(1, char('x' + c))) {
          m_ply_xyz[c] = p.offset;
          m_ply_double = p.type == "double";
        }
    m_count = checked.vertices;
    std::ifstream sized(m_filename, std::ios::binary);
    if(internal::file_size(sized) < m_data + m_count * m_record)
      throw Bad_input(m_filename + ": the file is shorter than its " + std::to_string(m_count) + " vertices");
  }

  static std::string canonical_type(const std::string& t)
  {
    static const char* const pairs[][2] = {{"int8", "char"},   {"uint8", "uchar"},   {"int16", "short"},
                                           {"uint16", "ushort"}, {"int32", "int"},   {"uint32", "uint"},
                                           {"float32", "float"}, {"float64", "double"}};
    for(const auto& p : pairs)
      if(t == p[0])
        return p[1];
    return t;
  }

  // The LAS attributes of the records, as read_point_set() adds them.
  template <typename Point_set>
  void las_properties(const std::vector<unsigned char>& buffer, std::size_t count, Point_set& points) const
  {
    const internal::Las_format_layout& layout = internal::las_layout(m_las.header.point_format);
    std::vector<std::uint16_t> intensity(count), red, green, blue;
    std::vector<unsigned char> classification(count), return_number(count), number_of_returns(count);
    std::vector<double> gps_time;
    std::vector<internal::Las_extra_bytes> extras = m_las.extras;
    if(layout.gps_time >= 0)
      gps_time.resize(count);
    if(layout.rgb >= 0)
      red.resize(count), green.resize(count), blue.resize(count);
    for(internal::Las_extra_bytes& e : extras)
      e.values.resize(count);
    for(std::size_t k = 0; k < count; ++k) {
      const unsigned char* p = buffer.data() + k * m_record;
      intensity[k] = internal::le_u16(p + 12);
      return_number[k] = layout.extended ? p[14] & 15 : p[14] & 7;
      number_of_returns[k] = layout.extended ? p[14] >> 4 : (p[14] >> 3) & 7;
      classification[k] = layout.extended ? p[16] : p[15] & 31;
      if(layout.gps_time >= 0)
        gps_time[k] = internal::le_f64(p + layout.gps_time);
      if(layout.rgb >= 0) {
        red[k] = internal::le_u16(p + layout.rgb);
        green[k] = internal::le_u16(p + layout.rgb + 2);
        blue[k] = internal::le_u16(p + layout.rgb + 4);
      }
      for(internal::Las_extra_bytes& e : extras) {
        const double v = internal::las_extra_value(p + e.offset, e.data_type);
        e.values[k] = e.scaled ? v * e.scale + e.add : v;
      }
    }
    internal::add_property(points, "intensity", intensity);
    internal::add_property(points, "classification", classification);
    internal::add_property(points, "return_number", return_number);
    internal::add_property(points, "number_of_returns", number_of_returns);
    internal::add_property(points, "gps_time", gps_time);
    internal::add_property(points, "red", red);
    internal::add_property(points, "green", green);
    internal::add_property(points, "blue", blue);
    for(const internal::Las_extra_bytes& e : extras)
      internal::add_extra_property(points, e);
  }

  // The PLY vertex properties but x, y, z (and the normals), in file order, with the types that
  // CGAL's reader gives them; then the normals when nx, ny and nz are all there.
  template <typename Point, typename Vector>
  void ply_properties(const std::vector<unsigned char>& buffer, std::size_t count,
                      CGAL::Point_set_3<Point, Vector>& points) const
  {
    std::size_t normal[3] = {0, 0, 0};
    bool normal_double = false;
    int normals = 0;
    for(const Ply_property& p : m_ply) {
      if(p.name == "x" || p.name == "y" || p.name == "z")
        continue;
      if(p.name == "nx" || p.name == "ny" || p.name == "nz") {
        normal[p.name[1] - 'x'] = p.offset;
        normal_double = p.type == "double";
        ++normals;
        continue;
      }
      const auto add = [&](auto tag, auto decode) {
        typedef decltype(tag) T;
        std::vector<T> values(count);
        for(std::size_t k = 0; k < count; ++k)
          values[k] = static_cast<T>(decode(buffer.data() + k * m_record + p.offset));
        auto map = points.template add_property_map<T>(p.name, T()).first;
        std::size_t k = 0;
        for(auto i : points)
          map[i] = values[k++];
      };
      if(p.type == "char")
        add(std::int8_t(0), [](const unsigned char* b) { return static_cast<std::int8_t>(b[0]); });
      else if(p.type == "uchar")
        add(std::uint8_t(0), [](const unsigned char* b) { return b[0]; });
      else if(p.type == "short")
        add(std::int16_t(0), [](const unsigned char* b) { return static_cast<std::int16_t>(internal::le_u16(b)); });
      else if(p.type == "ushort")
        add(std::uint16_t(0), [](const unsigned char* b) { return internal::le_u16(b); });
      else if(p.type == "int")
        add(std::int32_t(0), [](const unsigned char* b) { return internal::le_i32(b); });
      else if(p.type == "uint")
        add(std::uint32_t(0), [](const unsigned char* b) { return internal::le_u32(b); });
      else if(p.type == "float")
        add(0.f, [](const unsigned char* b) { return internal::le_f32(b); });
      else
        add(0.0, [](const unsigned char* b) { return internal::le_f64(b); });
    }
    if(normals == 3) { // read as the coordinates' type, as CGAL's reader does
      points.add_normal_map();
      std::size_t k = 0;
      for(auto i : points) {
        const unsigned char* b = buffer.data() + (k++) * m_record;
        double v[3];
        for(int c = 0; c < 3; ++c)
          v[c] = normal_double ? internal::le_f64(b + normal[c]) : double(internal::le_f32(b + normal[c]));
        if(!m_ply_double)
          for(double& c : v)
            c = double(float(c));
        points.normal(i) = Vector(v[0], v[1], v[2]);
      }
    }
  }

  std::string m_filename, m_format;
  std::uint64_t m_count = 0, m_data = 0;
  std::size_t m_record = 0;
  internal::Las_data m_las;          // LAS: the header and the extra bytes described
  std::vector<Ply_property> m_ply;   // PLY: the vertex properties
  std::size_t m_ply_xyz[3] = {0, 0, 0};
  bool m_ply_double = false;
};

} // namespace Point_set_object_recognition
} // namespace CGAL

#endif // CGAL_POINT_SET_OBJECT_RECOGNITION_POINT_SET_FILE_READER_H
