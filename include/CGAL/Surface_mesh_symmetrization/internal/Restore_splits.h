// Copyright (c) 2026 CGAL Global Shape Analysis contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_SURFACE_MESH_SYMMETRIZATION_INTERNAL_RESTORE_SPLITS_H
#define CGAL_SURFACE_MESH_SYMMETRIZATION_INTERNAL_RESTORE_SPLITS_H

// Splits of a triangle mesh whose connectivity is mirrored by vertex pairs (`partner`), made in
// mirror pairs so that it stays mirrored: the edge table and the red-green face split that the
// restore path of symmetric_simplification() uses to refine its meta-mesh, and the splits that
// spend the last faces of its decimation where the result is farthest from the input
// (split_farthest()). The positions need not be mirror images: only the connectivity is mirrored.

#include <CGAL/Surface_mesh_symmetrization/internal/Surface_index.h>
#include <CGAL/Surface_mesh_symmetrization/internal/Symmetric_connectivity.h>
#include <CGAL/Surface_mesh_symmetrization/internal/Symmetry_geometry.h>
#include <CGAL/Shape_analysis/internal/Parallel.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <unordered_map>
#include <utility>
#include <vector>

namespace CGAL {
namespace Surface_mesh_symmetrization {
namespace internal {

// The edges of a triangle mesh: their ends, and per face its edges (edge k from corner k to k + 1).
struct Edge_table
{
  std::unordered_map<std::uint64_t, std::uint32_t> index;
  std::vector<std::array<std::uint32_t, 2>> ends;
  std::vector<std::array<std::uint32_t, 3>> of_face;

  explicit Edge_table(const std::vector<std::array<std::uint32_t, 3>>& triangles) : of_face(triangles.size())
  {
    for(std::size_t f = 0; f < triangles.size(); ++f)
      for(std::size_t k = 0; k < 3; ++k) {
        const std::uint32_t a = triangles[f][k], b = triangles[f][(k + 1) % 3];
        const auto it = index.emplace(edge_key(a, b), std::uint32_t(ends.size()));
        if(it.second)
          ends.push_back({{a, b}});
        of_face[f][k] = it.first->second;
      }
  }

  // The edge from a to b, or no_partner.
  std::uint32_t find(std::uint32_t a, std::uint32_t b) const
  {
    const auto it = index.find(edge_key(a, b));
    return it == index.end() ? no_partner : it->second;
  }

  // The two faces of every edge (no_partner where it has fewer).
  std::vector<std::array<std::uint32_t, 2>> faces_of_edges() const
  {
    std::vector<std::array<std::uint32_t, 2>> faces(ends.size(), {{no_partner, no_partner}});
    for(std::uint32_t f = 0; f < of_face.size(); ++f)
      for(std::uint32_t e : of_face[f])
        (faces[e][0] == no_partner ? faces[e][0] : faces[e][1]) = f;
    return faces;
  }

