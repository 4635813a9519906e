// Convex hull of a digitized shape: conv({z in B cap Z^d : inside(z)}) for any inside
// predicate on an integer box B (d = 2 or 3), e.g. the Gauss digitization of a shape at a
// grid step (convergence experiments).
//
// Only the extreme points of each axis-parallel column can be hull vertices, so each column
// of the box is scanned from both ends until the predicate holds: for a convex shape this
// costs O(columns + boundary) predicate calls, O(|B|) for an arbitrary one (every call is
// the caller's, exact or not as the predicate is). The column extremes then go to the exact
// hull (lattice_hull_2d_exact / lattice_hull_3d_exact: escalation Int64 -> Int128 -> BigInt,
// see arith/escalate.hpp). The box is given by int64 bounds; 2D vertices are on Int64 (they
// are points of the box), the 3D hull (normals, volume) on BigInt.
#pragma once

#include <zdg/arith/error.hpp>
#include <zdg/arith/integer.hpp>
#include <zdg/kernel/hulls/lattice_hull_2d.hpp>
#include <zdg/kernel/hulls/lattice_hull_3d.hpp>
#include <zdg/kernel/images/box.hpp>

#include <cstdint>
#include <string>
#include <vector>

namespace zdg {

/// Hull vertices (counterclockwise from the lowest-then-leftmost) of the points (x, y) of the
/// box with inside(x, y) true.
template <class Inside>
Escalated<std::vector<Point2<Int64>>> digitized_shape_hull_2d_exact(const Box2& box,
                                                                    Inside&& inside) {
  if (box.lo.x > box.hi.x || box.lo.y > box.hi.y) return {{}, IntKind::int64};
  std::vector<Point2<Int64>> ext;
  for (std::int64_t x = box.lo.x; x <= box.hi.x; ++x) {
    std::int64_t lo = box.lo.y;
    while (lo <= box.hi.y && !inside(x, lo)) ++lo;
    if (lo > box.hi.y) continue;
    std::int64_t hi = box.hi.y;
    while (hi > lo && !inside(x, hi)) --hi;
    ext.push_back({x, lo});
    if (hi != lo) ext.push_back({x, hi});
  }
  return lattice_hull_2d_exact<Int64>(std::span<const Point2<Int64>>(ext));
}

/// The exact 3D hull of the points (x, y, z) of the box with inside(x, y, z) true.
template <class Inside>
Escalated<LatticeHull3d<BigInt>> digitized_shape_hull_3d_exact(const Box3& box, Inside&& inside) {
  std::vector<Point3<Int64>> ext;
  if (box.lo.x <= box.hi.x && box.lo.y <= box.hi.y && box.lo.z <= box.hi.z) {
    for (std::int64_t x = box.lo.x; x <= box.hi.x; ++x) {
      for (std::int64_t y = box.lo.y; y <= box.hi.y; ++y) {
        std::int64_t lo = box.lo.z;
        while (lo <= box.hi.z && !inside(x, y, lo)) ++lo;
        if (lo > box.hi.z) continue;
        std::int64_t hi = box.hi.z;
        while (hi > lo && !inside(x, y, hi)) --hi;
        ext.push_back({x, y, lo});
        if (hi != lo) ext.push_back({x, y, hi});
      }
    }
  }
  return lattice_hull_3d_exact<Int64>(std::span<const Point3<Int64>>(ext));
}

} // namespace zdg
