// Copyright (c) 2026 CGAL Global Shape Analysis contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_SURFACE_MESH_SYMMETRIZATION_INTERNAL_SYMMETRIC_FLIPS_H
#define CGAL_SURFACE_MESH_SYMMETRIZATION_INTERNAL_SYMMETRIC_FLIPS_H

// Edge flips that keep a connectivity mirrored and bring the surface closer to a reference
// surface: an edge and its mirror edge are flipped together (an edge that is its own mirror image
// alone, when its quad is), when the two quads' new faces lie closer to the reference than the old
// ones. The positions need not be mirror images (the symmetric simplification's restored mesh
// follows the asymmetric input): only the connectivity is mirrored. Where a piecewise linear
// surface through given vertices follows a crease of the reference depends on which diagonal
// each quad takes; the remeshing picks them for symmetry, these flips for the reference.

#include <CGAL/Surface_mesh_symmetrization/internal/Surface_index.h>
#include <CGAL/Surface_mesh_symmetrization/internal/Symmetric_connectivity.h>

#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/Euler_operations.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <tuple>
#include <vector>

namespace CGAL {
namespace Surface_mesh_symmetrization {
namespace internal {

class Symmetric_flipper
{
public:
  typedef CGAL::Simple_cartesian<double>::Point_3 Point;
  typedef CGAL::Surface_mesh<Point> Mesh;
  typedef Mesh::Vertex_index Vertex;
  typedef Mesh::Face_index Face;
  typedef Mesh::Edge_index Edge;
  typedef Mesh::Halfedge_index Halfedge;

  // `s`: a closed manifold surface; `partner`: per point its mirror vertex (the connectivity
  // mirrored by it); `reference`: the surface to follow.
  Symmetric_flipper(const Surface& s, const std::vector<std::uint32_t>& partner, const Surface_index& reference)
    : m_reference(reference)
  {
    m_mirror = m_mesh.add_property_map<Vertex, Vertex>("v:mirror", Vertex()).first;
    std::vector<Vertex> vertex;
    for(const Vector_3d& p : s.points)
      vertex.push_back(m_mesh.add_vertex(Point(p.x, p.y, p.z)));
    for(const auto& t : s.triangles)
      m_valid = m_valid && m_mesh.add_face(vertex[t[0]], vertex[t[1]], vertex[t[2]]) != Mesh::null_face();
    for(std::size_t i = 0; i < s.points.size(); ++i)
      if(partner[i] != no_partner)
        m_mirror[vertex[i]] = vertex[partner[i]];
  }

  // Whether every face of the surface could be added (a manifold surface): flip() and
  // export_surface() do nothing otherwise.
  bool valid() const { return m_valid; }

  // Flips, by rounds of the best gains first, the mirror pairs of edges whose quads' faces come
  // closer to the reference by at least `gain` (the largest distance of their sample points, over
  // both quads, shrinks to that fraction or less, and neither quad's own grows beyond
  // max(its own, `floor`)) from farther than `floor`; at most `rounds` rounds.
  // Returns the number of edges flipped.
  std::size_t flip(double gain, double floor, int rounds)
  {
    std::size_t flips = 0;
    if(!m_valid)
      return flips;
    for(int round = 0; round < rounds; ++round) {
      std::vector<std::pair<double, std::uint32_t>> candidates; // (after / before, edge)
      for(Edge e : m_mesh.edges()) {
        double ratio = 0;
        if(plan(m_mesh.halfedge(e), gain, floor, ratio))
          candidates.emplace_back(ratio, std::uint32_t(e.idx()));
      }
      std::sort(candidates.begin(), candidates.end());
      std::size_t done = 0;
      for(const auto& c : candidates) {
        const Halfedge h = m_mesh.halfedge(Edge(c.second));
        double ratio = 0;
        if(!plan(h, gain, floor, ratio)) // still valid after the flips before
          continue;
        const Vertex a = m_mesh.source(h), b = m_mesh.target(h);
        const Vertex ma = m_mirror[a], mb = m_mirror[b];
        const bool self = (ma == a && mb == b) || (ma == b && mb == a);
        const Halfedge mh = self ? Halfedge() : CGAL::halfedge(ma, mb, m_mesh).first;
        CGAL::Euler::flip_edge(h, m_mesh);
        ++done;
        if(!self) {
          CGAL::Euler::flip_edge(mh, m_mesh);
          ++done;
        }
      }
      flips += done;
      if(done == 0)
        break;
    }
    return flips;
  }

