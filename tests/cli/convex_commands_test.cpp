// zdg convex check|envelope: the JSON form (verdicts and witnesses of worked examples, checked
// against the definition: the witness cell has no vertex in the set), coordinates past 64 bits,
// the envelope file read back and checked fully convex by the command itself.
#include "tests/support/cli.hpp"

#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>
#include <string>

namespace {

using zdg::test::run_zdg;

class ConvexCli : public ::testing::Test {
protected:
  void SetUp() override { dir_ = zdg::test::scratch_dir("convex_input"); }
  void TearDown() override { std::filesystem::remove_all(dir_); }
  std::string path(const std::string& name) const { return (dir_ / name).string(); }
  std::string write_file(const std::string& name, const std::string& text) {
    std::ofstream(dir_ / name) << text;
    return path(name);
  }

private:
  std::filesystem::path dir_;
};

TEST_F(ConvexCli, KnightMoveIsHConvexButNotFullyConvex) {
  const auto in = write_file("knight.txt", "# two points\n0 0\n2 1\n2 1\n");
  auto r = run_zdg("convex check " + in + " --json");
  ASSERT_EQ(r.status, 0) << r.err;
  auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["convex"], false);
  EXPECT_EQ(j["definition"], "full");
  EXPECT_EQ(j["dimension"], 2);
  EXPECT_EQ(j["points"], 2);
  // The segment crosses the edge {1} x (0,1) at (1, 1/2): Khalimsky (2, 1).
  EXPECT_EQ(j["witness"]["dimension"], 1);
  EXPECT_EQ(j["witness"]["khalimsky"], nlohmann::json({"2", "1"}));
  EXPECT_EQ(j["witness"]["vertices"], nlohmann::json::parse(R"([["1", "0"], ["1", "1"]])"));

  r = run_zdg("convex check " + in + " --definition hull --json");
  ASSERT_EQ(r.status, 0) << r.err;
  j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["convex"], true);
  EXPECT_FALSE(j.contains("witness"));

  r = run_zdg("convex check " + in);
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("not fully convex: the 1-cell {1} x (0, 1)"), std::string::npos) << r.out;
}

TEST_F(ConvexCli, HoleIsTheHullWitness) {
  const auto in = write_file("ring.txt", "0 0\n1 0\n2 0\n0 1\n2 1\n0 2\n1 2\n2 2\n");
  for (const char* def : {"hull", "full"}) {
    auto r = run_zdg("convex check " + in + " --json --definition " + def);
    ASSERT_EQ(r.status, 0) << r.err;
    auto j = nlohmann::json::parse(r.out);
    EXPECT_EQ(j["convex"], false) << def;
    EXPECT_EQ(j["witness"]["dimension"], 0) << def;
    EXPECT_EQ(j["witness"]["point"], nlohmann::json({"1", "1"})) << def;
  }
}

TEST_F(ConvexCli, ThreeDimensionalAndPast64Bits) {
  // The unit cube translated by about 10^30: fully convex, computed past int64.
  std::string cube;
  const std::string big = "1000000000000000000000000000000";
  for (int k = 0; k < 8; ++k) {
    cube += std::to_string(k & 1) + " " + std::to_string((k >> 1) & 1) + " " + big +
            ((k >> 2) & 1 ? "1" : "0") + "\n";
  }
  auto r = run_zdg("convex check " + write_file("cube.txt", cube) + " --json");
  ASSERT_EQ(r.status, 0) << r.err;
  auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["convex"], true);
  EXPECT_EQ(j["dimension"], 3);
  EXPECT_EQ(j["points"], 8);
  EXPECT_NE(j["integer_type"], "int64");
}

TEST_F(ConvexCli, EnvelopeIsFullyConvexAndRefusesToOverwrite) {
  const auto in = write_file("knight.txt", "0 0\n2 1\n");
  const auto out = path("env.txt");
  auto r = run_zdg("convex envelope " + in + " -o " + out + " --json");
  ASSERT_EQ(r.status, 0) << r.err;
  auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["points"], 4);
  EXPECT_EQ(j["input_points"], 2);
  EXPECT_EQ(j["iterations"], 1);
  const std::string text = zdg::test::read_file(out);
  EXPECT_NE(text.find("0 0\n1 0\n1 1\n2 1\n"), std::string::npos) << text;
  r = run_zdg("convex check " + out + " --json");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(nlohmann::json::parse(r.out)["convex"], true);

  r = run_zdg("convex envelope " + in + " -o " + out);
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("exists"), std::string::npos) << r.err;
  r = run_zdg("convex envelope " + in + " -o " + out + " --force");
  EXPECT_EQ(r.status, 0) << r.err;
}

// zdg serve "convex check" answers what the command line prints.
TEST_F(ConvexCli, ServeAnswersWhatTheCommandLinePrints) {
  const auto in = write_file("t.txt", "0 0 0\n1 1 2\n");
  const auto c = run_zdg("convex check " + in + " --json");
  ASSERT_EQ(c.status, 0) << c.err;
  const auto s = run_zdg("serve convex check", R"({"points": [[0, 0, 0], [1, 1, 2]]})"
                                               "\n");
  ASSERT_EQ(s.status, 0) << s.err;
  EXPECT_EQ(nlohmann::json::parse(s.out), nlohmann::json::parse(c.out));
  EXPECT_EQ(nlohmann::json::parse(c.out)["witness"]["khalimsky"], nlohmann::json({"1", "1", "2"}));
  const auto h =
      run_zdg("serve convex check", R"({"points": [[0, 0], [2, 1]], "definition": "hull"})"
                                    "\n");
  ASSERT_EQ(h.status, 0) << h.err;
  EXPECT_EQ(nlohmann::json::parse(h.out)["convex"], true);
}

} // namespace
