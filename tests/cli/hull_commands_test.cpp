// zdg hull points|disc|ellipse|halfplanes|delaunay: JSON output (checked against the kernel and
// worked examples) and exit status 2 with the line number on bad input.
#include "tests/support/cli.hpp"

#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>
#include <string>

namespace {

using zdg::test::run_zdg;

// Input files of one test, in a scratch directory removed at the end of the test.
class HullCli : public ::testing::Test {
protected:
  void SetUp() override { dir_ = zdg::test::scratch_dir("hull_input"); }
  void TearDown() override { std::filesystem::remove_all(dir_); }
  std::string write_file(const std::string& name, const std::string& text) {
    auto p = dir_ / name;
    std::ofstream(p) << text;
    return p.string();
  }

private:
  std::filesystem::path dir_;
};

TEST_F(HullCli, DiscRadiusFive) {
  auto r = run_zdg("hull disc 0 0 5 --json");
  ASSERT_EQ(r.status, 0) << r.err;
  auto j = nlohmann::json::parse(r.out);
  // 12 lattice points on the circle x^2 + y^2 = 25; 81 lattice points in the disc,
  // of which 12 on the hull boundary ... Pick: area2 = 2 I + B - 2.
  ASSERT_EQ(j["vertices"].size(), 12u);
  EXPECT_EQ(j["vertices"][0], nlohmann::json({"0", "-5"}));
  EXPECT_EQ(j["vertices"][1], nlohmann::json({"3", "-4"}));
  EXPECT_EQ(j["boundary_points"], "12");
  EXPECT_EQ(j["interior_points"], "69"); // 81 points in the disc, 12 on the boundary
  EXPECT_EQ(j["area2"], "148");
}

TEST_F(HullCli, DiscWithRationalAndDecimalData) {
  auto a = run_zdg("hull disc -3/4 0.5 1000.5 --json");
  ASSERT_EQ(a.status, 0) << a.err;
  auto j = nlohmann::json::parse(a.out);
  EXPECT_GT(j["vertices"].size(), 100u);
  // Same disc written differently.
  auto b = run_zdg("hull disc -0.75 1/2 2001/2 --json");
  EXPECT_EQ(nlohmann::json::parse(b.out), j);
}

TEST_F(HullCli, EllipseAndPoints2d) {
  auto e = run_zdg("hull ellipse 0 0 3 1/2 --json");
  ASSERT_EQ(e.status, 0) << e.err;
  auto j = nlohmann::json::parse(e.out);
  EXPECT_EQ(j["vertices"], nlohmann::json::parse(R"([["-3","0"],["3","0"]])"));
  EXPECT_EQ(j["boundary_points"], "7");
  auto f = write_file("tri.txt", "0 0\n4 0\n# a comment\n\n0 3\n1 1\n2 0\n");
  auto p = run_zdg("hull points '" + f + "' --json");
  ASSERT_EQ(p.status, 0) << p.err;
  EXPECT_EQ(nlohmann::json::parse(p.out),
            nlohmann::json::parse(R"({"vertices":[["0","0"],["4","0"],["0","3"]],"area2":"12",
                                      "boundary_points":"8","interior_points":"3"})"));
}

TEST_F(HullCli, Points3dCube) {
  std::string text;
  for (int z = 0; z <= 2; ++z) {
    for (int y = 0; y <= 2; ++y) {
      for (int x = 0; x <= 2; ++x)
        text += std::to_string(x) + " " + std::to_string(y) + " " + std::to_string(z) + "\n";
    }
  }
  auto r = run_zdg("hull points '" + write_file("cube.txt", text) + "' --json");
  ASSERT_EQ(r.status, 0) << r.err;
  auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["vertices"].size(), 8u);
  EXPECT_EQ(j["facets"].size(), 6u);
  EXPECT_EQ(j["volume6"], "48");
  EXPECT_EQ(j["vertices"][0], nlohmann::json({"0", "0", "0"}));
}

TEST_F(HullCli, HugeCoordinates) {
  // Beyond int64: parsed as BigInt, computed by escalation.
  auto f =
      write_file("big.txt", "0 0\n100000000000000000000000 0\n0 100000000000000000000000\n1 1\n");
  auto r = run_zdg("hull points '" + f + "' --json");
  ASSERT_EQ(r.status, 0) << r.err;
  auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["vertices"].size(), 3u);
  EXPECT_EQ(j["area2"], "10000000000000000000000000000000000000000000000");
}

