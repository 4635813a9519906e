#include <zdg/kernel/transforms/power_map.hpp>

#include "tests/support/tower.hpp"
#include "tests/support/transform_oracle.hpp"

#include <gtest/gtest.h>

namespace zdg {
namespace {

// Random weights on a random case: about one point in `sparsity` is a site.
Image<std::int64_t> random_weights(const Domain& dom, std::int64_t wmax) {
  std::mt19937 rng(*rc::gen::arbitrary<std::uint32_t>());
  int sparsity = *rc::gen::inRange(1, 12);
  Image<std::int64_t> w(dom, std::int64_t{0});
  for (auto& x : w.values()) {
    if (static_cast<int>(rng() % static_cast<unsigned>(sparsity)) == 0) {
      x = 1 + static_cast<std::int64_t>(rng() % static_cast<unsigned>(wmax));
    }
  }
  w.values()[rng() % w.values().size()] = wmax;
  return w;
}

template <class I>
class PowerMapTyped : public ::testing::Test {};
TYPED_TEST_SUITE(PowerMapTyped, test::TowerTypes, test::TowerNames);

// The chosen site minimises d_p(x, c)^p - w(c) over all sites (oracle: brute force), and the
// sign flag is that of the minimal power.
TYPED_TEST(PowerMapTyped, SiteMinimisesThePower) {
  test::check_property([] {
    auto c = test::random_transform_case(true);
    c.opt.min_engine_bits = test::engine_bits<TypeParam>();
    const Domain& dom = c.shape.domain();
    auto w = random_weights(dom, *rc::gen::inRange<std::int64_t>(1, 60));
    auto map = power_map(w, c.opt);
    for (std::int64_t i = 0; i < dom.size(); ++i) {
      bool first = true;
      std::int64_t best = 0;
      for (std::int64_t j = 0; j < dom.size(); ++j) {
        if (w[j] <= 0) continue;
        std::int64_t pw = test::metric_length<std::int64_t>(dom, c.opt, i, j) - w[j];
        if (first || pw < best) best = pw;
        first = false;
      }
      std::int64_t s = map.site[static_cast<std::size_t>(i)];
      RC_ASSERT(s >= 0);
      RC_ASSERT(w[s] > 0);
      RC_ASSERT(test::metric_length<std::int64_t>(dom, c.opt, i, s) - w[s] == best);
      RC_ASSERT((map.negative[static_cast<std::size_t>(i)] != 0) == (best < 0));
    }
  });
}

TEST(PowerMap, Errors) {
  Image<std::int64_t> w(Domain({4, 4}), std::int64_t{0});
  EXPECT_THROW(power_map(w, {}), InvalidArgument); // no site
  w.values()[3] = -2;
  EXPECT_THROW(power_map(w, {}), InvalidArgument); // negative weight
  w.values()[3] = 2;
  TransformOptions linf;
  linf.metric = Metric::linf();
  EXPECT_THROW(power_map(w, linf), InvalidArgument);
  EXPECT_NO_THROW(power_map(w, {}));
}

} // namespace
} // namespace zdg
