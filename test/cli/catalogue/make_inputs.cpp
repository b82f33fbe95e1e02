// Copyright (c) 2026 CGAL Global Shape Analysis contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later

// The inputs of the bad-input catalogue (cases.txt): a few good files (a small mesh, a symmetric
// mesh, a flat square, a street scene with a post and a box) and, for every reader, files that
// are empty, truncated, lying in their headers, of the wrong type, or hold NaN, infinities,
// 1e300 or 1e-300. Written into the folder given as the only argument; deterministic.
//
//   catalogue_inputs DIR

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

namespace {

namespace fs = std::filesystem;
fs::path dir;

void text(const std::string& name, const std::string& content)
{
  std::ofstream(dir / name, std::ios::binary) << content;
}

struct Bytes
{
  std::string s;
  template <typename T> Bytes& put(T v)
  {
    s.append(reinterpret_cast<const char*>(&v), sizeof(T)); // little-endian hosts
    return *this;
  }
  Bytes& raw(const std::string& r)
  {
    s += r;
    return *this;
  }
  Bytes& zeros(std::size_t n)
  {
    s.append(n, '\0');
    return *this;
  }
};

void binary(const std::string& name, const Bytes& b) { text(name, b.s); }

struct Mesh
{
  std::vector<std::array<double, 3>> v;
  std::vector<std::array<int, 3>> f;
};

// An ellipsoid (a subdivided octahedron, `levels` times), symmetric about x = 0, y = 0, z = 0.
Mesh ellipsoid(int levels, double a, double b, double c)
{
  Mesh m;
  m.v = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
  m.f = {{0, 2, 4}, {2, 1, 4}, {1, 3, 4}, {3, 0, 4}, {2, 0, 5}, {1, 2, 5}, {3, 1, 5}, {0, 3, 5}};
  for(int l = 0; l < levels; ++l) {
    std::vector<std::array<int, 3>> next;
    std::vector<std::pair<std::pair<int, int>, int>> mids;
    auto mid = [&](int i, int j) {
      const auto key = std::make_pair(std::min(i, j), std::max(i, j));
      for(const auto& k : mids)
        if(k.first == key)
          return k.second;
      std::array<double, 3> p;
      for(int d = 0; d < 3; ++d)
        p[d] = (m.v[i][d] + m.v[j][d]) / 2;
      const double n = std::sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]);
      for(double& x : p)
        x /= n;
      m.v.push_back(p);
      mids.push_back({key, int(m.v.size()) - 1});
      return int(m.v.size()) - 1;
    };
    for(const auto& t : m.f) {
      const int a0 = mid(t[0], t[1]), b0 = mid(t[1], t[2]), c0 = mid(t[2], t[0]);
      next.push_back({t[0], a0, c0});
      next.push_back({a0, t[1], b0});
      next.push_back({c0, b0, t[2]});
      next.push_back({a0, b0, c0});
    }
    m.f = next;
  }
  for(auto& p : m.v)
    p = {p[0] * a, p[1] * b, p[2] * c};
  return m;
}

std::string off(const Mesh& m)
{
  std::ostringstream o;
  o.precision(17);
  o << "OFF\n" << m.v.size() << " " << m.f.size() << " 0\n";
  for(const auto& p : m.v)
    o << p[0] << " " << p[1] << " " << p[2] << "\n";
  for(const auto& t : m.f)
    o << "3 " << t[0] << " " << t[1] << " " << t[2] << "\n";
  return o.str();
}

// A binary little-endian PLY cloud of double x, y, z.
Bytes ply_cloud(const std::vector<std::array<double, 3>>& p, std::size_t declared)
{
  Bytes b;
  b.raw("ply\nformat binary_little_endian 1.0\nelement vertex " + std::to_string(declared) +
        "\nproperty double x\nproperty double y\nproperty double z\nend_header\n");
  for(const auto& q : p)
    b.put(q[0]).put(q[1]).put(q[2]);
  return b;
}

