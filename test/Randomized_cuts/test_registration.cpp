// Tests of CGAL::Randomized_cuts::register_meshes() and of the similarity-alignment machinery
// under it: the closed-form similarity solver recovers an exact transform from point pairs, the
// principal frame and the 24 axis orientations are what they claim, ICP converges from a nearby
// start; a procedural shape moved by a large rotation, a scale and a translation is put back
// (with and without vertex noise, with and without partition weighting, through a vertex point
// map); two shapes of the same class align far better than they start; results do not depend on
// the thread count and repeat with the same seed; bad input is refused with Bad_input.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polyhedron_3.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/helpers.h>

#include <CGAL/Randomized_cuts/register_meshes.h>
#include <Shape_analysis_support/Procedural_shapes.h>
#include <CGAL/Shape_analysis/internal/Similarity_alignment.h>

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <set>
#include <string>
#include <vector>

namespace {

typedef CGAL::Exact_predicates_inexact_constructions_kernel Kernel;
typedef Kernel::Point_3 Point;
typedef CGAL::Surface_mesh<Point> Mesh;
typedef Mesh::Vertex_index vertex_descriptor;

namespace RC = CGAL::Randomized_cuts;
namespace SAI = CGAL::Shape_analysis::internal;
namespace SAS = CGAL::Shape_analysis_support;
using SAI::Matrix_3d;
using SAI::Similarity_3d;
using SAI::Vector_3d;

const double pi = 3.14159265358979323846;

// ---------------------------------------------------------------------------------------------
// Helpers

// 120 degrees about a skew axis, scale 1.7, a translation of several shape sizes.
Similarity_3d large_motion()
{
  const SAS::Rigid_transform r =
    SAS::Rigid_transform::from_axis_angle(Vector_3d(1, 2, -0.7), 2 * pi / 3, Vector_3d(3, -5, 2));
  Similarity_3d t;
  t.rotation = r.rotation;
  t.scale = 1.7;
  t.translation = r.translation;
  return t;
}

void apply(SAS::Labelled_triangle_mesh& m, const Similarity_3d& t)
{
  for(auto& p : m.points) {
    const Vector_3d q = t(Vector_3d(p[0], p[1], p[2]));
    p = {q.x, q.y, q.z};
  }
}

Mesh to_mesh(const SAS::Labelled_triangle_mesh& m)
{
  Mesh mesh;
  SAS::fill_polygon_mesh(m, mesh);
  return mesh;
}

// A four-legged body with a head: no rotational symmetry (only a mirror one, which no rotation
// reproduces). Cell 0.17: about 5000 faces.
SAS::Labelled_triangle_mesh animal(std::uint64_t seed = 0, double cell = 0.17)
{
  return SAS::mesh_procedural_shape(SAS::body_with_limbs(seed, true), cell);
}

double diagonal(const SAS::Labelled_triangle_mesh& m)
{
  Vector_3d lo(std::numeric_limits<double>::infinity()), hi(-std::numeric_limits<double>::infinity());
  for(std::size_t v = 0; v < m.points.size(); ++v) {
    lo = lo.min(m.point(v));
    hi = hi.max(m.point(v));
  }
  return (hi - lo).length();
}

Similarity_3d to_similarity(const RC::Registration_result<Kernel>& r)
{
  Similarity_3d t;
  for(std::size_t i = 0; i < 3; ++i) {
    t.rotation[i] = Vector_3d(r.rotation[i][0], r.rotation[i][1], r.rotation[i][2]);
    t.translation[int(i)] = r.translation[i];
  }
  t.scale = r.scale;
  return t;
}

// The largest distance between the images of the vertices of `m` under `a` and `b`.
double largest_displacement(const SAS::Labelled_triangle_mesh& m, const Similarity_3d& a,
                            const Similarity_3d& b)
{
  double d = 0;
  for(std::size_t v = 0; v < m.points.size(); ++v)
    d = (std::max)(d, (a(m.point(v)) - b(m.point(v))).length());
  return d;
}

// How far a registration is from the known transform `truth` (source -> target).
struct Transform_error
{
  double rotation_degrees, scale_relative, displacement_relative;
};

Transform_error error_of(const RC::Registration_result<Kernel>& r, const Similarity_3d& truth,
                         const SAS::Labelled_triangle_mesh& source, double target_diagonal)
{
  const Similarity_3d t = to_similarity(r);
  Transform_error e;
  e.rotation_degrees = SAI::rotation_angle_between(t.rotation, truth.rotation) * 180 / pi;
  e.scale_relative = std::abs(t.scale / truth.scale - 1);
  e.displacement_relative = largest_displacement(source, t, truth) / target_diagonal;
  return e;
}

std::vector<Vector_3d> random_points(std::size_t n, std::uint64_t seed)
{
  SAI::Random_stream rng(seed);
  std::vector<Vector_3d> p(n);
  for(auto& q : p)
    q = Vector_3d(rng.uniform(-1, 2), rng.uniform(-0.5, 0.5), rng.uniform(0, 3));
  return p;
}

// ---------------------------------------------------------------------------------------------
// Machinery

TEST(SimilaritySolver, RecoversExactTransform)
{
  const Similarity_3d truth = large_motion();
  const std::vector<Vector_3d> from = random_points(50, 1);
  std::vector<Vector_3d> to;
  for(const Vector_3d& p : from)
    to.push_back(truth(p));
  Similarity_3d found;
  ASSERT_TRUE(SAI::best_similarity(from, to, std::vector<double>(), found));
  EXPECT_LT(SAI::max_difference(found.rotation, truth.rotation), 1e-10);
  EXPECT_NEAR(found.scale, 1.7, 1e-10);
  EXPECT_LT((found.translation - truth.translation).length(), 1e-9);
  EXPECT_NEAR(SAI::determinant(found.rotation), 1.0, 1e-12);

  // Weights: pairs of weight 0 are ignored, even when they are wildly wrong.
  std::vector<Vector_3d> to_bad = to;
  std::vector<double> weights(from.size(), 2.0);
  for(std::size_t i = 0; i < from.size(); i += 5) {
    to_bad[i] = to_bad[i] + Vector_3d(10, -20, 30);
    weights[i] = 0;
  }
  ASSERT_TRUE(SAI::best_similarity(from, to_bad, weights, found));
  EXPECT_LT(SAI::max_difference(found.rotation, truth.rotation), 1e-10);
  EXPECT_NEAR(found.scale, 1.7, 1e-10);
  // ... and change the answer when they count.
  ASSERT_TRUE(SAI::best_similarity(from, to_bad, std::vector<double>(), found));
  EXPECT_GT(SAI::max_difference(found.rotation, truth.rotation), 1e-3);

  // Rigid: scale stays 1, and the rotation is still found when the data has scale 1.
  Similarity_3d rigid_truth = truth;
  rigid_truth.scale = 1;
  std::vector<Vector_3d> to_rigid;
  for(const Vector_3d& p : from)
    to_rigid.push_back(rigid_truth(p));
  ASSERT_TRUE(SAI::best_similarity(from, to_rigid, std::vector<double>(), found, false));
  EXPECT_EQ(found.scale, 1.0);
  EXPECT_LT(SAI::max_difference(found.rotation, truth.rotation), 1e-10);

  // Coplanar points mapped by a proper rotation: no reflection is returned.
  std::vector<Vector_3d> flat = from, flat_to;
  for(Vector_3d& p : flat)
    p.z = 0;
  for(const Vector_3d& p : flat)
    flat_to.push_back(truth(p));
  ASSERT_TRUE(SAI::best_similarity(flat, flat_to, std::vector<double>(), found));
  EXPECT_NEAR(SAI::determinant(found.rotation), 1.0, 1e-12);
  EXPECT_LT(SAI::max_difference(found.rotation, truth.rotation), 1e-9);

  // Composition and inverse.
  const Similarity_3d back = truth.inverse().after(truth);
  EXPECT_LT(SAI::max_difference(back.rotation, SAI::identity_matrix()), 1e-12);
  EXPECT_NEAR(back.scale, 1.0, 1e-12);
  EXPECT_LT(back.translation.length(), 1e-12);

  // Degenerate: all source points at one place.
  const std::vector<Vector_3d> same(10, Vector_3d(1, 2, 3));
  Similarity_3d untouched;
  EXPECT_FALSE(SAI::best_similarity(same, std::vector<Vector_3d>(10, Vector_3d(0.0)),
                                    std::vector<double>(), untouched));
  EXPECT_EQ(untouched.scale, 1.0);
}

TEST(SimilaritySolver, AxisOrientationsAndPrincipalFrame)
{
  const std::vector<Matrix_3d> o = SAI::axis_orientations();
  ASSERT_EQ(o.size(), 24u);
  EXPECT_EQ(SAI::max_difference(o[0], SAI::identity_matrix()), 0.0);
  std::set<std::vector<double>> distinct;
  for(const Matrix_3d& m : o) {
    EXPECT_EQ(SAI::determinant(m), 1.0);
    EXPECT_LT(SAI::max_difference(SAI::multiply(m, SAI::transpose(m)), SAI::identity_matrix()), 1e-15);
    distinct.insert({m[0].x, m[0].y, m[0].z, m[1].x, m[1].y, m[1].z, m[2].x, m[2].y, m[2].z});
  }
  EXPECT_EQ(distinct.size(), 24u);

  // A box 4 x 2 x 1 rotated: the principal axes are the rotated box axes, by decreasing length.
  const Similarity_3d motion = large_motion();
  SAI::Random_stream rng(7);
  std::vector<Vector_3d> points;
  for(int i = 0; i < 4000; ++i)
    points.push_back(motion(Vector_3d(rng.uniform(-2, 2), rng.uniform(-1, 1), rng.uniform(-0.5, 0.5))));
  const SAI::Pca_frame f = SAI::weighted_pca(points);
  EXPECT_LT((f.centroid - motion.translation).length(), 0.1);
  for(int k = 0; k < 3; ++k) {
    const Vector_3d axis(motion.rotation[0][k], motion.rotation[1][k], motion.rotation[2][k]);
    EXPECT_GT(std::abs(SAI::dot(f.axes[std::size_t(k)], axis)), 0.99) << "axis " << k;
  }
  EXPECT_NEAR(SAI::determinant(f.axes), 1.0, 1e-12);
  EXPECT_GT(f.variances.x, f.variances.y);
  EXPECT_GT(f.variances.y, f.variances.z);
  // Variance of a uniform [-a, a] is a^2/3, times the scale squared.
  EXPECT_NEAR(f.variances.x, 4.0 / 3.0 * 1.7 * 1.7, 0.15);

  // Weights move the centroid.
  std::vector<Vector_3d> two = {Vector_3d(0, 0, 0), Vector_3d(4, 0, 0)};
  EXPECT_NEAR(SAI::weighted_pca(two, {1.0, 3.0}).centroid.x, 3.0, 1e-12);
}

TEST(Icp, ConvergesToTheExactTransformAndTrimsOutliers)
{
  // Points sampled on a shape and on its moved copy; 5% more target points are far outliers.
  const SAS::Labelled_triangle_mesh source_mesh = animal(0, 0.2);
  SAS::Labelled_triangle_mesh target_mesh = source_mesh;
  const Similarity_3d truth = large_motion();
  apply(target_mesh, truth);
  const auto triangles = [](const SAS::Labelled_triangle_mesh& m) {
    std::vector<std::array<Vector_3d, 3>> t;
    for(const auto& f : m.triangles)
      t.push_back({m.point(f[0]), m.point(f[1]), m.point(f[2])});
    return t;
  };
  const SAI::Closest_surface_point source_surface(triangles(source_mesh)),
    target_surface(triangles(target_mesh));
  SAI::Random_stream rng(5);
  std::vector<Vector_3d> source, target;
  for(int i = 0; i < 1500; ++i) {
    const Vector_3d p = source_mesh.point(rng.index(source_mesh.points.size()));
    source.push_back(p);
  }
  for(int i = 0; i < 1500; ++i)
    target.push_back(target_mesh.point(rng.index(target_mesh.points.size())));
  for(int i = 0; i < 75; ++i)
    target.push_back(truth(Vector_3d(rng.uniform(8, 9), rng.uniform(8, 9), rng.uniform(8, 9))));

  // A start 6 degrees, 5% of scale and a bit of translation away.
  Similarity_3d start = truth;
  start.rotation = SAI::multiply(
    SAS::Rigid_transform::from_axis_angle(Vector_3d(0, 1, 1), 0.1, Vector_3d(0.0)).rotation,
    truth.rotation);
  start.scale = 1.6;
  start.translation = truth.translation + Vector_3d(0.1, 0, -0.1);
  SAI::Icp_workspace w;
  SAI::Icp_options o;
  o.keep_fraction = 0.9;
  o.max_iterations = 20;
  o.tolerance = 1e-9;

  // Against the surfaces, point to plane: the exact transform in a few iterations.
  const auto on_surfaces = SAI::make_similarity_icp(source, source_surface, target, target_surface);
  const double start_rms = on_surfaces.trimmed_rms(start, o, w);
  const SAI::Icp_result r = on_surfaces.run(start, o, w);
  EXPECT_LT(r.rms, 1e-6 * start_rms);
  EXPECT_LT(SAI::rotation_angle_between(r.transform.rotation, truth.rotation), 1e-7);
  EXPECT_NEAR(r.transform.scale, 1.7, 1e-7);
  EXPECT_LT((r.transform.translation - truth.translation).length(), 1e-6);
  EXPECT_GT(r.iterations, 1u);
  EXPECT_LT(r.iterations, 12u);
  EXPECT_TRUE(r.converged);

  // Point to point (closed-form steps) on the surfaces: the same way, linearly.
  o.point_to_plane = false;
  const SAI::Icp_result p2p = on_surfaces.run(start, o, w);
  EXPECT_LT(p2p.rms, 0.05 * start_rms);
  EXPECT_LT(SAI::rotation_angle_between(p2p.transform.rotation, truth.rotation), 3e-3);
  EXPECT_GT(p2p.rms, r.rms);
  o.point_to_plane = true;
  // Multi-threaded queries: the same.
  o.number_of_threads = 0;
  const SAI::Icp_result parallel = on_surfaces.run(start, o, w);
  EXPECT_EQ(parallel.rms, r.rms);
  EXPECT_EQ(parallel.transform.scale, r.transform.scale);
  o.number_of_threads = 1;

  // Without trimming the outliers pull the transform away.
  o.keep_fraction = 1.0;
  const SAI::Icp_result untrimmed = on_surfaces.run(start, o, w);
  EXPECT_GT(SAI::rotation_angle_between(untrimmed.transform.rotation, truth.rotation), 1e-3);
  EXPECT_GT(std::abs(untrimmed.transform.scale - 1.7), 1e-2);

  // Between the samples only (independent samples): close, up to the sample spacing.
  o.keep_fraction = 0.9;
  const SAI::Closest_sample source_closest(source), target_closest(target);
  const auto on_samples = SAI::make_similarity_icp(source, source_closest, target, target_closest);
  const SAI::Icp_result s = on_samples.run(start, o, w);
  EXPECT_LT(s.rms, start_rms);
  EXPECT_LT(SAI::rotation_angle_between(s.transform.rotation, truth.rotation), 0.02);
  EXPECT_NEAR(s.transform.scale, 1.7, 0.02);
}

// ---------------------------------------------------------------------------------------------
// register_meshes

TEST(Registration, RecoversALargeSimilarity)
{
  const SAS::Labelled_triangle_mesh source = animal(0);
  SAS::Labelled_triangle_mesh target = source;
  const Similarity_3d truth = large_motion();
  apply(target, truth);
  const Mesh s = to_mesh(source), t = to_mesh(target);
  const double diag = diagonal(target);

  const auto r = RC::register_meshes(s, t, RC::parameters::number_of_samples(40).random_seed(1));
  const Transform_error e = error_of(r, truth, source, diag);
  // The last ICP stage works on the surfaces (point to plane): an exact copy is put back exactly,
  // up to rounding.
  EXPECT_LT(e.rotation_degrees, 1e-3);
  EXPECT_LT(e.scale_relative, 1e-6);
  EXPECT_LT(e.displacement_relative, 1e-6);
  EXPECT_LT(r.rms_distance, 1e-6 * diag);
  EXPECT_GT(r.initial_rms_distance, 0.1 * diag);
  EXPECT_EQ(r.number_of_restarts, 24u);
  EXPECT_LT(r.best_restart, 24u);
  EXPECT_EQ(r.number_of_points, 2000u);
  EXPECT_GT(r.number_of_iterations, 0u);

  // The affine transformation is the same map as rotation, scale and translation.
  const Similarity_3d st = to_similarity(r);
  for(std::size_t v = 0; v < source.points.size(); v += 97) {
    const Point p(source.points[v][0], source.points[v][1], source.points[v][2]);
    const Point q = r.transformation.transform(p);
    const Vector_3d expected = st(source.point(v));
    EXPECT_NEAR(q.x(), expected.x, 1e-9);
    EXPECT_NEAR(q.y(), expected.y, 1e-9);
    EXPECT_NEAR(q.z(), expected.z, 1e-9);
  }

  // The other way round: the inverse transform.
  const auto back = RC::register_meshes(t, s, RC::parameters::number_of_samples(40).random_seed(1));
  const Transform_error eb = error_of(back, truth.inverse(), target, diagonal(source));
  EXPECT_LT(eb.rotation_degrees, 1e-3);
  EXPECT_NEAR(back.scale, 1 / 1.7, 1e-6);
  EXPECT_LT(eb.displacement_relative, 1e-6);
}

TEST(Registration, NoisyVerticesAndUniformSampling)
{
  const SAS::Labelled_triangle_mesh source = animal(0);
  SAS::Labelled_triangle_mesh target = source;
  const Similarity_3d truth = large_motion();
  apply(target, truth);
  const double diag = diagonal(target);
  // Noise of 1% of the bounding-box diagonal on every coordinate.
  SAI::Random_stream rng(11);
  for(auto& p : target.points)
    for(double& c : p)
      c += rng.uniform(-0.01, 0.01) * diag;
  const Mesh s = to_mesh(source), t = to_mesh(target);

  for(bool weighting : {true, false}) {
    const auto r = RC::register_meshes(
      s, t, RC::parameters::number_of_samples(40).partition_weighting(weighting).random_seed(2));
    const Transform_error e = error_of(r, truth, source, diag);
    EXPECT_LT(e.rotation_degrees, 1.0) << "weighting " << weighting;
    EXPECT_LT(e.scale_relative, 0.005) << "weighting " << weighting;
    EXPECT_LT(e.displacement_relative, 0.005) << "weighting " << weighting;
    // The noise itself is the floor (uniform noise of +-1% per coordinate: 0.58% standard
    // deviation across the surface, less after trimming the worst 10%).
    EXPECT_LT(r.rms_distance, 0.006 * diag) << "weighting " << weighting;
  }
}

TEST(Registration, ShapesOfTheSameClass)
{
  // Two different four-legged bodies (sizes and positions jittered), the second moved far away.
  const SAS::Labelled_triangle_mesh a = animal(1);
  SAS::Labelled_triangle_mesh b = animal(2);
  const Similarity_3d truth = large_motion();
  apply(b, truth);
  const Mesh ma = to_mesh(a), mb = to_mesh(b);
  const double diag = diagonal(b);
  const auto r = RC::register_meshes(ma, mb, RC::parameters::number_of_samples(40).random_seed(3));
  EXPECT_LT(r.rms_distance, 0.01 * diag);
  EXPECT_LT(r.rms_distance, 0.01 * r.initial_rms_distance);
  // The parts correspond: the alignment is close to the motion applied (the shapes differ by a
  // few percent).
  const Transform_error e = error_of(r, truth, a, diag);
  EXPECT_LT(e.rotation_degrees, 3.0);
  EXPECT_LT(e.scale_relative, 0.05);
}

// A mesh onto itself stays where it is: the identity competes with the restarts. A flat square is
// the hard case: its turns within its plane change only the trimmed distance at its border.
TEST(Registration, MeshOntoItselfIsTheIdentityAlsoWhenFlat)
{
  for(const Mesh& m : {to_mesh(SAS::flat_square(8)), to_mesh(animal(0))}) {
    const auto r = RC::register_meshes(m, m, RC::parameters::number_of_samples(10).random_seed(3));
    EXPECT_EQ(r.best_restart, r.number_of_restarts);
    EXPECT_EQ(r.rms_distance, r.initial_rms_distance);
    EXPECT_EQ(r.scale, 1.0);
    for(int i = 0; i < 3; ++i)
      for(int j = 0; j < 4; ++j)
        EXPECT_EQ(r.transformation.m(i, j), i == j ? 1.0 : 0.0);
  }
}

TEST(Registration, TargetVertexPointMap)
{
  // The target is the same mesh seen through a vertex point map that moves it.
  const SAS::Labelled_triangle_mesh source = animal(0);
  Mesh s = to_mesh(source);
  const Similarity_3d truth = large_motion();
  auto moved = s.add_property_map<vertex_descriptor, Point>("v:moved").first;
  SAS::Labelled_triangle_mesh target = source;
  apply(target, truth);
  for(vertex_descriptor v : vertices(s)) {
    const Point& p = s.point(v);
    const Vector_3d q = truth(Vector_3d(p.x(), p.y(), p.z()));
    moved[v] = Point(q.x, q.y, q.z);
  }
  const auto r = RC::register_meshes(s, s, RC::parameters::number_of_samples(30).random_seed(4),
                                     RC::parameters::vertex_point_map(moved));
  const Transform_error e = error_of(r, truth, source, diagonal(target));
  EXPECT_LT(e.rotation_degrees, 1e-3);
  EXPECT_LT(e.displacement_relative, 1e-6);
}

TEST(Registration, DeterministicForAnyThreadCount)
{
  const SAS::Labelled_triangle_mesh source = animal(0, 0.2);
  SAS::Labelled_triangle_mesh target = animal(5, 0.2);
  apply(target, large_motion());
  const Mesh s = to_mesh(source), t = to_mesh(target);
  const auto np = RC::parameters::number_of_samples(30).number_of_points(1000).random_seed(9);
  const auto a = RC::register_meshes(s, t, np.number_of_threads(1));
  const auto b = RC::register_meshes(s, t, np.number_of_threads(0));
  // Again, with a progress callback: progress goes from 0 to 1 without going back.
  std::vector<double> fractions;
  std::function<void(double)> record = [&](double f) { fractions.push_back(f); };
  const auto c = RC::register_meshes(s, t, np.number_of_threads(2).progress_callback(record));
  ASSERT_FALSE(fractions.empty());
  EXPECT_EQ(fractions.back(), 1.0);
  EXPECT_GE(fractions.front(), 0.0);
  for(std::size_t i = 1; i < fractions.size(); ++i)
    EXPECT_GE(fractions[i], fractions[i - 1]);

  for(const auto* x : {&b, &c}) {
    EXPECT_EQ(a.rms_distance, x->rms_distance);
    EXPECT_EQ(a.scale, x->scale);
    EXPECT_EQ(a.translation, x->translation);
    EXPECT_EQ(a.rotation, x->rotation);
    EXPECT_EQ(a.best_restart, x->best_restart);
    EXPECT_EQ(a.number_of_iterations, x->number_of_iterations);
    for(int i = 0; i < 3; ++i)
      for(int j = 0; j < 4; ++j)
        EXPECT_EQ(a.transformation.m(i, j), x->transformation.m(i, j));
  }
  // Another seed draws other points: another (still good) result.
  const auto d = RC::register_meshes(s, t, np.random_seed(10));
  EXPECT_NE(a.rms_distance, d.rms_distance);
  EXPECT_LT(std::abs(d.rms_distance - a.rms_distance), 0.5 * a.rms_distance);
}

TEST(Registration, WorksWithPolyhedron)
{
  typedef CGAL::Polyhedron_3<Kernel> Polyhedron;
  const SAS::Labelled_triangle_mesh source = SAS::mesh_procedural_shape(SAS::three_sphere_chain(3), 0.3);
  SAS::Labelled_triangle_mesh target = source;
  apply(target, large_motion());
  Polyhedron s, t;
  SAS::fill_polygon_mesh(source, s);
  SAS::fill_polygon_mesh(target, t);
  const auto r = RC::register_meshes(s, t, RC::parameters::number_of_samples(20).number_of_points(800));
  // The chain is nearly symmetric about its axis: only the distance is a meaningful check.
  EXPECT_LT(r.rms_distance, 1e-6 * diagonal(target));
  EXPECT_NEAR(r.scale, 1.7, 1e-6);
}

TEST(Options, RegisterMeshesOptionsHoldTheDefaultsAndTheNamedParameters)
{
  const RC::Register_meshes_options defaults;
  const RC::Register_meshes_options read = RC::register_meshes_options();
  EXPECT_EQ(read.number_of_points, defaults.number_of_points);
  EXPECT_EQ(read.number_of_iterations, defaults.number_of_iterations);
  EXPECT_EQ(read.overlap, defaults.overlap);
  EXPECT_EQ(read.partition_weighting, defaults.partition_weighting);
  EXPECT_EQ(read.number_of_samples, defaults.number_of_samples);
  EXPECT_EQ(read.random_seed, defaults.random_seed);
  EXPECT_EQ(read.sampling_method, defaults.sampling_method);
  EXPECT_EQ(read.part_size, defaults.part_size);
  // The registration samples fewer segmentations per partition function than partition_function().
  EXPECT_LT(defaults.number_of_samples, RC::Partition_function_options().number_of_samples);

  const RC::Register_meshes_options given = RC::register_meshes_options(
    RC::parameters::number_of_points(123).overlap(0.5).number_of_iterations(7).number_of_samples(9)
      .partition_weighting(false).random_seed(4).part_size(0.1));
  EXPECT_EQ(given.number_of_points, 123u);
  EXPECT_EQ(given.overlap, 0.5);
  EXPECT_EQ(given.number_of_iterations, 7u);
  EXPECT_EQ(given.number_of_samples, 9u);
  EXPECT_FALSE(given.partition_weighting);
  EXPECT_EQ(given.random_seed, 4u);
  EXPECT_EQ(given.part_size, 0.1);
}

TEST(BadInput, MeshesAndParameters)
{
  const Mesh good = to_mesh(SAS::mesh_procedural_shape(SAS::three_sphere_chain(0), 0.4));
  const auto quick = RC::parameters::number_of_samples(5).number_of_points(100);
  auto expect_bad = [](const auto& call, const std::string& part) {
    try {
      call();
      ADD_FAILURE() << "no exception, expected one mentioning '" << part << "'";
    } catch(const CGAL::Shape_analysis::Bad_input& e) {
      EXPECT_NE(std::string(e.what()).find(part), std::string::npos) << e.what();
      EXPECT_EQ(std::string(e.what()).find('\n'), std::string::npos);
    }
  };

  const Mesh empty;
  expect_bad([&] { RC::register_meshes(empty, good, quick); }, "source mesh): the mesh has no faces");
  expect_bad([&] { RC::register_meshes(good, empty, quick); }, "target mesh): the mesh has no faces");
  expect_bad([&] { RC::register_meshes(good, empty, quick.partition_weighting(false)); },
             "target mesh): the mesh has no faces");

  Mesh quad;
  {
    const auto v0 = quad.add_vertex(Point(0, 0, 0)), v1 = quad.add_vertex(Point(1, 0, 0)),
               v2 = quad.add_vertex(Point(1, 1, 0)), v3 = quad.add_vertex(Point(0, 1, 0));
    quad.add_face(v0, v1, v2, v3);
  }
  expect_bad([&] { RC::register_meshes(quad, good, quick); }, "not a triangle");

  Mesh nan_mesh = good;
  nan_mesh.point(*vertices(nan_mesh).begin()) =
    Point(std::numeric_limits<double>::quiet_NaN(), 0, 0);
  expect_bad([&] { RC::register_meshes(good, nan_mesh, quick); }, "not a finite number");

  Mesh flat;
  {
    const auto v0 = flat.add_vertex(Point(0, 0, 0)), v1 = flat.add_vertex(Point(1, 0, 0)),
               v2 = flat.add_vertex(Point(2, 0, 0));
    flat.add_face(v0, v1, v2);
  }
  expect_bad([&] { RC::register_meshes(flat, good, quick.partition_weighting(false)); }, "no area");

  expect_bad([&] { RC::register_meshes(good, good, quick.number_of_points(5)); }, "number_of_points");
  expect_bad([&] { RC::register_meshes(good, good, quick.overlap(0.0)); }, "overlap");
  expect_bad([&] { RC::register_meshes(good, good, quick.overlap(1.5)); }, "overlap");
  // The partition function's own checks, with the registration's name and the mesh.
  expect_bad([&] { RC::register_meshes(good, good, quick.part_size(0.5)); }, "register_meshes (source mesh): ");
}

} // namespace
