// Moments of a digital set X in digital balls: for a centre c and the ball
// B = { o in Z^3 : |o|^2 <= r2 }, the exact integers
//   m0 = #{ o in B : c + o in X },  m1 = sum o,  m2 = sum o o^T  (xx yy zz xy xz yz),
// coordinates relative to the centre (voxel units). These are the integral invariants of
// Coeurjolly, Lachaud, Levallois (CVIU 2014) before scaling by h (estimators/ii_3d.hpp).
//
// Algorithm (ball_moments_by_columns): B is a union of column segments |t| <= w(u, v) =
// floor(sqrt(r2 - u^2 - v^2)); the runs of X along z (kernel/images/column_runs.hpp) meet them
// in intervals [lo, hi] whose moments are closed forms (count, sum t, sum t^2 = (P(hi) -
// P(lo - 1))/6, P(m) = m (m + 1)(2m + 1)). Cost: O(#runs in the columns of the disc), about pi r2
// column operations per centre, plus one predicate evaluation per voxel of the blocks within
// reach. Vectorized forms (AVX-512F or AVX2, r <= 100, second order) give the same integers as
// the portable loop and the brute force (derivation: docs/NOTES.md, "estimators/ball_moments.hpp").
//
// Integer width: column arithmetic in int32 (|t| <= r <= 256: every term below 2^31), sums
// of a line of the disc in int32 when r <= 100 (every term below 2 r (r+1)(2r+1) in
// absolute value, 2r + 1 of them: any partial sum below 2 r (r+1)(2r+1)^2 < 2^31) and
// int64 beyond, totals in int64 (below (2r+3)^3 (r+1)^2 < 2^48 for r <= 256).
// Requirements: 0 <= r2 <= 256^2, the box checked (check_voxel_box), centres within
// kMaxVoxelCoordinate - 264; the predicate callable from several threads at once. Voxels
// outside the box are outside X.
#pragma once

#include <zdg/kernel/surfaces/digital_surface.hpp>

#include <array>
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace zdg {

/// Exact moments of the inside voxels of a digital ball, coordinates relative to its centre
/// (voxel units): m0 = count, m1 = sums of x, y, z, m2 = sums of xx, yy, zz, xy, xz, yz.
struct BallMoments {
  std::int64_t m0 = 0;
  std::array<std::int64_t, 3> m1{};
  std::array<std::int64_t, 6> m2{};
  friend bool operator==(const BallMoments&, const BallMoments&) = default;
};

/// The moments of { o : |o|^2 <= r2, centre + o in box and inside } by brute force,
/// O(r^3). The oracle of the fast counters.
BallMoments direct_ball_moments(const VoxelPredicate& inside, const VoxelBox& box,
                                const Voxel& centre, std::int64_t r2);

/// Work done by ball_moments_by_columns.
struct ColumnMomentsStats {
  std::size_t centres = 0;
  std::size_t segments = 0;       ///< column segments of the balls (pi r2 per centre)
  std::size_t layer_segments = 0; ///< segments intersected with a second or later run
  std::size_t evaluations = 0;    ///< predicate evaluations (voxels of the needed blocks)
  std::size_t region_voxels = 0;  ///< voxels of the bounding box of the balls
  int layers = 0;                 ///< most runs in one column
  int simd_lanes = 0;             ///< 16: the AVX-512 form computed the sums, 8: AVX2, 0: portable
};

struct ColumnMoments {
  std::vector<BallMoments> moments; ///< one per centre, in the given order
  ColumnMomentsStats stats;
};

/// The moments of X in the ball of squared radius r2 around every centre, by column runs
/// (above). threads: 0 = hardware concurrency. With second_order false only m0 is computed
/// (m1, m2 are left zero). The second-order sums of radius <= 100 run hand-vectorized on CPUs
/// with AVX-512F (16 columns per step) or AVX2 (8), same integers.
ColumnMoments ball_moments_by_columns(const VoxelPredicate& inside, const VoxelBox& box,
                                      std::span<const Voxel> centres, std::int64_t r2,
                                      unsigned threads = 0, bool second_order = true);

namespace detail {
/// ball_moments_by_columns with vectorized forms of at most max_lanes lanes (16: AVX-512 or
/// AVX2, 8: AVX2 at most, 0: the portable loop), for tests that compare them.
ColumnMoments ball_moments_by_columns(const VoxelPredicate& inside, const VoxelBox& box,
                                      std::span<const Voxel> centres, std::int64_t r2,
                                      unsigned threads, bool second_order, int max_lanes);
/// The lanes of the widest vectorized form this CPU runs (16, 8 or 0).
int ball_moments_simd_lanes();
} // namespace detail

} // namespace zdg
