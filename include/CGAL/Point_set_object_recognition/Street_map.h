// Copyright (c) 2026 CGAL Global Shape Analysis contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_POINT_SET_OBJECT_RECOGNITION_STREET_MAP_H
#define CGAL_POINT_SET_OBJECT_RECOGNITION_STREET_MAP_H

/// \file Street_map.h
/// The streets of a map in the coordinates of a scan, and the nearest street to a location (for
/// the context features of objects, thesis section 4.3.4). Needs no map library:
/// `read_street_map()` fills it from OpenStreetMap.

#include <CGAL/Shape_analysis/Bad_input.h>

#include <CGAL/Bbox_2.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <limits>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Point_set_object_recognition {

using CGAL::Shape_analysis::Bad_input;

/*!
\ingroup PkgPointSetObjectRecognitionRef
The point of a street nearest to a location (`Street_map::nearest()`).
*/
struct Street_point
{
  /// the distance from the location to the street (metres, horizontal); infinite when the map
  /// has no street
  double distance = std::numeric_limits<double>::infinity();
  /// the nearest point of the street, in the coordinates of the scan
  std::array<double, 2> point{{0, 0}};
  /// the unit direction of the street's segment there, from the street's first point toward its
  /// last (at a point shared by two segments, the earlier segment's)
  std::array<double, 2> direction{{1, 0}};
  /// the index of the street in `Street_map::streets()`
  std::size_t street = 0;
};

/*!
\ingroup PkgPointSetObjectRecognitionRef
The streets of a map as polylines in the horizontal coordinates of a scan (what
`read_street_map()` returns), with the nearest street to any location.

The map is immutable once built: its queries are `const` and safe to call from several threads at
once, and copies are independent. The segments are indexed by a uniform grid of about one cell per
segment (within each cell the segments that come within half a cell diagonal of its centre); a
query visits rings of cells around the location until no unvisited cell can hold a nearer
segment, so that the answer is exact and costs a few cells near the streets. (A grid rather than
\cgal's AABB tree: an AABB tree cannot be copied and builds its search structure lazily on the
first query, which is not thread-safe; the grid is neither.)
*/
class Street_map
{
public:
  /// One street: a polyline and the value of its OpenStreetMap `highway` tag.
  struct Street
  {
    /// the points of the polyline in the horizontal coordinates of the scan (metres), at least 2
    std::vector<std::array<double, 2>> points;
    /// the value of its `highway` tag (for example `residential`), empty when unknown
    std::string highway;
  };

  /// An empty map: no street; `nearest()` answers an infinite distance.
  Street_map() = default;

  /// A map of `streets`.
  /// \param streets the streets, each with at least two points, every coordinate finite
  /// \throws CGAL::Shape_analysis::Bad_input when a street has fewer than two points or a
  ///         coordinate that is not finite
  explicit Street_map(std::vector<Street> streets) : m_streets(std::move(streets))
  {
    for(std::size_t s = 0; s < m_streets.size(); ++s) {
      const std::vector<std::array<double, 2>>& p = m_streets[s].points;
      if(p.size() < 2)
        throw Bad_input("Street_map: street " + std::to_string(s) + " has fewer than two points");
      for(const std::array<double, 2>& q : p)
        if(!std::isfinite(q[0]) || !std::isfinite(q[1]))
          throw Bad_input("Street_map: street " + std::to_string(s) + " has a coordinate that is not finite");
      for(std::size_t i = 0; i + 1 < p.size(); ++i)
        if(p[i] != p[i + 1])
          m_segments.push_back(Segment{p[i], p[i + 1], s});
    }
    build_grid();
  }

  /// \returns the streets, in the order given
  const std::vector<Street>& streets() const { return m_streets; }

  /// \returns whether the map has no street
  bool empty() const { return m_streets.empty(); }

  /// \returns the number of segments of positive length of all the streets
  std::size_t number_of_segments() const { return m_segments.size(); }

