// The property table of Wardetzky, Mathur, Kalberer, Grinspun, "Discrete Laplace operators: no
// free lunch" (SGP 2007), measured on digital surfaces for the Laplacians of zdg's driver
// (papers/laplacian-comparison): each operator is assembled as L = W^{-1} S (W diagonal, its
// mass; S its weights, S_ij for i != j the weight of u_j - u_i) exactly as its lb-* estimator
// builds it, and measured:
//
//   constants   max_i |(L 1)_i|                                  (0 for all, to rounding)
//   symmetry    max |S_ij - S_ji| / max |S|                      (W L = S symmetric?)
//   locality    off-diagonal entries per row (mean, max) and the support radius
//               max |x_j - x_i| / h over them (a local operator: bounded as h -> 0)
//   positivity  the fraction of off-diagonal entries below -1e-12 max |S| and the smallest one
//               relative to max |S| (Wardetzky's POS: every weight >= 0)
//   linear      max |L u| for u linear along a digital plane: the faces of the cube |Q x|_inf <=
//               A (Q: 0.5 rad about (1, 2, 3)) digitized at h = 1, u = g_f . x with g_f the unit
//               gradient (0.48, -0.6, 0.64) projected on face f, at the elements of face f
//               farther from its edges than the operator's support radius + the radius of its
//               normal estimate + 2 (0 for an operator with linear precision on this staircase;
//               units: 1 / h at |g_f| = 1); the II normals of heat and polygonal have radius 3
//               there (their laws would give 1 and 2 voxels: too few for a normal)
//
// The closed shape is any bounded 3D shape of the registry (convergence/shape.hpp) in its own
// box, digitized at h untranslated. The operators (names as in laplacian_operator_names):
//   cotan          cotangent of the primal quads split into triangles    at the pointels
//   cotan-mc       cotangent of the marching-cubes mesh                  at its vertices
//   meanvalue      mean-value weights, split quads (Floater 2003)        at the pointels
//   idt            intrinsic Delaunay cotangent, split quads             at the pointels
//   polygonal      de Goes et al. 2020, lambda = 1, II normals R = h^{1/3} at the pointels
//   heat           heat kernel t = h^{2/5}, cut at 5 sqrt(2t), weights h^2 n_II . n_elem
//                  (II radius 2 h^{1/3})                                 at the surfel centres
//   combinatorial  (1 / area) graph Laplacian of the surfel adjacency    at the surfel centres
// Convergence of Delta u is the driver's (zdg converge with the lb-* estimators).
//
// Cost: the operators' assembly on both surfaces (the heat kernel's matrix has one entry per
// pair within its radius: refused above 5 10^7 pairs, InvalidArgument). Errors
// (InvalidArgument): a shape that is not 3D, has no box or is clipped by it, h <= 0, an unknown
// operator, a cube too small to leave an element away from its edges.
#pragma once

#include <zdg/arith/point.hpp>
#include <zdg/kernel/surfaces/surfel_complex.hpp>

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace zdg {

/// The quads of the complex split into triangles as triangulate_quads does, on one vertex per
/// sheet through each pointel (the corners of the surfels around a pointel that its linels
/// join; a pinched pointel, where two sheets of the surface touch, gets one copy per sheet, at
/// its position): every edge in exactly two triangles, run in opposite directions, as the
/// mean-value and intrinsic Delaunay Laplacians need (lb-meanvalue, lb-idt). O(F) (union-find).
struct SheetTriangles {
  std::vector<Point3<double>> vertices;
  std::vector<std::array<std::int64_t, 3>> triangles;
};
SheetTriangles sheet_triangles(const SurfelComplex& complex);

/// cotan, cotan-mc, meanvalue, idt, polygonal, heat, combinatorial.
const std::vector<std::string>& laplacian_operator_names();

struct LaplacianProperties {
  std::string op;        ///< the operator's name
  std::string estimator; ///< its driver estimator (lb-cotan, ...)
  std::string elements;  ///< where it lives (pointels, ...)
  std::int64_t size = 0; ///< rows on the closed shape
  double constants = 0;
  double asymmetry = 0;
  double mean_row_entries = 0;
  std::int64_t max_row_entries = 0;
  double support_radius = 0; ///< in units of h
  double negative_fraction = 0;
  double min_weight = 0;
  double linear_defect = 0;
  std::int64_t linear_points = 0; ///< elements of the cube where it was measured
};

struct LaplacianComparisonSettings {
  std::string shape = "sphere1";
  double h = 0.1;
  double cube_half_side = 20;         ///< A, in voxels (h = 1)
  std::vector<std::string> operators; ///< empty: all
  unsigned threads = 0;               ///< 0: hardware concurrency
};

std::vector<LaplacianProperties> measure_laplacian_properties(const LaplacianComparisonSettings& s);

} // namespace zdg
