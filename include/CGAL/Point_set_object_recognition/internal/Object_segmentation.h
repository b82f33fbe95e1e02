// Copyright (c) 2026 CGAL Global Shape Analysis contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_POINT_SET_OBJECT_RECOGNITION_INTERNAL_OBJECT_SEGMENTATION_H
#define CGAL_POINT_SET_OBJECT_RECOGNITION_INTERNAL_OBJECT_SEGMENTATION_H

// The machinery of segment_objects.h: a graph index over the points near a set of locations
// (nodes: cells of a grid, or the points themselves, weighted by their point counts; edges: the
// k nearest nodes with Gaussian weights on their length), built once and shared by all objects;
// per object, the subgraph around its location with the background penalty, hard foreground
// seeds, optional contraction, and the s-t minimum cut (Shape_analysis/internal/Min_cut.h).

#include <CGAL/Point_set_object_recognition/internal/Voxel_grid.h>
#include <CGAL/Shape_analysis/Bad_input.h>
#include <CGAL/Shape_analysis/internal/Min_cut.h>
#include <CGAL/Shape_analysis/internal/Parallel.h>
#include <CGAL/Shape_analysis/internal/Point_tree.h>
#include <CGAL/Shape_analysis/internal/Vector_3d.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <limits>
#include <numeric>
#include <unordered_map>
#include <utility>
#include <vector>

namespace CGAL {
namespace Point_set_object_recognition {
namespace internal {

namespace SAI = CGAL::Shape_analysis::internal;
typedef std::array<double, 3> P3;

enum class Segmentation_kind { ALL, COMPONENTS, MIN_CUT, MIN_CUT_AUTO };

struct Segmentation_options
{
  Segmentation_kind kind = Segmentation_kind::MIN_CUT_AUTO;
  double radius = 2;               // fixed background radius (min-cut), or radius (all, components)
  double foreground_height = 1.2;  // height of the hard foreground above the location
  std::size_t neighbors = 8;       // k of the kNN graph
  double sigma = 0.8;              // edge weight exp(-(d / sigma)^2): 4 cells by default
  double background_weight = 0.1;  // foreground reward per point at the location (data term scale)
  double outer_factor = 10.0;      // ... times this at radius + ramp width (then hard background)
  double ramp_width = 1.0;         // width of the second ramp (m)
  double cell = 0.2;               // graph nodes: cells of this side; 0: the points
  std::size_t maximum_nodes = 1000; // contraction target (0: none)
  std::size_t seed_neighbors = 3;   // nodes nearest to the seed's node also in the hard foreground
  std::size_t minimum_foreground = 35;
  double maximum_cut = 0.4;
  double spacing = 0.3;            // connected components
  std::vector<double> radii{1, 2, 3, 4, 5}; // automatic radius
  std::size_t threads = 0;
  // Walls (facades): points of the columns of side `wall_column` that span more than
  // `wall_height` of height, within `wall_tolerance` of the line fitted to the high points of such
  // columns around when that line is long and thin (a pole or a tree is not; 0: no walls). They
  // form their own graph nodes, with no edge to the others, and never seed the foreground.
  double wall_height = 3.5, wall_column = 0.2, wall_tolerance = 0.05;
  bool wall_nodes = false; // whether walls have graph nodes (the interactive segmenter's constraints)
};

struct Segmentation_output
{
  std::vector<std::size_t> points; // increasing
  double radius = 0, cut = 0, seconds = 0;
  std::size_t seed = std::size_t(-1);
};

inline double horizontal_distance(const P3& a, const P3& b) { return std::hypot(a[0] - b[0], a[1] - b[1]); }

// Whether horizontal_distance(a, b) <= radius, without std::hypot unless the squared distance
// lies within a relative 1e-12 of the squared radius (both are within a few units in the last
// place of the exact values: elsewhere they agree).
inline bool horizontally_within(const P3& a, const P3& b, double radius)
{
  const double dx = a[0] - b[0], dy = a[1] - b[1];
  const double q = dx * dx + dy * dy, r2 = radius * radius;
  if(q < r2 * (1 - 1e-12))
    return true;
  if(q > r2 * (1 + 1e-12))
    return false;
  return std::hypot(dx, dy) <= radius;
}

// A hash map from 64-bit keys (never all ones) to 32-bit values, by open addressing with linear
// probing: the grids of the segmentation look up millions of keys, most of them absent.
class Key_map
{
public:
  static constexpr std::uint32_t none = std::numeric_limits<std::uint32_t>::max();

  explicit Key_map(std::size_t expected = 0) { reserve(expected); }

  std::size_t size() const { return m_size; }
  bool empty() const { return m_size == 0; }

  void reserve(std::size_t n)
  {
    std::size_t capacity = 16;
    while(capacity < 2 * n + 2)
      capacity *= 2;
    if(capacity > m_slots.size())
      rehash(capacity);
  }

  // The value of `key`, inserting `value` when absent; and whether it was inserted.
  std::pair<std::uint32_t, bool> emplace(std::uint64_t key, std::uint32_t value)
  {
    if(2 * (m_size + 1) > m_slots.size())
      rehash((std::max)(std::size_t(16), 2 * m_slots.size()));
    std::size_t h = slot(key);
    while(m_slots[h].key != empty_key) {
      if(m_slots[h].key == key)
        return {m_slots[h].value, false};
      h = (h + 1) & m_mask;
    }
    m_slots[h].key = key, m_slots[h].value = value;
    ++m_size;
    return {value, true};
  }

  // The value of `key`, `none` when absent.
  std::uint32_t find(std::uint64_t key) const
  {
    if(m_size == 0)
      return none;
    std::size_t h = slot(key);
    while(m_slots[h].key != empty_key) {
      if(m_slots[h].key == key)
        return m_slots[h].value;
      h = (h + 1) & m_mask;
    }
    return none;
  }

private:
  static constexpr std::uint64_t empty_key = ~std::uint64_t(0);
  struct Slot
  {
    std::uint64_t key;
    std::uint32_t value;
  };

  std::size_t slot(std::uint64_t key) const
  {
    return std::size_t((key * 0x9E3779B97F4A7C15ull) >> m_shift) & m_mask;
  }

  void rehash(std::size_t capacity)
  {
    std::vector<Slot> slots(capacity, Slot{empty_key, 0});
    slots.swap(m_slots);
    m_mask = capacity - 1;
    m_shift = 64;
    for(std::size_t c = capacity; c > 1; c /= 2)
      --m_shift;
    m_size = 0;
    for(const Slot& s : slots)
      if(s.key != empty_key)
        emplace(s.key, s.value);
  }

  std::vector<Slot> m_slots;
  std::size_t m_mask = 0, m_size = 0;
  int m_shift = 64;
};

// Columns (i, j) of a grid, keyed i | j << 32, to 32-bit values: a dense array over their
// bounding box when it is not much larger than the columns expected, a Key_map otherwise.
class Column_index
{
public:
  static constexpr std::uint32_t none = Key_map::none;

  static std::uint64_t key(long i, long j) { return std::uint64_t(i) | (std::uint64_t(j) << 32); }

  // For the columns of [i0, i1] x [j0, j1], about `expected` of them.
  void reset(long i0, long j0, long i1, long j1, std::size_t expected)
  {
    m_i0 = i0, m_j0 = j0, m_ni = i1 - i0 + 1, m_nj = j1 - j0 + 1;
    m_dense = m_ni > 0 && m_nj > 0 && double(m_ni) * double(m_nj) <= 16.0 * double(expected) + double(1 << 20);
    m_cells.assign(m_dense ? std::size_t(m_ni * m_nj) : 0, none);
    m_map = Key_map(m_dense ? 0 : expected);
  }

  std::pair<std::uint32_t, bool> emplace(std::uint64_t k, std::uint32_t value)
  {
    if(!m_dense)
      return m_map.emplace(k, value);
    std::uint32_t& c = m_cells[cell(k)];
    if(c != none)
      return {c, false};
    c = value;
    return {value, true};
  }

  std::uint32_t find(std::uint64_t k) const
  {
    if(!m_dense)
      return m_map.find(k);
    const long i = long(k & 0xFFFFFFFFu) - m_i0, j = long(k >> 32) - m_j0;
    if(i < 0 || j < 0 || i >= m_ni || j >= m_nj)
      return none;
    return m_cells[std::size_t(j * m_ni + i)];
  }

private:
  std::size_t cell(std::uint64_t k) const
  {
    return std::size_t((long(k >> 32) - m_j0) * m_ni + (long(k & 0xFFFFFFFFu) - m_i0));
  }

