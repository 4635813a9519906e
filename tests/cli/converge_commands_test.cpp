#include "tests/support/cli.hpp"
#include "tests/support/png.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <set>

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

// Issue #41: a check with nothing to check is not a pass. A box that misses the shape and an
// empty shape measure no boundary element: exit 1, "pass": false with the reason, no NaN PASS.
TEST(ConvergeCli, NoLevelToFitIsNotAPass) {
  auto r = run_zdg("converge --shape ellipse:20,7 --estimator ii-curvature --h 1,0.5,0.25 "
                   "--box 100:200 --json");
  EXPECT_EQ(r.status, 1) << r.err;
  auto j = nlohmann::json::parse(r.out);
  bool checked = false;
  for (const auto& f : j["fits"]) {
    if (f["norm"] != "linf") continue;
    checked = true;
    EXPECT_EQ(f["pass"], false) << f.dump();
    EXPECT_NE(f["reason"].get<std::string>().find("no verdict: no element measured"),
              std::string::npos)
        << f.dump();
  }
  EXPECT_TRUE(checked);
  const auto dir = zdg::test::scratch_dir("nolevel");
  auto t = run_zdg("converge --shape 'poly:x^2+y^2+1' --estimator ii-curvature --h 1,0.5,0.25 "
                   "-o " +
                   (dir / "out").string());
  EXPECT_EQ(t.status, 1) << t.err;
  EXPECT_EQ(t.out.find("PASS"), std::string::npos) << t.out;
  EXPECT_NE(t.out.find("FAIL (no verdict"), std::string::npos) << t.out;
  const auto summary = nlohmann::json::parse(zdg::test::read_file(dir / "out" / "summary.json"));
  EXPECT_EQ(summary["all_pass"], false);
  std::filesystem::remove_all(dir);
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
  EXPECT_EQ(r.out.find("page:"), std::string::npos) << r.out;
  EXPECT_FALSE(std::filesystem::exists(dir / "convergence.png"));
  EXPECT_FALSE(std::filesystem::exists(dir / "convergence.html"));
  std::filesystem::remove_all(dir);
}

// Bad input of zdg converge (issue #18 items 7, 8, 10 and the per-estimator parameters): each
// row exits with status 2 and one line on stderr, creates nothing, and leaves an existing
// output untouched. A row is flags, or a TOML file (its text) with flags.
TEST(ConvergeCli, BadInputRowsExitTwoWithOneLineAndWriteNothing) {
  struct Row {
    std::string flags, toml, expect;
  };
  const std::string base = "--shape ball:10 --estimator gauss-area --h 0.5:0.25:2";
  const std::string tbase = "shape = \"ball:10\"\nestimator = \"gauss-area\"\nh = \"0.5:0.25:2\"\n";
  const std::string deep = std::string(5000, '(') + "x" + std::string(5000, ')');
  std::string product = "(x+y+1)^64";
  for (int i = 0; i < 20; ++i) product += "*(x+y+1)^64";
  const std::vector<Row> rows = {
      // TOML values checked like the flags (item 8)
      {"", tbase + "tolerance = inf\n", "key 'tolerance'"},
      {"", tbase + "tolerance = 1e300\n", "key 'tolerance'"},
      {"", tbase + "tolerance = -3.0\n", "key 'tolerance'"},
      {"", tbase + "tolerance = nan\n", "key 'tolerance'"},
      {"", tbase + "translations = -2\n", "key 'translations'"},
      {"", tbase + "threads = 1025\n", "key 'threads'"},
      {"", tbase + "fit_levels = 1\n", "key 'fit_levels'"},
      {"", tbase + "k = 0\n", "key 'k'"},
      {"", tbase + "box = \"3:1\"\n", "key 'box'"},
      {"", tbase + "h2 = 3\n", "unknown key 'h2'"},
      {"", tbase + "tolerance = \n", "run.toml:4"},
      {base + " --tolerance inf", "", "--tolerance"},
      {base + " --tolerance 1e300", "", "--tolerance"},
      {base + " --tolerance -3", "", "--tolerance"},
      {base + " --threads 100000", "", "--threads"},
      {base + " --translations x", "", "--translations"},
      // shape parameters (item 10)
      {"--shape flower:20,7,6,1" + std::string(400, '0') + " --estimator gauss-area --h 0.5", "",
       "out of range"},
      {"--shape ball:0." + std::string(400, '0') + "1 --estimator gauss-area --h 0.5", "",
       "out of range"},
      {"--shape ball:2000000000 --estimator gauss-area --h 0.5", "", "out of range"},
      // poly: depth and degree (item 7)
      {"--shape 'poly:" + deep + "' --estimator ii-curvature --h 0.5", "", "nesting"},
      {"--shape 'poly:" + product + "' --estimator ii-curvature --h 0.5", "", "poly:"},
      {"--shape 'poly:(x+y)^40*(x-y)^40' --estimator ii-curvature --h 0.5", "", "total degree 80"},
      // per-estimator parameters
      {"--shape ball:10 --estimator bc-curvature:alpha=3 --h 0.5", "", "(0, 2]"},
      {"--shape ball:10 --estimator bc-curvature:q=3 --h 0.5", "", "no parameter 'q'"},
      {"--shape ball:10 --estimator mdss-curvature:k=3 --h 0.5", "", "it has none"},
      {"--shape ball:10 --estimator ii-curvature:k=inf --h 0.5", "", "not a finite number"},
      {"--shape ball:10 --estimator ii-curvature:k=5 --estimator ii-curvature:k=5 --h 0.5", "",
       "given twice"},
      {"", "shape = \"ball:10\"\nh = \"0.5\"\nestimators = [{name = \"ii-curvature\", k = -1}]\n",
       "run.toml:3"},
      {"--shape ball:10 --estimator ii-curvature --k 0 --h 0.5", "", "--k"},
  };
  auto dir = zdg::test::scratch_dir("converge_bad");
  // An existing output: its files must stay as they are.
  const auto existing = dir / "existing";
  std::filesystem::create_directories(existing);
  { std::ofstream(existing / "results.csv") << "old results\n"; }
  for (const auto& row : rows) {
    std::string args = "converge ";
    if (!row.toml.empty()) {
      std::ofstream(dir / "run.toml") << row.toml;
      args.append("'").append((dir / "run.toml").string()).append("' ");
    }
    args += row.flags;
    for (const auto& out : {dir / "fresh", existing}) {
      std::string full = args;
      full.append(" --quiet --no-plot --force -o '").append(out.string()).append("'");
      auto r = run_zdg(full);
      EXPECT_EQ(r.status, 2) << args << "\n" << r.err;
      EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << args << "\n" << r.err;
      EXPECT_EQ(r.err.rfind("zdg: ", 0), 0u) << r.err;
      EXPECT_NE(r.err.find(row.expect), std::string::npos) << args << "\n" << r.err;
      EXPECT_LT(r.err.size(), 400u) << r.err;
    }
    EXPECT_FALSE(std::filesystem::exists(dir / "fresh")) << args;
    EXPECT_EQ(zdg::test::read_file(existing / "results.csv"), "old results\n") << args;
    EXPECT_FALSE(std::filesystem::exists(existing / "summary.json")) << args;
  }
  std::filesystem::remove_all(dir);
}

