// Copyright (c) 2026 CGAL Global Shape Analysis contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef SHAPE_ANALYSIS_SUPPORT_URBAN_OSM_H
#define SHAPE_ANALYSIS_SUPPORT_URBAN_OSM_H

// The OpenStreetMap extract of a generated street scene (Urban_scene.h), so that tests and
// benchmarks have a street map with ground truth: the scene's local frame is placed in a UTM zone
// at an offset (the scene's point (x, y) is at easting x + offset_x, northing y + offset_y) and
// written as OSM XML with node latitudes and longitudes from GeographicLib.
//
// Ways: the street's centre line (y = 0, from x = -margin to street_length + margin, a node every
// 10 m, highway=residential), a cross street at each end (x = -margin and street_length + margin,
// highway=tertiary, sharing the junction node), a footway on each sidewalk (highway=footway, which
// read_street_map leaves out by default) and each building's footprint (building=yes).
//
// Also write_street_grid_osm: a grid of streets of any size, for benchmarks of the reader.

#if !defined(CGAL_SHAPE_ANALYSIS_USE_OSMIUM)
#error "Urban_osm.h needs GeographicLib: link the target CGAL::Shape_analysis_osm"
#endif

#include <Shape_analysis_support/Urban_scene.h>

#include <CGAL/Shape_analysis/Bad_input.h>

#include <GeographicLib/UTMUPS.hpp>

#include <array>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <ostream>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Shape_analysis_support {

// Writes OSM XML: nodes at points of the local frame, then ways (node index lists and tags).
class Osm_xml_writer
{
public:
  Osm_xml_writer(int utm_zone, bool north, std::array<double, 2> utm_offset)
      : m_zone(utm_zone), m_north(north), m_offset(utm_offset)
  {
    if(utm_zone < 1 || utm_zone > 60)
      throw CGAL::Shape_analysis::Bad_input("Osm_xml_writer: the UTM zone must be from 1 to 60");
  }

  // Adds a node at (x, y) of the local frame; returns its id (1, 2, ...).
  long node(double x, double y)
  {
    double lat = 0, lon = 0;
    GeographicLib::UTMUPS::Reverse(m_zone, m_north, x + m_offset[0], y + m_offset[1], lat, lon);
    m_nodes.push_back({{lat, lon}});
    return long(m_nodes.size());
  }

  // Adds the nodes of a straight line from (xa, ya) to (xb, yb) every `step` metres (at least 2).
  std::vector<long> line(double xa, double ya, double xb, double yb, double step)
  {
    const int n = (std::max)(1, int(std::ceil(std::hypot(xb - xa, yb - ya) / step)));
    std::vector<long> ids;
    for(int i = 0; i <= n; ++i)
      ids.push_back(node(xa + (xb - xa) * i / n, ya + (yb - ya) * i / n));
    return ids;
  }

  void way(std::vector<long> nodes, std::vector<std::pair<std::string, std::string>> tags)
  {
    m_ways.push_back({std::move(nodes), std::move(tags)});
  }

  // Latitudes and longitudes with 7 decimals, as OpenStreetMap stores them (about 1 cm).
  void write(std::ostream& os) const
  {
    os << "<?xml version='1.0' encoding='UTF-8'?>\n"
       << "<osm version=\"0.6\" generator=\"CGAL Shape_analysis_support\">\n";
    char buffer[160];
    for(std::size_t i = 0; i < m_nodes.size(); ++i) {
      std::snprintf(buffer, sizeof(buffer), "  <node id=\"%zu\" version=\"1\" lat=\"%.7f\" lon=\"%.7f\"/>\n", i + 1,
                    m_nodes[i][0], m_nodes[i][1]);
      os << buffer;
    }
    for(std::size_t w = 0; w < m_ways.size(); ++w) {
      os << "  <way id=\"" << w + 1 << "\" version=\"1\">\n";
      for(long id : m_ways[w].first)
        os << "    <nd ref=\"" << id << "\"/>\n";
      for(const auto& t : m_ways[w].second)
        os << "    <tag k=\"" << t.first << "\" v=\"" << t.second << "\"/>\n";
      os << "  </way>\n";
    }
    os << "</osm>\n";
  }

private:
  int m_zone;
  bool m_north;
  std::array<double, 2> m_offset;
  std::vector<std::array<double, 2>> m_nodes; // latitude, longitude
  std::vector<std::pair<std::vector<long>, std::vector<std::pair<std::string, std::string>>>> m_ways;
};

