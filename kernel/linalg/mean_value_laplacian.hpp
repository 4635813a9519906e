// The mean-value Laplacian of a triangle mesh: the weights of Floater's mean value coordinates
// (M. S. Floater, "Mean value coordinates", Computer Aided Geometric Design 20(1), 2003), one of
// the operators of Wardetzky, Mathur, Kalberer, Grinspun, "Discrete Laplace operators: no free
// lunch", SGP 2007:
//
//   (L u)_i = (1 / D_i) sum_j w_ij (u_j - u_i),   w_ij = (tan(a_ij / 2) + tan(b_ij / 2)) / |e_ij|,
//
// a_ij and b_ij the angles at vertex i of the (one or two) triangles that share the edge ij (3D
// angles on a surface), D_i = (1/4) sum_j w_ij |e_ij|^2. The normalization D makes L exact on the
// function |x - x_i|^2 in a planar 1-ring and equal to the cotangent Laplacian on the regular
// equilateral grid (2 / (3 a^2) sum over the six neighbours); with the cotangent weights in place
// of w, D_i would be the Voronoi area of Meyer et al. 2003. Floater's coordinates are not a
// Laplacian of a metric, so neither is this one.
//
// Properties (tested): L 1 = 0 (to rounding: the diagonal is minus the row's sum); w_ij > 0 for
// every edge (the angles are in (0, pi)); linear precision on a planar mesh: sum_j w_ij (x_j - x_i)
// = 0 at every interior vertex (Floater's theorem); not symmetric: w_ij != w_ji in general, and no
// diagonal D' makes D' L symmetric. O(F) time and memory (12 entries per triangle); doubles,
// int64 indices; tan(a / 2) = |p x q| / (|p| |q| + p . q), without cancellation for a < pi / 2.
//
// Errors (InvalidArgument): an index out of range, a degenerate triangle (zero area or a zero
// edge), a triangle that repeats a vertex, an edge shared by more than two triangles
// (non-manifold).
#pragma once

#include <zdg/arith/point.hpp>
#include <zdg/kernel/linalg/sparse_matrix.hpp>

#include <array>
#include <cstdint>
#include <span>
#include <vector>

namespace zdg {

struct MeanValueLaplacian {
  SparseMatrix weights;     ///< W: W_ij = w_ij (i != j), W_ii = -sum_j w_ij; not symmetric
  std::vector<double> mass; ///< D_i = (1/4) sum_j w_ij |e_ij|^2

  /// L u = D^{-1} W u (0 where D_i = 0: a vertex of no triangle).
  std::vector<double> apply(std::span<const double> u, unsigned threads = 1) const;
};

/// The mean-value Laplacian of the triangles (vertex indices, any orientation).
MeanValueLaplacian mean_value_laplacian(std::span<const Point3<double>> vertices,
                                        std::span<const std::array<std::int64_t, 3>> triangles);

} // namespace zdg
