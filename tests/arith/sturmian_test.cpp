#include <zdg/arith/sturmian.hpp>

#include "tests/support/tower.hpp"
#include <zdg/arith/christoffel.hpp>
#include <zdg/arith/error.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <set>
#include <string>
#include <vector>

namespace zdg {
namespace {

template <class I>
class SturmianTyped : public ::testing::Test {};
TYPED_TEST_SUITE(SturmianTyped, test::TowerTypes, test::TowerNames);

struct SurdInput {
  std::int64_t a, b, d, c;
};

// A random surd (a + b sqrt d)/c: small entries, d not a square.
SurdInput random_surd() {
  const auto d = *rc::gen::suchThat(rc::gen::inRange<std::int64_t>(2, 400), [](std::int64_t v) {
    const auto s = static_cast<std::int64_t>(std::sqrt(static_cast<double>(v)));
    for (auto t = std::max<std::int64_t>(0, s - 1); t <= s + 1; ++t) {
      if (t * t == v) return false;
    }
    return true;
  });
  const auto b = *rc::gen::suchThat(rc::gen::inRange<std::int64_t>(-5, 6),
                                    [](std::int64_t v) { return v != 0; });
  const auto c = *rc::gen::suchThat(rc::gen::inRange<std::int64_t>(-30, 31),
                                    [](std::int64_t v) { return v != 0; });
  return {*rc::gen::inRange<std::int64_t>(-50, 51), b, d, c};
}

// The oracle of the round trip: x = (r + t sqrt(Delta)) / w from the expansion, tested against
// x0 = (P + sqrt D) / Q: x is a root of Q^2 X^2 - 2 P Q X + P^2 - D (both parts in Q(sqrt
// Delta) vanish) and the same root (the irrational parts have the same sign).
bool expansion_evaluates_to(const PeriodicContinuedFraction<BigInt>& cf,
                            const QuadraticSurd<BigInt>& x0) {
  auto product = [](const std::vector<BigInt>& terms) {
    BigInt m00 = 1, m01 = 0, m10 = 0, m11 = 1;
    for (const auto& a : terms) {
      // M * [[a, 1], [1, 0]]
      BigInt n00 = m00 * a + m01, n10 = m10 * a + m11;
      m01 = m00;
      m11 = m10;
      m00 = n00;
      m10 = n10;
    }
    return std::vector<BigInt>{m00, m01, m10, m11};
  };
  // The purely periodic tail y = (A y + B)/(C y + E): C y^2 + (E - A) y - B = 0, y > 1.
  const auto M = product(cf.period);
  const BigInt A = M[0], B = M[1], C = M[2], E = M[3];
  const BigInt Delta = (E - A) * (E - A) + 4 * B * C;
  // y = (A - E + sqrt Delta) / (2C); x = (p y + p') / (q y + q') with the preperiod's matrix.
  const auto N = product(cf.preperiod);
  const BigInt u1 = N[0] * (A - E) + 2 * C * N[1], v1 = N[0];
  const BigInt u2 = N[2] * (A - E) + 2 * C * N[3], v2 = N[2];
  // x = (u1 + v1 s) / (u2 + v2 s) = (r + t s) / w, s = sqrt(Delta).
  const BigInt r = u1 * u2 - v1 * v2 * Delta, t = v1 * u2 - u1 * v2, w = u2 * u2 - v2 * v2 * Delta;
  if (w == 0) return false;
  // Q^2 x^2 - 2PQ x + P^2 - D, times w^2: rational part and sqrt(Delta) part.
  const BigInt &P = x0.P, &D = x0.D, &Q = x0.Q;
  const BigInt rat = Q * Q * (r * r + t * t * Delta) - 2 * P * Q * r * w + (P * P - D) * w * w;
  const BigInt irr = Q * Q * 2 * r * t - 2 * P * Q * t * w;
  if (rat != 0 || irr != 0) return false;
  return (t * w > 0) == (Q > 0);
}

// Theorem (Lagrange 1770; Euler): the continued fraction of a quadratic surd is eventually
// periodic, and the periodic expansion evaluates back to the surd (exact oracle above).
TYPED_TEST(SturmianTyped, PeriodicExpansionEvaluatesBackToTheSurd) {
  using I = TypeParam;
  test::check_property([] {
    const auto s = random_surd();
    const auto x = make_surd<I>(I(s.a), I(s.b), I(s.d), I(s.c));
    const auto cf = periodic_continued_fraction(x);
    RC_ASSERT(!cf.period.empty());
    PeriodicContinuedFraction<BigInt> big;
    for (const auto& t : cf.preperiod) big.preperiod.push_back(to_bigint(t));
    for (const auto& t : cf.period) big.period.push_back(to_bigint(t));
    const QuadraticSurd<BigInt> xb{to_bigint(x.P), to_bigint(x.D), to_bigint(x.Q)};
    RC_ASSERT(expansion_evaluates_to(big, xb));
    // Every term after the first is positive.
    for (std::size_t k = 1; k < big.preperiod.size() + big.period.size(); ++k) {
      RC_ASSERT(big.term(k) >= 1);
    }
    // The exact form agrees with the typed one.
    const auto e = periodic_continued_fraction_exact(s.a, s.b, s.d, s.c);
    RC_ASSERT(e.value.preperiod == big.preperiod);
    RC_ASSERT(e.value.period == big.period);
  });
}

// Theorem (Legendre): sqrt(d) = [s; (a_1, ..., a_{m-1}, 2s)] with a_1 .. a_{m-1} a palindrome;
// Galois: the reduced surd s + sqrt(d) is purely periodic.
TYPED_TEST(SturmianTyped, SquareRootsArePalindromicAndReducedSurdsPurelyPeriodic) {
  using I = TypeParam;
  test::check_property([] {
    const auto s0 = random_surd();
    const I d(s0.d);
    const auto cf = periodic_continued_fraction(make_surd<I>(I(0), I(1), d, I(1)));
    const I s = isqrt(d);
    RC_ASSERT(cf.preperiod == std::vector<I>{s});
    RC_ASSERT(cf.period.back() == I(2) * s);
    std::vector<I> mid(cf.period.begin(), cf.period.end() - 1);
    RC_ASSERT(std::equal(mid.begin(), mid.end(), mid.rbegin()));
    const auto reduced = periodic_continued_fraction(make_surd<I>(s, I(1), d, I(1)));
    RC_ASSERT(reduced.preperiod.empty());
  });
}

// floor(k x) by isqrt against the floor of an exact comparison: m <= k x < m + 1 checked as
// inequalities between integers and k^2 D (squares compared with their signs).
TYPED_TEST(SturmianTyped, FloorMultipleIsTheFloor) {
  using I = TypeParam;
  test::check_property([] {
    const auto s = random_surd();
    const auto x = make_surd<I>(I(s.a), I(s.b), I(s.d), I(s.c));
    const auto k = *rc::gen::inRange<std::int64_t>(-1000, 1001);
    const BigInt m = to_bigint(floor_multiple(x, I(k)));
    const BigInt P = to_bigint(x.P), D = to_bigint(x.D), Q = to_bigint(x.Q);
    // k x >= m  <=>  sign(Q) (kP + sign(k) sqrt(k^2 D) - mQ) >= 0; compare u + sigma sqrt(v).
    auto sign_of = [](const BigInt& u, int sigma, const BigInt& v) {
      // sign of u + sigma sqrt(v), v >= 0 not a square unless 0
      if (sigma == 0 || v == 0) return u > 0 ? 1 : (u < 0 ? -1 : 0);
      if (u >= 0 && sigma > 0) return 1;
      if (u <= 0 && sigma < 0) return -1;
      const BigInt u2 = u * u;
      if (sigma > 0) return u2 > v ? -1 : 1; // u < 0
      return u2 > v ? 1 : -1;                // u > 0
    };
    const int sig = k > 0 ? 1 : (k < 0 ? -1 : 0);
    const BigInt v = BigInt(k) * k * D;
    const int qs = Q > 0 ? 1 : -1;
    RC_ASSERT(qs * sign_of(BigInt(k) * P - m * Q, sig, v) >= 0);
    RC_ASSERT(qs * sign_of(BigInt(k) * P - (m + 1) * Q, sig, v) < 0);
  });
}

// A random slope in (0, 1): the fractional part of a random surd.
template <class I>
QuadraticSurd<I> random_slope() {
  const auto s = random_surd();
  return fractional_part(make_surd<I>(I(s.a), I(s.b), I(s.d), I(s.c)));
}

// Theorem (Lothaire, Prop. 2.2.24): the standard words of alpha's continued fraction are
// prefixes of the characteristic word floor((n + 1) alpha) - floor(n alpha).
TYPED_TEST(SturmianTyped, StandardWordsArePrefixesOfTheCharacteristicWord) {
  using I = TypeParam;
  test::check_property([] {
    const auto alpha = random_slope<I>();
    const auto n = static_cast<std::size_t>(*rc::gen::inRange(0, 400));
    const auto cf = periodic_continued_fraction(alpha);
    RC_ASSERT(standard_word_prefix(cf, n) == characteristic_word(alpha, n));
  });
}

// Theorems (Morse, Hedlund 1940): a Sturmian word is balanced (two factors of one length hold
// numbers of 1 that differ by at most 1) and has exactly n + 1 factors of length n. On a finite
// prefix the count is at most n + 1, and n + 1 once the prefix holds every factor (checked when
// the partial quotients are small, so that every factor of length <= 6 occurs in 4000 letters).
TYPED_TEST(SturmianTyped, BalancedWithComplexityNPlusOne) {
  using I = TypeParam;
  test::check_property([] {
    const auto alpha = random_slope<I>();
    const auto cf = periodic_continued_fraction(alpha);
    const std::string w = standard_word_prefix(cf, 4000);
    for (std::size_t len = 1; len <= 30; ++len) {
      std::size_t lo = len, hi = 0;
      for (std::size_t i = 0; i + len <= 400; ++i) {
        const auto ones =
            static_cast<std::size_t>(std::count(w.begin() + i, w.begin() + i + len, '1'));
        lo = std::min(lo, ones);
        hi = std::max(hi, ones);
      }
      RC_ASSERT(hi - lo <= 1);
    }
    bool small = true;
    for (std::size_t k = 0; k < 10; ++k) small = small && cf.term(k) <= 8;
    for (std::size_t len = 1; len <= 6; ++len) {
      std::set<std::string> factors;
      for (std::size_t i = 0; i + len <= w.size(); ++i) factors.insert(w.substr(i, len));
      RC_ASSERT(factors.size() <= len + 1);
      if (small) RC_ASSERT(factors.size() == len + 1);
    }
  });
}

// Theorem (best approximation of the convergents; Berstel et al. 2008, ch. 2): for each
// convergent p/q of alpha (q >= 2), the lower Christoffel word of slope p/(q - p) is 0 w 1 with w
// the prefix of length q - 2 of the characteristic word.
TYPED_TEST(SturmianTyped, ChristoffelConvergentsAreCentralPrefixes) {
  using I = TypeParam;
  test::check_property([] {
    const auto alpha = random_slope<I>();
    const auto cf = periodic_continued_fraction(alpha);
    const std::string c = characteristic_word(alpha, 600);
    for (const auto& [p, q] : surd_convergents(cf, 12)) {
      if (q < 2 || q > 600 || p < 1) continue;
      const std::string word = lower_christoffel_word(p, I(q - p));
      const auto length = static_cast<std::size_t>(std::stoll(to_string(q)));
      std::string expect = "0"; // appended (GCC 12 warns falsely on "0" + std::string&&)
      expect.append(c, 0, length - 2).append("1");
      RC_ASSERT(word == expect);
    }
  });
}

TEST(Sturmian, WorkedExamples) {
  auto cf = [](std::int64_t a, std::int64_t b, std::int64_t d, std::int64_t c) {
    return periodic_continued_fraction_exact(a, b, d, c).value;
  };
  using V = std::vector<BigInt>;
  EXPECT_EQ(cf(0, 1, 2, 1).preperiod, V{1});
  EXPECT_EQ(cf(0, 1, 2, 1).period, V{2});                // sqrt 2 = [1; (2)]
  EXPECT_EQ(cf(0, 1, 3, 1).period, (V{1, 2}));           // sqrt 3 = [1; (1, 2)]
  EXPECT_EQ(cf(0, 1, 7, 1).period, (V{1, 1, 1, 4}));     // sqrt 7 = [2; (1, 1, 1, 4)]
  EXPECT_EQ(cf(0, 1, 13, 1).period, (V{1, 1, 1, 1, 6})); // sqrt 13 = [3; (1, 1, 1, 1, 6)]
  EXPECT_EQ(cf(1, 1, 5, 2).preperiod, V{});              // the golden ratio = [(1)]
  EXPECT_EQ(cf(1, 1, 5, 2).period, V{1});
  EXPECT_EQ(cf(3, -1, 5, 2).preperiod, (V{0, 2})); // 1/phi^2 = [0; 2, (1)]
  EXPECT_EQ(cf(3, -1, 5, 2).period, V{1});
  // The Fibonacci word is the characteristic word of slope 1/phi^2 = (3 - sqrt 5)/2.
  const auto alpha = make_surd<BigInt>(3, -1, 5, 2);
  EXPECT_EQ(characteristic_word(alpha, 34), "0100101001001010010100100101001001");
  EXPECT_EQ(standard_word_prefix(periodic_continued_fraction(alpha), 34),
            "0100101001001010010100100101001001");
  // Errors: a rational, a square, a zero denominator, a slope outside (0, 1).
  EXPECT_THROW(make_surd<Int64>(1, 0, 2, 1), InvalidArgument);
  EXPECT_THROW(make_surd<Int64>(1, 1, 9, 1), InvalidArgument);
  EXPECT_THROW(make_surd<Int64>(1, 1, 2, 0), InvalidArgument);
  EXPECT_THROW(make_surd<Int64>(1, 1, -2, 1), InvalidArgument);
  EXPECT_THROW(characteristic_word(make_surd<Int64>(0, 1, 2, 1), 5), InvalidArgument);
  EXPECT_THROW(standard_word_prefix(periodic_continued_fraction(make_surd<Int64>(0, 1, 2, 1)), 5),
               InvalidArgument);
  EXPECT_THROW(periodic_continued_fraction(make_surd<Int64>(0, 1, 1000003, 1), 10),
               InvalidArgument);
}

// Near 2^62: Int64 overflows (OverflowError, never a wrong term) and the exact form escalates;
// 4 sqrt(n^2 + 1) = sqrt(m^2 + 16) with m = 4n = 2^32 is [m; (2m/16, 2m)] (16 divides 2m).
TEST(Sturmian, LargeEntriesEscalate) {
  const std::int64_t n = std::int64_t{1} << 30, d = n * n + 1;
  EXPECT_THROW(periodic_continued_fraction(make_surd<Int64>(0, 4, d, 1)), OverflowError);
  const auto e = periodic_continued_fraction_exact(0, 4, d, 1);
  EXPECT_EQ(e.served, IntKind::int128);
  const BigInt m = BigInt(1) << 32;
  EXPECT_EQ(e.value.preperiod, std::vector<BigInt>{m});
  EXPECT_EQ(e.value.period, (std::vector<BigInt>{m / 8, 2 * m}));
  EXPECT_TRUE(expansion_evaluates_to(e.value, make_surd<BigInt>(0, 4, d, 1)));
}

} // namespace
} // namespace zdg
