// Convex hull of a finite set of points of Z^2.
//
//   conv(S) for S in Z^2 finite: its vertices, counterclockwise, starting at the lowest
//   (then leftmost) one. Points on an edge but not at a corner are not vertices (collinear
//   points excluded); duplicates are allowed. Degenerate sets: one distinct point gives one
//   vertex, collinear points give the two endpoints (lowest-then-leftmost first).
//
// Algorithm: past 64 points the Akl-Toussaint throw-away (1978, O(n)), then Andrew's monotone
// chain (1979), O(n log n), on the exact orientation sign((b - a) x (c - a)).
// Width: about 2 b + 2 bits for b-bit coordinates (Int64: below 2^30); lattice_hull_2d<I>()
// throws OverflowError past I, lattice_hull_2d_exact() escalates Int64 -> Int128 -> BigInt
// (arith/escalate.hpp), so every coordinate size works.
#pragma once

#include <zdg/arith/escalate.hpp>
#include <zdg/arith/integer.hpp>
#include <zdg/arith/point.hpp>

#include <cstddef>
#include <span>
#include <vector>

namespace zdg {

/// Sign of the cross product (b - a) x (c - a): 1 when a, b, c turn left (counterclockwise),
/// -1 right, 0 collinear. Throws OverflowError when an intermediate leaves I.
template <TowerInt I>
int orientation(const Point2<I>& a, const Point2<I>& b, const Point2<I>& c) {
  I l = (b.x - a.x) * (c.y - a.y);
  I r = (b.y - a.y) * (c.x - a.x);
  return l > r ? 1 : (l < r ? -1 : 0);
}

/// Indices into pts of the hull vertices (counterclockwise from the lowest-then-leftmost;
/// among duplicates the first index). Computed on I: may throw OverflowError.
template <TowerInt I>
std::vector<std::size_t> lattice_hull_2d_indices(std::span<const Point2<I>> pts);

/// Hull vertices of pts, computed on I (may throw OverflowError).
template <TowerInt I>
std::vector<Point2<I>> lattice_hull_2d(std::span<const Point2<I>> pts);
/// Hull vertices of pts, exact by escalation from Int64 (the vertices are input points, so
/// they are returned in the input type I), with the type that served.
template <TowerInt I>
Escalated<std::vector<Point2<I>>> lattice_hull_2d_exact(std::span<const Point2<I>> pts);

} // namespace zdg
