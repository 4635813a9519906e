#include <zdg/estimators/ii_curvature.hpp>

#include "tests/support/tower.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace {

using zdg::Pixel;

// Disc of radius rho (in pixels) centred at (0.3, 0.1) pixels: double test, enough here.
class Disc final : public zdg::GaussDigitization2 {
public:
  explicit Disc(double rho)
      : GaussDigitization2(zdg::Box2{{-5000, -5000}, {5000, 5000}}), rho_(rho) {}

protected:
  bool inside(const Pixel& z) const override {
    double x = static_cast<double>(z.x) - 0.3, y = static_cast<double>(z.y) - 0.1;
    return x * x + y * y <= rho_ * rho_;
  }

private:
  double rho_;
};

TEST(IICurvature, IncrementalCountEqualsDirectCount) {
  // The symmetric-difference update along any 4-connected walk keeps the exact count.
  zdg::test::check_property([](std::vector<std::uint8_t> moves, std::uint8_t r) {
    Disc disc(40);
    zdg::DigitalBallCounter counter(disc, 3.0 + (r % 12) + 0.5);
    Pixel c{38, 0};
    RC_ASSERT(counter.move_to(c) == counter.direct_count(c));
    for (auto m : moves) {
      Pixel d = zdg::freeman_step(m % 4);
      int len = 1 + (m / 4) % 3;
      c = Pixel{c.x + len * d.x, c.y + len * d.y};
      RC_ASSERT(counter.move_to(c) == counter.direct_count(c));
    }
  });
}

TEST(IICurvature, DigitalBallSize) {
  Disc disc(10);
  zdg::DigitalBallCounter counter(disc, 2.0);
  EXPECT_EQ(counter.ball_size(), 13); // |d|^2 <= 4: 1 + 4 + 4 + 4
  zdg::DigitalBallCounter unit(disc, 1.0);
  EXPECT_EQ(unit.ball_size(), 5);
}

TEST(IICurvature, CircleCurvatureIsCloseToOneOverRadius) {
  // Unit circle at h = 1/400, R = 0.5: the II estimator is within a few percent.
  const double h = 1.0 / 400;
  Disc disc(400);
  auto contours = zdg::digital_contours(disc, {0}, {});
  ASSERT_EQ(contours.size(), 1u);
  auto k = zdg::ii_curvature(disc, contours[0], h, 0.5);
  ASSERT_EQ(k.size(), contours[0].size());
  double worst = 0;
  for (double v : k) worst = std::max(worst, std::abs(v - 1.0));
  EXPECT_LT(worst, 0.1);
}

TEST(IICurvature, GreenCountsGiveTheSameCurvatures) {
  // The contour counter (complete boundary: one disc) and the incremental counter return the
  // same integers, hence bit-identical curvatures.
  const double h = 1.0 / 150;
  Disc disc(150);
  auto contours = zdg::digital_contours(disc, {0}, {});
  ASSERT_EQ(contours.size(), 1u);
  for (double radius : {0.05, 0.3, 1.7}) {
    zdg::ContourBallCounter counter(disc, contours, radius / h);
    EXPECT_EQ(zdg::ii_curvature(counter, contours[0], h, radius),
              zdg::ii_curvature(disc, contours[0], h, radius));
  }
  zdg::ContourBallCounter other(disc, contours, 3.0);
  EXPECT_THROW((void)zdg::ii_curvature(other, contours[0], h, 0.3), zdg::InvalidArgument);
}

} // namespace
