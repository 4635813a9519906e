// The boundary of a digitized set of Z^3 as a digital surface: its boundary surfels, the
// adjacency of surfels along their linels, tracking of a connected surface from a seed, and
// the primal polygonal surface (one quad per surfel) with its Euler characteristic.
//
// The set is X = { z in box : inside(z) }; voxels outside the box count as outside, so the
// surface is always closed. Its boundary surfels are the surfels between a voxel of X and a
// 6-neighbour not in X, oriented from the inner to the outer voxel
// (kernel/surfaces/cubical_cells.hpp).
//
// Surfel adjacency (bel-adjacency of Herman and Udupa; Herman, "Discrete multidimensional
// Jordan surfaces", CVGIP 1992; DGtal's SurfelAdjacency): through each of its 4 linels a
// boundary surfel s (inner voxel I, outer voxel O = I + n) has exactly one follower. For the
// tangent direction t, with I1 = I + t and O1 = O + t:
//   (a) O1 in X: the surfel between O1 (inner) and O (outer)  -- concave turn;
//   (b) I1 in X, O1 not: the surfel between I1 and O1         -- flat;
//   (c) I1 not in X: the surfel between I and I1              -- convex turn.
// When I and O1 are in X but O and I1 are not, (a) and (c) both apply: INTERIOR adjacency
// picks (a) (X is taken 18-connected, its complement 6-connected), EXTERIOR picks (c). Either
// choice makes the relation symmetric, so every boundary surfel has exactly four neighbours
// and the boundary splits into closed connected surfaces.
//
// Complexity: the scan costs one predicate evaluation per voxel of the box and O(nx ny)
// memory (two slices); tracking costs O(#surfels) predicate evaluations and hash operations
// and never looks at voxels away from the surface. Coordinates are int64; boxes are checked
// at entry (|coordinate| <= 2^40, InvalidArgument past it).
#pragma once

#include <zdg/kernel/surfaces/cubical_cells.hpp>

#include <array>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <optional>
#include <span>
#include <vector>

namespace zdg {

/// Membership of a voxel in the digitized set (for a shape at step h: z is inside when h z
/// is in the shape).
using VoxelPredicate = std::function<bool(const Voxel&)>;

/// A binary image of a box of voxels, x fastest, then y, then z; nonzero = inside.
struct BinaryVolume {
  VoxelBox box;
  std::vector<std::uint8_t> data;

  /// Evaluates the predicate on every voxel of the box.
  static BinaryVolume from_predicate(const VoxelPredicate& inside, const VoxelBox& box);
  std::size_t index(const Voxel& z) const {
    const auto nx = std::size_t(box.hi.x - box.lo.x + 1), ny = std::size_t(box.hi.y - box.lo.y + 1);
    return (std::size_t(z.z - box.lo.z) * ny + std::size_t(z.y - box.lo.y)) * nx +
           std::size_t(z.x - box.lo.x);
  }
  /// False outside the box.
  bool at(const Voxel& z) const { return box.contains(z) && data[index(z)] != 0; }
};

enum class SurfelAdjacency { interior, exterior };

/// All boundary surfels of X by scanning the box slice by slice, sorted.
std::vector<Surfel> boundary_surfels(const VoxelPredicate& inside, const VoxelBox& box);
/// All boundary surfels of the inside voxels of a binary volume, sorted.
std::vector<Surfel> boundary_surfels(const BinaryVolume& volume);

/// A boundary surfel found by walking from the inside voxel `start` along +x to the last
/// inside voxel; O(walk length). Throws InvalidArgument if start is not in X.
Surfel find_boundary_surfel(const VoxelPredicate& inside, const VoxelBox& box, const Voxel& start);

/// The follower of the boundary surfel s through its linel in direction sign * e_tangent
/// (tangent_axis != orthogonal_axis(s), sign = +-1). s must be a boundary surfel of X.
Surfel adjacent_surfel(const VoxelPredicate& inside, const VoxelBox& box, const Surfel& s,
                       int tangent_axis, int sign,
                       SurfelAdjacency adjacency = SurfelAdjacency::interior);

/// The four followers of s, in the order of surfel_linels(s).
std::array<Surfel, 4> surfel_neighbours(const VoxelPredicate& inside, const VoxelBox& box,
                                        const Surfel& s,
                                        SurfelAdjacency adjacency = SurfelAdjacency::interior);

/// The connected digital surface containing the boundary surfel `seed`, in breadth-first
/// order from the seed. Throws InvalidArgument if seed is not a boundary surfel of X.
std::vector<Surfel> track_surface(const VoxelPredicate& inside, const VoxelBox& box,
                                  const Surfel& seed,
                                  SurfelAdjacency adjacency = SurfelAdjacency::interior);

/// The boundary surfels orthogonal to x on the line { (x, y, z) : box.lo.x <= x <= box.hi.x }:
/// seeds on every connected surface that the line crosses, in O(nx) evaluations.
std::vector<Surfel> line_boundary_surfels(const VoxelPredicate& inside, const VoxelBox& box,
                                          std::int64_t y, std::int64_t z);

/// The union of the connected surfaces through the given seeds, each surfel once (surfaces
/// in the order of their first seed, breadth-first within each). A driver finds every
/// component of a shape without scanning the box by seeding from a few lines.
std::vector<Surfel> track_surfaces(const VoxelPredicate& inside, const VoxelBox& box,
                                   std::span<const Surfel> seeds,
                                   SurfelAdjacency adjacency = SurfelAdjacency::interior);

/// The primal polygonal surface: vertices are the pointels (Khalimsky points), one quad per
/// surfel, counterclockwise seen from outside (surfel_pointels).
struct QuadSurface {
  std::vector<KPoint> vertices;
  std::vector<std::array<std::uint32_t, 4>> quads;
  std::size_t edge_count = 0; ///< distinct linels (unordered vertex pairs of the quads)
};

QuadSurface primal_surface(std::span<const Surfel> surfels);

/// V - E + F of the primal surface (2 for a sphere, 0 for a torus, 2 - 2g in general).
std::int64_t euler_characteristic(const QuadSurface& surface);

} // namespace zdg
