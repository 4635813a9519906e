#include <zdg/kernel/digitization/polynomial_sign.hpp>
#include <zdg/kernel/images/column_runs.hpp>

#include "tests/support/tower.hpp"

#include "tests/support/digital_sets.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <memory>
#include <string>

namespace {

using zdg::ColumnRuns;
using zdg::Voxel;
using zdg::VoxelBox;

// A set with several runs per column: two balls and a sprinkle of voxels given by a hash.
zdg::VoxelPredicate sprinkled(std::int64_t r2a, std::int64_t r2b, std::uint32_t salt) {
  const auto a = zdg::test::ball_predicate({-2, 1, -3}, r2a);
  const auto b = zdg::test::ball_predicate({3, -1, 4}, r2b);
  return [=](const Voxel& z) {
    const auto hsh = std::uint32_t(z.x * 73856093) ^ std::uint32_t(z.y * 19349663) ^
                     std::uint32_t(z.z * 83492791) ^ salt;
    return a(z) || b(z) || (hsh % 11 == 0);
  };
}

// Theorem: z belongs to a run of column (x, y) iff (x, y, z) is in the box and in X, for
// every voxel of the region (no mask); the layers hold the runs in increasing z, and
// covering(k, ...) says whether a column of the range has more than k runs.
TEST(ColumnRuns, RunsAreTheSetColumnByColumn) {
  zdg::test::check_property([] {
    const auto in =
        sprinkled(*rc::gen::inRange<std::int64_t>(0, 20), *rc::gen::inRange<std::int64_t>(0, 20),
                  *rc::gen::arbitrary<std::uint32_t>());
    const VoxelBox box{{-6, -5, -7}, {5, 6, 8}};
    const std::int64_t lx = *rc::gen::inRange<std::int64_t>(-9, 0);
    const std::int64_t lz = *rc::gen::inRange<std::int64_t>(-10, 0);
    const VoxelBox region{{lx, -7, lz},
                          {lx + *rc::gen::inRange<std::int64_t>(0, 16), 7,
                           lz + *rc::gen::inRange<std::int64_t>(0, 20)}};
    const ColumnRuns runs = zdg::column_runs(in, box, region, unsigned(*rc::gen::inRange(1, 4)));
    std::size_t evaluated = 0;
    for (std::int64_t y = region.lo.y; y <= region.hi.y; ++y)
      for (std::int64_t x = region.lo.x; x <= region.hi.x; ++x) {
        const auto r = runs.runs(x, y);
        int count = 0;
        for (std::int64_t z = region.lo.z; z <= region.hi.z; ++z) {
          const Voxel p{x, y, z};
          if (box.contains(p)) ++evaluated;
          bool member = false;
          for (const auto& [b, e] : r) member = member || (b <= z && z <= e);
          RC_ASSERT(member == (box.contains(p) && in(p)));
        }
        for (std::size_t k = 1; k < r.size(); ++k) RC_ASSERT(r[k - 1].second + 1 < r[k].first);
        count = int(r.size());
        RC_ASSERT(count <= runs.layers());
      }
    RC_ASSERT(runs.evaluations == evaluated);
    for (int k = 1; k < runs.layers(); ++k)
      for (std::int64_t y = region.lo.y; y <= region.hi.y; ++y) {
        const std::int64_t x0 = *rc::gen::inRange(region.lo.x, region.hi.x + 1);
        const std::int64_t x1 = *rc::gen::inRange(x0, region.hi.x + 1);
        bool deeper = false;
        for (std::int64_t x = x0; x <= x1; ++x) deeper = deeper || int(runs.runs(x, y).size()) > k;
        RC_ASSERT(runs.covering(k, y, x0, x1) == deeper);
        std::int64_t first = x1 + 1, last = x1;
        for (std::int64_t x = x0; x <= x1; ++x)
          if (int(runs.runs(x, y).size()) > k) {
            first = std::min(first, x);
            last = x;
          }
        if (first > x1) last = x1;
        RC_ASSERT(runs.deeper_range(k, y, x0, x1) == std::make_pair(first, last));
      }
  });
}

// A random mask of the blocks of region: with k > 0 a block is needed with probability 1/k,
// with k < 0 with probability 1 - 1/|k| (the shrunk value 0 of the generator: needed).
zdg::BlockMask random_mask(const VoxelBox& region, int k) {
  const std::int64_t B = ColumnRuns::kBlock;
  zdg::BlockMask mask;
  mask.bx = (region.hi.x - region.lo.x + B) / B;
  mask.by = (region.hi.y - region.lo.y + B) / B;
  mask.bz = (region.hi.z - region.lo.z + B) / B;
  for (std::int64_t i = 0; i < mask.bx * mask.by * mask.bz; ++i) {
    const int g = *rc::gen::inRange(0, k > 0 ? k : -k);
    mask.needed.push_back(k > 0 ? (g == 0 ? 1 : 0) : (g != -k - 1 ? 1 : 0));
  }
  return mask;
}

// With a block mask, only the voxels of needed blocks are evaluated and the runs are exact
// there.
TEST(ColumnRuns, MaskedRunsAreExactOnNeededBlocks) {
  zdg::test::check_property([] {
    const auto in = sprinkled(25, 16, *rc::gen::arbitrary<std::uint32_t>());
    const VoxelBox box{{-20, -20, -20}, {20, 20, 20}};
    const VoxelBox region{{-19, -18, -21}, {14, 17, 22}};
    const std::int64_t B = ColumnRuns::kBlock;
    const zdg::BlockMask mask = random_mask(region, 3);
    const ColumnRuns runs = zdg::column_runs(in, box, region, 2, &mask);
    std::size_t needed_voxels = 0;
    for (std::int64_t z = region.lo.z; z <= region.hi.z; ++z)
      for (std::int64_t y = region.lo.y; y <= region.hi.y; ++y)
        for (std::int64_t x = region.lo.x; x <= region.hi.x; ++x) {
          if (!mask.at((x - region.lo.x) / B, (y - region.lo.y) / B, (z - region.lo.z) / B))
            continue;
          const Voxel p{x, y, z};
          if (box.contains(p)) ++needed_voxels;
          bool member = false;
          for (const auto& [b, e] : runs.runs(x, y)) member = member || (b <= z && z <= e);
          RC_ASSERT(member == (box.contains(p) && in(p)));
        }
    RC_ASSERT(runs.evaluations == needed_voxels);
  });
}

// A polynomial digitization is read by columns (PolynomialDigitization::column): the runs,
// the deeper-column lists and the evaluation count equal those of the same predicate read
// voxel by voxel (wrapped in a lambda, which column_runs cannot see through), with a mask.
TEST(ColumnRuns, PolynomialColumnsEqualVoxelByVoxel) {
  zdg::test::check_property([] {
    // A Goursat-like quartic with a cavity: several runs per column.
    const auto f = std::make_shared<const zdg::PolynomialSign>(zdg::Polynomial::parse(
        "x^4+y^4+z^4-8*(x^2+y^2+z^2)+" + std::to_string(*rc::gen::inRange(10, 31)), 3));
    const double h = 1.0 / double(*rc::gen::inRange(3, 9));
    const std::array<double, 3> t{std::ldexp(*rc::gen::inRange(-8, 9), -4), 0.25,
                                  std::ldexp(*rc::gen::inRange(-8, 9), -5)};
    const zdg::VoxelPredicate by_column = zdg::PolynomialDigitization(f, h, t);
    const zdg::VoxelPredicate by_voxel = [by_column](const Voxel& z) { return by_column(z); };
    const VoxelBox box{{-30, -30, -30}, {30, 30, 30}};
    const VoxelBox region{{-31, -29, -33}, {27, 30, 31}};
    const zdg::BlockMask mask = random_mask(region, -4);
    const ColumnRuns a = zdg::column_runs(by_column, box, region, 2, &mask);
    const ColumnRuns b = zdg::column_runs(by_voxel, box, region, 2, &mask);
    RC_ASSERT(a.begin == b.begin);
    RC_ASSERT(a.end == b.end);
    RC_ASSERT(a.deeper == b.deeper);
    RC_ASSERT(a.deeper_x == b.deeper_x);
    RC_ASSERT(a.evaluations == b.evaluations);
  });
}

TEST(ColumnRuns, WorkedExampleAndErrors) {
  // Column (0, 0) of { z : z in [-3, -1] or z in [2, 2] or z >= 5 } in region z in [-4, 6].
  const zdg::VoxelPredicate in = [](const Voxel& p) {
    return p.x == 0 && p.y == 0 && ((p.z >= -3 && p.z <= -1) || p.z == 2 || p.z >= 5);
  };
  const VoxelBox box{{-1, -1, -10}, {1, 1, 10}};
  const auto runs = zdg::column_runs(in, box, {{0, 0, -4}, {0, 1, 6}});
  EXPECT_EQ(runs.layers(), 3);
  using R = std::vector<std::pair<std::int64_t, std::int64_t>>;
  EXPECT_EQ(runs.runs(0, 0), (R{{-3, -1}, {2, 2}, {5, 6}}));
  EXPECT_TRUE(runs.runs(0, 1).empty());
  EXPECT_TRUE(runs.covering(2, 0, 0, 0));
  EXPECT_FALSE(runs.covering(1, 1, 0, 0));
  // The box clips: voxels outside it are outside.
  const auto clipped = zdg::column_runs(in, {{-1, -1, -10}, {1, 1, 5}}, {{0, 0, -4}, {0, 0, 6}});
  EXPECT_EQ(clipped.runs(0, 0), (R{{-3, -1}, {2, 2}, {5, 5}}));
  EXPECT_THROW(zdg::column_runs(in, box, {{0, 0, 0}, {0, 0, std::int64_t{1} << 29}}),
               zdg::InvalidArgument);
  zdg::BlockMask wrong;
  EXPECT_THROW(zdg::column_runs(in, box, {{0, 0, -4}, {0, 0, 6}}, 1, &wrong), zdg::InvalidArgument);
}

} // namespace
