// The long sweeps (label "slow"): the disc hull against enumeration for every radius up to
// 400 at the origin and at the centre (1/2, 1/3), and every radius up to 40 in steps of 1/7
// for a centre (2/7, -3/5); the count of vertices grows like r^{2/3} (Balog-Barany 1991).
#include <zdg/kernel/hulls/convex_body_hull.hpp>

#include "tests/support/tower.hpp"
#include <zdg/kernel/hulls/lattice_hull_2d.hpp>

#include <vector>

namespace {

using namespace zdg;

std::vector<Point2<Int64>> brute(const QuadraticBody<Int64>& K) {
  std::vector<Point2<Int64>> pts;
  for (Int64 y = K.ylo; y <= K.yhi; ++y) {
    // Column extremes suffice for the hull: scan each row from both ends.
    Int64 lo = K.xlo, hi = K.xhi;
    while (lo <= hi && !K.contains({lo, y})) ++lo;
    while (hi >= lo && !K.contains({hi, y})) --hi;
    if (lo <= hi) {
      pts.push_back({lo, y});
      pts.push_back({hi, y});
    }
  }
  return lattice_hull_2d<Int64>(std::span<const Point2<Int64>>(pts));
}

TEST(ConvexBodyHullSlow, EveryRadiusUpTo400) {
  using R = Rational<Int64>;
  for (std::int64_t r = 0; r <= 400; ++r) {
    for (auto [cx, cy] :
         {std::pair{R(0), R(0)}, std::pair{R(Int64(1), Int64(2)), R(Int64(1), Int64(3))}}) {
      auto K = disc_body(cx, cy, R(r));
      ASSERT_EQ(convex_body_hull<Int64>(K), brute(K))
          << "r = " << r << " centre " << cx << ", " << cy;
    }
  }
}

TEST(ConvexBodyHullSlow, RationalRadiiInStepsOfOneSeventh) {
  using R = Rational<Int64>;
  for (std::int64_t k = 0; k <= 280; ++k) {
    auto K = disc_body(R(Int64(2), Int64(7)), R(Int64(-3), Int64(5)), R(Int64(k), Int64(7)));
    ASSERT_EQ(convex_body_hull<Int64>(K), brute(K)) << "r = " << k << "/7";
  }
}

} // namespace
