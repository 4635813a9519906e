// DSL subsegments: the reversed climb (ReversedSmartDSS) and the two floor-sum searches agree
// with each other and with DSS recognition of the enumerated points (itself checked against
// brute force), on every tower type, for small values and for values near 2^62; the answer
// does not depend on how the line is written (non-reduced a, b).
#include "arith/dsl_subsegment.hpp"

#include "arith/dss_recognizer.hpp"
#include "tests/support/tower.hpp"

#include <cstdint>
#include <cstdlib>
#include <optional>
#include <vector>

namespace {

using namespace zdg;
using test::check_property;

// Recognition of the points (x, floor((a x - mu) / b)), x0 <= x <= x1.
DssCharacteristics recognized(const BigInt& a, const BigInt& b, const BigInt& mu, const BigInt& x0,
                              const BigInt& x1) {
  auto y = [&](const BigInt& x) { return floor_div(BigInt(a * x - mu), b); };
  DssRecognizer<BigInt> rec({x0, y(x0)});
  for (BigInt x = x0 + 1; x <= x1; ++x) {
    if (!rec.extend_front({x, y(x)})) throw std::logic_error("a DSL piece is not a DSS");
  }
  return rec.characteristics();
}

struct Case {
  BigInt a, b, mu, x0, x1;
};

Case random_case(bool huge) {
  std::int64_t b = huge ? *test::int64_in(1, std::int64_t{1} << 62) : *test::int64_in(1, 60);
  std::int64_t a = *test::int64_in(0, b - 1);
  std::int64_t lim = huge ? std::int64_t{1} << 62 : 1000;
  std::int64_t mu = *test::int64_in(-lim, lim), x0 = *test::int64_in(-lim, lim);
  std::int64_t len = *rc::gen::oneOf(test::int64_in(0, 12), test::int64_in(0, 150));
  if (!huge && *rc::gen::arbitrary<bool>()) len = *test::int64_in(0, 2 * b + 3);
  return {BigInt(a), BigInt(b), BigInt(mu), BigInt(x0), BigInt(x0) + len};
}

template <class I>
class DslSubsegmentTest : public ::testing::Test {};
TYPED_TEST_SUITE(DslSubsegmentTest, zdg::test::TowerTypes, zdg::test::TowerNames);

// Oracle: recognition of the enumerated points. The reversed climb and both searches give it
// (or, on a narrow type, report an overflow: never a wrong answer).
TYPED_TEST(DslSubsegmentTest, AllAlgorithmsEqualRecognitionOfThePoints) {
  using I = TypeParam;
  check_property([] {
    Case c = random_case(*rc::gen::weightedElement<int>({{3, 0}, {1, 1}}) == 1);
    auto want = recognized(c.a, c.b, c.mu, c.x0, c.x1);
    DslSubsegment<BigInt> w{want.a, want.b, want.mu};
    auto big = [](const DslSubsegment<I>& r) {
      return DslSubsegment<BigInt>{to_bigint(r.a), to_bigint(r.b), to_bigint(r.mu)};
    };
    try {
      I a = int_cast<I>(c.a), b = int_cast<I>(c.b), mu = int_cast<I>(c.mu);
      I x0 = int_cast<I>(c.x0), x1 = int_cast<I>(c.x1);
      RC_ASSERT(big(subsegment_top_down(a, b, mu, x0, x1)) == w);
      RC_ASSERT(big(subsegment_bottom_up(a, b, mu, x0, x1)) == w);
      RC_ASSERT(big(subsegment_reversed_smart_dss(a, b, mu, x0, x1)) == w);
    } catch (const OverflowError&) {
      RC_ASSERT((!std::same_as<I, BigInt>));
    }
    RC_ASSERT(dsl_subsegment_exact(c.a, c.b, c.mu, c.x0, c.x1).value == w);
  });
}

// Values near 2^62 and windows up to 2^61 points (too long to enumerate): the reversed climb
// equals both floor-sum searches.
TYPED_TEST(DslSubsegmentTest, ReversedClimbEqualsSearchesNearTwoTo62) {
  using I = TypeParam;
  check_property([] {
    std::int64_t b = *test::int64_in(std::int64_t{1} << 61, std::int64_t{1} << 62);
    std::int64_t a = *test::int64_in(0, b - 1);
    std::int64_t lim = std::int64_t{1} << 62;
    std::int64_t mu = *test::int64_in(-lim, lim), x0 = *test::int64_in(-lim, lim);
    int k = *rc::gen::inRange(0, 62);
    std::int64_t len = *test::int64_in(0, std::int64_t{1} << k);
    BigInt x1 = BigInt(x0) + len;
    auto want = subsegment_top_down(BigInt(a), BigInt(b), BigInt(mu), BigInt(x0), x1);
    RC_ASSERT(subsegment_bottom_up(BigInt(a), BigInt(b), BigInt(mu), BigInt(x0), x1) == want);
    try {
      auto r = subsegment_reversed_smart_dss(I(a), I(b), I(mu), I(x0), int_cast<I>(x1));
      RC_ASSERT((DslSubsegment<BigInt>{to_bigint(r.a), to_bigint(r.b), to_bigint(r.mu)}) == want);
    } catch (const OverflowError&) {
      RC_ASSERT((std::same_as<I, Int64>));
    }
  });
}

// Exhaustive on small lines: every 0 <= a < b <= 9 (6 under sanitizers), every offset and
// every window of up to 2 b + 2 points; the reversed climb equals recognition of the points.
TEST(DslSubsegment, ReversedClimbExhaustiveOnSmallLines) {
  const std::int64_t max_b = std::getenv("ZDG_SANITIZE") != nullptr ? 6 : 9;
  for (std::int64_t b = 1; b <= max_b; ++b) {
    for (std::int64_t a = 0; a < b; ++a) {
      for (std::int64_t mu = -b; mu < b; ++mu) {
        for (std::int64_t x0 = -3; x0 < b; ++x0) {
          for (std::int64_t len = 0; len <= 2 * b + 2; ++len) {
            auto want = recognized(BigInt(a), BigInt(b), BigInt(mu), BigInt(x0), BigInt(x0 + len));
            auto r = subsegment_reversed_smart_dss(Int64(a), Int64(b), Int64(mu), Int64(x0),
                                                   Int64(x0 + len));
            ASSERT_EQ((DslSubsegment<BigInt>{to_bigint(r.a), to_bigint(r.b), to_bigint(r.mu)}),
                      (DslSubsegment<BigInt>{want.a, want.b, want.mu}))
                << a << "/" << b << " mu " << mu << " x " << x0 << ".." << x0 + len;
          }
        }
      }
    }
  }
}

// Shrunk counterexample of a first draft: the window holds two upper leaning points of a/b
// (x = -997, -994), so a/b itself is the answer although no earlier node of its run fits.
TEST(DslSubsegment, RegressionAnswerIsTheInputSlope) {
  EXPECT_EQ(
      subsegment_reversed_smart_dss(Int64(1), Int64(3), Int64(-1000), Int64(-999), Int64(-994)),
      (DslSubsegment<Int64>{1, 3, -1000}));
}

// The same line written with a common factor g: (g a, g b, mu') with ceil(mu'/g) = mu.
TEST(DslSubsegment, NonReducedLinesGiveTheSameAnswer) {
  check_property([] {
    Case c = random_case(false);
    std::int64_t g = *test::int64_in(2, 7), t = *test::int64_in(0, g - 1);
    BigInt mu2 = c.mu * g - t; // ceil(mu2 / g) = mu
    auto r1 = dsl_subsegment_exact(c.a, c.b, c.mu, c.x0, c.x1).value;
    auto r2 = dsl_subsegment_exact(c.a * g, c.b * g, mu2, c.x0, c.x1).value;
    RC_ASSERT(r1 == r2);
  });
}

TEST(DslSubsegment, WorkedExamples) {
  // Slope 3/7: 8 points from a leaning point hold a full period.
  EXPECT_EQ(subsegment_top_down(Int64(3), Int64(7), Int64(0), Int64(0), Int64(7)),
            (DslSubsegment<Int64>{3, 7, 0}));
  // y = floor(3x/7) on x = 0..2 is (0,0),(1,0),(2,0): horizontal.
  EXPECT_EQ(subsegment_bottom_up(Int64(3), Int64(7), Int64(0), Int64(0), Int64(2)),
            (DslSubsegment<Int64>{0, 1, 0}));
  // x = 0..3: (0,0),(1,0),(2,0),(3,1): slope 1/3, mu = 0.
  EXPECT_EQ(subsegment_top_down(Int64(3), Int64(7), Int64(0), Int64(0), Int64(3)),
            (DslSubsegment<Int64>{1, 3, 0}));
  // One point.
  EXPECT_EQ(subsegment_top_down(Int64(3), Int64(7), Int64(0), Int64(5), Int64(5)),
            (DslSubsegment<Int64>{0, 1, -2}));
  // The same with the reversed climb; x = 2..4 of slope 2/5: (2,0),(3,1),(4,1), slope 1/2.
  EXPECT_EQ(subsegment_reversed_smart_dss(Int64(3), Int64(7), Int64(0), Int64(0), Int64(7)),
            (DslSubsegment<Int64>{3, 7, 0}));
  EXPECT_EQ(subsegment_reversed_smart_dss(Int64(3), Int64(7), Int64(0), Int64(0), Int64(3)),
            (DslSubsegment<Int64>{1, 3, 0}));
  EXPECT_EQ(subsegment_reversed_smart_dss(Int64(2), Int64(5), Int64(0), Int64(2), Int64(4)),
            (DslSubsegment<Int64>{1, 2, 1}));
}

TEST(DslSubsegment, RejectsBadArguments) {
  EXPECT_THROW(subsegment_top_down(Int64(1), Int64(0), Int64(0), Int64(0), Int64(1)),
               InvalidArgument);
  EXPECT_THROW(subsegment_top_down(Int64(5), Int64(5), Int64(0), Int64(0), Int64(1)),
               InvalidArgument);
  EXPECT_THROW(subsegment_bottom_up(Int64(1), Int64(3), Int64(0), Int64(2), Int64(1)),
               InvalidArgument);
  EXPECT_THROW(subsegment_reversed_smart_dss(Int64(-1), Int64(3), Int64(0), Int64(0), Int64(1)),
               InvalidArgument);
}

// Values near 2^62 and a window of 2^61 points: answered exactly (escalating as needed).
TEST(DslSubsegment, HugeValues) {
  BigInt b = (BigInt(1) << 62) - 57, a = (BigInt(1) << 61) + 12345;
  BigInt x0 = (BigInt(1) << 62) - 3, x1 = x0 + (BigInt(1) << 61);
  auto r = dsl_subsegment_exact(a, b, BigInt(17), x0, x1);
  auto r2 = subsegment_bottom_up(a, b, BigInt(17), x0, x1);
  EXPECT_EQ(r.value, r2);
  EXPECT_EQ(subsegment_top_down(a, b, BigInt(17), x0, x1), r2);
  EXPECT_GT(r.value.b, 0);
  EXPECT_LE(r.value.b, b);
}

} // namespace
