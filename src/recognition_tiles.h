// Copyright (c) 2026 CGAL Global Shape Analysis contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef SHAPE_ANALYSIS_RECOGNITION_TILES_H
#define SHAPE_ANALYSIS_RECOGNITION_TILES_H

// `points recognize --work-dir`: the recognition of a scan larger than memory. The scan is read
// piece by piece (PSOR::Point_set_file_reader); a first pass finds its box, a second counts the
// points of the tiles (PSOR::Tile_plan) and writes each tile's points (its own and its margin's)
// to the work folder; the tiles are then recognized a few at a time (PSOR::recognize_tile), each
// result written to the work folder, and merged in the order of the tiles as
// recognize_objects() merges them. Memory: the tiles in flight and 4 bytes and a bit per point
// (the object and kind of every point, for the output), 24 per point of an object. A run that stops (killed, or a tile that
// fails) leaves the finished tiles in the work folder; the next run with the same input and
// options goes on from them.

#include "points_common.h"
#include "ranks.h"

#include <CGAL/Point_set_object_recognition/Point_set_file_reader.h>
#include <CGAL/Point_set_object_recognition/recognize_objects.h>

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>
#endif

#include <algorithm>
#include <array>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace shape_analysis_cli {

// The scans of a run read as one, piece by piece (PSOR::Point_set_file_reader): their points one
// after the other, the files in the order given, a folder's LAS, PLY and KITTI files (.las, .ply,
// .bin) in the order of their names. They must have the same properties.
class Scan_files
{
public:
  // Opens them; Cli_error for a file that cannot be read in pieces, an empty folder, or files
  // with other properties than the first's.
  explicit Scan_files(const std::vector<std::string>& inputs);
  std::uint64_t number_of_points() const { return m_first.back(); }
  const std::string& filename() const { return m_readers.front().filename(); } // the first one
  const std::string& format() const { return m_readers.front().format(); }
  std::vector<std::string> files() const;
  // As PSOR::Point_set_file_reader's, over the files one after the other.
  void read_coordinates(std::uint64_t first, std::size_t count, std::vector<double>& xyz) const;
  void read(std::uint64_t first, std::size_t count, CGAL::Point_set_3<Point_3>& points) const;
  // The records as stored, when every file is a PLY file with the same vertex records (else false).
  bool read_ply_records(std::uint64_t first, std::size_t count, std::vector<unsigned char>& bytes) const;
  std::size_t record_length() const { return m_readers.front().record_length(); }
  // The scale, offset and CRS records of the scans when they are LAS files that share them (else
  // none): the LAS output keeps them.
  std::optional<PSOR::Las_georeference> las_georeference() const;

private:
  // Calls f(reader, its first point, count) for the parts of the points [first, first + count)
  // in each file, in order.
  template <typename F>
  void for_each_file(std::uint64_t first, std::size_t count, const F& f) const
  {
    for(std::size_t k = 0; k < m_readers.size() && count > 0; ++k) {
      if(first >= m_first[k + 1])
        continue;
      const std::size_t m = std::size_t(std::min<std::uint64_t>(count, m_first[k + 1] - first));
      f(m_readers[k], first - m_first[k], m);
      first += m, count -= m;
    }
  }

  std::vector<PSOR::Point_set_file_reader> m_readers;
  std::vector<std::uint64_t> m_first{0}; // the index of each file's first point, then the total
};

// Runs `f` (no collective call inside) on every rank, then throws on every rank the error of the
// lowest rank that failed, if any.
template <typename F>
void together(const Ranks& ranks, const F& f)
{
  std::string error;
  try {
    f();
  } catch(const std::exception& e) {
    error = e.what();
  }
  error = ranks.first_error(error);
  if(!error.empty())
    throw Cli_error(error);
}

