#include <zdg/kernel/topology/homology_generators.hpp>

#include "tests/support/binary_images.hpp"
#include "tests/support/cubical_homology.hpp"
#include "tests/support/tower.hpp"
#include <zdg/arith/error.hpp>
#include <zdg/kernel/topology/betti_numbers.hpp>

#include <gtest/gtest.h>

#include <map>
#include <set>
#include <vector>

namespace zdg {
namespace {

using Cell = std::array<std::int64_t, 3>;

// The cells of the union of the closed object voxels (Khalimsky coordinates), by dimension.
std::vector<std::vector<Cell>> closed_voxel_cells(const Image<std::uint8_t>& img) {
  const int d = img.dim();
  std::set<Cell> all;
  for (std::int64_t v = 0; v < img.size(); ++v) {
    if (img[v] == 0) continue;
    const auto p = img.domain().point(v);
    for (int code = 0; code < (d == 3 ? 27 : 9); ++code) {
      Cell x{0, 0, 0};
      int c = code;
      for (int k = 0; k < d; ++k) {
        x[static_cast<std::size_t>(k)] =
            2 * (p[static_cast<std::size_t>(k)] - img.domain().lower(k)) + c % 3;
        c /= 3;
      }
      all.insert(x);
    }
  }
  std::vector<std::vector<Cell>> by_dim(static_cast<std::size_t>(d) + 1);
  for (const auto& x : all) {
    int odd = 0;
    for (auto a : x) odd += a % 2 != 0;
    by_dim[static_cast<std::size_t>(odd)].push_back(x);
  }
  return by_dim;
}

std::vector<Cell> boundary_of(const Cell& x) {
  std::vector<Cell> b;
  for (std::size_t k = 0; k < 3; ++k) {
    if (x[k] % 2 == 0) continue;
    for (int s = -1; s <= 1; s += 2) {
      auto y = x;
      y[k] += s;
      b.push_back(y);
    }
  }
  return b;
}

// Theorems checked on random images (Kaczynski, Mischaikow, Mrozek 2004, ch. 3): every generator
// is a chain of cells of the complex whose boundary is zero mod 2 (a cycle); there are b_k of
// them (the Betti numbers of kernel/topology/betti_numbers.hpp, an independent computation);
// and their classes are independent and nonzero: adding them to the columns of the boundary
// matrix of the (k+1)-cells raises its rank over Z/2 by b_k (no nonzero sum is a boundary).
void check_generators(const Image<std::uint8_t>& img) {
  const int d = img.dim();
  const auto g = homology_generators(img);
  const auto cells = closed_voxel_cells(img);
  const auto b = betti_numbers(img, default_adjacency_pair(d), 1);
  RC_ASSERT(g.generators.size() == static_cast<std::size_t>(d));
  for (int k = 0; k < d; ++k) {
    const auto& gens = g.generators[static_cast<std::size_t>(k)];
    RC_ASSERT(static_cast<std::int64_t>(gens.size()) == b.b[static_cast<std::size_t>(k)]);
    std::map<Cell, std::int64_t> row;
    for (const auto& x : cells[static_cast<std::size_t>(k)])
      row.emplace(x, static_cast<std::int64_t>(row.size()));
    std::vector<std::vector<std::int64_t>> boundaries;
    for (const auto& y : cells[static_cast<std::size_t>(k) + 1]) {
      std::vector<std::int64_t> col;
      for (const auto& f : boundary_of(y)) col.push_back(row.at(f));
      boundaries.push_back(col);
    }
    auto with = boundaries;
    for (const auto& chain : gens) {
      RC_ASSERT(!chain.empty());
      std::map<Cell, int> bd;
      std::vector<std::int64_t> col;
      for (const auto& x : chain) {
        RC_ASSERT(row.count(x) == 1u); // a k-cell of the complex
        col.push_back(row.at(x));
        for (const auto& f : boundary_of(x)) bd[f] ^= 1;
      }
      for (const auto& [f, parity] : bd) RC_ASSERT(parity == 0); // a cycle
      with.push_back(col);
    }
    const auto rows = static_cast<std::int64_t>(row.size());
    RC_ASSERT(test::detail::rank_mod2(with, rows) - test::detail::rank_mod2(boundaries, rows) ==
              static_cast<std::int64_t>(gens.size()));
  }
}

TEST(HomologyGenerators, CyclesWhoseClassesAreABasis3D) {
  test::check_property([] { check_generators(test::random_binary_image(3, 5)); });
}

TEST(HomologyGenerators, CyclesWhoseClassesAreABasis2D) {
  test::check_property([] { check_generators(test::random_binary_image(2, 9)); });
}

// Worked example: the solid torus has one component, one loop and no void; its loop generator
// is a cycle of edges around the hole.
TEST(HomologyGenerators, SolidTorusHasOneLoop) {
  const auto torus = test::torus_image(6, 2);
  const auto g = homology_generators(torus);
  EXPECT_EQ(g.generators[0].size(), 1u);
  EXPECT_EQ(g.generators[1].size(), 1u);
  EXPECT_EQ(g.generators[2].size(), 0u);
  EXPECT_GE(g.generators[1][0].size(), 8u);
}

TEST(HomologyGenerators, RejectsOtherDimensions) {
  EXPECT_THROW(homology_generators(Image<std::uint8_t>{Domain({4})}), InvalidArgument);
}

} // namespace
} // namespace zdg
