// Measures of a convex lattice polygon given by its vertices (counterclockwise, as
// lattice_hull_2d and the convex-body hulls return them).
//
//   area2     = 2 area = sum_i (x_i y_{i+1} - x_{i+1} y_i)                 (shoelace)
//   boundary  = sum_i gcd(|x_{i+1} - x_i|, |y_{i+1} - y_i|)   lattice points on the boundary
//   interior  = (area2 - boundary + 2) / 2                                  (Pick 1899)
//   lattice width = min over u in Z^2 \ {0} of (max_P <u, p> - min_P <u, p>), with a
//   direction u attaining it.
// Degenerate inputs: one vertex (a point) has boundary 1; two vertices (a segment) have
// area2 0, boundary gcd + 1, interior 0, lattice width 0.
//
// Complexity: O(V log C) for the counts; the lattice width runs the generalized Gauss
// reduction of Kaib and Schnorr (J. Algorithms 21, 1996: "The generalized Gauss reduction
// algorithm") on the width norm w(u) = max <u, p> - min <u, p>, O(V log^2 C) for coordinates
// of size C. Width: products of two coordinates (the shoelace terms): Int64 is safe below
// 2^30; lattice_polygon_measures_exact() escalates to Int128 and BigInt on overflow.
#pragma once

#include <zdg/arith/escalate.hpp>
#include <zdg/arith/integer.hpp>
#include <zdg/arith/point.hpp>

#include <span>

namespace zdg {

template <TowerInt I>
struct LatticePolygonMeasures {
  I area2{0};    // twice the area
  I boundary{0}; // lattice points on the boundary (vertices included)
  I interior{0}; // lattice points in the interior (Pick)
};

/// Twice the signed area (positive for counterclockwise vertices).
template <TowerInt I>
I polygon_area2(std::span<const Point2<I>> v);

/// area2, boundary and interior lattice point counts of a convex lattice polygon with
/// counterclockwise vertices (any number: 0 gives all zeros). Computed on I.
template <TowerInt I>
LatticePolygonMeasures<I> lattice_polygon_measures(std::span<const Point2<I>> v);

/// The same, exact by escalation (Int64 -> Int128 -> BigInt); results as BigInt, with the
/// type that served.
Escalated<LatticePolygonMeasures<BigInt>>
lattice_polygon_measures_exact(std::span<const Point2<BigInt>> v);

template <TowerInt I>
struct LatticeWidth {
  I width{0};
  Point2<I> direction{I(0), I(1)}; // a primitive u attaining the width
};

/// Lattice width of the convex hull of v (>= 1 vertex). Computed on I.
template <TowerInt I>
LatticeWidth<I> lattice_width(std::span<const Point2<I>> v);

} // namespace zdg
