// Copyright (c) 2026 CGAL Global Shape Analysis contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_SURFACE_MESH_SYMMETRIZATION_INTERNAL_SIDE_OVERLAY_H
#define CGAL_SURFACE_MESH_SYMMETRIZATION_INTERNAL_SIDE_OVERLAY_H

// Symmetric connectivity by overlaying the two sides' triangulations where they differ, on a
// surface given in the frame of its reflection plane (x -> -x) with exact mirror pairs. Copying one
// side over the other (Side_copy.h) loses the other side's edges, its creases among them; the
// overlay keeps the edges of both:
// - the faces without a mirror face (and those across the plane that are not their own mirror
//   image) are cut at the plane, as for the copy;
// - on the positive side, these pieces (C) and the mirror images of the negative side's (M) cover
//   the same part of the surface with the same vertices (every vertex has its partner, and the
//   border of the faces without a mirror face is mirrored), by two triangulations;
// - C's pieces joined by the edges M lacks, and M's by those C lacks, make groups; a group of C and
//   one of M with the same border make a region (the edges the two share cut the overlay into small
//   independent regions); only regions with a sharp edge (overlay_sharp_angle between the normals
//   of its two faces, in C or in M) are overlaid: elsewhere the two tessellations describe nearly
//   the same surface and the copy does as well with fewer faces;
// - a region that is a disk is mapped to the plane (its border on a circle by arc length, its inner
//   vertices by mean-value weights: Tutte's embedding, without folds); when M's triangles keep
//   their orientation there and cover the disk once, the edges of C and M are inserted into a
//   constrained Delaunay triangulation with exact constructions, which splits them where they cross
//   (with rounded crossings, an edge split at one may cross the other edge again next to it, making
//   points that coincide in space: 872 on PSB mesh 321);
// - a crossing lies on an edge of C at a point P of the positive side and on an edge of M, the
//   mirror image of a point Q of the negative side: it goes to (P + mirror(Q)) / 2, its partner to
//   the mirror image of that; the region's faces on the positive side are the triangulation's,
//   those on the negative side their mirror images. Regions that are not disks, whose map folds M
//   or that would get an edge shorter than 1e-10 of C's mean edge are left as they are, to the
//   copy.

#include <CGAL/Shape_analysis/internal/Union_find.h>
#include <CGAL/Surface_mesh_symmetrization/internal/Side_copy.h>
#include <CGAL/Surface_mesh_symmetrization/internal/Symmetric_connectivity.h>

#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Constrained_triangulation_2.h>
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>

#include <Eigen/Sparse>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <map>
#include <set>
#include <unordered_map>
#include <utility>
#include <vector>

namespace CGAL {
namespace Surface_mesh_symmetrization {
namespace internal {

// The angle between the normals of an edge's two faces (in C or in M) from which a region is
// overlaid rather than copied. Bench_symmetric_remeshing, remeshing to the input's faces, Hausdorff
// distance to the input / normal deviation to the symmetrized surface (with the flips' bound of
// symmetric_meta_mesh(), 0.05 of the mean edge): copying (every region) -> overlaying the regions
// with an edge sharper than 0.5 rad: PSB mesh 321 0.00242 / 0.0108 -> 0.00147 / 0.0099, 323 0.00070
// / 0.0151 -> 0.00049 / 0.0134 (copying a whole side: 0.00179 / 0.0103, 0.00064 / 0.0130); the cow
// 0.0107 / 1.86 -> 0.0107 / 1.98, the camel 0.00151 / 1.59 -> 0.00154 / 1.57, PSB 1 0.0164 / 0.83
// -> 0.0162 / 0.87, 22 0.00277 / 0.96 -> 0.00275 / 0.98. Overlaying every region (angle 0) gives
// 321 and 323 the same distances but the cow's normals 2.46 and the armadillo's meta-mesh 3.7 times
// the faces (21 s instead of 2.8); 0.8 rad leaves 323 at 0.00064.
constexpr double overlay_sharp_angle = 0.5;

class Side_overlay
{
public:
  typedef std::array<std::uint32_t, 3> Triangle;

