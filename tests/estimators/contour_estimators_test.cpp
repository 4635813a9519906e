#include <zdg/estimators/contour_estimators.hpp>

#include <zdg/estimators/binomial_convolver.hpp>
#include <zdg/estimators/gauss_area.hpp>
#include <zdg/estimators/ii_curvature.hpp>
#include <zdg/estimators/lambda_mst.hpp>
#include <zdg/estimators/mlp_length.hpp>

#include "tests/support/digital_sets.hpp"
#include "tests/support/tower.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>

namespace {

// The disc x^2 + y^2 <= r2 as a 2D image of side 2 r + 5 centred at (r + 2, r + 2), with a
// square hole of side 3 at its centre.
zdg::Image<std::uint8_t> disc_with_hole(std::int64_t r, std::int64_t r2) {
  const std::int64_t n = 2 * r + 5, c = r + 2;
  zdg::Image<std::uint8_t> img(zdg::Domain({n, n}, {-c, -c}));
  for (std::int64_t y = -c; y < n - c; ++y)
    for (std::int64_t x = -c; x < n - c; ++x) {
      const bool hole = std::abs(x) <= 1 && std::abs(y) <= 1;
      img[(y + c) * n + (x + c)] = x * x + y * y <= r2 && !hole ? 1 : 0;
    }
  return img;
}

// The image's estimators are the library's on the image's contours: the same numbers as
// ii_curvature on the image-set (incremental counter), binomial_convolver, lambda_mst and
// mlp_length on each contour, on several threads; gauss-area is h^2 times the pixel count.
TEST(ContourEstimators, SameNumbersAsTheEstimatorsOnEachContour) {
  const auto img = disc_with_hole(30, 900);
  const auto contours = zdg::image_contours(img, 8, 4);
  ASSERT_EQ(contours.contours.size(), 2u);
  const zdg::BinaryImageSet2 set(img);
  const double h = 0.1, R = 0.5;
  zdg::ContourEstimateRequest all{true, true, true, true, true};
  const auto e = zdg::contour_estimates(img, contours, all, h, R, 3);
  std::int64_t pixels = 0;
  for (auto v : img.values()) pixels += v != 0;
  EXPECT_DOUBLE_EQ(e.gauss_area, h * h * double(pixels));
  EXPECT_EQ(e.bc_mask_order, 26);
  for (std::size_t c = 0; c < contours.contours.size(); ++c) {
    const auto& k = contours.contours[c];
    const auto ii = zdg::ii_curvature(set, k, h, R);
    ASSERT_EQ(e.ii_curvature[c].size(), ii.size());
    for (std::size_t i = 0; i < ii.size(); ++i) EXPECT_NEAR(e.ii_curvature[c][i], ii[i], 1e-12);
    EXPECT_EQ(e.mlp_length[c], zdg::mlp_length(k, h));
    const auto lm = zdg::lambda_mst_tangents(k.pointels(), true);
    ASSERT_EQ(e.lmst_tangent[c].size(), lm.size());
    for (std::size_t i = 0; i < lm.size(); ++i) EXPECT_EQ(e.lmst_tangent[c][i], lm[i]);
  }
  // The outer contour takes the full mask; the hole (12 linels) a lowered one.
  const auto bc = zdg::binomial_convolver(contours.contours[0], h, 26);
  for (std::size_t i = 0; i < bc.tangent.size(); ++i) EXPECT_EQ(e.bc_tangent[0][i], bc.tangent[i]);
  EXPECT_EQ(e.bc_lowered, 1);
  EXPECT_EQ(e.bc_skipped, 0);
}

// On the disc of radius r pixels (h = 1/r, radius 1), the II curvature is close to 1 (mean
// within 0.05; pointwise the lattice-count noise of the digital ball dominates: measured max
// error 0.20 with R = 60 pixels, checked < 0.3) and the MLP length close to 2 pi (O(h)).
TEST(ContourEstimators, UnitDiscValues) {
  const std::int64_t r = 200;
  const std::int64_t n = 2 * r + 5, c = r + 2;
  zdg::Image<std::uint8_t> img(zdg::Domain({n, n}, {-c, -c}));
  for (std::int64_t y = -c; y < n - c; ++y)
    for (std::int64_t x = -c; x < n - c; ++x) img[(y + c) * n + (x + c)] = x * x + y * y <= r * r;
  const auto contours = zdg::image_contours(img, 4, 8);
  ASSERT_EQ(contours.contours.size(), 1u);
  const double h = 1.0 / double(r);
  const auto e = zdg::contour_estimates(img, contours, {true, false, false, true, true}, h, 0.3);
  double worst = 0, mean = 0;
  for (double k : e.ii_curvature[0]) {
    worst = std::max(worst, std::abs(k - 1));
    mean += k;
  }
  mean /= double(e.ii_curvature[0].size());
  std::printf("disc r = %d pixels, R = 0.3: mean kappa %.4f, max |kappa - 1| %.4f\n", int(r), mean,
              worst);
  EXPECT_NEAR(mean, 1.0, 0.05);
  EXPECT_LT(worst, 0.3);
  EXPECT_NEAR(e.mlp_length[0], 2 * std::numbers::pi, 0.02);
  EXPECT_NEAR(e.gauss_area, std::numbers::pi, 0.01);
}

TEST(ContourEstimators, TinyContoursAndBadArguments) {
  zdg::Image<std::uint8_t> dot(zdg::Domain({3, 3}),
                               std::vector<std::uint8_t>{0, 0, 0, 0, 1, 0, 0, 0, 0});
  const auto contours = zdg::image_contours(dot, 4, 8);
  const auto e =
      zdg::contour_estimates(dot, contours, {false, true, false, false, false}, 1.0, 2.0);
  EXPECT_EQ(e.bc_skipped, 1);
  EXPECT_TRUE(std::isnan(e.bc_tangent[0][0].x));
  EXPECT_THROW(zdg::contour_estimates(dot, contours, {true, false, false, false, false}, 1.0, 0.0),
               zdg::InvalidArgument);
  EXPECT_THROW(zdg::contour_estimates(dot, contours, {}, 0.0, 1.0), zdg::InvalidArgument);
}

} // namespace
