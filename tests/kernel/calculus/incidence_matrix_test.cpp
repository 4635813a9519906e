#include <zdg/kernel/calculus/incidence_matrix.hpp>

#include <zdg/arith/error.hpp>

#include "tests/support/tower.hpp"

#include <gtest/gtest.h>
#include <rapidcheck.h>

#include <cstdint>
#include <limits>

namespace {

using zdg::IncidenceMatrix;
using zdg::IntegerTriplet;

// A random m x n matrix with entries in {-1, 0, 1}, given entry by entry.
struct Dense {
  std::int64_t m = 0, n = 0;
  std::vector<std::int64_t> a;
  std::int64_t at(std::int64_t i, std::int64_t j) const { return a[std::size_t(i * n + j)]; }
  IncidenceMatrix sparse() const {
    std::vector<IntegerTriplet> t;
    for (std::int64_t i = 0; i < m; ++i)
      for (std::int64_t j = 0; j < n; ++j)
        if (at(i, j) != 0) t.push_back({i, j, at(i, j)});
    return IncidenceMatrix::from_triplets(m, n, t);
  }
};

Dense random_dense(int max_side) {
  Dense d;
  d.m = *rc::gen::inRange(0, max_side + 1);
  d.n = *rc::gen::inRange(0, max_side + 1);
  d.a = *rc::gen::container<std::vector<std::int64_t>>(std::size_t(d.m * d.n),
                                                       rc::gen::inRange<std::int64_t>(-1, 2));
  return d;
}

TEST(IncidenceMatrix, DuplicatesSummedZerosDroppedAndLargeSumsRejected) {
  const auto m =
      IncidenceMatrix::from_triplets(2, 3, {{0, 1, 1}, {0, 1, -1}, {1, 2, 1}, {1, 0, -1}});
  EXPECT_EQ(m.nonzeros(), 2);
  EXPECT_EQ(m.at(0, 1), 0);
  EXPECT_EQ(m.at(1, 0), -1);
  EXPECT_EQ(m.at(1, 2), 1);
  EXPECT_EQ(m.column, (std::vector<std::int64_t>{0, 2}));
  EXPECT_THROW(IncidenceMatrix::from_triplets(1, 1, {{0, 0, 1}, {0, 0, 1}}), zdg::InvalidArgument);
  EXPECT_THROW(IncidenceMatrix::from_triplets(1, 1, {{0, 1, 1}}), zdg::InvalidArgument);
  EXPECT_THROW(IncidenceMatrix::from_triplets(-1, 1, {}), zdg::InvalidArgument);
}

// Transpose, negation, products with vectors and matrices against the dense definitions.
TEST(IncidenceMatrix, OperationsMatchTheDenseDefinitions) {
  zdg::test::check_property([] {
    const Dense a = random_dense(6);
    const auto s = a.sparse();
    for (std::int64_t i = 0; i < a.m; ++i)
      for (std::int64_t j = 0; j < a.n; ++j) {
        RC_ASSERT(s.at(i, j) == a.at(i, j));
        RC_ASSERT(s.transpose().at(j, i) == a.at(i, j));
        RC_ASSERT(s.negated().at(i, j) == -a.at(i, j));
      }
    const auto x = *rc::gen::container<std::vector<std::int64_t>>(
        std::size_t(a.n), rc::gen::inRange<std::int64_t>(-1000, 1000));
    const auto y = s.multiply(std::span<const std::int64_t>(x));
    const std::vector<double> xd(x.begin(), x.end());
    const auto yd = s.multiply(std::span<const double>(xd));
    const auto yr = s.to_real().multiply(xd);
    for (std::int64_t i = 0; i < a.m; ++i) {
      std::int64_t want = 0;
      for (std::int64_t j = 0; j < a.n; ++j) want += a.at(i, j) * x[std::size_t(j)];
      RC_ASSERT(y[std::size_t(i)] == want);
      RC_ASSERT(yd[std::size_t(i)] == double(want));
      RC_ASSERT(yr[std::size_t(i)] == double(want));
    }
    Dense b = random_dense(6);
    b.m = a.n;
    b.a = *rc::gen::container<std::vector<std::int64_t>>(std::size_t(b.m * b.n),
                                                         rc::gen::inRange<std::int64_t>(-1, 2));
    const auto p = zdg::integer_product(s, b.sparse());
    std::size_t k = 0;
    for (std::int64_t i = 0; i < a.m; ++i)
      for (std::int64_t j = 0; j < b.n; ++j) {
        std::int64_t want = 0;
        for (std::int64_t l = 0; l < a.n; ++l) want += a.at(i, l) * b.at(l, j);
        if (want == 0) continue;
        RC_ASSERT(k < p.size());
        RC_ASSERT(p[k].row == i && p[k].col == j && p[k].value == want);
        ++k;
      }
    RC_ASSERT(k == p.size());
  });
}

TEST(IncidenceMatrix, OverflowIsLoud) {
  const auto m = IncidenceMatrix::from_triplets(1, 2, {{0, 0, 1}, {0, 1, 1}});
  const std::int64_t big = std::numeric_limits<std::int64_t>::max();
  EXPECT_THROW(m.multiply(std::vector<std::int64_t>{big, 1}), zdg::OverflowError);
  EXPECT_EQ(m.multiply(std::vector<std::int64_t>{big, -1})[0], big - 1);
  const auto n = IncidenceMatrix::from_triplets(1, 1, {{0, 0, -1}});
  EXPECT_THROW(n.multiply(std::vector<std::int64_t>{std::numeric_limits<std::int64_t>::min()}),
               zdg::OverflowError);
  EXPECT_THROW(m.multiply(std::vector<std::int64_t>{1}), zdg::InvalidArgument);
  EXPECT_THROW(zdg::integer_product(m, m), zdg::InvalidArgument);
}

} // namespace