  /// \returns the bounding box of the streets (an empty box, `CGAL::Bbox_2()`, when the map is empty)
  CGAL::Bbox_2 bbox() const
  {
    CGAL::Bbox_2 b;
    for(const Street& s : m_streets)
      for(const std::array<double, 2>& p : s.points)
        b += CGAL::Bbox_2(p[0], p[1], p[0], p[1]);
    return b;
  }

  /// The point of the streets nearest to \f$ (x, y) \f$ (an exact answer; at equal distances the
  /// segment that comes first in street order).
  /// \param x the first coordinate of the location, in the coordinates of the scan
  /// \param y its second coordinate
  /// \returns the distance, the nearest point, the street's direction there and its index
  /// \throws CGAL::Shape_analysis::Bad_input when `x` or `y` is not finite
  Street_point nearest(double x, double y) const
  {
    if(!std::isfinite(x) || !std::isfinite(y))
      throw Bad_input("Street_map: the location of a query is not finite");
    Street_point best;
    if(m_segments.empty())
      return best;
    // The location clamped to the grid: segments lie inside the grid, so clamping (a projection
    // onto a convex set) brings the location no farther from any of them.
    const std::int64_t ci = clamp_index(std::floor((x - m_x0) / m_cell), m_nx);
    const std::int64_t cj = clamp_index(std::floor((y - m_y0) / m_cell), m_ny);
    const std::int64_t last_ring = (std::max)((std::max)(ci, m_nx - 1 - ci), (std::max)(cj, m_ny - 1 - cj));
    double best_d2 = std::numeric_limits<double>::infinity();
    std::size_t best_segment = m_segments.size();
    const auto visit = [&](std::int64_t i, std::int64_t j) {
      const std::size_t cell = std::size_t(j * m_nx + i);
      for(std::uint32_t k = m_cell_start[cell]; k < m_cell_start[cell + 1]; ++k) {
        const std::size_t s = m_cell_segments[k];
        const double d2 = squared_distance(m_segments[s], x, y);
        if(d2 < best_d2 || (d2 == best_d2 && s < best_segment))
          best_d2 = d2, best_segment = s;
      }
    };
    for(std::int64_t r = 0; r <= last_ring; ++r) {
      // Cells of ring r are at least (r - 1) cells away from the clamped location.
      if(best_segment < m_segments.size() && r >= 1 && std::sqrt(best_d2) <= double(r - 1) * m_cell)
        break;
      for(std::int64_t j = (std::max<std::int64_t>)(cj - r, 0); j <= (std::min)(cj + r, m_ny - 1); ++j) {
        if(j == cj - r || j == cj + r) {
          for(std::int64_t i = (std::max<std::int64_t>)(ci - r, 0); i <= (std::min)(ci + r, m_nx - 1); ++i)
            visit(i, j);
        } else {
          if(ci - r >= 0)
            visit(ci - r, j);
          if(r > 0 && ci + r < m_nx)
            visit(ci + r, j);
        }
      }
    }
    const Segment& s = m_segments[best_segment];
    const double dx = s.b[0] - s.a[0], dy = s.b[1] - s.a[1], length = std::hypot(dx, dy);
    const double t = parameter(s, x, y);
    best.distance = std::sqrt(best_d2);
    best.point = {{s.a[0] + t * dx, s.a[1] + t * dy}};
    best.direction = {{dx / length, dy / length}};
    best.street = s.street;
    return best;
  }

  /// \param x the first coordinate of a location, in the coordinates of the scan
  /// \param y its second coordinate
  /// \returns the distance from \f$ (x, y) \f$ to the nearest street (infinite when the map is empty)
  /// \throws CGAL::Shape_analysis::Bad_input when `x` or `y` is not finite
  double distance(double x, double y) const { return nearest(x, y).distance; }

