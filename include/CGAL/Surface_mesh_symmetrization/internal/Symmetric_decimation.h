// Copyright (c) 2026 CGAL Global Shape Analysis contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_SURFACE_MESH_SYMMETRIZATION_INTERNAL_SYMMETRIC_DECIMATION_H
#define CGAL_SURFACE_MESH_SYMMETRIZATION_INTERNAL_SYMMETRIC_DECIMATION_H

// Symmetry-preserving decimation (symmetric_decimation()): edge collapses of the Garland-Heckbert
// kind in which an edge and its mirror edge collapse together, on a mesh given in the frame of
// its reflection plane (the reflection is x -> -x, so mirrored positions stay exact).
//
// CGAL's edge_collapse() collapses one edge at a time from a private queue: collapsing the mirror
// edge too from its visitor would leave dead edges in that queue. Hence this loop over clusters,
// with CGAL's Euler operations and link condition. A cluster is
// - a pair: edge (a, b) and its mirror (a', b'), four vertices off the plane and apart (neither
//   mirror vertex in the other edge's stars); both collapse, to mirrored positions on a's side;
// - a self-mirrored edge: (a, b) on the plane, or (a, a') across it; it collapses onto the plane;
// - a T: edge (p, b) from a vertex p on the plane and its mirror (p, b'); both collapse into p
//   (b and b' not adjacent, their other common neighbours neighbours of p, both of degree 4 at
//   least, so that the second collapse remains possible after the first).
// Edges without a mirror edge, and edges at a border, are never collapsed: the mesh keeps the
// symmetric connectivity it has. A cluster's priority is the Garland-Heckbert error (plane
// quadrics of the incident faces, unit normals) of its worst edge, of the three vertices' quadric
// for a T; the placement the quadric's optimum (with x = 0 for a self-mirrored edge or a T), else
// the best of the edge's ends and midpoint.
// Without mirrored positions (the symmetric simplification: a symmetric connectivity on the
// positions of an asymmetric surface), each merged vertex goes to its own quadric's optimum (a
// T's too, off the plane), and the quadrics are given (the planes of the input's faces under
// each vertex's faces); once allow_other_positions(), the ends and midpoint of a cluster's edge
// are tried where that optimum folds a face.

#include <CGAL/Surface_mesh_symmetrization/internal/Symmetric_connectivity.h>

#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/Euler_operations.h>

#include <Eigen/Dense>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <functional>
#include <limits>
#include <queue>
#include <stdexcept>
#include <utility>
#include <vector>

namespace CGAL {
namespace Surface_mesh_symmetrization {
namespace internal {

class Symmetric_decimator
{
public:
  typedef CGAL::Simple_cartesian<double>::Point_3 Point;
  typedef CGAL::Surface_mesh<Point> Mesh;
  typedef Mesh::Vertex_index Vertex;
  typedef Mesh::Edge_index Edge;
  typedef Mesh::Halfedge_index Halfedge;
  typedef Eigen::Matrix<double, 4, 4, Eigen::DontAlign> Quadric;

  // `s`: the surface in the plane's frame, pairs exactly mirrored (make_pairs_exact()); `partner`:
  // per point its mirror vertex (pair_vertices()). `given`: per point, the quadric it starts with
  // (else the planes of its faces). Throws Bad_input for a non-manifold surface.
  Symmetric_decimator(const Surface& s, const std::vector<std::uint32_t>& partner, bool mirrored_positions = true,
                      const std::vector<Quadric>* given = nullptr)
    : m_mirrored_positions(mirrored_positions)
  {
    std::vector<Vertex> v(s.points.size());
    std::vector<char> used(s.points.size(), 0);
    for(const auto& t : s.triangles)
      for(std::uint32_t i : t)
        used[i] = 1;
    for(std::size_t i = 0; i < s.points.size(); ++i)
      if(used[i])
        v[i] = m_mesh.add_vertex(Point(s.points[i].x, s.points[i].y, s.points[i].z));
    for(const auto& t : s.triangles)
      if(m_mesh.add_face(v[t[0]], v[t[1]], v[t[2]]) == Mesh::null_face())
        throw Bad_input("symmetric_decimation: the mesh is not manifold (or has a face twice)");
    m_mirror = m_mesh.add_property_map<Vertex, Vertex>("v:mirror", Vertex()).first;
    m_quadric = m_mesh.add_property_map<Vertex, Quadric>("v:quadric", Quadric::Zero()).first;
    m_stamp = m_mesh.add_property_map<Edge, std::uint32_t>("e:stamp", 0).first;
    for(std::size_t i = 0; i < s.points.size(); ++i)
      if(used[i] && partner[i] != no_partner && used[partner[i]])
        m_mirror[v[i]] = v[partner[i]];
    for(auto f : m_mesh.faces()) {
      const Eigen::Vector4d r = given == nullptr ? face_plane(m_mesh.halfedge(f)) : Eigen::Vector4d::Zero();
      for(Vertex w : CGAL::vertices_around_face(m_mesh.halfedge(f), m_mesh))
        m_quadric[w] += r * r.transpose();
    }
    for(std::size_t i = 0; given != nullptr && i < s.points.size(); ++i)
      if(used[i])
        m_quadric[v[i]] = (*given)[i];
    m_cost_quantum = (std::max)(1e-12 * s.diagonal() * s.diagonal(), (std::numeric_limits<double>::min)());
    for(Edge e : m_mesh.edges())
      push(e);
  }

