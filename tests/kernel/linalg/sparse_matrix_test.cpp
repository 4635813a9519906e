#include <zdg/kernel/linalg/sparse_matrix.hpp>

#include "tests/support/tower.hpp"

#include <zdg/arith/error.hpp>

#include <gtest/gtest.h>

#include <map>
#include <utility>

namespace {

// The CSR matrix of random triplets equals the dense sum of the triplets (the oracle), its
// product equals the dense product, its transpose the dense transpose, on any thread count.
TEST(SparseMatrix, TripletsProductsAndTransposeMatchDenseOracle) {
  zdg::test::check_property([] {
    const auto rows = *rc::gen::inRange<std::int64_t>(0, 9);
    const auto cols = *rc::gen::inRange<std::int64_t>(1, 9);
    const int n = *rc::gen::inRange(0, 40);
    std::vector<zdg::SparseTriplet> t;
    std::map<std::pair<std::int64_t, std::int64_t>, double> dense;
    for (int k = 0; k < n && rows > 0; ++k) {
      const auto i = *rc::gen::inRange<std::int64_t>(0, rows);
      const auto j = *rc::gen::inRange<std::int64_t>(0, cols);
      const double v = *rc::gen::inRange(-5, 6);
      t.push_back({i, j, v});
      dense[{i, j}] += v;
    }
    const auto m = zdg::SparseMatrix::from_triplets(rows, cols, t);
    RC_ASSERT(m.nonzeros() == static_cast<std::int64_t>(dense.size()));
    for (std::int64_t i = 0; i < rows; ++i) {
      for (std::int64_t k = m.row_start[std::size_t(i)] + 1; k < m.row_start[std::size_t(i) + 1];
           ++k)
        RC_ASSERT(m.column[std::size_t(k - 1)] < m.column[std::size_t(k)]);
      for (std::int64_t j = 0; j < cols; ++j) {
        const auto it = dense.find({i, j});
        RC_ASSERT(m.at(i, j) == (it == dense.end() ? 0.0 : it->second));
      }
    }
    std::vector<double> x(static_cast<std::size_t>(cols));
    for (auto& v : x) v = *rc::gen::inRange(-9, 10);
    const auto y = m.multiply(x, *rc::gen::inRange(1u, 4u));
    for (std::int64_t i = 0; i < rows; ++i) {
      double s = 0;
      for (const auto& [ij, v] : dense)
        if (ij.first == i) s += v * x[std::size_t(ij.second)];
      RC_ASSERT(y[std::size_t(i)] == s);
    }
    const auto tr = m.transpose();
    for (std::int64_t i = 0; i < rows; ++i)
      for (std::int64_t j = 0; j < cols; ++j) RC_ASSERT(tr.at(j, i) == m.at(i, j));
    if (rows == cols) {
      const auto sym = zdg::add(1.0, m, 1.0, tr);
      RC_ASSERT(sym.asymmetry() == 0.0);
    }
  });
}

TEST(SparseMatrix, RefusesEntriesOutsideAndMismatchedVectors) {
  EXPECT_THROW(zdg::SparseMatrix::from_triplets(2, 2, {{2, 0, 1.0}}), zdg::InvalidArgument);
  EXPECT_THROW(zdg::SparseMatrix::from_triplets(2, 2, {{0, -1, 1.0}}), zdg::InvalidArgument);
  const auto m = zdg::SparseMatrix::from_triplets(2, 3, {{0, 2, 1.0}});
  EXPECT_THROW(m.multiply(std::vector<double>(2)), zdg::InvalidArgument);
  EXPECT_THROW(m.asymmetry(), zdg::InvalidArgument);
  const auto d = zdg::SparseMatrix::diagonal(std::vector<double>{1, 2});
  EXPECT_EQ(d.at(1, 1), 2.0);
  EXPECT_EQ(d.at(0, 1), 0.0);
}

} // namespace
