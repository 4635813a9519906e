// The Stern-Brocot tree: parents, depth, path, following a path.
#include <zdg/arith/stern_brocot.hpp>

#include "tests/support/tower.hpp"

#include <numeric>

namespace {

using namespace zdg;
using test::check_property;

template <class I>
class SternBrocot : public ::testing::Test {};
TYPED_TEST_SUITE(SternBrocot, test::TowerTypes, test::TowerNames);

// Theorem: p/q is the mediant of its parents a/b < p/q < c/d, which are Farey neighbours
// (c b - a d = 1); following the path from 1/1 leads back to p/q, and the path length is the
// depth.
TYPED_TEST(SternBrocot, ParentsAreNeighboursAndPathLeadsBack) {
  using I = TypeParam;
  check_property([] {
    std::int64_t p = *test::int64_in(1, 5000), q = *test::int64_in(1, 5000);
    I g = gcd(I(p), I(q));
    I P = I(p) / g, Q = I(q) / g;
    auto par = stern_brocot_parents(P, Q);
    RC_ASSERT(par.left.p + par.right.p == P);
    RC_ASSERT(par.left.q + par.right.q == Q);
    RC_ASSERT(par.right.p * par.left.q - par.left.p * par.right.q == 1);
    std::string path = stern_brocot_path(P, Q);
    RC_ASSERT(I(static_cast<std::int64_t>(path.size())) == stern_brocot_depth(P, Q));
    Fraction<I> f = stern_brocot_follow<I>(path);
    RC_ASSERT(f.p == P && f.q == Q);
  });
}

// Theorem: the parents are the two fractions of smallest denominators bracketing p/q among
// the fractions with denominator < q (Farey neighbours) -- checked by brute force.
TYPED_TEST(SternBrocot, ParentsAreFareyNeighboursByBruteForce) {
  using I = TypeParam;
  check_property([] {
    std::int64_t p = *test::int64_in(1, 60), q = *test::int64_in(2, 60);
    RC_PRE(std::gcd(p, q) == 1);
    // Brute force: the closest fractions a/b < p/q < c/d with b, d <= q (and 1/0 as +inf).
    std::int64_t lp = 0, lq = 1, rp = 1, rq = 0;
    for (std::int64_t b = 1; b <= q; ++b) {
      for (std::int64_t a = 0; a <= p * b / q + 1; ++a) {
        if (a * q < p * b && a * lq > lp * b) lp = a, lq = b;
        if (a * q > p * b && (rq == 0 || a * rq < rp * b)) rp = a, rq = b;
      }
    }
    auto par = stern_brocot_parents(I(p), I(q));
    RC_ASSERT(par.left.p == I(lp) && par.left.q == I(lq));
    RC_ASSERT(par.right.p == I(rp) && par.right.q == I(rq));
  });
}

TYPED_TEST(SternBrocot, WorkedExamples) {
  using I = TypeParam;
  // Concrete Mathematics 4.5: 5/7 is LRRL.
  EXPECT_EQ(stern_brocot_path(I(5), I(7)), "LRRL");
  EXPECT_EQ(stern_brocot_path(I(1), I(1)), "");
  EXPECT_EQ(stern_brocot_depth(I(3), I(1)), 2);
  auto par = stern_brocot_parents(I(1), I(1));
  EXPECT_EQ(par.left, (Fraction<I>{0, 1}));
  EXPECT_EQ(par.right, (Fraction<I>{1, 0}));
  auto p23 = stern_brocot_parents(I(2), I(3));
  EXPECT_EQ(p23.left, (Fraction<I>{1, 2}));
  EXPECT_EQ(p23.right, (Fraction<I>{1, 1}));
  EXPECT_EQ(mediant(Fraction<I>{1, 2}, Fraction<I>{1, 1}), (Fraction<I>{2, 3}));
  EXPECT_THROW(stern_brocot_parents(I(2), I(4)), InvalidArgument);
  EXPECT_THROW(stern_brocot_depth(I(0), I(1)), InvalidArgument);
  EXPECT_THROW(stern_brocot_follow<I>("LRX"), InvalidArgument);
}

TEST(SternBrocotBig, DepthOfHugeFractionWithoutWalkingThePath) {
  // 10^30 / 1 has depth 10^30 - 1: computed from the continued fraction, never walked.
  BigInt p = BigInt(1);
  for (int i = 0; i < 30; ++i) p *= 10;
  EXPECT_EQ(stern_brocot_depth(p, BigInt(1)), p - 1);
  auto runs = stern_brocot_path_runs(p, BigInt(1));
  ASSERT_EQ(runs.size(), 1u);
  EXPECT_EQ(runs[0].first, 'R');
  EXPECT_THROW(stern_brocot_path(p, BigInt(1)), InvalidArgument);
}

} // namespace