  // The quadric of the plane through p with unit normal n (the squared distance to it).
  static Quadric plane_quadric(const Vector_3d& n, const Vector_3d& p)
  {
    const Eigen::Vector4d r(n.x, n.y, n.z, -SAI::dot(n, p));
    return r * r.transpose();
  }

  const Mesh& mesh() const { return m_mesh; }
  Vertex mirror(Vertex v) const { return m_mirror[v]; }
  std::size_t number_of_faces() const { return m_mesh.number_of_faces(); }
  std::size_t collapses() const { return m_collapses; }
  std::size_t t_clusters() const { return m_t_clusters; } ///< of the collapses, the T clusters
  double largest_cost() const { return m_largest_cost; }

  // Collapses the cheapest valid cluster whose cost is at most `maximum_cost`; false when there is
  // none left.
  bool step(double maximum_cost = std::numeric_limits<double>::infinity())
  {
    while(!m_queue.empty()) {
      const Entry top = m_queue.top();
      m_queue.pop();
      const Edge e(top.edge);
      if(m_mesh.is_removed(e) || m_stamp[e] != top.stamp)
        continue;
      Plan plan;
      if(!plan_cluster(e, plan))
        continue;
      if(plan.cost > maximum_cost)
        return false;
      apply(plan);
      return true;
    }
    return false;
  }

  // From now on, a cluster whose optimal placement folds a face may collapse at the best of its
  // ends and midpoint that does not (without mirrored positions only). For when step() finds no
  // cluster left: without mirrored positions the quadrics are the input's, and where the restore
  // stretched the mesh their optima fold faces (the decimation of a posed bust, PSB mesh 281,
  // stalled at 1.6 times its target). Not from the start: the cow's and the camel's Hausdorff
  // distances at a fifth of the faces would grow by 20% and 6%. False when already allowed.
  bool allow_other_positions()
  {
    if(m_other_positions || m_mirrored_positions)
      return false;
    m_other_positions = true;
    for(Edge e : m_mesh.edges())
      push(e);
    return true;
  }

  // The live vertices and faces (vertex order of the mesh), and each vertex's partner.
  void export_surface(Surface& s, std::vector<std::uint32_t>& partner) const
  {
    std::vector<std::uint32_t> index(m_mesh.num_vertices(), no_partner);
    s = Surface();
    for(Vertex v : m_mesh.vertices()) {
      index[v.idx()] = std::uint32_t(s.points.size());
      const Point& p = m_mesh.point(v);
      s.points.emplace_back(p.x(), p.y(), p.z());
    }
    partner.assign(s.points.size(), no_partner);
    for(Vertex v : m_mesh.vertices())
      if(m_mirror[v] != Vertex())
        partner[index[v.idx()]] = index[m_mirror[v].idx()];
    for(auto f : m_mesh.faces()) {
      std::array<std::uint32_t, 3> t{{0, 0, 0}};
      std::size_t k = 0;
      for(Vertex w : CGAL::vertices_around_face(m_mesh.halfedge(f), m_mesh))
        t[k++] = index[w.idx()];
      s.triangles.push_back(t);
    }
  }

private:
  struct Entry
  {
    double cost;
    std::uint32_t edge, stamp;
    bool operator<(const Entry& o) const { return cost != o.cost ? cost > o.cost : edge > o.edge; } // min-heap
  };

  // A cluster ready to collapse: its edges (the second null for a self-mirrored edge) and the
  // position of the vertex each leaves.
  struct Plan
  {
    Edge edge, mirror_edge;
    bool paired = false, t_cluster = false;
    Vertex far_end; // of a T's mirror edge
    Vector_3d position, mirror_position;
    double cost = 0;
  };