  // The surface, flipped (unchanged when not valid()).
  void export_surface(Surface& s) const
  {
    if(!m_valid)
      return;
    s.points.clear();
    s.triangles.clear();
    for(Vertex v : m_mesh.vertices())
      s.points.push_back(point(v));
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

  // The largest distance to the reference of the sample points of triangle (a, b, c): its
  // centroid and the centroids of its three corner quarters.
  double deviation(const Vector_3d& a, const Vector_3d& b, const Vector_3d& c) const
  {
    double largest = 0;
    for(const Vector_3d& q : {(a + b + c) / 3.0, (a * 2.0 + b + c) / 4.0, (a + b * 2.0 + c) / 4.0,
                              (a + b + c * 2.0) / 4.0}) {
      const Surface_point p = m_reference.closest(q, m_hint);
      if(p.found) {
        m_hint = p.face;
        largest = (std::max)(largest, std::sqrt(p.squared_distance));
      }
    }
    return largest;
  }

  // Whether the edge of h can be flipped (with the flip, quad a d b c becomes faces a d c and
  // d b c); its faces' deviation before and after.
  bool quad(Halfedge h, double& before, double& after) const
  {
    const Vertex a = m_mesh.source(h), b = m_mesh.target(h), c = m_mesh.target(m_mesh.next(h)),
                 d = m_mesh.target(m_mesh.next(m_mesh.opposite(h)));
    if(m_mesh.is_border(m_mesh.edge(h)) || c == d || CGAL::halfedge(c, d, m_mesh).second)
      return false;
    const Vector_3d pa = point(a), pb = point(b), pc = point(c), pd = point(d);
    const Vector_3d n = SAI::cross(pb - pa, pc - pa) + SAI::cross(pa - pb, pd - pb);
    const Vector_3d n1 = SAI::cross(pd - pa, pc - pa), n2 = SAI::cross(pb - pd, pc - pd);
    const double scale = n.length();
    if(!(SAI::dot(n1, n) > 0 && SAI::dot(n2, n) > 0 && n1.length() > 1e-6 * scale && n2.length() > 1e-6 * scale))
      return false; // the flip would fold or flatten a face
    before = (std::max)(deviation(pa, pb, pc), deviation(pb, pa, pd));
    after = (std::max)(deviation(pa, pd, pc), deviation(pd, pb, pc));
    return true;
  }

  // Whether the edge of h and its mirror edge should be flipped, and the ratio of the deviations.
  bool plan(Halfedge h, double gain, double floor, double& ratio) const
  {
    const Vertex a = m_mesh.source(h), b = m_mesh.target(h), c = m_mesh.target(m_mesh.next(h)),
                 d = m_mesh.target(m_mesh.next(m_mesh.opposite(h)));
    const Vertex ma = m_mirror[a], mb = m_mirror[b], mc = m_mirror[c], md = m_mirror[d];
    if(ma == Vertex() || mb == Vertex() || mc == Vertex() || md == Vertex())
      return false;
    double before = 0, after = 0;
    if(!quad(h, before, after))
      return false;
    const bool self = (ma == a && mb == b) || (ma == b && mb == a);
    if(self) { // the quad must be its own mirror image, and so the new edge
      if(!((mc == c && md == d) || (mc == d && md == c)))
        return false;
    } else {
      const auto mh = CGAL::halfedge(ma, mb, m_mesh);
      if(!mh.second)
        return false;
      const Halfedge g = mh.first; // from ma to mb: the mirror quad is turned the other way
      const Vertex gc = m_mesh.target(m_mesh.next(g)), gd = m_mesh.target(m_mesh.next(m_mesh.opposite(g)));
      if(!((gc == md && gd == mc) || (gc == mc && gd == md)))
        return false;
      // The two quads must not share a face, nor the new edges be one edge.
      const Face f[4] = {m_mesh.face(h), m_mesh.face(m_mesh.opposite(h)), m_mesh.face(g),
                         m_mesh.face(m_mesh.opposite(g))};
      if(f[0] == f[2] || f[0] == f[3] || f[1] == f[2] || f[1] == f[3])
        return false;
      if((mc == c && md == d) || (mc == d && md == c))
        return false;
      double mirror_before = 0, mirror_after = 0;
      if(!quad(g, mirror_before, mirror_after))
        return false;
      // Neither side may get worse (the sides differ where the input is not symmetric).
      if(after > (std::max)(before, floor) || mirror_after > (std::max)(mirror_before, floor))
        return false;
      before = (std::max)(before, mirror_before);
      after = (std::max)(after, mirror_after);
    }
    if(!(before > floor) || !(after <= gain * before))
      return false;
    ratio = after / before;
    return true;
  }

  const Surface_index& m_reference;
  mutable std::uint32_t m_hint = Surface_index::no_face; // of the queries: not for concurrent use
  Mesh m_mesh;
  Mesh::Property_map<Vertex, Vertex> m_mirror;
  bool m_valid = true;
};

} // namespace internal
} // namespace Surface_mesh_symmetrization
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_SYMMETRIZATION_INTERNAL_SYMMETRIC_FLIPS_H
