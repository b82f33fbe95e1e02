// Copyright (c) 2026 CGAL Global Shape Analysis contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_SHAPE_ANALYSIS_INTERNAL_POINT_TREE_H
#define CGAL_SHAPE_ANALYSIS_INTERNAL_POINT_TREE_H

// The nearest-neighbour queries of the graph machinery (component links, surface samples, the
// nodes of the point-cloud segmentation graph) on CGAL's kd-tree (Spatial_searching: Kd_tree with
// the sliding-midpoint splitter, Orthogonal_k_neighbor_search), behind the small interface the
// callers use: caller's ids, a distance bound, and the answers of a scan in the order given where
// the kd-tree leaves ties open (among points at the same distance, the ones given first).
// bench/spatial_indexes.cpp measures this against CGAL's kd-tree used directly.

#include <CGAL/Shape_analysis/internal/Vector_3d.h>

#include <CGAL/Kd_tree.h>
#include <CGAL/Orthogonal_k_neighbor_search.h>
#include <CGAL/Search_traits_3.h>
#include <CGAL/Search_traits_adapter.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/property_map.h>

#include <algorithm>
#include <cstdint>
#include <limits>
#include <memory>
#include <tuple>
#include <utility>
#include <vector>

namespace CGAL {
namespace Shape_analysis {
namespace internal {

class Point_tree
{
  typedef CGAL::Simple_cartesian<double> Kernel;
  typedef Kernel::Point_3 Point;

  // The kd-tree holds each distinct point once, with its number among the distinct points, in
  // its own arrays (a query then reads no other array: with positions alone it read 2.5 times
  // slower). Copies of a point are common (the samples of faces meeting at a vertex, up to
  // thousands at a fan's centre) and would make a tie of thousands for the kd-tree to sort out.
  typedef std::pair<Point, std::uint32_t> Entry;
  typedef CGAL::First_of_pair_property_map<Entry> Point_map;
  typedef CGAL::Search_traits_3<Kernel> Base_traits;
  typedef CGAL::Search_traits_adapter<Entry, Point_map, Base_traits> Traits;
  typedef CGAL::Orthogonal_k_neighbor_search<Traits> Search;
  typedef Search::Tree Tree;
  typedef Search::Distance Distance;

  struct Data
  {
    std::vector<Vector_3d> points;         // per distinct point
    std::vector<std::uint32_t> first_copy; // per distinct point, its copies' positions in
    std::vector<std::uint32_t> copies;     // copies[first_copy[i], first_copy[i + 1]), increasing
    std::vector<std::uint32_t> ids;        // per position, the caller's id
    std::unique_ptr<Tree> tree;
  };

public:
  typedef std::pair<double, std::uint32_t> Candidate; // squared distance, id (or position)

  Point_tree() = default;

  // `ids[k]` is the caller's id of point `points[k]`.
  Point_tree(const std::vector<Vector_3d>& points, const std::vector<std::uint32_t>& ids)
  {
    if(points.empty())
      return;
    auto d = std::make_shared<Data>();
    d->ids = ids;
    // Copies found by sorting the positions by coordinates (in one array).
    struct Keyed
    {
      double x, y, z;
      std::uint32_t i;
      bool operator<(const Keyed& o) const { return std::tie(x, y, z) < std::tie(o.x, o.y, o.z); }
    };
    std::vector<Keyed> sorted(points.size());
    for(std::size_t i = 0; i < points.size(); ++i)
      sorted[i] = Keyed{points[i].x, points[i].y, points[i].z, std::uint32_t(i)};
    std::sort(sorted.begin(), sorted.end());
    std::vector<std::uint32_t> group(points.size()); // per position, its run of copies in `sorted`
    std::uint32_t runs = 0;
    for(std::size_t j = 0; j < sorted.size(); ++j) {
      if(j > 0 && sorted[j - 1] < sorted[j])
        ++runs;
      group[sorted[j].i] = runs;
    }
    // Distinct points numbered as they first come in the caller's order (the tree is built in
    // that order), each with its copies' positions, increasing.
    const std::uint32_t none = (std::numeric_limits<std::uint32_t>::max)();
    std::vector<std::uint32_t> number(std::size_t(runs) + 1, none), distinct_of(points.size());
    std::vector<Entry> entries;
    for(std::size_t i = 0; i < points.size(); ++i) {
      std::uint32_t& k = number[group[i]];
      if(k == none) {
        k = std::uint32_t(d->points.size());
        d->points.push_back(points[i]);
        entries.emplace_back(Point(points[i].x, points[i].y, points[i].z), k);
      }
      distinct_of[i] = k;
    }
    d->first_copy.assign(d->points.size() + 1, 0);
    for(std::uint32_t k : distinct_of)
      ++d->first_copy[k + 1];
    for(std::size_t k = 0; k < d->points.size(); ++k)
      d->first_copy[k + 1] += d->first_copy[k];
    d->copies.resize(points.size());
    std::vector<std::uint32_t> fill(d->first_copy.begin(), d->first_copy.end() - 1);
    for(std::size_t i = 0; i < points.size(); ++i)
      d->copies[fill[distinct_of[i]]++] = std::uint32_t(i);
    d->tree.reset(new Tree(entries.begin(), entries.end()));
    d->tree->build();
    m_data = std::move(d);
  }

