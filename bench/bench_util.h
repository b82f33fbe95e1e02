// Copyright (c) 2026 CGAL Global Shape Analysis contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_SHAPE_ANALYSIS_BENCH_BENCH_UTIL_H
#define CGAL_SHAPE_ANALYSIS_BENCH_BENCH_UTIL_H

// What every benchmark program needs: the seconds since a time point, and the items of a
// comma-separated command-line list.

#include <chrono>
#include <cstddef>
#include <sstream>
#include <string>
#include <vector>

namespace bench_util {

inline double seconds_since(std::chrono::steady_clock::time_point start)
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// The non-empty items of "a,b,c".
inline std::vector<std::string> split(const std::string& list)
{
  std::vector<std::string> items;
  std::stringstream in(list);
  std::string item;
  while(std::getline(in, item, ','))
    if(!item.empty())
      items.push_back(item);
  return items;
}

// The numbers of "1,2,3" (std::stoull: throws on an item that is not one).
inline std::vector<unsigned long long> split_numbers(const std::string& list)
{
  std::vector<unsigned long long> numbers;
  for(const std::string& item : split(list))
    numbers.push_back(std::stoull(item));
  return numbers;
}

} // namespace bench_util

#endif // CGAL_SHAPE_ANALYSIS_BENCH_BENCH_UTIL_H