  // What overlay() did.
  struct Counts
  {
    std::size_t overlaid = 0;  // of them, overlaid (the others are left to the copy)
    std::size_t crossings = 0; // vertices made where an edge of one side crosses one of the other
  };

  // Overlays the sides of `s` (pairs `partner`) where their connectivity differs (see above). When
  // the result would not be a closed manifold, `s` and `partner` are unchanged and no region is
  // overlaid.
  static Counts overlay(Surface& s, std::vector<std::uint32_t>& partner)
  {
    Counts counts;
    Surface c = s;
    std::vector<std::uint32_t> p = partner;
    std::vector<char> listed = faces_to_copy(c, p);
    cut_at_plane(c, p, listed);

    // Positive pieces and the mirror images of the negative ones, in regions joined by edges.
    std::vector<Triangle> pieces; // positive pieces (C), then mirrored negative ones (M)
    std::vector<char> is_mirrored;
    std::vector<char> keep(c.triangles.size(), 1);
    for(std::size_t f = 0; f < c.triangles.size(); ++f) {
      if(!listed[f])
        continue;
      const Triangle& t = c.triangles[f];
      const double x = c.points[t[0]].x + c.points[t[1]].x + c.points[t[2]].x;
      if(x == 0)
        return counts; // a listed piece in the plane: left to the copy
      keep[f] = 0;
      if(x > 0) {
        pieces.push_back(t);
        is_mirrored.push_back(0);
      } else {
        if(p[t[0]] == no_partner || p[t[1]] == no_partner || p[t[2]] == no_partner)
          pieces.push_back(t); // (never overlaid: see below)
        else
          pieces.push_back({{p[t[2]], p[t[1]], p[t[0]]}});
        is_mirrored.push_back(1);
      }
    }
    const std::map<std::uint32_t, std::vector<std::uint32_t>> regions = match_regions(pieces, is_mirrored);

    std::vector<Triangle> added;
    std::vector<char> overlaid_piece(pieces.size(), 0);
    for(const auto& region : regions) {
      // (A negative piece without partners keeps its own indices: its group's border matches no
      // C group's, and Region::number() refuses M vertices that C lacks.)
      std::vector<Triangle> C, M;
      for(std::uint32_t i : region.second)
        (is_mirrored[i] ? M : C).push_back(pieces[i]);
      if(!has_sharp_edge(c, C) && !has_sharp_edge(c, M))
        continue; // (elsewhere the two sides' tessellations differ by little)
      std::vector<Triangle> faces;
      std::vector<Vector_3d> crossing_p, crossing_q; // per crossing: P, mirror(Q)
      if(C.empty() || M.empty() || !overlay_region(c, C, M, faces, crossing_p, crossing_q))
        continue;
      // New points: the crossings on the positive side, then their partners.
      const std::uint32_t first = std::uint32_t(c.points.size()), n = std::uint32_t(crossing_p.size());
      for(std::uint32_t k = 0; k < n; ++k) {
        c.points.push_back((crossing_p[k] + crossing_q[k]) * 0.5); // (off the plane: see cross())
        p.push_back(first + n + k);
      }
      for(std::uint32_t k = 0; k < n; ++k) {
        c.points.push_back(mirrored(c.points[first + k]));
        p.push_back(first + k);
      }
      const auto remap = [&](std::uint32_t v) { return v >= region_base ? first + (v - region_base) : v; };
      for(const Triangle& t : faces) {
        const Triangle u{{remap(t[0]), remap(t[1]), remap(t[2])}};
        added.push_back(u);
        added.push_back({{p[u[2]], p[u[1]], p[u[0]]}});
      }
      for(std::uint32_t i : region.second)
        overlaid_piece[i] = 1;
      counts.crossings += n;
      ++counts.overlaid;
    }
    if(counts.overlaid == 0)
      return Counts();
    // The faces: those not listed, the listed ones of regions not overlaid, the overlays.
    std::vector<Triangle> out;
    std::size_t piece = 0;
    for(std::size_t f = 0; f < c.triangles.size(); ++f) {
      if(keep[f]) {
        out.push_back(c.triangles[f]);
        continue;
      }
      if(!overlaid_piece[piece])
        out.push_back(c.triangles[f]);
      ++piece;
    }
    out.insert(out.end(), added.begin(), added.end());
    c.triangles.swap(out);
    if(!is_closed_manifold(c))
      return Counts();
    drop_unused_points(c, p);
    std::swap(s, c);
    partner.swap(p);
    return counts;
  }

private:
  // Regions: the C pieces joined by their edges that M lacks, the M pieces by theirs that C lacks;
  // a group of C pieces and one of M pieces with the same border make a region (the edges common to
  // both triangulations cut the overlay into small independent pieces). Per region, its pieces.
  static std::map<std::uint32_t, std::vector<std::uint32_t>> match_regions(const std::vector<Triangle>& pieces,
                                                                           const std::vector<char>& is_mirrored)
  {
    std::unordered_map<std::uint64_t, int> sides_of; // bit 1: in C, bit 2: in M
    for(std::uint32_t i = 0; i < pieces.size(); ++i)
      for(int k = 0; k < 3; ++k)
        sides_of[edge_key(pieces[i][k], pieces[i][(k + 1) % 3])] |= is_mirrored[i] ? 2 : 1;
    SAI::Union_find sets(pieces.size());
    {
      std::unordered_map<std::uint64_t, std::uint32_t> first[2];
      for(std::uint32_t i = 0; i < pieces.size(); ++i)
        for(int k = 0; k < 3; ++k) {
          const std::uint64_t e = edge_key(pieces[i][k], pieces[i][(k + 1) % 3]);
          if(sides_of[e] == 3)
            continue;
          const auto it = first[is_mirrored[i]].emplace(e, i);
          if(!it.second)
            sets.absorb(it.first->second, i);
        }
    }
    std::map<std::uint32_t, std::vector<std::uint32_t>> groups;
    for(std::uint32_t i = 0; i < pieces.size(); ++i)
      groups[sets.find(i)].push_back(i);
    const auto border_of = [&](const std::vector<std::uint32_t>& group) {
      std::set<std::pair<std::uint32_t, std::uint32_t>> directed, border;
      for(std::uint32_t i : group)
        for(int k = 0; k < 3; ++k)
          directed.insert({pieces[i][k], pieces[i][(k + 1) % 3]});
      for(const auto& e : directed)
        if(!directed.count({e.second, e.first}))
          border.insert(e);
      return std::vector<std::pair<std::uint32_t, std::uint32_t>>(border.begin(), border.end());
    };
    std::map<std::vector<std::pair<std::uint32_t, std::uint32_t>>, std::uint32_t> m_group_of_border;
    for(const auto& g : groups)
      if(is_mirrored[g.first])
        m_group_of_border.emplace(border_of(g.second), g.first);
    std::map<std::uint32_t, std::vector<std::uint32_t>> regions;
    for(const auto& g : groups) {
      if(is_mirrored[g.first])
        continue;
      const auto it = m_group_of_border.find(border_of(g.second));
      if(it == m_group_of_border.end())
        continue; // left to the copy
      std::vector<std::uint32_t>& r = regions[g.first];
      r = g.second;
      r.insert(r.end(), groups[it->second].begin(), groups[it->second].end());
    }
    return regions;
  }

