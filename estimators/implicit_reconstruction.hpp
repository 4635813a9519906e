// Implicit surface reconstruction from oriented points: each method gives a field on the
// lattice h Z^3 around the points, negative inside and positive outside; the object is the
// digitization {z : f(h z) < 0} (its digital surface, components and Betti numbers are those
// of zdg's kernel) and the mesh is zdg's marching cubes of that set with the vertices placed
// on the zero crossing of f along each surfel's edge (kernel/surfaces/marching_cubes.hpp).
//
//   hoppe    signed distance to the nearest tangent plane (Hoppe, DeRose, Duchamp,
//            McDonald, Stuetzle, "Surface reconstruction from unorganized points",
//            SIGGRAPH 1992): plane i passes through o_i, the centroid of the k nearest
//            points of p_i, with normal n_i; f(q) = (q - o_j) . n_j for the centre o_j nearest
//            to q. Defined everywhere (far from the data the sign is the nearest plane's).
//   winding  1/2 - w(q), w the generalized winding number of the oriented points (Barill,
//            Dickson, Schmidt, Levin, Jacobson, "Fast winding numbers for soups and clouds",
//            SIGGRAPH 2018): w(q) = sum_i a_i (p_i - q) . n_i / (4 pi |p_i - q|^3), a_i the
//            area of p_i's Voronoi cell among its max(k, 20) nearest projected on its tangent
//            plane (point_areas). Evaluated by the tree of the paper (WindingTree: second-order
//            Taylor expansions of far clusters, Barnes-Hut criterion |q - c| > beta r) or
//            exactly (the brute-force sum, `winding_exact`).
//   poisson  CGAL's Poisson surface reconstruction (Kazhdan, Bolitho, Hoppe, SGP 2006, as
//            CGAL::Poisson_reconstruction_function: Delaunay refinement, a sparse solve,
//            the function shifted to 0 at the median of the input points), sampled on the grid.
//   rbf      interpolation by the triharmonic kernel phi(r) = r^3 plus a linear polynomial
//            (Carr, Beatson, Cherrie, Mitchell, Fright, McCallum, Evans, "Reconstruction and
//            representation of 3D objects with radial basis functions", SIGGRAPH 2001): at
//            most `rbf_centers` points (every ceil(N / rbf_centers)-th), each with f = 0 and
//            the off-surface constraints f(p +- e n) = +-e (e halved up to 5 times until the
//            nearest point of p + e n is p, else the constraint is dropped, as in the paper);
//            one dense LU solve of the (3m + 4)-sized system (Eigen's PartialPivLU).
//   imls     implicit moving least squares (Kolluri, "Provably good moving least squares",
//            ACM TALG 4(2), 2008): f(q) = sum_i t_i(q) (q - p_i) . n_i / sum_i t_i(q), t_i(q) =
//            exp(-|q - p_i|^2 / rho^2) over the points within 4 rho (the nearest point's plane
//            when none); rho defaults to the median distance from a point to its k-th nearest.
//
// Normals are required (given with the points or estimated by estimators/point_normals.hpp),
// oriented outward; they need not be unit (they are normalized).
//
// Errors (InvalidArgument, one line): a cloud that fails validate_point_cloud, no normals,
// k < 1 or k > N - 1, h not positive and finite, a grid of more than `max_samples` samples,
// bad method parameters; CGAL's solver failing (Error naming it).
// Cost (N points, G grid samples): hoppe O(N k log N + G log N); winding O(N k log N) plus
// O(G log N) expected for the tree (O(G N) exact); imls O(G (log N + m)) with m the points
// within 4 rho; rbf O(m^3 + G m); poisson CGAL's. Memory O(N + G). Threads: every loop over
// samples is parallel; results do not depend on the thread count.
#pragma once

#include <zdg/kernel/images/image.hpp>
#include <zdg/kernel/points/kd_tree.hpp>
#include <zdg/kernel/points/point_cloud.hpp>
#include <zdg/kernel/surfaces/mesh.hpp>
#include <zdg/kernel/topology/betti_numbers.hpp>

#include <array>
#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace zdg {

enum class ReconstructionMethod { hoppe, winding, poisson, rbf, imls };

std::string to_string(ReconstructionMethod method);
/// "hoppe", "winding", "poisson", "rbf", "imls"; InvalidArgument listing them otherwise.
ReconstructionMethod reconstruction_method_of(std::string_view name);
const std::vector<std::string>& reconstruction_method_names();

