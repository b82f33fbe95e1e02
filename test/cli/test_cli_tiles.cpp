// Copyright (c) 2026 CGAL Global Shape Analysis contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later

// `points recognize --work-dir` (out of core): the scan read piece by piece and the tiles
// processed from the work folder give the bytes of the run that holds the scan in memory; a
// second run reuses every finished tile; runs killed (SIGKILL) at random moments, three times in
// a row, then run to their end, give the same bytes; --only-objects and a LAS scan's georeference
// as in memory. With MPI: the ranks of `mpirun -np 2` (also with --only-objects) and `-np 3` give
// the same bytes; a rank that fails makes the job fail with one message and no output, and the
// job run again finishes it; whole jobs killed (SIGKILL to mpirun and its ranks) three times
// resume to the same bytes. The tool is run as a process on a generated street.

#include <gtest/gtest.h>

#include "tool_process.h"

#include <algorithm>
#include <chrono>
#include <fstream>
#include <csignal>
#include <cstring>
#include <iostream>
#include <random>
#include <sys/file.h>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

namespace {

namespace fs = std::filesystem;
using namespace tool_process;

// The number after `"name": ` in a report, or -1.
long report_number(const std::string& report, const std::string& name)
{
  const std::size_t at = report.find("\"" + name + "\": ");
  return at == std::string::npos ? -1 : std::stol(report.substr(at + name.size() + 4));
}

class TilesTest : public ::testing::Test
{
protected:
  void SetUp() override
  {
    root = fs::temp_directory_path() / ("shape_analysis_tiles_" + std::to_string(::getpid()));
    fs::remove_all(root);
    fs::create_directories(root);
    scan = (root / "scan.ply").string();
    ASSERT_TRUE(run_tool({"points", "generate", "--points", "200000", "--length", "120", "--seed", "4", "-q", "-o", scan}));
    ASSERT_TRUE(run_tool(recognize(root / "memory", "")));
    objects = read_file(root / "memory" / "objects.ply");
    locations = read_file(root / "memory" / "locations.csv");
    ASSERT_GT(objects.size(), 200000u * 24);
    ASSERT_GT(locations.size(), 100u);
  }
  void TearDown() override { fs::remove_all(root); }

  // `points recognize` of the scan into `dir`, out of core in `work` unless it is empty.
  std::vector<std::string> recognize(const fs::path& dir, const std::string& work) const
  {
    fs::create_directories(dir);
    std::vector<std::string> args = {"points", "recognize", scan, "-q", "--tile-size", "15", "--threads", "2",
                                     "-o", (dir / "objects.ply").string(), "--locations", (dir / "locations.csv").string(),
                                     "--report", (dir / "report.json").string()};
    if(!work.empty())
      args.insert(args.end(), {"--work-dir", work});
    return args;
  }

