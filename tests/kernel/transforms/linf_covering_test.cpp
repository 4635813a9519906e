#include <zdg/kernel/transforms/linf_covering.hpp>

#include "tests/support/tower.hpp"
#include "tests/support/transform_oracle.hpp"

#include <gtest/gtest.h>

namespace zdg {
namespace {

// R(y) = max { v(c) : d_inf(c, y) < v(c) } and the returned centre attains it (oracle: every
// pair), on random 1D-4D cases with torus axes and negative lower bounds.
TEST(LinfCovering, LargestCoveringCubeEqualsBruteForce) {
  test::check_property([] {
    auto c = test::random_transform_case();
    c.opt.metric = Metric::linf();
    const Domain& dom = c.shape.domain();
    std::mt19937 rng(*rc::gen::arbitrary<std::uint32_t>());
    std::vector<std::int64_t> v(static_cast<std::size_t>(dom.size()));
    for (auto& x : v) x = rng() % 5 == 0 ? static_cast<std::int64_t>(rng() % 6) : 0;
    auto r = v;
    std::vector<std::int64_t> site;
    detail::linf_covering(dom, c.opt, r, &site);
    for (std::int64_t y = 0; y < dom.size(); ++y) {
      std::int64_t best = 0;
      for (std::int64_t ctr = 0; ctr < dom.size(); ++ctr) {
        const std::int64_t vc = v[static_cast<std::size_t>(ctr)];
        if (test::metric_length<std::int64_t>(dom, c.opt, ctr, y) < vc) best = std::max(best, vc);
      }
      const auto uy = static_cast<std::size_t>(y);
      RC_ASSERT(r[uy] == best);
      if (best == 0) {
        RC_ASSERT(site[uy] == -1);
      } else {
        RC_ASSERT(v[static_cast<std::size_t>(site[uy])] == best);
        RC_ASSERT(test::metric_length<std::int64_t>(dom, c.opt, site[uy], y) < best);
      }
    }
  });
}

TEST(LinfCovering, HugeValuesDoNotOverflow) {
  Domain dom({5});
  std::vector<std::int64_t> r{0, 0, std::numeric_limits<std::int64_t>::max(), 0, 0};
  detail::linf_covering(dom, {}, r, nullptr);
  for (auto x : r) EXPECT_EQ(x, std::numeric_limits<std::int64_t>::max());
}

} // namespace
} // namespace zdg
