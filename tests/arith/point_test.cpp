#include <zdg/arith/point.hpp>

#include <zdg/arith/integer.hpp>

#include "tests/support/tower.hpp"

#include <gtest/gtest.h>

#include <cstdint>
#include <sstream>

namespace {

using zdg::Point2;
using zdg::Point3;

TEST(Point, LexicographicOrderAndPrinting) {
  using P = zdg::Point2<std::int64_t>;
  EXPECT_LT((P{1, 5}), (P{2, 0}));
  EXPECT_LT((P{1, 0}), (P{1, 1}));
  EXPECT_EQ((P{3, 4}), (P{3, 4}));
  std::ostringstream s;
  s << zdg::Point3<int>{1, -2, 3};
  EXPECT_EQ(s.str(), "(1, -2, 3)");
}

TEST(Point, WorkedExamples) {
  using P = Point3<std::int64_t>;
  EXPECT_EQ(cross(P{1, 0, 0}, P{0, 1, 0}), (P{0, 0, 1})); // e_x x e_y = e_z
  EXPECT_EQ(dot(P{1, 2, 3}, P{4, -5, 6}), 12);
  EXPECT_EQ(cross(Point2<int>{2, 1}, Point2<int>{1, 3}), 5); // det [[2, 1], [1, 3]]
  EXPECT_EQ((P{1, 2, 3} - P{1, 1, 1}) * 2, (P{0, 2, 4}));
  EXPECT_EQ(-(Point2<int>{1, -2}), (Point2<int>{-1, 2}));
}

template <class I>
class PointTower : public ::testing::Test {};
TYPED_TEST_SUITE(PointTower, zdg::test::TowerTypes, zdg::test::TowerNames);

// Lagrange's identity |a x b|^2 = |a|^2 |b|^2 - (a . b)^2, a x b orthogonal to a and b,
// antisymmetry and bilinearity: the vector product is the exterior product of R^3.
TYPED_TEST(PointTower, CrossProductIdentities) {
  using I = TypeParam;
  zdg::test::check_property([] {
    auto c = [] { return I(*rc::gen::inRange<std::int64_t>(-1000, 1001)); };
    const Point3<I> a{c(), c(), c()}, b{c(), c(), c()}, d{c(), c(), c()};
    const Point3<I> n = cross(a, b);
    RC_ASSERT(dot(n, n) == dot(a, a) * dot(b, b) - dot(a, b) * dot(a, b));
    RC_ASSERT(dot(n, a) == I(0));
    RC_ASSERT(dot(n, b) == I(0));
    RC_ASSERT(cross(b, a) == -n);
    RC_ASSERT(cross(a + d, b) == n + cross(d, b));
    RC_ASSERT((a + b) - b == a);
    // 2D: the determinant is the z of the 3D product of the embedded vectors.
    const Point2<I> p{a.x, a.y}, q{b.x, b.y};
    RC_ASSERT(cross(p, q) == cross(Point3<I>{a.x, a.y, I(0)}, Point3<I>{b.x, b.y, I(0)}).z);
    RC_ASSERT(I(3) * p == p + p + p);
  });
}

// On the checked types an overflow throws instead of wrapping.
TEST(Point, OverflowIsLoud) {
  using I = zdg::Int64;
  const Point2<I> big{I(INT64_MAX), I(1)};
  EXPECT_THROW(big + big, zdg::OverflowError);
  EXPECT_THROW(dot(big, big), zdg::OverflowError);
}

} // namespace
