// Copyright (c) 2026 CGAL Global Shape Analysis contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later

// libFuzzer target of the readers and of the option parsing of shape_analysis (issue 26). One
// binary; the reader is chosen by the environment variable SHAPE_ANALYSIS_FUZZ (scripts/fuzz.sh
// runs each in turn):
//   off, ply_mesh, obj, stl   the tool's mesh reader (read_triangle_mesh()) on a file of that type
//   ply, xyz, las, kitti      read_point_set() on a point file of that type
//   pieces_ply, pieces_las, pieces_kitti
//                             Point_set_file_reader on a point file of that type, every point
//                             read in pieces of 7 (coordinates, properties, records)
//   seg                       the tool's label files
//   locations                 the tool's locations (.csv)
//   truth                     the ground truth of 'points generate' (.json)
//   labels                    labelled objects of 'points train' (.csv)
//   model                     the model files of 'points train' (.json)
//   osm                       read_street_map() (when built with libosmium)
//   command_line              the option parsing, the input split at '\n' into arguments
// A reader may refuse its input with Bad_input or the tool's errors: anything else (a crash, an
// abort, a sanitizer report, an exception of another type, a hang) is a finding.

#include "cli_common.h"
#include "points_common.h"
#include "recognition_files.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Point_set_3.h>
#include <CGAL/Point_set_object_recognition/Point_set_file_reader.h>
#include <CGAL/Point_set_object_recognition/read_point_set.h>
#ifdef CGAL_SHAPE_ANALYSIS_USE_OSMIUM
#include <CGAL/Point_set_object_recognition/read_street_map.h>
#endif
#include <CGAL/Shape_analysis/Bad_input.h>

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <new>
#include <string>
#include <unistd.h>
#include <vector>

namespace {

namespace SAC = shape_analysis_cli;

const std::string& target()
{
  static const std::string t = [] {
    const char* e = std::getenv("SHAPE_ANALYSIS_FUZZ");
    return std::string(e ? e : "off");
  }();
  return t;
}

// The input as a file with the extension the reader expects (one file per process).
std::string as_file(const std::uint8_t* data, std::size_t size, const std::string& extension)
{
  static const std::string base = "/tmp/shape_analysis_fuzz_" + std::to_string(::getpid());
  const std::string path = base + extension;
  std::ofstream(path, std::ios::binary).write(reinterpret_cast<const char*>(data), std::streamsize(size));
  return path;
}

void read_one(const std::uint8_t* data, std::size_t size)
{
  const std::string& t = target();
  if(t == "off" || t == "ply_mesh" || t == "obj" || t == "stl") {
    SAC::read_triangle_mesh(as_file(data, size, "." + (t == "ply_mesh" ? std::string("ply") : t)));
  } else if(t == "ply" || t == "xyz" || t == "las" || t == "kitti") {
    CGAL::Point_set_3<CGAL::Epick::Point_3> points;
    CGAL::Point_set_object_recognition::read_point_set(as_file(data, size, t == "kitti" ? ".bin" : "." + t), points);
  } else if(t == "pieces_ply" || t == "pieces_las" || t == "pieces_kitti") {
    const std::string e = t == "pieces_kitti" ? ".bin" : "." + t.substr(7);
    const CGAL::Point_set_object_recognition::Point_set_file_reader reader(as_file(data, size, e));
    CGAL::Point_set_3<CGAL::Epick::Point_3> points;
    std::vector<double> xyz;
    std::vector<unsigned char> records;
    for(std::uint64_t first = 0; first < reader.number_of_points() && first < 70000; first += 7) {
      const std::size_t count = std::size_t(std::min<std::uint64_t>(7, reader.number_of_points() - first));
      reader.read_coordinates(first, count, xyz);
      reader.read(first, count, points);
      reader.read_records(first, count, records);
    }
  } else if(t == "seg") {
    SAC::read_labels(as_file(data, size, ".seg"));
  } else if(t == "locations") {
    SAC::read_locations_file(as_file(data, size, ".csv"));
  } else if(t == "truth") {
    SAC::read_truth_objects(as_file(data, size, ".json"));
  } else if(t == "labels") {
    SAC::read_labelled_objects(as_file(data, size, ".csv"));
  } else if(t == "model") {
    SAC::read_recognition_model(as_file(data, size, ".json"));
#ifdef CGAL_SHAPE_ANALYSIS_USE_OSMIUM
  } else if(t == "osm") {
    CGAL::Point_set_object_recognition::read_street_map(as_file(data, size, ".osm"), "EPSG:32618", {{583000, 4507000, 0}});
#endif
  } else if(t == "command_line") {
    std::vector<std::string> words{"shape_analysis"};
    std::string word;
    for(std::size_t i = 0; i < size && words.size() < 64; ++i) {
      if(data[i] == '\n') {
        words.push_back(word);
        word.clear();
      } else
        word += char(data[i]);
    }
    words.push_back(word);
    std::vector<char*> argv;
    for(std::string& w : words)
      argv.push_back(&w[0]);
    SAC::run_command_line(int(argv.size()), argv.data(), false);
  } else {
    std::fprintf(stderr, "SHAPE_ANALYSIS_FUZZ: unknown target '%s'\n", t.c_str());
    std::abort();
  }
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  try {
    read_one(data, size);
  } catch(const CGAL::Shape_analysis::Bad_input&) {
  } catch(const SAC::Cli_error&) {
  } catch(const SAC::Usage_error&) {
  } catch(const std::bad_alloc&) {
  }
  return 0;
}
