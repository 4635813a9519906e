// MDSS curvature: sign and order of magnitude on digitized circles, and the reason it is a
// negative control: its error does not vanish as the resolution grows.
#include <zdg/estimators/mdss_curvature.hpp>

#include "tests/support/contours.hpp"
#include <zdg/arith/error.hpp>

#include <gtest/gtest.h>

#include <cmath>

namespace {

// On a digitized disc of radius r pixels (counter-clockwise contour) the osculating circle
// through the half-tangent ends has, on average, the order of the disc's curvature 1/r: a
// DSS tolerates about one pixel of sagitta, so the three points lie flatter than the circle
// and the estimate is biased low (measured means 0.54, 0.65, 0.72 for r = 30, 120, 480).
TEST(MdssCurvature, AverageIsAboutTheCircleCurvature) {
  for (std::int64_t r : {30, 120, 480}) {
    auto pts = zdg::test::disc_contour(0, 0, r * r);
    const double h = 1.0 / double(r); // the unit circle at step h
    auto k = zdg::mdss_curvature(pts, h);
    double mean = 0;
    for (double v : k) mean += v;
    mean /= double(k.size());
    EXPECT_GT(mean, 0.4) << "r = " << r;
    EXPECT_LT(mean, 1.2) << "r = " << r;
  }
}

// Coeurjolly-Miguet-Tougne curvature is not multigrid convergent: its worst error on the unit
// circle stays large as h shrinks (the negative control of the 2D experiments).
TEST(MdssCurvature, WorstErrorDoesNotVanish) {
  double worst_fine = 0;
  auto pts = zdg::test::disc_contour(0, 0, 2000 * 2000);
  for (double v : zdg::mdss_curvature(pts, 1.0 / 2000))
    worst_fine = std::max(worst_fine, std::abs(v - 1));
  EXPECT_GT(worst_fine, 0.2);
}

TEST(MdssCurvature, RejectsBadStep) {
  auto pts = zdg::test::disc_contour(0, 0, 25);
  EXPECT_THROW(zdg::mdss_curvature(pts, -1.0), zdg::InvalidArgument);
}

} // namespace
