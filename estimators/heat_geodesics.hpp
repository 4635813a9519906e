// Geodesic distance on a digital surface by the heat method (Crane, Weischedel, Wardetzky,
// "Geodesics in heat: a new approach to computing distance based on heat flow", ACM ToG 2013),
// on the surfels with a tangential gradient from the estimated normals.
//
// Discretization. For each surfel s, with centre x_s, estimated unit normal n_s (the II normal:
// the digital surface's elementary normals do not converge, so the staircase's own gradient
// and metric would not) and weight w_s = area(s) max(mu(s), mu_min) (the surfel measure of
// estimators/digital_integration.hpp, floored so that the masses stay positive):
//   - the gradient G_s u in the tangent plane of n_s is the least-squares plane fit
//     argmin_g sum_r (u(r) - u(s) - g . P_s (x_r - x_s))^2 over the surfels r of the 2-ring of s
//     (neighbours of neighbours across linels: 12 surfels on a flat patch), P_s = I - n_s n_s^T;
//     exact for linear functions on planes, O(h) on smooth surfaces;
//   - the stiffness A = G^T W G (the Dirichlet energy sum_s w_s |G_s u|^2, symmetric positive
//     semi-definite, A 1 = 0) and the mass W = diag(w).
//   - K, the graph Laplacian of the surfel adjacency (sum over linels of (u(r) - u(s))^2): the
//     least-squares stiffness A does not see the checkerboard modes of the 2-ring stencil
//     (their fitted gradient vanishes), so a heat step with A alone rings around the source
//     (measured: the distance then decreases over the first three rings); A + K is monotone
//     there.
// The three steps of the heat method: (1) heat flow for a time t from the source,
// (W + t (A + K)) u = e_source; (2) the normalized field X_s = -G_s u / |G_s u|; (3) the distance
// as the least-squares potential of X, A phi = G^T W X (A is singular on constants: solved as (A +
// eps W) phi = G^T W X with eps = 1e-9 tr(A) / tr(W)), shifted so that phi(source) = 0. Default t =
// h^2 (Crane et al.: t = m h^2 with h the mean spacing, m = 1). Both matrices are factored once
// (kernel/linalg/sparse_spd_solver.hpp, CHOLMOD when present), so each further source costs two
// solves.
//
// Accuracy (measured in tests/estimators/heat_geodesics_test.cpp, II normals R = 2 h^{1/3}):
// on the unit sphere, the mean | max error against the great-circle distance is 0.024 | 0.165
// at h = 0.1, 0.0062 | 0.089 at h = 0.05, 0.0146 | 0.050 at h = 0.025 (the mean no longer
// falls there: t = h^2 ties the smoothing to the grid). Cost: O(n k^2) to assemble (k = 13
// surfels per stencil), A has about 41 entries per row (the 4-ring), two sparse Cholesky
// factorizations (about n^{3/2} flops on a surface; CHOLMOD's supernodes run in BLAS: 2.7 s
// at n = 30,000 with OpenBLAS, 20 s with the reference BLAS), O(nnz(L)) per source (0.1 s).
// Widths: doubles; int64 indices.
#pragma once

#include <zdg/arith/point.hpp>
#include <zdg/kernel/linalg/sparse_matrix.hpp>
#include <zdg/kernel/linalg/sparse_spd_solver.hpp>
#include <zdg/kernel/surfaces/surfel_complex.hpp>

#include <array>
#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <utility>
#include <vector>

namespace zdg {

/// The least-squares tangential gradient on the surfels: 3 rows (x, y, z components) per
/// surfel, row 3 s + a. InvalidArgument when the sizes differ or a normal is not unit; Error
/// when a stencil is degenerate (all its surfels on one line in the tangent plane).
SparseMatrix tangential_gradient(const SurfelComplex& complex,
                                 std::span<const Point3<double>> normals);

class HeatGeodesics {
public:
  /// Prepares the heat method on the surfels of `complex` with unit normals and weights (one
  /// per surfel; weights below mu_min times the surfel's area are raised to it), time t > 0
  /// (0: h^2 with h^2 the mean surfel area). InvalidArgument on bad sizes or parameters.
  HeatGeodesics(const SurfelComplex& complex, std::span<const Point3<double>> normals,
                std::span<const double> weights, double t = 0, double mu_min = 0.05,
                SpdBackend backend = SpdBackend::automatic);
  ~HeatGeodesics();
  HeatGeodesics(HeatGeodesics&&) noexcept;
  HeatGeodesics& operator=(HeatGeodesics&&) noexcept;

  /// The distance of every surfel to the surfel `source` (InvalidArgument outside [0, n)).
  std::vector<double> distance(std::int64_t source) const;
  double time() const { return t_; }
  std::int64_t size() const { return n_; }
  /// The backend that factored the systems (spd_backend_name).
  SpdBackend backend() const;

private:
  std::int64_t n_ = 0;
  double t_ = 0;
  SparseMatrix gradient_;
  std::vector<double> weights_;
  struct Solvers;
  std::unique_ptr<Solvers> solvers_;
};

/// The surfel whose centre is nearest to p, and its distance; InvalidArgument for an empty
/// complex. O(n).
std::pair<std::int64_t, double> nearest_surfel(const SurfelComplex& complex, Point3<double> p);

} // namespace zdg