  bool empty() const { return !m_data; }

  // The id of the nearest point to `q` at most sqrt(max_squared_distance) away (the first given
  // among equally near ones), and its squared distance; returns false when there is none.
  bool nearest(const Vector_3d& q, double max_squared_distance, std::uint32_t& id,
               double& squared_distance) const
  {
    if(!m_data)
      return false;
    std::vector<Candidate> found;
    nearest_positions(q, 1, found);
    if(found.empty() || found.front().first > max_squared_distance)
      return false;
    id = m_data->ids[found.front().second];
    squared_distance = found.front().first;
    return true;
  }

  // The ids of the (at most) `k` nearest points to `q` closer than sqrt(max_squared_distance)
  // (every point by default), nearest first (equally near ones in the order given), with their
  // squared distances, in `result` (cleared first).
  void k_nearest(const Vector_3d& q, std::size_t k, std::vector<Candidate>& result,
                 double max_squared_distance = std::numeric_limits<double>::infinity()) const
  {
    result.clear();
    if(!m_data || k == 0)
      return;
    nearest_positions(q, k, result);
    while(!result.empty() && !(result.back().first < max_squared_distance))
      result.pop_back();
    for(Candidate& r : result)
      r.second = m_data->ids[r.second];
  }

private:
  // The k smallest (squared distance, position) pairs, in increasing order. The kd-tree returns
  // the nearest distinct points, but which of several tied at the farthest distance is its
  // choice: every point nearer than the farthest returned is known, so the answer holds when k
  // of them are; otherwise the search is widened.
  void nearest_positions(const Vector_3d& q, std::size_t k, std::vector<Candidate>& out) const
  {
    const Data& d = *m_data;
    const std::size_t n = d.points.size();
    const Point query(q.x, q.y, q.z);
    std::size_t wanted = (std::min)(k + 1, n);
    for(;;) {
      out.clear();
      double farthest = 0;
      const Search search(*d.tree, query, unsigned(wanted), 0.0, true, Distance(), false);
      for(auto it = search.begin(); it != search.end(); ++it) {
        const std::uint32_t i = it->first.second;
        const double dist = (d.points[i] - q).squared_length();
        farthest = (std::max)(farthest, dist);
        for(std::uint32_t c = d.first_copy[i]; c < d.first_copy[i + 1]; ++c)
          out.emplace_back(dist, d.copies[c]);
      }
      std::sort(out.begin(), out.end());
      if(wanted == n || (out.size() > k && out[k - 1].first < farthest))
        break;
      wanted = (std::min)(2 * wanted, n);
    }
    if(out.size() > k)
      out.resize(k);
  }

  std::shared_ptr<const Data> m_data; // shared by copies (never changed once built)
};

} // namespace internal
} // namespace Shape_analysis
} // namespace CGAL

#endif // CGAL_SHAPE_ANALYSIS_INTERNAL_POINT_TREE_H
