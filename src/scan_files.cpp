// Copyright (c) 2026 CGAL Global Shape Analysis contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The scans of a run read as one, piece by piece (recognition_tiles.h, Scan_files).

#include "recognition_tiles.h"

#include <algorithm>
#include <filesystem>
#include <typeindex>

namespace shape_analysis_cli {

namespace fs = std::filesystem;

Scan_files::Scan_files(const std::vector<std::string>& inputs)
{
  std::vector<std::string> files;
  for(const std::string& input : inputs) {
    std::error_code ec;
    if(!fs::is_directory(input, ec)) {
      files.push_back(input);
      continue;
    }
    std::vector<std::string> found;
    for(const auto& entry : fs::directory_iterator(input, ec)) {
      const std::string e = lower_extension(entry.path().string());
      if(entry.is_regular_file(ec) && (e == ".las" || e == ".ply" || e == ".bin"))
        found.push_back(entry.path().string());
    }
    if(found.empty())
      throw Cli_error(input + ": a folder without .las, .ply or .bin files");
    std::sort(found.begin(), found.end());
    files.insert(files.end(), found.begin(), found.end());
  }
  std::vector<std::pair<std::string, std::type_index>> layout;
  for(const std::string& file : files) {
    try {
      m_readers.emplace_back(file);
      CGAL::Point_set_3<Point_3> one;
      m_readers.back().read(0, 1, one);
      for(const std::string& name : one.properties())
        if(name == "object" || name == "ground")
          throw Cli_error(file + " already has an 'object' or a 'ground' property");
      const auto properties = one.properties_and_types();
      if(m_readers.size() == 1)
        layout = properties;
      else if(properties != layout)
        throw Cli_error(file + " has other properties than " + files.front() + " (the scans of a run must have the same)");
    } catch(const CGAL::Shape_analysis::Bad_input& e) {
      throw Cli_error(std::string(e.what()) + " (--work-dir reads LAS, binary PLY and KITTI scans)");
    }
    m_first.push_back(m_first.back() + m_readers.back().number_of_points());
  }
}

std::vector<std::string> Scan_files::files() const
{
  std::vector<std::string> names;
  for(const PSOR::Point_set_file_reader& r : m_readers)
    names.push_back(r.filename());
  return names;
}

void Scan_files::read_coordinates(std::uint64_t first, std::size_t count, std::vector<double>& xyz) const
{
  xyz.clear();
  std::vector<double> part;
  for_each_file(first, count, [&](const PSOR::Point_set_file_reader& r, std::uint64_t from, std::size_t m) {
    r.read_coordinates(from, m, part);
    xyz.insert(xyz.end(), part.begin(), part.end());
  });
}

void Scan_files::read(std::uint64_t first, std::size_t count, CGAL::Point_set_3<Point_3>& points) const
{
  bool started = false;
  CGAL::Point_set_3<Point_3> part;
  for_each_file(first, count, [&](const PSOR::Point_set_file_reader& r, std::uint64_t from, std::size_t m) {
    if(!started)
      r.read(from, m, points);
    else {
      r.read(from, m, part);
      points.join(part);
    }
    started = true;
  });
}

bool Scan_files::read_ply_records(std::uint64_t first, std::size_t count, std::vector<unsigned char>& bytes) const
{
  for(const PSOR::Point_set_file_reader& r : m_readers)
    if(r.format() != "ply" || r.record_length() != record_length())
      return false;
  bytes.clear();
  std::vector<unsigned char> part;
  for_each_file(first, count, [&](const PSOR::Point_set_file_reader& r, std::uint64_t from, std::size_t m) {
    r.read_records(from, m, part);
    bytes.insert(bytes.end(), part.begin(), part.end());
  });
  return true;
}

std::optional<PSOR::Las_georeference> Scan_files::las_georeference() const
{
  const std::optional<PSOR::Las_georeference> first = m_readers.front().las_georeference();
  const auto same = [](const PSOR::Las_georeference& a, const PSOR::Las_georeference& b) {
    if(a.scale != b.scale || a.offset != b.offset || a.wkt != b.wkt || a.crs_records.size() != b.crs_records.size())
      return false;
    for(std::size_t r = 0; r < a.crs_records.size(); ++r)
      if(a.crs_records[r].record_id != b.crs_records[r].record_id || a.crs_records[r].data != b.crs_records[r].data)
        return false;
    return true;
  };
  for(const PSOR::Point_set_file_reader& reader : m_readers) {
    const std::optional<PSOR::Las_georeference> g = reader.las_georeference();
    if(!first || !g || !same(*first, *g))
      return std::nullopt;
  }
  return first;
}

} // namespace shape_analysis_cli
