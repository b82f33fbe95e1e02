// Copyright (c) 2026 CGAL Global Shape Analysis contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_POINT_SET_OBJECT_RECOGNITION_READ_STREET_MAP_H
#define CGAL_POINT_SET_OBJECT_RECOGNITION_READ_STREET_MAP_H

/// \file read_street_map.h
/// The streets of an OpenStreetMap extract in the coordinates of a scan (libosmium and
/// GeographicLib: link `CGAL::Shape_analysis_osm`).

#if !defined(CGAL_SHAPE_ANALYSIS_USE_OSMIUM) && !defined(DOXYGEN_RUNNING)
#error "read_street_map.h needs libosmium, expat, zlib and GeographicLib: link the target CGAL::Shape_analysis_osm (Debian libosmium2-dev, libexpat1-dev, zlib1g-dev, libgeographiclib-dev)"
#endif

#include <CGAL/Point_set_object_recognition/Street_map.h>
#include <CGAL/Shape_analysis/Bad_input.h>

#include <GeographicLib/UTMUPS.hpp>

#include <osmium/handler.hpp>
#include <osmium/handler/node_locations_for_ways.hpp>
#include <osmium/index/map/flex_mem.hpp>
#include <osmium/io/gzip_compression.hpp>
#include <osmium/io/pbf_input.hpp>
#include <osmium/io/xml_input.hpp>
#include <osmium/osm/way.hpp>
#include <osmium/visitor.hpp>

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <exception>
#include <fstream>
#include <string>
#include <system_error>
#include <vector>

namespace CGAL {
namespace Point_set_object_recognition {

/*!
\ingroup PkgPointSetObjectRecognitionRef
A UTM zone of the WGS 84 datum (`parse_utm_crs()`).
*/
struct Utm_zone
{
  int zone = 0;      ///< the zone number, 1 to 60
  bool north = true; ///< whether the northern hemisphere's coordinates (EPSG:326zz) or the southern's (EPSG:327zz)
};

/*!
\ingroup PkgPointSetObjectRecognitionRef
Reads a coordinate reference system given as the EPSG code of a WGS 84 UTM zone.

Accepted, in any case and with spaces around: `EPSG:326zz` (zone zz, north) and `EPSG:327zz`
(zone zz, south) with zz from 01 to 60, and the bare codes `326zz` and `327zz`. Anything else
(`EPSG:4326`, the polar `EPSG:32661`, `UTM18`...) is refused.

\param crs the code
\returns the zone and the hemisphere
\throws CGAL::Shape_analysis::Bad_input when `crs` is not such a code (the message says what is
        accepted)
*/
inline Utm_zone parse_utm_crs(const std::string& crs)
{
  std::string s;
  for(char c : crs)
    if(!std::isspace(static_cast<unsigned char>(c)))
      s += static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  if(s.compare(0, 5, "EPSG:") == 0)
    s = s.substr(5);
  Utm_zone z;
  const bool utm = s.size() == 5 && s.find_first_not_of("0123456789") == std::string::npos &&
                   (s.compare(0, 3, "326") == 0 || s.compare(0, 3, "327") == 0);
  if(utm) {
    z.zone = std::stoi(s.substr(3));
    z.north = s[2] == '6';
  }
  if(z.zone < 1 || z.zone > 60)
    throw Bad_input("the CRS '" + crs + "' is not a UTM zone of WGS 84: give EPSG:326zz (zone zz, north) or "
                    "EPSG:327zz (zone zz, south), zz from 01 to 60, for example EPSG:32618");
  return z;
}

/*!
\ingroup PkgPointSetObjectRecognitionRef
What `read_street_map()` read, besides the streets.
*/
struct Street_map_read_statistics
{
  std::size_t ways = 0;           ///< the ways of the file
  std::size_t highway_ways = 0;   ///< the ways tagged `highway`
  std::size_t path_ways = 0;      ///< of these, the ways left out as paths or areas (see `read_street_map()`)
  std::size_t incomplete_ways = 0; ///< the streets that refer to nodes missing from the file
  std::size_t skipped_ways = 0;   ///< of these, the ones without two consecutive nodes in the file (left out)
  std::size_t streets = 0;        ///< the polylines of the map
};

/// \cond SKIP_IN_MANUAL
namespace internal {

// `highway` values that are not streets: paths, mapped sidewalks, areas and roads not built.
inline bool is_path_highway(const char* v)
{
  static const char* const paths[] = {"footway", "path", "cycleway", "bridleway", "steps", "pedestrian",
                                      "corridor", "elevator", "platform", "proposed", "construction",
                                      "abandoned", "disused", "razed", "bus_stop", "services", "rest_area",
                                      "via_ferrata", "escape", "raceway"};
  for(const char* p : paths)
    if(std::string(v) == p)
      return true;
  return false;
}

// Collects the streets of the ways whose nodes NodeLocationsForWays located.
class Street_collector : public osmium::handler::Handler
{
public:
  Street_collector(Utm_zone zone, const std::array<double, 3>& origin, bool include_paths)
      : m_zone(zone), m_origin(origin), m_include_paths(include_paths)
  {}

