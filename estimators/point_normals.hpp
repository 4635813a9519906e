// Normals of a point cloud from the k nearest neighbours of each point, oriented by propagation
// over the minimum spanning tree of the Riemannian graph (Hoppe, DeRose, Duchamp, McDonald,
// Stuetzle, "Surface reconstruction from unorganized points", SIGGRAPH 1992, sections 3.2-3.3).
//
// Neighbourhood N(p): p and its k nearest other points (kernel/points/kd_tree.hpp: the order
//   (squared distance, index), ties included, so N(p) is a function of the points alone).
// pca: the unit eigenvector of the smallest eigenvalue of the covariance
//   C = sum_{q in N(p)} (q - c)(q - c)^T, c the centroid of N(p) (Eigen's self-adjoint solver,
//   tridiagonalization and implicit QR, on C scaled by its largest entry; Eigen's closed form
//   for 3x3 loses up to 1e-7 on thin neighbourhoods). On points of a plane it is the
//   plane's normal up to rounding: the error is about 1e-16 times the neighbourhood's extent
//   over its smallest in-plane spread (tests: 1e-9 on random planes). On a C^2 surface sampled
//   without noise the error is O(r), r the neighbourhood radius (the convergence study
//   measures it; no row in papers/THEORY.md yet).
// jet: the osculating jet of degree 2 fitted to N(p) (estimators/jet_fitting.hpp, jet_fit;
//   Cazals, Pouget 2005); needs k >= 5 (the 6 coefficients of a quadric).
// VCM (estimators/vcm_normal.hpp) does not apply: it integrates over the Voronoi cells of a
//   digital surface's pointels through an exact distance transform on the lattice; on an
//   arbitrary point cloud it would need the cells of a 3D Voronoi diagram (or a sampled offset),
//   a different algorithm.
// Orientation (mst): the Riemannian graph joins i and j when one is among the k nearest of the
//   other (the kNN graph symmetrized), with weight 1 - |n_i . n_j|. Each connected component is
//   seeded at its point of largest z (the smallest index among equal z), whose normal is made
//   +z (n_z >= 0); the normals are then propagated along the component's minimum spanning
//   tree (Prim from the seed, ties broken by (weight, index)): a normal is flipped when its dot
//   product with its tree parent's is negative. Without orientation, each normal is turned
//   into the half-space n_z > 0 (n_y > 0 when n_z = 0, then n_x > 0).
//
// The result does not depend on the thread count (each normal is a function of its
// neighbourhood, whatever the order of the queries; the orientation is sequential).
// Complexity: the kd-tree O(N log N), a Morton sort of the points O(N log N) (the queries run
// in that order, for locality), the queries O(N (log N + k)) expected, PCA O(N k), jet O(N k) CGAL
// fits of 6 coefficients, the orientation O(N k log(N k)) time and O(N k) memory (the graph).
// Threads through kernel/parallel/parallel_for.hpp (0 = all cores).
//
// Errors: InvalidArgument, one line: k < 3, k > N - 1 (too few neighbours: "k = 10 needs at
// least 11 points, the cloud has 5"), jet with k < 5, and the cloud's own checks
// (validate_point_cloud: empty, not finite, repeated points).
#pragma once

#include <zdg/arith/point.hpp>
#include <zdg/kernel/points/kd_tree.hpp>
#include <zdg/kernel/points/point_cloud.hpp>

#include <cstddef>
#include <span>
#include <string>
#include <vector>

namespace zdg {

enum class PointNormalMethod { pca, jet };
enum class PointNormalOrientation { none, mst };

/// "pca", "jet" / "none", "mst"; and back (InvalidArgument for another name).
std::string point_normal_method_name(PointNormalMethod m);
PointNormalMethod point_normal_method_from_name(const std::string& name);
std::string point_normal_orientation_name(PointNormalOrientation o);
PointNormalOrientation point_normal_orientation_from_name(const std::string& name);

struct PointNormalsOptions {
  std::size_t k = 10; ///< neighbours of each point, itself not counted
  PointNormalMethod method = PointNormalMethod::pca;
  PointNormalOrientation orientation = PointNormalOrientation::mst;
  unsigned threads = 0; ///< 0 = all cores
};

struct PointNormals {
  std::vector<Point3<double>> normals; ///< unit, one per point
  bool oriented = false;               ///< propagated over the MST
  std::size_t components = 0;          ///< of the Riemannian graph (0 when not oriented)
};

/// The unit eigenvector of the smallest eigenvalue of the covariance of the points (at least
/// 3, not all on one line for a meaningful answer); its sign is that of Eigen's solver.
Point3<double> pca_normal(std::span<const Point3<double>> neighbourhood);

/// Normals of every point of the cloud (validated first; source names it in errors).
PointNormals point_normals(const PointCloud& cloud, const PointNormalsOptions& options,
                           const std::string& source = "points");

/// The same on a kd-tree already built over the cloud's points (tree.point(i) is point i).
PointNormals point_normals(const KdTree& tree, const PointNormalsOptions& options);

/// Orients the given normals (one per tree point, non-zero) over the MST of the Riemannian
/// graph of the k nearest, as above; returns the number of connected components.
std::size_t orient_normals_mst(const KdTree& tree, std::size_t k,
                               std::vector<Point3<double>>& normals, unsigned threads = 0);

} // namespace zdg
