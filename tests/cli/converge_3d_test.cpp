// zdg converge on 3D shapes and estimators, and zdg paper for the 3D configurations.
#include "tests/support/cli.hpp"
#include "tests/support/paths.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <filesystem>

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
  for (const char* name : {"cviu2014-ii3d", "hausdorff"}) {
    for (const char* file : {"config.toml", "quick.toml", "README.md"}) {
      EXPECT_TRUE(std::filesystem::exists(std::filesystem::path(zdg::test::source_dir()) /
                                          "papers" / name / file))
          << name << "/" << file;
    }
  }
}

} // namespace
