// Tests of CGAL::Consistent_segmentation::consistent_segmentation() and symmetric_segmentation():
// procedural chair and table sets with known part labels must be co-segmented so that one global
// matching of segment ids to labels is right on most of the area; parts found only in some chairs
// (armrests) get segments of their own; known labels are kept exactly and the rest is filled in
// (one example labels a set, a labelled set labels a new mesh, half-labelled meshes are
// completed); the symmetric mode gives mirror faces the same id; the result does not depend on
// the number of threads; CGAL's meshes of different animals are split into real parts, not into one
// segment and scraps; bad input is refused with Bad_input without touching the output maps; each
// over-segment's own alignment follows an articulated part; merge_repeated_segments() gives the
// legs of the chairs one id and their armrests another.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polyhedron_3.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/Polygon_mesh_processing/measure.h>

#include <CGAL/Consistent_segmentation/Consistent_segmentation_options.h>
#include <CGAL/Consistent_segmentation/consistent_segmentation.h>
#include <CGAL/Consistent_segmentation/hierarchical_segmentation.h>
#include <CGAL/Consistent_segmentation/merge_repeated_segments.h>
#include <Shape_analysis_support/Procedural_furniture.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <set>
#include <string>
#include <tuple>
#include <unordered_map>
#include <vector>

