// Copyright (c) 2026 CGAL Global Shape Analysis contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The segmented points of a scan read piece by piece, written piece by piece by the ranks of a
// run (recognition_tiles.h, stage_objects_file_in_pieces()).

#include "recognition_tiles.h"

#include <CGAL/Point_set_3/IO/PLY.h>
#include <CGAL/Point_set_object_recognition/write_point_set.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <memory>
#include <sstream>

namespace shape_analysis_cli {

namespace fs = std::filesystem;

namespace {

// The points first to first + count - 1 of the scan with this rank's objects, kinds and labels
// for those in its part (-1, 0, -1 for the others).
struct Piece
{
  CGAL::Point_set_3<Point_3> points;
  std::vector<int> object, label;
  std::vector<char> ground;
};

Piece read_piece(const Scan_files& reader, const Recognition_in_tiles& m, const std::vector<int>& label,
                 std::uint64_t first, std::size_t count)
{
  Piece p;
  reader.read(first, count, p.points);
  p.object.assign(count, -1);
  p.ground.assign(count, 0);
  if(!label.empty())
    p.label.assign(count, -1);
  for(std::size_t k = 0; k < count; ++k)
    if(first + k >= m.first && first + k - m.first < m.object.size()) {
      const std::size_t i = std::size_t(first + k - m.first);
      p.object[k] = m.object[i], p.ground[k] = m.ground[i];
      if(!label.empty())
        p.label[k] = label[i];
    }
  return p;
}

// Writes `bytes` at `offset` of the file `path`.
void write_at(const std::string& path, std::uint64_t offset, const char* bytes, std::size_t size)
{
  std::fstream out(path, std::ios::binary | std::ios::in | std::ios::out);
  out.seekp(std::streamoff(offset));
  if(!out.write(bytes, std::streamsize(size)) || !out.flush())
    throw Cli_error("error while writing '" + path + "' (disk full?)");
}

} // namespace

void stage_objects_file_in_pieces(Output_files& outputs, const std::string& path,
                                  const Scan_files& reader, const Recognition_in_tiles& m,
                                  const std::string& command, const std::vector<int>& label,
                                  const std::string& comment, const std::vector<std::string>& class_names,
                                  std::size_t piece)
{
  const Ranks& ranks = Ranks::world();
  const std::uint64_t n = reader.number_of_points(), last = m.first + m.object.size();
  const bool las = lower_extension(path) == ".las";
  // The bytes of a piece as a PLY file of its own (header and records).
  const auto ply_bytes = [&](const Piece& p) {
    std::ostringstream bytes;
    write_objects_file(bytes, false, reader.filename(), p.points, p.object, p.ground, command, p.label, comment, class_names);
    return bytes.str();
  };
  // The header (a placeholder of its size for LAS, written at the end) and the records' size, from
  // the first point; rank 0 stages the file with it.
  std::string header, temporary;
  std::size_t record = 0;
  std::unique_ptr<PSOR::Las_point_set_pieces<Point_3>> las_pieces;
  std::vector<std::pair<unsigned, std::string>> names;
  together(ranks, [&]() {
    const Piece one = read_piece(reader, m, label, 0, 1);
    if(las) {
      las_pieces = std::make_unique<PSOR::Las_point_set_pieces<Point_3>>(
        objects_las_points(reader.filename(), one.points, one.object, one.ground, one.label, class_names, names),
        m.lowest, PSOR::parameters::class_names(names));
      header.assign(las_pieces->header({}).size(), '\0');
      record = las_pieces->record_length();
    } else {
      const std::string bytes = ply_bytes(one);
      const std::size_t end = bytes.find("end_header\n"), count = bytes.find("element vertex 1\n");
      if(end == std::string::npos || count == std::string::npos || count > end)
        throw Cli_error("cannot write " + path);
      header = bytes.substr(0, count) + "element vertex " + std::to_string(n) + "\n" +
               bytes.substr(count + 17, end + 11 - count - 17);
      record = bytes.size() - end - 11;
    }
    if(ranks.rank() == 0)
      outputs.stage_file(path, [&](const std::string& file) {
        temporary = file;
        std::ofstream out(file, std::ios::binary | std::ios::trunc);
        if(!out.write(header.data(), std::streamsize(header.size())) || !out.flush())
          throw Cli_error("cannot write '" + path + "'");
      });
  });
  temporary = ranks.broadcast(temporary);
  // Each rank its own records, in place.
  PSOR::Las_point_set_pieces<Point_3>::Summary summary;
  together(ranks, [&]() {
    for(std::uint64_t first = m.first; first < last; first += piece) {
      const std::size_t count = std::size_t(std::min<std::uint64_t>(piece, last - first));
      const Piece p = read_piece(reader, m, label, first, count);
      if(las) {
        std::vector<unsigned char> bytes;
        try {
          summary.merge(las_pieces->records(
            objects_las_points(reader.filename(), p.points, p.object, p.ground, p.label, class_names, names), bytes));
        } catch(const CGAL::Shape_analysis::Bad_input& e) {
          throw Cli_error(e.what());
        }
        write_at(temporary, header.size() + first * record, reinterpret_cast<const char*>(bytes.data()), bytes.size());
      } else {
        const std::string bytes = ply_bytes(p);
        const std::size_t end = bytes.find("end_header\n") + 11;
        if(bytes.size() - end != count * record)
          throw Cli_error("cannot write '" + path + "': records of different sizes");
        write_at(temporary, header.size() + first * record, bytes.data() + end, bytes.size() - end);
      }
    }
  });
  if(!las)
    return;
  // The LAS header: the counts of every rank, the box of every rank's records.
  std::vector<std::uint64_t> counts(summary.by_return.begin(), summary.by_return.end());
  counts.push_back(summary.number_of_points);
  ranks.sum(counts);
  std::vector<double> lo(summary.min.begin(), summary.min.end()), hi(summary.max.begin(), summary.max.end());
  if(summary.number_of_points == 0)
    lo.assign(3, 1e300), hi.assign(3, -1e300);
  ranks.min_max(lo, hi);
  together(ranks, [&]() {
    if(ranks.rank() != 0)
      return;
    PSOR::Las_point_set_pieces<Point_3>::Summary all;
    std::copy(counts.begin(), counts.begin() + 15, all.by_return.begin());
    all.number_of_points = counts[15];
    std::copy(lo.begin(), lo.end(), all.min.begin());
    std::copy(hi.begin(), hi.end(), all.max.begin());
    const std::vector<unsigned char> bytes = las_pieces->header(all);
    write_at(temporary, 0, reinterpret_cast<const char*>(bytes.data()), bytes.size());
  });
}

} // namespace shape_analysis_cli
