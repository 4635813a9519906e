#include <zdg/estimators/gauss_volume.hpp>

#include "tests/support/tower.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace {

using zdg::Voxel;

// The count is #G_h(X) exactly (brute-force oracle), whatever the number of threads.
TEST(GaussVolume, CountEqualsBruteForce) {
  zdg::test::check_property([] {
    const auto r2 = *rc::gen::inRange<std::int64_t>(0, 60);
    const auto cx = *rc::gen::inRange<std::int64_t>(-5, 6);
    const int threads = *rc::gen::inRange(1, 4);
    const zdg::VoxelBox box{{cx - 6, -4, 3}, {cx + 3, 5, 12}};
    const zdg::VoxelPredicate in = [&](const Voxel& z) {
      const auto dx = z.x - cx, dy = z.y, dz = z.z - 7;
      return dx * dx + dy * dy + dz * dz <= r2;
    };
    std::int64_t brute = 0;
    for (auto z = box.lo.z; z <= box.hi.z; ++z)
      for (auto y = box.lo.y; y <= box.hi.y; ++y)
        for (auto x = box.lo.x; x <= box.hi.x; ++x) brute += in({x, y, z});
    const auto g = zdg::gauss_volume(in, box, 0.5, threads);
    RC_ASSERT(g.count == brute);
    RC_ASSERT(g.volume == 0.125 * double(brute));
  });
}

// h^3 #G_h(B) -> 4 pi / 3 for the unit ball, with an O(h) error.
TEST(GaussVolume, UnitBallConverges) {
  const std::int64_t n = 40; // h = 1/40
  const zdg::VoxelPredicate in = [&](const Voxel& z) {
    return z.x * z.x + z.y * z.y + z.z * z.z <= n * n;
  };
  const auto g = zdg::gauss_volume(in, {{-n, -n, -n}, {n, n, n}}, 1.0 / double(n), 2);
  EXPECT_NEAR(g.volume, 4 * std::numbers::pi / 3, 3.0 / double(n));
  EXPECT_GT(g.count, 0);
}

TEST(GaussVolume, Errors) {
  const zdg::VoxelPredicate in = [](const Voxel&) { return true; };
  EXPECT_THROW(zdg::gauss_volume(in, {{0, 0, 0}, {1, 1, 1}}, 0.0), zdg::InvalidArgument);
  EXPECT_THROW(zdg::gauss_volume(in, {{0, 0, 1}, {1, 1, 0}}, 1.0), zdg::InvalidArgument);
}

} // namespace