// A street: flat ground 30 m x 30 m (0.2 m spacing), a post (2.5 m) at (3, 3), a box (a car,
// 4 x 1.8 x 1.5 m) at (-6, 2), a wall along y = 12.
std::vector<std::array<double, 3>> scene()
{
  std::vector<std::array<double, 3>> p;
  std::uint64_t state = 12345;
  auto jitter = [&]() {
    state = state * 6364136223846793005ull + 1442695040888963407ull;
    return (double((state >> 11) & 0xFFFFF) / double(0xFFFFF) - 0.5) * 0.01;
  };
  for(double x = -15; x <= 15; x += 0.2)
    for(double y = -15; y <= 15; y += 0.2)
      p.push_back({x + jitter(), y + jitter(), jitter()});
  for(double z = 0.05; z <= 2.5; z += 0.04)
    for(int k = 0; k < 16; ++k)
      p.push_back({3 + 0.08 * std::cos(k * 0.3927), 3 + 0.08 * std::sin(k * 0.3927), z + jitter()});
  for(double x = -8; x <= -4; x += 0.08)
    for(double z = 0.3; z <= 1.5; z += 0.08) {
      p.push_back({x, 2 - 0.9 + jitter(), z});
      p.push_back({x, 2 + 0.9 + jitter(), z});
    }
  for(double x = -8; x <= -4; x += 0.08)
    for(double y = 1.1; y <= 2.9; y += 0.08)
      p.push_back({x, y, 1.5 + jitter()});
  for(double x = -15; x <= 15; x += 0.1)
    for(double z = 0.1; z <= 8; z += 0.1)
      p.push_back({x, 12 + jitter(), z});
  return p;
}

