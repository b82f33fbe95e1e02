// Copyright (c) 2026 CGAL Global Shape Analysis contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The segmented points of a scan read piece by piece, written piece by piece by the ranks of a
// run (recognition_tiles.h, stage_objects_file_in_pieces()).

#include "recognition_tiles.h"

#include <CGAL/Point_set_3/IO/PLY.h>
#include <CGAL/Point_set_object_recognition/write_point_set.h>

#include <fcntl.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <memory>
#include <mutex>
#include <numeric>
#include <sstream>

namespace shape_analysis_cli {

namespace fs = std::filesystem;

namespace {

// The points first to first + count - 1 of the scan (unless only their values are asked for) with
// this rank's objects, kinds and labels for those in its part (-1, 0, -1 for the others).
struct Piece
{
  CGAL::Point_set_3<Point_3> points;
  std::vector<int> object, label;
  std::vector<char> ground;
};

Piece read_piece(const Scan_files& reader, const Recognition_in_tiles& m, const std::vector<int>& label,
                 std::uint64_t first, std::size_t count, bool values_only = false)
{
  Piece p;
  if(!values_only)
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
        p.label[k] = m.object[i] >= 0 ? label[std::size_t(m.object[i])] : -1;
    }
  return p;
}

// Keeps the points of `p` that are in an object (and their records, `record` bytes each, when
// `records` is not null), in order.
void keep_object_points(Piece& p, std::vector<unsigned char>* records, std::size_t record)
{
  Piece kept;
  const bool points = !p.points.empty();
  if(points)
    kept.points.copy_properties(p.points);
  std::size_t k = 0, w = 0;
  for(auto i = p.points.begin(); k < p.object.size(); ++k) {
    if(p.object[k] >= 0) {
      if(points)
        kept.points.insert(p.points, *i);
      kept.object.push_back(p.object[k]);
      kept.ground.push_back(p.ground[k]);
      if(!p.label.empty())
        kept.label.push_back(p.label[k]);
      if(records)
        std::copy_n(records->begin() + std::ptrdiff_t(k * record), record, records->begin() + std::ptrdiff_t(w++ * record));
    }
    if(points)
      ++i;
  }
  if(records)
    records->resize(w * record);
  p = std::move(kept);
}

// Reserves the disk blocks of the file `path` up to `size` bytes (its size then), so that writing
// into a mapping of it cannot run out of space; false where the file system cannot (nothing done).
bool reserve(const std::string& path, std::uint64_t size)
{
  const int fd = ::open(path.c_str(), O_RDWR | O_CLOEXEC);
  if(fd < 0)
    return false;
  struct stat st;
  int error = ::fstat(fd, &st) == 0 && S_ISREG(st.st_mode) ? 0 : EOPNOTSUPP;
  if(error == 0)
    while((error = ::fallocate(fd, 0, 0, off_t(size)) == 0 ? 0 : errno) == EINTR) {
    }
  ::close(fd);
  if(error == ENOSPC || error == EFBIG || error == EDQUOT)
    throw Cli_error("cannot write '" + path + "': no room for " + std::to_string(size) + " bytes on its disk");
  return error == 0;
}

// Writes `bytes` at `offset` of the file `path`: through a mapping of the file when its blocks are
// reserved up to there (reserve(); threads and ranks then write side by side without the file's
// write lock: 15.9 s instead of 16.9 s for the 4.1 GB of a 10^8-point output here), else with
// pwrite().
void write_at(const std::string& path, std::uint64_t offset, const char* bytes, std::size_t size)
{
  const int fd = ::open(path.c_str(), O_RDWR | O_CLOEXEC);
  if(fd < 0)
    throw Cli_error("cannot open '" + path + "' to write it: " + std::strerror(errno));
  struct stat st;
  bool done = false;
  if(size > 0 && ::fstat(fd, &st) == 0 && S_ISREG(st.st_mode) && std::uint64_t(st.st_size) >= offset + size) {
    const std::uint64_t page = std::uint64_t(::sysconf(_SC_PAGESIZE)), start = offset / page * page;
    void* map = ::mmap(nullptr, std::size_t(offset + size - start), PROT_READ | PROT_WRITE, MAP_SHARED, fd, off_t(start));
    if(map != MAP_FAILED) {
      std::memcpy(static_cast<char*>(map) + (offset - start), bytes, size);
      done = ::munmap(map, std::size_t(offset + size - start)) == 0;
    }
  }
  for(std::size_t written = 0; !done && written < size;) {
    const ssize_t w = ::pwrite(fd, bytes + written, size - written, off_t(offset + written));
    if(w < 0 && errno == EINTR)
      continue;
    if(w <= 0) {
      ::close(fd);
      throw Cli_error("error while writing '" + path + "' (disk full?)");
    }
    written += std::size_t(w);
  }
  ::close(fd);
}

// The vertex properties ("type name") of the PLY header `text`.
std::vector<std::string> vertex_properties(const std::string& text)
{
  std::vector<std::string> properties;
  std::istringstream in(text);
  std::string line;
  bool vertex = false;
  while(std::getline(in, line) && line.rfind("end_header", 0) != 0) {
    if(line.rfind("element ", 0) == 0)
      vertex = line.rfind("element vertex ", 0) == 0;
    else if(vertex && line.rfind("property ", 0) == 0)
      properties.push_back(line.substr(9));
  }
  return properties;
}

// The PLY records of the output made from the scan's own records: each followed by the values of
// `suffix` (the output's properties after the scan's: object, ground, label, colours).
class Ply_records_from_scan
{
public:
  // Whether the output (its header `output`) extends the scan's records (`scan`: the scan's header).
  bool prepare(const std::string& scan, const std::string& output)
  {
    const std::vector<std::string> in = vertex_properties(scan), out = vertex_properties(output);
    if(in.empty() || out.size() <= in.size() || !std::equal(in.begin(), in.end(), out.begin()))
      return false;
    m_suffix.assign(out.begin() + std::ptrdiff_t(in.size()), out.end());
    for(const std::string& p : m_suffix)
      if(p != "int object" && p != "uchar ground" && p != "int label" && p != "uchar red" && p != "uchar green" &&
         p != "uchar blue")
        return false;
    return true;
  }
  // The output's records of the scan's `records` (`record` bytes each) and the piece's values.
  std::string records(const std::vector<unsigned char>& records, std::size_t record, const Piece& p) const
  {
    enum { OBJECT, GROUND, LABEL, RED, GREEN, BLUE };
    std::vector<int> codes;
    for(const std::string& s : m_suffix)
      codes.push_back(s == "int object" ? OBJECT : s == "uchar ground" ? GROUND : s == "int label" ? LABEL
                      : s == "uchar red" ? RED : s == "uchar green" ? GREEN : BLUE);
    std::vector<std::array<unsigned char, 3>> colours; // per object (or class) + 1, as objects_point_set() gives them
    const auto colour = [&](int by) -> const std::array<unsigned char, 3>& {
      if(std::size_t(by + 1) >= colours.size()) {
        const std::size_t from = colours.size();
        colours.resize(std::size_t(by + 2));
        for(std::size_t c = from; c < colours.size(); ++c)
          colours[c] = c == 0 ? std::array<unsigned char, 3>{{160, 160, 160}} : label_colour(c);
      }
      return colours[std::size_t(by + 1)];
    };
    std::string bytes;
    const std::size_t count = p.object.size();
    bytes.reserve(count * (record + 4 * codes.size()));
    for(std::size_t k = 0; k < count; ++k) {
      bytes.append(reinterpret_cast<const char*>(records.data() + k * record), record);
      const int by = p.label.empty() ? p.object[k] : p.label[k];
      for(int code : codes) {
        if(code == OBJECT || code == LABEL) {
          const std::int32_t v = code == OBJECT ? p.object[k] : p.label[k];
          bytes.append(reinterpret_cast<const char*>(&v), 4);
        } else if(code == GROUND)
          bytes.push_back(char(p.ground[k] ? 1 : 0));
        else
          bytes.push_back(char(colour(by < 0 ? -1 : by)[std::size_t(code - RED)]));
      }
    }
    return bytes;
  }

private:
  std::vector<std::string> m_suffix;
};

// The first `end` bytes of the file `path`, up to its PLY header's end.
std::string ply_header_of(const std::string& path)
{
  std::ifstream in(path, std::ios::binary);
  std::string text, line;
  while(std::getline(in, line)) {
    text += line + "\n";
    if(line.rfind("end_header", 0) == 0)
      break;
  }
  return text;
}

} // namespace

