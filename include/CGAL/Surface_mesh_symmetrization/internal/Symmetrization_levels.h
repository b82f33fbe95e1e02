// Copyright (c) 2026 CGAL Global Shape Analysis contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_SURFACE_MESH_SYMMETRIZATION_INTERNAL_SYMMETRIZATION_LEVELS_H
#define CGAL_SURFACE_MESH_SYMMETRIZATION_INTERNAL_SYMMETRIZATION_LEVELS_H

// The multiresolution hierarchy of the symmetrization: coarser levels made with CGAL's edge
// collapse (each with about 1/8 of the vertices of the previous one), the closest points that
// link each level to the next finer one, the weights of the symmetries on the coarser levels,
// and the seeding of a finer level with the displacements of the coarser one.

#include <CGAL/Shape_analysis/internal/Parallel.h>
#include <CGAL/Surface_mesh_symmetrization/internal/Surface_index.h>

#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/Euler_operations.h>
#include <CGAL/Surface_mesh_simplification/edge_collapse.h>
#include <CGAL/Surface_mesh_simplification/Policies/Edge_collapse/Count_stop_predicate.h>
#include <CGAL/Surface_mesh_simplification/Policies/Edge_collapse/Edge_length_cost.h>
#include <CGAL/Surface_mesh_simplification/Policies/Edge_collapse/Midpoint_placement.h>

#include <array>
#include <cstdint>
#include <memory>
#include <utility>
#include <vector>

