// floor_sum against the brute-force sum, for every sign, and at the int64 boundary.
#include <zdg/arith/floor_sum.hpp>

#include "tests/support/check_registry.hpp"
#include "tests/support/tower.hpp"

namespace {

using namespace zdg;
using test::check_property;

template <class I>
class FloorSum : public ::testing::Test {};
TYPED_TEST_SUITE(FloorSum, test::TowerTypes, test::TowerNames);

// Oracle: the brute-force sum of floor((a i + b) / m), i in [0, n), for every sign of m, a, b
// (the registered property floor_sum.oracle of zdg check: n <= 200, m, a, b of up to 64, 128,
// 256 bits by type, computed from that type upwards by escalation).
TYPED_TEST(FloorSum, EqualsBruteForceSum) {
  test::expect_registered_property("floor_sum.oracle", int_kind<TypeParam>(), 400);
}

// Exact by escalation: on arbitrary int64 inputs (results up to ~2^190) floor_sum_exact
// agrees with the closed reduction computed in BigInt, and int64 serves exactly when it
// does not overflow.
TEST(FloorSumExact, EscalatesAndAgreesWithBigInt) {
  check_property([] {
    std::int64_t n = *test::int64_in(0, std::numeric_limits<std::int64_t>::max());
    std::int64_t m = *test::edgy_int64(), a = *test::edgy_int64(), b = *test::edgy_int64();
    RC_PRE(m != 0);
    auto r = floor_sum_exact(BigInt(n), BigInt(m), BigInt(a), BigInt(b));
    RC_ASSERT(r.value == floor_sum(BigInt(n), BigInt(m), BigInt(a), BigInt(b)));
    if (r.served != IntKind::int64) {
      RC_ASSERT_THROWS_AS(floor_sum(Int64(n), Int64(m), Int64(a), Int64(b)), OverflowError);
    }
  });
}

TYPED_TEST(FloorSum, WorkedExamples) {
  using I = TypeParam;
  // AtCoder Library practice contest "Floor Sum" sample: (4, 10, 6, 3) -> 3, (6, 5, 4, 3) -> 13,
  // (1, 1, 0, 0) -> 0, (31415, 92653, 58979, 32384) -> 314095480.
  EXPECT_EQ(floor_sum(I(4), I(10), I(6), I(3)), 3);
  EXPECT_EQ(floor_sum(I(6), I(5), I(4), I(3)), 13);
  EXPECT_EQ(floor_sum(I(1), I(1), I(0), I(0)), 0);
  EXPECT_EQ(floor_sum(I(31415), I(92653), I(58979), I(32384)), 314095480);
  EXPECT_EQ(floor_sum(I(0), I(7), I(3), I(-5)), 0);
  EXPECT_THROW(floor_sum(I(-1), I(7), I(3), I(5)), InvalidArgument);
  EXPECT_THROW(floor_sum(I(1), I(0), I(3), I(5)), InvalidArgument);
}

TEST(FloorSumExact, Int64BoundaryServedByWiderTypes) {
  // sum_{i<2^62} floor((2^62 - 1) i / 3): about 2^184 / 6, far beyond int64 and int128.
  BigInt n = BigInt(1) << 62, a = n - 1;
  auto r = floor_sum_exact(n, BigInt(3), a, BigInt(0));
  EXPECT_EQ(r.served, IntKind::bigint);
  // 2^62 = 4^31 = 1 (mod 3), so 3 divides a = 2^62 - 1 and every term is exact:
  // the sum is a n (n - 1) / 6.
  EXPECT_EQ(r.value, a * n * (n - 1) / 6);
}

} // namespace
