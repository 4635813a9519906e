// Piecewise-smooth normal vector fields on a digital surface by the Ambrosio-Tortorelli (AT)
// functional in discrete calculus (Coeurjolly, Foare, Gueth, Lachaud, "Piecewise smooth
// reconstruction of normal vector field on digital data", Pacific Graphics 2016, Computer
// Graphics Forum 35(7); the discretization with u a 0-form and v a 1-form: Foare, Lachaud,
// Talbot, "Image restoration and segmentation using the Ambrosio-Tortorelli functional and
// discrete calculus", ICPR 2016). Given input unit normals g (one per surfel, e.g. the II
// normals of estimators/ii_3d.hpp), AT finds a field u close to g, smooth except across a thin
// set of linels where the discontinuity function v drops to 0: the sharp features.
//
// Cells (kernel/surfaces/surfel_complex.hpp, the dual side): u is a dual 0-form (one 3-vector per
// surfel), v a dual 1-form (one scalar per linel: linel e is the dual edge between its surfels
// face[0] and face[1], (d0 u)(e) = u(face[1]) - u(face[0])). The functional, in grid units
// (every cell counts 1, as in the papers' calculus on unit cells):
//
//   AT_eps(u, v) = alpha sum_s |u(s) - g(s)|^2 + sum_e v(e)^2 |(d0 u)(e)|^2
//                  + lambda eps G(v) + lambda / (4 eps) sum_e (1 - v(e))^2
//
//   G(v) = sum_{c in surfels and pointels} sum_{e in E(c)} (v(e) - mean_{E(c)} v)^2 = v^T L v
//
// where E(c) is the set of linels incident to the cell c (the 4 sides of a surfel; the k
// linels around a pointel, k = 4 on a flat part, 3..6 at corners and saddles). G is the
// unsigned analogue of the ICPR 1-form term |d v|^2 + |delta v|^2: the codifferential delta
// couples the sides of a surfel (a dual 0-cell), d the linels around a pointel (a dual 2-cell);
// unsigned, because v is a weight, not an oriented flux, and the linel orientations of a
// digital surface are arbitrary. G is a graph Laplacian (G(1) = 0, L symmetric positive
// semi-definite: per cell, (1/k) sum_{i<j in E(c)} (v_i - v_j)^2) and for an affine v on a
// planar grid it equals the integral of |grad v|^2 exactly (tested): a linel is coupled with
// weight 1/2 to the four linels perpendicular to it (a shared surfel and a shared pointel), 1/4
// to the opposite side of each of its two surfels, 1/4 to the collinear linel at each pointel.
//
// Units: with surfels of side h, sum_e |d0 u|^2 is the integral of |grad u|^2 (exact for an
// affine u on a plane), G that of |grad v|^2, and a linel stands for an area h^2 / 2, so the
// grid-unit functional is the continuous AT functional
//   alpha' int |u - g|^2 + int v^2 |grad u|^2 + lambda' (eps' int |grad v|^2
//                                                         + int (1 - v)^2 / (4 eps'))
// with alpha' = alpha / h^2, lambda' = sqrt(2) lambda / h, eps' = eps h / sqrt(2): the
// parameters are per cell, as in the papers' calculus on unit cells (DGtal's
// ShortcutsGeometry: alpha 0.1, lambda 0.025, eps 2 -> 0.25 by halving). eps 2 -> 0.25 is a
// discontinuity band of about 2 down to 1/4 cell, alpha = 0.1 a smoothing length of about
// 1/sqrt(alpha) ~ 3 cells; a discontinuity costs about lambda per cell of its length.
//
// Defaults (measured, tests/estimators/ambrosio_tortorelli_test.cpp; g = II normals of radius
// 3h): alpha 0.1, lambda 0.015, eps 2 -> 0.25 by halving, 10 steps per eps, tolerance 1e-4.
// lambda = 0.015 rather than 0.025: on a cube turned by a generic rotation (h = 0.1) lambda
// 0.025 cuts the edges too softly and smooths across them (mean error 2 to 5 cells from an
// edge 3.45 -> 3.99 deg), 0.01 cuts a coarse unit sphere (h = 0.1, 0.1 rad per cell) into
// facets (3.37 -> 5.05 deg); 0.015 gives 19.1 -> 14.9 deg within 2 cells of an edge, 3.45 ->
// 3.70 deg at 2 to 5 cells, 3.36 -> 2.81 deg beyond, and 3.37 -> 3.48 deg on the sphere (3.29
// -> 2.63 deg at h = 0.05, 3.04 -> 2.34 deg at h = 0.025). With an accurate input (II at the
// convergent radius 2 h^{1/3}: 0.17 deg on the sphere at h = 0.1, 0.11 deg at h = 0.05) AT
// adds the bias of its smoothing over the staircase (0.88 and 0.51 deg; 0.43 deg at h = 0.1
// with alpha = 0.5): AT is meant for inputs blurred or noisy at the scale of a few cells.
//
// Minimisation (the papers' alternating scheme): u = g, v = 1; for eps = epsilon1,
// epsilon1 / factor, ... while eps >= epsilon2: repeat at most max_iterations times
//   u-step  (alpha I + d0^T V^2 d0) u = alpha g, V = diag(v): one factorization, three solves
//   v-step  (lambda / (4 eps) I + diag(|d0 u|^2) + lambda eps L) v = lambda / (4 eps) 1
// until max_e |v_new(e) - v_old(e)| < tolerance. Each half step is the exact minimiser of the
// functional in its block (both matrices are symmetric positive definite), so AT_eps does not
// increase from one half step to the next at fixed eps (tested); 0 < v <= 1 (an M-matrix with
// a positive right-hand side). The unit normals are u / |u| at the end (u itself shrinks where
// the field turns: it is an average of unit vectors).
//
// Cost: per half step one sparse Cholesky factorization (kernel/linalg/sparse_spd_solver.hpp:
// CHOLMOD when zdg has it, else Eigen SimplicialLDLT) of an n x n matrix with 5 entries per row (u,
// n = #surfels) or of an m x m matrix with about 9 entries per row (v, m = 2 #surfels linels):
// about n^{3/2} flops each (nested dissection on a surface), O(n log n) memory; at most
// levels x max_iterations x 2 factorizations, levels = 1 + floor(log(epsilon1 / epsilon2) /
// log(factor)). Measured (CHOLMOD, 2 shared cores, defaults): unit sphere h = 0.05 (7470
// surfels) 39 steps in 10 s, h = 0.025 (30078 surfels) 23 steps in 44 s; the v-step (twice as
// many unknowns, 9 or more entries per row) dominates. Widths: indices int64 (the solver needs n <
// 2^31), values double.
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
  double alpha = 0.1;          ///< data fidelity (> 0): the larger, the closer u stays to g
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
