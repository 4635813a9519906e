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
//   - K, the graph Laplacian of the surfel adjacency: A alone misses the checkerboard modes
//     of the 2-ring stencil and rings around the source; A + K is monotone there.
// Heat method: (1) (W + t (A + K)) u = e_source; (2) X_s = -G_s u / |G_s u|; (3) A phi = G^T W X
// (solved as (A + eps W) phi = G^T W X, eps = 1e-9 tr(A) / tr(W)), shifted to phi(source) = 0.
// Default t = h^2 (Crane et al., m = 1). Both matrices are factored once
// (kernel/linalg/sparse_spd_solver.hpp): a further source costs two solves (details:
// docs/NOTES.md, "estimators/heat_geodesics.hpp").
//
// Cost: O(n k^2) to assemble (k = 13 surfels per stencil), A about 41 entries per row, two
// sparse Cholesky factorizations (about n^{3/2} flops), O(nnz(L)) per source. Widths: doubles,
// int64 indices (accuracy and timings: bench/README.md, "estimators/heat_geodesics.hpp").
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
