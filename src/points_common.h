// Copyright (c) 2026 CGAL Global Shape Analysis contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef SHAPE_ANALYSIS_POINTS_COMMON_H
#define SHAPE_ANALYSIS_POINTS_COMMON_H

// What the `points segment|recognize|train|evaluate` subcommands share: locations files, scans
// read in their own coordinates, objects.ply, the names of the methods.

#include "cli_common.h"

#include <CGAL/Point_set_3.h>
#include <CGAL/Point_set_object_recognition/read_point_set.h>
#include <CGAL/Point_set_object_recognition/segment_objects.h>

#include <Shape_analysis_support/Urban_scan.h>

#include <array>
#include <map>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

namespace shape_analysis_cli {

namespace PSOR = CGAL::Point_set_object_recognition;

// A location of locations.csv; z is NaN when the file leaves it empty.
typedef std::array<double, 3> Location;

std::string trim(const std::string& s);
// The trimmed cells of a CSV line (a trailing comma gives an empty last cell).
std::vector<std::string> csv_cells(const std::string& line);
// Reads the next line of a CSV file that is not blank, as its cells (`csv_cells()`; a UTF-8 byte
// order mark on the first line left out); `number`: its line number. False at the end.
bool next_csv_row(std::istream& in, std::size_t& number, std::vector<std::string>& cells);

// A locations.csv: per row its location and, when the file has those columns, its label (a
// class name, or `background`) and confidence (NaN when absent).
struct Locations_file
{
  std::vector<Location> locations;
  std::vector<std::string> labels;
  std::vector<double> confidences;
  bool labelled = false; // the file has the column `label`
};

// locations.csv: a header line `x,y,z` or `x,y,z,label,confidence`, then one location per line
// (z may be empty). Throws Cli_error on anything else.
Locations_file read_locations_file(const std::string& path);
std::vector<Location> read_locations(const std::string& path);

// The segmentation method of a command-line name (all, cc, mincut, mincut-auto) and back.
PSOR::Segmentation_method segmentation_method(const std::string& name);
std::string segmentation_method_name(PSOR::Segmentation_method m);
std::string localization_method_name(PSOR::Localization_method m);

// The report's "objects": per object its location, points, radius, cut and seconds.
Json objects_report(const std::vector<std::array<double, 3>>& locations, const std::vector<PSOR::Object_segmentation>& objects);

// Reads a scan in the file's coordinates; refuses an empty one and one that already has the
// properties objects.ply adds. `read_seconds`: the time it took.
PSOR::Point_set_read_result read_scan_to_segment(const std::string& input, CGAL::Point_set_3<Point_3>& points,
                                                 double& read_seconds);

// Stages the segmented points (objects_output.cpp), PLY or LAS by the extension of `path`: the
// input's points in input order with their properties, 'object' (per point its location's row, -1
// for none), 'ground' (1 for ground), with `label` (not empty) 'label' (per point its object's
// class index, -1 for none; an input's own integer 'label' becomes 'input_label') and, unless the
// input has colours, colours by class or by object (grey for none). PLY: `comment` adds header
// comment lines. LAS (1.4, point format 7, millimetres): 'object', 'ground', 'label' as extra bytes,
// the classification 2 for the ground, 64 + class for the points of classified objects (named
// after `class_names` in the Classification Lookup record), 1 for the others; the input's
// classification becomes 'input_classification'.
void stage_objects_file(Output_files& outputs, const std::string& path, const std::string& input,
                        const CGAL::Point_set_3<Point_3>& points, const std::vector<int>& object,
                        const std::vector<char>& ground, const std::string& command,
                        const std::vector<int>& label = {}, const std::string& comment = "",
                        const std::vector<std::string>& class_names = {},
                        const std::optional<PSOR::Las_georeference>& georeference = std::nullopt);
// stage_objects_file() of the points in an object only (`object` >= 0), in order.
void stage_object_points_file(Output_files& outputs, const std::string& path, const std::string& input,
                              const CGAL::Point_set_3<Point_3>& points, const std::vector<int>& object,
                              const std::string& command,
                              const std::vector<int>& label, const std::string& comment,
                              const std::vector<std::string>& class_names);
// The points that stage_objects_file() writes as LAS (write_las_point_set() of them with
// `names`, the class names of the Classification Lookup record).
CGAL::Point_set_3<Point_3> objects_las_points(const std::string& input, const CGAL::Point_set_3<Point_3>& points,
                                              const std::vector<int>& object, const std::vector<char>& ground,
                                              const std::vector<int>& label, const std::vector<std::string>& class_names,
                                              std::vector<std::pair<unsigned, std::string>>& names);

// What stage_objects_file() writes, into `out` (LAS when `las`, else PLY).
void write_objects_file(std::ostream& out, bool las, const std::string& input, const CGAL::Point_set_3<Point_3>& points,
                        const std::vector<int>& object, const std::vector<char>& ground, const std::string& command,
                        const std::vector<int>& label = {}, const std::string& comment = "",
                        const std::vector<std::string>& class_names = {},
                        const std::optional<PSOR::Las_georeference>& georeference = std::nullopt);

// The points of `points generate`: x y z, instance, label, intensity, colours by class
// (scene_segments.cpp).
CGAL::Point_set_3<Point_3> scan_points(const CGAL::Shape_analysis_support::Urban_scan& scan);

// `points generate` of many points (scene_segments.cpp): the street cut into segments of about
// `segment_points` points, each a street of its own (its own seed) placed after the previous one
// along x, generated, scanned and written to `out` (binary PLY with `comment`, or LAS 1.4) one at
// a time; the instances numbered on from one segment to the next. What was generated:
struct Segmented_scene
{
  std::size_t segments = 0, number_of_points = 0, object_points = 0, triangles = 0;
  std::vector<CGAL::Shape_analysis_support::Urban_object> objects; // moved and renumbered
  std::map<int, std::size_t> scanned;                               // per instance, its points
};
Segmented_scene generate_in_segments(const CGAL::Shape_analysis_support::Urban_scene_options& so, std::ostream& out,
                                     bool las, const std::string& comment, std::size_t segment_points,
                                     Progress& progress);
// The same, each segment staged in `outputs` as a file of its own instead, `output`'s name with
// _0000, _0001... before its extension (LAS files with one offset, so that their points one after
// the other are those of the single file).
Segmented_scene generate_segment_files(const CGAL::Shape_analysis_support::Urban_scene_options& so,
                                       std::size_t segment_points, Progress& progress, Output_files& outputs,
                                       const std::string& output, const std::string& comment);

// The horizontal box of a scan: xmin, ymin, xmax, ymax (points_train_command.cpp).
std::array<double, 4> horizontal_bbox(const CGAL::Point_set_3<Point_3>& points);

// Registers `points recognize` (points_recognize_command.cpp) and, through the next, `points train`.
void add_points_recognize_commands(CLI::App* points, std::function<int()>& run);
// Registers `points train` (points_train_command.cpp).
void add_points_train_command(CLI::App* points, std::function<int()>& run);

// Prints and returns (JSON) the recognition precision and recall per class of the labelled
// locations of `locations_path` against the labelled objects of `labels_path` (a match within
// `radius` metres, horizontally), as the thesis' table 4.5 (points_recognize_command.cpp).
Json evaluate_recognition_files(const std::string& labels_path, const std::string& locations_path, double radius,
                                double minimum_points);

} // namespace shape_analysis_cli

#endif // SHAPE_ANALYSIS_POINTS_COMMON_H
