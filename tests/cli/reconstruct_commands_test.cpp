// zdg reconstruct (cli/reconstruct_commands.cpp): points sampled on a sphere, with their exact
// normals or without (PCA normals then), give one ball (Betti numbers of the solid 1, 0, 0) whose
// mesh vertices lie within a grid step of it; --html writes the viewer page; an existing output is
// kept without --force.
#include <zdg/kernel/io/point_cloud_io.hpp>

#include "tests/support/cli.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <zdg/kernel/io/ply_read.hpp>

#include <cmath>
#include <filesystem>
#include <random>
#include <string>

namespace zdg {
namespace {

namespace fs = std::filesystem;

PointCloud sphere(std::size_t n, bool normals) {
  std::mt19937_64 rng(5);
  std::normal_distribution<double> g;
  PointCloud c;
  while (c.size() < n) {
    const Point3<double> v{g(rng), g(rng), g(rng)};
    const double l = std::sqrt(dot(v, v));
    if (l < 1e-3) continue;
    c.points.push_back((2 / l) * v);
    if (normals) c.normals.push_back((1 / l) * v);
  }
  return c;
}

TEST(Reconstruct, SphereFromPointsWithAndWithoutNormals) {
  const fs::path dir = test::scratch_dir("reconstruct_sphere");
  write_point_cloud((dir / "n.ply").string(), sphere(2000, true));
  write_point_cloud((dir / "p.xyz").string(), sphere(2000, false));
  for (const char* method : {"hoppe", "winding", "imls"}) {
    for (const char* in : {"n.ply", "p.xyz"}) {
      const std::string out = (dir / (std::string(method) + "_" + in + ".ply")).string();
      const auto r = test::run_zdg("reconstruct " + (dir / in).string() + " --method " + method +
                                   " --h 0.2 -o " + out + " --threads 2 --json");
      ASSERT_EQ(r.status, 0) << r.err;
      const auto j = nlohmann::json::parse(r.out);
      EXPECT_EQ(j["method"], method);
      EXPECT_EQ(j["normals"], std::string(in) == "n.ply" ? "given" : "estimated");
      EXPECT_EQ(j["betti"], nlohmann::json({"1", "0", "0"})) << method << " " << in;
      const PlyMesh m = read_ply(out);
      EXPECT_EQ(std::to_string(m.mesh.face_count()), j["mesh"]["faces"].get<std::string>());
      for (const auto& v : m.mesh.vertices)
        EXPECT_NEAR(std::sqrt(dot(v, v)), 2.0, 0.2) << method << " " << in;
    }
  }
}

TEST(Reconstruct, ViewerPageAndExistingOutputs) {
  const fs::path dir = test::scratch_dir("reconstruct_outputs");
  write_point_cloud((dir / "n.ply").string(), sphere(800, true));
  const std::string args = "reconstruct " + (dir / "n.ply").string() + " --h 0.25 -o " +
                           (dir / "m.obj").string() + " --html " + (dir / "m.html").string() +
                           " --quiet";
  auto r = test::run_zdg(args);
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(test::read_file(dir / "m.html").find("<html"), std::string::npos);
  r = test::run_zdg(args);
  EXPECT_EQ(r.status, 2);
  r = test::run_zdg(args + " --force");
  EXPECT_EQ(r.status, 0) << r.err;
}

} // namespace
} // namespace zdg
