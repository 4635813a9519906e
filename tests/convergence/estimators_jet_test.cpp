// The jet-fitting estimators of the registry through the driver: on sphere9 the mean errors
// of the four quantities fall from h = 1 to h = 0.5 and stay below a few percent of the
// curvature 1/9 (no proven rate on digital surfaces: a smoke test, not a slope check), the
// four share one fit, and a non-integer degree is refused.
#include <zdg/arith/error.hpp>
#include <zdg/convergence/experiment.hpp>

#include <gtest/gtest.h>

#include <cstdlib>
#include <string>
#include <vector>

namespace {

// Under the sanitizers (about 15x slower) the fine step is coarser.
const bool kSanitized = std::getenv("ZDG_SANITIZE") != nullptr;

zdg::ErrorStats run_once(const std::string& est, double h, double degree = 0) {
  auto s = zdg::parse_shape("sphere9");
  auto box = *s->bounding_box();
  zdg::RunInput in{*s, h, {0.1, -0.2, 0.05}, box, 3, 1.0 / 3.0, degree};
  return zdg::find_estimator(est).run(in);
}

TEST(JetEstimators, ErrorsFallOnTheSphere) {
  for (const char* est : {"jet-mean", "jet-k1", "jet-k2", "jet-normal"}) {
    const auto coarse = run_once(est, 1.0), fine = run_once(est, kSanitized ? 0.7071 : 0.5);
    EXPECT_LT(fine.mean, coarse.mean) << est;
    EXPECT_LT(fine.mean, 0.035) << est;
    EXPECT_GT(fine.n, coarse.n) << est;
  }
  if (!kSanitized) {
    EXPECT_LT(run_once("jet-mean", 0.5, 3).mean, 0.03);
  }
}

TEST(JetEstimators, RegistryAndBadDegree) {
  const auto& e = zdg::find_estimator("jet-mean");
  EXPECT_EQ(e.dimension, 3);
  EXPECT_EQ(e.shared_computation, "jet-3d");
  ASSERT_NE(e.parameter("degree"), nullptr);
  EXPECT_THROW(run_once("jet-mean", 1.0, 2.5), zdg::InvalidArgument);
  EXPECT_THROW(zdg::parse_estimator_spec("jet-k1:degree=7"), zdg::InvalidArgument);
}

} // namespace
