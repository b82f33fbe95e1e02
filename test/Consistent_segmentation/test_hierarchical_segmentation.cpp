// Tests of CGAL::Consistent_segmentation::hierarchical_segmentation(): procedural shapes whose
// parts are known must be recovered, separate pieces must be separated, CGAL's demo meshes give
// valid segmentations (K segments, connected, numbered by decreasing area), the result does not
// depend on a rigid motion or on the order of the faces, a prior segmentation is followed,
// Polyhedron_3 works, and bad input is refused with Bad_input without touching the output map.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polyhedron_3.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Surface_mesh/IO/OFF.h>
#include <CGAL/boost/graph/generators.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/Polygon_mesh_processing/connected_components.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Polygon_mesh_processing/orientation.h>

#include <CGAL/Consistent_segmentation/hierarchical_segmentation.h>
#include <Shape_analysis_support/Procedural_shapes.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <limits>
#include <map>
#include <numeric>
#include <queue>
#include <set>
#include <string>
#include <vector>

namespace {

typedef CGAL::Exact_predicates_inexact_constructions_kernel Kernel;
typedef Kernel::Point_3 Point;
typedef CGAL::Surface_mesh<Point> Mesh;
typedef Mesh::Vertex_index vertex_descriptor;
typedef Mesh::Face_index face_descriptor;
typedef CGAL::Polyhedron_3<Kernel> Polyhedron;

namespace CS = CGAL::Consistent_segmentation;
namespace SAI = CGAL::Shape_analysis::internal;
namespace PMP = CGAL::Polygon_mesh_processing;
namespace SAS = CGAL::Shape_analysis_support;
using SAI::Vector_3d;

// A part-recovery threshold: the real algorithm scores >= 0.97 on every procedural shape; random
// labels or a plausible but wrong split score far below (see MeasuresRejectWrongSegmentations).
const double recovery_threshold = 0.95;
const std::size_t unset = std::numeric_limits<std::size_t>::max();

// ---------------------------------------------------------------------------------------------
// Helpers

std::string data_file(const std::string& name) { return std::string(SHAPE_ANALYSIS_DATA_DIR) + "/" + name; }

Mesh read_mesh(const std::string& name)
{
  Mesh m;
  std::ifstream in(data_file(name));
  EXPECT_TRUE(in.good()) << "cannot open " << data_file(name);
  EXPECT_TRUE(CGAL::IO::read_OFF(in, m)) << "cannot read " << name;
  return m;
}

Mesh to_surface_mesh(const SAS::Labelled_triangle_mesh& lm)
{
  Mesh m;
  SAS::fill_polygon_mesh(lm, m);
  return m;
}

// The triangles of a Surface_mesh as a soup (for shuffling).
SAS::Labelled_triangle_mesh to_soup(const Mesh& m)
{
  SAS::Labelled_triangle_mesh lm;
  for(auto v : vertices(m))
    lm.points.push_back({m.point(v).x(), m.point(v).y(), m.point(v).z()});
  for(auto f : faces(m)) {
    std::array<std::size_t, 3> t;
    std::size_t i = 0;
    for(auto v : vertices_around_face(halfedge(f, m), m))
      t[i++] = v;
    lm.triangles.push_back(t);
    lm.labels.push_back(0);
  }
  lm.number_of_labels = 1;
  return lm;
}

// Segments `m` with `np`; returns the label of each face (by face index) and the count.
template <typename NP>
std::vector<std::size_t> segment(const Mesh& m, const NP& np, std::size_t* count = nullptr)
{
  Mesh copy = m; // the property map is added to a copy: `m` stays const
  auto seg = copy.add_property_map<face_descriptor, std::size_t>("f:test_segment", unset).first;
  const std::size_t n = CS::hierarchical_segmentation(copy, seg, np);
  if(count != nullptr)
    *count = n;
  std::vector<std::size_t> labels;
  for(auto f : faces(copy))
    labels.push_back(seg[f]);
  return labels;
}

std::vector<std::size_t> segment_k(const Mesh& m, std::size_t k, std::size_t* count = nullptr)
{
  return segment(m, CS::parameters::number_of_segments(k), count);
}

std::vector<double> face_areas(const Mesh& m)
{
  std::vector<double> a;
  for(auto f : faces(m))
    a.push_back(PMP::face_area(f, m));
  return a;
}

// Connected pieces of each label through the edges of `m`.
std::vector<std::size_t> pieces_per_label(const Mesh& m, const std::vector<std::size_t>& labels,
                                          std::size_t k)
{
  std::vector<std::size_t> pieces(k, 0);
  std::vector<char> seen(num_faces(m), 0);
  for(auto f0 : faces(m)) {
    if(seen[f0])
      continue;
    ++pieces[labels[f0]];
    std::queue<face_descriptor> queue;
    queue.push(f0);
    seen[f0] = 1;
    while(!queue.empty()) {
      const face_descriptor f = queue.front();
      queue.pop();
      for(auto h : halfedges_around_face(halfedge(f, m), m)) {
        const face_descriptor g = face(opposite(h, m), m);
        if(g == Mesh::null_face() || seen[g] || labels[g] != labels[f])
          continue;
        seen[g] = 1;
        queue.push(g);
      }
    }
  }
  return pieces;
}

// Every face labelled in 0..k-1, every label used, numbered by decreasing area, and (for a
// connected mesh) every segment connected.
void expect_valid_segmentation(const Mesh& m, const std::vector<std::size_t>& labels,
                               std::size_t count, std::size_t k, bool connected_segments)
{
  EXPECT_EQ(count, k);
  ASSERT_EQ(labels.size(), num_faces(m));
  std::vector<double> area(k, 0.0);
  std::vector<std::size_t> faces_of(k, 0);
  const std::vector<double> a = face_areas(m);
  for(std::size_t f = 0; f < labels.size(); ++f) {
    ASSERT_NE(labels[f], unset) << "face " << f << " was not labelled";
    ASSERT_LT(labels[f], k);
    area[labels[f]] += a[f];
    ++faces_of[labels[f]];
  }
  for(std::size_t l = 0; l < k; ++l)
    EXPECT_GT(faces_of[l], 0u) << "label " << l << " unused";
  for(std::size_t l = 0; l + 1 < k; ++l)
    EXPECT_GE(area[l], area[l + 1]) << "labels " << l << " and " << l + 1;
  if(connected_segments) {
    const std::vector<std::size_t> pieces = pieces_per_label(m, labels, k);
    for(std::size_t l = 0; l < k; ++l)
      EXPECT_EQ(pieces[l], 1u) << "segment " << l << " is in " << pieces[l] << " pieces";
  }
}

struct Agreement
{
  double rand_index;
  double overlap; // area-weighted best-matching overlap
};

Agreement agreement(const std::vector<std::size_t>& a, const std::vector<std::size_t>& b,
                    const std::vector<double>& areas)
{
  return {SAS::rand_index(a, b), SAS::matched_overlap(a, b, &areas)};
}

bool recovers(const Agreement& x)
{
  return x.rand_index >= recovery_threshold && x.overlap >= recovery_threshold;
}

// Segments a procedural shape into its number of parts and checks that the parts are recovered
// and numbered by decreasing area.
void expect_parts_recovered(const SAS::Procedural_shape& shape, double cell, const char* what)
{
  SCOPED_TRACE(what);
  const SAS::Labelled_triangle_mesh lm = SAS::mesh_procedural_shape(shape, cell);
  const Mesh m = to_surface_mesh(lm);
  const std::size_t k = lm.number_of_labels;
  std::size_t count = 0;
  const std::vector<std::size_t> labels = segment_k(m, k, &count);
  expect_valid_segmentation(m, labels, count, k, true);
  const std::vector<double> areas = lm.areas();
  const Agreement x = agreement(labels, lm.labels, areas);
  EXPECT_TRUE(recovers(x)) << "Rand index " << x.rand_index << ", overlap " << x.overlap;
  // The segment of each part is the one of its rank by area.
  std::vector<double> part_area(k, 0.0);
  for(std::size_t f = 0; f < areas.size(); ++f)
    part_area[lm.labels[f]] += areas[f];
  std::vector<std::size_t> rank(k);
  std::iota(rank.begin(), rank.end(), std::size_t(0));
  std::sort(rank.begin(), rank.end(), [&](std::size_t a, std::size_t b) { return part_area[a] > part_area[b]; });
  std::vector<std::map<std::size_t, double>> votes(k);
  for(std::size_t f = 0; f < areas.size(); ++f)
    votes[lm.labels[f]][labels[f]] += areas[f];
  std::size_t checked = 0;
  for(std::size_t r = 0; r < k; ++r) {
    // Only parts whose area differs by 5% from the parts of the neighbouring ranks.
    const bool distinct = (r == 0 || part_area[rank[r - 1]] > 1.05 * part_area[rank[r]]) &&
                          (r + 1 == k || part_area[rank[r]] > 1.05 * part_area[rank[r + 1]]);
    if(!distinct)
      continue;
    const auto& v = votes[rank[r]];
    const auto best = std::max_element(v.begin(), v.end(), [](const auto& p, const auto& q) {
      return p.second < q.second;
    });
    EXPECT_EQ(best->first, r) << "part " << rank[r] << " of rank " << r << " by area";
    ++checked;
  }
  EXPECT_GE(checked, 1u) << "the largest part at least is checked";
}

// ---------------------------------------------------------------------------------------------
// The automatic number of segments (number_of_segments 0)

TEST(AutomaticCount, NeverMergesPartsBoundedByCreasesAndSegmentsAsIfGiven)
{
  // Parts joined along concave creases stay apart: the count chosen is at least the number of
  // parts (the boundaries between them, creases, raise the score of every count that keeps them),
  // within [2, 12]; the segmentation is the one given that count.
  const std::pair<SAS::Procedural_shape, double> shapes[] = {{SAS::three_sphere_chain(), 0.2},
                                                             {SAS::three_sphere_chain(2), 0.18},
                                                             {SAS::body_with_limbs(), 0.14},
                                                             {SAS::body_with_limbs(4, true), 0.14},
                                                             {SAS::star(6), 0.16}};
  for(const auto& s : shapes) {
    const SAS::Labelled_triangle_mesh lm = SAS::mesh_procedural_shape(s.first, s.second);
    const Mesh m = to_surface_mesh(lm);
    std::size_t automatic = 0, given = 0;
    const std::vector<std::size_t> labels = segment_k(m, 0, &automatic);
    EXPECT_GE(automatic, lm.number_of_labels);
    EXPECT_GE(automatic, 2u);
    EXPECT_LE(automatic, 12u);
    EXPECT_EQ(segment_k(m, automatic, &given), labels);
    EXPECT_EQ(given, automatic);
  }
  // The chain of three spheres with even creases: exactly its three parts.
  const SAS::Labelled_triangle_mesh lm = SAS::mesh_procedural_shape(SAS::three_sphere_chain(2), 0.18);
  std::size_t automatic = 0;
  segment_k(to_surface_mesh(lm), 0, &automatic);
  EXPECT_EQ(automatic, 3u);
}

TEST(AutomaticCount, TinyMeshes)
{
  // A tetrahedron: at most its four faces; two triangles: two.
  Mesh t;
  const auto a = t.add_vertex(Point(0, 0, 0)), b = t.add_vertex(Point(1, 0, 0)), c = t.add_vertex(Point(0, 1, 0)),
             d = t.add_vertex(Point(0, 0, 1));
  t.add_face(a, c, b);
  t.add_face(a, b, d);
  t.add_face(a, d, c);
  t.add_face(b, c, d);
  std::size_t count = 0;
  segment_k(t, 0, &count);
  EXPECT_GE(count, 2u);
  EXPECT_LE(count, 4u);
  Mesh two;
  const auto p = two.add_vertex(Point(0, 0, 0)), q = two.add_vertex(Point(1, 0, 0)), r = two.add_vertex(Point(0, 1, 0)),
             u = two.add_vertex(Point(1, 1, 0.2));
  two.add_face(p, q, r);
  two.add_face(q, u, r);
  segment_k(two, 0, &count);
  EXPECT_EQ(count, 2u);
}

// ---------------------------------------------------------------------------------------------
// Procedural shapes: the known parts are recovered

TEST(ProceduralParts, ThreeSphereChain)
{
  expect_parts_recovered(SAS::three_sphere_chain(), 0.2, "seed 0");
  expect_parts_recovered(SAS::three_sphere_chain(1), 0.2, "seed 1");
  expect_parts_recovered(SAS::three_sphere_chain(2), 0.18, "seed 2");
}

TEST(ProceduralParts, BodyWithFourLegs)
{
  expect_parts_recovered(SAS::body_with_limbs(), 0.14, "four legs");
  expect_parts_recovered(SAS::body_with_limbs(4, true), 0.14, "four legs and a head");
}

TEST(ProceduralParts, Star)
{
  expect_parts_recovered(SAS::star(6), 0.16, "six arms");
  expect_parts_recovered(SAS::star(8, 3), 0.15, "eight arms");
}

TEST(ProceduralParts, MeasuresRejectWrongSegmentations)
{
  // The agreement measures would catch a wrong algorithm: random labels and a plausible split
  // across the parts (three slabs along z, of about equal area) stay far below the threshold.
  const SAS::Labelled_triangle_mesh lm = SAS::mesh_procedural_shape(SAS::three_sphere_chain(), 0.2);
  const std::vector<double> areas = lm.areas();
  SAS::Procedural_random rng(1);
  std::vector<std::size_t> random_labels(lm.number_of_faces());
  for(auto& l : random_labels)
    l = rng.index(3);
  const Agreement random = agreement(random_labels, lm.labels, areas);
  EXPECT_FALSE(recovers(random)) << random.rand_index << " " << random.overlap;
  EXPECT_LT(random.rand_index, 0.7);

  std::vector<std::size_t> slabs(lm.number_of_faces());
  for(std::size_t f = 0; f < slabs.size(); ++f) {
    const double z = lm.centroid(f).z;
    slabs[f] = z < -0.3 ? 0 : (z < 0.3 ? 1 : 2);
  }
  const Agreement slab = agreement(slabs, lm.labels, areas);
  EXPECT_FALSE(recovers(slab)) << slab.rand_index << " " << slab.overlap;
  EXPECT_LT(slab.overlap, 0.7);

  // A split along the chain but at the wrong places (the middle of the spheres) fails too.
  std::vector<std::size_t> shifted(lm.number_of_faces());
  for(std::size_t f = 0; f < shifted.size(); ++f) {
    const double x = lm.centroid(f).x;
    shifted[f] = x < -1.45 ? 0 : (x < 1.4 ? 1 : 2);
  }
  const Agreement shift = agreement(shifted, lm.labels, areas);
  EXPECT_FALSE(recovers(shift)) << shift.rand_index << " " << shift.overlap;
}

// ---------------------------------------------------------------------------------------------
// Separate pieces

TEST(SeparatePieces, EachBoxIsOneSegment)
{
  for(double gap : {1.0, 0.15}) { // far apart (spanning links) and close (proximity links)
    SCOPED_TRACE("gap " + std::to_string(gap));
    const SAS::Labelled_triangle_mesh lm = SAS::mesh_procedural_shape(SAS::separate_boxes(4, gap), 0.15);
    ASSERT_EQ(SAS::number_of_components(lm), 4u);
    const Mesh m = to_surface_mesh(lm);
    std::size_t count = 0;
    const std::vector<std::size_t> labels = segment_k(m, 4, &count);
    expect_valid_segmentation(m, labels, count, 4, true);
    // Exactly the boxes, and the largest box (the last one) is segment 0.
    EXPECT_EQ(SAS::rand_index(labels, lm.labels), 1.0);
    for(std::size_t f = 0; f < labels.size(); ++f)
      ASSERT_EQ(labels[f], 3 - lm.labels[f]);

    // With fewer segments than boxes, no box is split.
    const std::vector<std::size_t> two = segment_k(m, 2, &count);
    EXPECT_EQ(count, 2u);
    std::vector<std::set<std::size_t>> segments_of_box(4);
    for(std::size_t f = 0; f < two.size(); ++f)
      segments_of_box[lm.labels[f]].insert(two[f]);
    for(std::size_t b = 0; b < 4; ++b)
      EXPECT_EQ(segments_of_box[b].size(), 1u) << "box " << b;
  }
}

// Tens of components: 36 icosahedra ("pebbles") of different sizes in a 6 x 6 grid, neighbours
// close to each other (proximity links), the last row far away (spanning links). With one
// segment per pebble, every pebble must be exactly one segment; with fewer, none may be split.
TEST(SeparatePieces, TensOfComponents)
{
  Mesh m;
  std::vector<std::size_t> pebble_of_face;
  const std::size_t rows = 6, columns = 6;
  for(std::size_t r = 0; r < rows; ++r)
    for(std::size_t c = 0; c < columns; ++c) {
      const std::size_t id = r * columns + c;
      const double radius = 0.6 + 0.02 * double(id);
      const double y = r + 1 < rows ? 3.0 * double(r) : 40.0; // the last row is far away
      const Point center(3.0 * double(c), y, 0.1 * double(id % 4));
      CGAL::make_icosahedron<Mesh, Point>(m, center, radius);
      pebble_of_face.resize(num_faces(m), id);
    }
  ASSERT_EQ(num_faces(m), rows * columns * 20);

  std::size_t count = 0;
  const std::vector<std::size_t> labels = segment_k(m, rows * columns, &count);
  ASSERT_EQ(count, rows * columns);
  EXPECT_EQ(SAS::rand_index(labels, pebble_of_face), 1.0);

  for(std::size_t k : {5u, 12u}) {
    const std::vector<std::size_t> fewer = segment_k(m, k, &count);
    ASSERT_EQ(count, k);
    std::vector<std::set<std::size_t>> segments_of_pebble(rows * columns);
    for(std::size_t f = 0; f < fewer.size(); ++f)
      segments_of_pebble[pebble_of_face[f]].insert(fewer[f]);
    for(std::size_t p = 0; p < rows * columns; ++p)
      EXPECT_EQ(segments_of_pebble[p].size(), 1u) << "pebble " << p << " split with k = " << k;
  }
}

// ---------------------------------------------------------------------------------------------
// CGAL's demo meshes

TEST(RealMeshes, ElephantAndCamel)
{
  for(const auto& job : std::vector<std::pair<std::string, std::size_t>>{
        {"elephant.off", 6}, {"elephant.off", 12}, {"camel.off", 8}, {"hand.off", 6}}) {
    SCOPED_TRACE(job.first + " K=" + std::to_string(job.second));
    const Mesh m = read_mesh(job.first);
    ASSERT_GT(num_faces(m), 1000u);
    std::size_t count = 0;
    const std::vector<std::size_t> labels = segment_k(m, job.second, &count);
    expect_valid_segmentation(m, labels, count, job.second, true);
  }
}

// A Surface_mesh with removed but uncollected faces (its face indices have gaps) is segmented
// exactly like the same mesh after collect_garbage().
TEST(RealMeshes, RemovedFacesAreIgnored)
{
  Mesh m = read_mesh("elephant.off");
  std::vector<face_descriptor> doomed;
  for(face_descriptor f : faces(m))
    if(doomed.size() < 200 && (std::size_t(f) % 7 == 3))
      doomed.push_back(f);
  for(face_descriptor f : doomed)
    CGAL::Euler::remove_face(halfedge(f, m), m);
  ASSERT_TRUE(m.has_garbage());
  // Remember each face across the compaction (collect_garbage() may reorder faces).
  auto original = m.add_property_map<face_descriptor, std::size_t>("f:original", 0).first;
  for(face_descriptor f : faces(m))
    original[f] = std::size_t(f);
  auto seg = m.add_property_map<face_descriptor, std::size_t>("f:segment", unset).first;
  ASSERT_EQ(CS::hierarchical_segmentation(m, seg, CS::parameters::number_of_segments(6)), 6u);
  std::map<std::size_t, std::size_t> with_garbage;
  for(face_descriptor f : faces(m))
    with_garbage[original[f]] = seg[f];
  ASSERT_EQ(with_garbage.size(), m.number_of_faces());
  // Removed faces do not count as faces.
  EXPECT_THROW(CS::hierarchical_segmentation(
                 m, seg, CS::parameters::number_of_segments(m.number_of_faces() + 1)),
               CS::Bad_input);

  m.collect_garbage();
  ASSERT_FALSE(m.has_garbage());
  ASSERT_EQ(CS::hierarchical_segmentation(m, seg, CS::parameters::number_of_segments(6)), 6u);
  std::vector<std::size_t> before, after;
  for(face_descriptor f : faces(m)) {
    before.push_back(with_garbage.at(original[f]));
    after.push_back(seg[f]);
  }
  EXPECT_EQ(SAS::rand_index(before, after), 1.0);
}

TEST(RealMeshes, ElephantWithHolesHasBoundaries)
{
  const Mesh m = read_mesh("elephant-with-holes.off");
  ASSERT_GT(num_faces(m), 1000u);
  std::size_t border_edges = 0;
  for(auto e : edges(m))
    border_edges += is_border(e, m) ? 1 : 0;
  ASSERT_GT(border_edges, 0u);
  std::size_t count = 0;
  const std::vector<std::size_t> labels = segment_k(m, 6, &count);
  SAS::Labelled_triangle_mesh soup = to_soup(m);
  const bool connected = SAS::number_of_components(soup) == 1;
  expect_valid_segmentation(m, labels, count, 6, connected);
}

TEST(RealMeshes, BlobbyWithThreeComponents)
{
  const Mesh m = read_mesh("blobby_3cc.off");
  SAS::Labelled_triangle_mesh soup = to_soup(m);
  std::vector<std::size_t> component;
  ASSERT_EQ(SAS::number_of_components(soup, &component), 3u);
  std::size_t count = 0;
  const std::vector<std::size_t> three = segment_k(m, 3, &count);
  expect_valid_segmentation(m, three, count, 3, true);
  EXPECT_EQ(SAS::rand_index(three, component), 1.0) << "each component is one segment";
  const std::vector<std::size_t> seven = segment_k(m, 7, &count);
  expect_valid_segmentation(m, seven, count, 7, false);
  // No segment spans two components (they are far apart compared with the parts).
  std::vector<std::set<std::size_t>> components_of(7);
  for(std::size_t f = 0; f < seven.size(); ++f)
    components_of[seven[f]].insert(component[f]);
  for(std::size_t l = 0; l < 7; ++l)
    EXPECT_EQ(components_of[l].size(), 1u) << "segment " << l;
}

// ---------------------------------------------------------------------------------------------
// Invariances

TEST(Invariance, RigidTransform)
{
  const auto transform = SAS::Rigid_transform::from_axis_angle(Vector_3d(0.3, -1, 0.6), 2.1,
                                                               Vector_3d(10, -3, 7));
  { // procedural: known parts
    const SAS::Labelled_triangle_mesh lm = SAS::mesh_procedural_shape(SAS::body_with_limbs(), 0.14);
    SAS::Labelled_triangle_mesh moved = lm;
    SAS::transform_points(moved, transform);
    const std::vector<std::size_t> a = segment_k(to_surface_mesh(lm), 5);
    const std::vector<std::size_t> b = segment_k(to_surface_mesh(moved), 5);
    EXPECT_GE(SAS::rand_index(a, b), 0.995);
  }
  { // elephant
    const Mesh m = read_mesh("elephant.off");
    Mesh moved = m;
    for(auto v : vertices(moved)) {
      const Point& p = moved.point(v);
      const Vector_3d q = transform(Vector_3d(p.x(), p.y(), p.z()));
      moved.point(v) = Point(q.x, q.y, q.z);
    }
    const std::vector<std::size_t> a = segment_k(m, 6);
    const std::vector<std::size_t> b = segment_k(moved, 6);
    EXPECT_GE(SAS::rand_index(a, b), 0.995);
    // A uniform scale does not matter either.
    Mesh scaled = m;
    for(auto v : vertices(scaled))
      scaled.point(v) = Point(37 * m.point(v).x(), 37 * m.point(v).y(), 37 * m.point(v).z());
    EXPECT_GE(SAS::rand_index(a, segment_k(scaled, 6)), 0.995);
  }
}

// Faces pointing inwards (every face reversed, or one component reversed) give the same
// segmentation: each component is treated as oriented outwards.
TEST(Invariance, Orientation)
{
  for(const std::string name : {"elephant.off", "camel.off", "elephant-with-holes.off"}) {
    SCOPED_TRACE(name);
    const Mesh m = read_mesh(name);
    Mesh reversed = m;
    PMP::reverse_face_orientations(reversed);
    for(std::size_t k : {4u, 8u})
      EXPECT_EQ(SAS::rand_index(segment_k(m, k), segment_k(reversed, k)), 1.0) << "k = " << k;
  }
  // blobby_3cc: reverse one of its three components only.
  const Mesh m = read_mesh("blobby_3cc.off");
  Mesh partly = m;
  auto component = partly.add_property_map<face_descriptor, std::size_t>("f:cc", 0).first;
  PMP::connected_components(partly, component);
  std::vector<face_descriptor> first;
  for(face_descriptor f : faces(partly))
    if(component[f] == 0)
      first.push_back(f);
  PMP::reverse_face_orientations(first, partly);
  EXPECT_EQ(SAS::rand_index(segment_k(m, 4), segment_k(partly, 4)), 1.0);
}

// A vertex that no face uses, however far, changes nothing.
TEST(Invariance, UnusedVertex)
{
  const Mesh m = read_mesh("blobby_3cc.off");
  Mesh with_extra = m;
  with_extra.add_vertex(Point(1000, 1000, 1000));
  for(std::size_t k : {2u, 4u})
    EXPECT_EQ(SAS::rand_index(segment_k(m, k), segment_k(with_extra, k)), 1.0) << "k = " << k;
}

TEST(Invariance, FaceOrder)
{
  auto check = [](const SAS::Labelled_triangle_mesh& lm, std::size_t k, const char* what) {
    SCOPED_TRACE(what);
    const std::vector<std::size_t> a = segment_k(to_surface_mesh(lm), k);
    for(std::uint64_t seed : {1u, 2u}) {
      SAS::Labelled_triangle_mesh shuffled = lm;
      const std::vector<std::size_t> order = SAS::shuffle_faces(shuffled, seed, seed == 2);
      const std::vector<std::size_t> b = segment_k(to_surface_mesh(shuffled), k);
      std::vector<std::size_t> back(b.size());
      for(std::size_t i = 0; i < b.size(); ++i)
        back[order[i]] = b[i];
      EXPECT_GE(SAS::rand_index(a, back), 0.995) << "seed " << seed;
    }
  };
  check(SAS::mesh_procedural_shape(SAS::star(6), 0.16), 7, "star");
  check(to_soup(read_mesh("elephant.off")), 6, "elephant");
}

TEST(Invariance, VertexPointMapAndFaceIndexMap)
{
  const Mesh m = read_mesh("elephant.off");
  const auto transform = SAS::Rigid_transform::from_axis_angle(Vector_3d(1, 1, 0), 0.9, Vector_3d(0, 2, 0));
  // Segmenting through a vertex point map of moved points is segmenting the moved mesh.
  Mesh with_map = m;
  auto moved_points = with_map.add_property_map<vertex_descriptor, Point>("v:moved").first;
  Mesh moved = m;
  for(auto v : vertices(with_map)) {
    const Point& p = m.point(v);
    const Vector_3d q = transform(Vector_3d(p.x(), p.y(), p.z()));
    moved_points[v] = Point(q.x, q.y, q.z);
    moved.point(v) = moved_points[v];
  }
  const std::vector<std::size_t> through_map =
    segment(with_map, CS::parameters::number_of_segments(6).vertex_point_map(moved_points));
  EXPECT_EQ(through_map, segment_k(moved, 6));

  // A face index map in reverse order gives the same partition.
  Mesh reversed = m;
  auto index = reversed.add_property_map<face_descriptor, std::size_t>("f:reversed_index").first;
  const std::size_t n = num_faces(reversed);
  for(auto f : faces(reversed))
    index[f] = n - 1 - std::size_t(f);
  const std::vector<std::size_t> a = segment_k(m, 6);
  const std::vector<std::size_t> b =
    segment(reversed, CS::parameters::face_index_map(index).number_of_segments(6));
  EXPECT_GE(SAS::rand_index(a, b), 0.995);
}

// ---------------------------------------------------------------------------------------------
// Parameters

TEST(Parameters, PriorSegmentationIsFollowed)
{
  // A capsule has no crease: left alone, the 2-segmentation cuts it near the middle. A prior
  // boundary at x = 0.6 is followed instead.
  SAS::Procedural_shape capsule;
  capsule.add(SAS::Shape_primitive::capsule(Vector_3d(-1.5, 0, 0), Vector_3d(1.5, 0, 0), 0.5, 0));
  const SAS::Labelled_triangle_mesh lm = SAS::mesh_procedural_shape(capsule, 0.14);
  Mesh m = to_surface_mesh(lm);
  auto prior = m.add_property_map<face_descriptor, int>("f:prior", 0).first;
  std::vector<std::size_t> prior_labels;
  for(auto f : faces(m)) {
    const bool right = lm.centroid(std::size_t(f)).x > 0.6;
    prior[f] = right ? 7 : -2; // arbitrary values
    prior_labels.push_back(right ? 1 : 0);
  }
  const std::vector<double> areas = lm.areas();
  const std::vector<std::size_t> without = segment_k(m, 2);
  const std::vector<std::size_t> with =
    segment(m, CS::parameters::number_of_segments(2).prior_segment_map(prior));
  const Agreement x_with = agreement(with, prior_labels, areas);
  const Agreement x_without = agreement(without, prior_labels, areas);
  EXPECT_GE(x_with.rand_index, 0.98);
  EXPECT_GE(x_with.overlap, 0.98);
  EXPECT_LT(x_without.overlap, 0.9) << "without the prior the cut is elsewhere";
  // The larger side of the prior (x < 0.6) is segment 0.
  std::size_t left_zero = 0, left = 0;
  for(std::size_t f = 0; f < with.size(); ++f)
    if(prior_labels[f] == 0) {
      ++left;
      left_zero += with[f] == 0 ? 1 : 0;
    }
  EXPECT_GT(double(left_zero), 0.98 * double(left));
  // A factor of 1 makes the prior irrelevant.
  EXPECT_EQ(segment(m, CS::parameters::number_of_segments(2).prior_segment_map(prior).prior_boundary_factor(1.0)),
            without);
}

TEST(Parameters, ProgressRefinementDeterminismAndExtremeCounts)
{
  const Mesh m = to_surface_mesh(SAS::mesh_procedural_shape(SAS::three_sphere_chain(), 0.2));
  // Progress: fractions in [0, 1], non-decreasing, ending at 1.
  std::vector<double> progress;
  std::size_t count = 0;
  const std::vector<std::size_t> a = segment(
    m, CS::parameters::number_of_segments(3).progress_callback([&](double x) { progress.push_back(x); }),
    &count);
  ASSERT_GE(progress.size(), 2u);
  for(std::size_t i = 0; i < progress.size(); ++i) {
    EXPECT_GE(progress[i], 0.0);
    EXPECT_LE(progress[i], 1.0);
    if(i > 0) {
      EXPECT_GE(progress[i], progress[i - 1]);
    }
  }
  EXPECT_EQ(progress.back(), 1.0);
  // Deterministic.
  EXPECT_EQ(segment_k(m, 3), a);
  // Without boundary refinement the parts are still found.
  const SAS::Labelled_triangle_mesh lm = SAS::mesh_procedural_shape(SAS::three_sphere_chain(), 0.2);
  const std::vector<std::size_t> raw =
    segment(m, CS::parameters::number_of_segments(3).boundary_refinement(false), &count);
  expect_valid_segmentation(m, raw, count, 3, true);
  EXPECT_TRUE(recovers(agreement(raw, lm.labels, lm.areas())));
  // K = 1: one segment.
  EXPECT_EQ(segment_k(m, 1, &count), std::vector<std::size_t>(num_faces(m), 0));
  EXPECT_EQ(count, 1u);
  // K = number of faces on a tetrahedron with four different face areas (1, 3, 1.5, 3.5):
  // one face per segment, numbered by decreasing area.
  Mesh tetra;
  const vertex_descriptor v0 = tetra.add_vertex(Point(0, 0, 0)), v1 = tetra.add_vertex(Point(2, 0, 0)),
                          v2 = tetra.add_vertex(Point(0, 1, 0)), v3 = tetra.add_vertex(Point(0, 0, 3));
  tetra.add_face(v0, v2, v1); // area 1
  tetra.add_face(v0, v1, v3); // area 3
  tetra.add_face(v0, v3, v2); // area 1.5
  tetra.add_face(v1, v2, v3); // area 3.5
  ASSERT_TRUE(CGAL::is_closed(tetra));
  EXPECT_EQ(segment_k(tetra, 4, &count), (std::vector<std::size_t>{3, 1, 2, 0}));
  EXPECT_EQ(count, 4u);
  // A larger concavity exponent still finds the parts; the CGAL parameter random_seed is accepted
  // (and ignored) in the same chain.
  const std::vector<std::size_t> sharp = segment(
    m, CS::parameters::number_of_segments(3).concavity_exponent(20.0).random_seed(3));
  EXPECT_TRUE(recovers(agreement(sharp, lm.labels, lm.areas())));
}

TEST(Parameters, WorksWithPolyhedron)
{
  const SAS::Labelled_triangle_mesh lm = SAS::mesh_procedural_shape(SAS::three_sphere_chain(), 0.2);
  Polyhedron poly;
  const auto poly_faces = SAS::fill_polygon_mesh(lm, poly);
  ASSERT_EQ(poly_faces.size(), lm.number_of_faces());
  auto seg = get(CGAL::dynamic_face_property_t<std::size_t>(), poly);
  for(auto f : faces(poly))
    put(seg, f, unset);
  const std::size_t count = CS::hierarchical_segmentation(poly, seg, CS::parameters::number_of_segments(3));
  EXPECT_EQ(count, 3u);
  std::vector<std::size_t> labels;
  for(auto f : poly_faces)
    labels.push_back(get(seg, f));
  for(std::size_t l : labels)
    ASSERT_LT(l, 3u);
  EXPECT_TRUE(recovers(agreement(labels, lm.labels, lm.areas())));
  // Same partition as with Surface_mesh.
  EXPECT_GE(SAS::rand_index(labels, segment_k(to_surface_mesh(lm), 3)), 0.995);
}

// ---------------------------------------------------------------------------------------------
// Bad input

// Expects Bad_input whose message contains `needle`, and the output map untouched.
template <typename NP>
void expect_bad_input(const Mesh& m, const NP& np, const std::string& needle)
{
  Mesh copy = m;
  auto seg = copy.add_property_map<face_descriptor, std::size_t>("f:test_segment", 12345).first;
  try {
    CS::hierarchical_segmentation(copy, seg, np);
    ADD_FAILURE() << "no exception, expected one about '" << needle << "'";
  } catch(const CS::Bad_input& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("hierarchical_segmentation"), std::string::npos) << what;
    EXPECT_NE(what.find(needle), std::string::npos) << what;
  } catch(const std::exception& e) {
    ADD_FAILURE() << "wrong exception type: " << e.what();
  }
  for(auto f : faces(copy))
    ASSERT_EQ(seg[f], 12345u) << "the output map was written";
}

