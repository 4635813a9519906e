// Lattice polygon measures: Pick's theorem checked against brute-force counts of the
// boundary and interior lattice points, the shoelace area against a known example, and the
// lattice width against a search over all small primitive directions.
#include <zdg/kernel/hulls/lattice_polygon.hpp>

#include "tests/support/tower.hpp"
#include <cmath>
#include <limits>
#include <numeric>
#include <zdg/kernel/hulls/lattice_hull_2d.hpp>

#include <vector>

namespace {

using namespace zdg;

template <class I>
class LatticePolygon : public ::testing::Test {};
TYPED_TEST_SUITE(LatticePolygon, test::TowerTypes, test::TowerNames);

// Pick (1899): area = interior + boundary / 2 - 1; both counts by enumeration.
TYPED_TEST(LatticePolygon, PickCountsMatchEnumeration) {
  using I = TypeParam;
  test::check_property([] {
    int n = *rc::gen::inRange(1, 12);
    std::vector<Point2<I>> pts;
    for (int i = 0; i < n; ++i) {
      pts.push_back(
          {I(*rc::gen::inRange<std::int64_t>(-8, 9)), I(*rc::gen::inRange<std::int64_t>(-8, 9))});
    }
    auto v = lattice_hull_2d<I>(std::span<const Point2<I>>(pts));
    auto m = lattice_polygon_measures<I>(std::span<const Point2<I>>(v));
    I inside = 0, on = 0;
    for (int y = -8; y <= 8; ++y) {
      for (int x = -8; x <= 8; ++x) {
        Point2<I> q{I(x), I(y)};
        if (v.size() <= 2) {
          // point or segment: on it iff collinear and between the ends
          bool hit = v.size() == 1 ? q == v[0]
                                   : orientation(v[0], v[1], q) == 0 &&
                                         (q.x - v[0].x) * (q.x - v[1].x) <= 0 &&
                                         (q.y - v[0].y) * (q.y - v[1].y) <= 0;
          if (hit) on += 1;
          continue;
        }
        int worst = 1;
        for (std::size_t i = 0; i < v.size(); ++i) {
          worst = std::min(worst, orientation(v[i], v[(i + 1) % v.size()], q));
        }
        if (worst > 0) inside += 1;
        if (worst == 0) on += 1;
      }
    }
    RC_ASSERT(m.boundary == on);
    RC_ASSERT(m.interior == inside);
    if (v.size() >= 3) RC_ASSERT(m.area2 == 2 * m.interior + m.boundary - 2);
  });
}

// The width is attained by the returned direction and no primitive u with |u_i| <= 12 gives
// less.
TYPED_TEST(LatticePolygon, LatticeWidthIsTheMinimumOverDirections) {
  using I = TypeParam;
  test::check_property([] {
    int n = *rc::gen::inRange(3, 10);
    std::vector<Point2<I>> pts;
    for (int i = 0; i < n; ++i) {
      pts.push_back(
          {I(*rc::gen::inRange<std::int64_t>(-6, 7)), I(*rc::gen::inRange<std::int64_t>(-6, 7))});
    }
    auto v = lattice_hull_2d<I>(std::span<const Point2<I>>(pts));
    auto w = lattice_width<I>(std::span<const Point2<I>>(v));
    auto along = [&](const I& a, const I& b) {
      I lo = a * v[0].x + b * v[0].y, hi = lo;
      for (const auto& p : v) {
        I s = a * p.x + b * p.y;
        lo = std::min(lo, s);
        hi = std::max(hi, s);
      }
      return I(hi - lo);
    };
    RC_ASSERT(gcd(w.direction.x, w.direction.y) == 1);
    RC_ASSERT(along(w.direction.x, w.direction.y) == w.width);
    for (int a = -12; a <= 12; ++a) {
      for (int b = -12; b <= 12; ++b) {
        if ((a != 0 || b != 0)) RC_ASSERT(along(I(a), I(b)) >= w.width);
      }
    }
  });
}

TEST(LatticePolygonExamples, KnownValues) {
  using P = Point2<Int64>;
  // The triangle (0,0), (4,0), (0,3): area 6, boundary 4 + 3 + 1 = 8, interior 3;
  // lattice width 3 (along (0, 1)).
  std::vector<P> t = {{0, 0}, {4, 0}, {0, 3}};
  auto m = lattice_polygon_measures<Int64>(std::span<const P>(t));
  EXPECT_EQ(m.area2, 12);
  EXPECT_EQ(m.boundary, 8);
  EXPECT_EQ(m.interior, 3);
  EXPECT_EQ(lattice_width<Int64>(std::span<const P>(t)).width, 3);
  // The empty triangle (0,0), (1,0), (0,1) has width 1; the triangle (0,0), (2,1), (1,2)
  // (area 3/2, one interior point) has width 2 (it is no unimodular image of a width-1 one).
  std::vector<P> e = {{0, 0}, {1, 0}, {0, 1}}, f = {{0, 0}, {2, 1}, {1, 2}};
  EXPECT_EQ(lattice_width<Int64>(std::span<const P>(e)).width, 1);
  EXPECT_EQ(lattice_width<Int64>(std::span<const P>(f)).width, 2);
  auto mf = lattice_polygon_measures<Int64>(std::span<const P>(f));
  EXPECT_EQ(mf.interior, 1);
  EXPECT_EQ(mf.boundary, 3);
}

// The exact entry point: a translate by 2^62 of the triangle above has the same measures;
// Int64 overflows on the shoelace terms, the escalation says which type served.
TEST(LatticePolygonExamples, ExactMeasuresEscalate) {
  const BigInt t = BigInt(1) << 62;
  std::vector<Point2<BigInt>> far = {{t, -t}, {t + 4, -t}, {t, -t + 3}};
  std::vector<Point2<Int64>> far64 = {
      {Int64(std::int64_t{1} << 62), Int64(-(std::int64_t{1} << 62))},
      {Int64((std::int64_t{1} << 62) + 4), Int64(-(std::int64_t{1} << 62))},
      {Int64(std::int64_t{1} << 62), Int64(-(std::int64_t{1} << 62) + 3)}};
  EXPECT_THROW(lattice_polygon_measures<Int64>(std::span<const Point2<Int64>>(far64)),
               OverflowError);
  auto m = lattice_polygon_measures_exact(std::span<const Point2<BigInt>>(far));
  EXPECT_NE(m.served, IntKind::int64);
  EXPECT_EQ(m.value.area2, 12);
  EXPECT_EQ(m.value.boundary, 8);
  EXPECT_EQ(m.value.interior, 3);
  std::vector<Point2<BigInt>> near = {{0, 0}, {4, 0}, {0, 3}};
  EXPECT_EQ(lattice_polygon_measures_exact(std::span<const Point2<BigInt>>(near)).served,
            IntKind::int64);
}

// The incremental meter gives the batch measures (which Pick's enumeration above checks), on
// polygons of every size, including coordinates near +-2^63 where the 128-bit running sums
// spill into BigInt and vertices given as BigInt.
TEST(LatticePolygonMeter, AgreesWithTheBatchMeasures) {
  test::check_property([] {
    int n = *rc::gen::inRange(0, 14);
    const bool huge = *rc::gen::arbitrary<bool>();
    std::vector<Point2<BigInt>> pts;
    for (int i = 0; i < n; ++i) {
      pts.push_back({BigInt(*test::edgy_int64()), BigInt(*test::edgy_int64())});
      if (!huge) pts.back() = {pts.back().x % 100, pts.back().y % 100};
    }
    auto v = lattice_hull_2d<BigInt>(std::span<const Point2<BigInt>>(pts));
    const auto want = lattice_polygon_measures<BigInt>(std::span<const Point2<BigInt>>(v));
    LatticePolygonMeter meter;
    const bool as_big = *rc::gen::arbitrary<bool>();
    for (const auto& p : v) {
      if (as_big) {
        meter.add(p.x, p.y);
      } else {
        meter.add(p.x.convert_to<std::int64_t>(), p.y.convert_to<std::int64_t>());
      }
    }
    const auto got = meter.finish();
    RC_ASSERT(meter.count() == v.size());
    RC_ASSERT(got.area2 == want.area2);
    RC_ASSERT(got.boundary == want.boundary);
    RC_ASSERT(got.interior == want.interior);
  });
}

TEST(LatticePolygonMeter, RegressionExtremeCrossTermsSpillIntoBigInt) {
  const std::int64_t m = std::numeric_limits<std::int64_t>::min();
  const std::int64_t M = std::numeric_limits<std::int64_t>::max();
  // A triangle whose shoelace terms are about 2^127 each.
  std::vector<Point2<BigInt>> v{
      {BigInt(m), BigInt(m)}, {BigInt(M), BigInt(m)}, {BigInt(M), BigInt(M)}};
  LatticePolygonMeter meter;
  for (const auto& p : v) meter.add(p.x.convert_to<std::int64_t>(), p.y.convert_to<std::int64_t>());
  const auto want = lattice_polygon_measures<BigInt>(std::span<const Point2<BigInt>>(v));
  EXPECT_EQ(meter.finish().area2, want.area2);
  EXPECT_EQ(meter.finish().boundary, want.boundary);
}

// Theorem (the bound of the header): a convex lattice polygon of perimeter P has at most
// convex_lattice_polygon_max_vertices(P) vertices. Oracle: the hulls of random point sets
// (perimeter computed in long double, rounded up), and the extremal polygons built from the
// shortest primitive edge vectors sorted by angle (the most vertices for their perimeter).
TEST(LatticePolygonVertexBound, BoundsEveryConvexLatticePolygon) {
  test::check_property([] {
    int n = *rc::gen::inRange(1, 40);
    const std::int64_t span = *rc::gen::inRange<std::int64_t>(1, 1000);
    std::vector<Point2<Int64>> pts;
    for (int i = 0; i < n; ++i) {
      pts.push_back({Int64(*rc::gen::inRange<std::int64_t>(-span, span + 1)),
                     Int64(*rc::gen::inRange<std::int64_t>(-span, span + 1))});
    }
    auto v = lattice_hull_2d<Int64>(std::span<const Point2<Int64>>(pts));
    long double perimeter = 0;
    for (std::size_t i = 0; v.size() > 1 && i < v.size(); ++i) {
      const auto& a = v[i];
      const auto& b = v[(i + 1) % v.size()];
      perimeter += std::hypot(static_cast<long double>((b.x - a.x).value()),
                              static_cast<long double>((b.y - a.y).value()));
    }
    RC_ASSERT(v.size() <=
              convex_lattice_polygon_max_vertices(static_cast<double>(perimeter) * (1 + 1e-12)));
  });
  // Extremal polygons: all primitive vectors of norm <= t, sorted by angle, form a convex
  // lattice polygon (their sum is 0 by symmetry).
  for (int t : {1, 2, 3, 5, 8, 13, 30, 60}) {
    std::size_t count = 0;
    long double perimeter = 0;
    for (int x = -t; x <= t; ++x) {
      for (int y = -t; y <= t; ++y) {
        if (x * x + y * y == 0 || x * x + y * y > t * t || std::gcd(x, y) != 1) continue;
        ++count;
        perimeter += std::sqrt(static_cast<long double>(x * x + y * y));
      }
    }
    EXPECT_LE(count,
              convex_lattice_polygon_max_vertices(static_cast<double>(perimeter) * (1 + 1e-12)))
        << "t = " << t;
    // ... and the bound is not far off for them (within a factor 2.5).
    EXPECT_LE(convex_lattice_polygon_max_vertices(static_cast<double>(perimeter)),
              5 * count / 2 + 4);
  }
  EXPECT_EQ(convex_lattice_polygon_max_vertices(0), 1u);
  EXPECT_EQ(convex_lattice_polygon_max_vertices(1e300), UINT64_MAX);
}

} // namespace
