// Direct solver of sparse symmetric positive definite systems A x = b: one sparse Cholesky
// factorization (fill-reducing ordering), then any number of solves by two triangular sweeps
// (the Ambrosio-Tortorelli steps, the heat method's systems).
// Backends: SuiteSparse CHOLMOD (supernodal; Chen, Davis, Hager, Rajamanickam, ACM TOMS 2008)
// when zdg was built with it (ZDG_CHOLMOD, default AUTO), loaded at the first solver that asks
// for it; else Eigen's SimplicialLDLT (AMD ordering). `automatic` takes CHOLMOD when it loads.
// Cost: O(nnz(L)) memory, about sum_j nnz(L_j)^2 flops to factor (about n^{3/2}, nnz(L) about
// n log n on surface meshes); a solve is O(nnz(L)).
// Input: A square, symmetric (lower triangle read), positive definite, else zdg::Error naming
// the backend. Widths: 32-bit indices, n and nnz(A) below 2^31 (InvalidArgument past it);
// values double. Not thread-safe: one solver per thread.
#pragma once

#include <zdg/kernel/linalg/sparse_matrix.hpp>

#include <memory>
#include <span>
#include <string>
#include <vector>

namespace zdg {

enum class SpdBackend { automatic, cholmod, eigen_ldlt };

/// CHOLMOD's fill-reducing ordering: approximate minimum degree (AMD: the cheaper analysis), or
/// METIS's nested dissection (a costlier analysis, less fill on large surface meshes; figures in
/// bench/README.md, "Laplace-Beltrami spectra"). The Eigen backend orders by AMD either way.
enum class SpdOrdering { minimum_degree, nested_dissection };

/// "cholmod", "eigen-simplicial-ldlt" (automatic: "automatic").
std::string spd_backend_name(SpdBackend backend);

class SparseSpdSolver {
public:
  /// Factors A. InvalidArgument when A is not square or too large, or when `cholmod` is asked
  /// for and zdg was built without it; Error when the factorization fails.
  explicit SparseSpdSolver(const SparseMatrix& a, SpdBackend backend = SpdBackend::automatic,
                           SpdOrdering ordering = SpdOrdering::minimum_degree);
  ~SparseSpdSolver();
  SparseSpdSolver(SparseSpdSolver&&) noexcept;
  SparseSpdSolver& operator=(SparseSpdSolver&&) noexcept;

  /// Factors B, a matrix with the same size and the same stored pattern as the A of the
  /// constructor (the pattern of the last matrix factored), reusing the fill-reducing ordering
  /// and the symbolic analysis: the numeric factorization only (the iterations of the
  /// Ambrosio-Tortorelli minimisation change the values, not the pattern). InvalidArgument when
  /// the pattern differs; Error when the factorization fails (the solver is then unusable).
  void refactor(const SparseMatrix& b);
  /// The number of negative eigenvalues of B, a symmetric matrix with the pattern of the
  /// matrix analysed (e.g. L - mu M beside L - sigma M), by Sylvester's law of inertia: the
  /// negative pivots of B's LDL^T without pivoting, in the ordering and on the supernodal
  /// structure of the analysis (CHOLMOD backend: dense blocks and BLAS, about the flops and
  /// the time of one numeric Cholesky factorization, O(nnz(L)) memory beside the factor kept);
  /// the Eigen backend calls zdg::negative_inertia(B). The factor of A is left as it is.
  /// InvalidArgument when B's pattern differs; Error when a pivot is 0 or not finite (B, or a
  /// leading minor in the elimination order, is singular).
  std::int64_t negative_inertia(const SparseMatrix& b) const;
  /// x with B x = b, B the last matrix negative_inertia counted, by its LDL^T (kept, CHOLMOD
  /// backend: O(nnz(L)) per solve; B indefinite: no pivoting, the accuracy degrades with B's
  /// smallest pivots). InvalidArgument with the Eigen backend, before any count, or when b does
  /// not have n entries.
  std::vector<double> solve_counted(std::span<const double> b) const;
  /// x with A x = b (b has n entries; InvalidArgument otherwise).
  std::vector<double> solve(std::span<const double> b) const;
  std::int64_t size() const;
  /// The backend that factored A (never `automatic`).
  SpdBackend backend() const;

  /// Whether CHOLMOD serves: zdg was built with it and its library loads (at the first call).
  static bool cholmod_available();
  /// The CHOLMOD library zdg loads at its first use ("libcholmod.so.3"; empty when built
  /// without CHOLMOD).
  static std::string cholmod_library();

private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

/// The number of negative eigenvalues of a symmetric matrix A (Sylvester's law of inertia: the
/// negative pivots of A's sparse LDL^T factorization, Eigen's SimplicialLDLT with AMD ordering,
/// no pivoting). Used to count the eigenvalues of L x = lambda M x below mu as the inertia of
/// L - mu M. Error when a pivot is 0 or not finite (A singular, or its leading minors in the AMD
/// order are); InvalidArgument when A is not square or past the 32-bit indices. Cost: one
/// factorization, as SparseSpdSolver's Eigen backend.
std::int64_t negative_inertia(const SparseMatrix& a);

} // namespace zdg