  Vector_3d point(Vertex v) const
  {
    const Point& p = m_mesh.point(v);
    return Vector_3d(p.x(), p.y(), p.z());
  }

  // The plane of the face of h, (n, -n.p) with n its unit normal (zero when degenerate).
  Eigen::Vector4d face_plane(Halfedge h) const
  {
    const Vector_3d a = point(m_mesh.source(h)), b = point(m_mesh.target(h)), c = point(m_mesh.target(m_mesh.next(h)));
    Vector_3d n = SAI::cross(b - a, c - a);
    const double l = n.length();
    if(!(l > 0))
      return Eigen::Vector4d::Zero();
    n = n / l;
    return Eigen::Vector4d(n.x, n.y, n.z, -SAI::dot(n, a));
  }

  static double cost_at(const Quadric& q, const Vector_3d& p)
  {
    const Eigen::Vector4d h(p.x, p.y, p.z, 1.0);
    return (std::max)(0.0, double(h.transpose() * q * h));
  }

  // The position minimizing the quadric q (with x = 0 when `on_plane`), else the best of a, b and
  // their midpoint (moved onto the plane when `on_plane`).
  static Vector_3d place(const Quadric& q, const Vector_3d& a, const Vector_3d& b, bool on_plane)
  {
    const int first = on_plane ? 1 : 0, n = 3 - first;
    const Eigen::MatrixXd A = q.block(first, first, n, n);
    const Eigen::VectorXd rhs = -q.block(first, 3, n, 1);
    const Eigen::FullPivLU<Eigen::MatrixXd> lu(A);
    const double scale = A.cwiseAbs().maxCoeff();
    if(scale > 0 && lu.rank() == n && std::abs(lu.determinant()) > 1e-12 * std::pow(scale, n)) {
      const Eigen::VectorXd x = lu.solve(rhs);
      Vector_3d p(0, 0, 0);
      for(int i = 0; i < n; ++i)
        (i + first == 0 ? p.x : i + first == 1 ? p.y : p.z) = x(i);
      if(std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z) &&
         (p - (a + b) * 0.5).length() <= 2 * (a - b).length()) // not far off (a nearly flat quadric)
        return p;
    }
    Vector_3d best = a;
    double best_cost = std::numeric_limits<double>::infinity();
    for(Vector_3d c : {a, b, (a + b) * 0.5}) {
      if(on_plane)
        c.x = 0;
      const double k = cost_at(q, c);
      if(k < best_cost)
        best_cost = k, best = c;
    }
    return best;
  }

  // The positions to try for the vertex that merges a and b: place()'s, then, once
  // allow_other_positions(), a, b and their midpoint by increasing cost.
  std::vector<Vector_3d> positions(const Quadric& q, const Vector_3d& a, const Vector_3d& b, bool on_plane) const
  {
    std::vector<Vector_3d> c{place(q, a, b, on_plane)};
    if(!m_other_positions)
      return c;
    std::array<std::pair<double, Vector_3d>, 3> more{
      {{cost_at(q, a), a}, {cost_at(q, b), b}, {cost_at(q, (a + b) * 0.5), (a + b) * 0.5}}};
    std::stable_sort(more.begin(), more.end(),
                     [](const std::pair<double, Vector_3d>& x, const std::pair<double, Vector_3d>& y) { return x.first < y.first; });
    for(const auto& m : more)
      c.push_back(m.second);
    return c;
  }

  // The first of positions() at which collapsing the edge of h keeps the faces (and that of `mh`,
  // if given, at the mirror position), in `p`.
  bool first_valid(const Quadric& q, Halfedge h, Halfedge mh, bool on_plane, Vector_3d& p) const
  {
    for(const Vector_3d& c : positions(q, point(m_mesh.source(h)), point(m_mesh.target(h)), on_plane))
      if(keeps_faces(h, c) && (mh == Halfedge() || keeps_faces(mh, c))) {
        p = c;
        return true;
      }
    return false;
  }

  bool on_border(Vertex v) const { return m_mesh.is_border(v, false); }

