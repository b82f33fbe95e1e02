// Copyright (c) 2026 CGAL Global Shape Analysis contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef SHAPE_ANALYSIS_SUPPORT_SYMMETRY_METRICS_H
#define SHAPE_ANALYSIS_SUPPORT_SYMMETRY_METRICS_H

// The figures by which the tests and benchmarks judge a symmetrization, for positions of the
// vertices of one CGAL::Surface_mesh (its connectivity fixed, its positions moved):
//   - the RMS symmetry error, relative to the bounding-box diagonal of the mesh, with the mirror
//     points of compute_symmetric_map();
//   - the distortion: RMS relative change of the edge lengths and of the edge vectors;
//   - the naive baseline: every vertex moved halfway to the image of its mirror point.
// The mesh's vertex and face indices must be dense (no removed elements): position i is that of
// vertex i, face f of the symmetric map is face f.

#include <CGAL/Surface_mesh_symmetrization/compute_symmetric_map.h>
#include <CGAL/Shape_analysis/internal/Similarity_transform.h>
#include <CGAL/Shape_analysis/internal/Vector_3d.h>

#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/iterator.h>

#include <boost/property_map/property_map.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Shape_analysis_support {

template <typename Point>
class Symmetry_metrics
{
public:
  typedef CGAL::Shape_analysis::internal::Vector_3d Vector_3d;
  typedef CGAL::Surface_mesh<Point> Mesh;

  // Reads the connectivity and the input positions of `mesh`, which must outlive this object.
  explicit Symmetry_metrics(const Mesh& mesh) : m_mesh(mesh)
  {
    m_points = positions_of(mesh);
    for(auto f : faces(mesh)) {
      std::array<std::uint32_t, 3> t{{0, 0, 0}};
      std::size_t k = 0;
      for(auto v : CGAL::vertices_around_face(halfedge(f, mesh), mesh))
        if(k < 3)
          t[k++] = std::uint32_t(std::size_t(v));
      m_triangles.push_back(t);
    }
    for(const auto& t : m_triangles)
      for(int k = 0; k < 3; ++k) {
        std::uint32_t a = t[std::size_t(k)], b = t[std::size_t((k + 1) % 3)];
        if(a > b)
          std::swap(a, b);
        m_edges.emplace_back(a, b);
      }
    std::sort(m_edges.begin(), m_edges.end());
    m_edges.erase(std::unique(m_edges.begin(), m_edges.end()), m_edges.end());
    Vector_3d lo(std::numeric_limits<double>::infinity()), hi(-std::numeric_limits<double>::infinity());
    for(const auto& t : m_triangles)
      for(std::uint32_t v : t) {
        lo = lo.min(m_points[v]);
        hi = hi.max(m_points[v]);
      }
    m_diagonal = m_triangles.empty() ? 0.0 : (hi - lo).length();
  }

  // The positions of the vertices of `m` (this mesh or a copy of it, moved).
  static std::vector<Vector_3d> positions_of(const Mesh& m)
  {
    std::vector<Vector_3d> p;
    for(auto v : vertices(m))
      p.emplace_back(m.point(v).x(), m.point(v).y(), m.point(v).z());
    return p;
  }

  // The input positions.
  const std::vector<Vector_3d>& points() const { return m_points; }

  // RMS relative change of the edge lengths between `x0` and `x` (edges of positive length).
  double edge_distortion(const std::vector<Vector_3d>& x0, const std::vector<Vector_3d>& x) const
  {
    return rms_over_edges(x0, [&](std::uint32_t i, std::uint32_t j, double l0) {
      const double l = (x[i] - x[j]).length();
      return l / l0 - 1;
    });
  }

  // RMS relative change of the edge vectors between `x0` and `x`: |(x_i - x_j) - (x0_i - x0_j)|
  // over |x0_i - x0_j| (edges of positive length). It counts stretching and bending alike.
  double edge_vector_distortion(const std::vector<Vector_3d>& x0, const std::vector<Vector_3d>& x) const
  {
    return rms_over_edges(x0, [&](std::uint32_t i, std::uint32_t j, double l0) {
      return ((x[i] - x[j]) - (x0[i] - x0[j])).length() / l0;
    });
  }

