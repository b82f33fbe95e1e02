// Copyright (c) 2026 CGAL Global Shape Analysis contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_POINT_SET_OBJECT_RECOGNITION_INTERNAL_WALL_DETECTION_H
#define CGAL_POINT_SET_OBJECT_RECOGNITION_INTERNAL_WALL_DETECTION_H

// The points of the walls (facades) of a scene, which the segmentation of objects keeps apart
// (the wall constants of Segmentation_options.h): the tall columns, those whose high points
// spread along a line, the fine cells where those high points stack, and the points under them.

#include <CGAL/Point_set_object_recognition/internal/Column_index.h>
#include <CGAL/Point_set_object_recognition/internal/Point_columns.h>
#include <CGAL/Point_set_object_recognition/internal/Segmentation_options.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

namespace CGAL {
namespace Point_set_object_recognition {
namespace internal {

class Wall_finder
{
public:
  explicit Wall_finder(const Point_columns& columns)
    : m_p(columns.points()), m_lo(columns.lo()), m_hi(columns.hi()), m_s(wall_column_side)
  {}

  // Flags the points of `active` (increasing) that lie on a wall in `wall` (per point), and with
  // `drop_walls` removes them from `active`. The passes go over `active` in order (the points'
  // columns found once), not column by column.
  void find(std::vector<std::uint32_t>& active, bool drop_walls, std::vector<char>& wall)
  {
    wall.assign(m_p.size(), 0);
    if(active.empty())
      return;
    assign_columns(active);
    if(!find_tall_columns())
      return;
    sum_high_points(active);
    find_spread_columns();
    stack_high_points(active);
    mark_wall_cells();
    flag_points(active, drop_walls, wall);
  }

private:
  static constexpr std::uint32_t none = std::numeric_limits<std::uint32_t>::max();
  static constexpr unsigned char outside = 255;
  struct Stack { double lo, hi; int n; std::uint64_t key; };

  std::uint64_t column_key(const P3& q) const
  {
    return Column_index::key(long((q[0] - m_lo[0]) / m_s), long((q[1] - m_lo[1]) / m_s));
  }
  std::uint64_t fine_key(const P3& q) const
  {
    return Column_index::key(long((q[0] - m_lo[0]) / m_fine), long((q[1] - m_lo[1]) / m_fine));
  }
  static void add(Stack& st, double z, std::uint64_t key)
  {
    if(st.n == 0)
      st = Stack{z, z, 0, key};
    st.lo = (std::min)(st.lo, z), st.hi = (std::max)(st.hi, z), ++st.n;
  }

  // The columns of side s, numbered as they are met; per active point its column; per column
  // its key and the range of its heights.
  void assign_columns(const std::vector<std::uint32_t>& active)
  {
    {
      const std::uint64_t k0 = column_key(m_lo), k1 = column_key(m_hi);
      m_column.reset(long(k0 & 0xFFFFFFFFu), long(k0 >> 32), long(k1 & 0xFFFFFFFFu), long(k1 >> 32),
                     active.size() / 4 + 16);
    }
    // The fine cells (of side half the tolerance) of the high points of walls. When they divide
    // the columns exactly (a power of two of them along each axis, as by default: then a fine
    // cell lies in a single column), per point its fine cell in its column (`per` x `per` of
    // them, row by row; `outside` when there is none).
    m_fine = 0.5 * wall_line_tolerance;
    m_per = long(std::lround(m_s / m_fine));
    m_nested = m_per >= 1 && m_per <= 16 && (m_per & (m_per - 1)) == 0 && double(m_per) * m_fine == m_s;
    m_masks = m_nested && m_per * m_per <= 64; // then a column's fine cells are bits of a mask
    m_fine_of.assign(m_masks ? active.size() : 0, outside);
    m_column_of.assign(active.size(), 0);
    // (Consecutive points mostly share their column: the range goes by runs.)
    std::uint64_t run_key = 0;
    std::uint32_t run_column = none;
    double run_lo = 0, run_hi = 0;
    for(std::size_t a = 0; a < active.size(); ++a) {
      const P3& q = m_p[active[a]];
      std::uint64_t key;
      if(m_masks) {
        // The column from the fine cell: s = per fine exactly, per a power of two, so the
        // quotient by s is that by `fine` over per exactly, and its integer part that of the
        // fine cell over per.
        const std::uint64_t f = fine_key(q);
        const long fi = long(f & 0xFFFFFFFFu), fj = long(f >> 32);
        key = Column_index::key(fi / m_per, fj / m_per);
        m_fine_of[a] = (unsigned char)((fj % m_per) * m_per + fi % m_per);
      } else
        key = column_key(q);
      if(run_column == none || key != run_key) {
        if(run_column != none)
          m_range[run_column] = {{run_lo, run_hi}};
        const auto ins = m_column.emplace(key, std::uint32_t(m_keys.size()));
        if(ins.second)
          m_keys.push_back(key), m_range.push_back({{q[2], q[2]}});
        run_key = key, run_column = ins.first, run_lo = m_range[run_column][0], run_hi = m_range[run_column][1];
      }
      run_lo = (std::min)(run_lo, q[2]), run_hi = (std::max)(run_hi, q[2]);
      m_column_of[a] = run_column;
    }
    if(run_column != none)
      m_range[run_column] = {{run_lo, run_hi}};
  }

