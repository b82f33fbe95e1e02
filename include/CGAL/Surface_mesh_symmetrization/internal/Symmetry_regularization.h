// Copyright (c) 2026 CGAL Global Shape Analysis contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_SURFACE_MESH_SYMMETRIZATION_INTERNAL_SYMMETRY_REGULARIZATION_H
#define CGAL_SURFACE_MESH_SYMMETRIZATION_INTERNAL_SYMMETRY_REGULARIZATION_H

// The relations between symmetries made exact (regularize_symmetries()), on plain doubles:
//   1. axis groups: planes and rotations whose lines nearly coincide (at least three of them, or a
//      rotation with a plane) get one common axis, and the planes of a group angles that are
//      multiples of pi / k (k a rotation's order, or from the number of planes m to 2 m), or else
//      perpendicular where they nearly are;
//   2. directions: each group axis, plane normal or rotation axis, taken in the order of the input,
//      is made parallel or perpendicular to the directions fixed before it when it nearly is;
//   0. and 3. duplicates (the same plane or turn twice, within the tolerances) are dropped, first
//      and again once the others moved.

#include <CGAL/Surface_mesh_symmetrization/internal/Rotation_detection.h>
#include <CGAL/Surface_mesh_symmetrization/internal/Symmetry_geometry.h>

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

namespace CGAL {
namespace Surface_mesh_symmetrization {
namespace internal {

// One symmetry as the regularization sees it.
struct Regular_symmetry
{
  enum Kind { PLANE, ROTATION, OTHER };
  Kind kind = OTHER;
  Vector_3d direction; // a plane's unit normal, a rotation's unit axis
  double offset = 0;   // a plane: n.x = offset
  Vector_3d point;     // a rotation: the point of its axis nearest the reference centre
  double angle = 0;    // a rotation: the turn about `direction`, radians, in (0, pi]
  bool dropped = false;
};

inline Vector_3d unit(const Vector_3d& v) { return v / v.length(); }

// The rotation of w that takes the unit vector `from` to the unit vector `to` (the shortest one).
inline Vector_3d align_turn(const Vector_3d& from, const Vector_3d& to, const Vector_3d& w)
{
  const Vector_3d axis = SAI::cross(from, to);
  const double s = axis.length();
  if(!(s > 1e-300))
    return w;
  return turn(axis / s, std::atan2(s, SAI::dot(from, to)), w);
}

// A plane, a rotation (a proper orthogonal linear part, not the identity) or another map, with a
// rotation's axis point taken nearest `centre`.
inline Regular_symmetry regular_symmetry(const Affine_3d& a, bool is_reflection, const Plane_3d& plane,
                                         const Vector_3d& centre)
{
  Regular_symmetry r;
  if(is_reflection) {
    r.kind = Regular_symmetry::PLANE;
    r.direction = plane.normal;
    r.offset = plane.offset;
    return r;
  }
  const Eigen::Matrix3d l = a.eigen_linear();
  if((l.transpose() * l - Eigen::Matrix3d::Identity()).norm() > 1e-6 || l.determinant() < 0)
    return r; // not a rotation
  const double c = std::clamp((l.trace() - 1) / 2, -1.0, 1.0);
  const Vector_3d w(0.5 * (l(2, 1) - l(1, 2)), 0.5 * (l(0, 2) - l(2, 0)), 0.5 * (l(1, 0) - l(0, 1)));
  Eigen::JacobiSVD<Eigen::Matrix3d> svd(l - Eigen::Matrix3d::Identity(), Eigen::ComputeFullU | Eigen::ComputeFullV);
  const Eigen::Vector3d v = svd.matrixV().col(2); // the direction that the turn keeps
  Vector_3d axis(v(0), v(1), v(2));
  double angle = std::atan2(SAI::dot(axis, w), c);
  if(!(std::abs(angle) > 1e-9))
    return r; // the identity
  if(angle < 0) {
    axis = axis * -1.0;
    angle = -angle;
  }
  if(std::abs(SAI::dot(axis, a.translation)) > 1e-9 * (std::max)(1.0, a.translation.length()))
    return r; // a screw motion (a turn and a slide along the axis): left as it is
  // The axis' points p solve (L - I) p = -t (rank 2): the least-squares solution from the same
  // decomposition, then the one nearest `centre`.
  svd.setThreshold(1e-9);
  const Eigen::Vector3d p = svd.solve(Eigen::Vector3d(-a.translation.x, -a.translation.y, -a.translation.z));
  Vector_3d q(p(0), p(1), p(2));
  q = q + axis * SAI::dot(centre - q, axis);
  r.kind = Regular_symmetry::ROTATION;
  r.direction = axis;
  r.point = q;
  r.angle = angle;
  return r;
}

// The order k of a turn by 2 pi / k (within 1e-3 of the angle), 0 when it is no such turn.
inline std::size_t turn_order(double angle)
{
  const double k = 2 * 3.14159265358979323846 / angle;
  const double n = std::round(k);
  return n >= 2 && std::abs(k - n) < 1e-3 * k ? std::size_t(n) : 0;
}

class Symmetry_regularization
{
public:
  // `angle` in radians, `offset` in length units, `centre` the reference point (the surface's area
  // centroid): a plane whose normal changes keeps its point nearest the centre.
  Symmetry_regularization(std::vector<Regular_symmetry> symmetries, double angle, double offset, const Vector_3d& centre)
    : m_s(std::move(symmetries)), m_sin(std::sin(angle)), m_cos(std::cos(angle)), m_angle(angle), m_offset(offset),
      m_centre(centre)
  {
    drop_duplicates(); // before the groups, which they would weigh twice
    if(!(angle > 0))
      return; // no turn allowed: the duplicates only
    for(Regular_symmetry& s : m_s) // a k-fold turn by 2 pi / k exactly
      if(s.kind == Regular_symmetry::ROTATION && turn_order(s.angle) > 0 &&
         std::abs(s.angle - 2 * 3.14159265358979323846 / double(turn_order(s.angle))) <= angle)
        s.angle = 2 * 3.14159265358979323846 / double(turn_order(s.angle));
    find_groups();
    for(Group& g : m_groups)
      fit_group(g);
    fix_directions();
    drop_duplicates();
  }

