// The exact 3D hull: facet planes support the point set (every point on the inner side, every
// facet vertex on its plane, facets convex and counterclockwise seen from outside), Euler's
// formula V - E + F = 2, worked examples (cubes with coplanar and collinear lattice points),
// degenerate sets, the lattice point count against "q in conv(S) iff adding q keeps the
// volume", and coordinates near 2^62 by escalation. CGAL's hull is the oracle in
// lattice_hull_cgal_test.cpp.
#include <zdg/kernel/hulls/lattice_hull_3d.hpp>

#include "tests/support/tower.hpp"

#include <set>
#include <vector>

namespace {

using namespace zdg;

template <TowerInt I>
void check_supporting(const LatticeHull3d<I>& hi, const std::vector<Point3<I>>& ptsi) {
  // In BigInt: the checks multiply normals by coordinates and cross products.
  using B = BigInt;
  auto big = [](const Point3<I>& p) {
    return Point3<B>{to_bigint(p.x), to_bigint(p.y), to_bigint(p.z)};
  };
  LatticeHull3d<B> h;
  h.dimension = hi.dimension;
  h.facets = hi.facets;
  for (const auto& v : hi.vertices) h.vertices.push_back(big(v));
  for (const auto& v : hi.normals) h.normals.push_back(big(v));
  std::vector<Point3<B>> pts;
  for (const auto& p : ptsi) pts.push_back(big(p));
  RC_ASSERT(h.dimension == 3);
  std::size_t edges = 0;
  for (std::size_t f = 0; f < h.facets.size(); ++f) {
    const auto& poly = h.facets[f];
    const auto& n = h.normals[f];
    RC_ASSERT(poly.size() >= 3);
    edges += poly.size();
    B c = dot(n, h.vertices[poly[0]]);
    for (auto i : poly) RC_ASSERT(dot(n, h.vertices[i]) == c);
    for (const auto& p : pts) RC_ASSERT(dot(n, p) <= c);
    // Strictly convex, counterclockwise about n.
    for (std::size_t i = 0; i < poly.size(); ++i) {
      const auto& a = h.vertices[poly[i]];
      const auto& b = h.vertices[poly[(i + 1) % poly.size()]];
      const auto& c2 = h.vertices[poly[(i + 2) % poly.size()]];
      RC_ASSERT(dot(cross((b - a), (c2 - b)), n) > 0);
    }
  }
  // Euler: V - E + F = 2 (each edge in two facets).
  RC_ASSERT(edges % 2 == 0);
  RC_ASSERT(static_cast<long>(h.vertices.size()) - static_cast<long>(edges / 2) +
                static_cast<long>(h.facets.size()) ==
            2);
}

template <class I>
class LatticeHull3dTest : public ::testing::Test {};
TYPED_TEST_SUITE(LatticeHull3dTest, test::TowerTypes, test::TowerNames);

TYPED_TEST(LatticeHull3dTest, FacetsSupportThePointsAndSatisfyEuler) {
  using I = TypeParam;
  test::check_property([] {
    int n = *rc::gen::inRange(4, 80);
    std::int64_t span = *rc::gen::element<std::int64_t>(1, 2, 3, 50, 100000);
    std::vector<Point3<I>> pts;
    for (int i = 0; i < n; ++i) {
      pts.push_back({I(*rc::gen::inRange<std::int64_t>(-span, span + 1)),
                     I(*rc::gen::inRange<std::int64_t>(-span, span + 1)),
                     I(*rc::gen::inRange<std::int64_t>(-span, span + 1))});
    }
    auto h = lattice_hull_3d<I>(std::span<const Point3<I>>(pts));
    if (h.dimension < 3) return; // tiny spans can be flat; CGAL test covers those
    check_supporting(h, pts);
    // Every vertex is an input point.
    for (const auto& v : h.vertices) RC_ASSERT(std::find(pts.begin(), pts.end(), v) != pts.end());
  });
}

// q in conv(S) iff conv(S + q) has the same 6 * volume (for a full-dimensional S).
TYPED_TEST(LatticeHull3dTest, LatticePointCountMatchesVolumeTest) {
  using I = TypeParam;
  test::check_property([] {
    int n = *rc::gen::inRange(4, 12);
    std::vector<Point3<I>> pts;
    for (int i = 0; i < n; ++i) {
      pts.push_back({I(*rc::gen::inRange<std::int64_t>(-2, 3)),
                     I(*rc::gen::inRange<std::int64_t>(-2, 3)),
                     I(*rc::gen::inRange<std::int64_t>(-2, 3))});
    }
    auto h = lattice_hull_3d<I>(std::span<const Point3<I>>(pts));
    if (h.dimension < 3) return;
    // The oracle's hulls on Int64 (small data), whatever the type under test.
    std::vector<Point3<Int64>> small;
    for (const auto& p : pts)
      small.push_back({int_cast<Int64>(p.x), int_cast<Int64>(p.y), int_cast<Int64>(p.z)});
    const Int64 vol6 = lattice_hull_3d<Int64>(std::span<const Point3<Int64>>(small)).volume6;
    RC_ASSERT(to_bigint(h.volume6) == to_bigint(vol6));
    if constexpr (!std::same_as<I, Int64>) {
      // The wide types agree with Int64 (whose count the brute force checks).
      auto h64 = lattice_hull_3d<Int64>(std::span<const Point3<Int64>>(small));
      RC_ASSERT(to_bigint(lattice_points_in_hull_3d(h)) ==
                to_bigint(lattice_points_in_hull_3d(h64)));
      return;
    }
    I brute = 0;
    for (int x = -2; x <= 2; ++x) {
      for (int y = -2; y <= 2; ++y) {
        for (int z = -2; z <= 2; ++z) {
          auto more = small;
          more.push_back({x, y, z});
          if (lattice_hull_3d<Int64>(std::span<const Point3<Int64>>(more)).volume6 == vol6)
            brute += 1;
        }
      }
    }
    RC_ASSERT(lattice_points_in_hull_3d(h) == brute);
  });
}

TEST(LatticeHull3dExamples, CubeWithAllItsLatticePoints) {
  using P = Point3<Int64>;
  std::vector<P> cube;
  for (int z = 0; z <= 2; ++z) {
    for (int y = 0; y <= 2; ++y) {
      for (int x = 0; x <= 2; ++x) cube.push_back({x, y, z});
    }
  }
  auto h = lattice_hull_3d<Int64>(std::span<const P>(cube));
  EXPECT_EQ(h.dimension, 3);
  EXPECT_EQ(h.vertices.size(), 8u);
  EXPECT_EQ(h.facets.size(), 6u);
  for (const auto& f : h.facets) EXPECT_EQ(f.size(), 4u);
  EXPECT_EQ(h.volume6, 48);
  EXPECT_EQ(lattice_points_in_hull_3d(h), 27);
  std::set<std::tuple<long, long, long>> normals;
  for (const auto& n : h.normals) normals.insert({n.x.value(), n.y.value(), n.z.value()});
  std::set<std::tuple<long, long, long>> want = {{1, 0, 0},  {-1, 0, 0}, {0, 1, 0},
                                                 {0, -1, 0}, {0, 0, 1},  {0, 0, -1}};
  EXPECT_EQ(normals, want);
}

TEST(LatticeHull3dExamples, ReeveTetrahedron) {
  // Reeve's tetrahedron (0,0,0), (1,0,0), (0,1,0), (1,1,r): no lattice point but its
  // vertices, volume r/6 (no Pick formula in 3D).
  using P = Point3<Int64>;
  for (int r = 1; r <= 5; ++r) {
    std::vector<P> t = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, r}};
    auto h = lattice_hull_3d<Int64>(std::span<const P>(t));
    EXPECT_EQ(h.volume6, r);
    EXPECT_EQ(h.facets.size(), 4u);
    EXPECT_EQ(lattice_points_in_hull_3d(h), 4);
  }
}

