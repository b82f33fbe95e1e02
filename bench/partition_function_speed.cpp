// Copyright (c) 2026 CGAL Global Shape Analysis contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later

// Running time of the partition function (min-cut sampling), against the thesis's figure of
// 0.6 s per sampled cut and 4 minutes per mesh (400 cuts) at about 4,000 faces.
//
//   bench_partition_function_speed [--samples 400] [--repeats 5] [--faces 4000]
//                                  [--camel FILE] [--armadillo FILE] [--output FILE]
//                                  [--other-samplers N]
//
// camel.off (CGAL's data) is decimated to --faces faces with CGAL's edge-collapse
// (Surface_mesh_simplification, Lindstrom-Turk cost and placement), as the thesis decimated its
// meshes to about 4,000 faces; armadillo.off (52,000 faces) is used at full resolution. Each
// timing is one call of partition_function() (dual graph and links included, file reading and
// decimation excluded), on all cores (TBB) and on one thread; min and median over the repeats.
// With --other-samplers N > 0, the K-means and hierarchical samplers are timed too, with N samples.
// The multi-scale partition function (part sizes 0.02, 0.05, 0.1) is timed on the camel, against
// one single-scale run, and the minimum cuts alone with our max-flow against Boost's.
// JSON to stdout and to FILE; progress to stderr.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/Surface_mesh_simplification/edge_collapse.h>
#include <CGAL/Surface_mesh_simplification/Policies/Edge_collapse/Count_stop_predicate.h>

#include <CGAL/Randomized_cuts/partition_function.h>
#include <CGAL/Shape_analysis/internal/Min_cut.h>
#include <CGAL/Shape_analysis/internal/Random.h>
#include <CGAL/Shape_analysis/internal/Shortest_paths.h>
#include <Shape_analysis_support/Json.h>
#include <CGAL/Shape_analysis/internal/Parallel.h>

#include <boost/graph/adjacency_list.hpp>
#include <boost/graph/boykov_kolmogorov_max_flow.hpp>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <fstream>
#include <functional>
#include <iostream>
#include <string>
#include <thread>
#include <vector>

