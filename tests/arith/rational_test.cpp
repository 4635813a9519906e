#include <zdg/arith/rational.hpp>

#include "tests/support/tower.hpp"

#include <string>

namespace {

using namespace zdg;
using test::check_property;

template <class I>
class RationalTest : public ::testing::Test {};
TYPED_TEST_SUITE(RationalTest, test::TowerTypes, test::TowerNames);

// Invariant: every rational is reduced with a positive denominator, and the field operations
// agree with cross-multiplication in BigInt.
TYPED_TEST(RationalTest, ReducedAndFieldOperationsExact) {
  using I = TypeParam;
  check_property([] {
    auto small = test::int64_in(-1'000'000, 1'000'000);
    std::int64_t a = *small, b = *small, c = *small, d = *small;
    RC_PRE(b != 0 && d != 0);
    Rational<I> x{I(a), I(b)}, y{I(c), I(d)};
    for (const auto& r : {x, y, x + y, x - y, x * y}) {
      RC_ASSERT(r.den() > 0);
      RC_ASSERT(gcd(r.num(), r.den()) == 1);
    }
    auto same = [](const Rational<I>& r, const BigInt& num, const BigInt& den) {
      return to_bigint(r.num()) * den == num * to_bigint(r.den());
    };
    BigInt A(a), B(b), C(c), D(d);
    RC_ASSERT(same(x + y, A * D + C * B, B * D));
    RC_ASSERT(same(x - y, A * D - C * B, B * D));
    RC_ASSERT(same(x * y, A * C, B * D));
    if (c != 0) RC_ASSERT(same(x / y, A * D, B * C));
    const int s = B * D > 0 ? 1 : -1;
    const bool less = x < y;
    RC_ASSERT(less == (A * D * s < C * B * s));
    RC_ASSERT(to_bigint(x.floor()) == floor_div(A, B));
  });
}

TYPED_TEST(RationalTest, ParsingWorkedExamples) {
  using I = TypeParam;
  EXPECT_EQ(parse_rational<I>("7"), Rational<I>(7));
  EXPECT_EQ(parse_rational<I>("-3/4"), Rational<I>(I(-3), I(4)));
  EXPECT_EQ(parse_rational<I>("6/-8").str(), "-3/4");
  EXPECT_EQ(parse_rational<I>("1000.5"), Rational<I>(I(2001), I(2)));
  EXPECT_EQ(parse_rational<I>("-.25"), Rational<I>(I(-1), I(4)));
  EXPECT_EQ(parse_rational<I>("3."), Rational<I>(3));
  EXPECT_THROW(parse_rational<I>("5/0"), InvalidArgument);
  EXPECT_THROW(parse_rational<I>("x/3"), InvalidArgument);
  EXPECT_THROW(parse_rational<I>("1.2.3"), InvalidArgument);
  EXPECT_THROW(parse_rational<I>("."), InvalidArgument);
  EXPECT_THROW(parse_rational<I>(""), InvalidArgument);
  EXPECT_THROW(Rational<I>(I(1), I(0)), InvalidArgument);
}

// Theorem: rational text is decimal: "P/Q" with any leading zeros on P and Q is P/Q reduced,
// and "I.F" is (I F read as one integer) / 10^|F|, for every type (oracle: the int64 values
// and their reduction by BigInt cross-multiplication).
TYPED_TEST(RationalTest, TextIsDecimalWhateverTheLeadingZeros) {
  using I = TypeParam;
  check_property([] {
    const std::int64_t p = *test::int64_in(-1'000'000'000, 1'000'000'000);
    const std::int64_t q = *test::int64_in(1, 1'000'000'000);
    const auto zp = static_cast<std::size_t>(*rc::gen::inRange(0, 4));
    const auto zq = static_cast<std::size_t>(*rc::gen::inRange(0, 4));
    const std::string ps = std::to_string(p < 0 ? -p : p);
    const std::string text = (p < 0 ? "-" : "") + std::string(zp, '0') + ps + "/" +
                             std::string(zq, '0') + std::to_string(q);
    const Rational<I> r = parse_rational<I>(text);
    RC_ASSERT(to_bigint(r.num()) * BigInt(q) == BigInt(p) * to_bigint(r.den()));
    // The same digits with a decimal point: p / 10^k.
    const auto k = static_cast<std::size_t>(*rc::gen::inRange(0, 6));
    std::string digits = std::string(zp + k, '0') + ps;
    digits.insert(digits.size() - k, ".");
    const Rational<I> d = parse_rational<I>((p < 0 ? "-" : "") + digits);
    BigInt ten_k = 1;
    for (std::size_t i = 0; i < k; ++i) ten_k *= 10;
    RC_ASSERT(to_bigint(d.num()) * ten_k == BigInt(p) * to_bigint(d.den()));
  });
}

// Found by the number fuzz target (tests/fuzz/regressions/number/): a numerator too large for
// int64 with a malformed denominator was OverflowError on Int64 but InvalidArgument on BigInt;
// the syntax is now decided first, the same for every type.
TYPED_TEST(RationalTest, RegressionMalformedTextIsInvalidForEveryTypeEvenWhenAPartOverflows) {
  using I = TypeParam;
  EXPECT_THROW(parse_rational<I>("17014118346046923173713/6037158841\x9a"
                                 "05720"),
               InvalidArgument);
  EXPECT_THROW(parse_rational<I>("1701411834604692317371317014118346046923173713/x"),
               InvalidArgument);
  // The second finding: a zero denominator after a numerator beyond int64.
  EXPECT_THROW(parse_rational<I>("-92233753284607758088/0"), InvalidArgument);
  EXPECT_THROW(parse_rational<I>("99999999999999999999999999999999999999999/-000"),
               InvalidArgument);
}

// Issue #18: "010/3" was read as 8/3 (octal) by the BigInt parser.
TYPED_TEST(RationalTest, RegressionLeadingZerosAreDecimal) {
  using I = TypeParam;
  EXPECT_EQ(parse_rational<I>("010/3"), Rational<I>(I(10), I(3)));
  EXPECT_EQ(parse_rational<I>("09/08"), Rational<I>(I(9), I(8)));
  EXPECT_EQ(parse_rational<I>("0.010"), Rational<I>(I(1), I(100)));
  EXPECT_EQ(parse_rational<I>("-007.50"), Rational<I>(I(-15), I(2)));
  EXPECT_THROW(parse_rational<I>("0x10"), InvalidArgument);
  EXPECT_THROW(parse_rational<I>("1e3"), InvalidArgument);
  EXPECT_THROW(parse_rational<I>("1/ 2"), InvalidArgument);
  EXPECT_THROW(parse_rational<I>("1.-2"), InvalidArgument);
}

} // namespace