  bool m_dense = false;
  long m_i0 = 0, m_j0 = 0, m_ni = 0, m_nj = 0;
  std::vector<std::uint32_t> m_cells;
  Key_map m_map;
};

// Items grouped by the columns (i, j) of a grid (keys i | j << 32): per column its items, in the
// order given.
struct Key_lists
{
  Column_index index;               // key -> list
  std::vector<std::uint64_t> keys;  // per list, its key
  std::vector<std::size_t> first;   // per list, its first item (one more at the end)
  std::vector<std::uint32_t> items;

  std::size_t size() const { return keys.size(); }

  template <typename KeyOf> void assign(const std::vector<std::uint32_t>& all, const KeyOf& key_of)
  {
    std::vector<std::uint64_t> key_of_item(all.size());
    long i0 = 0, j0 = 0, i1 = -1, j1 = -1;
    for(std::size_t k = 0; k < all.size(); ++k) {
      const std::uint64_t key = key_of(all[k]);
      key_of_item[k] = key;
      const long i = long(key & 0xFFFFFFFFu), j = long(key >> 32);
      if(k == 0)
        i0 = i1 = i, j0 = j1 = j;
      i0 = (std::min)(i0, i), i1 = (std::max)(i1, i), j0 = (std::min)(j0, j), j1 = (std::max)(j1, j);
    }
    index.reset(i0, j0, i1, j1, all.size() / 4 + 16);
    keys.clear();
    std::vector<std::uint32_t> list_of(all.size());
    std::vector<std::size_t> count;
    for(std::size_t k = 0; k < all.size(); ++k) {
      const std::uint64_t key = key_of_item[k];
      const auto ins = index.emplace(key, std::uint32_t(keys.size()));
      if(ins.second)
        keys.push_back(key), count.push_back(0);
      ++count[ins.first];
      list_of[k] = ins.first;
    }
    first.assign(keys.size() + 1, 0);
    for(std::size_t c = 0; c < keys.size(); ++c)
      first[c + 1] = first[c] + count[c];
    items.assign(all.size(), 0);
    std::vector<std::size_t> fill(first.begin(), first.end() - 1);
    for(std::size_t k = 0; k < all.size(); ++k)
      items[fill[list_of[k]]++] = all[k];
  }

  // The list of `key`, `Key_map::none` when there is none.
  std::uint32_t find(std::uint64_t key) const { return index.find(key); }
  const std::uint32_t* begin(std::uint32_t list) const { return items.data() + first[list]; }
  const std::uint32_t* end(std::uint32_t list) const { return items.data() + first[list + 1]; }

  // Calls g(i, j, list) for the squares (keyed by their column i and row j of side `side` from
  // `lo`) that have a list and meet the square of half side `radius` around `at`.
  template <typename G>
  void for_square_lists(const P3& lo, double side, const P3& at, double radius, const G& g) const
  {
    const long i0 = (std::max)(0L, long(std::floor((at[0] - radius - lo[0]) / side)));
    const long i1 = long(std::floor((at[0] + radius - lo[0]) / side));
    const long j0 = (std::max)(0L, long(std::floor((at[1] - radius - lo[1]) / side)));
    const long j1 = long(std::floor((at[1] + radius - lo[1]) / side));
    for(long j = j0; j <= j1; ++j)
      for(long i = i0; i <= i1; ++i) {
        const std::uint32_t c = find(Column_index::key(i, j));
        if(c != Key_map::none)
          g(i, j, c);
      }
  }

  // Calls f on the items of those lists.
  template <typename F>
  void for_square(const P3& lo, double side, const P3& at, double radius, const F& f) const
  {
    for_square_lists(lo, side, at, radius, [&](long, long, std::uint32_t c) {
      for(const std::uint32_t* q = begin(c); q != end(c); ++q)
        f(*q);
    });
  }
};

// The points of a cloud by columns (squares of side 1 m in (x, y)), built once per call and
// shared by the graphs of its rounds.
class Point_columns
{
public:
  static constexpr std::uint32_t none = std::numeric_limits<std::uint32_t>::max();

  // Bad_input for too many points, a coordinate that is not finite or too large a scene.
  explicit Point_columns(const std::vector<P3>& points) : m_p(points)
  {
    if(points.size() >= std::size_t(none))
      throw CGAL::Shape_analysis::Bad_input("segment_objects: too many points (at most 2^32 - 2)");
    {
      P3 lo, hi; // locals: the loop keeps them in registers
      checked_bounds(points, m_side, "segment_objects", lo, hi);
      m_lo = lo, m_hi = hi;
    }
    const std::size_t n = points.size();
    const long ni = long((m_hi[0] - m_lo[0]) / m_side) + 1, nj = long((m_hi[1] - m_lo[1]) / m_side) + 1;
    m_column_of_point.assign(n, none);
    if(double(ni) * double(nj) <= 4.0 * double(n) + double(1 << 20)) {
      // A dense grid: column (i, j) is list j ni + i (empty lists included), by a counting sort.
      m_lists.index.reset(0, 0, ni - 1, nj - 1, n);
      m_lists.keys.resize(std::size_t(ni * nj));
      for(long j = 0; j < nj; ++j)
        for(long i = 0; i < ni; ++i) {
          const std::uint64_t k = Column_index::key(i, j);
          m_lists.index.emplace(k, std::uint32_t(j * ni + i));
          m_lists.keys[std::size_t(j * ni + i)] = k;
        }
      // Consecutive points mostly share their column (a scan's order): the counts and the fills
      // go by runs of points of one column.
      m_lists.first.assign(m_lists.keys.size() + 1, 0);
      std::uint32_t run_column = none;
      std::size_t run = 0;
      for(std::size_t i = 0; i < n; ++i) {
        const std::uint32_t c = std::uint32_t(long((m_p[i][1] - m_lo[1]) / m_side) * ni + long((m_p[i][0] - m_lo[0]) / m_side));
        m_column_of_point[i] = c;
        if(c != run_column) {
          if(run_column != none)
            m_lists.first[run_column + 1] += run;
          run_column = c, run = 0;
        }
        ++run;
      }
      if(run_column != none)
        m_lists.first[run_column + 1] += run;
      for(std::size_t c = 0; c < m_lists.keys.size(); ++c)
        m_lists.first[c + 1] += m_lists.first[c];
      m_lists.items.resize(n);
      std::vector<std::size_t> fill(m_lists.first.begin(), m_lists.first.end() - 1);
      for(std::size_t i = 0; i < n;) {
        const std::uint32_t c = m_column_of_point[i];
        std::uint32_t* out = m_lists.items.data() + fill[c];
        const std::size_t from = i;
        for(; i < n && m_column_of_point[i] == c; ++i)
          *out++ = std::uint32_t(i);
        fill[c] += i - from;
      }
    } else {
      std::vector<std::uint32_t> all(n);
      std::iota(all.begin(), all.end(), 0u);
      m_lists.assign(all, [&](std::uint32_t i) { return key(m_p[i][0], m_p[i][1]); });
      for(std::uint32_t c = 0; c < m_lists.size(); ++c)
        for(const std::uint32_t* q = m_lists.begin(c); q != m_lists.end(c); ++q)
          m_column_of_point[*q] = c;
    }
  }

  // Bad_input for a location that is not finite or lies outside the cloud's horizontal box.
  void check(const std::vector<P3>& locations) const
  {
    for(const P3& l : locations) {
      for(double c : l)
        if(!std::isfinite(c))
          throw CGAL::Shape_analysis::Bad_input("segment_objects: a location is not finite");
      if(l[0] < m_lo[0] - 1e-9 || l[0] > m_hi[0] + 1e-9 || l[1] < m_lo[1] - 1e-9 || l[1] > m_hi[1] + 1e-9)
        throw CGAL::Shape_analysis::Bad_input("segment_objects: a location lies outside the point cloud (its "
                                              "horizontal bounding box)");
    }
  }

  const std::vector<P3>& points() const { return m_p; }
  const P3& lo() const { return m_lo; }
  const P3& hi() const { return m_hi; }
  double side() const { return m_side; }
  const Key_lists& lists() const { return m_lists; }
  std::uint32_t column_of_point(std::size_t i) const { return m_column_of_point[i]; }
  std::uint64_t key(double x, double y) const
  {
    return Column_index::key(long((x - m_lo[0]) / m_side), long((y - m_lo[1]) / m_side));
  }

