// Slow sweeps (label "slow"): the fitted l_inf slopes of the 2D estimators over finer grid
// steps and random translations meet their proven rates (THEORY.md) on the finest levels.
#include "convergence/experiment.hpp"

#include <gtest/gtest.h>

namespace {

zdg::ExperimentResult sweep(std::vector<std::string> shapes, std::vector<std::string> ests,
                            const std::string& h, int translations, int fit_levels,
                            const char* k = nullptr) {
  zdg::ExperimentConfig c;
  c.shapes = std::move(shapes);
  c.estimators = std::move(ests);
  c.hs = zdg::parse_grid_steps(h);
  c.translations = translations;
  c.seed = 42;
  c.fit_levels = fit_levels;
  c.threads = 2;
  if (k != nullptr) c.k_text = k;
  return zdg::run_experiment(c);
}

void expect_all_linf_pass(const zdg::ExperimentResult& r) {
  for (const auto& f : r.fits) {
    if (f.norm != "linf" || !f.pass) continue;
    EXPECT_TRUE(*f.pass) << f.shape << " " << f.estimator << ": slope " << f.fit.slope
                         << " expected >= " << *f.expected << " - 0.1";
  }
  EXPECT_TRUE(r.all_pass);
}

TEST(ConvergenceSlow, IntegralInvariantCurvatureEllipseAndFlower) {
  expect_all_linf_pass(
      sweep({"ellipse:20,7", "flower:20,7,6"}, {"ii-curvature"}, "exp:30:57:3", 2, 6, "5"));
}

TEST(ConvergenceSlow, GaussAreaAndMomentsOnConvexShapes) {
  expect_all_linf_pass(sweep({"polygon:-15,-10,12,-13,17,9,-8,14", "ball:10", "ellipse:20,7"},
                             {"gauss-area", "moments"}, "exp:10:60:2", 10, 0));
}

TEST(ConvergenceSlow, BinomialConvolverTangent) {
  expect_all_linf_pass(
      sweep({"ellipse:20,7", "flower:20,7,6"}, {"bc-tangent"}, "exp:20:56:3", 3, 8, "1"));
}

} // namespace