  void way(const osmium::Way& way)
  {
    ++statistics.ways;
    const char* highway = way.tags().get_value_by_key("highway");
    if(!highway)
      return;
    ++statistics.highway_ways;
    const char* area = way.tags().get_value_by_key("area");
    if(!m_include_paths && (is_path_highway(highway) || (area && std::string(area) == "yes"))) {
      ++statistics.path_ways;
      return;
    }
    // The runs of consecutive located nodes (an extract cuts the ways that leave it).
    Street_map::Street run;
    run.highway = highway;
    bool incomplete = false;
    std::size_t kept = 0;
    const auto flush = [&]() {
      if(run.points.size() >= 2)
        streets.push_back(run), ++kept;
      run.points.clear();
    };
    for(const osmium::NodeRef& n : way.nodes()) {
      if(!n.location().valid()) {
        incomplete = true;
        flush();
        continue;
      }
      run.points.push_back(project(n.location().lat(), n.location().lon()));
    }
    flush();
    statistics.incomplete_ways += incomplete ? 1 : 0;
    statistics.skipped_ways += kept == 0 ? 1 : 0;
  }

  std::vector<Street_map::Street> streets;
  Street_map_read_statistics statistics;

private:
  // UTM in the zone given (GeographicLib extends it beyond the zone's 6 degrees), in the
  // hemisphere given (continued across the equator), minus the local origin.
  std::array<double, 2> project(double lat, double lon) const
  {
    int zone = 0;
    bool north = true;
    double x = 0, y = 0;
    try {
      GeographicLib::UTMUPS::Forward(lat, lon, zone, north, x, y, m_zone.zone);
      if(north != m_zone.north)
        GeographicLib::UTMUPS::Transfer(zone, north, x, y, m_zone.zone, m_zone.north, x, y, zone);
    } catch(const GeographicLib::GeographicErr& e) {
      throw Bad_input("a node at latitude " + std::to_string(lat) + ", longitude " + std::to_string(lon) +
                      " cannot be projected into UTM zone " + std::to_string(m_zone.zone) + ": " + e.what());
    }
    return {{x - m_origin[0], y - m_origin[1]}};
  }