  fs::path root;
  std::string scan, objects, locations;
};

// Writes the binary PLY `from` as `parts` files of `folder` (part0.ply, ...): the same header with
// each part's count, the vertex records cut at `cuts`.
void split_ply(const std::string& from, const fs::path& folder, const std::vector<std::size_t>& cuts)
{
  const std::string bytes = read_file(from);
  const std::size_t end = bytes.find("end_header\n") + 11, at = bytes.find("element vertex ");
  const std::size_t n = std::stoul(bytes.substr(at + 15)), record = (bytes.size() - end) / n;
  const std::string count = "element vertex " + std::to_string(n) + "\n";
  fs::create_directories(folder);
  for(std::size_t k = 0; k + 1 < cuts.size(); ++k) {
    std::string header = bytes.substr(0, end);
    header.replace(at, count.size(), "element vertex " + std::to_string(cuts[k + 1] - cuts[k]) + "\n");
    std::ofstream out(folder / ("part" + std::to_string(k) + ".ply"), std::ios::binary);
    out << header << bytes.substr(end + cuts[k] * record, (cuts[k + 1] - cuts[k]) * record);
  }
}

TEST_F(TilesTest, AFolderOfScansIsRecognizedAsTheirUnion)
{
  // The scan in three files (one of 10 points), in a folder with a file that is not a scan.
  const std::string ply = read_file(scan);
  const std::size_t n = std::stoul(ply.substr(ply.find("element vertex ") + 15));
  split_ply(scan, root / "parts", {0, n / 3, n / 3 + 10, n});
  std::ofstream(root / "parts" / "notes.txt") << "not a scan\n";
  const fs::path dir = root / "folder";
  std::vector<std::string> args = recognize(dir, (dir / "work").string());
  args[2] = (root / "parts").string();
  ASSERT_TRUE(run_tool(args));
  EXPECT_TRUE(read_file(dir / "objects.ply") == objects);
  EXPECT_EQ(read_file(dir / "locations.csv"), locations);
  EXPECT_NE(read_file(dir / "report.json").find("part2.ply"), std::string::npos);
}

// A scan in acquisition order is read back by runs of consecutive points (`.runs` files, no copy);
// a scan in random order has its tiles' points copied (a third pass): both give the bytes of the
// in-memory run of the same file.
TEST_F(TilesTest, ScatteredPointsAreCopiedOrderedOnesReadInRuns)
{
  const fs::path dir = root / "runs";
  std::vector<std::string> ordered = recognize(dir, (dir / "work").string());
  ordered[5] = "60"; // tiles as wide as the street: a scan line crosses one or two
  ASSERT_TRUE(run_tool(ordered));
  long runs = 0, copies = 0;
  for(const auto& entry : fs::directory_iterator(dir / "work" / "points"))
    (entry.path().extension() == ".runs" ? runs : copies) += 1;
  EXPECT_GE(runs, 3); // a file per tile and thread
  EXPECT_EQ(copies, 0);
  // The same street with its points shuffled.
  std::string ply = read_file(scan);
  const std::size_t end = ply.find("end_header\n") + 11, n = std::stoul(ply.substr(ply.find("element vertex ") + 15));
  const std::size_t record = (ply.size() - end) / n;
  std::vector<std::size_t> order(n);
  for(std::size_t i = 0; i < n; ++i)
    order[i] = i;
  std::shuffle(order.begin(), order.end(), std::mt19937(3));
  std::string shuffled = ply.substr(0, end);
  for(std::size_t i : order)
    shuffled.append(ply, end + i * record, record);
  const std::string file = (root / "shuffled.ply").string();
  std::ofstream(file, std::ios::binary) << shuffled;
  std::vector<std::string> in_memory = recognize(root / "shuffled_memory", ""), out_of_core = recognize(dir / "shuffled", (dir / "shuffled_work").string());
  in_memory[2] = out_of_core[2] = file;
  ASSERT_TRUE(run_tool(in_memory));
  ASSERT_TRUE(run_tool(out_of_core));
  EXPECT_TRUE(read_file(dir / "shuffled" / "objects.ply") == read_file(root / "shuffled_memory" / "objects.ply"));
  runs = copies = 0;
  for(const auto& entry : fs::directory_iterator(dir / "shuffled_work" / "points"))
    (entry.path().extension() == ".runs" ? runs : copies) += 1;
  EXPECT_EQ(runs, 0);
  EXPECT_GT(copies, 10);
}

// The records of the binary PLY `bytes` whose int property `object` is at least 0, and their number.
std::string object_records(const std::string& bytes, std::size_t& count)
{
  const std::size_t end = bytes.find("end_header\n") + 11;
  std::istringstream header(bytes.substr(0, end));
  std::string line;
  std::size_t record = 0, object = std::string::npos, n = 0;
  bool vertex = false;
  while(std::getline(header, line)) {
    std::istringstream words(line);
    std::string word, type, name;
    words >> word;
    if(word == "element") {
      words >> name >> n;
      vertex = name == "vertex";
    } else if(word == "property" && vertex) {
      words >> type >> name;
      if(name == "object")
        object = record;
      record += type == "double" ? 8 : (type == "int" || type == "float") ? 4 : type == "uchar" ? 1 : 0;
    }
  }
  std::string kept;
  count = 0;
  for(std::size_t i = 0; object != std::string::npos && i < n; ++i) {
    std::int32_t o;
    std::memcpy(&o, bytes.data() + end + i * record + object, 4);
    if(o >= 0) {
      kept.append(bytes, end + i * record, record);
      ++count;
    }
  }
  return kept;
}

// --only-objects: the records of the points in objects, as the whole output has them, in memory
// and out of core (PLY and LAS) alike.
TEST_F(TilesTest, OnlyObjectsWritesTheObjectPointsOfTheWholeOutput)
{
  std::size_t expected_count = 0;
  const std::string expected = object_records(objects, expected_count);
  ASSERT_GT(expected_count, 1000u);
  for(const std::string& ext : {std::string(".ply"), std::string(".las")}) {
    std::vector<std::string> memory = recognize(root / "only_memory", ""),
                             pieces = recognize(root / "only_pieces", (root / ("only_work" + ext)).string());
    memory[9] = (root / "only_memory" / ("objects" + ext)).string();
    pieces[9] = (root / "only_pieces" / ("objects" + ext)).string();
    memory.push_back("--only-objects");
    pieces.push_back("--only-objects");
    ASSERT_TRUE(run_tool(memory)) << ext;
    ASSERT_TRUE(run_tool(pieces)) << ext;
    const std::string only = read_file(memory[9]);
    EXPECT_TRUE(only == read_file(pieces[9])) << ext;
    if(ext == ".ply") {
      std::size_t count = 0;
      EXPECT_TRUE(object_records(only, count) == expected);
      EXPECT_EQ(count, expected_count);
      EXPECT_EQ(only.size() - (only.find("end_header\n") + 11), expected.size()); // no other point
    } else {
      std::uint64_t n = 0;
      std::memcpy(&n, only.data() + 247, 8); // LAS 1.4: the 64-bit point count
      EXPECT_EQ(n, expected_count);
    }
  }
}

TEST_F(TilesTest, OutOfCoreGivesTheInMemoryBytesAndReusesFinishedTiles)
{
  const std::string work = (root / "work").string();
  ASSERT_TRUE(run_tool(recognize(root / "first", work)));
  EXPECT_TRUE(read_file(root / "first" / "objects.ply") == objects);
  EXPECT_EQ(read_file(root / "first" / "locations.csv"), locations);
  EXPECT_EQ(report_number(read_file(root / "first" / "report.json"), "tiles_reused"), 0);
  long finished = 0;
  for(const auto& entry : fs::directory_iterator(work + "/tiles"))
    finished += entry.path().extension() != ".part";
  EXPECT_GT(finished, 10);
  // Again: every tile is read back from the work folder.
  ASSERT_TRUE(run_tool(recognize(root / "second", work)));
  EXPECT_TRUE(read_file(root / "second" / "objects.ply") == objects);
  EXPECT_EQ(report_number(read_file(root / "second" / "report.json"), "tiles_reused"), finished);
  // LAS (1.4, the points piece by piece, the header from every piece's records): the same bytes.
  std::vector<std::string> las = recognize(root / "las", work);
  las[9] = (root / "las" / "objects.las").string();
  std::vector<std::string> las_in_memory = recognize(root / "las_memory", "");
  las_in_memory[9] = (root / "las_memory" / "objects.las").string();
  ASSERT_TRUE(run_tool(las));
  ASSERT_TRUE(run_tool(las_in_memory));
  EXPECT_GT(fs::file_size(root / "las" / "objects.las"), 200000u * 30);
  EXPECT_TRUE(read_file(root / "las" / "objects.las") == read_file(root / "las_memory" / "objects.las"));
  // Another tile size is another plan: nothing reused.
  std::vector<std::string> other = recognize(root / "third", work);
  other[5] = "20";
  ASSERT_TRUE(run_tool(other));
  EXPECT_EQ(report_number(read_file(root / "third" / "report.json"), "tiles_reused"), 0);
}

TEST_F(TilesTest, KilledRunsResumeToTheSameBytes)
{
  // The time of a whole out-of-core run, for the moments of the kills.
  const auto start = std::chrono::steady_clock::now();
  ASSERT_TRUE(run_tool(recognize(root / "timed", (root / "timed_work").string())));
  const double whole = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::mt19937 random(11);
  std::uniform_real_distribution<double> moment(0.05 * whole, 0.95 * whole);
  long resumed = 0;
  for(int round = 0; round < 4; ++round) {
    const fs::path dir = root / ("round" + std::to_string(round));
    const std::string work = (dir / "work").string();
    for(int kill = 0; kill < 3; ++kill) {
      const pid_t pid = start_tool(recognize(dir, work), 0);
      ASSERT_GT(pid, 0);
      std::this_thread::sleep_for(std::chrono::duration<double>(moment(random)));
      ::kill(pid, SIGKILL);
      wait_for(pid);
    }
    ASSERT_TRUE(run_tool(recognize(dir, work)));
    EXPECT_TRUE(read_file(dir / "objects.ply") == objects) << "round " << round;
    EXPECT_EQ(read_file(dir / "locations.csv"), locations) << "round " << round;
    const long reused = report_number(read_file(dir / "report.json"), "tiles_reused");
    std::cout << "round " << round << ": the last run reused " << reused << " tiles\n";
    resumed += reused > 0;
  }
  // At least one of the runs went on from tiles a killed run had finished.
  EXPECT_GT(resumed, 0);
}

TEST_F(TilesTest, KeepGoingLeavesOutAFailingTileAndTheNextRunDoesIt)
{
  const fs::path dir = root / "keep_going";
  const std::string work = (dir / "work").string();
  std::vector<std::string> args = recognize(dir, work);
  args.push_back("--keep-going");
  Launch launch;
  launch.environment.emplace_back("SHAPE_ANALYSIS_FAIL_TILE", "5");
  launch.standard_error = (root / "errors.txt").string();
  int status = wait_for(start_program(tool, args, launch));
  ASSERT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << read_file(root / "errors.txt");
  const std::string report = read_file(dir / "report.json");
  EXPECT_NE(report.find("\"tile\": 5"), std::string::npos) << report.substr(0, 2000);
  EXPECT_NE(report.find("failed on purpose"), std::string::npos);
  EXPECT_FALSE(read_file(dir / "objects.ply") == objects); // a tile's objects are missing
  // Without --keep-going the same fault fails the run, with no output.
  const fs::path strict = root / "strict";
  status = wait_for(start_program(tool, recognize(strict, (strict / "work").string()), launch));
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 1);
  EXPECT_FALSE(fs::exists(strict / "objects.ply"));
  // Run again without the fault: only tile 5 is done, the outputs are whole.
  launch.environment.clear();
  status = wait_for(start_program(tool, args, launch));
  ASSERT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << read_file(root / "errors.txt");
  EXPECT_TRUE(read_file(dir / "objects.ply") == objects);
  EXPECT_EQ(read_file(dir / "locations.csv"), locations);
  long finished = 0;
  for(const auto& entry : fs::directory_iterator(work + "/tiles"))
    finished += entry.path().extension() != ".part" && entry.path().extension() != ".failed";
  EXPECT_EQ(report_number(read_file(dir / "report.json"), "tiles_reused"), finished - 1);
}

