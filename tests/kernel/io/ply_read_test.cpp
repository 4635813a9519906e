// The PLY reader: worked files in each format (ascii, both byte orders, every scalar type, a
// mixed-size mesh split into triangles, elements and lists it skips), the round trip through
// zdg's own writer as a property (the reader's oracle is the mesh written: coordinates and
// fields equal to their float32 roundings, zdg's field names restored), and a table of bad
// files, each a one-line IoError naming what was wrong.
#include <zdg/arith/error.hpp>
#include <zdg/kernel/io/mesh_io.hpp>
#include <zdg/kernel/io/ply_read.hpp>

#include "tests/support/cli.hpp"

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <bit>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <limits>

namespace zdg {
namespace {

namespace fs = std::filesystem;

const std::string kTetra = "ply\nformat ascii 1.0\ncomment tetrahedron\nelement vertex 4\n"
                           "property float x\nproperty float y\nproperty float z\n"
                           "property float q\nelement face 4\n"
                           "property list uchar int vertex_indices\nproperty float k\n"
                           "end_header\n0 0 0 1\n1 0 0 2\n0 1 0 3\n0 0 1 4\n"
                           "3 0 2 1 0.5\n3 0 1 3 1.5\n3 0 3 2 2.5\n3 1 2 3 3.5\n";

TEST(PlyRead, AsciiTetrahedron) {
  const PlyMesh p = parse_ply(kTetra, "tetra.ply");
  EXPECT_EQ(p.format, "ascii");
  EXPECT_EQ(p.mesh.face_size, 3);
  EXPECT_EQ(p.mesh.vertex_count(), 4);
  EXPECT_EQ(p.mesh.face_count(), 4);
  EXPECT_EQ(p.mesh.indices, (std::vector<std::int64_t>{0, 2, 1, 0, 1, 3, 0, 3, 2, 1, 2, 3}));
  ASSERT_EQ(p.mesh.face_scalars.size(), 1u);
  EXPECT_EQ(p.mesh.face_scalars[0].first, "k");
  EXPECT_EQ(p.mesh.face_scalars[0].second, (std::vector<double>{0.5, 1.5, 2.5, 3.5}));
  ASSERT_EQ(p.vertex_scalars.size(), 1u);
  EXPECT_EQ(p.vertex_scalars[0].first, "q");
  EXPECT_EQ(p.vertex_scalars[0].second, (std::vector<double>{1, 2, 3, 4}));
  EXPECT_EQ(p.mesh.vertices[3].z, 1.0);
  EXPECT_FALSE(p.triangulated);
}

TEST(PlyRead, MixedFacesAreSplitIntoFansAndOtherElementsSkipped) {
  const std::string text = "ply\r\nformat ascii 1.0\r\nelement vertex 5\r\nproperty double x\r\n"
                           "property double y\r\nproperty double z\r\nelement face 2\r\n"
                           "property list uchar uint vertex_index\r\nproperty list uchar float "
                           "texcoord\r\nproperty int part\r\nelement edge 1\r\n"
                           "property int vertex1\r\nproperty int vertex2\r\nend_header\r\n"
                           "0 0 0\r\n1 0 0\r\n1 1 0\r\n0 1 0\r\n0.5 2 0\r\n"
                           "4 0 1 2 3 2 0.1 0.2 7\r\n3 3 2 4 0 -1\r\n0 1\r\n";
  const PlyMesh p = parse_ply(text, "mixed.ply");
  EXPECT_TRUE(p.triangulated);
  EXPECT_EQ(p.file_faces, 2);
  EXPECT_EQ(p.mesh.face_size, 3);
  EXPECT_EQ(p.mesh.indices, (std::vector<std::int64_t>{0, 1, 2, 0, 2, 3, 3, 2, 4}));
  ASSERT_EQ(p.mesh.face_scalars.size(), 1u);
  EXPECT_EQ(p.mesh.face_scalars[0].second, (std::vector<double>{7, 7, -1}));
  EXPECT_EQ(p.other, (std::vector<std::string>{"face.texcoord", "edge"}));
}

std::string big_endian_triangle() {
  std::string b = "ply\nformat binary_big_endian 1.0\nelement vertex 3\nproperty short x\n"
                  "property uchar y\nproperty double z\nelement face 1\n"
                  "property list ushort uint vertex_indices\nproperty int label\n"
                  "property char c\nend_header\n";
  auto put = [&](const auto v) {
    unsigned char bytes[sizeof(v)];
    std::memcpy(bytes, &v, sizeof(v));
    if constexpr (std::endian::native == std::endian::little)
      for (std::size_t i = 0; i < sizeof(v); ++i) b.push_back(char(bytes[sizeof(v) - 1 - i]));
    else
      b.append(reinterpret_cast<const char*>(bytes), sizeof(v));
  };
  const std::int16_t xs[3] = {0, -2, 3};
  const std::uint8_t ys[3] = {0, 1, 200};
  const double zs[3] = {0, 0.5, 1e300};
  for (int i = 0; i < 3; ++i) {
    put(xs[i]);
    put(ys[i]);
    put(zs[i]);
  }
  put(std::uint16_t{3});
  for (std::uint32_t i : {0u, 1u, 2u}) put(i);
  put(std::int32_t{-7});
  put(std::int8_t{-128});
  return b;
}

TEST(PlyRead, BinaryBigEndianWithEveryIntegerWidth) {
  const PlyMesh p = parse_ply(big_endian_triangle(), "be.ply");
  EXPECT_EQ(p.format, "binary_big_endian");
  ASSERT_EQ(p.mesh.vertex_count(), 3);
  EXPECT_EQ(p.mesh.vertices[1].x, -2);
  EXPECT_EQ(p.mesh.vertices[2].y, 200);
  EXPECT_EQ(p.mesh.vertices[2].z, 1e300);
  ASSERT_EQ(p.mesh.face_scalars.size(), 2u);
  EXPECT_EQ(p.mesh.face_scalars[0].second, std::vector<double>{-7});
  EXPECT_EQ(p.mesh.face_scalars[1].second, std::vector<double>{-128});
}

// Regression (shrunk by ReadsBackWhatWritePlyWrote): a face element of no records gives no
// face size; the mesh is read as triangles, of which it has none.
TEST(PlyRead, EmptyFaceElement) {
  const PlyMesh p = parse_ply("ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\n"
                              "property float y\nproperty float z\nelement face 0\n"
                              "property list uchar int vertex_indices\nend_header\n1 2 3\n",
                              "empty.ply");
  EXPECT_EQ(p.mesh.face_size, 3);
  EXPECT_EQ(p.mesh.face_count(), 0);
  EXPECT_EQ(p.mesh.vertex_count(), 1);
}

// A random closed-or-not mesh: V vertices, F faces of size k with indices in range, fields.
PolygonMesh random_mesh() {
  PolygonMesh m;
  m.face_size = *rc::gen::inRange(3, 7);
  const int nv = *rc::gen::inRange(3, 40);
  const int nf = *rc::gen::inRange(0, 40);
  const auto coord =
      rc::gen::map(rc::gen::inRange(-100000, 100000), [](int v) { return double(v) / 64.0 + 0.1; });
  for (int i = 0; i < nv; ++i) m.vertices.push_back({*coord, *coord, *coord});
  for (int i = 0; i < nf * m.face_size; ++i) m.indices.push_back(*rc::gen::inRange(0, nv));
  const int fields = *rc::gen::inRange(0, 4);
  const char* names[] = {"ii-mean", "at-v", "mean curvature", "z"}; // distinct property names
  for (int j = 0; j < fields; ++j) {
    std::vector<double> v;
    for (int f = 0; f < nf; ++f) v.push_back(*coord);
    m.face_scalars.emplace_back(names[j], v);
  }
  if (*rc::gen::arbitrary<bool>())
    for (int f = 0; f < nf; ++f) m.face_normals.push_back({*coord, *coord, *coord});
  if (*rc::gen::arbitrary<bool>())
    for (int i = 0; i < nv; ++i) m.vertex_normals.push_back({*coord, *coord, *coord});
  return m;
}

RC_GTEST_PROP(PlyRead, ReadsBackWhatWritePlyWrote, ()) {
  const PolygonMesh m = random_mesh();
  static const fs::path dir = test::scratch_dir("ply_round_trip");
  const std::string path = (dir / "m.ply").string();
  fs::remove(path);
  write_ply(path, m, 1);
  const PlyMesh p = read_ply(path);
  const auto f32 = [](double v) { return double(float(v)); };
  RC_ASSERT(p.format == std::string("binary_little_endian"));
  // A mesh of no faces has no face size to read back (see EmptyFaceElement).
  RC_ASSERT(m.face_count() == 0 || p.mesh.face_size == m.face_size);
  RC_ASSERT(p.mesh.indices == m.indices);
  RC_ASSERT(p.mesh.vertex_count() == m.vertex_count());
  for (std::size_t i = 0; i < m.vertices.size(); ++i) {
    RC_ASSERT(p.mesh.vertices[i].x == f32(m.vertices[i].x));
    RC_ASSERT(p.mesh.vertices[i].z == f32(m.vertices[i].z));
  }
  RC_ASSERT(p.mesh.face_normals.size() == m.face_normals.size());
  for (std::size_t i = 0; i < m.face_normals.size(); ++i)
    RC_ASSERT(p.mesh.face_normals[i].y == f32(m.face_normals[i].y));
  RC_ASSERT(p.mesh.vertex_normals.size() == m.vertex_normals.size());
  RC_ASSERT(p.mesh.face_scalars.size() == m.face_scalars.size());
  // zdg's comment restores the names, except where a name holds a space (the comment is then
  // ambiguous: the reader keeps the property names).
  bool spaced = false;
  for (const auto& f : m.face_scalars) spaced = spaced || f.first.find(' ') != std::string::npos;
  for (std::size_t j = 0; j < m.face_scalars.size(); ++j) {
    RC_ASSERT(p.mesh.face_scalars[j].first ==
              (spaced ? ply_property_name(m.face_scalars[j].first) : m.face_scalars[j].first));
    for (std::size_t f = 0; f < m.face_scalars[j].second.size(); ++f)
      RC_ASSERT(p.mesh.face_scalars[j].second[f] == f32(m.face_scalars[j].second[f]));
  }
  RC_ASSERT(p.vertex_scalars.empty());
}

// The same mesh written as ascii by hand reads as the binary one does.
RC_GTEST_PROP(PlyRead, AsciiAndBinaryAgree, ()) {
  const PolygonMesh m = random_mesh();
  std::string t = "ply\nformat ascii 1.0\nelement vertex " + std::to_string(m.vertex_count()) +
                  "\nproperty float x\nproperty float y\nproperty float z\nelement face " +
                  std::to_string(m.face_count()) + "\nproperty list uchar int vertex_indices\n";
  for (std::size_t j = 0; j < m.face_scalars.size(); ++j)
    t += "property double f" + std::to_string(j) + "\n";
  t += "end_header\n";
  char buf[64];
  for (const auto& v : m.vertices) {
    std::snprintf(buf, sizeof buf, "%.9g %.9g %.9g\n", double(float(v.x)), double(float(v.y)),
                  double(float(v.z)));
    t += buf;
  }
  for (std::int64_t f = 0; f < m.face_count(); ++f) {
    t += std::to_string(m.face_size);
    for (const auto i : m.face(f)) {
      std::snprintf(buf, sizeof buf, " %lld", static_cast<long long>(i));
      t += buf;
    }
    for (const auto& s : m.face_scalars) {
      std::snprintf(buf, sizeof buf, " %.17g", s.second[std::size_t(f)]);
      t += buf;
    }
    t += "\n";
  }
  const PlyMesh p = parse_ply(t, "m.ply");
  RC_ASSERT(p.mesh.indices == m.indices);
  for (std::size_t i = 0; i < m.vertices.size(); ++i)
    RC_ASSERT(p.mesh.vertices[i].y == double(float(m.vertices[i].y)));
  for (std::size_t j = 0; j < m.face_scalars.size(); ++j)
    RC_ASSERT(p.mesh.face_scalars[j].second == m.face_scalars[j].second);
}

// Each bad file: an IoError whose one line holds the expected words.
TEST(PlyRead, BadFilesAreOneLineErrors) {
  const std::string head = "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\n"
                           "property float y\nproperty float z\nelement face 1\n"
                           "property list uchar int vertex_indices\nend_header\n";
  const std::string verts = "0 0 0\n1 0 0\n0 1 0\n";
  const std::vector<std::pair<std::string, std::string>> rows = {
      {"", "not a PLY file"},
      {"PLY\n", "not a PLY file"},
      {"ply\nformat ascii 1.0\nelement vertex 0\n", "no end_header"},
      {"ply\nelement vertex 0\nend_header\n", "no format line"},
      {"ply\nformat ascii 2.0\nend_header\n", "PLY version '2.0'"},
      {"ply\nformat binary_middle_endian 1.0\nend_header\n", "unknown format"},
      {"ply\nformat ascii 1.0\nproperty float x\nend_header\n", "property before any element"},
      {"ply\nformat ascii 1.0\nelement vertex -1\nend_header\n", "not a non-negative integer"},
      {"ply\nformat ascii 1.0\nelement vertex 1\nproperty quad x\nend_header\n",
       "unknown property type 'quad'"},
      {"ply\nformat ascii 1.0\nelement vertex 1\nproperty list float int x\nend_header\n",
       "list count type"},
      {"ply\nformat ascii 1.0\nfoo\nend_header\n", "unknown header line 'foo'"},
      {"ply\nformat ascii 1.0\nelement vertex 0\nproperty float x\nproperty float y\n"
       "end_header\n",
       "no scalar property 'z'"},
      {"ply\nformat ascii 1.0\nelement vertex 0\nproperty float x\nproperty float y\n"
       "property float z\nend_header\n",
       "no face element"},
      {head + verts + "3 0 1 3\n", "vertex index 3 out of range (3 vertices)"},
      {head + verts + "2 0 1\n", "2 vertices (at least 3 needed)"},
      {head + verts + "3 0 1\n", "ends inside face 0"},
      {head + verts + "3 0 1 2 4\n", "bytes after the last element"},
      {head + "0 0 0\nnan 0 0\n0 1 0\n3 0 1 2\n", "coordinate x is not finite"},
      {head + "0 0 0\n1e999 0 0\n0 1 0\n3 0 1 2\n", "not finite"},
      {head + "0 0 0\n1 zero 0\n0 1 0\n3 0 1 2\n", "'zero' is not a number"},
      {head + verts + "3 0 1 2.5\n", "'2.5' is not an integer"},
      {head + verts + "300 0 1 2\n", "out of the property's type range"},
      {"ply\nformat binary_little_endian 1.0\nelement vertex 4000000000\nproperty float x\n"
       "property float y\nproperty float z\nelement face 0\n"
       "property list uchar int vertex_indices\nend_header\n",
       "claims 4000000000 records"},
  };
  for (const auto& [text, expected] : rows) {
    try {
      (void)parse_ply(text, "bad.ply");
      ADD_FAILURE() << "no error for: " << text;
    } catch (const IoError& e) {
      const std::string what = e.what();
      EXPECT_NE(what.find(expected), std::string::npos) << what << "\nexpected: " << expected;
      EXPECT_EQ(what.find('\n'), std::string::npos) << what;
      EXPECT_EQ(what.rfind("bad.ply", 0), 0u) << what;
    }
  }
}

} // namespace
} // namespace zdg
