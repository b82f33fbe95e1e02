// Copyright (c) 2026 CGAL Global Shape Analysis contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_SURFACE_MESH_SYMMETRIZATION_INTERNAL_SIDE_COPY_H
#define CGAL_SURFACE_MESH_SYMMETRIZATION_INTERNAL_SIDE_COPY_H

// Symmetric connectivity by copying one side across the plane (the thesis' fallback of symmetric
// remeshing, and on the whole surface the simple alternative to it), on a surface given in the
// frame of its reflection plane (x -> -x) with exact mirror pairs:
// - the faces to copy (those without a mirror face and those across the plane that are not their
//   own mirror image, or all of them) are cut at the plane: each of
//   their edges with ends strictly on both sides gets a vertex on the plane, and every face with
//   such an edge splits into pieces on one side each;
// - their pieces on the negative side are dropped and replaced by the mirror images of those on
//   the positive side (new vertices where a positive vertex has no partner).
// The set of faces without a mirror face is its own mirror image up to its border (an edge of a
// face with a mirror face has a mirror edge), so the copy fits in: the result is closed when the
// input is, unless two copied pieces meet at a vertex only. Where the copy would pinch the surface
// so, at a vertex on the plane, that vertex moves off the plane and the copy starts again; when the
// result still is not a closed manifold, the caller copies all faces instead.

#include <CGAL/Surface_mesh_symmetrization/internal/Symmetric_connectivity.h>

#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <map>
#include <utility>
#include <vector>