// `points generate` above twice --segment-points: segments, each a street of its own after the
// previous one, written one at a time into one PLY or LAS file (or a file each); the same bytes for
// the same seed.
TEST(Generator, ManyPointsAreWrittenSegmentBySegment)
{
  const fs::path root = fs::temp_directory_path() / ("shape_analysis_segments_" + std::to_string(::getpid()));
  fs::remove_all(root);
  fs::create_directories(root);
  const auto generate = [&](const std::string& name) {
    return std::vector<std::string>{"points", "generate", "--points", "60000", "--length", "90", "--segment-points",
                                    "20000", "--seed", "2", "-q", "-o", (root / name).string(), "--truth",
                                    (root / (name + ".json")).string(), "--report", (root / (name + ".report.json")).string()};
  };
  ASSERT_TRUE(run_tool(generate("a.ply")));
  ASSERT_TRUE(run_tool(generate("b.ply")));
  ASSERT_TRUE(run_tool(generate("c.las")));
  const std::string report = read_file(root / "a.ply.report.json");
  EXPECT_EQ(report_number(report, "segments"), 3);
  const long n = report_number(report, "number_of_points");
  EXPECT_GT(n, 50000);
  EXPECT_LT(n, 70000);
  const std::string ply = read_file(root / "a.ply");
  EXPECT_TRUE(ply == read_file(root / "b.ply"));
  // The header announces the whole (its count padded with spaces), 39 bytes per vertex follow.
  const std::size_t at = ply.find("element vertex "), end = ply.find("end_header\n") + 11;
  EXPECT_EQ(std::stol(ply.substr(at + 15)), n);
  EXPECT_EQ(ply.size() - end, std::size_t(n) * 39);
  // The truth: ids 1 to the number of objects, each once, along the three segments.
  const std::string truth = read_file(root / "a.ply.json");
  const long objects = report_number(report, "number_of_objects");
  EXPECT_GT(objects, 20);
  for(long id : {1L, objects})
    EXPECT_NE(truth.find("\"id\": " + std::to_string(id) + ","), std::string::npos) << id;
  EXPECT_EQ(truth.find("\"id\": " + std::to_string(objects + 1) + ","), std::string::npos);
  // Both files read back (piece by piece) with every point, and their objects found.
  for(const std::string name : {"a.ply", "c.las"}) {
    const std::string out = (root / (name + ".objects.ply")).string(), r = (root / (name + ".r.json")).string();
    ASSERT_TRUE(run_tool({"points", "recognize", (root / name).string(), "-q", "-o", out, "--report", r,
                          "--work-dir", (root / (name + ".work")).string()}))
      << name;
    EXPECT_EQ(report_number(read_file(r), "number_of_points"), n) << name;
    EXPECT_NE(read_file(r).find("\"location\""), std::string::npos) << name;
  }
  // --segment-files: a file per segment, whose records one after the other are c.las's; the folder
  // recognized as one scan finds the same objects.
  fs::create_directories(root / "tiles");
  std::vector<std::string> files = generate("tiles/d.las");
  files.push_back("--segment-files");
  ASSERT_TRUE(run_tool(files));
  const auto records = [](const std::string& las) {
    std::uint32_t data = 0;
    std::memcpy(&data, las.data() + 96, 4);
    return las.substr(data);
  };
  std::string joined;
  for(const std::string name : {"d_0000.las", "d_0001.las", "d_0002.las"})
    joined += records(read_file(root / "tiles" / name));
  EXPECT_FALSE(fs::exists(root / "tiles" / "d_0003.las"));
  EXPECT_TRUE(joined == records(read_file(root / "c.las")));
  for(const std::string scan : {(root / "c.las").string(), (root / "tiles").string()})
    ASSERT_TRUE(run_tool({"points", "recognize", scan, "-q", "-o", (root / "o.las").string(), "--locations",
                          (root / (scan == (root / "c.las").string() ? "c.csv" : "d.csv")).string(), "--work-dir",
                          (root / "work_d").string()}));
  EXPECT_EQ(read_file(root / "c.csv"), read_file(root / "d.csv"));
  // Without segments, --segment-files is refused.
  EXPECT_FALSE(run_tool({"points", "generate", "--points", "5000", "-q", "-o", (root / "e.las").string(), "--segment-files"}));
  fs::remove_all(root);
}

