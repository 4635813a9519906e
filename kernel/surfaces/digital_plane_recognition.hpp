// Recognition of naive digital plane segments: is a finite S of Z^3 inside a naive plane?
//
//   S is a naive digital plane segment when there are a primitive N in Z^3 and mu in Z with
//       mu <= N . x < mu + omega   for every x in S,   omega = ||N||_inf,
//   i.e. the arithmetic width max N.S - min N.S is at most ||N||_inf - 1 (Reveilles 1991;
//   Debled-Rennesson 1995). recognize_naive_plane answers with such (N, mu, omega) or says
//   that none exists.
//
// Theorem used (the chord formulation of Gerard, Debled-Rennesson, Zimmermann, "An
//   elementary digital plane recognition algorithm", Discrete Applied Math. 151, 2005): let
//   D = S - S be the set of chords (it is symmetric and contains 0). S is a naive plane
//   segment if and only if some unit vector e_k (k = x, y or z) lies outside conv(D).
//   Proof. If N, mu exist, let k be an axis with |N_k| = ||N||_inf and s the sign of N_k:
//   (sN) . d <= ||N||_inf - 1 < (sN) . e_k for every chord d (D is symmetric), so the plane
//   (sN) . y = ||N||_inf - 1/2 separates e_k from conv(D). Conversely if e_k is not in the
//   polytope conv(D), a facet of it, of primitive outward normal n and offset h = max n.D,
//   has n . e_k > h, i.e. n_k >= h + 1 (integers): the width of S along n is h <= n_k - 1 <=
//   ||n||_inf - 1, and N = n, mu = min n.S certify S.
// Algorithm: the vertices V of conv(S) (kernel/hulls/lattice_hull_3d.hpp), the chords V - V (the
//   polytope conv(S - S) = conv(V - V)), their hull, and a scan of its facets against e_x,
//   e_y, e_z. Among the certifying facets the one of least ||n||_inf (then ||n||_1, then
//   lexicographic) is returned, so the answer does not depend on the order of the points.
//   A set that spans no volume (coplanar points) is a plane segment: its plane's normal
//   (or, for collinear points, the least primitive normal orthogonal to the line) with
//   width 0.
// Complexity: O(n log n) for conv(S) (typical Quickhull), then O(v^2 log v) for the chords
//   of its v vertices (v = O(m^{2/3}) for a digital plane piece over an m x m window:
//   Andrews' bound on lattice polytopes).
// Width: chords have coordinates below 2^(b+1) for |coordinates| < 2^b, the hull predicates
//   of the chords need 3b + 9 bits: Int64 serves |coordinates| < 2^17 for sure;
//   recognize_naive_plane<I> throws OverflowError past I, recognize_naive_plane_exact
//   escalates Int64 -> Int128 -> BigInt.
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