namespace CGAL {
namespace Surface_mesh_symmetrization {
namespace internal {

// One level of the multiresolution hierarchy.
struct Level
{
  Surface original;                       // positions x0 at this level
  std::vector<std::pair<std::uint32_t, std::uint32_t>> edges;
  double mean_edge = 0;
  // Per vertex of the next finer level: its closest point on this level's original surface.
  std::vector<Surface_point> finer_on_this;
  std::vector<std::vector<double>> weights; // [symmetry][vertex] (empty: 1)
  // Per face, the faces across its three edges (no_face at a border or a non-manifold edge);
  // built on first use.
  mutable std::vector<std::array<std::uint32_t, 3>> adjacent;
  // The closest-point index of the current positions of this level, refitted as they move.
  mutable std::unique_ptr<Surface_index> index;
};

// Decimates `s` with CGAL's edge collapse (edge-length cost, midpoint placement) to about
// `target` vertices. Returns false when the surface cannot be built as a halfedge mesh or does
// not get smaller.
inline bool decimate(const Surface& s, std::size_t target, Surface& result)
{
  typedef CGAL::Simple_cartesian<double> K;
  typedef CGAL::Surface_mesh<K::Point_3> Mesh;
  namespace SMS = CGAL::Surface_mesh_simplification;
  Mesh mesh;
  std::vector<std::uint32_t> used(s.points.size(), 0);
  for(const auto& t : s.triangles)
    for(std::uint32_t v : t)
      used[v] = 1;
  std::vector<Mesh::Vertex_index> vertex(s.points.size());
  for(std::size_t i = 0; i < s.points.size(); ++i)
    if(used[i])
      vertex[i] = mesh.add_vertex(K::Point_3(s.points[i].x, s.points[i].y, s.points[i].z));
  std::vector<Mesh::Vertex_index> corners(3);
  for(const auto& t : s.triangles) {
    for(int c = 0; c < 3; ++c)
      corners[std::size_t(c)] = vertex[t[std::size_t(c)]];
    if(CGAL::Euler::add_face(corners, mesh) == Mesh::null_face())
      return false; // a face that a halfedge mesh cannot hold: no coarser level
  }
  const std::size_t before = num_vertices(mesh);
  if(before <= target)
    return false;
  SMS::Count_stop_predicate<Mesh> stop(3 * target);
  SMS::edge_collapse(mesh, stop,
                     CGAL::parameters::get_cost(SMS::Edge_length_cost<Mesh>())
                       .get_placement(SMS::Midpoint_placement<Mesh>()));
  mesh.collect_garbage();
  if(num_vertices(mesh) >= before || num_faces(mesh) == 0)
    return false;
  result = Surface();
  result.points.reserve(num_vertices(mesh));
  for(Mesh::Vertex_index v : mesh.vertices()) {
    const K::Point_3& p = mesh.point(v);
    result.points.emplace_back(p.x(), p.y(), p.z());
  }
  for(Mesh::Face_index f : mesh.faces()) {
    std::array<std::uint32_t, 3> t{{0, 0, 0}};
    int c = 0;
    for(Mesh::Vertex_index v : vertices_around_face(mesh.halfedge(f), mesh))
      t[std::size_t(c++)] = std::uint32_t(v.idx());
    result.triangles.push_back(t);
  }
  return true;
}

// The weight of symmetry k at vertex i of `level`.
inline double vertex_weight(const Level& level, std::size_t k, std::size_t i)
{
  const std::vector<double>& w = level.weights[k];
  return w.empty() ? 1.0 : w[i];
}

// Appends coarser levels to `levels` (the finest first, the input) until `number_of_levels`
// (0: up to 8, while a level keeps at least half of `coarsest_level_size` vertices), a level
// would have fewer than 20 vertices, or the decimation fails.
inline void add_coarser_levels(std::vector<Level>& levels, std::size_t number_of_levels,
                               std::size_t coarsest_level_size)
{
  const std::size_t max_levels = number_of_levels == 0 ? 8 : number_of_levels;
  while(levels.size() < max_levels) {
    const Surface& fine = levels.back().original;
    std::size_t used = 0;
    {
      std::vector<char> u(fine.points.size(), 0);
      for(const auto& t : fine.triangles)
        for(std::uint32_t v : t)
          u[v] = 1;
      for(char c : u)
        used += c ? 1 : 0;
    }
    const std::size_t target = used / 8;
    if(number_of_levels == 0 && target < coarsest_level_size / 2)
      break;
    if(target < 20)
      break;
    Level coarse;
    if(!decimate(fine, target, coarse.original))
      break;
    levels.push_back(std::move(coarse));
  }
}

// Links between levels (per vertex of a level, its closest point on the next coarser one) and
// the weights of the coarser levels (the weight of the closest point on the finer one).
inline void link_levels(std::vector<Level>& levels, std::size_t number_of_symmetries, std::size_t threads)
{
  for(std::size_t l = 1; l < levels.size(); ++l) {
    const Surface& fine = levels[l - 1].original;
    Level& coarse = levels[l];
    const Surface_index coarse_index(coarse.original);
    coarse.finer_on_this.resize(fine.number_of_vertices());
    SAI::Parallel_workspaces<char> parallel(threads);
    parallel.for_each(0, fine.number_of_vertices(), [&](std::size_t i, char&) {
      coarse.finer_on_this[i] = coarse_index.closest(fine.points[i]);
    });
    std::unique_ptr<Surface_index> fine_index; // made when a symmetry has weights
    coarse.weights.resize(number_of_symmetries);
    for(std::size_t k = 0; k < number_of_symmetries; ++k) {
      const std::vector<double>& wf = levels[l - 1].weights[k];
      if(wf.empty())
        continue;
      if(!fine_index)
        fine_index = std::make_unique<Surface_index>(fine);
      std::vector<double>& wc = coarse.weights[k];
      wc.assign(coarse.original.number_of_vertices(), 0.0);
      for(std::size_t i = 0; i < wc.size(); ++i) {
        const Surface_point c = fine_index->closest(coarse.original.points[i]);
        if(!c.found)
          continue;
        const auto& t = fine.triangles[c.face];
        wc[i] = c.barycentric[0] * wf[t[0]] + c.barycentric[1] * wf[t[1]] + c.barycentric[2] * wf[t[2]];
      }
    }
  }
  for(Level& level : levels) {
    level.edges = level.original.edges();
    double sum = 0;
    for(const auto& e : level.edges)
      sum += (level.original.points[e.first] - level.original.points[e.second]).length();
    level.mean_edge = level.edges.empty() ? 0.0 : sum / double(level.edges.size());
  }
}

// The positions of `fine` seeded by the displacements `coarse_x` - x0 of the next coarser level,
// interpolated at the closest points of its vertices.
inline std::vector<Vector_3d> seeded_positions(const Level& fine, const Level& coarse,
                                               const std::vector<Vector_3d>& coarse_x)
{
  std::vector<Vector_3d> seeded = fine.original.points;
  for(std::size_t i = 0; i < seeded.size(); ++i) {
    const Surface_point& c = coarse.finer_on_this[i];
    if(!c.found)
      continue;
    const auto& t = coarse.original.triangles[c.face];
    Vector_3d d;
    for(int j = 0; j < 3; ++j)
      d += (coarse_x[t[std::size_t(j)]] - coarse.original.points[t[std::size_t(j)]]) * c.barycentric[std::size_t(j)];
    seeded[i] += d;
  }
  return seeded;
}

} // namespace internal
} // namespace Surface_mesh_symmetrization
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_SYMMETRIZATION_INTERNAL_SYMMETRIZATION_LEVELS_H