  Utm_zone m_zone;
  std::array<double, 3> m_origin;
  bool m_include_paths;
};

// The osmium format of a file, from its name: PBF, gzipped XML or XML.
inline std::string osm_file_format(const std::string& path)
{
  std::string lower;
  for(char c : path)
    lower += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  const auto ends = [&](const std::string& e) {
    return lower.size() >= e.size() && lower.compare(lower.size() - e.size(), e.size(), e) == 0;
  };
  if(ends(".pbf"))
    return "pbf";
  if(ends(".gz"))
    return "osm.gz";
  if(ends(".bz2") || ends(".o5m") || ends(".o5c") || ends(".opl"))
    throw Bad_input(path + ": this OpenStreetMap format is not read (.osm, .osm.gz and .osm.pbf are); "
                          "convert it with osmium cat");
  return "osm";
}

} // namespace internal
/// \endcond

/*!
\ingroup PkgPointSetObjectRecognitionRef

Reads the streets of an OpenStreetMap extract into the coordinates of a scan.

The file is read with libosmium: OSM XML (`.osm`, or any other extension), gzipped XML
(`.osm.gz`) or PBF (`.osm.pbf`). The streets are its ways tagged `highway`, except, unless
`include_paths`, paths and what is not a street for vehicles (`highway` = `footway`, `path`,
`cycleway`, `bridleway`, `steps`, `pedestrian`, `corridor`, `elevator`, `platform`, `proposed`,
`construction`, `abandoned`, `disused`, `razed`, `bus_stop`, `services`, `rest_area`,
`via_ferrata`, `escape`, `raceway`, and ways tagged `area=yes`): sidewalks mapped as footways
would otherwise be the nearest "street" of every object on them. A way whose nodes are not all in
the file (an extract cuts the ways that leave it) keeps its runs of at least two consecutive nodes
that are.

Node coordinates (latitude and longitude of WGS 84) are projected by GeographicLib's
`UTMUPS::Forward()` into the UTM zone of `crs` (beyond the zone's 6 degrees, the projection is
extended; across the equator, the northings are continued in the hemisphere of `crs`), then the
local origin of the scan is subtracted: a street point lands where a point of the scan at the same
place lies, when the scan was read by `read_point_set()` with that origin
(`Point_set_read_result::offset`).

\param osm_path the file to read
\param crs the coordinate reference system of the scan: a UTM zone of WGS 84 as an EPSG code,
       see `parse_utm_crs()`
\param local_origin the local origin of the scan (only its first two coordinates are used)
\param include_paths whether to keep every way tagged `highway` (paths and footways included)
\param statistics if not null, receives the counts of what was read
\returns the streets, in the order of the file, in the coordinates of the scan
\throws CGAL::Shape_analysis::Bad_input, naming the file, when `crs` is not a UTM EPSG code, the
        local origin is not finite, the file cannot be opened, is not an OpenStreetMap file (the
        parser's message is given), has no street (no way tagged `highway` with two consecutive
        nodes in the file), or a node cannot be projected into the zone (more than 60 degrees of
        longitude away)
*/
inline Street_map read_street_map(const std::string& osm_path, const std::string& crs,
                                  const std::array<double, 3>& local_origin, bool include_paths = false,
                                  Street_map_read_statistics* statistics = nullptr)
{
  const std::string who = "read_street_map: ";
  const Utm_zone zone = [&] {
    try {
      return parse_utm_crs(crs);
    } catch(const Bad_input& e) {
      throw Bad_input(who + e.what());
    }
  }();
  if(!std::isfinite(local_origin[0]) || !std::isfinite(local_origin[1]))
    throw Bad_input(who + "the local origin is not finite");
  if(!std::ifstream(osm_path))
    throw Bad_input(who + osm_path + ": cannot open the file for reading");
  typedef osmium::index::map::FlexMem<osmium::unsigned_object_id_type, osmium::Location> Index;
  internal::Street_collector collector(zone, local_origin, include_paths);
  try {
    const osmium::io::File file(osm_path, internal::osm_file_format(osm_path));
    osmium::io::Reader reader(file, osmium::osm_entity_bits::node | osmium::osm_entity_bits::way);
    Index index;
    osmium::handler::NodeLocationsForWays<Index> locations(index);
    locations.ignore_errors(); // missing nodes: invalid locations, handled by the collector
    osmium::apply(reader, locations, collector);
    reader.close();
  } catch(const Bad_input& e) {
    const std::string what = e.what();
    throw Bad_input(who + (what.compare(0, osm_path.size(), osm_path) == 0 ? what : osm_path + ": " + what));
  } catch(const osmium::io_error& e) {
    throw Bad_input(who + osm_path + ": not an OpenStreetMap file (" + e.what() + ")");
  } catch(const std::system_error& e) {
    throw Bad_input(who + osm_path + ": cannot read the file (" + e.what() + ")");
  } catch(const std::exception& e) {
    throw Bad_input(who + osm_path + ": cannot read the file as OpenStreetMap (" + e.what() + ")");
  }
  Street_map_read_statistics s = collector.statistics;
  s.streets = collector.streets.size();
  if(collector.streets.empty()) {
    std::string why = std::to_string(s.ways) + " ways";
    if(s.highway_ways != 0)
      why += ", " + std::to_string(s.highway_ways) + " tagged highway, of which " + std::to_string(s.path_ways) +
             " paths and " + std::to_string(s.skipped_ways) + " without two consecutive nodes in the file" +
             (s.skipped_ways != 0 ? " (is it sorted, nodes before ways?)" : "");
    throw Bad_input(who + osm_path + ": the map has no street, no way tagged highway that is a road with its nodes (" +
                    why + ")");
  }
  if(statistics)
    *statistics = s;
  return Street_map(std::move(collector.streets));
}

} // namespace Point_set_object_recognition
} // namespace CGAL

#endif // CGAL_POINT_SET_OBJECT_RECOGNITION_READ_STREET_MAP_H