// A LAS scan's scale, offset and coordinate system records are those of the LAS output, in memory
// and out of core alike (the same bytes).
TEST(LasOutput, KeepsTheScansGeoreference)
{
  const fs::path root = fs::temp_directory_path() / ("shape_analysis_georeference_" + std::to_string(::getpid()));
  fs::remove_all(root);
  fs::create_directories(root);
  ASSERT_TRUE(run_tool({"points", "generate", "--points", "40000", "--length", "60", "--seed", "3", "-q", "-o",
                        (root / "plain.las").string()}));
  // A WKT record inserted before the points, and the x offset moved by 0.25 m (the scene with it):
  // an offset the writer's own rule (a multiple of 100 m) would not choose.
  std::string las = read_file(root / "plain.las");
  ASSERT_GT(las.size(), 375u);
  const auto u32 = [&](std::size_t at) {
    std::uint32_t v = 0;
    for(int b = 3; b >= 0; --b)
      v = (v << 8) | static_cast<unsigned char>(las[at + std::size_t(b)]);
    return v;
  };
  const auto set_u32 = [&](std::size_t at, std::uint32_t v) {
    for(int b = 0; b < 4; ++b)
      las[at + std::size_t(b)] = char((v >> (8 * b)) & 0xFF);
  };
  const std::string wkt = "PROJCS[\"WGS 84 / UTM zone 18N\",AUTHORITY[\"EPSG\",\"32618\"]]";
  std::string vlr(54, '\0');
  vlr.replace(2, 15, "LASF_Projection");
  vlr[18] = char(2112 & 0xFF), vlr[19] = char(2112 >> 8);
  vlr[20] = char(wkt.size() & 0xFF), vlr[21] = char(wkt.size() >> 8);
  vlr += wkt;
  const std::uint32_t data = u32(96);
  las.insert(data, vlr);
  set_u32(96, data + std::uint32_t(vlr.size()));
  set_u32(100, u32(100) + 1);
  double offset_x;
  std::memcpy(&offset_x, las.data() + 155, 8);
  offset_x += 0.25;
  std::memcpy(&las[155], &offset_x, 8);
  std::ofstream(root / "scan.las", std::ios::binary) << las;

  for(const std::string& work : {std::string(), (root / "work").string()}) {
    const fs::path out = root / (work.empty() ? "memory.las" : "pieces.las");
    std::vector<std::string> args = {"points", "recognize", (root / "scan.las").string(), "-q", "-o", out.string()};
    if(!work.empty())
      args.insert(args.end(), {"--work-dir", work});
    ASSERT_TRUE(run_tool(args)) << work;
    const std::string o = read_file(out);
    ASSERT_GT(o.size(), 375u);
    EXPECT_EQ(o.substr(131, 48), las.substr(131, 48)) << "scale and offset, " << work;
    EXPECT_NE(o.find("LASF_Projection"), std::string::npos) << work;
    EXPECT_NE(o.find(wkt), std::string::npos) << work;
    EXPECT_EQ(static_cast<unsigned char>(o[6]) & 0x10, 0x10) << work; // WKT declared
  }
  EXPECT_TRUE(read_file(root / "memory.las") == read_file(root / "pieces.las"));
  fs::remove_all(root);
}

