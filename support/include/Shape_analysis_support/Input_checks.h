// Copyright (c) 2026 CGAL Global Shape Analysis contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef SHAPE_ANALYSIS_SUPPORT_INPUT_CHECKS_H
#define SHAPE_ANALYSIS_SUPPORT_INPUT_CHECKS_H

// Checks of input files made before CGAL's readers see them, for the tool (the library's readers
// make the same checks themselves).

#include <CGAL/Shape_analysis/internal/Ply_header.h>

#include <array>
#include <cerrno>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace CGAL {
namespace Shape_analysis_support {

// Bad_input, its message starting with `path`, unless the PLY file `path` has a header with
// a vertex element that has x, y and z properties (CGAL's reader puts vertices without them at
// the origin).
inline void check_ply_vertices(const std::string& path)
{
  CGAL::Shape_analysis::internal::read_ply_header(path);
}

namespace input_checks_internal {

// The non-empty lines of `in` without their '#' comments, as words, with their line numbers.
inline bool next_words(std::istream& in, std::size_t& number, std::vector<std::string>& words)
{
  std::string line;
  while(std::getline(in, line)) {
    ++number;
    const std::size_t hash = line.find('#');
    if(hash != std::string::npos)
      line.erase(hash);
    std::istringstream w(line);
    words.clear();
    std::string word;
    while(w >> word)
      words.push_back(word);
    if(!words.empty())
      return true;
  }
  return false;
}

inline bool whole_number(const std::string& w, long long& v)
{
  char* end = nullptr;
  errno = 0;
  v = std::strtoll(w.c_str(), &end, 10);
  return !w.empty() && end == w.c_str() + w.size() && errno == 0;
}

} // namespace input_checks_internal

// Reads an ASCII OFF file ([ST][C][N]OFF) with every check on the way: its header, the counts,
// that each vertex line starts with three finite numbers (its position; normals, colours and
// texture coordinates after them are ignored), that each face line is "n i1 ... in" with n >= 3
// and indices of existing vertices (a colour after them is ignored). Returns what is wrong, or an
// empty string when the file was read into `points` and `faces`. A binary OFF is not read:
// `binary` is set and the file is left to CGAL's reader. The homogeneous and n-dimensional
// variants (4OFF, nOFF) are refused. CGAL's ASCII reader is not used: it converts a negative
// size or index to an unsigned integer (undefined behaviour), trusts the counts and reads past
// the end of a short line of an STOFF file (all found by fuzzing).
inline std::string read_ascii_off(const std::string& path, std::vector<std::array<double, 3>>& points,
                                  std::vector<std::vector<std::size_t>>& faces, bool& binary)
{
  using namespace input_checks_internal;
  binary = false;
  points.clear();
  faces.clear();
  std::ifstream in(path);
  std::size_t line = 0;
  std::vector<std::string> w;
  if(!next_words(in, line, w))
    return "the file is empty";
  {
    // [ST][C][N]OFF, its counts possibly on the same line.
    std::string key = w[0];
    for(const char* prefix : {"ST", "C", "N"})
      if(key.compare(0, std::strlen(prefix), prefix) == 0 && key.size() > 3)
        key.erase(0, std::strlen(prefix));
    if(key != "OFF") { // (4OFF, nOFF, SKEL and garbled keywords are not checked: refused)
      if(w[0].find("OFF") == std::string::npos)
        return "the file does not start with 'OFF'";
      std::string shown = w[0].substr(0, 24);
      for(char& c : shown)
        if(!std::isprint(static_cast<unsigned char>(c)))
          c = '?';
      return "the header '" + shown + "' is not one of OFF, COFF, NOFF, CNOFF, STOFF, STCOFF, STCNOFF";
    }
    if(w.size() > 1 && w[1] == "BINARY") {
      binary = true;
      return std::string();
    }
  }
  w.erase(w.begin());
  if(w.empty() && !next_words(in, line, w))
    return "the header has no counts (vertices faces edges)";
  long long nv = 0, nf = 0;
  if(w.size() < 2 || !whole_number(w[0], nv) || !whole_number(w[1], nf) || nv < 0 || nf < 0)
    return "line " + std::to_string(line) + ": the counts of vertices and faces are not two whole numbers >= 0";
  for(long long v = 0; v < nv; ++v) {
    if(!next_words(in, line, w))
      return "the header announces " + std::to_string(nv) + " vertices, the file ends after " + std::to_string(v);
    std::array<double, 3> position{};
    for(std::size_t k = 0; k < 3; ++k) {
      double& x = position[k];
      if(k >= w.size())
        return "line " + std::to_string(line) + ": vertex " + std::to_string(v) + " has fewer than 3 coordinates";
      char* end = nullptr;
      x = std::strtod(w[k].c_str(), &end);
      if(end != w[k].c_str() + w[k].size())
        return "line " + std::to_string(line) + ": vertex " + std::to_string(v) + ": '" + w[k] + "' is not a number";
      if(!std::isfinite(x))
        return "line " + std::to_string(line) + ": vertex " + std::to_string(v) + ": '" + w[k] + "' is not a finite number";
    }
    points.push_back(position);
  }
  for(long long f = 0; f < nf; ++f) {
    if(!next_words(in, line, w))
      return "the header announces " + std::to_string(nf) + " faces, the file ends after " + std::to_string(f);
    long long n = 0, index = 0;
    if(!whole_number(w[0], n) || n < 3 || std::size_t(n) + 1 > w.size())
      return "line " + std::to_string(line) + ": face " + std::to_string(f) + " is not 'n i1 ... in' with n >= 3";
    faces.emplace_back();
    for(long long k = 1; k <= n; ++k) {
      if(!whole_number(w[std::size_t(k)], index))
        return "line " + std::to_string(line) + ": face " + std::to_string(f) + ": '" + w[std::size_t(k)] +
               "' is not a vertex index";
      if(index < 0 || index >= nv)
        return "line " + std::to_string(line) + ": face " + std::to_string(f) + " refers to vertex " +
               std::to_string(index) + "; the vertices are 0 to " + std::to_string(nv - 1);
      faces.back().push_back(std::size_t(index));
    }
  }
  return std::string();
}

// For an OBJ file: the first face whose vertex index is 0 (OBJ counts from 1) or refers to a
// vertex that the file does not have, or an empty string.
inline std::string check_obj_faces(const std::string& path)
{
  using namespace input_checks_internal;
  std::ifstream in(path);
  std::size_t line = 0;
  long long vertices = 0, total = 0;
  std::vector<std::string> w;
  {
    std::ifstream count(path);
    std::size_t l = 0;
    while(next_words(count, l, w))
      total += w[0] == "v" ? 1 : 0;
  }
  while(next_words(in, line, w)) {
    if(w[0] == "v")
      ++vertices;
    if(w[0] != "f")
      continue;
    for(std::size_t k = 1; k < w.size(); ++k) {
      long long index = 0;
      const std::string first = w[k].substr(0, w[k].find('/'));
      if(!whole_number(first, index))
        return "line " + std::to_string(line) + ": '" + w[k] + "' is not a vertex index";
      if(index == 0)
        return "line " + std::to_string(line) + ": vertex index 0 (OBJ counts vertices from 1)";
      if(index > total)
        return "line " + std::to_string(line) + ": vertex index " + first + ", the file has " +
               std::to_string(total) + " vertices";
      if(index < 0 && -index > vertices)
        return "line " + std::to_string(line) + ": relative vertex index " + first + " points before the first vertex";
    }
  }
  return std::string();
}

} // namespace Shape_analysis_support
} // namespace CGAL

#endif // SHAPE_ANALYSIS_SUPPORT_INPUT_CHECKS_H
