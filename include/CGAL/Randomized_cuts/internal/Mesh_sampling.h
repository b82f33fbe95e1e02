// Copyright (c) 2026 CGAL Global Shape Analysis contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_RANDOMIZED_CUTS_INTERNAL_MESH_SAMPLING_H
#define CGAL_RANDOMIZED_CUTS_INTERNAL_MESH_SAMPLING_H

// The options of the partition function, and the sampling of a mesh's dual graph (with links
// between its connected components) that the public functions share.

#include <CGAL/Randomized_cuts/Partition_function_options.h>
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

// The sampling options of `o`, with the part sizes of `np` if it gives `part_sizes` (one part size
// for every function but multiscale_partition_function(), which checks the number).
template <typename NamedParameters>
Sampling_options sampling_options(const Partition_function_options& o, const NamedParameters& np)
{
  Sampling_options s(o);
  s.part_sizes = SAI::parameter_value(np, snp::part_sizes_tag, s.part_sizes);
  return s;
}

// The sampling options of `np` (the defaults of Partition_function_options for the others).
template <typename NamedParameters>
Sampling_options sampling_options(const NamedParameters& np)
{
  return sampling_options(partition_function_options(np), np);
}

// The options of the links between connected components.
inline SAI::Component_link_options link_options(const Partition_function_options& po,
                                                const std::string& who)
{
  SAI::Component_link_options o;
  o.link_distance = po.component_link_distance;
  o.factor = po.component_link_factor;
  if(!(o.link_distance >= 0) || !std::isfinite(o.link_distance))
    throw CGAL::Shape_analysis::Bad_input(who + ": component_link_distance must be a finite number >= 0");
  if(!(o.factor > 0) || !std::isfinite(o.factor))
    throw CGAL::Shape_analysis::Bad_input(who + ": component_link_factor must be a finite number > 0");
  return o;
}

// The dual graph of a mesh, linked into one piece, and its sampling options. `mesh_np` gives the
// maps of the mesh (vertex_point_map, geom_traits, face_index_map); `o` the options.
template <typename TriangleMesh, typename NamedParameters>
struct Mesh_sampling
{
  SAI::Mesh_dual_graph<TriangleMesh, NamedParameters> mesh_graph;
  Sampling_options options;

  Mesh_sampling(const TriangleMesh& tm, const NamedParameters& mesh_np, const Sampling_options& o,
                const std::string& who)
    : mesh_graph(tm, mesh_np, o.concavity_exponent, who), options(o)
  {
    const SAI::Component_link_options links = link_options(options, who);
    check_sampling_options(options, mesh_graph.graph.number_of_nodes(), who);
    SAI::add_component_links(mesh_graph.graph, links);
  }

  // The maps and the options of `np`.
  Mesh_sampling(const TriangleMesh& tm, const NamedParameters& np, const std::string& who)
    : Mesh_sampling(tm, np, sampling_options(np), who)
  {}

  const Dual_graph& graph() const { return mesh_graph.graph; }

  Sampling_result run() const { return Cut_sampling(mesh_graph.graph, options).run(); }
};

} // namespace internal
} // namespace Randomized_cuts
} // namespace CGAL

#endif // CGAL_RANDOMIZED_CUTS_INTERNAL_MESH_SAMPLING_H
