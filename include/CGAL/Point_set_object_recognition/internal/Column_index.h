// Copyright (c) 2026 CGAL Global Shape Analysis contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_POINT_SET_OBJECT_RECOGNITION_INTERNAL_COLUMN_INDEX_H
#define CGAL_POINT_SET_OBJECT_RECOGNITION_INTERNAL_COLUMN_INDEX_H

// Items by the columns (i, j) of a horizontal grid, for the segmentation of objects: a hash map
// from 64-bit keys, the index of a grid's columns and the lists of items per column; and the
// horizontal distance their queries go by.

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Point_set_object_recognition {
namespace internal {

typedef std::array<double, 3> P3;

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
// probing: the grids of the segmentation look up millions of keys, most of them absent (0.52 of
// the time of std::unordered_map on a street's cells: bench/spatial_indexes.cpp, key_map_street).
class Key_map
{
public:
  static constexpr std::uint32_t none = std::numeric_limits<std::uint32_t>::max();

  explicit Key_map(std::size_t expected = 0) { reserve(expected); }

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

  // The box of columns given to reset(): [i_first(), i_last()] x [j_first(), j_last()].
  long i_first() const { return m_i0; }
  long j_first() const { return m_j0; }
  long i_last() const { return m_i0 + m_ni - 1; }
  long j_last() const { return m_j0 + m_nj - 1; }

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
    // Only the columns of the index's box are visited, however large `radius` (the bounds are
    // clamped in floating point before any conversion, so that 1e300 is no overflow either).
    long i0, i1, j0, j1;
    if(!span(at[0] - radius - lo[0], at[0] + radius - lo[0], side, index.i_first(), index.i_last(), i0, i1) ||
       !span(at[1] - radius - lo[1], at[1] + radius - lo[1], side, index.j_first(), index.j_last(), j0, j1))
      return;
    for(long j = j0; j <= j1; ++j)
      for(long i = i0; i <= i1; ++i) {
        const std::uint32_t c = find(Column_index::key(i, j));
        if(c != Key_map::none)
          g(i, j, c);
      }
  }

  // The columns [x0, x1] of [first, last] that meet [a, b] (offsets from the grid's origin),
  // false when none does.
  static bool span(double a, double b, double side, long first, long last, long& x0, long& x1)
  {
    const double f0 = std::floor(a / side), f1 = std::floor(b / side);
    if(!(f0 <= double(last)) || !(f1 >= double(first)))
      return false;
    x0 = f0 <= double(first) ? first : long(f0);
    x1 = f1 >= double(last) ? last : long(f1);
    return x0 <= x1;
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

} // namespace internal
} // namespace Point_set_object_recognition
} // namespace CGAL

#endif // CGAL_POINT_SET_OBJECT_RECOGNITION_INTERNAL_COLUMN_INDEX_H
