// Copyright (c) 2026 CGAL Global Shape Analysis contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef SHAPE_ANALYSIS_CLI_SYMMETRY_FILES_H
#define SHAPE_ANALYSIS_CLI_SYMMETRY_FILES_H

// What the `symmetry` subcommands share: their common options, the plane (given or detected) and
// its JSON, the symmetrization of the input; and the files they write besides meshes: coloured
// and support PLY, the symmetric map as text, and what maps mesh values back to the input's
// points and faces.

#include "cli_common.h"

#include <CGAL/IO/Color.h>
#include <CGAL/Surface_mesh_symmetrization/compute_symmetric_map.h>
#include <CGAL/Surface_mesh_symmetrization/detect_reflective_symmetries.h>
#include <CGAL/Surface_mesh_symmetrization/detect_rotational_symmetries.h>
#include <CGAL/Surface_mesh_symmetrization/regularize_symmetries.h>
#include <CGAL/Surface_mesh_symmetrization/symmetrize.h>

#include <CLI/CLI.hpp>

#include <array>
#include <functional>
#include <ostream>
#include <string>
#include <vector>

namespace shape_analysis_cli {

namespace SMS = CGAL::Surface_mesh_symmetrization;
typedef SMS::Symmetry<Kernel> Symmetry;

// The files and switches of the commands; the library's options with the library's defaults.
// `detection` holds --samples, --seed and --threads (the last one also given to symmetrize() and
// transfer_vertex_attribute()).
struct Common_options
{
  std::string input, report, plane;
  std::vector<std::string> planes; // every --plane given (symmetrize and enhance take several)
  SMS::Detect_reflective_symmetries_options detection;
  bool quiet = false;
  bool verbose = false;
};

struct Symmetrize_command_options : Common_options
{
  std::string output_off, map;
  SMS::Symmetrize_options symmetrization;
  // --rotation [ax,ay,az,px,py,pz,k]: a turn about an axis instead of a plane, detected when no
  // value is given.
  std::string rotation;
  bool rotation_requested = false;
  std::size_t detected_planes = 1; // without --plane: how many of the best detected planes
  // --regularize DEG: regularize_symmetries()'s maximum_angle for several planes; negative (not
  // given): the library's default for detected planes, none for planes given.
  double regularize = -1;
};

// The symmetries a symmetrization used, several planes with what their regularization did
// (`regularization`: null when it did not run, else maximum_angle, largest_turn_degrees, dropped).
struct Used_symmetries
{
  std::vector<Symmetry> all;
  Json regularization;
};

// Adds --rotation to `cmd` (symmetrize, enhance); `o.rotation_requested` is set by
// note_rotation_option() from the command's callback.
void add_rotation_option(CLI::App* cmd, Symmetrize_command_options& o);
// Adds --detected-planes and --regularize to `cmd` (symmetrize, enhance).
void add_several_planes_option(CLI::App* cmd, Symmetrize_command_options& o);
void note_rotation_option(const CLI::App* cmd, Symmetrize_command_options& o);

// The turn of --rotation ax,ay,az,px,py,pz,k: by 2 pi / k about the axis through (px,py,pz) along
// (ax,ay,az), k >= 2, or for k = 0 by Rotational_symmetry::angle() of a surface of revolution;
// Usage_error otherwise.
Symmetry parse_rotation(const std::string& text);

// Usage_error for a bad --plane or --rotation, or both given (before any file is read).
void check_symmetry_options(const Symmetrize_command_options& o);

// The rotation's axis (unit), the point of the axis nearest the origin, its angle in degrees, and
// its order k when the angle is 2 pi / k (null otherwise), read off the transformation.
Json rotation_json(const Symmetry& s);

// The input, --plane, --samples, --seed, --threads, -q and -v.
void add_common_options(CLI::App* cmd, Common_options& o, bool with_plane);

// "a,b,c,d" as a plane; Usage_error when it is not four numbers.
Kernel::Plane_3 parse_plane(const std::string& text);

// The reflective symmetry to use: the given plane, or the best detected one (Cli_error when none).
Symmetry symmetry_of(const Common_options& o, const Mesh& mesh, Progress& progress, double& seconds,
                     bool& detected);

// The plane as JSON: unit normal n and offset d of n.x = d, and coefficients a,b,c,d of
// a x + b y + c z + d = 0 (for --plane); and as the text of --plane.
Json plane_json(const Symmetry& s);
std::string plane_text(const Symmetry& s);

// Symmetrizes `input.mesh` in place (the plane or, with --rotation, the turn given or detected);
// returns the result and the symmetry used.
// With several planes (--plane repeated, or --detected-planes N), regularized by --regularize
// (by default when detected), `symmetry` is the first and `used` (when given) receives them all.
SMS::Symmetrization_result<Kernel> symmetrize_input(const Symmetrize_command_options& o, Input_mesh& input,
                                                    Progress& progress, Symmetry& symmetry,
                                                    double& detect_seconds, bool& detected,
                                                    Used_symmetries* used = nullptr);

// The options of symmetrize() as the library's named parameters, and the report's figures of a
// symmetrization.
Json symmetrization_parameters(const Symmetrize_command_options& o);
void add_symmetrization_report(Json& report, const SMS::Symmetrization_result<Kernel>& r,
                               const Symmetry& s, bool detected, double detect_seconds,
                               const Used_symmetries& used = {});


// Adds `remesh` and `decimate` to the `symmetry` command (symmetry_remesh_command.cpp).
void add_symmetry_remesh_commands(CLI::App* symmetry, std::function<int()>& run);

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
