#include <zdg/kernel/calculus/modular_rank.hpp>

#include <zdg/arith/error.hpp>

#include "tests/support/tower.hpp"

#include <gtest/gtest.h>
#include <rapidcheck.h>

#include <cstdint>
#include <utility>

namespace {

using zdg::IncidenceMatrix;
using zdg::IntegerTriplet;

// The rank over Q by fraction-free (Bareiss) elimination: exact in int64 for these sizes
// (entries of absolute value 1, at most 7 x 7: every minor is below 7^{7/2} < 2^12).
std::int64_t bareiss_rank(std::vector<std::vector<std::int64_t>> a) {
  const std::size_t m = a.size(), n = m ? a[0].size() : 0;
  std::int64_t prev = 1, rank = 0;
  std::size_t row = 0;
  for (std::size_t col = 0; col < n && row < m; ++col) {
    std::size_t p = row;
    while (p < m && a[p][col] == 0) ++p;
    if (p == m) continue;
    std::swap(a[p], a[row]);
    for (std::size_t i = row + 1; i < m; ++i) {
      for (std::size_t j = col + 1; j < n; ++j)
        a[i][j] = (a[row][col] * a[i][j] - a[i][col] * a[row][j]) / prev;
      a[i][col] = 0;
    }
    prev = a[row][col];
    ++row;
    ++rank;
  }
  return rank;
}

TEST(ModularRank, EqualsTheRationalRankOfRandomSignMatrices) {
  zdg::test::check_property([] {
    const int m = *rc::gen::inRange(0, 8), n = *rc::gen::inRange(0, 8);
    std::vector<std::vector<std::int64_t>> a(
        static_cast<std::size_t>(m), std::vector<std::int64_t>(static_cast<std::size_t>(n)));
    std::vector<IntegerTriplet> t;
    const int density = *rc::gen::inRange(1, 10);
    for (int i = 0; i < m; ++i)
      for (int j = 0; j < n; ++j) {
        const int r = *rc::gen::inRange(0, 10);
        const std::int64_t v = r >= density ? 0 : (*rc::gen::arbitrary<bool>() ? 1 : -1);
        a[std::size_t(i)][std::size_t(j)] = v;
        if (v) t.push_back({i, j, v});
      }
    const auto s = IncidenceMatrix::from_triplets(m, n, t);
    const auto want = bareiss_rank(a);
    const auto r = zdg::exact_rank(s);
    RC_ASSERT(r.rank == want);
    RC_ASSERT(r.rank_p1 == want);
    RC_ASSERT(r.rank_p2 == want);
    RC_ASSERT(zdg::rank_mod_p(s.transpose(), 2147483647u) == want);
    // Modulo a small prime the rank may only drop.
    RC_ASSERT(zdg::rank_mod_p(s, 2) <= want);
    RC_ASSERT(zdg::rank_mod_p(s, 3) <= want);
  });
}

// [[1, 1], [1, -1]] has determinant -2: rank 2 over Q, 1 modulo 2.
TEST(ModularRank, ASmallPrimeCanLoseRank) {
  const auto s =
      IncidenceMatrix::from_triplets(2, 2, {{0, 0, 1}, {0, 1, 1}, {1, 0, 1}, {1, 1, -1}});
  EXPECT_EQ(zdg::rank_mod_p(s, 2), 1);
  EXPECT_EQ(zdg::rank_mod_p(s, 3), 2);
  EXPECT_EQ(zdg::exact_rank(s).rank, 2);
}

// The incidence matrix of a long path and of a long cycle (directed edges i -> i + 1): ranks
// n - 1 for n vertices, by contraction without fill.
TEST(ModularRank, GraphIncidences) {
  const std::int64_t n = 100000;
  std::vector<IntegerTriplet> path, cycle;
  for (std::int64_t i = 0; i + 1 < n; ++i) {
    path.push_back({i, i, -1});
    path.push_back({i, i + 1, 1});
  }
  cycle = path;
  cycle.push_back({n - 1, n - 1, -1});
  cycle.push_back({n - 1, 0, 1});
  EXPECT_EQ(zdg::exact_rank(IncidenceMatrix::from_triplets(n - 1, n, path)).rank, n - 1);
  EXPECT_EQ(zdg::exact_rank(IncidenceMatrix::from_triplets(n, n, cycle)).rank, n - 1);
}

TEST(ModularRank, RejectsNonPrimes) {
  const auto s = IncidenceMatrix::from_triplets(1, 1, {{0, 0, 1}});
  EXPECT_THROW(zdg::rank_mod_p(s, 1), zdg::InvalidArgument);
  EXPECT_THROW(zdg::rank_mod_p(s, 2147483649u), zdg::InvalidArgument);
  EXPECT_THROW(zdg::rank_mod_p(s, 2147483645u), zdg::InvalidArgument);
}

} // namespace