  // Calls f on the items of the columns of `lists` (keyed as these columns) that meet the square
  // of half side `radius` around `at`.
  template <typename F>
  void for_columns(const P3& at, double radius, const F& f, const Key_lists& lists) const
  {
    lists.for_square(m_lo, m_side, at, radius, f);
  }

  // The points within `radius` of (x, y) horizontally, increasing.
  void points_within(const P3& at, double radius, std::vector<std::uint32_t>& out) const
  {
    points_within(at, radius, out, [](std::uint32_t) { return true; });
    std::sort(out.begin(), out.end());
  }

  // The points within `radius` of (x, y) horizontally for which keep(i) holds, in no particular
  // order.
  template <typename Keep>
  void points_within(const P3& at, double radius, std::vector<std::uint32_t>& out, const Keep& keep) const
  {
    out.clear();
    for_columns(at, radius, [&](std::uint32_t i) {
      if(keep(i) && horizontally_within(m_p[i], at, radius))
        out.push_back(i);
    }, m_lists);
  }

private:
  const std::vector<P3>& m_p;
  static constexpr double m_side = 1.0;
  P3 m_lo{{0, 0, 0}}, m_hi{{0, 0, 0}};
  Key_lists m_lists;
  std::vector<std::uint32_t> m_column_of_point;
};

// The graph nodes of the points near a set of locations: those of the columns of `columns` that
// come within `reach` of a location (horizontally).
class Segmentation_index
{
public:
  static constexpr std::uint32_t none = std::numeric_limits<std::uint32_t>::max();

  Segmentation_index(const Point_columns& columns, const std::vector<P3>& locations, double reach,
                     const Segmentation_options& o, bool with_graph)
    : m_p(columns.points()), m_o(o), m_pc(columns)
  {
    m_lo = columns.lo(), m_side = columns.side();
    if(!with_graph)
      return;
    // The columns within `reach` of a location, and their points.
    std::vector<char> near_column(columns.lists().size(), 0);
    for(const P3& l : locations)
      columns.lists().for_square_lists(m_lo, m_side, l, reach, [&](long i, long j, std::uint32_t c) {
        const double x0 = m_lo[0] + double(i) * m_side, y0 = m_lo[1] + double(j) * m_side;
        const double dx = (std::max)(0.0, (std::max)(x0 - l[0], l[0] - x0 - m_side));
        const double dy = (std::max)(0.0, (std::max)(y0 - l[1], l[1] - y0 - m_side));
        if(dx * dx + dy * dy <= reach * reach)
          near_column[c] = 1;
      });
    // (By runs of points of one column: consecutive points mostly share it.)
    std::vector<std::uint32_t> near;
    near.reserve(m_p.size());
    for(std::size_t i = 0; i < m_p.size();) {
      const std::uint32_t c = columns.column_of_point(i);
      std::size_t j = i + 1;
      while(j < m_p.size() && columns.column_of_point(j) == c)
        ++j;
      if(near_column[c])
        for(; i < j; ++i)
          near.push_back(std::uint32_t(i));
      i = j;
    }
    build_graph(std::move(near));
  }

  const std::vector<P3>& points() const { return m_p; }

  // The points within `radius` of (x, y) horizontally, increasing.
  void points_within(const P3& at, double radius, std::vector<std::uint32_t>& out) const
  {
    m_pc.points_within(at, radius, out);
  }

  // The points off walls within `radius` of (x, y) horizontally, in no particular order.
  void points_off_walls_within(const P3& at, double radius, std::vector<std::uint32_t>& out) const
  {
    m_pc.points_within(at, radius, out, [&](std::uint32_t i) { return !is_wall(i); });
  }

  // The graph nodes whose centroids lie within `radius` of (x, y) horizontally, increasing; the
  // nodes of walls only `with_walls` (they have no edges: they never join an object).
  void nodes_within(const P3& at, double radius, std::vector<std::uint32_t>& out, bool with_walls = false) const
  {
    out.clear();
    const auto add = [&](std::uint32_t v) {
      if(horizontally_within(m_centroid[v], at, radius))
        out.push_back(v);
    };
    for_columns(at, radius, add, m_node_columns);
    if(with_walls)
      for_columns(at, radius, add, m_wall_node_columns);
    std::sort(out.begin(), out.end());
  }

  std::size_t number_of_nodes() const { return m_count.size(); }
  const P3& centroid(std::size_t v) const { return m_centroid[v]; }
  double count(std::size_t v) const { return m_count[v]; }
  std::uint32_t node_of_point(std::size_t i) const { return m_node_of_point[i]; }
  // Whether point i was found on a wall (only with the graph).
  bool is_wall(std::size_t i) const { return !m_wall.empty() && m_wall[i] != 0; }
  template <typename F> void for_members(std::size_t v, const F& f) const
  {
    for(std::size_t k = m_member_first[v]; k < m_member_first[v + 1]; ++k)
      f(m_members[k]);
  }
  template <typename F> void for_adjacent(std::size_t v, const F& f) const
  {
    for(std::size_t k = m_adjacent_first[v]; k < m_adjacent_first[v + 1]; ++k)
      f(m_adjacent[k], m_adjacent_weight[k]);
  }

private:
  std::uint64_t column_of(double x, double y) const
  {
    return Column_index::key(long((x - m_lo[0]) / m_side), long((y - m_lo[1]) / m_side));
  }
  // Calls f on the items of the columns of `lists` that meet the square of half side `radius`
  // around `at`.
  template <typename F>
  void for_columns(const P3& at, double radius, const F& f, const Key_lists& lists) const
  {
    lists.for_square(m_lo, m_side, at, radius, f);
  }