  // Whether two faces of T meet at an edge with an angle of overlay_sharp_angle or more between
  // their normals.
  static bool has_sharp_edge(const Surface& c, const std::vector<Triangle>& T)
  {
    std::map<std::pair<std::uint32_t, std::uint32_t>, Vector_3d> normal; // per directed edge, its face's
    for(const Triangle& t : T) {
      Vector_3d nt = SAI::cross(c.points[t[1]] - c.points[t[0]], c.points[t[2]] - c.points[t[0]]);
      const double l = nt.length();
      nt = l > 0 ? nt / l : nt;
      for(int k = 0; k < 3; ++k)
        normal[{t[k], t[(k + 1) % 3]}] = nt;
    }
    for(const auto& e : normal) {
      const auto o = normal.find({e.first.second, e.first.first});
      if(o != normal.end() && SAI::dot(e.second, o->second) <= std::cos(overlay_sharp_angle))
        return true;
    }
    return false;
  }

  // Index base of the crossings in the faces overlay_region() returns.
  static constexpr std::uint32_t region_base = 0x80000000u;

  // The map to the plane and C, M alone in doubles; their overlay with exact constructions (with
  // rounded crossings, an edge split at one may cross the other edge again next to it, making
  // points that coincide in space).
  typedef CGAL::Exact_predicates_inexact_constructions_kernel K2;
  typedef CGAL::Exact_predicates_exact_constructions_kernel KE;
  struct Info
  {
    std::uint32_t index = no_partner;
  };
  typedef CGAL::Triangulation_vertex_base_with_info_2<Info, K2> Vb;
  typedef CGAL::Constrained_triangulation_face_base_2<K2> Fb;
  typedef CGAL::Triangulation_data_structure_2<Vb, Fb> Tds;
  typedef CGAL::Constrained_triangulation_2<K2, Tds, CGAL::Exact_predicates_tag> CT;
  typedef CGAL::Triangulation_vertex_base_with_info_2<Info, KE> Vbe;
  typedef CGAL::Constrained_triangulation_face_base_2<KE> Fbe;
  typedef CGAL::Triangulation_data_structure_2<Vbe, Fbe> Tdse;
  typedef CGAL::Constrained_Delaunay_triangulation_2<KE, Tdse, CGAL::Exact_intersections_tag> CDT;