  // Whether collapsing the edge of h to p keeps every surviving face around its ends turned the
  // same way (no fold) and not degenerate.
  bool keeps_faces(Halfedge h, const Vector_3d& p) const
  {
    const Vertex a = m_mesh.source(h), b = m_mesh.target(h);
    for(Vertex end : {a, b})
      for(Halfedge g : CGAL::halfedges_around_target(m_mesh.halfedge(end), m_mesh)) {
        if(m_mesh.is_border(g))
          continue;
        std::array<Vector_3d, 3> c;
        bool has_a = false, has_b = false;
        Halfedge k = g;
        for(int i = 0; i < 3; ++i, k = m_mesh.next(k)) {
          const Vertex w = m_mesh.target(k);
          has_a = has_a || w == a, has_b = has_b || w == b;
          c[std::size_t(i)] = (w == a || w == b) ? p : point(w);
        }
        if(has_a && has_b)
          continue; // a face of the edge: it goes
        std::array<Vector_3d, 3> o;
        k = g;
        for(int i = 0; i < 3; ++i, k = m_mesh.next(k))
          o[std::size_t(i)] = point(m_mesh.target(k));
        const Vector_3d before = SAI::cross(o[1] - o[0], o[2] - o[0]), after = SAI::cross(c[1] - c[0], c[2] - c[0]);
        if(!(SAI::dot(before, after) > 0) || !(after.length() > 1e-12 * before.length()))
          return false;
      }
    return true;
  }

  // The cluster of edge e, if it can collapse: its plan.
  bool plan_cluster(Edge e, Plan& plan) const
  {
    const Halfedge h = m_mesh.halfedge(e);
    const Vertex a = m_mesh.source(h), b = m_mesh.target(h), ma = m_mirror[a], mb = m_mirror[b];
    if(ma == Vertex() || mb == Vertex() || m_mesh.is_border(e) || on_border(a) || on_border(b))
      return false;
    if(!CGAL::Euler::does_satisfy_link_condition(e, m_mesh))
      return false;
    const Quadric q = m_quadric[a] + m_quadric[b];
    plan.edge = e;
    if((ma == a && mb == b) || (ma == b && mb == a)) { // self-mirrored: onto the plane
      plan.paired = false;
      if(!first_valid(q, h, Halfedge(), m_mirrored_positions, plan.position))
        return false;
      plan.cost = cost_at(q, plan.position);
      return true;
    }
    if((ma == a) != (mb == b))
      return plan_t_cluster(h, q, plan);
    const auto mh = CGAL::halfedge(ma, mb, m_mesh);
    if(!mh.second || ma == b || mb == a)
      return false; // no mirror edge
    // The mirror edge apart: neither of its ends in the stars of a and b.
    for(Vertex end : {a, b})
      for(Vertex w : CGAL::vertices_around_target(m_mesh.halfedge(end), m_mesh))
        if(w == ma || w == mb)
          return false;
    const Vector_3d pa = point(a), pb = point(b);
    const Quadric mq = m_quadric[ma] + m_quadric[mb];
    plan.paired = true;
    plan.mirror_edge = m_mesh.edge(mh.first);
    if(!CGAL::Euler::does_satisfy_link_condition(plan.mirror_edge, m_mesh))
      return false;
    if(m_mirrored_positions) {
      plan.position = place(q, pa, pb, false);
      if(!(pa.x * pb.x > 0) || !(plan.position.x * pa.x > 0))
        return false; // a pair lies on one side, and so does its merged vertex
      plan.mirror_position = mirrored(plan.position);
      if(!keeps_faces(h, plan.position) || !keeps_faces(mh.first, plan.mirror_position))
        return false;
    } else if(!first_valid(q, h, Halfedge(), false, plan.position) ||
              !first_valid(mq, mh.first, Halfedge(), false, plan.mirror_position))
      return false;
    plan.cost = (std::max)(cost_at(q, plan.position), cost_at(mq, plan.mirror_position));
    return true;
  }

  // The cluster of the edge of h from a vertex on the plane to one off it, with its mirror edge
  // (a T): both collapse into the vertex on the plane (which stays on it with mirrored
  // positions). The second collapse
  // must remain possible after the first (the link condition): the two off-plane ends are not
  // adjacent, their other common neighbours are neighbours of the plane vertex (then the second
  // edge's only common neighbours are its two apices), and they are not of degree 3 (then the
  // second edge is not in a tetrahedron, a small closed component).
  bool plan_t_cluster(Halfedge h, const Quadric& q, Plan& plan) const
  {
    const Vertex p = m_mirror[m_mesh.source(h)] == m_mesh.source(h) ? m_mesh.source(h) : m_mesh.target(h);
    const Vertex o = p == m_mesh.source(h) ? m_mesh.target(h) : m_mesh.source(h), mo = m_mirror[o];
    const auto mh = CGAL::halfedge(p, mo, m_mesh);
    if(!mh.second || mo == o || on_border(mo) || m_mesh.degree(mo) < 4 || m_mesh.degree(o) < 4)
      return false; // (of degree 3, b' could end in a tetrahedron after the first collapse; both
                    // ends checked, so that either edge of the T plans it alike)
    for(Vertex w : CGAL::vertices_around_target(m_mesh.halfedge(o), m_mesh)) {
      if(w == mo)
        return false;
      if(w == p)
        continue;
      bool common = false, next_to_p = false;
      for(Vertex x : CGAL::vertices_around_target(m_mesh.halfedge(w), m_mesh))
        common = common || x == mo, next_to_p = next_to_p || x == p;
      if(common && !next_to_p)
        return false;
    }
    const Quadric all = q + m_quadric[mo];
    plan.t_cluster = true;
    plan.far_end = mo;
    plan.mirror_edge = m_mesh.edge(mh.first);
    if(!CGAL::Euler::does_satisfy_link_condition(plan.mirror_edge, m_mesh) ||
       !first_valid(all, h, mh.first, m_mirrored_positions, plan.position))
      return false;
    plan.cost = cost_at(all, plan.position);
    return true;
  }

