// Plane-probing normal estimation on the boundary surfels of a digitized 3D shape (Lachaud,
// Provencal, Roussillon, "Two plane-probing algorithms for the computation of the normal
// vector to a digital plane", JMIV 59, 2017; Lachaud, Meyron, Roussillon, "An optimized
// framework for plane-probing algorithms", JMIV 62, 2020; DGtal's
// PlaneProbingDigitalSurfaceLocalEstimator for the use on digital surfaces).
//
// At a surfel s (inner voxel I in X, outer voxel O = I + sigma e_a not in X; X the digitized
// set, voxels outside the box are outside) the H- or R-algorithm of
// kernel/surfaces/plane_probing.hpp runs with the predicate "x is in the inner 26-boundary of X" (x
// in X with a 26-neighbour not in X) from a tetrahedron built on s. On a digital half-space {N . x
// < c} the inner 26-boundary is the standard plane {c - ||N||_1 <= N . x < c} (the pointels of the
// surface, which DGtal's estimator probes, form such a plane too), and the runs from the start
// below are those on the solid (same steps; kernel test); on a curved solid it keeps the rays of R
// near the surface instead of letting them cross the interior.
// The start is built on s with the solid X:
//   octant: for each choice of signs (s_b, s_c) of the two tangent axes, the frame
//     u_a = sigma e_a, u_b = s_b e_b, u_c = s_c e_c (the octant of the trivial normal sigma e_a
//     with the tangent signs), and
//   apex: starting at q = O (outside), while some q - u_k (k = a, b, c in that order) is
//     outside, q <- q - u_k (q stays outside and goes down the octant), at most 256 moves;
//     the octant is usable when the walk ends with every q - u_k in X, i.e. (q - u_0, q - u_1,
//     q - u_2; q) is a valid initial tetrahedron (base triangle in X, apex out).
//   The usable octant with the shortest walk is taken (the first of (+,+), (+,-), (-,+), (-,-)
//   on a tie), then o = q - u_0 - u_1 - u_2 and the frame (u_x, u_y, u_z) in axis order.
//   sheared (only when no octant is usable): the same walk in the frames u_a = sigma e_a,
//   u_b = u_a + s_b e_b, u_c = u_a + s_c e_c (unimodular like the octants); the shortest walk
//   is taken, on a tie the frame whose signs (s_b, s_c) agree with the tangent components of
//   a local normal (from the moment of X about the inner voxel in its 5 x 5 x 5 block: the
//   normal points away from where X extends; a rule that commutes with the 48 symmetries),
//   then the order above. Where none starts either (the surfel's axis nearly orthogonal to
//   the normal: a riser of the staircase), the sheared frames around the other two axes a'
//   with a nonzero local normal component, u_a' along its sign, the larger component first.
// Why this start: on a digital half-space {x : N . x < c} with N primitive and three nonzero
// components, only the octant of N can end the walk (in any other one, q - u_k climbs), and
// the walk ends at an apex with c <= N . q < c + min |N_k|. When N . q = c (always when some
// |N_k| = 1) the run is the run on the standard plane of normal N from its lowest layer
// (kernel/surfaces/plane_probing.hpp) and the estimate is N exactly, at every surfel whose probes
// stay inside the box; from a higher apex it need not be (JMIV 2020 starts the tetrahedron on the
// lowest layer, or uses its parallelepiped variant to start anywhere: not done here).
// When a tangent component of N is zero or small, no octant walk ends (q - u_b stays at the
// height of q: on a curved surface the walk slides along the outermost layer until the
// component changes sign); N . (u_a + s_b e_b) = |N_a| + s_b N_b is positive for both signs
// whenever |N_b| < |N_a|, so a sheared frame starts there. In the sheared frame's coordinates
// the run is a plane-probing run on the plane of normal M^T N (M the frame), with positive
// components: the same guarantees, relative to that frame.
// DGtal picks the octant from a maximal-segment pre-estimation and probes the pointels of the
// surface.
// Measured on digital balls of radius 10, 15, 30 voxels (H and R alike): the octants alone
// leave 51%, 43%, 30% of the surfels to the trivial normal (the sides of the flat caps), for a
// mean angle to the radial direction of 0.37, 0.32, 0.22 rad (at most 1.5); with the sheared
// frames every surfel is probed, mean 0.20, 0.17, 0.12 rad, at most 0.77, 0.73, 0.74 rad
// (the octant-started ones stay within 0.35 rad).
// The normal is the final (m_1 - m_0) x (m_2 - m_0), oriented out of X (its dot product with
// every final m_k is 1), normalised. When no octant and no sheared frame is usable (thin
// parts, the box) or the probing does not end within max_steps, the surfel gets its trivial
// normal sigma e_a and counts as a fallback.
//
// Theory: exact on digital planes (above); no convergence rate is proven on curved surfaces
// (JMIV 2020 studies the planes; the estimates are local and parameter-free, their error does
// not vanish as h -> 0 in general).
// Complexity: per surfel at most 8 walks of 256 moves (3 predicate calls each) and 125 calls
// for the local normal, then the probing (H: at most ||N||_1 steps of 6 calls; R: O(log) calls
// per ray). Width: Int64, each surfel re-run on Int128 when checked arithmetic overflows (far
// rays of R on large sets).
#pragma once

#include <zdg/kernel/surfaces/digital_surface.hpp>
#include <zdg/kernel/surfaces/plane_probing.hpp>

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace zdg {

/// The plane-probing estimate at one surfel.
struct SurfelProbe {
  Point3<double> normal;        ///< unit, outward
  Point3<std::int64_t> exact{}; ///< the integer normal (zero for a fallback)
  bool probed = false;          ///< false: no usable start, the trivial normal
  bool sheared = false;         ///< probed from a sheared frame (no octant was usable)
  std::uint64_t steps = 0;      ///< tetrahedron updates
  std::uint64_t predicate_calls = 0;
};

/// The estimate at the boundary surfel s of {z in box : inside(z)}.
SurfelProbe probing_surfel_normal(const VoxelPredicate& inside, const VoxelBox& box,
                                  const Surfel& s, ProbingAlgorithm algorithm,
                                  std::uint64_t max_steps = 1'000'000);

/// The estimates at every surfel (in order), on `threads` threads (0: hardware concurrency);
/// the predicate must be callable from several threads at once.
std::vector<SurfelProbe> probing_normals(const VoxelPredicate& inside, const VoxelBox& box,
                                         std::span<const Surfel> surfels,
                                         ProbingAlgorithm algorithm, unsigned threads = 0);

} // namespace zdg
