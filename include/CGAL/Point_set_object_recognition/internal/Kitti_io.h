// Copyright (c) 2026 CGAL Global Shape Analysis contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_POINT_SET_OBJECT_RECOGNITION_INTERNAL_KITTI_IO_H
#define CGAL_POINT_SET_OBJECT_RECOGNITION_INTERNAL_KITTI_IO_H

// KITTI velodyne scans (.bin): no header, one record of 16 bytes per point, float32 x, y, z and
// reflectance, little-endian.

#include <CGAL/Point_set_object_recognition/internal/Binary_io.h>
#include <CGAL/Shape_analysis/Bad_input.h>

#include <CGAL/Point_set_3.h>
#include <CGAL/number_utils.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <fstream>
#include <string>
#include <vector>

namespace CGAL {
namespace Point_set_object_recognition {
namespace internal {

// The content of a KITTI scan: x, y, z of each point (floats widened to double) and reflectance.
struct Kitti_data
{
  std::vector<double> xyz;
  std::vector<float> reflectance;
};

// Reads the KITTI velodyne file `filename`; throws Bad_input if it is missing, empty, or not a
// whole number of 16-byte records.
inline Kitti_data read_kitti(const std::string& filename)
{
  typedef CGAL::Shape_analysis::Bad_input Bad_input;
  std::ifstream in;
  open_for_reading(in, filename);
  const std::uint64_t size = file_size(in);
  if(size == 0)
    throw Bad_input(filename + ": the file is empty");
  if(size % 16 != 0)
    throw Bad_input(filename + ": the size of a KITTI velodyne file (" + std::to_string(size) +
                    " bytes) must be a multiple of 16 (float32 x, y, z, reflectance per point)");
  const std::size_t n = static_cast<std::size_t>(size / 16);
  Kitti_data data;
  data.xyz.resize(3 * n);
  data.reflectance.resize(n);
  const std::size_t chunk = 1 << 16;
  std::vector<unsigned char> buffer(16 * std::min(chunk, n));
  for(std::size_t first = 0; first < n;) {
    const std::size_t m = std::min(chunk, n - first);
    if(!in.read(reinterpret_cast<char*>(buffer.data()), static_cast<std::streamsize>(16 * m)))
      throw Bad_input(filename + ": cannot read the point data");
    for(std::size_t k = 0; k < m; ++k) {
      const unsigned char* p = buffer.data() + 16 * k;
      for(int c = 0; c < 3; ++c)
        data.xyz[3 * (first + k) + c] = le_f32(p + 4 * c);
      data.reflectance[first + k] = le_f32(p + 12);
    }
    first += m;
  }
  return data;
}

// Writes `points` as a KITTI velodyne file: each point plus `origin` as float32 x, y, z, and the
// float property "reflectance" (0 without it). Written to a temporary file then renamed.
template <typename Point>
void write_kitti(const std::string& filename, const CGAL::Point_set_3<Point>& points,
                 const std::array<double, 3>& origin = {{0, 0, 0}})
{
  const auto reflectance = points.template property_map<float>("reflectance");
  Atomic_output_file out(filename);
  Le_buffer b;
  for(typename CGAL::Point_set_3<Point>::Index i : points) {
    const Point& p = points.point(i);
    b.f32(static_cast<float>(CGAL::to_double(p.x()) + origin[0]));
    b.f32(static_cast<float>(CGAL::to_double(p.y()) + origin[1]));
    b.f32(static_cast<float>(CGAL::to_double(p.z()) + origin[2]));
    b.f32(reflectance.second ? reflectance.first[i] : 0.f);
    if(b.bytes.size() >= (1 << 20)) {
      out.write(b.bytes);
      b.bytes.clear();
    }
  }
  out.write(b.bytes);
  out.commit();
}

} // namespace internal
} // namespace Point_set_object_recognition
} // namespace CGAL

#endif // CGAL_POINT_SET_OBJECT_RECOGNITION_INTERNAL_KITTI_IO_H
