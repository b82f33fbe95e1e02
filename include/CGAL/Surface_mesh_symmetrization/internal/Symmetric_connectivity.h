// Copyright (c) 2026 CGAL Global Shape Analysis contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_SURFACE_MESH_SYMMETRIZATION_INTERNAL_SYMMETRIC_CONNECTIVITY_H
#define CGAL_SURFACE_MESH_SYMMETRIZATION_INTERNAL_SYMMETRIC_CONNECTIVITY_H

// The connectivity of a mesh under a reflection: the frame of the plane (in which the reflection
// is x -> -x, exactly), the pairing of the vertices with their mirror vertices, and which edges
// and faces have a mirror edge or face.

#include <CGAL/Shape_analysis/internal/Point_tree.h>
#include <CGAL/Shape_analysis/internal/Vector_3d.h>
#include <CGAL/Surface_mesh_symmetrization/internal/Symmetry_geometry.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Surface_mesh_symmetrization {
namespace internal {

// The key of the undirected edge between vertices a and b.
inline std::uint64_t edge_key(std::uint32_t a, std::uint32_t b)
{
  return a < b ? (std::uint64_t(a) << 32 | b) : (std::uint64_t(b) << 32 | a);
}

// The frame of a plane: x the signed distance to the plane, (y, z) along it, from the projection
// of a point near the surface (so that the coordinates stay small).
struct Plane_frame
{
  Vector_3d origin;
  std::array<Vector_3d, 3> axis;

  Plane_frame(const Plane_3d& plane, const Vector_3d& near)
  {
    const Vector_3d n = plane.normal;
    origin = near - n * plane.signed_distance(near);
    axis[0] = n;
    // The coordinate axis least aligned with n, made orthogonal to it.
    const Vector_3d e = std::abs(n.x) < 0.6 ? Vector_3d(1, 0, 0) : Vector_3d(0, 1, 0);
    axis[1] = e - n * SAI::dot(n, e);
    axis[1] = axis[1] / axis[1].length();
    axis[2] = SAI::cross(axis[0], axis[1]);
  }

  Vector_3d to_frame(const Vector_3d& p) const
  {
    const Vector_3d d = p - origin;
    return Vector_3d(SAI::dot(d, axis[0]), SAI::dot(d, axis[1]), SAI::dot(d, axis[2]));
  }
  Vector_3d from_frame(const Vector_3d& q) const { return origin + axis[0] * q.x + axis[1] * q.y + axis[2] * q.z; }
};

// The mirror image of a point given in a plane's frame.
inline Vector_3d mirrored(const Vector_3d& q) { return Vector_3d(-q.x, q.y, q.z); }

constexpr std::uint32_t no_partner = (std::numeric_limits<std::uint32_t>::max)();

// The mean length of the edges of `s` (0 without edges).
inline double mean_edge_length(const Surface& s)
{
  const auto edges = s.edges();
  double sum = 0;
  for(const auto& e : edges)
    sum += (s.points[e.first] - s.points[e.second]).length();
  return edges.empty() ? 0.0 : sum / double(edges.size());
}

// Per point (in a plane's frame) its mirror partner: the point nearest to its mirror image when
// that one's nearest is the point too (mutual), within `tolerance`; itself for a point that is its
// own nearest (on the plane); no_partner otherwise. `used`: the points to pair (others: none).
inline std::vector<std::uint32_t> pair_vertices(const std::vector<Vector_3d>& q, const std::vector<char>& used,
                                                double tolerance)
{
  std::vector<Vector_3d> kept;
  std::vector<std::uint32_t> ids;
  for(std::size_t i = 0; i < q.size(); ++i)
    if(used[i]) {
      kept.push_back(q[i]);
      ids.push_back(std::uint32_t(i));
    }
  const SAI::Point_tree tree(kept, ids);
  std::vector<std::uint32_t> nearest(q.size(), no_partner), partner(q.size(), no_partner);
  for(std::uint32_t i : ids) {
    double d2 = 0;
    std::uint32_t j = no_partner;
    if(tree.nearest(mirrored(q[i]), tolerance * tolerance, j, d2))
      nearest[i] = j;
  }
  for(std::uint32_t i : ids)
    if(nearest[i] != no_partner && nearest[nearest[i]] == i)
      partner[i] = nearest[i];
  return partner;
}

// A face whose three corners are their own partners would lie in the plane once they are moved
// onto it (a face cannot be its own mirror image otherwise): the corner farthest from the plane
// loses its partner, face after face.
inline void unpair_faces_in_plane(const Surface& s, std::vector<std::uint32_t>& partner)
{
  for(const auto& t : s.triangles) {
    if(partner[t[0]] != t[0] || partner[t[1]] != t[1] || partner[t[2]] != t[2])
      continue;
    std::uint32_t far = t[0];
    for(std::uint32_t v : t)
      if(std::abs(s.points[v].x) > std::abs(s.points[far].x))
        far = v;
    partner[far] = no_partner;
  }
}

// Makes the pairs exact: a pair's points become mirror images (the mean of one and the image of
// the other), a point that is its own partner goes onto the plane.
inline void make_pairs_exact(std::vector<Vector_3d>& q, const std::vector<std::uint32_t>& partner)
{
  for(std::size_t i = 0; i < q.size(); ++i) {
    const std::uint32_t j = partner[i];
    if(j == std::uint32_t(i))
      q[i].x = 0;
    else if(j != no_partner && i < j) {
      q[i] = (q[i] + mirrored(q[j])) * 0.5;
      q[j] = mirrored(q[i]);
    }
  }
}

// How much of a surface has mirror partners: vertices (those of faces), edges and faces.
struct Connectivity_counts
{
  std::size_t vertices = 0, paired_vertices = 0, edges = 0, symmetric_edges = 0, faces = 0, symmetric_faces = 0;
};

inline Connectivity_counts count_symmetric_connectivity(const Surface& s, const std::vector<std::uint32_t>& partner)
{
  Connectivity_counts c;
  std::vector<char> used(s.points.size(), 0);
  std::vector<std::array<std::uint32_t, 3>> faces;
  for(const auto& t : s.triangles) {
    std::array<std::uint32_t, 3> k = t;
    std::sort(k.begin(), k.end());
    faces.push_back(k);
    for(std::uint32_t v : t)
      used[v] = 1;
  }
  std::sort(faces.begin(), faces.end());
  for(std::size_t v = 0; v < used.size(); ++v)
    if(used[v]) {
      ++c.vertices;
      c.paired_vertices += partner[v] != no_partner ? 1 : 0;
    }
  const auto edges = s.edges();
  c.edges = edges.size();
  for(const auto& e : edges) {
    std::uint32_t a = partner[e.first], b = partner[e.second];
    if(a == no_partner || b == no_partner)
      continue;
    if(a > b)
      std::swap(a, b);
    c.symmetric_edges += std::binary_search(edges.begin(), edges.end(), std::make_pair(a, b)) ? 1 : 0;
  }
  c.faces = faces.size();
  for(const auto& f : faces) {
    std::array<std::uint32_t, 3> m{{partner[f[0]], partner[f[1]], partner[f[2]]}};
    if(m[0] == no_partner || m[1] == no_partner || m[2] == no_partner)
      continue;
    std::sort(m.begin(), m.end());
    c.symmetric_faces += std::binary_search(faces.begin(), faces.end(), m) ? 1 : 0;
  }
  return c;
}

} // namespace internal
} // namespace Surface_mesh_symmetrization
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_SYMMETRIZATION_INTERNAL_SYMMETRIC_CONNECTIVITY_H
