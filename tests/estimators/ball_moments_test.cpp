#include <zdg/estimators/ball_moments.hpp>

#include "tests/support/tower.hpp"

#include "tests/support/digital_sets.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace {

using zdg::BallMoments;
using zdg::Voxel;
using zdg::VoxelBox;

// Several runs per column: two balls, an ellipsoid shell with a hole, a sprinkle of voxels.
zdg::VoxelPredicate mixed(std::int64_t r2a, std::int64_t r2b, std::uint32_t salt) {
  const auto a = zdg::test::ball_predicate({-4, 2, -3}, r2a);
  const auto b = zdg::test::ball_predicate({5, -1, 4}, r2b);
  return [=](const Voxel& z) {
    const std::int64_t e = 4 * z.x * z.x + 9 * z.y * z.y + z.z * z.z;
    const auto hsh = std::uint32_t(z.x * 73856093) ^ std::uint32_t(z.y * 19349663) ^
                     std::uint32_t(z.z * 83492791) ^ salt;
    return a(z) || b(z) || (e >= 30 && e <= 90) || hsh % 13 == 0;
  };
}

// Theorem: the moments from the column runs equal the brute-force moments of the digital
// ball, at any centre (inside, outside, near or beyond the box faces), for any radius,
// thread count and order.
TEST(BallMoments, ColumnMomentsEqualDirectMoments) {
  zdg::test::check_property([] {
    const auto in =
        mixed(*rc::gen::inRange<std::int64_t>(0, 30), *rc::gen::inRange<std::int64_t>(0, 30),
              *rc::gen::arbitrary<std::uint32_t>());
    const VoxelBox box{{-9, -7, -10}, {8, 9, 7}};
    const auto r2 = *rc::gen::inRange<std::int64_t>(0, 50);
    const int threads = *rc::gen::inRange(0, 4);
    const bool second = *rc::gen::arbitrary<bool>();
    const auto n = *rc::gen::inRange<std::size_t>(1, 40);
    std::vector<Voxel> centres;
    for (std::size_t i = 0; i < n; ++i)
      centres.push_back({*rc::gen::inRange<std::int64_t>(-13, 13),
                         *rc::gen::inRange<std::int64_t>(-12, 13),
                         *rc::gen::inRange<std::int64_t>(-14, 12)});
    const auto m = zdg::ball_moments_by_columns(in, box, centres, r2, threads, second);
    RC_ASSERT(m.moments.size() == n);
    for (std::size_t i = 0; i < n; ++i) {
      const BallMoments d = zdg::direct_ball_moments(in, box, centres[i], r2);
      if (second) {
        RC_ASSERT(m.moments[i] == d);
      } else {
        RC_ASSERT(m.moments[i].m0 == d.m0);
      }
    }
  });
}

// The same on solid shapes with larger balls near their boundary: whole groups of columns
// inside or outside the runs (summed in O(1)), every axis chosen, a cavity giving two runs.
TEST(BallMoments, ColumnMomentsEqualDirectMomentsOnSolids) {
  zdg::test::check_property([] {
    const std::int64_t R = *rc::gen::inRange<std::int64_t>(8, 16);
    const auto outer = zdg::test::ball_predicate({0, 0, 0}, R * R);
    const auto cavity = zdg::test::ball_predicate(
        {*rc::gen::inRange<std::int64_t>(-3, 4), 0, *rc::gen::inRange<std::int64_t>(-3, 4)},
        *rc::gen::inRange<std::int64_t>(0, 30));
    const auto slab = *rc::gen::arbitrary<bool>();
    const zdg::VoxelPredicate in = [&](const Voxel& z) {
      return (outer(z) && !cavity(z)) || (slab && z.x + z.y > 2 * R && z.x + z.y < 2 * R + 6);
    };
    const VoxelBox box{{-40, -40, -40}, {40, 40, 40}};
    const auto r2 = *rc::gen::inRange<std::int64_t>(20, 200);
    std::vector<Voxel> centres;
    for (int i = 0; i < 6; ++i) {
      // a voxel near the sphere of radius R in a random direction
      const double th = *rc::gen::inRange(0, 628) / 100.0, ph = *rc::gen::inRange(0, 314) / 100.0;
      centres.push_back({std::int64_t(std::lround(R * std::sin(ph) * std::cos(th))),
                         std::int64_t(std::lround(R * std::sin(ph) * std::sin(th))),
                         std::int64_t(std::lround(R * std::cos(ph)))});
    }
    const auto m = zdg::ball_moments_by_columns(in, box, centres, r2, 2, true);
    for (std::size_t i = 0; i < centres.size(); ++i)
      RC_ASSERT(m.moments[i] == zdg::direct_ball_moments(in, box, centres[i], r2));
  });
}

