#include <zdg/estimators/mlp_length.hpp>

#include <zdg/arith/error.hpp>

#include "tests/support/digital_sets.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace {

using zdg::Pixel;

using Disc = zdg::test::DiscDigitization;

class Rect final : public zdg::GaussDigitization2 {
public:
  Rect(int w, int h) : GaussDigitization2(zdg::Box2{{0, 0}, {w - 1, h - 1}}) {}

protected:
  bool inside(const Pixel&) const override { return true; }
};

TEST(MlpLength, RectangleIsThePolygonOfItsCornerPixelCentres) {
  Rect r(7, 4);
  auto c = zdg::digital_contours(r, {0}, {}).at(0);
  auto v = zdg::minimum_length_polygon(c);
  EXPECT_EQ(v.size(), 4u);
  EXPECT_DOUBLE_EQ(zdg::mlp_length(c, 1.0), 2.0 * (6 + 3));
}

TEST(MlpLength, DigitalDiscPerimeterConvergesToTwoPiR) {
  for (std::int64_t r : {50, 400}) {
    Disc d(r * r);
    auto c = zdg::digital_contours(d, {0}, {}).at(0);
    double len = zdg::mlp_length(c, 1.0 / static_cast<double>(r));
    EXPECT_NEAR(len, 2 * std::numbers::pi, 2.0 / static_cast<double>(r)) << r;
    // The MLP is convex for a convex set: every turn is a left turn.
    auto v = zdg::minimum_length_polygon(c);
    for (std::size_t i = 0; i < v.size(); ++i) {
      const Pixel& a = v[i];
      const Pixel& b = v[(i + 1) % v.size()];
      const Pixel& e = v[(i + 2) % v.size()];
      EXPECT_GT((b.x - a.x) * (e.y - a.y) - (b.y - a.y) * (e.x - a.x), 0);
    }
  }
}

TEST(MlpLength, RejectsTinyContours) {
  zdg::DigitalContour c{{0, 0}, {0, 1}};
  EXPECT_THROW(zdg::minimum_length_polygon(c), zdg::InvalidArgument);
}

} // namespace