namespace CGAL {
namespace Surface_mesh_symmetrization {
namespace internal {

// Per face, whether the partners of its corners make a face.
inline std::vector<char> faces_with_mirror(const Surface& s, const std::vector<std::uint32_t>& partner)
{
  std::vector<std::array<std::uint32_t, 3>> sorted;
  for(auto t : s.triangles) {
    std::sort(t.begin(), t.end());
    sorted.push_back(t);
  }
  std::sort(sorted.begin(), sorted.end());
  std::vector<char> mirrored_face(s.triangles.size(), 0);
  for(std::size_t f = 0; f < s.triangles.size(); ++f) {
    const auto& t = s.triangles[f];
    std::array<std::uint32_t, 3> m{{partner[t[0]], partner[t[1]], partner[t[2]]}};
    if(m[0] == no_partner || m[1] == no_partner || m[2] == no_partner)
      continue;
    std::sort(m.begin(), m.end());
    mirrored_face[f] = std::binary_search(sorted.begin(), sorted.end(), m) ? 1 : 0;
  }
  return mirrored_face;
}

// The faces to copy: those without a mirror face, and those across the plane that are not their
// own mirror image (such a face and its mirror face cross each other on the plane: a fold).
inline std::vector<char> faces_to_copy(const Surface& s, const std::vector<std::uint32_t>& partner)
{
  std::vector<char> listed = faces_with_mirror(s, partner);
  for(std::size_t f = 0; f < listed.size(); ++f) {
    const auto& t = s.triangles[f];
    bool positive = false, negative = false, own_mirror = true;
    for(std::uint32_t v : t) {
      positive = positive || s.points[v].x > 0;
      negative = negative || s.points[v].x < 0;
      own_mirror = own_mirror && (partner[v] == t[0] || partner[v] == t[1] || partner[v] == t[2]);
    }
    listed[f] = !listed[f] || (positive && negative && !own_mirror);
  }
  return listed;
}

// Cuts the `listed` faces at the plane x = 0 (see above); the pieces of a listed face are listed.
inline void cut_at_plane(Surface& s, std::vector<std::uint32_t>& partner, std::vector<char>& listed)
{
  std::map<std::pair<std::uint32_t, std::uint32_t>, std::uint32_t> cut;
  for(std::size_t f = 0; f < s.triangles.size(); ++f)
    for(int k = 0; listed[f] && k < 3; ++k) {
      const std::uint32_t a = (std::min)(s.triangles[f][k], s.triangles[f][(k + 1) % 3]),
                          b = (std::max)(s.triangles[f][k], s.triangles[f][(k + 1) % 3]);
      const Vector_3d pa = s.points[a], pb = s.points[b];
      if(!(pa.x * pb.x < 0) || cut.count({a, b}))
        continue;
      Vector_3d q = pa + (pb - pa) * (pa.x / (pa.x - pb.x));
      q.x = 0;
      cut[{a, b}] = std::uint32_t(s.points.size());
      partner.push_back(std::uint32_t(s.points.size()));
      s.points.push_back(q);
    }
  if(cut.empty())
    return;
  std::vector<std::array<std::uint32_t, 3>> triangles;
  std::vector<char> pieces_listed;
  const auto add = [&](std::uint32_t a, std::uint32_t b, std::uint32_t c, char l) {
    triangles.push_back({{a, b, c}});
    pieces_listed.push_back(l);
  };
  for(std::size_t f = 0; f < s.triangles.size(); ++f) {
    std::vector<std::uint32_t> p; // the face's corners with the cut vertices between them
    std::vector<char> is_cut;
    for(int k = 0; k < 3; ++k) {
      const std::uint32_t a = s.triangles[f][k], b = s.triangles[f][(k + 1) % 3];
      p.push_back(a), is_cut.push_back(0);
      const auto it = cut.find({(std::min)(a, b), (std::max)(a, b)});
      if(it != cut.end())
        p.push_back(it->second), is_cut.push_back(1);
    }
    const std::size_t n = p.size();
    const auto at = [&](std::size_t i) { return p[i % n]; };
    if(n == 3) {
      add(p[0], p[1], p[2], listed[f]);
    } else if(n == 4) { // one cut edge, the third corner on the plane: a fan from the cut vertex
      const std::size_t i = std::size_t(std::find(is_cut.begin(), is_cut.end(), 1) - is_cut.begin());
      add(at(i), at(i + 1), at(i + 2), listed[f]);
      add(at(i), at(i + 2), at(i + 3), listed[f]);
    } else { // two cut edges: the corner between them alone, the quadrilateral by its shorter diagonal
      std::size_t j = 0;
      while(is_cut[j] || !is_cut[(j + 1) % n] || !is_cut[(j + n - 1) % n])
        ++j;
      add(at(j), at(j + 1), at(j + 4), listed[f]);
      const std::uint32_t q0 = at(j + 1), q1 = at(j + 2), q2 = at(j + 3), q3 = at(j + 4);
      if((s.points[q0] - s.points[q2]).squared_length() <= (s.points[q1] - s.points[q3]).squared_length()) {
        add(q0, q1, q2, listed[f]);
        add(q0, q2, q3, listed[f]);
      } else {
        add(q0, q1, q3, listed[f]);
        add(q1, q2, q3, listed[f]);
      }
    }
  }
  s.triangles.swap(triangles);
  listed.swap(pieces_listed);
}

// Drops the points no face uses (partners of dropped points become none).
inline void drop_unused_points(Surface& s, std::vector<std::uint32_t>& partner)
{
  std::vector<std::uint32_t> index(s.points.size(), no_partner);
  for(const auto& t : s.triangles)
    for(std::uint32_t v : t)
      index[v] = 0;
  Surface out;
  for(std::size_t i = 0; i < s.points.size(); ++i)
    if(index[i] == 0) {
      index[i] = std::uint32_t(out.points.size());
      out.points.push_back(s.points[i]);
    }
  std::vector<std::uint32_t> p(out.points.size(), no_partner);
  for(std::size_t i = 0; i < s.points.size(); ++i)
    if(index[i] != no_partner && partner[i] != no_partner)
      p[index[i]] = index[partner[i]];
  for(auto t : s.triangles)
    out.triangles.push_back({{index[t[0]], index[t[1]], index[t[2]]}});
  std::swap(s, out);
  partner.swap(p);
}

// Whether the triangles make a closed, oriented 2-manifold (each vertex's faces one fan).
inline bool is_closed_manifold(const Surface& s)
{
  typedef CGAL::Surface_mesh<CGAL::Simple_cartesian<double>::Point_3> Mesh;
  Mesh mesh;
  std::vector<Mesh::Vertex_index> v;
  for(std::size_t i = 0; i < s.points.size(); ++i)
    v.push_back(mesh.add_vertex());
  std::vector<std::size_t> incident(s.points.size(), 0);
  for(const auto& t : s.triangles) {
    if(mesh.add_face(v[t[0]], v[t[1]], v[t[2]]) == Mesh::null_face())
      return false;
    for(std::uint32_t i : t)
      ++incident[i];
  }
  for(auto h : mesh.halfedges())
    if(mesh.is_border(h))
      return false;
  for(std::size_t i = 0; i < s.points.size(); ++i)
    if(incident[i] > 0 && mesh.degree(v[i]) != incident[i])
      return false; // two fans
  return true;
}

// Replaces the listed faces on the negative side by the mirror images of those on the positive
// side; the number of faces copied, or no_partner for a listed face in the plane.
inline std::size_t copy_positive_side(Surface& c, std::vector<std::uint32_t>& p, const std::vector<char>& listed)
{
  std::vector<std::array<std::uint32_t, 3>> out;
  std::size_t copied = 0;
  for(std::size_t f = 0; f < c.triangles.size(); ++f) {
    const auto t = c.triangles[f];
    const double side = c.points[t[0]].x + c.points[t[1]].x + c.points[t[2]].x;
    if(!listed[f])
      out.push_back(t);
    else if(side == 0)
      return no_partner;
    else if(side > 0) {
      std::array<std::uint32_t, 3> m;
      for(int k = 0; k < 3; ++k) {
        const std::uint32_t u = t[k];
        if(p[u] == no_partner && c.points[u].x == 0)
          p[u] = u;
        if(p[u] == no_partner) {
          p[u] = std::uint32_t(c.points.size());
          p.push_back(u);
          c.points.push_back(mirrored(c.points[u]));
        }
        m[2 - k] = p[u];
      }
      out.push_back(t);
      out.push_back(m);
      ++copied;
    }
  }
  c.triangles.swap(out);
  drop_unused_points(c, p);
  return copied;
}

// The vertices on the plane where the copy would pinch the surface: around such a vertex (of a
// listed face) the faces are not on the positive side over one sector and on the negative side
// over the other (faces across the plane, their own mirror images, are skipped), or two faces on
// one side meet at an edge in the plane; and the corners of a listed face that lies in the plane.
inline std::vector<std::uint32_t> pinching_vertices(const Surface& c, const std::vector<char>& listed)
{
  std::vector<int> side(c.triangles.size());
  std::vector<std::vector<std::uint32_t>> faces_of(c.points.size());
  std::vector<char> check(c.points.size(), 0);
  for(std::size_t f = 0; f < c.triangles.size(); ++f) {
    const auto& t = c.triangles[f];
    const double x = c.points[t[0]].x + c.points[t[1]].x + c.points[t[2]].x;
    side[f] = x > 0 ? 1 : x < 0 ? -1 : 0;
    for(std::uint32_t v : t)
      if(c.points[v].x == 0) {
        faces_of[v].push_back(std::uint32_t(f));
        check[v] = check[v] || listed[f];
      }
  }
  std::vector<std::uint32_t> pinching;
  std::vector<char> in_plane(c.points.size(), 0); // corners of a listed face in the plane
  for(std::size_t f = 0; f < c.triangles.size(); ++f)
    for(std::uint32_t v : c.triangles[f])
      in_plane[v] = in_plane[v] || (listed[f] && side[f] == 0);
  for(std::uint32_t v = 0; v < c.points.size(); ++v) {
    if(in_plane[v]) {
      pinching.push_back(v);
      continue;
    }
    if(!check[v])
      continue;
    // The faces around v in order: from the face of corner a (a, b after v) to the face of corner b.
    std::map<std::uint32_t, std::uint32_t> face_from;
    for(std::uint32_t f : faces_of[v]) {
      const auto& t = c.triangles[f];
      const int k = t[0] == v ? 0 : t[1] == v ? 1 : 2;
      face_from[t[(k + 1) % 3]] = f;
    }
    std::vector<int> sides;
    bool same_side_plane_edge = false;
    std::uint32_t f = faces_of[v].front();
    for(std::size_t step = 0; step < faces_of[v].size(); ++step) {
      const auto& t = c.triangles[f];
      const int k = t[0] == v ? 0 : t[1] == v ? 1 : 2;
      const std::uint32_t b = t[(k + 2) % 3];
      const auto next = face_from.find(b);
      if(next == face_from.end())
        break;
      if(side[f] != 0)
        sides.push_back(side[f]);
      same_side_plane_edge = same_side_plane_edge || (c.points[b].x == 0 && side[f] != 0 && side[f] == side[next->second]);
      f = next->second;
    }
    std::size_t changes = 0;
    for(std::size_t i = 0; i < sides.size(); ++i)
      changes += sides[i] != sides[(i + 1) % sides.size()] ? 1 : 0;
    if(changes != 2 || same_side_plane_edge)
      pinching.push_back(v);
  }
  return pinching;
}

// Copies across the plane the faces without a mirror face (all faces when `all_faces`), as
// described above. A vertex on the plane where the copy would pinch the surface moves off it, to
// the positive side by a hundredth of the mean edge length (and loses its partner), and the copy
// starts again. Returns the number of faces copied, or no_partner (and `s`, `partner` unchanged)
// when the result is not a closed manifold or a copied face lies in the plane.
inline std::size_t copy_across_plane(Surface& s, std::vector<std::uint32_t>& partner, bool all_faces)
{
  Surface base = s;
  std::vector<std::uint32_t> base_partner = partner;
  const double shift = 0.01 * mean_edge_length(s);
  for(int attempt = 0; attempt < 8; ++attempt) {
    Surface c = base;
    std::vector<std::uint32_t> p = base_partner;
    std::vector<char> listed(c.triangles.size(), 1);
    if(!all_faces)
      listed = faces_to_copy(c, p);
    cut_at_plane(c, p, listed);
    const std::vector<std::uint32_t> pinching = pinching_vertices(c, listed);
    for(std::uint32_t v : pinching)
      if(v < base.points.size()) { // (cut vertices do not pinch)
        base.points[v].x = shift;
        base_partner[v] = no_partner;
      }
    if(!pinching.empty())
      continue;
    const std::size_t copied = copy_positive_side(c, p, listed);
    if(copied == no_partner || !is_closed_manifold(c))
      return no_partner;
    std::swap(s, c);
    partner.swap(p);
    return copied;
  }
  return no_partner;
}

} // namespace internal
} // namespace Surface_mesh_symmetrization
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_SYMMETRIZATION_INTERNAL_SIDE_COPY_H
