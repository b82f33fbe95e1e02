// Copyright (c) 2026 CGAL Global Shape Analysis contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later

// The partition function on the Princeton Segmentation Benchmark subset in ../shared/data/psb:
//  - segmentation: Rand Index error of segment_with_partition_function, beside
//    hierarchical_segmentation and CGAL's SDF segmentation (default parameters) run on the same
//    meshes in the same process (K = the most frequent human segment count; with --segments auto
//    the two segmentations choose it, SDF keeps the human count);
//  - edge prediction: how well the partition function of the whole mesh predicts the edges where
//    people cut (an edge is positive when some human segmentation separates its two faces), beside
//    local concavity (the dihedral angle, positive when concave, negative when convex): ROC AUC and
//    precision of the top 2% of the edges.
//
//   bench_partition_function_psb [--ids 1,2,21-28] [--classes Human,Cup] [--psb DIR]
//       [--samples 400] [--method mincut|kmeans|hierarchical] [--part-size 0.05] [--clusters 10]
//       [--randomness 0.02] [--no-segmentation] [--segments auto] [--no-hierarchical] [--no-sdf]
//       [--edge-variants] [--output FILE]
//
// The partition function whose edge prediction is measured is the one of the chosen sampler, by
// default the library's (partition_function()'s default); the segmentation always samples min-cuts
// (its own default), and with --method mincut its whole-mesh values are the ones measured.
// --edge-variants implies --method mincut. --edge-variants also
// measures the three samplers, their mean, the mean over three part sizes, values spread by one or
// two rings of faces, and global values whose ties are ordered by the local concavity.
// Averages as the benchmark does: per mesh (over its human segmentations), then per class, then
// over classes. JSON to stdout (and to FILE, rewritten after every mesh); progress to stderr.

#include "edge_prediction.h"
#include "psb_io.h"

#include <CGAL/mesh_segmentation.h>

#include <CGAL/Consistent_segmentation/hierarchical_segmentation.h>
#include <CGAL/Randomized_cuts/partition_function.h>
#include <CGAL/Randomized_cuts/segment_with_partition_function.h>
#include <Shape_analysis_support/Json.h>

#include <chrono>
#include <cstdlib>
#include <map>
#include <string>
#include <vector>

