// Plane-probing normal estimation: the H- and R-algorithms on a digital plane.
//
//   Given a predicate InPlane(x) on Z^3 and a starting point o, a plane-probing algorithm
//   deforms a tetrahedron (q - m_0, q - m_1, q - m_2; q), q = o + m_0 + m_1 + m_2, whose base
//   triangle is in the set and whose apex q is not, asking InPlane as locally as possible,
//   until one face is parallel to the set; its normal (m_1 - m_0) x (m_2 - m_0) is the
//   estimate. On the standard plane P(N) = {x : 0 <= N . x < ||N||_1} of a primitive N with
//   positive components, started at o = 0 with m = (e_x, e_y, e_z), both algorithms return N
//   exactly, the R-algorithm with a reduced basis of the plane's lattice (Lachaud, Provencal,
//   Roussillon, "Two plane-probing algorithms for the computation of the normal vector to a
//   digital plane", JMIV 59, 2017; Lachaud, Meyron, Roussillon, "An optimized framework for
//   plane-probing algorithms", JMIV 62, 2020).
//
// One step: the candidates are the points q - m_s0 + m_s1 + lambda m_s2 for the six
//   permutations s of (0, 1, 2): lambda = 0 only (H: a hexagon around q), or for the
//   R-algorithm the point of each ray {lambda >= 0} that is in the set and closest in the
//   sense below (found by an exponential then a quaternary search along the ray, the R1
//   optimisation of JMIV 2020). When the in-set hexagon points are one, or two or three that
//   are neither opposite nor separated by exactly one out-of-set point ("planar" state), the
//   closest candidate x replaces the vertex q - m_s0 (m_s0 <- m_s0 - m_s1 - lambda m_s2);
//   otherwise (no candidate, or a "non-convex"/"non-planar" hexagon) the algorithm stops.
//   Closest: x beats y unless y lies strictly inside the sphere through the triangle and x
//   (an exact 5 x 5 in-sphere determinant, oriented by the 4 x 4 orientation determinant);
//   on the sphere the lexicographically smaller relative point wins (the tie rule of
//   DGtal's PlaneProbingNeighborhood, so step counts compare with DGtal's).
//
// Complexity: each step lowers sum_k N.m_k (from ||N||_1, staying >= 3) by at least 1, so
//   H makes at most ||N||_1 - 3 steps of 6 predicate calls; R makes O(log) calls per ray and
//   far fewer steps on typical normals (about 200 for random 70-bit components, 575 for
//   140-bit ones), but not logarithmically many in general: (2^35 + 1, -(2^35/3 + 7), 12345)
//   takes 9.3e5 steps, and normals close to a multiple of a small vector, such as
//   (2^64 + 1, 2^64 + 3, 2^65 + 1), take minutes (measured). Each step is O(1) exact
//   arithmetic.
// Width: the in-sphere determinant is of degree 5 in the frame's coordinates, which are at
//   most ||N||_1 (H can build long frames) and near sqrt(||N||) for the reduced frames of R:
//   Int64 serves ||N||_1 < 2^11 for sure and R on random normals up to about 2^25, Int128 up
//   to about 2^50 (measured: 70-bit normals already need Int128). probe_standard_plane<I>
//   throws OverflowError past I; probe_standard_plane_exact escalates Int64 -> Int128 ->
//   BigInt.
// Input (probe_standard_plane): a primitive normal with three nonzero components of any
//   signs (the octant is brought to the positive one by reflecting the axes, and the result
//   reflected back); InvalidArgument otherwise, or when max_steps steps do not end it.
#pragma once

#include <zdg/arith/escalate.hpp>
#include <zdg/arith/integer.hpp>
#include <zdg/arith/point.hpp>

#include <array>
#include <cstdint>
#include <string_view>

namespace zdg {

enum class ProbingAlgorithm { h, r };

constexpr std::string_view to_string(ProbingAlgorithm a) {
  return a == ProbingAlgorithm::h ? "h" : "r";
}

template <TowerInt I>
struct PlaneProbingResult {
  Point3<I> normal{};               // (m_1 - m_0) x (m_2 - m_0) at the end
  std::array<Point3<I>, 3> frame{}; // m_0, m_1, m_2 at the end
  Point3<I> apex{};                 // q
  std::uint64_t steps = 0;          // tetrahedron updates
  std::uint64_t predicate_calls = 0;
  bool reduced_basis = false; // the two shortest of m_1 - m_0, m_2 - m_1, m_0 - m_2 are
                              // Lagrange-Gauss reduced
};

/// Probes the standard plane {x : 0 <= N . x < ||N||_1} from the origin (computed on I).
template <TowerInt I>
PlaneProbingResult<I> probe_standard_plane(const Point3<I>& normal, ProbingAlgorithm algorithm,
                                           std::uint64_t max_steps = 100'000'000);

/// The same for normals of any size, exact by escalation (results as BigInt).
template <TowerInt I>
Escalated<PlaneProbingResult<BigInt>>
probe_standard_plane_exact(const Point3<I>& normal, ProbingAlgorithm algorithm,
                           std::uint64_t max_steps = 100'000'000);

} // namespace zdg
