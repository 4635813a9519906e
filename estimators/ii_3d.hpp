// Integral-invariant curvature estimators on the boundary surfels of a digitized 3D shape
// (Coeurjolly, Lachaud, Levallois, "Multigrid convergent principal curvature estimators in
// digital geometry", CVIU 2014; Pottmann et al. 2007 for the expansions). With X_h the
// digitization at step h and B the digital ball of radius R/h (offsets o in Z^3 with
// |o|^2 <= floor((R/h)^2)):
//   volume   V = h^3 #(B(x) intersected with X_h)       H  = 8/(3R) - 4V/(pi R^4)
//   moments  m_pqs = h^{3+p+q+s} sum x^p y^q z^s over B(x) and X_h, J = covariance matrix
//            [m_200 m_110 m_101; ...] - m_1 m_1^T / m_000, eigenvalues l1 >= l2 >= l3 with
//            eigenvectors v1, v2, v3:
//            k1 = 6/(pi R^6) (l2 - 3 l1) + 8/(5R),  k2 = 6/(pi R^6) (l1 - 3 l2) + 8/(5R),
//            so k1 <= k2; principal directions v1 (of k1), v2 (of k2); normal v3.
// Each estimate at a surfel averages the kernels centred at its inner and at its outer voxel,
// as DGtal's implementation behind the paper's experiments does (DigitalSurfaceConvolver,
// lambda = 1/2): H from the average of the two counts, the principal curvatures and
// directions from the average of the two covariance matrices (each about its own
// centroid). Rates: O(h^{1/3}) for H, k1, k2 with R = k h^{1/3}; O(h^{2/3}) for the normal
// (CVIU 2014, Thm 6; Lachaud-Coeurjolly-Levallois 2017).
//
// Counting: ii_surfel_moments counts the ball at every distinct inner/outer voxel from the
// column runs of the set (estimators/ball_moments.hpp): about pi r^2 column operations per
// voxel, r = R/h, plus one predicate evaluation per voxel of the blocks within reach of a
// ball. ii_surfel_moments_incremental is the previous counter, kept as a second oracle and
// for comparison: the distinct voxels are ordered along a greedy walk (the next voxel is the
// unvisited one nearest in l1 distance among the 3-neighbourhood, else the next one in
// lexicographic order), cut into chunks, 8 per thread; a chunk starts with one full count of
// the ball, then follows the walk by unit moves (moving the ball by +-e_a removes one voxel
// per row of the ball along a and adds one: 2 pi r^2 predicate look-ups per move, cached in a
// byte block over the bounding box of the centres grown by r, shared by the threads when it
// takes at most 512 MiB, else one block per chunk of at most 128 MiB). Both give the same
// integers (tested, with the brute-force count).
//
// Integer width: counts and moments are exact int64, relative to the ball centre; with
// r <= 256 (checked at entry, InvalidArgument past it) every sum is below (2r+3)^3 (r+1)^2
// < 2^48, and the covariance numerators m0 m2 - m1 m1^T use int128_t.
#pragma once

#include <zdg/estimators/ball_moments.hpp>
#include <zdg/kernel/surfaces/digital_surface.hpp>

#include <array>
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace zdg {

/// The kernels of one surfel: centred at its inner and at its outer voxel.
struct SurfelBallMoments {
  BallMoments inner, outer;
};

/// Work done by the counters (for benchmarks and tests).
struct IIStats {
  std::size_t voxels = 0;                ///< distinct kernel centres
  std::size_t predicate_evaluations = 0; ///< voxels whose membership was evaluated
  // column counter (ii_surfel_moments)
  std::size_t segments = 0; ///< column segments of the balls (pi r^2 per centre)
  int layers = 0;           ///< most runs of the set in one column
  // incremental walk (ii_surfel_moments_incremental)
  std::size_t full_counts = 0; ///< balls counted from scratch (one per chunk and long jump)
  std::size_t unit_moves = 0;  ///< incremental moves by one voxel
  std::size_t chunks = 0;
  bool shared_cache = false; ///< one cache for all threads, else one per chunk
};

struct IISurfelMoments {
  std::vector<SurfelBallMoments> moments; ///< one per surfel, in the given order
  IIStats stats;
};

namespace detail {
/// ii_surfel_moments_incremental with the size limit of the shared predicate cache (bytes)
/// exposed, so that tests reach the per-chunk caches too.
IISurfelMoments ii_surfel_moments_incremental(const VoxelPredicate& inside, const VoxelBox& box,
                                              std::span<const Surfel> surfels, std::int64_t r2,
                                              unsigned threads, bool second_order,
                                              std::size_t shared_cache_bytes);
} // namespace detail

/// floor((R/h)^2): the squared radius of the digital ball in voxel units. Throws
/// InvalidArgument unless R > 0, h > 0 and R/h <= 256.
std::int64_t ii_digital_radius2(double R, double h);

/// Ball moments at the inner and outer voxels of every surfel, from the column runs of the
/// set (estimators/ball_moments.hpp), in parallel (threads >= 1, 0 = hardware concurrency).
/// With second_order false only m0 is computed (m1, m2 are left zero). Voxels outside the
/// box count as outside. The predicate must be callable from several threads at once.
IISurfelMoments ii_surfel_moments(const VoxelPredicate& inside, const VoxelBox& box,
                                  std::span<const Surfel> surfels, std::int64_t r2,
                                  unsigned threads = 0, bool second_order = true);

/// The same integers by the incremental walk (the previous counter, 2 pi r^2 look-ups per
/// unit move; see above).
IISurfelMoments ii_surfel_moments_incremental(const VoxelPredicate& inside, const VoxelBox& box,
                                              std::span<const Surfel> surfels, std::int64_t r2,
                                              unsigned threads = 0, bool second_order = true);

/// II mean curvature at every surfel (H = 1/r on a sphere of radius r).
std::vector<double> ii_mean_curvature(const VoxelPredicate& inside, const VoxelBox& box,
                                      std::span<const Surfel> surfels, double h, double R,
                                      unsigned threads = 0);

/// II principal curvatures, directions and normal at one surfel.
struct IIPrincipalCurvatures {
  double k1 = 0, k2 = 0; ///< k1 <= k2
  Point3<double> d1, d2; ///< unit principal directions of k1 and k2
  Point3<double> normal; ///< unit, outward (positive dot with the trivial normal)
  double mean() const { return 0.5 * (k1 + k2); }
  double gaussian() const { return k1 * k2; }
};

/// II principal curvatures at every surfel. (d1, d2, normal) is a direct orthonormal frame
/// (the sign of d1 is that of the eigenvector: a direction, not an orientation).
std::vector<IIPrincipalCurvatures>
ii_principal_curvatures(const VoxelPredicate& inside, const VoxelBox& box,
                        std::span<const Surfel> surfels, double h, double R, unsigned threads = 0);

/// The formulas alone, from the moments of one surfel (for drivers that keep the moments):
/// H from the averaged count, and the principal curvatures from the average of the
/// covariance matrices of the two kernels (the moments must have been computed with
/// second_order = true: InvalidArgument otherwise).
double ii_mean_curvature_from_moments(const SurfelBallMoments& m, double h, double R);
IIPrincipalCurvatures ii_principal_curvatures_from_moments(const SurfelBallMoments& m,
                                                           const Surfel& s, double h, double R);

} // namespace zdg
