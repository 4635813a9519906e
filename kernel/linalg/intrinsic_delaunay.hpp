// The intrinsic Delaunay triangulation of a triangle mesh and its cotangent Laplacian (Bobenko,
// Springborn, "A discrete Laplace-Beltrami operator for simplicial surfaces", Discrete Comput.
// Geom. 38, 2007; Fisher, Springborn, Bobenko, Schroeder, "An algorithm for the construction of
// intrinsic Delaunay triangulations with applications to digital geometry processing",
// Computing 81, 2007): the mesh is kept as a metric (a length per edge); every edge that is not
// locally Delaunay (cot a + cot b < 0, a and b the angles opposite it) is flipped inside the
// quadrilateral its two triangles unfold to, the new length from the law of cosines
//   |cd|^2 = |ca|^2 + |ad|^2 - 2 |ca| |ad| cos(angle at a in the first + in the second triangle),
// until every edge is locally Delaunay. Flips change neither the vertices (the triangles still
// name the input's vertex indices; several edges may join the same two vertices), nor the
// metric of the surface, nor its total area. The cotangent Laplacian of the result, L = M^{-1} S
// with S_ij = sum over the edges ij of (cot a + cot b) / 2 and M_i a third of the intrinsic area
// of the triangles at i, has S_ij >= 0 off the diagonal, S symmetric, S 1 = 0, and is the
// cotangent Laplacian of kernel/linalg/cotan_laplacian.hpp when the mesh is already Delaunay
// (every edge's cot a + cot b >= 0); it does not depend on how ties (cot a + cot b = 0: four
// cocircular vertices) are flipped, which is why edges are flipped only below -1e-12.
//
// Complexity: O(F) to build, then O(1) per flip; the number of flips is finite (Bobenko,
// Springborn 2007) and in practice a small multiple of the number of edges; more than 10^3 F
// flips throws Error (it would be a floating-point cycle). Precision: lengths, angles and
// cotangents in double from the edge lengths (Heron's formula in Kahan's stable order), so a
// weight is known to about 1e-15 relative to the triangle's aspect ratio.
//
// Errors (InvalidArgument): an index out of range, a triangle that repeats a vertex or is
// degenerate (zero area), an edge shared by more than two triangles (non-manifold), or two
// triangles that run their common edge in the same direction (not consistently oriented).
// Boundary edges (one triangle) are allowed and never flipped.
#pragma once

#include <zdg/arith/point.hpp>
#include <zdg/kernel/linalg/cotan_laplacian.hpp>

#include <array>
#include <cstdint>
#include <span>
#include <vector>

namespace zdg {

struct IntrinsicTriangulation {
  std::vector<std::array<std::int64_t, 3>> triangles; ///< vertex indices of the input
  std::vector<std::array<double, 3>> lengths;         ///< lengths[f][k]: the edge opposite corner k
  /// twin[3 f + k]: the slot 3 g + m of the same edge in its other triangle, -1 on the boundary.
  std::vector<std::int64_t> twin;
  std::int64_t flips = 0; ///< the number of flips made

  /// The area of triangle f from its lengths.
  double area(std::size_t f) const;
  /// cot of the angle at corner k of triangle f.
  double cotangent(std::size_t f, int k) const;
};

/// The intrinsic triangulation of the mesh as given (its edge lengths), not flipped.
IntrinsicTriangulation
intrinsic_triangulation(std::span<const Point3<double>> vertices,
                        std::span<const std::array<std::int64_t, 3>> triangles);

/// Flips the non-Delaunay edges of t until every edge is locally Delaunay.
void make_intrinsic_delaunay(IntrinsicTriangulation& t);

/// The cotangent Laplacian of the intrinsic triangulation t on n vertices (t's indices < n).
CotanLaplacian intrinsic_cotan_laplacian(const IntrinsicTriangulation& t, std::int64_t n);

/// The intrinsic Delaunay Laplacian of the mesh: the three steps above.
CotanLaplacian intrinsic_delaunay_laplacian(std::span<const Point3<double>> vertices,
                                            std::span<const std::array<std::int64_t, 3>> triangles);

} // namespace zdg
