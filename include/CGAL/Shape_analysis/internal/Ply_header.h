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
#include <cctype>
#include <iterator>
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

// Whether `name` holds a control character (a NUL byte cuts it short where CGAL's reader looks
// properties up by C string: two properties "x\0..." of different types made it call a member of
// a null pointer).
inline bool has_control_character(const std::string& name)
{
  return std::any_of(name.begin(), name.end(), [](char c) {
    const unsigned char u = static_cast<unsigned char>(c);
    return u < 0x20 || u == 0x7f;
  });
}

// The size in bytes of a PLY scalar type (a known one).
inline std::size_t type_size(const std::string& t)
{
  if(t == "char" || t == "uchar" || t == "int8" || t == "uint8")
    return 1;
  if(t == "short" || t == "ushort" || t == "int16" || t == "uint16")
    return 2;
  if(t == "double" || t == "float64")
    return 8;
  return 4;
}

// What is wrong with the type of vertex property `name` for CGAL's reader, or an empty string.
// It takes coordinates and normals as float or double only (another type made it call a member of
// a null pointer), and x, y, z (nx, ny, nz) of one type (a double x beside a float z: the same).
// `coordinate_type` / `normal_type` hold the first type seen in each group ("float", "double").
inline std::string vertex_property_type_error(const std::string& name, const std::string& type, bool list,
                                              std::string& coordinate_type, std::string& normal_type)
{
  const bool coordinate = name == "x" || name == "y" || name == "z";
  const bool normal = name == "nx" || name == "ny" || name == "nz";
  if(list || !(coordinate || normal))
    return std::string();
  const bool real = type == "float" || type == "double" || type == "float32" || type == "float64";
  if(!real)
    return "the vertex property '" + name + "' is " + type + "; coordinates and normals must be float or double";
  const std::string precision = (type == "float" || type == "float32") ? "float" : "double";
  std::string& first = coordinate ? coordinate_type : normal_type;
  if(first.empty())
    first = precision;
  else if(first != precision)
    return "the vertex property '" + name + "' is " + type + " and another " +
           (coordinate ? "coordinate" : "normal") + " is " + first + "; they must have one type";
  return std::string();
}

// An element of a PLY header: its name, count, and the least bytes of one of its items.
struct Ply_element_size
{
  std::string name;
  double count = 0;
  std::size_t properties = 0;
  double binary_bytes = 0; // the sizes of its properties (a list's count only: it may be empty)
};

// Bad_input unless the vertex element has scalar x, y and z, and the file can hold the items that
// the header announces (CGAL's reader reserves memory for the vertex count first, and loops over
// the items of every element): at least two characters per ASCII property ("0 ") or the
// properties' sizes in binary, and no more items of any element than bytes.
inline void check_elements(const std::string& path, const Ply_header& h,
                           const std::vector<std::string>& vertex_lists, std::ifstream& in,
                           std::size_t header_bytes, const std::vector<Ply_element_size>& elements)
{
  for(const char* c : {"x", "y", "z"}) {
    if(std::find(h.vertex_properties.begin(), h.vertex_properties.end(), c) == h.vertex_properties.end())
      throw Bad_input(path + ": the PLY file's vertices have no '" + c + "' property (they need x, y and z)");
    if(std::find(vertex_lists.begin(), vertex_lists.end(), c) != vertex_lists.end())
      throw Bad_input(path + ": the PLY file's vertex property '" + std::string(c) + "' is a list, not a number");
  }
  in.clear();
  in.seekg(0, std::ios::end);
  const std::streamoff size = in.tellg();
  const double data = size > std::streamoff(header_bytes) ? double(size - std::streamoff(header_bytes)) : 0.0;
  double needed = 0;
  for(const Ply_element_size& e : elements) {
    std::string shown = e.name.substr(0, 24);
    for(char& c : shown)
      if(!std::isprint(static_cast<unsigned char>(c)))
        c = '?';
    const double item = h.format == "ascii" ? 2.0 * double(e.properties) : e.binary_bytes;
    needed += e.count * item;
    if(e.count * item > data || e.count > data)
      throw Bad_input(path + ": the PLY header announces " + std::to_string(std::size_t(e.count)) + " " +
                      (e.name == "vertex" ? std::string("vertices") : "'" + shown + "' elements") +
                      "; the " + std::to_string(std::size_t(data)) + " bytes after the header cannot hold them");
  }
  if(needed > data)
    throw Bad_input(path + ": the PLY header's elements need at least " + std::to_string(std::size_t(needed)) +
                    " bytes; the file has " + std::to_string(std::size_t(data)) + " after the header");
}