  /// \param x the first coordinate of a location, in the coordinates of the scan
  /// \param y its second coordinate
  /// \returns the unit direction of the nearest street at its point nearest to \f$ (x, y) \f$
  ///          (\f$ (1, 0) \f$ when the map is empty)
  /// \throws CGAL::Shape_analysis::Bad_input when `x` or `y` is not finite
  std::array<double, 2> direction(double x, double y) const { return nearest(x, y).direction; }

private:
  struct Segment
  {
    std::array<double, 2> a, b;
    std::size_t street;
  };

  // The parameter in [0, 1] of the point of s nearest to (x, y).
  static double parameter(const Segment& s, double x, double y)
  {
    const double dx = s.b[0] - s.a[0], dy = s.b[1] - s.a[1];
    const double t = ((x - s.a[0]) * dx + (y - s.a[1]) * dy) / (dx * dx + dy * dy);
    return (std::min)(1.0, (std::max)(0.0, t));
  }

  static double squared_distance(const Segment& s, double x, double y)
  {
    const double t = parameter(s, x, y);
    const double px = s.a[0] + t * (s.b[0] - s.a[0]) - x, py = s.a[1] + t * (s.b[1] - s.a[1]) - y;
    return px * px + py * py;
  }

  static std::int64_t clamp_index(double v, std::int64_t n)
  {
    return v < 0 ? 0 : (v >= double(n - 1) ? n - 1 : std::int64_t(v));
  }

  // The grid: about one cell per segment, at most 4 n + 1024 cells; each segment in the cells
  // whose centre lies within half a cell diagonal of it (every cell it crosses, and a few more).
  void build_grid()
  {
    if(m_segments.empty())
      return;
    const CGAL::Bbox_2 b = bbox();
    const double w = b.xmax() - b.xmin(), h = b.ymax() - b.ymin();
    double total = 0;
    for(const Segment& s : m_segments)
      total += std::hypot(s.b[0] - s.a[0], s.b[1] - s.a[1]);
    const double n = double(m_segments.size());
    m_cell = (std::max)({std::sqrt(w * h / n), total / n, 1e-9 * (std::max)(w, h), 1e-6});
    while((w / m_cell + 1) * (h / m_cell + 1) > 4 * n + 1024)
      m_cell *= 1.5;
    m_x0 = b.xmin(), m_y0 = b.ymin();
    m_nx = std::int64_t(w / m_cell) + 1, m_ny = std::int64_t(h / m_cell) + 1;
    std::vector<std::pair<std::uint64_t, std::uint32_t>> entries; // (cell, segment)
    const double reach2 = 0.5 * m_cell * m_cell * (1 + 1e-9);
    for(std::size_t k = 0; k < m_segments.size(); ++k) {
      const Segment& s = m_segments[k];
      const std::int64_t i0 = clamp_index(std::floor(((std::min)(s.a[0], s.b[0]) - m_x0) / m_cell) - 1, m_nx);
      const std::int64_t i1 = clamp_index(std::floor(((std::max)(s.a[0], s.b[0]) - m_x0) / m_cell) + 1, m_nx);
      const std::int64_t j0 = clamp_index(std::floor(((std::min)(s.a[1], s.b[1]) - m_y0) / m_cell) - 1, m_ny);
      const std::int64_t j1 = clamp_index(std::floor(((std::max)(s.a[1], s.b[1]) - m_y0) / m_cell) + 1, m_ny);
      for(std::int64_t j = j0; j <= j1; ++j)
        for(std::int64_t i = i0; i <= i1; ++i)
          if(squared_distance(s, m_x0 + (double(i) + 0.5) * m_cell, m_y0 + (double(j) + 0.5) * m_cell) <= reach2)
            entries.emplace_back(std::uint64_t(j * m_nx + i), std::uint32_t(k));
    }
    std::sort(entries.begin(), entries.end());
    m_cell_start.assign(std::size_t(m_nx * m_ny) + 1, 0);
    m_cell_segments.resize(entries.size());
    for(std::size_t e = 0; e < entries.size(); ++e) {
      ++m_cell_start[entries[e].first + 1];
      m_cell_segments[e] = entries[e].second;
    }
    for(std::size_t c = 1; c < m_cell_start.size(); ++c)
      m_cell_start[c] += m_cell_start[c - 1];
  }