namespace {

typedef CGAL::Exact_predicates_inexact_constructions_kernel Kernel;
typedef CGAL::Surface_mesh<Kernel::Point_3> Mesh;
typedef Mesh::Edge_index Edge;
namespace SAS = CGAL::Shape_analysis_support;
typedef SAS::Json Json;
namespace RC = CGAL::Randomized_cuts;
namespace SMS = CGAL::Surface_mesh_simplification;

double median(std::vector<double> s)
{
  std::sort(s.begin(), s.end());
  const std::size_t n = s.size();
  return n % 2 ? s[n / 2] : 0.5 * (s[n / 2 - 1] + s[n / 2]);
}

// Times `repeats` calls of partition_function with the given method, samples and threads.
Json time_partition_function(const Mesh& mesh, RC::Sampling_method method, std::size_t samples,
                             std::size_t threads, std::size_t repeats, const std::string& label,
                             double* median_seconds = nullptr)
{
  std::vector<double> seconds;
  std::vector<double> values(num_edges(mesh), 0.0);
  auto value_map = CGAL::make_property_map(values); // indexed by edge index
  double sum = 0;
  for(std::size_t r = 0; r < repeats; ++r) {
    const auto start = std::chrono::steady_clock::now();
    RC::partition_function(mesh, value_map,
                           RC::parameters::sampling_method(method)
                             .number_of_samples(samples)
                             .number_of_threads(threads)
                             .random_seed(static_cast<unsigned int>(r)));
    seconds.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
    sum = 0;
    for(double v : values)
      sum += v;
    std::cerr << "  " << label << " run " << r + 1 << "/" << repeats << ": " << seconds.back()
              << " s\n";
  }
  Json j = Json::object();
  j["samples"] = samples;
  j["threads"] = threads == 0 ? Json("all") : Json(threads);
  j["runs"] = repeats;
  j["min_seconds"] = *std::min_element(seconds.begin(), seconds.end());
  j["median_seconds"] = median(seconds);
  j["seconds"] = seconds;
  j["median_seconds_per_sample"] = median(seconds) / double(samples);
  j["mean_edge_value"] = sum / double(values.size());
  if(median_seconds != nullptr)
    *median_seconds = median(seconds);
  return j;
}

// The minimum cuts of `samples` min-cut samples (random face pairs, penalties of part size 0.05)
// on the dual graph of `mesh`, solved on one thread by our Boykov-Kolmogorov (no terminal arcs,
// buffers reused) and by Boost's boykov_kolmogorov_max_flow on an adjacency list of the same
// arcs (between the two faces themselves). Distances and capacities
// are computed once, outside the timings; the two flows must agree.
Json compare_max_flows(const Mesh& mesh, std::size_t samples)
{
  namespace SAI = CGAL::Shape_analysis::internal;
  typedef CGAL::Shape_analysis::parameters::Default_named_parameters Defaults;
  const Defaults defaults;
  const RC::internal::Mesh_sampling<Mesh, Defaults> sampling(mesh, defaults, "bench");
  const SAI::Dual_graph& g = sampling.graph();
  const std::size_t n = g.number_of_nodes(), m = g.number_of_edges();
  std::vector<std::vector<double>> capacity(samples, std::vector<double>(m));
  std::vector<std::pair<std::uint32_t, std::uint32_t>> pair(samples);
  SAI::Graph_shortest_paths from_a, from_b;
  for(std::size_t i = 0; i < samples; ++i) {
    SAI::Random_stream rng(1, i);
    const auto a = static_cast<std::uint32_t>(rng.index(n));
    auto b = static_cast<std::uint32_t>(rng.index(n - 1));
    b += b >= a ? 1 : 0;
    pair[i] = {a, b};
    from_a.run(g, g.traversal_cost, a);
    from_b.run(g, g.traversal_cost, b);
    for(std::size_t e = 0; e < m; ++e) {
      const std::uint32_t u = g.edge_source[e], v = g.edge_target[e];
      const double da = 0.5 * (from_a.distance(u) + from_a.distance(v));
      const double db = 0.5 * (from_b.distance(u) + from_b.distance(v));
      const double d = da + db > 0 ? (std::min)(da, db) / (da + db) : 0.5;
      capacity[i][e] = g.cut_cost[e] * RC::internal::seed_distance_penalty(d, 0.05);
    }
  }
  std::vector<double> ours(samples), boost_flow(samples);
  const auto start_ours = std::chrono::steady_clock::now();
  {
    SAI::Dual_graph_min_cut cut(g);
    SAI::Dual_graph_min_cut::Workspace w;
    for(std::size_t i = 0; i < samples; ++i)
      ours[i] = cut.solve(capacity[i], pair[i].first, pair[i].second, w);
  }
  const double ours_seconds =
    std::chrono::duration<double>(std::chrono::steady_clock::now() - start_ours).count();
  const auto start_boost = std::chrono::steady_clock::now();
  {
    // Boost's Boykov-Kolmogorov on an adjacency list: one arc each way per edge, built once.
    typedef boost::adjacency_list_traits<boost::vecS, boost::vecS, boost::directedS> Traits;
    typedef boost::adjacency_list<
      boost::vecS, boost::vecS, boost::directedS,
      boost::property<boost::vertex_color_t, boost::default_color_type,
                      boost::property<boost::vertex_distance_t, long,
                                      boost::property<boost::vertex_predecessor_t, Traits::edge_descriptor>>>,
      boost::property<boost::edge_capacity_t, double,
                      boost::property<boost::edge_residual_capacity_t, double,
                                      boost::property<boost::edge_reverse_t, Traits::edge_descriptor>>>>
      Bk_graph;
    Bk_graph bg(n);
    auto cap = get(boost::edge_capacity, bg);
    auto rev = get(boost::edge_reverse, bg);
    std::vector<std::pair<Traits::edge_descriptor, Traits::edge_descriptor>> arcs(m);
    for(std::size_t e = 0; e < m; ++e) {
      const auto a = boost::add_edge(g.edge_source[e], g.edge_target[e], bg).first;
      const auto b = boost::add_edge(g.edge_target[e], g.edge_source[e], bg).first;
      rev[a] = b, rev[b] = a;
      arcs[e] = {a, b};
    }
    for(std::size_t i = 0; i < samples; ++i) {
      for(std::size_t e = 0; e < m; ++e)
        cap[arcs[e].first] = cap[arcs[e].second] = capacity[i][e];
      boost_flow[i] = boost::boykov_kolmogorov_max_flow(bg, boost::vertex(pair[i].first, bg), boost::vertex(pair[i].second, bg));
    }
  }
  const double boost_seconds =
    std::chrono::duration<double>(std::chrono::steady_clock::now() - start_boost).count();
  double largest_difference = 0;
  for(std::size_t i = 0; i < samples; ++i)
    largest_difference = (std::max)(largest_difference,
                                    std::abs(ours[i] - boost_flow[i]) / (std::max)(1e-300, boost_flow[i]));
  Json j = Json::object();
  j["cuts"] = samples;
  j["threads"] = 1;
  j["ours_seconds"] = ours_seconds;
  j["boost_boykov_kolmogorov_seconds"] = boost_seconds;
  j["boost_over_ours"] = boost_seconds / ours_seconds;
  j["largest_relative_flow_difference"] = largest_difference;
  std::cerr << "  max-flow, " << samples << " cuts on one thread: ours " << ours_seconds
            << " s, Boost " << boost_seconds << " s\n";
  return j;
}

bool read_mesh(const std::string& file, Mesh& mesh)
{
  return CGAL::IO::read_polygon_mesh(file, mesh) && !faces(mesh).empty() && is_triangle_mesh(mesh);
}

} // namespace