  // Per column, its lowest height when it is tall, NaN otherwise; whether there is a tall column.
  bool find_tall_columns()
  {
    const std::size_t nc = m_keys.size();
    m_tall.assign(nc, std::numeric_limits<double>::quiet_NaN());
    for(std::uint32_t c = 0; c < nc; ++c)
      if(m_range[c][1] - m_range[c][0] > wall_column_height)
        m_tall[c] = m_range[c][0], m_tall_columns.push_back(c);
    return !m_tall_columns.empty();
  }

  // Per tall column, the moments of its high points (relative to the grid's corner); the high
  // points (positions in `active`).
  void sum_high_points(const std::vector<std::uint32_t>& active)
  {
    const double high = 2.0; // above the lowest point of its column: above the small objects
    m_moments.assign(m_keys.size(), std::array<double, 6>{{0, 0, 0, 0, 0, 0}});
    m_high_points.reserve(active.size());
    // (By runs of points of one column, the sums in registers: the same additions in the same
    // order.)
    for(std::size_t a = 0; a < active.size();) {
      const std::uint32_t c = m_column_of[a];
      if(std::isnan(m_tall[c])) {
        for(++a; a < active.size() && m_column_of[a] == c; ++a) {
        }
        continue;
      }
      const double above = m_tall[c] + high;
      std::array<double, 6>& mc = m_moments[c];
      double m0 = mc[0], m1 = mc[1], m2 = mc[2], m3 = mc[3], m4 = mc[4], m5 = mc[5];
      for(; a < active.size() && m_column_of[a] == c; ++a) {
        const P3& q = m_p[active[a]];
        if(q[2] > above) {
          const double x = q[0] - m_lo[0], y = q[1] - m_lo[1];
          m0 += 1, m1 += x, m2 += y, m3 += x * x, m4 += x * y, m5 += y * y;
          m_high_points.push_back(std::uint32_t(a));
        }
      }
      mc = {{m0, m1, m2, m3, m4, m5}};
    }
  }

  // The tall columns whose high points around (within 0.5 m) spread along a line longer than
  // 0.2 m: a wall (or a tree; a pole does not).
  void find_spread_columns()
  {
    const int reach = int(std::ceil(0.5 / m_s));
    m_spread.assign(m_keys.size(), 0);
    for(std::uint32_t c : m_tall_columns) {
      const std::uint64_t key = m_keys[c];
      const long ci = long(key & 0xFFFFFFFFu), cj = long(key >> 32);
      double n = 0, sx = 0, sy = 0, sxx = 0, sxy = 0, syy = 0;
      for(long dj = -reach; dj <= reach; ++dj)
        for(long di = -reach; di <= reach; ++di) {
          if(ci + di < 0 || cj + dj < 0)
            continue;
          const std::uint32_t a = m_column.find(Column_index::key(ci + di, cj + dj));
          if(a == Key_map::none || std::isnan(m_tall[a]))
            continue;
          const std::array<double, 6>& m = m_moments[a];
          n += m[0], sx += m[1], sy += m[2], sxx += m[3], sxy += m[4], syy += m[5];
        }
      if(n < 10)
        continue;
      const double mx = sx / n, my = sy / n;
      const double a = sxx / n - mx * mx, b = sxy / n - mx * my, d = syy / n - my * my;
      const double l1 = 0.5 * (a + d) + std::sqrt(0.25 * (a - d) * (a - d) + b * b);
      if(!(std::sqrt(l1) > 0.2))
        continue; // a pole
      m_spread[c] = 1, ++m_spread_columns;
    }
  }

