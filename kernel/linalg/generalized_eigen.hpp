// The k smallest eigenpairs of a symmetric generalized eigenproblem L x = lambda M x: L
// symmetric positive semi-definite (a Laplacian's stiffness in the positive convention, e.g.
// minus the cotangent matrix S of kernel/linalg/cotan_laplacian.hpp, or -W L of the heat
// operator), M symmetric positive definite (a lumped, diagonal, or consistent sparse mass).
// Returns 0 <= lambda_1 <= ... <= lambda_k with M-orthonormal x_i (x_i^T M x_j = delta_ij); the
// constants span the kernel of a connected surface's Laplacian (lambda_1 = 0 up to rounding).
//
// Algorithm: implicitly restarted Lanczos (Spectra 1.0, SymGEigsShiftSolver, shift-invert mode;
// Qiu, https://spectralib.org; Lehoucq, Sorensen, Yang, ARPACK Users' Guide, 1998) on
// (L - sigma M)^{-1} M with the M inner product, sigma < 0 a small shift below the spectrum so
// that L - sigma M is positive definite even though L is singular: one sparse Cholesky
// factorization (kernel/linalg/sparse_spd_solver.hpp, CHOLMOD with METIS's nested dissection, or
// Eigen), then one solve and one product by M per Lanczos step. Lanczos can miss copies of a
// multiple eigenvalue (the sphere's are 2l + 1 fold): the result is certified by Sylvester's law
// of inertia, the number of eigenvalues below mu = lambda_k (1 - 1e-6) being the count of
// negative pivots of the LDL^T factorization of L - mu M (counted once, on the Cholesky
// factorization's ordering and supernodes: SparseSpdSolver::negative_inertia). While it exceeds
// the number found below mu, Lanczos runs again on the operator deflated by the vectors found:
// first (CHOLMOD) at shift mu by that LDL^T, selecting the operator's most negative eigenvalues
// (the missing ones are the only eigenvalues below mu left), a pair kept only when its residual
// ||L x - lambda M x|| is at most 1e-6 (||L x|| + |lambda| ||M x||); then at sigma (at most k + 1
// runs in all, else Error). Every eigenvalue below mu is then found, so the first k are the k
// smallest; an eigenvalue within 1e-6 lambda_k (up to 8e-6 when a pivot of exactly 0 moves mu)
// below lambda_k can escape the certificate (the LDL^T pivots' rounding needs that margin).
// Cost: the factorization and the count (each about the flops of one Cholesky factorization,
// O(nnz(factor)) memory each), plus about ncv + (restarts x (ncv - k)) solves of O(nnz(factor))
// per run at sigma (2 want + 10 at mu) and O(ncv n) memory for the Krylov basis
// (ncv = max(2k + 1, 20) by default, at most n). Application: the Laplace-Beltrami spectrum as a
// shape descriptor (Reuter, Wolter, Peinecke, "Laplace-Beltrami spectra as 'Shape-DNA' of surfaces
// and solids", CAD 38(4), 2006); on the sphere of radius r the eigenvalues are l(l+1)/r^2 with
// multiplicity 2l+1 (papers/lb-spectrum/README.md).
//
// Requirements (InvalidArgument, one line, otherwise): L and M square of the same size n;
// 1 <= k < n; L and M symmetric (max |a_ij - a_ji| <= 1e-10 max |a_ij|); the diagonal of M
// positive. Error when L - sigma M does not factor (L not positive semi-definite or M not
// positive definite) or when Lanczos does not converge within max_iterations restarts.
// Widths: doubles; n and nnz below 2^31 (the sparse solver's limit). Deterministic: the
// starting vector is fixed.
#pragma once

#include <zdg/kernel/linalg/sparse_matrix.hpp>
#include <zdg/kernel/linalg/sparse_spd_solver.hpp>

#include <cstdint>
#include <vector>

namespace zdg {

struct GeneralizedEigenOptions {
  /// The shift sigma (< 0); 0 selects -1e-6 max_i L_ii / M_ii (a scale of the spectrum's top).
  double shift = 0;
  /// Krylov subspace dimension ncv (k < ncv <= n); 0 selects min(n, max(2k + 1, 20)).
  std::int64_t subspace = 0;
  std::int64_t max_iterations = 1000; ///< Lanczos restarts
  double tolerance = 1e-10;           ///< relative accuracy of the Ritz values
  SpdBackend backend = SpdBackend::automatic;
};

struct GeneralizedEigenpairs {
  std::vector<double> values;                 ///< k eigenvalues, increasing
  std::vector<std::vector<double>> vectors;   ///< vectors[i]: n entries, M-orthonormal
  double shift = 0;                           ///< the sigma used
  std::int64_t iterations = 0;                ///< Lanczos restarts
  std::int64_t operations = 0;                ///< solves with L - sigma M
  SpdBackend backend = SpdBackend::automatic; ///< the factorization's backend
};

/// The k smallest eigenpairs of L x = lambda M x (requirements above).
GeneralizedEigenpairs smallest_generalized_eigenpairs(const SparseMatrix& l, const SparseMatrix& m,
                                                      std::int64_t k,
                                                      const GeneralizedEigenOptions& options = {});

} // namespace zdg
