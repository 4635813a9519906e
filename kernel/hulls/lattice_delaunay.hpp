// Delaunay triangulations of lattice points of Z^2 and Z^3 with exact predicates, their
// Voronoi cells as rational polytopes, and the Delaunay certificate of a nearest site.
//
// Triangulation: CGAL's Delaunay_triangulation_2 / _3 on Exact_predicates_inexact_constructions
// (filtered predicates, exact for every double input; the lattice coordinates are doubles
// exactly when |x| <= 2^53, checked). Degenerate configurations, which the lattice is full of
// (four cocircular or five cospherical points), are resolved by CGAL's symbolic perturbation in
// 3D (Devillers, Teillaud, "Perturbations for Delaunay and weighted Delaunay 3D
// triangulations", CGTA 44, 2011) and by its insertion order in 2D: either way the result is a
// Delaunay triangulation (no point strictly inside the circumcircle / circumsphere of a cell,
// which the tests check exactly on lattices), deterministic for one input. Duplicate points
// are merged (the first occurrence is the vertex). O(n log n) expected.
//
// Voronoi cells: the cell of site s is {x : |x - s| <= |x - t| for every site t}; its vertices
// are the circumcentres of the Delaunay cells around s, exact rationals (Cramer's rule on the
// integer coordinates in BigInt), deduplicated (cocircular cells share their centre). The cell
// is bounded iff s is not on the boundary of the convex hull. Unbounded cells list the
// vertices they have (their rays are not represented).
//
// Nearest-site certificate (the property that ties the triangulation to the Voronoi map of
// zdg transform voronoi): a site s is a nearest site of x iff no Delaunay neighbour of s is
// strictly closer to x (the Delaunay graph's greedy walk ends at a nearest site; Okabe, Boots,
// Sugihara, Chiu, "Spatial tessellations", 2000, property D5).
//
// Errors: InvalidArgument (a dimension other than 2 or 3, no point, a coordinate past 2^53).
#pragma once

#include <zdg/arith/integer.hpp>
#include <zdg/arith/rational.hpp>

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace zdg {

struct LatticeDelaunay {
  int dim = 2;
  /// The affine dimension of the points (0: one point, 1: collinear, 2: coplanar in 3D, ...).
  int affine_dim = 0;
  /// Distinct points, dim coordinates each (vertex v is points[v*dim .. v*dim+dim)).
  std::vector<std::int64_t> points;
  /// For every input point, its vertex.
  std::vector<std::size_t> vertex_of_input;
  /// Cells (triangles in 2D, tetrahedra in 3D), dim + 1 vertices each, positively oriented
  /// (counterclockwise / positive volume); empty when affine_dim < dim.
  std::vector<std::array<std::size_t, 4>> cells;
  /// The Delaunay graph: the sorted neighbours of each vertex (every finite edge).
  std::vector<std::vector<std::size_t>> neighbours;
  /// Whether each vertex is on the boundary of the convex hull (all are when affine_dim < dim).
  std::vector<bool> on_hull;

  std::size_t vertex_count() const { return on_hull.size(); }
};

/// The Delaunay triangulation of the points (dim coordinates each, row after row).
LatticeDelaunay lattice_delaunay(const std::vector<std::int64_t>& coords, int dim);

/// The circumcentre of cell c, exact.
std::vector<Rational<BigInt>> circumcentre(const LatticeDelaunay& t, std::size_t c);

struct VoronoiCell {
  std::size_t site = 0;
  bool bounded = false;
  /// Distinct vertices (circumcentres); in 2D in counterclockwise order around the site.
  std::vector<std::vector<Rational<BigInt>>> vertices;
};

/// The Voronoi cells of every vertex (site) of the triangulation (affine_dim == dim, else
/// InvalidArgument: the cells are slabs, not polytopes with vertices).
std::vector<VoronoiCell> voronoi_cells(const LatticeDelaunay& t);

/// Whether vertex s is a nearest site of the lattice point x (dim coordinates), by the Delaunay
/// certificate: no neighbour of s strictly closer (exact, squared distances in Int128).
bool delaunay_nearest(const LatticeDelaunay& t, std::size_t s, const std::vector<std::int64_t>& x);

} // namespace zdg
