// Copyright (c) 2026 CGAL Global Shape Analysis contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The segmented points of 'points segment' and 'points recognize': the input's points with their
// objects, ground and classes, as PLY or as LAS.

#include "points_common.h"

#include <CGAL/Point_set_3.h>
#include <CGAL/Point_set_3/IO/PLY.h>
#include <CGAL/Point_set_object_recognition/Point_set_file_reader.h>
#include <CGAL/Point_set_object_recognition/write_point_set.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <string>
#include <vector>

namespace shape_analysis_cli {

namespace {

namespace PSOR = CGAL::Point_set_object_recognition;
typedef CGAL::Point_set_3<Point_3> Point_set;

// Renames the integer property `from` of `ps`, if any, to `to` (as int); throws Cli_error when
// `from` is a property of another type or `to` exists.
void move_property_to(CGAL::Point_set_3<Point_3>& ps, const std::string& from, const std::string& to)
{
  const std::vector<std::string> names = ps.properties();
  if(std::find(names.begin(), names.end(), from) == names.end())
    return;
  std::vector<int> values;
  const auto take = [&](auto tag) {
    typedef decltype(tag) T;
    if(values.empty() && ps.template has_property_map<T>(from)) {
      auto map = ps.template property_map<T>(from).first;
      for(auto i : ps)
        values.push_back(int(map[i]));
      ps.remove_property_map(map);
    }
  };
  take(int()), take((unsigned char)0), take((unsigned int)0), take(short()), take((unsigned short)0), take((signed char)0);
  if(values.size() != ps.size())
    throw Cli_error("the input's '" + from + "' property is not an integer property");
  auto added = ps.template add_property_map<int>(to, -1);
  if(!added.second)
    throw Cli_error("the input has both '" + from + "' and '" + to + "' properties");
  std::size_t k = 0;
  for(auto i : ps)
    added.first[i] = values[k++];
}

// The LAS classification codes of the classes: 64 (the first code the specification leaves to
// users) and up.
constexpr int first_class_code = 64;

// The input's points with 'object', 'ground', 'label' (when `label` is not empty; an input's own
// integer 'label' becomes 'input_label') and, unless the input has colours, colours by class or by
// object (grey for none): `colour_bytes` 1 for 8-bit colours (PLY), 2 for 16-bit ones (LAS).
Point_set objects_point_set(const std::string& input, const Point_set& points, const std::vector<int>& object,
                            const std::vector<char>& ground, const std::vector<int>& label, int colour_bytes)
{
  Point_set result = points;
  auto object_map = result.add_property_map<int>("object", -1);
  auto ground_map = result.add_property_map<unsigned char>("ground", 0);
  if(!object_map.second || !ground_map.second)
    throw Cli_error(input + " already has an 'object' or a 'ground' property");
  Point_set::Property_map<int> label_map;
  if(!label.empty()) {
    move_property_to(result, "label", "input_label"); // e.g. the true classes of a generated scan
    auto added = result.add_property_map<int>("label", -1);
    if(!added.second)
      throw Cli_error(input + " already has a 'label' property");
    label_map = added.first;
  }
  const auto has_colour = [&](auto tag) {
    typedef decltype(tag) T;
    return result.has_property_map<T>("red") || result.has_property_map<T>("green") || result.has_property_map<T>("blue");
  };
  const bool coloured = !has_colour((unsigned char)0) && !has_colour((unsigned short)0);
  const unsigned scale = colour_bytes == 2 ? 257 : 1;
  std::array<Point_set::Property_map<unsigned char>, 3> rgb8;
  std::array<Point_set::Property_map<unsigned short>, 3> rgb16;
  const char* channel[3] = {"red", "green", "blue"};
  for(int c = 0; c < 3 && coloured; ++c)
    if(colour_bytes == 2)
      rgb16[c] = result.add_property_map<unsigned short>(channel[c], 0).first;
    else
      rgb8[c] = result.add_property_map<unsigned char>(channel[c], 0).first;
  std::size_t k = 0;
  for(auto i : result) {
    object_map.first[i] = object[k];
    ground_map.first[i] = ground[k] ? 1 : 0;
    if(!label.empty())
      label_map[i] = label[k];
    if(coloured) {
      const int by = label.empty() ? object[k] : label[k]; // colours by class when there are classes
      const auto rgb = by < 0 ? std::array<unsigned char, 3>{{160, 160, 160}} : label_colour(std::size_t(by) + 1);
      for(int c = 0; c < 3; ++c)
        if(colour_bytes == 2)
          rgb16[c][i] = static_cast<unsigned short>(rgb[c] * scale);
        else
          rgb8[c][i] = rgb[c];
    }
    ++k;
  }
  return result;
}

// Makes `result` (objects_point_set()) the points of a LAS 1.4 file of write_las_point_set():
// the classification 2 for the ground, 64 + the class for the points of a classified object (with
// `class_names` in the Classification Lookup record, returned as (code, name)), 1 for the others;
// an input classification kept as 'input_classification'; 8-bit colours widened to 16 bits.
std::vector<std::pair<unsigned, std::string>> make_objects_las(Point_set& result, const std::vector<std::string>& class_names)
{
  move_property_to(result, "classification", "input_classification");
  for(const char* c : {"red", "green", "blue"})
    if(result.has_property_map<unsigned char>(c)) {
      auto narrow = result.property_map<unsigned char>(c).first;
      std::vector<unsigned short> values;
      for(auto i : result)
        values.push_back(static_cast<unsigned short>(narrow[i] * 257));
      result.remove_property_map(narrow);
      auto wide = result.add_property_map<unsigned short>(c, 0).first;
      std::size_t k = 0;
      for(auto i : result)
        wide[i] = values[k++];
    }
  const bool named = !class_names.empty() && first_class_code + class_names.size() <= 256;
  auto classification = result.add_property_map<unsigned char>("classification", 1).first;
  const auto ground = result.property_map<unsigned char>("ground").first;
  const auto label = result.property_map<int>("label");
  for(auto i : result) {
    if(ground[i])
      classification[i] = 2;
    else if(named && label.second && label.first[i] >= 0)
      classification[i] = static_cast<unsigned char>(first_class_code + label.first[i]);
  }
  std::vector<std::pair<unsigned, std::string>> names;
  for(std::size_t c = 0; named && c < class_names.size(); ++c)
    names.emplace_back(unsigned(first_class_code + c), class_names[c]);
  return names;
}

// The scale, offset and CRS records of the scan `input` when it is a LAS file (else none).
std::optional<PSOR::Las_georeference> input_georeference(const std::string& input)
{
  if(lower_extension(input) != ".las")
    return std::nullopt;
  try {
    return PSOR::Point_set_file_reader(input).las_georeference();
  } catch(const CGAL::Shape_analysis::Bad_input&) {
    return std::nullopt;
  }
}

// Writes `result` (objects_point_set()) as LAS 1.4 (make_objects_las(), write_las_point_set()),
// with `georeference`, else that of the scan `input` when it is a LAS file.
void write_objects_las(std::ostream& out, Point_set& result, const std::string& input,
                       const std::vector<std::string>& class_names,
                       const std::optional<PSOR::Las_georeference>& georeference)
{
  const auto names = make_objects_las(result, class_names);
  try {
    PSOR::write_las_point_set(
      out, result, PSOR::parameters::class_names(names).las_georeference(georeference ? georeference : input_georeference(input)));
  } catch(const CGAL::Shape_analysis::Bad_input& e) {
    throw Cli_error(e.what());
  }
}

} // namespace

void write_objects_file(std::ostream& out, bool las, const std::string& input, const Point_set& points,
                        const std::vector<int>& object, const std::vector<char>& ground, const std::string& command,
                        const std::vector<int>& label, const std::string& comment,
                        const std::vector<std::string>& class_names,
                        const std::optional<PSOR::Las_georeference>& georeference)
{
  Point_set result = objects_point_set(input, points, object, ground, label, las ? 2 : 1);
  if(las)
    return write_objects_las(out, result, input, class_names, georeference);
  CGAL::IO::set_mode(out, CGAL::IO::BINARY);
  if(!CGAL::IO::write_PLY(out, result, "written by shape_analysis " + command + " (CGAL Global Shape Analysis)" +
                                          (comment.empty() ? std::string() : "\n" + comment)))
    throw Cli_error("cannot write the segmented points");
}

Point_set objects_las_points(const std::string& input, const Point_set& points, const std::vector<int>& object,
                             const std::vector<char>& ground, const std::vector<int>& label,
                             const std::vector<std::string>& class_names,
                             std::vector<std::pair<unsigned, std::string>>& names)
{
  Point_set result = objects_point_set(input, points, object, ground, label, 2);
  names = make_objects_las(result, class_names);
  return result;
}

void stage_objects_file(Output_files& outputs, const std::string& path, const std::string& input,
                        const Point_set& points, const std::vector<int>& object, const std::vector<char>& ground,
                        const std::string& command, const std::vector<int>& label, const std::string& comment,
                        const std::vector<std::string>& class_names,
                        const std::optional<PSOR::Las_georeference>& georeference)
{
  const bool las = lower_extension(path) == ".las";
  outputs.stage(path, true, [&](std::ostream& out) {
    write_objects_file(out, las, input, points, object, ground, command, label, comment, class_names, georeference);
  });
}

void stage_object_points_file(Output_files& outputs, const std::string& path, const std::string& input,
                              const Point_set& points, const std::vector<int>& object, const std::string& command,
                              const std::vector<int>& label, const std::string& comment,
                              const std::vector<std::string>& class_names)
{
  Point_set kept;
  kept.copy_properties(points);
  std::vector<int> kept_object, kept_label;
  std::size_t k = 0;
  for(Point_set::Index i : points) {
    if(object[k] >= 0) {
      kept.insert(points, i);
      kept_object.push_back(object[k]);
      if(!label.empty())
        kept_label.push_back(label[k]);
    }
    ++k;
  }
  const std::vector<char> kept_ground(kept_object.size(), 0); // a point in an object is not ground
  // A LAS output has the offset of the whole scan (or its georeference), as out of core.
  std::optional<PSOR::Las_georeference> georeference = input_georeference(input);
  if(!georeference && !points.empty()) {
    georeference.emplace();
    for(int c = 0; c < 3; ++c) {
      double lowest = points.point(*points.begin())[c];
      for(Point_set::Index i : points)
        lowest = std::min(lowest, points.point(i)[c]);
      georeference->offset[std::size_t(c)] = std::floor(lowest / 100) * 100;
    }
  }
  stage_objects_file(outputs, path, input, kept, kept_object, kept_ground, command, kept_label, comment, class_names,
                     georeference);
}

} // namespace shape_analysis_cli
