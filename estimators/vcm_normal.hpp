// Normals of a digital surface from the digital Voronoi covariance measure (VCM): Mérigot,
// Ovsjanikov, Guibas, "Voronoi-based curvature and feature estimation from point clouds",
// IEEE TVCG 17(6), 2011; its digital version Cuel, Lachaud, Thibert, "Voronoi-based geometry
// estimator for 3D digital surfaces", DGCI 2014, LNCS 8668; Cuel, Lachaud, Mérigot, Thibert,
// "Robust geometry estimation using the generalized Voronoi covariance measure", SIAM J.
// Imaging Sci. 8(2), 2015 (DGtal's VoronoiCovarianceMeasure and
// VoronoiCovarianceMeasureOnDigitalSurface).
//
// Definition: the VCM of the R-offset of the surfels' pointels K (lattice h (Z^3 - 1/2)),
//   V_{K,R}(chi) = int_{K^R} (x - p_K(x)) (x - p_K(x))^T chi(p_K(x)) dx,
// discretized on the same lattice, a point with m nearest points of K giving 1/m to each
// (exactly symmetric under the 48 lattice symmetries). The normal at a surfel with centre c
// is the eigenvector of the largest eigenvalue of V_{K,R}(chi_r), chi_r the indicator of
// B(c, r), oriented by the trivial normal (details: docs/NOTES.md, "estimators/vcm_normal.hpp").
//
// Algorithm: the exact squared Euclidean distance transform to K on the box of K grown by
// ceil(R / h) + 1 (kernel/transforms/distance_transform.hpp, O(N) for N lattice points of the box);
// for every p in K and every offset o with |o|^2 <= floor((R/h)^2), x = p + o belongs to the cell
// of p iff DT(x) = |o|^2: one pass counts the nearest points of every x, a second adds
// (1/m) o o^T to p's cell. Then, per surfel, the pointels within r of its centre are
// enumerated in a dense index over the box. Time O(N + |K| (R/h)^3 + F (r/h)^3), memory
// 4 + 2 + 4 bytes per box point (distance, counts, index) plus 48 bytes per point of K.
// Width: distances are exact integers (uint32: the box's squared diagonal is checked to fit,
// InvalidArgument otherwise); offsets in voxel units; the matrices are sums of fractions
// o o^T / m in double (the quantity is a real eigenvector). R / h and r / h at most 256.
//
// Rates (proven O(h^{1/8}) for R = r = k h^{1/4}): papers/THEORY.md, "vcm-normal".
#pragma once

#include <zdg/arith/point.hpp>
#include <zdg/kernel/surfaces/cubical_cells.hpp>

#include <span>
#include <vector>

namespace zdg {

/// VCM normals at every surfel: unit, outward (positive dot with the trivial normal), with
/// the offset radius R and the kernel radius r (continuous units, grid step h). Throws
/// InvalidArgument unless h, R, r > 0, R/h <= 256, r/h <= 256 and surfels is non-empty.
std::vector<Point3<double>> vcm_normals(std::span<const Surfel> surfels, double h, double R,
                                        double r, unsigned threads = 0);

} // namespace zdg
