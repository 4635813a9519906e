// Continued fractions: round trip, canonical form, convergent determinants, worked examples.
#include <zdg/arith/continued_fraction.hpp>

#include "tests/support/check_registry.hpp"
#include "tests/support/tower.hpp"

namespace {

using namespace zdg;
using test::check_property;

template <class I>
class ContinuedFraction : public ::testing::Test {};
TYPED_TEST_SUITE(ContinuedFraction, test::TowerTypes, test::TowerNames);

// Theorem (Euclid): the canonical expansion of p/q evaluates back to p/q reduced, its terms
// after the first are >= 1 and its last term is >= 2 when there are several.
TYPED_TEST(ContinuedFraction, RoundTripAndCanonicalForm) {
  using I = TypeParam;
  check_property([] {
    std::int64_t p = *test::edgy_int64(), q = *test::edgy_int64();
    RC_PRE(q != 0);
    if constexpr (std::same_as<I, Int64>) {
      RC_PRE(p != std::numeric_limits<std::int64_t>::min());
      RC_PRE(q != std::numeric_limits<std::int64_t>::min());
    }
    auto terms = continued_fraction(I(p), I(q));
    RC_ASSERT(!terms.empty());
    for (std::size_t k = 1; k < terms.size(); ++k) RC_ASSERT(terms[k] >= 1);
    if (terms.size() > 1) RC_ASSERT(terms.back() >= 2);
    RC_ASSERT(terms.front() == floor_div(I(p), I(q)));
    Rational<I> back = from_continued_fraction(std::span<const I>(terms));
    RC_ASSERT(back == Rational<I>(I(p), I(q)));
  });
}

// Theorem: consecutive convergents satisfy p_k q_{k-1} - p_{k-1} q_k = (-1)^{k+1}, and the
// even (odd) convergents approach p/q from below (above).
TYPED_TEST(ContinuedFraction, ConvergentDeterminantsAndAlternation) {
  using I = TypeParam;
  check_property([] {
    std::int64_t p = *test::int64_in(-1'000'000'000'000, 1'000'000'000'000);
    std::int64_t q = *test::int64_in(1, 1'000'000'000'000);
    auto terms = continued_fraction(I(p), I(q));
    auto conv = convergents(std::span<const I>(terms));
    BigInt P(p), Q(q);
    for (std::size_t k = 0; k < conv.size(); ++k) {
      BigInt pk = to_bigint(conv[k].first), qk = to_bigint(conv[k].second);
      RC_ASSERT(qk > 0);
      if (k > 0) {
        BigInt det = pk * to_bigint(conv[k - 1].second) - to_bigint(conv[k - 1].first) * qk;
        RC_ASSERT(det == (k % 2 == 1 ? 1 : -1));
      }
      // sign of pk/qk - P/Q: <= 0 for even k, >= 0 for odd k
      BigInt diff = pk * Q - P * qk;
      RC_ASSERT((k % 2 == 0 ? diff <= 0 : diff >= 0));
    }
  });
}

TYPED_TEST(ContinuedFraction, WorkedExamples) {
  using I = TypeParam;
  // 415/93 = [4; 2, 6, 7] (a classic example, e.g. Wikipedia "Continued fraction").
  auto t = continued_fraction(I(415), I(93));
  std::vector<I> expect{4, 2, 6, 7};
  EXPECT_EQ(t, expect);
  // -7/3 = [-3; 1, 2]
  std::vector<I> neg{-3, 1, 2};
  EXPECT_EQ(continued_fraction(I(-7), I(3)), neg);
  EXPECT_EQ(continued_fraction(I(7), I(-3)), neg);
  // 355/113 (Zu Chongzhi's approximation of pi) = [3; 7, 16]
  std::vector<I> zu{3, 7, 16};
  EXPECT_EQ(continued_fraction(I(355), I(113)), zu);
  auto c = convergents(std::span<const I>(zu));
  EXPECT_EQ(c[1], (std::pair<I, I>{22, 7}));
  EXPECT_THROW(continued_fraction(I(1), I(0)), InvalidArgument);
  std::vector<I> bad{1, 0, 2};
  EXPECT_THROW(from_continued_fraction(std::span<const I>(bad)), InvalidArgument);
  // A non-canonical expansion is accepted: [1; 1] = 2.
  std::vector<I> noncanon{1, 1};
  EXPECT_EQ(from_continued_fraction(std::span<const I>(noncanon)), Rational<I>(2));
}

// Fibonacci ratios have all-ones expansions: the worst case of Euclid (Lame).
TEST(ContinuedFractionBig, FibonacciRatiosNeedManySteps) {
  BigInt a = 1, b = 1;
  for (int i = 0; i < 300; ++i) {
    BigInt c = a + b;
    a = b;
    b = c;
  }
  auto t = continued_fraction(b, a);
  for (std::size_t k = 0; k + 1 < t.size(); ++k) EXPECT_EQ(t[k], 1);
  EXPECT_EQ(t.back(), 2);
  EXPECT_EQ(from_continued_fraction(std::span<const BigInt>(t)), Rational<BigInt>(b, a));
}

// The registered property cf.roundtrip (zdg check): Euclid's expansion, canonical form and
// evaluation back to p/q, on values of up to 64, 128, 256 bits by type.
TYPED_TEST(ContinuedFraction, RegisteredRoundTripHolds) {
  test::expect_registered_property("cf.roundtrip", int_kind<TypeParam>(), 300);
}

} // namespace

namespace {
// Shrunk counterexample: the remainder p - a q was formed through a product that leaves
// int64 although every term fits.
TEST(ContinuedFractionRegression, RemainderWithoutOverflowingProduct) {
  auto t = zdg::continued_fraction(zdg::Int64(9223372036854775806), zdg::Int64(-14));
  auto back = zdg::from_continued_fraction(std::span<const zdg::Int64>(t));
  EXPECT_EQ(back, zdg::Rational<zdg::Int64>(zdg::Int64(-4611686018427387903), zdg::Int64(7)));
}

} // namespace
