// Normals of a digital surface from the digital Voronoi covariance measure (VCM): Mérigot,
// Ovsjanikov, Guibas, "Voronoi-based curvature and feature estimation from point clouds",
// IEEE TVCG 17(6), 2011; its digital version Cuel, Lachaud, Thibert, "Voronoi-based geometry
// estimator for 3D digital surfaces", DGCI 2014, LNCS 8668; Cuel, Lachaud, Mérigot, Thibert,
// "Robust geometry estimation using the generalized Voronoi covariance measure", SIAM J.
// Imaging Sci. 8(2), 2015 (DGtal's VoronoiCovarianceMeasure and
// VoronoiCovarianceMeasureOnDigitalSurface).
//
// Definition. K is the set of the pointels of the given surfels (the corners of the surfel
// quads, DGtal's Pointels embedding), on the lattice h (Z^3 - 1/2); with p_K(x) the nearest
// point of K, the VCM of the R-offset K^R is the matrix-valued measure
//   V_{K,R}(chi) = int_{K^R} (x - p_K(x)) (x - p_K(x))^T chi(p_K(x)) dx,
// discretized on the same lattice: x runs over the lattice points with d(x, K) <= R, each
// adding (x - p)(x - p)^T to the cell of its nearest point p of K. Where x has m > 1 nearest
// points (a set of measure zero in the continuous definition, frequent on a lattice), each of
// them receives 1/m of it: the estimator then commutes exactly with the 48 symmetries of the
// lattice (DGtal keeps the one site its Voronoi map picks). The normal at a surfel s with
// centre c is the eigenvector of the largest eigenvalue of V_{K,R}(chi_r), chi_r the indicator
// of the closed ball B(c, r), i.e. the sum of the cell matrices of the points of K within r of
// c, oriented by the surfel's trivial normal.
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
// Rates: the papers prove that the digital VCM converges to the VCM of the continuous surface
// as h -> 0 (stability of the VCM under Hausdorff perturbation, d_H(K, dX) = O(h) for
// digitizations of C^2 boundaries with positive reach) and deduce multigrid convergence of the
// normal in O(h^{1/8}) for offset and kernel radii R, r of order h^{1/4} (DGCI 2014, SIAM 2015;
// observed about O(h)). The registry claims that rate for R = r = k h^{1/4} and gives no
// verdict for other radius laws (papers/THEORY.md).
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