  // The overlay of the triangulations C and M of one region (vertices of `s`), step by step; each
  // step false when the region is not a disk, its map to the plane folds M or merges points.
  struct Region
  {
    const Surface& s;
    const std::vector<Triangle>&C, &M;
    std::unordered_map<std::uint32_t, std::uint32_t> local; // C's vertices numbered from 0
    std::vector<std::uint32_t> global;
    std::size_t n = 0;
    std::map<std::pair<std::uint32_t, std::uint32_t>, int> c_edges,
      m_edges;                             // directed, local
    std::vector<std::uint32_t> next, loop; // along the border
    std::vector<char> on_border;
    std::vector<double> u, w; // the map to the plane
    std::vector<K2::Point_2> at;
    CGAL::Orientation way = CGAL::COLLINEAR; // of C's faces there

    Region(const Surface& s, const std::vector<Triangle>& C, const std::vector<Triangle>& M) : s(s), C(C), M(M) {}

    // C's vertices numbered (M's must be the same), the directed edges of both.
    bool number()
    {
      for(const Triangle& t : C)
        for(std::uint32_t v : t)
          if(local.emplace(v, std::uint32_t(global.size())).second)
            global.push_back(v);
      {
        std::vector<char> seen(global.size(), 0);
        for(const Triangle& t : M)
          for(std::uint32_t v : t) {
            const auto it = local.find(v);
            if(it == local.end())
              return false;
            seen[it->second] = 1;
          }
        if(std::find(seen.begin(), seen.end(), 0) != seen.end())
          return false;
      }
      n = global.size();
      // Directed edges of C: the border is the edges without their opposite; M's border must be the
      // same.
      for(const Triangle& t : C)
        for(int k = 0; k < 3; ++k)
          if(++c_edges[{local[t[k]], local[t[(k + 1) % 3]]}] > 1)
            return false;
      for(const Triangle& t : M)
        for(int k = 0; k < 3; ++k)
          if(++m_edges[{local[t[k]], local[t[(k + 1) % 3]]}] > 1)
            return false;
      return true;
    }

