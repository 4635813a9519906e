// The 2D picture: a digitized disc and its contour coloured by x (a signed value): decoded
// with libpng's reader, the left of the contour is blue, the right red, the object grey.
#include <zdg/kernel/render/render_contours.hpp>

#include "tests/support/cli.hpp"
#include "tests/support/png.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace zdg {
namespace {

namespace fs = std::filesystem;

using test::decode_png;

bool coloured(Rgb c) {
  return std::abs(int(c.r) - int(c.b)) > 40;
}

TEST(RenderContours, DiscWithSignedValues) {
  const auto dir = test::scratch_dir("render2d");
  // A disc of radius 12 centred at (25, 20) in a 40 x 50 image (rows y, columns x), with
  // lower bounds (-3, 5): the lattice point (x, y) is pixel (x - 5, y + 3).
  Image<std::uint8_t> img(Domain({40, 50}, {-3, 5}));
  for (std::int64_t i = 0; i < img.size(); ++i) {
    const auto p = img.domain().point(i);
    img[i] = (p[1] - 25) * (p[1] - 25) + (p[0] - 20) * (p[0] - 20) <= 144 ? 1 : 0;
  }
  ContourPolyline c;
  for (int k = 0; k < 200; ++k) {
    const double t = 2 * std::numbers::pi * k / 200;
    c.points.push_back({25 + 12.5 * std::cos(t), 20 + 12.5 * std::sin(t)});
    c.values.push_back(12.5 * std::cos(t));
  }
  ContourRenderOptions opt;
  opt.width = 500;
  opt.height = 400;
  const auto rep = render_contours_png((dir / "disc.png").string(), img, {c}, "x", opt);
  EXPECT_EQ(rep.color_map, ColorMap::coolwarm);
  EXPECT_GT(rep.pixels_per_unit, 5);
  const RgbImage pic = decode_png(dir / "disc.png");
  // The row through the disc's centre: y = 20 -> pixel row 23 of 40.
  const int ah = opt.height - (16 + opt.width / 40) - opt.width / 40;
  const int row = (16 + opt.width / 40) + static_cast<int>((ah - rep.pixels_per_unit * 40) / 2 +
                                                           23.5 * rep.pixels_per_unit);
  int left = -1, right = -1;
  for (int x = 0; x < opt.width - 180; ++x) {
    if (coloured(pic.at(x, row))) {
      if (left < 0) left = x;
      right = x;
    }
  }
  ASSERT_GT(right - left, 100);
  EXPECT_GT(pic.at(left, row).b, pic.at(left, row).r + 40);
  EXPECT_GT(pic.at(right, row).r, pic.at(right, row).b + 40);
  const Rgb inside = pic.at((left + right) / 2, row);
  EXPECT_EQ(inside, (Rgb{170, 170, 170}));
  // Errors.
  ContourPolyline bad = c;
  bad.values.pop_back();
  EXPECT_THROW(render_contours(img, {bad}, "x"), InvalidArgument);
  ContourPolyline far = c;
  far.points[3].x = 1e30;
  EXPECT_THROW(render_contours(img, {far}, "x"), InvalidArgument);
  far.points[3].x = std::nan("");
  EXPECT_THROW(render_contours(img, {far}, "x"), InvalidArgument);
  EXPECT_THROW(render_contours(Image<std::uint8_t>(Domain({2, 2, 2})), {}, ""), InvalidArgument);
  // No values: black contours, no colour bar.
  ContourPolyline plain = c;
  plain.values.clear();
  const RgbImage black = render_contours(img, {plain}, "", opt);
  int ink = 0;
  for (int x = 0; x < opt.width; ++x) {
    EXPECT_FALSE(coloured(black.at(x, row))) << x;
    ink += black.at(x, row) == Rgb{20, 20, 20} ? 1 : 0;
  }
  EXPECT_GE(ink, 4); // the frame's two sides and the contour's two crossings
  fs::remove_all(dir);
}

} // namespace
} // namespace zdg
