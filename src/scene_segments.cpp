// Copyright (c) 2026 CGAL Global Shape Analysis contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// `points generate` of more points than memory should hold (points_common.h,
// generate_in_segments()): the street generated, scanned and written one segment at a time.

#include "points_common.h"

#include <CGAL/Point_set_3/IO/PLY.h>
#include <CGAL/Point_set_object_recognition/write_point_set.h>

#include <Shape_analysis_support/Urban_scan.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

namespace shape_analysis_cli {

namespace {

namespace SAS = CGAL::Shape_analysis_support;

// The scan of a segment moved by `shift` along x, its instances made unique by `first_id`.
void move_segment(SAS::Urban_scan& scan, double shift, int first_id)
{
  for(SAS::Urban_scan_point& p : scan.points) {
    p.x += shift;
    if(p.instance > 0)
      p.instance += first_id;
  }
}

} // namespace

CGAL::Point_set_3<Point_3> scan_points(const SAS::Urban_scan& scan)
{
  CGAL::Point_set_3<Point_3> ps;
  SAS::fill_point_set(scan, ps, true);
  // Colours by class, so that MeshLab shows them; CloudCompare also shows the scalar fields.
  auto red = ps.add_property_map<unsigned char>("red", 0).first;
  auto green = ps.add_property_map<unsigned char>("green", 0).first;
  auto blue = ps.add_property_map<unsigned char>("blue", 0).first;
  auto label = ps.property_map<int>("label").first;
  for(auto i : ps) {
    const auto c = label_colour(std::size_t(label[i]));
    red[i] = c[0], green[i] = c[1], blue[i] = c[2];
  }
  return ps;
}

namespace {

// The number of segments for `points` points in segments of `segment_points`.
std::size_t segments_for(std::size_t points, std::size_t segment_points)
{
  return (points + segment_points - 1) / segment_points;
}

// The LAS offset of generated scans: below any point (x from 0, y and z above -1 km).
PSOR::Las_georeference generated_scan_georeference()
{
  PSOR::Las_georeference g;
  g.offset = {{0, -1000, -1000}};
  return g;
}

// Segment s of the street (a street of its own, moved after the previous ones along x), its
// objects and counts added to `result`: its scanned points.
CGAL::Point_set_3<Point_3> scan_segment(const SAS::Urban_scene_options& so, std::size_t s, Segmented_scene& result,
                                        Progress& progress)
{
  const std::size_t segments = result.segments;
  const double length = so.street_length / double(segments);
  SAS::Urban_scene_options o = so;
  o.street_length = length;
  o.target_points = so.target_points / segments + (s + 1 == segments ? so.target_points % segments : 0);
  o.seed = so.seed * 1000003 + s; // each segment a street of its own
  progress.stage("segment " + std::to_string(s + 1) + " of " + std::to_string(segments) + ": " +
                 std::to_string(int(length)) + " m, " + std::to_string(o.target_points) + " points");
  const SAS::Urban_scene scene = SAS::make_urban_scene(o);
  SAS::Urban_scan scan = SAS::scan_urban_scene(scene, o);
  const double shift = double(s) * length;
  const int first_id = int(result.objects.size());
  for(SAS::Urban_object b : scene.objects) { // moved and renumbered as their points
    b.x += shift;
    b.id += first_id;
    b.bbox = CGAL::Bbox_3(b.bbox.xmin() + shift, b.bbox.ymin(), b.bbox.zmin(), b.bbox.xmax() + shift, b.bbox.ymax(),
                          b.bbox.zmax());
    result.objects.push_back(b);
  }
  for(const SAS::Urban_scan_point& p : scan.points)
    if(p.instance > 0) {
      ++result.object_points;
      ++result.scanned[p.instance + first_id];
    }
  result.triangles += scene.triangles.size();
  move_segment(scan, shift, first_id);
  CGAL::Point_set_3<Point_3> ps = scan_points(scan);
  result.number_of_points += ps.size();
  return ps;
}

} // namespace

Segmented_scene generate_segment_files(const SAS::Urban_scene_options& so, std::size_t segment_points,
                                       Progress& progress, Output_files& outputs, const std::string& output,
                                       const std::string& comment)
{
  Segmented_scene result;
  result.segments = segments_for(so.target_points, segment_points);
  const std::size_t dot = output.size() - lower_extension(output).size();
  std::vector<std::string> names;
  for(std::size_t s = 0; s < result.segments; ++s) {
    std::string number = std::to_string(s);
    number.insert(0, std::max<std::size_t>(std::to_string(result.segments - 1).size(), 4) - number.size(), '0');
    names.push_back(output.substr(0, dot) + "_" + number + output.substr(dot));
    outputs.add_output(names.back(), "scanned segment", {".ply", ".las"});
  }
  for(std::size_t s = 0; s < result.segments; ++s) {
    const CGAL::Point_set_3<Point_3> ps = scan_segment(so, s, result, progress);
    outputs.stage(names[s], true, [&](std::ostream& out) {
      if(lower_extension(output) == ".las") {
        PSOR::write_las_point_set(out, ps, PSOR::parameters::las_georeference(generated_scan_georeference()));
        return;
      }
      CGAL::IO::set_mode(out, CGAL::IO::BINARY);
      if(!CGAL::IO::write_PLY(out, ps, comment))
        throw Cli_error("cannot write " + names[s]);
    });
  }
  return result;
}

Segmented_scene generate_in_segments(const SAS::Urban_scene_options& so, std::ostream& out, bool las,
                                     const std::string& comment, std::size_t segment_points_wanted, Progress& progress)
{
  Segmented_scene result;
  result.segments = segments_for(so.target_points, segment_points_wanted);
  // PLY: the header of the first segment, its count left room for the whole's and rewritten at
  // the end. LAS: a header of the right size written at the end (Las_point_set_pieces).
  std::string ply_header;
  std::size_t ply_count_at = 0;
  const std::string room(20, ' ');
  std::unique_ptr<PSOR::Las_point_set_pieces<Point_3>> las_pieces;
  PSOR::Las_point_set_pieces<Point_3>::Summary summary;
  for(std::size_t s = 0; s < result.segments; ++s) {
    const CGAL::Point_set_3<Point_3> ps = scan_segment(so, s, result, progress);
    if(las) {
      if(!las_pieces) {
        las_pieces = std::make_unique<PSOR::Las_point_set_pieces<Point_3>>(
          ps, std::array<double, 3>{{0, 0, 0}}, PSOR::parameters::las_georeference(generated_scan_georeference()));
        out.write(std::string(las_pieces->header({}).size(), '\0').data(), std::streamsize(las_pieces->header({}).size()));
      }
      std::vector<unsigned char> records;
      summary.merge(las_pieces->records(ps, records));
      out.write(reinterpret_cast<const char*>(records.data()), std::streamsize(records.size()));
    } else {
      std::ostringstream bytes;
      CGAL::IO::set_mode(bytes, CGAL::IO::BINARY);
      if(!CGAL::IO::write_PLY(bytes, ps, comment))
        throw Cli_error("cannot write the scan");
      const std::string b = bytes.str();
      const std::size_t end = b.find("end_header\n") + 11;
      if(s == 0) {
        const std::string count = "element vertex " + std::to_string(ps.size());
        ply_count_at = b.find(count) + 15;
        ply_header = b.substr(0, end);
        ply_header.replace(ply_count_at, count.size() - 15, room);
        out << ply_header;
      }
      out.write(b.data() + end, std::streamsize(b.size() - end));
    }
    if(!out)
      throw Cli_error("cannot write the scan (disk full?)");
  }
  if(las) {
    const std::vector<unsigned char> header = las_pieces->header(summary);
    out.seekp(0);
    out.write(reinterpret_cast<const char*>(header.data()), std::streamsize(header.size()));
  } else {
    std::string count = std::to_string(result.number_of_points);
    count.resize(room.size(), ' '); // trailing spaces end the line as PLY readers expect
    out.seekp(std::streamoff(ply_count_at));
    out << count;
  }
  out.seekp(0, std::ios::end);
  return result;
}

} // namespace shape_analysis_cli
