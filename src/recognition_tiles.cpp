// Copyright (c) 2026 CGAL Global Shape Analysis contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// `points recognize --work-dir`: the recognition of a scan larger than memory (recognition_tiles.h).
//
// The work folder holds `plan` (what was planned: the scan, the options, the tiles' counts;
// written once every tile's points are in `points/`), `points/<tile>` (the points a tile holds:
// index, x, y, z as 64-bit numbers, in the scan's order) and `tiles/<tile>` (a finished tile's
// result). Files are written under a temporary name and renamed, so a file present is whole.

#include "recognition_tiles.h"
#include "ranks.h"

#include <CGAL/Point_set_3/IO/PLY.h>
#include <CGAL/Shape_analysis/available_processors.h>
#include <CGAL/Point_set_object_recognition/write_point_set.h>

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>
#endif

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <mutex>
#include <typeindex>
#include <sstream>
#include <limits>
#include <unordered_map>

namespace shape_analysis_cli {

namespace {

namespace fs = std::filesystem;
const char* const plan_magic = "shape_analysis tile plan 1";
const char tile_magic[8] = {'S', 'A', 'T', 'I', 'L', 'E', '1', 0};

// Native binary records of the work folder (read back by the same program on the same machine).
struct Record_writer
{
  std::string bytes;
  template <typename T> void put(const T& v) { bytes.append(reinterpret_cast<const char*>(&v), sizeof(T)); }
};

struct Record_reader
{
  const std::string& bytes;
  std::size_t at = 0;
  template <typename T> T get()
  {
    T v;
    if(at + sizeof(T) > bytes.size())
      throw Cli_error("a tile file of the work folder is truncated (remove the folder and run again)");
    std::memcpy(&v, bytes.data() + at, sizeof(T));
    at += sizeof(T);
    return v;
  }
};

std::string read_file(const fs::path& path)
{
  std::ifstream in(path, std::ios::binary);
  if(!in)
    throw Cli_error("cannot read " + path.string());
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

// Writes `bytes` to `path` through a temporary file renamed into place.
void write_whole_file(const fs::path& path, const std::string& bytes)
{
  const fs::path temporary = path.string() + ".part";
  {
    std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
    if(!out.write(bytes.data(), std::streamsize(bytes.size())) || !out.flush())
      throw Cli_error("cannot write " + temporary.string() + " (disk full?)");
  }
  std::error_code ec;
  fs::rename(temporary, path, ec);
  if(ec)
    throw Cli_error("cannot rename " + temporary.string() + ": " + ec.message());
}

// What decides the plan and the tiles' results: the scans (paths, sizes, times), the options.
std::string plan_key(const Scan_files& reader, const PSOR::Recognize_objects_options& o, const std::string& identity)
{
  std::ostringstream k;
  k.precision(17);
  k << plan_magic << "\nscans " << reader.number_of_points();
  for(const std::string& file : reader.files()) {
    const fs::path scan = fs::absolute(file);
    k << "\nscan " << scan.string() << ' ' << fs::file_size(scan) << ' ' << fs::last_write_time(scan).time_since_epoch().count();
  }
  k << "\ntiles " << o.tile_size << ' ' << o.tile_margin;
  if(o.tile_origin)
    k << ' ' << (*o.tile_origin)[0] << ' ' << (*o.tile_origin)[1];
  k << "\nrecognition " << identity << '\n';
  return k.str();
}

// Calls f(first, xyz) for the pieces of the points [begin, end) of the scan, in order.
template <typename F>
void for_each_piece(const Scan_files& reader, std::uint64_t begin, std::uint64_t end, const F& f)
{
  const std::size_t piece = std::size_t(1) << 20;
  std::vector<double> xyz;
  for(std::uint64_t first = begin; first < end; first += piece) {
    reader.read_coordinates(first, std::size_t(std::min<std::uint64_t>(piece, end - first)), xyz);
    f(first, xyz);
  }
}

// The records of part `part` waiting to be appended to the tiles' point files (flushed to
// `points/<tile>.<part>` when they pass a budget).
class Tile_records
{
public:
  Tile_records(const fs::path& dir, std::size_t part) : m_dir(dir), m_part("." + std::to_string(part)) {}
  void add(std::size_t t, std::uint64_t index, const double* xyz)
  {
    if(t != m_last_tile || !m_last) // consecutive points mostly fall in the same tile
      m_last = &m_waiting[t], m_last_tile = t;
    m_last->append(reinterpret_cast<const char*>(&index), 8);
    m_last->append(reinterpret_cast<const char*>(xyz), 24);
    if((m_bytes += 32) > (std::size_t(32) << 20))
      flush();
  }
  void flush()
  {
    for(auto& w : m_waiting) {
      const fs::path file = m_dir / "points" / (std::to_string(w.first) + m_part);
      std::ofstream out(file, std::ios::binary | std::ios::app);
      if(!out.write(w.second.data(), std::streamsize(w.second.size())) || !out.flush())
        throw Cli_error("cannot write " + file.string() + " (disk full?)");
    }
    m_waiting.clear();
    m_last = nullptr;
    m_bytes = 0;
  }

private:
  fs::path m_dir;
  std::string m_part;
  std::unordered_map<std::size_t, std::string> m_waiting;
  std::string* m_last = nullptr;
  std::size_t m_last_tile = 0, m_bytes = 0;
};

// The plan of the scan and each tile's points in `points/<tile>.<part>`, from two passes over the
// scan: the points [begin, end) of this rank cut into `parts` parts, each read by a thread of its
// own; part j of rank r is part r * parts + j of the files (their order is the scan's).
PSOR::Tile_plan index_scan(const Scan_files& reader, const fs::path& dir, const PSOR::Recognize_objects_options& o,
                           std::uint64_t begin, std::uint64_t end, std::size_t parts, std::array<double, 3>& lowest,
                           std::array<double, 3>& highest,
                           Progress& progress)
{
  const Ranks& ranks = Ranks::world();
  const auto first_of = [&](std::size_t j) { return begin + (end - begin) * j / parts; };
  progress.stage("indexing " + reader.filename() + ": its box");
  std::vector<std::vector<double>> part_lo(parts, std::vector<double>(3, 1e300)), part_hi(parts, std::vector<double>(3, -1e300));
  together(ranks, [&]() {
    run_parts(parts, [&](std::size_t j) {
      for_each_piece(reader, first_of(j), first_of(j + 1), [&](std::uint64_t first, const std::vector<double>& xyz) {
        std::vector<double>& lo = part_lo[j];
        std::vector<double>& hi = part_hi[j];
        for(std::size_t k = 0; k < xyz.size(); k += 3) {
          if(!std::isfinite(xyz[k]) || !std::isfinite(xyz[k + 1]) || !std::isfinite(xyz[k + 2]))
            throw Cli_error(reader.filename() + ": point " + std::to_string(first + k / 3) +
                            " has a coordinate that is not finite");
          for(int c = 0; c < 3; ++c)
            lo[c] = std::min(lo[c], xyz[k + c]), hi[c] = std::max(hi[c], xyz[k + c]);
        }
      });
    });
  });
  std::vector<double> lo(3, 1e300), hi(3, -1e300);
  for(std::size_t j = 0; j < parts; ++j)
    for(int c = 0; c < 3; ++c)
      lo[c] = std::min(lo[c], part_lo[j][c]), hi[c] = std::max(hi[c], part_hi[j][c]);
  ranks.min_max(lo, hi);
  lowest = {{lo[0], lo[1], lo[2]}};
  highest = {{hi[0], hi[1], hi[2]}};
  PSOR::Tile_plan plan;
  together(ranks, [&]() {
    const auto np = PSOR::parameters::tile_size(o.tile_size).tile_margin(o.tile_margin);
    const CGAL::Bbox_2 box(lo[0], lo[1], hi[0], hi[1]);
    plan = o.tile_origin ? PSOR::plan_tiles(box, np.tile_origin(*o.tile_origin)) : PSOR::plan_tiles(box, np);
    if(ranks.rank() == 0) {
      fs::remove_all(dir / "points");
      fs::create_directories(dir / "points");
    }
  });

  progress.stage("indexing " + reader.filename() + ": the points of each tile");
  // First the runs of consecutive points each tile holds: a scan in the order of its acquisition
  // gives few, and each tile then reads its runs from the scan itself (`points/<tile>.<part>.runs`).
  // When a part has too many (runs of fewer than 32 points on average), every tile's points are
  // copied instead (`points/<tile>.<part>`), in a third pass.
  std::vector<std::uint64_t> counts(plan.number_of_tiles(), 0);
  std::vector<std::uint64_t> scattered{0};
  std::mutex mutex;
  together(ranks, [&]() {
    run_parts(parts, [&](std::size_t j) {
      std::vector<std::uint64_t> own(plan.number_of_tiles(), 0);
      std::unordered_map<std::size_t, std::vector<std::pair<std::uint64_t, std::uint64_t>>> runs;
      std::size_t number_of_runs = 0, last_tile = 0;
      std::vector<std::pair<std::uint64_t, std::uint64_t>>* last = nullptr;
      const std::uint64_t budget = (first_of(j + 1) - first_of(j)) / 32 + 16;
      for_each_piece(reader, first_of(j), first_of(j + 1), [&](std::uint64_t first, const std::vector<double>& xyz) {
        for(std::size_t k = 0; k < xyz.size(); k += 3) {
          ++own[plan.tile_of(xyz[k], xyz[k + 1])];
          const std::uint64_t i = first + k / 3;
          plan.for_each_tile_holding(xyz[k], xyz[k + 1], [&](std::size_t t) {
            if(number_of_runs > budget)
              return;
            if(t != last_tile || !last)
              last = &runs[t], last_tile = t;
            if(!last->empty() && last->back().second == i)
              ++last->back().second;
            else
              last->emplace_back(i, i + 1), ++number_of_runs;
          });
        }
        if(j == 0)
          progress.fraction(double(first + xyz.size() / 3 - first_of(0)) / double(std::max<std::uint64_t>(first_of(1) - first_of(0), 1)));
      });
      const std::string part = "." + std::to_string(std::size_t(ranks.rank()) * parts + j);
      if(number_of_runs <= budget)
        for(const auto& r : runs) {
          std::string bytes(reinterpret_cast<const char*>(r.second.data()), r.second.size() * 16);
          write_whole_file(dir / "points" / (std::to_string(r.first) + part + ".runs"), bytes);
        }
      std::lock_guard<std::mutex> lock(mutex);
      scattered[0] += number_of_runs > budget;
      for(std::size_t t = 0; t < own.size(); ++t)
        counts[t] += own[t];
    });
  });
  ranks.sum(counts);
  ranks.sum(scattered);
  plan.number_of_points.assign(counts.begin(), counts.end());
  if(scattered[0] == 0)
    return plan;
  // Scattered points: a copy of every tile's points, part by part (the runs written are dropped).
  progress.stage("indexing " + reader.filename() + ": copying the points of each tile");
  together(ranks, [&]() {
    if(ranks.rank() == 0)
      for(const auto& entry : fs::directory_iterator(dir / "points"))
        if(entry.path().extension() == ".runs")
          fs::remove(entry.path());
  });
  together(ranks, [&]() {
    run_parts(parts, [&](std::size_t j) {
      Tile_records records(dir, std::size_t(ranks.rank()) * parts + j);
      for_each_piece(reader, first_of(j), first_of(j + 1), [&](std::uint64_t first, const std::vector<double>& xyz) {
        for(std::size_t k = 0; k < xyz.size(); k += 3)
          plan.for_each_tile_holding(xyz[k], xyz[k + 1], [&](std::size_t t) { records.add(t, first + k / 3, &xyz[k]); });
      });
      records.flush();
    });
  });
  return plan;
}

// The plan file: the key, the scan's box, the grid, the tiles' counts and the number of parts of the tiles' point
// files (the ranks that wrote them).
std::string plan_text(const std::string& key, const PSOR::Tile_plan& plan, int parts, const std::array<double, 3>& lowest,
                      const std::array<double, 3>& highest)
{
  std::ostringstream p;
  p.precision(17);
  p << key << "parts " << parts << "\nbox " << lowest[0] << ' ' << lowest[1] << ' ' << lowest[2] << ' ' << highest[0] << ' '
    << highest[1] << ' ' << highest[2] << "\norigin " << plan.origin[0] << ' ' << plan.origin[1] << "\ngrid " << plan.columns
    << ' ' << plan.rows << "\ncounts";
  for(std::size_t t = 0; t < plan.number_of_tiles(); ++t)
    if(plan.number_of_points[t] > 0)
      p << ' ' << t << ' ' << plan.number_of_points[t];
  p << "\nend\n";
  return p.str();
}

// The plan of a plan file's `text` when it was made with `key`.
bool read_plan(const std::string& text, const std::string& key, const PSOR::Recognize_objects_options& o,
               PSOR::Tile_plan& plan, int& parts, std::array<double, 3>& lowest, std::array<double, 3>& highest)
{
  if(text.compare(0, key.size(), key) != 0)
    return false;
  std::istringstream in(text.substr(key.size()));
  std::string word;
  plan.tile_size = o.tile_size, plan.tile_margin = o.tile_margin;
  if(!(in >> word >> parts >> word >> lowest[0] >> lowest[1] >> lowest[2] >> highest[0] >> highest[1] >> highest[2] >> word >> plan.origin[0] >> plan.origin[1] >>
       word >> plan.columns >> plan.rows >> word) ||
     word != "counts" || parts < 1)
    return false;
  plan.number_of_points.assign(plan.number_of_tiles(), 0);
  std::size_t t = 0, count = 0;
  while(in >> word && word != "end") {
    t = std::stoull(word);
    if(!(in >> count) || t >= plan.number_of_tiles())
      return false;
    plan.number_of_points[t] = count;
  }
  return word == "end";
}

// The points that tile t holds, from its files (one per part of the scan that was indexed, in the
// scan's order): their scan indices and coordinates; a part's runs read from the scan itself.
void read_tile_points(const Scan_files& reader, const fs::path& dir, std::size_t t, int parts,
                      std::vector<std::uint64_t>& index, std::vector<Point_3>& points)
{
  index.clear();
  points.clear();
  std::vector<double> xyz;
  for(int part = 0; part < parts; ++part) {
    const fs::path file = dir / "points" / (std::to_string(t) + "." + std::to_string(part));
    std::error_code ec;
    if(fs::exists(file.string() + ".runs", ec)) {
      const std::string bytes = read_file(file.string() + ".runs");
      if(bytes.size() % 16 != 0)
        throw Cli_error(file.string() + ".runs: not whole runs (remove the work folder and run again)");
      for(std::size_t k = 0; k < bytes.size() / 16; ++k) {
        std::uint64_t run[2];
        std::memcpy(run, bytes.data() + 16 * k, 16);
        if(run[1] <= run[0] || run[1] > reader.number_of_points())
          throw Cli_error(file.string() + ".runs: a run beyond the scan (remove the work folder and run again)");
        reader.read_coordinates(run[0], std::size_t(run[1] - run[0]), xyz);
        for(std::uint64_t i = run[0]; i < run[1]; ++i) {
          const double* p = &xyz[3 * (i - run[0])];
          index.push_back(i);
          points.emplace_back(p[0], p[1], p[2]);
        }
      }
      continue;
    }
    if(!fs::exists(file, ec))
      continue;
    const std::string bytes = read_file(file);
    if(bytes.size() % 32 != 0)
      throw Cli_error(file.string() + ": not whole point records (remove the work folder and run again)");
    for(std::size_t k = 0; k < bytes.size() / 32; ++k) {
      std::uint64_t i = 0;
      double p[3];
      std::memcpy(&i, bytes.data() + 32 * k, 8);
      std::memcpy(p, bytes.data() + 32 * k + 8, 24);
      index.push_back(i);
      points.emplace_back(p[0], p[1], p[2]);
    }
  }
}

// A tile's result as a file: its square and counts, the kinds of its own points that are not
// ground, its locations with their objects (scan indices and each point's horizontal distance
// to the location), classes and features.
std::string tile_result_bytes(const PSOR::Tile_plan& plan, std::size_t t, const std::vector<std::uint64_t>& index,
                              const std::vector<Point_3>& points, const PSOR::Tile_recognition& r)
{
  Record_writer w;
  w.bytes.append(tile_magic, 8);
  w.put<std::uint64_t>(t);
  w.put<std::uint64_t>(r.tile.number_of_points);
  w.put<double>(r.tile.seconds);
  std::vector<std::uint64_t> own;
  for(std::size_t k = 0; k < points.size(); ++k)
    if(r.kind[k] != PSOR::Point_kind::GROUND && plan.tile_of(points[k].x(), points[k].y()) == t)
      own.push_back(k);
  w.put<std::uint64_t>(own.size());
  for(std::uint64_t k : own) {
    w.put<std::uint64_t>(index[k]);
    w.put<std::uint8_t>(std::uint8_t(r.kind[k]));
  }
  w.put<std::uint64_t>(r.locations.size());
  for(std::size_t k = 0; k < r.locations.size(); ++k) {
    const PSOR::Object_location& l = r.locations[k];
    const PSOR::Object_segmentation& s = r.objects[k];
    for(double c : l.position)
      w.put<double>(c);
    w.put<std::uint64_t>(l.number_of_points);
    w.put<double>(l.height);
    w.put<double>(s.radius);
    w.put<double>(s.cut_cost);
    w.put<double>(s.seconds);
    w.put<std::uint64_t>(s.seed == PSOR::Object_segmentation::no_point ? ~std::uint64_t(0) : index[s.seed]);
    w.put<std::uint64_t>(s.points.size());
    for(std::size_t i : s.points) {
      w.put<std::uint64_t>(index[i]);
      w.put<double>(std::hypot(points[i].x() - l.position[0], points[i].y() - l.position[1]));
    }
  }
  w.put<std::uint64_t>(r.labels.size());
  for(std::size_t k = 0; k < r.labels.size(); ++k) {
    w.put<std::uint64_t>(r.labels[k]);
    w.put<double>(r.confidences[k]);
  }
  w.put<std::uint64_t>(r.features.size());
  w.put<std::uint64_t>(r.features.empty() ? 0 : r.features.front().size());
  for(const std::vector<double>& row : r.features)
    for(double v : row)
      w.put<double>(v);
  w.bytes.append(tile_magic, 8);
  return w.bytes;
}

// Per object merged, its points and their distances to its location, by point: the distance of
// the object that holds a point, when another claims it (16 bytes per object point; a map of every
// claimed point took 2.3 GB at 10^9 points).
struct Claims
{
  std::vector<std::vector<std::pair<std::uint64_t, double>>> by_object;

  double distance(int object, std::uint64_t i) const
  {
    const auto& points = by_object[std::size_t(object)];
    return std::lower_bound(points.begin(), points.end(), std::make_pair(i, -std::numeric_limits<double>::infinity()))
      ->second;
  }
};

// Merges the result file of a tile into `m` as recognize_objects() merges tiles: its locations
// after those merged before, the kinds of its own points, each point of its objects claimed by
// the nearest location (the first at equal distances).
void merge_tile(const fs::path& file, const PSOR::Tile_plan& plan, std::size_t t, Recognition_in_tiles& m, Claims& claims)
{
  const std::string bytes = read_file(file);
  Record_reader in{bytes};
  const auto check = [&](bool ok) {
    if(!ok)
      throw Cli_error(file.string() + ": not a tile result of this program (remove the work folder and run again)");
  };
  check(bytes.size() >= 16 && std::memcmp(bytes.data(), tile_magic, 8) == 0 &&
        std::memcmp(bytes.data() + bytes.size() - 8, tile_magic, 8) == 0);
  in.at = 8;
  check(in.get<std::uint64_t>() == t);
  PSOR::Scene_tile tile = plan.tile(t);
  tile.number_of_points = std::size_t(in.get<std::uint64_t>());
  tile.seconds = in.get<double>();
  PSOR::Object_recognition_result& r = m.result;
  r.largest_tile = std::max(r.largest_tile, tile.number_of_points);
  const std::uint64_t begin = m.first, end = m.first + m.ground.size();
  for(std::uint64_t k = 0, n = in.get<std::uint64_t>(); k < n; ++k) {
    const std::uint64_t i = in.get<std::uint64_t>();
    const bool ground = in.get<std::uint8_t>() == std::uint8_t(PSOR::Point_kind::GROUND);
    if(i >= begin && i < end)
      m.ground[i - begin] = ground;
  }
  const std::uint64_t locations = in.get<std::uint64_t>();
  tile.number_of_locations = std::size_t(locations);
  for(std::uint64_t k = 0; k < locations; ++k) {
    PSOR::Object_location l;
    for(double& c : l.position)
      c = in.get<double>();
    l.number_of_points = std::size_t(in.get<std::uint64_t>());
    l.height = in.get<double>();
    PSOR::Object_segmentation s;
    s.radius = in.get<double>();
    s.cut_cost = in.get<double>();
    s.seconds = in.get<double>();
    const std::uint64_t seed = in.get<std::uint64_t>();
    s.seed = seed == ~std::uint64_t(0) ? PSOR::Object_segmentation::no_point : std::size_t(seed);
    const int id = int(r.objects.size());
    std::vector<std::pair<std::uint64_t, double>> distances;
    for(std::uint64_t p = 0, n = in.get<std::uint64_t>(); p < n; ++p) {
      const std::uint64_t i = in.get<std::uint64_t>();
      const double d = in.get<double>();
      if(i < begin || i >= end)
        continue;
      s.points.push_back(std::size_t(i));
      distances.emplace_back(i, d);
      int& claim = m.object[i - begin];
      if(claim < 0 || (claim != id && d < claims.distance(claim, i)))
        claim = id;
    }
    std::sort(distances.begin(), distances.end());
    distances.shrink_to_fit();
    claims.by_object.push_back(std::move(distances));
    r.locations.push_back(l);
    r.objects.push_back(std::move(s));
  }
  for(std::uint64_t k = 0, n = in.get<std::uint64_t>(); k < n; ++k) {
    r.labels.push_back(std::size_t(in.get<std::uint64_t>()));
    r.confidences.push_back(in.get<double>());
  }
  const std::uint64_t rows = in.get<std::uint64_t>(), columns = in.get<std::uint64_t>();
  for(std::uint64_t k = 0; k < rows; ++k) {
    std::vector<double> row(columns);
    for(double& v : row)
      v = in.get<double>();
    r.features.push_back(std::move(row));
  }
  check(in.at + 8 == bytes.size());
  r.tiles.push_back(tile);
}

// Whether tile t must fail: the tests' way to make one rank fail (SHAPE_ANALYSIS_FAIL_TILE=t).
bool fail_on_purpose(std::size_t t)
{
  const char* v = std::getenv("SHAPE_ANALYSIS_FAIL_TILE");
  return v && std::to_string(t) == v;
}

// Runs body() on `threads` threads (0: one per available processor) at once, each until it returns.
template <typename Body>
void on_threads(std::size_t threads, const Body& body)
{
#ifdef CGAL_LINKED_WITH_TBB
  if(threads != 1) {
    tbb::task_arena arena(int(threads == 0 ? CGAL::Shape_analysis::available_processors() : threads));
    arena.execute([&]() {
      const std::size_t workers = std::size_t(arena.max_concurrency());
      tbb::parallel_for(std::size_t(0), workers, std::size_t(1), [&](std::size_t) { body(); });
    });
    return;
  }
#endif
  body();
}

// The tiles that own points, recognized by the ranks and their threads, each taking the next tile
// not taken (a slow tile does not hold the others back); a tile finished before is skipped. A
// tile that fails stops the run, or with `keep_going` leaves `tiles/<tile>.failed` (its error).
// Returns the tiles skipped.
std::size_t recognize_tiles(const Scan_files& reader, const PSOR::Tile_plan& plan, int parts, const fs::path& dir,
                            std::size_t threads, bool keep_going, const Tile_recognizer& recognize, Progress& progress)
{
  const Ranks& ranks = Ranks::world();
  // The largest tiles first: the last tiles taken are small ones, so the ranks and threads end
  // together (the results do not depend on the order).
  std::vector<std::size_t> busy = plan.tiles_with_points();
  std::stable_sort(busy.begin(), busy.end(), [&](std::size_t a, std::size_t b) {
    return plan.number_of_points[a] > plan.number_of_points[b];
  });
  progress.stage("recognizing the objects of " + std::to_string(busy.size()) + " tiles");
  std::size_t reused = 0, finished = 0;
  Ranks::Counter counter(ranks);
  together(ranks, [&]() {
    std::mutex mutex; // guards `failure`, the counts and the progress
    std::string failure;
    on_threads(threads, [&]() {
      for(std::uint64_t b = counter.next(); b < busy.size(); b = counter.next()) {
        const std::size_t t = busy[std::size_t(b)];
        const fs::path result = dir / "tiles" / std::to_string(t);
        std::error_code exists;
        bool done = fs::exists(result, exists);
        fs::remove(result.string() + ".failed", exists);
        if(!done) {
          try {
            std::vector<std::uint64_t> index;
            std::vector<Point_3> points;
            read_tile_points(reader, dir, t, parts, index, points);
            if(fail_on_purpose(t))
              throw Cli_error("failed on purpose (SHAPE_ANALYSIS_FAIL_TILE)");
            const PSOR::Tile_recognition r = recognize(plan, t, points);
            write_whole_file(result, tile_result_bytes(plan, t, index, points, r));
          } catch(const std::exception& e) {
            if(keep_going) {
              std::string why = e.what();
              std::replace(why.begin(), why.end(), '\n', ' ');
              write_whole_file(result.string() + ".failed", why);
              continue;
            }
            std::lock_guard<std::mutex> lock(mutex);
            if(failure.empty())
              failure = "tile " + std::to_string(t) + ": " + e.what();
            return;
          }
        }
        std::lock_guard<std::mutex> lock(mutex);
        reused += done;
        progress.fraction(double(++finished) / double(busy.size()));
      }
    });
    if(!failure.empty())
      throw Cli_error(failure + " (the finished tiles stay in " + dir.string() + ")");
  });
  std::vector<std::uint64_t> total = {reused};
  ranks.sum(total);
  return std::size_t(total[0]);
}

} // namespace

Recognition_in_tiles recognize_in_tiles(const Scan_files& reader, const std::string& work_dir,
                                        const PSOR::Recognize_objects_options& options, const std::string& identity,
                                        bool keep_going, const Tile_recognizer& recognize, Progress& progress)
{
  const Ranks& ranks = Ranks::world();
  const fs::path dir(work_dir);
  const std::uint64_t n = reader.number_of_points();
  Recognition_in_tiles m;
  m.first = n * std::uint64_t(ranks.rank()) / std::uint64_t(ranks.size());
  const std::uint64_t last = n * std::uint64_t(ranks.rank() + 1) / std::uint64_t(ranks.size());
  Stopwatch indexing;
  const std::string key = plan_key(reader, options, identity);
  std::string text;
  Folder_lock lock; // rank 0's, for the whole run: one run at a time in a work folder
  together(ranks, [&]() {
    std::error_code ec;
    fs::create_directories(dir, ec);
    if(!fs::is_directory(dir, ec))
      throw Cli_error("--work-dir " + work_dir + ": not a folder that can be created");
    if(ranks.rank() == 0) {
      lock.take(dir / "lock", work_dir);
      if(fs::exists(dir / "plan", ec))
        text = read_file(dir / "plan");
    }
  });
  text = ranks.broadcast(text);
  PSOR::Tile_plan plan;
  // The points' files: a part per thread of each rank (rank 0's number of threads for all).
  const std::size_t parts_per_rank = std::size_t(std::stoul(ranks.broadcast(std::to_string(
    options.number_of_threads > 0 ? options.number_of_threads : CGAL::Shape_analysis::available_processors()))));
  int parts = ranks.size() * int(parts_per_rank);
  if(!read_plan(text, key, options, plan, parts, m.lowest, m.highest)) { // a new plan: the tiles done before are not for it
    parts = ranks.size() * int(parts_per_rank);
    together(ranks, [&]() {
      std::error_code ec;
      if(ranks.rank() == 0) {
        fs::remove(dir / "plan", ec);
        fs::remove_all(dir / "tiles", ec);
      }
    });
    plan = index_scan(reader, dir, options, m.first, last, parts_per_rank, m.lowest, m.highest, progress);
    together(ranks, [&]() {
      if(ranks.rank() == 0)
        write_whole_file(dir / "plan", plan_text(key, plan, parts, m.lowest, m.highest));
    });
  }
  together(ranks, [&]() { fs::create_directories(dir / "tiles"); });
  m.seconds_indexing = indexing.seconds();
  Stopwatch tiles;
  m.tiles_reused = recognize_tiles(reader, plan, parts, dir, options.number_of_threads, keep_going, recognize, progress);
  m.seconds_tiles = tiles.seconds();
  Stopwatch merging;

  progress.stage("merging the tiles");
  m.object.assign(std::size_t(last - m.first), -1);
  m.ground.assign(std::size_t(last - m.first), 1);
  together(ranks, [&]() {
    Claims claims;
    for(std::size_t t : plan.tiles_with_points()) {
      const fs::path result = dir / "tiles" / std::to_string(t);
      std::error_code ec;
      if(keep_going && fs::exists(result.string() + ".failed", ec)) {
        // Left out: its own points are neither ground nor in an object.
        m.failed_tiles.emplace_back(t, read_file(result.string() + ".failed"));
        std::vector<std::uint64_t> index;
        std::vector<Point_3> points;
        read_tile_points(reader, dir, t, parts, index, points);
        for(std::size_t k = 0; k < points.size(); ++k)
          if(index[k] >= m.first && index[k] < last && plan.tile_of(points[k].x(), points[k].y()) == t)
            m.ground[std::size_t(index[k] - m.first)] = 0;
        PSOR::Scene_tile tile = plan.tile(t);
        tile.number_of_points = points.size();
        m.result.tiles.push_back(tile);
        continue;
      }
      merge_tile(result, plan, t, m, claims);
    }
  });
  // An object holds no point that its own tile calls ground.
  m.object_points.assign(m.result.objects.size(), 0);
  for(std::size_t k = 0; k < m.result.objects.size(); ++k) {
    std::vector<std::size_t>& points = m.result.objects[k].points;
    points.erase(std::remove_if(points.begin(), points.end(), [&](std::size_t i) { return m.ground[i - m.first] != 0; }),
                 points.end());
    m.object_points[k] = points.size();
  }
  ranks.sum(m.object_points);
  for(std::size_t i = 0; i < m.object.size(); ++i)
    if(m.ground[i])
      m.object[i] = -1;
  m.seconds_merging = merging.seconds();
  return m;
}

} // namespace shape_analysis_cli
