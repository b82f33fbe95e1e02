// Copyright (c) 2026 CGAL Global Shape Analysis contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#include "cli_common.h"

#include <CGAL/IO/polygon_soup_io.h>
#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polygon_mesh_processing/repair_polygon_soup.h>
#include <Shape_analysis_support/Input_checks.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <map>
#include <sstream>

namespace shape_analysis_cli {

namespace fs = std::filesystem;
namespace PMP = CGAL::Polygon_mesh_processing;

void check_input_file(const std::string& path)
{
  std::error_code ec;
  if(!fs::exists(path, ec))
    throw Cli_error("cannot read '" + path + "': no such file");
  if(fs::is_directory(path, ec))
    throw Cli_error("cannot read '" + path + "': it is a directory");
  if(!fs::is_regular_file(path, ec))
    throw Cli_error("cannot read '" + path + "': not a regular file (a device or a pipe)");
  std::ifstream probe(path, std::ios::binary);
  if(!probe)
    throw Cli_error("cannot read '" + path + "': permission denied or unreadable");
}

Input_mesh read_triangle_mesh(const std::string& path)
{
  check_input_file(path);
  const std::string ext = lower_extension(path);
  if(ext != ".off" && ext != ".ply" && ext != ".obj" && ext != ".stl")
    throw Cli_error("cannot read '" + path + "': unknown mesh format '" + ext +
                    "' (use .off, .ply, .obj or .stl)");

  if(ext == ".ply") {
    try {
      CGAL::Shape_analysis_support::check_ply_vertices(path);
    } catch(const CGAL::Shape_analysis::Bad_input& e) {
      throw Cli_error(std::string("cannot read '") + path + "'" + (e.what() + path.size()));
    }
  }
  Input_mesh result;
  std::vector<std::vector<std::size_t>> polygons;
  bool ok = false, read = false;
  if(ext == ".off") { // ASCII OFF: our checked reader (CGAL's trusts sizes, indices and counts)
    std::vector<std::array<double, 3>> positions;
    bool binary = false;
    const std::string why = CGAL::Shape_analysis_support::read_ascii_off(path, positions, polygons, binary);
    if(!why.empty())
      throw Cli_error("cannot read '" + path + "': " + why);
    if(!binary) {
      result.points.reserve(positions.size());
      for(const auto& p : positions)
        result.points.emplace_back(p[0], p[1], p[2]);
      ok = read = true;
    }
  } else if(ext == ".obj") { // (before CGAL's reader, which trusts the indices)
    const std::string why = CGAL::Shape_analysis_support::check_obj_faces(path);
    if(!why.empty())
      throw Cli_error("cannot read '" + path + "': " + why);
  }
  try {
    if(!read)
      ok = CGAL::IO::read_polygon_soup(path, result.points, polygons, CGAL::parameters::verbose(false));
  } catch(const std::exception&) {
    ok = false;
  }
  if(!ok)
    throw Cli_error("cannot read '" + path + "': not a valid " + ext.substr(1) +
                    " mesh file (or a coordinate that is not a number)");
  if(polygons.empty())
    throw Cli_error("'" + path + "' has no faces");
  const std::vector<Point_3>& points = result.points;
  // Every point, used or not, must be finite (points are sorted and merged by position below).
  for(std::size_t v = 0; v < points.size(); ++v)
    if(!std::isfinite(points[v].x()) || !std::isfinite(points[v].y()) || !std::isfinite(points[v].z()))
      throw Cli_error("'" + path + "': vertex " + std::to_string(v) +
                      " has a coordinate that is not a finite number");
  // The reports' areas and lengths are in the mesh's units: their squares must stay finite.
  for(std::size_t v = 0; v < points.size(); ++v)
    if(!(std::abs(points[v].x()) <= 1e150 && std::abs(points[v].y()) <= 1e150 && std::abs(points[v].z()) <= 1e150))
      throw Cli_error("'" + path + "': vertex " + std::to_string(v) +
                      " has a coordinate above 1e150 in magnitude (areas would overflow); scale the mesh");
  for(std::size_t i = 0; i < polygons.size(); ++i) {
    const auto& p = polygons[i];
    if(p.size() != 3)
      throw Cli_error("'" + path + "': face " + std::to_string(i) + " has " +
                      std::to_string(p.size()) +
                      " vertices; only triangle meshes are accepted (triangulate it first)");
    for(std::size_t v : p) {
      if(v >= points.size())
        throw Cli_error("'" + path + "': face " + std::to_string(i) + " refers to vertex " +
                        std::to_string(v) + ", which does not exist");
    }
  }

  // The file's vertex index of every position (the smallest when the file repeats a point).
  std::map<Point_3, std::size_t> first_index;
  for(std::size_t i = 0; i < points.size(); ++i)
    first_index.emplace(points[i], i);

  // One point per position: files that repeat points along seams, or give each face its own
  // corners, become connected surfaces. Face order is kept.
  result.merged_points = PMP::merge_duplicate_points_in_polygon_soup(result.points, polygons);

  // Faces that cannot be part of a surface: a repeated corner, or the same corners as an earlier
  // face. They are left out of the mesh (and labelled like a neighbour).
  const std::size_t n = polygons.size();
  result.mesh_face.assign(n, Input_mesh::left_out);
  std::vector<std::vector<std::size_t>> kept;
  std::vector<std::size_t> kept_input;
  kept.reserve(n);
  {
    std::vector<std::array<std::size_t, 4>> corners(n); // sorted corners + input index
    for(std::size_t i = 0; i < n; ++i) {
      corners[i] = {polygons[i][0], polygons[i][1], polygons[i][2], i};
      std::sort(corners[i].begin(), corners[i].begin() + 3);
    }
    std::sort(corners.begin(), corners.end());
    std::vector<char> repeated(n, 0);
    for(std::size_t k = 1; k < n; ++k)
      if(std::equal(corners[k].begin(), corners[k].begin() + 3, corners[k - 1].begin()))
        repeated[corners[k][3]] = 1; // a later copy of the same face
    for(std::size_t i = 0; i < n; ++i) {
      const auto& p = polygons[i];
      if(p[0] == p[1] || p[1] == p[2] || p[0] == p[2] || repeated[i])
        continue;
      result.mesh_face[i] = kept.size();
      kept.push_back(p);
      kept_input.push_back(i);
    }
  }
  result.left_out_faces = n - kept.size();
  if(kept.empty())
    throw Cli_error("'" + path + "': every face is degenerate (repeats a vertex)");

  // Non-manifold or inconsistently oriented input: orient the soup (this may duplicate points and
  // flip faces, but keeps the faces and their order).
  if(!PMP::is_polygon_soup_a_polygon_mesh(kept)) {
    PMP::orient_polygon_soup(result.points, kept);
    if(!PMP::is_polygon_soup_a_polygon_mesh(kept))
      throw Cli_error("'" + path + "': the faces cannot be assembled into a surface");
  }
  PMP::polygon_soup_to_polygon_mesh(result.points, kept, result.mesh);
  if(num_faces(result.mesh) != kept.size())
    throw Cli_error("'" + path + "': some faces could not be added to the surface");

  result.triangles.resize(n);
  for(std::size_t i = 0; i < n; ++i)
    result.triangles[i] = {polygons[i][0], polygons[i][1], polygons[i][2]};
  for(std::size_t k = 0; k < kept.size(); ++k) // as oriented
    result.triangles[kept_input[k]] = {kept[k][0], kept[k][1], kept[k][2]};

  // Orienting may have duplicated points: every point's file index is found by its position.
  result.input_index.resize(result.points.size());
  for(std::size_t i = 0; i < result.points.size(); ++i)
    result.input_index[i] = first_index.at(result.points[i]);
  // The mesh's vertices: face k of the mesh is kept[k], whose three corners have distinct
  // positions, so each vertex is matched to its point by position.
  result.vertex_point.assign(num_vertices(result.mesh), Input_mesh::left_out);
  std::size_t k = 0;
  for(Mesh::Face_index f : faces(result.mesh)) {
    for(Mesh::Vertex_index v : vertices_around_face(halfedge(f, result.mesh), result.mesh))
      for(std::size_t p : kept[k])
        if(result.points[p] == result.mesh.point(v))
          result.vertex_point[v] = p;
    ++k;
  }
  return result;
}

std::vector<std::size_t> Input_mesh::input_labels(const std::vector<std::size_t>& mesh_labels) const
{
  const std::size_t n = triangles.size();
  std::vector<std::size_t> labels(n, 0);
  if(left_out_faces == 0) {
    for(std::size_t i = 0; i < n; ++i)
      labels[i] = mesh_labels[mesh_face[i]];
    return labels;
  }
  // Faces of the mesh around each point (by input point index).
  std::vector<std::vector<std::size_t>> around(points.size());
  for(std::size_t i = 0; i < n; ++i)
    if(mesh_face[i] != left_out)
      for(std::size_t v : triangles[i])
        around[v].push_back(i);
  for(std::size_t i = 0; i < n; ++i) {
    if(mesh_face[i] != left_out) {
      labels[i] = mesh_labels[mesh_face[i]];
      continue;
    }
    std::size_t best = left_out, best_shared = 0;
    for(std::size_t v : triangles[i])
      for(std::size_t j : around[v]) {
        std::size_t shared = 0;
        for(std::size_t a : triangles[i])
          for(std::size_t b : triangles[j])
            shared += (a == b) ? 1 : 0;
        if(shared > best_shared || (shared == best_shared && j < best)) {
          best_shared = shared;
          best = j;
        }
      }
    labels[i] = best == left_out ? 0 : mesh_labels[mesh_face[best]];
  }
  return labels;
}

std::vector<long long> read_labels(const std::string& path)
{
  check_input_file(path);
  std::ifstream in(path);
  std::vector<long long> labels;
  std::string line;
  std::size_t line_number = 0;
  while(std::getline(in, line)) {
    ++line_number;
    if(line.find_first_not_of(" \t\r") == std::string::npos)
      continue;
    std::istringstream fields(line);
    long long v;
    std::string rest;
    if(!(fields >> v) || (fields >> rest))
      throw Cli_error("'" + path + "': line " + std::to_string(line_number) +
                      " is not one integer label");
    labels.push_back(v);
  }
  return labels;
}

std::array<unsigned char, 3> label_colour(std::size_t label)
{
  // Hue by the golden angle, alternating brightness so neighbours in the sequence differ.
  const double hue = std::fmod(0.08 + double(label) * 0.6180339887498949, 1.0) * 6.0;
  const double s = (label % 3 == 2) ? 0.45 : 0.65;
  const double v = (label % 2 == 0) ? 0.95 : 0.78;
  const int sector = static_cast<int>(hue) % 6;
  const double f = hue - std::floor(hue);
  const double p = v * (1 - s), q = v * (1 - s * f), t = v * (1 - s * (1 - f));
  double r = v, g = t, b = p;
  switch(sector) {
  case 0: r = v; g = t; b = p; break;
  case 1: r = q; g = v; b = p; break;
  case 2: r = p; g = v; b = t; break;
  case 3: r = p; g = q; b = v; break;
  case 4: r = t; g = p; b = v; break;
  default: r = v; g = p; b = q; break;
  }
  auto byte = [](double x) { return static_cast<unsigned char>(std::lround(255 * x)); };
  return {byte(r), byte(g), byte(b)};
}

namespace {
template <typename T>
void put_binary(std::ostream& out, T value)
{
  out.write(reinterpret_cast<const char*>(&value), sizeof(T)); // little-endian hosts
}
} // namespace

void write_face_ply(std::ostream& out, const std::vector<Point_3>& points,
                    const std::vector<std::array<std::size_t, 3>>& triangles,
                    const std::function<std::array<unsigned char, 3>(std::size_t)>& colour,
                    const std::string& property, bool integer_property,
                    const std::function<double(std::size_t)>& value)
{
  out << "ply\nformat binary_little_endian 1.0\n"
      << "comment written by shape_analysis (CGAL Global Shape Analysis)\n"
      << "element vertex " << points.size() << "\n"
      << "property double x\nproperty double y\nproperty double z\n"
      << "element face " << triangles.size() << "\n"
      << "property list uchar int vertex_indices\n"
      << "property uchar red\nproperty uchar green\nproperty uchar blue\n"
      << "property " << (integer_property ? "int " : "float ") << property << "\n"
      << "end_header\n";
  for(const Point_3& p : points) {
    put_binary(out, CGAL::to_double(p.x()));
    put_binary(out, CGAL::to_double(p.y()));
    put_binary(out, CGAL::to_double(p.z()));
  }
  for(std::size_t i = 0; i < triangles.size(); ++i) {
    put_binary(out, static_cast<unsigned char>(3));
    for(std::size_t v : triangles[i])
      put_binary(out, static_cast<std::int32_t>(v));
    const auto c = colour(i);
    out.write(reinterpret_cast<const char*>(c.data()), 3);
    if(integer_property)
      put_binary(out, static_cast<std::int32_t>(value(i)));
    else
      put_binary(out, static_cast<float>(value(i)));
  }
}

void write_labelled_ply(std::ostream& out, const std::vector<Point_3>& points,
                        const std::vector<std::array<std::size_t, 3>>& triangles,
                        const std::vector<std::size_t>& labels)
{
  write_face_ply(
    out, points, triangles, [&](std::size_t f) { return label_colour(labels[f]); }, "segment", true,
    [&](std::size_t f) { return static_cast<double>(labels[f]); });
}

void write_off(std::ostream& out, const std::vector<Point_3>& points,
               const std::vector<std::array<std::size_t, 3>>& triangles)
{
  out << "OFF\n" << points.size() << ' ' << triangles.size() << " 0\n";
  out << std::setprecision(17);
  for(const Point_3& p : points)
    out << p.x() << ' ' << p.y() << ' ' << p.z() << '\n';
  for(const auto& t : triangles)
    out << "3 " << t[0] << ' ' << t[1] << ' ' << t[2] << '\n';
}

double bounding_box_diagonal(const std::vector<Point_3>& points)
{
  if(points.empty())
    return 0;
  const CGAL::Bbox_3 box = CGAL::bbox_3(points.begin(), points.end());
  const double dx = box.xmax() - box.xmin(), dy = box.ymax() - box.ymin(),
               dz = box.zmax() - box.zmin();
  return std::sqrt(dx * dx + dy * dy + dz * dz);
}

double finite_number(const std::string& cell, const std::string& where)
{
  double v = 0;
  std::size_t used = 0;
  try {
    v = std::stod(cell, &used);
  } catch(const std::exception&) {
    used = 0;
  }
  if(cell.empty() || used != cell.size() || !std::isfinite(v))
    throw Cli_error(where + "'" + cell + "' is not a finite number");
  return v;
}

const CLI::Validator positive_count(
  [](std::string& text) {
    std::size_t used = 0;
    long long n = 0;
    try {
      n = std::stoll(text, &used);
    } catch(const std::exception&) {
      used = 0;
    }
    return used == text.size() && n > 0 ? std::string() : "must be a positive whole number (got " + text + ")";
  },
  "N > 0");

const CLI::Validator positive_count_or_auto(
  [](std::string& text) {
    if(text == "auto") {
      text = "0";
      return std::string();
    }
    std::string copy = text;
    const std::string error = positive_count(copy);
    return error.empty() ? error : "must be a positive whole number or auto (got " + text + ")";
  },
  "N > 0 or auto");

std::string count_or_auto(std::size_t k)
{
  return k == 0 ? std::string("auto") : std::to_string(k);
}

std::string count_in_words(std::size_t k)
{
  return k == 0 ? std::string("an automatic number of") : std::to_string(k);
}

std::string lower_extension(const std::string& path)
{
  std::string ext = fs::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  return ext;
}

void require_extension(const std::string& path, std::initializer_list<const char*> extensions, const std::string& what)
{
  const std::string ext = lower_extension(path);
  std::string formats, names;
  bool found = false;
  for(const char* e : extensions) {
    found = found || ext == e;
    std::string format = std::string(e).substr(1);
    std::transform(format.begin(), format.end(), format.begin(), [](unsigned char c) { return char(std::toupper(c)); });
    formats += (formats.empty() ? "" : " or ") + format;
    names += std::string(names.empty() ? "'" : " or '") + e + "'";
  }
  if(!found)
    throw Usage_error("the " + what + " is written as " + formats + ": name it " + names + " (got '" + path + "')");
}

void write_labels(std::ostream& out, const std::vector<std::size_t>& labels)
{
  std::string buffer;
  buffer.reserve(labels.size() * 3);
  for(std::size_t l : labels) {
    buffer += std::to_string(l);
    buffer += '\n';
  }
  out << buffer;
}

Input_mesh read_input_mesh(const std::string& path, Progress& progress, double& read_seconds)
{
  progress.stage("reading " + path);
  Stopwatch reading;
  Input_mesh mesh = read_triangle_mesh(path);
  read_seconds = reading.seconds();
  if(mesh.merged_points > 0 || mesh.left_out_faces > 0)
    progress.stage("merged " + std::to_string(mesh.merged_points) + " duplicate points; left " +
                   std::to_string(mesh.left_out_faces) + " degenerate or repeated faces out");
  return mesh;
}

std::vector<std::size_t>
labels_per_input_face(const Input_mesh& input,
                      const Mesh::Property_map<Mesh::Face_index, std::size_t>& mesh_labels)
{
  std::vector<std::size_t> labels;
  labels.reserve(num_faces(input.mesh));
  for(auto f : faces(input.mesh))
    labels.push_back(mesh_labels[f]);
  return input.input_labels(labels);
}

void stage_segmentation(Output_files& outputs, Progress& progress, const Input_mesh& input,
                        const std::vector<std::size_t>& labels, const std::string& ply,
                        const std::string& seg)
{
  if(!ply.empty()) {
    progress.stage("writing " + ply);
    outputs.stage(ply, true, [&](std::ostream& out) {
      write_labelled_ply(out, input.points, input.triangles, labels);
    });
  }
  if(!seg.empty()) {
    progress.stage("writing " + seg);
    outputs.stage(seg, false, [&](std::ostream& out) { write_labels(out, labels); });
  }
}

void add_input_report(Json& report, const std::string& prefix, const std::string& path,
                      const Input_mesh& input)
{
  report[prefix.empty() ? std::string("input") : prefix] = path;
  const std::string p = prefix.empty() ? std::string() : prefix + "_";
  report[p + "faces"] = input.number_of_input_faces();
  report[p + "vertices"] = input.points.size();
  report[p + "merged_duplicate_points"] = input.merged_points;
  report[p + "left_out_faces"] = input.left_out_faces;
}

Json input_report(const std::string& command, const std::string& path, const Input_mesh& input)
{
  Json report = Json::object();
  report["command"] = command;
  add_input_report(report, "", path, input);
  return report;
}

void stage_report(Output_files& outputs, const std::string& path, Json report, double seconds,
                  double read_seconds, double total_seconds,
                  const std::vector<std::pair<std::string, std::string>>& named_outputs)
{
  report["seconds"] = seconds;
  report["seconds_reading"] = read_seconds;
  report["seconds_total"] = total_seconds;
  Json out = Json::object();
  for(const auto& o : named_outputs)
    out[o.first] = o.second.empty() ? Json() : Json(o.second);
  report["outputs"] = out;
  outputs.stage(path, false, [&](std::ostream& s) { s << SAS::to_text(report) << '\n'; });
}

Progress::Progress(std::string command, bool quiet, bool verbose)
  : m_command(std::move(command)), m_tty(::isatty(2) != 0)
{
  m_quiet = quiet || !(m_tty || verbose);
}

void Progress::stage(const std::string& message)
{
  if(m_quiet)
    return;
  if(m_last_percent >= 0 && m_tty)
    std::cerr << '\n';
  m_last_percent = -1;
  std::cerr << "[" << m_command << "] " << message << std::endl;
}

void Progress::fraction(double f)
{
  if(m_quiet || !m_tty)
    return;
  const int percent = static_cast<int>(100 * std::clamp(f, 0.0, 1.0));
  if(percent == m_last_percent)
    return;
  m_last_percent = percent;
  std::cerr << "\r[" << m_command << "] " << percent << "%" << std::flush;
}

void Progress::done()
{
  if(!m_quiet && m_tty && m_last_percent >= 0)
    std::cerr << '\n';
  m_last_percent = -1;
}

} // namespace shape_analysis_cli