void stage_objects_file_in_pieces(Output_files& outputs, const std::string& path,
                                  const Scan_files& reader, const Recognition_in_tiles& m,
                                  const std::string& command, const std::vector<int>& label,
                                  const std::string& comment, const std::vector<std::string>& class_names,
                                  std::size_t threads, bool only_objects, std::size_t piece)
{
  const Ranks& ranks = Ranks::world();
  const std::uint64_t last = m.first + m.object.size();
  const bool las = lower_extension(path) == ".las";
  // The parts of the rank's points its threads write; where each part's records start in the
  // output: all the points before it, or with `only_objects` those in an object (every rank's).
  const std::size_t parts = std::max<std::size_t>(1, threads);
  const auto part_first = [&](std::size_t j) { return m.first + (last - m.first) * j / parts; };
  std::vector<std::uint64_t> out_first(parts + 1, 0);
  std::uint64_t n = reader.number_of_points();
  if(only_objects) {
    for(std::size_t j = 0; j < parts; ++j)
      out_first[j + 1] = out_first[j] + std::uint64_t(std::count_if(m.object.begin() + std::ptrdiff_t(part_first(j) - m.first),
                                                                    m.object.begin() + std::ptrdiff_t(part_first(j + 1) - m.first),
                                                                    [](int o) { return o >= 0; }));
    std::vector<std::uint64_t> by_rank(std::size_t(ranks.size()), 0);
    by_rank[std::size_t(ranks.rank())] = out_first[parts];
    ranks.sum(by_rank);
    const std::uint64_t before = std::accumulate(by_rank.begin(), by_rank.begin() + ranks.rank(), std::uint64_t(0));
    for(std::uint64_t& f : out_first)
      f += before;
    n = std::accumulate(by_rank.begin(), by_rank.end(), std::uint64_t(0));
  } else {
    for(std::size_t j = 0; j <= parts; ++j)
      out_first[j] = part_first(j);
  }
  // The bytes of a piece as a PLY file of its own (header and records).
  const auto ply_bytes = [&](const Piece& p) {
    std::ostringstream bytes;
    write_objects_file(bytes, false, reader.filename(), p.points, p.object, p.ground, command, p.label, comment, class_names);
    return bytes.str();
  };
  // The header (for LAS, zeros of its size until the end, when the box and counts are known) and
  // the records' size, from the first point; rank 0 stages the file with it.
  std::string header, temporary;
  std::size_t record = 0;
  std::unique_ptr<PSOR::Las_point_set_pieces<Point_3>> las_pieces;
  std::vector<std::pair<unsigned, std::string>> names;
  together(ranks, [&]() {
    const Piece one = read_piece(reader, m, label, 0, 1);
    if(las) {
      // The layout first: it names the classes (`names`) that the header's lookup record lists.
      const CGAL::Point_set_3<Point_3> layout =
        objects_las_points(reader.filename(), one.points, one.object, one.ground, one.label, class_names, names);
      las_pieces = std::make_unique<PSOR::Las_point_set_pieces<Point_3>>(
        layout, m.lowest, PSOR::parameters::class_names(names).las_georeference(reader.las_georeference()));
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
        {
          std::ofstream out(file, std::ios::binary | std::ios::trunc);
          if(!out.write(header.data(), std::streamsize(header.size())) || !out.flush())
            throw Cli_error("cannot write '" + path + "'");
        }
        reserve(file, header.size() + n * record);
      });
  });
  temporary = ranks.broadcast(temporary);
  // Each rank its own records, in place, with its threads, each a part of the rank's points. A PLY
  // output of a PLY scan that it extends is made from the scan's records once the first piece
  // shows it is the same.
  PSOR::Las_point_set_pieces<Point_3>::Summary summary;
  Ply_records_from_scan fast;
  bool from_scan = false;
  together(ranks, [&]() {
    if(las || m.object.empty())
      return;
    std::vector<unsigned char> records;
    const std::size_t count = std::size_t(std::min<std::uint64_t>(piece, last - m.first));
    const Piece p = read_piece(reader, m, label, m.first, count);
    const std::string slow = ply_bytes(p);
    from_scan = fast.prepare(ply_header_of(reader.filename()), slow) && reader.read_ply_records(m.first, count, records) &&
                fast.records(records, reader.record_length(), p) == slow.substr(slow.find("end_header\n") + 11);
  });
  together(ranks, [&]() {
    std::mutex mutex;
    std::vector<std::string> errors(parts);
    const auto write_part = [&](std::size_t j) {
      std::uint64_t at = out_first[j]; // the output's record of the piece's first point written
      for(std::uint64_t first = part_first(j); first < part_first(j + 1); first += piece) {
        const std::size_t count = std::size_t(std::min<std::uint64_t>(piece, part_first(j + 1) - first));
        const auto values = m.object.begin() + std::ptrdiff_t(first - m.first);
        if(only_objects && std::none_of(values, values + std::ptrdiff_t(count), [](int o) { return o >= 0; }))
          continue; // nothing of the piece is written: not read
        Piece p = read_piece(reader, m, label, first, count, from_scan);
        std::vector<unsigned char> records;
        if(from_scan)
          reader.read_ply_records(first, count, records);
        if(only_objects)
          keep_object_points(p, from_scan ? &records : nullptr, reader.record_length());
        const std::uint64_t written = p.object.size();
        if(written == 0)
          continue;
        if(las) {
          std::vector<unsigned char> bytes;
          PSOR::Las_point_set_pieces<Point_3>::Summary s;
          try {
            s = las_pieces->records(
              objects_las_points(reader.filename(), p.points, p.object, p.ground, p.label, class_names, names), bytes);
          } catch(const CGAL::Shape_analysis::Bad_input& e) {
            throw Cli_error(e.what());
          }
          write_at(temporary, header.size() + at * record, reinterpret_cast<const char*>(bytes.data()), bytes.size());
          std::lock_guard<std::mutex> lock(mutex);
          summary.merge(s);
        } else if(from_scan) {
          const std::string bytes = fast.records(records, reader.record_length(), p);
          write_at(temporary, header.size() + at * record, bytes.data(), bytes.size());
        } else {
          const std::string bytes = ply_bytes(p);
          const std::size_t end = bytes.find("end_header\n") + 11;
          if(bytes.size() - end != written * record)
            throw Cli_error("cannot write '" + path + "': records of different sizes");
          write_at(temporary, header.size() + at * record, bytes.data() + end, bytes.size() - end);
        }
        at += written;
      }
    };
    run_parts(parts, [&](std::size_t j) {
      try {
        write_part(j);
      } catch(const std::exception& e) {
        errors[j] = e.what();
      }
    });
    for(const std::string& e : errors)
      if(!e.empty())
        throw Cli_error(e);
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