  // Flags the points of `active` (increasing) that lie on a wall (see Segmentation_options), and
  // with `drop_walls` removes them from `active`. The passes go over `active` in order (the
  // points' columns found once), not column by column.
  void find_walls(std::vector<std::uint32_t>& active, bool drop_walls)
  {
    m_wall.assign(m_p.size(), 0);
    const double s = m_o.wall_column;
    if(!(m_o.wall_height > 0) || !(s > 0) || active.empty())
      return;
    // The columns of side s, numbered as they are met; per active point its column; per column
    // its key and the range of its heights.
    const auto column_key = [&](const P3& q) {
      return Column_index::key(long((q[0] - m_lo[0]) / s), long((q[1] - m_lo[1]) / s));
    };
    Column_index column;
    {
      const std::uint64_t k0 = column_key(m_pc.lo()), k1 = column_key(m_pc.hi());
      column.reset(long(k0 & 0xFFFFFFFFu), long(k0 >> 32), long(k1 & 0xFFFFFFFFu), long(k1 >> 32),
                   active.size() / 4 + 16);
    }
    // The fine cells (of side half the tolerance) of the high points of walls. When they divide
    // the columns exactly (a power of two of them along each axis, as by default: then a fine
    // cell lies in a single column), per point its fine cell in its column (`per` x `per` of
    // them, row by row; `outside` when there is none).
    const double fine = 0.5 * m_o.wall_tolerance;
    const auto fine_key = [&](const P3& q) {
      return Column_index::key(long((q[0] - m_lo[0]) / fine), long((q[1] - m_lo[1]) / fine));
    };
    const long per = long(std::lround(s / fine));
    const bool nested = per >= 1 && per <= 16 && (per & (per - 1)) == 0 && double(per) * fine == s;
    const bool masks = nested && per * per <= 64; // then a column's fine cells are bits of a mask
    const unsigned char outside = 255;
    std::vector<unsigned char> fine_of(masks ? active.size() : 0, outside);
    std::vector<std::uint64_t> keys;
    std::vector<std::array<double, 2>> range; // lowest, highest
    std::vector<std::uint32_t> column_of(active.size());
    // (Consecutive points mostly share their column: the range goes by runs.)
    std::uint64_t run_key = 0;
    std::uint32_t run_column = none;
    double run_lo = 0, run_hi = 0;
    for(std::size_t a = 0; a < active.size(); ++a) {
      const P3& q = m_p[active[a]];
      std::uint64_t key;
      if(masks) {
        // The column from the fine cell: s = per fine exactly, per a power of two, so the
        // quotient by s is that by `fine` over per exactly, and its integer part that of the
        // fine cell over per.
        const std::uint64_t f = fine_key(q);
        const long fi = long(f & 0xFFFFFFFFu), fj = long(f >> 32);
        key = Column_index::key(fi / per, fj / per);
        fine_of[a] = (unsigned char)((fj % per) * per + fi % per);
      } else
        key = column_key(q);
      if(run_column == none || key != run_key) {
        if(run_column != none)
          range[run_column] = {{run_lo, run_hi}};
        const auto ins = column.emplace(key, std::uint32_t(keys.size()));
        if(ins.second)
          keys.push_back(key), range.push_back({{q[2], q[2]}});
        run_key = key, run_column = ins.first, run_lo = range[run_column][0], run_hi = range[run_column][1];
      }
      run_lo = (std::min)(run_lo, q[2]), run_hi = (std::max)(run_hi, q[2]);
      column_of[a] = run_column;
    }
    if(run_column != none)
      range[run_column] = {{run_lo, run_hi}};
    const std::size_t nc = keys.size();
    // Per column, its lowest height when it is tall, NaN otherwise.
    const double not_tall = std::numeric_limits<double>::quiet_NaN();
    std::vector<double> tall(nc, not_tall);
    std::vector<std::uint32_t> tall_columns;
    for(std::uint32_t c = 0; c < nc; ++c)
      if(range[c][1] - range[c][0] > m_o.wall_height)
        tall[c] = range[c][0], tall_columns.push_back(c);
    if(tall_columns.empty())
      return;
    const double high = 2.0; // above the lowest point of its column: above the small objects
    // Per tall column, the moments of its high points (relative to the grid's corner); the high
    // points (positions in `active`).
    std::vector<std::array<double, 6>> moments(nc, std::array<double, 6>{{0, 0, 0, 0, 0, 0}});
    std::vector<std::uint32_t> high_points;
    high_points.reserve(active.size());
    // (By runs of points of one column, the sums in registers: the same additions in the same
    // order.)
    for(std::size_t a = 0; a < active.size();) {
      const std::uint32_t c = column_of[a];
      if(std::isnan(tall[c])) {
        for(++a; a < active.size() && column_of[a] == c; ++a) {
        }
        continue;
      }
      const double above = tall[c] + high;
      double m0 = moments[c][0], m1 = moments[c][1], m2 = moments[c][2], m3 = moments[c][3], m4 = moments[c][4],
             m5 = moments[c][5];
      for(; a < active.size() && column_of[a] == c; ++a) {
        const P3& q = m_p[active[a]];
        if(q[2] > above) {
          const double x = q[0] - m_lo[0], y = q[1] - m_lo[1];
          m0 += 1, m1 += x, m2 += y, m3 += x * x, m4 += x * y, m5 += y * y;
          high_points.push_back(std::uint32_t(a));
        }
      }
      moments[c] = {{m0, m1, m2, m3, m4, m5}};
    }
    // The tall columns whose high points around (within 0.5 m) spread along a line longer than
    // 0.2 m: a wall (or a tree; a pole does not).
    const int reach = int(std::ceil(0.5 / s));
    std::vector<char> spread(nc, 0);
    std::size_t spread_columns = 0;
    for(std::uint32_t c : tall_columns) {
      const std::uint64_t key = keys[c];
      const long ci = long(key & 0xFFFFFFFFu), cj = long(key >> 32);
      double n = 0, sx = 0, sy = 0, sxx = 0, sxy = 0, syy = 0;
      for(long dj = -reach; dj <= reach; ++dj)
        for(long di = -reach; di <= reach; ++di) {
          if(ci + di < 0 || cj + dj < 0)
            continue;
          const std::uint32_t a = column.find(Column_index::key(ci + di, cj + dj));
          if(a == Key_map::none || std::isnan(tall[a]))
            continue;
          const std::array<double, 6>& m = moments[a];
          n += m[0], sx += m[1], sy += m[2], sxx += m[3], sxy += m[4], syy += m[5];
        }
      if(n < 10)
        continue;
      const double mx = sx / n, my = sy / n;
      const double a = sxx / n - mx * mx, b = sxy / n - mx * my, d = syy / n - my * my;
      const double l1 = 0.5 * (a + d) + std::sqrt(0.25 * (a - d) * (a - d) + b * b);
      if(!(std::sqrt(l1) > 0.2))
        continue; // a pole
      spread[c] = 1, ++spread_columns;
    }
    // The high points of those columns mark the fine cells under them, with the range of their
    // heights; column by column (the high points grouped by column, in order). When the fine
    // cells divide the columns exactly (a power of two of them along each axis, as by default:
    // then a fine cell lies in a single column), the stacks of the column are gathered in a small
    // array of its fine cells; else (and for a point rounded out of its column) in a map.
    struct Stack { double lo, hi; int n; std::uint64_t key; };
    Key_map stack_of; // fine cell -> its stack of high points of walls
    std::vector<Stack> stacks;
    std::vector<Stack> local(nested ? std::size_t(per * per) : 0);
    const auto add = [](Stack& st, double z, std::uint64_t key) {
      if(st.n == 0)
        st = Stack{z, z, 0, key};
      st.lo = (std::min)(st.lo, z), st.hi = (std::max)(st.hi, z), ++st.n;
    };
    if(spread_columns > 0) {
      std::vector<std::uint32_t> first(nc + 1, 0);
      for(std::uint32_t a : high_points)
        if(spread[column_of[a]])
          ++first[column_of[a] + 1];
      for(std::size_t c = 0; c < nc; ++c)
        first[c + 1] += first[c];
      std::vector<std::uint32_t> by_column(first[nc]);
      {
        std::vector<std::uint32_t> fill(first.begin(), first.end() - 1);
        for(std::uint32_t a : high_points)
          if(spread[column_of[a]])
            by_column[fill[column_of[a]]++] = a;
      }
      for(std::uint32_t c = 0; c < nc; ++c) {
        if(first[c] == first[c + 1])
          continue;
        const long ci = long(keys[c] & 0xFFFFFFFFu), cj = long(keys[c] >> 32);
        if(nested)
          std::fill(local.begin(), local.end(), Stack{0, 0, 0, 0});
        for(std::uint32_t h = first[c]; h < first[c + 1]; ++h) {
          const P3& p = m_p[active[by_column[h]]];
          if(masks && fine_of[by_column[h]] != outside) {
            const long f = fine_of[by_column[h]], li = f % per, lj = f / per;
            add(local[std::size_t(f)], p[2], Column_index::key(per * ci + li, per * cj + lj));
            continue;
          }
          const std::uint64_t key = fine_key(p);
          if(nested) {
            const long li = long(key & 0xFFFFFFFFu) - per * ci, lj = long(key >> 32) - per * cj;
            if(li >= 0 && lj >= 0 && li < per && lj < per) {
              add(local[std::size_t(lj * per + li)], p[2], key);
              continue;
            }
          }
          const auto ins = stack_of.emplace(key, std::uint32_t(stacks.size()));
          if(ins.second)
            stacks.push_back(Stack{0, 0, 0, key});
          add(stacks[ins.first], p[2], key);
        }
        if(nested)
          for(const Stack& st : local)
            if(st.n > 0)
              stacks.push_back(st);
      }
    }
    // A wall's fine cells stack several high points over a metre at least (a crown's do not).
    // The cells of walls and their eight neighbours: with nested fine cells (at most 8 x 8 per
    // column), bits of a mask per column; else in a map.
    std::vector<std::uint64_t> mask(masks ? nc : 0, 0);
    Key_map high_cells;
    for(const Stack& st : stacks)
      if(st.n >= 3 && st.hi - st.lo > 1.0) {
        const long fi = long(st.key & 0xFFFFFFFFu), fj = long(st.key >> 32);
        for(long dj = -1; dj <= 1; ++dj) // the cell and its eight neighbours
          for(long di = -1; di <= 1; ++di) {
            const long gi = fi + di, gj = fj + dj;
            if(gi < 0 || gj < 0)
              continue;
            if(!masks) {
              high_cells.emplace(Column_index::key(gi, gj), 1);
              continue;
            }
            const std::uint32_t a = column.find(Column_index::key(gi / per, gj / per));
            if(a != Key_map::none) // else no point lies in that cell
              mask[a] |= std::uint64_t(1) << ((gj % per) * per + gi % per);
          }
      }
    // The points under the high points of walls: the walls' lower parts.
    // (With `drop_walls`, the points off walls move to the front of `active` as they are met.)
    std::size_t off = 0;
    if(masks)
      for(std::size_t a = 0; a < active.size(); ++a) {
        const std::uint32_t i = active[a];
        const std::uint64_t m = mask[column_of[a]];
        const bool wall = m != 0 && fine_of[a] != outside && ((m >> fine_of[a]) & 1) != 0;
        m_wall[i] = wall ? 1 : 0;
        active[off] = i;
        off += wall && drop_walls ? 0 : 1; // (no branch)
      }
    else {
      if(!high_cells.empty())
        for(std::uint32_t i : active)
          m_wall[i] = high_cells.find(fine_key(m_p[i])) != Key_map::none ? 1 : 0;
      for(std::size_t a = 0; a < active.size(); ++a)
        if(!drop_walls || !m_wall[active[a]])
          active[off++] = active[a];
    }
    active.resize(off);
  }