  const std::vector<Regular_symmetry>& symmetries() const { return m_s; }
  std::size_t number_of_groups() const { return m_groups.size(); }

private:
  struct Group
  {
    std::vector<std::size_t> members; // in input order
    Vector_3d axis;
    Vector_3d point;
  };

  bool is(std::size_t i, Regular_symmetry::Kind k) const { return m_s[i].kind == k && !m_s[i].dropped; }

  // The point of plane i nearest the centre.
  Vector_3d foot(std::size_t i) const
  {
    const Regular_symmetry& s = m_s[i];
    return m_centre - s.direction * (SAI::dot(s.direction, m_centre) - s.offset);
  }

  // Whether symmetry i lies on the line (a, p): a plane containing it, a rotation about it.
  bool on_line(std::size_t i, const Vector_3d& a, const Vector_3d& p) const
  {
    const Regular_symmetry& s = m_s[i];
    if(s.kind == Regular_symmetry::PLANE)
      return std::abs(SAI::dot(s.direction, a)) <= m_sin && std::abs(SAI::dot(s.direction, p) - s.offset) <= m_offset;
    if(s.kind == Regular_symmetry::ROTATION) {
      const Vector_3d d = s.point - p;
      return std::abs(SAI::dot(s.direction, a)) >= m_cos && (d - a * SAI::dot(d, a)).length() <= m_offset;
    }
    return false;
  }

  void try_group(const Vector_3d& a, const Vector_3d& p, std::vector<int>& group_of)
  {
    Group g;
    bool rotation = false;
    for(std::size_t i = 0; i < m_s.size(); ++i)
      if(group_of[i] < 0 && !m_s[i].dropped && on_line(i, a, p)) {
        g.members.push_back(i);
        rotation = rotation || m_s[i].kind == Regular_symmetry::ROTATION;
      }
    if(g.members.size() < 3 && !(rotation && g.members.size() >= 2))
      return;
    g.axis = a;
    g.point = p;
    for(std::size_t i : g.members)
      group_of[i] = int(m_groups.size());
    m_groups.push_back(g);
  }

