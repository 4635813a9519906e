// Output-sensitive hulls of Z^2 inside a disc, an ellipse and a polygon, against brute force:
// enumerate the lattice points of the body's box with the body's own exact membership test,
// then take their monotone-chain hull. Vertex lists must agree exactly (same order).
#include <zdg/kernel/hulls/convex_body_hull.hpp>

#include "tests/support/check_registry.hpp"
#include "tests/support/tower.hpp"
#include <zdg/kernel/hulls/lattice_hull_2d.hpp>
#include <zdg/kernel/hulls/lattice_polygon.hpp>

#include <cstdlib>
#include <vector>

namespace {

using namespace zdg;
using test::check_property;

// The oracle runs on Int64 whatever the type under test (the data are small): enumerate the
// box with the body's exact membership test, then the monotone chain.
template <TowerInt I>
QuadraticBody<Int64> narrow(const QuadraticBody<I>& K) {
  auto c = [](const I& v) { return int_cast<Int64>(v); };
  return {c(K.D),     c(K.Cx),  c(K.Cy),  c(K.alpha), c(K.beta),
          c(K.gamma), c(K.xlo), c(K.xhi), c(K.ylo),   c(K.yhi)};
}
template <TowerInt I>
PolygonBody<Int64> narrow(const PolygonBody<I>& K) {
  PolygonBody<Int64> o;
  for (const auto& [a, b, c] : K.rows)
    o.rows.push_back({int_cast<Int64>(a), int_cast<Int64>(b), int_cast<Int64>(c)});
  o.xlo = int_cast<Int64>(K.xlo);
  o.xhi = int_cast<Int64>(K.xhi);
  o.ylo = int_cast<Int64>(K.ylo);
  o.yhi = int_cast<Int64>(K.yhi);
  return o;
}

template <TowerInt I, class Body>
std::vector<Point2<I>> brute_hull(const Body& body) {
  auto K = narrow(body);
  std::vector<Point2<Int64>> pts;
  for (Int64 y = K.ylo; y <= K.yhi; ++y) {
    for (Int64 x = K.xlo; x <= K.xhi; ++x) {
      if (K.contains({x, y})) pts.push_back({x, y});
    }
  }
  std::vector<Point2<I>> out;
  for (const auto& p : lattice_hull_2d<Int64>(std::span<const Point2<Int64>>(pts))) {
    out.push_back({int_cast<I>(p.x), int_cast<I>(p.y)});
  }
  return out;
}

template <TowerInt I>
Rational<I> rat(std::int64_t p, std::int64_t q = 1) {
  return Rational<I>(I(p), I(q));
}

template <class I>
class ConvexBodyHull : public ::testing::Test {};
TYPED_TEST_SUITE(ConvexBodyHull, test::TowerTypes, test::TowerNames);

// Oracle: brute force, for every integer radius 0..R at the origin (R = 100 on Int64, the
// full sweep; a subset on the wider types).
TYPED_TEST(ConvexBodyHull, DiscAtOriginMatchesEnumerationForEveryRadius) {
  using I = TypeParam;
  const int R = std::same_as<I, Int64> ? 100 : 30;
  for (int r = 0; r <= R; ++r) {
    auto body = disc_body(rat<I>(0), rat<I>(0), rat<I>(r));
    auto fast = convex_body_hull<I>(body);
    ASSERT_EQ(fast, brute_hull<I>(body)) << "radius " << r;
  }
}

TYPED_TEST(ConvexBodyHull, RationalDiscsMatchEnumeration) {
  using I = TypeParam;
  check_property([] {
    auto q = *rc::gen::inRange<std::int64_t>(1, 8);
    auto cx = rat<I>(*rc::gen::inRange<std::int64_t>(-40 * q, 40 * q), q);
    auto cy = rat<I>(*rc::gen::inRange<std::int64_t>(-40 * q, 40 * q), q);
    auto rq = *rc::gen::inRange<std::int64_t>(1, 6);
    auto r = rat<I>(*rc::gen::inRange<std::int64_t>(0, 25 * rq), rq);
    auto body = disc_body(cx, cy, r);
    RC_ASSERT(convex_body_hull<I>(body) == brute_hull<I>(body));
  });
}

TYPED_TEST(ConvexBodyHull, RationalEllipsesMatchEnumeration) {
  using I = TypeParam;
  check_property([] {
    auto q = *rc::gen::inRange<std::int64_t>(1, 6);
    auto cx = rat<I>(*rc::gen::inRange<std::int64_t>(-20 * q, 20 * q), q);
    auto cy = rat<I>(*rc::gen::inRange<std::int64_t>(-20 * q, 20 * q), q);
    auto a = rat<I>(*rc::gen::inRange<std::int64_t>(1, 300), *rc::gen::inRange<std::int64_t>(1, 9));
    auto b = rat<I>(*rc::gen::inRange<std::int64_t>(1, 300), *rc::gen::inRange<std::int64_t>(1, 9));
    auto body = ellipse_body(cx, cy, a, b);
    RC_ASSERT(convex_body_hull<I>(body) == brute_hull<I>(body));
  });
}

// Random polygons: a box plus random rational cuts (kept bounded by the box).
TYPED_TEST(ConvexBodyHull, RationalPolygonsMatchEnumeration) {
  using I = TypeParam;
  check_property([] {
    std::vector<HalfPlane<I>> hs = {{rat<I>(1), rat<I>(0), rat<I>(30)},
                                    {rat<I>(-1), rat<I>(0), rat<I>(30)},
                                    {rat<I>(0), rat<I>(1), rat<I>(30)},
                                    {rat<I>(0), rat<I>(-1), rat<I>(30)}};
    int n = *rc::gen::inRange(0, 7);
    for (int i = 0; i < n; ++i) {
      auto a =
          rat<I>(*rc::gen::inRange<std::int64_t>(-9, 10), *rc::gen::inRange<std::int64_t>(1, 4));
      auto b =
          rat<I>(*rc::gen::inRange<std::int64_t>(-9, 10), *rc::gen::inRange<std::int64_t>(1, 4));
      auto c =
          rat<I>(*rc::gen::inRange<std::int64_t>(-40, 200), *rc::gen::inRange<std::int64_t>(1, 5));
      hs.push_back({a, b, c});
    }
    auto [kind, body] = polygon_body<I>(std::span<const HalfPlane<I>>(hs));
    RC_ASSERT(kind != RegionKind::unbounded);
    if (kind == RegionKind::empty) {
      // An empty real region has no lattice point in the box either.
      for (int y = -30; y <= 30; ++y) {
        for (int x = -30; x <= 30; ++x) {
          bool in = true;
          for (const auto& h : hs) in = in && h.a * rat<I>(x) + h.b * rat<I>(y) <= h.c;
          RC_ASSERT(!in);
        }
      }
      return;
    }
    RC_ASSERT(convex_body_hull<I>(body) == brute_hull<I>(body));
  });
}

// Thin slivers: few or no lattice points per row, where the first vertex and the edges need
// the careful cases of the walk.
TYPED_TEST(ConvexBodyHull, ThinSliversMatchEnumeration) {
  using I = TypeParam;
  check_property([] {
    auto p = *rc::gen::inRange<std::int64_t>(-12, 13);
    auto q = *rc::gen::inRange<std::int64_t>(1, 13);
    auto off = *rc::gen::inRange<std::int64_t>(-20, 20);
    auto eps = rat<I>(*rc::gen::inRange<std::int64_t>(0, 4), *rc::gen::inRange<std::int64_t>(1, 9));
    // off <= q y - p x <= off + eps, |x| <= 40
    std::vector<HalfPlane<I>> hs = {{rat<I>(-p), rat<I>(q), rat<I>(off) + eps},
                                    {rat<I>(p), rat<I>(-q), rat<I>(-off)},
                                    {rat<I>(1), rat<I>(0), rat<I>(40)},
                                    {rat<I>(-1), rat<I>(0), rat<I>(40)}};
    auto [kind, body] = polygon_body<I>(std::span<const HalfPlane<I>>(hs));
    RC_ASSERT(kind == RegionKind::bounded);
    RC_ASSERT(convex_body_hull<I>(body) == brute_hull<I>(body));
  });
}

// A long thin diagonal sliver 0 <= 1000 y - 999 x <= 1/2, 0 <= x <= 10^7: its lattice
// points are (1000 k, 999 k), k = 0..10^4 (a segment). Scanning rows would meet 10^7 rows,
// almost all empty; the scan along the flat direction meets one line.
TEST(ConvexBodyHullThin, LongDiagonalSliverIsScannedAlongItsFlatDirection) {
  using I = Int64;
  std::vector<HalfPlane<I>> hs = {{rat<I>(-999), rat<I>(1000), rat<I>(1, 2)},
                                  {rat<I>(999), rat<I>(-1000), rat<I>(0)},
                                  {rat<I>(1), rat<I>(0), rat<I>(10000000)},
                                  {rat<I>(-1), rat<I>(0), rat<I>(0)}};
  auto h = halfplane_hull<I>(std::span<const HalfPlane<I>>(hs));
  ASSERT_EQ(h.region, RegionKind::bounded);
  EXPECT_EQ(h.vertices, (std::vector<Point2<I>>{{0, 0}, {10000000, 9990000}}));
  // Up to 3 instead of 1/2: the lattice points are (s + 1000 j, s + 999 j) on the lines
  // 1000 y - 999 x = s, s = 0..3; the hull is the parallelogram of the ends of s = 0 and 3.
  hs[0].c = rat<I>(3);
  auto g = halfplane_hull<I>(std::span<const HalfPlane<I>>(hs));
  EXPECT_EQ(g.vertices,
            (std::vector<Point2<I>>{{0, 0}, {10000000, 9990000}, {9999003, 9989004}, {3, 3}}));
}

// A needle-like ellipse (semi-axes 1/2 and 10^9): scanned by columns, one or two lines.
TEST(ConvexBodyHullThin, TallThinEllipse) {
  using Q = Rational<BigInt>;
  auto r = ellipse_hull_exact(Q(BigInt(1), BigInt(3)), Q(0), Q(BigInt(1), BigInt(2)),
                              Q(BigInt(1000000000)));
  // Only the column x = 0 meets the lattice: y^2 <= 10^18 (1 - 4/9), |y| <= 745355992.
  ASSERT_EQ(r.value.vertices.size(), 2u);
  EXPECT_EQ(r.value.vertices[0].y, BigInt(-745355992));
  EXPECT_EQ(r.value.vertices[1].y, BigInt(745355992));
  EXPECT_EQ(r.value.vertices[1].x, BigInt(0));
}

TEST(ConvexBodyHullRegion, ClassifiesEmptyUnboundedAndBounded) {
  using I = Int64;
  auto kind = [](std::vector<std::array<std::int64_t, 3>> rows) {
    std::vector<HalfPlane<I>> hs;
    for (auto [a, b, c] : rows) hs.push_back({rat<I>(a), rat<I>(b), rat<I>(c)});
    return halfplane_hull<I>(std::span<const HalfPlane<I>>(hs)).region;
  };
  EXPECT_EQ(kind({}), RegionKind::unbounded);
  EXPECT_EQ(kind({{1, 0, 3}}), RegionKind::unbounded);
  EXPECT_EQ(kind({{1, 0, 3}, {-1, 0, -1}}), RegionKind::unbounded); // a strip
  EXPECT_EQ(kind({{1, 0, 3}, {-1, 0, -4}}), RegionKind::empty);     // 4 <= x <= 3
  EXPECT_EQ(kind({{1, 1, 0}, {-1, 0, 0}, {0, -1, -1}}), RegionKind::empty);
  EXPECT_EQ(kind({{1, 1, 10}, {-1, 0, 0}, {0, -1, 0}}), RegionKind::bounded);
  EXPECT_EQ(kind({{0, 0, -1}}), RegionKind::empty);
  EXPECT_EQ(kind({{1, 1, 10}, {-1, 0, 0}}), RegionKind::unbounded);
  // A bounded region without lattice points: no vertices.
  std::vector<HalfPlane<I>> tiny = {{rat<I>(1), rat<I>(0), rat<I>(2, 3)},
                                    {rat<I>(-1), rat<I>(0), rat<I>(-1, 3)},
                                    {rat<I>(0), rat<I>(1), rat<I>(5)},
                                    {rat<I>(0), rat<I>(-1), rat<I>(5)}};
  auto h = halfplane_hull<I>(std::span<const HalfPlane<I>>(tiny));
  EXPECT_EQ(h.region, RegionKind::bounded);
  EXPECT_TRUE(h.vertices.empty());
}

// A worked example: the disc of radius 5 at the origin has the 12 vertices (+-3, +-4),
// (+-4, +-3) and (0, +-5), (+-5, 0): the lattice points on the circle (25 = 9 + 16 = 25 + 0).
TEST(ConvexBodyHullExample, RadiusFiveDisc) {
  auto v = disc_hull<Int64>(rat<Int64>(0), rat<Int64>(0), rat<Int64>(5));
  std::vector<Point2<Int64>> want = {{0, -5}, {3, -4}, {4, -3}, {5, 0},  {4, 3},   {3, 4},
                                     {0, 5},  {-3, 4}, {-4, 3}, {-5, 0}, {-4, -3}, {-3, -4}};
  EXPECT_EQ(v, want);
}

// Gauss circle problem: N(r) = #{(x, y) : x^2 + y^2 <= r^2} (OEIS A000328) from the hull
// alone, by Pick: N = interior + boundary. N(10^3) = 3141549, N(10^4) = 314159053,
// N(10^6) = 3141592649625 (the classical table of the circle problem).
TEST(ConvexBodyHullExample, GaussCircleCountsByPick) {
  auto count = [](std::int64_t r) {
    auto v = disc_hull<Int64>(rat<Int64>(0), rat<Int64>(0), rat<Int64>(r));
    auto m = lattice_polygon_measures<Int64>(std::span<const Point2<Int64>>(v));
    return m.interior + m.boundary;
  };
  EXPECT_EQ(count(5), 81);
  EXPECT_EQ(count(1000), 3141549);
  EXPECT_EQ(count(10000), 314159053);
  EXPECT_EQ(count(1000000), 3141592649625);
}

// Exact by escalation: a disc centred near 2^62 is the translate of the same disc at the
// origin (integer translations preserve Z^2), and the Int64 attempt overflows.
TEST(ConvexBodyHullEscalation, HugeCentreIsATranslate) {
  const std::int64_t t = (std::int64_t{1} << 62) - 12345;
  for (std::int64_t r : {0, 1, 7, 30}) {
    auto near0 = disc_hull_exact(Rational<BigInt>(BigInt(1), BigInt(3)),
                                 Rational<BigInt>(BigInt(0)), Rational<BigInt>(BigInt(r)));
    auto far = disc_hull_exact(Rational<BigInt>(BigInt(t) * 3 + 1, BigInt(3)),
                               Rational<BigInt>(BigInt(-t)), Rational<BigInt>(BigInt(r)));
    EXPECT_NE(far.served, IntKind::int64);
    ASSERT_EQ(near0.value.vertices.size(), far.value.vertices.size());
    for (std::size_t i = 0; i < far.value.vertices.size(); ++i) {
      EXPECT_EQ(far.value.vertices[i].x, near0.value.vertices[i].x + t);
      EXPECT_EQ(far.value.vertices[i].y, near0.value.vertices[i].y - t);
    }
  }
  // A radius with a denominator near 2^40: the cleared squares leave int64.
  const BigInt den = (BigInt(1) << 40) + 1;
  auto odd = disc_hull_exact(Rational<BigInt>(0), Rational<BigInt>(0),
                             Rational<BigInt>(BigInt(5) * den + 1, den));
  auto five = disc_hull_exact(Rational<BigInt>(0), Rational<BigInt>(0), Rational<BigInt>(5));
  EXPECT_NE(odd.served, IntKind::int64);
  EXPECT_EQ(odd.value.vertices, five.value.vertices); // no lattice point in 5 < |p| <= 5 + 2^-40
}

TEST(ConvexBodyHullErrors, RejectsBadData) {
  EXPECT_THROW(disc_body(rat<Int64>(0), rat<Int64>(0), rat<Int64>(-1, 2)), InvalidArgument);
  EXPECT_THROW(ellipse_body(rat<Int64>(0), rat<Int64>(0), rat<Int64>(0), rat<Int64>(1)),
               InvalidArgument);
}

TYPED_TEST(ConvexBodyHull, FloorSqrtIsExact) {
  using I = TypeParam;
  check_property([] {
    std::int64_t a = *rc::gen::inRange<std::int64_t>(0, std::int64_t{1} << 62);
    I n = I(a);
    I s = floor_sqrt(n);
    RC_ASSERT(s * s <= n);
    RC_ASSERT((s + 1) * (s + 1) > n);
  });
}

// A sink that records what it receives, as BigInt.
struct RecordingSink : HullVertexSink {
  std::vector<Point2<BigInt>> v;
  std::size_t small = 0, big = 0;
  void vertex(std::int64_t x, std::int64_t y) override {
    v.push_back({BigInt(x), BigInt(y)});
    ++small;
  }
  void vertex(const BigInt& x, const BigInt& y) override {
    v.push_back({x, y});
    ++big;
  }
};

// The streamed vertices are the vertices of disc_hull_exact / ellipse_hull_exact, in the same
// order, each exactly once: for rational discs and ellipses (tall ones are scanned by columns
// and buffered), and for data whose int64 run overflows after having sent a prefix.
TEST(ConvexBodyHullStream, StreamsTheExactHullInOrder) {
  check_property([] {
    auto q = *rc::gen::inRange<std::int64_t>(1, 8);
    auto cx = Rational<BigInt>(BigInt(*rc::gen::inRange<std::int64_t>(-400, 400)), BigInt(q));
    auto cy = Rational<BigInt>(BigInt(*rc::gen::inRange<std::int64_t>(-400, 400)), BigInt(q));
    auto r = Rational<BigInt>(BigInt(*rc::gen::inRange<std::int64_t>(0, 3000)),
                              BigInt(*rc::gen::inRange<std::int64_t>(1, 7)));
    RecordingSink s;
    auto h = disc_hull_stream(cx, cy, r, s);
    auto want = disc_hull_exact(cx, cy, r);
    RC_ASSERT(s.v == want.value.vertices);
    RC_ASSERT(h.vertices == want.value.vertices.size());
    RC_ASSERT(h.served == want.served);
    RC_ASSERT(want.value.vertices.size() <= disc_hull_max_vertices(r));
    auto a = Rational<BigInt>(BigInt(*rc::gen::inRange<std::int64_t>(1, 3000)),
                              BigInt(*rc::gen::inRange<std::int64_t>(1, 7)));
    RecordingSink e;
    auto he = ellipse_hull_stream(cx, cy, a, r + Rational<BigInt>(1), e);
    auto we = ellipse_hull_exact(cx, cy, a, r + Rational<BigInt>(1));
    RC_ASSERT(e.v == we.value.vertices);
    RC_ASSERT(he.vertices == we.value.vertices.size());
    RC_ASSERT(we.value.vertices.size() <= ellipse_hull_max_vertices(a, r + Rational<BigInt>(1)));
  });
}

TEST(ConvexBodyHullStream, AnOverflowAfterAPrefixSendsEveryVertexOnce) {
  // Centre (1/1777, 0), radius 1000: the int64 walk hands over 103 vertices, then the cleared
  // squares (about (1777 * 1000)^2 times direction norms) leave int64; the int128 walk must
  // skip those 103 and send the rest.
  const Rational<BigInt> cx(BigInt(1), BigInt(1777)), cy(BigInt(0)), r(BigInt(1000));
  std::size_t sent_by_int64 = 0;
  try {
    convex_body_hull_walk<Int64>(disc_body(Rational<Int64>(Int64(1), Int64(1777)),
                                           Rational<Int64>(0), Rational<Int64>(1000)),
                                 [&](const Point2<Int64>&) { ++sent_by_int64; });
  } catch (const OverflowError&) {
  }
  EXPECT_GT(sent_by_int64, 10u); // the case does test a prefix
  RecordingSink s;
  auto h = disc_hull_stream(cx, cy, r, s);
  auto want = disc_hull_exact(cx, cy, r);
  EXPECT_EQ(s.v, want.value.vertices);
  EXPECT_EQ(h.served, IntKind::int128);
  EXPECT_EQ(want.served, IntKind::int128);
  EXPECT_GT(want.value.vertices.size(), sent_by_int64);
  EXPECT_EQ(s.small + s.big, want.value.vertices.size());
}

// The bound of disc_hull_max_vertices against the observed counts: above them, and within a
// factor two (the hull has about 3.45 r^{2/3} vertices; the bound is about 6.53 r^{2/3}).
TEST(ConvexBodyHullStream, VertexBoundAboveTheObservedCounts) {
  for (std::int64_t r : {1, 2, 10, 100, 1000, 100000, 10000000}) {
    auto n = disc_hull_exact(Rational<BigInt>(0), Rational<BigInt>(0), Rational<BigInt>(r))
                 .value.vertices.size();
    auto bound = disc_hull_max_vertices(Rational<BigInt>(r));
    EXPECT_LE(n, bound) << r;
    if (r >= 1000) {
      EXPECT_LE(bound, 2 * n) << r;
    }
  }
  EXPECT_EQ(disc_hull_max_vertices(Rational<BigInt>(BigInt(1) << 200)), UINT64_MAX);
}

// Issue #41: the vertex bound is the library's, so every front end refuses a huge disc before
// any work (a radius of 10^15 used to grow memory in `zdg serve hull disc`).
TEST(ConvexBodyHullStream, VertexBoundIsCheckedBeforeAnyWork) {
  const Rational<BigInt> zero(0), huge(BigInt("1000000000000000"));
  EXPECT_GT(disc_hull_max_vertices(huge), kHullMaxVertices);
  try {
    disc_hull_exact(zero, zero, huge);
    FAIL() << "no refusal";
  } catch (const InvalidArgument& e) {
    EXPECT_NE(std::string(e.what()).find("more than the vertex bound 100000000"), std::string::npos)
        << e.what();
  }
  EXPECT_THROW(disc_hull_exact(zero, zero, Rational<BigInt>(BigInt(1) << 64)), InvalidArgument);
  EXPECT_THROW(ellipse_hull_exact(zero, zero, huge, huge), InvalidArgument);
  RecordingSink s;
  EXPECT_THROW(disc_hull_stream(zero, zero, huge, s), InvalidArgument);
  EXPECT_THROW(ellipse_hull_stream(zero, zero, huge, Rational<BigInt>(1), s), InvalidArgument);
  EXPECT_TRUE(s.v.empty());
  // A lowered bound refuses a small disc; a raised one lets it through.
  EXPECT_THROW(disc_hull_exact(zero, zero, Rational<BigInt>(1000), 10), InvalidArgument);
  EXPECT_THROW(check_disc_hull_vertices(Rational<BigInt>(1000), 10), InvalidArgument);
  EXPECT_EQ(disc_hull_exact(zero, zero, Rational<BigInt>(5), 1000).value.vertices.size(),
            12u); // (+-5, 0), (0, +-5), (+-3, +-4), (+-4, +-3): all on the circle
  EXPECT_THROW(disc_hull_exact(zero, zero, Rational<BigInt>(-1)), InvalidArgument);
}

// The registered property hull.disc.pick (zdg check): discs of radius <= 6 with rational centre
// (denominators <= 12) anywhere up to 2^64, 2^128, 2^256, against the enumerated lattice points
// and Pick's theorem.
TEST(DiscHull, RegisteredPickPropertyHolds) {
  test::expect_registered_property("hull.disc.pick", IntKind::int64, 200);
  test::expect_registered_property("hull.disc.pick", IntKind::int128, 100);
  test::expect_registered_property("hull.disc.pick", IntKind::bigint, 100);
}

} // namespace
