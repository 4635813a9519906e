// Sparse integer incidence matrices: the exterior derivatives of a cell complex
// (kernel/calculus/exterior_derivative.hpp) as exact integer operators, A = (a_ij) with a_ij in
// {-1, 0, +1}, in compressed sparse row form (row i holds (column[k], value[k]) for
// row_start[i] <= k < row_start[i + 1], columns strictly increasing, zeros never stored).
//
// Exactness: entries are int8; products with integer vectors (cochains) and matrix products
// are accumulated in int64 with checked additions (OverflowError naming the row, never a
// silent wrap), so identities such as d1 d0 = 0 are decided exactly. The conversion to the
// real CSR matrix of kernel/linalg/sparse_matrix.hpp feeds the solvers.
//
// Costs: from_triplets O(nnz log nnz); transpose, multiply O(nnz); product(A, B)
// O(sum over the nonzeros a_ik of the length of row k of B), plus the sort of the result.
// Indices int64.
#pragma once

#include <zdg/kernel/linalg/sparse_matrix.hpp>

#include <cstdint>
#include <span>
#include <vector>

namespace zdg {

/// One entry (i, j, a) of an integer matrix.
struct IntegerTriplet {
  std::int64_t row = 0, col = 0, value = 0;
};

struct IncidenceMatrix {
  std::int64_t rows = 0, cols = 0;
  std::vector<std::int64_t> row_start{0}; ///< rows + 1 entries
  std::vector<std::int64_t> column;       ///< strictly increasing within a row
  std::vector<std::int8_t> value;         ///< -1 or +1

  std::int64_t nonzeros() const { return static_cast<std::int64_t>(column.size()); }

  /// The matrix of the triplets, duplicates summed (in int64, checked) and zero sums dropped.
  /// InvalidArgument for an index outside [0, rows) x [0, cols), negative sizes, or an entry
  /// whose sum is not in {-1, 0, +1} (naming it: the cells are not an incidence).
  static IncidenceMatrix from_triplets(std::int64_t rows, std::int64_t cols,
                                       std::vector<IntegerTriplet> triplets);
  /// a_ij (0 where not stored); O(log(row length)).
  int at(std::int64_t i, std::int64_t j) const;
  /// A^T.
  IncidenceMatrix transpose() const;
  /// -A.
  IncidenceMatrix negated() const;
  /// y = A x exactly (x has cols entries; InvalidArgument otherwise; OverflowError when a sum
  /// leaves int64).
  std::vector<std::int64_t> multiply(std::span<const std::int64_t> x) const;
  /// y = A x in double.
  std::vector<double> multiply(std::span<const double> x) const;
  /// The same matrix with double entries.
  SparseMatrix to_real() const;
  /// The largest number of nonzeros in a row.
  std::int64_t max_row_nonzeros() const;
};

/// The nonzero entries of the product A B, exactly (int64, checked: OverflowError), sorted by
/// (row, col). InvalidArgument when a.cols != b.rows.
std::vector<IntegerTriplet> integer_product(const IncidenceMatrix& a, const IncidenceMatrix& b);

} // namespace zdg
