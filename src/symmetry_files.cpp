// Copyright (c) 2026 CGAL Global Shape Analysis contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#include "symmetry_files.h"

#include <CGAL/IO/PLY.h>

#include <Eigen/Dense>

#include <cmath>
#include <cstdint>
#include <iomanip>
#include <sstream>

namespace shape_analysis_cli {

void add_common_options(CLI::App* cmd, Common_options& o, bool with_plane)
{
  cmd->add_option("input", o.input, "Triangle mesh (.off, .ply, .obj, .stl)")->required();
  if(with_plane)
    cmd->add_option("--plane", o.plane,
                    "Symmetry plane a,b,c,d (a x + b y + c z + d = 0); detected when absent (symmetrize "
                    "and enhance: repeat it for several planes)")
      ->multi_option_policy(CLI::MultiOptionPolicy::TakeLast)
      ->each([&o](const std::string& v) { o.planes.push_back(v); });
  cmd->add_option("--samples", o.detection.number_of_samples, "Number of points sampled for the detection (>= 20)")
    ->capture_default_str();
  cmd->add_option("--seed", o.detection.random_seed, "Random seed of the detection (same seed, same result)")
    ->capture_default_str();
  cmd->add_option("--threads", o.detection.number_of_threads, "Largest number of threads (0: all cores)")
    ->capture_default_str();
  cmd->add_flag("-q,--quiet", o.quiet, "No progress on stderr");
  cmd->add_flag("-v,--verbose", o.verbose, "Progress on stderr even when it is not a terminal");
}

// "a,b,c,d" as a plane; Usage_error when it is not four numbers.
std::vector<double> parse_numbers(const std::string& text, const std::string& option, const std::string& expected);

Kernel::Plane_3 parse_plane(const std::string& text)
{
  const std::vector<double> v = parse_numbers(text, "--plane", "four numbers a,b,c,d");
  if(v.size() != 4)
    throw Usage_error("--plane needs four numbers a,b,c,d (got '" + text + "')");
  return Kernel::Plane_3(v[0], v[1], v[2], v[3]);
}

// Numbers separated by commas; Usage_error naming `option` and `expected` when one is not a number.
std::vector<double> parse_numbers(const std::string& text, const std::string& option, const std::string& expected)
{
  std::vector<double> v;
  std::stringstream ss(text);
  std::string item;
  while(std::getline(ss, item, ',')) {
    std::size_t used = 0;
    double x = 0;
    try {
      x = std::stod(item, &used);
    } catch(const std::exception&) {
      used = 0;
    }
    while(used < item.size() && std::isspace(static_cast<unsigned char>(item[used])))
      ++used;
    if(item.empty() || used != item.size())
      throw Usage_error(option + " needs " + expected + " (got '" + text + "')");
    v.push_back(x);
  }
  return v;
}

void add_rotation_option(CLI::App* cmd, Symmetrize_command_options& o)
{
  cmd->add_option("--rotation", o.rotation,
                  "Symmetrize about a turn instead of a plane: ax,ay,az,px,py,pz,k (k-fold about the axis "
                  "through p along a; k = 0: a surface of revolution), or the best detected one when no "
                  "value is given")
    ->expected(0, 1);
}

void note_rotation_option(const CLI::App* cmd, Symmetrize_command_options& o)
{
  o.rotation_requested = cmd->count("--rotation") > 0;
}

Symmetry parse_rotation(const std::string& text)
{
  const std::string expected = "seven numbers ax,ay,az,px,py,pz,k (k = 0 or an integer from 2 to 360)";
  const std::vector<double> v = parse_numbers(text, "--rotation", expected);
  bool finite = true;
  for(double x : v)
    finite = finite && std::isfinite(x);
  if(v.size() != 7 || !finite || !(v[6] == std::floor(v[6])) || v[6] == 1 || v[6] < 0 || v[6] > 360)
    throw Usage_error("--rotation needs " + expected + " (got '" + text + "')");
  SMS::Rotational_symmetry<Kernel> r;
  r.axis = Kernel::Vector_3(v[0], v[1], v[2]);
  r.point = Kernel::Point_3(v[3], v[4], v[5]);
  r.order = std::size_t(v[6]);
  try {
    return SMS::rotational_symmetry<Kernel>(r.point, r.axis, r.angle());
  } catch(const CGAL::Shape_analysis::Bad_input&) {
    throw Usage_error("--rotation: the axis (ax,ay,az) is the zero vector (got '" + text + "')");
  }
}

void add_several_planes_option(CLI::App* cmd, Symmetrize_command_options& o)
{
  cmd->add_option("--detected-planes", o.detected_planes,
                  "Without --plane: symmetrize about this many of the best detected planes at once, each "
                  "weighted by its support (partial symmetries)")
    ->capture_default_str()
    ->check(positive_count);
  cmd->add_option("--regularize", o.regularize,
                  "With several planes: make those nearly perpendicular perpendicular, those nearly sharing an axis "
                  "share it (at multiples of pi/k), duplicates dropped, turning a plane by at most this many degrees "
                  "(0 to 30; default " +
                    Json(SMS::Regularize_symmetries_options().maximum_angle).dump() +
                    " for detected planes, 0 = off for planes given)")
    ->check(CLI::Range(0.0, 30.0));
}

void check_symmetry_options(const Symmetrize_command_options& o)
{
  if(o.rotation_requested && !o.plane.empty())
    throw Usage_error("give either --plane or --rotation, not both");
  if(o.detected_planes != 1 && (!o.plane.empty() || o.rotation_requested))
    throw Usage_error("--detected-planes is for detected planes: not with --plane or --rotation");
  if(o.regularize >= 0 && o.planes.size() < 2 && o.detected_planes < 2)
    throw Usage_error("--regularize is for several planes (--plane repeated, or --detected-planes N)");
  for(const std::string& p : o.planes)
    parse_plane(p);
  if(o.rotation_requested && !o.rotation.empty())
    parse_rotation(o.rotation);
}

Json rotation_json(const Symmetry& s)
{
  Eigen::Matrix3d m;
  Eigen::Vector3d t;
  for(int i = 0; i < 3; ++i) {
    for(int j = 0; j < 3; ++j)
      m(i, j) = CGAL::to_double(s.transformation.m(i, j));
    t(i) = CGAL::to_double(s.transformation.m(i, 3));
  }
  // The axis from the skew part (sin of the angle times the axis), the angle from the trace.
  Eigen::Vector3d axis(m(2, 1) - m(1, 2), m(0, 2) - m(2, 0), m(1, 0) - m(0, 1));
  const double sine = 0.5 * axis.norm(), cosine = 0.5 * (m.trace() - 1);
  if(axis.norm() > 0)
    axis.normalize();
  else { // a half turn: the axis is the column of R + I of largest norm
    const Eigen::Matrix3d p = m + Eigen::Matrix3d::Identity();
    int k = 0;
    for(int j = 1; j < 3; ++j)
      if(p.col(j).norm() > p.col(k).norm())
        k = j;
    axis = p.col(k).normalized();
  }
  const double angle = std::atan2(sine, cosine);
  // The point of the axis nearest the origin: the least-norm solution of (I - R) p = t.
  const Eigen::Vector3d point =
    (Eigen::Matrix3d::Identity() - m).jacobiSvd(Eigen::ComputeFullU | Eigen::ComputeFullV).solve(t);
  Json j = Json::object();
  j["axis"] = Json(std::vector<double>{axis(0), axis(1), axis(2)});
  j["point"] = Json(std::vector<double>{point(0), point(1), point(2)});
  j["angle_degrees"] = angle * 180 / 3.14159265358979323846;
  const double k = angle > 0 ? 2 * 3.14159265358979323846 / angle : 0;
  j["order"] = k >= 2 && std::abs(k - std::round(k)) < 1e-6 * k ? Json(std::size_t(std::round(k))) : Json();
  return j;
}

// The reflective symmetry to use: the given plane, or the best detected one.
Symmetry symmetry_of(const Common_options& o, const Mesh& mesh, Progress& progress, double& seconds,
                     bool& detected)
{
  Stopwatch watch;
  if(o.planes.size() > 1)
    throw Usage_error("one --plane only (symmetrize and enhance take several)");
  detected = o.plane.empty();
  if(!detected) {
    const Symmetry s = SMS::reflective_symmetry<Kernel>(parse_plane(o.plane));
    seconds = watch.seconds();
    return s;
  }
  progress.stage("detecting the symmetry plane");
  std::vector<Symmetry> found;
  const SMS::Detect_reflective_symmetries_options& d = o.detection;
  SMS::detect_reflective_symmetries(mesh, std::back_inserter(found),
                                    SMS::parameters::number_of_samples(d.number_of_samples)
                                      .random_seed(d.random_seed)
                                      .number_of_threads(d.number_of_threads)
                                      .maximum_number_of_symmetries(1));
  seconds = watch.seconds();
  if(found.empty())
    throw Cli_error("no reflective symmetry found (give one with --plane a,b,c,d)");
  return found.front();
}

// The plane as JSON: unit normal n and offset d of n.x = d, and coefficients a,b,c,d of
// a x + b y + c z + d = 0 (for --plane).
Json plane_json(const Symmetry& s)
{
  const double a = CGAL::to_double(s.plane.a()), b = CGAL::to_double(s.plane.b()),
               c = CGAL::to_double(s.plane.c()), d = CGAL::to_double(s.plane.d());
  const double l = std::sqrt(a * a + b * b + c * c);
  Json p = Json::object();
  p["normal"] = Json(std::vector<double>{a / l, b / l, c / l});
  p["offset"] = -d / l;
  p["coefficients"] = Json(std::vector<double>{a / l, b / l, c / l, d / l});
  return p;
}

std::string plane_text(const Symmetry& s)
{
  const Json p = plane_json(s);
  std::ostringstream out;
  out << std::setprecision(9);
  const double a = CGAL::to_double(s.plane.a()), b = CGAL::to_double(s.plane.b()),
               c = CGAL::to_double(s.plane.c()), d = CGAL::to_double(s.plane.d());
  const double l = std::sqrt(a * a + b * b + c * c);
  out << a / l << ',' << b / l << ',' << c / l << ',' << d / l;
  return out.str();
}

// ---------------------------------------------------------------------------------------------

// Several planes regularized (regularize_symmetries()) when --regularize asks for it, or by default
// when they were detected; what it did as the report's "regularization" (null when not run).
Json regularize(const Symmetrize_command_options& o, const Input_mesh& input, std::vector<Symmetry>& symmetries)
{
  const double angle = o.regularize >= 0 ? o.regularize
                                         : (o.planes.size() <= 1 ? SMS::Regularize_symmetries_options().maximum_angle : 0.0);
  if(!(angle > 0))
    return Json();
  const std::vector<Symmetry> r = SMS::regularize_symmetries(input.mesh, symmetries, SMS::parameters::maximum_angle(angle));
  // Each plane kept turned from the nearest plane given: the largest such turn.
  const auto unit_normal = [](const Symmetry& s) {
    const Kernel::Vector_3 n = s.plane.orthogonal_vector();
    return n / std::sqrt(CGAL::to_double(n.squared_length()));
  };
  double turn = 0;
  for(const Symmetry& x : r) {
    double c = 0;
    for(const Symmetry& s : symmetries)
      c = (std::max)(c, std::abs(CGAL::to_double(unit_normal(x) * unit_normal(s))));
    turn = (std::max)(turn, std::acos((std::min)(1.0, c)) * 180 / 3.14159265358979323846);
  }
  Json j;
  j["maximum_angle"] = angle;
  j["maximum_offset"] = SMS::Regularize_symmetries_options().maximum_offset;
  j["largest_turn_degrees"] = turn;
  j["dropped"] = symmetries.size() - r.size();
  symmetries = r;
  return j;
}

// Symmetrizes `input.mesh` in place; returns the result and the symmetry used.
SMS::Symmetrization_result<Kernel> symmetrize_input(const Symmetrize_command_options& o, Input_mesh& input,
                                                    Progress& progress, Symmetry& symmetry,
                                                    double& detect_seconds, bool& detected,
                                                    Used_symmetries* used)
{
  std::vector<Symmetry> symmetries;
  if(o.rotation_requested) {
    Stopwatch watch;
    detected = o.rotation.empty();
    if(detected) {
      progress.stage("detecting the rotational symmetry");
      std::vector<SMS::Rotational_symmetry<Kernel>> found;
      const SMS::Detect_reflective_symmetries_options& d = o.detection;
      SMS::detect_rotational_symmetries(input.mesh, std::back_inserter(found),
                                        SMS::parameters::number_of_samples(d.number_of_samples)
                                          .random_seed(d.random_seed)
                                          .number_of_threads(d.number_of_threads)
                                          .maximum_number_of_symmetries(1));
      if(found.empty())
        throw Cli_error("no rotational symmetry found (give one with --rotation ax,ay,az,px,py,pz,k)");
      symmetry = found.front().symmetry();
    } else
      symmetry = parse_rotation(o.rotation);
    detect_seconds = watch.seconds();
  } else if(o.planes.size() > 1) { // several planes given
    detected = false;
    for(const std::string& p : o.planes)
      symmetries.push_back(SMS::reflective_symmetry<Kernel>(parse_plane(p)));
    symmetry = symmetries.front();
  } else if(o.plane.empty() && o.detected_planes > 1) { // the best planes detected, with their supports
    Stopwatch watch;
    detected = true;
    progress.stage("detecting the symmetry planes");
    const SMS::Detect_reflective_symmetries_options& d = o.detection;
    SMS::detect_reflective_symmetries(input.mesh, std::back_inserter(symmetries),
                                      SMS::parameters::number_of_samples(d.number_of_samples)
                                        .random_seed(d.random_seed)
                                        .number_of_threads(d.number_of_threads)
                                        .maximum_number_of_symmetries(o.detected_planes));
    detect_seconds = watch.seconds();
    if(symmetries.empty())
      throw Cli_error("no reflective symmetry found (give one with --plane a,b,c,d)");
    symmetry = symmetries.front();
  } else
    symmetry = symmetry_of(o, input.mesh, progress, detect_seconds, detected);
  Json regularization;
  if(symmetries.size() > 1) { // several planes: their relations made exact
    regularization = regularize(o, input, symmetries);
    symmetry = symmetries.front();
  }
  if(symmetries.empty())
    symmetries.push_back(symmetry);
  if(used != nullptr)
    *used = Used_symmetries{symmetries, regularization};
  progress.stage("symmetrizing " + std::to_string(num_vertices(input.mesh)) + " vertices " +
                 (symmetry.is_reflection ? "about the plane " + plane_text(symmetry)
                                         : std::string("under the turn ") + rotation_json(symmetry).dump()));
  std::function<void(double)> on_progress = [&](double f) { progress.fraction(f); };
  const SMS::Symmetrize_options& so = o.symmetrization;
  auto result = SMS::symmetrize(input.mesh, symmetries,
                                SMS::parameters::number_of_iterations(so.number_of_iterations)
                                  .shape_weight(so.shape_weight)
                                  .displacement_weight(so.displacement_weight)
                                  .number_of_levels(so.number_of_levels)
                                  .coarsest_level_size(so.coarsest_level_size)
                                  .symmetry_tolerance(so.symmetry_tolerance)
                                  .target_symmetry_error(so.target_symmetry_error)
                                  .final_symmetry_weight(so.final_symmetry_weight)
                                  .support_weighting(so.support_weighting)
                                  .number_of_threads(o.detection.number_of_threads)
                                  .progress_callback(on_progress));
  progress.done();
  return result;
}

// The options of symmetrize() as the library's named parameters (support_weighting: null for the
// library's choice by the number of symmetries).
Json symmetrization_parameters(const Symmetrize_command_options& o)
{
  const SMS::Symmetrize_options& so = o.symmetrization;
  Json parameters = Json::object();
  parameters["number_of_iterations"] = so.number_of_iterations;
  parameters["shape_weight"] = so.shape_weight;
  parameters["displacement_weight"] = so.displacement_weight;
  parameters["number_of_levels"] = so.number_of_levels;
  parameters["coarsest_level_size"] = so.coarsest_level_size;
  parameters["symmetry_tolerance"] = so.symmetry_tolerance;
  parameters["target_symmetry_error"] = so.target_symmetry_error;
  parameters["final_symmetry_weight"] = so.final_symmetry_weight;
  parameters["support_weighting"] = so.support_weighting ? Json(*so.support_weighting) : Json();
  parameters["number_of_threads"] = o.detection.number_of_threads;
  return parameters;
}

void add_symmetrization_report(Json& report, const SMS::Symmetrization_result<Kernel>& r,
                               const Symmetry& s, bool detected, double detect_seconds,
                               const Used_symmetries& used)
{
  if(used.all.size() > 1) { // each plane, with its support fraction (1 for a plane given)
    Json planes = Json::array();
    for(const Symmetry& x : used.all) {
      Json j = plane_json(x);
      j["support"] = x.support_fraction;
      planes.push_back(j);
    }
    report["planes"] = planes;
  }
  if(used.all.size() > 1 || !used.regularization.is_null()) // (one plane left after dropping duplicates)
    report["regularization"] = used.regularization;
  if(s.is_reflection) {
    report["plane"] = plane_json(s);
    report["plane_detected"] = detected;
  } else {
    report["rotation"] = rotation_json(s);
    report["rotation_detected"] = detected;
  }
  report["seconds_detection"] = detect_seconds;
  report["symmetry_error_before"] = r.symmetry_error_before;
  report["symmetry_error_after"] = r.symmetry_error_after;
  report["distortion"] = r.distortion;
  report["levels"] = Json(r.level_sizes);
  report["symmetry_errors"] = Json(r.symmetry_errors);
}

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
