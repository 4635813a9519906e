// Lattice polygon measures: Pick's theorem checked against brute-force counts of the
// boundary and interior lattice points, the shoelace area against a known example, and the
// lattice width against a search over all small primitive directions.
#include <zdg/kernel/lattice_polygon.hpp>

#include "tests/support/tower.hpp"
#include <zdg/kernel/lattice_hull_2d.hpp>

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

} // namespace
