#include <zdg/estimators/binomial_convolver.hpp>

#include <zdg/arith/error.hpp>

#include "tests/support/digital_sets.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace {

using zdg::Pixel;

using Disc = zdg::test::DiscDigitization;

TEST(BinomialConvolver, MaskOrderFollowsTheLaw) {
  EXPECT_EQ(zdg::binomial_mask_order(1.0, 1.0), 2);
  EXPECT_EQ(zdg::binomial_mask_order(0.001, 1.0), 10000);
  EXPECT_EQ(zdg::binomial_mask_order(0.01, 1.0) % 2, 0);
  EXPECT_THROW(zdg::binomial_mask_order(0.0, 1.0), zdg::InvalidArgument);
  EXPECT_EQ(zdg::binomial_mask_order(0.001, 1.0, 14.0 / 9), 46416); // 10^{14/3}, made even
  EXPECT_THROW(zdg::binomial_mask_order(0.01, 1.0, 2.5), zdg::InvalidArgument);
}

TEST(BinomialConvolver, UnitCircleTangentAndCurvature) {
  // Disc of radius 500 pixels at h = 1/500: the unit circle.
  const double h = 1.0 / 500;
  Disc disc(500 * 500);
  auto c = zdg::digital_contours(disc, {0}, {}).at(0);
  auto est = zdg::binomial_convolver(c, h, zdg::binomial_mask_order(h, 1.0));
  auto pts = c.pointels();
  double worst_angle = 0, worst_k = 0;
  for (std::size_t i = 0; i < pts.size(); ++i) {
    double x = h * (static_cast<double>(pts[i].x) - 0.5),
           y = h * (static_cast<double>(pts[i].y) - 0.5);
    double r = std::hypot(x, y);
    double tx = -y / r, ty = x / r; // counter-clockwise
    worst_angle = std::max(worst_angle,
                           std::acos(std::min(1.0, est.tangent[i].x * tx + est.tangent[i].y * ty)));
    worst_k = std::max(worst_k, std::abs(est.curvature[i] - 1.0));
  }
  EXPECT_LT(worst_angle, 0.02);
  EXPECT_LT(worst_k, 0.15);
}

TEST(BinomialConvolver, RejectsMasksWiderThanTheContour) {
  Disc disc(4);
  auto c = zdg::digital_contours(disc, {0}, {}).at(0);
  EXPECT_THROW(zdg::binomial_convolver(c, 0.5, 1000), zdg::InvalidArgument);
  EXPECT_THROW(zdg::binomial_convolver(c, 0.5, 3), zdg::InvalidArgument);
}

} // namespace
