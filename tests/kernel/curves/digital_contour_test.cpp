#include <zdg/kernel/curves/digital_contour.hpp>

#include <zdg/arith/error.hpp>

#include "tests/support/tower.hpp"

#include <gtest/gtest.h>

#include <cstdlib>
#include <set>
#include <vector>

namespace {

using zdg::Pixel;

// A finite set given by a bitmap, as a Gauss digitization.
class BitmapSet final : public zdg::GaussDigitization2 {
public:
  BitmapSet(int w, int h, std::vector<bool> bits)
      : GaussDigitization2(zdg::Box2{{0, 0}, {w - 1, h - 1}}), w_(w), bits_(std::move(bits)) {}

protected:
  bool inside(const Pixel& z) const override {
    return bits_[static_cast<std::size_t>(z.y * w_ + z.x)];
  }

private:
  int w_;
  std::vector<bool> bits_;
};

// Disc x^2 + y^2 <= r2 (integers).
class DiscSet final : public zdg::GaussDigitization2 {
public:
  explicit DiscSet(std::int64_t r2)
      : GaussDigitization2(zdg::Box2{{-1000, -1000}, {1000, 1000}}), r2_(r2) {}

protected:
  bool inside(const Pixel& z) const override { return z.x * z.x + z.y * z.y <= r2_; }

private:
  std::int64_t r2_;
};

void check_contour(const zdg::GaussDigitization2& set, const zdg::DigitalContour& c) {
  // Closed, unit 4-connected steps, set on the left of every linel.
  Pixel p = c.start;
  for (auto code : c.codes) {
    ASSERT_LT(code, 4);
    ASSERT_TRUE(set.contains(zdg::DigitalContour::inner_pixel(p, code)));
    ASSERT_FALSE(set.contains(zdg::DigitalContour::outer_pixel(p, code)));
    Pixel d = zdg::freeman_step(code);
    p = Pixel{p.x + d.x, p.y + d.y};
  }
  ASSERT_EQ(p, c.start);
}

TEST(DigitalContour, DiscContourIsClosedAndItsShoelaceAreaIsThePixelCount) {
  DiscSet disc(50 * 50 + 7);
  auto contours = zdg::digital_contours(disc, {0}, {});
  ASSERT_EQ(contours.size(), 1u);
  check_contour(disc, contours[0]);
  std::int64_t count = 0;
  for (std::int64_t x = -60; x <= 60; ++x) {
    for (std::int64_t y = -60; y <= 60; ++y) count += x * x + y * y <= 50 * 50 + 7 ? 1 : 0;
  }
  EXPECT_EQ(contours[0].twice_signed_area(), 2 * count);
  EXPECT_EQ(contours[0].pointels().size(), contours[0].size());
}

TEST(DigitalContour, InnerAndOuterPixelsOfEachFreemanCode) {
  // Pixel (0,0) has pointels (0,0), (1,0), (1,1), (0,1) counter-clockwise.
  EXPECT_EQ(zdg::DigitalContour::inner_pixel({0, 0}, 0), (Pixel{0, 0}));
  EXPECT_EQ(zdg::DigitalContour::outer_pixel({0, 0}, 0), (Pixel{0, -1}));
  EXPECT_EQ(zdg::DigitalContour::inner_pixel({1, 0}, 1), (Pixel{0, 0}));
  EXPECT_EQ(zdg::DigitalContour::inner_pixel({1, 1}, 2), (Pixel{0, 0}));
  EXPECT_EQ(zdg::DigitalContour::inner_pixel({0, 1}, 3), (Pixel{0, 0}));
  EXPECT_EQ(zdg::DigitalContour::outer_pixel({0, 1}, 3), (Pixel{-1, 0}));
}

TEST(DigitalContour, RandomBitmapsAllContoursSumToThePixelCount) {
  // Theorem: scanning every row finds every boundary (outer and holes); the signed
  // shoelace areas (outer counter-clockwise, holes clockwise) add up to the pixel count.
  zdg::test::check_property([](std::vector<bool> bits) {
    const int w = 9;
    int h = static_cast<int>(bits.size()) / w;
    RC_PRE(h >= 1);
    bits.resize(static_cast<std::size_t>(w * h));
    BitmapSet set(w, h, bits);
    std::vector<std::int64_t> rows;
    for (int y = 0; y < h; ++y) rows.push_back(y);
    auto contours = zdg::digital_contours(set, rows, {});
    std::int64_t twice = 0;
    std::set<std::pair<Pixel, int>> linels;
    for (const auto& c : contours) {
      check_contour(set, c);
      twice += c.twice_signed_area();
      Pixel p = c.start;
      for (auto code : c.codes) {
        RC_ASSERT(linels.insert({p, code}).second); // each linel on one contour, once
        Pixel d = zdg::freeman_step(code);
        p = Pixel{p.x + d.x, p.y + d.y};
      }
    }
    std::int64_t count = 0;
    for (bool b : bits) count += b ? 1 : 0;
    RC_ASSERT(twice == 2 * count);
  });
}

TEST(DigitalContour, RegressionDiagonalPixelsAreTwoComponents) {
  // 4-connectivity of the set: two pixels touching at a corner give two contours.
  BitmapSet set(2, 2, {true, false, false, true});
  auto contours = zdg::digital_contours(set, {0, 1}, {});
  ASSERT_EQ(contours.size(), 2u);
  EXPECT_EQ(contours[0].size(), 4u);
  EXPECT_EQ(contours[1].size(), 4u);
}

TEST(DigitalContour, TrackingRejectsANonBoundaryLinel) {
  DiscSet disc(25);
  EXPECT_THROW(zdg::track_contour(disc, {0, 0}, 0), zdg::InvalidArgument);
}

} // namespace