TEST(BadInput, MeshesThatCannotBeSegmented)
{
  const auto k2 = CS::parameters::number_of_segments(2);
  expect_bad_input(Mesh(), k2, "no faces");
  // A mesh with vertices but no face.
  Mesh points_only;
  points_only.add_vertex(Point(0, 0, 0));
  expect_bad_input(points_only, k2, "no faces");

  const Mesh cube_quad = read_mesh("cube_quad.off");
  ASSERT_EQ(num_faces(cube_quad), 6u);
  expect_bad_input(cube_quad, k2, "not a triangle");
  // One quad among triangles.
  Mesh mixed;
  const vertex_descriptor a = mixed.add_vertex(Point(0, 0, 0)), b = mixed.add_vertex(Point(1, 0, 0)),
                          c = mixed.add_vertex(Point(1, 1, 0)), d = mixed.add_vertex(Point(0, 1, 0)),
                          e = mixed.add_vertex(Point(2, 0, 0));
  mixed.add_face(a, b, c, d);
  mixed.add_face(b, e, c);
  expect_bad_input(mixed, k2, "not a triangle");

  Mesh nan = to_surface_mesh(SAS::mesh_procedural_shape(SAS::three_sphere_chain(), 0.3));
  nan.point(*std::next(vertices(nan).begin(), 10)) = Point(0, std::numeric_limits<double>::quiet_NaN(), 0);
  expect_bad_input(nan, k2, "finite");
  Mesh inf = to_surface_mesh(SAS::mesh_procedural_shape(SAS::three_sphere_chain(), 0.3));
  inf.point(*vertices(inf).begin()) = Point(std::numeric_limits<double>::infinity(), 0, 0);
  expect_bad_input(inf, k2, "finite");
}

