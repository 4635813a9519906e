// DSL subsegments: SmartDSS (top-down), the reversed climb (ReversedSmartDSS) and the two
// floor-sum searches agree with each other and with DSS recognition of the enumerated points
// (itself checked against brute force), on every tower type, for small values and for values
// near 2^62; the answer does not depend on how the line is written (non-reduced a, b).
#include <zdg/arith/dsl_subsegment.hpp>

#include "tests/support/check_registry.hpp"
#include "tests/support/tower.hpp"
#include <zdg/arith/dss_recognizer.hpp>

#include <algorithm>
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
      RC_ASSERT(big(subsegment_top_down_search(a, b, mu, x0, x1)) == w);
      RC_ASSERT(big(subsegment_bottom_up(a, b, mu, x0, x1)) == w);
      RC_ASSERT(big(subsegment_reversed_smart_dss(a, b, mu, x0, x1)) == w);
      RC_ASSERT(big(subsegment_smart_dss(a, b, mu, x0, x1)) == w);
    } catch (const OverflowError&) {
      RC_ASSERT((!std::same_as<I, BigInt>));
    }
    RC_ASSERT(dsl_subsegment_exact(c.a, c.b, c.mu, c.x0, c.x1).value == w);
    RC_ASSERT(
        dsl_subsegment_exact(c.a, c.b, c.mu, c.x0, c.x1, DslSubsegmentAlgorithm::smart_dss).value ==
        w);
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
    auto want = subsegment_top_down_search(BigInt(a), BigInt(b), BigInt(mu), BigInt(x0), x1);
    RC_ASSERT(subsegment_bottom_up(BigInt(a), BigInt(b), BigInt(mu), BigInt(x0), x1) == want);
    try {
      auto r = subsegment_reversed_smart_dss(I(a), I(b), I(mu), I(x0), int_cast<I>(x1));
      RC_ASSERT((DslSubsegment<BigInt>{to_bigint(r.a), to_bigint(r.b), to_bigint(r.mu)}) == want);
    } catch (const OverflowError&) {
      RC_ASSERT((std::same_as<I, Int64>));
    }
  });
}

// A slope a/b in [0, 1) with long runs in its Stern-Brocot path (close to a simple fraction
// u/v, or to 0 or 1) half of the time, else uniform.
std::int64_t random_numerator(std::int64_t b) {
  if (*rc::gen::arbitrary<bool>()) return *test::int64_in(0, b - 1);
  std::int64_t v = *test::int64_in(1, 6), u = *test::int64_in(0, v);
  std::int64_t a = b / v * u + *test::int64_in(-3, 3);
  return std::clamp(a, std::int64_t{0}, b - 1);
}

// SmartDSS equals the reversed climb (each checked against recognition above) on lines with
// a, b, mu, x0 near 2^62 (or of moderate size, where windows of up to 2 b + 3 points hold
// every case) and windows up to 2^62 points; on Int64, an overflow is reported, never a
// wrong answer.
TYPED_TEST(DslSubsegmentTest, SmartDssEqualsReversedClimbOnLargeValues) {
  using I = TypeParam;
  check_property([] {
    const bool huge = *rc::gen::arbitrary<bool>();
    std::int64_t b = huge ? *test::int64_in(std::int64_t{1} << 61, std::int64_t{1} << 62)
                          : *test::int64_in(1, 1000000);
    std::int64_t a = random_numerator(b);
    std::int64_t lim = std::int64_t{1} << 62;
    std::int64_t mu = *test::int64_in(-lim, lim), x0 = *test::int64_in(-lim, lim);
    std::int64_t len;
    if (huge) {
      len = *test::int64_in(0, std::int64_t{1} << *rc::gen::inRange(0, 62));
    } else {
      len = *test::int64_in(0, 2 * b + 3);
    }
    BigInt x1 = BigInt(x0) + len;
    auto want = subsegment_reversed_smart_dss(BigInt(a), BigInt(b), BigInt(mu), BigInt(x0), x1);
    try {
      auto r = subsegment_smart_dss(I(a), I(b), I(mu), I(x0), int_cast<I>(x1));
      RC_ASSERT((DslSubsegment<BigInt>{to_bigint(r.a), to_bigint(r.b), to_bigint(r.mu)}) == want);
    } catch (const OverflowError&) {
      RC_ASSERT((std::same_as<I, Int64>));
    }
  });
}

