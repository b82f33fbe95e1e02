// Copyright (c) 2026 CGAL Global Shape Analysis contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later

// shape_analysis: the command-line tool of CGAL Global Shape Analysis.
// Exit codes: 0 success, 1 the job failed (bad input, unreadable file...), 2 bad command line.

#include "cli_common.h"

#include <CGAL/Shape_analysis/Bad_input.h>

#include <iostream>
#include <string>

namespace {

std::string one_line(std::string s)
{
  for(char& c : s)
    if(c == '\n' || c == '\r')
      c = ' ';
  while(!s.empty() && s.back() == ' ')
    s.pop_back();
  return s;
}

// The first option of the parsed command line given an empty value ("-o ''"), or null: an
// empty file name or number is never meant, and would otherwise read as "not given".
const CLI::Option* option_with_empty_value(const CLI::App& app)
{
  for(const CLI::Option* o : app.get_options())
    if(o->count() > 0 && o->get_expected_min() > 0)
      for(const std::string& r : o->results())
        if(r.empty())
          return o;
  for(const CLI::App* sub : app.get_subcommands())
    if(const CLI::Option* o = option_with_empty_value(*sub))
      return o;
  return nullptr;
}

} // namespace

int main(int argc, char** argv)
{
  using namespace shape_analysis_cli;
  CLI::App app{"shape_analysis: global shape analysis of triangle meshes and point clouds "
               "(CGAL Global Shape Analysis)"};
  app.require_subcommand(1);
  app.set_version_flag("--version", "shape_analysis 0.1.0");
  std::function<int()> run;
  add_segment_command(app, run);
  add_register_command(app, run);
  add_partition_commands(app, run);
  add_coseg_command(app, run);
  add_symmetry_command(app, run);
  add_points_command(app, run);

  try {
    app.parse(argc, argv);
  } catch(const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch(const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch(const CLI::CallForVersion& e) {
    return app.exit(e);
  } catch(const CLI::ParseError& e) {
    std::cerr << "shape_analysis: error: " << one_line(e.what())
              << " (see shape_analysis --help)" << std::endl;
    return 2;
  }
  if(const CLI::Option* o = option_with_empty_value(app)) {
    std::cerr << "shape_analysis: error: " << o->get_name() << " is given an empty value" << std::endl;
    return 2;
  }

  const std::string command = app.get_subcommands().empty() ? std::string("shape_analysis")
                                                            : app.get_subcommands().front()->get_name();
  try {
    return run ? run() : 2;
  } catch(const CGAL::Shape_analysis::Bad_input& e) {
    std::cerr << "shape_analysis " << command << ": error: " << one_line(e.what()) << std::endl;
  } catch(const Usage_error& e) {
    std::cerr << "shape_analysis " << command << ": error: " << one_line(e.what()) << std::endl;
    return 2;
  } catch(const Cli_error& e) {
    std::cerr << "shape_analysis " << command << ": error: " << one_line(e.what()) << std::endl;
  } catch(const std::bad_alloc&) {
    std::cerr << "shape_analysis " << command << ": error: out of memory" << std::endl;
  } catch(const std::exception& e) {
    std::cerr << "shape_analysis " << command << ": error: " << one_line(e.what()) << std::endl;
  }
  return 1;
}
