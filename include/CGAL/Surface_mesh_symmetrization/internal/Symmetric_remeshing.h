// Copyright (c) 2026 CGAL Global Shape Analysis contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_SURFACE_MESH_SYMMETRIZATION_INTERNAL_SYMMETRIC_REMESHING_H
#define CGAL_SURFACE_MESH_SYMMETRIZATION_INTERNAL_SYMMETRIC_REMESHING_H

// Symmetric remeshing (symmetric_remeshing()), on a closed surface given in the frame of its
// reflection plane (the reflection is x -> -x):
// 1. mirror points: each vertex without a mirror partner gets one, a new vertex where its mirror
//    image meets the surface (the nearest point with a normal turned the mirrored way), inserted in
//    the face that holds it (the face split in three, or the edge and its two faces split when the
//    point is on an edge; a point at a vertex without a partner pairs with that vertex). Faces are
//    only split, so a point is located among the pieces of the input face it lies on;
// 2. exact pairs: a pair's vertices move to exact mirror positions (their mean), a vertex that is
//    its own partner onto the plane;
// 3. flips: the vertex set is now symmetric, the triangulation not; an edge without a mirror edge
//    is flipped when the new edge has one (or is its own mirror image), best gain first, then
//    least change of the surface (the squared distances of the new edge's midpoint to the planes
//    of the two faces replaced), never across a fold. Only edges without a mirror are flipped and
//    each flip adds one or two mirrored edges, so the flips end and never undo a correspondence.
// Where the sides' triangulations still differ around a sharp edge they are overlaid
// (Side_overlay.h); what is left without a mirror is copied across the plane (Side_copy.h).

#include <CGAL/Surface_mesh_symmetrization/internal/Surface_index.h>
#include <CGAL/Surface_mesh_symmetrization/internal/Symmetric_connectivity.h>
#include <CGAL/Shape_analysis/Bad_input.h>

#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/Euler_operations.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>
#include <tuple>
#include <vector>

namespace CGAL {
namespace Surface_mesh_symmetrization {
namespace internal {

class Symmetric_remesher
{
public:
  typedef CGAL::Simple_cartesian<double>::Point_3 Point;
  typedef CGAL::Surface_mesh<Point> Mesh;
  typedef Mesh::Vertex_index Vertex;
  typedef Mesh::Face_index Face;
  typedef Mesh::Edge_index Edge;
  typedef Mesh::Halfedge_index Halfedge;

  // `s`: a closed manifold surface in the plane's frame; `partner`: per point its mirror partner
  // (pair_vertices()). Throws Bad_input for a surface that is not closed or not manifold.
  Symmetric_remesher(const Surface& s, const std::vector<std::uint32_t>& partner, const std::string& who)
    : m_surface(s), m_vertex(s.points.size())
  {
    std::vector<char> used(s.points.size(), 0);
    for(const auto& t : s.triangles)
      for(std::uint32_t i : t)
        used[i] = 1;
    for(std::size_t i = 0; i < s.points.size(); ++i)
      if(used[i])
        m_vertex[i] = m_mesh.add_vertex(Point(s.points[i].x, s.points[i].y, s.points[i].z));
    m_mirror = m_mesh.add_property_map<Vertex, Vertex>("v:mirror", Vertex()).first;
    m_origin = m_mesh.add_property_map<Face, std::uint32_t>("f:origin", no_partner).first;
    for(const auto& t : s.triangles) {
      const Face f = m_mesh.add_face(m_vertex[t[0]], m_vertex[t[1]], m_vertex[t[2]]);
      if(f == Mesh::null_face())
        throw Bad_input(who + ": the mesh is not manifold (or has a face twice)");
      m_origin[f] = std::uint32_t(m_children.size());
      m_children.push_back({f});
    }
    for(Halfedge h : m_mesh.halfedges())
      if(m_mesh.is_border(h))
        throw Bad_input(who + ": the mesh is not closed (symmetric remeshing needs a closed surface)");
    for(std::size_t i = 0; i < s.points.size(); ++i)
      if(used[i] && partner[i] != no_partner && used[partner[i]])
        m_mirror[m_vertex[i]] = m_vertex[partner[i]];
  }

  const Mesh& mesh() const { return m_mesh; }

  // Step 1: a mirror point for each vertex without a partner, if the surface passes within `reach`
  // of its mirror image. Returns the number of vertices paired.
  std::size_t insert_mirror_points(double reach)
  {
    const Surface_index index(m_surface);
    const std::vector<Vector_3d> normals = m_surface.vertex_normals();
    std::size_t paired = 0;
    std::uint32_t hint = Surface_index::no_face;
    for(std::size_t i = 0; i < m_vertex.size(); ++i) {
      const Vertex v = m_vertex[i];
      if(v == Vertex() || m_mirror[v] != Vertex())
        continue;
      const Surface_point c =
        index.closest_compatible(mirrored(m_surface.points[i]), mirrored(normals[i]), 0.0, hint, reach);
      if(!c.found || !(c.squared_distance <= reach * reach))
        continue;
      hint = c.face;
      paired += insert(v, c.face, c.point) ? 1 : 0;
    }
    return paired;
  }