// Exhaustive on small lines: every 0 <= a < b <= 9 (6 under sanitizers), every offset and
// every window of up to 2 b + 2 points; SmartDSS and the reversed climb equal recognition of
// the points.
TEST(DslSubsegment, SmartDssAndReversedClimbExhaustiveOnSmallLines) {
  const std::int64_t max_b = std::getenv("ZDG_SANITIZE") != nullptr ? 6 : 9;
  for (std::int64_t b = 1; b <= max_b; ++b) {
    for (std::int64_t a = 0; a < b; ++a) {
      for (std::int64_t mu = -b; mu < b; ++mu) {
        for (std::int64_t x0 = -3; x0 < b; ++x0) {
          for (std::int64_t len = 0; len <= 2 * b + 2; ++len) {
            auto want = recognized(BigInt(a), BigInt(b), BigInt(mu), BigInt(x0), BigInt(x0 + len));
            DslSubsegment<Int64> w{int_cast<Int64>(want.a), int_cast<Int64>(want.b),
                                   int_cast<Int64>(want.mu)};
            ASSERT_EQ(subsegment_reversed_smart_dss(Int64(a), Int64(b), Int64(mu), Int64(x0),
                                                    Int64(x0 + len)),
                      w)
                << a << "/" << b << " mu " << mu << " x " << x0 << ".." << x0 + len;
            ASSERT_EQ(
                subsegment_smart_dss(Int64(a), Int64(b), Int64(mu), Int64(x0), Int64(x0 + len)), w)
                << "SmartDSS " << a << "/" << b << " mu " << mu << " x " << x0 << ".." << x0 + len;
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
    auto r3 =
        dsl_subsegment_exact(c.a * g, c.b * g, mu2, c.x0, c.x1, DslSubsegmentAlgorithm::smart_dss)
            .value;
    RC_ASSERT(r1 == r3);
  });
}

TEST(DslSubsegment, WorkedExamples) {
  // Slope 3/7: 8 points from a leaning point hold a full period.
  EXPECT_EQ(subsegment_top_down_search(Int64(3), Int64(7), Int64(0), Int64(0), Int64(7)),
            (DslSubsegment<Int64>{3, 7, 0}));
  // y = floor(3x/7) on x = 0..2 is (0,0),(1,0),(2,0): horizontal.
  EXPECT_EQ(subsegment_bottom_up(Int64(3), Int64(7), Int64(0), Int64(0), Int64(2)),
            (DslSubsegment<Int64>{0, 1, 0}));
  // x = 0..3: (0,0),(1,0),(2,0),(3,1): slope 1/3, mu = 0.
  EXPECT_EQ(subsegment_top_down_search(Int64(3), Int64(7), Int64(0), Int64(0), Int64(3)),
            (DslSubsegment<Int64>{1, 3, 0}));
  // One point.
  EXPECT_EQ(subsegment_top_down_search(Int64(3), Int64(7), Int64(0), Int64(5), Int64(5)),
            (DslSubsegment<Int64>{0, 1, -2}));
  // The same with the reversed climb; x = 2..4 of slope 2/5: (2,0),(3,1),(4,1), slope 1/2.
  EXPECT_EQ(subsegment_reversed_smart_dss(Int64(3), Int64(7), Int64(0), Int64(0), Int64(7)),
            (DslSubsegment<Int64>{3, 7, 0}));
  EXPECT_EQ(subsegment_reversed_smart_dss(Int64(3), Int64(7), Int64(0), Int64(0), Int64(3)),
            (DslSubsegment<Int64>{1, 3, 0}));
  EXPECT_EQ(subsegment_reversed_smart_dss(Int64(2), Int64(5), Int64(0), Int64(2), Int64(4)),
            (DslSubsegment<Int64>{1, 2, 1}));
}

// SmartDSS on hand-checked windows, including whole Stern-Brocot runs crossed in one jump.
TEST(DslSubsegment, SmartDssWorkedExamples) {
  // Slope 3/7 from an upper leaning point: the prefixes read 0/1, 1/3, 2/5, then 3/7 at
  // x = 7 (the first point above 2/5 x is (7, 3)).
  EXPECT_EQ(subsegment_smart_dss(Int64(3), Int64(7), Int64(0), Int64(0), Int64(2)),
            (DslSubsegment<Int64>{0, 1, 0}));
  EXPECT_EQ(subsegment_smart_dss(Int64(3), Int64(7), Int64(0), Int64(0), Int64(4)),
            (DslSubsegment<Int64>{1, 3, 0}));
  EXPECT_EQ(subsegment_smart_dss(Int64(3), Int64(7), Int64(0), Int64(0), Int64(6)),
            (DslSubsegment<Int64>{2, 5, 0}));
  EXPECT_EQ(subsegment_smart_dss(Int64(3), Int64(7), Int64(0), Int64(0), Int64(7)),
            (DslSubsegment<Int64>{3, 7, 0}));
  // y = floor(99 x / 100) on x = 0..50: (0,0), then (x, x - 1): 49 x - 50 y in [0, 50), the
  // run 1/2, 2/3, ..., 49/50 (path L R^48) crossed in one jump.
  EXPECT_EQ(subsegment_smart_dss(Int64(99), Int64(100), Int64(0), Int64(0), Int64(50)),
            (DslSubsegment<Int64>{49, 50, 0}));
  // y = floor((x + 99) / 100) on x = 0..50: (0,0), then (x, 1): x - 50 y in [-49, 0], the run
  // 1/2, 1/3, ..., 1/50 below the line (path L^49).
  EXPECT_EQ(subsegment_smart_dss(Int64(1), Int64(100), Int64(-99), Int64(0), Int64(50)),
            (DslSubsegment<Int64>{1, 50, -49}));
  // One point; a window holding two periods: the line itself.
  EXPECT_EQ(subsegment_smart_dss(Int64(3), Int64(7), Int64(0), Int64(5), Int64(5)),
            (DslSubsegment<Int64>{0, 1, -2}));
  EXPECT_EQ(subsegment_smart_dss(Int64(3), Int64(7), Int64(5), Int64(-20), Int64(20)),
            (DslSubsegment<Int64>{3, 7, 5}));
}

TEST(DslSubsegment, RejectsBadArguments) {
  EXPECT_THROW(subsegment_smart_dss(Int64(1), Int64(0), Int64(0), Int64(0), Int64(1)),
               InvalidArgument);
  EXPECT_THROW(subsegment_smart_dss(Int64(3), Int64(3), Int64(0), Int64(0), Int64(1)),
               InvalidArgument);
  EXPECT_THROW(subsegment_smart_dss(Int64(1), Int64(3), Int64(0), Int64(2), Int64(1)),
               InvalidArgument);
  EXPECT_THROW(subsegment_top_down_search(Int64(1), Int64(0), Int64(0), Int64(0), Int64(1)),
               InvalidArgument);
  EXPECT_THROW(subsegment_top_down_search(Int64(5), Int64(5), Int64(0), Int64(0), Int64(1)),
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
  EXPECT_EQ(subsegment_top_down_search(a, b, BigInt(17), x0, x1), r2);
  EXPECT_EQ(subsegment_smart_dss(a, b, BigInt(17), x0, x1), r2);
  EXPECT_EQ(dsl_subsegment_exact(a, b, BigInt(17), x0, x1, DslSubsegmentAlgorithm::smart_dss).value,
            r2);
  EXPECT_GT(r.value.b, 0);
  EXPECT_LE(r.value.b, b);
}

// The registered property dss.subsegment (zdg check): windows of up to 16 points of lines with
// parameters of up to 64, 128, 256 bits, against the brute-force minimal line of the points.
TYPED_TEST(DslSubsegmentTest, RegisteredSubsegmentHolds) {
  test::expect_registered_property("dss.subsegment", int_kind<TypeParam>(), 300);
}

} // namespace
