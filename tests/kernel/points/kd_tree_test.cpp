#include <zdg/kernel/points/kd_tree.hpp>

#include "tests/support/tower.hpp"

#include <gtest/gtest.h>
#include <rapidcheck.h>

#include <algorithm>

namespace zdg {
namespace {

// Random clouds: either spread in a box, or on a small lattice (many equal distances, the
// case where a tree's pruning meets ties).
std::vector<Point3<double>> random_cloud() {
  const int n = *rc::gen::inRange(0, 300);
  const bool lattice = *rc::gen::arbitrary<bool>();
  std::vector<Point3<double>> p;
  for (int i = 0; i < n; ++i) {
    if (lattice)
      p.push_back({double(*rc::gen::inRange(-3, 4)), double(*rc::gen::inRange(-3, 4)),
                   double(*rc::gen::inRange(-3, 4))});
    else
      p.push_back({*rc::gen::inRange(-100000, 100000) / 1000.0,
                   *rc::gen::inRange(-100000, 100000) / 1000.0,
                   *rc::gen::inRange(-100000, 100000) / 1000.0});
  }
  return p;
}

std::vector<Neighbour> brute_order(const std::vector<Point3<double>>& p, const Point3<double>& q) {
  std::vector<Neighbour> all;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const double dx = q.x - p[i].x, dy = q.y - p[i].y, dz = q.z - p[i].z;
    all.push_back({i, dx * dx + dy * dy + dz * dz});
  }
  std::sort(all.begin(), all.end(), [](const Neighbour& a, const Neighbour& b) {
    return a.distance2 < b.distance2 || (a.distance2 == b.distance2 && a.index < b.index);
  });
  return all;
}

void expect_same(const std::vector<Neighbour>& got, const std::vector<Neighbour>& want) {
  RC_ASSERT(got.size() == want.size());
  for (std::size_t i = 0; i < got.size(); ++i) {
    RC_ASSERT(got[i].index == want[i].index);
    RC_ASSERT(got[i].distance2 == want[i].distance2);
  }
}

// Oracle: sorting every point by (squared distance, index); the tree's k nearest are its first
// k, ties at the k-th distance included.
TEST(KdTree, NearestEqualTheBruteForceOrder) {
  test::check_property([] {
    const auto p = random_cloud();
    const KdTree tree(p);
    RC_ASSERT(tree.size() == p.size());
    std::vector<Neighbour> got;
    for (int t = 0; t < 5; ++t) {
      const Point3<double> q =
          p.empty() || *rc::gen::arbitrary<bool>()
              ? Point3<double>{*rc::gen::inRange(-4, 5) * 1.0, *rc::gen::inRange(-4, 5) * 0.5, 0.25}
              : p[*rc::gen::inRange<std::size_t>(0, p.size())];
      const auto k = *rc::gen::inRange<std::size_t>(0, 40);
      tree.nearest(q, k, got);
      auto want = brute_order(p, q);
      want.resize(std::min(k, want.size()));
      expect_same(got, want);
    }
  });
}

// Oracle: the brute-force order cut at squared distance r^2 (boundary included).
TEST(KdTree, WithinEqualsTheBruteForceBall) {
  test::check_property([] {
    const auto p = random_cloud();
    const KdTree tree(p);
    std::vector<Neighbour> got;
    for (int t = 0; t < 5; ++t) {
      const Point3<double> q{*rc::gen::inRange(-4, 5) * 1.0, *rc::gen::inRange(-4, 5) * 1.0,
                             *rc::gen::inRange(-4, 5) * 1.0};
      const double r = *rc::gen::inRange(-1, 8) * 0.5;
      tree.within(q, r, got);
      auto want = brute_order(p, q);
      std::erase_if(want, [&](const Neighbour& n) { return r < 0 || n.distance2 > r * r; });
      expect_same(got, want);
    }
  });
}

TEST(KdTree, LatticeTiesKeepTheSmallestIndices) {
  // The 6 axis neighbours of the origin are at distance 1; k = 4 keeps the 4 first indices.
  const std::vector<Point3<double>> p = {{0, 0, 1}, {1, 0, 0},  {0, 0, -1}, {-1, 0, 0},
                                         {0, 1, 0}, {0, -1, 0}, {0, 0, 0}};
  const KdTree tree(p);
  std::vector<Neighbour> got;
  tree.nearest({0, 0, 0}, 5, got);
  ASSERT_EQ(got.size(), 5u);
  EXPECT_EQ(got[0].index, 6u);
  for (std::size_t i = 1; i < 5; ++i) {
    EXPECT_EQ(got[i].index, i - 1);
    EXPECT_EQ(got[i].distance2, 1.0);
  }
}

} // namespace
} // namespace zdg