  // The graph of the points `active` (increasing).
  void build_graph(std::vector<std::uint32_t> active)
  {
    // Nodes: the cells of side `cell` (or the points), numbered by their first point.
    find_walls(active, !m_o.wall_nodes); // without wall nodes, the walls never join an object
    m_node_of_point.assign(m_p.size(), none);
    std::vector<std::uint32_t> first_of_node;
    if(m_o.cell > 0) {
      Key_map cell(active.size() / 4 + 16); // key -> node
      std::uint64_t last_key = 0;
      std::uint32_t last_node = none; // of the previous point (consecutive points often share it)
      for(std::uint32_t i : active) {
        const std::uint64_t key = voxel_key(m_p[i][0], m_p[i][1], m_p[i][2], m_o.cell, m_lo) | wall_bit(i);
        if(last_node == none || key != last_key) {
          const auto ins = cell.emplace(key, std::uint32_t(first_of_node.size()));
          if(ins.second)
            first_of_node.push_back(i);
          last_key = key, last_node = ins.first;
        }
        m_node_of_point[i] = last_node;
      }
    } else
      for(std::uint32_t i : active) {
        m_node_of_point[i] = std::uint32_t(first_of_node.size());
        first_of_node.push_back(i);
      }
    const std::size_t n = first_of_node.size();
    m_member_first.assign(n + 1, 0);
    for(std::uint32_t i : active)
      ++m_member_first[m_node_of_point[i] + 1];
    for(std::size_t v = 0; v < n; ++v)
      m_member_first[v + 1] += m_member_first[v];
    m_members.assign(active.size(), 0);
    {
      std::vector<std::size_t> fill(m_member_first.begin(), m_member_first.end() - 1);
      for(std::uint32_t i : active)
        m_members[fill[m_node_of_point[i]]++] = i;
    }
    m_centroid.assign(n, P3{{0, 0, 0}});
    m_count.assign(n, 0);
    std::vector<std::uint32_t> wall_nodes, other_nodes;
    for(std::size_t v = 0; v < n; ++v) {
      P3 c{{0, 0, 0}};
      for_members(v, [&](std::uint32_t i) {
        for(int a = 0; a < 3; ++a)
          c[a] += m_p[i][a];
      });
      const double k = double(m_member_first[v + 1] - m_member_first[v]);
      m_centroid[v] = {c[0] / k, c[1] / k, c[2] / k};
      m_count[v] = k;
      (m_wall[first_of_node[v]] ? wall_nodes : other_nodes).push_back(std::uint32_t(v));
    }
    const auto centroid_column = [&](std::uint32_t v) { return column_of(m_centroid[v][0], m_centroid[v][1]); };
    m_node_columns.assign(other_nodes, centroid_column);
    m_wall_node_columns.assign(wall_nodes, centroid_column);
    // Edges: the k nearest nodes of every node, symmetrized, with weights
    // exp(-(d / sigma)^2) times the smaller point count of their two nodes. With cells, the
    // nearest are looked for among the nodes of the 3 x 3 x 3 cells around, then of larger blocks
    // while they hold fewer than k others (up to 7 x 7 x 7: a node farther than three cells is no
    // neighbour); the nodes by vertical stacks of cells, by increasing height. Without, in a
    // kd-tree.
    constexpr int maximum_reach = 3;
    std::vector<SAI::Vector_3d> c(n);
    std::vector<std::uint32_t> ids(n);
    for(std::size_t v = 0; v < n; ++v) {
      c[v] = SAI::Vector_3d(m_centroid[v][0], m_centroid[v][1], m_centroid[v][2]);
      ids[v] = std::uint32_t(v);
    }
    const std::size_t k = m_o.neighbors;
    std::vector<std::uint32_t> knn(n * k, none);
    SAI::Point_tree tree;
    Key_lists stacks; // the nodes off walls by their cells' columns (i, j), by increasing k
    struct Stack_entry
    {
      SAI::Vector_3d c;
      std::uint32_t k, v;
    };
    std::vector<Stack_entry> entries; // the nodes of `stacks.items`, with their centroids and k
    std::vector<std::uint64_t> cell_key(n, 0);
    if(m_o.cell <= 0)
      tree = SAI::Point_tree(c, ids);
    else {
      for(std::size_t v = 0; v < n; ++v) {
        const P3& q = m_p[first_of_node[v]];
        cell_key[v] = voxel_key(q[0], q[1], q[2], m_o.cell, m_lo);
      }
      stacks.assign(other_nodes, [&](std::uint32_t v) {
        return Column_index::key(long(cell_key[v] & 0x1FFFFF), long((cell_key[v] >> 21) & 0x1FFFFF));
      });
      for(std::size_t s = 0; s < stacks.size(); ++s)
        std::sort(stacks.items.begin() + long(stacks.first[s]), stacks.items.begin() + long(stacks.first[s + 1]),
                  [&](std::uint32_t a, std::uint32_t b) { return cell_key[a] < cell_key[b]; });
      entries.reserve(stacks.items.size());
      for(std::uint32_t u : stacks.items)
        entries.push_back(Stack_entry{c[u], std::uint32_t(cell_key[u] >> 42), u});
    }
    // The k nearest (by distance, then index) among the pairs r, in order, into knn's row of v
    // (the m smallest pairs whatever the order of r: the candidates are distinct).
    const auto keep_nearest = [&](std::vector<std::pair<double, std::uint32_t>>& r, std::size_t v) {
      const std::size_t m = (std::min)(k, r.size());
      std::size_t kept = 0;
      for(std::size_t j = 0; j < r.size(); ++j) {
        const std::pair<double, std::uint32_t> x = r[j];
        if(kept == m && !(x < r[m - 1]))
          continue;
        std::size_t f = kept < m ? kept++ : m - 1;
        for(; f > 0 && x < r[f - 1]; --f)
          r[f] = r[f - 1];
        r[f] = x;
      }
      for(std::size_t j = 0; j < m; ++j)
        knn[v * k + j] = r[j].second;
    };
    typedef std::vector<std::pair<double, std::uint32_t>> Candidates;
    if(m_o.cell > 0) {
      // Stack by stack, its nodes by increasing height. The stacks around by rings (ring 0: the
      // stack itself; ring d: the stacks d columns away), found once per stack, each with a cursor
      // on its first node not below the cube where the ring entered (the cubes rise with the
      // nodes). The cube of half side `reach` is that of reach - 1 and the nodes of its new
      // layers (heights ck +- reach) in the rings already in, and those of the new ring.
      constexpr std::size_t ring_size = 8 * maximum_reach; // the most stacks in a ring
      SAI::Parallel_workspaces<Candidates> parallel(m_o.threads);
      const std::size_t block = 32;
      parallel.for_each(0, (stacks.size() + block - 1) / block, [&](std::size_t b, Candidates& r) {
        struct Ring_stack { const Stack_entry *cursor, *begin, *end; };
        for(std::size_t s = b * block; s < (std::min)(stacks.size(), (b + 1) * block); ++s) {
          const long ci = long(stacks.keys[s] & 0xFFFFFFFFu), cj = long(stacks.keys[s] >> 32);
          bool known[maximum_reach + 1] = {};
          std::size_t size[maximum_reach + 1] = {};
          Ring_stack ring[maximum_reach + 1][ring_size];
          for(const Stack_entry* node = entries.data() + stacks.first[s]; node != entries.data() + stacks.first[s + 1];
              ++node) {
            const std::uint32_t v = node->v;
            const long ck = long(node->k);
            const SAI::Vector_3d cv = node->c;
            const auto take = [&](const Stack_entry* e) {
              if(e->v != v)
                r.emplace_back((e->c - cv).squared_length(), e->v);
            };
            // The nodes of ring d within the cube of half side `reach` (as the ring enters).
            const auto enter = [&](long d, long reach) {
              if(!known[d]) {
                std::size_t a = 0;
                for(long dj = -d; dj <= d; ++dj)
                  for(long di = -d; di <= d; ++di) {
                    if((std::max)(std::abs(di), std::abs(dj)) != d || ci + di < 0 || cj + dj < 0)
                      continue;
                    const std::uint32_t t = stacks.find(Column_index::key(ci + di, cj + dj));
                    if(t != Key_map::none)
                      ring[d][a++] = Ring_stack{entries.data() + stacks.first[t], entries.data() + stacks.first[t],
                                                entries.data() + stacks.first[t + 1]};
                  }
                size[d] = a, known[d] = true;
              }
              const std::uint32_t k0 = std::uint32_t((std::max)(0L, ck - reach)), k1 = std::uint32_t(ck + reach);
              for(std::size_t a = 0; a < size[d]; ++a) {
                Ring_stack& t = ring[d][a];
                const Stack_entry* e = t.cursor;
                while(e != t.end && e->k < k0)
                  ++e;
                t.cursor = e;
                for(; e != t.end && e->k <= k1; ++e)
                  take(e);
              }
            };
            // The nodes of ring d at heights ck +- reach (the ring entered at a smaller reach).
            const auto extend = [&](long d, long reach) {
              const long below = ck - reach, above = ck + reach;
              for(std::size_t a = 0; a < size[d]; ++a) {
                const Ring_stack& t = ring[d][a];
                for(const Stack_entry* e = t.cursor; e != t.begin && long((e - 1)->k) >= below;) {
                  --e;
                  if(long(e->k) == below)
                    take(e);
                }
                for(const Stack_entry* e = t.cursor; e != t.end && long(e->k) <= above; ++e)
                  if(long(e->k) == above)
                    take(e);
              }
            };
            // The 3 x 3 x 3 cells, else the smallest block (up to 7 x 7 x 7) holding k others.
            r.clear();
            enter(0, 1), enter(1, 1);
            for(long reach = 2; reach <= maximum_reach && r.size() < k; ++reach) {
              for(long d = 0; d < reach; ++d)
                extend(d, reach);
              enter(reach, reach);
            }
            keep_nearest(r, v);
          }
        }
      });
    } else {
      SAI::Parallel_workspaces<Candidates> parallel(m_o.threads);
      const std::size_t block = 256;
      parallel.for_each(0, (n + block - 1) / block, [&](std::size_t b, Candidates& r) {
        for(std::size_t v = b * block; v < (std::min)(n, (b + 1) * block); ++v) {
          if(m_wall[first_of_node[v]])
            continue; // walls have no edges
          tree.k_nearest(c[v], k + 1, r);
          std::size_t m = 0;
          for(const auto& q : r)
            if(q.second != v && m < k && m_wall[first_of_node[q.second]] == m_wall[first_of_node[v]])
              knn[v * k + m++] = q.second;
        }
      });
    }
    // The edges, each once: from its first node unless the other holds it too and is smaller.
    std::vector<char> emit(n * k, 0);
    m_adjacent_first.assign(n + 1, 0);
    for(std::size_t v = 0; v < n; ++v) {
      std::size_t degree = 0;
      for(std::size_t m = 0; m < k; ++m) {
        const std::uint32_t u = knn[v * k + m];
        if(u == none)
          break;
        bool twice = false;
        if(u < v) {
          const std::uint32_t* row = knn.data() + u * k; // `none` never matches: a full scan
          for(std::size_t j = 0; j < k; ++j)
            twice |= row[j] == v;
        }
        const char once = twice ? 0 : 1; // (no branch)
        emit[v * k + m] = once, degree += std::size_t(once), m_adjacent_first[u + 1] += std::size_t(once);
      }
      m_adjacent_first[v + 1] += degree;
    }
    for(std::size_t v = 0; v < n; ++v)
      m_adjacent_first[v + 1] += m_adjacent_first[v];
    m_adjacent.assign(m_adjacent_first[n], 0);
    m_adjacent_weight.assign(m_adjacent_first[n], 0);
    std::vector<std::size_t> fill(m_adjacent_first.begin(), m_adjacent_first.end() - 1);
    const double s2 = m_o.sigma * m_o.sigma;
    for(std::size_t v = 0; v < n; ++v)
      for(std::size_t m = 0; m < k; ++m) {
        if(!emit[v * k + m])
          continue;
        const std::uint32_t u = knn[v * k + m];
        const std::uint32_t a = (std::min)(std::uint32_t(v), u), b = (std::max)(std::uint32_t(v), u);
        const double d2 = (c[a] - c[b]).squared_length();
        const double w = std::exp(-d2 / s2) * (std::min)(m_count[a], m_count[b]);
        m_adjacent[fill[a]] = b, m_adjacent_weight[fill[a]++] = w;
        m_adjacent[fill[b]] = a, m_adjacent_weight[fill[b]++] = w;
      }
    // Per node, its neighbours by increasing index (an insertion sort: the lists are short).
    for(std::size_t v = 0; v < n; ++v)
      for(std::size_t e = m_adjacent_first[v] + 1; e < m_adjacent_first[v + 1]; ++e) {
        const std::uint32_t a = m_adjacent[e];
        const double w = m_adjacent_weight[e];
        std::size_t f = e;
        for(; f > m_adjacent_first[v] && m_adjacent[f - 1] > a; --f)
          m_adjacent[f] = m_adjacent[f - 1], m_adjacent_weight[f] = m_adjacent_weight[f - 1];
        m_adjacent[f] = a, m_adjacent_weight[f] = w;
      }
  }

