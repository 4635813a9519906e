// zdg mesh at (cli/mesh_commands.cpp): a noisy cube mesh written as PLY comes back with AT's
// fields (unit at-n, at-v, 6 large segments, each on one side of the cube); an inpainted
// patch of a plane gets the plane's normal; --force; --json's keys.
#include <zdg/kernel/io/mesh_io.hpp>
#include <zdg/kernel/io/ply_read.hpp>

#include "tests/support/cli.hpp"
#include "tests/support/triangle_meshes.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <filesystem>
#include <map>
#include <set>
#include <string>
#include <vector>

namespace zdg {
namespace {

const std::vector<double>& field(const PolygonMesh& m, const std::string& name) {
  for (const auto& [n, v] : m.face_scalars)
    if (n == name) return v;
  static const std::vector<double> none;
  ADD_FAILURE() << "no field " << name;
  return none;
}

TEST(MeshAt, NoisyCubeGetsSixSegmentsAndUnitNormals) {
  const auto dir = test::scratch_dir("mesh_at_cube");
  auto m = test::cube_mesh(12);
  test::add_vertex_noise(m.mesh, 0.15 * 2.0 / 12, 2);
  write_ply((dir / "cube.ply").string(), m.mesh);
  const std::string out = (dir / "out.ply").string();
  const auto r = test::run_zdg("mesh at " + (dir / "cube.ply").string() + " -o " + out +
                               " --threads 2 --json");
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["input"]["faces"], 12 * 144);
  EXPECT_EQ(j["input"]["normals"], "faces");
  EXPECT_EQ(j["solver"], "conjugate-gradient");
  EXPECT_GE(j["segments"].get<int>(), 6);
  const PolygonMesh back = read_ply(out).mesh;
  ASSERT_EQ(back.face_count(), m.mesh.face_count());
  const auto &nx = field(back, "at-nx"), &ny = field(back, "at-ny"), &nz = field(back, "at-nz");
  const auto& seg = field(back, "segment");
  const auto& v = field(back, "at-v");
  ASSERT_EQ(seg.size(), m.side.size());
  std::map<int, std::set<int>> sides;
  std::map<int, int> sizes;
  for (std::size_t f = 0; f < seg.size(); ++f) {
    EXPECT_NEAR(nx[f] * nx[f] + ny[f] * ny[f] + nz[f] * nz[f], 1.0, 1e-5); // float32
    EXPECT_LE(v[f], 1.0 + 1e-6);
    sides[int(seg[f])].insert(m.side[f]);
    ++sizes[int(seg[f])];
  }
  int large = 0;
  for (const auto& [label, count] : sizes) {
    if (count < int(seg.size() / 100)) continue;
    ++large;
    EXPECT_EQ(sides[label].size(), 1u) << "segment " << label;
  }
  EXPECT_EQ(large, 6);
  // Again without --force: refused; with it: replaced.
  EXPECT_EQ(test::run_zdg("mesh at " + (dir / "cube.ply").string() + " -o " + out).status, 2);
  const auto again = test::run_zdg("mesh at " + (dir / "cube.ply").string() + " -o " + out +
                                   " --force --solver cholesky");
  EXPECT_EQ(again.status, 0) << again.err;
  std::filesystem::remove_all(dir);
}

TEST(MeshAt, InpaintedPatchOfAPlaneGetsThePlanesNormal) {
  const auto dir = test::scratch_dir("mesh_at_plane");
  auto m = test::plane_mesh(16);
  // Face normals in the file: +z, scrambled on a patch that the field "mask" marks.
  std::vector<double> mask(std::size_t(m.mesh.face_count()), 0.0);
  for (std::int64_t f = 0; f < m.mesh.face_count(); ++f) {
    const auto q = m.mesh.face(f)[0];
    const bool in = q % 17 >= 5 && q % 17 < 10 && q / 17 >= 5 && q / 17 < 10;
    mask[std::size_t(f)] = in ? 1 : 0;
    m.mesh.face_normals.push_back(in ? Point3<double>{1, 0, 0} : Point3<double>{0, 0, 1});
  }
  m.mesh.face_scalars.emplace_back("mask", mask);
  write_ply((dir / "plane.ply").string(), m.mesh);
  const std::string out = (dir / "out.ply").string();
  const auto r = test::run_zdg("mesh at " + (dir / "plane.ply").string() + " -o " + out +
                               " --inpaint mask --json");
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["inpainted"], 50);
  EXPECT_EQ(j["input"]["normals"], "file");
  EXPECT_EQ(j["segments"], 1);
  const PolygonMesh back = read_ply(out).mesh;
  const auto& nz = field(back, "at-nz");
  for (const double z : nz) EXPECT_NEAR(z, 1.0, 1e-6);
  std::filesystem::remove_all(dir);
}

} // namespace
} // namespace zdg