// The CVIU 2014 comparison in one configuration: II, BC and MDSS, each with its own
// parameters, on the same shapes; every entry has its rows, fits and parameters.
TEST(ConvergeCli, PerEstimatorParametersInOneRun) {
  auto r = run_zdg("converge --shape ellipse:20,7 --estimator ii-curvature:k=5,alpha=1/3 "
                   "--estimator bc-curvature:k=1,alpha=14/9 --estimator mdss-curvature "
                   "--estimator ii-curvature:k=3 --h 0.5:0.25:3 --json --quiet");
  ASSERT_EQ(r.status == 0 || r.status == 1, true) << r.err;
  auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["runs"].size(), 12u);
  EXPECT_EQ(j["fits"].size(), 12u);
  std::set<std::string> labels;
  for (const auto& run : j["runs"]) labels.insert(run["estimator"].get<std::string>());
  EXPECT_EQ(labels,
            (std::set<std::string>{"ii-curvature:k=5,alpha=1/3", "bc-curvature:k=1,alpha=14/9",
                                   "mdss-curvature", "ii-curvature:k=3"}));
  for (const auto& run : j["runs"]) {
    if (run["estimator"] == "ii-curvature:k=3") {
      EXPECT_EQ(run["k"], 3.0);
    }
    if (run["estimator"] == "bc-curvature:k=1,alpha=14/9") {
      EXPECT_NEAR(run["alpha"], 14.0 / 9, 1e-15);
    }
  }
  for (const auto& f : j["fits"]) {
    if (f["estimator"] == "bc-curvature:k=1,alpha=14/9" && f["norm"] == "linf") {
      EXPECT_NEAR(f["expected"].get<double>(), 4.0 / 9, 1e-12);
      EXPECT_TRUE(f.contains("hypotheses"));
    }
    if (f["estimator"] == "mdss-curvature") {
      EXPECT_TRUE(f["expected"].is_null());
    }
  }
}

TEST(ConvergeCli, UnknownPaperIsAnError) {
  auto r = run_zdg("paper no-such-paper -o /tmp/zdg-never-written");
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("cviu2014-ii2d"), std::string::npos) << r.err;
}

} // namespace

TEST(ConvergeCli, ComparisonPlotHasAnErrorAndATimeRow) {
  // Two estimators on two shapes: the comparison layout, one column per shape and two rows
  // (errors, then seconds per run), against the one-estimator layout (one row, one panel).
  auto dir = zdg::test::scratch_dir("converge");
  auto two = run_zdg("converge --shape ball:10 --shape ellipse:10,6 --estimator gauss-area "
                     "--estimator dss-length --h 0.5:0.25:2 --tolerance 10 --quiet -o '" +
                     (dir / "two").string() + "'");
  ASSERT_EQ(two.status, 0) << two.err;
  auto one = run_zdg("converge --shape ball:10 --estimator gauss-area --h 0.5:0.25:2 --tolerance "
                     "10 --quiet -o '" +
                     (dir / "one").string() + "'");
  ASSERT_EQ(one.status, 0) << one.err;
  if (!std::filesystem::exists(dir / "two" / "convergence.png")) {
    GTEST_SKIP() << "no plot drawn (matplotlib missing): " << two.err;
  }
  const auto a = zdg::test::decode_png(dir / "two" / "convergence.png");
  const auto b = zdg::test::decode_png(dir / "one" / "convergence.png");
  EXPECT_GT(a.height, b.height * 3 / 2); // two rows
  EXPECT_GT(a.width, b.width * 3 / 2);   // two shape columns
  std::filesystem::remove_all(dir);
}
