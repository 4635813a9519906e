// Convex hull of a finite set of points of Z^3.
//
//   conv(S), S in Z^3 finite: its vertices (extreme points: points inside an edge or a facet
//   are not vertices), its facets as vertex cycles counterclockwise seen from outside (the
//   triangles of a flat facet are merged exactly: coplanar facets become one polygon), the
//   primitive integer outward normal of each facet, and 6 * volume (an integer). Degenerate
//   sets are reported by `dimension`: 0 (one point), 1 (a segment: two vertices, no facet),
//   2 (a planar polygon: its two sides as two facets with opposite normals, volume 0).
//   lattice_points_in_hull_3d counts #(conv(S) cap Z^3).
//
// Algorithm: a pre-filter keeps the points extreme on their axis-parallel lines, then Quickhull
//   (Barber, Dobkin, Huhdanpaa, ACM TOMS 1996) on exact signs n . p > n . a, n = (b - a) x (c - a):
//   O(n log n) typical, O(n^2) worst; coplanar points never become false vertices.
// Width: n . p and 6 * volume need 3b + 6 bits for coordinates below 2^b (Int64: below 2^19);
//   lattice_hull_3d<I>() throws OverflowError past I, _exact() escalates Int64 -> Int128 ->
//   BigInt. lattice_points_in_hull_3d scans the xy-columns of the bounding box: O(X Y F).
#pragma once

#include <zdg/arith/escalate.hpp>
#include <zdg/arith/integer.hpp>
#include <zdg/arith/point.hpp>

#include <cstddef>
#include <span>
#include <vector>

namespace zdg {

template <TowerInt I>
struct LatticeHull3d {
  int dimension = -1;                           // -1 for an empty input
  std::vector<Point3<I>> vertices;              // lexicographically sorted
  std::vector<std::vector<std::size_t>> facets; // indices into vertices, ccw from outside
  std::vector<Point3<I>> normals;               // primitive outward normal per facet
  I volume6{0};                                 // 6 * volume
};

/// The hull computed on I (throws OverflowError when I is too narrow).
template <TowerInt I>
LatticeHull3d<I> lattice_hull_3d(std::span<const Point3<I>> pts);

/// The hull of points of any size, exact by escalation from Int64 (results as BigInt), with
/// the type that served.
template <TowerInt I>
Escalated<LatticeHull3d<BigInt>> lattice_hull_3d_exact(std::span<const Point3<I>> pts);

/// #(conv cap Z^3) for a hull from lattice_hull_3d (any dimension).
template <TowerInt I>
I lattice_points_in_hull_3d(const LatticeHull3d<I>& h);

} // namespace zdg
