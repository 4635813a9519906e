#include "tests/support/cli.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>

namespace {

using zdg::test::run_zdg;

TEST(ConvergeCli, ListNamesShapesAndEstimators) {
  auto r = run_zdg("converge --list");
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("ellipse:A,B[,THETA]"), std::string::npos);
  EXPECT_NE(r.out.find("ii-curvature"), std::string::npos);
  auto j = nlohmann::json::parse(run_zdg("converge --list --json").out);
  EXPECT_FALSE(j["shapes"].empty());
  EXPECT_EQ(j["estimators"][0]["dimension"], 2);
}

TEST(ConvergeCli, BadInputExitsWithStatusTwoAndOneLine) {
  auto r = run_zdg("converge --shape ellipse:20 --estimator ii-curvature --h 0.5 --json");
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("zdg: shape 'ellipse:20'"), std::string::npos) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1);
  EXPECT_EQ(run_zdg("converge --shape ball:1 --estimator nope --h 0.5 --json").status, 2);
  EXPECT_EQ(run_zdg("converge --shape ball:1 --estimator gauss-area --h 0.5:x:2 --json").status, 2);
  EXPECT_EQ(run_zdg("converge --shape ball:1 --estimator gauss-area --h 0.5").status, 2); // no -o
  EXPECT_EQ(
      run_zdg("converge --shape 'poly:x^2+y^^2' --estimator ii-curvature --h 0.5 --json").status,
      2);
}

TEST(ConvergeCli, JsonRunsAndFits) {
  auto r = run_zdg("converge --shape ellipse:20,7 --estimator ii-curvature --h 0.5:0.1:3 --k 5 "
                   "--alpha 1/3 --translations 2 --seed 1 --json --quiet");
  ASSERT_EQ(r.status, 0) << r.err;
  auto j = nlohmann::json::parse(r.out);
  ASSERT_EQ(j["runs"].size(), 6u);
  for (const char* key :
       {"shape", "estimator", "h", "translation", "linf", "l2", "mean", "n", "seconds"}) {
    EXPECT_TRUE(j["runs"][0].contains(key)) << key;
  }
  ASSERT_EQ(j["fits"].size(), 3u);
  EXPECT_EQ(j["fits"][0]["norm"], "linf");
  EXPECT_TRUE(j["fits"][0]["pass"].get<bool>());
  for (const char* key : {"shape", "estimator", "norm", "slope", "stderr", "expected", "pass"}) {
    EXPECT_TRUE(j["fits"][0].contains(key)) << key;
  }
}

TEST(ConvergeCli, FailedTheoryCheckExitsWithStatusOne) {
  // The binomial curvature on the six-petal flower at coarse steps is far from its rate.
  auto r = run_zdg("converge --shape flower:20,7,6 --estimator bc-curvature --h 1:0.2:5 --json");
  EXPECT_EQ(r.status, 1) << r.err;
  auto j = nlohmann::json::parse(r.out);
  EXPECT_FALSE(j["fits"][0]["pass"].get<bool>());
}

TEST(ConvergeCli, TomlConfigWritesResultsAndRefusesToOverwrite) {
  auto dir = zdg::test::scratch_dir("converge");
  {
    std::ofstream f(dir / "run.toml");
    f << "shape = [\"ball:10\", \"ellipse:20,7\"]\nestimator = \"moments\"\nh = \"0.5:0.1:3\"\n"
         "translations = 1\nseed = 5\ntolerance = 2.0\n";
  }
  auto out = dir / "out";
  auto r =
      run_zdg("converge '" + (dir / "run.toml").string() + "' -o '" + out.string() + "' --no-plot");
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_TRUE(std::filesystem::exists(out / "results.csv"));
  auto summary = nlohmann::json::parse(zdg::test::read_file(out / "summary.json"));
  EXPECT_EQ(summary["config"]["seed"], 5);
  EXPECT_TRUE(summary["provenance"].contains("commit"));
  EXPECT_TRUE(summary["provenance"].contains("compiler"));
  std::string csv = zdg::test::read_file(out / "results.csv");
  EXPECT_EQ(std::count(csv.begin(), csv.end(), '\n'), 1 + 2 * 3);
  // Existing results are not overwritten without --force.
  auto again =
      run_zdg("converge '" + (dir / "run.toml").string() + "' -o '" + out.string() + "' --no-plot");
  EXPECT_EQ(again.status, 2);
  EXPECT_NE(again.err.find("--force"), std::string::npos);
  // Unknown keys are errors.
  {
    std::ofstream f(dir / "bad.toml");
    f << "shape = \"ball:1\"\nestimatr = \"moments\"\n";
  }
  auto bad = run_zdg("converge '" + (dir / "bad.toml").string() + "' --json");
  EXPECT_EQ(bad.status, 2);
  EXPECT_NE(bad.err.find("estimatr"), std::string::npos);
  std::filesystem::remove_all(dir);
}

TEST(ConvergeCli, NoPlotNamesNoPlotFile) {
  auto dir = zdg::test::scratch_dir("converge");
  auto r = run_zdg(
      "converge --shape ball:10 --estimator gauss-area --h 0.5:0.25:2 --tolerance 10 --quiet -o '" +
      dir.string() + "' --no-plot");
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("results.csv"), std::string::npos) << r.out;
  EXPECT_EQ(r.out.find("convergence.png"), std::string::npos) << r.out;
  EXPECT_EQ(r.out.find("plot:"), std::string::npos) << r.out;
  EXPECT_FALSE(std::filesystem::exists(dir / "convergence.png"));
  std::filesystem::remove_all(dir);
}

TEST(ConvergeCli, UnknownPaperIsAnError) {
  auto r = run_zdg("paper no-such-paper -o /tmp/zdg-never-written");
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("cviu2014-ii2d"), std::string::npos) << r.err;
}

} // namespace
