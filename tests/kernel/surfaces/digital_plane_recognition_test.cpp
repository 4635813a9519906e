// Naive digital plane recognition, on every tower type:
// - soundness: a positive answer is a certificate (every point in mu <= N.x < mu + ||N||_inf,
//   N primitive);
// - completeness against brute force: on small sets of [0,2]^3 the answer equals an
//   exhaustive search over all normals with ||N||_inf <= 32 (a certifying facet normal of
//   conv(S - S) is the cross product of two chords of chords, of components at most
//   2 * 4 * 4 = 32, so the search is complete: the chord theorem in the header);
// - pieces of naive planes P(N, mu) of any octant and dominant axis are recognized, with
//   coordinates and normals far past 2^64 by escalation;
// - worked examples: a unit cube's 8 corners is no naive plane; a staircase is.
#include <zdg/kernel/surfaces/digital_plane_recognition.hpp>

#include "tests/support/tower.hpp"

#include <numeric>
#include <vector>

namespace {

using namespace zdg;

template <TowerInt I>
void check_certificate(const NaivePlaneRecognition<I>& r, const std::vector<Point3<I>>& pts) {
  RC_ASSERT(r.is_plane);
  const auto& n = r.normal;
  RC_ASSERT(gcd(gcd(n.x, n.y), n.z) == I(1));
  RC_ASSERT(r.omega == std::max({abs(n.x), abs(n.y), abs(n.z)}));
  bool touches = false;
  for (const auto& p : pts) {
    I h = dot(n, p) - r.mu;
    RC_ASSERT(I(0) <= h);
    RC_ASSERT(h < r.omega);
    touches = touches || h == I(0);
  }
  RC_ASSERT(touches); // mu is the minimum
}

// Exhaustive: is there a primitive N, ||N||_inf <= B, with width_N(S) <= ||N||_inf - 1?
bool brute_force_is_plane(const std::vector<Point3<std::int64_t>>& pts, std::int64_t bound) {
  for (std::int64_t a = -bound; a <= bound; ++a) {
    for (std::int64_t b = -bound; b <= bound; ++b) {
      for (std::int64_t c = 0; c <= bound; ++c) { // N and -N certify alike
        std::int64_t w = std::max({std::abs(a), std::abs(b), std::abs(c)});
        if (w == 0) continue;
        std::int64_t lo = INT64_MAX, hi = INT64_MIN;
        for (const auto& p : pts) {
          std::int64_t h = a * p.x + b * p.y + c * p.z;
          lo = std::min(lo, h);
          hi = std::max(hi, h);
        }
        if (hi - lo <= w - 1) return true;
      }
    }
  }
  return false;
}

template <class I>
class NaivePlaneRecognitionTest : public ::testing::Test {};
TYPED_TEST_SUITE(NaivePlaneRecognitionTest, test::TowerTypes, test::TowerNames);

TYPED_TEST(NaivePlaneRecognitionTest, AgreesWithExhaustiveSearchOnSmallSets) {
  using I = TypeParam;
  test::check_property([] {
    const int n = *rc::gen::inRange(1, 9);
    std::vector<Point3<std::int64_t>> raw;
    std::vector<Point3<I>> pts;
    for (int i = 0; i < n; ++i) {
      Point3<std::int64_t> p{*rc::gen::inRange<std::int64_t>(0, 3),
                             *rc::gen::inRange<std::int64_t>(0, 3),
                             *rc::gen::inRange<std::int64_t>(0, 3)};
      raw.push_back(p);
      pts.push_back({I(p.x), I(p.y), I(p.z)});
    }
    auto r = recognize_naive_plane<I>(std::span<const Point3<I>>(pts));
    RC_ASSERT(r.is_plane == brute_force_is_plane(raw, 32));
    if (r.is_plane) check_certificate(r, pts);
  });
}

// Points of the naive plane mu <= N.x < mu + ||N||_inf over a window of the two other axes.
template <TowerInt I>
std::vector<Point3<I>> naive_plane_piece(const Point3<I>& n, const I& mu, const I& x0, const I& y0,
                                         int w, int h) {
  // Dominant axis k: solve for the coordinate along k.
  const I ax = abs(n.x), ay = abs(n.y), az = abs(n.z);
  std::vector<Point3<I>> pts;
  for (int i = 0; i < w; ++i) {
    for (int j = 0; j < h; ++j) {
      const I u = x0 + I(i), v = y0 + I(j);
      if (az >= ax && az >= ay) {
        // mu <= a u + b v + c z < mu + |c|: z = ceil(r / c) for c > 0, floor(r / c) for c < 0.
        I r = mu - n.x * u - n.y * v;
        I z = n.z > I(0) ? ceil_div(r, n.z) : floor_div(r, n.z);
        pts.push_back({u, v, z});
      } else if (ay >= ax) {
        I r = mu - n.x * u - n.z * v;
        I y = n.y > I(0) ? ceil_div(r, n.y) : floor_div(r, n.y);
        pts.push_back({u, y, v});
      } else {
        I r = mu - n.y * u - n.z * v;
        I x = n.x > I(0) ? ceil_div(r, n.x) : floor_div(r, n.x);
        pts.push_back({x, u, v});
      }
    }
  }
  return pts;
}

TYPED_TEST(NaivePlaneRecognitionTest, PiecesOfNaivePlanesAreRecognized) {
  using I = TypeParam;
  test::check_property([] {
    std::int64_t a = *rc::gen::inRange<std::int64_t>(-40, 41);
    std::int64_t b = *rc::gen::inRange<std::int64_t>(-40, 41);
    std::int64_t c = *rc::gen::inRange<std::int64_t>(-40, 41);
    RC_PRE(a != 0 || b != 0 || c != 0);
    std::int64_t g = std::gcd(std::gcd(a, b), c);
    const Point3<I> n{I(a / g), I(b / g), I(c / g)};
    const I mu(*rc::gen::inRange<std::int64_t>(-1000, 1000));
    const I x0(*rc::gen::inRange<std::int64_t>(-1000, 1000));
    const I y0(*rc::gen::inRange<std::int64_t>(-1000, 1000));
    auto pts = naive_plane_piece(n, mu, x0, y0, *rc::gen::inRange(1, 12), *rc::gen::inRange(1, 12));
    // The generator itself: each point in the plane.
    const I omega = std::max({abs(n.x), abs(n.y), abs(n.z)});
    for (const auto& p : pts) {
      RC_ASSERT(mu <= dot(n, p));
      RC_ASSERT(dot(n, p) < mu + omega);
    }
    auto r = recognize_naive_plane<I>(std::span<const Point3<I>>(pts));
    check_certificate(r, pts);
  });
}

TYPED_TEST(NaivePlaneRecognitionTest, ASquarePieceAndAPointAboveIt) {
  // A 12 x 12 piece of the naive plane 0 <= 2x + 5y + 13z < 13 is recognized; the point
  // (6, 6, 0), at height 42 (more than three slab thicknesses above), breaks it.
  using I = TypeParam;
  const Point3<I> n{I(2), I(5), I(13)};
  auto pts = naive_plane_piece(n, I(0), I(0), I(0), 12, 12);
  auto r = recognize_naive_plane<I>(std::span<const Point3<I>>(pts));
  ASSERT_TRUE(r.is_plane);
  for (const auto& p : pts) {
    EXPECT_LE(r.mu, dot(r.normal, p));
    EXPECT_LT(dot(r.normal, p), r.mu + r.omega);
  }
  EXPECT_LE(r.omega, I(13));
  pts.push_back({I(6), I(6), I(0)});
  EXPECT_FALSE(recognize_naive_plane<I>(std::span<const Point3<I>>(pts)).is_plane);
}

TYPED_TEST(NaivePlaneRecognitionTest, WorkedExamples) {
  using I = TypeParam;
  // The 8 corners of a unit cube: every direction has width >= ||N||_inf.
  std::vector<Point3<I>> cube;
  for (int x = 0; x < 2; ++x)
    for (int y = 0; y < 2; ++y)
      for (int z = 0; z < 2; ++z) cube.push_back({I(x), I(y), I(z)});
  EXPECT_FALSE(recognize_naive_plane<I>(std::span<const Point3<I>>(cube)).is_plane);
  // A staircase z = floor((x + y) / 2): the naive plane 0 <= x + y - 2z < 2, N = (-1,-1,2).
  std::vector<Point3<I>> stairs;
  for (int x = 0; x < 6; ++x)
    for (int y = 0; y < 6; ++y) stairs.push_back({I(x), I(y), I((x + y) / 2)});
  auto r = recognize_naive_plane<I>(std::span<const Point3<I>>(stairs));
  ASSERT_TRUE(r.is_plane);
  EXPECT_EQ(r.normal, (Point3<I>{I(-1), I(-1), I(2)}));
  EXPECT_EQ(r.mu, I(-1));
  EXPECT_EQ(r.omega, I(2));
  // One point, two points, a flat set: planes of width 0.
  std::vector<Point3<I>> one{{I(4), I(-2), I(7)}};
  EXPECT_TRUE(recognize_naive_plane<I>(std::span<const Point3<I>>(one)).is_plane);
  std::vector<Point3<I>> flat{{I(0), I(0), I(5)}, {I(3), I(0), I(5)}, {I(0), I(7), I(5)}};
  auto f = recognize_naive_plane<I>(std::span<const Point3<I>>(flat));
  ASSERT_TRUE(f.is_plane);
  EXPECT_EQ(f.normal, (Point3<I>{I(0), I(0), I(-1)}));
  EXPECT_EQ(f.omega, I(1));
  // No point: a clear error.
  std::vector<Point3<I>> none;
  EXPECT_THROW(recognize_naive_plane<I>(std::span<const Point3<I>>(none)), InvalidArgument);
}

TEST(NaivePlaneRecognition, HugePlanesByEscalation) {
  // The normal (3, 2^70 + 1, 2^71 + 5) (primitive: the last two differ by an odd number...
  // checked below) over a 6 x 6 window far from the origin: Int64 cannot serve.
  const BigInt big = BigInt(1) << 70;
  Point3<BigInt> n{BigInt(3), big + 1, 2 * big + 5};
  ASSERT_EQ(gcd(gcd(n.x, n.y), n.z), BigInt(1));
  auto pts = naive_plane_piece(n, BigInt(-7) * big, big, -big, 6, 6);
  auto r = recognize_naive_plane_exact(std::span<const Point3<BigInt>>(pts));
  EXPECT_NE(r.served, IntKind::int64); // coordinates near 2^70
  ASSERT_TRUE(r.value.is_plane);
  for (const auto& p : pts) {
    BigInt h = dot(r.value.normal, p) - r.value.mu;
    EXPECT_GE(h, 0);
    EXPECT_LT(h, r.value.omega);
  }
  // Small inputs are served by int64.
  std::vector<Point3<Int64>> small{{Int64(0), Int64(0), Int64(0)}, {Int64(1), Int64(0), Int64(0)}};
  EXPECT_EQ(recognize_naive_plane_exact(std::span<const Point3<Int64>>(small)).served,
            IntKind::int64);
}

} // namespace