// A radius past the int32 line sums (r > 100).
TEST(BallMoments, LargeRadius) {
  const std::int64_t r2 = 101 * 101 + 7;
  const auto big = zdg::test::ball_predicate({3, -2, 1}, 90 * 90);
  const VoxelBox box{{-200, -200, -200}, {200, 200, 200}};
  const std::vector<Voxel> centres{{90, 5, -7}};
  const auto m = zdg::ball_moments_by_columns(big, box, centres, r2, 2, true);
  EXPECT_EQ(m.moments[0], zdg::direct_ball_moments(big, box, centres[0], r2));
}

// Centres far apart get one set of runs per tile: the voxels evaluated stay near the balls.
TEST(BallMoments, FarCentresUseTiles) {
  const zdg::VoxelPredicate in = [](const Voxel& z) { return (z.x + 2 * z.y + 3 * z.z) % 5 < 2; };
  const VoxelBox box{{-100, -100, -100}, {6000, 6000, 100}};
  const std::vector<Voxel> centres{{1, 2, 3}, {5100, 5100, 0}, {-50, 5900, 60}};
  const std::int64_t r2 = 30;
  const auto m = zdg::ball_moments_by_columns(in, box, centres, r2, 2, true);
  for (std::size_t i = 0; i < centres.size(); ++i)
    EXPECT_EQ(m.moments[i], zdg::direct_ball_moments(in, box, centres[i], r2)) << i;
  EXPECT_LT(m.stats.evaluations, 3u * 48 * 48 * 48);
}

// The AVX-512 and AVX2 forms of the sums (used on CPUs that have them, r <= 100) and the
// portable form give the same integers: random sets with several runs per column, random
// radii, centres anywhere (the tails of the lines: every line length mod 16). Where the CPU
// lacks a form, the next narrower one runs.
TEST(BallMoments, VectorizedAndPortableSumsAgree) {
  zdg::test::check_property([] {
    const auto in =
        mixed(*rc::gen::inRange<std::int64_t>(0, 400), *rc::gen::inRange<std::int64_t>(0, 400),
              *rc::gen::arbitrary<std::uint32_t>());
    const VoxelBox box{{-30, -25, -28}, {27, 29, 26}};
    const auto r2 = *rc::gen::inRange<std::int64_t>(0, 600);
    std::vector<Voxel> centres;
    for (int i = 0; i < 8; ++i)
      centres.push_back({*rc::gen::inRange<std::int64_t>(-32, 32),
                         *rc::gen::inRange<std::int64_t>(-32, 32),
                         *rc::gen::inRange<std::int64_t>(-32, 32)});
    const int widest = zdg::detail::ball_moments_simd_lanes();
    const auto slow = zdg::detail::ball_moments_by_columns(in, box, centres, r2, 1, true, 0);
    RC_ASSERT(slow.stats.simd_lanes == 0);
    for (const int lanes : {8, 16}) {
      const auto fast = zdg::detail::ball_moments_by_columns(in, box, centres, r2, 1, true, lanes);
      RC_ASSERT(fast.stats.simd_lanes == std::min(lanes, widest));
      RC_ASSERT(fast.moments == slow.moments);
    }
    RC_ASSERT(slow.moments[0] == zdg::direct_ball_moments(in, box, centres[0], r2));
  });
}