TEST(BadInput, ParametersOutOfRange)
{
  const Mesh m = to_surface_mesh(SAS::mesh_procedural_shape(SAS::three_sphere_chain(), 0.3));
  const std::size_t n = num_faces(m);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  namespace P = CS::parameters;
  expect_bad_input(m, P::number_of_segments(n + 1), "number_of_segments");
  expect_bad_input(m, P::number_of_segments(-1), "number_of_segments"); // converts to a huge count
  expect_bad_input(m, P::number_of_segments(2).concavity_exponent(-1.0), "concavity_exponent");
  expect_bad_input(m, P::number_of_segments(2).concavity_exponent(nan), "concavity_exponent");
  expect_bad_input(m, P::number_of_segments(2).prior_boundary_factor(0.5), "prior_boundary_factor");
  expect_bad_input(m, P::number_of_segments(2).prior_boundary_factor(nan), "prior_boundary_factor");
  expect_bad_input(m, P::number_of_segments(2).component_link_distance(-0.1), "component_link_distance");
  expect_bad_input(m, P::number_of_segments(2).component_link_factor(0.0), "component_link_factor");
  expect_bad_input(m, P::number_of_segments(2).component_link_factor(std::numeric_limits<double>::infinity()),
                   "component_link_factor");
  // In range at the limits: K = number of faces works.
  std::size_t count = 0;
  const std::vector<std::size_t> all = segment_k(m, n, &count);
  EXPECT_EQ(count, n);
  EXPECT_EQ(std::set<std::size_t>(all.begin(), all.end()).size(), n);
}

} // namespace
