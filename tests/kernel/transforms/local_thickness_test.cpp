#include <zdg/kernel/transforms/local_thickness.hpp>

#include "tests/support/tower.hpp"
#include "tests/support/transform_oracle.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace zdg {
namespace {

// A random small case of the local thickness (l2, no torus): 1-D to 4-D, odd and non-cubic
// extents, lower bounds of any sign, any density, at least one background point.
TransformOptions random_case(std::mt19937& rng, Image<std::uint8_t>& shape) {
  auto pick = [&](int lo, int hi) {
    return lo + static_cast<int>(rng() % static_cast<unsigned>(hi - lo + 1));
  };
  const int d = pick(1, 4);
  const int max_extent[] = {0, 30, 12, 7, 4};
  std::vector<std::int64_t> ext, low;
  for (int k = 0; k < d; ++k) {
    ext.push_back(pick(1, max_extent[d]));
    low.push_back(pick(-5, 5));
  }
  Domain dom(ext, low);
  const int density = pick(0, 100);
  std::vector<std::uint8_t> v(static_cast<std::size_t>(dom.size()));
  for (auto& x : v) x = pick(0, 99) < density ? 1 : 0;
  v[rng() % v.size()] = 0;
  shape = Image<std::uint8_t>(dom, v);
  TransformOptions opt;
  opt.threads = static_cast<unsigned>(pick(1, 3));
  return opt;
}

std::int64_t squared_distance(const std::vector<std::int64_t>& a,
                              const std::vector<std::int64_t>& b) {
  std::int64_t s = 0;
  for (std::size_t k = 0; k < a.size(); ++k) s += (a[k] - b[k]) * (a[k] - b[k]);
  return s;
}

// The definition, by enumeration: every centre c of the object, every integer s = 1, 2, ... for
// which the open ball |y - c|^2 < s meets no background point of the domain (the inscribed
// balls), and every point y of that ball: R2(y) = the largest such s.
Image<std::int64_t> brute_force(const Image<std::uint8_t>& shape) {
  const Domain& dom = shape.domain();
  std::vector<std::vector<std::int64_t>> pts;
  for (std::int64_t i = 0; i < dom.size(); ++i) pts.push_back(dom.point(i));
  Image<std::int64_t> r2(dom, std::int64_t{0});
  for (std::int64_t c = 0; c < dom.size(); ++c) {
    if (shape[c] == 0) continue;
    for (std::int64_t s = 1;; ++s) {
      bool inscribed = true;
      for (std::int64_t b = 0; b < dom.size() && inscribed; ++b) {
        inscribed = shape[b] != 0 || squared_distance(pts[static_cast<std::size_t>(b)],
                                                      pts[static_cast<std::size_t>(c)]) >= s;
      }
      if (!inscribed) break;
      for (std::int64_t y = 0; y < dom.size(); ++y) {
        if (squared_distance(pts[static_cast<std::size_t>(y)], pts[static_cast<std::size_t>(c)]) <
            s)
          r2[y] = std::max(r2[y], s);
      }
    }
  }
  return r2;
}

template <class I>
class LocalThicknessTyped : public ::testing::Test {};
TYPED_TEST_SUITE(LocalThicknessTyped, test::TowerTypes, test::TowerNames);

// Hildebrand-Ruegsegger's definition, enumerated: the largest inscribed ball containing each
// point, on every engine width of the distance transform.
TYPED_TEST(LocalThicknessTyped, EqualsLargestInscribedBallByEnumeration) {
  test::check_property([] {
    std::mt19937 rng(*rc::gen::arbitrary<std::uint32_t>());
    Image<std::uint8_t> shape;
    auto opt = random_case(rng, shape);
    opt.min_engine_bits = test::engine_bits<TypeParam>();
    const auto r2 = local_thickness_squared_radius(shape, opt);
    RC_ASSERT(r2 == brute_force(shape));
    const auto t = local_thickness(shape, opt);
    for (std::int64_t i = 0; i < shape.size(); ++i) {
      RC_ASSERT(t[i] == static_cast<float>(2.0 * std::sqrt(static_cast<double>(r2[i]))));
    }
  });
}

// The smallest sum of d squares >= s (the squared distance from a ball's centre to the nearest
// lattice point outside the open ball |v|^2 < s), by enumeration.
std::int64_t next_sum_of_squares(std::int64_t s, int d) {
  std::int64_t best = -1;
  const auto r = static_cast<std::int64_t>(std::sqrt(static_cast<double>(s))) + 2;
  std::vector<std::int64_t> v(static_cast<std::size_t>(d), 0);
  for (;;) {
    std::int64_t q = 0;
    for (auto x : v) q += x * x;
    if (q >= s && (best < 0 || q < best)) best = q;
    int k = d - 1;
    while (k >= 0 && v[static_cast<std::size_t>(k)] == r) v[static_cast<std::size_t>(k--)] = 0;
    if (k < 0) break;
    ++v[static_cast<std::size_t>(k)];
  }
  return best;
}

// A digital ball B(c, s) with a margin of background: every inscribed ball B(c', DT(c')) lies
// in it, and DT(c') <= DT(c) (for w a shortest vector with |w|^2 = DT(c) and u = c' - c, one of
// c' + w, c' - w is outside: |u + w|^2 >= |w|^2 when u.w >= 0), so R2 = DT(c) = the smallest
// sum of d squares >= s at every point of the ball: the thickness of a ball is its diameter.
TEST(LocalThickness, BallHasItsDiameterEverywhere) {
  test::check_property([] {
    const int d = *rc::gen::inRange(2, 4);
    const std::int64_t s = *rc::gen::inRange<std::int64_t>(1, d == 2 ? 200 : 60);
    const auto r = static_cast<std::int64_t>(std::sqrt(static_cast<double>(s))) + 1;
    const std::int64_t half = 2 * r + 1;
    const std::int64_t shift = *rc::gen::inRange<std::int64_t>(-3, 4);
    Domain dom(std::vector<std::int64_t>(static_cast<std::size_t>(d), 2 * half + 1),
               std::vector<std::int64_t>(static_cast<std::size_t>(d), -half + shift));
    Image<std::uint8_t> shape(dom, std::uint8_t{0});
    const std::vector<std::int64_t> c(static_cast<std::size_t>(d), shift);
    for (std::int64_t i = 0; i < dom.size(); ++i) shape[i] = squared_distance(dom.point(i), c) < s;
    TransformOptions opt;
    opt.threads = static_cast<unsigned>(*rc::gen::inRange(1, 4));
    const auto r2 = local_thickness_squared_radius(shape, opt);
    const std::int64_t expected = next_sum_of_squares(s, d);
    for (std::int64_t i = 0; i < dom.size(); ++i) RC_ASSERT(r2[i] == (shape[i] ? expected : 0));
  });
}

// A slab of w layers between two background layers (the other axes span the domain): the
// largest inscribed balls are centred on the middle layer(s), of squared radius
// floor((w + 1) / 2)^2, and every layer lies in one of them.
TEST(LocalThickness, SlabOfWidthW) {
  test::check_property([] {
    const std::int64_t w = *rc::gen::inRange<std::int64_t>(1, 12);
    const std::int64_t ny = *rc::gen::inRange<std::int64_t>(1, 9);
    const std::int64_t nx = *rc::gen::inRange<std::int64_t>(1, 9);
    const int axis = *rc::gen::inRange(0, 3);
    std::vector<std::int64_t> ext{ny, nx};
    ext.insert(ext.begin() + axis, w + 2);
    Domain dom(ext);
    Image<std::uint8_t> shape(dom, std::uint8_t{0});
    for (std::int64_t i = 0; i < dom.size(); ++i) {
      const auto t = dom.point(i)[static_cast<std::size_t>(axis)];
      shape[i] = t >= 1 && t <= w;
    }
    const auto r2 = local_thickness_squared_radius(shape, {});
    const auto t = local_thickness(shape, {});
    const std::int64_t h = (w + 1) / 2;
    for (std::int64_t i = 0; i < dom.size(); ++i) {
      RC_ASSERT(r2[i] == (shape[i] ? h * h : 0));
      RC_ASSERT(t[i] == (shape[i] ? static_cast<float>(2 * h) : 0.0f));
    }
  });
}

// Worked example (2-D): a bar 3 wide (squared radius floor(4 / 2)^2 = 4) joined to a 7 x 7
// square (the centre's ball, DT 16, holds the disc |v|^2 < 16): the square's points within
// that disc get 16, its corners only smaller balls, the bar 4 up to its end.
TEST(LocalThickness, BarAndSquare) {
  // Rows 1..7, columns 1..7: the square; rows 3..5, columns 8..14: the bar; background around.
  Domain dom({9, 16});
  Image<std::uint8_t> shape(dom, std::uint8_t{0});
  for (std::int64_t y = 1; y <= 7; ++y) {
    for (std::int64_t x = 1; x <= 7; ++x) shape.at(std::vector<std::int64_t>{y, x}) = 1;
  }
  for (std::int64_t y = 3; y <= 5; ++y) {
    for (std::int64_t x = 8; x <= 14; ++x) shape.at(std::vector<std::int64_t>{y, x}) = 1;
  }
  const auto r2 = local_thickness_squared_radius(shape, {});
  auto at = [&](std::int64_t y, std::int64_t x) { return r2.at(std::vector<std::int64_t>{y, x}); };
  EXPECT_EQ(at(4, 4), 16); // the centre of the square
  EXPECT_EQ(at(1, 4), 16); // |(-3, 0)|^2 = 9 < 16
  EXPECT_EQ(at(2, 2), 16); // |(-2, -2)|^2 = 8 < 16
  EXPECT_EQ(at(1, 1), 9);  // the corner: the ball of (3, 3) (DT 9) holds it, |(2, 2)|^2 = 8
  EXPECT_EQ(at(4, 12), 4); // the bar, away from the square
  EXPECT_EQ(at(4, 14), 4); // the bar's end: ball of (4, 13), DT 4 (the background at x = 15)
  EXPECT_EQ(at(0, 0), 0);
  EXPECT_EQ(r2, brute_force(shape));
}

TEST(LocalThickness, RejectsOtherMetricsTorusAndNoBackground) {
  Image<std::uint8_t> shape(Domain({4, 4}), std::uint8_t{1});
  shape[0] = 0;
  TransformOptions opt;
  opt.metric = Metric::linf();
  EXPECT_THROW(local_thickness(shape, opt), InvalidArgument);
  opt.metric = Metric::l1();
  EXPECT_THROW(local_thickness(shape, opt), InvalidArgument);
  opt.metric = Metric::l2();
  opt.torus = {true, false};
  EXPECT_THROW(local_thickness(shape, opt), InvalidArgument);
  Image<std::uint8_t> full(Domain({3, 3}), std::uint8_t{1});
  EXPECT_THROW(local_thickness(full, {}), InvalidArgument);
}

} // namespace
} // namespace zdg
