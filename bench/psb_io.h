// Copyright (c) 2026 CGAL Global Shape Analysis contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_SHAPE_ANALYSIS_BENCH_PSB_IO_H
#define CGAL_SHAPE_ANALYSIS_BENCH_PSB_IO_H

// What the benchmark programs on the Princeton Segmentation Benchmark share: reading its meshes
// in file face order, selecting meshes on the command line, writing JSON reports.

#include "bench_util.h"
#include "psb.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/OFF.h>
#include <CGAL/IO/polygon_soup_io.h>
#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <Shape_analysis_support/Json.h>

#include <cctype>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <set>
#include <sstream>
#include <string>
#include <vector>
namespace SAS = CGAL::Shape_analysis_support;

namespace psb {

typedef CGAL::Exact_predicates_inexact_constructions_kernel Kernel;
typedef Kernel::Point_3 Point;
typedef CGAL::Surface_mesh<Point> Mesh;

// Reads an OFF file into `mesh` keeping the file's face order. A file that is not a valid
// polygon mesh as it stands is read as a polygon soup, oriented (points duplicated where needed)
// and converted, which also keeps the face order; `note` then says so.
inline bool read_mesh(const std::filesystem::path& file, Mesh& mesh, std::string& note)
{
  {
    std::ifstream in(file);
    if(in && CGAL::IO::read_OFF(in, mesh) && !faces(mesh).empty())
      return true;
  }
  mesh.clear();
  std::vector<Point> points;
  std::vector<std::vector<std::size_t>> polygons;
  if(!CGAL::IO::read_polygon_soup(file.string(), points, polygons) || polygons.empty())
    return false;
  CGAL::Polygon_mesh_processing::orient_polygon_soup(points, polygons);
  CGAL::Polygon_mesh_processing::polygon_soup_to_polygon_mesh(points, polygons, mesh);
  note = "read as a polygon soup and oriented";
  return !faces(mesh).empty();
}

using bench_util::split;

inline std::string lower(std::string s)
{
  for(char& c : s)
    c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

// "1,2,21-28" -> {1, 2, 21, ..., 28}
inline bool parse_ids(const std::string& list, std::set<int>& ids)
{
  try {
    for(const std::string& item : split(list)) {
      const std::size_t dash = item.find('-', 1);
      if(dash == std::string::npos)
        ids.insert(std::stoi(item));
      else
        for(int i = std::stoi(item.substr(0, dash)), last = std::stoi(item.substr(dash + 1));
            i <= last; ++i)
          ids.insert(i);
    }
  } catch(...) {
    return false;
  }
  return true;
}

// The meshes of the subset in `dir` of the given classes (lower case) and ids (all when empty).
inline std::vector<Mesh_entry> select_meshes(const std::filesystem::path& dir,
                                             const std::set<std::string>& classes,
                                             const std::set<int>& ids)
{
  std::vector<Mesh_entry> all = list_meshes(dir), selected;
  for(auto& m : all)
    if((classes.empty() || classes.count(lower(m.mesh_class))) && (ids.empty() || ids.count(m.id)))
      selected.push_back(std::move(m));
  return selected;
}

// Writes `report` to `file` (through a temporary file, so that a reader never sees half of it).
inline void write_output(const std::string& file, const SAS::Json& report)
{
  namespace fs = std::filesystem;
  if(file.empty())
    return;
  std::error_code ec;
  if(fs::exists(file, ec) && !fs::is_regular_file(file, ec)) {
    // A device or a pipe (--output /dev/null): written in place, never replaced by a file.
    std::ofstream out(file);
    out << SAS::to_text(report) << '\n';
    if(!out)
      std::cerr << "cannot write " << file << '\n';
    return;
  }
  const std::string tmp = file + ".tmp";
  {
    std::ofstream out(tmp);
    out << SAS::to_text(report) << '\n';
    if(!out) {
      std::cerr << "cannot write " << tmp << '\n';
      return;
    }
  }
  fs::rename(tmp, file, ec);
  if(ec)
    std::cerr << "cannot rename " << tmp << " to " << file << ": " << ec.message() << '\n';
}

} // namespace psb

#endif // CGAL_SHAPE_ANALYSIS_BENCH_PSB_IO_H
