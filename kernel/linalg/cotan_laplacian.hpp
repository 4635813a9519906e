// Laplacians of surface meshes: the cotangent Laplacian of a triangle mesh (Pinkall-Polthier,
// "Computing discrete minimal surfaces and their conjugates", Exp. Math. 1993; Meyer, Desbrun,
// Schroeder, Barr 2003) and the combinatorial (graph) Laplacian of the surfel adjacency of a
// digital surface (kernel/surfaces/surfel_complex.hpp), the comparators of the heat-kernel operator
// (estimators/heat_laplace_beltrami.hpp; Caissard et al., JMIV 2019, Table 1).
//
// Cotangent: L = M^{-1} S, S_ij = (cot a_ij + cot b_ij) / 2, S_ii = -sum_j S_ij, M_i the lumped
// mass (area / 3 per incident triangle); S symmetric, S 1 = 0, linear precision; L u -> Delta_S u
// only on meshes whose normals converge (Hildebrandt, Polthier, Wardetzky 2006), not on a
// digital staircase. Combinatorial: (L u)(s) = (1 / area(s)) sum over the four surfels r
// adjacent to s of (u(r) - u(s)). Properties: docs/NOTES.md, "kernel/linalg/cotan_laplacian.hpp".
// O(n) time and memory (12 entries per triangle, 5 per surfel); doubles, int64 indices.
#pragma once

#include <zdg/arith/point.hpp>
#include <zdg/kernel/linalg/sparse_matrix.hpp>
#include <zdg/kernel/surfaces/mesh.hpp>
#include <zdg/kernel/surfaces/surfel_complex.hpp>

#include <array>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

namespace zdg {

struct CotanLaplacian {
  SparseMatrix stiffness;   ///< S (symmetric, rows sum to 0)
  std::vector<double> mass; ///< lumped barycentric areas M_i

  /// L u = M^{-1} S u (0 where M_i = 0: a vertex of no triangle).
  std::vector<double> apply(std::span<const double> u, unsigned threads = 1) const;
};

/// Checks a triangle's vertex indices for the triangle-mesh Laplacians: each in [0, n) and the
/// three distinct. InvalidArgument "WHO: triangle F uses vertex V of N" / "... repeats a vertex".
void check_triangle_indices(const std::array<std::int64_t, 3>& tri, std::int64_t n,
                            const std::string& who, std::size_t f);

/// The cotangent Laplacian of the triangles (vertex indices, any orientation). InvalidArgument
/// for an index out of range or a degenerate triangle (zero area).
CotanLaplacian cotan_laplacian(std::span<const Point3<double>> vertices,
                               std::span<const std::array<std::int64_t, 3>> triangles);

/// The cotangent Laplacian of a mesh of triangles, or of quads split as below;
/// InvalidArgument for other faces (and as above).
CotanLaplacian cotan_laplacian(const PolygonMesh& mesh);

/// Each quad (v0, v1, v2, v3) as the triangles (v0, v1, v2), (v0, v2, v3).
std::vector<std::array<std::int64_t, 3>>
triangulate_quads(std::span<const std::array<std::int64_t, 4>> quads);

/// The combinatorial Laplacian on the surfels of the complex (the matrix above).
SparseMatrix combinatorial_laplacian(const SurfelComplex& complex);

} // namespace zdg
