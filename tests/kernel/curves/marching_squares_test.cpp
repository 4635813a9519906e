#include <zdg/kernel/curves/marching_squares.hpp>

#include "tests/support/binary_images.hpp"
#include "tests/support/tower.hpp"

#include <gtest/gtest.h>
#include <rapidcheck.h>

#include <cmath>
#include <numbers>

namespace zdg {
namespace {

double value_at(const Image<double>& f, const Pixel& z) {
  const std::array<std::int64_t, 2> p{z.y, z.x};
  return f.values()[std::size_t(f.domain().index(p))];
}

// Without grey values (or a binary image at level 1/2) every vertex is its linel's midpoint,
// and the polygons keep the contours' orientation: their signed areas are the contours'
// (the shoelace of the midpoints differs from the pointels' only at the corners: checked as
// the sign) and there is one vertex per linel.
TEST(MarchingSquares, BinaryImagesGiveTheLinelMidpoints) {
  test::check_property([] {
    const auto img = test::random_binary_image(2, 12);
    const int k = *rc::gen::element(4, 8);
    const auto c = image_contours(img, k, 12 - k);
    Image<double> grey(img.domain());
    for (std::int64_t i = 0; i < img.domain().size(); ++i)
      grey.values()[std::size_t(i)] = img.values()[std::size_t(i)] != 0 ? 1.0 : 0.0;
    const GreyLevel2 level{[&](const Pixel& z) { return value_at(grey, z); }, 0.5};
    for (const GreyLevel2* g : {static_cast<const GreyLevel2*>(nullptr), &level}) {
      const auto polys = marching_squares(c, img.domain(), g);
      RC_ASSERT(polys.size() == c.contours.size());
      for (std::size_t i = 0; i < polys.size(); ++i) {
        const auto& dc = c.contours[i];
        RC_ASSERT(polys[i].vertices.size() == dc.size());
        const ContourEmbedding e{1.0};
        Pixel p = dc.start;
        for (std::size_t j = 0; j < dc.size(); ++j) {
          const auto m = e.linel_midpoint(p, dc.codes[j]);
          // Lattice coordinates: the embedding puts pointels at p - 1/2, pixels at z.
          RC_ASSERT(polys[i].vertices[j].x == m.x);
          RC_ASSERT(polys[i].vertices[j].y == m.y);
          p = Pixel{p.x + freeman_step(dc.codes[j]).x, p.y + freeman_step(dc.codes[j]).y};
        }
        RC_ASSERT((polys[i].signed_area() > 0) == (dc.twice_signed_area() > 0));
      }
    }
  });
}

// Linear interpolation is exact on affine functions: every vertex of the level line of
// f = a x + b y + c lies on it, up to rounding.
TEST(MarchingSquares, AffineFunctionsAreReproducedExactly) {
  test::check_property([] {
    const double a = *rc::gen::inRange(-20, 21) / 4.0, b = *rc::gen::inRange(-20, 21) / 4.0;
    RC_PRE(a != 0 || b != 0);
    const double c = *rc::gen::inRange(-50, 51) / 7.0;
    const Domain dom({16, 16}, {-8, -8});
    Image<double> f(dom);
    Image<std::uint8_t> mask(dom);
    const double level = 0.3;
    for (std::int64_t i = 0; i < dom.size(); ++i) {
      const auto p = dom.point(i);
      f.values()[std::size_t(i)] = a * double(p[1]) + b * double(p[0]) + c;
      mask.values()[std::size_t(i)] = f.values()[std::size_t(i)] >= level;
    }
    const auto contours = image_contours(mask, 4, 8);
    const GreyLevel2 g{[&](const Pixel& z) { return value_at(f, z); }, level};
    const double scale = std::fabs(a) + std::fabs(b) + std::fabs(c) + 1;
    for (const auto& poly : marching_squares(contours, dom, &g)) {
      for (const auto& v : poly.vertices) {
        // Vertices on the image's border edges keep t = 1/2 only when the outer pixel is
        // outside the domain; those are not on the level line.
        if (v.x <= -8 || v.x >= 7 || v.y <= -8 || v.y >= 7) continue;
        RC_ASSERT(std::fabs(a * v.x + b * v.y + c - level) <= 1e-12 * scale * 16);
      }
    }
  });
}

// Worked example: the grey disc f = R - |z| (R = 20) at level 0: the polygon's length and
// area approach the circle's (2 pi R, pi R^2) to within 0.2 %, far better than the linel
// contour (length 8R, off by 27 %).
TEST(MarchingSquares, GreyDiscLengthAndArea) {
  const double R = 20;
  const Domain dom({51, 51}, {-25, -25});
  Image<double> f(dom);
  Image<std::uint8_t> mask(dom);
  for (std::int64_t i = 0; i < dom.size(); ++i) {
    const auto p = dom.point(i);
    f.values()[std::size_t(i)] = R - std::hypot(double(p[0]) + 0.3, double(p[1]) - 0.1);
    mask.values()[std::size_t(i)] = f.values()[std::size_t(i)] >= 0;
  }
  const auto c = image_contours(mask, 4, 8);
  ASSERT_EQ(c.contours.size(), 1u);
  const GreyLevel2 g{[&](const Pixel& z) { return value_at(f, z); }, 0.0};
  const auto polys = marching_squares(c, dom, &g);
  EXPECT_NEAR(polys[0].length() / (2 * std::numbers::pi * R), 1.0, 2e-3);
  EXPECT_NEAR(polys[0].signed_area() / (std::numbers::pi * R * R), 1.0, 2e-3);
}

} // namespace
} // namespace zdg
