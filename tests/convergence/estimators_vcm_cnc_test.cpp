// The VCM normal and the corrected curvature estimators of the registry through the driver: on
// sphere1 (the unit sphere) the mean errors fall from h = 0.2 to h = 0.1 and stay small, the
// registry declares the parameters and the shared computation of the CNC family, no proven
// rate is claimed, and bad radii are refused.
#include <zdg/arith/error.hpp>
#include <zdg/convergence/experiment.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <string>

namespace {

zdg::ErrorStats run_once(const std::string& est, double h, double k = 1, double alpha = 0.5) {
  auto s = zdg::parse_shape("sphere1");
  auto box = *s->bounding_box();
  zdg::RunInput in{*s, h, {0.01, -0.02, 0.005}, box, k, alpha};
  return zdg::find_estimator(est).run(in);
}

TEST(VcmCncEstimators, ErrorsFallOnTheUnitSphere) {
  // Mean-error bounds at h = 0.1 (curvature 1); measured 0.038, 0.0078, 0.015, 0.033, 0.017.
  const std::pair<const char*, double> cases[] = {{"vcm-normal", 0.06},
                                                  {"cnc-mean", 0.02},
                                                  {"cnc-gaussian", 0.04},
                                                  {"cnc-k1", 0.06},
                                                  {"cnc-k2", 0.04}};
  for (const auto& [est, bound] : cases) {
    const auto coarse = run_once(est, 0.2), fine = run_once(est, 0.1);
    EXPECT_LT(fine.mean, coarse.mean) << est;
    EXPECT_LT(fine.mean, bound) << est;
    EXPECT_GT(fine.n, coarse.n) << est;
  }
}

TEST(VcmCncEstimators, RegistryEntries) {
  for (const char* name : {"vcm-normal", "cnc-mean", "cnc-gaussian", "cnc-k1", "cnc-k2"}) {
    const auto& e = zdg::find_estimator(name);
    EXPECT_EQ(e.dimension, 3) << name;
    ASSERT_NE(e.parameter("k"), nullptr) << name;
    ASSERT_NE(e.parameter("alpha"), nullptr) << name;
    EXPECT_EQ(e.parameter("alpha")->default_text, "1/2") << name;
    EXPECT_EQ(e.shared_computation, std::string(name).starts_with("cnc-") ? "cnc-3d" : "") << name;
    auto s = zdg::parse_shape("sphere1");
    EXPECT_FALSE(e.proven_rate(*s, {1, 0.5}).has_value()) << name;
  }
}

TEST(VcmCncEstimators, BadRadiusIsRefused) {
  // R = 1000 h^{1/2} is more than 256 h: one clear error.
  EXPECT_THROW(run_once("vcm-normal", 0.1, 1000), zdg::InvalidArgument);
  EXPECT_THROW(zdg::parse_estimator_spec("cnc-mean:alpha=2"), zdg::InvalidArgument);
}

} // namespace