void meshes()
{
  const Mesh tetra{{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}}, {{0, 2, 1}, {0, 1, 3}, {1, 2, 3}, {0, 3, 2}}};
  text("tetra.off", off(tetra));
  text("ellipsoid.off", off(ellipsoid(3, 2, 1, 0.6)));
  text("ellipsoid2.off", off(ellipsoid(2, 1.9, 1.1, 0.7)));
  {
    // The ellipsoid as PLY with vertex colours (red on the side x > 0), for `symmetry transfer`.
    const Mesh e = ellipsoid(3, 2, 1, 0.6);
    std::ostringstream o;
    o.precision(17);
    o << "ply\nformat ascii 1.0\nelement vertex " << e.v.size()
      << "\nproperty double x\nproperty double y\nproperty double z\nproperty uchar red\nproperty uchar green\n"
         "property uchar blue\nelement face "
      << e.f.size() << "\nproperty list uchar int vertex_indices\nend_header\n";
    for(const auto& p : e.v)
      o << p[0] << " " << p[1] << " " << p[2] << (p[0] > 0 ? " 255 0 0\n" : " 0 0 255\n");
    for(const auto& t : e.f)
      o << "3 " << t[0] << " " << t[1] << " " << t[2] << "\n";
    text("ellipsoid_colours.ply", o.str());
  }
  // A flat square, 8 x 8 cells (open, two triangles a cell).
  Mesh flat;
  for(int j = 0; j <= 8; ++j)
    for(int i = 0; i <= 8; ++i)
      flat.v.push_back({i / 8.0 - 0.5, j / 8.0 - 0.5, 0});
  for(int j = 0; j < 8; ++j)
    for(int i = 0; i < 8; ++i) {
      const int a = j * 9 + i;
      flat.f.push_back({a, a + 1, a + 10});
      flat.f.push_back({a, a + 10, a + 9});
    }
  text("flat.off", off(flat));
  text("one_face.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n");
  text("empty_file.off", "");
  text("header_only.off", "OFF\n");
  text("no_faces.off", "OFF\n3 0 0\n0 0 0\n1 0 0\n0 1 0\n");
  text("lying_count.off", "OFF\n100 4 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n3 1 2 3\n3 0 3 2\n");
  text("truncated.off", "OFF\n4 4 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1");
  text("huge_count.off", "OFF\n99999999999 99999999999 0\n0 0 0\n");
  text("negative_count.off", "OFF\n-4 -4 0\n");
  text("negative_index.off", "OFF\n4 4 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 -3\n3 1 2 3\n3 0 3 2\n");
  text("index_out.off", "OFF\n4 4 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 9\n3 1 2 3\n3 0 3 2\n");
  const std::string tail = "3 0 2 1\n3 0 1 3\n3 1 2 3\n3 0 3 2\n";
  text("nan.off", "OFF\n4 4 0\n0 0 0\n1 0 0\n0 1 0\nnan 0 1\n" + tail);
  text("inf.off", "OFF\n4 4 0\n0 0 0\n1 0 0\n0 1 0\ninf 0 1\n" + tail);
  text("huge.off", "OFF\n4 4 0\n0 0 0\n1e300 0 0\n0 1e300 0\n0 0 1e300\n" + tail);
  text("huge_offset.off", "OFF\n4 4 0\n1e300 0 0\n1e300 1 0\n1e300 0 1\n1e300 1 1\n" + tail);
  text("tiny.off", "OFF\n4 4 0\n0 0 0\n1e-300 0 0\n0 1e-300 0\n0 0 1e-300\n" + tail);
  text("flat_tetra.off", "OFF\n4 4 0\n0 0 0\n1 0 0\n0 1 0\n1 1 0\n" + tail);
  text("quad.off", "OFF\n8 6 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n0 0 1\n1 0 1\n1 1 1\n0 1 1\n4 0 3 2 1\n4 4 5 6 7\n"
                   "4 0 1 5 4\n4 1 2 6 5\n4 2 3 7 6\n4 3 0 4 7\n");
  text("degenerate.off", "OFF\n3 2 0\n0 0 0\n1 0 0\n0 1 0\n3 0 0 1\n3 1 2 2\n");
  text("words.off", "this is not a mesh\n");
  text("homogeneous.off", "4OFF\n4 1 0\n0 0 0 1\n1 0 0 1\n0 1 0 1\n0 0 1 1\n3 0 1 2\n");
  text("letters.off", "OFF\n4 4 0\n0 0 0\n1 x 0\n0 1 0\n0 0 1\n" + tail);
  Bytes noise;
  std::uint32_t s = 7;
  for(int i = 0; i < 4096; ++i) {
    s = s * 1664525u + 1013904223u;
    noise.put(std::uint8_t(s >> 24));
  }
  binary("noise.off", noise);
  binary("noise.ply", noise);
  binary("noise.obj", noise);
  binary("noise.stl", noise);
  // PLY meshes.
  const std::string ply_head = "ply\nformat ascii 1.0\nelement vertex 4\n";
  const std::string faces = "element face 4\nproperty list uchar int vertex_indices\nend_header\n";
  const std::string ply_tail = "3 0 2 1\n3 0 1 3\n3 1 2 3\n3 0 3 2\n";
  text("uvw_mesh.ply", ply_head + "property float u\nproperty float v\nproperty float w\n" + faces +
                           "0 0 0\n1 0 0\n0 1 0\n0 0 1\n" + ply_tail);
  text("no_end_header.ply", ply_head + "property float x\nproperty float y\nproperty float z\n");
  text("bad_format.ply", "ply\nformat cobol 1.0\nelement vertex 0\nend_header\n");
  text("not_ply.ply", "plx\nformat ascii 1.0\nend_header\n");
  text("lying_mesh.ply", ply_head + "property float x\nproperty float y\nproperty float z\n" + faces +
                             "0 0 0\n1 0 0\n");
  Bytes tb;
  tb.raw("ply\nformat binary_little_endian 1.0\nelement vertex 4\nproperty double x\nproperty double y\n"
         "property double z\nelement face 4\nproperty list uchar int vertex_indices\nend_header\n");
  tb.put(0.0).put(0.0).put(0.0).put(1.0);
  binary("truncated_mesh.ply", tb);
  Bytes nb;
  nb.raw("ply\nformat binary_little_endian 1.0\nelement vertex 4\nproperty double x\nproperty double y\n"
         "property double z\nelement face 4\nproperty list uchar int vertex_indices\nend_header\n");
  const double q = std::numeric_limits<double>::quiet_NaN();
  for(double v : {0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 1.0, 0.0, q, 0.0, 1.0})
    nb.put(v);
  for(const auto& t : tetra.f)
    nb.put(std::uint8_t(3)).put(std::int32_t(t[0])).put(std::int32_t(t[1])).put(std::int32_t(t[2]));
  binary("nan_mesh.ply", nb);
  // OBJ and STL.
  const std::string obj_v = "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\n";
  text("tetra.obj", obj_v + "f 1 3 2\nf 1 2 4\nf 2 3 4\nf 1 4 3\n");
  text("zero_index.obj", obj_v + "f 0 1 2\n");
  text("index_out.obj", obj_v + "f 1 2 9\n");
  text("empty.obj", "");
  text("no_faces.obj", obj_v);
  text("nan.obj", "v 0 0 0\nv nan 0 0\nv 0 1 0\nf 1 2 3\n");
  Bytes stl;
  stl.zeros(80).put(std::uint32_t(1000));
  binary("truncated.stl", stl);
  text("words.stl", "solid x\n facet normal 0 0 1\n  outer loop\n   vertex a b c\n");
  text("empty.stl", "");
}