// The map of `scene` (see the top of this file) placed at `utm_offset` in zone `utm_zone`.
inline void write_street_osm(std::ostream& os, const Urban_scene& scene, int utm_zone, bool north,
                             std::array<double, 2> utm_offset)
{
  Osm_xml_writer w(utm_zone, north, utm_offset);
  const double x0 = -scene.margin, x1 = scene.street_length + scene.margin, cross = scene.back_y + 40;
  const std::vector<long> main = w.line(x0, 0, x1, 0, 10.);
  w.way(main, {{"highway", "residential"}, {"name", "Generated Street"}});
  for(int end = 0; end < 2; ++end) {
    const double x = end ? x1 : x0;
    std::vector<long> south = w.line(x, -cross, x, 0, 10.), north_part = w.line(x, 0, x, cross, 10.);
    south.back() = end ? main.back() : main.front(); // the junction is the main street's node
    south.insert(south.end(), north_part.begin() + 1, north_part.end());
    w.way(south, {{"highway", "tertiary"}, {"name", end ? "East Cross Street" : "West Cross Street"}});
  }
  const double sidewalk = 0.5 * (scene.road_half_width + scene.facade_y);
  for(double y : {-sidewalk, sidewalk})
    w.way(w.line(0, y, scene.street_length, y, 20.), {{"highway", "footway"}, {"footway", "sidewalk"}});
  for(const CGAL::Bbox_3& b : scene.buildings) {
    std::vector<long> ring{w.node(b.xmin(), b.ymin()), w.node(b.xmax(), b.ymin()), w.node(b.xmax(), b.ymax()),
                           w.node(b.xmin(), b.ymax())};
    ring.push_back(ring.front());
    w.way(ring, {{"building", "yes"}});
  }
  w.write(os);
}

// A grid of `rows` + `columns` straight streets `spacing` metres apart (from (0, 0) to
// ((columns - 1) spacing, (rows - 1) spacing)), a node every `node_spacing` metres, each street
// one way, tagged highway=residential; a building between each four streets.
inline void write_street_grid_osm(std::ostream& os, int rows, int columns, double spacing, double node_spacing,
                                  int utm_zone, bool north, std::array<double, 2> utm_offset)
{
  Osm_xml_writer w(utm_zone, north, utm_offset);
  const double width = (columns - 1) * spacing, height = (rows - 1) * spacing;
  for(int r = 0; r < rows; ++r)
    w.way(w.line(0, r * spacing, width, r * spacing, node_spacing), {{"highway", "residential"}});
  for(int c = 0; c < columns; ++c)
    w.way(w.line(c * spacing, 0, c * spacing, height, node_spacing), {{"highway", "residential"}});
  for(int r = 0; r + 1 < rows; ++r)
    for(int c = 0; c + 1 < columns; ++c) {
      const double xa = c * spacing + 15, ya = r * spacing + 15, xb = (c + 1) * spacing - 15, yb = (r + 1) * spacing - 15;
      std::vector<long> ring{w.node(xa, ya), w.node(xb, ya), w.node(xb, yb), w.node(xa, yb)};
      ring.push_back(ring.front());
      w.way(ring, {{"building", "yes"}});
    }
  w.write(os);
}

// write_street_osm into a file; throws Bad_input when it cannot be written.
inline void write_street_osm(const std::string& path, const Urban_scene& scene, int utm_zone, bool north,
                             std::array<double, 2> utm_offset)
{
  std::ofstream out(path);
  if(!out)
    throw CGAL::Shape_analysis::Bad_input(path + ": cannot open the file for writing");
  write_street_osm(out, scene, utm_zone, north, utm_offset);
  if(!out.flush())
    throw CGAL::Shape_analysis::Bad_input(path + ": cannot write the file");
}

} // namespace Shape_analysis_support
} // namespace CGAL

#endif // SHAPE_ANALYSIS_SUPPORT_URBAN_OSM_H
