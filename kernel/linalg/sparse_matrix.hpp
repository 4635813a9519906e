// Sparse real matrices in compressed sparse row (CSR) form, the exchange type of the discrete
// calculus of zdg (Laplace-Beltrami operators, the Ambrosio-Tortorelli systems, the heat
// method): A = (a_ij), row i holding the pairs (column[k], value[k]) for
// row_start[i] <= k < row_start[i + 1], columns strictly increasing within a row.
//
// Built from triplets (i, j, a): duplicates are summed (the usual assembly of finite-element and
// discrete-exterior-calculus matrices), explicit zeros are kept (the pattern then says where
// an entry may be). Products y = A x are O(nnz), in parallel over contiguous row chunks
// (kernel/parallel/parallel_for.hpp: the result does not depend on the number of threads).
//
// Widths: indices int64 (a 2048^3 volume has more than 2^31 surfels), values double (the
// entries are not rational: Gaussian weights, cotangents, normals). Eigen stays private to the
// .cpp files (kernel/linalg/sparse_spd_solver.hpp converts).
#pragma once

#include <cstdint>
#include <span>
#include <vector>

namespace zdg {

/// One entry (i, j, a) of a matrix being assembled.
struct SparseTriplet {
  std::int64_t row = 0, col = 0;
  double value = 0;
};

struct SparseMatrix {
  std::int64_t rows = 0, cols = 0;
  std::vector<std::int64_t> row_start{0}; ///< rows + 1 entries
  std::vector<std::int64_t> column;       ///< strictly increasing within a row
  std::vector<double> value;

  std::int64_t nonzeros() const { return static_cast<std::int64_t>(column.size()); }

  /// The matrix of the triplets (duplicates summed). InvalidArgument for an index outside
  /// [0, rows) x [0, cols) or negative sizes. O(nnz log nnz).
  static SparseMatrix from_triplets(std::int64_t rows, std::int64_t cols,
                                    std::vector<SparseTriplet> triplets);
  /// The n x n identity times d.
  static SparseMatrix diagonal(std::span<const double> d);

  /// y = A x (x has cols entries). InvalidArgument on a size mismatch.
  std::vector<double> multiply(std::span<const double> x, unsigned threads = 1) const;
  /// a_ij (0 where not stored); O(log(row length)).
  double at(std::int64_t i, std::int64_t j) const;
  /// A^T.
  SparseMatrix transpose() const;
  /// max |a_ij - a_ji| over the stored entries of both (square matrices).
  double asymmetry() const;
};

/// s A + t B (same sizes; InvalidArgument otherwise).
SparseMatrix add(double s, const SparseMatrix& a, double t, const SparseMatrix& b);

} // namespace zdg
