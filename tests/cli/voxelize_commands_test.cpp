// zdg voxelize: the written volume equals the library's voxelization in each mode and format,
// the JSON report (voxels, dims, origin, mode), a million faces on one voxel in bounded time.
#include "tests/support/cli.hpp"
#include <zdg/kernel/digitization/voxelize.hpp>
#include <zdg/kernel/io/ply_read.hpp>
#include <zdg/kernel/io/volume_io.hpp>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>

namespace zdg {
namespace {

struct Files {
  std::filesystem::path dir = test::scratch_dir("voxelize");
  ~Files() { std::filesystem::remove_all(dir); }
  std::string operator()(const std::string& name) const {
    std::string q(1, '\'');
    q.append((dir / name).string());
    q.push_back('\'');
    return q;
  }
  std::string path(const std::string& name) const { return (dir / name).string(); }
  void write(const std::string& name, const std::string& bytes) const {
    std::ofstream(path(name), std::ios::binary) << bytes;
  }
};

// The tetrahedron x, y, z >= 0, x + y + z <= 1 at decimal coordinates (0.1 is not dyadic),
// faces oriented outwards.
const char* kTetrahedron = "ply\nformat ascii 1.0\nelement vertex 4\nproperty double x\n"
                           "property double y\nproperty double z\nelement face 4\n"
                           "property list uchar int vertex_indices\nend_header\n"
                           "0.1 0.1 0.1\n1.1 0.1 0.1\n0.1 1.1 0.1\n0.1 0.1 1.1\n"
                           "3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n";

TEST(VoxelizeCommands, EachModeEqualsTheLibrary) {
  Files f;
  f.write("tet.ply", kTetrahedron);
  const PolygonMesh mesh = read_ply(f.path("tet.ply")).mesh;
  for (const std::string mode : {"6", "26", "conservative", "solid"}) {
    for (const std::string ext : {".npy", ".vol", ".nii", ".vdb"}) {
      const std::string out = "out_" + mode + ext;
      const auto r = test::run_zdg("voxelize " + f("tet.ply") + " --h 0.1 --mode " + mode + " -o " +
                                   f(out) + " --json");
      ASSERT_EQ(r.status, 0) << r.err;
      const auto j = nlohmann::json::parse(r.out);
      const VoxelizationGrid g = voxel_grid_for(mesh, 0.1);
      const Image<std::uint8_t> want = voxelize(mesh, g, parse_voxelization_mode(mode), 1);
      std::int64_t count = 0;
      for (auto x : want.values()) count += x;
      EXPECT_EQ(j["mode"], mode);
      EXPECT_EQ(j["voxels"], std::to_string(count));
      EXPECT_EQ(j["dims"], nlohmann::json({g.extents[0], g.extents[1], g.extents[2]}));
      EXPECT_EQ(j["origin"][0], "-0.1"); // 0.1 (floor(0.1 / 0.1) - 2), 0.1 / 0.1 = 1
      const ScalarVolume v = read_volume(f.path(out));
      ASSERT_EQ(v.count(), want.size());
      EXPECT_EQ(v.array.shape,
                (std::vector<std::int64_t>{g.extents[2], g.extents[1], g.extents[0]}));
      for (std::int64_t i = 0; i < want.size(); ++i) ASSERT_EQ(v.value(i), want[i]) << i;
    }
  }
}

TEST(VoxelizeCommands, OriginAsGivenAndTextReport) {
  Files f;
  f.write("tet.ply", kTetrahedron);
  auto r = test::run_zdg("voxelize " + f("tet.ply") + " --h 0.25 --origin -1,-0.5,0 -o " +
                         f("a.npy") + " --json");
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["origin"], nlohmann::json({"-1", "-0.5", "0"}));
  // x up to 1.1: floor((1.1 + 1) / 0.25) + 3 = 11; y: floor(1.6 / 0.25) + 3 = 9; z: 7.
  EXPECT_EQ(j["dims"], nlohmann::json({11, 9, 7}));
  r = test::run_zdg("voxelize " + f("tet.ply") + " --h 0.25 -o " + f("a.npy"));
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("exists"), std::string::npos);
  r = test::run_zdg("voxelize " + f("tet.ply") + " --h 0.25 -o " + f("a.npy") + " --force");
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("voxels (conservative)"), std::string::npos) << r.out;
}

// An open mesh: solid refuses it (one line, exit 2), --winding takes it.
TEST(VoxelizeCommands, WindingForAnOpenMesh) {
  Files f;
  std::string open = kTetrahedron;
  open.replace(open.find("element face 4"), 14, "element face 3");
  open.erase(open.rfind("3 1 2 3\n"));
  f.write("open.ply", open);
  auto r = test::run_zdg("voxelize " + f("open.ply") + " --h 0.05 --mode solid -o " + f("a.npy"));
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("not closed"), std::string::npos) << r.err;
  r = test::run_zdg("voxelize " + f("open.ply") + " --h 0.05 --mode solid --winding 0.5 -o " +
                    f("a.npy") + " --json");
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["winding"], 0.5);
  const PolygonMesh mesh = read_ply(f.path("open.ply")).mesh;
  const Image<std::uint8_t> want = voxelize_winding(mesh, voxel_grid_for(mesh, 0.05), 0.5, 1);
  std::int64_t count = 0;
  for (auto x : want.values()) count += x;
  EXPECT_EQ(j["voxels"], std::to_string(count));
  EXPECT_GT(count, 0);
}

// A million copies of one small face inside one voxel (binary PLY): voxelized once, at once.
TEST(VoxelizeCommands, MillionFacesOnOneVoxel) {
  Files f;
  const int faces = 1000000;
  std::string ply = "ply\nformat binary_little_endian 1.0\nelement vertex 3\nproperty float x\n"
                    "property float y\nproperty float z\nelement face " +
                    std::to_string(faces) +
                    "\nproperty list uchar int vertex_indices\nend_header\n";
  const float v[9] = {0.25f, 0.25f, 0.25f, 0.5f, 0.25f, 0.25f, 0.25f, 0.5f, 0.25f};
  std::string body(sizeof v + static_cast<std::size_t>(faces) * 13, '\0');
  std::memcpy(body.data(), v, sizeof v);
  const std::int32_t idx[3] = {0, 1, 2};
  for (std::size_t k = 0; k < static_cast<std::size_t>(faces); ++k) {
    body[sizeof v + 13 * k] = 3;
    std::memcpy(body.data() + sizeof v + 13 * k + 1, idx, sizeof idx);
  }
  ply += body;
  f.write("many.ply", ply);
  const auto r =
      test::run_zdg("voxelize " + f("many.ply") + " --h 1 -o " + f("out.npy") + " --json");
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["voxels"], "1");
  EXPECT_EQ(j["faces"], faces);
}

} // namespace
} // namespace zdg