// The largest radius of the int32 line sums (r = 100) on a full box, every moment at its
// largest: the vectorized and portable forms equal the closed forms of the full ball
// (m1 = 0, the three diagonal second moments equal, no cross moments).
TEST(BallMoments, LargestInt32RadiusOnAFullBox) {
  const zdg::VoxelPredicate all = [](const Voxel&) { return true; };
  const VoxelBox box{{-101, -101, -101}, {101, 101, 101}};
  const std::vector<Voxel> c{{0, 0, 0}, {1, -1, 0}};
  const std::int64_t r2 = 100 * 100;
  std::int64_t count = 0, sxx = 0;
  for (std::int64_t x = -100; x <= 100; ++x)
    for (std::int64_t y = -100; y <= 100; ++y)
      for (std::int64_t z = -100; z <= 100; ++z)
        if (x * x + y * y + z * z <= r2) {
          ++count;
          sxx += x * x;
        }
  for (const int simd : {16, 8, 0}) {
    const auto m = zdg::detail::ball_moments_by_columns(all, box, c, r2, 1, true, simd);
    for (const auto& b : m.moments) {
      EXPECT_EQ(b.m0, count) << simd;
      EXPECT_EQ(b.m1, (std::array<std::int64_t, 3>{0, 0, 0})) << simd;
      EXPECT_EQ(b.m2, (std::array<std::int64_t, 6>{sxx, sxx, sxx, 0, 0, 0})) << simd;
    }
  }
}

TEST(BallMoments, WorkedExamplesAndErrors) {
  // The full ball of radius 1 (7 voxels): m0 = 7, m1 = 0, m2 = diag(2, 2, 2).
  const zdg::VoxelPredicate all = [](const Voxel&) { return true; };
  const VoxelBox box{{-5, -5, -5}, {5, 5, 5}};
  const std::vector<Voxel> c{{0, 0, 0}, {5, 5, 5}};
  const auto m = zdg::ball_moments_by_columns(all, box, c, 1, 1, true);
  EXPECT_EQ(m.moments[0].m0, 7);
  EXPECT_EQ(m.moments[0].m2, (std::array<std::int64_t, 6>{2, 2, 2, 0, 0, 0}));
  // At the corner of the box only the octant inside counts: 4 voxels, m1 = (-1, -1, -1).
  EXPECT_EQ(m.moments[1].m0, 4);
  EXPECT_EQ(m.moments[1].m1, (std::array<std::int64_t, 3>{-1, -1, -1}));
  EXPECT_TRUE(zdg::ball_moments_by_columns(all, box, {}, 4).moments.empty());
  EXPECT_THROW(zdg::ball_moments_by_columns(all, box, c, -1), zdg::InvalidArgument);
  EXPECT_THROW(zdg::ball_moments_by_columns(all, box, c, 257 * 257), zdg::InvalidArgument);
  EXPECT_THROW(zdg::direct_ball_moments(all, box, c[0], -1), zdg::InvalidArgument);
  const std::vector<Voxel> far{{std::int64_t{1} << 41, 0, 0}};
  EXPECT_THROW(zdg::ball_moments_by_columns(all, box, far, 4), zdg::InvalidArgument);
}

// An error raised by the predicate in a worker thread reaches the caller.
TEST(BallMoments, PredicateErrorsPropagate) {
  const VoxelBox box{{-8, -8, -8}, {8, 8, 8}};
  const zdg::VoxelPredicate bad = [](const Voxel& z) {
    if (z.y == 3) throw zdg::OverflowError("predicate overflow at y = 3");
    return z.x < 0;
  };
  const std::vector<Voxel> c{{0, 0, 0}, {1, 2, 3}};
  EXPECT_THROW(zdg::ball_moments_by_columns(bad, box, c, 16, 3), zdg::OverflowError);
}

} // namespace
