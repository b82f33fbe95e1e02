// Copyright (c) 2026 CGAL Global Shape Analysis contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#include "cli_common.h"

#include <CGAL/IO/polygon_soup_io.h>
#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>
#include <unistd.h>

namespace shape_analysis_cli {

namespace fs = std::filesystem;
namespace PMP = CGAL::Polygon_mesh_processing;

Mesh read_triangle_mesh(const std::string& path)
{
  std::error_code ec;
  if(!fs::exists(path, ec))
    throw Cli_error("cannot read '" + path + "': no such file");
  if(fs::is_directory(path, ec))
    throw Cli_error("cannot read '" + path + "': it is a directory");
  {
    std::ifstream probe(path, std::ios::binary);
    if(!probe)
      throw Cli_error("cannot read '" + path + "': permission denied or unreadable");
  }
  std::string ext = fs::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  if(ext != ".off" && ext != ".ply" && ext != ".obj" && ext != ".stl")
    throw Cli_error("cannot read '" + path + "': unknown mesh format '" + ext +
                    "' (use .off, .ply, .obj or .stl)");

  std::vector<Point_3> points;
  std::vector<std::vector<std::size_t>> polygons;
  bool ok = false;
  try {
    ok = CGAL::IO::read_polygon_soup(path, points, polygons, CGAL::parameters::verbose(false));
  } catch(const std::exception&) {
    ok = false;
  }
  if(!ok)
    throw Cli_error("cannot read '" + path + "': not a valid " + ext.substr(1) +
                    " mesh file (or a coordinate that is not a number)");
  if(polygons.empty())
    throw Cli_error("'" + path + "' has no faces");
  for(std::size_t i = 0; i < points.size(); ++i)
    if(!std::isfinite(points[i].x()) || !std::isfinite(points[i].y()) || !std::isfinite(points[i].z()))
      throw Cli_error("'" + path + "': vertex " + std::to_string(i) +
                      " has a coordinate that is not a finite number");
  for(std::size_t i = 0; i < polygons.size(); ++i) {
    const auto& p = polygons[i];
    if(p.size() != 3)
      throw Cli_error("'" + path + "': face " + std::to_string(i) + " has " +
                      std::to_string(p.size()) +
                      " vertices; only triangle meshes are accepted (triangulate it first)");
    for(std::size_t v : p)
      if(v >= points.size())
        throw Cli_error("'" + path + "': face " + std::to_string(i) + " refers to vertex " +
                        std::to_string(v) + ", which does not exist");
    if(p[0] == p[1] || p[1] == p[2] || p[0] == p[2])
      throw Cli_error("'" + path + "': face " + std::to_string(i) +
                      " repeats a vertex (remove degenerate faces first)");
  }
  // Non-manifold or inconsistently oriented input: orient the soup (this may duplicate vertices
  // and flip faces, but keeps the faces and their order).
  if(!PMP::is_polygon_soup_a_polygon_mesh(polygons)) {
    PMP::orient_polygon_soup(points, polygons);
    if(!PMP::is_polygon_soup_a_polygon_mesh(polygons))
      throw Cli_error("'" + path + "': the faces cannot be assembled into a surface "
                      "(duplicated faces?)");
  }
  Mesh mesh;
  PMP::polygon_soup_to_polygon_mesh(points, polygons, mesh);
  if(num_faces(mesh) != polygons.size())
    throw Cli_error("'" + path + "': some faces could not be added to the surface");
  return mesh;
}

std::vector<long long> read_labels(const std::string& path)
{
  std::ifstream in(path);
  if(!in)
    throw Cli_error("cannot read '" + path + "': no such file or unreadable");
  std::vector<long long> labels;
  std::string line;
  std::size_t line_number = 0;
  while(std::getline(in, line)) {
    ++line_number;
    std::istringstream fields(line);
    long long v;
    if(!(fields >> v)) {
      if(line.find_first_not_of(" \t\r") == std::string::npos)
        continue;
      throw Cli_error("'" + path + "': line " + std::to_string(line_number) +
                      " is not an integer label");
    }
    labels.push_back(v);
  }
  return labels;
}

Output_files::~Output_files()
{
  if(!m_committed)
    for(const auto& s : m_staged) {
      std::error_code ec;
      fs::remove(s.first, ec);
    }
}

void Output_files::check_writable(const std::string& path, const std::string& what)
{
  const fs::path p(path);
  const fs::path dir = p.has_parent_path() ? p.parent_path() : fs::path(".");
  std::error_code ec;
  if(!fs::is_directory(dir, ec))
    throw Cli_error("cannot write " + what + " '" + path + "': directory '" + dir.string() +
                    "' does not exist");
  if(fs::is_directory(p, ec))
    throw Cli_error("cannot write " + what + " '" + path + "': it is a directory");
}

void Output_files::stage(const std::string& path, bool binary,
                         const std::function<void(std::ostream&)>& writer)
{
  const std::string temporary = path + ".tmp" + std::to_string(::getpid());
  {
    std::ofstream out(temporary, binary ? std::ios::binary | std::ios::trunc : std::ios::trunc);
    if(!out)
      throw Cli_error("cannot write '" + path + "'");
    m_staged.emplace_back(temporary, path);
    writer(out);
    out.flush();
    if(!out)
      throw Cli_error("error while writing '" + path + "' (disk full?)");
  }
}

void Output_files::commit()
{
  for(const auto& s : m_staged) {
    std::error_code ec;
    fs::rename(s.first, s.second, ec);
    if(ec)
      throw Cli_error("cannot write '" + s.second + "': " + ec.message());
  }
  m_committed = true;
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

void write_labelled_ply(std::ostream& out, const Mesh& mesh, const std::vector<std::size_t>& labels)
{
  out << "ply\nformat binary_little_endian 1.0\n"
      << "comment written by shape_analysis (CGAL Global Shape Analysis)\n"
      << "element vertex " << num_vertices(mesh) << "\n"
      << "property float x\nproperty float y\nproperty float z\n"
      << "element face " << num_faces(mesh) << "\n"
      << "property list uchar int vertex_indices\n"
      << "property uchar red\nproperty uchar green\nproperty uchar blue\n"
      << "property int segment\n"
      << "end_header\n";
  std::vector<int> index(mesh.number_of_vertices() + mesh.number_of_removed_vertices(), -1);
  int next = 0;
  for(auto v : vertices(mesh)) {
    index[v] = next++;
    const Point_3& p = mesh.point(v);
    put_binary(out, static_cast<float>(p.x()));
    put_binary(out, static_cast<float>(p.y()));
    put_binary(out, static_cast<float>(p.z()));
  }
  std::size_t i = 0;
  for(auto f : faces(mesh)) {
    put_binary(out, static_cast<unsigned char>(3));
    for(auto v : CGAL::vertices_around_face(mesh.halfedge(f), mesh))
      put_binary(out, static_cast<std::int32_t>(index[v]));
    const auto c = label_colour(labels[i]);
    out.write(reinterpret_cast<const char*>(c.data()), 3);
    put_binary(out, static_cast<std::int32_t>(labels[i]));
    ++i;
  }
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