    // The border: C's edges without their opposite, one loop (a disk), the same as M's; on the unit
    // circle by arc length.
    bool find_border()
    {
      next.assign(n, no_partner);
      std::size_t border = 0, undirected = 0;
      for(const auto& e : c_edges) {
        const bool inner = c_edges.count({e.first.second, e.first.first}) > 0;
        undirected += inner ? (e.first.first < e.first.second ? 1 : 0) : 1;
        if(inner)
          continue;
        if(next[e.first.first] != no_partner)
          return false; // the border passes twice through a vertex
        next[e.first.first] = e.first.second;
        ++border;
      }
      for(const auto& e : m_edges)
        if(!m_edges.count({e.first.second, e.first.first}) && next[e.first.first] != e.first.second)
          return false;
      std::size_t m_border = 0;
      for(const auto& e : m_edges)
        m_border += m_edges.count({e.first.second, e.first.first}) ? 0 : 1;
      if(border < 3 || m_border != border || long(n) - long(undirected) + long(C.size()) != 1)
        return false; // not a disk
      // The border loop, on the unit circle by arc length.
      {
        std::uint32_t start = 0;
        while(next[start] == no_partner)
          ++start;
        for(std::uint32_t v = start; loop.size() <= border;) {
          loop.push_back(v);
          v = next[v];
          if(v == no_partner)
            return false; // the border enters a vertex twice and never leaves it
          if(v == start)
            break;
        }
        if(loop.size() != border)
          return false; // several border loops
      }
      u.assign(n, 0);
      w.assign(n, 0);
      on_border.assign(n, 0);
      {
        std::vector<double> length(border + 1, 0);
        for(std::size_t i = 0; i < border; ++i)
          length[i + 1] = length[i] + (s.points[global[loop[(i + 1) % border]]] - s.points[global[loop[i]]]).length();
        if(!(length[border] > 0))
          return false;
        for(std::size_t i = 0; i < border; ++i) {
          const double angle = 2 * CGAL_PI * length[i] / length[border];
          u[loop[i]] = std::cos(angle);
          w[loop[i]] = std::sin(angle);
          on_border[loop[i]] = 1;
        }
      }
      return true;
    }

    // Inner vertices by mean-value weights (tan(half angle) / length, all positive): Tutte's
    // embedding.
    bool map_inner_vertices()
    {
      {
        std::vector<std::uint32_t> unknown(n, no_partner);
        std::uint32_t count = 0;
        for(std::size_t v = 0; v < n; ++v)
          if(!on_border[v])
            unknown[v] = count++;
        if(count > 0) {
          std::vector<Eigen::Triplet<double>> entries;
          Eigen::VectorXd bu = Eigen::VectorXd::Zero(count), bw = Eigen::VectorXd::Zero(count);
          std::vector<double> diagonal(count, 0);
          for(const Triangle& t : C)
            for(int k = 0; k < 3; ++k) {
              const std::uint32_t i = local[t[k]];
              if(on_border[i])
                continue;
              const Vector_3d pi = s.points[t[k]];
              for(int l : {1, 2}) {
                const std::uint32_t j = local[t[(k + l) % 3]];
                const Vector_3d d1 = s.points[t[(k + 1) % 3]] - pi, d2 = s.points[t[(k + 2) % 3]] - pi;
                const double l1 = d1.length(), l2 = d2.length();
                if(!(l1 > 0 && l2 > 0))
                  return false;
                const double cosine = (std::max)(-1.0, (std::min)(1.0, SAI::dot(d1, d2) / (l1 * l2)));
                const double weight = std::tan(0.5 * std::acos(cosine)) / (l == 1 ? l1 : l2);
                if(!(weight >= 0) || !std::isfinite(weight))
                  return false;
                diagonal[unknown[i]] += weight;
                if(on_border[j]) {
                  bu[unknown[i]] += weight * u[j];
                  bw[unknown[i]] += weight * w[j];
                } else
                  entries.emplace_back(unknown[i], unknown[j], -weight);
              }
            }
          for(std::uint32_t i = 0; i < count; ++i) {
            if(!(diagonal[i] > 0))
              return false;
            entries.emplace_back(i, i, diagonal[i]);
          }
          Eigen::SparseMatrix<double> A(count, count);
          A.setFromTriplets(entries.begin(), entries.end());
          Eigen::SparseLU<Eigen::SparseMatrix<double>> solver;
          solver.compute(A);
          if(solver.info() != Eigen::Success)
            return false;
          const Eigen::VectorXd xu = solver.solve(bu), xw = solver.solve(bw);
          if(solver.info() != Eigen::Success)
            return false;
          for(std::size_t v = 0; v < n; ++v)
            if(!on_border[v]) {
              u[v] = xu[unknown[v]];
              w[v] = xw[unknown[v]];
              if(!std::isfinite(u[v]) || !std::isfinite(w[v]))
                return false;
            }
        }
      }
      return true;
    }