// With a model, the objects' classes out of core (a class per object, not per point) are those
// of the run in memory: the same bytes, PLY and LAS.
TEST(ClassifiedOutOfCore, GivesTheInMemoryBytes)
{
  const fs::path root = fs::temp_directory_path() / ("shape_analysis_classified_" + std::to_string(::getpid()));
  fs::remove_all(root);
  fs::create_directories(root);
  const std::string train = (root / "train.ply").string(), scan = (root / "scan.ply").string();
  ASSERT_TRUE(run_tool({"points", "generate", "--points", "150000", "--length", "90", "--seed", "2", "-q", "-o", train,
                        "--truth", (root / "truth.json").string()}));
  ASSERT_TRUE(run_tool({"points", "train", train, "--labels", (root / "truth.json").string(), "-q", "-o",
                        (root / "model.json").string()}));
  ASSERT_TRUE(run_tool({"points", "generate", "--points", "150000", "--length", "90", "--seed", "3", "-q", "-o", scan}));
  for(const std::string ext : {".ply", ".las"}) {
    const auto recognize = [&](const std::string& name, const std::string& work) {
      std::vector<std::string> args = {"points", "recognize", scan, "-q", "--tile-size", "20", "--threads", "2",
                                       "--model", (root / "model.json").string(), "-o", (root / (name + ext)).string(),
                                       "--locations", (root / (name + ext + ".csv")).string()};
      if(!work.empty())
        args.insert(args.end(), {"--work-dir", (root / work).string()});
      return run_tool(args);
    };
    ASSERT_TRUE(recognize("memory", "")) << ext;
    ASSERT_TRUE(recognize("pieces", "work" + ext)) << ext;
    const std::string memory = read_file(root / ("memory" + ext));
    EXPECT_GT(memory.size(), 150000u * 30) << ext;
    EXPECT_TRUE(memory == read_file(root / ("pieces" + ext))) << ext;
    EXPECT_EQ(read_file(root / ("memory" + ext + ".csv")), read_file(root / ("pieces" + ext + ".csv"))) << ext;
    EXPECT_NE(read_file(root / ("memory" + ext + ".csv")).find("label"), std::string::npos) << ext;
  }
  fs::remove_all(root);
}

