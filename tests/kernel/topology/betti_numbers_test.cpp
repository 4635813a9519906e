#include <zdg/kernel/topology/betti_numbers.hpp>

#include "tests/support/binary_images.hpp"
#include "tests/support/check_registry.hpp"
#include "tests/support/cubical_homology.hpp"
#include "tests/support/tower.hpp"
#include <zdg/arith/error.hpp>
#include <zdg/kernel/topology/connected_components.hpp>

#include <gtest/gtest.h>

namespace zdg {
namespace {

const AdjacencyPair kPairs3[4] = {{3, 26, 6}, {3, 6, 26}, {3, 18, 6}, {3, 6, 18}};
const AdjacencyPair kPairs2[2] = {{2, 8, 4}, {2, 4, 8}};

// Theorem (Alexander duality on the continuous analog, kernel/topology/betti_numbers.hpp): b0 = the
// k-components, b2 = the bounded kbar-components of the background, b1 from chi. Oracle: the
// homology over Z/2 of the cell complex of the pair, by brute force
// (tests/support/cubical_homology.hpp), and its alternating cell count for chi.
TEST(BettiNumbers, EqualBruteForceHomologyOfTheComplex3D) {
  test::check_property([] {
    const auto pair = kPairs3[*rc::gen::inRange(0, 4)];
    const auto img = test::random_binary_image(3, 5);
    const auto h = test::object_homology(img, pair);
    const auto got = betti_numbers(img, pair, *rc::gen::inRange(1u, 4u));
    RC_ASSERT(got.euler == h.euler());
    RC_ASSERT(got.b[0] == h.betti[0]);
    RC_ASSERT(got.b[1] == h.betti[1]);
    RC_ASSERT(got.b[2] == h.betti[2]);
    RC_ASSERT(h.betti[3] == 0);
  });
}

TEST(BettiNumbers, EqualBruteForceHomologyOfTheComplex2D) {
  test::check_property([] {
    const auto pair = kPairs2[*rc::gen::inRange(0, 2)];
    const auto img = test::random_binary_image(2, 9);
    const auto h = test::object_homology(img, pair);
    const auto got = betti_numbers(img, pair, *rc::gen::inRange(1u, 4u));
    RC_ASSERT(got.euler == h.euler());
    RC_ASSERT(got.b[0] == h.betti[0]);
    RC_ASSERT(got.b[1] == h.betti[1]);
    RC_ASSERT(got.b[2] == 0);
    RC_ASSERT(h.betti[2] == 0);
    // In 2D, b1 counts the holes: the bounded background components.
    RC_ASSERT(got.b[1] == count_components(img, pair.background, Phase::background).bounded);
  });
}

// The local tables of the 2D pairs sum to 4 chi, as the 3D ones sum to 8 chi.
TEST(BettiNumbers, TwoDimensionalBlockWeightsSumToFourChi) {
  test::check_property([] {
    const auto pair = kPairs2[*rc::gen::inRange(0, 2)];
    const auto img = test::random_binary_image(2, 9);
    const auto n0 = img.domain().extent(0), n1 = img.domain().extent(1);
    auto at = [&](std::int64_t i, std::int64_t j) {
      return i >= 0 && j >= 0 && i < n0 && j < n1 && img[i * n1 + j] != 0;
    };
    std::int64_t sum = 0;
    for (std::int64_t i = -1; i < n0; ++i) {
      for (std::int64_t j = -1; j < n1; ++j) {
        unsigned c = 0;
        for (unsigned a = 0; a < 2; ++a) {
          for (unsigned b = 0; b < 2; ++b) c |= (at(i + a, j + b) ? 1u : 0u) << (a * 2 + b);
        }
        sum += euler_block_weight(pair, c);
      }
    }
    RC_ASSERT(sum == 4 * euler_characteristic(img, pair));
  });
}

// Closed forms: a ball is contractible (1, 0, 0), a solid torus is a circle (1, 1, 0), a
// hollow sphere is a 2-sphere (1, 0, 1), under every pair; a disc is (1, 0), an annulus (1, 1).
TEST(BettiNumbers, ClosedFormsOfBallTorusAndSphere) {
  for (const auto& pair : kPairs3) {
    EXPECT_EQ(betti_numbers(test::ball_image(9, 80), pair).b,
              (std::array<std::int64_t, 3>{1, 0, 0}));
    EXPECT_EQ(betti_numbers(test::torus_image(10, 3), pair).b,
              (std::array<std::int64_t, 3>{1, 1, 0}));
    EXPECT_EQ(betti_numbers(test::hollow_sphere_image(10, 30, 99), pair).b,
              (std::array<std::int64_t, 3>{1, 0, 1}));
    // Two disjoint hollow spheres and a torus side by side: (3, 1, 2), chi = 4.
    Image<std::uint8_t> scene(Domain({23, 77, 29}), std::uint8_t{0});
    test::paste(scene, test::hollow_sphere_image(10, 30, 99), {0, 0, 0});
    test::paste(scene, test::hollow_sphere_image(10, 30, 99), {0, 24, 0});
    test::paste(scene, test::torus_image(10, 3), {7, 48, 0});
    const auto b = betti_numbers(scene, pair, 2);
    EXPECT_EQ(b.b, (std::array<std::int64_t, 3>{3, 1, 2})) << pair.name();
    EXPECT_EQ(b.euler, 4);
  }
  for (const auto& pair : kPairs2) {
    EXPECT_EQ(betti_numbers(test::annulus_image(12, -1, 100), pair).b,
              (std::array<std::int64_t, 3>{1, 0, 0}));
    EXPECT_EQ(betti_numbers(test::annulus_image(12, 30, 120), pair).b,
              (std::array<std::int64_t, 3>{1, 1, 0}));
  }
}

TEST(BettiNumbers, WorkedExamplesWhereThePairsDiffer) {
  // Two voxels sharing only a corner: one component for 26, two for 18 and 6.
  Image<std::uint8_t> corner(Domain({2, 2, 2}), std::uint8_t{0});
  corner[0] = corner[7] = 1;
  EXPECT_EQ(betti_numbers(corner, {3, 26, 6}).b, (std::array<std::int64_t, 3>{1, 0, 0}));
  EXPECT_EQ(betti_numbers(corner, {3, 18, 6}).b, (std::array<std::int64_t, 3>{2, 0, 0}));
  EXPECT_EQ(betti_numbers(corner, {3, 6, 26}).b, (std::array<std::int64_t, 3>{2, 0, 0}));
  // The six voxels off a main diagonal of a 2x2x2 block: a 6-ring around the diagonal. Under
  // (6,26) the two background corners are 26-adjacent through it: a tunnel (b1 = 1); under
  // (6,18) they are not: no tunnel; under 18 and 26 the ring is a filled blob.
  Image<std::uint8_t> ring(Domain({2, 2, 2}), std::uint8_t{1});
  ring[0] = ring[7] = 0;
  EXPECT_EQ(betti_numbers(ring, {3, 6, 26}).b, (std::array<std::int64_t, 3>{1, 1, 0}));
  EXPECT_EQ(betti_numbers(ring, {3, 6, 18}).b, (std::array<std::int64_t, 3>{1, 0, 0}));
  EXPECT_EQ(betti_numbers(ring, {3, 18, 6}).b, (std::array<std::int64_t, 3>{1, 0, 0}));
  EXPECT_EQ(betti_numbers(ring, {3, 26, 6}).b, (std::array<std::int64_t, 3>{1, 0, 0}));
  // A 3x3x3 cube with its centre removed: a cavity under every pair.
  Image<std::uint8_t> hollow(Domain({3, 3, 3}), std::uint8_t{1});
  hollow[13] = 0;
  for (const auto& pair : kPairs3) {
    EXPECT_EQ(betti_numbers(hollow, pair).b, (std::array<std::int64_t, 3>{1, 0, 1}));
  }
  // Empty image: everything 0.
  EXPECT_EQ(
      betti_numbers(Image<std::uint8_t>(Domain({4, 4, 4}), std::uint8_t{0}), {3, 26, 6}).euler, 0);
}

TEST(BettiNumbers, RefusesAPairOfAnotherDimension) {
  Image<std::uint8_t> flat(Domain({3, 3}), std::uint8_t{1});
  EXPECT_THROW(betti_numbers(flat, {3, 26, 6}), InvalidArgument);
  Image<std::uint8_t> cube(Domain({3, 3, 3}), std::uint8_t{1});
  EXPECT_THROW(betti_numbers(cube, {3, 26, 26}), InvalidArgument);
  EXPECT_THROW(euler_characteristic(cube, {2, 8, 4}), InvalidArgument);
}

} // namespace
// The registered property betti.euler (zdg check): components and bounded background components
// by breadth-first search, chi by counting the cells of the complex on the doubled grid.
TEST(BettiNumbers, RegisteredEulerPropertyHolds) {
  test::expect_registered_property("betti.euler", IntKind::int64, 300);
}

} // namespace zdg