namespace {

using psb::Mesh;
typedef Mesh::Face_index Face;
typedef Mesh::Edge_index Edge;
namespace SAS = CGAL::Shape_analysis_support;
typedef SAS::Json Json;
namespace RC = CGAL::Randomized_cuts;
namespace CS = CGAL::Consistent_segmentation;

using bench_util::seconds_since;

// Labels of a face map as a vector in face-index order.
template <typename Map>
std::vector<std::size_t> labels_of(const Mesh& mesh, const Map& map)
{
  std::vector<std::size_t> labels(mesh.number_of_faces());
  for(Face f : faces(mesh))
    labels[f.idx()] = static_cast<std::size_t>(map[f]);
  return labels;
}

// The signed dihedral angle of every interior edge: positive when concave (the normals converge),
// negative when convex. Orientation as the file gives it (the PSB meshes are oriented outwards).
double signed_dihedral(const Mesh& mesh, Edge e)
{
  const auto h = halfedge(e, mesh), o = opposite(h, mesh);
  const Face f = face(h, mesh), g = face(o, mesh);
  auto normal = [&](Face x) {
    const auto hx = halfedge(x, mesh);
    const auto& p = mesh.point(source(hx, mesh));
    const auto& q = mesh.point(target(hx, mesh));
    const auto& r = mesh.point(target(next(hx, mesh), mesh));
    auto n = CGAL::cross_product(q - p, r - p);
    const double l = std::sqrt(CGAL::to_double(n.squared_length()));
    return l > 0 ? n / l : n;
  };
  auto centroid = [&](Face x) {
    const auto hx = halfedge(x, mesh);
    return CGAL::centroid(mesh.point(source(hx, mesh)), mesh.point(target(hx, mesh)),
                          mesh.point(target(next(hx, mesh), mesh)));
  };
  const auto nf = normal(f), ng = normal(g);
  const double c = std::clamp(CGAL::to_double(nf * ng), -1.0, 1.0);
  const double angle = std::acos(c);
  const bool concave = CGAL::to_double((ng - nf) * (centroid(g) - centroid(f))) < 0;
  return concave ? angle : -angle;
}

// Each round, an edge takes the largest value among the edges of its two faces: values spread
// by one ring of faces per round (a cut made one ring away from an edge then counts for it).
std::vector<double> dilate(const Mesh& mesh, std::vector<double> values, int rounds)
{
  std::vector<double> face_value(mesh.number_of_faces());
  for(int r = 0; r < rounds; ++r) {
    for(Face f : faces(mesh)) {
      double v = 0;
      for(auto h : halfedges_around_face(halfedge(f, mesh), mesh))
        v = (std::max)(v, values[edge(h, mesh).idx()]);
      face_value[f.idx()] = v;
    }
    for(Edge e : edges(mesh)) {
      double v = values[e.idx()];
      for(auto h : {halfedge(e, mesh), opposite(halfedge(e, mesh), mesh)})
        if(!is_border(h, mesh))
          v = (std::max)(v, face_value[face(h, mesh).idx()]);
      values[e.idx()] = v;
    }
  }
  return values;
}

struct Class_sums
{
  std::map<std::string, double> sum;
  std::map<std::string, std::size_t> count;
  void add(const std::string& key, double v)
  {
    sum[key] += v;
    ++count[key];
  }
};

void usage(const char* name)
{
  std::cerr << "usage: " << name
            << " [--ids 1,2,21-28] [--classes Human,Cup] [--psb DIR] [--samples 400]"
               " [--method mincut|kmeans|hierarchical] [--part-size 0.05] [--clusters 10] [--randomness 0.02]"
               " [--no-segmentation] [--segments auto]"
               " [--no-hierarchical] [--no-sdf] [--edge-variants] [--output FILE]\n";
}

} // namespace