// One run at a time in a work folder: a second finds it locked and fails at once, with no output.
TEST_F(TilesTest, AWorkFolderInUseIsRefused)
{
  const fs::path dir = root / "locked";
  fs::create_directories(dir / "work");
  const int fd = ::open((dir / "work" / "lock").c_str(), O_RDWR | O_CREAT, 0644);
  ASSERT_GE(fd, 0);
  ASSERT_EQ(::flock(fd, LOCK_EX | LOCK_NB), 0); // as a run in progress holds it
  Launch launch;
  launch.standard_error = (root / "errors.txt").string();
  const int status = wait_for(start_program(tool, recognize(dir, (dir / "work").string()), launch));
  ::close(fd);
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 1);
  EXPECT_NE(read_file(root / "errors.txt").find("another run is using this folder"), std::string::npos);
  EXPECT_FALSE(fs::exists(dir / "objects.ply"));
  // Released: the run goes.
  ASSERT_TRUE(run_tool(recognize(dir, (dir / "work").string())));
  EXPECT_TRUE(read_file(dir / "objects.ply") == objects);
}

#ifdef SHAPE_ANALYSIS_MPIRUN

// The arguments of `mpirun -np ranks` running the tool with `args`, one thread per rank.
std::vector<std::string> with_ranks(int ranks, std::vector<std::string> args)
{
  for(std::size_t k = 0; k + 1 < args.size(); ++k)
    if(args[k] == "--threads")
      args[k + 1] = "1";
  args.insert(args.begin(), {"--allow-run-as-root", "--oversubscribe", "-np", std::to_string(ranks), tool});
  return args;
}