  // The RMS symmetry error of positions `x` under `symmetry`, relative to the diagonal of the
  // input, over the vertices that have a mirror point.
  template <typename Symmetry>
  double symmetry_error(const std::vector<Vector_3d>& x, const Symmetry& symmetry, std::size_t threads) const
  {
    double sum = 0, count = 0;
    for(const auto& m : mirror_points(x, symmetry, threads))
      if(m.found) {
        sum += m.distance * m.distance;
        count += 1;
      }
    return (count > 0 ? std::sqrt(sum / count) : 0.0) / m_diagonal;
  }

  // The naive baseline: every vertex of positions `x` moved halfway to the image, under
  // `symmetry`, of its mirror point; vertices without one stay.
  template <typename Symmetry>
  std::vector<Vector_3d> naive_symmetrization(const std::vector<Vector_3d>& x, const Symmetry& symmetry,
                                              std::size_t threads) const
  {
    const auto mirrors = mirror_points(x, symmetry, threads);
    namespace SAI = CGAL::Shape_analysis::internal;
    SAI::Matrix_3d linear;
    Vector_3d translation;
    for(int i = 0; i < 3; ++i) {
      for(int j = 0; j < 3; ++j)
        linear[std::size_t(i)][j] = CGAL::to_double(symmetry.transformation.m(i, j));
      translation[i] = CGAL::to_double(symmetry.transformation.m(i, 3));
    }
    std::vector<Vector_3d> result = x;
    for(std::size_t i = 0; i < x.size(); ++i) {
      const auto& m = mirrors[i];
      if(!m.found)
        continue;
      const auto& t = m_triangles[m.face];
      const Vector_3d p = x[t[0]] * m.barycentric[0] + x[t[1]] * m.barycentric[1] + x[t[2]] * m.barycentric[2];
      result[i] = (x[i] + (SAI::multiply(linear, p) + translation)) * 0.5;
    }
    return result;
  }

private:
  // The mesh's points read from positions: vertex v at x[v].
  struct Position_map
  {
    typedef typename Mesh::Vertex_index key_type;
    typedef Point value_type;
    typedef Point reference;
    typedef boost::readable_property_map_tag category;
    const std::vector<Vector_3d>* x;
    friend Point get(const Position_map& map, key_type v)
    {
      const Vector_3d& p = (*map.x)[std::size_t(v)];
      return Point(p.x, p.y, p.z);
    }
  };

  template <typename Symmetry>
  std::vector<CGAL::Surface_mesh_symmetrization::Mirror_point>
  mirror_points(const std::vector<Vector_3d>& x, const Symmetry& symmetry, std::size_t threads) const
  {
    namespace SY = CGAL::Surface_mesh_symmetrization;
    return SY::compute_symmetric_map(m_mesh, symmetry,
                                     SY::parameters::vertex_point_map(Position_map{&x}).number_of_threads(threads));
  }

  // The RMS of `term(i, j, l0)` over the edges (i, j) of positive input length l0 in `x0`.
  template <typename Term>
  double rms_over_edges(const std::vector<Vector_3d>& x0, const Term& term) const
  {
    double sum = 0;
    std::size_t count = 0;
    for(const auto& e : m_edges) {
      const double l0 = (x0[e.first] - x0[e.second]).length();
      if(!(l0 > 0))
        continue;
      const double d = term(e.first, e.second, l0);
      sum += d * d;
      ++count;
    }
    return count > 0 ? std::sqrt(sum / double(count)) : 0.0;
  }

  const Mesh& m_mesh;
  std::vector<Vector_3d> m_points;
  std::vector<std::array<std::uint32_t, 3>> m_triangles;
  std::vector<std::pair<std::uint32_t, std::uint32_t>> m_edges;
  double m_diagonal = 0;
};

} // namespace Shape_analysis_support
} // namespace CGAL

#endif // SHAPE_ANALYSIS_SUPPORT_SYMMETRY_METRICS_H
