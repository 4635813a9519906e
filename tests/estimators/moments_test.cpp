#include <zdg/estimators/moments.hpp>

#include "tests/support/tower.hpp"
#include <zdg/estimators/gauss_area.hpp>

#include <gtest/gtest.h>

namespace {

using zdg::Pixel;

class BitmapSet final : public zdg::GaussDigitization2 {
public:
  BitmapSet(int w, int h, int x0, int y0, std::vector<bool> bits)
      : GaussDigitization2(zdg::Box2{{x0, y0}, {x0 + w - 1, y0 + h - 1}}), w_(w), x0_(x0), y0_(y0),
        bits_(std::move(bits)) {}

protected:
  bool inside(const Pixel& z) const override {
    return bits_[static_cast<std::size_t>((z.y - y0_) * w_ + (z.x - x0_))];
  }

private:
  int w_, x0_, y0_;
  std::vector<bool> bits_;
};

TEST(Moments, ContourSumsEqualBruteForcePixelSums) {
  // Faulhaber's sums along the vertical linels equal the sums over the pixels.
  zdg::test::check_property([](std::vector<bool> bits, std::int8_t ox, std::int8_t oy) {
    const int w = 8;
    int h = static_cast<int>(bits.size()) / w;
    RC_PRE(h >= 1);
    bits.resize(static_cast<std::size_t>(w * h));
    BitmapSet set(w, h, ox, oy, bits);
    std::vector<std::int64_t> rows;
    for (int y = 0; y < h; ++y) rows.push_back(oy + y);
    auto contours = zdg::digital_contours(set, rows, {});
    auto exact = zdg::digital_moments_exact(contours);
    const auto& s = exact.value;
    RC_ASSERT(exact.served == zdg::IntKind::int64);
    // Every tower type gives the same sums.
    auto s128 = zdg::digital_moments<zdg::Int128>(contours);
    auto sbig = zdg::digital_moments<zdg::BigInt>(contours);
    std::int64_t e[6] = {0, 0, 0, 0, 0, 0};
    for (int y = 0; y < h; ++y) {
      for (int x = 0; x < w; ++x) {
        if (!bits[static_cast<std::size_t>(y * w + x)]) continue;
        std::int64_t X = ox + x, Y = oy + y;
        e[0] += 1;
        e[1] += X;
        e[2] += Y;
        e[3] += X * X;
        e[4] += X * Y;
        e[5] += Y * Y;
      }
    }
    for (std::size_t i = 0; i < 6; ++i) {
      RC_ASSERT(s[i] == zdg::BigInt(e[i]));
      RC_ASSERT(zdg::to_bigint(s128[i]) == s[i]);
      RC_ASSERT(sbig[i] == s[i]);
    }
    RC_ASSERT(zdg::pixel_count(contours) == e[0]);
  });
}

} // namespace
