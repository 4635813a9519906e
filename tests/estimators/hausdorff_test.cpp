#include <zdg/estimators/hausdorff.hpp>

#include <zdg/arith/error.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

namespace {

using zdg::Point2;
using zdg::Point3;

TEST(Hausdorff, BoundIsHalfTheDiagonalOfAPixelOrVoxel) {
  // Lachaud-Thibert 2016: sqrt(d) h / 2, the half-diagonal of a cell of side h.
  EXPECT_DOUBLE_EQ(zdg::hausdorff_bound(2, 0.5), std::sqrt(2.0) / 4);
  EXPECT_DOUBLE_EQ(zdg::hausdorff_bound(3, 2.0), std::sqrt(3.0));
  EXPECT_THROW(zdg::hausdorff_bound(4, 0.5), zdg::InvalidArgument);
  EXPECT_THROW(zdg::hausdorff_bound(3, 0), zdg::InvalidArgument);
  EXPECT_THROW(zdg::hausdorff_bound(2, NAN), zdg::InvalidArgument);
}

TEST(Hausdorff, DistancesToASphereAndACircleAreRadialGaps) {
  // Oracle: the nearest point of a sphere (circle) of radius r is on the ray from the centre,
  // at distance | |p| - r |.
  std::mt19937_64 rng(1);
  std::uniform_real_distribution<double> u(-3, 3);
  std::vector<Point3<double>> p3;
  std::vector<Point2<double>> p2;
  for (int i = 0; i < 50; ++i) {
    p3.push_back({u(rng), u(rng), u(rng) + 0.01});
    p2.push_back({u(rng), u(rng) + 0.01});
  }
  const double r = 2;
  auto d3 = zdg::projection_distances(p3, [&](Point3<double> p) {
    const double n = std::sqrt(p.x * p.x + p.y * p.y + p.z * p.z);
    return Point3<double>{r * p.x / n, r * p.y / n, r * p.z / n};
  });
  auto d2 = zdg::projection_distances(p2, [&](Point2<double> p) {
    const double n = std::hypot(p.x, p.y);
    return Point2<double>{r * p.x / n, r * p.y / n};
  });
  for (std::size_t i = 0; i < p3.size(); ++i) {
    EXPECT_NEAR(d3[i],
                std::abs(std::sqrt(p3[i].x * p3[i].x + p3[i].y * p3[i].y + p3[i].z * p3[i].z) - r),
                1e-12);
    EXPECT_NEAR(d2[i], std::abs(std::hypot(p2[i].x, p2[i].y) - r), 1e-12);
  }
  auto c = zdg::check_hausdorff_bound(d3, 3, 10.0);
  EXPECT_DOUBLE_EQ(c.max_distance, *std::max_element(d3.begin(), d3.end()));
  EXPECT_TRUE(c.holds()); // 8.7 >= any gap here (< 3.3)
  EXPECT_FALSE(zdg::check_hausdorff_bound(d3, 3, 0.01).holds());
}

TEST(Hausdorff, NotANumberNeverHolds) {
  std::vector<double> d{0.1, NAN, 0.2};
  auto c = zdg::check_hausdorff_bound(d, 2, 1.0);
  EXPECT_TRUE(std::isnan(c.max_distance));
  EXPECT_FALSE(c.holds());
}

} // namespace
