#include <zdg/arith/escalate.hpp>

#include "tests/support/tower.hpp"

namespace {

using namespace zdg;

// The first type on which the computation does not overflow serves, and the value is exact.
TEST(Escalate, ServesOnTheNarrowestTypeThatDoesNotOverflow) {
  auto square = [](const BigInt& x) {
    return escalate([&]<class I>(std::type_identity<I>) {
      I v = int_cast<I>(x);
      return to_bigint(I(v * v));
    });
  };
  auto small = square(BigInt(3037000499)); // (2^63)^(1/2) rounded down: fits int64
  EXPECT_EQ(small.served, IntKind::int64);
  EXPECT_EQ(small.value, BigInt(3037000499) * 3037000499);
  auto mid = square(BigInt(3037000500));
  EXPECT_EQ(mid.served, IntKind::int128);
  auto big = square(BigInt(1) << 64);
  EXPECT_EQ(big.served, IntKind::bigint);
  EXPECT_EQ(big.value, BigInt(1) << 128);
  EXPECT_EQ(to_string(IntKind::int128), "int128");
}

TEST(Escalate, OtherErrorsPropagate) {
  EXPECT_THROW(
      escalate([]<class I>(std::type_identity<I>) -> int { throw InvalidArgument("bad input"); }),
      InvalidArgument);
  auto r = escalate_from(IntKind::int128,
                         []<class I>(std::type_identity<I>) { return std::string(int_name<I>()); });
  EXPECT_EQ(r.value, "int128");
}

} // namespace
