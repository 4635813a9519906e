// The heat-kernel Laplace-Beltrami operator on a digital surface (Belkin, Sun, Wang, "Discrete
// Laplace operator on meshed surfaces", SoCG 2008, and "Constructing Laplace operator from
// point clouds in R^d", SODA 2009; on digital surfaces with the surfel measure: Caissard,
// Coeurjolly, Lachaud, Roussillon, "Laplace-Beltrami operator on digital surfaces", JMIV 2019).
//
//   (L u)(s) = 1 / (4 pi t^2) sum_{|x_r - x_s| <= rho} exp(-|x_r - x_s|^2 / (4t))
//                                                            (u(r) - u(s)) w(r)
// with w(r) = area(r) mu(r) (estimators/digital_integration.hpp), t = h^alpha, rho = c sqrt(2t)
// (c = 5: the Gaussian mass left out is below 4e-6). L u -> Delta_S u uniformly for
// 0 < alpha < min(1/2, 2 beta / 3), beta the normals' rate (Caissard et al. 2019, Thm 4;
// details: docs/NOTES.md, "estimators/heat_laplace_beltrami.hpp").
// Properties (tested): L 1 = 0 exactly; W L symmetric for W = diag(w), -W L positive
// semi-definite when every w > 0. apply() evaluates each pair once for both rows, in rounds of
// disjoint blocks: bit for bit the same for any thread count; O(n k / 2) exp evaluations for k
// surfels per kernel ball (about 2 pi c^2 t / h^2).
// Precision: apply() evaluates the kernel in single precision (vector exp; AVX2+FMA clone on
// x86-64), row i within 1e-5 sum_j |L_ij| |u_j - u_i| of the exact operator at c = 5; sums in
// double, L 1 = 0 exactly. matrix(): std::exp in double, 12 bytes per entry. Widths: doubles,
// indices int64 (timings: bench/README.md).
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
