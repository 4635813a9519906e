// Hulls of digitized shapes: the Gauss digitization of a disc gives the output-sensitive disc
// hull; of a ball, the hull of all its lattice points; of a non-convex shape (an annulus),
// the hull of the brute-force point list.
#include <zdg/kernel/hulls/digitized_shape_hull.hpp>

#include "tests/support/tower.hpp"
#include <zdg/kernel/hulls/convex_body_hull.hpp>

#include <vector>

namespace {

using namespace zdg;

TEST(DigitizedShapeHull, DiscDigitizationMatchesTheDiscHull) {
  test::check_property([] {
    std::int64_t q = *rc::gen::inRange<std::int64_t>(1, 6);
    std::int64_t cx = *rc::gen::inRange<std::int64_t>(-30, 30),
                 cy = *rc::gen::inRange<std::int64_t>(-30, 30);
    std::int64_t r = *rc::gen::inRange<std::int64_t>(0, 40);
    // (x - cx/q)^2 + (y - cy/q)^2 <= (r/q)^2, exactly in integers.
    auto inside = [&](std::int64_t x, std::int64_t y) {
      std::int64_t u = q * x - cx, v = q * y - cy;
      return u * u + v * v <= r * r;
    };
    auto h = digitized_shape_hull_2d_exact(Box2{{-80, -80}, {80, 80}}, inside).value;
    auto want =
        disc_hull<Int64>(Rational<Int64>(Int64(cx), Int64(q)), Rational<Int64>(Int64(cy), Int64(q)),
                         Rational<Int64>(Int64(r), Int64(q)));
    RC_ASSERT(h == want);
  });
}

TEST(DigitizedShapeHull, AnnulusHasTheHullOfItsPoints) {
  auto inside = [](std::int64_t x, std::int64_t y) {
    std::int64_t d = x * x + y * y;
    return d >= 49 && d <= 100;
  };
  std::vector<Point2<Int64>> all;
  for (int y = -12; y <= 12; ++y) {
    for (int x = -12; x <= 12; ++x) {
      if (inside(x, y)) all.push_back({x, y});
    }
  }
  EXPECT_EQ(digitized_shape_hull_2d_exact(Box2{{-12, -12}, {12, 12}}, inside).value,
            lattice_hull_2d<Int64>(std::span<const Point2<Int64>>(all)));
  EXPECT_TRUE(digitized_shape_hull_2d_exact(Box2{{0, 0}, {3, 3}}, [](std::int64_t, std::int64_t) {
                return false;
              }).value.empty());
}

TEST(DigitizedShapeHull, BallDigitizationMatchesTheHullOfAllItsPoints) {
  for (std::int64_t r : {0, 1, 3, 6}) {
    auto inside = [r](std::int64_t x, std::int64_t y, std::int64_t z) {
      return x * x + y * y + z * z <= r * r;
    };
    std::vector<Point3<Int64>> all;
    for (std::int64_t z = -r; z <= r; ++z) {
      for (std::int64_t y = -r; y <= r; ++y) {
        for (std::int64_t x = -r; x <= r; ++x) {
          if (inside(x, y, z)) all.push_back({x, y, z});
        }
      }
    }
    auto e = digitized_shape_hull_3d_exact(Box3{{-8, -8, -8}, {8, 8, 8}}, inside);
    const auto& a = e.value;
    EXPECT_EQ(e.served, IntKind::int64);
    auto b = lattice_hull_3d<Int64>(std::span<const Point3<Int64>>(all));
    ASSERT_EQ(a.vertices.size(), b.vertices.size());
    for (std::size_t i = 0; i < a.vertices.size(); ++i) {
      EXPECT_EQ(a.vertices[i].x, to_bigint(b.vertices[i].x));
      EXPECT_EQ(a.vertices[i].y, to_bigint(b.vertices[i].y));
      EXPECT_EQ(a.vertices[i].z, to_bigint(b.vertices[i].z));
    }
    EXPECT_EQ(a.facets, b.facets);
    EXPECT_EQ(a.volume6, to_bigint(b.volume6));
    EXPECT_EQ(lattice_points_in_hull_3d(a), BigInt(static_cast<std::int64_t>(all.size())));
  }
}

} // namespace