  // Step 2: pairs at exact mirror positions, vertices that are their own partner on the plane.
  void make_pairs_exact()
  {
    for(Vertex v : m_mesh.vertices()) {
      const Vertex w = m_mirror[v];
      if(w == v) {
        Point& p = m_mesh.point(v);
        p = Point(0, p.y(), p.z());
      } else if(w != Vertex() && v < w) {
        const Vector_3d q = (point(v) + mirrored(point(w))) * 0.5, r = mirrored(q);
        m_mesh.point(v) = Point(q.x, q.y, q.z);
        m_mesh.point(w) = Point(r.x, r.y, r.z);
      }
    }
  }

  // Step 3: flips that give edges mirror edges, while the surface moves by at most `bound` (the
  // root of the flip error). Returns the number of flips.
  std::size_t flip(double bound)
  {
    std::size_t flips = 0;
    for(;;) {
      std::vector<std::tuple<int, double, std::uint32_t>> candidates; // (-gain, error, edge)
      for(Edge e : m_mesh.edges()) {
        double error = 0;
        const int gain = flip_gain(m_mesh.halfedge(e), error);
        if(gain > 0 && error <= bound * bound)
          candidates.emplace_back(-gain, error, std::uint32_t(e.idx()));
      }
      std::sort(candidates.begin(), candidates.end());
      std::size_t done = 0;
      for(const auto& c : candidates) {
        const Halfedge h = m_mesh.halfedge(Edge(std::get<2>(c)));
        double error = 0;
        if(flip_gain(h, error) > 0 && error <= bound * bound) { // still valid after the flips before
          CGAL::Euler::flip_edge(h, m_mesh);
          ++done;
        }
      }
      flips += done;
      if(done == 0)
        return flips;
    }
  }

  // The vertices (in the mesh's order), faces and partners.
  void export_surface(Surface& s, std::vector<std::uint32_t>& partner) const
  {
    s = Surface();
    for(Vertex v : m_mesh.vertices())
      s.points.push_back(point(v));
    partner.assign(s.points.size(), no_partner);
    for(Vertex v : m_mesh.vertices())
      if(m_mirror[v] != Vertex())
        partner[v.idx()] = std::uint32_t(m_mirror[v].idx());
    for(Face f : m_mesh.faces()) {
      const Halfedge h = m_mesh.halfedge(f);
      s.triangles.push_back({{std::uint32_t(m_mesh.source(h).idx()), std::uint32_t(m_mesh.target(h).idx()),
                              std::uint32_t(m_mesh.target(m_mesh.next(h)).idx())}});
    }
  }

private:
  Vector_3d point(Vertex v) const
  {
    const Point& p = m_mesh.point(v);
    return Vector_3d(p.x(), p.y(), p.z());
  }

  // The barycentric coordinates of p (on the plane of the face of h, or near it) for the corners
  // target(h), target(next(h)), target(next(next(h))); all -1 for a degenerate face.
  std::array<double, 3> barycentric(Halfedge h, const Vector_3d& p) const
  {
    const Vector_3d a = point(m_mesh.target(h)), b = point(m_mesh.target(m_mesh.next(h))),
                    c = point(m_mesh.source(h));
    const Vector_3d n = SAI::cross(b - a, c - a);
    const double nn = SAI::dot(n, n);
    if(!(nn > 0))
      return {{-1, -1, -1}};
    const double u = SAI::dot(SAI::cross(b - p, c - p), n) / nn, v = SAI::dot(SAI::cross(c - p, a - p), n) / nn;
    return {{u, v, 1 - u - v}};
  }

  // Pairs v with a new vertex at p, on input face f (or with the vertex at p when it has no
  // partner). False when p is at a vertex that has one.
  bool insert(Vertex v, std::uint32_t f, const Vector_3d& p)
  {
    Halfedge best;
    std::array<double, 3> b{{-1, -1, -1}};
    double best_min = -std::numeric_limits<double>::infinity();
    for(Face child : m_children[f]) {
      const Halfedge h = m_mesh.halfedge(child);
      const std::array<double, 3> c = barycentric(h, p);
      const double m = (std::min)({c[0], c[1], c[2]});
      if(m > best_min)
        best_min = m, best = h, b = c;
    }
    if(best == Halfedge())
      return false;
    const double eps = 1e-3;
    const int small = (b[0] < eps) + (b[1] < eps) + (b[2] < eps);
    Vertex w;
    if(small >= 2) { // at a corner
      const int k = b[0] >= b[1] && b[0] >= b[2] ? 0 : b[1] >= b[2] ? 1 : 2;
      w = m_mesh.target(k == 0 ? best : k == 1 ? m_mesh.next(best) : m_mesh.prev(best));
      if(w == v || m_mirror[w] != Vertex())
        return false;
    } else if(small == 1) { // on the edge opposite the small coordinate's corner
      const int k = b[0] < eps ? 0 : b[1] < eps ? 1 : 2;
      w = split_edge(k == 0 ? m_mesh.prev(best) : k == 1 ? best : m_mesh.next(best), p);
    } else {
      const Halfedge g = CGAL::Euler::add_center_vertex(best, m_mesh);
      w = m_mesh.target(g);
      m_mesh.point(w) = Point(p.x, p.y, p.z);
      adopt_faces_around(w, f);
    }
    m_mirror[w] = v;
    m_mirror[v] = w;
    return true;
  }

