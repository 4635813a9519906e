// zdg normals (cli/points_commands.cpp): points sampled on a sphere come back, in each output
// format, with unit normals that point out (the oracle: the exact outward normal p / |p|);
// --orient none gives the same lines, each in z >= 0; --json's keys; --force.
#include <zdg/kernel/io/point_cloud_io.hpp>

#include "tests/support/cli.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <filesystem>
#include <random>
#include <string>

namespace zdg {
namespace {

namespace fs = std::filesystem;

PointCloud sphere(std::size_t n) {
  std::mt19937_64 rng(7);
  std::normal_distribution<double> g;
  PointCloud c;
  while (c.size() < n) {
    const Point3<double> v{g(rng), g(rng), g(rng)};
    const double l = std::sqrt(dot(v, v));
    if (l > 1e-3) c.points.push_back((3 / l) * v);
  }
  return c;
}

TEST(Normals, SphereNormalsPointOutInEveryFormat) {
  const fs::path dir = test::scratch_dir("normals_sphere");
  const PointCloud c = sphere(1000);
  const std::string in = (dir / "s.xyz").string();
  write_point_cloud(in, c);
  for (const char* ext : {".ply", ".xyz", ".npy"}) {
    const std::string out = (dir / (std::string("n") + ext)).string();
    const auto r = test::run_zdg("normals " + in + " -o " + out + " --threads 2 --json");
    ASSERT_EQ(r.status, 0) << r.err;
    const auto j = nlohmann::json::parse(r.out);
    EXPECT_EQ(j["points"], 1000);
    EXPECT_EQ(j["k"], 10);
    EXPECT_EQ(j["method"], "pca");
    EXPECT_EQ(j["oriented"], true);
    EXPECT_EQ(j["components"], 1);
    EXPECT_GE(j["seconds"].get<double>(), 0.0);
    const PointCloud back = read_point_cloud(out);
    ASSERT_EQ(back.size(), c.size());
    ASSERT_TRUE(back.has_normals());
    for (std::size_t i = 0; i < c.size(); ++i) {
      EXPECT_EQ(back.points[i], c.points[i]);
      EXPECT_NEAR(dot(back.normals[i], back.normals[i]), 1.0, 1e-12);
      EXPECT_GT(dot(back.normals[i], c.points[i]), 0) << "point " << i;
    }
  }
}

TEST(Normals, JetAndUnorientedAndForce) {
  const fs::path dir = test::scratch_dir("normals_options");
  const std::string in = (dir / "s.npy").string(), out = (dir / "n.ply").string();
  write_point_cloud(in, sphere(500));
  auto r = test::run_zdg("normals " + in + " -o " + out + " --method jet --k 12 --json");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(nlohmann::json::parse(r.out)["method"], "jet");
  const PointCloud jet = read_point_cloud(out);
  r = test::run_zdg("normals " + in + " -o " + out + " --orient none");
  EXPECT_EQ(r.status, 2) << "an existing output needs --force";
  r = test::run_zdg("normals " + in + " -o " + out + " --orient none --force --json");
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["oriented"], false);
  EXPECT_EQ(j["components"], 0);
  const PointCloud none = read_point_cloud(out);
  for (std::size_t i = 0; i < none.size(); ++i) {
    EXPECT_GE(none.normals[i].z, 0);
    // The same line as the oriented jet's normal, within the two estimators' difference.
    EXPECT_GT(std::abs(dot(none.normals[i], jet.normals[i])), 0.95);
    EXPECT_GT(dot(jet.normals[i], jet.points[i]), 0);
  }
  r = test::run_zdg("normals " + in + " -o " + (dir / "t.xyz").string());
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("500 points, k = 10, pca normals, oriented over the MST (1 component)"),
            std::string::npos)
      << r.out;
}

} // namespace
} // namespace zdg
