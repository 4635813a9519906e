#include <zdg/kernel/transforms/distributed_transform.hpp>

#include <zdg/arith/error.hpp>
#include <zdg/kernel/transforms/distance_transform.hpp>
#include <zdg/kernel/transforms/voronoi_map.hpp>

#include "tests/support/thread_exchange.hpp"
#include "tests/support/tower.hpp"
#include "tests/support/transform_oracle.hpp"

#include <gtest/gtest.h>
#include <rapidcheck.h>

#include <mutex>

namespace zdg {
namespace {

// What the team computed, gathered into whole-volume arrays in C order.
template <class T>
struct Gathered {
  std::vector<T> values;
  std::vector<std::int64_t> sites;
  std::vector<std::uint64_t> largest; // as returned on each rank
};

// Runs the distributed transform of the mask (items of `item` bytes) on P thread ranks, each
// given only its slices, and puts each rank's columns back in place.
template <class T>
Gathered<T> run_distributed(const Domain& dom, const std::vector<std::uint8_t>& mask, int item,
                            const TransformOptions& opt, int P, bool with_sites) {
  Gathered<T> g;
  g.values.assign(static_cast<std::size_t>(dom.size()), T{});
  if (with_sites) g.sites.assign(static_cast<std::size_t>(dom.size()), -2);
  g.largest.assign(static_cast<std::size_t>(P), 0);
  const std::int64_t n0 = dom.extent(0), slice = dom.stride(0);
  std::mutex lock;
  test::run_team(P, [&](RankExchange& ex) {
    const DistributedPart part = distributed_part(dom, ex.rank(), ex.size());
    const std::int64_t w = part.columns.size();
    std::vector<std::uint8_t> slab(mask.begin() + part.slices.begin * slice * item,
                                   mask.begin() + part.slices.end * slice * item);
    std::vector<T> out(static_cast<std::size_t>(n0 * w));
    std::vector<std::int64_t> sites;
    const T mx = distance_transform_distributed<T>(dom, slab.data(), item, opt, ex, out.data(),
                                                   with_sites ? &sites : nullptr);
    const std::lock_guard<std::mutex> hold(lock);
    g.largest[static_cast<std::size_t>(ex.rank())] = mx;
    for (std::int64_t z = 0; z < n0; ++z) {
      for (std::int64_t j = 0; j < w; ++j) {
        const auto at = static_cast<std::size_t>(z * slice + part.columns.begin + j);
        g.values[at] = out[static_cast<std::size_t>(z * w + j)];
        if (with_sites) g.sites[at] = sites[static_cast<std::size_t>(z * w + j)];
      }
    }
  });
  return g;
}

// The mask with items of `item` bytes: a foreground point gets one nonzero byte somewhere.
std::vector<std::uint8_t> widen(const Image<std::uint8_t>& shape, int item) {
  std::vector<std::uint8_t> m(static_cast<std::size_t>(shape.size() * item), 0);
  for (std::int64_t i = 0; i < shape.size(); ++i) {
    if (shape[i] != 0) m[static_cast<std::size_t>(i * item + i % item)] = 1;
  }
  return m;
}

// Theorem (separability, as for the out-of-core transform): the passes along axes d-1 .. 1
// commute with cutting the volume into slabs of slices, and the pass along axis 0 with cutting
// it into blocks of columns; the transpose between moves values without changing them. So the
// distributed values and Voronoi sites are those of the single-process engine, to the bit, for
// every P (including ranks with no slice or no column), metric, torus axes and lower bounds.
TEST(DistributedTransform, EqualsTheSingleProcessTransform) {
  test::check_property([] {
    const auto c = test::random_transform_case();
    RC_PRE(c.shape.dim() >= 2);
    const int P = *rc::gen::inRange(1, 6);
    const int item = *rc::gen::element(1, 2, 8);
    const auto mask = widen(c.shape, item);
    const Domain& dom = c.shape.domain();
    std::vector<std::uint64_t> expect(static_cast<std::size_t>(dom.size()));
    distance_transform_into<std::uint64_t>(dom, mask.data(), item, c.opt, expect.data());
    const auto g = run_distributed<std::uint64_t>(dom, mask, item, c.opt, P, true);
    RC_ASSERT(g.values == expect);
    RC_ASSERT(g.sites == voronoi_map(dom, mask.data(), c.opt, item).site);
    const std::uint64_t mx = *std::max_element(expect.begin(), expect.end());
    for (auto m : g.largest) RC_ASSERT(m == mx);
  });
}

// Worked example: 7 slices of 5 x 3 over 4 ranks (slices 2, 2, 2, 1; columns 4, 4, 4, 3) and
// over 9 ranks (two without a slice, six with one column only); l_2 into uint16, one background
// point at (3, 2, 1): the value at (z, y, x) is (z-3)^2 + (y-2)^2 + (x-1)^2.
TEST(DistributedTransform, UnevenAndEmptyParts) {
  const Domain dom({7, 5, 3});
  std::vector<std::uint8_t> mask(static_cast<std::size_t>(dom.size()), 1);
  mask[static_cast<std::size_t>(dom.index(std::vector<std::int64_t>{3, 2, 1}))] = 0;
  TransformOptions opt;
  for (int P : {4, 9}) {
    const auto g = run_distributed<std::uint16_t>(dom, mask, 1, opt, P, true);
    for (std::int64_t i = 0; i < dom.size(); ++i) {
      const auto p = dom.point(i);
      const std::int64_t v =
          (p[0] - 3) * (p[0] - 3) + (p[1] - 2) * (p[1] - 2) + (p[2] - 1) * (p[2] - 1);
      EXPECT_EQ(g.values[static_cast<std::size_t>(i)], v) << "P = " << P << ", point " << i;
      EXPECT_EQ(g.sites[static_cast<std::size_t>(i)], 3 * 15 + 2 * 3 + 1);
    }
    EXPECT_EQ(g.largest, std::vector<std::uint64_t>(static_cast<std::size_t>(P), 9 + 4 + 1));
  }
  EXPECT_EQ(distributed_part(dom, 3, 4).slices.begin, 6);
  EXPECT_EQ(distributed_part(dom, 3, 4).columns.size(), 3);
  EXPECT_EQ(distributed_part(dom, 8, 9).slices.size(), 0);
}

// The parts of rank_range tile [0, n) in order, and their sizes differ by at most one.
TEST(DistributedTransform, RankRangesTileTheItems) {
  test::check_property([] {
    const std::int64_t n = *rc::gen::inRange<std::int64_t>(0, 100000);
    const int parts = *rc::gen::inRange(1, 300);
    std::int64_t at = 0, lo = n, hi = 0;
    for (int k = 0; k < parts; ++k) {
      const RankRange r = rank_range(n, parts, k);
      RC_ASSERT(r.begin == at);
      at = r.end;
      lo = std::min(lo, r.size());
      hi = std::max(hi, r.size());
    }
    RC_ASSERT(at == n);
    RC_ASSERT(hi - lo <= 1);
  });
  EXPECT_THROW(rank_range(10, 0, 0), InvalidArgument);
  EXPECT_THROW(rank_range(10, 3, 3), InvalidArgument);
}

// Errors are the same on every rank, raised before or at the same collective step (no rank
// is left waiting): no background anywhere (the slices of every rank looked at), a 1-D image,
// values past the output type.
TEST(DistributedTransform, ErrorsOnEveryRank) {
  const Domain dom({6, 4});
  std::vector<std::uint8_t> full(static_cast<std::size_t>(dom.size()), 1);
  try {
    run_distributed<std::uint32_t>(dom, full, 1, {}, 3, false);
    FAIL() << "no background";
  } catch (const InvalidArgument& e) {
    EXPECT_NE(std::string(e.what()).find("no background point"), std::string::npos) << e.what();
  }
  std::vector<std::uint8_t> line{1, 0, 1};
  EXPECT_THROW(run_distributed<std::uint32_t>(Domain({3}), line, 1, {}, 2, false), InvalidArgument);
  const Domain big({300, 2});
  std::vector<std::uint8_t> m(static_cast<std::size_t>(big.size()), 1);
  m[0] = 0;
  EXPECT_THROW(run_distributed<std::uint8_t>(big, m, 1, {}, 2, false), OverflowError);
  std::vector<std::uint8_t> m3(m.size() * 3, 1);
  m3[0] = m3[1] = m3[2] = 0;
  EXPECT_THROW(run_distributed<std::uint32_t>(big, m3, 3, {}, 2, false), InvalidArgument);
}

} // namespace
} // namespace zdg
