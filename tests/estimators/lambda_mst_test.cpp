// lambda-MST tangents: exact on digital straight lines, the weight function, convergence on
// a digitized circle.
#include <zdg/estimators/lambda_mst.hpp>

#include "tests/support/contours.hpp"
#include "tests/support/tower.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <numeric>

namespace {

using P = zdg::Point2<std::int64_t>;

// Weight: lambda(t) = 64 t^3 (1 - t)^3: zero at the ends of a segment, 1 at its middle.
TEST(LambdaMst, WeightIsTheC2Bump) {
  EXPECT_EQ(zdg::lambda_mst_weight(0.0), 0.0);
  EXPECT_EQ(zdg::lambda_mst_weight(1.0), 0.0);
  EXPECT_DOUBLE_EQ(zdg::lambda_mst_weight(0.5), 1.0);
  for (double t = 0; t <= 1; t += 0.01) {
    EXPECT_NEAR(zdg::lambda_mst_weight(t), 64 * std::pow(t * (1 - t), 3), 1e-12);
  }
}

// On a long piece of a digital straight line every maximal segment has the line's slope,
// so the tangent is exactly the line's direction away from the two ends.
TEST(LambdaMst, ExactDirectionOnDigitalStraightLines) {
  zdg::test::check_property([] {
    std::int64_t b = *rc::gen::inRange<std::int64_t>(1, 12);
    std::int64_t a = *rc::gen::inRange<std::int64_t>(0, b + 1);
    RC_PRE(std::gcd(a, b) == 1);
    std::int64_t mu = *rc::gen::inRange<std::int64_t>(-b, 1);
    // Naive line mu <= a x - b y < mu + b, one point per x, over ten periods.
    std::vector<P> pts;
    for (std::int64_t x = 0; x <= 10 * b; ++x) {
      std::int64_t y = (a * x - mu) >= 0 ? (a * x - mu) / b : -((mu - a * x + b - 1) / b);
      pts.push_back({x, y});
    }
    auto t = zdg::lambda_mst_tangents(pts, false);
    const double angle = std::atan2(double(a), double(b));
    for (std::size_t i = 2 * b; i + 2 * b < pts.size(); ++i) {
      RC_ASSERT(std::abs(std::atan2(t[i].y, t[i].x) - angle) < 1e-12);
    }
  });
}

// Digitized circle of radius r pixels (tests/support/contours.hpp): the tangent error is small
// and decreases with r (LVV 2007 observe about r^{-2/3}); the length from the tangents is
// close to 2 pi r.
TEST(LambdaMst, TangentConvergesOnDigitizedCircles) {
  double previous = 1e9, previous_len_error = 1e9;
  for (std::int64_t r : {20, 80, 320}) {
    auto pts = zdg::test::disc_contour(0, 0, r * r);
    auto t = zdg::lambda_mst_tangents(pts, true);
    double worst = 0;
    for (std::size_t i = 0; i < pts.size(); ++i) {
      // True tangent at the pointel's position h (p - 1/2): counter-clockwise unit vector.
      double x = pts[i].x - 0.5, y = pts[i].y - 0.5, n = std::hypot(x, y);
      double tx = -y / n, ty = x / n;
      worst = std::max(worst, std::acos(std::clamp(t[i].x * tx + t[i].y * ty, -1.0, 1.0)));
    }
    EXPECT_LT(worst, 0.25) << "r = " << r;
    EXPECT_LT(worst, previous) << "r = " << r;
    previous = worst;
    // Length of the contour from the tangents: close to 2 pi r.
    double len_error =
        std::abs(zdg::lambda_mst_length(pts, 1.0 / double(r)) - 2 * std::numbers::pi);
    EXPECT_LT(len_error, 0.1) << "r = " << r;
    EXPECT_LT(len_error, previous_len_error) << "r = " << r;
    previous_len_error = len_error;
  }
}

} // namespace