TEST(LatticeHull3dExamples, DegenerateSets) {
  using P = Point3<Int64>;
  auto hull = [](std::vector<P> p) { return lattice_hull_3d<Int64>(std::span<const P>(p)); };
  EXPECT_EQ(hull({}).dimension, -1);
  auto pt = hull({{1, 2, 3}, {1, 2, 3}});
  EXPECT_EQ(pt.dimension, 0);
  EXPECT_EQ(lattice_points_in_hull_3d(pt), 1);
  auto seg = hull({{0, 0, 0}, {2, 4, 6}, {1, 2, 3}, {3, 6, 9}});
  EXPECT_EQ(seg.dimension, 1);
  EXPECT_EQ(seg.vertices, (std::vector<P>{{0, 0, 0}, {3, 6, 9}}));
  EXPECT_EQ(lattice_points_in_hull_3d(seg), 4);
  // A 3x3 square in the plane x + y + z = 0 (spanned by (1,-1,0), (0,1,-1)).
  std::vector<P> sq;
  for (int s = 0; s <= 2; ++s) {
    for (int t = 0; t <= 2; ++t) sq.push_back({s, -s + t, -t});
  }
  auto pl = hull(sq);
  EXPECT_EQ(pl.dimension, 2);
  EXPECT_EQ(pl.vertices.size(), 4u);
  ASSERT_EQ(pl.facets.size(), 2u);
  EXPECT_EQ(pl.normals[0].x, -pl.normals[1].x);
  EXPECT_EQ(pl.volume6, 0);
  EXPECT_EQ(lattice_points_in_hull_3d(pl), 9);
}

