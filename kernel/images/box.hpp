// Inclusive integer boxes of Z^2 and Z^3: [lo.x, hi.x] x [lo.y, hi.y] (x [lo.z, hi.z]).
// A box with some hi < lo is empty. Pixels and voxels are the int64 points of zdg's images
// and digitizations; their coordinates are bounded by the box, which the caller keeps inside
// int64 (digitizations size their box from the shape and h, checked there).
#pragma once

#include <zdg/arith/point.hpp>

#include <cstdint>

namespace zdg {

using Pixel = Point2<std::int64_t>;
using Voxel = Point3<std::int64_t>;

struct Box2 {
  Pixel lo, hi;
  bool empty() const { return hi.x < lo.x || hi.y < lo.y; }
  bool contains(const Pixel& p) const {
    return lo.x <= p.x && p.x <= hi.x && lo.y <= p.y && p.y <= hi.y;
  }
};

struct Box3 {
  Voxel lo, hi;
  bool empty() const { return hi.x < lo.x || hi.y < lo.y || hi.z < lo.z; }
  bool contains(const Voxel& p) const {
    return lo.x <= p.x && p.x <= hi.x && lo.y <= p.y && p.y <= hi.y && lo.z <= p.z && p.z <= hi.z;
  }
};

} // namespace zdg
