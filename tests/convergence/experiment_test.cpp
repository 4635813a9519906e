#include <zdg/convergence/experiment.hpp>

#include "tests/support/experiments.hpp"
#include <zdg/arith/error.hpp>
#include <zdg/convergence/theory.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <sstream>

namespace {

using zdg::test::linf_fit;

TEST(Fit, ExactPowerLawHasItsSlopeAndNoError) {
  std::vector<double> h{0.1, 0.05, 0.02, 0.01}, e;
  for (double x : h) e.push_back(3 * std::pow(x, 1.5));
  auto f = zdg::fit_loglog(h, e);
  EXPECT_NEAR(f.slope, 1.5, 1e-12);
  EXPECT_NEAR(f.stderr_slope, 0, 1e-9);
  EXPECT_EQ(f.n, 4);
  auto g = zdg::fit_loglog({0.1}, {1.0});
  EXPECT_TRUE(std::isnan(g.slope));
}

TEST(Experiment, GridStepSyntaxes) {
  auto a = zdg::parse_grid_steps("0.1:0.001:3");
  ASSERT_EQ(a.size(), 3u);
  EXPECT_NEAR(a[1], 0.01, 1e-15);
  auto b = zdg::parse_grid_steps("exp:0:87");
  ASSERT_EQ(b.size(), 88u);
  EXPECT_NEAR(b.back(), std::exp(-8.7), 1e-18);
  auto c = zdg::parse_grid_steps("1/2,0.25");
  EXPECT_EQ(c, (std::vector<double>{0.5, 0.25}));
  EXPECT_THROW(zdg::parse_grid_steps("0.1:x:3"), zdg::InvalidArgument);
  EXPECT_THROW(zdg::parse_grid_steps("0.001:0.1:3"), zdg::InvalidArgument);
  EXPECT_THROW(zdg::parse_grid_steps("-1"), zdg::InvalidArgument);
  EXPECT_THROW(zdg::parse_box("3:1"), zdg::InvalidArgument);
}

// k is one value for every shape or one per shape, in the order of the shapes.
TEST(Experiment, ParameterKPerShape) {
  EXPECT_EQ(zdg::parse_k_per_shape("5", 3), (std::vector<double>{5, 5, 5}));
  EXPECT_EQ(zdg::parse_k_per_shape("5,5,3", 3), (std::vector<double>{5, 5, 3}));
  EXPECT_EQ(zdg::parse_k_per_shape("1/2,8.9", 2), (std::vector<double>{0.5, 8.9}));
  EXPECT_THROW(zdg::parse_k_per_shape("5,3", 3), zdg::InvalidArgument);
  EXPECT_THROW(zdg::parse_k_per_shape("5,-3", 2), zdg::InvalidArgument);
  zdg::ExperimentConfig c;
  c.shapes = {"ball:10", "ellipse:20,7"};
  c.estimators = {"ii-curvature"};
  c.hs = {0.5};
  c.k_text = "3,5";
  auto r = zdg::run_experiment(c);
  ASSERT_EQ(r.runs.size(), 2u);
  for (const auto& run : r.runs) EXPECT_EQ(run.k, run.shape == "ball:10" ? 3.0 : 5.0);
  c.k_text = "3,5,7";
  EXPECT_THROW(zdg::run_experiment(c), zdg::InvalidArgument);
}

TEST(Experiment, GaussAreaOfAGridAlignedLatticePolygonIsPicksCount) {
  // Exact case: at h = 1 the Gauss count of a lattice polygon is A + B/2 + 1 (Pick).
  auto shape = zdg::parse_shape("polygon:0,0,10,0,10,7,0,7");
  const auto& est = zdg::find_estimator("gauss-area");
  zdg::RunInput in{*shape, 1.0, {0.0, 0.0}, {{-1, 11}, {-1, 8}}, 0, 0};
  auto s = est.run(in);
  EXPECT_DOUBLE_EQ(s.linf, (70 + 34 / 2 + 1) - 70.0);
  auto tri = zdg::parse_shape("polygon:0,0,12,0,0,8");
  zdg::RunInput in2{*tri, 0.5, {0.0, 0.0}, {{-1, 13}, {-1, 9}}, 0, 0};
  // At h = 1/2 the triangle is the lattice triangle (0,0), (24,0), (0,16): A = 192,
  // B = 24 + 16 + gcd(24, 16) = 48, count = 192 + 24 + 1 = 217, area 217 / 4.
  EXPECT_DOUBLE_EQ(est.run(in2).linf, 217 / 4.0 - 48);
}

TEST(Experiment, IICurvatureSlopeOnTheEllipseSmoke) {
  zdg::ExperimentConfig c;
  c.shapes = {"ellipse:20,7"};
  c.estimators = {"ii-curvature"};
  c.hs = zdg::parse_grid_steps("0.5:0.05:5");
  c.k_text = "5";
  c.threads = 2;
  auto r = zdg::run_experiment(c);
  ASSERT_EQ(r.runs.size(), 5u);
  const auto& f = linf_fit(r, "ii-curvature");
  EXPECT_NEAR(*f.expected, 1.0 / 3, 1e-12);
  EXPECT_GT(f.fit.slope, 1.0 / 3 - 0.1);
  EXPECT_TRUE(*f.pass);
  EXPECT_TRUE(r.all_pass);
  std::ostringstream csv;
  zdg::write_results_csv(r, csv);
  EXPECT_NE(csv.str().find("\"ellipse:20,7\",ii-curvature,0.5,0"), std::string::npos);
}

TEST(Experiment, MomentsAndTangentSlopesSmoke) {
  zdg::ExperimentConfig c;
  c.shapes = {"ellipse:20,7"};
  c.estimators = {"moments", "bc-tangent", "mlp-length"};
  c.hs = zdg::parse_grid_steps("0.4:0.05:4");
  c.translations = 2;
  c.seed = 3;
  auto r = zdg::run_experiment(c);
  EXPECT_EQ(r.runs.size(), 24u);
  EXPECT_GT(linf_fit(r, "mlp-length").fit.slope, 0.9);
  EXPECT_GT(linf_fit(r, "moments").fit.slope, 0.9);
  EXPECT_GT(linf_fit(r, "bc-tangent").fit.slope, 2.0 / 3 - 0.2);
}

// The estimators built on maximal segments: DSS length converges at O(h) on a convex
// polygon, the lambda-MST tangent at least at its proven h^{1/3} on the ellipse.
TEST(Experiment, MaximalSegmentEstimatorsSmoke) {
  zdg::ExperimentConfig c;
  c.shapes = {"polygon:-9,-7,10,-8,6,9,-5,6"};
  c.estimators = {"dss-length"};
  c.hs = {0.2, 0.1, 0.05, 0.025};
  c.translations = 2;
  c.seed = 7;
  c.threads = 2;
  auto r = zdg::run_experiment(c);
  EXPECT_GT(linf_fit(r, "dss-length").fit.slope, 0.8);
  ASSERT_TRUE(linf_fit(r, "dss-length").pass.has_value());
  EXPECT_TRUE(*linf_fit(r, "dss-length").pass);
  c.shapes = {"ellipse:20,7"};
  c.estimators = {"lmst-tangent", "mdss-curvature"};
  c.hs = {0.4, 0.2, 0.1, 0.05};
  auto t = zdg::run_experiment(c);
  EXPECT_GT(linf_fit(t, "lmst-tangent").fit.slope, 1.0 / 3.0 - 0.1);
  EXPECT_TRUE(linf_fit(t, "lmst-tangent").pass.value_or(false));
  // The negative control gets no verdict: theory proves no rate.
  EXPECT_FALSE(linf_fit(t, "mdss-curvature").pass.has_value());
}

TEST(Experiment, RejectsMismatchedInput) {
  zdg::ExperimentConfig c;
  c.shapes = {"ellipse:20,7"};
  c.estimators = {"no-such"};
  c.hs = {0.1};
  EXPECT_THROW(zdg::run_experiment(c), zdg::InvalidArgument);
  c.estimators = {"gauss-area"};
  c.shapes = {"poly:x^2+y^2-4"};
  EXPECT_THROW(zdg::run_experiment(c), zdg::InvalidArgument); // area unknown
}

TEST(Theory, RatesOfTheRegistry) {
  auto e = zdg::parse_shape("ellipse:20,7");
  EXPECT_NEAR(zdg::theory_rate("ii-curvature", *e, 1.0 / 3)->slope, 1.0 / 3, 1e-15);
  EXPECT_FALSE(zdg::theory_rate("ii-curvature", *e, 0.5).has_value());
  // Binomial convolver: bias h^{2-a} against noise h^{a/2} (tangent), h^{a-1} (curvature).
  EXPECT_NEAR(zdg::theory_rate("bc-curvature", *e, 14.0 / 9)->slope, 4.0 / 9, 1e-15);
  EXPECT_NEAR(zdg::theory_rate("bc-curvature", *e, 4.0 / 3)->slope, 1.0 / 3, 1e-15);
  EXPECT_NEAR(zdg::theory_rate("bc-curvature", *e, 1.5)->slope, 0.5, 1e-15);
  EXPECT_NEAR(zdg::theory_rate("bc-tangent", *e, 4.0 / 3)->slope, 2.0 / 3, 1e-15);
  EXPECT_FALSE(zdg::theory_rate("bc-curvature", *e, 1.0).has_value());
  auto p = zdg::parse_shape("polygon:0,0,1,0,0,1");
  EXPECT_EQ(zdg::theory_rate("gauss-area", *p, 0)->slope, 1.0);
  EXPECT_FALSE(zdg::theory_rate("ii-curvature", *p, 1.0 / 3).has_value());
}

} // namespace