  // Candidate lines: the rotations' axes, then the lines where two planes meet, in input order.
  void find_groups()
  {
    std::vector<int> group_of(m_s.size(), -1);
    for(std::size_t i = 0; i < m_s.size(); ++i)
      if(is(i, Regular_symmetry::ROTATION) && group_of[i] < 0)
        try_group(m_s[i].direction, m_s[i].point, group_of);
    for(std::size_t i = 0; i < m_s.size(); ++i)
      for(std::size_t j = i + 1; j < m_s.size() && group_of[i] < 0; ++j) {
        if(!is(i, Regular_symmetry::PLANE) || !is(j, Regular_symmetry::PLANE) || group_of[j] >= 0)
          continue;
        const Vector_3d c = SAI::cross(m_s[i].direction, m_s[j].direction);
        if(c.length() <= m_sin)
          continue;
        const Vector_3d a = unit(c);
        // The point of the line nearest the centre: on both planes and on the plane a.x = a.centre.
        Eigen::Matrix3d m;
        Eigen::Vector3d b;
        const Vector_3d rows[3] = {m_s[i].direction, m_s[j].direction, a};
        const double rhs[3] = {m_s[i].offset, m_s[j].offset, SAI::dot(a, m_centre)};
        for(int r = 0; r < 3; ++r) {
          m(r, 0) = rows[r].x;
          m(r, 1) = rows[r].y;
          m(r, 2) = rows[r].z;
          b(r) = rhs[r];
        }
        const Eigen::Vector3d x = m.colPivHouseholderQr().solve(b);
        try_group(a, Vector_3d(x(0), x(1), x(2)), group_of);
      }
    std::sort(m_groups.begin(), m_groups.end(),
              [](const Group& x, const Group& y) { return x.members.front() < y.members.front(); });
  }

  // One axis for the group: the direction most nearly perpendicular to its planes' normals and
  // parallel to its rotations' axes; the planes' normals made perpendicular to it, their angles
  // regularized; the point nearest the planes and the rotation axes.
  void fit_group(Group& g)
  {
    Eigen::Matrix3d m = Eigen::Matrix3d::Zero();
    std::vector<std::size_t> orders;
    std::size_t planes = 0;
    for(std::size_t i : g.members) {
      const Eigen::Vector3d d(m_s[i].direction.x, m_s[i].direction.y, m_s[i].direction.z);
      if(m_s[i].kind == Regular_symmetry::PLANE) {
        m += d * d.transpose();
        ++planes;
      } else {
        m += Eigen::Matrix3d::Identity() - d * d.transpose();
        if(turn_order(m_s[i].angle) > 0)
          orders.push_back(turn_order(m_s[i].angle));
      }
    }
    Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(m);
    Vector_3d a(eig.eigenvectors()(0, 0), eig.eigenvectors()(1, 0), eig.eigenvectors()(2, 0));
    if(SAI::dot(a, g.axis) < 0)
      a = a * -1.0;
    a = unit(a);
    // Normals into the plane perpendicular to the axis, each plane through its old point nearest
    // the centre for now.
    std::vector<Vector_3d> feet;
    for(std::size_t i : g.members) {
      Regular_symmetry& s = m_s[i];
      if(s.kind == Regular_symmetry::PLANE) {
        feet.push_back(foot(i));
        s.direction = unit(s.direction - a * SAI::dot(s.direction, a));
      } else
        s.direction = SAI::dot(s.direction, a) < 0 ? a * -1.0 : a;
    }
    if(planes >= 2)
      regularize_angles(g, a, orders, planes);
    // The point: nearest (least squares) to the planes and to the rotation axes, on the plane
    // through the centre perpendicular to the axis.
    Eigen::Matrix3d lhs = Eigen::Matrix3d::Zero();
    Eigen::Vector3d rhs = Eigen::Vector3d::Zero();
    const Eigen::Vector3d ae(a.x, a.y, a.z);
    std::size_t f = 0;
    for(std::size_t i : g.members) {
      const Regular_symmetry& s = m_s[i];
      const Eigen::Vector3d n(s.direction.x, s.direction.y, s.direction.z);
      if(s.kind == Regular_symmetry::PLANE) {
        const Vector_3d& q = feet[f++];
        lhs += n * n.transpose();
        rhs += n * SAI::dot(s.direction, q);
      } else {
        const Eigen::Matrix3d p = Eigen::Matrix3d::Identity() - ae * ae.transpose();
        lhs += p;
        rhs += p * Eigen::Vector3d(s.point.x, s.point.y, s.point.z);
      }
    }
    lhs += ae * ae.transpose();
    rhs += ae * SAI::dot(a, m_centre);
    const Eigen::Vector3d x = lhs.colPivHouseholderQr().solve(rhs);
    g.axis = a;
    g.point = Vector_3d(x(0), x(1), x(2));
    place_on_axis(g);
  }