    // C's faces all one way (Tutte), M's the same way, covering the disk once.
    bool covers_once()
    {
      at.resize(n);
      for(std::size_t v = 0; v < n; ++v)
        at[v] = K2::Point_2(u[v], w[v]);
      const auto orientation = [&](const Triangle& t) {
        return CGAL::orientation(at[local.at(t[0])], at[local.at(t[1])], at[local.at(t[2])]);
      };
      const auto area = [&](const Triangle& t) {
        return std::abs(CGAL::area(at[local.at(t[0])], at[local.at(t[1])], at[local.at(t[2])]));
      };
      way = orientation(C.front());
      if(way == CGAL::COLLINEAR)
        return false;
      double c_area = 0, m_area = 0;
      for(const Triangle& t : C) {
        if(orientation(t) != way)
          return false;
        c_area += area(t);
      }
      for(const Triangle& t : M) {
        if(orientation(t) != way)
          return false;
        m_area += area(t);
      }
      if(!(std::abs(m_area - c_area) <= 1e-9 * c_area))
        return false; // M wraps around a vertex more than once

      return true;
    }

    // The overlay: its faces (crossings numbered from region_base), per crossing its points on C
    // and on M.
    bool cross(std::vector<Triangle>& faces, std::vector<Vector_3d>& on_c, std::vector<Vector_3d>& on_m)
    {
      // C and M alone, to locate the crossings in; their overlay.
      CT tc, tm;
      CDT overlay;
      std::vector<CT::Vertex_handle> vc(n), vm(n);
      std::vector<CDT::Vertex_handle> vo(n);
      for(std::size_t v = 0; v < n; ++v) {
        vc[v] = tc.insert(at[v]);
        vm[v] = tm.insert(at[v]);
        vo[v] = overlay.insert(KE::Point_2(at[v].x(), at[v].y()));
        vc[v]->info().index = vm[v]->info().index = vo[v]->info().index = std::uint32_t(v);
      }
      if(tc.number_of_vertices() != n || overlay.number_of_vertices() != n)
        return false; // two vertices at one point of the map
      for(const auto& e : c_edges) {
        tc.insert_constraint(vc[e.first.first], vc[e.first.second]);
        overlay.insert_constraint(vo[e.first.first], vo[e.first.second]);
      }
      for(const auto& e : m_edges) {
        tm.insert_constraint(vm[e.first.first], vm[e.first.second]);
        overlay.insert_constraint(vo[e.first.first], vo[e.first.second]);
      }
      if(tc.number_of_vertices() != n || tm.number_of_vertices() != n)
        return false;
      // The hull must be the border: every edge on the infinite face joins consecutive border
      // vertices.
      for(auto f = overlay.all_faces_begin(); f != overlay.all_faces_end(); ++f) {
        if(!overlay.is_infinite(f))
          continue;
        const int k = f->index(overlay.infinite_vertex());
        const auto a = f->vertex(overlay.cw(k)), b = f->vertex(overlay.ccw(k));
        const std::uint32_t ia = a->info().index, ib = b->info().index;
        if(ia == no_partner || ib == no_partner || !on_border[ia] || !on_border[ib] ||
           (next[ia] != ib && next[ib] != ia))
          return false;
      }
      // The crossings: their points on C and on M, interpolated in the faces that hold them.
      const auto interpolate = [&](const CT& t, const K2::Point_2& x, Vector_3d& result) {
        const CT::Face_handle f = t.locate(x);
        if(f == CT::Face_handle() || t.is_infinite(f))
          return false;
        const K2::Point_2 &p0 = f->vertex(0)->point(), &p1 = f->vertex(1)->point(), &p2 = f->vertex(2)->point();
        const double total = CGAL::area(p0, p1, p2);
        if(!(std::abs(total) > 0))
          return false;
        const double b0 = CGAL::area(x, p1, p2) / total, b1 = CGAL::area(p0, x, p2) / total, b2 = 1 - b0 - b1;
        result = s.points[global[f->vertex(0)->info().index]] * b0 + s.points[global[f->vertex(1)->info().index]] * b1 +
                 s.points[global[f->vertex(2)->info().index]] * b2;
        return true;
      };
      on_c.clear();
      on_m.clear();
      for(auto v = overlay.finite_vertices_begin(); v != overlay.finite_vertices_end(); ++v) {
        if(v->info().index != no_partner)
          continue;
        Vector_3d pc, pm;
        const K2::Point_2 x(CGAL::to_double(v->point().x()), CGAL::to_double(v->point().y()));
        if(!interpolate(tc, x, pc) || !interpolate(tm, x, pm) || !(pc.x + pm.x > 0))
          return false; // (a crossing on the plane: an edge in it, a pinch the copy handles)
        v->info().index = std::uint32_t(n + on_c.size());
        on_c.push_back(pc);
        on_m.push_back(pm);
      }
      faces.clear();
      for(auto f = overlay.finite_faces_begin(); f != overlay.finite_faces_end(); ++f) {
        std::array<std::uint32_t, 3> t;
        for(int k = 0; k < 3; ++k) {
          const std::uint32_t i = f->vertex(k)->info().index;
          t[k] = i < n ? global[i] : region_base + (i - std::uint32_t(n));
        }
        if(way == CGAL::CLOCKWISE)
          std::swap(t[1], t[2]);
        faces.push_back(t);
      }
      // No edge shorter than 1e-10 of C's mean edge (crossings of nearly concurrent edges
      // would otherwise make points that coincide in space): such a region is left to the copy.
      double mean = 0;
      for(const auto& e : c_edges)
        mean += (s.points[global[e.first.first]] - s.points[global[e.first.second]]).length();
      mean /= double(c_edges.size());
      const auto position = [&](std::uint32_t v) {
        return v >= region_base ? (on_c[v - region_base] + on_m[v - region_base]) * 0.5 : s.points[v];
      };
      for(const Triangle& t : faces)
        for(int k = 0; k < 3; ++k)
          if(!((position(t[k]) - position(t[(k + 1) % 3])).length() > 1e-10 * mean))
            return false;
      return true;
    }
  };

  static bool overlay_region(const Surface& s, const std::vector<Triangle>& C, const std::vector<Triangle>& M,
                             std::vector<Triangle>& faces, std::vector<Vector_3d>& on_c, std::vector<Vector_3d>& on_m)
  {
    Region r(s, C, M);
    return r.number() && r.find_border() && r.map_inner_vertices() && r.covers_once() && r.cross(faces, on_c, on_m);
  }
};

} // namespace internal
} // namespace Surface_mesh_symmetrization
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_SYMMETRIZATION_INTERNAL_SIDE_OVERLAY_H
