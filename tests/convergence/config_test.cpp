// Experiment descriptions: TOML files and flags pass one validation (issue #18 item 8: a TOML
// value is refused exactly when the flag with that value is), TOML types and syntax errors are
// one line with the file and line, estimator entries may carry their own parameters (strings
// or tables), and the example configurations of papers/ are valid.
#include "tests/support/paths.hpp"
#include <zdg/convergence/config.hpp>

#include <zdg/arith/error.hpp>

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace {

using zdg::ExperimentSettings;
using zdg::InvalidArgument;
using zdg::Setting;

std::string base() {
  return "shape = \"ball:10\"\nestimator = \"gauss-area\"\nh = \"0.5:0.25:2\"\n";
}

std::string toml_error(const std::string& text) {
  try {
    zdg::parse_experiment_config(text, "run.toml");
  } catch (const InvalidArgument& e) {
    return e.what();
  }
  return "no error";
}

std::string flag_error(const std::string& key, const std::string& value) {
  ExperimentSettings s;
  s.shapes = {{"ball:10", "--shape"}};
  s.estimators = {{"gauss-area", "--estimator"}};
  s.h = Setting{"0.5:0.25:2", "--h"};
  const Setting v{value, "--" + key};
  if (key == "tolerance") s.tolerance = v;
  if (key == "translations") s.translations = v;
  if (key == "threads") s.threads = v;
  if (key == "fit-levels") s.fit_levels = v;
  if (key == "seed") s.seed = v;
  if (key == "k") s.k = v;
  if (key == "alpha") s.alpha = v;
  if (key == "box") s.box = v;
  if (key == "h") s.h = v;
  try {
    zdg::validate_experiment_settings(s);
  } catch (const InvalidArgument& e) {
    return e.what();
  }
  return "no error";
}

TEST(ExperimentConfig, TomlKeysAndEstimatorEntries) {
  auto c = zdg::parse_experiment_config(
      "shapes = [\"ellipse:20,7\", \"flower:20,7,6\"]\n"
      "estimators = [\"ii-curvature:k=5\", {name = \"bc-curvature\", alpha = \"14/9\"},\n"
      "              \"mdss-curvature\"]\n"
      "h = \"exp:30:60:3\"\nk = 3\nalpha = \"1/3\"\ntranslations = 2\nseed = 2014\n"
      "fit_levels = 8\nthreads = 2\ntolerance = 0.25\nbox = [-30, 30]\ntitle = \"II against BC\"\n",
      "run.toml");
  EXPECT_EQ(c.shapes, (std::vector<std::string>{"ellipse:20,7", "flower:20,7,6"}));
  EXPECT_EQ(c.estimators, (std::vector<std::string>{"ii-curvature:k=5", "bc-curvature:alpha=14/9",
                                                    "mdss-curvature"}));
  EXPECT_EQ(c.hs.size(), 11u);
  EXPECT_EQ(*c.k_text, "3");
  EXPECT_EQ(*c.alpha_text, "1/3");
  EXPECT_EQ(c.translations, 2);
  EXPECT_EQ(c.seed, 2014u);
  EXPECT_EQ(c.fit_levels, 8);
  EXPECT_EQ(c.threads, 2);
  EXPECT_EQ(c.tolerance, 0.25);
  EXPECT_EQ(*c.box, (std::pair<double, double>{-30, 30}));
  EXPECT_EQ(c.title, "II against BC");
  // [[estimators]] sections are the same array of tables.
  auto t =
      zdg::parse_experiment_config(base().substr(0, base().find("estimator")) +
                                       "h = [0.5, 0.25]\n[[estimators]]\nname = \"ii-curvature\"\n"
                                       "k = 5\n[[estimators]]\nname = \"ii-curvature\"\nk = 3\n",
                                   "run.toml");
  EXPECT_EQ(t.estimators, (std::vector<std::string>{"ii-curvature:k=5", "ii-curvature:k=3"}));
  EXPECT_EQ(t.hs, (std::vector<double>{0.5, 0.25}));
}

// Issue #18 item 8: one validation for flags and TOML. Each row is refused both ways, with
// one line naming the flag or the file, line and key.
TEST(ExperimentConfig, TomlValuesAreCheckedLikeTheFlags) {
  const std::pair<const char*, const char*> rows[] = {
      {"tolerance", "inf"},  {"tolerance", "1e300"}, {"tolerance", "-3.0"},   {"tolerance", "nan"},
      {"tolerance", "11"},   {"translations", "-1"}, {"translations", "1e9"}, {"threads", "-1"},
      {"threads", "100000"}, {"fit-levels", "1"},    {"seed", "-5"},          {"k", "0"},
      {"k", "inf"},          {"alpha", "-1"},        {"alpha", "nan"},
  };
  for (const auto& [key, value] : rows) {
    const std::string f = flag_error(key, value);
    EXPECT_NE(f, "no error") << "--" << key << " " << value;
    EXPECT_NE(f.find(std::string("--") + key), std::string::npos) << f;
    std::string toml_key = key;
    if (toml_key == "fit-levels") toml_key = "fit_levels";
    const std::string t = toml_error(base() + toml_key + " = " + value + "\n");
    EXPECT_NE(t, "no error") << toml_key << " = " << value;
    EXPECT_NE(t.find("run.toml:4: key '" + toml_key + "'"), std::string::npos) << t;
    EXPECT_EQ(t.find('\n'), std::string::npos) << t;
  }
  // And the same values are accepted both ways.
  for (const auto& [key, value] : {std::pair<const char*, const char*>{"tolerance", "0"},
                                   {"tolerance", "10"},
                                   {"translations", "0"},
                                   {"threads", "2"},
                                   {"fit-levels", "0"},
                                   {"k", "5"},
                                   {"alpha", "1/3"}}) {
    EXPECT_EQ(flag_error(key, value), "no error") << key << " " << value;
    std::string toml_key = key;
    if (toml_key == "fit-levels") toml_key = "fit_levels";
    const bool quoted = std::string(value).find('/') != std::string::npos;
    EXPECT_EQ(toml_error(base() + toml_key + " = " + (quoted ? "\"" : "") + value +
                         (quoted ? "\"" : "") + "\n"),
              "no error")
        << key << " " << value;
  }
}

TEST(ExperimentConfig, TomlStructureErrorsAreOneLineWithTheLine) {
  EXPECT_NE(toml_error(base() + "tolerance = \n").find("run.toml:4"), std::string::npos);
  EXPECT_NE(toml_error(base() + "estimatr = 3\n").find("unknown key 'estimatr'"),
            std::string::npos);
  EXPECT_NE(toml_error(base() + "threads = true\n").find("must be a string or a number"),
            std::string::npos);
  EXPECT_NE(toml_error(base() + "shapes = [\"ball:3\"]\n").find("given twice"), std::string::npos);
  EXPECT_NE(toml_error("shape = []\n").find("empty array"), std::string::npos);
  EXPECT_NE(toml_error("shape = \"ball:1\"\nh = \"1\"\nestimators = [{k = 1}]\n").find("no 'name'"),
            std::string::npos);
  EXPECT_NE(toml_error("shape = \"ball:1\"\nh = \"1\"\nestimators = [{name = \"ii-curvature\", "
                       "r = 1}]\n")
                .find("unknown key 'r'"),
            std::string::npos);
  EXPECT_NE(toml_error("shape = \"ball:1\"\nestimator = \"gauss-area\"\n").find("no grid steps"),
            std::string::npos);
  // Shape and estimator errors name the file and line of the value.
  EXPECT_NE(toml_error("shape = \"ball:1\"\nh = \"1\"\nestimator = \"bc-curvature:alpha=3\"\n")
                .find("run.toml:3: key 'estimator': estimator 'bc-curvature:alpha=3'"),
            std::string::npos);
  EXPECT_NE(toml_error("estimator = \"gauss-area\"\nh = \"1\"\nshape = \"flower:20,7,1/2\"\n")
                .find("run.toml:3"),
            std::string::npos);
  EXPECT_NE(toml_error(base() + "estimators = [\"ii-curvature\"]\n").find("given twice"),
            std::string::npos);
  // Two entries with one label, and a 3D estimator on a 2D shape.
  EXPECT_NE(toml_error("shape = \"ball:1\"\nh = \"1\"\nestimators = [\"ii-curvature:k=5\", "
                       "\"ii-curvature:k=5\"]\n")
                .find("given twice"),
            std::string::npos);
  EXPECT_NE(toml_error("shape = \"ball:1\"\nh = \"1\"\nestimators = [\"ii-mean\"]\n").find("3D"),
            std::string::npos);
}

TEST(ExperimentConfig, FlagsOverrideTheFile) {
  ExperimentSettings flags;
  flags.tolerance = Setting{"2", "--tolerance"};
  flags.estimators = {{"moments", "--estimator"}};
  flags.fill_from(zdg::parse_experiment_toml(base() + "tolerance = 0.5\nseed = 9\n", "run.toml"));
  auto c = zdg::validate_experiment_settings(flags);
  EXPECT_EQ(c.tolerance, 2.0);
  EXPECT_EQ(c.seed, 9u);
  EXPECT_EQ(c.estimators, (std::vector<std::string>{"moments"}));
  EXPECT_EQ(c.shapes, (std::vector<std::string>{"ball:10"}));
}

// Every configuration shipped in papers/ is valid (the CVIU 2014 comparison of II, BC and MDSS
// in one file among them).
TEST(ExperimentConfig, PapersConfigurationsAreValid) {
  namespace fs = std::filesystem;
  int n = 0;
  for (const auto& dir : fs::directory_iterator(fs::path(zdg::test::source_dir()) / "papers")) {
    if (!dir.is_directory()) continue;
    for (const char* name : {"config.toml", "quick.toml"}) {
      const auto file = dir.path() / name;
      if (!fs::exists(file)) continue;
      std::ifstream in(file);
      std::stringstream text;
      text << in.rdbuf();
      EXPECT_NO_THROW(zdg::parse_experiment_config(text.str(), file.string())) << file;
      ++n;
    }
  }
  EXPECT_GE(n, 10);
  std::ifstream in(fs::path(zdg::test::source_dir()) / "papers/cviu2014-compare/config.toml");
  std::stringstream text;
  text << in.rdbuf();
  auto c = zdg::parse_experiment_config(text.str(), "config.toml");
  EXPECT_EQ(c.estimators.size(), 3u);
  EXPECT_EQ(c.shapes.size(), 3u);
}

} // namespace