  // The high points of those columns mark the fine cells under them, with the range of their
  // heights; column by column (the high points grouped by column, in order). When the fine
  // cells divide the columns exactly (a power of two of them along each axis, as by default:
  // then a fine cell lies in a single column), the stacks of the column are gathered in a small
  // array of its fine cells; else (and for a point rounded out of its column) in a map.
  void stack_high_points(const std::vector<std::uint32_t>& active)
  {
    if(m_spread_columns == 0)
      return;
    const std::size_t nc = m_keys.size();
    std::vector<std::uint32_t> first(nc + 1, 0);
    for(std::uint32_t a : m_high_points)
      if(m_spread[m_column_of[a]])
        ++first[m_column_of[a] + 1];
    for(std::size_t c = 0; c < nc; ++c)
      first[c + 1] += first[c];
    std::vector<std::uint32_t> by_column(first[nc]);
    {
      std::vector<std::uint32_t> fill(first.begin(), first.end() - 1);
      for(std::uint32_t a : m_high_points)
        if(m_spread[m_column_of[a]])
          by_column[fill[m_column_of[a]]++] = a;
    }
    Key_map stack_of; // fine cell -> its stack of high points of walls
    std::vector<Stack> local(m_nested ? std::size_t(m_per * m_per) : 0);
    for(std::uint32_t c = 0; c < nc; ++c) {
      if(first[c] == first[c + 1])
        continue;
      const long ci = long(m_keys[c] & 0xFFFFFFFFu), cj = long(m_keys[c] >> 32);
      if(m_nested)
        std::fill(local.begin(), local.end(), Stack{0, 0, 0, 0});
      for(std::uint32_t h = first[c]; h < first[c + 1]; ++h) {
        const P3& p = m_p[active[by_column[h]]];
        if(m_masks && m_fine_of[by_column[h]] != outside) {
          const long f = m_fine_of[by_column[h]], li = f % m_per, lj = f / m_per;
          add(local[std::size_t(f)], p[2], Column_index::key(m_per * ci + li, m_per * cj + lj));
          continue;
        }
        const std::uint64_t key = fine_key(p);
        if(m_nested) {
          const long li = long(key & 0xFFFFFFFFu) - m_per * ci, lj = long(key >> 32) - m_per * cj;
          if(li >= 0 && lj >= 0 && li < m_per && lj < m_per) {
            add(local[std::size_t(lj * m_per + li)], p[2], key);
            continue;
          }
        }
        const auto ins = stack_of.emplace(key, std::uint32_t(m_stacks.size()));
        if(ins.second)
          m_stacks.push_back(Stack{0, 0, 0, key});
        add(m_stacks[ins.first], p[2], key);
      }
      if(m_nested)
        for(const Stack& st : local)
          if(st.n > 0)
            m_stacks.push_back(st);
    }
  }

  // A wall's fine cells stack several high points over a metre at least (a crown's do not).
  // The cells of walls and their eight neighbours: with nested fine cells (at most 8 x 8 per
  // column), bits of a mask per column; else in a map.
  void mark_wall_cells()
  {
    m_mask.assign(m_masks ? m_keys.size() : 0, 0);
    for(const Stack& st : m_stacks)
      if(st.n >= 3 && st.hi - st.lo > 1.0) {
        const long fi = long(st.key & 0xFFFFFFFFu), fj = long(st.key >> 32);
        for(long dj = -1; dj <= 1; ++dj) // the cell and its eight neighbours
          for(long di = -1; di <= 1; ++di) {
            const long gi = fi + di, gj = fj + dj;
            if(gi < 0 || gj < 0)
              continue;
            if(!m_masks) {
              m_high_cells.emplace(Column_index::key(gi, gj), 1);
              continue;
            }
            const std::uint32_t a = m_column.find(Column_index::key(gi / m_per, gj / m_per));
            if(a != Key_map::none) // else no point lies in that cell
              m_mask[a] |= std::uint64_t(1) << ((gj % m_per) * m_per + gi % m_per);
          }
      }
  }

  // The points under the high points of walls: the walls' lower parts.
  // (With `drop_walls`, the points off walls move to the front of `active` as they are met.)
  void flag_points(std::vector<std::uint32_t>& active, bool drop_walls, std::vector<char>& wall) const
  {
    std::size_t off = 0;
    if(m_masks)
      for(std::size_t a = 0; a < active.size(); ++a) {
        const std::uint32_t i = active[a];
        const std::uint64_t m = m_mask[m_column_of[a]];
        const bool on_wall = m != 0 && m_fine_of[a] != outside && ((m >> m_fine_of[a]) & 1) != 0;
        wall[i] = on_wall ? 1 : 0;
        active[off] = i;
        off += on_wall && drop_walls ? 0 : 1; // (no branch)
      }
    else {
      if(!m_high_cells.empty())
        for(std::uint32_t i : active)
          wall[i] = m_high_cells.find(fine_key(m_p[i])) != Key_map::none ? 1 : 0;
      for(std::size_t a = 0; a < active.size(); ++a)
        if(!drop_walls || !wall[active[a]])
          active[off++] = active[a];
    }
    active.resize(off);
  }

  const std::vector<P3>& m_p;
  const P3 m_lo, m_hi;
  const double m_s;    // the side of the columns
  double m_fine = 0;   // the side of the fine cells
  long m_per = 0;      // fine cells per column along an axis
  bool m_nested = false, m_masks = false;
  Column_index m_column;                     // key -> column
  std::vector<std::uint64_t> m_keys;         // per column, its key
  std::vector<std::array<double, 2>> m_range; // per column, its lowest and highest heights
  std::vector<std::uint32_t> m_column_of;    // per active point, its column
  std::vector<unsigned char> m_fine_of;      // per active point, its fine cell in its column
  std::vector<double> m_tall;
  std::vector<std::uint32_t> m_tall_columns, m_high_points;
  std::vector<std::array<double, 6>> m_moments;
  std::vector<char> m_spread;
  std::size_t m_spread_columns = 0;
  std::vector<Stack> m_stacks;
  std::vector<std::uint64_t> m_mask;
  Key_map m_high_cells;
};

} // namespace internal
} // namespace Point_set_object_recognition
} // namespace CGAL

#endif // CGAL_POINT_SET_OBJECT_RECOGNITION_INTERNAL_WALL_DETECTION_H
