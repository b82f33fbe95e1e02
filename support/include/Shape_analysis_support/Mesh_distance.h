// Copyright (c) 2026 CGAL Global Shape Analysis contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef SHAPE_ANALYSIS_SUPPORT_MESH_DISTANCE_H
#define SHAPE_ANALYSIS_SUPPORT_MESH_DISTANCE_H

// The distance between two triangle meshes by which the tests and benchmarks judge a remeshing or
// a simplification (what Metro measures): the two-sided Hausdorff distance, estimated from the
// vertices of each mesh and points drawn on its faces in proportion to their areas (a fixed
// seed: the same meshes give the same figure), each with its exact distance to the other mesh
// (CGAL's AABB tree); the mean of those distances; and the mean angle between the normals of a
// sample's face and of the nearest face of the other mesh.

#include <CGAL/Shape_analysis/internal/Random.h>
#include <CGAL/Shape_analysis/internal/Triangle_sampling.h>
#include <CGAL/Shape_analysis/internal/Vector_3d.h>

#include <CGAL/AABB_face_graph_triangle_primitive.h>
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/Surface_mesh.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <vector>

namespace CGAL {
namespace Shape_analysis_support {

struct Mesh_distance
{
  double hausdorff = 0; ///< the larger of the two one-sided distances
  double mean = 0;      ///< the mean distance of the samples of both meshes to the other one
  /// the mean angle, in degrees, between the normal of the face of each sample drawn on a face and
  /// the normal of the face of the other mesh nearest to it (a blurred or misplaced crease turns
  /// the nearest faces away from the samples' own)
  double normal_deviation = 0;
};

namespace mesh_distance_internal {

// The unit normal of a triangle (zero when degenerate).
inline CGAL::Shape_analysis::internal::Vector_3d unit_normal(const std::array<CGAL::Shape_analysis::internal::Vector_3d, 3>& c)
{
  const CGAL::Shape_analysis::internal::Vector_3d a = CGAL::Shape_analysis::internal::cross(c[1] - c[0], c[2] - c[0]);
  const double l = a.length();
  return l > 0 ? a / l : CGAL::Shape_analysis::internal::Vector_3d(0, 0, 0);
}

// The corners of face f of m.
template <typename Point>
std::array<CGAL::Shape_analysis::internal::Vector_3d, 3>
corners_of(const CGAL::Surface_mesh<Point>& m, typename CGAL::Surface_mesh<Point>::Face_index f)
{
  std::array<CGAL::Shape_analysis::internal::Vector_3d, 3> c;
  std::size_t k = 0;
  for(auto v : CGAL::vertices_around_face(halfedge(f, m), m)) {
    const Point& p = m.point(v);
    c[k++ % 3] = CGAL::Shape_analysis::internal::Vector_3d(CGAL::to_double(p.x()), CGAL::to_double(p.y()),
                                                           CGAL::to_double(p.z()));
  }
  return c;
}

// The largest and the summed distance to `to` of the vertices of `from` and of `samples` points on
// its faces; `count` gets the number of points; `angles` the summed angle (degrees) between the
// normals of the face of each sample and of its nearest face of `to`, `angle_count` their number.
template <typename Point>
void one_sided(const CGAL::Surface_mesh<Point>& from, const CGAL::Surface_mesh<Point>& to, std::size_t samples,
               double& largest, double& sum, std::size_t& count, double& angles, std::size_t& angle_count)
{
  typedef CGAL::Surface_mesh<Point> Mesh;
  typedef typename CGAL::Kernel_traits<Point>::Kernel Kernel;
  typedef CGAL::AABB_face_graph_triangle_primitive<Mesh> Primitive;
  typedef CGAL::AABB_tree<CGAL::AABB_traits<Kernel, Primitive>> Tree;
  namespace SAI = CGAL::Shape_analysis::internal;
  Tree tree(faces(to).first, faces(to).second, to);
  tree.accelerate_distance_queries();
  std::vector<Point> points;
  for(auto v : vertices(from))
    points.push_back(from.point(v));
  std::vector<std::array<SAI::Vector_3d, 3>> corners;
  std::vector<double> areas;
  for(auto f : faces(from)) {
    const std::array<SAI::Vector_3d, 3> c = corners_of(from, f);
    corners.push_back(c);
    areas.push_back(0.5 * SAI::cross(c[1] - c[0], c[2] - c[0]).length());
  }
  const SAI::Weighted_triangle_sampler sampler(areas);
  SAI::Random_stream random(20261205);
  const std::size_t vertex_points = points.size();
  std::vector<SAI::Vector_3d> sample_normal; // of the face each sample lies on
  for(std::size_t i = 0; i < samples && !areas.empty(); ++i) {
    const std::size_t t = sampler.triangle(random);
    const SAI::Vector_3d q = SAI::Weighted_triangle_sampler::point_in(corners[t], random);
    points.emplace_back(q.x, q.y, q.z);
    sample_normal.push_back(unit_normal(corners[t]));
  }
  std::vector<SAI::Vector_3d> to_normal(to.number_of_faces() + to.number_of_removed_faces());
  for(auto f : faces(to))
    to_normal[std::size_t(f)] = unit_normal(corners_of(to, f));
  for(std::size_t i = 0; i < points.size(); ++i) {
    const auto nearest = tree.closest_point_and_primitive(points[i]);
    const double d = std::sqrt(CGAL::to_double(CGAL::squared_distance(points[i], nearest.first)));
    largest = (std::max)(largest, d);
    sum += d;
    if(i >= vertex_points) {
      const double c = SAI::dot(sample_normal[i - vertex_points], to_normal[std::size_t(nearest.second)]);
      angles += std::acos((std::max)(-1.0, (std::min)(1.0, c))) * 180.0 / CGAL_PI;
      ++angle_count;
    }
  }
  count += points.size();
}

} // namespace mesh_distance_internal

// The distances between `a` and `b`, from their vertices and `samples` points on each, relative to
// `scale` (the bounding-box diagonal of the reference mesh, say).
template <typename Point>
Mesh_distance mesh_distance(const CGAL::Surface_mesh<Point>& a, const CGAL::Surface_mesh<Point>& b, double scale,
                            std::size_t samples = 200000)
{
  double ab = 0, ba = 0, sum = 0, angles = 0;
  std::size_t count = 0, angle_count = 0;
  mesh_distance_internal::one_sided(a, b, samples, ab, sum, count, angles, angle_count);
  mesh_distance_internal::one_sided(b, a, samples, ba, sum, count, angles, angle_count);
  Mesh_distance d;
  d.hausdorff = (std::max)(ab, ba) / scale;
  d.mean = count > 0 ? sum / double(count) / scale : 0.0;
  d.normal_deviation = angle_count > 0 ? angles / double(angle_count) : 0.0;
  return d;
}

} // namespace Shape_analysis_support
} // namespace CGAL

#endif // SHAPE_ANALYSIS_SUPPORT_MESH_DISTANCE_H
