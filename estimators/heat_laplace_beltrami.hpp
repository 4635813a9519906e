// The heat-kernel Laplace-Beltrami operator on a digital surface (Belkin, Sun, Wang, "Discrete
// Laplace operator on meshed surfaces", SoCG 2008, and "Constructing Laplace operator from
// point clouds in R^d", SODA 2009; on digital surfaces with the surfel measure: Caissard,
// Coeurjolly, Lachaud, Roussillon, "Laplace-Beltrami operator on digital surfaces", JMIV 2019).
//
// For surfels s, r with centres x_s, x_r and weights w(r) = area(r) mu(r) (mu the surfel
// measure n_est . n_elem, estimators/digital_integration.hpp; h^2 mu(r) on the grid of step h):
//     (L u)(s) = 1 / (4 pi t^2) sum_{r : |x_r - x_s| <= rho} exp(-|x_r - x_s|^2 / (4t))
//                                                              (u(r) - u(s)) w(r)
// (the d = 2 normalization 1 / (t (4 pi t)^{d/2})), with t = h^alpha: L u -> Delta_S u, the
// Laplace-Beltrami operator of the continuous surface (negative semi-definite: Delta_S x =
// -2x/R^2 on a sphere of radius R), uniformly (strong consistency), for
// 0 < alpha < min(2 / (d + 2), 2 beta / (d + 1)) = min(1/2, 2 beta / 3) with beta the rate of the
// normal estimator (2/3 for the integral-invariant normal: alpha < 4/9) (Caissard et al. 2019,
// Thm 4). The kernel is truncated at rho = c sqrt(2t) (c = 5 by default: the Gaussian mass left
// out is exp(-c^2/2) < 4e-6 of the total).
//
// Properties (measured in tests/estimators/heat_laplace_beltrami_test.cpp and the paper
// papers/lb-digital): L 1 = 0 exactly; the matrix W L is symmetric for W = diag(w) (L is
// self-adjoint for the weighted inner product), off-diagonal entries >= 0 where w > 0, so
// -W L is positive semi-definite when every w > 0; L is not local (its support grows like
// sqrt(t)/h surfels across).
//
// Algorithm: a grid of cubes of side rho over the centres (counting sort of the cells, 27
// neighbouring cells per cell). apply() evaluates each pair once for both of its rows (the
// kernel is symmetric): the cells are cut into blocks of 256 surfels, the pairs of blocks in
// neighbouring cells are coloured greedily into rounds in which no block appears twice, and
// each round's pairs run in parallel (kernel/parallel/parallel_rounds.hpp), each block's sums added
// in round order, so the result does not depend on the number of threads (bit for bit). Cost: O(n k
// / 2) exp evaluations for k surfels per kernel ball (about 2 pi c^2 t / h^2 on a surface of step
// h).
//
// Precision of apply(): the kernel values are computed in single precision (8 lanes of explicit
// vector code, an AVX2+FMA clone chosen at load time on x86-64 with GCC: an exp by Cody-Waite
// reduction and a degree-7 polynomial, relative error below 2e-7; the coordinates as floats
// relative to the first centre of their block, in units of rho, so that the rounding is relative
// to rho and no float leaves its range, whatever the coordinates' magnitude), within a
// relative 2.4e-7 + 4e-7 c^2 of the exact value (1e-5 at the default c = 5, reached only near the
// cut, where the value is exp(-c^2/2) of the largest); the sums are double precision, and the sums
// with u and with 1 take the same products, so L 1 = 0 exactly. Row i of apply() is therefore
// within 1e-5 sum_j |L_ij| |u_j - u_i| of the exact operator (tested against matrix(), which uses
// std::exp in double precision: 1.9e-6 measured); the estimator's own error (O(t) bias, normals) is
// orders of magnitude larger. Measured on the 2-core development machine (bench/calculus_bench.cpp,
// 2 threads, median of 7): sphere1 at h = 0.025, 30,078 surfels, t = h^0.4 so that the kernel
// covers the whole sphere (9.0e8 pairs): 0.43 s (1.25 s with one double-precision exp per ordered
// pair); 10^6 surfels with t = 4 h^2 (9.9e8 pairs): 1.7-2.0 s (5.0 s). matrix() stores the same n k
// entries (12 bytes each: int64 column, double) as a SparseMatrix. Widths: doubles (floats for the
// kernel values of apply()); indices int64.
#pragma once

#include <zdg/arith/point.hpp>
#include <zdg/kernel/linalg/sparse_matrix.hpp>

#include <array>
#include <cstdint>
#include <span>
#include <vector>

namespace zdg {

/// t = h^alpha, the time of the heat kernel at grid step h. InvalidArgument unless h > 0 and
/// 0 < alpha < 1 (the theorem needs alpha < min(1/2, 2 beta / 3); alpha >= 1 makes t <= h, a
/// kernel narrower than a surfel).
double heat_kernel_time(double h, double alpha);

class HeatLaplaceBeltrami {
public:
  /// The operator on the centres with weights w (equal sizes), time t > 0, truncation radius
  /// c sqrt(2t) (c > 0). threads: 0 = hardware concurrency. InvalidArgument otherwise.
  HeatLaplaceBeltrami(std::span<const Point3<double>> centres, std::span<const double> weights,
                      double t, double cutoff_sigmas = 5.0, unsigned threads = 0);

  /// L u (u has one value per centre). Matrix-free, O(n k).
  std::vector<double> apply(std::span<const double> u) const;
  /// L as a sparse matrix (row s: the weights of (u(r) - u(s))); the diagonal holds minus the
  /// sum of the row's other entries.
  SparseMatrix matrix() const;

  std::int64_t size() const { return static_cast<std::int64_t>(order_.size()); }
  double time() const { return t_; }
  double radius() const { return rho_; }
  /// The number of pairs (s, r), r != s, within the radius (the matrix has this many
  /// off-diagonal entries).
  std::int64_t pair_count() const;

private:
  double t_ = 0, rho_ = 0;
  unsigned threads_ = 0;
  std::vector<std::int64_t> order_;      // sorted position -> input index
  std::vector<double> x_, y_, z_, w_;    // by sorted position
  std::vector<std::int64_t> cell_start_; // cells in sorted order: [cell_start_[c], [c + 1])
  std::vector<std::int64_t> neighbours_; // per cell: up to 27 neighbour cells, -1 padded
  // apply()'s schedule: blocks of at most 256 positions within one cell ([block_start_[b],
  // [b + 1])); pairs_ by rounds (round k: [round_start_[k], [k + 1])): round 0 pairs each block
  // with itself, the later ones the pairs I < J of blocks in neighbouring cells, no block twice
  // in a round, so that the blocks of a round are written by one thread each and every sum is
  // added in the same order for any number of threads.
  std::vector<std::int64_t> block_start_;
  std::vector<float> xf_, yf_, zf_; // relative to the first centre of their block, / rho
  std::vector<std::array<std::int64_t, 2>> pairs_;
  std::vector<std::int64_t> round_start_;

  template <class Fn>
  void for_each_pair_of_cell(std::int64_t cell, Fn&& fn) const;
};

} // namespace zdg