int main(int argc, char** argv)
{
  std::string camel = std::string(SHAPE_ANALYSIS_DATA_DIR) + "/camel.off";
  std::string armadillo = std::string(SHAPE_ANALYSIS_DATA_DIR) + "/armadillo.off";
  std::string output;
  std::size_t samples = 400, repeats = 5, target_faces = 4000, other = 0;
  for(int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    auto value = [&]() -> std::string {
      if(i + 1 >= argc) {
        std::cerr << "missing value after " << arg << '\n';
        std::exit(EXIT_FAILURE);
      }
      return argv[++i];
    };
    if(arg == "--samples")
      samples = std::stoul(value());
    else if(arg == "--repeats")
      repeats = std::max<std::size_t>(1, std::stoul(value()));
    else if(arg == "--faces")
      target_faces = std::stoul(value());
    else if(arg == "--camel")
      camel = value();
    else if(arg == "--armadillo")
      armadillo = value();
    else if(arg == "--other-samplers")
      other = std::stoul(value());
    else if(arg == "--output")
      output = value();
    else {
      std::cerr << "usage: " << argv[0]
                << " [--samples 400] [--repeats 5] [--faces 4000] [--camel FILE]"
                   " [--armadillo FILE] [--other-samplers N] [--output FILE]\n";
      return arg == "--help" ? EXIT_SUCCESS : EXIT_FAILURE;
    }
  }

  Json report = Json::object();
  report["benchmark"] = "partition_function_speed";
  report["hardware_threads"] = std::thread::hardware_concurrency();
  report["tbb"] = CGAL::Shape_analysis::internal::parallel_available();
  Json thesis = Json::object();
  thesis["seconds_per_min_cut_sample"] = 0.6;
  thesis["seconds_per_mesh_400_samples"] = 240.0;
  thesis["faces"] = 4000;
  report["thesis"] = thesis;

  // camel, decimated with CGAL's edge collapse.
  Mesh mesh;
  if(!read_mesh(camel, mesh)) {
    std::cerr << "cannot read " << camel << '\n';
    return EXIT_FAILURE;
  }
  const std::size_t original_faces = num_faces(mesh);
  const auto decimate_start = std::chrono::steady_clock::now();
  // A closed triangle mesh has 3/2 edges per face.
  SMS::Count_stop_predicate<Mesh> stop(target_faces * 3 / 2);
  SMS::edge_collapse(mesh, stop);
  mesh.collect_garbage();
  const double decimate_seconds =
    std::chrono::duration<double>(std::chrono::steady_clock::now() - decimate_start).count();
  std::cerr << camel << ": " << original_faces << " faces decimated to " << num_faces(mesh)
            << " in " << decimate_seconds << " s\n";

  Json camel_json = Json::object();
  camel_json["input"] = camel;
  camel_json["original_faces"] = original_faces;
  camel_json["faces"] = num_faces(mesh);
  camel_json["decimation"] = "CGAL::Surface_mesh_simplification::edge_collapse, Count_stop_predicate, "
                             "Lindstrom-Turk";
  camel_json["decimation_seconds"] = decimate_seconds;
  double all_median = 0;
  Json all = time_partition_function(mesh, RC::MIN_CUT, samples, 0, repeats,
                                     "camel min-cut all threads", &all_median);
  Json one = time_partition_function(mesh, RC::MIN_CUT, samples, 1, repeats, "camel min-cut 1 thread");
  const double ours_per_sample = all_median / double(samples);
  camel_json["min_cut_all_threads"] = all;
  camel_json["min_cut_one_thread"] = one;
  camel_json["speedup_over_thesis_per_sample"] = 0.6 / ours_per_sample;
  // Multi-scale: three part sizes from one set of seeds and distances, against three runs.
  {
    const std::vector<double> sizes = {0.02, 0.05, 0.1};
    std::vector<std::vector<double>> multi(num_edges(mesh));
    std::vector<double> seconds;
    for(std::size_t r = 0; r < repeats; ++r) {
      const auto start = std::chrono::steady_clock::now();
      RC::multiscale_partition_function(mesh, CGAL::make_property_map(multi),
                                        RC::parameters::part_sizes(sizes)
                                          .number_of_samples(samples)
                                          .random_seed(static_cast<unsigned int>(r)));
      seconds.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
    }
    Json m = Json::object();
    m["part_sizes"] = sizes;
    m["samples"] = samples;
    m["median_seconds"] = median(seconds);
    m["median_seconds_three_single_runs"] = 3 * all_median;
    m["cost_relative_to_one_single_run"] = median(seconds) / all_median;
    camel_json["multiscale_all_threads"] = m;
    std::cerr << "  camel multi-scale (3 part sizes): " << median(seconds) << " s\n";
  }
  camel_json["max_flow_only"] = compare_max_flows(mesh, samples);
  if(other > 0) {
    camel_json["k_means_all_threads"] =
      time_partition_function(mesh, RC::K_MEANS, other, 0, 1, "camel k-means");
    camel_json["hierarchical_all_threads"] =
      time_partition_function(mesh, RC::HIERARCHICAL, other, 0, 1, "camel hierarchical");
  }
  report["camel_decimated"] = camel_json;

  Mesh big;
  if(read_mesh(armadillo, big)) {
    Json a = Json::object();
    a["input"] = armadillo;
    a["faces"] = num_faces(big);
    a["min_cut_all_threads"] = time_partition_function(big, RC::MIN_CUT, samples, 0,
                                                       std::min<std::size_t>(repeats, 3),
                                                       "armadillo min-cut all threads");
    if(other > 0) {
      a["k_means_all_threads"] = time_partition_function(big, RC::K_MEANS, other, 0, 1, "armadillo k-means");
      a["hierarchical_all_threads"] =
        time_partition_function(big, RC::HIERARCHICAL, other, 0, 1, "armadillo hierarchical");
    }
    report["armadillo"] = a;
  } else {
    report["armadillo"] = "cannot read " + armadillo;
  }

  const std::string text = SAS::to_text(report);
  std::cout << text << '\n';
  if(!output.empty()) {
    std::ofstream out(output);
    out << text << '\n';
  }
  return EXIT_SUCCESS;
}
