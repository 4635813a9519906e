// Interpolated corrected curvature measures on the primal quads of a digital surface (Lachaud,
// Romon, Thibert, Coeurjolly, "Interpolated corrected curvature measures for polygonal
// surfaces", Computer Graphics Forum (SGP) 39(5), 2020; the theory of corrected normal
// currents: Lachaud, Romon, Thibert, "Corrected curvature measures", Discrete Comput. Geom. 68,
// 2022).
//
// A face is the bilinear quad of a surfel's four pointels (surfel_pointels order) carrying the
// bilinearly interpolated, non-renormalised corrected normal u; its measures mu0 (area), mu1
// (twice the mean curvature measure), mu2 (Gaussian) and muXY (anisotropic) are integrated
// exactly by the 2 x 2 Gauss-Legendre rule. The normal at a pointel is the normalised sum of
// its surfels' normals. At a surfel, the measures of the ball B(c_s, R) (faces weighted by
// DGtal's inclusion ratio) give H = mu1 / (2 mu0), G = mu2 / mu0 and k1 <= k2 from sym(muXY);
// outward normals make convex parts positive. Formulas, defaults (R = h^{1/2}) and rates:
// docs/NOTES.md, "estimators/corrected_curvature.hpp".
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
