// Laplace-Beltrami spectra of digitized 3D shapes, for the estimator lb-spectrum and the
// eigenspace-stability experiment (papers/lb-spectrum/README.md).
//
// The operators, as a generalized problem K x = lambda M x (K symmetric positive
// semi-definite, M diagonal positive; kernel/linalg/generalized_eigen.hpp):
//   cotan     cotangent Laplacian of the primal quad surface split into triangles, at the
//             pointels: K = -S (kernel/linalg/cotan_laplacian.hpp; the split diagonals of the
//             square surfels get weight 0), M = a quarter of the incident quads' areas
//   cotan-mc  the same on the marching-cubes mesh ((6,26), level 1/2), at its vertices
//   heat      heat-kernel operator on the surfel centres (estimators/heat_laplace_beltrami.hpp,
//             t = h^{2/5}, II normal radius 2 h^{1/3}, weights w = h^2 n_II . n_elem):
//             K = -W L, M = W (W L is symmetric; every w must be positive)
// The sphere of radius r: the eigenvalues of -Delta are l(l+1)/r^2, l = 0, 1, ..., with
// multiplicity 2l+1 (spherical harmonics); the index range of cluster l in increasing order is
// [l^2, (l+1)^2). Eigenvalue i (1-based among the non-zero ones) is l(l+1)/r^2 for the l with
// l^2 <= i < (l+1)^2.
//
// Eigenspace stability (the seeds' experiment): the principal angles (kernel/linalg/
// principal_angles.hpp, in the M inner product) between the eigenspace of cluster l of one
// discretization and
//   - that of another (a finer h): its eigenvectors sampled at the nodes of the first by the
//     nearest node (both in the shape's frame);
//   - itself mapped by a symmetry of the cube (a signed permutation of the axes, 48 of them):
//     x -> u(g x) sampled at the nearest node of g x. A shape digitized with translation 0 and
//     invariant under g (a sphere centred at the origin) has node sets invariant under g, so an
//     operator that commutes with g leaves each eigenspace invariant: angles ~ 0.
// Cost: the eigensolve (generalized_eigen.hpp), the nearest-node lookups on a uniform grid of
// the nodes, O(n) expected each; the angles O(n (2l+1)^2).
#pragma once

#include <zdg/arith/point.hpp>
#include <zdg/convergence/estimator.hpp>

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace zdg {

struct SurfelComplex;

/// The mass of the operator `cotan` at each pointel: a quarter of the area of each incident
/// quad (O(surfels)).
std::vector<double> quad_corner_mass(const SurfelComplex& complex);

enum class SpectrumOperator { cotan, cotan_mc, heat };

/// "cotan", "cotan-mc", "heat".
std::string spectrum_operator_name(SpectrumOperator op);
/// The operator of a name above; InvalidArgument listing them otherwise.
SpectrumOperator parse_spectrum_operator(const std::string& name);

/// The first `count` non-zero eigenvalues of -Delta on the sphere of radius r, increasing
/// (l(l+1)/r^2 repeated 2l+1 times). InvalidArgument unless r > 0 and count >= 0.
std::vector<double> sphere_laplacian_eigenvalues(double r, std::int64_t count);

/// The radius of a sphere shape (sphere1, sphere9: the umbilic class of convergence/shapes_3d);
/// InvalidArgument naming `who` for any other shape.
double sphere_radius(const Shape& shape, const std::string& who);

/// The k smallest eigenpairs of one operator on one digitization.
struct SurfaceSpectrum {
  std::vector<Point3<double>> nodes;        ///< in the shape's frame (translation removed)
  std::vector<double> mass;                 ///< diagonal of M
  std::vector<double> values;               ///< k, increasing
  std::vector<std::vector<double>> vectors; ///< M-orthonormal
};

/// Digitizes in.shape at in.h with in.translation (the whole surface: InvalidArgument when the
/// box clips it), assembles `op` and computes its `k` smallest eigenpairs (1 <= k < nodes).
SurfaceSpectrum surface_spectrum(const RunInput& in, SpectrumOperator op, std::int64_t k);

/// A symmetry of the cube: (g x)_i = sign[i] x_{axis[i]} (axis a permutation, signs +-1).
struct CubeSymmetry {
  std::array<int, 3> axis{0, 1, 2};
  std::array<int, 3> sign{1, 1, 1};
};
/// The 48 symmetries (the identity first).
std::vector<CubeSymmetry> cube_symmetries();

/// Principal angles (radians, increasing) between the eigenspaces of cluster l of a and of b
/// (b's eigenvectors at a's nodes by nearest node). InvalidArgument when a or b has fewer than
/// (l+1)^2 eigenpairs.
std::vector<double> cluster_angles(const SurfaceSpectrum& a, const SurfaceSpectrum& b, int l);
/// Principal angles between the eigenspace of cluster l of a and its image under g.
std::vector<double> cluster_angles(const SurfaceSpectrum& a, const CubeSymmetry& g, int l);

} // namespace zdg