void clouds()
{
  const std::vector<std::array<double, 3>> p = scene();
  binary("scene.ply", ply_cloud(p, p.size()));
  {
    std::ostringstream o;
    o.precision(9);
    for(const auto& x : p)
      o << x[0] << " " << x[1] << " " << x[2] << "\n";
    text("scene.xyz", o.str());
  }
  binary("one_point.ply", ply_cloud({{0, 0, 0}}, 1));
  binary("no_points.ply", ply_cloud({}, 0));
  binary("lying_cloud.ply", ply_cloud({{0, 0, 0}, {1, 1, 1}}, 1000));
  Bytes t = ply_cloud({{0, 0, 0}, {1, 1, 1}}, 2);
  t.s.resize(t.s.size() - 5);
  binary("truncated_cloud.ply", t);
  const double q = std::numeric_limits<double>::quiet_NaN(), inf = std::numeric_limits<double>::infinity();
  std::vector<std::array<double, 3>> bad = p;
  bad[100][2] = q;
  binary("nan_cloud.ply", ply_cloud(bad, bad.size()));
  bad[100][2] = inf;
  binary("inf_cloud.ply", ply_cloud(bad, bad.size()));
  bad[100][2] = 1e300;
  binary("huge_cloud.ply", ply_cloud(bad, bad.size()));
  std::vector<std::array<double, 3>> tiny = p;
  for(auto& x : tiny)
    for(double& c : x)
      c *= 1e-300;
  binary("tiny_cloud.ply", ply_cloud(tiny, tiny.size()));
  std::vector<std::array<double, 3>> far = p;
  for(auto& x : far)
    x[0] += 1e15;
  binary("far_cloud.ply", ply_cloud(far, far.size()));
  text("uvw_cloud.ply", "ply\nformat ascii 1.0\nelement vertex 3\nproperty float u\nproperty float v\n"
                        "property float w\nend_header\n1 2 3\n4 5 6\n7 8 9\n");
  text("nan_ascii.ply", "ply\nformat ascii 1.0\nelement vertex 2\nproperty float x\nproperty float y\n"
                        "property float z\nend_header\n1 2 3\nnan 5 6\n");
  text("empty.ply", "");
  text("words.xyz", "1 2 3\nthis is not a point\n");
  text("two_columns.xyz", "1 2\n3 4\n");
  text("nan.xyz", "1 2 3\nnan 2 3\n");
  text("empty.xyz", "");
  // LAS.
  Bytes las;
  las.raw("LASF").zeros(20).put(std::uint8_t(1)).put(std::uint8_t(2)).zeros(201);
  binary("truncated.las", las); // 227 bytes of a header of zeros but the version
  Bytes sig;
  sig.raw("LASX").zeros(400);
  binary("bad_signature.las", sig);
  Bytes ver;
  ver.raw("LASF").zeros(20).put(std::uint8_t(3)).put(std::uint8_t(9)).zeros(400);
  binary("bad_version.las", ver);
  text("short.las", "LAS");
  text("empty.las", "");
  text("compressed.laz", "LASF");
  // KITTI velodyne .bin: x, y, z, reflectance as float32.
  Bytes k;
  for(int i = 0; i < 1000; ++i)
    k.put(float(i % 40) * 0.5f).put(float(i / 40) * 0.5f).put(0.0f).put(0.5f);
  binary("scan.bin", k);
  Bytes k15 = k;
  k15.s.resize(15);
  binary("ragged.bin", k15);
  Bytes kn = k;
  const float fq = std::numeric_limits<float>::quiet_NaN();
  std::memcpy(&kn.s[16 * 10 + 8], &fq, 4);
  binary("nan.bin", kn);
  text("empty.bin", "");
}

