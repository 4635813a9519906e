// Gauss volume estimator: Vol(X) ~ h^3 #G_h(X), the number of digital points of the
// digitization times the volume of a voxel. Converges in O(h) for convex X (better for
// smooth strictly convex sets: Kraetzel; Guo, exponent 243/158), see papers/THEORY.md.
//
// The count is exact (int64; the box volume is checked at entry to fit, InvalidArgument
// past it). It is made line by line along x (one predicate evaluation per voxel of the box,
// nothing stored), the z-slices being shared among `threads` threads.
#pragma once

#include <zdg/kernel/surfaces/digital_surface.hpp>

#include <cstdint>

namespace zdg {

struct GaussVolume {
  std::int64_t count = 0; ///< #{ z in box : inside(z) }, exact
  double volume = 0;      ///< h^3 count
};

/// Counts the inside voxels of the box and scales by h^3 (h > 0, threads >= 1; 0 means the
/// hardware concurrency).
GaussVolume gauss_volume(const VoxelPredicate& inside, const VoxelBox& box, double h,
                         unsigned threads = 0);

} // namespace zdg
