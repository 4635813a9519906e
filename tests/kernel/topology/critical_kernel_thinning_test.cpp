#include <zdg/kernel/topology/critical_kernel_thinning.hpp>

#include "tests/support/binary_images.hpp"
#include "tests/support/thinning_checks.hpp"
#include "tests/support/tower.hpp"
#include <zdg/arith/error.hpp>
#include <zdg/kernel/topology/betti_numbers.hpp>

#include <gtest/gtest.h>

namespace zdg {
namespace {

const SkeletonKind kKinds[4] = {SkeletonKind::ultimate, SkeletonKind::curve, SkeletonKind::surface,
                                SkeletonKind::medial_axis};

std::int64_t count(const Image<std::uint8_t>& img) {
  std::int64_t n = 0;
  for (auto v : img.values()) n += v != 0;
  return n;
}

// Bertrand's theorem: a subset meeting every critical clique has the topology of the object.
// Random images, both dimensions, every skeleton kind, random anchors: subset, anchors kept,
// same Betti numbers for object and background (brute-force homology), and a fixed point
// (thinning the result deletes nothing) for the ultimate and curve kinds.
TEST(CriticalKernelThinning, SubsetHomotopyEquivalentAndFixedPoint) {
  test::check_property([] {
    const int dim = *rc::gen::inRange(2, 4);
    const AdjacencyPair pair = default_adjacency_pair(dim);
    const auto kind = kKinds[*rc::gen::inRange(0, 4)];
    const auto img = test::random_binary_image(dim, dim == 3 ? 6 : 10);
    ThinningOptions opt;
    opt.skeleton = kind;
    opt.threads = *rc::gen::inRange(1u, 4u);
    Image<std::uint8_t> anchors(img.domain(), std::uint8_t{0});
    if (*rc::gen::arbitrary<bool>()) {
      for (std::int64_t i = 0; i < img.size(); ++i) anchors[i] = *rc::gen::inRange(0, 10) == 0;
      opt.anchors = &anchors;
    }
    std::vector<std::int64_t> log;
    opt.deletions = &log;
    const auto r = critical_kernel_thinning(img, opt);
    RC_ASSERT(r.deleted == static_cast<std::int64_t>(log.size()));
    test::check_subset_and_homotopy(img, r.skeleton, pair);
    for (std::int64_t i = 0; i < img.size(); ++i) {
      if (opt.anchors != nullptr && anchors[i] != 0 && img[i] != 0) RC_ASSERT(r.skeleton[i] != 0);
    }
    // (Isthmus persistence makes the surface kind a fixed point only given its anchors.)
    if (kind == SkeletonKind::ultimate || kind == SkeletonKind::curve) {
      opt.deletions = nullptr;
      RC_ASSERT(critical_kernel_thinning(r.skeleton, opt).skeleton == r.skeleton);
    }
  });
}

// Symmetric: for a symmetry of the cube (of the square in 2D), rotating the input, thinning
// and rotating back gives the thinning of the input, point for point (ultimate, curve and
// surface kinds). Four random symmetries per case here; all 48 on every case in
// critical_kernel_thinning_slow_test.cpp, and all 48 on a fixed shape below.
TEST(CriticalKernelThinning, InvariantUnderSymmetriesOfTheCube) {
  test::check_property([] {
    const int dim = *rc::gen::inRange(2, 4);
    const std::int64_t n = *rc::gen::inRange(3, dim == 3 ? 8 : 12);
    const auto img = test::random_cubic_image(dim, n);
    // (Not the medial-axis kind: the reduced medial axis breaks ties of the power diagram by
    // scan order, so its anchors are not symmetric.)
    const auto kind = kKinds[*rc::gen::inRange(0, 3)];
    ThinningOptions opt;
    opt.skeleton = kind;
    const auto ref = critical_kernel_thinning(img, opt).skeleton;
    const auto all = test::symmetries(dim);
    for (int t = 0; t < 4; ++t) {
      const auto& s =
          all[static_cast<std::size_t>(*rc::gen::inRange<int>(0, static_cast<int>(all.size())))];
      const auto moved = critical_kernel_thinning(test::apply_symmetry(img, s), opt).skeleton;
      RC_ASSERT(test::apply_symmetry(moved, s, true) == ref);
    }
  });
}

TEST(CriticalKernelThinning, AllFortyEightSymmetriesOnATorus) {
  // A solid torus tilted off the axes (so that no symmetry maps it onto itself), cropped to a
  // cube.
  const auto img = test::image_from({13, 13, 13}, [](const std::vector<std::int64_t>& c) {
    const std::int64_t x = c[0] + c[1] / 3, y = c[1] - c[2] / 4, z = c[2] + 3;
    const std::int64_t q = x * x + y * y, s = q + 144 + z * z - 25;
    return s <= 0 || s * s <= 4 * 144 * q;
  });
  for (auto kind : {SkeletonKind::ultimate, SkeletonKind::curve, SkeletonKind::surface}) {
    ThinningOptions opt;
    opt.skeleton = kind;
    const auto ref = critical_kernel_thinning(img, opt).skeleton;
    EXPECT_GT(count(ref), 8);
    for (const auto& s : test::symmetries(3)) {
      const auto moved = critical_kernel_thinning(test::apply_symmetry(img, s), opt).skeleton;
      EXPECT_EQ(test::apply_symmetry(moved, s, true), ref);
    }
  }
}

TEST(CriticalKernelThinning, SymmetriesAreTheGroupOfTheCube) {
  const auto s3 = test::symmetries(3);
  EXPECT_EQ(s3.size(), 48u);
  EXPECT_EQ(test::symmetries(2).size(), 8u);
  // Each symmetry is a bijection with its inverse, and they are pairwise different.
  Image<std::uint8_t> img(Domain({3, 3, 3}), std::uint8_t{0});
  for (std::int64_t i = 0; i < 27; ++i) img[i] = static_cast<std::uint8_t>(i);
  std::vector<Image<std::uint8_t>> seen;
  for (const auto& s : s3) {
    const auto m = test::apply_symmetry(img, s);
    EXPECT_EQ(test::apply_symmetry(m, s, true), img);
    for (const auto& other : seen) EXPECT_FALSE(other == m);
    seen.push_back(m);
  }
}

// Closed forms: a ball centred on a point thins to that point, a solid torus to a closed
// curve (1, 1, 0), a hollow sphere to a closed surface (1, 0, 1); a 2x2x2 block is a fixed
// point (symmetric thinning cannot choose among its points).
TEST(CriticalKernelThinning, BallTorusSphereAndBlock) {
  const auto ball = test::ball_image(9, 80);
  const auto b = critical_kernel_thinning(ball).skeleton;
  EXPECT_EQ(count(b), 1);
  EXPECT_NE(b[(10 * 21 + 10) * 21 + 10], 0);
  const auto torus = test::torus_image(10, 3);
  for (auto kind : {SkeletonKind::ultimate, SkeletonKind::curve}) {
    ThinningOptions opt;
    opt.skeleton = kind;
    const auto c = critical_kernel_thinning(torus, opt).skeleton;
    EXPECT_EQ(betti_numbers(c, {3, 26, 6}).b, (std::array<std::int64_t, 3>{1, 1, 0}));
    EXPECT_LT(count(c), count(torus) / 10);
  }
  const auto sphere = test::hollow_sphere_image(10, 30, 99);
  for (auto kind : {SkeletonKind::ultimate, SkeletonKind::surface}) {
    ThinningOptions opt;
    opt.skeleton = kind;
    const auto s = critical_kernel_thinning(sphere, opt).skeleton;
    EXPECT_EQ(betti_numbers(s, {3, 26, 6}).b, (std::array<std::int64_t, 3>{1, 0, 1}));
    EXPECT_LT(count(s), count(sphere) / 2);
  }
  Image<std::uint8_t> block(Domain({2, 2, 2}), std::uint8_t{1});
  EXPECT_EQ(critical_kernel_thinning(block).skeleton, block);
  const auto disc = test::annulus_image(12, -1, 120);
  EXPECT_EQ(count(critical_kernel_thinning(disc).skeleton), 1);
  const auto ring = test::annulus_image(12, 30, 120);
  EXPECT_EQ(betti_numbers(critical_kernel_thinning(ring).skeleton, {2, 8, 4}).b,
            (std::array<std::int64_t, 3>{1, 1, 0}));
}

TEST(CriticalKernelThinning, ThreadCountDoesNotChangeTheResult) {
  const auto torus = test::torus_image(12, 4);
  ThinningOptions opt;
  opt.threads = 1;
  const auto a = critical_kernel_thinning(torus, opt);
  opt.threads = 4;
  const auto b = critical_kernel_thinning(torus, opt);
  EXPECT_EQ(a.skeleton, b.skeleton);
  EXPECT_EQ(a.passes, b.passes);
  EXPECT_GT(a.passes, 1);
}

TEST(CriticalKernelThinning, RefusesOtherPairs) {
  Image<std::uint8_t> img(Domain({4, 4, 4}), std::uint8_t{1});
  ThinningOptions opt;
  opt.pair = {3, 6, 26};
  EXPECT_THROW(critical_kernel_thinning(img, opt), InvalidArgument);
  opt.pair = {3, 18, 6};
  EXPECT_THROW(critical_kernel_thinning(img, opt), InvalidArgument);
}

} // namespace
} // namespace zdg
