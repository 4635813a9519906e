// Christoffel words: the prefix-count convention, palindromic centre, reverse, balance,
// Lyndon property, standard factorization, conjugates.
#include <zdg/arith/christoffel.hpp>
#include <zdg/arith/escalate.hpp>

#include "tests/support/check_registry.hpp"
#include "tests/support/tower.hpp"

#include <algorithm>
#include <numeric>

namespace {

using namespace zdg;
using test::check_property;

template <class I>
class Christoffel : public ::testing::Test {};
TYPED_TEST_SUITE(Christoffel, test::TowerTypes, test::TowerNames);

// A random reduced slope p/q with p >= 0, q > 0 and p + q <= limit.
std::pair<std::int64_t, std::int64_t> gen_slope(std::int64_t limit) {
  std::int64_t q = *test::int64_in(1, limit - 1);
  std::int64_t p = *test::int64_in(0, limit - q);
  std::int64_t g = std::gcd(p, q);
  return {p / g, q / g};
}

int ones(const std::string& w, std::size_t from, std::size_t len) {
  return static_cast<int>(std::count(w.begin() + static_cast<std::ptrdiff_t>(from),
                                     w.begin() + static_cast<std::ptrdiff_t>(from + len), '1'));
}

// Convention (ARCHITECTURE.md, Conventions): q letters 0, p letters 1, and the prefix of length k
// has floor(k p / (p + q)) letters 1; the letter accessor and prefix count agree with the word.
TYPED_TEST(Christoffel, PrefixCountConvention) {
  using I = TypeParam;
  check_property([] {
    auto [p, q] = gen_slope(400);
    std::string w = lower_christoffel_word(I(p), I(q));
    RC_ASSERT(w.size() == static_cast<std::size_t>(p + q));
    RC_ASSERT(ones(w, 0, w.size()) == p);
    for (std::size_t k = 0; k <= w.size(); ++k) {
      RC_ASSERT(ones(w, 0, k) == (static_cast<std::int64_t>(k) * p) / (p + q));
      RC_ASSERT(christoffel_prefix_ones(I(p), I(q), I(static_cast<std::int64_t>(k))) ==
                I((static_cast<std::int64_t>(k) * p) / (p + q)));
    }
    std::size_t k = *rc::gen::inRange<std::size_t>(1, w.size() + 1);
    RC_ASSERT(christoffel_letter(I(p), I(q), I(static_cast<std::int64_t>(k))) == w[k - 1] - '0');
  });
}

// Theorem (Berstel et al., Prop. 1.6 / 4.2): for p, q > 0 the lower word is 0 w 1 with w a
// palindrome, and the upper word is 1 w 0, its reverse.
TYPED_TEST(Christoffel, CentralPalindromeAndUpperIsReverse) {
  using I = TypeParam;
  check_property([] {
    auto [p, q] = gen_slope(500);
    RC_PRE(p > 0);
    std::string lo = lower_christoffel_word(I(p), I(q));
    std::string up = upper_christoffel_word(I(p), I(q));
    RC_ASSERT(lo.front() == '0' && lo.back() == '1');
    std::string mid = lo.substr(1, lo.size() - 2);
    RC_ASSERT(std::equal(mid.begin(), mid.end(), mid.rbegin()));
    RC_ASSERT(up == "1" + mid + "0");
    RC_ASSERT(std::string(lo.rbegin(), lo.rend()) == up);
  });
}

// Theorem: Christoffel words are balanced (any two factors of the same length differ by at
// most one letter 1, circularly) and the lower word is a Lyndon word (strictly smaller than
// each of its proper conjugates); the upper word is one of its conjugates.
TYPED_TEST(Christoffel, BalancedLyndonAndConjugates) {
  using I = TypeParam;
  check_property([] {
    auto [p, q] = gen_slope(60);
    std::string w = lower_christoffel_word(I(p), I(q));
    std::string ww = w + w;
    for (std::size_t len = 1; len <= w.size(); ++len) {
      int lo = 1 << 30, hi = -1;
      for (std::size_t i = 0; i < w.size(); ++i) {
        int c = ones(ww, i, len);
        lo = std::min(lo, c);
        hi = std::max(hi, c);
      }
      RC_ASSERT(hi - lo <= 1);
    }
    bool upper_is_conjugate = false;
    std::string up = upper_christoffel_word(I(p), I(q));
    for (std::size_t k = 0; k < w.size(); ++k) {
      std::string c = conjugate(w, k);
      if (k > 0) RC_ASSERT(w < c);
      upper_is_conjugate = upper_is_conjugate || c == up;
    }
    RC_ASSERT(upper_is_conjugate);
  });
}

// Theorem (Borel-Laubie): the lower word is the product of the lower words of the two
// Stern-Brocot parents of p/q, left then right.
TYPED_TEST(Christoffel, StandardFactorizationMatchesSternBrocotParents) {
  using I = TypeParam;
  check_property([] {
    auto [p, q] = gen_slope(500);
    RC_PRE(p > 0);
    auto sf = standard_factorization(I(p), I(q));
    RC_ASSERT(sf.u + sf.v == lower_christoffel_word(I(p), I(q)));
    auto par = stern_brocot_parents(I(p), I(q));
    RC_ASSERT(sf.of.left == par.left && sf.of.right == par.right);
    if (par.left.q > 0) RC_ASSERT(sf.u == lower_christoffel_word(par.left.p, par.left.q));
    if (par.right.q > 0) {
      RC_ASSERT(sf.v == lower_christoffel_word(par.right.p, par.right.q));
    } else {
      RC_ASSERT(sf.v == "1");
    }
  });
}

TYPED_TEST(Christoffel, WorkedExamples) {
  using I = TypeParam;
  // Berstel et al., Fig. 1.2: the lower Christoffel word of slope 4/7 is 00100100101.
  EXPECT_EQ(lower_christoffel_word(I(4), I(7)), "00100100101");
  EXPECT_EQ(upper_christoffel_word(I(4), I(7)), "10100100100");
  auto sf = standard_factorization(I(4), I(7));
  EXPECT_EQ(sf.u, "001");      // 1/2
  EXPECT_EQ(sf.v, "00100101"); // 3/5
  EXPECT_EQ(lower_christoffel_word(I(0), I(1)), "0");
  EXPECT_EQ(lower_christoffel_word(I(1), I(1)), "01");
  EXPECT_EQ(lower_christoffel_word(I(3), I(1)), "0111");
  EXPECT_THROW(lower_christoffel_word(I(2), I(4)), InvalidArgument);
  EXPECT_THROW(lower_christoffel_word(I(-1), I(2)), InvalidArgument);
  EXPECT_THROW(lower_christoffel_word(I(1), I(0)), InvalidArgument);
  EXPECT_THROW(standard_factorization(I(0), I(1)), InvalidArgument);
  EXPECT_EQ(conjugate("0011", 1), "0110");
}

// Letters of a slope whose word cannot be materialized are still exact, near 2^62.
TEST(ChristoffelHuge, LetterAccessNearTheInt64Limit) {
  const std::int64_t q = (std::int64_t{1} << 62) - 57, p = q - 2; // coprime: q odd
  EXPECT_THROW(christoffel_letter(Int64(p), Int64(q), Int64(q)), OverflowError);
  auto r = escalate(
      [&]<class I>(std::type_identity<I>) { return christoffel_letter(I(p), I(q), I(q)); });
  EXPECT_EQ(r.served, IntKind::int128);
  // floor(q p / (p+q)) - floor((q-1) p / (p+q)), checked in BigInt.
  BigInt P(p), Q(q), N = P + Q;
  int expect = static_cast<int>(BigInt(Q * P / N - (Q - 1) * P / N));
  EXPECT_EQ(r.value, expect);
  EXPECT_THROW(lower_christoffel_word(Int64(p), Int64(q)), InvalidArgument);
}

// The registered property christoffel.factorization (zdg check): letters by the floor formula,
// factors by the Stern-Brocot parents found by search.
TYPED_TEST(Christoffel, RegisteredFactorizationHolds) {
  test::expect_registered_property("christoffel.factorization", int_kind<TypeParam>(), 300);
}

} // namespace