  // Splits the edge of h at the point of its line nearest to p, and the faces on both sides; the
  // new vertex.
  Vertex split_edge(Halfedge h, const Vector_3d& p)
  {
    const Vector_3d a = point(m_mesh.source(h)), d = point(m_mesh.target(h)) - a;
    const double t = (std::min)(0.999, (std::max)(0.001, SAI::dot(p - a, d) / SAI::dot(d, d)));
    const std::uint32_t inside = m_origin[m_mesh.face(h)], outside = m_origin[m_mesh.face(m_mesh.opposite(h))];
    const Halfedge g = CGAL::Euler::split_edge(h, m_mesh); // g: source(h) -> new vertex, h: new -> target
    const Vertex w = m_mesh.target(g);
    const Vector_3d q = a + d * t;
    m_mesh.point(w) = Point(q.x, q.y, q.z);
    const Halfedge k = m_mesh.opposite(h); // target -> new vertex, on the other face
    adopt_new(CGAL::Euler::split_face(g, m_mesh.next(m_mesh.next(g)), m_mesh), inside);
    adopt_new(CGAL::Euler::split_face(k, m_mesh.next(m_mesh.next(k)), m_mesh), outside);
    return w;
  }

  void adopt(Face face, std::uint32_t origin)
  {
    m_origin[face] = origin;
    m_children[origin].push_back(face);
  }

  // The face of h or of its opposite that is new (made by a split) is a piece of input face `origin`.
  void adopt_new(Halfedge h, std::uint32_t origin)
  {
    for(Face face : {m_mesh.face(h), m_mesh.face(m_mesh.opposite(h))})
      if(m_origin[face] == no_partner)
        adopt(face, origin);
  }

  void adopt_faces_around(Vertex w, std::uint32_t origin)
  {
    for(Face face : CGAL::faces_around_target(m_mesh.halfedge(w), m_mesh))
      if(m_origin[face] == no_partner)
        adopt(face, origin);
  }

  // The number of edges given a mirror by flipping the edge of h (0 when it has one, when the
  // flip is not possible or folds the surface), and the flip's error.
  int flip_gain(Halfedge h, double& error) const
  {
    const Vertex a = m_mesh.source(h), b = m_mesh.target(h), c = m_mesh.target(m_mesh.next(h)),
                 d = m_mesh.target(m_mesh.next(m_mesh.opposite(h)));
    if(c == d || has_mirror_edge(a, b) || CGAL::halfedge(c, d, m_mesh).second)
      return 0;
    const Vertex mc = m_mirror[c], md = m_mirror[d];
    if(mc == Vertex() || md == Vertex())
      return 0;
    int gain = 1; // (c, d) its own mirror image
    if(!((mc == c && md == d) || (mc == d && md == c))) {
      if(!CGAL::halfedge(mc, md, m_mesh).second || (mc == a && md == b) || (mc == b && md == a))
        return 0;
      gain = 2; // (c, d) and its mirror edge
    }
    const Vector_3d pa = point(a), pb = point(b), pc = point(c), pd = point(d);
    const Vector_3d n1 = SAI::cross(pb - pa, pc - pa), n2 = SAI::cross(pa - pb, pd - pb), n = n1 + n2;
    const Vector_3d m1 = SAI::cross(pd - pa, pc - pa), m2 = SAI::cross(pb - pd, pc - pd);
    const double scale = n.length();
    if(!(SAI::dot(m1, n) > 0 && SAI::dot(m2, n) > 0 && m1.length() > 1e-9 * scale && m2.length() > 1e-9 * scale))
      return 0;
    const Vector_3d mid = (pc + pd) * 0.5;
    error = 0;
    for(const Vector_3d& nf : {n1, n2}) {
      const double l = nf.length();
      const double distance = l > 0 ? SAI::dot(nf, mid - pa) / l : 0.0;
      error += distance * distance;
    }
    return gain;
  }

  bool has_mirror_edge(Vertex a, Vertex b) const
  {
    const Vertex ma = m_mirror[a], mb = m_mirror[b];
    return ma != Vertex() && mb != Vertex() && CGAL::halfedge(ma, mb, m_mesh).second;
  }

  const Surface& m_surface;
  Mesh m_mesh;
  std::vector<Vertex> m_vertex;               // per input point
  std::vector<std::vector<Face>> m_children;  // per input face, the faces it is split into
  Mesh::Property_map<Vertex, Vertex> m_mirror;
  Mesh::Property_map<Face, std::uint32_t> m_origin;
};

} // namespace internal
} // namespace Surface_mesh_symmetrization
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_SYMMETRIZATION_INTERNAL_SYMMETRIC_REMESHING_H
