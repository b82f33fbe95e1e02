// Copyright (c) 2026 CGAL Global Shape Analysis contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_SHAPE_ANALYSIS_INTERNAL_MESH_CHECKS_H
#define CGAL_SHAPE_ANALYSIS_INTERNAL_MESH_CHECKS_H

// Checks shared by the public entry points: what they need of a mesh, with a one-line reason.

#include <CGAL/Shape_analysis/Bad_input.h>
#include <CGAL/Shape_analysis/internal/Vector_3d.h>

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/number_utils.h>

#include <boost/property_map/property_map.hpp>

#include <cmath>
#include <limits>
#include <memory>
#include <string>
#include <vector>

namespace CGAL {
namespace Shape_analysis {
namespace internal {

// Throws Bad_input unless `tm` is a non-empty triangle mesh whose face corners have finite
// coordinates (read with `to_vector`, a functor from points to Vector_3d). Unused vertices are
// not looked at.
template <typename TriangleMesh, typename VertexPointMap, typename ToVector>
void check_triangle_mesh(const TriangleMesh& tm, VertexPointMap vpm, const ToVector& to_vector,
                         const std::string& who)
{
  if(faces(tm).empty())
    throw Bad_input(who + ": the mesh has no faces");
  std::size_t index = 0;
  for(auto f : faces(tm)) {
    std::size_t degree = 0;
    for(auto h : CGAL::halfedges_around_face(halfedge(f, tm), tm)) {
      if(++degree > 3)
        break;
      const Vector_3d p = to_vector(get(vpm, target(h, tm)));
      if(!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
        throw Bad_input(who + ": a corner of face " + std::to_string(index) +
                        " has a coordinate that is not a finite number");
    }
    if(degree != 3)
      throw Bad_input(who + ": face " + std::to_string(index) +
                      " is not a triangle; triangulate the mesh first");
    ++index;
  }
}

// Face indices 0..n-1 over the faces that `faces(tm)` lists, from any face index map: a
// `Surface_mesh` with removed but uncollected faces, or a user map with gaps, gives indices that
// are not contiguous; this map renumbers them densely (in the order of the original indices).
template <typename FaceIndexMap>
class Dense_face_index_map
{
public:
  typedef typename boost::property_traits<FaceIndexMap>::key_type key_type;
  typedef std::size_t value_type;
  typedef std::size_t reference;
  typedef boost::readable_property_map_tag category;

  template <typename FaceGraph>
  Dense_face_index_map(const FaceGraph& tm, FaceIndexMap fim, const std::string& who)
    : m_fim(fim), m_dense(std::make_shared<std::vector<std::size_t>>())
  {
    const std::size_t none = (std::numeric_limits<std::size_t>::max)();
    std::vector<std::size_t>& dense = *m_dense;
    for(auto f : faces(tm)) {
      const std::size_t i = static_cast<std::size_t>(get(fim, f));
      if(i >= dense.size())
        dense.resize(i + 1, none);
      if(dense[i] != none)
        throw Bad_input(who + ": the face index map gives two faces the same index");
      dense[i] = 0;
    }
    for(std::size_t& d : dense)
      if(d != none)
        d = m_size++;
  }

  // Number of faces.
  std::size_t size() const { return m_size; }

  friend std::size_t get(const Dense_face_index_map& m, const key_type& f)
  {
    return (*m.m_dense)[static_cast<std::size_t>(get(m.m_fim, f))];
  }

private:
  FaceIndexMap m_fim;
  std::shared_ptr<std::vector<std::size_t>> m_dense;
  std::size_t m_size = 0;
};

} // namespace internal
} // namespace Shape_analysis
} // namespace CGAL

#endif // CGAL_SHAPE_ANALYSIS_INTERNAL_MESH_CHECKS_H
