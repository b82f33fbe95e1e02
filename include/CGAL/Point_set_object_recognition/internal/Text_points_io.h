// Copyright (c) 2026 CGAL Global Shape Analysis contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_POINT_SET_OBJECT_RECOGNITION_INTERNAL_TEXT_POINTS_IO_H
#define CGAL_POINT_SET_OBJECT_RECOGNITION_INTERNAL_TEXT_POINTS_IO_H

// Text point files: the XYZ reader of read_point_set() (CGAL's prints its own error lines on
// std::cerr and says only "cannot read"), and the diagnosis of an ASCII PLY file that CGAL's
// reader refused (which vertex, which value).

#include <CGAL/Shape_analysis/Bad_input.h>
#include <CGAL/Shape_analysis/internal/Ply_header.h>

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace CGAL {
namespace Point_set_object_recognition {
namespace internal {

// `word` as a number into `v`; false when it is not one number.
inline bool parse_number(const std::string& word, double& v)
{
  char* end = nullptr;
  errno = 0;
  v = std::strtod(word.c_str(), &end);
  return !word.empty() && end == word.c_str() + word.size();
}

// What is wrong with the value `word` of a coordinate, or an empty string.
inline std::string coordinate_problem(const std::string& word)
{
  double v = 0;
  if(!parse_number(word, v))
    return "'" + word + "' is not a number";
  if(!std::isfinite(v))
    return "'" + word + "' is not a finite number";
  return std::string();
}

struct Xyz_points
{
  std::vector<double> xyz;     // x, y, z per point
  std::vector<double> normals; // nx, ny, nz per point when every line has them, else empty
};

// Reads the XYZ file `filename`: one point a line, "x y z" or "x y z nx ny nz"; empty lines,
// lines starting with '#' and a first line holding only the number of points are skipped.
// Bad_input "<filename>: line N: ..." on a line of another shape or a value that is not a
// finite number.
inline Xyz_points read_xyz(const std::string& filename)
{
  std::ifstream in(filename);
  if(!in)
    throw CGAL::Shape_analysis::Bad_input(filename + ": cannot open the file for reading");
  Xyz_points r;
  std::string line;
  std::size_t number = 0, with_normals = 0, points = 0;
  bool first = true;
  double v[7];
  while(std::getline(in, line)) {
    ++number;
    // The values of the line, parsed in place (a word that is not a number: its text).
    const char* c = line.c_str();
    const char* const end = c + line.size();
    const auto blank = [](char x) { return x == ' ' || x == '\t' || x == '\r'; };
    while(c < end && blank(*c))
      ++c;
    if(c == end || *c == '#')
      continue;
    std::size_t count = 0;
    std::string bad;
    while(c < end && count < 7) {
      char* after = nullptr;
      const double x = std::strtod(c, &after);
      const char* word_end = c;
      while(word_end < end && !blank(*word_end))
        ++word_end;
      if(after != word_end || !std::isfinite(x)) {
        bad = "'" + std::string(c, word_end) + (after != word_end ? "' is not a number" : "' is not a finite number");
        break;
      }
      v[count++] = x;
      c = word_end;
      while(c < end && blank(*c))
        ++c;
    }
    const auto where = [&]() { return filename + ": line " + std::to_string(number) + ": "; };
    if(!bad.empty())
      throw CGAL::Shape_analysis::Bad_input(where() + bad);
    if(first && count == 1 && c == end && v[0] >= 0 && v[0] == std::floor(v[0])) {
      first = false; // the number of points
      continue;
    }
    first = false;
    if(c != end || (count != 3 && count != 6))
      throw CGAL::Shape_analysis::Bad_input(where() + "expected 'x y z' or 'x y z nx ny nz', got " +
                                            (c != end ? std::string("more than 6") : std::to_string(count)) + " values");
    for(std::size_t k = 0; k < count; ++k)
      (k < 3 ? r.xyz : r.normals).push_back(v[k]);
    with_normals += count == 6 ? 1 : 0;
    ++points;
  }
  if(with_normals != points)
    r.normals.clear();
  return r;
}

// For an ASCII PLY file that CGAL's reader refused: the first vertex whose x, y or z is not a
// finite number, or that has too few values, as "<filename>: vertex N: ..."; an empty string when
// none is found (the message stays CGAL's "cannot read").
inline std::string diagnose_ascii_ply(const std::string& filename)
{
  CGAL::Shape_analysis::internal::Ply_header h;
  try {
    h = CGAL::Shape_analysis::internal::read_ply_header(filename);
  } catch(const CGAL::Shape_analysis::Bad_input& e) {
    return e.what();
  }
  if(h.format != "ascii")
    return std::string();
  std::ifstream in(filename);
  std::string line;
  while(std::getline(in, line))
    if(line.compare(0, 10, "end_header") == 0)
      break;
  std::vector<std::size_t> coordinate; // the positions of x, y, z among the vertex properties
  for(const char* c : {"x", "y", "z"})
    for(std::size_t k = 0; k < h.vertex_properties.size(); ++k)
      if(h.vertex_properties[k] == c)
        coordinate.push_back(k);
  for(std::size_t v = 0; v < h.vertices; ++v) {
    if(!std::getline(in, line))
      return filename + ": the header announces " + std::to_string(h.vertices) + " vertices, the file has " +
             std::to_string(v);
    std::istringstream words(line);
    std::vector<std::string> w;
    std::string word;
    while(words >> word)
      w.push_back(word);
    for(std::size_t k : coordinate) {
      if(k >= w.size())
        return filename + ": vertex " + std::to_string(v) + " has " + std::to_string(w.size()) + " values, " +
               std::to_string(h.vertex_properties.size()) + " expected";
      const std::string problem = coordinate_problem(w[k]);
      if(!problem.empty())
        return filename + ": vertex " + std::to_string(v) + ": " + problem;
    }
  }
  return std::string();
}

} // namespace internal
} // namespace Point_set_object_recognition
} // namespace CGAL

#endif // CGAL_POINT_SET_OBJECT_RECOGNITION_INTERNAL_TEXT_POINTS_IO_H
