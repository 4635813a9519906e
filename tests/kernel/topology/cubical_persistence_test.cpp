#include <zdg/kernel/topology/cubical_persistence.hpp>

#include "tests/support/binary_images.hpp"
#include "tests/support/tower.hpp"
#include <zdg/arith/error.hpp>
#include <zdg/kernel/topology/betti_numbers.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <map>
#include <set>
#include <vector>

namespace zdg {
namespace {

using Diagram = std::vector<PersistencePair>;
constexpr double kInf = std::numeric_limits<double>::infinity();

// Oracle: the definition. Every cell of the Khalimsky grid of the image (d = 2 or 3, no slab),
// its value the least of its top cofaces, ordered by (value, dimension, index); the standard
// reduction of the whole boundary matrix over Z/2 (no clearing, no compression, no duality):
// column j reduced to low(j) gives the pair (low(j), j), a cell that is no low and whose column
// is zero an essential class. Cubic in the number of cells.
std::vector<Diagram> brute_force_persistence(const Image<double>& img) {
  const int d = img.dim();
  std::vector<std::int64_t> n(static_cast<std::size_t>(d)), m(static_cast<std::size_t>(d));
  std::int64_t cells = 1;
  for (int k = 0; k < d; ++k) {
    n[static_cast<std::size_t>(k)] = img.domain().extent(k);
    m[static_cast<std::size_t>(k)] = 2 * n[static_cast<std::size_t>(k)] + 1;
    cells *= m[static_cast<std::size_t>(k)];
  }
  const auto coords = [&](std::int64_t c) {
    std::vector<std::int64_t> x(static_cast<std::size_t>(d));
    for (int k = d; k-- > 0;) {
      x[static_cast<std::size_t>(k)] = c % m[static_cast<std::size_t>(k)];
      c /= m[static_cast<std::size_t>(k)];
    }
    return x;
  };
  const auto index = [&](const std::vector<std::int64_t>& x) {
    std::int64_t c = 0;
    for (int k = 0; k < d; ++k)
      c = c * m[static_cast<std::size_t>(k)] + x[static_cast<std::size_t>(k)];
    return c;
  };
  std::vector<double> value(static_cast<std::size_t>(cells));
  std::vector<int> dim(static_cast<std::size_t>(cells));
  for (std::int64_t c = 0; c < cells; ++c) {
    const auto x = coords(c);
    int odd = 0;
    for (auto v : x) odd += v % 2 != 0;
    dim[static_cast<std::size_t>(c)] = odd;
    // The least value over the voxels whose closure holds the cell.
    double best = kInf;
    for (std::int64_t vox = 0; vox < img.size(); ++vox) {
      const auto p = img.domain().point(vox);
      bool face = true;
      for (int k = 0; k < d; ++k) {
        const auto a = x[static_cast<std::size_t>(k)], lo = 2 * p[static_cast<std::size_t>(k)];
        face = face && a >= lo && a <= lo + 2;
      }
      if (face) best = std::min(best, img[vox]);
    }
    value[static_cast<std::size_t>(c)] = best;
  }
  std::vector<std::int64_t> order(static_cast<std::size_t>(cells));
  for (std::int64_t c = 0; c < cells; ++c) order[static_cast<std::size_t>(c)] = c;
  std::sort(order.begin(), order.end(), [&](std::int64_t a, std::int64_t b) {
    const auto ua = static_cast<std::size_t>(a), ub = static_cast<std::size_t>(b);
    if (value[ua] != value[ub]) return value[ua] < value[ub];
    if (dim[ua] != dim[ub]) return dim[ua] < dim[ub];
    return a < b;
  });
  std::vector<std::int64_t> position(static_cast<std::size_t>(cells));
  for (std::size_t i = 0; i < order.size(); ++i)
    position[static_cast<std::size_t>(order[i])] = static_cast<std::int64_t>(i);
  // Columns as sorted sets of row positions.
  std::vector<std::set<std::int64_t>> col(static_cast<std::size_t>(cells));
  for (std::size_t j = 0; j < order.size(); ++j) {
    const auto x = coords(order[j]);
    for (int k = 0; k < d; ++k) {
      if (x[static_cast<std::size_t>(k)] % 2 == 0) continue;
      for (int s = -1; s <= 1; s += 2) {
        auto y = x;
        y[static_cast<std::size_t>(k)] += s;
        col[j].insert(position[static_cast<std::size_t>(index(y))]);
      }
    }
  }
  std::map<std::int64_t, std::size_t> low_owner;
  std::vector<bool> is_low(static_cast<std::size_t>(cells), false);
  std::vector<Diagram> out(static_cast<std::size_t>(d) + 1);
  for (std::size_t j = 0; j < order.size(); ++j) {
    while (!col[j].empty()) {
      const auto low = *col[j].rbegin();
      const auto it = low_owner.find(low);
      if (it == low_owner.end()) break;
      for (auto r : col[it->second]) {
        if (!col[j].erase(r)) col[j].insert(r);
      }
    }
    if (col[j].empty()) continue;
    const auto low = *col[j].rbegin();
    low_owner[low] = j;
    is_low[static_cast<std::size_t>(low)] = true;
    const auto birth = value[static_cast<std::size_t>(order[static_cast<std::size_t>(low)])];
    const auto death = value[static_cast<std::size_t>(order[j])];
    if (birth < death) {
      out[static_cast<std::size_t>(
              dim[static_cast<std::size_t>(order[static_cast<std::size_t>(low)])])]
          .push_back({birth, death});
    }
  }
  for (std::size_t j = 0; j < order.size(); ++j) {
    if (col[j].empty() && !is_low[j]) {
      out[static_cast<std::size_t>(dim[static_cast<std::size_t>(order[j])])].push_back(
          {value[static_cast<std::size_t>(order[j])], kInf});
    }
  }
  for (auto& g : out) {
    std::sort(g.begin(), g.end(), [](const PersistencePair& a, const PersistencePair& b) {
      return a.birth != b.birth ? a.birth < b.birth : a.death < b.death;
    });
  }
  return out;
}

// Random values on a random box: few distinct values (ties everywhere) or spread ones, some
// negative, some fractional.
Image<double> random_values(int dim, int max_extent) {
  std::vector<std::int64_t> ext;
  std::int64_t n = 1;
  for (int k = 0; k < dim; ++k) {
    ext.push_back(*rc::gen::inRange<std::int64_t>(1, max_extent + 1));
    n *= ext.back();
  }
  const int levels = *rc::gen::inRange(1, 40);
  const auto draws = *rc::gen::container<std::vector<int>>(static_cast<std::size_t>(n),
                                                           rc::gen::inRange(0, levels));
  const double scale = *rc::gen::element(1.0, 0.5, -0.25);
  Image<double> img{Domain(ext)};
  for (std::int64_t i = 0; i < n; ++i) img[i] = scale * draws[static_cast<std::size_t>(i)];
  return img;
}

// Theorem (the persistence algorithm computes the pairs of the standard reduction, Edelsbrunner,
// Letscher, Zomorodian 2002; duality, Kaji et al. 2020; clearing and compression, Chen-Kerber
// 2011, Bauer-Kerber-Reininghaus 2014): the diagrams equal those of the standard reduction of
// the full boundary matrix, and dimension d is empty (the box is contractible).
TEST(CubicalPersistence, EqualsStandardReductionOfTheFullBoundaryMatrix3D) {
  test::check_property([] {
    const auto img = random_values(3, 4);
    const auto want = brute_force_persistence(img);
    const auto got = cubical_persistence(img);
    RC_ASSERT(got.diagrams.size() == 3u);
    for (std::size_t k = 0; k < 3; ++k) RC_ASSERT(got.diagrams[k] == want[k]);
    RC_ASSERT(want[3].empty());
  });
}

TEST(CubicalPersistence, EqualsStandardReductionOfTheFullBoundaryMatrix2D) {
  test::check_property([] {
    const auto img = random_values(2, 7);
    const auto want = brute_force_persistence(img);
    const auto got = cubical_persistence(img);
    RC_ASSERT(got.diagrams.size() == 2u);
    for (std::size_t k = 0; k < 2; ++k) RC_ASSERT(got.diagrams[k] == want[k]);
    RC_ASSERT(want[2].empty());
  });
}

// Theorem (the persistence equation / structure theorem, Zomorodian-Carlsson 2005): the k-th
// Betti number of the sublevel set at t equals the number of k-pairs with birth <= t < death.
// The sublevel set is the union of the closed voxels of value <= t: the (26,6) / (8,4) analog
// of kernel/topology/betti_numbers.hpp, an independent O(N) computation (Alexander duality).
TEST(CubicalPersistence, PairsAliveAtEachLevelCountTheBettiNumbersOfTheSublevelSet) {
  test::check_property([] {
    const int dim = *rc::gen::inRange(2, 4);
    const auto img = random_values(dim, dim == 3 ? 6 : 12);
    const auto got = cubical_persistence(img);
    const AdjacencyPair pair = default_adjacency_pair(dim);
    std::set<double> levels(img.values().begin(), img.values().end());
    for (double t : levels) {
      Image<std::uint8_t> sub(img.domain());
      for (std::int64_t i = 0; i < img.size(); ++i) sub[i] = img[i] <= t;
      const BettiNumbers b = betti_numbers(sub, pair, 1);
      for (int k = 0; k < dim; ++k) {
        std::int64_t alive = 0;
        for (const auto& p : got.diagrams[static_cast<std::size_t>(k)])
          alive += p.birth <= t && t < p.death;
        RC_ASSERT(alive == b.b[static_cast<std::size_t>(k)]);
      }
    }
  });
}

// The diagrams depend on the values only through their order: an increasing map of the values
// maps the diagrams (the filtration is the same sequence of complexes).
TEST(CubicalPersistence, InvariantUnderIncreasingMapsOfTheValues) {
  test::check_property([] {
    const auto img = random_values(3, 5);
    Image<double> mapped = img;
    for (auto& v : mapped.values()) v = 3 * v - 7;
    const auto a = cubical_persistence(img), b = cubical_persistence(mapped);
    for (std::size_t k = 0; k < 3; ++k) {
      RC_ASSERT(a.diagrams[k].size() == b.diagrams[k].size());
      for (std::size_t i = 0; i < a.diagrams[k].size(); ++i) {
        RC_ASSERT(3 * a.diagrams[k][i].birth - 7 == b.diagrams[k][i].birth);
        RC_ASSERT(3 * a.diagrams[k][i].death - 7 == b.diagrams[k][i].death);
      }
    }
  });
}

// Worked example: a hollow cube. The shell of a 3x3x3 box (value 0) encloses its centre (value
// 5): a 2-class born at 0 dies at 5; one component; nothing in dimension 1.
TEST(CubicalPersistence, HollowCubeHasOneVoid) {
  Image<double> img{Domain({3, 3, 3}), 0.0};
  img[13] = 5.0; // the centre
  const auto got = cubical_persistence(img);
  EXPECT_EQ(got.diagrams[0], (Diagram{{0.0, kInf}}));
  EXPECT_TRUE(got.diagrams[1].empty());
  EXPECT_EQ(got.diagrams[2], (Diagram{{0.0, 5.0}}));
}

// Worked example: a ring of value 1 around a hole of value 3 in 2D, and two minima 0 and 2
// on the ring joined at 1: H0 pairs (2 is not a minimum: it is inside the ring at level 1).
TEST(CubicalPersistence, RingInTwoDimensions) {
  Image<double> img{Domain({3, 3}), 1.0};
  img[4] = 3.0;
  img[0] = 0.0;
  img[8] = 0.5;
  const auto got = cubical_persistence(img);
  // 0 and 0.5 are diagonal corners: joined at 1 by the ring; the hole opens at 1, closes at 3.
  EXPECT_EQ(got.diagrams[0], (Diagram{{0.0, kInf}, {0.5, 1.0}}));
  EXPECT_EQ(got.diagrams[1], (Diagram{{1.0, 3.0}}));
}

// A diagonal contact is a connection: the closed squares of two diagonal pixels share a vertex
// (GUDHI's convention), so two diagonal minima merge at once.
TEST(CubicalPersistence, DiagonalPixelsTouch) {
  Image<double> img{Domain({2, 2}), std::vector<double>{0.0, 4.0, 4.0, 0.0}};
  const auto got = cubical_persistence(img);
  EXPECT_EQ(got.diagrams[0], (Diagram{{0.0, kInf}}));
  EXPECT_TRUE(got.diagrams[1].empty());
}

TEST(CubicalPersistence, RejectsNaNAndOtherDimensions) {
  Image<double> img{Domain({2, 2}), 0.0};
  img[3] = std::nan("");
  EXPECT_THROW(cubical_persistence(img), InvalidArgument);
  EXPECT_THROW(cubical_persistence(Image<double>{Domain({4})}), InvalidArgument);
  EXPECT_THROW(cubical_persistence(Image<double>{Domain({2, 2, 2, 2})}), InvalidArgument);
}

// The dt filtration: -DT inside, +DT(background) outside, exact squared distances.
TEST(SignedSquaredDistance, NegativeDepthInsidePositiveDistanceOutside) {
  Image<std::uint8_t> mask{Domain({1, 7})};
  for (int i = 1; i <= 3; ++i) mask[i] = 1;
  const auto s = signed_squared_distance(mask, 1);
  EXPECT_EQ(s.values(), (std::vector<double>{1, -1, -4, -1, 1, 4, 9}));
  EXPECT_THROW(signed_squared_distance(Image<std::uint8_t>{Domain({3, 3}), 1}), InvalidArgument);
  EXPECT_THROW(signed_squared_distance(Image<std::uint8_t>{Domain({3, 3}), 0}), InvalidArgument);
}

// Theorem: the sublevel set of the signed distance at -1 is the object (the (26,6) analog): its
// Betti numbers are the pairs of the dt filtration alive at -1.
TEST(SignedSquaredDistance, SublevelSetAtMinusOneIsTheObject) {
  test::check_property([] {
    const auto mask = test::random_binary_image(3, 6);
    std::int64_t object = 0;
    for (auto x : mask.values()) object += x != 0;
    RC_PRE(object > 0 && object < mask.size());
    const auto s = signed_squared_distance(mask, 1);
    for (std::int64_t i = 0; i < mask.size(); ++i) RC_ASSERT((s[i] <= -1) == (mask[i] != 0));
    const auto got = cubical_persistence(s);
    const BettiNumbers b = betti_numbers(mask, default_adjacency_pair(3), 1);
    for (std::size_t k = 0; k < 3; ++k) {
      std::int64_t alive = 0;
      for (const auto& p : got.diagrams[k]) alive += p.birth <= -1 && -1 < p.death;
      RC_ASSERT(alive == b.b[k]);
    }
  });
}

} // namespace
} // namespace zdg
