// Copyright (c) 2026 CGAL Global Shape Analysis contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_RANDOMIZED_CUTS_INTERNAL_MESH_SAMPLING_H
#define CGAL_RANDOMIZED_CUTS_INTERNAL_MESH_SAMPLING_H

// The named parameters of the partition function, and the sampling of a mesh's dual graph (with
// links between its connected components) that the public functions share.

#include <CGAL/Randomized_cuts/internal/Cut_sampling.h>
#include <CGAL/Shape_analysis/parameters.h>
#include <CGAL/Shape_analysis/internal/Component_links.h>
#include <CGAL/Shape_analysis/internal/Mesh_dual_graph.h>

#include <cmath>
#include <functional>
#include <string>
#include <type_traits>
#include <vector>

namespace CGAL {
namespace Randomized_cuts {
namespace internal {

namespace snp = CGAL::Shape_analysis::internal_np;

// Reads the sampling options of `np` (defaults of the thesis).
template <typename NamedParameters>
Sampling_options sampling_options(const NamedParameters& np, const std::string& who)
{
  using SAI::parameter_value;
  using CGAL::parameters::get_parameter;
  Sampling_options o;
  o.method = parameter_value<Sampling_method>(np, snp::sampling_method_tag, MIN_CUT);
  o.number_of_samples =
    parameter_value<std::size_t>(np, CGAL::internal_np::number_of_samples, std::size_t(400));
  o.convergence_tolerance = parameter_value<double>(np, snp::convergence_tolerance_tag, 0.0);
  o.seed = parameter_value<std::uint64_t>(np, CGAL::internal_np::random_seed, std::uint64_t(0));
  const double part_size = parameter_value<double>(np, snp::part_size_tag, 0.05);
  o.part_sizes = parameter_value<std::vector<double>>(np, snp::part_sizes_tag,
                                                     std::vector<double>{part_size});
  o.number_of_clusters =
    parameter_value<std::size_t>(np, snp::number_of_clusters_tag, std::size_t(10));
  o.randomness = parameter_value<double>(np, snp::randomness_tag, 0.02);
  o.score_weighting = parameter_value<bool>(np, snp::score_weighting_tag, false);
  o.number_of_threads = parameter_value<std::size_t>(np, snp::number_of_threads_tag, std::size_t(0));
  o.progress = parameter_value<std::function<void(double)>>(np, snp::progress_callback_tag,
                                                           std::function<void(double)>());
  (void)who;
  return o;
}

// The options of the links between connected components.
template <typename NamedParameters>
SAI::Component_link_options link_options(const NamedParameters& np, const std::string& who)
{
  SAI::Component_link_options o;
  o.link_distance = SAI::parameter_value<double>(np, snp::component_link_distance_tag, 0.1);
  o.factor = SAI::parameter_value<double>(np, snp::component_link_factor_tag, 0.01);
  if(!(o.link_distance >= 0) || !std::isfinite(o.link_distance))
    throw CGAL::Shape_analysis::Bad_input(who + ": component_link_distance must be a finite number >= 0");
  if(!(o.factor > 0) || !std::isfinite(o.factor))
    throw CGAL::Shape_analysis::Bad_input(who + ": component_link_factor must be a finite number > 0");
  return o;
}

// The dual graph of a mesh, linked into one piece, and its sampling options.
template <typename TriangleMesh, typename NamedParameters>
struct Mesh_sampling
{
  SAI::Mesh_dual_graph<TriangleMesh, NamedParameters> mesh_graph;
  Sampling_options options;

  Mesh_sampling(const TriangleMesh& tm, const NamedParameters& np, const std::string& who)
    : mesh_graph(tm, np, who), options(sampling_options(np, who))
  {
    const SAI::Component_link_options links = link_options(np, who);
    check_sampling_options(options, mesh_graph.graph.number_of_nodes(), who);
    SAI::add_component_links(mesh_graph.graph, links);
  }

  const Dual_graph& graph() const { return mesh_graph.graph; }

  Sampling_result run() const { return Cut_sampling(mesh_graph.graph, options).run(); }
};

} // namespace internal
} // namespace Randomized_cuts
} // namespace CGAL

#endif // CGAL_RANDOMIZED_CUTS_INTERNAL_MESH_SAMPLING_H