  // Wall points have their own cells: a high bit of the key that voxel keys never use.
  std::uint64_t wall_bit(std::uint32_t i) const { return m_wall[i] ? (std::uint64_t(1) << 63) : 0; }

  const std::vector<P3>& m_p;
  const Segmentation_options& m_o;
  std::vector<char> m_wall;
  double m_side = 1.0;
  P3 m_lo{{0, 0, 0}};
  const Point_columns& m_pc;
  Key_lists m_node_columns, m_wall_node_columns;
  std::vector<std::uint32_t> m_node_of_point, m_members, m_adjacent;
  std::vector<std::size_t> m_member_first, m_adjacent_first;
  std::vector<P3> m_centroid;
  std::vector<double> m_count, m_adjacent_weight;
};

// A small graph of one object: nodes with a penalty (to the sink) and a hard side, weighted
// edges; contracted by heavy-edge matching.
struct Object_graph
{
  std::vector<double> reward, penalty, points, cells; // per node: foreground reward (to the source), background
                                                      // penalty (to the sink), point count, fine nodes
  std::vector<char> seed;                     // per node: hard foreground
  std::vector<std::array<std::uint32_t, 2>> edges;
  std::vector<double> weight;
  std::vector<std::uint32_t> coarse; // per fine node: its node after contraction

  void clear()
  {
    reward.clear(), penalty.clear(), points.clear(), cells.clear(), seed.clear(), edges.clear(), weight.clear(), coarse.clear();
  }