TEST_F(HullCli, HalfPlanes) {
  auto b =
      run_zdg("hull halfplanes '" + write_file("b.txt", "1 1 10\n-1 0 0\n0 -1 1/2\n") + "' --json");
  ASSERT_EQ(b.status, 0) << b.err;
  auto j = nlohmann::json::parse(b.out);
  EXPECT_EQ(j["region"], "bounded");
  EXPECT_EQ(j["vertices"], nlohmann::json::parse(R"([["0","0"],["10","0"],["0","10"]])"));
  auto u = run_zdg("hull halfplanes '" + write_file("u.txt", "1 0 3\n-1 0 0\n") + "' --json");
  ASSERT_EQ(u.status, 0);
  EXPECT_EQ(nlohmann::json::parse(u.out)["region"], "unbounded");
  auto e = run_zdg("hull halfplanes '" + write_file("e.txt", "1 0 3\n-1 0 -4\n0 1 1\n0 -1 1\n") +
                   "' --json");
  ASSERT_EQ(e.status, 0);
  EXPECT_EQ(nlohmann::json::parse(e.out)["region"], "empty");
}

// hull delaunay: the 3 x 3 grid (every unit square cocircular) has 8 triangles and 16 edges,
// 8 points on the hull; the centre's Voronoi cell is the unit square about it (4 vertices
// once each, exact halves); a duplicate is merged; a coordinate past 2^53 names its line.
TEST_F(HullCli, DelaunayOfAGridWithVoronoiCells) {
  std::string text = "# 3 x 3 grid, one duplicate\n";
  for (int y = 0; y < 3; ++y)
    for (int x = 0; x < 3; ++x) text += std::to_string(x) + " " + std::to_string(y) + "\n";
  text += "1 1\n";
  const auto f = write_file("grid.txt", text);
  auto r = run_zdg("hull delaunay " + f + " --voronoi --json");
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["points"], "10");
  EXPECT_EQ(j["vertices"].size(), 9u);
  EXPECT_EQ(j["cells"].size(), 8u);
  EXPECT_EQ(j["edges"], "16");
  EXPECT_EQ(j["hull_vertices"], "8");
  EXPECT_EQ(j["vertex_of_input"][9], j["vertex_of_input"][4]);
  const auto centre = j["vertex_of_input"][4].get<std::size_t>();
  const auto& cell = j["voronoi"][centre];
  EXPECT_TRUE(cell["bounded"].get<bool>());
  ASSERT_EQ(cell["vertices"].size(), 4u);
  for (const auto& v : cell["vertices"]) {
    for (const auto& x : v) EXPECT_TRUE(x == "1/2" || x == "3/2") << x;
  }
  r = run_zdg("hull delaunay " + f);
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("8 triangles"), std::string::npos) << r.out;
  const auto big = write_file("big.txt", "0 0\n1 0\n0 18014398509481985\n");
  r = run_zdg("hull delaunay " + big);
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("big.txt:3: coordinate 18014398509481985 is past 2^53"), std::string::npos)
      << r.err;
  const auto line = write_file("line.txt", "0 0\n1 1\n2 2\n");
  r = run_zdg("hull delaunay " + line + " --voronoi --json");
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("span 1 dimension(s) of 2"), std::string::npos) << r.err;
}

TEST_F(HullCli, BadInputExitsTwoWithTheLine) {
  auto empty = run_zdg("hull points '" + write_file("empty.txt", "") + "'");
  EXPECT_EQ(empty.status, 2);
  EXPECT_NE(empty.err.find("empty"), std::string::npos);
  auto mixed = run_zdg("hull points '" + write_file("mixed.txt", "1 2 3\n4 5 6\n7 8\n") + "'");
  EXPECT_EQ(mixed.status, 2);
  EXPECT_NE(mixed.err.find(":3:"), std::string::npos) << mixed.err;
  auto nan = run_zdg("hull points '" + write_file("nan.txt", "1 2\n3 4\n5 five\n") + "'");
  EXPECT_EQ(nan.status, 2);
  EXPECT_NE(nan.err.find(":3:"), std::string::npos) << nan.err;
  auto hp = run_zdg("hull halfplanes '" + write_file("hp.txt", "1 0 3\n1 / 2\n") + "'");
  EXPECT_EQ(hp.status, 2);
  EXPECT_NE(hp.err.find(":2:"), std::string::npos) << hp.err;
  auto neg = run_zdg("hull disc 0 0 -1");
  EXPECT_EQ(neg.status, 2);
  EXPECT_NE(neg.err.find("negative radius"), std::string::npos);
  EXPECT_EQ(run_zdg("hull disc 0 0 abc").status, 2);
  EXPECT_EQ(run_zdg("hull ellipse 0 0 0 1").status, 2);
  EXPECT_EQ(run_zdg("hull points /nonexistent/file").status, 2);
}

} // namespace
