#include <zdg/kernel/topology/simple_points.hpp>

#include "tests/support/binary_images.hpp"
#include "tests/support/check_registry.hpp"
#include "tests/support/cubical_homology.hpp"
#include "tests/support/simple_point_oracles.hpp"
#include "tests/support/tower.hpp"
#include <zdg/arith/error.hpp>

#include <gtest/gtest.h>

namespace zdg {
namespace {

const AdjacencyPair kPairs3[4] = {{3, 26, 6}, {3, 6, 26}, {3, 18, 6}, {3, 6, 18}};
const AdjacencyPair kPairs2[2] = {{2, 8, 4}, {2, 4, 8}};

// 2D, all 256 configurations of both pairs: the table, the definition (topological numbers),
// Bertrand's geodesic numbers by breadth-first search and Yokoi's connectivity number agree.
TEST(SimplePoints, TwoDimensionalTablesAgreeWithDefinitionAndYokoiOnAllConfigurations) {
  for (const auto& pair : kPairs2) {
    const auto& table = SimplePointTable::of(pair);
    int simple = 0;
    for (std::uint32_t c = 0; c < 256; ++c) {
      const bool def = is_simple_by_definition(pair, c);
      EXPECT_EQ(table.simple(c), def) << pair.name() << " " << c;
      EXPECT_EQ(test::geodesic_simple(2, pair.object, pair.background, c), def) << c;
      EXPECT_EQ(test::yokoi_connectivity_number(pair.object, c) == 1, def) << c;
      simple += def;
    }
    // Duality: x is (8,4)-simple in X iff it is (4,8)-simple in the complement.
    for (std::uint32_t c = 0; c < 256; ++c) {
      EXPECT_EQ(is_simple_by_definition(pair, c),
                is_simple_by_definition(pair.complement(), ~c & 255u));
    }
    EXPECT_GT(simple, 0);
  }
}

// 3D, random configurations (uniform and at every density): the definition equals Bertrand's
// geodesic topological numbers computed by breadth-first search, and for (26,6) and (6,26)
// Kong's contractible-attachment criterion.
TEST(SimplePoints, DefinitionAgreesWithIndependentCharacterizations3D) {
  test::check_property([] {
    const auto pair = kPairs3[*rc::gen::inRange(0, 4)];
    const int density = *rc::gen::inRange(0, 101);
    std::uint32_t c = 0;
    const auto draws = *rc::gen::container<std::vector<int>>(26, rc::gen::inRange(0, 100));
    for (int j = 0; j < 26; ++j) c |= (draws[static_cast<std::size_t>(j)] < density ? 1u : 0u) << j;
    const bool def = is_simple_by_definition(pair, c);
    RC_ASSERT(test::geodesic_simple(3, pair.object, pair.background, c) == def);
    if (pair.background == 26 || pair.object == 26) {
      RC_ASSERT(test::attachment_is_contractible(pair.object, c) == def);
    }
    // Duality between a pair and its complement.
    RC_ASSERT(is_simple_by_definition(pair.complement(), ~c & 0x3FFFFFFu) == def);
    const auto t = topological_numbers(pair, c);
    RC_ASSERT(t.object ==
              test::geodesic_topological_number(3, pair.object, pair.background == 18, c));
  });
}

// Theorem (Kong-Rosenfeld; the point of simple points): deleting a simple point keeps every
// Betti number of the object and of the background. Oracle: brute-force homology over Z/2 of
// the cell complexes (tests/support/cubical_homology.hpp), the background as the object of
// the complementary pair in the image padded with background.
TEST(SimplePoints, DeletingASimplePointKeepsTheBettiNumbersOfObjectAndBackground) {
  test::check_property([] {
    const int dim = *rc::gen::inRange(2, 4);
    const auto pair =
        dim == 3 ? kPairs3[*rc::gen::inRange(0, 4)] : kPairs2[*rc::gen::inRange(0, 2)];
    auto img = test::random_binary_image(dim, dim == 3 ? 5 : 8);
    std::vector<std::int64_t> object;
    for (std::int64_t i = 0; i < img.size(); ++i) {
      if (img[i] != 0) object.push_back(i);
    }
    RC_PRE(!object.empty());
    const std::int64_t x = *rc::gen::elementOf(object);
    const bool simple = is_simple_by_definition(pair, neighbourhood_configuration(img, x));
    const auto before = test::object_homology(img, pair);
    const auto before_bg = test::object_homology(test::padded_complement(img), pair.complement());
    img[x] = 0;
    const auto after = test::object_homology(img, pair);
    const auto after_bg = test::object_homology(test::padded_complement(img), pair.complement());
    RC_CLASSIFY(simple);
    // (The converse fails: a point that is not simple can change the topology without
    // changing any Betti number, so only this direction is a theorem.)
    if (simple) {
      RC_ASSERT(before.betti == after.betti);
      RC_ASSERT(before_bg.betti == after_bg.betti);
    }
  });
}

// simple_point_mask (zdg topology simple, serve, Python) marks exactly the object points the
// one-point query is_simple_point accepts (the 2D look-up table or the 3D definition), and
// counts them; its deletions keep the homology (the property above) point by point.
TEST(SimplePoints, MaskIsThePointwiseQuery) {
  test::check_property([] {
    const int dim = *rc::gen::inRange(2, 4);
    const auto pair =
        dim == 3 ? kPairs3[*rc::gen::inRange(0, 4)] : kPairs2[*rc::gen::inRange(0, 2)];
    const auto img = test::random_binary_image(dim, dim == 3 ? 5 : 8);
    std::int64_t count = -1;
    const auto mask = simple_point_mask(img, pair, &count);
    std::int64_t n = 0;
    for (std::int64_t i = 0; i < img.size(); ++i) {
      const bool expected = img[i] != 0 && is_simple_point(img, i, pair);
      RC_ASSERT((mask[i] == 1) == expected);
      n += expected ? 1 : 0;
    }
    RC_ASSERT(count == n);
  });
}

// Shrunk counterexample (it showed that the 6-adjacency paired with 18 must be 6+): in the
// 2x2x2 block of x, the six points off a main diagonal whose ends are background form a
// hexagon that bounds a disc under (6,18); x on it is simple, its two ring neighbours being
// 6-connected in G_6+ through the corner of the block.
TEST(SimplePoints, RegressionHexagonUnderSixEighteen) {
  Image<std::uint8_t> img(Domain({2, 2, 5}), std::uint8_t{1});
  img[1] = img[14] = img[15] = img[17] = 0;
  const auto c = neighbourhood_configuration(img, 10);
  EXPECT_TRUE(is_simple_by_definition({3, 6, 18}, c));
  EXPECT_FALSE(is_simple_by_definition({3, 6, 26}, c));
  EXPECT_EQ(topological_numbers({3, 6, 26}, c).object, 2);
}

TEST(SimplePoints, WorkedExamples) {
  // 3D: an isolated point, an interior point and the end of a segment.
  EXPECT_EQ(topological_numbers({3, 26, 6}, 0), (TopologicalNumbers{0, 1}));
  EXPECT_EQ(topological_numbers({3, 26, 6}, 0x3FFFFFFu), (TopologicalNumbers{1, 0}));
  const std::uint32_t east = 1u << neighbour_bit(3, 0, 0, 1);
  const std::uint32_t west = 1u << neighbour_bit(3, 0, 0, -1);
  EXPECT_TRUE(is_simple_by_definition({3, 26, 6}, east));         // end point
  EXPECT_FALSE(is_simple_by_definition({3, 26, 6}, east | west)); // middle of a segment
  EXPECT_EQ(topological_numbers({3, 26, 6}, east | west), (TopologicalNumbers{2, 1}));
  // The corner neighbour alone: 26-simple (end point), not 18- or 6-simple (isolated).
  const std::uint32_t corner = 1u << neighbour_bit(3, 1, 1, 1);
  EXPECT_TRUE(is_simple_by_definition({3, 26, 6}, corner));
  EXPECT_FALSE(is_simple_by_definition({3, 18, 6}, corner));
  EXPECT_FALSE(is_simple_by_definition({3, 6, 26}, corner));
  // In an image: the centre of a 3x3x3 cube is not simple, a corner of it is.
  Image<std::uint8_t> cube(Domain({3, 3, 3}), std::uint8_t{1});
  EXPECT_FALSE(is_simple_point(cube, 13, {3, 26, 6}));
  EXPECT_TRUE(neighbourhood_configuration(cube, 0) != 0);
  EXPECT_EQ(neighbourhood_configuration(cube, 13), 0x3FFFFFFu);
  // 2D: the end of a row, the middle of a row.
  Image<std::uint8_t> row(Domain({1, 3}), std::uint8_t{1});
  EXPECT_TRUE(is_simple_point(row, 0, {2, 8, 4}));
  EXPECT_FALSE(is_simple_point(row, 1, {2, 8, 4}));
  EXPECT_THROW(is_simple_point(row, 1, {3, 26, 6}), InvalidArgument);
  row[1] = 0;
  EXPECT_THROW(is_simple_point(row, 1, {2, 8, 4}), InvalidArgument);
  EXPECT_THROW(neighbour_bit(3, 0, 0, 0), InvalidArgument);
  EXPECT_THROW(topological_numbers({3, 26, 6}, 1u << 26), InvalidArgument);
}

} // namespace
// The registered property simple_point.lut (zdg check): the 2D table and the definition against
// Yokoi's connectivity number.
TEST(SimplePoints, RegisteredLookUpTablePropertyHolds) {
  test::expect_registered_property("simple_point.lut", IntKind::int64, 600);
}

} // namespace zdg