  // Merges pairs of nodes joined by their heaviest edge (seeds only with seeds) until at most
  // `target` nodes remain or a round merges less than 5% of them.
  void contract(std::size_t target)
  {
    const std::size_t fine = penalty.size();
    coarse.resize(fine);
    std::iota(coarse.begin(), coarse.end(), 0u);
    std::vector<std::size_t> first;
    std::vector<std::pair<std::uint32_t, double>> adjacent;
    std::vector<std::uint32_t> mate, rename;
    while(target > 0 && penalty.size() > target) {
      const std::size_t n = penalty.size();
      first.assign(n + 1, 0);
      for(const auto& e : edges)
        ++first[e[0] + 1], ++first[e[1] + 1];
      for(std::size_t v = 0; v < n; ++v)
        first[v + 1] += first[v];
      adjacent.resize(2 * edges.size());
      {
        std::vector<std::size_t> fill(first.begin(), first.end() - 1);
        for(std::size_t e = 0; e < edges.size(); ++e) {
          adjacent[fill[edges[e][0]]++] = {edges[e][1], weight[e]};
          adjacent[fill[edges[e][1]]++] = {edges[e][0], weight[e]};
        }
      }
      const std::uint32_t unmatched = std::numeric_limits<std::uint32_t>::max();
      mate.assign(n, unmatched);
      std::size_t merges = 0;
      for(std::size_t v = 0; v < n && n - merges > target; ++v) {
        if(mate[v] != unmatched)
          continue;
        std::uint32_t best = unmatched;
        double best_w = 0;
        for(std::size_t a = first[v]; a < first[v + 1]; ++a) {
          const std::uint32_t u = adjacent[a].first;
          if(u == v || mate[u] != unmatched || seed[u] != seed[v])
            continue;
          if(adjacent[a].second > best_w || (adjacent[a].second == best_w && u < best)) {
            best_w = adjacent[a].second;
            best = u;
          }
        }
        if(best == unmatched)
          continue;
        mate[v] = best, mate[best] = std::uint32_t(v);
        ++merges;
      }
      if(merges < n / 20 + 1)
        break;
      rename.assign(n, unmatched);
      std::uint32_t next = 0;
      for(std::size_t v = 0; v < n; ++v)
        if(rename[v] == unmatched) {
          rename[v] = next;
          if(mate[v] != unmatched)
            rename[mate[v]] = next;
          ++next;
        }
      std::vector<double> re(next, 0), pe(next, 0), po(next, 0), ce(next, 0);
      std::vector<char> se(next, 0);
      for(std::size_t v = 0; v < n; ++v) {
        re[rename[v]] += reward[v], pe[rename[v]] += penalty[v], po[rename[v]] += points[v], ce[rename[v]] += cells[v];
        se[rename[v]] = seed[v];
      }
      reward.swap(re), penalty.swap(pe), points.swap(po), cells.swap(ce), seed.swap(se);
      // Edges: renamed, self loops dropped, parallel ones summed.
      std::vector<std::pair<std::array<std::uint32_t, 2>, double>> merged;
      merged.reserve(edges.size());
      for(std::size_t e = 0; e < edges.size(); ++e) {
        std::uint32_t a = rename[edges[e][0]], b = rename[edges[e][1]];
        if(a == b)
          continue;
        if(a > b)
          std::swap(a, b);
        merged.push_back({{{a, b}}, weight[e]});
      }
      std::sort(merged.begin(), merged.end(),
                [](const auto& x, const auto& y) { return x.first < y.first; });
      edges.clear(), weight.clear();
      for(const auto& m : merged) {
        if(!edges.empty() && edges.back() == m.first)
          weight.back() += m.second;
        else
          edges.push_back(m.first), weight.push_back(m.second);
      }
      for(std::uint32_t& c : coarse)
        c = rename[c];
    }
  }
};

// Per-thread buffers of the segmentation of objects.
struct Segmentation_workspace
{
  SAI::Terminal_min_cut cut;
  Object_graph graph;
  std::vector<std::uint32_t> local_of, nodes, candidates;
};

// The data term per point at horizontal distance d from the location, for the background radius
// R, in two linear ramps: a foreground reward (the cost of putting the point in the background)
// falling from `background_weight` at the location to 0 at R, then a background penalty (the
// cost of putting it in the foreground) rising from 0 at R to `outer_factor` times that weight
// at R + ramp_width; beyond, the hard background.
inline double foreground_reward(double d, double R, const Segmentation_options& o)
{
  return d < R ? o.background_weight * (1 - d / R) : 0.0;
}
inline double background_penalty(double d, double R, const Segmentation_options& o)
{
  return d <= R ? 0.0 : o.background_weight * o.outer_factor * (std::min)(1.0, (d - R) / o.ramp_width);
}

// The hard foreground: the point nearest to the vertical segment from the location up to
// `height` above it (the thesis takes the point nearest to the segment's top; the segment
// prefers the object to a wall right behind it), the nearest to the top among equally near
// ones, and its three nearest neighbours, among `candidates` (in any order); empty when there is none.
inline std::vector<std::uint32_t> foreground_seeds(const std::vector<P3>& p, const std::vector<std::uint32_t>& candidates,
                                                   const P3& location, double height)
{
  std::vector<std::uint32_t> seeds;
  if(candidates.empty())
    return seeds;
  const P3 target{{location[0], location[1], location[2] + height}};
  auto d2 = [&](const P3& a, const P3& b) {
    return (a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) + (a[2] - b[2]) * (a[2] - b[2]);
  };
  const double z0 = (std::min)(location[2], target[2]), z1 = (std::max)(location[2], target[2]);
  auto to_segment = [&](const P3& a) {
    const double z = (std::min)(z1, (std::max)(z0, a[2]));
    return d2(a, P3{{location[0], location[1], z}});
  };
  std::uint32_t best = candidates.front();
  double best_d = to_segment(p[best]), best_top = d2(p[best], target);
  for(std::uint32_t i : candidates) {
    const double d = to_segment(p[i]), top = d2(p[i], target);
    if(d < best_d || (d == best_d && (top < best_top || (top == best_top && i < best)))) // ties: the first point
      best_d = d, best_top = top, best = i;
  }
  std::vector<std::pair<double, std::uint32_t>> near;
  for(std::uint32_t i : candidates)
    if(i != best)
      near.emplace_back(d2(p[i], p[best]), i);
  const std::size_t m = (std::min)(near.size(), std::size_t(3));
  std::partial_sort(near.begin(), near.begin() + long(m), near.end());
  seeds.push_back(best);
  for(std::size_t k = 0; k < m; ++k)
    seeds.push_back(near[k].second);
  return seeds;
}

// The hard foreground of the object at `location` among the points within 2 m of it (within the
// graph of radius R when there is none).
inline std::vector<std::uint32_t> object_seeds(const Segmentation_index& index, const P3& location, double R,
                                               const Segmentation_options& o, std::vector<std::uint32_t>& candidates)
{
  index.points_off_walls_within(location, (std::min)(R + o.ramp_width, 2.0), candidates);
  if(candidates.empty())
    index.points_off_walls_within(location, R + o.ramp_width, candidates);
  return foreground_seeds(index.points(), candidates, location, o.foreground_height);
}

// One min-cut at background radius R: fills `w.graph` (and w.nodes, the index's nodes of the
// graph), solves, and returns the foreground nodes (indices into w.nodes) with the cut cost:
// the weight of the edges cut, inside the graph and to the hard background beyond it, over the
// mean point count of the foreground's nodes (so that with one point per node it is the plain
// sum of the Gaussian weights cut).
struct Cut_outcome
{
  std::vector<std::uint32_t> foreground; // positions in w.nodes
  double cut = 0;
  std::size_t points = 0;
};

inline void build_object_graph(const Segmentation_index& index, const P3& location, double R,
                               const std::vector<std::uint32_t>& seed_points, const Segmentation_options& o,
                               Segmentation_workspace& w, std::vector<double>& outside, bool with_walls = false)
{
  index.nodes_within(location, R + o.ramp_width, w.nodes, with_walls);
  if(w.local_of.size() < index.number_of_nodes())
    w.local_of.assign(index.number_of_nodes(), Segmentation_index::none);
  for(std::size_t k = 0; k < w.nodes.size(); ++k)
    w.local_of[w.nodes[k]] = std::uint32_t(k);
  Object_graph& g = w.graph;
  g.clear();
  const std::size_t n = w.nodes.size();
  g.reward.resize(n), g.penalty.resize(n), g.points.resize(n), g.cells.assign(n, 1.0), g.seed.assign(n, 0);
  outside.assign(n, 0.0);
  for(std::size_t k = 0; k < n; ++k) {
    const std::uint32_t v = w.nodes[k];
    g.points[k] = index.count(v);
    const double d = horizontal_distance(index.centroid(v), location);
    g.reward[k] = index.count(v) * foreground_reward(d, R, o);
    g.penalty[k] = index.count(v) * background_penalty(d, R, o);
    index.for_adjacent(v, [&](std::uint32_t u, double weight) {
      const std::uint32_t l = w.local_of[u];
      if(l == Segmentation_index::none)
        outside[k] += weight;
      else if(l > k)
        g.edges.push_back({{std::uint32_t(k), l}}), g.weight.push_back(weight);
    });
    g.penalty[k] += outside[k];
  }
  // The hard foreground: the nodes of the seed points and, with cells, the `seed_neighbors`
  // nodes nearest to the first one (the thesis' point and its three neighbours, on nodes).
  std::vector<std::uint32_t> seed_nodes;
  for(std::uint32_t i : seed_points)
    seed_nodes.push_back(index.node_of_point(i));
  if(!seed_points.empty() && o.cell > 0 && seed_nodes.front() != Segmentation_index::none) {
    const std::uint32_t v0 = seed_nodes.front();
    std::vector<std::pair<double, std::uint32_t>> near;
    index.for_adjacent(v0, [&](std::uint32_t u, double) {
      const P3& a = index.centroid(u);
      const P3& b = index.centroid(v0);
      near.emplace_back((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) + (a[2] - b[2]) * (a[2] - b[2]), u);
    });
    std::sort(near.begin(), near.end());
    for(std::size_t k = 0; k < near.size() && k < o.seed_neighbors; ++k)
      seed_nodes.push_back(near[k].second);
  }
  for(std::uint32_t v : seed_nodes)
    if(v != Segmentation_index::none && w.local_of[v] != Segmentation_index::none)
      g.seed[w.local_of[v]] = 1;
  for(std::uint32_t v : w.nodes)
    w.local_of[v] = Segmentation_index::none;
}

// The nodes of the source side connected to a seed through edges of the source side: the
// foreground (the reward of the data term would otherwise add any separate cluster within the
// radius for free).
inline std::vector<char> connected_to_seeds(std::size_t n, const std::vector<std::array<std::uint32_t, 2>>& edges,
                                            const std::vector<char>& seed, const std::vector<char>& source_side)
{
  std::vector<std::size_t> first(n + 1, 0);
  for(const auto& e : edges)
    if(source_side[e[0]] && source_side[e[1]])
      ++first[e[0] + 1], ++first[e[1] + 1];
  for(std::size_t v = 0; v < n; ++v)
    first[v + 1] += first[v];
  std::vector<std::uint32_t> adjacent(first[n]);
  {
    std::vector<std::size_t> fill(first.begin(), first.end() - 1);
    for(const auto& e : edges)
      if(source_side[e[0]] && source_side[e[1]])
        adjacent[fill[e[0]]++] = e[1], adjacent[fill[e[1]]++] = e[0];
  }
  std::vector<char> reached(n, 0);
  std::vector<std::uint32_t> stack;
  for(std::size_t v = 0; v < n; ++v)
    if(seed[v] && source_side[v])
      reached[v] = 1, stack.push_back(std::uint32_t(v));
  while(!stack.empty()) {
    const std::uint32_t v = stack.back();
    stack.pop_back();
    for(std::size_t a = first[v]; a < first[v + 1]; ++a)
      if(!reached[adjacent[a]])
        reached[adjacent[a]] = 1, stack.push_back(adjacent[a]);
  }
  return reached;
}

inline Cut_outcome min_cut_at_radius(const Segmentation_index& index, const P3& location, double R,
                                     const std::vector<std::uint32_t>& seed_points, const Segmentation_options& o,
                                     Segmentation_workspace& w)
{
  std::vector<double> outside;
  build_object_graph(index, location, R, seed_points, o, w, outside);
  Object_graph& g = w.graph;
  const std::size_t fine = g.penalty.size();
  // Per fine node, the weight to the hard background beyond the graph (already in its penalty).
  std::vector<double> fine_outside = outside;
  g.contract(o.maximum_nodes);
  if(g.coarse.empty()) {
    g.coarse.resize(fine);
    std::iota(g.coarse.begin(), g.coarse.end(), 0u);
  }
  const std::size_t n = g.penalty.size();
  std::vector<double> coarse_outside(n, 0.0);
  for(std::size_t k = 0; k < fine; ++k)
    coarse_outside[g.coarse[k]] += fine_outside[k];
  SAI::Terminal_min_cut& cut = w.cut;
  cut.reset(n);
  for(std::size_t e = 0; e < g.edges.size(); ++e)
    cut.add_edge(g.edges[e][0], g.edges[e][1], g.weight[e]);
  for(std::size_t k = 0; k < n; ++k) {
    cut.set_terminal_capacity(k, g.reward[k], g.penalty[k]);
    if(g.seed[k])
      cut.constrain(k, SAI::Terminal_min_cut::SOURCE);
  }
  cut.solve();
  std::vector<char> source_side(n);
  for(std::size_t k = 0; k < n; ++k)
    source_side[k] = cut.is_source_side(k) ? 1 : 0;
  const std::vector<char> fg = connected_to_seeds(n, g.edges, g.seed, source_side);
  Cut_outcome r;
  double edge_cut = 0, fg_points = 0, fg_cells = 0;
  for(std::size_t e = 0; e < g.edges.size(); ++e)
    if(fg[g.edges[e][0]] != fg[g.edges[e][1]])
      edge_cut += g.weight[e];
  for(std::size_t k = 0; k < n; ++k)
    if(fg[k]) {
      edge_cut += coarse_outside[k];
      fg_points += g.points[k];
      fg_cells += g.cells[k];
    }
  for(std::size_t k = 0; k < fine; ++k)
    if(fg[g.coarse[k]])
      r.foreground.push_back(std::uint32_t(k));
  r.points = std::size_t(fg_points + 0.5);
  r.cut = fg_cells > 0 ? edge_cut / (fg_points / fg_cells) : 0.0;
  return r;
}

// Segments the object at `location` (index built with the graph for min-cut methods).
inline Segmentation_output segment_one(const Segmentation_index& index, const P3& location,
                                       const Segmentation_options& o, Segmentation_workspace& w)
{
  const auto start = std::chrono::steady_clock::now();
  Segmentation_output out;
  const std::vector<P3>& p = index.points();
  if(o.kind == Segmentation_kind::ALL || o.kind == Segmentation_kind::COMPONENTS) {
    index.points_within(location, o.radius, w.candidates);
    const std::vector<std::uint32_t> seeds = foreground_seeds(p, w.candidates, location, o.foreground_height);
    out.radius = o.radius;
    if(!seeds.empty())
      out.seed = seeds.front();
    if(o.kind == Segmentation_kind::ALL || w.candidates.empty())
      out.points.assign(w.candidates.begin(), w.candidates.end());
    else {
      std::vector<P3> q;
      q.reserve(w.candidates.size());
      std::size_t seed_k = 0;
      for(std::size_t k = 0; k < w.candidates.size(); ++k) {
        q.push_back(p[w.candidates[k]]);
        if(w.candidates[k] == out.seed)
          seed_k = k;
      }
      P3 lo, hi;
      checked_bounds(q, o.spacing, "segment_objects", lo, hi);
      std::size_t components = 0;
      const std::vector<std::uint32_t> c = voxel_components(q, std::vector<char>(q.size(), 1), o.spacing, lo, components);
      for(std::size_t k = 0; k < q.size(); ++k)
        if(c[k] == c[seed_k])
          out.points.push_back(w.candidates[k]);
    }
  } else {
    const double largest = o.kind == Segmentation_kind::MIN_CUT ? o.radius : o.radii.back();
    const std::vector<std::uint32_t> seeds = object_seeds(index, location, largest, o, w.candidates);
    if(!seeds.empty()) {
      out.seed = seeds.front();
      const std::vector<double> fixed{o.radius};
      const std::vector<double>& radii = o.kind == Segmentation_kind::MIN_CUT ? fixed : o.radii;
      Cut_outcome best;
      std::vector<std::uint32_t> best_nodes;
      double best_radius = radii.back();
      // The first radius whose foreground is big enough with a cut cost under the threshold;
      // when none is, the smallest radius with a foreground big enough (a larger radius that
      // does not give a clean cut only takes more of what the object touches), else the largest.
      bool fallback_big = false;
      for(double R : radii) {
        Cut_outcome c = min_cut_at_radius(index, location, R, seeds, o, w);
        const bool big = c.points > o.minimum_foreground;
        if(radii.size() == 1 || (big && c.cut < o.maximum_cut)) {
          best = std::move(c), best_nodes = w.nodes, best_radius = R;
          break;
        }
        if((big && !fallback_big) || (!fallback_big && R == radii.back())) {
          fallback_big = big;
          best = std::move(c), best_nodes = w.nodes, best_radius = R;
        }
      }
      out.radius = best_radius;
      out.cut = best.cut;
      for(std::uint32_t k : best.foreground)
        index.for_members(best_nodes[k], [&](std::uint32_t i) { out.points.push_back(i); });
      std::sort(out.points.begin(), out.points.end());
    } else
      out.radius = o.kind == Segmentation_kind::MIN_CUT ? o.radius : o.radii.back();
  }
  out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return out;
}

} // namespace internal
} // namespace Point_set_object_recognition
} // namespace CGAL

#endif // CGAL_POINT_SET_OBJECT_RECOGNITION_INTERNAL_OBJECT_SEGMENTATION_H
