// zdg converge on 3D shapes and estimators, and zdg paper for the 3D configurations.
#include "tests/support/cli.hpp"
#include "tests/support/paths.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>
#include <map>
#include <string>

namespace {

using zdg::test::run_zdg;

TEST(Converge3dCli, SphereMeanCurvatureJson) {
  auto r = run_zdg("converge --shape sphere9 --estimator ii-mean --estimator hausdorff-rel "
                   "--h 1,0.7,0.5 --k 3 --alpha 1/3 --translations 1 --seed 3 --json --quiet");
  ASSERT_EQ(r.status, 0) << r.err;
  auto j = nlohmann::json::parse(r.out);
  ASSERT_EQ(j["runs"].size(), 6u);
  EXPECT_EQ(j["runs"][0]["shape"], "sphere9");
  EXPECT_EQ(j["runs"][0]["offset"].size(), 3u);
  for (const auto& run : j["runs"]) {
    EXPECT_GT(run["n"].get<int>(), 1000);
    if (run["estimator"] == "ii-mean") {
      EXPECT_LT(run["linf"].get<double>(), 0.3);
    } else {
      EXPECT_LE(run["linf"].get<double>(), 1.0); // hausdorff-rel
    }
  }
  ASSERT_EQ(j["fits"].size(), 6u);
  EXPECT_EQ(j["fits"][0]["estimator"], "ii-mean");
  EXPECT_NEAR(j["fits"][0]["expected"].get<double>(), 1.0 / 3, 1e-12);
  EXPECT_TRUE(j["fits"][0]["pass"].get<bool>());
  EXPECT_TRUE(j["fits"][3]["pass"].is_null()); // hausdorff-rel: no rate, no verdict
}

TEST(Converge3dCli, ListAndDimensionErrors) {
  auto list = nlohmann::json::parse(run_zdg("converge --list --json").out);
  bool goursat = false, ii_k1 = false;
  for (const auto& s : list["shapes"]) goursat = goursat || s["name"] == "goursat-hole";
  for (const auto& e : list["estimators"])
    ii_k1 = ii_k1 || (e["name"] == "ii-k1" && e["dimension"] == 3);
  EXPECT_TRUE(goursat);
  EXPECT_TRUE(ii_k1);
  auto r = run_zdg("converge --shape sphere9 --estimator ii-curvature --h 0.5 --json");
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("is 2D but shape 'sphere9' is 3D"), std::string::npos) << r.err;
  EXPECT_EQ(run_zdg("converge --shape sphere9:2 --estimator ii-mean --h 0.5 --json").status, 2);
  EXPECT_EQ(run_zdg("converge --shape goursat --estimator gauss-volume --h 0.5 --json").status, 2);
}

TEST(Converge3dCli, PapersExist) {
  for (const char* name : {"cviu2014-ii3d", "hausdorff", "reconstruction"}) {
    for (const char* file : {"config.toml", "quick.toml", "README.md"}) {
      EXPECT_TRUE(std::filesystem::exists(std::filesystem::path(zdg::test::source_dir()) /
                                          "papers" / name / file))
          << name << "/" << file;
    }
  }
}

// A samples sweep (--samples): the runs carry N (h null), the fits are against log N with
// the rate in N, results.csv gains the column `samples` and summary.json the counts.
TEST(Converge3dCli, SamplesSweepOfAReconstruction) {
  auto r = run_zdg("converge --shape sphere1 --estimator recon-hausdorff:method=hoppe "
                   "--estimator recon-betti --samples 200,800,3200 --seed 4 --json --quiet");
  ASSERT_EQ(r.status, 0) << r.err;
  auto j = nlohmann::json::parse(r.out);
  ASSERT_EQ(j["runs"].size(), 6u);
  EXPECT_EQ(j["runs"][0]["samples"], 200);
  EXPECT_TRUE(j["runs"][0]["h"].is_null());
  EXPECT_EQ(j["runs"][5]["linf"], 0.0) << "the sphere's topology from 3200 points";
  EXPECT_EQ(j["fits"][0]["variable"], "N");
  EXPECT_EQ(j["fits"][0]["samples_min"], 200);
  EXPECT_EQ(j["fits"][0]["samples_max"], 3200);
  EXPECT_EQ(j["fits"][0]["expected"].get<double>(), -0.5);
  EXPECT_LT(j["fits"][0]["slope"].get<double>(), -0.4);
  EXPECT_TRUE(j["fits"][0]["pass"].get<bool>());
  const auto dir = zdg::test::scratch_dir("converge-samples");
  auto out = run_zdg("converge --shape sphere1 --estimator recon-normal:method=imls "
                     "--samples exp:55:65:5 --quiet --no-plot -o '" +
                     (dir / "out").string() + "'");
  ASSERT_EQ(out.status, 0) << out.err;
  std::ifstream csv(dir / "out" / "results.csv");
  std::string header;
  std::getline(csv, header);
  EXPECT_EQ(header, "shape,estimator,h,translation,offset,k,alpha,linf,l2,mean,n,seconds,samples");
  std::ifstream in(dir / "out" / "summary.json");
  const auto summary = nlohmann::json::parse(in);
  EXPECT_EQ(summary["config"]["samples"], "exp:55:65:5");
  EXPECT_EQ(summary["config"]["sample_counts"], nlohmann::json({245, 403, 665}));
  std::filesystem::remove_all(dir);
}

