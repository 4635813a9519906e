// Digital straight lines: membership and the point queries against the definition
// mu <= a x - b y < mu + omega, iteration, leaning points, the Christoffel word of a period,
// and the recognizer's minimal characteristics of a full period (every tower type).
#include <zdg/arith/digital_straight_line.hpp>

#include "tests/support/tower.hpp"
#include <zdg/arith/christoffel.hpp>
#include <zdg/arith/dss_recognizer.hpp>

#include <cstdint>
#include <numeric>

namespace {

using namespace zdg;
using test::check_property;

template <TowerInt I>
struct RandomLine {
  DigitalStraightLine<I> line;
};

template <TowerInt I>
DigitalStraightLine<I> random_line() {
  long a = *rc::gen::inRange(-30, 31), b = *rc::gen::inRange(-30, 31);
  RC_PRE(std::gcd(a, b) == 1);
  DslKind kind = *rc::gen::element(DslKind::naive, DslKind::standard);
  std::int64_t mu =
      *rc::gen::oneOf(rc::gen::inRange<std::int64_t>(-100, 101),
                      test::int64_in(-(std::int64_t{1} << 40), std::int64_t{1} << 40));
  return DigitalStraightLine<I>(I(a), I(b), I(mu), kind);
}

template <class I>
class DigitalStraightLineTest : public ::testing::Test {};
TYPED_TEST_SUITE(DigitalStraightLineTest, zdg::test::TowerTypes, zdg::test::TowerNames);

// Definition: the ordinates (abscissas) reported at x (y) are exactly the y (x) in a window
// around them that satisfy the double inequality.
TYPED_TEST(DigitalStraightLineTest, PointQueriesMatchTheDefinition) {
  using I = TypeParam;
  check_property([] {
    auto line = random_line<I>();
    I x = I(*rc::gen::inRange(-1000, 1000)), y = I(*rc::gen::inRange(-1000, 1000));
    I omega = line.omega();
    RC_ASSERT(omega == (line.kind() == DslKind::naive ? std::max(abs(line.a()), abs(line.b()))
                                                      : I(abs(line.a()) + abs(line.b()))));
    if (line.b() != 0) {
      auto r = line.ordinates_at(x);
      RC_ASSERT(!r.empty() || (line.kind() == DslKind::naive && abs(line.a()) > abs(line.b())));
      for (I t = r.lo - 3; t <= r.hi + 3; ++t) {
        RC_ASSERT(line.contains({x, t}) == (t >= r.lo && t <= r.hi));
      }
      if (line.kind() == DslKind::naive && abs(line.a()) <= abs(line.b())) {
        RC_ASSERT(r.lo == r.hi);
        RC_ASSERT(line.point_at_abscissa(x).y == r.lo);
      }
    }
    if (line.a() != 0) {
      auto r = line.abscissas_at(y);
      for (I t = r.lo - 3; t <= r.hi + 3; ++t) {
        RC_ASSERT(line.contains({t, y}) == (t >= r.lo && t <= r.hi));
      }
      if (line.kind() == DslKind::naive && abs(line.a()) >= abs(line.b())) {
        RC_ASSERT(r.lo == r.hi);
        RC_ASSERT(line.point_at_ordinate(y).x == r.lo);
      }
    }
  });
}

// Iteration walks the line with its two steps, in the direction (b, a); leaning points have
// the right remainders; a period is the lower Christoffel word of r(s0) / -r(s1).
TYPED_TEST(DigitalStraightLineTest, IterationLeaningPointsAndChristoffelWord) {
  using I = TypeParam;
  check_property([] {
    auto line = random_line<I>();
    auto u = line.upper_leaning_point(), l = line.lower_leaning_point();
    RC_ASSERT(line.remainder(u) == line.mu());
    RC_ASSERT(line.remainder(l) == line.mu() + line.omega() - 1);
    Step s0 = line.step0(), s1 = line.step1(), sh = line.shift();
    RC_ASSERT(line.remainder({I(sh.x), I(sh.y)}) == line.omega());
    const std::size_t n = static_cast<std::size_t>(to_double(line.omega())) + 1;
    auto pts = line.points(u, n);
    for (std::size_t k = 0; k < n; ++k) {
      RC_ASSERT(line.contains(pts[k]));
      if (k > 0) {
        I dx = pts[k].x - pts[k - 1].x, dy = pts[k].y - pts[k - 1].y;
        RC_ASSERT(((dx == s0.x && dy == s0.y) || (dx == s1.x && dy == s1.y)));
        RC_ASSERT(line.next(pts[k - 1]) == pts[k]);
      }
    }
    // One period brings the upper leaning point to the next one: u + (b, a).
    RC_ASSERT(pts.back() == (Point2<I>{u.x + line.b(), u.y + line.a()}));
    I p = line.remainder({I(s0.x), I(s0.y)}), q = -line.remainder({I(s1.x), I(s1.y)});
    RC_ASSERT(p >= 0 && q >= 0 && p + q == line.omega());
    std::string w = line.period_word();
    if (q > 0) {
      RC_ASSERT(w == lower_christoffel_word(p, q));
    } else {
      RC_ASSERT(w == "1");
    }
    // A full period (plus one point) is a DSS whose minimal characteristics are the line's.
    if (pts.size() >= 2) {
      Connectivity c = line.kind() == DslKind::naive ? Connectivity::eight : Connectivity::four;
      DssRecognizer<I> rec(pts[0], c);
      for (std::size_t k = 1; k < n; ++k) RC_ASSERT(rec.extend_front(pts[k]));
      auto ch = rec.characteristics();
      RC_ASSERT(ch.a == to_bigint(line.a()) && ch.b == to_bigint(line.b()) &&
                ch.mu == to_bigint(line.mu()) && ch.omega == to_bigint(line.omega()));
    }
  });
}

TEST(DigitalStraightLine, FirstQuadrantWordsAreChristoffelWordsOfTheSlope) {
  // Standard line of slope 3/8: the Christoffel word of 3/8; naive first octant: of 3/(8-3).
  DigitalStraightLine<Int64> standard(3, 8, 0, DslKind::standard), naive(3, 8, 0, DslKind::naive);
  EXPECT_EQ(standard.period_word(), lower_christoffel_word(Int64(3), Int64(8)));
  EXPECT_EQ(naive.period_word(), lower_christoffel_word(Int64(3), Int64(5)));
  EXPECT_EQ(naive.period_word(), "00100101");
  EXPECT_EQ(naive.point_at_abscissa(5), (Point2<Int64>{5, 1}));
}

TEST(DigitalStraightLine, RejectsBadParameters) {
  EXPECT_THROW(DigitalStraightLine<Int64>(0, 0, 0), InvalidArgument);
  EXPECT_THROW(DigitalStraightLine<Int64>(2, 4, 0), InvalidArgument);
  DigitalStraightLine<Int64> steep(5, 2, 0);
  EXPECT_THROW(steep.point_at_abscissa(1), InvalidArgument);
  EXPECT_THROW(steep.next({0, 5}), InvalidArgument);
}

TEST(DigitalStraightLine, RemaindersOverflowLoudlyOnInt64) {
  const std::int64_t big = std::int64_t{1} << 62;
  DigitalStraightLine<Int64> line(3, 7, 0);
  EXPECT_THROW(line.remainder({big, 0}), OverflowError);
  DigitalStraightLine<Int128> wide(3, 7, 0);
  EXPECT_EQ(to_bigint(wide.remainder({big, 0})), BigInt(3) * big);
}

} // namespace