  // The mirror edge of e under `partner`, or no_partner.
  std::uint32_t mirror(std::uint32_t e, const std::vector<std::uint32_t>& partner) const
  {
    const std::uint32_t a = partner[ends[e][0]], b = partner[ends[e][1]];
    return a == no_partner || b == no_partner ? no_partner : find(a, b);
  }
};

// The faces of `triangles` with the edges `split` split at `middle` (their new points): in four
// with three split edges, in two with one, kept with none (no face has two). `fresh`: per new
// face, whether it was made here.
inline void split_faces(std::vector<std::array<std::uint32_t, 3>>& triangles, const Edge_table& edges,
                        const std::vector<char>& split, const std::vector<std::uint32_t>& middle,
                        std::vector<char>& fresh)
{
  typedef std::array<std::uint32_t, 3> Triangle;
  std::vector<Triangle> out;
  fresh.clear();
  for(std::size_t f = 0; f < triangles.size(); ++f) {
    const Triangle& t = triangles[f];
    const Triangle& e = edges.of_face[f];
    const int n = split[e[0]] + split[e[1]] + split[e[2]];
    if(n == 3) {
      const std::uint32_t m0 = middle[e[0]], m1 = middle[e[1]], m2 = middle[e[2]];
      out.insert(out.end(), {Triangle{{t[0], m0, m2}}, Triangle{{m0, t[1], m1}}, Triangle{{m2, m1, t[2]}},
                             Triangle{{m0, m1, m2}}});
    } else if(n == 1) {
      std::size_t k = 0;
      while(!split[e[k]])
        ++k;
      const std::uint32_t m = middle[e[k]], a = t[k], b = t[(k + 1) % 3], c = t[(k + 2) % 3];
      out.insert(out.end(), {Triangle{{a, m, c}}, Triangle{{m, b, c}}});
    } else
      out.push_back(t);
    fresh.resize(out.size(), n > 0 ? 1 : 0);
  }
  triangles = std::move(out);
}

// How far every face of a mesh is from a reference surface, both ways: `own`, the largest squared
// distance of its points (Surface_index::samples_of() on a grid of `grid`) to the reference;
// `back`, the largest squared distance to the mesh of the points `reference_points` of the
// reference whose nearest face it is, `back_point` that point and `back_barycentric` where it
// lands on the face.
struct Face_distances
{
  std::vector<double> own, back;
  std::vector<Vector_3d> back_point;
  std::vector<std::array<double, 3>> back_barycentric;

  Face_distances(const Surface& s, const Surface_index& reference, const std::vector<Vector_3d>& reference_points,
                 std::uint32_t grid, std::size_t threads)
    : own(s.triangles.size(), 0.0), back(s.triangles.size(), 0.0), back_point(s.triangles.size()),
      back_barycentric(s.triangles.size())
  {
    SAI::Parallel_workspaces<std::uint32_t> hints(threads);
    hints.for_each(0, s.triangles.size(), [&](std::size_t f, std::uint32_t& hint) {
      Surface_index::samples_of(s.corners(f), grid, [&](const Vector_3d& p, std::uint32_t) {
        const Surface_point q = reference.closest(p, hint);
        if(q.found)
          hint = q.face, own[f] = (std::max)(own[f], q.squared_distance);
      });
    });
    // Per point of the reference (`reference_points`), its nearest face here and its squared
    // distance; gathered in the points' order.
    const Surface_index index(s);
    std::vector<double> distance(reference_points.size(), -1.0);
    std::vector<std::uint32_t> nearest(reference_points.size(), 0);
    hints.for_each(0, reference_points.size(), [&](std::size_t i, std::uint32_t& hint) {
      const Surface_point q = index.closest(reference_points[i], hint);
      if(q.found)
        hint = q.face, distance[i] = q.squared_distance, nearest[i] = q.face;
    });
    std::vector<std::size_t> farthest(s.triangles.size(), reference_points.size());
    for(std::size_t i = 0; i < distance.size(); ++i)
      if(distance[i] > back[nearest[i]])
        back[nearest[i]] = distance[i], farthest[nearest[i]] = i;
    for(std::size_t f = 0; f < s.triangles.size(); ++f)
      if(farthest[f] < reference_points.size()) {
        const auto c = s.corners(f);
        back_point[f] = reference_points[farthest[f]];
        closest_point_on_triangle(back_point[f], c[0], c[1], c[2], back_barycentric[f]);
      }
  }

