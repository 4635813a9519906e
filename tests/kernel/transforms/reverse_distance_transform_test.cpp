#include <zdg/kernel/transforms/reverse_distance_transform.hpp>

#include "tests/support/tower.hpp"
#include "tests/support/transform_oracle.hpp"
#include <zdg/kernel/transforms/distance_transform.hpp>

#include <gtest/gtest.h>

namespace zdg {
namespace {

template <class I>
class ReverseDistanceTransformTyped : public ::testing::Test {};
TYPED_TEST_SUITE(ReverseDistanceTransformTyped, test::TowerTypes, test::TowerNames);

// The union of the open DT balls { y : d(c, y)^p < DT(c) } is the shape (each ball avoids
// the background; each shape point lies in its own ball).
TYPED_TEST(ReverseDistanceTransformTyped, ReverseOfTheDistanceTransformIsTheShape) {
  test::check_property([] {
    auto c = test::random_transform_case();
    c.opt.min_engine_bits = test::engine_bits<TypeParam>();
    auto dt = distance_transform<std::int64_t>(c.shape, c.opt);
    auto rdt = reverse_distance_transform(dt, c.opt);
    for (std::int64_t i = 0; i < dt.size(); ++i) RC_ASSERT((rdt[i] != 0) == (c.shape[i] != 0));
  });
}

// Oracle: y is in the union iff some ball value v(c) > d(c, y)^p (brute force).
TYPED_TEST(ReverseDistanceTransformTyped, EqualsUnionOfBalls) {
  test::check_property([] {
    auto c = test::random_transform_case();
    c.opt.min_engine_bits = test::engine_bits<TypeParam>();
    const Domain& dom = c.shape.domain();
    std::mt19937 rng(*rc::gen::arbitrary<std::uint32_t>());
    Image<std::int64_t> v(dom, std::int64_t{0});
    for (auto& x : v.values()) x = rng() % 7 == 0 ? static_cast<std::int64_t>(rng() % 30) : 0;
    auto rdt = reverse_distance_transform(v, c.opt);
    for (std::int64_t y = 0; y < dom.size(); ++y) {
      bool in = false;
      for (std::int64_t ctr = 0; ctr < dom.size() && !in; ++ctr) {
        in = v[ctr] > test::metric_length<std::int64_t>(dom, c.opt, ctr, y);
      }
      RC_ASSERT((rdt[y] != 0) == in);
    }
  });
}

TEST(ReverseDistanceTransform, WorkedExample) {
  // One ball of squared radius 5 at the centre of a 5 x 5 grid: the points at squared
  // distance < 5 (0, 1, 2, 4).
  Image<std::int64_t> v(Domain({5, 5}), std::int64_t{0});
  v.values()[12] = 5;
  auto r = reverse_distance_transform(v, {});
  EXPECT_EQ(r.values(), (std::vector<std::uint8_t>{0, 0, 1, 0, 0, 0, 1, 1, 1, 0, 1, 1, 1,
                                                   1, 1, 0, 1, 1, 1, 0, 0, 0, 1, 0, 0}));
  Image<std::int64_t> none(Domain({3}), std::int64_t{0});
  EXPECT_EQ(reverse_distance_transform(none, {}).values(), (std::vector<std::uint8_t>{0, 0, 0}));
  none.values()[1] = -1;
  EXPECT_THROW(reverse_distance_transform(none, {}), InvalidArgument);
}

} // namespace
} // namespace zdg
