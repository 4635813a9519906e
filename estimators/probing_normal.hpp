// Plane-probing normal estimation on the boundary surfels of a digitized 3D shape (Lachaud,
// Provencal, Roussillon, "Two plane-probing algorithms for the computation of the normal
// vector to a digital plane", JMIV 59, 2017; Lachaud, Meyron, Roussillon, "An optimized
// framework for plane-probing algorithms", JMIV 62, 2020; DGtal's
// PlaneProbingDigitalSurfaceLocalEstimator for the use on digital surfaces).
//
// At a surfel s (inner voxel I in X, outer voxel O = I + sigma e_a) the H- or R-algorithm of
// kernel/surfaces/plane_probing.hpp runs with the predicate "x is in the inner 26-boundary of X"
// (voxels outside the box are outside), from a tetrahedron whose apex is found by a walk down
// the octant of the trivial normal, else in a sheared unimodular frame (start rules and why
// they are exact on planes: docs/NOTES.md, "estimators/probing_normal.hpp"). The normal is the
// final (m_1 - m_0) x (m_2 - m_0), outward, normalised; with no usable start or past max_steps
// the surfel gets its trivial normal sigma e_a and counts as a fallback.
//
// Theory: exact on digital planes of normal N when the walk ends on the lowest layer (always
// when some |N_k| = 1); no rate on curved surfaces (papers/THEORY.md, "probing-normal").
// Complexity per surfel: at most 8 walks of 256 moves (3 predicate calls each), 125 calls for
// the local normal, then the probing (H: at most ||N||_1 steps of 6 calls; R: O(log) calls per
// ray). Width: Int64, the surfel re-run on Int128 when checked arithmetic overflows.
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