// Regression: merging coplanar neighbours compared the two normals by a cross product (4b + 7
// bits), which overflowed int64 for coordinates of 17 bits although every other predicate
// fits (3b + 5 bits); hidden while lattice_hull_3d<Int64> escalated silently. Random points of
// span 10^5 (and 2^19 - 1) on Int64 give the BigInt hull.
TEST(LatticeHull3dRegression, Int64ServesCoordinatesBelow2To19) {
  using P = Point3<Int64>;
  std::uint64_t state = 12345;
  auto next = [&](std::int64_t span) {
    state = state * 6364136223846793005ULL + 1442695040888963407ULL;
    return static_cast<std::int64_t>((state >> 11) % static_cast<std::uint64_t>(2 * span + 1)) -
           span;
  };
  for (std::int64_t span : {std::int64_t{100000}, (std::int64_t{1} << 19) - 1}) {
    for (int round = 0; round < 20; ++round) {
      std::vector<P> pts;
      std::vector<Point3<BigInt>> big;
      for (int i = 0; i < 60; ++i) {
        pts.push_back({next(span), next(span), next(span)});
        big.push_back({to_bigint(pts.back().x), to_bigint(pts.back().y), to_bigint(pts.back().z)});
      }
      auto a = lattice_hull_3d<Int64>(std::span<const P>(pts));
      auto b = lattice_hull_3d<BigInt>(std::span<const Point3<BigInt>>(big));
      EXPECT_EQ(a.facets, b.facets);
      EXPECT_EQ(to_bigint(a.volume6), b.volume6);
    }
  }
}

TEST(LatticeHull3dEscalation, CoordinatesNear2To62AreATranslate) {
  using P = Point3<Int64>;
  const std::int64_t t = (std::int64_t{1} << 62) - 7;
  std::vector<P> small = {{0, 0, 0}, {3, 0, 0}, {0, 2, 0}, {0, 0, 5}, {1, 1, 1}, {2, 1, 3}};
  std::vector<Point3<BigInt>> far;
  for (const auto& p : small)
    far.push_back({BigInt(p.x.value() + t), BigInt(p.y.value() - t), BigInt(p.z.value() + t)});
  auto a = lattice_hull_3d<Int64>(std::span<const P>(small));
  auto b = lattice_hull_3d_exact(std::span<const Point3<BigInt>>(far));
  EXPECT_NE(b.served, IntKind::int64);
  EXPECT_EQ(to_bigint(a.volume6), b.value.volume6);
  ASSERT_EQ(a.vertices.size(), b.value.vertices.size());
  EXPECT_EQ(a.facets, b.value.facets);
  for (std::size_t i = 0; i < a.vertices.size(); ++i) {
    EXPECT_EQ(to_bigint(a.vertices[i].x) + t, b.value.vertices[i].x);
  }
  // The same points as Int64: lattice_hull_3d<Int64> overflows, the exact entry escalates.
  std::vector<P> far64;
  for (const auto& p : small) far64.push_back({p.x + t, p.y - t, p.z + t});
  EXPECT_THROW(lattice_hull_3d<Int64>(std::span<const P>(far64)), OverflowError);
  auto c = lattice_hull_3d_exact<Int64>(std::span<const P>(far64));
  EXPECT_EQ(c.served, b.served);
  EXPECT_EQ(c.value.volume6, b.value.volume6);
  // Small BigInt points are served by Int64.
  std::vector<Point3<BigInt>> small_big;
  for (const auto& p : small) small_big.push_back({to_bigint(p.x), to_bigint(p.y), to_bigint(p.z)});
  auto d = lattice_hull_3d_exact(std::span<const Point3<BigInt>>(small_big));
  EXPECT_EQ(d.served, IntKind::int64);
  EXPECT_EQ(d.value.volume6, to_bigint(a.volume6));
}

} // namespace
