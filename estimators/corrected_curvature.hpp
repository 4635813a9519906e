// Interpolated corrected curvature measures on the primal quads of a digital surface (Lachaud,
// Romon, Thibert, Coeurjolly, "Interpolated corrected curvature measures for polygonal
// surfaces", Computer Graphics Forum (SGP) 39(5), 2020; the theory of corrected normal
// currents: Lachaud, Romon, Thibert, "Corrected curvature measures", Discrete Comput. Geom. 68,
// 2022).
//
// A face is the quad of the four pointels of a surfel (kernel/surfaces/cubical_cells.hpp,
// surfel_pointels, counterclockwise seen from outside), parametrised bilinearly over
// (s, t) in [0, 1]^2 by its corners x_00, x_10, x_11, x_01, and carries the corrected normal
// field u(s, t) interpolated bilinearly from the corrected normals u_i at its corners (not
// renormalised: the paper's "non-unit" interpolation, DGtal's unit_u = false). The measures
// of the face are the Lipschitz-Killing forms of the corrected normal current:
//   mu0 = int <u, x_s x x_t>                          (area)
//   mu1 = int <u, u_s x x_t + x_s x u_t>              (twice the mean curvature measure)
//   mu2 = int <u, u_s x u_t>                          (Gaussian curvature measure)
//   muXY(X, Y) = int <u, <Y, u_t> X x x_s - <Y, u_s> X x x_t>   (anisotropic measure)
// ds dt over [0, 1]^2. On a triangle with linear interpolation these are the closed forms of
// the paper (mu0 = 1/2 det(u_M, B - A, C - A), mu1 = 1/2 sum det(u_M, u_C - u_B, A), mu2 =
// 1/2 det(u_A, u_B, u_C), u_M the mean normal; DGtal's CorrectedNormalCurrentFormula). On a
// bilinear quad each integrand is a polynomial of degree <= 2 in s and in t, so the 2 x 2
// Gauss-Legendre rule integrates it exactly: the values are the closed forms of the bilinear
// model, rounded once per operation. (DGtal splits a polygon into triangles around its
// centroid instead, with the normalised mean normal there; on a planar quad with one normal
// both give the same area.) Sanity identity (tested): when u_i = x_i / rho for all corners
// (the radial field of a sphere of radius rho, exact on the corners), u = x / rho on the
// whole face, so mu1 = 2 mu0 / rho and mu2 = mu0 / rho^2 exactly, whatever the quad.
//
// Corrected normals of the digital surface: one unit normal per surfel (the II normal in the
// paper's digital experiments and in DGtal's curvature-comparator-ii-cnc-3d); the normal u_i at
// a pointel is the normalised sum of the normals of the given surfels that have it as a corner
// (DGtal's computeVertexNormalsFromFaceNormals). Sheets meeting at a pointel share its vertex.
//
// Curvatures at a surfel s: the measures of the ball B(c_s, R) around the surfel centre,
// summed over the faces weighted by the inclusion ratio of DGtal's SurfaceMesh (with d_min,
// d_max the least and largest distance from c_s to the face's centroid and corners: 1 when
// d_max <= R, 0 when d_min >= R, (R - d_min) / (d_max - d_min) otherwise), and normalised as
// in the paper and DGtal's CorrectedNormalCurrentComputer:
//   H = mu1(B) / (2 mu0(B)),   G = mu2(B) / mu0(B),
//   k1 <= k2 from the eigenvalues l0 <= l1 of sym(muXY(B)) + 1000 mu0(B) u_s u_s^T (the term
//   pushes the normal direction to the largest eigenvalue): k1 = -l1 / mu0, k2 = -l0 / mu0,
//   directions the eigenvectors of l1, l0.
// Signs: with outward normals a convex part has positive curvatures (a sphere of radius rho:
// H = 1/rho, G = 1/rho^2). Radius: the paper's digital experiments and DGtal's comparator
// use R = h^{1/2} with II normals of radius 3 h^{1/3} (the registry's defaults).
//
// Rates: the measures are stable under perturbation of positions and normals (DCG 2022,
// stability theorem): with convergent normals the ball measures converge; the pointwise rate
// of the normalised curvatures on digital surfaces is not instantiated here (no verdict).
//
// Complexity: O(F) for the face measures (F surfels), then O(F m) for m faces per ball after a
// hash of the face centres in cells of side R + h (27 cells per query); threads through
// parallel_for, the result does not depend on the thread count. Floating point only
// (curvatures are not rational); the cell indices are int64 Khalimsky coordinates.
// Input: one unit normal per surfel, R > 0, h > 0 (InvalidArgument otherwise).
#pragma once

#include <zdg/arith/point.hpp>
#include <zdg/kernel/surfaces/cubical_cells.hpp>

#include <array>
#include <span>
#include <vector>

namespace zdg {

/// The corrected curvature measures of one face (or of a union of faces).
struct CorrectedMeasures {
  double mu0 = 0, mu1 = 0, mu2 = 0;
  std::array<double, 9> muxy{}; ///< row-major: muxy[3 i + j] = muXY(e_i, e_j)
  CorrectedMeasures& add(const CorrectedMeasures& m, double weight);
};

/// The measures of the bilinear quad x[0..3] (corners in cyclic order) with the corrected
/// normals u[0..3] at its corners, interpolated bilinearly.
CorrectedMeasures quad_corrected_measures(const std::array<Point3<double>, 4>& x,
                                          const std::array<Point3<double>, 4>& u);

/// The curvatures from the measures of a ball and the corrected normal n at its centre.
struct CorrectedCurvatures {
  double mean = 0, gaussian = 0;
  double k1 = 0, k2 = 0; ///< from the anisotropic measure, k1 <= k2
  Point3<double> d1, d2; ///< unit principal directions of k1 and k2
};
CorrectedCurvatures corrected_curvatures(const CorrectedMeasures& ball, const Point3<double>& n);

/// The corrected normal at every pointel: the normalised sum of the normals of its surfels.
/// Returned as the four corner normals of every surfel, in the order of surfel_pointels.
std::vector<std::array<Point3<double>, 4>> corner_normals(std::span<const Surfel> surfels,
                                                          std::span<const Point3<double>> normals);

/// The measures of every face of the surfels at grid step h with the given unit normals.
std::vector<CorrectedMeasures> face_corrected_measures(std::span<const Surfel> surfels,
                                                       std::span<const Point3<double>> normals,
                                                       double h, unsigned threads = 0);

/// Curvatures at surfels[queries[i]] for each i, from the measures of the ball of radius R
/// around its centre (the measures of all surfels count).
std::vector<CorrectedCurvatures> cnc_curvatures(std::span<const Surfel> surfels,
                                                std::span<const Point3<double>> normals, double h,
                                                double R, std::span<const std::size_t> queries,
                                                unsigned threads = 0);

/// Curvatures at every surfel.
std::vector<CorrectedCurvatures> cnc_curvatures(std::span<const Surfel> surfels,
                                                std::span<const Point3<double>> normals, double h,
                                                double R, unsigned threads = 0);

} // namespace zdg
