#include <zdg/estimators/mdca_curvature.hpp>

#include <zdg/arith/error.hpp>
#include <zdg/convergence/estimator.hpp>
#include <zdg/convergence/fit.hpp>
#include <zdg/convergence/shape.hpp>
#include <zdg/kernel/curves/digital_contour.hpp>

#include "tests/support/predicate_contour.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <vector>

namespace {

using zdg::test::contour_of;

using zdg::Pixel;

// A digital disc is one digital circular arc (the whole contour): every linel gets the
// curvature of one separating circle, which lies between the inner and outer pixel centres,
// so 1/kappa is within one pixel of the radius; at step h, kappa scales by 1/h.
TEST(MdcaCurvature, DigitalCirclesGiveOneOverRadius) {
  for (double rho : {4.3, 10.0, 25.5, 80.2}) {
    auto c = contour_of(
        [=](const Pixel& z) {
          const double x = double(z.x) - 0.21, y = double(z.y) + 0.37;
          return x * x + y * y <= rho * rho;
        },
        static_cast<std::int64_t>(rho) + 1);
    const double h = 0.5;
    const auto k = zdg::mdca_curvature(c, h);
    ASSERT_EQ(k.size(), c.size());
    for (double v : k) {
      EXPECT_NEAR(v, k[0], 1e-12); // one arc, one circle
      EXPECT_GT(1.0 / (v * h), rho - 1.0);
      EXPECT_LT(1.0 / (v * h), rho + 1.0);
    }
  }
}

// Sign convention: convex parts positive, concave parts negative (a hole's contour runs
// clockwise, so a disc-shaped hole has negative curvature everywhere).
TEST(MdcaCurvature, SignFollowsTheOrientation) {
  auto ring = [](const Pixel& z) {
    const double r2 = double(z.x * z.x + z.y * z.y);
    return r2 <= 30.0 * 30.0 && r2 > 12.0 * 12.0;
  };
  zdg::test::PredicateSet set(ring, 34);
  auto cs = zdg::digital_contours(set, {}, {0});
  ASSERT_EQ(cs.size(), 2u);
  for (const auto& c : cs) {
    const auto k = zdg::mdca_curvature(c, 1.0);
    const bool hole = c.twice_signed_area() < 0;
    for (double v : k) {
      if (hole) {
        EXPECT_LT(v, 0);
        EXPECT_NEAR(-1.0 / v, 12.0, 1.0);
      } else {
        EXPECT_GT(v, 0);
        EXPECT_NEAR(1.0 / v, 30.0, 1.0);
      }
    }
  }
}

TEST(MdcaCurvature, BadInput) {
  zdg::DigitalContour tiny;
  tiny.start = {0, 0};
  tiny.codes = {0, 2};
  EXPECT_THROW((void)zdg::mdca_curvature(tiny, 1.0), zdg::InvalidArgument);
  auto c = contour_of([](const Pixel& z) { return z.x * z.x + z.y * z.y <= 9; }, 4);
  EXPECT_THROW((void)zdg::mdca_curvature(c, 0.0), zdg::InvalidArgument);
  EXPECT_THROW((void)zdg::mdca_curvature(c, -1.0), zdg::InvalidArgument);
}

// Multigrid behaviour through the registry entry: on the ellipse (20, 7) the l_inf and l_2
// errors decrease with h (h = 0.1 .. 0.02), with a positive fitted slope.
TEST(MdcaCurvature, ErrorDecreasesOnTheEllipse) {
  const auto& e = zdg::find_estimator("mdca-curvature");
  auto shape = zdg::parse_shape("ellipse:20,7");
  std::vector<double> hs{0.1, 0.05, 0.02}, linf, l2;
  for (double h : hs) {
    zdg::RunInput in{*shape, h, {0.013, -0.021}, {{-21, 21}, {-8, 8}}, 0, 0};
    auto s = e.run(in);
    linf.push_back(s.linf);
    l2.push_back(s.l2);
  }
  for (std::size_t i = 1; i < hs.size(); ++i) EXPECT_LT(l2[i], l2[i - 1]);
  auto fit = zdg::fit_loglog(hs, l2);
  EXPECT_GT(fit.slope, 0.2);
}

} // namespace