// The header of the PLY file `path`; Bad_input, its message starting with `path`, when the file
// does not start with "ply", has no "end_header" within its first 64 KiB, a line that is not a
// PLY header line, a format other than ascii / binary_little_endian / binary_big_endian (or two
// formats), an element given twice or with a count that is not a whole number, a property of an
// unknown type, outside an element or given twice in an element, or a vertex element without
// scalar x, y and z properties of one type, float or double (nx, ny, nz too, when present), or
// with more items than the file can hold. (CGAL's reader trusts the header: two properties
// named x of different types, an integer y, or a double x beside a float z made it call a member
// of a null pointer; a count of 10^9 in a small file made it reserve gigabytes.)
inline Ply_header read_ply_header(const std::string& path)
{
  std::ifstream in(path, std::ios::binary);
  if(!in)
    throw Bad_input(path + ": cannot open the file for reading");
  static const char* const types[] = {"char",  "uchar", "short",  "ushort", "int",    "uint",
                                      "float", "double", "int8",  "uint8",  "int16",  "uint16",
                                      "int32", "uint32", "float32", "float64"};
  const auto is_type = [&](const std::string& t) {
    return std::find_if(std::begin(types), std::end(types), [&](const char* x) { return t == x; }) != std::end(types);
  };
  Ply_header h;
  std::string line;
  std::size_t read = 0, number = 0;
  bool magic = false, end = false, in_vertex = false, has_vertex = false;
  std::vector<std::string> properties, vertex_lists;
  std::string coordinate_type, normal_type; // float or double, once seen
  std::vector<Ply_element_size> elements;
  while(std::getline(in, line)) {
    ++number;
    read += line.size() + 1;
    if(read > 65536)
      break;
    if(!line.empty() && line.back() == '\r')
      line.pop_back();
    std::istringstream words(line);
    std::string word, extra;
    words >> word;
    const auto bad = [&](const std::string& what) {
      return Bad_input(path + ": PLY header line " + std::to_string(number) + ": " + what);
    };
    if(!magic) {
      if(word != "ply")
        throw Bad_input(path + ": not a PLY file (its first line is not 'ply')");
      magic = true;
    } else if(word == "format") {
      if(!h.format.empty())
        throw bad("a second format");
      words >> h.format;
    } else if(word == "element") {
      std::string name, count;
      words >> name >> count;
      const bool whole = !count.empty() && count.find_first_not_of("0123456789") == std::string::npos && count.size() < 19;
      if(name.empty() || !whole || (words >> extra) || has_control_character(name))
        throw bad("expected 'element NAME COUNT' (a name of printable characters)");
      if(std::any_of(elements.begin(), elements.end(), [&](const Ply_element_size& e) { return e.name == name; }))
        throw bad("a second element '" + name + "'");
      const unsigned long long items = std::stoull(count);
      elements.push_back(Ply_element_size{name, double(items), 0, 0.0});
      properties.clear();
      in_vertex = name == "vertex";
      has_vertex = has_vertex || in_vertex;
      h.has_faces = h.has_faces || name == "face";
      if(in_vertex)
        h.vertices = std::size_t(items);
    } else if(word == "property") {
      if(elements.empty())
        throw bad("a property outside any element");
      std::string type, name, count_type;
      words >> type;
      const bool list = type == "list";
      if(list)
        words >> count_type >> type;
      words >> name;
      if(name.empty() || (words >> extra) || !is_type(type) || (list && !is_type(count_type)) ||
         has_control_character(name))
        throw bad("expected 'property TYPE NAME' or 'property list TYPE TYPE NAME' with PLY types "
                  "(a name of printable characters)");
      if(std::find(properties.begin(), properties.end(), name) != properties.end())
        throw bad("a second property '" + name + "' in the element '" + elements.back().name + "'");
      properties.push_back(name);
      elements.back().properties += 1;
      elements.back().binary_bytes += double(type_size(list ? count_type : type));
      if(in_vertex) {
        h.vertex_properties.push_back(name);
        if(list)
          vertex_lists.push_back(name);
        const std::string why = vertex_property_type_error(name, type, list, coordinate_type, normal_type);
        if(!why.empty())
          throw bad(why);
      }
    } else if(word == "end_header") {
      end = true;
      break;
    } else if(word != "comment" && word != "obj_info" && !word.empty()) {
      throw bad("'" + word + "' is not a PLY header keyword");
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
  check_elements(path, h, vertex_lists, in, read, elements);
  return h;
}

} // namespace internal
} // namespace Shape_analysis
} // namespace CGAL

#endif // CGAL_SHAPE_ANALYSIS_INTERNAL_PLY_HEADER_H
