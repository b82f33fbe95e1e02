// Tests of the point-cloud readers of CGAL::Point_set_object_recognition: LAS round trips
// (formats 1, 3, 6) with UTM coordinates that come back to the micrometre after adding the
// offset, with their attributes exact; the LAS 1.4 64-bit point count; a hand-made LAS file with
// a VLR, extra bytes per record and flag bits around the packed fields; KITTI round trip; XYZ
// and PLY with properties; the local-origin rule; bad files refused with Bad_input and clear
// words; CGAL's demo point files when the build extracted them.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Point_set_3.h>

#include <CGAL/Point_set_object_recognition/internal/Kitti_io.h>
#include <CGAL/Point_set_object_recognition/internal/Las_writer.h>
#include <CGAL/Point_set_object_recognition/write_point_set.h>
#include <CGAL/Point_set_object_recognition/read_point_set.h>
#include <CGAL/Point_set_object_recognition/Point_set_file_reader.h>
#include <CGAL/Point_set_3/IO/PLY.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <sstream>
#include <string>
#include <vector>

namespace {

typedef CGAL::Exact_predicates_inexact_constructions_kernel Kernel;
typedef Kernel::Point_3 Point;
typedef CGAL::Point_set_3<Point> Point_set;
namespace PR = CGAL::Point_set_object_recognition;
namespace PRI = CGAL::Point_set_object_recognition::internal;
using CGAL::Shape_analysis::Bad_input;
typedef std::vector<unsigned char> Bytes;

// A scratch directory of this test program, removed at the end.
class Io : public ::testing::Test
{
protected:
  void SetUp() override
  {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    dir = std::filesystem::temp_directory_path() /
          (std::string("psor_io_") + info->name() + "_" + std::to_string(std::hash<std::string>()(info->name()) % 100000));
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
  }
  void TearDown() override { std::filesystem::remove_all(dir); }
  std::string path(const std::string& name) const { return (dir / name).string(); }
  std::filesystem::path dir;
};

Bytes load(const std::string& file)
{
  std::ifstream in(file, std::ios::binary);
  return Bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

void save(const std::string& file, const Bytes& b)
{
  std::ofstream out(file, std::ios::binary);
  out.write(reinterpret_cast<const char*>(b.data()), static_cast<std::streamsize>(b.size()));
}

void save_text(const std::string& file, const std::string& text) { std::ofstream(file) << text; }

// Little-endian fields, written independently of the library's encoder.
void put(Bytes& b, std::uint64_t v, int n)
{
  for(int i = 0; i < n; ++i)
    b.push_back(static_cast<unsigned char>((v >> (8 * i)) & 0xff));
}
void put_f64(Bytes& b, double d)
{
  std::uint64_t u;
  std::memcpy(&u, &d, 8);
  put(b, u, 8);
}
std::uint64_t get(const Bytes& b, std::size_t at, int n)
{
  std::uint64_t v = 0;
  for(int i = n - 1; i >= 0; --i)
    v = (v << 8) | b.at(at + i);
  return v;
}
double get_f64(const Bytes& b, std::size_t at)
{
  const std::uint64_t u = get(b, at, 8);
  double d;
  std::memcpy(&d, &u, 8);
  return d;
}

// Throws Bad_input whose message holds `words`.
template <typename F>
void expect_bad_input(F f, const std::string& words)
{
  try {
    f();
    ADD_FAILURE() << "no exception; expected Bad_input with \"" << words << "\"";
  } catch(const Bad_input& e) {
    EXPECT_NE(std::string(e.what()).find(words), std::string::npos) << e.what();
    EXPECT_EQ(std::string(e.what()).find('\n'), std::string::npos) << e.what();
  }
}

// A street-sized UTM point cloud (x ~ 5.0e5, y ~ 4.2e6, z ~ 30-80 m), coordinates on a mm grid,
// with all the LAS attributes; `world` receives the exact coordinates.
Point_set utm_cloud(std::size_t n, bool extended, std::vector<std::array<double, 3>>& world)
{
  Point_set ps;
  auto intensity = ps.add_property_map<unsigned short>("intensity", 0).first;
  auto cls = ps.add_property_map<unsigned char>("classification", 0).first;
  auto rn = ps.add_property_map<unsigned char>("return_number", 0).first;
  auto nr = ps.add_property_map<unsigned char>("number_of_returns", 0).first;
  auto gps = ps.add_property_map<double>("gps_time", 0).first;
  auto red = ps.add_property_map<unsigned short>("red", 0).first;
  auto green = ps.add_property_map<unsigned short>("green", 0).first;
  auto blue = ps.add_property_map<unsigned short>("blue", 0).first;
  world.clear();
  for(std::size_t i = 0; i < n; ++i) {
    const std::array<double, 3> w{{(500123456.0 + 7919.0 * double(i % 97) + 13.0 * double(i)) / 1000,
                                   (4200654321.0 + 104729.0 * double(i % 31) - 17.0 * double(i)) / 1000,
                                   (31234.0 + 523.0 * double(i % 89)) / 1000}};
    world.push_back(w);
    const auto idx = *ps.insert(Point(w[0], w[1], w[2]));
    intensity[idx] = static_cast<unsigned short>((i * 4099) % 65536);
    cls[idx] = static_cast<unsigned char>(extended ? (i * 37) % 256 : i % 32);
    const unsigned max_returns = extended ? 15 : 7;
    nr[idx] = static_cast<unsigned char>(1 + i % max_returns);
    rn[idx] = static_cast<unsigned char>(1 + (i / 3) % nr[idx]);
    gps[idx] = 1.5e8 + 0.1 * double(i) + 1e-7 * double(i % 7);
    red[idx] = static_cast<unsigned short>((i * 997) % 65536);
    green[idx] = static_cast<unsigned short>(65535 - (i * 31) % 65536);
    blue[idx] = static_cast<unsigned short>((i * i) % 65536);
  }
  return ps;
}

bool has(const std::vector<std::string>& names, const std::string& n)
{
  return std::find(names.begin(), names.end(), n) != names.end();
}

template <typename T>
T value(const Point_set& ps, const std::string& name, Point_set::Index i)
{
  auto pm = ps.property_map<T>(name);
  EXPECT_TRUE(pm.second) << "no property " << name;
  return pm.second ? pm.first[i] : T();
}

// ---------------------------------------------------------------------------------------------
// LAS

void check_las_round_trip(const std::string& file, unsigned format)
{
  const bool extended = format >= 6;
  std::vector<std::array<double, 3>> world;
  const Point_set original = utm_cloud(1000, extended, world);
  PRI::write_las(file, original, {{0.001, 0.001, 0.001}}, {{500000, 4200000, 0}}, format);
  EXPECT_FALSE(std::filesystem::exists(file + ".tmp"));

  Point_set ps;
  const PR::Point_set_read_result r = PR::read_point_set(file, ps);
  ASSERT_EQ(r.number_of_points, 1000u);
  ASSERT_EQ(ps.size(), 1000u);
  EXPECT_EQ(r.format, "las");
  // Automatic origin: x and y above 1e5 are shifted to their minimum floored to 100 m, z not.
  double min_x = 1e300, min_y = 1e300;
  for(const auto& w : world) {
    min_x = std::min(min_x, w[0]);
    min_y = std::min(min_y, w[1]);
  }
  EXPECT_EQ(r.offset[0], std::floor(min_x / 100) * 100);
  EXPECT_EQ(r.offset[1], std::floor(min_y / 100) * 100);
  EXPECT_EQ(r.offset[2], 0.0);

  const bool gps = format != 0 && format != 2, rgb = format == 3 || format == 7;
  EXPECT_EQ(has(r.property_names, "gps_time"), gps);
  EXPECT_EQ(has(r.property_names, "red"), rgb);
  EXPECT_TRUE(has(r.property_names, "intensity") && has(r.property_names, "classification") &&
              has(r.property_names, "return_number") && has(r.property_names, "number_of_returns"));

  double max_error = 0, max_local = 0;
  std::size_t k = 0;
  auto io = original.begin();
  for(Point_set::Index i : ps) {
    const Point& p = ps.point(i);
    const double got[3] = {p.x() + r.offset[0], p.y() + r.offset[1], p.z() + r.offset[2]};
    for(int c = 0; c < 3; ++c)
      max_error = std::max(max_error, std::abs(got[c] - world[k][c]));
    max_local = std::max({max_local, std::abs(p.x()), std::abs(p.y())});
    const Point_set::Index j = *io++;
    EXPECT_EQ(value<unsigned short>(ps, "intensity", i), value<unsigned short>(original, "intensity", j));
    EXPECT_EQ(value<unsigned char>(ps, "classification", i), value<unsigned char>(original, "classification", j));
    EXPECT_EQ(value<unsigned char>(ps, "return_number", i), value<unsigned char>(original, "return_number", j));
    EXPECT_EQ(value<unsigned char>(ps, "number_of_returns", i),
              value<unsigned char>(original, "number_of_returns", j));
    if(gps) {
      EXPECT_EQ(value<double>(ps, "gps_time", i), value<double>(original, "gps_time", j));
    }
    if(rgb) {
      EXPECT_EQ(value<unsigned short>(ps, "red", i), value<unsigned short>(original, "red", j));
      EXPECT_EQ(value<unsigned short>(ps, "green", i), value<unsigned short>(original, "green", j));
      EXPECT_EQ(value<unsigned short>(ps, "blue", i), value<unsigned short>(original, "blue", j));
    }
    ++k;
  }
  EXPECT_LT(max_error, 1e-6) << "format " << format;
  EXPECT_LT(max_local, 5000.0);  // local coordinates are small
}

TEST_F(Io, LasRoundTripFormat1KeepsUtmCoordinatesAndAttributes) { check_las_round_trip(path("a.las"), 1); }
TEST_F(Io, LasRoundTripFormat3KeepsUtmCoordinatesAndAttributes) { check_las_round_trip(path("a.las"), 3); }
TEST_F(Io, LasRoundTripFormat6KeepsUtmCoordinatesAndAttributes) { check_las_round_trip(path("a.las"), 6); }
TEST_F(Io, LasRoundTripFormats0And7) { check_las_round_trip(path("a.las"), 0); check_las_round_trip(path("b.las"), 7); }

TEST_F(Io, LasWriterLayoutFollowsTheSpecification)
{
  std::vector<std::array<double, 3>> world;
  const Point_set ps = utm_cloud(5, false, world);
  // Format 3, LAS 1.2: header of 227 bytes, record of 34; GPS time at 20, RGB at 28.
  PRI::write_las(path("f3.las"), ps, {{0.001, 0.001, 0.001}}, {{500000, 4200000, 0}}, 3);
  Bytes b = load(path("f3.las"));
  ASSERT_EQ(b.size(), 227u + 5 * 34);
  EXPECT_EQ(std::string(b.begin(), b.begin() + 4), "LASF");
  EXPECT_EQ(b[24], 1);
  EXPECT_EQ(b[25], 2);
  EXPECT_EQ(get(b, 94, 2), 227u);
  EXPECT_EQ(get(b, 96, 4), 227u);
  EXPECT_EQ(b[104], 3);
  EXPECT_EQ(get(b, 105, 2), 34u);
  EXPECT_EQ(get(b, 107, 4), 5u);
  EXPECT_EQ(get_f64(b, 131), 0.001);
  EXPECT_EQ(get_f64(b, 163), 4200000.0);
  EXPECT_NEAR(get_f64(b, 187), world[0][0], 1e-6);  // min x (point 0 has the smallest x)
  const std::size_t p = 227 + 34;  // second point
  EXPECT_EQ(static_cast<std::int32_t>(get(b, p, 4)), std::int32_t(std::llround((world[1][0] - 500000) * 1000)));
  EXPECT_EQ(get(b, p + 12, 2), 4099u);
  EXPECT_EQ(b[p + 14] & 7, value<unsigned char>(ps, "return_number", *(ps.begin() + 1)));
  EXPECT_EQ((b[p + 14] >> 3) & 7, value<unsigned char>(ps, "number_of_returns", *(ps.begin() + 1)));
  EXPECT_EQ(get_f64(b, p + 20), value<double>(ps, "gps_time", *(ps.begin() + 1)));
  EXPECT_EQ(get(b, p + 28, 2), 997u);

  // Format 6, LAS 1.4: header of 375 bytes, legacy count 0, 64-bit count at 247, record of 30;
  // return bits 4+4 in byte 14, classification byte 16, GPS time at 22.
  const Point_set ps6 = utm_cloud(5, true, world);
  PRI::write_las(path("f6.las"), ps6, {{0.001, 0.001, 0.001}}, {{500000, 4200000, 0}}, 6);
  b = load(path("f6.las"));
  ASSERT_EQ(b.size(), 375u + 5 * 30);
  EXPECT_EQ(b[25], 4);
  EXPECT_EQ(get(b, 94, 2), 375u);
  EXPECT_EQ(b[104], 6);
  EXPECT_EQ(get(b, 105, 2), 30u);
  EXPECT_EQ(get(b, 107, 4), 0u);
  EXPECT_EQ(get(b, 247, 8), 5u);
  const std::size_t q = 375 + 2 * 30;  // third point
  const auto i2 = *(ps6.begin() + 2);
  EXPECT_EQ(b[q + 14] & 15, value<unsigned char>(ps6, "return_number", i2));
  EXPECT_EQ(b[q + 14] >> 4, value<unsigned char>(ps6, "number_of_returns", i2));
  EXPECT_EQ(b[q + 16], 74);  // classification 2 * 37
  EXPECT_EQ(get_f64(b, q + 22), value<double>(ps6, "gps_time", i2));
}

TEST_F(Io, Las14UsesThe64BitPointCount)
{
  std::vector<std::array<double, 3>> world;
  const Point_set ps = utm_cloud(300, true, world);
  PRI::write_las(path("a.las"), ps, {{0.001, 0.001, 0.001}}, {{500000, 4200000, 0}}, 6);
  Bytes b = load(path("a.las"));
  ASSERT_EQ(get(b, 107, 4), 0u);
  Point_set in;
  EXPECT_EQ(PR::read_point_set(path("a.las"), in).number_of_points, 300u);
  // A 64-bit count larger than the data is truncation, even with a plausible legacy count.
  for(int i = 0; i < 4; ++i)
    b[107 + i] = static_cast<unsigned char>((300 >> (8 * i)) & 0xff);
  b[247] = static_cast<unsigned char>(301 & 0xff);
  b[248] = static_cast<unsigned char>(301 >> 8);
  save(path("b.las"), b);
  expect_bad_input([&] { PR::read_point_set(path("b.las"), in); }, "truncated point data");
  EXPECT_TRUE(in.empty());
}

// A LAS 1.2 file of format 1 made byte by byte: one VLR of 20 bytes between header and points,
// records of 28 + 6 extra bytes, flag bits set around the packed return and class fields.
Bytes hand_made_las(std::uint32_t count_in_header, std::size_t points)
{
  const std::size_t vlr = 54 + 20, record = 34;
  Bytes b;
  b.insert(b.end(), {'L', 'A', 'S', 'F'});
  put(b, 7, 2);          // file source id
  put(b, 0, 2);          // global encoding
  b.insert(b.end(), 16, 0);
  b.push_back(1);
  b.push_back(2);
  b.insert(b.end(), 64, 'x');  // system identifier, generating software
  put(b, 100, 2);
  put(b, 2024, 2);
  put(b, 227, 2);            // header size
  put(b, 227 + vlr, 4);      // offset to point data
  put(b, 1, 4);              // one VLR
  b.push_back(1);            // format 1
  put(b, record, 2);         // record length with 6 extra bytes
  put(b, count_in_header, 4);
  for(int r = 0; r < 5; ++r)
    put(b, r == 0 ? count_in_header : 0, 4);
  for(double s : {0.01, 0.01, 0.001})
    put_f64(b, s);
  for(double o : {600000.0, 5000000.0, 100.0})
    put_f64(b, o);
  for(int c = 0; c < 6; ++c)
    put_f64(b, 0);
  EXPECT_EQ(b.size(), 227u);
  // VLR: reserved, user id, record id, length after header, description, payload.
  put(b, 0, 2);
  const std::string user = "LASF_Projection";
  b.insert(b.end(), user.begin(), user.end());
  b.insert(b.end(), 16 - user.size(), 0);
  put(b, 34735, 2);
  put(b, 20, 2);
  b.insert(b.end(), 32, 'd');
  b.insert(b.end(), 20, 0xAB);
  for(std::size_t i = 0; i < points; ++i) {
    put(b, static_cast<std::uint32_t>(std::int32_t(12345 + 100 * int(i))), 4);
    put(b, static_cast<std::uint32_t>(std::int32_t(-250 - int(i))), 4);
    put(b, static_cast<std::uint32_t>(std::int32_t(-5000)), 4);
    put(b, 1000 + i, 2);                                                  // intensity
    b.push_back(static_cast<unsigned char>(0xC0 | (3 << 3) | (1 + i % 3)));  // scan dir + edge bits
    b.push_back(static_cast<unsigned char>(0xE0 | (2 + i)));             // synthetic/key/withheld bits
    b.push_back(0xF0);                                                    // scan angle rank
    b.push_back(0x55);                                                    // user data
    put(b, 77, 2);                                                        // point source id
    put_f64(b, 12345.5 + double(i));                                      // GPS time
    b.insert(b.end(), 6, 0xEE);                                           // extra bytes
  }
  return b;
}

TEST_F(Io, LasWithVlrAndExtraBytesPerRecordIsReadField)
{
  save(path("hand.las"), hand_made_las(3, 3));
  Point_set ps;
  const auto r = PR::read_point_set(path("hand.las"), ps, PR::parameters::shift_to_local_origin(false));
  ASSERT_EQ(r.number_of_points, 3u);
  EXPECT_EQ(r.offset[0], 0.0);
  std::size_t k = 0;
  for(Point_set::Index i : ps) {
    const Point& p = ps.point(i);
    EXPECT_NEAR(p.x(), 600000 + 0.01 * (12345 + 100 * double(k)), 1e-9);
    EXPECT_NEAR(p.y(), 5000000 + 0.01 * (-250 - double(k)), 1e-9);
    EXPECT_NEAR(p.z(), 100 - 5.0, 1e-12);
    EXPECT_EQ(value<unsigned short>(ps, "intensity", i), 1000 + k);
    EXPECT_EQ(value<unsigned char>(ps, "return_number", i), 1 + k % 3);
    EXPECT_EQ(value<unsigned char>(ps, "number_of_returns", i), 3);
    EXPECT_EQ(value<unsigned char>(ps, "classification", i), 2 + k);
    EXPECT_EQ(value<double>(ps, "gps_time", i), 12345.5 + double(k));
    ++k;
  }
  // Automatic origin: (600100, 4999900, 0) floors of the minimum, z (95 m) not shifted.
  const auto a = PR::read_point_set(path("hand.las"), ps);
  EXPECT_EQ(a.offset[0], 600100.0);
  EXPECT_EQ(a.offset[1], 4999900.0);
  EXPECT_EQ(a.offset[2], 0.0);
  EXPECT_NEAR(ps.point(*ps.begin()).x(), 23.45, 1e-9);
}

// The scan's scale, offset and coordinate system records are read (VLRs and LAS 1.4 extended
// VLRs) and written again: the stored integers and the records come back unchanged.
TEST_F(Io, LasGeoreferenceIsKeptThroughReadAndWrite)
{
  save(path("hand.las"), hand_made_las(3, 3));
  Point_set ps;
  const auto r = PR::read_point_set(path("hand.las"), ps);
  ASSERT_TRUE(r.las_georeference.has_value());
  const PR::Las_georeference& g = *r.las_georeference;
  EXPECT_EQ(g.scale, (std::array<double, 3>{{0.01, 0.01, 0.001}}));
  EXPECT_EQ(g.offset, (std::array<double, 3>{{600000, 5000000, 100}}));
  ASSERT_EQ(g.crs_records.size(), 1u);
  EXPECT_EQ(g.crs_records[0].record_id, 34735);
  EXPECT_EQ(g.crs_records[0].description, std::string(32, 'd'));
  EXPECT_EQ(g.crs_records[0].data, Bytes(20, 0xAB));
  EXPECT_FALSE(g.wkt);
  EXPECT_TRUE(PR::Point_set_file_reader(path("hand.las")).las_georeference().has_value());

  PR::write_las_point_set(path("kept.las"), ps,
                          PR::parameters::local_origin(r.offset).las_georeference(r.las_georeference));
  const Bytes out = load(path("kept.las"));
  ASSERT_GT(out.size(), 375u);
  EXPECT_EQ(PRI::le_u16(out.data() + 6) & 0x10, 0); // GeoTIFF keys: not declared WKT
  for(int c = 0; c < 3; ++c) {
    EXPECT_EQ(PRI::le_f64(out.data() + 131 + 8 * c), g.scale[std::size_t(c)]);
    EXPECT_EQ(PRI::le_f64(out.data() + 155 + 8 * c), g.offset[std::size_t(c)]);
  }
  const std::uint32_t data = PRI::le_u32(out.data() + 96), record = PRI::le_u16(out.data() + 105);
  for(std::size_t i = 0; i < 3; ++i) { // the hand-made file's integers, exactly
    const unsigned char* p = out.data() + data + i * record;
    EXPECT_EQ(PRI::le_i32(p), std::int32_t(12345 + 100 * int(i)));
    EXPECT_EQ(PRI::le_i32(p + 4), std::int32_t(-250 - int(i)));
    EXPECT_EQ(PRI::le_i32(p + 8), -5000);
  }
  Point_set back;
  const auto rb = PR::read_point_set(path("kept.las"), back);
  ASSERT_TRUE(rb.las_georeference.has_value());
  ASSERT_EQ(rb.las_georeference->crs_records.size(), 1u);
  EXPECT_EQ(rb.las_georeference->crs_records[0].data, g.crs_records[0].data);
  EXPECT_EQ(rb.las_georeference->crs_records[0].record_id, 34735);
  // Written in pieces with the same georeference: the same file.
  const PR::Las_point_set_pieces<Point> pieces(
    ps, std::array<double, 3>{{0, 0, 0}}, PR::parameters::local_origin(r.offset).las_georeference(r.las_georeference));
  std::vector<unsigned char> records;
  const auto summary = pieces.records(ps, records);
  std::vector<unsigned char> whole = pieces.header(summary);
  whole.insert(whole.end(), records.begin(), records.end());
  EXPECT_TRUE(whole == out);
  // Without it: millimetres and no coordinate system record.
  PR::write_las_point_set(path("plain.las"), ps, PR::parameters::local_origin(r.offset));
  Point_set plain;
  const auto rp = PR::read_point_set(path("plain.las"), plain);
  EXPECT_TRUE(rp.las_georeference->crs_records.empty());
  EXPECT_EQ(rp.las_georeference->scale[0], 0.001);

  // A WKT record in an extended VLR of a LAS 1.4 file: read, then written as a VLR, WKT declared.
  Bytes wkt_file = out;
  const std::string wkt = "PROJCS[\"WGS 84 / UTM zone 32N\"]";
  const std::uint64_t start = wkt_file.size();
  put(wkt_file, 0, 2);
  const std::string user = "LASF_Projection";
  wkt_file.insert(wkt_file.end(), user.begin(), user.end());
  wkt_file.insert(wkt_file.end(), 16 - user.size(), 0);
  put(wkt_file, 2112, 2);
  put(wkt_file, wkt.size(), 8);
  wkt_file.insert(wkt_file.end(), 32, 0);
  wkt_file.insert(wkt_file.end(), wkt.begin(), wkt.end());
  Bytes field;
  put(field, start, 8);
  std::copy(field.begin(), field.end(), wkt_file.begin() + 235);
  field.clear();
  put(field, 1, 4);
  std::copy(field.begin(), field.end(), wkt_file.begin() + 243);
  wkt_file[6] = static_cast<unsigned char>(wkt_file[6] | 0x10);
  save(path("wkt.las"), wkt_file);
  Point_set w;
  const auto rw = PR::read_point_set(path("wkt.las"), w);
  ASSERT_EQ(rw.las_georeference->crs_records.size(), 2u);
  EXPECT_EQ(rw.las_georeference->crs_records[1].record_id, 2112);
  EXPECT_EQ(std::string(rw.las_georeference->crs_records[1].data.begin(), rw.las_georeference->crs_records[1].data.end()), wkt);
  EXPECT_TRUE(rw.las_georeference->wkt);
  PR::write_las_point_set(path("wkt_out.las"), w,
                          PR::parameters::local_origin(rw.offset).las_georeference(rw.las_georeference));
  const Bytes wo = load(path("wkt_out.las"));
  EXPECT_EQ(PRI::le_u16(wo.data() + 6) & 0x10, 0x10);
  EXPECT_EQ(PRI::le_u32(wo.data() + 100), PRI::le_u32(out.data() + 100) + 1); // one VLR more
  Point_set w2;
  const auto rw2 = PR::read_point_set(path("wkt_out.las"), w2);
  EXPECT_EQ(rw2.las_georeference->crs_records.size(), 2u);

  // Bad georeferences and records too large for a VLR are refused.
  PR::Las_georeference bad = g;
  bad.scale[1] = 0;
  expect_bad_input([&] { PR::write_las_point_set(path("bad.las"), ps, PR::parameters::las_georeference(bad)); },
                   "scale must be positive");
  EXPECT_FALSE(std::filesystem::exists(path("bad.las")));
  bad = g;
  bad.crs_records[0].data.assign(70000, 1);
  expect_bad_input([&] { PR::write_las_point_set(path("bad.las"), ps, PR::parameters::las_georeference(bad)); },
                   "65,535");
  // Points that do not fit 32-bit integers with the kept scale are refused, not wrapped.
  bad = g;
  bad.scale = {{1e-9, 1e-9, 1e-9}};
  expect_bad_input([&] {
    PR::write_las_point_set(path("bad.las"), ps, PR::parameters::local_origin(r.offset).las_georeference(bad));
  }, "32-bit");
}

TEST_F(Io, LasExtraBytesAndClassNamesRoundTrip)
{
  std::vector<std::array<double, 3>> world;
  Point_set ps = utm_cloud(50, true, world);
  auto object = ps.add_property_map<int>("object", -1).first;
  auto ground = ps.add_property_map<unsigned char>("ground", 0).first;
  auto score = ps.add_property_map<float>("score", 0.f).first;
  auto height = ps.add_property_map<double>("height_above_ground", 0.).first;
  auto delta = ps.add_property_map<short>("delta", 0).first;
  int k = 0;
  for(Point_set::Index i : ps) {
    object[i] = k % 5 == 0 ? -1 : 100000 + k;
    ground[i] = static_cast<unsigned char>(k % 2);
    score[i] = 0.25f * float(k);
    height[i] = 1.0 / (1 + k);
    delta[i] = static_cast<short>(-300 * k);
    ++k;
  }
  // As read with a local origin: the file has the coordinates plus that origin.
  const std::array<double, 3> origin{{500000, 4200000, 0}};
  for(Point_set::Index i : ps) {
    const Point& p = ps.point(i);
    ps.point(i) = Point(p.x() - origin[0], p.y() - origin[1], p.z());
  }
  PR::write_las_point_set(path("x.las"), ps,
                          PR::parameters::local_origin(origin).class_names(
                            std::vector<std::pair<unsigned, std::string>>{{64, "pole"}, {65, "a much too long class name"}}));
  const Bytes b = load(path("x.las"));
  // Format 7 (36 bytes) + int32, uint8, float, double, int16 = 55-byte records after two VLRs:
  // the Extra Bytes record (5 descriptors of 192 bytes), the Classification Lookup (256 x 16).
  const std::size_t vlrs = 54 + 5 * 192 + 54 + 4096;
  EXPECT_EQ(get(b, 96, 4), 375u + vlrs);
  EXPECT_EQ(get(b, 100, 4), 2u);
  EXPECT_EQ(get(b, 105, 2), 55u);
  ASSERT_EQ(b.size(), 375u + vlrs + 50 * 55);
  EXPECT_EQ(std::string(b.begin() + 375 + 2, b.begin() + 375 + 11), "LASF_Spec");
  EXPECT_EQ(get(b, 375 + 18, 2), 4u);
  EXPECT_EQ(b[375 + 54 + 2], 6) << "object: int32";
  EXPECT_EQ(std::string(b.begin() + 375 + 54 + 4, b.begin() + 375 + 54 + 10), "object");
  const std::size_t lookup = 375 + 54 + 5 * 192 + 54;
  EXPECT_EQ(get(b, lookup - 54 + 18, 2), 0u);
  EXPECT_EQ(b[lookup + 64 * 16], 64);
  EXPECT_EQ(std::string(b.begin() + lookup + 64 * 16 + 1, b.begin() + lookup + 64 * 16 + 5), "pole");
  EXPECT_EQ(std::string(b.begin() + lookup + 65 * 16 + 1, b.begin() + lookup + 66 * 16), "a much too long");

  Point_set back;
  const PR::Point_set_read_result r = PR::read_point_set(path("x.las"), back, PR::parameters::local_origin(origin));
  ASSERT_EQ(back.size(), 50u);
  EXPECT_TRUE(has(r.property_names, "object") && has(r.property_names, "ground") && has(r.property_names, "delta"));
  auto j = ps.begin();
  for(Point_set::Index i : back) {
    EXPECT_EQ(value<int>(back, "object", i), object[*j]);
    EXPECT_EQ(value<unsigned char>(back, "ground", i), ground[*j]);
    EXPECT_EQ(value<double>(back, "score", i), double(score[*j]));
    EXPECT_EQ(value<double>(back, "height_above_ground", i), height[*j]);
    EXPECT_EQ(value<int>(back, "delta", i), delta[*j]);
    EXPECT_EQ(value<unsigned char>(back, "classification", i), value<unsigned char>(ps, "classification", *j));
    EXPECT_NEAR(back.point(i).x(), ps.point(*j).x(), 0.0005) << "millimetres";
    EXPECT_NEAR(back.point(i).y(), ps.point(*j).y(), 0.0005);
    ++j;
  }
  // Bad input: nothing written.
  std::ostringstream os;
  EXPECT_THROW(PR::write_las_point_set(os, ps, PR::parameters::class_names(std::vector<std::pair<unsigned, std::string>>{
                                                 {300, "x"}})),
               CGAL::Shape_analysis::Bad_input);
  EXPECT_THROW(PR::write_las_point_set(os, ps, PR::parameters::local_origin(std::array<double, 3>{{0, NAN, 0}})),
               CGAL::Shape_analysis::Bad_input);
  ps.point(*ps.begin()) = Point(3e6, 0, 0); // 3,000 km from the others: beyond 32-bit millimetres
  EXPECT_THROW(PR::write_las_point_set(os, ps), CGAL::Shape_analysis::Bad_input);
  EXPECT_TRUE(os.str().empty());
  EXPECT_THROW(PR::write_las_point_set(path("y.las"), ps), CGAL::Shape_analysis::Bad_input);
  EXPECT_FALSE(std::filesystem::exists(path("y.las")) || std::filesystem::exists(path("y.las.tmp")));
}

TEST_F(Io, LasScaledAndUndescribedExtraBytesAreRead)
{
  // hand_made_las()'s 6 extra bytes (0xEE each) described as a scaled int16 then 4 bytes of type 0.
  Bytes b = hand_made_las(3, 3);
  b.erase(b.begin() + 227, b.begin() + 227 + 54 + 20);
  Bytes vlr;
  put(vlr, 0, 2);
  const std::string user = "LASF_Spec";
  vlr.insert(vlr.end(), user.begin(), user.end());
  vlr.insert(vlr.end(), 16 - user.size(), 0);
  put(vlr, 4, 2);
  put(vlr, 2 * 192, 2);
  vlr.insert(vlr.end(), 32, 0);
  Bytes d(2 * 192, 0);
  d[2] = 4, d[3] = 8 | 16; // int16 with a scale and an offset
  const std::string name = "half";
  std::copy(name.begin(), name.end(), d.begin() + 4);
  Bytes scale, offset;
  put_f64(scale, 0.5), put_f64(offset, 10.0);
  std::copy(scale.begin(), scale.end(), d.begin() + 112);
  std::copy(offset.begin(), offset.end(), d.begin() + 136);
  d[192 + 2] = 0, d[192 + 3] = 4; // 4 undescribed bytes
  vlr.insert(vlr.end(), d.begin(), d.end());
  b.insert(b.begin() + 227, vlr.begin(), vlr.end());
  const Bytes fixed = [&] {
    Bytes o;
    put(o, 227 + vlr.size(), 4);
    return o;
  }();
  std::copy(fixed.begin(), fixed.end(), b.begin() + 96);
  save(path("scaled.las"), b);
  Point_set ps;
  const auto r = PR::read_point_set(path("scaled.las"), ps);
  ASSERT_EQ(r.number_of_points, 3u);
  for(Point_set::Index i : ps)
    EXPECT_EQ(value<double>(ps, "half", i), double(std::int16_t(0xEEEE)) * 0.5 + 10.0);
  EXPECT_EQ(r.property_names.size(), ps.properties().size());
  // Descriptors beyond the record's extra bytes are refused.
  b[227 + 54 + 192 + 3] = 5;
  save(path("long.las"), b);
  EXPECT_THROW(PR::read_point_set(path("long.las"), ps), CGAL::Shape_analysis::Bad_input);
}

TEST_F(Io, ExplicitLocalOriginIsRespected)
{
  std::vector<std::array<double, 3>> world;
  const Point_set ps = utm_cloud(50, false, world);
  PRI::write_las(path("a.las"), ps, {{0.001, 0.001, 0.001}}, {{500000, 4200000, 0}}, 1);
  Point_set in;
  const std::array<double, 3> origin{{500000, 4200000, 10}};
  const auto r = PR::read_point_set(path("a.las"), in, PR::parameters::local_origin(origin));
  EXPECT_EQ(r.offset, origin);
  const Point& p = in.point(*in.begin());
  EXPECT_NEAR(p.x(), world[0][0] - 500000, 1e-9);
  EXPECT_NEAR(p.y(), world[0][1] - 4200000, 1e-9);
  EXPECT_NEAR(p.z(), world[0][2] - 10, 1e-9);
  // No shift at all: the file's coordinates, still to the micrometre.
  const auto n = PR::read_point_set(path("a.las"), in, PR::parameters::shift_to_local_origin(false));
  EXPECT_EQ(n.offset, (std::array<double, 3>{{0, 0, 0}}));
  EXPECT_NEAR(in.point(*in.begin()).x(), world[0][0], 1e-6);
  expect_bad_input([&] {
    PR::read_point_set(path("a.las"), in, PR::parameters::local_origin(origin).shift_to_local_origin(false));
  }, "shift_to_local_origin is false");
  expect_bad_input([&] {
    PR::read_point_set(path("a.las"), in, PR::parameters::local_origin(std::array<double, 3>{{std::nan(""), 0, 0}}));
  }, "local_origin must be finite");
}

TEST(LocalOrigin, RuleIsPerAxisAndFloorsTo100)
{
  using A = std::array<double, 3>;
  EXPECT_EQ(PRI::automatic_local_origin(A{{-99999, 5, 0}}, A{{99999, 7, 10}}), (A{{0, 0, 0}}));
  EXPECT_EQ(PRI::automatic_local_origin(A{{500123.456, 4200456.7, 31}}, A{{500900, 4201000, 80}}),
            (A{{500100, 4200400, 0}}));
  EXPECT_EQ(PRI::automatic_local_origin(A{{-150000.5, 0, 0}}, A{{-149000, 1, 1}}), (A{{-150100, 0, 0}}));
  EXPECT_EQ(PRI::automatic_local_origin(A{{50, 0, 0}}, A{{100000, 1, 1}}), (A{{0, 0, 0}}));
}

// ---------------------------------------------------------------------------------------------
// KITTI, XYZ, PLY

TEST_F(Io, KittiRoundTrip)
{
  Point_set ps;
  auto refl = ps.add_property_map<float>("reflectance", 0.f).first;
  for(int i = 0; i < 200; ++i) {
    const float x = 0.37f * float(i) - 30.f, y = 12.5f - 0.11f * float(i), z = -1.73f + 0.01f * float(i % 40);
    refl[*ps.insert(Point(x, y, z))] = float(i % 100) / 99.f;
  }
  PRI::write_kitti(path("scan.bin"), ps);
  const Bytes b = load(path("scan.bin"));
  ASSERT_EQ(b.size(), 200u * 16);
  float f;
  const std::uint32_t u = static_cast<std::uint32_t>(get(b, 16 * 3 + 4, 4));
  std::memcpy(&f, &u, 4);
  EXPECT_EQ(f, 12.5f - 0.11f * 3.f);  // y of point 3

  Point_set in;
  const auto r = PR::read_point_set(path("scan.bin"), in);
  EXPECT_EQ(r.format, "kitti");
  ASSERT_EQ(r.number_of_points, 200u);
  EXPECT_EQ(r.offset, (std::array<double, 3>{{0, 0, 0}}));
  EXPECT_EQ(r.property_names, std::vector<std::string>{"reflectance"});
  auto a = ps.begin();
  for(Point_set::Index i : in) {
    EXPECT_EQ(in.point(i), ps.point(*a));
    EXPECT_EQ(value<float>(in, "reflectance", i), refl[*a]);
    ++a;
  }
}

TEST_F(Io, XyzWithNormalsAndUtmCoordinatesKeepsMillimetres)
{
  save_text(path("cloud.xyz"), "3\n500123.456 4200456.789 12.345 0 0 1\n"
                               "500200.001 4200999.999 13 0 1 0\n# a comment\n500150.5 4200500.25 14.5 1 0 0\n");
  Point_set ps;
  const auto r = PR::read_point_set(path("cloud.xyz"), ps);
  EXPECT_EQ(r.format, "xyz");
  ASSERT_EQ(r.number_of_points, 3u);
  EXPECT_EQ(r.offset, (std::array<double, 3>{{500100, 4200400, 0}}));
  EXPECT_TRUE(has(r.property_names, "normal"));
  const Point& p = ps.point(*ps.begin());
  EXPECT_NEAR(p.x(), 23.456, 1e-9);
  EXPECT_NEAR(p.y(), 56.789, 1e-9);
  EXPECT_NEAR(p.x() + r.offset[0], 500123.456, 1e-9);
  EXPECT_EQ(ps.normal(*(ps.begin() + 1)), Kernel::Vector_3(0, 1, 0));
  // Other extensions of the same reader, in any case; points only: no normal map.
  save_text(path("cloud.PTS"), "1 2 3\n4 5 6\n");
  EXPECT_EQ(PR::read_point_set(path("cloud.PTS"), ps).number_of_points, 2u);
  EXPECT_FALSE(ps.has_normal_map());
  save_text(path("cloud.Txt"), "1 2 3\n");
  EXPECT_EQ(PR::read_point_set(path("cloud.Txt"), ps).offset, (std::array<double, 3>{{0, 0, 0}}));
}

TEST_F(Io, PlyKeepsItsProperties)
{
  save_text(path("c.ply"), "ply\nformat ascii 1.0\nelement vertex 3\nproperty double x\nproperty double y\n"
                           "property double z\nproperty uchar red\nproperty int label\nproperty float scalar_height\n"
                           "end_header\n1 2 3 255 4 0.5\n-1.5 0 7 10 -1 1.5\n0 0 0 0 9 2.5\n");
  Point_set ps;
  const auto r = PR::read_point_set(path("c.ply"), ps);
  EXPECT_EQ(r.format, "ply");
  ASSERT_EQ(r.number_of_points, 3u);
  EXPECT_EQ(r.offset, (std::array<double, 3>{{0, 0, 0}}));  // small coordinates: no shift
  EXPECT_TRUE(has(r.property_names, "label"));
  EXPECT_TRUE(has(r.property_names, "scalar_height"));
  const auto i1 = *(ps.begin() + 1);
  EXPECT_EQ(ps.point(i1), Point(-1.5, 0, 7));
  EXPECT_EQ(value<int>(ps, "label", i1), -1);
  EXPECT_EQ(value<float>(ps, "scalar_height", i1), 1.5f);
  EXPECT_EQ(value<unsigned char>(ps, "red", *ps.begin()), 255);
}

// ---------------------------------------------------------------------------------------------
// Bad files

TEST_F(Io, BadFilesAreRefusedWithClearMessages)
{
  Point_set ps;
  ps.insert(Point(1, 2, 3));
  auto read = [&](const std::string& name) { return [&ps, name] { PR::read_point_set(name, ps); }; };

  save(path("empty.las"), {});
  expect_bad_input(read(path("empty.las")), "the file is empty");
  EXPECT_TRUE(ps.empty());

  Bytes garbage(400, 0);
  garbage[0] = 'P';
  garbage[1] = 'K';
  save(path("sig.las"), garbage);
  expect_bad_input(read(path("sig.las")), "no \"LASF\" signature");

  Bytes shorter = hand_made_las(3, 3);
  shorter.resize(100);
  save(path("short.las"), shorter);
  expect_bad_input(read(path("short.las")), "truncated LAS header");

  Bytes truncated = hand_made_las(3, 3);
  truncated.resize(truncated.size() - 5);
  save(path("trunc.las"), truncated);
  expect_bad_input(read(path("trunc.las")), "truncated point data");

  save(path("more.las"), hand_made_las(2, 3));  // one more record than the header announces
  expect_bad_input(read(path("more.las")), "does not match the point count");

  Bytes laz = hand_made_las(3, 3);
  laz[104] |= 0x80;  // LASzip marks compressed point formats with bit 7
  save(path("laz.las"), laz);
  expect_bad_input(read(path("laz.las")), "compressed LAZ is not supported; decompress it with laszip");
  save(path("cloud.LAZ"), hand_made_las(3, 3));
  expect_bad_input(read(path("cloud.LAZ")), "compressed LAZ is not supported");

  Bytes format = hand_made_las(3, 3);
  format[104] = 11;
  save(path("fmt.las"), format);
  expect_bad_input(read(path("fmt.las")), "unknown LAS point data format 11");

  Bytes length = hand_made_las(3, 3);
  length[105] = 26;  // format 1 needs 28 bytes
  save(path("len.las"), length);
  expect_bad_input(read(path("len.las")), "point record length 26 is smaller than the 28 bytes");

  Bytes version = hand_made_las(3, 3);
  version[25] = 9;
  save(path("ver.las"), version);
  expect_bad_input(read(path("ver.las")), "unsupported LAS version 1.9");

  Bytes offset = hand_made_las(3, 3);
  offset[96] = 100;  // offset to point data inside the header
  offset[97] = 0;
  save(path("off.las"), offset);
  expect_bad_input(read(path("off.las")), "invalid offset to point data");

  save(path("none.las"), hand_made_las(0, 0));
  expect_bad_input(read(path("none.las")), "no points");

  expect_bad_input(read(path("missing.las")), "cannot open");
  expect_bad_input(read(path("missing.ply")), "cannot open");
  save_text(path("cloud.obj"), "v 1 2 3\n");
  expect_bad_input(read(path("cloud.obj")), "unknown point-set file extension \".obj\"");
  expect_bad_input(read(path("noextension")), "unknown point-set file extension");

  save(path("odd.bin"), Bytes(33, 0));
  expect_bad_input(read(path("odd.bin")), "multiple of 16");
  Bytes nan_point(16, 0);
  nan_point[2] = 0xc0;
  nan_point[3] = 0x7f;  // float NaN as x
  save(path("nan.bin"), nan_point);
  expect_bad_input(read(path("nan.bin")), "not finite");

  // Text files refused with the line, vertex or property named: name, content, words expected.
  const std::vector<std::array<std::string, 3>> refused{
    {"empty.xyz", "", "no points"},
    {"words.xyz", "1 2 3\nthis is not a point\n", "line 2: 'this' is not a number"},
    {"nan.xyz", "# a comment\n1 2 3\n\n4 nan 6\n", "line 4: 'nan' is not a finite number"},
    {"nan_ascii.ply",
     "ply\nformat ascii 1.0\nelement vertex 2\nproperty float x\nproperty float y\nproperty float z\nend_header\n"
     "1 2 3\n4 5 inf\n",
     "vertex 1: 'inf' is not a finite number"},
    {"bad.ply", "ply\nformat ascii 1.0\nelement vertex 2\nproperty double x\n", "no 'end_header' line"},
    // CGAL's reader would give every point the origin: the vertices need x, y and z ...
    {"uvw.ply",
     "ply\nformat ascii 1.0\nelement vertex 2\nproperty double u\nproperty double v\nproperty double w\n"
     "end_header\n1 2 3\n4 5 6\n",
     "no 'x' property"},
    // ... of a floating type, once each (CGAL's reader called a member of a null pointer).
    {"int_y.ply",
     "ply\nformat ascii 1.0\nelement vertex 1\nproperty double x\nproperty int y\nproperty double z\n"
     "end_header\n1 2 3\n",
     "'y' is int"},
    {"two_x.ply",
     "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty double x\nproperty double y\n"
     "property double z\nend_header\n1 2 3 4\n",
     "a second property 'x'"}};
  for(const auto& r : refused) {
    save_text(path(r[0]), r[1]);
    expect_bad_input(read(path(r[0])), r[2]);
  }
  std::filesystem::create_directories(path("folder.ply"));
  expect_bad_input(read(path("folder.ply")), "is a directory");
  EXPECT_TRUE(ps.empty());
}

TEST_F(Io, WriterRefusesWhatItCannotStore)
{
  std::vector<std::array<double, 3>> world;
  const Point_set ps = utm_cloud(10, false, world);
  expect_bad_input([&] { PRI::write_las(path("a.las"), ps, {{0.001, 0.001, 0.001}}, {{0, 0, 0}}, 1); },
                   "does not fit in 32-bit integers");
  EXPECT_FALSE(std::filesystem::exists(path("a.las")));
  EXPECT_FALSE(std::filesystem::exists(path("a.las.tmp")));
  expect_bad_input([&] { PRI::write_las(path("a.las"), ps, {{0.001, 0.001, 0.001}}, {{500000, 4200000, 0}}, 4); },
                   "point data format 4 is not written");
  expect_bad_input([&] { PRI::write_las(path("a.las"), ps, {{0, 0.001, 0.001}}, {{500000, 4200000, 0}}, 1); },
                   "scale must be positive");
  const Point_set wide = utm_cloud(40, true, world);  // classifications up to 255
  expect_bad_input([&] { PRI::write_las(path("a.las"), wide, {{0.001, 0.001, 0.001}}, {{500000, 4200000, 0}}, 1); },
                   "classification above 31");
}

// ---------------------------------------------------------------------------------------------
// CGAL's demo point files (extracted by the build into SHAPE_ANALYSIS_DATA_DIR when listed there)

// The bytes of `ps` as a binary PLY (every property, in the point set's order).
std::string ply_bytes(const Point_set& ps)
{
  std::ostringstream out;
  CGAL::IO::set_mode(out, CGAL::IO::BINARY);
  CGAL::IO::write_PLY(out, ps);
  return out.str();
}

// Point_set_file_reader gives, piece by piece (pieces of `piece` points, read in reverse order),
// exactly the points and properties that read_point_set() gives with the same origin.
void expect_pieces_equal_whole(const std::string& file, std::size_t piece)
{
  Point_set whole, all, part;
  const auto r = PR::read_point_set(file, whole);
  const PR::Point_set_file_reader reader(file);
  ASSERT_EQ(reader.number_of_points(), whole.size()) << file;
  EXPECT_EQ(reader.format(), r.format);
  std::vector<Point_set> pieces;
  for(std::uint64_t first = 0; first < reader.number_of_points(); first += piece)
    pieces.emplace_back();
  for(std::size_t k = pieces.size(); k-- > 0;) {
    const std::uint64_t first = k * piece;
    reader.read(first, std::size_t(std::min<std::uint64_t>(piece, reader.number_of_points() - first)), pieces[k], r.offset);
  }
  for(std::size_t k = 0; k < pieces.size(); ++k)
    if(k == 0)
      all = pieces[0];
    else
      all.join(pieces[k]);
  EXPECT_EQ(all.properties(), whole.properties()) << file;
  EXPECT_TRUE(ply_bytes(all) == ply_bytes(whole)) << file;
  // The coordinates alone, as stored.
  std::vector<double> xyz;
  reader.read_coordinates(1, 2, xyz);
  ASSERT_EQ(xyz.size(), 6u);
  const Point& second = whole.point(*(whole.begin() + 1));
  EXPECT_EQ(xyz[0] - r.offset[0], second.x());
  EXPECT_EQ(xyz[2] - r.offset[2], second.z());
  EXPECT_EQ(PR::Point_set_file_reader::automatic_local_origin({{xyz[0], xyz[1], xyz[2]}}, {{xyz[3], xyz[4], xyz[5]}})[0] != 0,
            r.offset[0] != 0);
}

TEST_F(Io, FileReaderPiecesAreReadPointSet)
{
  // LAS 1.2 and 1.4 (formats 1, 3, 6, 7) with UTM coordinates, extra bytes and class names.
  std::vector<std::array<double, 3>> world;
  for(unsigned format : {1u, 3u, 6u, 7u}) {
    Point_set utm = utm_cloud(1000, format >= 6, world);
    auto extra = utm.add_property_map<int>("instance", 0).first;
    auto value = utm.add_property_map<float>("score", 0).first;
    std::size_t k = 0;
    for(Point_set::Index i : utm)
      extra[i] = int(k) - 500, value[i] = float(k++) / 7.f;
    const std::string file = path("f" + std::to_string(format) + ".las");
    PRI::write_las(file, utm, {{0.001, 0.001, 0.001}}, {{500000, 4200000, 0}}, format);
    expect_pieces_equal_whole(file, 333);
  }
  // Binary PLY with float coordinates, normals and properties of every type.
  Point_set ply;
  ply.add_normal_map();
  auto c = ply.add_property_map<signed char>("c", 0).first;
  auto uc = ply.add_property_map<unsigned char>("red", 0).first;
  auto sh = ply.add_property_map<short>("s", 0).first;
  auto us = ply.add_property_map<unsigned short>("us", 0).first;
  auto ui = ply.add_property_map<unsigned int>("ui", 0).first;
  auto d = ply.add_property_map<double>("d", 0).first;
  for(int j = 0; j < 500; ++j) {
    const auto i = *ply.insert(Point(0.25 * j, -0.5 * j, 1.0 / (j + 1)), Kernel::Vector_3(0, 0.6, 0.8));
    c[i] = static_cast<signed char>(j % 200 - 100), uc[i] = static_cast<unsigned char>(j % 256);
    sh[i] = static_cast<short>(-j), us[i] = static_cast<unsigned short>(3 * j), ui[i] = 7u * unsigned(j);
    d[i] = std::sqrt(double(j));
  }
  {
    std::ofstream out(path("p.ply"), std::ios::binary);
    CGAL::IO::set_mode(out, CGAL::IO::BINARY);
    CGAL::IO::write_PLY(out, ply);
  }
  expect_pieces_equal_whole(path("p.ply"), 64);
  // KITTI.
  PRI::write_kitti(path("k.bin"), utm_cloud(1000, false, world), {{0, 0, 0}});
  expect_pieces_equal_whole(path("k.bin"), 100);
  // CGAL's airborne tile (double coordinates, colours, labels) when the build extracted it.
  const std::string b9 = std::string(SHAPE_ANALYSIS_DATA_DIR) + "/b9_training.ply";
  if(std::filesystem::exists(b9))
    expect_pieces_equal_whole(b9, 4096);
}

TEST_F(Io, FileReaderRefusesWhatItCannotReadInPieces)
{
  std::ofstream(path("a.xyz")) << "1 2 3\n4 5 6\n";
  expect_bad_input([&] { PR::Point_set_file_reader r(path("a.xyz")); }, "LAS, binary PLY or KITTI");
  EXPECT_FALSE(PR::Point_set_file_reader::readable(path("a.xyz")));
  std::ofstream(path("ascii.ply")) << "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float y\n"
                                      "property float z\nend_header\n1 2 3\n";
  expect_bad_input([&] { PR::Point_set_file_reader r(path("ascii.ply")); }, "binary_little_endian");
  std::ofstream(path("list.ply"), std::ios::binary)
    << "ply\nformat binary_little_endian 1.0\nelement vertex 1\nproperty float x\nproperty float y\n"
       "property float z\nproperty list uchar int i\nend_header\n";
  expect_bad_input([&] { PR::Point_set_file_reader r(path("list.ply")); }, "list");
  std::ofstream(path("short.ply"), std::ios::binary)
    << "ply\nformat binary_little_endian 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
       "property float z\nend_header\n0123456789ab0123456789ab";
  expect_bad_input([&] { PR::Point_set_file_reader r(path("short.ply")); }, "3 vertices");
  std::ofstream(path("odd.bin"), std::ios::binary) << "0123456789abcdefXYZ";
  expect_bad_input([&] { PR::Point_set_file_reader r(path("odd.bin")); }, "multiple of 16");
  std::ofstream(path("empty.las"));
  expect_bad_input([&] { PR::Point_set_file_reader r(path("empty.las")); }, "LAS");
  expect_bad_input([&] { PR::Point_set_file_reader r(path("missing.las")); }, "missing.las");
  // A range beyond the points.
  std::vector<std::array<double, 3>> world;
  PRI::write_kitti(path("k.bin"), utm_cloud(10, false, world), {{0, 0, 0}});
  const PR::Point_set_file_reader reader(path("k.bin"));
  std::vector<double> xyz;
  expect_bad_input([&] { reader.read_coordinates(8, 3, xyz); }, "beyond");
  Point_set ps;
  expect_bad_input([&] { reader.read(11, 0, ps); }, "beyond");
  reader.read(10, 0, ps);
  EXPECT_TRUE(ps.empty());
}

// A LAS file written in pieces (the pieces' records in reverse order at their places, the header
// of their merged summaries) is the file write_las_point_set() writes from the whole.
TEST_F(Io, LasWrittenInPiecesIsTheWholeFile)
{
  std::vector<std::array<double, 3>> world;
  Point_set whole = utm_cloud(1000, true, world);
  auto instance = whole.add_property_map<int>("instance", 0).first;
  std::size_t k = 0;
  for(Point_set::Index i : whole)
    instance[i] = int(k++ % 17) - 3;
  const std::vector<std::pair<unsigned, std::string>> names = {{64, "pole"}, {65, "car"}};
  std::ostringstream expected;
  PR::write_las_point_set(expected, whole, PR::parameters::class_names(names).local_origin(std::array<double, 3>{{10, 20, 0}}));
  std::array<double, 3> lowest{{1e300, 1e300, 1e300}};
  for(Point_set::Index i : whole)
    for(int c = 0; c < 3; ++c)
      lowest[std::size_t(c)] = std::min(lowest[std::size_t(c)], whole.point(i)[c]);
  const PR::Las_point_set_pieces<Point> pieces(whole, lowest,
                                               PR::parameters::class_names(names).local_origin(std::array<double, 3>{{10, 20, 0}}));
  const std::size_t header = pieces.header({}).size(), piece = 300;
  std::string file(header + whole.size() * pieces.record_length(), '\0');
  PR::Las_point_set_pieces<Point>::Summary all;
  for(std::size_t first : {900, 600, 300, 0}) { // the pieces in reverse order
    Point_set part = whole;
    part.remove(part.begin(), part.end()); // the properties kept
    part.collect_garbage();
    for(std::size_t j = first; j < std::min(first + piece, whole.size()); ++j)
      part.insert(whole, *(whole.begin() + std::ptrdiff_t(j)));
    std::vector<unsigned char> records;
    all.merge(pieces.records(part, records));
    ASSERT_EQ(records.size(), part.size() * pieces.record_length());
    std::copy(records.begin(), records.end(), file.begin() + std::ptrdiff_t(header + first * pieces.record_length()));
  }
  const std::vector<unsigned char> h = pieces.header(all);
  std::copy(h.begin(), h.end(), file.begin());
  EXPECT_EQ(all.number_of_points, whole.size());
  EXPECT_TRUE(file == expected.str());
  // A piece with other properties than the layout's is refused.
  Point_set other = utm_cloud(3, true, world);
  std::vector<unsigned char> records;
  expect_bad_input([&] { pieces.records(other, records); }, "other properties");
}

TEST(DemoData, CgalPointFilesAreRead)
{
  const std::string dir = SHAPE_ANALYSIS_DATA_DIR;
  int found = 0;
  Point_set ps;
  if(std::filesystem::exists(dir + "/b9_training.ply")) {
    // An urban LIDAR tile in projected coordinates with a label per point.
    const auto r = PR::read_point_set(dir + "/b9_training.ply", ps);
    EXPECT_EQ(r.number_of_points, 22300u);
    EXPECT_EQ(r.offset, (std::array<double, 3>{{596600, 243600, 0}}));
    EXPECT_TRUE(has(r.property_names, "label"));
    ++found;
  }
  for(const char* name : {"kitten.xyz", "sphere_20k.xyz", "oni.ply"}) {
    if(!std::filesystem::exists(dir + "/" + name))
      continue;
    const auto r = PR::read_point_set(dir + "/" + name, ps);
    EXPECT_GT(r.number_of_points, 1000u) << name;
    EXPECT_LT(r.number_of_points, 100000u) << name;
    EXPECT_EQ(r.offset, (std::array<double, 3>{{0, 0, 0}})) << name;
    ++found;
  }
  if(found == 0)
    GTEST_SKIP() << "no CGAL point file (b9_training.ply, kitten.xyz, sphere_20k.xyz, oni.ply) in " << dir;
}

// The options come from one place: without named parameters, the struct's defaults; a named
// parameter given lands in its member.
TEST(ReadPointSet, OptionsFromNamedParameters)
{
  const PR::Read_point_set_options d;
  const PR::Read_point_set_options o = PR::read_point_set_options();
  EXPECT_EQ(o.shift_to_local_origin, d.shift_to_local_origin);
  EXPECT_EQ(o.local_origin, d.local_origin);
  EXPECT_FALSE(o.local_origin.has_value());
  EXPECT_FALSE(PR::read_point_set_options(PR::parameters::shift_to_local_origin(false)).shift_to_local_origin);
  const PR::Read_point_set_options g =
    PR::read_point_set_options(PR::parameters::local_origin(std::array<double, 3>{{100.0, 200.0, 0.0}}));
  ASSERT_TRUE(g.local_origin.has_value());
  EXPECT_EQ((*g.local_origin)[1], 200.0);
}

} // namespace