  // Collapses edge e to p; the vertex kept, with the quadric of both ends.
  Vertex collapse(Edge e, const Vector_3d& p)
  {
    const Halfedge h = m_mesh.halfedge(e);
    const Quadric q = m_quadric[m_mesh.source(h)] + m_quadric[m_mesh.target(h)];
    const Vertex kept = CGAL::Euler::collapse_edge(e, m_mesh);
    m_mesh.point(kept) = Point(p.x, p.y, p.z);
    m_quadric[kept] = q;
    return kept;
  }

  void apply(const Plan& plan)
  {
    m_largest_cost = (std::max)(m_largest_cost, plan.cost);
    ++m_collapses;
    const Vertex s = collapse(plan.edge, plan.position);
    if(plan.t_cluster) { // then the mirror edge, from the vertex kept to the other off-plane end
      const Edge second = m_mesh.edge(CGAL::halfedge(s, plan.far_end, m_mesh).first);
      if(!CGAL::Euler::does_satisfy_link_condition(second, m_mesh)) // plan_t_cluster() rules it out
        throw std::logic_error("symmetric decimation: a T cluster's second collapse became invalid");
      const Vertex t = collapse(second, plan.position);
      ++m_t_clusters;
      m_mirror[t] = t;
      update_around(t);
      return;
    }
    if(!plan.paired) {
      m_mirror[s] = s;
      update_around(s);
      return;
    }
    const Vertex t = collapse(plan.mirror_edge, plan.mirror_position);
    m_mirror[s] = t, m_mirror[t] = s;
    update_around(s);
    update_around(t);
  }

  // Every edge within one ring of v: its cost and validity may have changed.
  void update_around(Vertex v)
  {
    for(Vertex w : CGAL::vertices_around_target(m_mesh.halfedge(v), m_mesh))
      for(Halfedge g : CGAL::halfedges_around_target(m_mesh.halfedge(w), m_mesh))
        push(m_mesh.edge(g));
  }

  // The order of a cost in the queue: costs within 1e-12 of the squared diagonal of each other are
  // mostly ranked equal (then by edge), so that rounding (another pose) seldom changes the order.
  double rank(double cost) const { return std::floor(cost / m_cost_quantum); }

  // Queues e (once per cluster: the one of its two edges with the smaller index).
  void push(Edge e)
  {
    ++m_stamp[e];
    Plan plan;
    if(!plan_cluster(e, plan))
      return;
    if((plan.paired || plan.t_cluster) && plan.mirror_edge.idx() < e.idx()) {
      const Edge m = plan.mirror_edge;
      ++m_stamp[m];
      // A T is planned from the edge it is queued under (its positions are tried along that edge).
      if(plan.t_cluster && !plan_cluster(m, plan))
        return;
      m_queue.push(Entry{rank(plan.cost), std::uint32_t(m.idx()), m_stamp[m]});
      return;
    }
    m_queue.push(Entry{rank(plan.cost), std::uint32_t(e.idx()), m_stamp[e]});
  }

  Mesh m_mesh;
  Mesh::Property_map<Vertex, Vertex> m_mirror;
  Mesh::Property_map<Vertex, Quadric> m_quadric;
  Mesh::Property_map<Edge, std::uint32_t> m_stamp;
  std::priority_queue<Entry> m_queue;
  std::size_t m_collapses = 0, m_t_clusters = 0;
  double m_largest_cost = 0;
  double m_cost_quantum = 1;
  bool m_mirrored_positions = true, m_other_positions = false;
};

} // namespace internal
} // namespace Surface_mesh_symmetrization
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_SYMMETRIZATION_INTERNAL_SYMMETRIC_DECIMATION_H