  // Angles between the planes of a group about its axis a: multiples of pi / k for a rotation's
  // order k, or else the smallest k from the number of planes m to 2 m (some planes of a k-fold set
  // may be missing), when every plane is within the tolerance of one; otherwise each plane
  // perpendicular to an earlier one of the group when it nearly is.
  void regularize_angles(const Group& g, const Vector_3d& a, std::vector<std::size_t> orders, std::size_t planes)
  {
    for(std::size_t k = planes; k <= 2 * planes; ++k)
      orders.push_back(k);
    const std::size_t first = *std::find_if(g.members.begin(), g.members.end(),
                                            [&](std::size_t i) { return m_s[i].kind == Regular_symmetry::PLANE; });
    const Vector_3d u = m_s[first].direction, v = SAI::cross(a, u);
    for(std::size_t k : orders)
      if(snap_angles(g, a, u, v, k))
        return;
    for(std::size_t x = 0; x < g.members.size(); ++x)
      for(std::size_t y = 0; y < x; ++y) {
        Regular_symmetry &p = m_s[g.members[x]], &q = m_s[g.members[y]];
        if(p.kind != Regular_symmetry::PLANE || q.kind != Regular_symmetry::PLANE ||
           std::abs(SAI::dot(p.direction, q.direction)) > m_sin)
          continue;
        const Vector_3d w = SAI::cross(a, q.direction);
        p.direction = SAI::dot(w, p.direction) < 0 ? w * -1.0 : w;
        break;
      }
  }

  bool snap_angles(const Group& g, const Vector_3d& a, const Vector_3d& u, const Vector_3d& v, std::size_t k)
  {
    const double pi = 3.14159265358979323846, step = pi / double(k);
    std::vector<double> multiples, residuals;
    double mean = 0;
    for(std::size_t i : g.members)
      if(m_s[i].kind == Regular_symmetry::PLANE) {
        const double phi = std::atan2(SAI::dot(m_s[i].direction, v), SAI::dot(m_s[i].direction, u));
        const double m = std::round(phi / step);
        multiples.push_back(m);
        residuals.push_back(phi - m * step);
        mean += residuals.back();
      }
    mean /= double(residuals.size());
    for(double r : residuals)
      if(std::abs(r - mean) > m_angle)
        return false;
    std::size_t j = 0;
    for(std::size_t i : g.members)
      if(m_s[i].kind == Regular_symmetry::PLANE)
        m_s[i].direction = turn(a, multiples[j++] * step + mean, u);
    return true;
  }

  // The group's members through its line: planes' offsets, rotations' axes and points.
  void place_on_axis(const Group& g)
  {
    for(std::size_t i : g.members) {
      Regular_symmetry& s = m_s[i];
      if(s.kind == Regular_symmetry::PLANE)
        s.offset = SAI::dot(s.direction, g.point);
      else {
        s.direction = SAI::dot(s.direction, g.axis) < 0 ? g.axis * -1.0 : g.axis;
        s.point = g.point + g.axis * SAI::dot(m_centre - g.point, g.axis);
      }
    }
  }

  // The direction fixed before that `v` is parallel to (within the tolerance), made exact; or the
  // one or two it is perpendicular to. Returns `v` unchanged when none.
  Vector_3d snapped(const Vector_3d& v) const
  {
    for(const Vector_3d& f : m_fixed) {
      const double c = SAI::dot(v, f);
      if(std::abs(c) >= m_cos)
        return c < 0 ? f * -1.0 : f;
    }
    std::vector<Vector_3d> perpendicular;
    for(const Vector_3d& f : m_fixed)
      if(std::abs(SAI::dot(v, f)) <= m_sin)
        perpendicular.push_back(f);
    for(std::size_t i = 0; i < perpendicular.size(); ++i)
      for(std::size_t j = i + 1; j < perpendicular.size(); ++j) {
        const Vector_3d c = SAI::cross(perpendicular[i], perpendicular[j]);
        if(c.length() <= m_sin)
          continue;
        const Vector_3d w = unit(c);
        if(std::abs(SAI::dot(v, w)) >= m_cos)
          return SAI::dot(v, w) < 0 ? w * -1.0 : w;
      }
    if(!perpendicular.empty()) {
      const Vector_3d& f = perpendicular.front();
      return unit(v - f * SAI::dot(v, f));
    }
    return v;
  }

