#include <zdg/kernel/curves/image_contours.hpp>

#include "tests/support/tower.hpp"

#include <gtest/gtest.h>

#include <set>
#include <utility>
#include <vector>

namespace {

struct Small2 {
  int nx = 0, ny = 0;
  std::vector<std::uint8_t> data;
  bool at(int x, int y) const {
    return x >= 0 && y >= 0 && x < nx && y < ny && data[std::size_t(y * nx + x)] != 0;
  }
};

rc::Gen<Small2> small_image(int max_side) {
  return rc::gen::exec([max_side] {
    Small2 v;
    v.nx = *rc::gen::inRange(1, max_side + 1);
    v.ny = *rc::gen::inRange(1, max_side + 1);
    const int density = *rc::gen::inRange(1, 10);
    v.data = *rc::gen::container<std::vector<std::uint8_t>>(
        std::size_t(v.nx * v.ny), rc::gen::map(rc::gen::inRange(0, 10), [density](int r) {
          return std::uint8_t(r < density);
        }));
    return v;
  });
}

zdg::Image<std::uint8_t> to_image(const Small2& v, std::int64_t lx = 0, std::int64_t ly = 0) {
  return zdg::Image<std::uint8_t>(zdg::Domain({v.ny, v.nx}, {ly, lx}), v.data);
}

// Oracle: k-components of the pixels where value == phase, in the box grown by one pixel
// (the grown ring belongs to the background); returns (components, components not touching
// the grown ring).
std::pair<int, int> components(const Small2& v, bool phase, int k) {
  const int W = v.nx + 2, H = v.ny + 2;
  auto val = [&](int x, int y) { return v.at(x - 1, y - 1) == phase; };
  std::vector<int> label(std::size_t(W * H), -1);
  int count = 0, bounded = 0;
  for (int y = 0; y < H; ++y)
    for (int x = 0; x < W; ++x) {
      if (!val(x, y) || label[std::size_t(y * W + x)] >= 0) continue;
      bool touches = false;
      std::vector<std::pair<int, int>> stack{{x, y}};
      label[std::size_t(y * W + x)] = count;
      while (!stack.empty()) {
        auto [a, b] = stack.back();
        stack.pop_back();
        touches = touches || a == 0 || b == 0 || a == W - 1 || b == H - 1;
        for (int dy = -1; dy <= 1; ++dy)
          for (int dx = -1; dx <= 1; ++dx) {
            if ((dx == 0 && dy == 0) || (k == 4 && dx != 0 && dy != 0)) continue;
            const int c = a + dx, d = b + dy;
            if (c < 0 || d < 0 || c >= W || d >= H || !val(c, d) ||
                label[std::size_t(d * W + c)] >= 0)
              continue;
            label[std::size_t(d * W + c)] = count;
            stack.push_back({c, d});
          }
      }
      ++count;
      bounded += touches ? 0 : 1;
    }
  return {count, bounded};
}

// Every boundary linel is on exactly one contour, with X on its left; the contours are closed;
// counterclockwise contours count the k-components of X (b0), clockwise ones the bounded
// kbar-components of the complement (b1), and the signed areas add up to the pixels.
TEST(ImageContours, ContoursCountComponentsAndHoles) {
  zdg::test::check_property([] {
    const Small2 v = *small_image(9);
    const int lx = *rc::gen::inRange(-4, 5), ly = *rc::gen::inRange(-4, 5);
    for (const auto& [k, kbar] : {std::pair{4, 8}, std::pair{8, 4}}) {
      const auto r = zdg::image_contours(to_image(v, lx, ly), k, kbar);
      std::set<std::pair<zdg::Pixel, int>> linels;
      std::int64_t area2 = 0, pixels = 0, pairs = 0;
      for (const auto& c : r.contours) {
        zdg::Pixel p = c.start;
        for (auto code : c.codes) {
          const auto in = zdg::DigitalContour::inner_pixel(p, code);
          const auto out = zdg::DigitalContour::outer_pixel(p, code);
          RC_ASSERT(v.at(int(in.x - lx), int(in.y - ly)));
          RC_ASSERT(!v.at(int(out.x - lx), int(out.y - ly)));
          RC_ASSERT(linels.insert({p, int(code)}).second);
          p = p + zdg::freeman_step(code);
        }
        RC_ASSERT(p == c.start);
        area2 += c.twice_signed_area();
      }
      for (int y = 0; y < v.ny; ++y)
        for (int x = 0; x < v.nx; ++x) {
          if (!v.at(x, y)) continue;
          ++pixels;
          pairs += !v.at(x + 1, y) + !v.at(x - 1, y) + !v.at(x, y + 1) + !v.at(x, y - 1);
        }
      RC_ASSERT(std::int64_t(linels.size()) == pairs);
      RC_ASSERT(r.linels() == pairs);
      RC_ASSERT(area2 == 2 * pixels);
      RC_ASSERT(r.b0 == components(v, true, k).first);
      RC_ASSERT(r.b1 == components(v, false, kbar).second);
    }
  });
}

// Under (4,8) the contours are those of the tracker of kernel/curves/digital_contour.hpp.
class ImageSet final : public zdg::GaussDigitization2 {
public:
  ImageSet(const Small2& v) : GaussDigitization2(zdg::Box2{{0, 0}, {v.nx - 1, v.ny - 1}}), v_(v) {}

protected:
  bool inside(const zdg::Pixel& z) const override { return v_.at(int(z.x), int(z.y)); }

private:
  const Small2& v_;
};

TEST(ImageContours, FourEightContoursAreThoseOfTrackContour) {
  zdg::test::check_property([] {
    const Small2 v = *small_image(8);
    const ImageSet set(v);
    const auto r = zdg::image_contours(to_image(v), 4, 8);
    for (const auto& c : r.contours) {
      const auto t = zdg::track_contour(set, c.start, c.codes.at(0));
      RC_ASSERT(t.codes == c.codes);
    }
  });
}

TEST(ImageContours, WorkedExamples) {
  // Two pixels touching at a corner: two contours under (4,8), one of 8 linels under (8,4).
  Small2 diag{2, 2, {1, 0, 0, 1}};
  auto r = zdg::image_contours(to_image(diag), 4, 8);
  EXPECT_EQ(r.contours.size(), 2u);
  EXPECT_EQ(r.b0, 2);
  r = zdg::image_contours(to_image(diag), 8, 4);
  ASSERT_EQ(r.contours.size(), 1u);
  EXPECT_EQ(r.contours[0].size(), 8u);
  // A ring: one outer contour (12 linels), one hole (4 linels).
  Small2 ring{3, 3, {1, 1, 1, 1, 0, 1, 1, 1, 1}};
  r = zdg::image_contours(to_image(ring), 8, 4);
  EXPECT_EQ(r.b0, 1);
  EXPECT_EQ(r.b1, 1);
  EXPECT_EQ(r.linels(), 16);
  EXPECT_THROW(zdg::image_contours(to_image(ring), 6, 26), zdg::InvalidArgument);
  EXPECT_THROW(zdg::image_contours(zdg::Image<std::uint8_t>(zdg::Domain({2, 2, 2})), 4, 8),
               zdg::InvalidArgument);
}

} // namespace