  std::vector<Street> m_streets;
  std::vector<Segment> m_segments;
  double m_x0 = 0, m_y0 = 0, m_cell = 1;
  std::int64_t m_nx = 0, m_ny = 0;
  std::vector<std::uint32_t> m_cell_start;    // per cell, its first entry in m_cell_segments
  std::vector<std::uint32_t> m_cell_segments; // segment indices, cell by cell, increasing
};

/*!
\ingroup PkgPointSetObjectRecognitionRef

Checks that a street map and a scan overlap: that some street comes within `margin` of the scan's
bounding box (meets the box grown by `margin` on every side). A map read with the wrong CRS, the
wrong local origin or of another town lies kilometres away and fails this check.

\param map the street map, in the coordinates of the scan
\param scan_bbox the horizontal bounding box of the scan (for example of the points of a
       `CGAL::Point_set_3`, as given by `CGAL::bbox_2()` of their \f$ (x, y) \f$)
\param margin how far from the box a street may lie (metres, finite, at least 0)
\throws CGAL::Shape_analysis::Bad_input when the map is empty, when no street meets the grown box
        (the message gives both boxes), or when `margin` is negative or not finite
*/
inline void check_street_map_overlap(const Street_map& map, const CGAL::Bbox_2& scan_bbox, double margin = 100.0)
{
  if(!(margin >= 0) || !std::isfinite(margin))
    throw Bad_input("check_street_map_overlap: the margin must be finite and at least 0");
  if(map.empty())
    throw Bad_input("the street map has no street");
  const double lo[2] = {scan_bbox.xmin() - margin, scan_bbox.ymin() - margin};
  const double hi[2] = {scan_bbox.xmax() + margin, scan_bbox.ymax() + margin};
  for(const Street_map::Street& s : map.streets())
    for(std::size_t i = 0; i + 1 < s.points.size(); ++i) {
      // Liang-Barsky: does the segment meet the box?
      const std::array<double, 2>&a = s.points[i], &b = s.points[i + 1];
      double t0 = 0, t1 = 1;
      bool meets = true;
      for(int c = 0; c < 2 && meets; ++c) {
        const double d = b[c] - a[c];
        if(d == 0) {
          meets = a[c] >= lo[c] && a[c] <= hi[c];
        } else {
          double u = (lo[c] - a[c]) / d, v = (hi[c] - a[c]) / d;
          if(u > v)
            std::swap(u, v);
          t0 = (std::max)(t0, u), t1 = (std::min)(t1, v);
          meets = t0 <= t1;
        }
      }
      if(meets)
        return;
    }
  const CGAL::Bbox_2 m = map.bbox();
  const auto box = [](double x0, double y0, double x1, double y1) {
    char text[160];
    std::snprintf(text, sizeof(text), "[%.1f, %.1f] x [%.1f, %.1f]", x0, x1, y0, y1);
    return std::string(text);
  };
  char within[40];
  std::snprintf(within, sizeof(within), "%g", margin);
  throw Bad_input("the street map (streets in " + box(m.xmin(), m.ymin(), m.xmax(), m.ymax()) +
                  " in scan coordinates) does not overlap the scan (" +
                  box(scan_bbox.xmin(), scan_bbox.ymin(), scan_bbox.xmax(), scan_bbox.ymax()) + ") within " +
                  within + " m: wrong CRS, wrong local origin or a map of another place?");
}

} // namespace Point_set_object_recognition
} // namespace CGAL

#endif // CGAL_POINT_SET_OBJECT_RECOGNITION_STREET_MAP_H
