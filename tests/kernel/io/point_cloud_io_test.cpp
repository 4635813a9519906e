// Point clouds in and out (kernel/io/point_cloud_io.hpp): every writer's file reads back to the
// same doubles (the oracle: the cloud written), each reader on worked examples (a PLY without
// faces, ascii and binary, a mesh's vertices, XYZ with comments, OFF and NOFF, npy of several
// dtypes and orders), and each class of bad input as one IoError/InvalidArgument line naming
// the file and the line or record.
#include <zdg/arith/error.hpp>
#include <zdg/kernel/io/npy_io.hpp>
#include <zdg/kernel/io/point_cloud_io.hpp>

#include "tests/support/cli.hpp"
#include "tests/support/tower.hpp"

#include <gtest/gtest.h>
#include <rapidcheck.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <limits>
#include <string>

namespace zdg {
namespace {

namespace fs = std::filesystem;

// The error of parsing bytes, "" when none.
std::string error_of(std::string_view bytes, PointCloudFormat f, const std::string& source) {
  try {
    (void)parse_point_cloud(bytes, f, source);
  } catch (const Error& e) {
    return e.what();
  }
  return "";
}

void expect_error(std::string_view bytes, PointCloudFormat f, const std::string& want) {
  const std::string e = error_of(bytes, f, "in.txt");
  EXPECT_NE(e.find(want), std::string::npos) << "got: '" << e << "', want '" << want << "'";
  EXPECT_EQ(e.find('\n'), std::string::npos) << e;
  EXPECT_EQ(e.rfind("in.txt", 0), 0u) << e;
}

// The bytes of an npy file: version 1.0 header padded to 64, then data.
std::string npy(const std::string& dict, const std::string& data) {
  std::string h = dict;
  const std::size_t total = 10 + h.size() + 1;
  h.append((64 - total % 64) % 64, ' ');
  h.push_back('\n');
  std::string out = "\x93NUMPY";
  out += '\x01';
  out += '\0';
  out += static_cast<char>(h.size() & 0xff);
  out += static_cast<char>(h.size() >> 8);
  return out + h + data;
}

template <class T>
std::string raw(std::initializer_list<T> v) {
  std::string out;
  for (const T x : v) out.append(reinterpret_cast<const char*>(&x), sizeof(T));
  return out;
}

PointCloud random_cloud(bool normals) {
  const int n = *rc::gen::inRange(1, 60);
  PointCloud c;
  // Doubles of every magnitude, with their full 53 bits: the text must round-trip them.
  const auto coordinate = [] {
    const double m =
        *rc::gen::inRange<std::int64_t>(-(std::int64_t{1} << 53), std::int64_t{1} << 53);
    return std::ldexp(m, *rc::gen::inRange(-80, 40));
  };
  for (int i = 0; i < n; ++i) c.points.push_back({coordinate(), coordinate(), double(i)});
  if (normals)
    for (int i = 0; i < n; ++i) c.normals.push_back({coordinate(), coordinate(), 1.0 + i});
  return c;
}

// Oracle: the cloud written. Each writer's file reads back to the same doubles, bit for bit.
TEST(PointCloudIo, EveryWriterRoundTripsExactly) {
  const fs::path dir = test::scratch_dir("point_cloud_round_trip");
  test::check_property([&] {
    const bool normals = *rc::gen::arbitrary<bool>();
    const PointCloud c = random_cloud(normals);
    for (const char* ext : {".ply", ".xyz", ".npy"}) {
      const std::string path = (dir / (std::string("c") + ext)).string();
      write_point_cloud(path, c);
      const PointCloud back = read_point_cloud(path);
      RC_ASSERT(back.points == c.points);
      RC_ASSERT(back.normals == c.normals);
      // The same through the bytes (the fuzzed path).
      const PointCloud again =
          parse_point_cloud(test::read_file(path), point_cloud_format_of(path), path);
      RC_ASSERT(again.points == c.points);
    }
  });
}

TEST(PointCloudIo, PlyWithoutFacesAsciiAndBigEndian) {
  const std::string ascii = "ply\nformat ascii 1.0\ncomment a scan\nelement vertex 3\n"
                            "property float x\nproperty float y\nproperty float z\n"
                            "property uchar red\nend_header\n0 0 0 255\n1 0 0 0\n0 1.5 0 7\n";
  const PointCloud a = parse_point_cloud(ascii, PointCloudFormat::ply, "a.ply");
  ASSERT_EQ(a.size(), 3u);
  EXPECT_FALSE(a.has_normals());
  EXPECT_EQ(a.points[2], (Point3<double>{0, 1.5, 0}));

  std::string be = "ply\nformat binary_big_endian 1.0\nelement vertex 2\nproperty short x\n"
                   "property short y\nproperty short z\nproperty double nx\nproperty double ny\n"
                   "property double nz\nend_header\n";
  const auto put16 = [&](std::int16_t v) {
    be += static_cast<char>((v >> 8) & 0xff);
    be += static_cast<char>(v & 0xff);
  };
  const auto put64 = [&](double v) {
    unsigned char b[8];
    std::memcpy(b, &v, 8);
    for (int k = 7; k >= 0; --k) be += static_cast<char>(b[k]);
  };
  put16(1), put16(-2), put16(3), put64(0), put64(0), put64(-1);
  put16(4), put16(5), put16(-6), put64(1), put64(0), put64(0);
  const PointCloud b = parse_point_cloud(be, PointCloudFormat::ply, "b.ply");
  ASSERT_EQ(b.size(), 2u);
  EXPECT_EQ(b.points[0], (Point3<double>{1, -2, 3}));
  EXPECT_EQ(b.normals[0], (Point3<double>{0, 0, -1}));
  EXPECT_EQ(b.points[1], (Point3<double>{4, 5, -6}));
}

TEST(PointCloudIo, PlyMeshGivesItsVertices) {
  const std::string mesh = "ply\nformat ascii 1.0\nelement vertex 3\nproperty double x\n"
                           "property double y\nproperty double z\nelement face 1\n"
                           "property list uchar int vertex_indices\nend_header\n"
                           "0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n";
  EXPECT_EQ(parse_point_cloud(mesh, PointCloudFormat::ply, "m.ply").size(), 3u);
}

TEST(PointCloudIo, XyzWithCommentsBlankLinesAndNormals) {
  const PointCloud c = parse_point_cloud("# a scan\n\n1 2 3 0 0 1\r\n  -4\t5e-1 +6 1 0 0 # x\n",
                                         PointCloudFormat::xyz, "s.xyz");
  ASSERT_EQ(c.size(), 2u);
  EXPECT_EQ(c.points[1], (Point3<double>{-4, 0.5, 6}));
  EXPECT_EQ(c.normals[0], (Point3<double>{0, 0, 1}));
  const PointCloud d = parse_point_cloud("0 0 0\n1 1 1", PointCloudFormat::xyz, "d.xyz");
  EXPECT_EQ(d.size(), 2u);
  EXPECT_FALSE(d.has_normals());
}

TEST(PointCloudIo, OffAndNoffVerticesFacesIgnored) {
  const PointCloud c = parse_point_cloud("OFF\n# tetra\n4 4 6\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n"
                                         "3 0 1 2\n3 0 1 3\n3 0 2 3\n3 1 2 3\n",
                                         PointCloudFormat::off, "t.off");
  ASSERT_EQ(c.size(), 4u);
  EXPECT_EQ(c.points[3], (Point3<double>{0, 0, 1}));
  const PointCloud n =
      parse_point_cloud("NOFF 2 0 0\n0 0 0 0 0 1\n1 0 0 0 1 0\n", PointCloudFormat::off, "n.off");
  ASSERT_EQ(n.size(), 2u);
  EXPECT_EQ(n.normals[1], (Point3<double>{0, 1, 0}));
}

TEST(PointCloudIo, NpyDtypesAndOrders) {
  const PointCloud f =
      parse_point_cloud(npy("{'descr': '<f4', 'fortran_order': False, 'shape': (2, 3), }",
                            raw<float>({1, 2, 3, 4, 5, 6})),
                        PointCloudFormat::npy, "f.npy");
  EXPECT_EQ(f.points[1], (Point3<double>{4, 5, 6}));
  // Fortran order: the columns one after the other.
  const PointCloud g =
      parse_point_cloud(npy("{'descr': '<f8', 'fortran_order': True, 'shape': (2, 3), }",
                            raw<double>({1, 4, 2, 5, 3, 6})),
                        PointCloudFormat::npy, "g.npy");
  EXPECT_EQ(g.points, f.points);
  const PointCloud h =
      parse_point_cloud(npy("{'descr': '<i2', 'fortran_order': False, 'shape': (1, 6), }",
                            raw<std::int16_t>({-1, 2, 3, 0, 0, 7})),
                        PointCloudFormat::npy, "h.npy");
  EXPECT_EQ(h.points[0], (Point3<double>{-1, 2, 3}));
  EXPECT_EQ(h.normals[0], (Point3<double>{0, 0, 7}));
}

TEST(PointCloudIo, FormatByExtension) {
  EXPECT_EQ(point_cloud_format_of("a/B.PLY"), PointCloudFormat::ply);
  EXPECT_EQ(point_cloud_format_of("x.xyz"), PointCloudFormat::xyz);
  EXPECT_EQ(point_cloud_format_of("x.off"), PointCloudFormat::off);
  EXPECT_EQ(point_cloud_format_of("x.npy"), PointCloudFormat::npy);
  try {
    (void)point_cloud_format_of("x.obj");
    ADD_FAILURE() << "no error";
  } catch (const IoError& e) {
    EXPECT_STREQ(e.what(), "x.obj: unknown point cloud format '.obj' (.ply, .xyz, .off or .npy)");
  }
  const fs::path dir = test::scratch_dir("point_cloud_off_out");
  PointCloud c;
  c.points = {{0, 0, 0}};
  EXPECT_THROW(write_point_cloud((dir / "c.off").string(), c), IoError);
  EXPECT_FALSE(fs::exists(dir / "c.off"));
}

// Each class of bad input: one line naming the file and the line or record.
TEST(PointCloudIo, BadInputIsOneLineNamingTheRecord) {
  using F = PointCloudFormat;
  // Empty, in every format.
  expect_error("", F::xyz, "in.txt: no points");
  expect_error("# nothing\n\n", F::xyz, "in.txt: no points");
  expect_error("OFF\n0 0 0\n", F::off, "in.txt: no points");
  expect_error("ply\nformat ascii 1.0\nelement vertex 0\nproperty float x\nproperty float y\n"
               "property float z\nend_header\n",
               F::ply, "in.txt: no points");
  expect_error(npy("{'descr': '<f8', 'fortran_order': False, 'shape': (0, 3), }", ""), F::npy,
               "in.txt: no points");
  // Not finite, naming the line / record.
  expect_error("0 0 0\n1 nan 2\n", F::xyz, "in.txt:2: 'nan' is not finite");
  expect_error("0 0 0\n1 1e999 2\n", F::xyz, "in.txt:2: '1e999' is out of the range");
  expect_error("OFF\n2 0 0\n0 0 0\n0 inf 0\n", F::off, "in.txt:4: 'inf' is not finite");
  expect_error("ply\nformat ascii 1.0\nelement vertex 2\nproperty float x\nproperty float y\n"
               "property float z\nend_header\n0 0 0\n1 nan 0\n",
               F::ply, "in.txt: vertex 1: coordinate y is not finite");
  expect_error(npy("{'descr': '<f8', 'fortran_order': False, 'shape': (2, 3), }",
                   raw<double>({0, 0, 0, 1, std::numeric_limits<double>::quiet_NaN(), 0})),
               F::npy, "in.txt: row 1, column 1: the value is not finite");
  // Malformed text.
  expect_error("1 2 x\n", F::xyz, "in.txt:1: 'x' is not a number");
  expect_error("1 2\n", F::xyz, "in.txt:1: 2 fields: 'x y z' or 'x y z nx ny nz' expected");
  expect_error("1 2 3\n4 5 6 0 0 1\n", F::xyz, "in.txt:2: 6 fields where the first point has 3");
  expect_error("1 2 3 4 5 6 7\n", F::xyz, "in.txt:1: more than 6 fields");
  expect_error("PLY\n", F::off, "in.txt:1: not an OFF file");
  expect_error("OFF\n-1 0 0\n", F::off, "in.txt:2: vertex count '-1'");
  expect_error("OFF\n3 0 0\n0 0 0\n1 1 1\n", F::off, "in.txt: the file ends after 2 of the 3");
  expect_error("OFF\n1000000000000 0 0\n0 0 0\n", F::off, "the file ends after 1 of the");
  expect_error("NOFF\n1 0 0\n0 0 0\n", F::off, "in.txt:3: vertex 0: 3 fields (6 expected in NOFF)");
  // Headers claiming more than the file holds (no memory taken for the claim).
  expect_error("ply\nformat binary_little_endian 1.0\nelement vertex 4000000000\n"
               "property float x\nproperty float y\nproperty float z\nend_header\n",
               F::ply, "in.txt: element vertex claims 4000000000 records");
  expect_error(npy("{'descr': '<f8', 'fortran_order': False, 'shape': (100000000000, 3), }",
                   raw<double>({0, 0, 0})),
               F::npy, "in.txt: truncated data");
  // Not a point cloud's shape or dtype.
  expect_error(
      npy("{'descr': '<f8', 'fortran_order': False, 'shape': (3,), }", raw<double>({0, 0, 0})),
      F::npy, "in.txt: an array of shape (3,) is not a point cloud (N x 3 or N x 6)");
  expect_error(
      npy("{'descr': '|b1', 'fortran_order': False, 'shape': (1, 3), }", std::string("\1\0\1", 3)),
      F::npy, "in.txt: a bool array is not a point cloud");
  // The cloud's own checks: repeated points, zero normals.
  expect_error("0 0 0\n1 1 1\n0 0 0\n", F::xyz, "in.txt: point 2 repeats point 0");
  expect_error("0 0 0 0 0 1\n1 1 1 0 0 0\n", F::xyz, "in.txt: the normal of point 1 is zero");
}

} // namespace
} // namespace zdg
