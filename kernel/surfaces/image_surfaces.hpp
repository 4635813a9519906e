// The boundary of a binary 3D image split into closed digital surfaces under an adjacency
// pair, with the Euler characteristic and genus of each surface and of the object.
//
// Pairs (object k, background kbar): (6,26), (6,18), (18,6), (26,6). Two boundary surfels are
// adjacent when they share a linel and the bel-adjacency of kernel/surfaces/digital_surface.hpp
// pairs them there: EXTERIOR for an object taken 6-connected (two voxels of X meeting along a linel
// only are separated), INTERIOR for an object taken 18- or 26-connected (they are joined). Each
// surfel has exactly four neighbours, so the boundary splits into closed surfaces, the
// connected components of this relation.
//
// Each surface is a closed oriented 2-manifold once every pointel where several of its sheets
// meet gets one vertex per sheet (kernel/surfaces/pointel_cycles.hpp): V = number of (pointel,
// sheet) pairs, E = 2 F (each linel of a surface bounds two of its surfels), F = surfels, so chi =
// V - F and genus = (2 - chi) / 2.
//
// The object. For a compact 3-manifold M with boundary, chi(dM) = 2 chi(M). Under (6,18) and
// (18,6) the sheets at every pointel are exactly those of the pair's continuous analog
// (Kong-Rosenfeld 1989; Lachaud-Montanvert 2000), so the sum of the chi of the surfaces is
// 2 chi(X) = 2 (b0 - b1 + b2). Under (26,6) (resp. (6,26)) the analog joins the two sheets of
// each pointel around which X (resp. its complement) is exactly two opposite voxels of the
// 2x2x2 block, a "pinched pointel": a neck that no quad surface has. Separating the sheets
// there adds 2 to the sum for each of them, so in general
//     sum_S chi(S) = 2 (b0 - b1 + b2) + 2 (pinched pointels),
// and object_euler() below is exact for the four pairs.
//
// Pinched linels (kernel/surfaces/pointel_cycles.hpp) are counted too: the surface is a 2-manifold
// there (its edges are the adjacent surfel pairs), but its quad mesh repeats an edge.
//
// Enclosed volume: the signed number of voxels enclosed by the oriented surface (divergence
// theorem with the field (x, 0, 0): the sum over its x-surfels of +-x of their plane),
// positive for a surface bounding a component from outside, negative for a cavity's.
//
// Algorithm: for each surfel and each of its four corners, the configuration of the 8 voxels
// around the pointel gives (table lookup) the neighbour across the linel that enters the
// pointel, found among the sorted codes by a binary search in its row; union-find by index
// (a root is the smallest surfel of its surface) on contiguous chunks of surfels in parallel,
// then the few unions that cross chunks. O(F log(row)) time, 9 bytes per surfel. Surfaces
// are numbered in the order of their first surfel; the result does not depend on the
// number of threads. Width: counts int64; the enclosed volume is summed in int128 and fits
// int64 (it is at most the number of voxels).
#pragma once

#include <zdg/kernel/images/image.hpp>
#include <zdg/kernel/surfaces/digital_surface.hpp>
#include <zdg/kernel/surfaces/image_surfels.hpp>
#include <zdg/kernel/topology/adjacency.hpp>

#include <cstdint>
#include <vector>

namespace zdg {

/// How an adjacency pair (object k, background kbar) splits a digital boundary.
struct SurfaceConvention {
  int object = 6, background = 26;
  SurfelAdjacency linels = SurfelAdjacency::exterior; ///< interior iff k in {18, 26}
  bool object_pinches = false;     ///< k = 26: two opposite voxels of X pinch the surface
  bool background_pinches = false; ///< kbar = 26: two opposite voxels of the complement do

  /// The convention of (k, kbar) in {(6,26), (6,18), (18,6), (26,6)}; InvalidArgument
  /// naming the pair otherwise.
  static SurfaceConvention of(int k, int kbar);
  /// The convention of a 3D pair (InvalidArgument for a 2D one).
  static SurfaceConvention of(const AdjacencyPair& pair);
  /// True at a pointel of this configuration byte that the pair's analog pinches.
  bool pinched(std::uint8_t configuration) const;
};

/// One closed digital surface.
struct BoundarySurface {
  std::int64_t surfels = 0;
  std::int64_t vertices = 0; ///< (pointel, sheet) pairs
  std::int64_t euler = 0;    ///< vertices - surfels
  std::int64_t genus = 0;    ///< (2 - euler) / 2
  std::int64_t volume = 0;   ///< signed number of enclosed voxels (< 0: a cavity's boundary)
  std::int64_t first = 0;    ///< position of its first surfel in the sorted codes
};

struct ImageSurfaces {
  SurfaceConvention convention;
  std::vector<std::uint64_t> surface_of; ///< per surfel (sorted code order): its surface
  std::vector<BoundarySurface> surfaces; ///< in the order of their first surfel
  std::int64_t pinched_pointels = 0;
  /// Linels where the two passages of a surface meet the same vertices at both ends
  /// (kernel/surfaces/pointel_cycles.hpp): edges that a quad mesh sees in four faces.
  std::int64_t pinched_linels = 0;

  /// Sum of the Euler characteristics of the surfaces.
  std::int64_t euler_sum() const;
  /// chi(X) = b0 - b1 + b2 of the object under the pair: (euler_sum - 2 pinched) / 2.
  std::int64_t object_euler() const;
};

/// The closed surfaces of the boundary surfels of the image (threads: 0 = all cores).
/// `surfels` must be image_surfels(image).
ImageSurfaces image_surfaces(const Image<std::uint8_t>& image, const ImageSurfels& surfels,
                             const SurfaceConvention& convention, unsigned threads = 0);

} // namespace zdg
