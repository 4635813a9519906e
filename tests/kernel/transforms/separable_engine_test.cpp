// The width choice of the separable engine (kernel/transforms/separable_engine.hpp): the bound
// need = 2 (sum_k m_k^p + w_max + L^p) + 2 L, and the narrowest engine integer that holds it.
// The transforms' own tests check the results against brute force on every width; these
// pin the bound itself and the metric parsing (kernel/transforms/lp_metric.hpp).
#include <zdg/kernel/transforms/separable_engine.hpp>

#include "tests/support/tower.hpp"

namespace {

using namespace zdg;

BigInt pow_big(std::int64_t t, int p) {
  BigInt r = 1;
  for (int i = 0; i < p; ++i) r *= t;
  return r;
}

// The bound is the documented formula, for random extents, exponents and torus flags.
TEST(SeparableEngine, BoundIsTheDocumentedFormula) {
  test::check_property([] {
    const int d = *rc::gen::inRange(1, 5);
    const int p = *rc::gen::inRange(1, 7);
    std::vector<std::int64_t> ext;
    std::vector<bool> torus;
    for (int k = 0; k < d; ++k) {
      ext.push_back(*rc::gen::inRange<std::int64_t>(1, 5000));
      torus.push_back(*rc::gen::arbitrary<bool>());
    }
    const std::int64_t w = *rc::gen::inRange<std::int64_t>(0, 1000000);
    TransformOptions opt;
    opt.metric = Metric::lp(p);
    opt.torus = torus;
    auto b = detail::envelope_bounds(Domain(ext), opt, BigInt(w));
    BigInt sum = 0;
    std::int64_t longest = 1;
    for (int k = 0; k < d; ++k) {
      const auto n = ext[static_cast<std::size_t>(k)];
      sum += pow_big(torus[static_cast<std::size_t>(k)] ? n / 2 : n - 1, p);
      longest = std::max(longest, torus[static_cast<std::size_t>(k)] ? 3 * n : n);
    }
    RC_ASSERT(b.value_max == sum);
    RC_ASSERT(b.need == 2 * (sum + w + pow_big(longest, p)) + 2 * BigInt(longest));
    // The narrowest width that holds the bound.
    const auto expect = b.need < BigInt(INT32_MAX)    ? detail::ValueWidth::I32
                        : b.need < BigInt(INT64_MAX)  ? detail::ValueWidth::I64
                        : b.need < (BigInt(1) << 126) ? detail::ValueWidth::I128
                                                      : detail::ValueWidth::Big;
    RC_ASSERT(b.width == expect);
  });
}

TEST(SeparableEngine, WidthExamplesAndForcedWidths) {
  TransformOptions opt; // l2
  // 1D, n = 10: need = 2 (81 + 100) + 20 = 382.
  auto small = detail::envelope_bounds(Domain({10}), opt, BigInt(0));
  EXPECT_EQ(small.need, 382);
  EXPECT_EQ(small.width, detail::ValueWidth::I32);
  // A line of 2^21 + 1 points in l3: m^3 = 2^63, past int64.
  opt.metric = Metric::lp(3);
  auto big = detail::envelope_bounds(Domain({(1 << 21) + 1}), opt, BigInt(0));
  EXPECT_EQ(big.width, detail::ValueWidth::I128);
  opt.metric = Metric::lp(40);
  EXPECT_EQ(detail::envelope_bounds(Domain({100}), opt, BigInt(0)).width, detail::ValueWidth::Big);
  opt.metric = Metric::l2();
  opt.min_engine_bits = 64;
  EXPECT_EQ(detail::envelope_bounds(Domain({10}), opt, BigInt(0)).width, detail::ValueWidth::I64);
  opt.min_engine_bits = 129;
  EXPECT_EQ(detail::envelope_bounds(Domain({10}), opt, BigInt(0)).width, detail::ValueWidth::Big);
  opt.min_engine_bits = 0;
  opt.torus = {true, false};
  EXPECT_THROW(detail::envelope_bounds(Domain({10}), opt, BigInt(0)), InvalidArgument);
}

TEST(LpMetric, ParsingAndPowers) {
  EXPECT_EQ(parse_metric("l1"), Metric::l1());
  EXPECT_EQ(parse_metric("L2"), Metric::l2());
  EXPECT_EQ(parse_metric("linf"), Metric::linf());
  EXPECT_EQ(parse_metric("l17").p, 17);
  for (const char* bad : {"l0", "l", "lx", "l-2", "2", "l123456789"}) {
    EXPECT_THROW(parse_metric(bad), InvalidArgument) << bad;
  }
  EXPECT_EQ(metric_power(Metric::lp(3), 7), 343);
  EXPECT_EQ(metric_power(Metric::linf(), 7), 7);
  EXPECT_EQ(Metric::lp(4).name(), "l4");
}

} // namespace