TEST_F(TilesTest, RanksGiveTheSameBytes)
{
  for(int ranks : {2, 3}) {
    const fs::path dir = root / ("ranks" + std::to_string(ranks));
    const std::string errors = (root / "errors.txt").string();
    Launch launch;
    launch.standard_error = errors;
    const int status = wait_for(start_program(SHAPE_ANALYSIS_MPIRUN, with_ranks(ranks, recognize(dir, (dir / "work").string())), launch));
    ASSERT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << read_file(errors);
    EXPECT_TRUE(read_file(dir / "objects.ply") == objects) << ranks << " ranks";
    if(ranks == 3) { // LAS: each rank its records, rank 0 the header of all
      std::vector<std::string> las = recognize(dir, (dir / "work").string());
      las[9] = (dir / "objects.las").string();
      std::vector<std::string> las_in_memory = recognize(root / "las_memory", "");
      las_in_memory[9] = (root / "las_memory" / "objects.las").string();
      ASSERT_TRUE(run_tool(las_in_memory));
      ASSERT_EQ(wait_for(start_program(SHAPE_ANALYSIS_MPIRUN, with_ranks(3, las), launch)), 0) << read_file(errors);
      EXPECT_TRUE(read_file(dir / "objects.las") == read_file(root / "las_memory" / "objects.las"));
    }
    if(ranks == 2) { // --only-objects: each rank's records after those of the ranks before
      std::vector<std::string> only = recognize(dir, (dir / "work").string()), only_in_memory = recognize(root / "only_memory", "");
      only[9] = (dir / "only.ply").string();
      only_in_memory[9] = (root / "only_memory" / "only.ply").string();
      only.push_back("--only-objects");
      only_in_memory.push_back("--only-objects");
      ASSERT_TRUE(run_tool(only_in_memory));
      ASSERT_EQ(wait_for(start_program(SHAPE_ANALYSIS_MPIRUN, with_ranks(2, only), launch)), 0) << read_file(errors);
      EXPECT_TRUE(read_file(dir / "only.ply") == read_file(root / "only_memory" / "only.ply"));
    }
    EXPECT_EQ(read_file(dir / "locations.csv"), locations) << ranks << " ranks";
    const std::string report = read_file(dir / "report.json");
    EXPECT_EQ(report_number(report, "ranks"), ranks);
    // Each rank indexed its part of the scan: tiles' point files of every rank.
    std::vector<int> parts(std::size_t(ranks), 0);
    for(const auto& entry : fs::directory_iterator(dir / "work" / "points"))
      ++parts[std::size_t(std::stoi(entry.path().extension().string().substr(1)))];
    for(int r = 0; r < ranks; ++r)
      EXPECT_GT(parts[std::size_t(r)], 0) << "rank " << r;
  }
}