  double worst(std::size_t f) const { return (std::max)(own[f], back[f]); }
};

// The splits of one round of split_farthest(): faces whose farthest point is the reference's get
// that point (and the mirror face the point at the same barycentric coordinates of the mirror
// corners), the others their longest edge split with its mirror edge; `point_splits` holds the
// pairs of faces, `edge_splits` the edges by their ends (the mirror edges included).
struct Farthest_splits
{
  std::vector<std::pair<std::uint32_t, std::uint32_t>> point_splits;
  std::vector<std::array<std::uint32_t, 2>> edge_splits;
  std::size_t new_faces = 0;
};

// Chooses the splits of one round: faces by decreasing distance (Face_distances::worst()), each
// split only when none of the faces it touches (either side) is touched by another split of the
// round, until `budget` new faces.
inline Farthest_splits choose_farthest_splits(const Surface& s, const std::vector<std::uint32_t>& partner,
                                              const Face_distances& d, std::size_t budget)
{
  const std::size_t nf = s.triangles.size();
  std::vector<std::uint32_t> order(nf);
  for(std::uint32_t f = 0; f < nf; ++f)
    order[f] = f;
  std::sort(order.begin(), order.end(), [&](std::uint32_t a, std::uint32_t b) {
    return d.worst(a) != d.worst(b) ? d.worst(a) > d.worst(b) : a < b;
  });
  const Edge_table edges(s.triangles);
  const std::vector<std::array<std::uint32_t, 2>> faces_of = edges.faces_of_edges();
  std::vector<char> used(nf, 0);
  Farthest_splits out;
  for(std::uint32_t f : order) {
    if(out.new_faces + 4 > budget || !(d.worst(f) > 0))
      break;
    if(used[f])
      continue;
    // The faces the split touches: f's mirror face, or the faces of the longest edge and its mirror.
    std::vector<std::uint32_t> touched;
    std::array<std::uint32_t, 2> pair{{no_partner, no_partner}};
    const bool insert_point = d.back[f] >= d.own[f];
    if(insert_point) {
      const std::uint32_t m = edges.mirror(edges.of_face[f][0], partner), c = partner[s.triangles[f][2]];
      for(std::uint32_t g : m == no_partner ? std::array<std::uint32_t, 2>{{no_partner, no_partner}} : faces_of[m])
        if(g != no_partner && c != no_partner && std::count(s.triangles[g].begin(), s.triangles[g].end(), c) > 0)
          pair = {{f, g}};
      if(pair[1] == no_partner || pair[1] == f)
        continue;
      touched = {f, pair[1]};
    } else {
      std::uint32_t e = edges.of_face[f][0];
      for(std::uint32_t x : edges.of_face[f])
        if((s.points[edges.ends[x][0]] - s.points[edges.ends[x][1]]).length() >
           (s.points[edges.ends[e][0]] - s.points[edges.ends[e][1]]).length())
          e = x;
      const std::uint32_t m = edges.mirror(e, partner);
      if(m == no_partner)
        continue;
      pair = {{e, m}};
      for(std::uint32_t x : {e, m})
        for(std::uint32_t g : faces_of[x])
          touched.push_back(g);
      std::sort(touched.begin(), touched.end());
      // An edge and its mirror edge on one face (or a face missing): one face would get two splits.
      if(std::adjacent_find(touched.begin(), touched.end()) != touched.end() && m != e)
        continue;
      touched.erase(std::unique(touched.begin(), touched.end()), touched.end());
    }
    if(std::any_of(touched.begin(), touched.end(), [&](std::uint32_t g) { return g == no_partner || used[g]; }))
      continue;
    for(std::uint32_t g : touched)
      used[g] = 1;
    if(insert_point) {
      out.point_splits.emplace_back(pair[0], pair[1]);
      out.new_faces += 4;
    } else {
      out.edge_splits.push_back(edges.ends[pair[0]]);
      if(pair[1] != pair[0])
        out.edge_splits.push_back(edges.ends[pair[1]]);
      out.new_faces += pair[1] != pair[0] ? 4 : 2;
    }
  }
  return out;
}

// Applies `splits` to `s` (and its pairs `partner`): the new points on the reference (the nearest
// point there whose face is turned the way of theirs).
inline void apply_farthest_splits(Surface& s, std::vector<std::uint32_t>& partner, const Farthest_splits& splits,
                                  const Face_distances& d, const Surface_index& reference)
{
  typedef std::array<std::uint32_t, 3> Triangle;
  std::uint32_t hint = Surface_index::no_face;
  const auto onto_reference = [&](const Vector_3d& p, const Vector_3d& normal) {
    Surface_point q = reference.closest_compatible(p, normal, 0.0, hint);
    if(!q.found)
      q = reference.closest(p, hint);
    if(q.found)
      hint = q.face;
    return q.found ? q.point : p;
  };
  for(const auto& fg : splits.point_splits) { // each face in three around its new point
    const std::uint32_t f = fg.first, g = fg.second, p = std::uint32_t(s.points.size());
    const Triangle t = s.triangles[f], u = s.triangles[g];
    Vector_3d mirrored(0, 0, 0);
    for(std::size_t k = 0; k < 3; ++k)
      mirrored += s.points[partner[t[k]]] * d.back_barycentric[f][k];
    s.points.push_back(d.back_point[f]);
    s.points.push_back(onto_reference(mirrored, s.area_vector(g)));
    partner.push_back(p + 1);
    partner.push_back(p);
    for(const auto& fv : {std::make_pair(f, t), std::make_pair(g, u)}) {
      const Triangle& x = fv.second;
      const std::uint32_t c = fv.first == f ? p : p + 1;
      s.triangles[fv.first] = Triangle{{x[0], x[1], c}};
      s.triangles.push_back(Triangle{{x[1], x[2], c}});
      s.triangles.push_back(Triangle{{x[2], x[0], c}});
    }
  }
  if(splits.edge_splits.empty())
    return;
  const Edge_table edges(s.triangles); // the split edges are still edges: their faces kept
  std::vector<char> split(edges.ends.size(), 0);
  std::vector<std::uint32_t> middle(edges.ends.size(), no_partner);
  std::vector<Vector_3d> normal(edges.ends.size(), Vector_3d(0, 0, 0));
  for(const auto& ab : splits.edge_splits)
    split[edges.find(ab[0], ab[1])] = 1;
  for(std::size_t f = 0; f < s.triangles.size(); ++f)
    for(std::uint32_t e : edges.of_face[f])
      if(split[e])
        normal[e] += s.area_vector(f);
  for(const auto& ab : splits.edge_splits) {
    const std::uint32_t e = edges.find(ab[0], ab[1]);
    middle[e] = std::uint32_t(s.points.size());
    s.points.push_back(onto_reference((s.points[ab[0]] + s.points[ab[1]]) * 0.5, normal[e]));
    partner.push_back(no_partner);
  }
  for(const auto& ab : splits.edge_splits) {
    const std::uint32_t e = edges.find(ab[0], ab[1]);
    partner[middle[e]] = middle[edges.mirror(e, partner)];
  }
  std::vector<char> fresh;
  split_faces(s.triangles, edges, split, middle, fresh);
}

// Splits `s` (a closed manifold surface whose connectivity `partner` mirrors) where it is
// farthest from `reference`, in at most `rounds` rounds of about equal numbers of new faces, until
// `faces` faces (or nothing is left to split); the distances are measured again every round, from
// the mesh's own points on a grid of `grid` per face and from the reference's vertices and edge
// midpoints. Returns the number of points added. The result
// does not depend on `threads`.
inline std::size_t split_farthest(Surface& s, std::vector<std::uint32_t>& partner, const Surface_index& reference,
                                  std::size_t faces, int rounds, std::uint32_t grid, std::size_t threads)
{
  const std::size_t points_before = s.points.size();
  // The reference's vertices and the midpoints of its edges (the corners and lines of its creases).
  const Surface& r = reference.surface();
  std::vector<Vector_3d> reference_points = r.points;
  const Edge_table reference_edges(r.triangles);
  for(const auto& e : reference_edges.ends)
    reference_points.push_back((r.points[e[0]] + r.points[e[1]]) * 0.5);
  for(int round = 0; round < rounds && s.triangles.size() + 4 <= faces; ++round) {
    const Face_distances d(s, reference, reference_points, grid, threads);
    const std::size_t left = faces - s.triangles.size();
    const Farthest_splits splits = choose_farthest_splits(s, partner, d, (std::max)(std::size_t(4), left / std::size_t(rounds - round)));
    if(splits.new_faces == 0)
      break;
    apply_farthest_splits(s, partner, splits, d, reference);
  }
  return s.points.size() - points_before;
}

} // namespace internal
} // namespace Surface_mesh_symmetrization
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_SYMMETRIZATION_INTERNAL_RESTORE_SPLITS_H
