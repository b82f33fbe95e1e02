// Copyright (c) 2026 CGAL Global Shape Analysis contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later

// The command line of shape_analysis, the tool of CGAL Global Shape Analysis: parsing, checks of
// the values, the run and its exit code (0 success, 1 the job failed: bad input, unreadable
// file...; 2 bad command line). main() is in shape_analysis.cpp; the fuzzer of the option parsing
// calls run_command_line() without running the job.

#include "cli_common.h"
#include "ranks.h"

#include <CGAL/Shape_analysis/Bad_input.h>

#include <algorithm>
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

// What is wrong with the first bad value of the parsed command line, or an empty string: an empty
// value ("-o ''": never meant, and it would read as "not given"), or a value of an unsigned option
// that is not a whole number >= 0 within 64 bits ("--seed -3" wrapped around to
// 18446744073709551613, an overflow read as the largest value).
std::string bad_option_value(const CLI::App& app)
{
  for(const CLI::Option* o : app.get_options()) {
    if(o->count() == 0)
      continue;
    const bool unsigned_option = o->get_type_name().compare(0, 4, "UINT") == 0;
    for(const std::string& r : o->results()) {
      if(r.empty() && o->get_expected_min() > 0)
        return o->get_name() + " is given an empty value";
      if(!unsigned_option)
        continue;
      if(r.empty() || r.find_first_not_of("0123456789") != std::string::npos)
        return o->get_name() + ": '" + r + "' is not a whole number >= 0";
      const std::size_t first = (std::min)(r.find_first_not_of('0'), r.size());
      if(r.size() - first > 20 || (r.size() - first == 20 && r.compare(first, 20, "18446744073709551615") > 0))
        return o->get_name() + ": " + r + " is too large (at most 18446744073709551615)";
    }
  }
  for(const CLI::App* sub : app.get_subcommands()) {
    const std::string m = bad_option_value(*sub);
    if(!m.empty())
      return m;
  }
  return std::string();
}

// A message for a word of the command line that should name a subcommand and does not
// ("shape_analysis frobnicate", "shape_analysis points frobnicate"), or an empty string.
std::string unknown_subcommand(CLI::App& app, int argc, char** argv)
{
  CLI::App* current = &app;
  std::string path = "shape_analysis";
  for(int i = 1; i < argc; ++i) {
    const std::string word = argv[i];
    if(word.empty() || word[0] == '-')
      return std::string();
    CLI::App* sub = nullptr;
    for(CLI::App* s : current->get_subcommands({}))
      if(s->check_name(word))
        sub = s;
    if(sub == nullptr) {
      if(current->get_require_subcommand_min() == 0)
        return std::string();
      std::string names;
      for(CLI::App* s : current->get_subcommands({}))
        names += (names.empty() ? "" : ", ") + s->get_name();
      return "unknown subcommand '" + word + "' of " + path + " (one of: " + names + ")";
    }
    current = sub;
    path += " " + sub->get_name();
  }
  return std::string();
}

} // namespace

namespace shape_analysis_cli {

int run_command_line(int argc, char** argv, bool execute)
{
  CLI::App app{"shape_analysis: global shape analysis of triangle meshes and point clouds "
               "(CGAL Global Shape Analysis)"};
  app.require_subcommand(1);
  app.set_version_flag("--version", "shape_analysis 0.1.0");
  std::function<int()> run;
  add_segment_command(app, run);
  add_register_command(app, run);
  add_deform_command(app, run);
  add_partition_commands(app, run);
  add_coseg_command(app, run);
  add_symmetry_command(app, run);
  add_points_command(app, run);

  const std::string unknown = unknown_subcommand(app, argc, argv);
  // Under mpirun every rank runs the command; one of them (rank 0) says what went wrong.
  const Ranks& ranks = Ranks::world();
  const bool speaks = ranks.rank() == 0;
  if(!unknown.empty()) {
    if(speaks)
      std::cerr << "shape_analysis: error: " << unknown << " (see shape_analysis --help)" << std::endl;
    return 2;
  }
  try {
    app.parse(argc, argv);
  } catch(const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch(const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch(const CLI::CallForVersion& e) {
    return app.exit(e);
  } catch(const CLI::ParseError& e) {
    if(speaks)
      std::cerr << "shape_analysis: error: " << one_line(e.what()) << " (see shape_analysis --help)" << std::endl;
    return 2;
  }
  const std::string bad_value = bad_option_value(app);
  if(!bad_value.empty()) {
    if(speaks)
      std::cerr << "shape_analysis: error: " << bad_value << std::endl;
    return 2;
  }

  if(!execute)
    return run ? 0 : 2;
  const std::string command = app.get_subcommands().empty() ? std::string("shape_analysis")
                                                            : app.get_subcommands().front()->get_name();
  const auto fail = [&](const std::string& what, int status) {
    if(speaks)
      std::cerr << "shape_analysis " << command << ": error: " << one_line(what) << std::endl;
    return status;
  };
  const CLI::App* points = app.get_subcommands().empty() ? nullptr : app.get_subcommands().front();
  if(ranks.size() > 1 && !(command == "points" && !points->get_subcommands().empty() &&
                           points->get_subcommands().front()->get_name() == "recognize"))
    return fail("only 'points recognize --work-dir' runs on several MPI ranks", 2);
  try {
    return run ? run() : 2;
  } catch(const CGAL::Shape_analysis::Bad_input& e) {
    return fail(e.what(), 1);
  } catch(const Usage_error& e) {
    return fail(e.what(), 2);
  } catch(const Cli_error& e) {
    return fail(e.what(), 1);
  } catch(const std::bad_alloc&) {
    return fail("out of memory", 1);
  } catch(const std::exception& e) {
    return fail(e.what(), 1);
  }
}

} // namespace shape_analysis_cli
