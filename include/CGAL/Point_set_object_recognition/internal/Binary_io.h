// Copyright (c) 2026 CGAL Global Shape Analysis contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_POINT_SET_OBJECT_RECOGNITION_INTERNAL_BINARY_IO_H
#define CGAL_POINT_SET_OBJECT_RECOGNITION_INTERNAL_BINARY_IO_H

// Little-endian decoding and encoding independent of the host's byte order, the size of an open
// file, and an output file that appears under its name only once completely written.

#include <CGAL/Shape_analysis/Bad_input.h>

#include <cstdint>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <string>
#include <vector>

namespace CGAL {
namespace Point_set_object_recognition {
namespace internal {

// The unsigned integer stored in the `n` bytes at `p`, least significant byte first.
inline std::uint64_t load_le(const unsigned char* p, int n)
{
  std::uint64_t v = 0;
  for(int i = n - 1; i >= 0; --i)
    v = (v << 8) | p[i];
  return v;
}

inline std::uint16_t le_u16(const unsigned char* p) { return static_cast<std::uint16_t>(load_le(p, 2)); }
inline std::uint32_t le_u32(const unsigned char* p) { return static_cast<std::uint32_t>(load_le(p, 4)); }
inline std::uint64_t le_u64(const unsigned char* p) { return load_le(p, 8); }

inline std::int32_t le_i32(const unsigned char* p)
{
  const std::uint32_t u = le_u32(p);
  std::int32_t v;
  std::memcpy(&v, &u, 4);
  return v;
}

inline float le_f32(const unsigned char* p)
{
  const std::uint32_t u = le_u32(p);
  float v;
  std::memcpy(&v, &u, 4);
  return v;
}

inline double le_f64(const unsigned char* p)
{
  const std::uint64_t u = le_u64(p);
  double v;
  std::memcpy(&v, &u, 8);
  return v;
}

// A byte buffer filled with little-endian values.
struct Le_buffer
{
  std::vector<unsigned char> bytes;

  void put(std::uint64_t v, int n)
  {
    for(int i = 0; i < n; ++i, v >>= 8)
      bytes.push_back(static_cast<unsigned char>(v & 0xff));
  }
  void u8(unsigned v) { put(v, 1); }
  void u16(unsigned v) { put(v, 2); }
  void u32(std::uint32_t v) { put(v, 4); }
  void u64(std::uint64_t v) { put(v, 8); }
  void i32(std::int32_t v)
  {
    std::uint32_t u;
    std::memcpy(&u, &v, 4);
    put(u, 4);
  }
  void f32(float v)
  {
    std::uint32_t u;
    std::memcpy(&u, &v, 4);
    put(u, 4);
  }
  void f64(double v)
  {
    std::uint64_t u;
    std::memcpy(&u, &v, 8);
    put(u, 8);
  }
  // `s` in a field of `n` bytes, cut or padded with zeros.
  void text(const std::string& s, std::size_t n)
  {
    for(std::size_t i = 0; i < n; ++i)
      bytes.push_back(i < s.size() ? static_cast<unsigned char>(s[i]) : 0);
  }
  void zeros(std::size_t n) { bytes.insert(bytes.end(), n, 0); }
};

// The size in bytes of a file open for reading; the read position is left at the start.
inline std::uint64_t file_size(std::ifstream& in)
{
  in.seekg(0, std::ios::end);
  const std::streamoff size = in.tellg();
  in.seekg(0, std::ios::beg);
  return size > 0 ? static_cast<std::uint64_t>(size) : 0;
}

// Opens `filename` for binary reading, or throws Bad_input.
inline void open_for_reading(std::ifstream& in, const std::string& filename)
{
  in.open(filename, std::ios::binary);
  if(!in)
    throw CGAL::Shape_analysis::Bad_input(filename + ": cannot open the file for reading");
}

// An output file written under a temporary name and renamed to its own name by `commit()`, so
// that an interrupted writer never leaves a half-written file; without `commit()` the temporary
// file is removed.
class Atomic_output_file
{
public:
  explicit Atomic_output_file(const std::string& filename)
    : m_name(filename), m_temporary(filename + ".tmp"), m_out(m_temporary, std::ios::binary)
  {
    if(!m_out)
      throw CGAL::Shape_analysis::Bad_input(filename + ": cannot open the file for writing");
  }
  Atomic_output_file(const Atomic_output_file&) = delete;
  Atomic_output_file& operator=(const Atomic_output_file&) = delete;
  ~Atomic_output_file()
  {
    if(!m_committed) {
      m_out.close();
      std::remove(m_temporary.c_str());
    }
  }

  void write(const std::vector<unsigned char>& bytes)
  {
    m_out.write(reinterpret_cast<const char*>(bytes.data()), static_cast<std::streamsize>(bytes.size()));
  }

  void commit()
  {
    m_out.close();
    if(!m_out || std::rename(m_temporary.c_str(), m_name.c_str()) != 0)
      throw CGAL::Shape_analysis::Bad_input(m_name + ": cannot write the file");
    m_committed = true;
  }

private:
  std::string m_name, m_temporary;
  std::ofstream m_out;
  bool m_committed = false;
};

} // namespace internal
} // namespace Point_set_object_recognition
} // namespace CGAL

#endif // CGAL_POINT_SET_OBJECT_RECOGNITION_INTERNAL_BINARY_IO_H