/// Samples of the lattice h Z^3: sample (i, j, k) (0 <= i < nx, ...) is the point h (lower +
/// (i, j, k)). Values are stored in C order, x fastest: index (k ny + j) nx + i.
struct SampleGrid {
  double h = 1;
  std::array<std::int64_t, 3> lower{}; ///< (x, y, z) index of sample (0, 0, 0) on Z^3
  std::int64_t nx = 0, ny = 0, nz = 0;

  std::int64_t size() const { return nx * ny * nz; }
  Point3<double> at(std::int64_t i, std::int64_t j, std::int64_t k) const {
    return {h * double(lower[0] + i), h * double(lower[1] + j), h * double(lower[2] + k)};
  }
  Point3<double> at(std::int64_t index) const {
    return at(index % nx, (index / nx) % ny, index / (nx * ny));
  }
};

/// The samples of h Z^3 in the points' bounding box grown by `margin` samples on each side.
/// InvalidArgument when h is not positive and finite, the cloud is empty, or the grid would
/// have more than max_samples samples (naming the count).
SampleGrid grid_around(const PointCloud& cloud, double h, int margin = 3,
                       std::int64_t max_samples = std::int64_t{1} << 31);

struct ImplicitField {
  SampleGrid grid;
  std::vector<double> values; ///< one per sample, negative inside
};

struct ReconstructionOptions {
  ReconstructionMethod method = ReconstructionMethod::hoppe;
  std::size_t k = 10;         ///< neighbours: hoppe's centroids, point areas, imls's rho
  double winding_beta = 2;    ///< the tree's accuracy (> 0; larger: more exact, slower)
  bool winding_exact = false; ///< brute-force winding numbers (no tree)
  std::size_t rbf_centers = 1000;
  double rbf_offset = 0;  ///< e; 0: 1/100 of the bounding box's diagonal
  double imls_radius = 0; ///< rho; 0: the median distance to the k-th nearest point
  unsigned threads = 0;
};

/// The field of `options.method` on `grid` (errors above).
ImplicitField reconstruct_field(const PointCloud& cloud, const SampleGrid& grid,
                                const ReconstructionOptions& options);

/// The Poisson field (CGAL, estimators/poisson_reconstruction.cpp); called by
/// reconstruct_field.
ImplicitField poisson_field(const PointCloud& cloud, const SampleGrid& grid, unsigned threads);

/// The area a_i of each point: its Voronoi cell among its k nearest neighbours projected on
/// its tangent plane (the plane through p_i normal to n_i), clipped to the square of half side
/// the k-th neighbour's distance (Barill et al. 2018, section 4.1). Needs normals.
std::vector<double> point_areas(const PointCloud& cloud, const KdTree& tree, std::size_t k,
                                unsigned threads = 0);

/// sum_i a_i (p_i - q) . n_i / (4 pi |p_i - q|^3) over every point (a point at q is skipped):
/// the reference of the tree.
double winding_number_exact(const PointCloud& cloud, std::span<const double> areas,
                            const Point3<double>& q);

/// The tree of Barill et al.: a binary tree of the points (median splits, leaves of at most
/// 8 points); each node keeps its area-weighted centre c, radius r (the farthest point) and
/// the moments sum a_i n_i, sum a_i (p_i - c) n_i^T and sum a_i n_i (p_i - c)(p_i - c)^T of
/// the Taylor expansion of order 2 of the kernel about c. A node with |q - c| > beta r
/// contributes its expansion, a leaf otherwise its exact sum; the error of one node is
/// O((r / |q - c|)^3) relative to its contribution (beta = 2: a node's expansion within 1/8 of
/// it; the sum over a sphere of 3000 points within 1e-2 of the exact one, 1e-3 at beta = 3).
class WindingTree {
public:
  WindingTree(const PointCloud& cloud, std::span<const double> areas);
  ~WindingTree();
  WindingTree(WindingTree&&) noexcept;
  WindingTree& operator=(WindingTree&&) noexcept;
  double operator()(const Point3<double>& q, double beta) const;

private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

/// A reconstruction: the field, the digitization of its negative set (a 3D image over the
/// grid, 1 inside), the Betti numbers of that solid ((6,26): a ball 1, 0, 0, a solid torus
/// 1, 1, 0) and the marching-cubes mesh of the set
/// ((6,26), vertices on the zero crossings, physical units).
struct Reconstruction {
  ImplicitField field;
  Image<std::uint8_t> inside;
  BettiNumbers betti;
  PolygonMesh mesh;
  std::int64_t inside_count = 0;
};

Reconstruction reconstruct(const PointCloud& cloud, double h, const ReconstructionOptions& options,
                           int margin = 3);

} // namespace zdg