  void fix_directions()
  {
    std::vector<int> group_of(m_s.size(), -1);
    for(std::size_t g = 0; g < m_groups.size(); ++g)
      for(std::size_t i : m_groups[g].members)
        group_of[i] = int(g);
    for(std::size_t i = 0; i < m_s.size(); ++i) {
      Regular_symmetry& s = m_s[i];
      if(s.kind == Regular_symmetry::OTHER || s.dropped)
        continue;
      if(group_of[i] < 0) {
        const Vector_3d d = snapped(s.direction);
        if(s.kind == Regular_symmetry::PLANE) {
          const Vector_3d q = foot(i);
          s.direction = d;
          s.offset = SAI::dot(d, q);
        } else {
          s.direction = d;
          s.point = s.point + d * SAI::dot(m_centre - s.point, d);
        }
        m_fixed.push_back(d);
      } else if(m_groups[std::size_t(group_of[i])].members.front() == i)
        fix_group(m_groups[std::size_t(group_of[i])]);
    }
  }

  // The group turned as one about its point: its axis snapped, then about the axis so that a
  // member's normal is parallel to a direction fixed before, when one nearly is.
  void fix_group(Group& g)
  {
    const Vector_3d a = snapped(g.axis);
    turn_group(g, [&](const Vector_3d& w) { return align_turn(g.axis, a, w); });
    g.axis = a;
    bool aligned = false;
    for(std::size_t i : g.members) {
      if(aligned || m_s[i].kind != Regular_symmetry::PLANE)
        continue;
      for(const Vector_3d& f : m_fixed) {
        const Vector_3d n = m_s[i].direction;
        if(std::abs(SAI::dot(n, f)) < m_cos || std::abs(SAI::dot(f, a)) > m_sin)
          continue;
        const Vector_3d target = unit(f - a * SAI::dot(f, a)) * (SAI::dot(n, f) < 0 ? -1.0 : 1.0);
        const double phi = std::atan2(SAI::dot(SAI::cross(n, target), a), SAI::dot(n, target));
        turn_group(g, [&](const Vector_3d& w) { return turn(a, phi, w); });
        m_s[i].direction = target;
        aligned = true;
        break;
      }
    }
    place_on_axis(g);
    m_fixed.push_back(a);
    for(std::size_t i : g.members)
      if(m_s[i].kind == Regular_symmetry::PLANE)
        m_fixed.push_back(m_s[i].direction);
  }

  template <typename Turn>
  void turn_group(const Group& g, const Turn& t)
  {
    for(std::size_t i : g.members)
      if(m_s[i].kind == Regular_symmetry::PLANE)
        m_s[i].direction = unit(t(m_s[i].direction));
  }

  // The same plane, or the same turn about the same axis, given twice: the later one is dropped.
  void drop_duplicates()
  {
    for(std::size_t j = 0; j < m_s.size(); ++j)
      for(std::size_t i = 0; i < j && !m_s[j].dropped; ++i) {
        const Regular_symmetry &x = m_s[i], &y = m_s[j];
        if(x.dropped || x.kind != y.kind || x.kind == Regular_symmetry::OTHER)
          continue;
        const double c = SAI::dot(x.direction, y.direction);
        if(std::abs(c) < m_cos)
          continue;
        if(x.kind == Regular_symmetry::PLANE)
          m_s[j].dropped = std::abs(x.offset - (c < 0 ? -y.offset : y.offset)) <= m_offset;
        else {
          const Vector_3d d = y.point - x.point;
          const double angle = c < 0 ? 2 * 3.14159265358979323846 - y.angle : y.angle;
          m_s[j].dropped = (d - x.direction * SAI::dot(d, x.direction)).length() <= m_offset &&
                           std::abs(std::remainder(angle - x.angle, 2 * 3.14159265358979323846)) <= m_angle;
        }
      }
  }

  std::vector<Regular_symmetry> m_s;
  double m_sin, m_cos, m_angle, m_offset;
  Vector_3d m_centre;
  std::vector<Group> m_groups;
  std::vector<Vector_3d> m_fixed;
};

} // namespace internal
} // namespace Surface_mesh_symmetrization
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_SYMMETRIZATION_INTERNAL_SYMMETRY_REGULARIZATION_H