int main(int argc, char** argv)
{
  std::set<std::string> classes;
  std::set<int> ids;
  std::string output;
  std::filesystem::path psb_dir = SHAPE_ANALYSIS_PSB_DIR;
  std::size_t samples = 400;
  double part_size = 0.05, randomness = 0.02;
  std::size_t clusters = 10;
  RC::Sampling_method method = RC::Partition_function_options().sampling_method; // the library's
  std::string method_name = method == RC::MIN_CUT ? "mincut" : method == RC::K_MEANS ? "kmeans" : "hierarchical";
  bool with_segmentation = true, with_hierarchical = true, with_sdf = true, edge_variants = false;
  bool automatic = false; // --segments auto: both segmentations choose their number of segments
  for(int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    auto value = [&]() -> std::string {
      if(i + 1 >= argc) {
        usage(argv[0]);
        std::exit(EXIT_FAILURE);
      }
      return argv[++i];
    };
    if(arg == "--classes")
      for(const std::string& c : psb::split(value()))
        classes.insert(psb::lower(c));
    else if(arg == "--ids") {
      if(!psb::parse_ids(value(), ids)) {
        usage(argv[0]);
        return EXIT_FAILURE;
      }
    } else if(arg == "--psb")
      psb_dir = value();
    else if(arg == "--output")
      output = value();
    else if(arg == "--samples")
      samples = std::stoul(value());
    else if(arg == "--part-size")
      part_size = std::stod(value());
    else if(arg == "--clusters")
      clusters = std::stoul(value());
    else if(arg == "--randomness")
      randomness = std::stod(value());
    else if(arg == "--method") {
      method_name = value();
      if(method_name == "mincut")
        method = RC::MIN_CUT;
      else if(method_name == "kmeans")
        method = RC::K_MEANS;
      else if(method_name == "hierarchical")
        method = RC::HIERARCHICAL;
      else {
        usage(argv[0]);
        return EXIT_FAILURE;
      }
    } else if(arg == "--no-segmentation")
      with_segmentation = false;
    else if(arg == "--segments") {
      if(value() != "auto") {
        usage(argv[0]);
        return EXIT_FAILURE;
      }
      automatic = true;
    } else if(arg == "--no-hierarchical")
      with_hierarchical = false;
    else if(arg == "--no-sdf")
      with_sdf = false;
    else if(arg == "--edge-variants")
      edge_variants = true;
    else {
      usage(argv[0]);
      return arg == "--help" ? EXIT_SUCCESS : EXIT_FAILURE;
    }
  }

  if(edge_variants) { // measured beside the min-cut values, whatever --method said
    method = RC::MIN_CUT;
    method_name = "mincut";
  }
  Json report = Json::object();
  report["benchmark"] = "partition_function_psb";
  report["psb_dir"] = psb_dir.string();
  Json settings = Json::object();
  settings["samples"] = samples;
  settings["method"] = method_name;
  settings["part_size"] = part_size;
  settings["clusters"] = clusters;
  settings["randomness"] = randomness;
  settings["segmentation"] = with_segmentation;
  settings["segments"] = automatic ? "number_of_segments = 0 (chosen by the function)"
                                   : "number_of_segments = the most frequent human count";
  settings["hierarchical"] = with_hierarchical;
  settings["sdf"] = with_sdf;
  settings["edge_variants"] = edge_variants;
  report["settings"] = settings;
  report["metrics"] =
    "rand_index_error: 1 - RI, mean over human segmentations, meshes of a class, classes; "
    "auc: ROC area of edge score vs 'some human cuts here'; top2_precision: share of such edges "
    "among the 2% highest-scoring edges";

  const std::vector<psb::Mesh_entry> meshes = psb::select_meshes(psb_dir, classes, ids);
  if(meshes.empty()) {
    report["skipped"] = "no PSB mesh with segmentations matches the selection in " + psb_dir.string();
    std::cout << SAS::to_text(report) << '\n';
    psb::write_output(output, report);
    return EXIT_SUCCESS;
  }

  Json per_mesh = Json::array();
  std::map<std::string, Class_sums> by_class;
  std::vector<std::string> class_order;
  std::map<std::string, double> total_seconds;
  std::size_t measured = 0;

  auto summarize = [&](bool complete) {
    Json per_class = Json::object();
    std::map<std::string, double> overall_sum;
    std::map<std::string, std::size_t> overall_count;
    for(const std::string& c : class_order) {
      Json j = Json::object();
      for(const auto& kv : by_class[c].sum) {
        const double mean = kv.second / double(by_class[c].count[kv.first]);
        j[kv.first] = mean;
        overall_sum[kv.first] += mean;
        ++overall_count[kv.first];
      }
      per_class[c] = j;
    }
    Json overall = Json::object();
    for(const auto& kv : overall_sum)
      overall[kv.first] = kv.second / double(overall_count[kv.first]);
    Json seconds = Json::object();
    for(const auto& kv : total_seconds)
      seconds[kv.first] = kv.second;
    Json out = report;
    out["complete"] = complete;
    out["meshes"] = measured;
    out["overall_mean_over_classes"] = overall;
    out["per_class"] = per_class;
    out["total_seconds"] = seconds;
    out["per_mesh"] = per_mesh;
    return out;
  };

  std::size_t index = 0;
  for(const psb::Mesh_entry& entry : meshes) {
    ++index;
    Json j = Json::object();
    j["id"] = entry.id;
    j["class"] = entry.mesh_class;
    Mesh mesh;
    std::string note;
    if(!psb::read_mesh(entry.off, mesh, note) || mesh.number_of_faces() != entry.human.front().size()) {
      j["error"] = "cannot read the mesh, or its face count differs from its segmentations'";
      per_mesh.push_back(j);
      std::cerr << "[" << index << "/" << meshes.size() << "] " << entry.id << ": unreadable\n";
      continue;
    }
    if(std::find(class_order.begin(), class_order.end(), entry.mesh_class) == class_order.end())
      class_order.push_back(entry.mesh_class);
    Class_sums& sums = by_class[entry.mesh_class];
    const std::size_t k = psb::mode_segment_count(entry);
    j["faces"] = mesh.number_of_faces();
    j["k"] = k;
    std::cerr << "[" << index << "/" << meshes.size() << "] " << entry.id << " " << entry.mesh_class
              << " faces=" << mesh.number_of_faces() << " k=" << k;

    auto record = [&](const std::string& key, double v) {
      j[key] = v;
      sums.add(key, v);
    };
    auto timed = [&](const std::string& key, double s) {
      j[key + "_seconds"] = s;
      total_seconds[key] += s;
    };

    // The partition function (and the segmentation built on it).
    std::vector<double> values(mesh.number_of_edges(), 0.0);
    auto value_map = CGAL::make_property_map(values);
    try {
      const auto start = std::chrono::steady_clock::now();
      const auto np = RC::parameters::number_of_samples(samples)
                        .part_size(part_size)
                        .number_of_clusters(clusters)
                        .randomness(randomness);
      if(with_segmentation) { // min-cut samples (the segmentation's own default)
        auto segment = mesh.add_property_map<Face, std::size_t>("f:pf", 0).first;
        const std::size_t got = RC::segment_with_partition_function(
          mesh, segment, np.sampling_method(RC::MIN_CUT).number_of_segments(automatic ? 0 : k).edge_value_map(value_map));
        j["pf_segments"] = got;
        timed("pf_segmentation", seconds_since(start));
        const double e = psb::mean_rand_index_error(entry, labels_of(mesh, segment));
        record("pf_segmentation_rand_index_error", e);
        std::cerr << " | pf-seg " << e;
        mesh.remove_property_map(segment);
      }
      if(!with_segmentation || method != RC::MIN_CUT) { // else: the segmentation's whole-mesh values
        const auto pf_start = std::chrono::steady_clock::now();
        RC::partition_function(mesh, value_map, np.sampling_method(method));
        timed("partition_function", seconds_since(pf_start));
      }
    } catch(const std::exception& ex) {
      j["pf_error"] = ex.what();
    }

    // Edge prediction: partition function vs local concavity.
    {
      std::vector<double> pf_score, concavity_score;
      std::vector<char> positive;
      for(Edge e : edges(mesh)) {
        if(is_border(e, mesh))
          continue;
        const Face f = face(halfedge(e, mesh), mesh), g = face(opposite(halfedge(e, mesh), mesh), mesh);
        bool cut = false;
        for(const auto& h : entry.human)
          cut = cut || h[f.idx()] != h[g.idx()];
        positive.push_back(cut ? 1 : 0);
        pf_score.push_back(values[e.idx()]);
        concavity_score.push_back(signed_dihedral(mesh, e));
      }
      const psb::Edge_prediction pf = psb::predict_edges(pf_score, positive);
      const psb::Edge_prediction cc = psb::predict_edges(concavity_score, positive);
      if(edge_variants) {
        // Other samplers, their mean, and values spread by one or two rings of faces (the
        // concavity spread the same way, for a fair comparison).
        std::map<std::string, std::vector<double>> by_edge;
        by_edge["mincut"] = values;
        for(RC::Sampling_method other : {RC::K_MEANS, RC::HIERARCHICAL}) {
          std::vector<double> v(mesh.number_of_edges(), 0.0);
          RC::partition_function(mesh, CGAL::make_property_map(v),
                                 RC::parameters::number_of_samples(samples).sampling_method(other));
          by_edge[other == RC::K_MEANS ? "kmeans" : "hierarchical"] = v;
        }
        std::vector<double> mix(mesh.number_of_edges(), 0.0), concavity(mesh.number_of_edges(), -4.0);
        for(std::size_t e = 0; e < mix.size(); ++e)
          mix[e] = (by_edge["mincut"][e] + by_edge["kmeans"][e] + by_edge["hierarchical"][e]) / 3.0;
        by_edge["mix"] = mix;
        // Min-cut values averaged over the part sizes 0.02, 0.05 and 0.1 (one multi-scale run).
        {
          std::vector<std::vector<double>> scales(mesh.number_of_edges());
          RC::multiscale_partition_function(mesh, CGAL::make_property_map(scales),
                                            RC::parameters::number_of_samples(samples));
          std::vector<double> mean(mesh.number_of_edges(), 0.0);
          for(std::size_t e = 0; e < mean.size(); ++e)
            for(double v : scales[e])
              mean[e] += v / double(scales[e].size());
          by_edge["multiscale"] = mean;
        }
        for(Edge e : edges(mesh))
          if(!is_border(e, mesh))
            concavity[e.idx()] = signed_dihedral(mesh, e);
        by_edge["concavity"] = concavity;
        for(const std::string name : {"mincut", "mix", "concavity"})
          for(int rounds : {1, 2})
            by_edge[name + "_dilated" + std::to_string(rounds)] = dilate(mesh, by_edge[name], rounds);
        // The global values first, the local concavity only to order the edges they tie on: the
        // concavity, mapped into [0, 1e-4], stays below the smallest step of the values with 400
        // samples (1 / 3600 for the hierarchical sampler, whose runs count 9 segmentations each).
        for(const std::string name : {"mincut", "multiscale", "hierarchical", "mix"}) {
          std::vector<double> v = by_edge[name];
          for(std::size_t e = 0; e < v.size(); ++e)
            v[e] += 1e-4 * (concavity[e] + CGAL_PI) / (2 * CGAL_PI);
          by_edge[name + "_then_concavity"] = v;
        }
        for(const auto& kv : by_edge) {
          std::vector<double> score;
          for(Edge e : edges(mesh))
            if(!is_border(e, mesh))
              score.push_back(kv.second[e.idx()]);
          const psb::Edge_prediction x = psb::predict_edges(score, positive);
          record("variant_" + kv.first + "_auc", x.auc);
          record("variant_" + kv.first + "_top2_precision", x.top_precision);
        }
      }
      record("pf_auc", pf.auc);
      record("pf_top2_precision", pf.top_precision);
      record("concavity_auc", cc.auc);
      record("concavity_top2_precision", cc.top_precision);
      j["human_cut_edge_fraction"] = double(pf.positives) / double(std::max<std::size_t>(1, pf.edges));
      std::cerr << " | auc pf " << pf.auc << " conc " << cc.auc << " | top2 pf " << pf.top_precision
                << " conc " << cc.top_precision;
    }

    if(with_hierarchical) {
      auto segment = mesh.add_property_map<Face, std::size_t>("f:hier", 0).first;
      const auto start = std::chrono::steady_clock::now();
      j["hierarchical_segments"] =
        CS::hierarchical_segmentation(mesh, segment, CS::parameters::number_of_segments(automatic ? 0 : k));
      timed("hierarchical", seconds_since(start));
      const double e = psb::mean_rand_index_error(entry, labels_of(mesh, segment));
      record("hierarchical_rand_index_error", e);
      std::cerr << " | hier " << e;
      mesh.remove_property_map(segment);
    }
    if(with_sdf) {
      auto sdf = mesh.add_property_map<Face, double>("f:sdf", 0.0).first;
      auto segment = mesh.add_property_map<Face, std::size_t>("f:sdf_segment", 0).first;
      const auto start = std::chrono::steady_clock::now();
      CGAL::sdf_values(mesh, sdf);
      CGAL::segmentation_from_sdf_values(mesh, sdf, segment);
      timed("sdf", seconds_since(start));
      const double e = psb::mean_rand_index_error(entry, labels_of(mesh, segment));
      record("sdf_rand_index_error", e);
      std::cerr << " | sdf " << e;
      mesh.remove_property_map(segment);
      mesh.remove_property_map(sdf);
    }
    std::cerr << std::endl;
    per_mesh.push_back(j);
    ++measured;
    psb::write_output(output, summarize(false));
  }
  const Json final_report = summarize(true);
  std::cout << SAS::to_text(final_report) << '\n';
  psb::write_output(output, final_report);
  return EXIT_SUCCESS;
}
