// Copyright (c) 2026 CGAL Global Shape Analysis contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#include "symmetry_files.h"

#include <CGAL/IO/PLY.h>

#include <cstdint>

namespace shape_analysis_cli {

namespace SMS = CGAL::Surface_mesh_symmetrization;

// The positions of the file's points after the mesh's vertices moved (points outside the mesh
// keep theirs).
std::vector<Point_3> moved_points(const Input_mesh& input, const Mesh& mesh)
{
  std::vector<Point_3> points = input.points;
  for(Mesh::Vertex_index v : mesh.vertices())
    if(input.vertex_point[v] != Input_mesh::left_out)
      points[input.vertex_point[v]] = mesh.point(v);
  return points;
}

// Binary PLY of a triangle soup with per-vertex colours (double coordinates).
void write_vertex_coloured_ply(std::ostream& out, const std::vector<Point_3>& points,
                               const std::vector<std::array<std::size_t, 3>>& triangles,
                               const std::vector<CGAL::IO::Color>& colours)
{
  out << "ply\nformat binary_little_endian 1.0\n"
      << "comment written by shape_analysis (CGAL Global Shape Analysis)\n"
      << "element vertex " << points.size() << "\n"
      << "property double x\nproperty double y\nproperty double z\n"
      << "property uchar red\nproperty uchar green\nproperty uchar blue\n"
      << "element face " << triangles.size() << "\n"
      << "property list uchar int vertex_indices\n"
      << "end_header\n";
  for(std::size_t i = 0; i < points.size(); ++i) {
    for(int k = 0; k < 3; ++k) {
      const double x = CGAL::to_double(points[i][k]);
      out.write(reinterpret_cast<const char*>(&x), sizeof x);
    }
    const unsigned char c[3] = {colours[i].red(), colours[i].green(), colours[i].blue()};
    out.write(reinterpret_cast<const char*>(c), 3);
  }
  for(const auto& t : triangles) {
    const unsigned char three = 3;
    out.write(reinterpret_cast<const char*>(&three), 1);
    for(std::size_t v : t) {
      const std::int32_t i = static_cast<std::int32_t>(v);
      out.write(reinterpret_cast<const char*>(&i), sizeof i);
    }
  }
}

// Binary PLY with per-face support: a colour from grey (0) to red (1) and a float `support`.
void write_support_ply(std::ostream& out, const std::vector<Point_3>& points,
                       const std::vector<std::array<std::size_t, 3>>& triangles,
                       const std::vector<double>& support)
{
  const auto clamped = [&](std::size_t f) { return (std::max)(0.0, (std::min)(1.0, support[f])); };
  write_face_ply(
    out, points, triangles,
    [&](std::size_t f) {
      const double s = clamped(f);
      return std::array<unsigned char, 3>{{static_cast<unsigned char>(200 + 55 * s),
                                           static_cast<unsigned char>(200 * (1 - s)),
                                           static_cast<unsigned char>(200 * (1 - s))}};
    },
    "support", false, clamped);
}

// Per input face, from per mesh face (faces left out of the mesh take `fallback`).
std::vector<double> per_input_face(const Input_mesh& input, const std::vector<double>& mesh_values,
                                   double fallback)
{
  std::vector<double> r(input.number_of_input_faces(), fallback);
  for(std::size_t i = 0; i < r.size(); ++i)
    if(input.mesh_face[i] != Input_mesh::left_out)
      r[i] = mesh_values[input.mesh_face[i]];
  return r;
}

// The symmetric map per point of the output file: "point face b0 b1 b2", the face being an input
// face and the coordinates in the order of its corners in the output; "point -1 0 0 0" for
// points without a mirror point.
void write_map(std::ostream& out, const Input_mesh& input, const Mesh& mesh,
               const std::vector<SMS::Mirror_point>& map)
{
  std::vector<std::size_t> input_face(num_faces(mesh), Input_mesh::left_out);
  for(std::size_t i = 0; i < input.mesh_face.size(); ++i)
    if(input.mesh_face[i] != Input_mesh::left_out)
      input_face[input.mesh_face[i]] = i;
  std::vector<Mesh::Face_index> face_of;
  for(Mesh::Face_index f : mesh.faces())
    face_of.push_back(f);
  std::vector<std::size_t> vertex_of_point(input.points.size(), Input_mesh::left_out);
  std::size_t k = 0;
  for(Mesh::Vertex_index v : mesh.vertices()) {
    const std::size_t p = input.vertex_point[v];
    if(p != Input_mesh::left_out && vertex_of_point[p] == Input_mesh::left_out)
      vertex_of_point[p] = k;
    ++k;
  }
  out << "# shape_analysis symmetry map: point face b0 b1 b2\n"
      << "# point: 0-based vertex of the output mesh; face: 0-based face of the output mesh (-1: no\n"
      << "# mirror point); b0 b1 b2: barycentric coordinates w.r.t. the face's corners in file order\n";
  out << std::setprecision(17);
  for(std::size_t p = 0; p < input.points.size(); ++p) {
    const std::size_t v = vertex_of_point[p];
    if(v == Input_mesh::left_out || !map[v].found || input_face[map[v].face] == Input_mesh::left_out) {
      out << p << " -1 0 0 0\n";
      continue;
    }
    const SMS::Mirror_point& m = map[v];
    const std::size_t f = input_face[m.face];
    // Corners of the mesh face in the order of the barycentric coordinates, as points.
    std::array<std::size_t, 3> corner{{0, 0, 0}};
    int c = 0;
    for(Mesh::Vertex_index u : vertices_around_face(mesh.halfedge(face_of[m.face]), mesh))
      corner[std::size_t(c++)] = input.vertex_point[u];
    std::array<double, 3> b{{0, 0, 0}};
    for(int j = 0; j < 3; ++j)
      for(int q = 0; q < 3; ++q)
        if(input.triangles[f][std::size_t(q)] == corner[std::size_t(j)])
          b[std::size_t(q)] += m.barycentric[std::size_t(j)];
    out << p << ' ' << f << ' ' << b[0] << ' ' << b[1] << ' ' << b[2] << '\n';
  }
}

} // namespace shape_analysis_cli