void side_files()
{
  // Labels (.seg) for the tetrahedron (4 faces) and the ellipsoid (512 faces).
  text("tetra.seg", "0\n0\n1\n1\n");
  text("short.seg", "0\n1\n");
  text("long.seg", "0\n0\n1\n1\n1\n");
  text("fraction.seg", "0\n1.5\n1\n1\n");
  // deform's handles and fixed vertices (for the tetrahedron)
  text("handles.txt", "0 0 0 2\n");
  text("handles_three_numbers.txt", "0 0 2\n");
  text("handles_far_vertex.txt", "9 0 0 2\n");
  text("handles_nan.txt", "0 nan 0 2\n");
  text("handles_twice.txt", "0 0 0 2\n0 1 0 2\n");
  text("fixed_handle.txt", "0\n");
  text("values_one_edge.txt", "0 1 0.5\n");
  text("negative.seg", "0\n-2\n1\n1\n");
  text("huge_label.seg", "0\n99999999999999999999999\n1\n1\n");
  text("words.seg", "zero\none\ntwo\nthree\n");
  text("empty.seg", "");
  // Locations (.csv) in the scene.
  text("locations.csv", "x,y,z\n3,3,0\n-6,2,0\n");
  text("no_header.csv", "3,3,0\n");
  text("nan_location.csv", "x,y,z\nnan,3,0\n");
  text("inf_location.csv", "x,y,z\ninf,3,0\n");
  text("outside.csv", "x,y,z\n1000,1000,0\n");
  text("huge_location.csv", "x,y,z\n1e300,3,0\n");
  text("words_location.csv", "x,y,z\nthree,three,zero\n");
  text("two_columns.csv", "x,y\n3,3\n");
  text("header_only.csv", "x,y,z\n");
  text("empty.csv", "");
  // Truth and labels (JSON), models, street maps.
  text("truth.json", "[{\"id\": 1, \"class\": \"post\", \"class_id\": 10, \"location\": [3, 3, 0], \"height\": 2.5, "
                     "\"bbox\": [2.9, 2.9, 0, 3.1, 3.1, 2.5], \"scanned_points\": 900}]\n");
  text("malformed.json", "{\"objects\": [\n");
  text("wrong_types.json", "{\"objects\": 5}\n");
  text("array.json", "[]\n");
  text("empty.json", "");
  text("nan_truth.json", "{\"objects\": [{\"id\": 1, \"class\": \"post\", \"location\": [NaN, 3, 0]}]}\n");
  text("labels.csv", "x,y,label\n3,3,post\n-6,2,car\n");
  text("bad_labels.csv", "x,y,label\n3,three,post\n");
  text("model_wrong.json", "{\"format\": \"something else\", \"classes\": 3}\n");
  text("malformed.osm", "<?xml version=\"1.0\"?>\n<osm version=\"0.6\">\n<node id=\"1\" lat=\"x\"\n");
  text("empty.osm", "");
  // Vertex colours for `symmetry transfer`: three vertices only.
  text("few_colours.ply", "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
                          "property float z\nproperty uchar red\nproperty uchar green\nproperty uchar blue\n"
                          "end_header\n0 0 0 255 0 0\n1 0 0 0 255 0\n0 1 0 0 0 255\n");
  fs::create_directories(dir / "folder.off");
  fs::create_directories(dir / "folder.ply");
  fs::create_directories(dir / "folder.seg");
  fs::create_directories(dir / "folder.csv");
  fs::create_directories(dir / "folder.json");
}

} // namespace

int main(int argc, char** argv)
{
  if(argc != 2) {
    std::cerr << "usage: " << argv[0] << " DIR\n";
    return 2;
  }
  dir = argv[1];
  std::error_code ec;
  fs::remove_all(dir, ec);
  fs::create_directories(dir);
  meshes();
  clouds();
  side_files();
  return 0;
}
