// The kd-tree of points and the refitted bounding-volume hierarchy.
// Part of test_shape_analysis_core (one translation unit: see test/CMakeLists.txt).

#include "test_core_fixtures.h"

#include <CGAL/Shape_analysis/internal/Bvh.h>
#include <CGAL/Shape_analysis/internal/Nearest_sample_tree.h>
#include <CGAL/Shape_analysis/internal/Point_tree.h>

#include <limits>

namespace {

TEST(PointTree, NearestMatchesBruteForce)
{
  SAS::Procedural_random rng(3);
  std::vector<Vector_3d> points;
  std::vector<std::uint32_t> ids;
  for(std::uint32_t i = 0; i < 500; ++i) {
    points.emplace_back(rng.uniform(), rng.uniform(), rng.uniform());
    ids.push_back(1000 + i);
  }
  const SAI::Point_tree tree(points, ids);
  for(int q = 0; q < 200; ++q) {
    const Vector_3d p(rng.uniform(-0.2, 1.2), rng.uniform(-0.2, 1.2), rng.uniform(-0.2, 1.2));
    double best = std::numeric_limits<double>::infinity();
    std::uint32_t best_i = 0;
    for(std::uint32_t i = 0; i < points.size(); ++i)
      if((points[i] - p).squared_length() < best) {
        best = (points[i] - p).squared_length();
        best_i = i;
      }
    std::uint32_t id = 0;
    double d2 = 0;
    ASSERT_TRUE(tree.nearest(p, std::numeric_limits<double>::infinity(), id, d2));
    EXPECT_EQ(id, ids[best_i]);
    EXPECT_EQ(d2, best);
    // With a radius below the nearest distance there is nothing.
    EXPECT_FALSE(tree.nearest(p, best * 0.99, id, d2));
  }
  std::uint32_t id = 0;
  double d2 = 0;
  EXPECT_FALSE(SAI::Point_tree().nearest(Vector_3d(), 1.0, id, d2)) << "an empty tree has no nearest";
}

TEST(PointTree, KNearestMatchesBruteForce)
{
  SAS::Procedural_random rng(5);
  std::vector<Vector_3d> points;
  std::vector<std::uint32_t> ids;
  for(std::uint32_t i = 0; i < 300; ++i) {
    points.emplace_back(rng.uniform(), rng.uniform(), rng.uniform());
    ids.push_back(7 * i + 1);
  }
  const SAI::Point_tree tree(points, ids);
  std::vector<std::pair<double, std::uint32_t>> result;
  for(std::size_t k : {1u, 5u, 17u, 400u}) {
    for(int q = 0; q < 50; ++q) {
      const Vector_3d p(rng.uniform(-0.2, 1.2), rng.uniform(-0.2, 1.2), rng.uniform(-0.2, 1.2));
      std::vector<std::pair<double, std::uint32_t>> expected;
      for(std::uint32_t i = 0; i < points.size(); ++i)
        expected.emplace_back((points[i] - p).squared_length(), ids[i]);
      std::sort(expected.begin(), expected.end());
      expected.resize((std::min)(k, expected.size()));
      tree.k_nearest(p, k, result);
      ASSERT_EQ(result.size(), expected.size());
      for(std::size_t j = 0; j < expected.size(); ++j) {
        EXPECT_EQ(result[j].first, expected[j].first) << "k " << k << " rank " << j;
        EXPECT_EQ(result[j].second, expected[j].second) << "k " << k << " rank " << j;
      }
    }
  }
  SAI::Point_tree().k_nearest(Vector_3d(), 3, result);
  EXPECT_TRUE(result.empty());
}

// Points of a lattice, each given twice: every query has several equally near points, and the
// k nearest are still those of a brute-force scan that breaks ties by the order given (the
// kd-tree alone picks among tied points as its cells fall); the nearest is the first copy.
TEST(PointTree, TiesGoToThePointGivenFirst)
{
  std::vector<Vector_3d> points;
  std::vector<std::uint32_t> ids;
  for(int copy = 0; copy < 2; ++copy)
    for(int x = 0; x < 6; ++x)
      for(int y = 0; y < 6; ++y)
        for(int z = 0; z < 6; ++z) {
          points.emplace_back(x, y, z);
          ids.push_back(std::uint32_t(2 * points.size() + 1));
        }
  const SAI::Point_tree tree(points, ids);
  std::vector<std::pair<double, std::uint32_t>> result;
  std::size_t tied_queries = 0;
  for(int x = 0; x < 11; ++x)
    for(int y = 0; y < 11; ++y)
      for(int z = 0; z < 11; z += 3) {
        const Vector_3d q(0.5 * x, 0.5 * y, 0.5 * z);
        std::vector<std::pair<double, std::uint32_t>> expected; // (distance, position)
        for(std::uint32_t i = 0; i < points.size(); ++i)
          expected.emplace_back((points[i] - q).squared_length(), i);
        std::sort(expected.begin(), expected.end());
        tied_queries += expected[1].first == expected[0].first ? 1 : 0;
        std::uint32_t id = 0;
        double d2 = 0;
        ASSERT_TRUE(tree.nearest(q, std::numeric_limits<double>::infinity(), id, d2));
        EXPECT_EQ(d2, expected[0].first);
        // nearest(): one of the nearest points, and of its two copies the first given.
        const std::size_t position = std::size_t((id - 1) / 2 - 1);
        EXPECT_LT(position, points.size() / 2) << "the first copy";
        EXPECT_EQ((points[position] - q).squared_length(), expected[0].first);
        for(std::size_t k : {1u, 3u, 7u, 20u}) {
          tree.k_nearest(q, k, result);
          ASSERT_EQ(result.size(), k);
          for(std::size_t j = 0; j < k; ++j) {
            EXPECT_EQ(result[j].first, expected[j].first);
            EXPECT_EQ(result[j].second, ids[expected[j].second]) << "k " << k << " rank " << j;
          }
        }
      }
  EXPECT_EQ(tied_queries, 11u * 11u * 4u) << "every query has tied nearest points";
}

// The ICP's own tree: the nearest sample of a brute-force scan, ties (a lattice given twice) to
// the sample given first.
TEST(NearestSampleTree, NearestMatchesBruteForceWithTies)
{
  SAS::Procedural_random rng(9);
  std::vector<Vector_3d> points;
  for(int copy = 0; copy < 2; ++copy)
    for(int x = 0; x < 5; ++x)
      for(int y = 0; y < 5; ++y)
        for(int z = 0; z < 5; ++z)
          points.emplace_back(x, y, z);
  for(int i = 0; i < 300; ++i)
    points.emplace_back(rng.uniform(0, 4), rng.uniform(0, 4), rng.uniform(0, 4));
  const SAI::Nearest_sample_tree tree(points);
  for(int q = 0; q < 400; ++q) {
    const Vector_3d p = q < 100 ? Vector_3d(0.5 * (q % 9), 0.5 * ((q / 9) % 9), 0.5 * (q % 7))
                                : Vector_3d(rng.uniform(-1, 5), rng.uniform(-1, 5), rng.uniform(-1, 5));
    std::uint32_t best = 0;
    for(std::uint32_t i = 1; i < points.size(); ++i)
      if((points[i] - p).squared_length() < (points[best] - p).squared_length())
        best = i;
    EXPECT_EQ(tree.nearest(p), best) << "query " << q;
  }
  EXPECT_TRUE(SAI::Nearest_sample_tree().empty());
}

// Boxes (segments) around random points: the nearest segment through the hierarchy is the one a
// brute-force scan finds, before and after the segments move and the boxes are refitted.
TEST(Bvh, NearestMatchesBruteForceAfterRefit)
{
  SAS::Procedural_random rng(7);
  const std::size_t n = 700;
  std::vector<Vector_3d> a(n), b(n);
  for(std::size_t i = 0; i < n; ++i) {
    a[i] = Vector_3d(rng.uniform(), rng.uniform(), rng.uniform());
    b[i] = a[i] + Vector_3d(rng.uniform(-0.05, 0.05), rng.uniform(-0.05, 0.05), rng.uniform(-0.05, 0.05));
  }
  // The squared distance from q to segment i.
  const auto distance = [&](std::size_t i, const Vector_3d& q) {
    const Vector_3d d = b[i] - a[i];
    const double t = (std::max)(0.0, (std::min)(1.0, SAI::dot(q - a[i], d) / d.squared_length()));
    return (a[i] + d * t - q).squared_length();
  };
  const auto box_of = [&](std::uint32_t i) {
    SAI::Bvh::Box box;
    box.extend(a[i]);
    box.extend(b[i]);
    return box;
  };
  std::vector<Vector_3d> centers(n);
  for(std::size_t i = 0; i < n; ++i)
    centers[i] = (a[i] + b[i]) * 0.5;
  SAI::Bvh bvh(centers, box_of);
  EXPECT_EQ(bvh.size(), n);
  for(int round = 0; round < 2; ++round) {
    if(round == 1) { // every segment moves (up to a fifth of the cube): the tree no longer fits well
      for(std::size_t i = 0; i < n; ++i) {
        const Vector_3d m(rng.uniform(-0.2, 0.2), rng.uniform(-0.2, 0.2), rng.uniform(-0.2, 0.2));
        a[i] += m;
        b[i] += m;
      }
      bvh.refit(box_of);
    }
    for(int k = 0; k < 300; ++k) {
      const Vector_3d q(rng.uniform(-0.3, 1.3), rng.uniform(-0.3, 1.3), rng.uniform(-0.3, 1.3));
      double expected = std::numeric_limits<double>::infinity();
      for(std::size_t i = 0; i < n; ++i)
        expected = (std::min)(expected, distance(i, q));
      std::size_t visited = 0;
      const double found = bvh.nearest(q, std::numeric_limits<double>::infinity(), [&](std::uint32_t j, double& best) {
        ++visited;
        best = (std::min)(best, distance(bvh.item(j), q));
      });
      EXPECT_EQ(found, expected) << "round " << round << " query " << k;
      EXPECT_LT(visited, n) << "the boxes prune";
      // A bound below the nearest distance finds nothing closer.
      EXPECT_EQ(bvh.nearest(q, 0.5 * expected, [&](std::uint32_t j, double& best) {
                  best = (std::min)(best, distance(bvh.item(j), q));
                }),
                0.5 * expected);
    }
  }
  EXPECT_TRUE(SAI::Bvh().empty());
  EXPECT_EQ(SAI::Bvh().nearest(Vector_3d(), 1.0, [](std::uint32_t, double&) {}), 1.0);
}

} // namespace