// Runs body(j) for j in [0, parts), each on a thread of its own (one after the other without TBB).
template <typename Body>
void run_parts(std::size_t parts, const Body& body)
{
#ifdef CGAL_LINKED_WITH_TBB
  if(parts > 1) {
    tbb::task_arena arena{int(parts)};
    arena.execute([&]() { tbb::parallel_for(std::size_t(0), parts, std::size_t(1), [&](std::size_t j) { body(j); }); });
    return;
  }
#endif
  for(std::size_t j = 0; j < parts; ++j)
    body(j);
}

// Recognizes one tile from the points it holds (PSOR::recognize_tile() with the run's options).
typedef std::function<PSOR::Tile_recognition(const PSOR::Tile_plan&, std::size_t, const std::vector<Point_3>&)>
  Tile_recognizer;

// What the run found: the recognition without its per-point vectors, and per point of this
// rank's part of the scan (the points `first` to `first + object.size() - 1`) its object (the
// row of its location, -1 for none) and whether it is ground.
struct Recognition_in_tiles
{
  PSOR::Object_recognition_result result; // object_of_point and kind left empty; objects' points: this rank's
  std::vector<std::uint64_t> object_points; // per object, its points that are not ground (all ranks')
  std::array<double, 3> lowest{{0, 0, 0}}, highest{{0, 0, 0}}; // the scan's box
  std::uint64_t first = 0;
  std::vector<int> object;
  std::vector<bool> ground; // a bit per point
  std::size_t tiles_reused = 0; // tiles found finished in the work folder
  std::vector<std::pair<std::size_t, std::string>> failed_tiles; // with keep_going: the tiles left out, their errors
  double seconds_indexing = 0;  // the passes over the scan
  double seconds_tiles = 0;     // recognizing the tiles (reading their points, writing their results)
  double seconds_merging = 0;   // reading every tile's result, this rank's part of the points
};

// An exclusive lock of a work folder (flock of its file `lock`), held until destroyed; a run that
// finds it taken fails at once (work_folder_lock.cpp).
class Folder_lock
{
public:
  Folder_lock() = default;
  Folder_lock(const Folder_lock&) = delete;
  Folder_lock& operator=(const Folder_lock&) = delete;
  ~Folder_lock();
  // Takes the lock of `file`, the lock file of the work folder `folder` (named in the errors).
  void take(const std::string& file, const std::string& folder);

private:
  int m_fd = -1;
};

// The recognition of the scan of `reader` in tiles of `options` (its tile_size, tile_margin,
// tile_origin and number_of_threads), the work in `work_dir` (created if needed), by the run's
// ranks (collective; with several, the work folder must be one they all see). `identity`
// names what else decides a tile's result (methods, model): finished tiles are reused only
// when it and the scan are the same. Throws Cli_error on a scan it cannot read or a folder it
// cannot write, and on a tile that fails unless `keep_going` (the tile is then left out: its own
// points neither ground nor in an object; listed in `failed_tiles`).
Recognition_in_tiles recognize_in_tiles(const Scan_files& reader, const std::string& work_dir,
                                        const PSOR::Recognize_objects_options& options, const std::string& identity,
                                        bool keep_going, const Tile_recognizer& recognize, Progress& progress);

// Stages the segmented points of a scan read piece by piece as PLY or LAS (stage_objects_file()'s
// content, the same bytes), pieces of `piece` points, each rank writing the records of its part of
// the scan (`m.first`, `m.object`, `m.ground`; `label`: the class of each object, or empty) into
// the file that rank 0
// stages in `outputs`, with `threads` threads (collective). A PLY output of a binary PLY scan
// whose records it extends is written from the scan's records (checked on the first piece). With
// `only_objects`, only the points in an object are written, in order.
void stage_objects_file_in_pieces(Output_files& outputs, const std::string& path,
                                  const Scan_files& reader, const Recognition_in_tiles& m,
                                  const std::string& command,
                                  const std::vector<int>& label, const std::string& comment,
                                  const std::vector<std::string>& class_names, std::size_t threads,
                                  bool only_objects = false, std::size_t piece = std::size_t(1) << 18);

} // namespace shape_analysis_cli

#endif // SHAPE_ANALYSIS_RECOGNITION_TILES_H
