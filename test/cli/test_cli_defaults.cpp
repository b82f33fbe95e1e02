// Copyright (c) 2026 CGAL Global Shape Analysis contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later

// The command-line tool writes no default of its own: its help and its report follow the
// library's options struct. The subcommand is built with other defaults than the library's and
// run in process; its help and its report must show them.

#include "cli_common.h"

#include <CGAL/Consistent_segmentation/Hierarchical_segmentation_options.h>

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace CS = CGAL::Consistent_segmentation;
namespace cli = shape_analysis_cli;
using cli::Json;

namespace {

// The help line of an option of `segment`, e.g. "-k,--segments UINT:POSITIVE [8]".
std::string help_line(const CS::Hierarchical_segmentation_options& defaults, const std::string& flag)
{
  CLI::App app;
  std::function<int()> run;
  cli::add_segment_command(app, run, defaults);
  std::istringstream help(app.get_subcommand("segment")->help());
  for(std::string line; std::getline(help, line);)
    if(line.find(flag + " ") != std::string::npos)
      return line;
  return "";
}

// Whether a help line shows `v` as the option's default ("=8" or "[8]", by CLI11's version).
bool shows_default(const std::string& line, double v)
{
  std::ostringstream s;
  s << v;
  return line.find("=" + s.str()) != std::string::npos || line.find("[" + s.str() + "]") != std::string::npos;
}

} // namespace

TEST(CliDefaults, SegmentHelpShowsTheLibraryDefaults)
{
  const CS::Hierarchical_segmentation_options library;
  EXPECT_TRUE(shows_default(help_line(library, "--segments"), double(library.number_of_segments)))
    << help_line(library, "--segments");
  EXPECT_TRUE(shows_default(help_line(library, "--concavity-exponent"), library.concavity_exponent));
  EXPECT_TRUE(shows_default(help_line(library, "--prior-factor"), library.prior_boundary_factor));
  EXPECT_TRUE(shows_default(help_line(library, "--link-distance"), library.component_link_distance));
  EXPECT_TRUE(shows_default(help_line(library, "--link-factor"), library.component_link_factor));
}

TEST(CliDefaults, SegmentHelpAndReportFollowAChangedDefault)
{
  CS::Hierarchical_segmentation_options changed;
  changed.number_of_segments = 5;
  changed.concavity_exponent = 7.5;
  changed.component_link_factor = 0.02;
  ASSERT_NE(changed.number_of_segments, CS::Hierarchical_segmentation_options().number_of_segments);
  EXPECT_TRUE(shows_default(help_line(changed, "--segments"), 5)) << help_line(changed, "--segments");
  EXPECT_TRUE(shows_default(help_line(changed, "--concavity-exponent"), 7.5));
  EXPECT_TRUE(shows_default(help_line(changed, "--link-factor"), 0.02));

  const std::filesystem::path report = std::filesystem::path(::testing::TempDir()) / "cli_defaults_report.json";
  CLI::App app;
  std::function<int()> run;
  cli::add_segment_command(app, run, changed);
  app.parse(std::string("segment ") + SHAPE_ANALYSIS_DATA_DIR + "/elephant.off -q --report " + report.string(), false);
  ASSERT_TRUE(bool(run));
  ASSERT_EQ(run(), 0);
  std::ifstream in(report);
  const Json r = Json::parse(in);
  std::filesystem::remove(report);
  EXPECT_EQ(r["segments"].get<std::size_t>(), 5u);
  EXPECT_EQ(r["parameters"]["number_of_segments"].get<std::size_t>(), 5u);
  EXPECT_EQ(r["parameters"]["concavity_exponent"].get<double>(), 7.5);
  EXPECT_EQ(r["parameters"]["component_link_factor"].get<double>(), 0.02);
  EXPECT_EQ(r["parameters"]["prior_boundary_factor"].get<double>(),
            CS::Hierarchical_segmentation_options().prior_boundary_factor);
}
