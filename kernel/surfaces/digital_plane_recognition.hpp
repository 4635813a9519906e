// Recognition of naive digital plane segments: is a finite S of Z^3 inside a naive plane?
//
// S is one when mu <= N . x < mu + ||N||_inf for every x in S, for some primitive N in Z^3 and
// mu in Z (Reveilles 1991; Debled-Rennesson 1995); recognize_naive_plane returns such (N, mu,
// omega = ||N||_inf) or says that none exists.
// Theorem (Gerard, Debled-Rennesson, Zimmermann, Discrete Applied Math. 151, 2005): S is one iff
// some unit vector e_k lies outside conv(S - S) (proof: docs/NOTES.md,
// "kernel/surfaces/digital_plane_recognition.hpp"). Algorithm: the hull of the chords V - V of
// the vertices V of conv(S) (kernel/hulls/lattice_hull_3d.hpp), its facets scanned against e_x,
// e_y, e_z; the certifying facet of least ||n||_inf (then ||n||_1, then lexicographic) wins, so
// the answer is order-independent; coplanar or collinear sets give width 0.
// Complexity: O(n log n) for conv(S), O(v^2 log v) for the chords of its v vertices.
// Width: chord hull predicates need 3b + 9 bits for |coordinates| < 2^b (Int64: below 2^17);
// recognize_naive_plane<I> throws OverflowError past I, _exact escalates to BigInt.
// Input: at least one point (InvalidArgument otherwise); duplicates are allowed.
#pragma once

#include <zdg/arith/escalate.hpp>
#include <zdg/arith/integer.hpp>
#include <zdg/arith/point.hpp>

#include <span>

namespace zdg {

template <TowerInt I>
struct NaivePlaneRecognition {
  bool is_plane = false;
  Point3<I> normal{}; // primitive; meaningful when is_plane
  I mu{0};            // min over S of normal . x
  I omega{0};         // ||normal||_inf
};

/// The recognition computed on I (throws OverflowError when I is too narrow).
template <TowerInt I>
NaivePlaneRecognition<I> recognize_naive_plane(std::span<const Point3<I>> points);

/// The recognition for points of any size, exact by escalation (results as BigInt).
template <TowerInt I>
Escalated<NaivePlaneRecognition<BigInt>>
recognize_naive_plane_exact(std::span<const Point3<I>> points);

} // namespace zdg
