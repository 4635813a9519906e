// The boundary of a binary 3D image split into closed digital surfaces under an adjacency
// pair, with the Euler characteristic and genus of each surface and of the object.
//
// Pairs (6,26), (6,18), (18,6), (26,6): boundary surfels sharing a linel are adjacent as the
// bel-adjacency of kernel/surfaces/digital_surface.hpp pairs them (EXTERIOR for a 6-connected
// object, INTERIOR for 18 or 26); each surfel has four neighbours, so the boundary splits into
// closed surfaces. With one vertex per sheet at each pointel (kernel/surfaces/pointel_cycles.hpp)
// each is a closed oriented 2-manifold: chi = V - F, genus = (2 - chi) / 2. The object:
// sum_S chi(S) = 2 (b0 - b1 + b2) + 2 (pinched pointels), exact for the four pairs (derivation:
// docs/NOTES.md, "kernel/surfaces/image_surfaces.hpp"). Enclosed volume: the signed number of
// voxels enclosed (divergence theorem), negative for a cavity.
// Algorithm: corner configurations by table lookup, union-find on parallel chunks, O(F log(row))
// time, 9 bytes per surfel; surfaces numbered by first surfel, independent of the thread count.
// Width: counts int64, the enclosed volume summed in int128 (it fits int64).
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
