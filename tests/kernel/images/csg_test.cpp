#include <zdg/kernel/images/csg.hpp>

#include "tests/support/tower.hpp"
#include <zdg/arith/error.hpp>
#include <zdg/kernel/topology/betti_numbers.hpp>

#include <gtest/gtest.h>

#include <random>
#include <vector>

namespace zdg {
namespace {

// Two random images of one random 2D or 3D domain (any lower bounds), and a thread count.
struct CsgCase {
  Image<std::uint8_t> a, b;
  unsigned threads;
};

CsgCase random_csg_case(bool zero_border = false) {
  std::mt19937 rng(*rc::gen::arbitrary<std::uint32_t>());
  auto pick = [&](int lo, int hi) { return lo + static_cast<int>(rng() % (hi - lo + 1)); };
  const int d = pick(2, 3);
  std::vector<std::int64_t> ext, low;
  for (int k = 0; k < d; ++k) {
    ext.push_back(pick(1, d == 2 ? 12 : 7));
    low.push_back(pick(-3, 3));
  }
  Domain dom(ext, low);
  auto fill = [&] {
    Image<std::uint8_t> img(dom);
    const int density = pick(0, 100);
    std::vector<std::int64_t> p(static_cast<std::size_t>(d));
    for (std::int64_t i = 0; i < dom.size(); ++i) {
      dom.point(i, p);
      bool border = false;
      for (int k = 0; k < d; ++k) {
        border = border || p[static_cast<std::size_t>(k)] == dom.lower(k) ||
                 p[static_cast<std::size_t>(k)] == dom.upper(k);
      }
      img[i] = (zero_border && border) ? 0 : (pick(0, 99) < density ? pick(1, 255) : 0);
    }
    return img;
  };
  CsgCase c{fill(), fill(), static_cast<unsigned>(pick(1, 4))};
  return c;
}

bool same_set(const Image<std::uint8_t>& x, const Image<std::uint8_t>& y) {
  if (!(x.domain() == y.domain())) return false;
  for (std::int64_t i = 0; i < x.size(); ++i) {
    if ((x[i] != 0) != (y[i] != 0)) return false;
  }
  return true;
}

using Op = CsgOperation;

// The Boolean algebra of sets (identities as properties): De Morgan, idempotence,
// commutativity, absorption, A \ B = A n B^c, A ^ B = (A \ B) u (B \ A), (A^c)^c = A; values 0
// and 1; the thread count changes nothing.
TEST(Csg, BooleanAlgebraIdentities) {
  test::check_property([] {
    const auto c = random_csg_case();
    const auto& a = c.a;
    const auto& b = c.b;
    const unsigned t = c.threads;
    auto comp = [&](const Image<std::uint8_t>& x) { return csg_complement(x, t); };
    auto op = [&](Op o, const Image<std::uint8_t>& x, const Image<std::uint8_t>& y) {
      return csg(o, x, y, t);
    };
    RC_ASSERT(same_set(comp(op(Op::union_of, a, b)), op(Op::intersection, comp(a), comp(b))));
    RC_ASSERT(same_set(comp(op(Op::intersection, a, b)), op(Op::union_of, comp(a), comp(b))));
    RC_ASSERT(same_set(op(Op::union_of, a, a), a));
    RC_ASSERT(same_set(op(Op::intersection, a, a), a));
    RC_ASSERT(op(Op::union_of, a, b) == op(Op::union_of, b, a));
    RC_ASSERT(op(Op::intersection, a, b) == op(Op::intersection, b, a));
    RC_ASSERT(same_set(op(Op::union_of, a, op(Op::intersection, a, b)), a));
    RC_ASSERT(same_set(op(Op::intersection, a, op(Op::union_of, a, b)), a));
    RC_ASSERT(op(Op::difference, a, b) == op(Op::intersection, a, comp(b)));
    RC_ASSERT(op(Op::symmetric_difference, a, b) ==
              op(Op::union_of, op(Op::difference, a, b), op(Op::difference, b, a)));
    RC_ASSERT(same_set(comp(comp(a)), a));
    const auto u = op(Op::union_of, a, b);
    for (auto v : u.values()) RC_ASSERT(v <= 1);
    RC_ASSERT(op(Op::symmetric_difference, a, b) == csg(Op::symmetric_difference, a, b, 1));
  });
}

// Theorem (Alexander duality for the digital pairs; Kong, Rosenfeld 1989): for X inside the box
// (its border in the complement), the complement under the dual pair has b0 = b2(X) + 1,
// b1 = b1(X), b2 = b0(X) in 3D, and b0 = b1(X) + 1, b1 = b0(X) in 2D.
TEST(Csg, ComplementSatisfiesAlexanderDuality) {
  test::check_property([] {
    const auto c = random_csg_case(true);
    const int d = c.a.dim();
    const AdjacencyPair pair = default_adjacency_pair(d);
    const BettiNumbers x = betti_numbers(c.a, pair, 1);
    const BettiNumbers y = betti_numbers(csg_complement(c.a, c.threads), pair.complement(), 1);
    if (d == 3) {
      RC_ASSERT(y.b[0] == x.b[2] + 1);
      RC_ASSERT(y.b[1] == x.b[1]);
      RC_ASSERT(y.b[2] == x.b[0]);
    } else {
      RC_ASSERT(y.b[0] == x.b[1] + 1);
      RC_ASSERT(y.b[1] == x.b[0]);
    }
  });
}

TEST(Csg, WorkedExampleAndErrors) {
  // Two overlapping 1 x 3 bars: union 4 points, intersection 2, difference 1, xor 2.
  Image<std::uint8_t> a(Domain({1, 4}), std::vector<std::uint8_t>{1, 1, 7, 0});
  Image<std::uint8_t> b(Domain({1, 4}), std::vector<std::uint8_t>{0, 3, 1, 1});
  EXPECT_EQ(csg(Op::union_of, a, b).values(), (std::vector<std::uint8_t>{1, 1, 1, 1}));
  EXPECT_EQ(csg(Op::intersection, a, b).values(), (std::vector<std::uint8_t>{0, 1, 1, 0}));
  EXPECT_EQ(csg(Op::difference, a, b).values(), (std::vector<std::uint8_t>{1, 0, 0, 0}));
  EXPECT_EQ(csg(Op::symmetric_difference, a, b).values(), (std::vector<std::uint8_t>{1, 0, 0, 1}));
  EXPECT_EQ(csg_complement(a).values(), (std::vector<std::uint8_t>{0, 0, 0, 1}));
  Image<std::uint8_t> other(Domain({1, 4}, {0, 1}));
  try {
    csg(Op::union_of, a, other);
    FAIL() << "no error";
  } catch (const InvalidArgument& e) {
    EXPECT_STREQ(e.what(), "csg union: the images differ in shape: (1, 4) and (1, 4) at (0, 1)");
  }
}

} // namespace
} // namespace zdg
