// Copyright (c) 2026 CGAL Global Shape Analysis contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_SHAPE_ANALYSIS_INTERNAL_PLY_HEADER_H
#define CGAL_SHAPE_ANALYSIS_INTERNAL_PLY_HEADER_H

// A check of a PLY file's header before CGAL's reader sees it: CGAL's reader takes a vertex
// element without x, y and z properties and gives every point the origin, so that a file of
// the wrong kind (a point cloud with other coordinate names, a mesh of indices only) would be
// processed without a word.

#include <CGAL/Shape_analysis/Bad_input.h>

#include <algorithm>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace CGAL {
namespace Shape_analysis {
namespace internal {

struct Ply_header
{
  std::string format;                        // "ascii", "binary_little_endian" or "binary_big_endian"
  std::size_t vertices = 0;                  // the count of the vertex element
  std::vector<std::string> vertex_properties; // its properties' names, in order
  bool has_faces = false;                    // an element "face"
};

// The header of the PLY file `path`; Bad_input, its message starting with `path`, when the file
// does not start with "ply", has no "format" line or no "end_header" within its first 64 KiB
// of header, or its vertex element lacks one of x, y and z.
inline Ply_header read_ply_header(const std::string& path)
{
  std::ifstream in(path, std::ios::binary);
  if(!in)
    throw Bad_input(path + ": cannot open the file for reading");
  Ply_header h;
  std::string line;
  std::size_t read = 0;
  bool magic = false, end = false, in_vertex = false, has_vertex = false;
  while(std::getline(in, line)) {
    read += line.size() + 1;
    if(read > 65536)
      break;
    if(!line.empty() && line.back() == '\r')
      line.pop_back();
    std::istringstream words(line);
    std::string word;
    words >> word;
    if(!magic) {
      if(word != "ply")
        throw Bad_input(path + ": not a PLY file (its first line is not 'ply')");
      magic = true;
    } else if(word == "format") {
      words >> h.format;
    } else if(word == "element") {
      std::string name;
      words >> name;
      in_vertex = name == "vertex";
      has_vertex = has_vertex || in_vertex;
      h.has_faces = h.has_faces || name == "face";
      if(in_vertex)
        words >> h.vertices;
    } else if(word == "property" && in_vertex) {
      std::string type, name;
      words >> type;
      if(type == "list")
        words >> type >> type;
      words >> name;
      h.vertex_properties.push_back(name);
    } else if(word == "end_header") {
      end = true;
      break;
    }
  }
  if(!magic)
    throw Bad_input(path + ": the file is empty");
  if(!end)
    throw Bad_input(path + ": the PLY header has no 'end_header' line");
  if(h.format != "ascii" && h.format != "binary_little_endian" && h.format != "binary_big_endian")
    throw Bad_input(path + ": the PLY header's format '" + h.format +
                    "' is not ascii, binary_little_endian or binary_big_endian");
  if(!has_vertex)
    throw Bad_input(path + ": the PLY file has no 'vertex' element");
  for(const char* c : {"x", "y", "z"})
    if(std::find(h.vertex_properties.begin(), h.vertex_properties.end(), c) == h.vertex_properties.end())
      throw Bad_input(path + ": the PLY file's vertices have no '" + c + "' property (they need x, y and z)");
  return h;
}

} // namespace internal
} // namespace Shape_analysis
} // namespace CGAL

#endif // CGAL_SHAPE_ANALYSIS_INTERNAL_PLY_HEADER_H
