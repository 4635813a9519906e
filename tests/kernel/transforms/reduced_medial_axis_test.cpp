#include <zdg/kernel/transforms/reduced_medial_axis.hpp>

#include "tests/support/tower.hpp"
#include "tests/support/transform_oracle.hpp"
#include <zdg/kernel/transforms/distance_transform.hpp>
#include <zdg/kernel/transforms/reverse_distance_transform.hpp>

#include <gtest/gtest.h>

namespace zdg {
namespace {

template <class I>
class ReducedMedialAxisTyped : public ::testing::Test {};
TYPED_TEST_SUITE(ReducedMedialAxisTyped, test::TowerTypes, test::TowerNames);

// Coeurjolly-Montanvert 2007: the medial balls are DT balls (centre in the shape, value the
// DT there) and their union is exactly the shape.
TYPED_TEST(ReducedMedialAxisTyped, BallsAreDtBallsAndRebuildTheShape) {
  test::check_property([] {
    auto c = test::random_transform_case();
    c.opt.min_engine_bits = test::engine_bits<TypeParam>();
    auto balls = reduced_medial_axis(c.shape, c.opt);
    auto dt = distance_transform<std::int64_t>(c.shape, c.opt);
    const Domain& dom = c.shape.domain();
    Image<std::int64_t> v(dom, std::int64_t{0});
    std::int64_t prev = -1;
    for (const auto& b : balls) {
      std::int64_t i = dom.index(b.centre);
      RC_ASSERT(i > prev); // sorted, no duplicates
      prev = i;
      RC_ASSERT(c.shape[i] != 0);
      RC_ASSERT(b.value == dt[i]);
      v[i] = b.value;
    }
    auto rebuilt = reverse_distance_transform(v, c.opt);
    for (std::int64_t i = 0; i < dom.size(); ++i) RC_ASSERT((rebuilt[i] != 0) == (c.shape[i] != 0));
  });
}

TEST(ReducedMedialAxis, DiscKeepsItsCentreBall) {
  // The l2 disc of squared radius < 10 centred in an 11 x 11 grid: the DT ball of the centre
  // is the whole disc and wins the power of the centre strictly (-10 against at best
  // 1 - 5), so it is kept; other balls survive only through ties of the power (at (2, 2) the
  // ball of (1, 1), DT 4, ties with it: 2 - 4 = 8 - 10).
  Domain dom({11, 11}, {-5, -5});
  Image<std::uint8_t> shape(dom, std::uint8_t{0});
  for (std::int64_t i = 0; i < dom.size(); ++i) {
    auto p = dom.point(i);
    shape[i] = p[0] * p[0] + p[1] * p[1] < 10 ? 1 : 0;
  }
  auto balls = reduced_medial_axis(shape, {});
  ASSERT_FALSE(balls.empty());
  bool centre = false;
  for (const auto& b : balls) {
    centre = centre || (b.centre == std::vector<std::int64_t>{0, 0} && b.value == 10);
    EXPECT_LE(b.value, 10);
  }
  EXPECT_TRUE(centre);
  EXPECT_LT(balls.size(), 10u); // the disc has 29 points
}

} // namespace
} // namespace zdg