TEST_F(TilesTest, AFailingRankFailsTheJobWithOneMessage)
{
  const fs::path dir = root / "failing";
  const std::string work = (dir / "work").string(), errors = (root / "errors.txt").string();
  Launch launch;
  launch.standard_error = errors;
  launch.environment.emplace_back("SHAPE_ANALYSIS_FAIL_TILE", "5");
  int status = wait_for(start_program(SHAPE_ANALYSIS_MPIRUN, with_ranks(2, recognize(dir, work)), launch));
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_NE(WEXITSTATUS(status), 0);
  const std::string said = read_file(errors);
  EXPECT_NE(said.find("tile 5: failed on purpose"), std::string::npos) << said;
  EXPECT_EQ(said.find("error"), said.rfind("error")) << said; // one message
  for(const char* output : {"objects.ply", "locations.csv", "report.json"})
    EXPECT_FALSE(fs::exists(dir / output)) << output;
  for(const auto& entry : fs::directory_iterator(dir))
    EXPECT_EQ(entry.path().filename().string().find(".tmp-"), std::string::npos) << entry.path();
  // Run again (without the fault): the finished tiles are reused, the outputs the same bytes.
  launch.environment.clear();
  status = wait_for(start_program(SHAPE_ANALYSIS_MPIRUN, with_ranks(2, recognize(dir, work)), launch));
  ASSERT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << read_file(errors);
  EXPECT_TRUE(read_file(dir / "objects.ply") == objects);
  EXPECT_GT(report_number(read_file(dir / "report.json"), "tiles_reused"), 0);
}

TEST_F(TilesTest, KilledJobsResumeToTheSameBytes)
{
  const fs::path dir = root / "killed";
  const std::string work = (dir / "work").string();
  Launch launch;
  launch.own_group = true;
  launch.standard_error = (root / "errors.txt").string();
  const auto start = std::chrono::steady_clock::now();
  wait_for(start_program(SHAPE_ANALYSIS_MPIRUN, with_ranks(2, recognize(root / "timed", (root / "timed_work").string())), launch));
  const double whole = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::mt19937 random(5);
  std::uniform_real_distribution<double> moment(0.1 * whole, 0.9 * whole);
  for(int kill = 0; kill < 3; ++kill) {
    const pid_t pid = start_program(SHAPE_ANALYSIS_MPIRUN, with_ranks(2, recognize(dir, work)), launch);
    ASSERT_GT(pid, 0);
    std::this_thread::sleep_for(std::chrono::duration<double>(moment(random)));
    ::killpg(pid, SIGKILL); // the whole job: mpirun and its ranks
    wait_for(pid);
  }
  std::this_thread::sleep_for(std::chrono::milliseconds(200)); // ranks already gone or going
  const int status = wait_for(start_program(SHAPE_ANALYSIS_MPIRUN, with_ranks(2, recognize(dir, work)), launch));
  ASSERT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << read_file(root / "errors.txt");
  EXPECT_TRUE(read_file(dir / "objects.ply") == objects);
  EXPECT_EQ(read_file(dir / "locations.csv"), locations);
  std::cout << "after 3 killed jobs, the last reused " << report_number(read_file(dir / "report.json"), "tiles_reused")
            << " tiles\n";
}

#endif

} // namespace
