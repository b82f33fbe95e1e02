// Tests of CGAL::Randomized_cuts: the partition function (three samplers, multi-scale), the
// consistency of cuts, the segmentation built on them. Procedural shapes with known parts: the
// values must be high at the necks where parts meet and near 0 far from them, mirror-symmetric
// limbs must get matching values, noise must not move the strongest cut away from the neck, the
// segmentation must recover the parts; results must not depend on the number of threads; bad
// input is refused with Bad_input.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polyhedron_3.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Surface_mesh/IO/OFF.h>
#include <CGAL/boost/graph/helpers.h>

#include <CGAL/Randomized_cuts/most_consistent_cuts.h>
#include <CGAL/Randomized_cuts/partition_function.h>
#include <CGAL/Randomized_cuts/register_meshes.h>
#include <CGAL/Randomized_cuts/segment_with_partition_function.h>
#include <Shape_analysis_support/Procedural_shapes.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <limits>
#include <map>
#include <set>
#include <string>
#include <vector>

namespace {

typedef CGAL::Exact_predicates_inexact_constructions_kernel Kernel;
typedef Kernel::Point_3 Point;
typedef CGAL::Surface_mesh<Point> Mesh;
typedef Mesh::Face_index face_descriptor;
typedef Mesh::Edge_index edge_descriptor;

namespace RC = CGAL::Randomized_cuts;
namespace SAI = CGAL::Shape_analysis::internal;
namespace SAS = CGAL::Shape_analysis_support;
using SAI::Vector_3d;

Mesh to_mesh(const SAS::Labelled_triangle_mesh& lm)
{
  Mesh m;
  SAS::fill_polygon_mesh(lm, m);
  return m;
}

// Two overlapping spheres: one neck (labels 0 and 1).
SAS::Procedural_shape dumbbell()
{
  SAS::Procedural_shape s;
  s.add(SAS::Shape_primitive::sphere(Vector_3d(-0.9, 0, 0), 1.0, 0));
  s.add(SAS::Shape_primitive::sphere(Vector_3d(0.9, 0, 0), 0.9, 1));
  return s;
}

template <typename NP>
std::vector<double> values_of(const Mesh& m, const NP& np, RC::Partition_function_result* result = nullptr)
{
  std::vector<double> v(num_edges(m), -1.0);
  const RC::Partition_function_result r = RC::partition_function(m, CGAL::make_property_map(v), np);
  if(result != nullptr)
    *result = r;
  return v;
}

// Distance in face rings of every face from the faces that touch a part boundary (ground truth).
std::vector<int> rings_from_boundary(const Mesh& m, const std::vector<std::size_t>& labels)
{
  std::vector<int> ring(num_faces(m), std::numeric_limits<int>::max());
  std::vector<face_descriptor> queue;
  for(edge_descriptor e : edges(m)) {
    const face_descriptor f = face(halfedge(e, m), m), g = face(opposite(halfedge(e, m), m), m);
    if(labels[f] != labels[g]) {
      for(face_descriptor x : {f, g})
        if(ring[x] != 0) {
          ring[x] = 0;
          queue.push_back(x);
        }
    }
  }
  for(std::size_t k = 0; k < queue.size(); ++k) {
    const face_descriptor f = queue[k];
    for(auto h : halfedges_around_face(halfedge(f, m), m)) {
      const face_descriptor g = face(opposite(h, m), m);
      if(ring[g] > ring[f] + 1) {
        ring[g] = ring[f] + 1;
        queue.push_back(g);
      }
    }
  }
  return ring;
}

struct Neck_figures
{
  std::map<std::pair<std::size_t, std::size_t>, double> neck_max; // per pair of labels
  double far_max = 0;  // edges at least 6 rings from any boundary
  double far_mean = 0;
};

// The largest value in the band of 2 rings around each neck, and the values far from the necks.
Neck_figures neck_figures(const Mesh& m, const std::vector<std::size_t>& labels,
                          const std::vector<double>& values)
{
  const std::vector<int> ring = rings_from_boundary(m, labels);
  // The neck a face belongs to: the label pair of the nearest boundary (found by spreading).
  Neck_figures x;
  std::size_t far_count = 0;
  for(edge_descriptor e : edges(m)) {
    const face_descriptor f = face(halfedge(e, m), m), g = face(opposite(halfedge(e, m), m), m);
    const int r = (std::min)(ring[f], ring[g]);
    if(r >= 6) {
      x.far_max = (std::max)(x.far_max, values[e]);
      x.far_mean += values[e];
      ++far_count;
    }
  }
  x.far_mean /= double((std::max<std::size_t>)(1, far_count));
  // Bands: faces within 2 rings of a boundary between labels a and b, where the nearest boundary
  // edge is found by breadth-first search from each boundary edge's faces.
  for(edge_descriptor e : edges(m)) {
    const face_descriptor f = face(halfedge(e, m), m), g = face(opposite(halfedge(e, m), m), m);
    if(labels[f] == labels[g])
      continue;
    const auto key = std::minmax(labels[f], labels[g]);
    // Edges around f and g up to 2 rings.
    std::set<face_descriptor> band = {f, g};
    for(int step = 0; step < 2; ++step) {
      std::set<face_descriptor> next = band;
      for(face_descriptor y : band)
        for(auto h : halfedges_around_face(halfedge(y, m), m))
          next.insert(face(opposite(h, m), m));
      band.swap(next);
    }
    double& best = x.neck_max[key];
    for(face_descriptor y : band)
      for(auto h : halfedges_around_face(halfedge(y, m), m))
        best = (std::max)(best, values[edge(h, m)]);
  }
  return x;
}

// ---------------------------------------------------------------------------------------------
// The partition function on shapes with known necks

TEST(PartitionFunction, ScoreWeightedValuesAreNearOneAtTheNeckAndNearZeroElsewhere)
{
  const SAS::Labelled_triangle_mesh lm = SAS::mesh_procedural_shape(dumbbell(), 0.2);
  const Mesh m = to_mesh(lm);
  const std::vector<double> v = values_of(m, RC::parameters::score_weighting(true).sampling_method(RC::MIN_CUT));
  const Neck_figures x = neck_figures(m, lm.labels, v);
  ASSERT_EQ(x.neck_max.size(), 1u);
  EXPECT_GE(x.neck_max.begin()->second, 0.9);
  EXPECT_LE(x.far_max, 0.02);
  for(double value : v) {
    EXPECT_GE(value, 0.0);
    EXPECT_LE(value, 1.0);
  }
}

TEST(PartitionFunction, MinCutValuesPeakAtEveryNeck)
{
  // Unweighted: a neck is cut by the samples whose two faces fall on its two sides (about
  // 2 p (1 - p) of them for parts of area shares p and 1 - p).
  const SAS::Labelled_triangle_mesh lm = SAS::mesh_procedural_shape(SAS::three_sphere_chain(), 0.2);
  const Mesh m = to_mesh(lm);
  const std::vector<double> v = values_of(m, RC::parameters::random_seed(3).sampling_method(RC::MIN_CUT));
  const Neck_figures x = neck_figures(m, lm.labels, v);
  ASSERT_EQ(x.neck_max.size(), 2u);
  // Cuts at a neck spread over the two or three nearly equally cheap edge loops of its crease.
  for(const auto& neck : x.neck_max) {
    EXPECT_GE(neck.second, 0.15) << "neck " << neck.first.first << "-" << neck.first.second;
    EXPECT_GE(neck.second, 10 * x.far_max);
  }
  EXPECT_LE(x.far_max, 0.03);
  EXPECT_LE(x.far_mean, 0.003);
}

TEST(PartitionFunction, KMeansAndHierarchicalSamplersAlsoFindTheNecks)
{
  const SAS::Labelled_triangle_mesh lm = SAS::mesh_procedural_shape(SAS::three_sphere_chain(), 0.25);
  const Mesh m = to_mesh(lm);
  for(RC::Sampling_method method : {RC::K_MEANS, RC::HIERARCHICAL}) {
    SCOPED_TRACE(method == RC::K_MEANS ? "K-means" : "hierarchical");
    const std::vector<double> v =
      values_of(m, RC::parameters::sampling_method(method).number_of_samples(100));
    const Neck_figures x = neck_figures(m, lm.labels, v);
    ASSERT_EQ(x.neck_max.size(), 2u);
    for(const auto& neck : x.neck_max)
      EXPECT_GE(neck.second, 0.3);
    // Each K-means sample has 10 segments, cut somewhere inside the spheres too: far values stay
    // well under the neck values on average.
    for(const auto& neck : x.neck_max)
      EXPECT_GE(neck.second, 5 * x.far_mean);
  }
}

// The hierarchical sampler weighs each cut edge by the levels of the merge sequence at which it
// is still cut, kept up to date merge by merge (O(E log k)). Against a reference that relabels
// the whole graph at every level and sums the weights of the levels where each edge is cut.
TEST(PartitionFunction, HierarchicalLevelsMatchARelabellingReference)
{
  namespace RCI = CGAL::Randomized_cuts::internal;
  const Mesh m = to_mesh(SAS::mesh_procedural_shape(SAS::three_sphere_chain(), 0.25));
  for(int run = 0; run < 8; ++run) {
    const std::size_t clusters = std::size_t(run / 2 == 0 ? 2 : run / 2 == 1 ? 7 : run / 2 == 2 ? 40 : 200);
    SCOPED_TRACE("clusters " + std::to_string(clusters) + (run % 2 ? ", weighted by score" : ""));
    RCI::Sampling_options o;
    o.sampling_method = RC::HIERARCHICAL;
    o.number_of_clusters = clusters;
    o.score_weighting = run % 2 == 1; // (then the levels' scores are kept up to date too)
    o.random_seed = 5;
    const RCI::Mesh_sampling<Mesh, decltype(CGAL::parameters::default_values())>
      sampling(m, CGAL::parameters::default_values(), o, "test");
    const RCI::Dual_graph& g = sampling.graph();
    const RCI::Hierarchical_sampler sampler(g, sampling.options);
    RCI::Hierarchical_sampler::Workspace w;
    for(std::size_t index = 0; index < 3; ++index) {
      RCI::Sample sample;
      sampler.draw(index, w, sample);
      // The same merge sequence, replayed from scratch at every level.
      SAI::Normalized_cut_clustering clustering(g.node_size, g.edge_source, g.edge_target, g.cut_cost);
      clustering.run(2, {}, {}, sampling.options.randomness, SAI::Random_stream(o.random_seed, index).next(),
                     RCI::small_segment_fraction * g.total_size());
      const auto& merges = clustering.merges();
      const std::size_t n = g.number_of_nodes();
      const std::size_t top = (std::max)(n - merges.size(), (std::min)(clusters, n));
      std::map<std::uint32_t, double> expected;
      double total = 0;
      SAI::Union_find sets(n);
      std::size_t applied = 0;
      for(std::size_t segments = n; segments >= 2; --segments) {
        if(segments <= top) {
          std::vector<std::uint32_t> label, cut_edges;
          std::vector<double> size, cut;
          const std::size_t k = sets.dense_labels(label);
          ASSERT_EQ(k, segments);
          const double score = RCI::cut_of_labelling(g, label, k, cut_edges, size, cut);
          const double weight = RCI::score_weight(score, sampling.options.score_weighting, g);
          for(std::uint32_t e : cut_edges)
            expected[e] += weight;
          total += weight;
        }
        if(segments == 2 || applied == merges.size())
          break;
        sets.absorb(merges[applied].survivor, merges[applied].absorbed);
        ++applied;
      }
      EXPECT_NEAR(sample.total_weight, total, 1e-7 * total); // (the incremental score drifts by rounding)
      ASSERT_EQ(sample.amounts.size(), expected.size());
      for(const auto& a : sample.amounts) {
        ASSERT_EQ(expected.count(a.first), 1u) << "edge " << a.first;
        EXPECT_NEAR(a.second, expected[a.first], 1e-7 * total) << "edge " << a.first;
      }
    }
  }
}

// Expected length of cut per leg: the sum of value x length over the edges below the torso,
// by quadrant (legs stand at x < 0 / y < 0, x < 0 / y > 0, x > 0 / y < 0, x > 0 / y > 0).
std::vector<double> cut_length_per_leg(const Mesh& m, const std::vector<double>& v)
{
  std::vector<double> sum(4, 0.0);
  for(edge_descriptor e : edges(m)) {
    const Point p = m.point(source(halfedge(e, m), m)), q = m.point(target(halfedge(e, m), m));
    const Point mid = CGAL::midpoint(p, q);
    if(mid.z() > -0.35) // the torso's bottom is at z = -0.55; legs meet it above
      continue;
    sum[(mid.x() > 0 ? 2 : 0) + (mid.y() > 0 ? 1 : 0)] += v[e] * std::sqrt(CGAL::squared_distance(p, q));
  }
  return sum;
}

TEST(PartitionFunction, MirrorSymmetricLimbsGetMatchingValues)
{
  // Four identical legs placed symmetrically about the planes x = 0 and y = 0. A leg is cut off
  // at its neck or lower down (when a sampled face on the leg makes the neck too expensive).
  SAS::Labelled_triangle_mesh lm = SAS::mesh_procedural_shape(SAS::body_with_limbs(0), 0.15);
  const Mesh m = to_mesh(lm);
  const auto np = RC::parameters::number_of_samples(800).random_seed(7).sampling_method(RC::MIN_CUT);
  const std::vector<double> legs = cut_length_per_leg(m, values_of(m, np));
  // The grid of the mesher is not mirror-symmetric, so the legs are meshed differently: their
  // values match within the tessellation's influence.
  const double lo = *std::min_element(legs.begin(), legs.end());
  const double hi = *std::max_element(legs.begin(), legs.end());
  EXPECT_GT(lo, 0.1);
  EXPECT_LE(hi - lo, 0.35 * hi) << legs[0] << " " << legs[1] << " " << legs[2] << " " << legs[3];
  // The mirror image (x -> -x, faces reversed) gets the mirrored values: the legs swap sides.
  for(auto& p : lm.points)
    p[0] = -p[0];
  for(auto& t : lm.triangles)
    std::swap(t[1], t[2]);
  const Mesh mirrored = to_mesh(lm);
  const std::vector<double> swapped = cut_length_per_leg(mirrored, values_of(mirrored, np));
  for(std::size_t leg = 0; leg < 4; ++leg)
    EXPECT_NEAR(swapped[(leg + 2) % 4], legs[leg], 0.03 * legs[leg]) << "leg " << leg;
}

TEST(PartitionFunction, NoiseKeepsTheStrongestCutAtTheNeck)
{
  SAS::Labelled_triangle_mesh lm = SAS::mesh_procedural_shape(dumbbell(), 0.2);
  // Every vertex moved by up to 5% of the mean edge length in each coordinate.
  const Mesh clean = to_mesh(lm);
  double length = 0;
  for(edge_descriptor e : edges(clean))
    length += std::sqrt(CGAL::squared_distance(clean.point(source(halfedge(e, clean), clean)),
                                               clean.point(target(halfedge(e, clean), clean))));
  length /= double(num_edges(clean));
  SAS::Procedural_random rng(99);
  for(auto& p : lm.points)
    for(double& c : p)
      c += rng.uniform(-0.05, 0.05) * length;
  const Mesh m = to_mesh(lm);
  const auto cuts = RC::most_consistent_cuts(m, RC::parameters::number_of_cuts(3));
  ASSERT_FALSE(cuts.empty());
  const RC::Cut<Mesh>& top = cuts.front();
  // Its smaller side is one sphere, up to a ring or two of faces.
  std::vector<std::size_t> side(num_faces(m), 0);
  for(face_descriptor f : top.smaller_side)
    side[f] = 1;
  EXPECT_GE(SAS::rand_index(side, lm.labels), 0.97);
  EXPECT_GT(top.consistency, 0.3);
  EXPECT_GT(top.number_of_samples, 100u); // about half of the 400 samples cut the neck
  // Every sample is counted once among the distinct cuts, which come by decreasing consistency.
  const auto all = RC::most_consistent_cuts(m);
  std::size_t total = 0;
  for(std::size_t i = 0; i < all.size(); ++i) {
    total += all[i].number_of_samples;
    EXPECT_GE(all[i].consistency, 0.0);
    EXPECT_LE(all[i].consistency, 1.0);
    if(i > 0)
      EXPECT_LE(all[i].consistency, all[i - 1].consistency);
  }
  EXPECT_EQ(total, 400u);
  EXPECT_EQ(all.front().edges, top.edges); // same seed, same ranking
}

TEST(PartitionFunction, CutsReportTheirEdgesLengthAndSides)
{
  const SAS::Labelled_triangle_mesh lm = SAS::mesh_procedural_shape(SAS::three_sphere_chain(), 0.25);
  const Mesh m = to_mesh(lm);
  std::vector<double> v(num_edges(m), 0.0);
  const auto cuts = RC::most_consistent_cuts(
    m, RC::parameters::number_of_samples(200).edge_value_map(CGAL::make_property_map(v)));
  ASSERT_GE(cuts.size(), 2u);
  EXPECT_EQ(v, values_of(m, RC::parameters::number_of_samples(200).sampling_method(RC::MIN_CUT)))
    << "the edge values are those of partition_function with the same parameters";
  for(const auto& c : cuts) {
    // The cut edges are exactly the edges between the smaller side and the rest.
    std::vector<char> in(num_faces(m), 0);
    for(face_descriptor f : c.smaller_side)
      in[f] = 1;
    std::set<edge_descriptor> expected;
    double length = 0, weighted = 0;
    for(edge_descriptor e : edges(m))
      if(in[face(halfedge(e, m), m)] != in[face(opposite(halfedge(e, m), m), m)]) {
        expected.insert(e);
        const double l = std::sqrt(CGAL::squared_distance(m.point(source(halfedge(e, m), m)),
                                                          m.point(target(halfedge(e, m), m))));
        length += l;
        weighted += l * v[e];
      }
    EXPECT_EQ(std::set<edge_descriptor>(c.edges.begin(), c.edges.end()), expected);
    EXPECT_NEAR(c.length, length, 1e-9 * length);
    EXPECT_NEAR(c.consistency, weighted / length, 1e-9);
    EXPECT_LE(2 * c.smaller_side.size(), num_faces(m) + 200); // by area, roughly by count
  }
}

TEST(PartitionFunction, MultiscaleValuesAreThoseOfEachPartSize)
{
  const SAS::Labelled_triangle_mesh lm = SAS::mesh_procedural_shape(SAS::body_with_limbs(1, true), 0.15);
  const Mesh m = to_mesh(lm);
  const std::vector<double> sizes = {0.02, 0.05, 0.12};
  std::vector<std::vector<double>> multi(num_edges(m));
  RC::multiscale_partition_function(m, CGAL::make_property_map(multi),
                                    RC::parameters::part_sizes(sizes).number_of_samples(150).random_seed(5));
  // Each part size's cut continues from the flow of the smaller part size (its penalties are
  // larger): it is a minimum cut for its own capacities, the one a separate run finds, except
  // where rounding decides between two cuts of the same cost.
  for(std::size_t k = 0; k < sizes.size(); ++k) {
    const std::vector<double> single =
      values_of(m, RC::parameters::part_size(sizes[k]).number_of_samples(150).random_seed(5).sampling_method(RC::MIN_CUT));
    std::size_t differ = 0;
    for(edge_descriptor e : edges(m)) {
      ASSERT_EQ(multi[e].size(), sizes.size());
      EXPECT_LE(std::abs(multi[e][k] - single[e]), 2.0 / 150 + 1e-12) << "part size " << sizes[k];
      differ += multi[e][k] != single[e] ? 1 : 0;
    }
    EXPECT_LE(differ, num_edges(m) / 100) << "part size " << sizes[k];
  }
  // Larger part sizes keep cuts away from the seeds: the small head and feet are cut less often
  // relative to the whole, and the values differ between scales.
  double differ = 0;
  for(edge_descriptor e : edges(m))
    differ += std::abs(multi[e][0] - multi[e][2]);
  EXPECT_GT(differ, 1.0);
}

// ---------------------------------------------------------------------------------------------
// Determinism and options

TEST(PartitionFunction, SameSeedSameValuesForAnyNumberOfThreads)
{
  const SAS::Labelled_triangle_mesh lm = SAS::mesh_procedural_shape(SAS::three_sphere_chain(), 0.4);
  const Mesh m = to_mesh(lm);
  for(RC::Sampling_method method : {RC::MIN_CUT, RC::K_MEANS, RC::HIERARCHICAL}) {
    for(bool weighted : {false, true}) {
      // 70 samples: two batches.
      const auto np = RC::parameters::sampling_method(method).number_of_samples(70).random_seed(42).score_weighting(weighted);
      const std::vector<double> one = values_of(m, np.number_of_threads(1));
      EXPECT_EQ(one, values_of(m, np.number_of_threads(2))) << "method " << int(method);
      EXPECT_EQ(one, values_of(m, np.number_of_threads(0))) << "method " << int(method);
      EXPECT_EQ(one, values_of(m, np.number_of_threads(1))) << "method " << int(method);
      EXPECT_NE(one, values_of(m, np.random_seed(43))) << "another seed, other samples";
    }
  }
  // Segmentation too.
  auto labels = [&](std::size_t threads) {
    Mesh copy = m;
    auto seg = copy.add_property_map<face_descriptor, std::size_t>("f:s", 0).first;
    RC::segment_with_partition_function(copy, seg, RC::parameters::number_of_segments(3)
                                                       .number_of_samples(100)
                                                       .number_of_threads(threads));
    std::vector<std::size_t> l;
    for(face_descriptor f : faces(copy))
      l.push_back(seg[f]);
    return l;
  };
  EXPECT_EQ(labels(1), labels(0));
}

TEST(PartitionFunction, ConvergenceToleranceStopsEarly)
{
  const SAS::Labelled_triangle_mesh lm = SAS::mesh_procedural_shape(dumbbell(), 0.3);
  const Mesh m = to_mesh(lm);
  RC::Partition_function_result r;
  values_of(m, RC::parameters::number_of_samples(4000).convergence_tolerance(0.02), &r);
  EXPECT_TRUE(r.converged);
  EXPECT_LT(r.number_of_samples, 4000u);
  EXPECT_EQ(r.number_of_samples % 64, 0u) << "checked after whole batches";
  EXPECT_LT(r.largest_change, 0.02);
  values_of(m, RC::parameters::number_of_samples(100), &r);
  EXPECT_FALSE(r.converged);
  EXPECT_EQ(r.number_of_samples, 100u);
  // Progress is reported up to 1.
  std::vector<double> progress;
  std::function<void(double)> cb = [&](double f) { progress.push_back(f); };
  values_of(m, RC::parameters::number_of_samples(130).progress_callback(cb));
  ASSERT_FALSE(progress.empty());
  EXPECT_EQ(progress.back(), 1.0);
  EXPECT_TRUE(std::is_sorted(progress.begin(), progress.end()));
}

TEST(PartitionFunction, SeparatePiecesAreCutApartAndPolyhedronWorks)
{
  // Two boxes apart: linked weakly, so that samples with one seed in each cut between them.
  const SAS::Labelled_triangle_mesh lm = SAS::mesh_procedural_shape(SAS::separate_boxes(2, 1.0), 0.2);
  typedef CGAL::Polyhedron_3<Kernel> Polyhedron;
  Polyhedron p;
  SAS::fill_polygon_mesh(lm, p);
  std::map<Polyhedron::Halfedge_handle, double> by_halfedge;
  std::map<boost::graph_traits<Polyhedron>::edge_descriptor, double> values;
  RC::partition_function(p, boost::make_assoc_property_map(values),
                         RC::parameters::number_of_samples(100).sampling_method(RC::MIN_CUT));
  ASSERT_EQ(values.size(), num_edges(p));
  // No mesh edge lies between the boxes: every value stays small (cuts go between the pieces).
  double largest = 0;
  for(const auto& kv : values)
    largest = (std::max)(largest, kv.second);
  EXPECT_LT(largest, 0.1);
  Polyhedron copy = p;
  std::map<boost::graph_traits<Polyhedron>::face_descriptor, std::size_t> segment;
  EXPECT_EQ(RC::segment_with_partition_function(copy, boost::make_assoc_property_map(segment),
                                                RC::parameters::number_of_segments(2).number_of_samples(60)),
            2u);
  std::vector<std::size_t> labels;
  for(auto f : faces(copy))
    labels.push_back(segment[f]);
  EXPECT_EQ(SAS::rand_index(labels, lm.labels), 1.0) << "each box is one segment";
}

TEST(PartitionFunction, ExtremeCoordinatesGiveTheSameValues)
{
  // Coordinates scaled by 2^500 and 2^-500 (an exact scaling): squared lengths and areas would
  // overflow or underflow; the values must be those of the mesh as it is.
  const SAS::Labelled_triangle_mesh lm = SAS::mesh_procedural_shape(dumbbell(), 0.4);
  const Mesh m = to_mesh(lm);
  const auto np = RC::parameters::number_of_samples(64).random_seed(2);
  const std::vector<double> reference = values_of(m, np);
  for(int exponent : {500, -500}) {
    Mesh scaled = m;
    for(auto v : vertices(scaled)) {
      const Point& p = scaled.point(v);
      scaled.point(v) = Point(std::ldexp(p.x(), exponent), std::ldexp(p.y(), exponent),
                              std::ldexp(p.z(), exponent));
    }
    EXPECT_EQ(values_of(scaled, np), reference) << "scaled by 2^" << exponent;
    const auto cuts = RC::most_consistent_cuts(scaled, np.number_of_cuts(1));
    const auto plain = RC::most_consistent_cuts(m, np.number_of_cuts(1));
    ASSERT_EQ(cuts.size(), 1u);
    EXPECT_EQ(cuts[0].length, std::ldexp(plain[0].length, exponent)) << "lengths in the mesh's units";
  }
}

TEST(PartitionFunction, CutsBetweenSeparatePiecesCrossNoEdge)
{
  const SAS::Labelled_triangle_mesh lm = SAS::mesh_procedural_shape(SAS::separate_boxes(2, 1.0), 0.25);
  const Mesh m = to_mesh(lm);
  const auto cuts = RC::most_consistent_cuts(m, RC::parameters::number_of_samples(100));
  ASSERT_FALSE(cuts.empty());
  // The cut between the boxes is the one most samples make: it crosses only the links between
  // the pieces, so it has no mesh edge; its smaller side is the smaller box.
  const RC::Cut<Mesh>& top = cuts.front();
  EXPECT_TRUE(top.edges.empty());
  EXPECT_EQ(top.length, 0.0);
  EXPECT_GT(top.consistency, 0.3);
  EXPECT_GT(top.number_of_samples, 30u);
  std::vector<std::size_t> side(num_faces(m), 0);
  for(face_descriptor f : top.smaller_side)
    side[f] = 1;
  EXPECT_EQ(SAS::rand_index(side, lm.labels), 1.0);
}

// ---------------------------------------------------------------------------------------------
// Segmentation

TEST(Segmentation, DegenerateFacesStillGiveTheRequestedSegments)
{
  // Three faces around an edge fan, the third with collinear corners (zero area).
  Mesh m;
  const auto v0 = m.add_vertex(Point(0, 0, 0)), v1 = m.add_vertex(Point(1, 0, 0)),
             v2 = m.add_vertex(Point(2, 0, 0)), v3 = m.add_vertex(Point(1, 1, 0));
  ASSERT_NE(m.add_face(v0, v1, v3), Mesh::null_face());
  ASSERT_NE(m.add_face(v1, v2, v3), Mesh::null_face());
  ASSERT_NE(m.add_face(v0, v2, v1), Mesh::null_face());
  auto seg = m.add_property_map<face_descriptor, std::size_t>("f:s", 9).first;
  EXPECT_EQ(RC::segment_with_partition_function(m, seg, RC::parameters::number_of_segments(3)
                                                           .number_of_samples(20)),
            3u);
  std::set<std::size_t> used;
  for(face_descriptor f : faces(m))
    used.insert(seg[f]);
  EXPECT_EQ(used, (std::set<std::size_t>{0, 1, 2}));
}

TEST(Segmentation, RecoversTheKnownParts)
{
  struct Case
  {
    const char* name;
    SAS::Procedural_shape shape;
    double cell;
  };
  const std::vector<Case> cases = {{"three spheres", SAS::three_sphere_chain(2), 0.2},
                                   {"body with head", SAS::body_with_limbs(3, true), 0.15},
                                   {"star", SAS::star(5, 4), 0.16}};
  for(const Case& c : cases) {
    SCOPED_TRACE(c.name);
    const SAS::Labelled_triangle_mesh lm = SAS::mesh_procedural_shape(c.shape, c.cell);
    Mesh m = to_mesh(lm);
    auto seg = m.add_property_map<face_descriptor, std::size_t>("f:s", 99).first;
    const std::size_t k = RC::segment_with_partition_function(
      m, seg, RC::parameters::number_of_segments(lm.number_of_labels).number_of_samples(200));
    EXPECT_EQ(k, lm.number_of_labels);
    std::vector<std::size_t> labels;
    std::vector<double> area(k, 0.0);
    const std::vector<double> areas = lm.areas();
    for(face_descriptor f : faces(m)) {
      ASSERT_LT(seg[f], k);
      labels.push_back(seg[f]);
      area[seg[f]] += areas[f];
    }
    for(std::size_t l = 0; l + 1 < k; ++l)
      EXPECT_GE(area[l], area[l + 1]) << "segments are numbered by decreasing area";
    EXPECT_GE(SAS::rand_index(labels, lm.labels), 0.95);
    EXPECT_GE(SAS::matched_overlap(labels, lm.labels, &areas), 0.95);
  }
}

TEST(Segmentation, TheAutomaticCountCutsEveryCreaseBetweenParts)
{
  // Parts joined along concave creases: the splits follow creases, so the segmentation goes on at
  // least until every part is apart (it may split a part further along the shallow concave bands
  // where the procedural parts blend), and no segment straddles two parts.
  struct Case
  {
    const char* name;
    SAS::Procedural_shape shape;
    std::size_t most; // segments: the spheres stop before the maximum (the rule fires)
  };
  const std::vector<Case> cases = {{"three spheres", SAS::three_sphere_chain(2), 11},
                                   {"body with head", SAS::body_with_limbs(3, true), 12},
                                   {"star", SAS::star(5, 4), 12}};
  for(const Case& c : cases) {
    SCOPED_TRACE(c.name);
    const SAS::Labelled_triangle_mesh lm = SAS::mesh_procedural_shape(c.shape, 0.15);
    Mesh m = to_mesh(lm);
    auto seg = m.add_property_map<face_descriptor, std::size_t>("f:s", 99).first;
    const std::size_t k = RC::segment_with_partition_function(
      m, seg, RC::parameters::number_of_segments(0).number_of_samples(200));
    EXPECT_GE(k, lm.number_of_labels);
    EXPECT_LE(k, c.most);
    // Per segment, the area of each part in it: most of it in one part.
    const std::vector<double> areas = lm.areas();
    std::vector<std::map<std::size_t, double>> area_by_part(k);
    std::vector<double> segment_area(k, 0.0);
    for(face_descriptor f : faces(m)) {
      ASSERT_LT(seg[f], k);
      area_by_part[seg[f]][lm.labels[f]] += areas[f];
      segment_area[seg[f]] += areas[f];
    }
    double inside = 0, total = 0;
    for(std::size_t s = 0; s < k; ++s) {
      double largest = 0;
      for(const auto& kv : area_by_part[s])
        largest = (std::max)(largest, kv.second);
      EXPECT_GT(segment_area[s], 0.0) << "segment " << s << " is empty";
      inside += largest;
      total += segment_area[s];
    }
    EXPECT_GE(inside / total, 0.95) << "the segments refine the parts";
  }
}

TEST(Segmentation, RealMeshGetsTheRequestedSegmentsAndEdgeValues)
{
  Mesh m;
  std::ifstream in(std::string(SHAPE_ANALYSIS_DATA_DIR) + "/elephant.off");
  ASSERT_TRUE(CGAL::IO::read_OFF(in, m));
  auto seg = m.add_property_map<face_descriptor, std::size_t>("f:s", 99).first;
  std::vector<double> v(num_edges(m), -1.0);
  const std::size_t k = RC::segment_with_partition_function(
    m, seg,
    RC::parameters::number_of_segments(6).number_of_samples(100).edge_value_map(CGAL::make_property_map(v)));
  EXPECT_EQ(k, 6u);
  std::set<std::size_t> used;
  for(face_descriptor f : faces(m))
    used.insert(seg[f]);
  EXPECT_EQ(used.size(), 6u);
  EXPECT_EQ(v, values_of(m, RC::parameters::number_of_samples(100).sampling_method(RC::MIN_CUT)))
    << "the whole mesh's partition function, as partition_function() gives it with min-cuts";
}

// ---------------------------------------------------------------------------------------------
// Options: the structs hold the defaults; the named parameters land in their members

// Every member of the partition function's options is equal.
void expect_same_sampling(const RC::Partition_function_options& a, const RC::Partition_function_options& b)
{
  EXPECT_EQ(a.sampling_method, b.sampling_method);
  EXPECT_EQ(a.number_of_samples, b.number_of_samples);
  EXPECT_EQ(a.convergence_tolerance, b.convergence_tolerance);
  EXPECT_EQ(a.random_seed, b.random_seed);
  EXPECT_EQ(a.part_size, b.part_size);
  EXPECT_EQ(a.number_of_clusters, b.number_of_clusters);
  EXPECT_EQ(a.randomness, b.randomness);
  EXPECT_EQ(a.score_weighting, b.score_weighting);
  EXPECT_EQ(a.number_of_threads, b.number_of_threads);
  EXPECT_EQ(a.concavity_exponent, b.concavity_exponent);
  EXPECT_EQ(a.component_link_distance, b.component_link_distance);
  EXPECT_EQ(a.component_link_factor, b.component_link_factor);
  EXPECT_EQ(bool(a.progress_callback), bool(b.progress_callback));
}

TEST(Options, WithoutNamedParametersTheyAreTheDefaults)
{
  expect_same_sampling(RC::partition_function_options(), RC::Partition_function_options());
  // The partition function alone samples hierarchical clusterings (the best boundary signal); the
  // functions that need each sample to be one cut, and the registration, sample min-cuts.
  EXPECT_EQ(RC::Partition_function_options().sampling_method, RC::HIERARCHICAL);
  EXPECT_EQ(RC::Register_meshes_options().sampling_method, RC::MIN_CUT);
  // A part size is the min-cut sampler's: given alone, it selects MIN_CUT; with a sampler, not.
  EXPECT_EQ(RC::partition_function_options(RC::parameters::part_size(0.1)).sampling_method, RC::MIN_CUT);
  EXPECT_EQ(RC::partition_function_options(RC::parameters::part_size(0.1).sampling_method(RC::K_MEANS)).sampling_method,
            RC::K_MEANS);
  RC::Partition_function_options min_cut;
  min_cut.sampling_method = RC::MIN_CUT;
  const RC::Multiscale_partition_function_options multiscale = RC::multiscale_partition_function_options();
  expect_same_sampling(multiscale, min_cut);
  EXPECT_EQ(multiscale.part_sizes, RC::Multiscale_partition_function_options().part_sizes);
  const RC::Most_consistent_cuts_options cuts = RC::most_consistent_cuts_options();
  expect_same_sampling(cuts, min_cut);
  EXPECT_EQ(cuts.number_of_cuts, RC::Most_consistent_cuts_options().number_of_cuts);
  EXPECT_EQ(cuts.duplicate_tolerance, RC::Most_consistent_cuts_options().duplicate_tolerance);
  const RC::Segment_with_partition_function_options seg = RC::segment_with_partition_function_options();
  expect_same_sampling(seg, min_cut);
  EXPECT_EQ(seg.number_of_segments, RC::Segment_with_partition_function_options().number_of_segments);
  EXPECT_EQ(seg.number_of_segments, 0u) << "chosen by default";
  EXPECT_EQ(seg.boundary_refinement, RC::Segment_with_partition_function_options().boundary_refinement);
  // The dual graph's defaults are the Core's, shared with the other packages.
  EXPECT_EQ(RC::Partition_function_options().concavity_exponent,
            CGAL::Shape_analysis::default_concavity_exponent);
  EXPECT_EQ(RC::Partition_function_options().component_link_distance,
            CGAL::Shape_analysis::default_component_link_distance);
  EXPECT_EQ(RC::Partition_function_options().component_link_factor,
            CGAL::Shape_analysis::default_component_link_factor);
}

TEST(Options, NamedParametersLandInTheirMembers)
{
  int called = 0;
  const RC::Partition_function_options o = RC::partition_function_options(
    RC::parameters::sampling_method(RC::HIERARCHICAL)
      .number_of_samples(7)
      .random_seed(9)
      .part_size(0.1)
      .concavity_exponent(3.5)
      .component_link_factor(0.5)
      .progress_callback([&](double) { ++called; })
      .vertex_point_map(CGAL::Identity_property_map<Point>()));
  EXPECT_EQ(o.sampling_method, RC::HIERARCHICAL);
  EXPECT_EQ(o.number_of_samples, 7u);
  EXPECT_EQ(o.random_seed, 9u);
  EXPECT_EQ(o.part_size, 0.1);
  EXPECT_EQ(o.concavity_exponent, 3.5);
  EXPECT_EQ(o.component_link_factor, 0.5);
  EXPECT_EQ(o.randomness, RC::Partition_function_options().randomness) << "not given: the default";
  ASSERT_TRUE(bool(o.progress_callback));
  o.progress_callback(0.5);
  EXPECT_EQ(called, 1);

  const std::vector<double> sizes{0.03, 0.06};
  EXPECT_EQ(RC::multiscale_partition_function_options(RC::parameters::part_sizes(sizes)).part_sizes, sizes);
  const RC::Most_consistent_cuts_options cuts =
    RC::most_consistent_cuts_options(RC::parameters::number_of_cuts(3).duplicate_tolerance(0.2).number_of_samples(11));
  EXPECT_EQ(cuts.number_of_cuts, 3u);
  EXPECT_EQ(cuts.duplicate_tolerance, 0.2);
  EXPECT_EQ(cuts.number_of_samples, 11u);
  const RC::Segment_with_partition_function_options seg = RC::segment_with_partition_function_options(
    RC::parameters::number_of_segments(4).boundary_refinement(false).concavity_exponent(2.0));
  EXPECT_EQ(seg.number_of_segments, 4u);
  EXPECT_FALSE(seg.boundary_refinement);
  EXPECT_EQ(seg.concavity_exponent, 2.0);
}

// ---------------------------------------------------------------------------------------------
// Bad input

TEST(BadInput, MeshesAndParametersAreRefused)
{
  std::vector<double> v;
  auto map = CGAL::make_property_map(v);
  Mesh empty;
  EXPECT_THROW(RC::partition_function(empty, map), CGAL::Shape_analysis::Bad_input);

  Mesh one;
  one.add_face(one.add_vertex(Point(0, 0, 0)), one.add_vertex(Point(1, 0, 0)), one.add_vertex(Point(0, 1, 0)));
  v.assign(3, 0.0);
  EXPECT_THROW(RC::partition_function(one, map), CGAL::Shape_analysis::Bad_input);

  Mesh quad;
  std::vector<Mesh::Vertex_index> q;
  for(int i = 0; i < 4; ++i)
    q.push_back(quad.add_vertex(Point(i & 1, i >> 1, 0)));
  quad.add_face(q[0], q[1], q[3], q[2]);
  v.assign(4, 0.0);
  EXPECT_THROW(RC::partition_function(quad, map), CGAL::Shape_analysis::Bad_input);

  const SAS::Labelled_triangle_mesh lm = SAS::mesh_procedural_shape(dumbbell(), 0.4);
  Mesh m = to_mesh(lm);
  Mesh nan = m;
  nan.point(*vertices(nan).begin()) = Point(std::numeric_limits<double>::quiet_NaN(), 0, 0);
  v.assign(num_edges(m), 7.0);
  EXPECT_THROW(RC::partition_function(nan, map), CGAL::Shape_analysis::Bad_input);
  EXPECT_EQ(v, std::vector<double>(num_edges(m), 7.0)) << "the output is untouched";

  auto refused = [&](const auto& np) {
    EXPECT_THROW(RC::partition_function(m, map, np), CGAL::Shape_analysis::Bad_input);
  };
  refused(RC::parameters::number_of_samples(0));
  refused(RC::parameters::part_size(0.0));
  refused(RC::parameters::part_size(0.5));
  refused(RC::parameters::number_of_clusters(1).sampling_method(RC::K_MEANS));
  refused(RC::parameters::randomness(0.0).sampling_method(RC::HIERARCHICAL));
  refused(RC::parameters::convergence_tolerance(-1.0));
  refused(RC::parameters::sampling_method(RC::Sampling_method(7)));
  refused(RC::parameters::concavity_exponent(-1.0));
  refused(RC::parameters::component_link_factor(0.0));
  refused(RC::parameters::part_sizes(std::vector<double>{0.02, 0.05}));
  std::vector<std::vector<double>> multi(num_edges(m));
  EXPECT_THROW(RC::multiscale_partition_function(m, CGAL::make_property_map(multi),
                                                 RC::parameters::part_sizes(std::vector<double>{})),
               CGAL::Shape_analysis::Bad_input);
  EXPECT_THROW(RC::multiscale_partition_function(m, CGAL::make_property_map(multi),
                                                 RC::parameters::sampling_method(RC::K_MEANS)),
               CGAL::Shape_analysis::Bad_input);
  EXPECT_THROW(RC::most_consistent_cuts(m, RC::parameters::duplicate_tolerance(2.0)),
               CGAL::Shape_analysis::Bad_input);

  auto seg = m.add_property_map<face_descriptor, std::size_t>("f:s", 5).first;
  EXPECT_THROW(RC::segment_with_partition_function(m, seg, RC::parameters::number_of_segments(num_faces(m) + 1)),
               CGAL::Shape_analysis::Bad_input);
  EXPECT_THROW(RC::segment_with_partition_function(m, seg, RC::parameters::sampling_method(RC::K_MEANS)),
               CGAL::Shape_analysis::Bad_input);
  for(face_descriptor f : faces(m))
    EXPECT_EQ(seg[f], 5u);
}

} // namespace
