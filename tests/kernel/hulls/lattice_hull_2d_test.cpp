// The exact 2D hull against gift wrapping (Jarvis march, an independent algorithm written
// here on BigInt), degenerate sets, and coordinates near 2^62 (exact by escalation).
#include <zdg/kernel/hulls/lattice_hull_2d.hpp>

#include "tests/support/check_registry.hpp"
#include "tests/support/tower.hpp"

#include <algorithm>
#include <vector>

namespace {

using namespace zdg;

// Jarvis march from the lowest-then-leftmost point: the next vertex is the point q with every
// other point left of (p, q), the farthest one among collinear candidates.
std::vector<Point2<BigInt>> jarvis(std::vector<Point2<BigInt>> pts) {
  std::vector<Point2<BigInt>> out;
  if (pts.empty()) return out;
  auto start = *std::min_element(pts.begin(), pts.end(), [](const auto& a, const auto& b) {
    return a.y < b.y || (a.y == b.y && a.x < b.x);
  });
  auto d2 = [](const Point2<BigInt>& a, const Point2<BigInt>& b) {
    return (a.x - b.x) * (a.x - b.x) + (a.y - b.y) * (a.y - b.y);
  };
  Point2<BigInt> p = start;
  for (;;) {
    out.push_back(p);
    std::optional<Point2<BigInt>> q;
    for (const auto& c : pts) {
      if (c == p) continue;
      if (!q) {
        q = c;
        continue;
      }
      int o = orientation(p, *q, c);
      if (o < 0 || (o == 0 && d2(p, c) > d2(p, *q))) q = c;
    }
    if (!q || *q == start) break;
    p = *q;
    if (out.size() > pts.size()) break;
  }
  return out;
}

template <class I>
class LatticeHull2d : public ::testing::Test {};
TYPED_TEST_SUITE(LatticeHull2d, test::TowerTypes, test::TowerNames);

TYPED_TEST(LatticeHull2d, AgreesWithGiftWrapping) {
  using I = TypeParam;
  test::check_property([] {
    std::int64_t span = *rc::gen::element<std::int64_t>(1, 3, 20, 1000000000);
    // Past 64 points the Akl-Toussaint throw-away runs first.
    int n = *rc::gen::element(1, 2, 3, 10, 50, 65, 200, 400);
    bool line = *rc::gen::inRange(0, 4) == 0;
    std::int64_t dx = *rc::gen::inRange<std::int64_t>(-5, 6),
                 dy = *rc::gen::inRange<std::int64_t>(-5, 6);
    std::vector<Point2<I>> pts;
    std::vector<Point2<BigInt>> big;
    for (int i = 0; i < n; ++i) {
      std::int64_t x, y;
      if (line) {
        std::int64_t t = *rc::gen::inRange<std::int64_t>(-9, 10);
        x = 3 + t * dx;
        y = -2 + t * dy;
      } else {
        x = *rc::gen::inRange<std::int64_t>(-span, span + 1);
        y = *rc::gen::inRange<std::int64_t>(-span, span + 1);
      }
      pts.push_back({I(x), I(y)});
      big.push_back({BigInt(x), BigInt(y)});
    }
    auto h = lattice_hull_2d<I>(std::span<const Point2<I>>(pts));
    auto want = jarvis(big);
    RC_ASSERT(h.size() == want.size());
    for (std::size_t i = 0; i < h.size(); ++i) {
      RC_ASSERT(to_bigint(h[i].x) == want[i].x);
      RC_ASSERT(to_bigint(h[i].y) == want[i].y);
    }
  });
}

TEST(LatticeHull2dExamples, DegenerateSets) {
  using P = Point2<Int64>;
  auto hull = [](std::vector<P> p) { return lattice_hull_2d<Int64>(std::span<const P>(p)); };
  EXPECT_TRUE(hull({}).empty());
  EXPECT_EQ(hull({{4, 4}, {4, 4}}), (std::vector<P>{{4, 4}}));
  EXPECT_EQ(hull({{2, 2}, {0, 0}, {1, 1}, {3, 3}}), (std::vector<P>{{0, 0}, {3, 3}}));
  EXPECT_EQ(hull({{0, 5}, {0, -1}, {0, 2}}), (std::vector<P>{{0, -1}, {0, 5}}));
  // A 3x3 grid: the 4 corners, counterclockwise from (0, 0); edge midpoints excluded.
  std::vector<P> grid;
  for (int y = 0; y < 3; ++y) {
    for (int x = 0; x < 3; ++x) grid.push_back({x, y});
  }
  EXPECT_EQ(hull(grid), (std::vector<P>{{0, 0}, {2, 0}, {2, 2}, {0, 2}}));
  // Lowest row with two points: the start is its leftmost point.
  EXPECT_EQ(hull({{5, 0}, {1, 0}, {3, 4}}), (std::vector<P>{{1, 0}, {5, 0}, {3, 4}}));
}

// Coordinates near 2^62: the differences overflow int64, the escalated hull is exact.
TEST(LatticeHull2dEscalation, CoordinatesNear2To62) {
  const std::int64_t M = std::int64_t{1} << 62;
  using P = Point2<Int64>;
  std::vector<P> p = {{-M, -M}, {M, -M}, {M, M}, {-M, M}, {0, 0}, {M - 1, 0}, {-M, 5}};
  std::vector<P> want = {{-M, -M}, {M, -M}, {M, M}, {-M, M}};
  EXPECT_THROW(lattice_hull_2d_indices<Int64>(std::span<const P>(p)), OverflowError);
  EXPECT_THROW(lattice_hull_2d<Int64>(std::span<const P>(p)), OverflowError); // computes on I
  auto e = lattice_hull_2d_exact<Int64>(std::span<const P>(p));
  EXPECT_EQ(e.value, want);
  EXPECT_EQ(e.served, IntKind::int128);
  // A nearly flat triangle whose orientation needs all 127 bits.
  std::vector<P> q = {{-M, -M + 1}, {M, M}, {M - 1, M - 1}, {0, 0}};
  auto h = lattice_hull_2d_exact<Int64>(std::span<const P>(q)).value;
  std::vector<Point2<BigInt>> qb;
  for (auto& x : q) qb.push_back({to_bigint(x.x), to_bigint(x.y)});
  auto w = jarvis(qb);
  ASSERT_EQ(h.size(), w.size());
  for (std::size_t i = 0; i < h.size(); ++i) EXPECT_EQ(to_bigint(h[i].x), w[i].x);
}

// The registered property hull.points.brute_force (zdg check): up to 16 points, clustered (with
// duplicates and collinear points) or spread over 64, 128, 256-bit coordinates, against the
// O(n^3) edge test; the measures against the shoelace formula, gcds and Pick.
TEST(LatticeHull2d, RegisteredBruteForcePropertyHolds) {
  test::expect_registered_property("hull.points.brute_force", IntKind::int64, 300);
  test::expect_registered_property("hull.points.brute_force", IntKind::int128, 100);
  test::expect_registered_property("hull.points.brute_force", IntKind::bigint, 100);
}

} // namespace
