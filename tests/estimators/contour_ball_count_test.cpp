#include <zdg/estimators/contour_ball_count.hpp>

#include "tests/support/digital_sets.hpp"
#include "tests/support/tower.hpp"
#include <zdg/estimators/ii_curvature.hpp>

#include <gtest/gtest.h>

#include <cstdint>
#include <numeric>
#include <vector>

namespace {

using zdg::Pixel;

// A random pixel set in [0, w) x [0, w) placed at an offset: several components, holes and
// diagonal pinches.
class Bitmap final : public zdg::GaussDigitization2 {
public:
  Bitmap(std::int64_t w, Pixel offset, std::vector<bool> bits)
      : GaussDigitization2(
            zdg::Box2{{offset.x - 2, offset.y - 2}, {offset.x + w + 1, offset.y + w + 1}}),
        w_(w), o_(offset), bits_(std::move(bits)) {}

protected:
  bool inside(const Pixel& z) const override {
    const std::int64_t x = z.x - o_.x, y = z.y - o_.y;
    if (x < 0 || y < 0 || x >= w_ || y >= w_) return false;
    return bits_[static_cast<std::size_t>(y * w_ + x)];
  }

private:
  std::int64_t w_;
  Pixel o_;
  std::vector<bool> bits_;
};

std::int64_t brute_count(const zdg::GaussDigitization2& set, const zdg::DigitalDisc& d,
                         const Pixel& c) {
  std::int64_t n = 0;
  for (std::int64_t dy = -d.r; dy <= d.r; ++dy) {
    for (std::int64_t dx = -d.half_width(dy); dx <= d.half_width(dy); ++dx) {
      n += set.contains(Pixel{c.x + dx, c.y + dy}) ? 1 : 0;
    }
  }
  return n;
}

// Every contour of the set: scan every row of its box.
std::vector<zdg::DigitalContour> all_contours(const zdg::GaussDigitization2& set) {
  std::vector<std::int64_t> rows(static_cast<std::size_t>(set.box().hi.y - set.box().lo.y + 1));
  std::iota(rows.begin(), rows.end(), set.box().lo.y);
  return zdg::digital_contours(set, rows, {});
}

TEST(ContourBallCount, GreenFormulaEqualsBruteForceOnRandomSets) {
  // Oracle: the pixel count of D n X by enumeration, on random sets with every contour known
  // (components, holes, pinches), random centres (inside, outside, across) and radii.
  zdg::test::check_property([](std::uint8_t size, std::uint8_t density, std::int32_t ox,
                               std::int32_t oy, std::vector<std::uint16_t> queries) {
    const std::int64_t w = 4 + size % 24;
    const Pixel offset{ox % 1000000, oy % 1000000};
    std::vector<bool> bits(static_cast<std::size_t>(w * w));
    std::uint64_t state = static_cast<std::uint64_t>(size) * 7919u + density + 1;
    for (auto&& b : bits) {
      state = state * 6364136223846793005ull + 1442695040888963407ull;
      b = (state >> 33) % 100 < 25u + density % 60u;
    }
    Bitmap set(w, offset, bits);
    auto contours = all_contours(set);
    for (auto q : queries) {
      const double rho = 0.5 + (q % 97) * 0.173;
      zdg::ContourBallCounter counter(set, contours, rho);
      const Pixel c{offset.x - 3 + (q / 97) % (w + 6), offset.y - 3 + (q / 7) % (w + 6)};
      RC_ASSERT(counter.count(c) == brute_count(set, counter.disc(), c));
    }
  });
}

TEST(ContourBallCount, AlongADiscContourEqualsTheIncrementalCounter) {
  // Disc of radius 60 pixels, ball radius 17.3: every linel's inner-pixel count agrees with
  // the symmetric-difference counter of estimators/ii_curvature.hpp.
  zdg::test::DiscDigitization disc(60 * 60 + 7);
  auto contours = zdg::digital_contours(disc, {0}, {});
  ASSERT_EQ(contours.size(), 1u);
  zdg::ContourBallCounter green(disc, contours, 17.3);
  zdg::DigitalBallCounter incremental(disc, 17.3);
  Pixel p = contours[0].start;
  for (auto code : contours[0].codes) {
    Pixel in = zdg::DigitalContour::inner_pixel(p, code);
    Pixel out = zdg::DigitalContour::outer_pixel(p, code);
    ASSERT_EQ(green.count(in), incremental.move_to(in));
    ASSERT_EQ(green.count(out), brute_count(disc, green.disc(), out));
    Pixel d = zdg::freeman_step(code);
    p = Pixel{p.x + d.x, p.y + d.y};
  }
}

TEST(ContourBallCount, WholeShapeInsideTheDiscAndFarAway) {
  zdg::test::DiscDigitization disc(25);
  auto contours = zdg::digital_contours(disc, {0}, {});
  zdg::ContourBallCounter big(disc, contours, 40);
  EXPECT_EQ(big.count(Pixel{3, -2}), brute_count(disc, big.disc(), Pixel{3, -2}));
  EXPECT_EQ(big.count(Pixel{0, 0}), 81); // 1 + 4 * 20 pixels with x^2 + y^2 <= 25
  zdg::ContourBallCounter small(disc, contours, 2);
  EXPECT_EQ(small.count(Pixel{100, 100}), 0);
  EXPECT_EQ(small.count(Pixel{0, 0}), small.disc().size);
}

} // namespace