// zdg laplacians (convergence/laplacian_comparison.hpp): the rows asked for, as JSON.
TEST(Converge3dCli, LaplaciansJson) {
  auto r = run_zdg("laplacians --json --h 0.2 --cube 14 --operator cotan --operator meanvalue");
  ASSERT_EQ(r.status, 0) << r.err;
  auto j = nlohmann::json::parse(r.out);
  ASSERT_EQ(j["operators"].size(), 2u);
  EXPECT_EQ(j["operators"][0]["operator"], "cotan");
  EXPECT_EQ(j["operators"][0]["estimator"], "lb-cotan");
  EXPECT_EQ(j["operators"][0]["asymmetry"].get<double>(), 0.0);
  EXPECT_GT(j["operators"][1]["asymmetry"].get<double>(), 1e-3); // mean value: not symmetric
  EXPECT_EQ(j["shape"], "sphere1");
  auto text = run_zdg("laplacians --h 0.2 --cube 14 --operator idt");
  ASSERT_EQ(text.status, 0) << text.err;
  EXPECT_NE(text.out.find("| idt | 416 |"), std::string::npos) << text.out;
}

// zdg paper laplacian-comparison --quick (papers/laplacian-comparison/run.py): the property
// table and the sweep merged; the intrinsic Delaunay slopes are the cotangent's (the staircase
// is already Delaunay), only the heat kernel converges; a second run without --force is refused.
TEST(Converge3dCli, PaperLaplacianComparisonQuick) {
  auto dir = zdg::test::scratch_dir("paper-laplacians");
  const std::string out = (dir / "out").string();
  auto r = run_zdg("paper laplacian-comparison --quick -o '" + out + "'");
  ASSERT_EQ(r.status, 0) << r.err << r.out;
  for (const char* f : {"table.md", "table.json", "properties.json", "results.csv", "summary.json"})
    EXPECT_TRUE(std::filesystem::exists(dir / "out" / f)) << f;
  std::ifstream in(dir / "out" / "table.json");
  const auto t = nlohmann::json::parse(in);
  ASSERT_EQ(t["rows"].size(), 7u);
  std::map<std::string, nlohmann::json> rows;
  for (const auto& row : t["rows"]) rows[row["operator"]] = row;
  for (const char* u : {"x", "x^2-y^2", "exp(z)"}) // the same errors, up to rounding
    EXPECT_NEAR(rows["idt"]["slope_linf"][u].get<double>(),
                rows["cotan"]["slope_linf"][u].get<double>(), 1e-9)
        << u;
  ASSERT_EQ(rows["heat"]["slope_linf"].size(), 3u);
  for (const auto& [op, row] : rows) {
    const double slope = row["slope_mean"]["x"].get<double>();
    if (op == "heat") {
      EXPECT_GT(slope, 0.3) << op;
    } else {
      EXPECT_LT(slope, -0.5) << op; // diverges like 1/h
    }
  }
  EXPECT_GT(rows["meanvalue"]["asymmetry"].get<double>(), 1e-3);
  auto again = run_zdg("paper laplacian-comparison --quick -o '" + out + "'");
  EXPECT_EQ(again.status, 2);
  EXPECT_NE(again.err.find("exists (use --force)"), std::string::npos) << again.err;
  std::filesystem::remove_all(dir);
}

} // namespace
