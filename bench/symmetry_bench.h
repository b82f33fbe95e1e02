// Copyright (c) 2026 CGAL Global Shape Analysis contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_SHAPE_ANALYSIS_BENCH_SYMMETRY_BENCH_H
#define CGAL_SHAPE_ANALYSIS_BENCH_SYMMETRY_BENCH_H

// What the two symmetry benchmark programs share: the mesh type, timing, reading the command line
// and writing the report.

#include "bench_util.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <Shape_analysis_support/Json.h>

#include <chrono>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

namespace symmetry_bench {

typedef CGAL::Exact_predicates_inexact_constructions_kernel Kernel;
typedef Kernel::Point_3 Point;
typedef CGAL::Surface_mesh<Point> Mesh;
namespace SAI = CGAL::Shape_analysis::internal;
namespace SAS = CGAL::Shape_analysis_support;
typedef SAS::Json Json;

using bench_util::seconds_since;
using bench_util::split;

// Walks argv: `flag()` is the current option, `value()` the one after it (exits with status 2
// when it is missing).
class Arguments
{
public:
  Arguments(int argc, char** argv) : m_argc(argc), m_argv(argv) {}
  bool next() { return ++m_i < m_argc; }
  std::string flag() const { return m_argv[m_i]; }
  std::string value()
  {
    if(m_i + 1 >= m_argc) {
      std::cerr << "missing value after " << flag() << "\n";
      std::exit(2);
    }
    return m_argv[++m_i];
  }

private:
  int m_argc;
  char** m_argv;
  int m_i = 0;
};

inline void write_report(const Json& result, const std::string& output)
{
  const std::string text = SAS::to_text(result);
  std::cout << text << std::endl;
  if(!output.empty())
    std::ofstream(output) << text << std::endl;
}

} // namespace symmetry_bench

#endif
