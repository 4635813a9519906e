// Piecewise-smooth normal vector fields on a digital surface by the Ambrosio-Tortorelli (AT)
// functional in discrete calculus (Coeurjolly, Foare, Gueth, Lachaud, "Piecewise smooth
// reconstruction of normal vector field on digital data", Pacific Graphics 2016, Computer
// Graphics Forum 35(7); the discretization with u a 0-form and v a 1-form: Foare, Lachaud,
// Talbot, "Image restoration and segmentation using the Ambrosio-Tortorelli functional and
// discrete calculus", ICPR 2016). Given input unit normals g (one per surfel, e.g. the II
// normals of estimators/ii_3d.hpp), AT finds a field u close to g, smooth except across a thin
// set of linels where the discontinuity function v drops to 0: the sharp features.
//
// u is a dual 0-form (a 3-vector per surfel), v a dual 1-form (a scalar per linel e, with
// (d0 u)(e) = u(face[1]) - u(face[0])) on kernel/surfaces/surfel_complex.hpp; in grid units
//   AT_eps(u, v) = alpha sum_s |u(s) - g(s)|^2 + sum_e v(e)^2 |(d0 u)(e)|^2
//                  + lambda eps v^T L v + lambda / (4 eps) sum_e (1 - v(e))^2,
// v^T L v = sum over the surfels and pointels c of sum_{e in E(c)} (v(e) - mean_{E(c)} v)^2, E(c)
// the linels incident to c (an unsigned graph Laplacian). The parameters are per cell (in
// continuous units alpha / h^2, sqrt(2) lambda / h, eps h / sqrt(2); derivation: docs/NOTES.md,
// "estimators/ambrosio_tortorelli.hpp").
//
// Defaults: alpha 2.0, lambda 0.015, eps 2 -> 0.25 by halving, 10 steps per eps, tolerance 1e-4
// (the measurements behind them: papers/at-normals/README.md).
//
// Minimisation (the papers' alternating scheme): u = g, v = 1; for eps = epsilon1, epsilon1 /
// factor, ... while eps >= epsilon2, at most max_iterations times: the u-step, then the v-step
// (both exact minimisers in their block: AT_eps does not increase at fixed eps; 0 < v <= 1),
// until max_e |v_new(e) - v_old(e)| < tolerance; the normals are u / |u| at the end.
//
// Cost: per half step one sparse Cholesky factorization (kernel/linalg/sparse_spd_solver.hpp)
// of n x n (u, n = #surfels, 5 entries per row) or m x m (v, m = 2n linels, about 9 per row):
// about n^{3/2} flops, O(n log n) memory; at most levels x max_iterations x 2 of them, levels =
// 1 + floor(log(epsilon1 / epsilon2) / log(factor)) (timings: bench/README.md). Widths: indices
// int64 (the solver needs n < 2^31), values double.
#pragma once

#include <zdg/arith/point.hpp>
#include <zdg/kernel/linalg/sparse_matrix.hpp>
#include <zdg/kernel/surfaces/surfel_complex.hpp>

#include <cstdint>
#include <span>
#include <string>
#include <vector>

namespace zdg {

struct ATParameters {
  double alpha = 2.0;          ///< data fidelity (> 0): the larger, the closer u stays to g
  double lambda = 0.015;       ///< cost of a discontinuity per cell of length (> 0)
  double epsilon1 = 2.0;       ///< first eps (>= epsilon2), in cells
  double epsilon2 = 0.25;      ///< last eps (> 0)
  double epsilon_factor = 2.0; ///< eps /= factor between levels (> 1)
  int max_iterations = 10;     ///< alternating (u, v) steps per eps (>= 1)
  double tolerance = 1e-4;     ///< stop a level when max |v_new - v_old| < tolerance (>= 0)
};

/// One half step of the minimisation, for the record.
struct ATStep {
  enum class Kind { start, u, v }; ///< start: the current (u, v) at a new eps
  Kind kind = Kind::start;
  double epsilon = 0;
  double energy = 0;   ///< AT_eps(u, v) after the step
  double v_change = 0; ///< max |v_new - v_old| (v steps; 0 otherwise)
};

/// Checks the parameters' domains (alpha, lambda, epsilon2 > 0, epsilon1 >= epsilon2, factor
/// > 1, max_iterations >= 1, tolerance >= 0, all finite): InvalidArgument "WHO: ..." otherwise.
void check_at_parameters(const ATParameters& p, const std::string& who);

struct ATResult {
  std::vector<Point3<double>> u;       ///< the raw minimiser, per surfel
  std::vector<Point3<double>> normals; ///< u / |u| (g where u = 0), per surfel
  std::vector<double> v;               ///< the discontinuity function, per linel
  std::vector<ATStep> steps;           ///< every half step, in order
  std::string backend;                 ///< the sparse solver that served
  int iterations = 0;                  ///< alternating (u, v) steps, all levels together
};

/// The matrix L of G(v) = v^T L v (m x m, m = #linels; see above): symmetric, L 1 = 0,
/// positive semi-definite. O(m) entries.
SparseMatrix at_linel_laplacian(const SurfelComplex& complex);

/// AT_eps(u, v) (see above). InvalidArgument on sizes other than #surfels for g, u and
/// #linels for v, or on parameters outside their domain (eps > 0 here).
double at_energy(const SurfelComplex& complex, std::span<const Point3<double>> g,
                 std::span<const Point3<double>> u, std::span<const double> v,
                 const ATParameters& parameters, double eps);

/// The u-step: the minimiser of AT_eps(., v), (alpha I + d0^T V^2 d0) u = alpha g.
std::vector<Point3<double>> at_solve_u(const SurfelComplex& complex,
                                       std::span<const Point3<double>> g, std::span<const double> v,
                                       const ATParameters& parameters);
/// The v-step: the minimiser of AT_eps(u, .), (lambda/(4 eps) I + diag(|d0 u|^2) + lambda eps L)
/// v = lambda/(4 eps) 1.
std::vector<double> at_solve_v(const SurfelComplex& complex, std::span<const Point3<double>> u,
                               const ATParameters& parameters, double eps);

/// The AT minimisation from u = g, v = 1 (see above). InvalidArgument for g of a size other
/// than #surfels or with non-finite entries, alpha <= 0, lambda <= 0, epsilon2 <= 0,
/// epsilon1 < epsilon2, epsilon_factor <= 1, max_iterations < 1, tolerance < 0 (or NaN).
ATResult at_normals(const SurfelComplex& complex, std::span<const Point3<double>> g,
                    const ATParameters& parameters = {});

/// How a per-linel v is brought to the surfels: the minimum or the mean over the 4 sides.
enum class ATSurfelPolicy { minimum, mean };
/// v per surfel (InvalidArgument when v has a size other than #linels).
std::vector<double> at_surfel_v(const SurfelComplex& complex, std::span<const double> v,
                                ATSurfelPolicy policy = ATSurfelPolicy::minimum);

} // namespace zdg
