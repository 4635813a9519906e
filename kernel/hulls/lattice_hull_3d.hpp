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
// Algorithm: a pre-filter keeps the points extreme in their axis-parallel lines (a point
//   strictly between two others on a line is no vertex; this leaves O(n^{2/3}) points of a
//   dense lattice body), then incremental construction with conflict lists, each face's
//   furthest conflict point inserted first (Quickhull: Barber, Dobkin, Huhdanpaa, ACM TOMS
//   1996): O(n log n) on typical inputs, O(n^2) in the worst case. Every decision is an exact
//   sign: "p strictly above the plane of a triangle" is n . p > n . a with
//   n = (b - a) x (c - a). Points not strictly above any face are discarded, so coplanar
//   points never become false vertices; flat triangles are merged and collinear boundary
//   points dropped at the end.
// Width: for coordinates below 2^b in magnitude, n has at most 2b + 4 bits and n . p (every
//   predicate, the coplanarity of neighbouring facets included) and 6 * volume at most 3b + 6:
//   Int64 serves coordinates below 2^19 for sure. lattice_hull_3d<I>() computes on I and throws
//   OverflowError past it; lattice_hull_3d_exact() escalates (Int64 -> Int128 -> BigInt).
//   The lattice point count scans the xy-columns of the bounding box: O(X Y F).
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