namespace {

typedef CGAL::Exact_predicates_inexact_constructions_kernel Kernel;
typedef Kernel::Point_3 Point;
typedef CGAL::Surface_mesh<Point> Mesh;
typedef Mesh::Face_index face_descriptor;
typedef Mesh::Property_map<face_descriptor, std::size_t> Id_map;
typedef Mesh::Property_map<face_descriptor, long long> Label_map;

namespace CS = CGAL::Consistent_segmentation;
namespace SAI = CGAL::Shape_analysis::internal;
namespace PMP = CGAL::Polygon_mesh_processing;
namespace SAS = CGAL::Shape_analysis_support;
using SAI::Vector_3d;

const std::size_t unset = std::numeric_limits<std::size_t>::max();

// ---------------------------------------------------------------------------------------------
// Helpers

// Coarser boxes than the benchmark's (about 1,000 faces per chair) keep the tests fast.
SAS::Furniture_options furniture(bool random_pose, double armrest_probability = 0.5)
{
  SAS::Furniture_options o;
  o.edge_length = 0.07;
  o.random_pose = random_pose;
  o.armrest_probability = armrest_probability;
  return o;
}

std::vector<Mesh> to_meshes(const std::vector<SAS::Furniture_model>& models)
{
  std::vector<Mesh> meshes(models.size());
  for(std::size_t i = 0; i < models.size(); ++i)
    SAS::fill_polygon_mesh(models[i].mesh, meshes[i]);
  return meshes;
}

std::vector<Id_map> id_maps(std::vector<Mesh>& meshes)
{
  std::vector<Id_map> maps;
  for(Mesh& m : meshes)
    maps.push_back(m.add_property_map<face_descriptor, std::size_t>("f:coseg_id", unset).first);
  return maps;
}

// The ids of every face of every mesh (faces in index order: the models' triangle order).
std::vector<std::vector<std::size_t>> read_ids(const std::vector<Mesh>& meshes, const std::vector<Id_map>& maps)
{
  std::vector<std::vector<std::size_t>> ids(meshes.size());
  for(std::size_t i = 0; i < meshes.size(); ++i)
    for(auto f : faces(meshes[i]))
      ids[i].push_back(maps[i][f]);
  return ids;
}

// Co-segments `models` with `np`; returns the ids per mesh and face.
template <typename NP>
std::vector<std::vector<std::size_t>> cosegment(const std::vector<SAS::Furniture_model>& models, const NP& np,
                                                CS::Consistent_segmentation_result* result = nullptr)
{
  std::vector<Mesh> meshes = to_meshes(models);
  std::vector<Id_map> maps = id_maps(meshes);
  const CS::Consistent_segmentation_result r = CS::consistent_segmentation(meshes, maps, np);
  if(result != nullptr)
    *result = r;
  return read_ids(meshes, maps);
}

// Every face got an id below the number of segments, and `meshes_of_segment` says exactly which
// meshes hold which id.
void expect_consistent_result(const std::vector<std::vector<std::size_t>>& ids,
                              const CS::Consistent_segmentation_result& r)
{
  ASSERT_EQ(r.meshes_of_segment.size(), r.number_of_segments);
  ASSERT_EQ(r.segment_area.size(), r.number_of_segments);
  std::vector<std::set<std::size_t>> seen(r.number_of_segments);
  for(std::size_t i = 0; i < ids.size(); ++i)
    for(std::size_t id : ids[i]) {
      ASSERT_LT(id, r.number_of_segments);
      seen[id].insert(i);
    }
  double area = 0;
  for(std::size_t s = 0; s < r.number_of_segments; ++s) {
    EXPECT_EQ(std::vector<std::size_t>(seen[s].begin(), seen[s].end()), r.meshes_of_segment[s]) << "segment " << s;
    for(std::size_t i = 0; i < ids.size(); ++i)
      EXPECT_EQ(r.occurs_in(s, i), seen[s].count(i) == 1);
    area += r.segment_area[s];
  }
  EXPECT_NEAR(area, double(ids.size()), 1e-9 * double(ids.size()));
}

// Fraction of the area (each model counting as 1) of `models[i]` for i in `which` whose id equals
// its true label.
double direct_accuracy(const std::vector<SAS::Furniture_model>& models,
                       const std::vector<std::vector<std::size_t>>& ids, const std::vector<std::size_t>& which)
{
  double right = 0;
  for(std::size_t i : which) {
    const SAS::Labelled_triangle_mesh& m = models[i].mesh;
    double total = 0, good = 0;
    for(std::size_t f = 0; f < m.number_of_faces(); ++f) {
      total += m.area(f);
      if(ids[i][f] == m.labels[f])
        good += m.area(f);
    }
    right += good / total;
  }
  return right / double(which.size());
}

template <typename F>
void expect_bad_input(F f, const std::string& words)
{
  try {
    f();
    ADD_FAILURE() << "no exception; expected one with '" << words << "'";
  } catch(const CGAL::Shape_analysis::Bad_input& e) {
    EXPECT_NE(std::string(e.what()).find(words), std::string::npos) << e.what();
  }
}

// The majority label (by area over the set) of every segment id.
std::map<std::size_t, std::size_t> majority_labels(const std::vector<SAS::Furniture_model>& models,
                                                   const std::vector<std::vector<std::size_t>>& ids)
{
  std::map<std::size_t, std::map<std::size_t, double>> overlap;
  for(std::size_t i = 0; i < models.size(); ++i)
    for(std::size_t f = 0; f < models[i].mesh.number_of_faces(); ++f)
      overlap[ids[i][f]][models[i].mesh.labels[f]] += models[i].mesh.area(f);
  std::map<std::size_t, std::size_t> result;
  for(const auto& kv : overlap)
    result[kv.first] = std::max_element(kv.second.begin(), kv.second.end(), [](const auto& a, const auto& b) {
                         return a.second < b.second;
                       })->first;
  return result;
}

// ---------------------------------------------------------------------------------------------
// The accuracy measure itself must reject wrong segmentations.

TEST(Measure, AccuracyRejectsWrongSegmentations)
{
  const auto models = SAS::procedural_chair_set(4, 3, furniture(false));
  std::vector<std::vector<std::size_t>> truth(models.size()), one(models.size()), by_piece(models.size()),
    swapped(models.size());
  for(std::size_t i = 0; i < models.size(); ++i) {
    truth[i] = models[i].mesh.labels;
    one[i].assign(truth[i].size(), 0);
    by_piece[i] = models[i].piece; // finer than the labels: still right
    swapped[i] = truth[i];
    if(i % 2 == 1) // the seat and back ids exchanged in every other chair
      for(std::size_t& l : swapped[i])
        l = l == SAS::SEAT ? SAS::BACK : l == SAS::BACK ? SAS::SEAT : l;
  }
  EXPECT_DOUBLE_EQ(SAS::furniture_label_accuracy(models, truth), 1.0);
  EXPECT_DOUBLE_EQ(SAS::furniture_label_accuracy(models, by_piece), 1.0);
  EXPECT_LT(SAS::furniture_label_accuracy(models, one), 0.6);
  EXPECT_LT(SAS::furniture_label_accuracy(models, swapped), 0.85);
}

// ---------------------------------------------------------------------------------------------
// Co-segmentation of sets

TEST(ChairSet, PartsAgreeAcrossTheSetInRandomPoses)
{
  const auto models = SAS::procedural_chair_set(10, 11, furniture(true));
  CS::Consistent_segmentation_result r;
  const auto ids = cosegment(models, CS::parameters::number_of_segments(8).random_seed(5), &r);
  expect_consistent_result(ids, r);
  EXPECT_EQ(r.number_of_segments, 8u);
  // 10 meshes, 4 partners: each mesh is aligned with its 8 candidates (shape distributions), and
  // keeps the links of its 4 best-aligned partners (at least 20 pairs, about 1,800 links each).
  EXPECT_GE(r.number_of_aligned_pairs, 10u * 8u / 2u);
  EXPECT_LE(r.number_of_aligned_pairs, 10u * 9u / 2u);
  EXPECT_GT(r.number_of_correspondences, 20u * 1500u);
  EXPECT_LT(r.mean_alignment_rms, 0.05);
  const double accuracy = SAS::furniture_label_accuracy(models, ids);
  EXPECT_GE(accuracy, 0.9);

  // Each mesh segmented alone has ids that mean nothing across the set: the same global matching
  // scores much lower (this is what the correspondences buy).
  std::vector<std::vector<std::size_t>> alone(models.size());
  for(std::size_t i = 0; i < models.size(); ++i) {
    Mesh m;
    SAS::fill_polygon_mesh(models[i].mesh, m);
    auto map = m.add_property_map<face_descriptor, std::size_t>("f:alone", unset).first;
    CS::hierarchical_segmentation(m, map, CS::parameters::number_of_segments(4));
    for(auto f : faces(m))
      alone[i].push_back(map[f]);
  }
  EXPECT_LT(SAS::furniture_label_accuracy(models, alone), accuracy - 0.1);
}

TEST(ChairSet, TheAutomaticCountIsTheMedianOfTheMeshesOwn)
{
  // number_of_segments 0: each mesh's automatic count (hierarchical_segmentation with 0), the
  // lower median over the set.
  const auto models = SAS::procedural_chair_set(6, 11, furniture(true));
  std::vector<std::size_t> counts;
  for(const SAS::Furniture_model& model : models) {
    Mesh m;
    SAS::fill_polygon_mesh(model.mesh, m);
    auto map = m.add_property_map<face_descriptor, std::size_t>("f:alone", unset).first;
    counts.push_back(CS::hierarchical_segmentation(m, map, CS::parameters::number_of_segments(0)));
  }
  std::sort(counts.begin(), counts.end());
  // The meshes' own counts differ (else any order statistic would pass), the median lies between.
  ASSERT_LT(counts.front(), counts.back());
  CS::Consistent_segmentation_result r;
  const auto ids = cosegment(models, CS::parameters::number_of_segments(0).random_seed(5), &r);
  expect_consistent_result(ids, r);
  EXPECT_EQ(r.number_of_segments, counts[(counts.size() - 1) / 2]);
  EXPECT_GE(r.number_of_segments, 2u);
  EXPECT_GE(SAS::furniture_label_accuracy(models, ids), 0.8);
}

TEST(ChairSet, ArmrestsGetSegmentsOfTheirOwn)
{
  const auto models = SAS::procedural_chair_set(10, 11, furniture(true));
  std::size_t with_arms = 0;
  for(const auto& m : models)
    with_arms += m.has_armrests ? 1 : 0;
  ASSERT_GT(with_arms, 1u);
  ASSERT_LT(with_arms, models.size() - 1);
  // Legs at different places of the chairs are told apart (one id per place, four or more in all:
  // nothing links the front legs to the back ones), and so are the left and right armrests: ten
  // segments leave room for both armrests.
  CS::Consistent_segmentation_result r;
  const auto ids = cosegment(models, CS::parameters::number_of_segments(10).random_seed(5), &r);
  const auto majority = majority_labels(models, ids);
  std::size_t armrest_segments = 0;
  for(const auto& kv : majority) {
    if(kv.second != SAS::ARMREST)
      continue;
    ++armrest_segments;
    // An armrest segment lies (nearly) only in chairs with armrests.
    double inside = 0, outside = 0;
    for(std::size_t i = 0; i < models.size(); ++i)
      for(std::size_t f = 0; f < ids[i].size(); ++f)
        if(ids[i][f] == kv.first)
          (models[i].has_armrests ? inside : outside) += models[i].mesh.area(f);
    EXPECT_LT(outside, 0.05 * inside) << "segment " << kv.first;
  }
  EXPECT_GE(armrest_segments, 2u);
  // Every armchair has most of its armrest area in armrest segments.
  for(std::size_t i = 0; i < models.size(); ++i) {
    if(!models[i].has_armrests)
      continue;
    double arm = 0, found = 0;
    for(std::size_t f = 0; f < ids[i].size(); ++f)
      if(models[i].mesh.labels[f] == SAS::ARMREST) {
        arm += models[i].mesh.area(f);
        if(majority.at(ids[i][f]) == SAS::ARMREST)
          found += models[i].mesh.area(f);
      }
    EXPECT_GT(found, 0.8 * arm) << "chair " << i;
  }
}

TEST(TableSet, TopsAndLegs)
{
  // A quarter of the tables stand on a central pedestal: there the top is split where the legs of
  // the four-legged ones are, so only the four-legged ones must be (nearly) perfect.
  const auto models = SAS::procedural_table_set(8, 21, furniture(true));
  CS::Consistent_segmentation_result r;
  const auto ids = cosegment(models, CS::parameters::number_of_segments(5).random_seed(2), &r);
  expect_consistent_result(ids, r);
  EXPECT_GE(SAS::furniture_label_accuracy(models, ids), 0.8);
  std::vector<SAS::Furniture_model> four_legged;
  std::vector<std::vector<std::size_t>> four_legged_ids;
  for(std::size_t i = 0; i < models.size(); ++i)
    if(models[i].number_of_pieces == 5) {
      four_legged.push_back(models[i]);
      four_legged_ids.push_back(ids[i]);
    }
  ASSERT_GE(four_legged.size(), 4u);
  EXPECT_GE(SAS::furniture_label_accuracy(four_legged, four_legged_ids), 0.97);
}

TEST(ChairSet, LargeSetsAlignOnlyWithPartners)
{
  const auto models = SAS::procedural_chair_set(14, 4, furniture(true));
  CS::Consistent_segmentation_result r;
  const auto ids =
    cosegment(models, CS::parameters::number_of_segments(8).number_of_partners(4).number_of_points(500), &r);
  expect_consistent_result(ids, r);
  // Each mesh is aligned with its 8 candidates: at least 14 * 8 / 2 pairs, at most 14 * 8, fewer
  // than all 91 only because candidates are shared; with 2 partners, 4 candidates: far fewer.
  EXPECT_GE(r.number_of_aligned_pairs, 56u);
  EXPECT_LE(r.number_of_aligned_pairs, 91u);
  CS::Consistent_segmentation_result two;
  cosegment(models, CS::parameters::number_of_segments(8).number_of_partners(2).number_of_points(500), &two);
  EXPECT_GE(two.number_of_aligned_pairs, 28u);
  EXPECT_LE(two.number_of_aligned_pairs, 56u);
  EXPECT_LT(two.number_of_correspondences, r.number_of_correspondences);
  EXPECT_GE(SAS::furniture_label_accuracy(models, ids), 0.85);
}

TEST(ChairSet, SameResultForAnyNumberOfThreadsAndSeedMatters)
{
  const auto models = SAS::procedural_chair_set(6, 8, furniture(true));
  const auto one = cosegment(models, CS::parameters::number_of_segments(6).random_seed(9).number_of_threads(1));
  const auto two = cosegment(models, CS::parameters::number_of_segments(6).random_seed(9).number_of_threads(2));
  const auto all = cosegment(models, CS::parameters::number_of_segments(6).random_seed(9));
  EXPECT_EQ(one, two);
  EXPECT_EQ(one, all);
  CS::Consistent_segmentation_result a, b;
  cosegment(models, CS::parameters::number_of_segments(6).random_seed(9), &a);
  cosegment(models, CS::parameters::number_of_segments(6).random_seed(10), &b);
  EXPECT_NE(a.number_of_correspondences, b.number_of_correspondences); // other samples
}

// ---------------------------------------------------------------------------------------------
// Several runs

TEST(Runs, RandDistanceIsTheChanceOfSplittingTwoPointsDifferently)
{
  const std::vector<double> area = {1.0, 1.0, 2.0};
  EXPECT_DOUBLE_EQ(CS::internal::rand_distance(area, {0, 0, 1}, {5, 5, 7}), 0.0); // same, other ids
  // {0,1 | 2} against {0 | 1,2}: pairs of points (by area, 4 in all) split in one, not the other:
  // 0-1 and 1-2 both ways, 2 * (1 * 1 + 1 * 2) = 6 out of 16.
  EXPECT_DOUBLE_EQ(CS::internal::rand_distance(area, {0, 0, 1}, {0, 1, 1}), 6.0 / 16.0);
  EXPECT_DOUBLE_EQ(CS::internal::rand_distance(area, {0, 1, 1}, {0, 0, 1}), 6.0 / 16.0);
  // Everything in one segment against each item alone: every pair of different items.
  EXPECT_DOUBLE_EQ(CS::internal::rand_distance(area, {0, 0, 0}, {0, 1, 2}), (16.0 - 1 - 1 - 4) / 16.0);
  // Items 1 and 2 only.
  EXPECT_DOUBLE_EQ(CS::internal::rand_distance(area, {0, 0, 1}, {0, 1, 1}, 1, 3), 4.0 / 9.0);

  // One minus the area-weighted Rand index of the benchmark's measure, on random segmentations.
  SAI::Random_stream random(7, 0);
  for(int trial = 0; trial < 20; ++trial) {
    const std::size_t n = 5 + random.index(60);
    std::vector<std::size_t> a(n), b(n);
    std::vector<double> w(n);
    for(std::size_t v = 0; v < n; ++v)
      a[v] = random.index(4), b[v] = random.index(6), w[v] = 0.1 + random.uniform();
    EXPECT_NEAR(CS::internal::rand_distance(w, a, b), 1.0 - SAS::rand_index(a, b, &w), 1e-12);
  }
}

TEST(Runs, TheRunClosestToTheOthersIsKept)
{
  // Two meshes: over-segments 0-3 (unit areas) and 4-5 (areas 1 and 3).
  const std::vector<double> area = {1, 1, 1, 1, 1, 3};
  const std::vector<std::size_t> offset = {0, 4, 6};
  const std::vector<std::vector<std::size_t>> ids = {
    {0, 1, 2, 3, 0, 0}, // run 0: far from the others (32 / 16 in all)
    {0, 0, 1, 1, 0, 1}, // runs 1 and 2 the same (16 / 16 each: the first of them is kept)
    {5, 5, 6, 6, 2, 3},
    {0, 0, 0, 1, 0, 1}, // run 3: an over-segment off runs 1 and 2 (24 / 16)
  };
  double disagreement = -1;
  EXPECT_EQ(CS::internal::consensus_run(ids, area, offset, disagreement), 1u);
  double sum = 0;
  for(std::size_t t : {0u, 2u, 3u})
    for(std::size_t i = 0; i < 2; ++i)
      sum += CS::internal::rand_distance(area, ids[1], ids[t], offset[i], offset[i + 1]);
  EXPECT_DOUBLE_EQ(disagreement, sum / 6.0);
  EXPECT_DOUBLE_EQ(disagreement, (16.0 / 16.0) / 6.0);
  // Of two runs, both as close to the other: the first.
  EXPECT_EQ(CS::internal::consensus_run({ids[3], ids[0]}, area, offset, disagreement), 0u);
  EXPECT_EQ(CS::internal::consensus_run({ids[2]}, area, offset, disagreement), 0u);
  EXPECT_EQ(disagreement, 0.0);
}

TEST(Runs, RunZeroIsTheSeedsOwnAndRunsAgreeOnAnEasySet)
{
  const auto models = SAS::procedural_chair_set(6, 8, furniture(true));
  CS::Consistent_segmentation_result one, two, four;
  const auto single = cosegment(models, CS::parameters::number_of_segments(6).random_seed(4).number_of_runs(1), &one);
  const auto first_of_two =
    cosegment(models, CS::parameters::number_of_segments(6).random_seed(4).number_of_runs(2), &two);
  const auto several = cosegment(models, CS::parameters::number_of_segments(6).random_seed(4), &four);
  EXPECT_EQ(one.number_of_runs, 1u);
  EXPECT_EQ(one.chosen_run, 0u);
  EXPECT_EQ(one.run_disagreement, 0.0);
  EXPECT_EQ(two.chosen_run, 0u); // the first of two
  EXPECT_EQ(single, first_of_two);
  EXPECT_EQ(one.number_of_correspondences, two.number_of_correspondences);
  ASSERT_EQ(four.number_of_runs, CS::Consistent_segmentation_options().number_of_runs);
  EXPECT_GT(four.number_of_runs, 2u);
  EXPECT_LT(four.chosen_run, four.number_of_runs);
  // Procedural chairs split the same way whatever the samples: the runs nearly agree.
  EXPECT_LT(four.run_disagreement, 0.02);
  expect_consistent_result(several, four);
}

TEST(ChairSet, SingleMeshAndProgress)
{
  const auto models = SAS::procedural_chair_set(1, 8, furniture(false));
  std::vector<double> reports;
  CS::Consistent_segmentation_result r;
  const auto ids = cosegment(models,
                             CS::parameters::number_of_segments(3).progress_callback(
                               [&](double f) { reports.push_back(f); }),
                             &r);
  expect_consistent_result(ids, r);
  EXPECT_EQ(r.number_of_segments, 3u);
  EXPECT_EQ(r.number_of_aligned_pairs, 0u);
  ASSERT_FALSE(reports.empty());
  EXPECT_TRUE(std::is_sorted(reports.begin(), reports.end()));
  EXPECT_DOUBLE_EQ(reports.back(), 1.0);
}

TEST(RealMeshes, DifferentAnimalsDoNotCollapseIntoOneSegment)
{
  // CGAL's elephant, cow and hand: loose correspondences, and over-segments on which few or no
  // samples fall. The segments must still split every mesh, not leave one segment covering
  // nearly everything beside a few unsupported scraps.
  std::vector<Mesh> meshes;
  for(const char* name : {"elephant.off", "cow.off", "hand.off"}) {
    Mesh m;
    ASSERT_TRUE(CGAL::IO::read_polygon_mesh(std::string(SHAPE_ANALYSIS_DATA_DIR) + "/" + name, m)) << name;
    meshes.push_back(m);
  }
  std::vector<Id_map> maps = id_maps(meshes);
  const auto r =
    CS::consistent_segmentation(meshes, maps, CS::parameters::number_of_segments(6).number_of_points(300));
  const auto ids = read_ids(meshes, maps);
  expect_consistent_result(ids, r);
  for(std::size_t s = 0; s < r.number_of_segments; ++s) {
    EXPECT_LT(r.segment_area[s], 0.7 * double(meshes.size())) << "segment " << s;
    EXPECT_GT(r.segment_area[s], 0.01) << "segment " << s;
  }
  for(std::size_t i = 0; i < meshes.size(); ++i) {
    // No segment covers more than 80% of any mesh.
    std::map<std::size_t, double> area;
    double total = 0;
    std::size_t f = 0;
    for(auto fd : faces(meshes[i])) {
      const double a = PMP::face_area(fd, meshes[i]);
      area[ids[i][f++]] += a;
      total += a;
    }
    for(const auto& kv : area)
      EXPECT_LT(kv.second, 0.8 * total) << "mesh " << i << " segment " << kv.first;
  }
}

// ---------------------------------------------------------------------------------------------
// Segmentation transfer

// Known labels for the models in `labelled` (all faces, or only those with `keep(i, f)`).
template <typename Keep>
std::vector<std::vector<std::size_t>> transfer(const std::vector<SAS::Furniture_model>& models,
                                               const std::vector<std::size_t>& labelled, Keep keep,
                                               std::size_t k, std::vector<Mesh>& meshes,
                                               CS::Consistent_segmentation_result* r = nullptr)
{
  meshes = to_meshes(models);
  std::vector<Label_map> known;
  for(std::size_t i = 0; i < meshes.size(); ++i) {
    known.push_back(meshes[i].add_property_map<face_descriptor, long long>("f:known", -1).first);
    if(std::find(labelled.begin(), labelled.end(), i) == labelled.end())
      continue;
    std::size_t f = 0;
    for(auto fd : faces(meshes[i])) {
      if(keep(i, f))
        known[i][fd] = static_cast<long long>(models[i].mesh.labels[f]);
      ++f;
    }
  }
  std::vector<Id_map> maps = id_maps(meshes);
  const auto result = CS::consistent_segmentation(
    meshes, maps, CS::parameters::number_of_segments(k).known_segment_maps(known).random_seed(3));
  if(r != nullptr)
    *r = result;
  return read_ids(meshes, maps);
}

void expect_known_kept(const std::vector<SAS::Furniture_model>& models, const std::vector<Mesh>& meshes,
                       const std::vector<std::vector<std::size_t>>& ids)
{
  for(std::size_t i = 0; i < meshes.size(); ++i) {
    auto known = meshes[i].property_map<face_descriptor, long long>("f:known").first;
    std::size_t f = 0;
    for(auto fd : faces(meshes[i])) {
      if(known[fd] >= 0)
        ASSERT_EQ(ids[i][f], static_cast<std::size_t>(known[fd])) << "mesh " << i << " face " << f;
      ++f;
    }
  }
  (void)models;
}

TEST(Transfer, OneExampleLabelsTheSet)
{
  // Chair 0 of this set has armrests: its four labels are the four parts.
  const auto models = SAS::procedural_chair_set(6, 15, furniture(true, 0.6));
  std::size_t example = models.size();
  for(std::size_t i = 0; i < models.size() && example == models.size(); ++i)
    if(models[i].has_armrests)
      example = i;
  ASSERT_LT(example, models.size());
  std::vector<Mesh> meshes;
  CS::Consistent_segmentation_result r;
  const auto ids = transfer(models, {example}, [](std::size_t, std::size_t) { return true; }, 4, meshes, &r);
  expect_known_kept(models, meshes, ids);
  EXPECT_EQ(r.number_of_segments, 4u);
  for(std::size_t l = 0; l < 4; ++l)
    EXPECT_EQ(r.segment_label[l], static_cast<long long>(l));
  std::vector<std::size_t> others;
  for(std::size_t i = 0; i < models.size(); ++i)
    if(i != example)
      others.push_back(i);
  // The ids are the labels themselves: no matching.
  EXPECT_GE(direct_accuracy(models, ids, others), 0.85);
}

TEST(Transfer, LabelledSetLabelsANewMesh)
{
  const auto models = SAS::procedural_chair_set(6, 27, furniture(true));
  std::vector<Mesh> meshes;
  const auto ids =
    transfer(models, {0, 1, 2, 3, 4}, [](std::size_t, std::size_t) { return true; }, 4, meshes);
  expect_known_kept(models, meshes, ids);
  EXPECT_GE(direct_accuracy(models, ids, {5}), 0.9);
}

TEST(Transfer, HalfLabelledMeshesAreCompleted)
{
  // Every chair has the labels of half of its pieces (every other piece, starting with the first
  // in even chairs and the second in odd ones): what one chair lacks, others have.
  const auto models = SAS::procedural_chair_set(6, 31, furniture(true));
  auto half = [&](std::size_t i, std::size_t f) { return (models[i].piece[f] + i) % 2 == 0; };
  std::vector<Mesh> meshes;
  const auto ids = transfer(models, {0, 1, 2, 3, 4, 5}, half, 4, meshes);
  expect_known_kept(models, meshes, ids);
  // Only the faces without a known label count.
  double right = 0, total = 0;
  for(std::size_t i = 0; i < models.size(); ++i)
    for(std::size_t f = 0; f < ids[i].size(); ++f)
      if(!half(i, f)) {
        total += models[i].mesh.area(f);
        if(ids[i][f] == models[i].mesh.labels[f])
          right += models[i].mesh.area(f);
      }
  EXPECT_GE(right / total, 0.9);
}

TEST(Transfer, MapsWithoutKnownLabelsChangeNothing)
{
  const auto models = SAS::procedural_chair_set(3, 5, furniture(true));
  const auto plain = cosegment(models, CS::parameters::number_of_segments(6).random_seed(3));
  std::vector<Mesh> meshes;
  const auto none = transfer(models, {}, [](std::size_t, std::size_t) { return true; }, 6, meshes);
  EXPECT_EQ(plain, none);
}

TEST(Transfer, SparseLabelsKeepTheirValues)
{
  // Labels 0..3 shifted to 10..13: ids 10..13 for them, the others after, ids 0..9 unused.
  const auto models = SAS::procedural_chair_set(3, 5, furniture(true, 1.0));
  std::vector<Mesh> meshes = to_meshes(models);
  std::vector<Label_map> known;
  for(std::size_t i = 0; i < meshes.size(); ++i) {
    known.push_back(meshes[i].add_property_map<face_descriptor, long long>("f:known", -1).first);
    std::size_t f = 0;
    if(i == 0)
      for(auto fd : faces(meshes[i]))
        known[i][fd] = 10 + static_cast<long long>(models[i].mesh.labels[f++]);
  }
  std::vector<Id_map> maps = id_maps(meshes);
  const auto r = CS::consistent_segmentation(meshes, maps,
                                             CS::parameters::number_of_segments(6).known_segment_maps(known));
  const auto ids = read_ids(meshes, maps);
  expect_consistent_result(ids, r);
  EXPECT_EQ(r.number_of_segments, 16u);
  for(std::size_t s = 0; s < 10; ++s)
    EXPECT_TRUE(r.meshes_of_segment[s].empty());
  for(std::size_t s = 10; s < 14; ++s)
    EXPECT_EQ(r.segment_label[s], static_cast<long long>(s));
  for(std::size_t f = 0; f < ids[0].size(); ++f)
    ASSERT_EQ(ids[0][f], 10 + models[0].mesh.labels[f]);

  known[1][*faces(meshes[1]).begin()] = 1LL << 40;
  expect_bad_input([&] { CS::consistent_segmentation(meshes, maps, CS::parameters::known_segment_maps(known)); },
                    "above the largest allowed");
}

TEST(Transfer, TwoKnownLabelsNeverMerge)
{
  // Far fewer segments asked than known labels: the known labels stay apart.
  const auto models = SAS::procedural_chair_set(3, 5, furniture(false, 1.0));
  std::vector<Mesh> meshes;
  CS::Consistent_segmentation_result r;
  const auto ids = transfer(models, {0}, [](std::size_t, std::size_t) { return true; }, 1, meshes, &r);
  expect_known_kept(models, meshes, ids);
  EXPECT_EQ(r.number_of_segments, 4u);
}

// ---------------------------------------------------------------------------------------------
// Symmetric segmentation

// The fraction of the area of `m` whose face has the id of the face closest to its mirror image.
double mirror_agreement(const SAS::Labelled_triangle_mesh& m, const std::vector<std::size_t>& ids,
                        const Vector_3d& n, double d)
{
  std::vector<Vector_3d> centers;
  for(const auto& t : m.triangles)
    centers.push_back((m.point(t[0]) + m.point(t[1]) + m.point(t[2])) / 3.0);
  double good = 0, total = 0;
  for(std::size_t f = 0; f < centers.size(); ++f) {
    const Vector_3d q = centers[f] - n * (2 * (SAI::dot(n, centers[f]) - d));
    std::size_t best = 0;
    double best_d = std::numeric_limits<double>::infinity();
    for(std::size_t g = 0; g < centers.size(); ++g) {
      const double e = (centers[g] - q).squared_length();
      if(e < best_d) {
        best_d = e;
        best = g;
      }
    }
    total += m.area(f);
    if(ids[best] == ids[f])
      good += m.area(f);
  }
  return good / total;
}

// A chair bent slightly out of symmetry: x += 0.04 sin(3 y) + 0.03 z^2 (its plane stays near x = 0).
SAS::Labelled_triangle_mesh bent_chair(std::uint64_t seed)
{
  SAS::Labelled_triangle_mesh m = SAS::procedural_chair(seed, 0, furniture(false, 1.0)).mesh;
  for(auto& p : m.points)
    p[0] += 0.04 * std::sin(3 * p[1]) + 0.03 * p[2] * p[2];
  return m;
}

TEST(Symmetric, MirrorFacesShareTheirSegment)
{
  for(std::uint64_t seed : {2u, 6u}) {
    SCOPED_TRACE(seed);
    const SAS::Labelled_triangle_mesh lm = bent_chair(seed);
    Mesh m;
    SAS::fill_polygon_mesh(lm, m);
    auto sym = m.add_property_map<face_descriptor, std::size_t>("f:sym", unset).first;
    const CS::Consistent_segmentation_result r = CS::symmetric_segmentation(
      m, Kernel::Plane_3(1, 0, 0, 0), sym, CS::parameters::number_of_segments(5).random_seed(1));
    const std::size_t k = r.number_of_segments;
    EXPECT_EQ(k, 5u);
    EXPECT_EQ(r.number_of_aligned_pairs, 0u);
    EXPECT_GT(r.number_of_correspondences, 500u); // mirror links
    std::vector<std::size_t> ids;
    for(auto f : faces(m)) {
      ASSERT_LT(sym[f], k);
      ids.push_back(sym[f]);
    }
    auto plain = m.add_property_map<face_descriptor, std::size_t>("f:plain", unset).first;
    CS::hierarchical_segmentation(m, plain, CS::parameters::number_of_segments(5));
    std::vector<std::size_t> plain_ids;
    for(auto f : faces(m))
      plain_ids.push_back(plain[f]);
    const double symmetric = mirror_agreement(lm, ids, Vector_3d(1, 0, 0), 0);
    const double alone = mirror_agreement(lm, plain_ids, Vector_3d(1, 0, 0), 0);
    EXPECT_GE(symmetric, 0.9);
    EXPECT_GT(symmetric, alone + 0.05);
  }
}

TEST(Symmetric, EachMirrorLinkCountsWithTheLowerSupportOfItsFaces)
{
  namespace CSI = CGAL::Consistent_segmentation::internal;
  const std::vector<double> support = {1.0, 0.5, 0.25, 0.0};
  std::vector<CSI::Correspondence> links = {{0, 0, 0, 1, 2.0}, {0, 2, 0, 1, 1.0}, {0, 0, 0, 0, 3.0},
                                            {0, 3, 0, 0, 1.0}, {0, 1, 0, 3, 1.0}};
  std::vector<CSI::Correspondence> all = links;
  CSI::weigh_by_support({}, all); // no support map: every link as it was
  ASSERT_EQ(all.size(), links.size());
  for(std::size_t i = 0; i < links.size(); ++i)
    EXPECT_EQ(all[i].weight, links[i].weight);
  CSI::weigh_by_support(support, links);
  ASSERT_EQ(links.size(), 3u); // the two links of face 3 (support 0) dropped
  EXPECT_DOUBLE_EQ(links[0].weight, 2.0 * 0.5);  // faces 0 and 1: the lower is 0.5
  EXPECT_DOUBLE_EQ(links[1].weight, 1.0 * 0.25); // faces 2 and 1: 0.25
  EXPECT_DOUBLE_EQ(links[2].weight, 3.0);        // face 0 with itself: 1
  EXPECT_EQ(links[1].node_a, 2u);
}

// Samples on the surface of a box (center `c`, half extents `h`, turned by `angle` about the z
// axis through `pivot`), uniform by area, with the faces' normals; node i is sample i.
void sample_box(const Vector_3d& c, const Vector_3d& h, double angle, const Vector_3d& pivot, std::size_t n,
                std::uint64_t seed, CGAL::Consistent_segmentation::internal::Surface_sample& out)
{
  SAS::Procedural_random rng(seed);
  const double area[3] = {h.y * h.z, h.x * h.z, h.x * h.y};
  const double total = area[0] + area[1] + area[2];
  const double co = std::cos(angle), si = std::sin(angle);
  auto turn = [&](const Vector_3d& v) { return Vector_3d(co * v.x - si * v.y, si * v.x + co * v.y, v.z); };
  for(std::size_t k = 0; k < n; ++k) {
    const double pick = rng.uniform() * total;
    const int axis = pick < area[0] ? 0 : pick < area[0] + area[1] ? 1 : 2;
    const double side = rng.uniform() < 0.5 ? -1.0 : 1.0;
    double local[3], normal[3] = {0, 0, 0};
    for(int a = 0; a < 3; ++a)
      local[a] = (2 * rng.uniform() - 1) * h[a];
    local[axis] = side * h[axis];
    normal[axis] = side;
    const Vector_3d p(local[0], local[1], local[2]);
    out.points.push_back(turn(c + p - pivot) + pivot);
    out.normals.push_back(turn(Vector_3d(normal[0], normal[1], normal[2])));
    out.node.push_back(std::uint32_t(out.node.size()));
  }
  out.diagonal = 2 * (h + Vector_3d(std::abs(c.x), std::abs(c.y), std::abs(c.z))).length();
}

TEST(Articulated, EachOverSegmentIsAlignedOnItsOwn)
{
  namespace CSI = CGAL::Consistent_segmentation::internal;
  // A body and an arm jointed at x = 1; the other mesh has its arm turned by `angle` about z.
  const Vector_3d body_c(0, 0, 0), body_h(1, 0.4, 0.4), arm_c(1.8, 0, 0), arm_h(0.8, 0.15, 0.15), joint(1, 0, 0);
  for(double degrees : {0.0, 25.0}) {
    SCOPED_TRACE(degrees);
    const double angle = degrees * CGAL_PI / 180;
    CSI::Surface_sample a, b;
    sample_box(body_c, body_h, 0, joint, 600, 1, a);
    sample_box(arm_c, arm_h, 0, joint, 300, 2, a);
    sample_box(body_c, body_h, 0, joint, 600, 3, b);
    sample_box(arm_c, arm_h, angle, joint, 300, 4, b);
    std::vector<std::size_t> part(900, 0);
    std::fill(part.begin() + 600, part.end(), 1); // over-segment 1: the arm
    const SAI::Closest_sample closest_b(b.points);
    const std::vector<SAI::Similarity_3d> t = CSI::align_parts(a, part, SAI::Similarity_3d(), b, closest_b);
    ASSERT_EQ(t.size(), 2u);
    // The body fits as it is.
    EXPECT_LT(SAI::rotation_angle_between(t[0].rotation, SAI::identity_matrix()), 1.5 * CGAL_PI / 180);
    EXPECT_LT((t[0](joint) - joint).length(), 0.03);
    // The arm turns about the joint with the other arm: its tip lands on the other tip.
    const double co = std::cos(angle), si = std::sin(angle);
    const Vector_3d tip(2.6, 0, 0), turned_tip = joint + Vector_3d(co, si, 0) * 1.6;
    // (A turn about the arm's own axis, which its square section hardly fixes, does not count.)
    const Vector_3d axis = SAI::multiply(t[1].rotation, Vector_3d(1, 0, 0));
    EXPECT_GT(SAI::dot(axis, Vector_3d(co, si, 0)), std::cos(3 * CGAL_PI / 180));
    EXPECT_LT((t[1](tip) - turned_tip).length(), 0.08);
    if(degrees > 0) // the mesh alignment alone leaves the tip far from the other's
      EXPECT_GT((tip - turned_tip).length(), 0.6);
    EXPECT_DOUBLE_EQ(t[1].scale, 1.0);
  }
  // Limits: an arm turned by 60 degrees, which the ICP alone would follow beyond 0.6 radians,
  // keeps the mesh alignment; so does an over-segment of fewer than 12 samples.
  CSI::Surface_sample a, b;
  sample_box(body_c, body_h, 0, joint, 600, 1, a);
  sample_box(arm_c, arm_h, 0, joint, 300, 2, a);
  sample_box(body_c, body_h, 0, joint, 600, 3, b);
  sample_box(arm_c, arm_h, CGAL_PI / 3, joint, 300, 4, b);
  std::vector<std::size_t> part(900, 0);
  std::fill(part.begin() + 600, part.end(), 1);
  const SAI::Closest_sample closest_b(b.points);
  SAI::Similarity_3d shifted;
  shifted.translation = Vector_3d(0.01, 0, 0);
  const std::vector<SAI::Similarity_3d> t = CSI::align_parts(a, part, shifted, b, closest_b);
  // The same ICP without the limit turns the arm by more: the correction is refused.
  std::vector<SAI::Vector_3d> arm;
  for(std::size_t i = 600; i < 900; ++i)
    arm.push_back(shifted(a.points[i]));
  const SAI::Icp_options io = CSI::part_icp_options();
  SAI::Icp_workspace w;
  const SAI::Icp_result free_arm =
    SAI::make_similarity_icp(arm, closest_b, b.points, closest_b).run(SAI::Similarity_3d(), io, w);
  EXPECT_GT(SAI::rotation_angle_between(free_arm.transform.rotation, SAI::identity_matrix()), CSI::max_part_turn);
  EXPECT_EQ(t[1].translation.x, shifted.translation.x);
  EXPECT_EQ(SAI::rotation_angle_between(t[1].rotation, SAI::identity_matrix()), 0.0);
  std::fill(part.begin() + 600, part.end(), 2);
  std::fill(part.begin() + 889, part.end(), 1); // over-segment 1: 11 samples of the arm's end
  const std::vector<SAI::Similarity_3d> u = CSI::align_parts(a, part, shifted, b, closest_b);
  ASSERT_EQ(u.size(), 3u);
  EXPECT_EQ(u[1].translation.x, shifted.translation.x);
  EXPECT_EQ(SAI::rotation_angle_between(u[1].rotation, SAI::identity_matrix()), 0.0);
}

TEST(Symmetric, SupportWeighsTheMirrorLinks)
{
  const SAS::Labelled_triangle_mesh lm = bent_chair(2);
  Mesh m;
  SAS::fill_polygon_mesh(lm, m);
  const Kernel::Plane_3 plane(1, 0, 0, 0);
  const auto np = CS::parameters::number_of_segments(5).random_seed(1);
  auto labels_of = [&](const std::string& name, auto support, CS::Consistent_segmentation_result& r) {
    auto map = m.add_property_map<face_descriptor, std::size_t>(name, unset).first;
    r = CS::symmetric_segmentation(m, plane, map, np.symmetry_support_map(support));
    std::vector<std::size_t> ids;
    for(auto f : faces(m))
      ids.push_back(map[f]);
    return ids;
  };
  auto plain_map = m.add_property_map<face_descriptor, std::size_t>("f:plain", unset).first;
  const CS::Consistent_segmentation_result plain = CS::symmetric_segmentation(m, plane, plain_map, np);
  std::vector<std::size_t> plain_ids;
  for(auto f : faces(m))
    plain_ids.push_back(plain_map[f]);

  // Support 1 everywhere: the whole surface is symmetric, as without the map.
  auto one = m.add_property_map<face_descriptor, double>("f:one", 1.0).first;
  CS::Consistent_segmentation_result r_one;
  EXPECT_EQ(labels_of("f:a", one, r_one), plain_ids);
  EXPECT_EQ(r_one.number_of_correspondences, plain.number_of_correspondences);

  // Support 0 everywhere: no mirror link is left, the mesh is segmented as alone (one mesh of a set).
  auto zero = m.add_property_map<face_descriptor, double>("f:zero", 0.0).first;
  CS::Consistent_segmentation_result r_zero;
  const std::vector<std::size_t> zero_ids = labels_of("f:b", zero, r_zero);
  EXPECT_EQ(r_zero.number_of_correspondences, 0u);
  std::vector<Mesh> alone(1, m);
  std::vector<Id_map> alone_maps = id_maps(alone);
  CS::consistent_segmentation(alone, alone_maps, np);
  std::vector<std::size_t> alone_ids;
  for(auto f : faces(alone[0]))
    alone_ids.push_back(alone_maps[0][f]);
  EXPECT_EQ(zero_ids, alone_ids);

  // Support on the faces above the seat only: only their links are kept.
  auto upper = m.add_property_map<face_descriptor, double>("f:upper", 0.0).first;
  const double middle = [&] {
    double low = 1e300, high = -1e300;
    for(auto v : vertices(m))
      low = (std::min)(low, m.point(v).z()), high = (std::max)(high, m.point(v).z());
    return 0.5 * (low + high);
  }();
  for(auto f : faces(m))
    upper[f] = CGAL::centroid(m.point(source(halfedge(f, m), m)), m.point(target(halfedge(f, m), m)),
                              m.point(target(next(halfedge(f, m), m), m))).z() > middle ? 1.0 : 0.0;
  CS::Consistent_segmentation_result r_upper;
  labels_of("f:c", upper, r_upper);
  EXPECT_GT(r_upper.number_of_correspondences, 0u);
  EXPECT_LT(r_upper.number_of_correspondences, plain.number_of_correspondences);

  // A support outside [0, 1] is refused, the output untouched.
  auto bad = m.add_property_map<face_descriptor, double>("f:bad", 1.5).first;
  auto untouched = m.add_property_map<face_descriptor, std::size_t>("f:untouched", unset).first;
  expect_bad_input([&] { CS::symmetric_segmentation(m, plane, untouched, np.symmetry_support_map(bad)); }, "support");
  for(auto f : faces(m))
    EXPECT_EQ(untouched[f], unset);
}

TEST(Symmetric, PlaneInAnyPose)
{
  // The bent chair moved rigidly, with its plane moved along and given unnormalized: the result
  // is as symmetric about the moved plane as the unmoved one is about x = 0 (the greedy merging
  // may break ties between mirror merges differently, so the labels need not be identical).
  SAS::Labelled_triangle_mesh lm = bent_chair(2);
  // Rotation by 90 degrees about z and a translation: x -> y, y -> -x.
  SAS::Labelled_triangle_mesh moved = lm;
  for(auto& p : moved.points)
    p = {-p[1] + 3.0, p[0] - 1.0, p[2] + 0.5};
  Mesh mm;
  SAS::fill_polygon_mesh(moved, mm);
  auto b = mm.add_property_map<face_descriptor, std::size_t>("f:b", unset).first;
  // The plane x = 0 becomes y = -1, i.e. 0 x + 2 y + 0 z + 2 = 0.
  const auto r = CS::symmetric_segmentation(mm, Kernel::Plane_3(0, 2, 0, 2), b, CS::parameters::number_of_segments(5));
  EXPECT_EQ(r.number_of_segments, 5u);
  std::vector<std::size_t> lb;
  for(auto f : faces(mm))
    lb.push_back(b[f]);
  EXPECT_GE(mirror_agreement(moved, lb, Vector_3d(0, 1, 0), -1), 0.9);
  // The same plane given with the opposite orientation: as symmetric.
  auto c = mm.add_property_map<face_descriptor, std::size_t>("f:c", unset).first;
  CS::symmetric_segmentation(mm, Kernel::Plane_3(0, -1, 0, -1), c, CS::parameters::number_of_segments(5));
  std::vector<std::size_t> lc;
  for(auto f : faces(mm))
    lc.push_back(c[f]);
  EXPECT_GE(mirror_agreement(moved, lc, Vector_3d(0, 1, 0), -1), 0.9);
}

// ---------------------------------------------------------------------------------------------
// Other mesh types and maps

// ---------------------------------------------------------------------------------------------
// Repeated parts within the meshes

// Per label, the fraction of its area (each model counting as 1) that carries the label's most
// common id, and that id.
std::pair<double, std::size_t> dominant_id(const std::vector<SAS::Furniture_model>& models,
                                           const std::vector<std::vector<std::size_t>>& ids, std::size_t label)
{
  std::map<std::size_t, double> by_id;
  double total = 0;
  for(std::size_t i = 0; i < models.size(); ++i) {
    const SAS::Labelled_triangle_mesh& m = models[i].mesh;
    double mesh_area = 0;
    for(std::size_t f = 0; f < m.number_of_faces(); ++f)
      mesh_area += m.area(f);
    for(std::size_t f = 0; f < m.number_of_faces(); ++f)
      if(m.labels[f] == label) {
        by_id[ids[i][f]] += m.area(f) / mesh_area;
        total += m.area(f) / mesh_area;
      }
  }
  std::pair<double, std::size_t> best(0.0, unset);
  for(const auto& kv : by_id)
    if(kv.second > best.first)
      best = std::make_pair(kv.second, kv.first);
  best.first = total > 0 ? best.first / total : 0.0;
  return best;
}

std::size_t distinct_ids(const std::vector<std::vector<std::size_t>>& ids)
{
  std::set<std::size_t> all;
  for(const auto& mesh : ids)
    all.insert(mesh.begin(), mesh.end());
  return all.size();
}

TEST(Repeated, ChairLegsAndArmrestsGetOneIdEach)
{
  const std::vector<SAS::Furniture_model> models = SAS::procedural_chair_set(8, 3, furniture(true, 1.0));
  std::vector<Mesh> meshes = to_meshes(models);
  std::vector<Id_map> maps = id_maps(meshes);
  CS::Consistent_segmentation_result r =
    CS::consistent_segmentation(meshes, maps, CS::parameters::number_of_segments(8).random_seed(1));
  const std::vector<std::vector<std::size_t>> before = read_ids(meshes, maps);
  // One id per leg place before: the legs' most common id covers about a quarter of their area.
  EXPECT_LT(dominant_id(models, before, SAS::LEG).first, 0.5);
  const double accuracy_before = SAS::furniture_label_accuracy(models, before);

  std::vector<Mesh> copies = meshes;
  std::vector<Id_map> copy_maps;
  for(Mesh& m : copies)
    copy_maps.push_back(m.property_map<face_descriptor, std::size_t>("f:coseg_id").first);
  CS::Consistent_segmentation_result r1 = r;
  const std::size_t removed = CS::merge_repeated_segments(meshes, maps, r, CS::parameters::number_of_threads(2));
  const std::vector<std::vector<std::size_t>> after = read_ids(meshes, maps);
  expect_consistent_result(after, r);
  EXPECT_EQ(removed, distinct_ids(before) - distinct_ids(after));
  EXPECT_EQ(removed, 4u); // four leg ids become one, two armrest ids one
  const auto legs = dominant_id(models, after, SAS::LEG);
  const auto arms = dominant_id(models, after, SAS::ARMREST);
  const auto seat = dominant_id(models, after, SAS::SEAT);
  const auto back = dominant_id(models, after, SAS::BACK);
  EXPECT_GE(legs.first, 0.95);
  EXPECT_GE(arms.first, 0.95);
  // Different kinds of parts are not merged: seat, back, legs and armrests keep apart, and the
  // ids still match the labels as well as before.
  const std::set<std::size_t> kinds = {legs.second, arms.second, seat.second, back.second};
  EXPECT_EQ(kinds.size(), 4u);
  EXPECT_GE(SAS::furniture_label_accuracy(models, after), accuracy_before - 1e-9);

  // One thread gives the same ids.
  CS::merge_repeated_segments(copies, copy_maps, r1, CS::parameters::number_of_threads(1));
  EXPECT_EQ(read_ids(copies, copy_maps), after);
  EXPECT_EQ(r1.number_of_segments, r.number_of_segments);
  EXPECT_EQ(r1.meshes_of_segment, r.meshes_of_segment);
}

// Known labels 0 and 5 (a seat and a back): ids 1 to 4 are unused, the other parts follow from 6.
// The labels keep their ids, the unused ids stay unused, the legs' ids merge after the labels.
TEST(Repeated, LabelsWithGapsKeepTheirIds)
{
  const std::vector<SAS::Furniture_model> models = SAS::procedural_chair_set(6, 3, furniture(true, 0.0));
  std::vector<Mesh> meshes = to_meshes(models);
  std::vector<Id_map> maps = id_maps(meshes);
  std::vector<Label_map> known;
  for(std::size_t i = 0; i < meshes.size(); ++i) {
    known.push_back(meshes[i].add_property_map<face_descriptor, long long>("f:known", -1).first);
    if(i == 0) {
      std::size_t f = 0;
      for(auto fd : faces(meshes[0])) {
        const std::size_t label = models[0].mesh.labels[f++];
        known[0][fd] = label == SAS::SEAT ? 0 : label == SAS::BACK ? 5 : -1;
      }
    }
  }
  CS::Consistent_segmentation_result r = CS::consistent_segmentation(
    meshes, maps, CS::parameters::number_of_segments(8).known_segment_maps(known).random_seed(1));
  ASSERT_EQ(r.segment_label[0], 0);
  ASSERT_EQ(r.segment_label[5], 5);
  for(std::size_t s = 1; s < 5; ++s)
    ASSERT_TRUE(r.meshes_of_segment[s].empty());
  const std::vector<std::vector<std::size_t>> before = read_ids(meshes, maps);
  const std::size_t removed = CS::merge_repeated_segments(meshes, maps, r);
  const std::vector<std::vector<std::size_t>> after = read_ids(meshes, maps);
  EXPECT_EQ(removed, distinct_ids(before) - distinct_ids(after));
  EXPECT_GE(removed, 3u); // the four leg ids
  EXPECT_EQ(r.number_of_segments, 6 + (distinct_ids(after) - 2));
  EXPECT_EQ(r.segment_label[0], 0);
  EXPECT_EQ(r.segment_label[5], 5);
  for(std::size_t s = 1; s < 5; ++s)
    EXPECT_TRUE(r.meshes_of_segment[s].empty());
  for(std::size_t i = 0; i < meshes.size(); ++i)
    for(std::size_t f = 0; f < after[i].size(); ++f) {
      ASSERT_LT(after[i][f], r.number_of_segments);
      if(before[i][f] == 0 || before[i][f] == 5)
        EXPECT_EQ(after[i][f], before[i][f]);
      else
        EXPECT_GE(after[i][f], 6u);
    }
  // Merged leg ids: the legs' most common id covers more of them than before.
  EXPECT_GT(dominant_id(models, after, SAS::LEG).first, dominant_id(models, before, SAS::LEG).first + 0.2)
    << dominant_id(models, before, SAS::LEG).first;
}

TEST(Repeated, KnownLabelsAndBadInput)
{
  const std::vector<SAS::Furniture_model> models = SAS::procedural_chair_set(4, 3, furniture(false, 0.0));
  std::vector<Mesh> meshes = to_meshes(models);
  std::vector<Id_map> maps = id_maps(meshes);
  CS::Consistent_segmentation_result r =
    CS::consistent_segmentation(meshes, maps, CS::parameters::number_of_segments(6).random_seed(1));
  const std::vector<std::vector<std::size_t>> ids = read_ids(meshes, maps);
  // Ids that carry known labels are never merged.
  CS::Consistent_segmentation_result labelled = r;
  for(std::size_t s = 0; s < labelled.number_of_segments; ++s)
    labelled.segment_label[s] = static_cast<long long>(s);
  EXPECT_EQ(CS::merge_repeated_segments(meshes, maps, labelled), 0u);
  EXPECT_EQ(read_ids(meshes, maps), ids);
  // Bad input: nothing written, the result unchanged.
  CS::Consistent_segmentation_result copy = r;
  EXPECT_THROW(CS::merge_repeated_segments(meshes, maps, copy, CS::parameters::duplicate_tolerance(2.0)), CS::Bad_input);
  EXPECT_THROW(CS::merge_repeated_segments(meshes, maps, copy, CS::parameters::number_of_points(3)), CS::Bad_input);
  std::vector<Id_map> fewer(maps.begin(), maps.end() - 1);
  EXPECT_THROW(CS::merge_repeated_segments(meshes, fewer, copy), CS::Bad_input);
  CS::Consistent_segmentation_result wrong_label = r;
  wrong_label.segment_label[1] = 0; // a labelled segment's id is its label
  EXPECT_THROW(CS::merge_repeated_segments(meshes, maps, wrong_label), CS::Bad_input);
  CS::Consistent_segmentation_result short_result = r;
  short_result.segment_area.pop_back();
  EXPECT_THROW(CS::merge_repeated_segments(meshes, maps, short_result), CS::Bad_input);
  maps[2][*faces(meshes[2]).begin()] = r.number_of_segments; // an id the result does not have
  EXPECT_THROW(CS::merge_repeated_segments(meshes, maps, copy), CS::Bad_input);
  maps[2][*faces(meshes[2]).begin()] = ids[2][0];
  EXPECT_EQ(read_ids(meshes, maps), ids);
  EXPECT_EQ(copy.number_of_segments, r.number_of_segments);
  EXPECT_EQ(copy.meshes_of_segment, r.meshes_of_segment);
  std::vector<Mesh> none;
  std::vector<Id_map> no_maps;
  EXPECT_THROW(CS::merge_repeated_segments(none, no_maps, copy), CS::Bad_input);
}

TEST(Parameters, PolyhedronAndVertexPointMaps)
{
  typedef CGAL::Polyhedron_3<Kernel> Polyhedron;
  typedef boost::graph_traits<Polyhedron>::face_descriptor poly_face;
  const auto models = SAS::procedural_chair_set(4, 12, furniture(true));
  std::vector<Polyhedron> polys(models.size());
  for(std::size_t i = 0; i < models.size(); ++i)
    SAS::fill_polygon_mesh(models[i].mesh, polys[i]);
  std::vector<std::map<poly_face, std::size_t>> storage(models.size());
  std::vector<boost::associative_property_map<std::map<poly_face, std::size_t>>> maps;
  for(auto& s : storage)
    maps.emplace_back(s);
  const auto r = CS::consistent_segmentation(polys, maps, CS::parameters::number_of_segments(6));
  EXPECT_EQ(r.number_of_segments, 6u);
  for(std::size_t i = 0; i < polys.size(); ++i)
    EXPECT_EQ(storage[i].size(), num_faces(polys[i]));

  // The same with explicit vertex point maps scaled by 2: ids follow the shapes, not the units.
  std::vector<Mesh> meshes = to_meshes(models);
  std::vector<Mesh::Property_map<Mesh::Vertex_index, Point>> scaled;
  for(Mesh& m : meshes) {
    auto p = m.add_property_map<Mesh::Vertex_index, Point>("v:scaled").first;
    for(auto v : vertices(m))
      p[v] = Point(2 * m.point(v).x(), 2 * m.point(v).y(), 2 * m.point(v).z());
    scaled.push_back(p);
  }
  std::vector<Id_map> a = id_maps(meshes);
  CS::consistent_segmentation(meshes, a, CS::parameters::number_of_segments(6));
  const auto ids_a = read_ids(meshes, a);
  std::vector<Id_map> b;
  for(Mesh& m : meshes)
    b.push_back(m.add_property_map<face_descriptor, std::size_t>("f:scaled_id", unset).first);
  CS::consistent_segmentation(meshes, b, CS::parameters::number_of_segments(6).vertex_point_maps(scaled));
  const auto ids_b = read_ids(meshes, b);
  for(std::size_t i = 0; i < meshes.size(); ++i)
    EXPECT_GE(SAS::rand_index(ids_a[i], ids_b[i]), 0.98) << "mesh " << i;
}

// Every member of the options, for comparisons.
auto option_values(const CS::Consistent_segmentation_options& o)
{
  return std::make_tuple(o.number_of_segments, o.concavity_exponent, o.prior_boundary_factor,
                         o.component_link_distance, o.component_link_factor, o.boundary_refinement,
                         bool(o.progress_callback), o.number_of_oversegments, o.adjacency_exponent,
                         o.number_of_points, o.normal_threshold, o.correspondence_distance,
                         o.number_of_partners, o.number_of_runs, o.random_seed, o.number_of_threads);
}

// The options read from no named parameters are the struct's defaults, the first stage's those of
// hierarchical_segmentation(); a named parameter given lands in its member, and only there.
TEST(Parameters, OptionsFromNamedParameters)
{
  const CS::Consistent_segmentation_options defaults;
  EXPECT_EQ(option_values(CS::consistent_segmentation_options()), option_values(defaults));
  const CS::Hierarchical_segmentation_options stage_one;
  EXPECT_EQ(defaults.number_of_segments, 0u) << "chosen from the meshes' own counts";
  EXPECT_NE(stage_one.number_of_segments, 0u);
  EXPECT_EQ(defaults.concavity_exponent, stage_one.concavity_exponent);

  const auto given = CS::consistent_segmentation_options(
    CS::parameters::number_of_oversegments(7).adjacency_exponent(0.25).random_seed(5u).component_link_factor(0.5)
      .number_of_runs(2).progress_callback([](double) {}));
  CS::Consistent_segmentation_options expected;
  expected.number_of_oversegments = 7;
  expected.adjacency_exponent = 0.25;
  expected.random_seed = 5;
  expected.component_link_factor = 0.5;
  expected.number_of_runs = 2;
  expected.progress_callback = [](double) {};
  EXPECT_EQ(option_values(given), option_values(expected));
}

// ---------------------------------------------------------------------------------------------
// Bad input

TEST(BadInput, SetsAndMeshesThatCannotBeSegmented)
{
  const auto models = SAS::procedural_chair_set(2, 1, furniture(false));
  std::vector<Mesh> meshes = to_meshes(models);
  std::vector<Id_map> maps = id_maps(meshes);
  auto untouched = [&]() {
    for(std::size_t i = 0; i < meshes.size(); ++i)
      for(auto f : faces(meshes[i]))
        if(maps[i][f] != unset)
          return false;
    return true;
  };

  std::vector<Mesh> none;
  std::vector<Id_map> no_maps;
  expect_bad_input([&] { CS::consistent_segmentation(none, no_maps); }, "empty");
  std::vector<Id_map> one_map(maps.begin(), maps.begin() + 1);
  expect_bad_input([&] { CS::consistent_segmentation(meshes, one_map); }, "1 face segment maps for 2 meshes");

  std::vector<Label_map> one_known{meshes[0].add_property_map<face_descriptor, long long>("f:k", -1).first};
  expect_bad_input([&] { CS::consistent_segmentation(meshes, maps, CS::parameters::known_segment_maps(one_known)); },
                   "1 known segment maps for 2 meshes");
  expect_bad_input([&] { CS::consistent_segmentation(meshes, maps, CS::parameters::prior_segment_maps(one_known)); },
                   "1 prior segment maps for 2 meshes");

  // A mesh without faces among good ones.
  std::vector<Mesh> with_empty = meshes;
  with_empty[1].clear();
  std::vector<Id_map> empty_maps = id_maps(with_empty);
  expect_bad_input([&] { CS::consistent_segmentation(with_empty, empty_maps); }, "mesh 1");
  expect_bad_input([&] { CS::consistent_segmentation(with_empty, empty_maps); }, "no faces");

  // A quad and a NaN.
  std::vector<Mesh> quad(1);
  {
    auto v0 = quad[0].add_vertex(Point(0, 0, 0)), v1 = quad[0].add_vertex(Point(1, 0, 0));
    auto v2 = quad[0].add_vertex(Point(1, 1, 0)), v3 = quad[0].add_vertex(Point(0, 1, 0));
    quad[0].add_face(v0, v1, v2, v3);
  }
  std::vector<Id_map> quad_maps = id_maps(quad);
  expect_bad_input([&] { CS::consistent_segmentation(quad, quad_maps); }, "triangle");
  std::vector<Mesh> nan = meshes;
  nan[0].point(*vertices(nan[0]).begin()) = Point(std::nan(""), 0, 0);
  std::vector<Id_map> nan_maps = id_maps(nan);
  expect_bad_input([&] { CS::consistent_segmentation(nan, nan_maps); }, "finite");
  // More segments than the set has faces (it gave fewer segments without a word).
  std::size_t faces_in_all = 0;
  for(const Mesh& m : meshes)
    faces_in_all += num_faces(m);
  expect_bad_input([&] { CS::consistent_segmentation(meshes, maps, CS::parameters::number_of_segments(faces_in_all + 1)); },
                   "exceeds the number of faces");
  // A symmetry plane beside the mesh (it segmented as if it were a symmetry); a normal of 1e-300
  // is a plane, not a zero normal.
  expect_bad_input([&] { CS::symmetric_segmentation(meshes[0], Kernel::Plane_3(0, 0, 1, 1000), maps[0]); },
                   "does not cross the mesh");
  EXPECT_TRUE(untouched());
  EXPECT_NO_THROW(CS::symmetric_segmentation(meshes[0], Kernel::Plane_3(1e-300, 0, 0, 0), maps[0],
                                             CS::parameters::number_of_segments(2)));
}

TEST(BadInput, ParametersOutOfRange)
{
  const auto models = SAS::procedural_chair_set(2, 1, furniture(false));
  std::vector<Mesh> meshes = to_meshes(models);
  std::vector<Id_map> maps = id_maps(meshes);
  namespace P = CS::parameters;
  expect_bad_input([&] { CS::consistent_segmentation(meshes, maps, P::number_of_oversegments(0)); },
                   "number_of_oversegments");
  expect_bad_input([&] { CS::consistent_segmentation(meshes, maps, P::adjacency_exponent(1.5)); },
                   "adjacency_exponent");
  expect_bad_input([&] { CS::consistent_segmentation(meshes, maps, P::adjacency_exponent(std::nan(""))); },
                   "adjacency_exponent");
  expect_bad_input([&] { CS::consistent_segmentation(meshes, maps, P::number_of_points(3)); }, "number_of_points");
  expect_bad_input([&] { CS::consistent_segmentation(meshes, maps, P::number_of_runs(0)); }, "number_of_runs");
  expect_bad_input([&] { CS::consistent_segmentation(meshes, maps, P::number_of_runs(1001)); }, "number_of_runs");
  expect_bad_input([&] { CS::consistent_segmentation(meshes, maps, P::normal_threshold(2.0)); }, "normal_threshold");
  expect_bad_input([&] { CS::consistent_segmentation(meshes, maps, P::correspondence_distance(0.0)); },
                   "correspondence_distance");
  expect_bad_input([&] { CS::consistent_segmentation(meshes, maps, P::concavity_exponent(-1.0)); }, "concavity");
  for(auto f : faces(meshes[0]))
    EXPECT_EQ(maps[0][f], unset);

  auto sym = meshes[0].add_property_map<face_descriptor, std::size_t>("f:sym", unset).first;
  expect_bad_input([&] { CS::symmetric_segmentation(meshes[0], Kernel::Plane_3(0, 0, 0, 1), sym); }, "degenerate");
  expect_bad_input(
    [&] { CS::symmetric_segmentation(meshes[0], Kernel::Plane_3(1, 0, 0, 0), sym, P::number_of_segments(1u << 30)); },
    "number_of_segments");
  for(auto f : faces(meshes[0]))
    EXPECT_EQ(sym[f], unset);
}

} // namespace
