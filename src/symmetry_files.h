// Copyright (c) 2026 CGAL Global Shape Analysis contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef SHAPE_ANALYSIS_CLI_SYMMETRY_FILES_H
#define SHAPE_ANALYSIS_CLI_SYMMETRY_FILES_H

// The files the `symmetry` subcommands write besides meshes: coloured and support PLY, the
// symmetric map as text, and what maps mesh values back to the input's points and faces.

#include "cli_common.h"

#include <CGAL/IO/Color.h>
#include <CGAL/Surface_mesh_symmetrization/compute_symmetric_map.h>

#include <array>
#include <ostream>
#include <vector>

namespace shape_analysis_cli {

// The positions of the file's points after the mesh's vertices moved (points outside the mesh
// keep theirs).
std::vector<Point_3> moved_points(const Input_mesh& input, const Mesh& mesh);

// Binary PLY of a triangle soup with per-vertex colours (double coordinates).
void write_vertex_coloured_ply(std::ostream& out, const std::vector<Point_3>& points,
                               const std::vector<std::array<std::size_t, 3>>& triangles,
                               const std::vector<CGAL::IO::Color>& colours);

// Binary PLY with per-face support: a colour from grey (0) to red (1) and a float `support`.
void write_support_ply(std::ostream& out, const std::vector<Point_3>& points,
                       const std::vector<std::array<std::size_t, 3>>& triangles,
                       const std::vector<double>& support);

// Per input face, from per mesh face (faces left out of the mesh take `fallback`).
std::vector<double> per_input_face(const Input_mesh& input, const std::vector<double>& mesh_values,
                                   double fallback);

// The symmetric map per point of the output file: "point face b0 b1 b2", the face being an input
// face and the coordinates in the order of its corners in the output; "point -1 0 0 0" for
// points without a mirror point.
void write_map(std::ostream& out, const Input_mesh& input, const Mesh& mesh,
               const std::vector<CGAL::Surface_mesh_symmetrization::Mirror_point>& map);

} // namespace shape_analysis_cli

#endif // SHAPE_ANALYSIS_CLI_SYMMETRY_FILES_H
