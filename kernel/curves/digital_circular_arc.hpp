// Digital circular arcs (DCA): recognition by circular separability, and the tangential cover
// of a contour by maximal digital circular arcs.
//
// Definition (Coeurjolly, Gerard, Reveilles, Tougne 2004; Roussillon, Sivignon, Tougne 2010;
// DGtal's StabbingCircleComputer). Given inner points P_0 .. P_{m-1} and outer points
// Q_0 .. Q_{k-1} of Z^2, the part is a digital circular arc when some Euclidean circle
// STRICTLY separates them: every P_i strictly on one side and every Q_j strictly on the other
// (no point on the circle), either the inner points inside and the outer ones outside (a
// convex part of a counter-clockwise contour) or the reverse (a concave part); straight lines
// count as circles of infinite radius. For a contour of linels (kernel/curves/digital_contour.hpp),
// the pair of linel l is P_l = inner_pixel, Q_l = outer_pixel (the pixel centres on either
// side of the linel), as in Roussillon and Lachaud 2011.
//
// Exact test. Lift p to u(p) = (x^2 + y^2, x, y, 1). A circle or line
//     f(p) = d (x^2 + y^2) + a x + b y + c = 0
// strictly separates when f(P_i) > 0 > f(Q_j), i.e. w = (d, a, b, c) satisfies w.u(P_i) > 0
// and w.(-u(Q_j)) > 0: a homogeneous system of strict linear inequalities in R^4, feasible
// exactly when the closed system w.v >= 1 (v = u(P_i) or -u(Q_j)) is (scale w). d < 0: the
// inner points inside the circle of centre -(a, b) / 2d (curvature > 0); d > 0: outside
// (curvature < 0); d = 0: a line. It is solved exactly by Seidel's randomized incremental
// algorithm for linear feasibility (keep a feasible point; when constraint i cuts it off,
// a feasible point exists iff one exists on the hyperplane v_i.w = 1: recurse there with the
// earlier constraints), with fraction-free (Bareiss) elimination so that the rows at depth k
// are (k + 1) x (k + 1) minors of the lifted points and the right-hand side. The order is a
// fixed pseudo-random one: results are deterministic.
//
// Tangential cover. For pairs (P_l, Q_l), l = 0 .. n-1 (open or closed sequence), a maximal
// arc is a run l = i .. j (indices modulo n when closed) that is a DCA while neither run
// i-1 .. j nor i .. j+1 is. The cover lists all of them, ordered by their first pair (both
// ends then increase strictly), computed by the two-pointer sweep of kernel/curves/maximal_segments
// (extend the front while recognizable, retract the back otherwise); on a closed sequence it
// starts with the maximal arc through pair 0 found by extending backwards first, and a whole
// closed sequence that is one DCA (a digital circle) gives one arc of length n. The sweep keeps
// the last separating circle as a witness: a pair that it separates is added in O(1), any other
// triggers one exact solve over the current run; when the front cannot be extended, the new back
// is found by bisection (sub-runs of a DCA are DCA), and the constraints that shaped the last
// solve go first in the next one (move-to-front).
//
// Each result carries a separating circle, in global coordinates, exact (BigInt): any circle
// of the (open) set of separating circles; its signed curvature -2d / sqrt(a^2 + b^2 - 4dc)
// (in grid units, 1/radius; > 0 when the inner points are inside, 0 for a line) is what the
// MDCA estimator reads (estimators/mdca_curvature.hpp).
//
// Complexity: one recognition costs O(m) per pass of the recursion, O(m) expected in Seidel's
// analysis (which assumes an objective with a unique optimum; this feasibility variant keeps any
// feasible point, so that bound is heuristic here, the answer exact either way: on the
// untranslated accelerated flower (20, 5, 5) at h = 0.003, about 100 solves do O(m^2) work and
// the cover takes 40-51 s, against 5-9 s for a translated digitization); the cover costs
// O(n) witness checks plus O(L) per solve, one solve each time the witness fails and
// O(log L) per new maximal arc (arcs of length L). Measured: 1.8-2.3 s for the 278,372 linels
// of the flower (20, 7, 6) at h = 0.001 (3,528 arcs of mean length 584; 41,656 solves). Width:
// the lifted points are taken in a local frame (origin at the first inner point of the run), so
// coordinates span the run's extent e and the rows are minors of entries <= 2 e^2, e, 1: Int64
// serves runs of extent below about 2^10, Int128 about 2^25; f<I> throws OverflowError past its
// type and f_exact escalates Int64 -> Int128 -> BigInt (arith/escalate.hpp), so every int64
// input is handled exactly. A cover on a wider type still solves each run of extent below 2^9
// on Int64 (the same exact steps, so the same circles), as most runs of a contour are short.
// Sources: D. Coeurjolly, Y. Gerard, J.-P. Reveilles, L. Tougne, An elementary algorithm for
// digital arc segmentation, Discrete Applied Math. 139, 2004; T. Roussillon, I. Sivignon,
// L. Tougne, On three constrained versions of the digital circular arc recognition problem,
// DGCI 2009; T. Roussillon, J.-O. Lachaud, Accurate curvature estimation along digital
// contours with maximal digital circular arcs, IWCIA 2011, LNCS 6636; R. Seidel, Small-
// dimensional linear programming and convex hulls made easy, DCG 6, 1991.
#pragma once

#include <zdg/arith/escalate.hpp>
#include <zdg/arith/integer.hpp>
#include <zdg/arith/point.hpp>
#include <zdg/kernel/curves/digital_contour.hpp>
#include <zdg/kernel/images/box.hpp>

#include <cstddef>
#include <optional>
#include <span>
#include <vector>

namespace zdg {

/// The circle (or line) d (x^2 + y^2) + a x + b y + c = 0 in global coordinates: positive on the
/// inner points, negative on the outer points.
struct SeparatingCircle {
  BigInt d, a, b, c;
  /// Signed curvature in grid units: -2d / sqrt(a^2 + b^2 - 4dc) (1/radius, > 0 when the inner
  /// points are inside the circle, < 0 when outside, 0 for a line).
  double curvature() const;
  /// The value d |p|^2 + a p.x + b p.y + c (exact).
  BigInt value(const Pixel& p) const;
  /// True when value > 0 on every inner point and < 0 on every outer point.
  bool separates(std::span<const Pixel> inner, std::span<const Pixel> outer) const;
  friend bool operator==(const SeparatingCircle&, const SeparatingCircle&) = default;
};

/// A separating circle of the inner and outer points (a witness that the part is a digital
/// circular arc), or nullopt when none exists; computed on I (may throw OverflowError).
/// Throws InvalidArgument when either list is empty.
template <TowerInt I>
std::optional<SeparatingCircle> is_digital_circular_arc(std::span<const Pixel> inner,
                                                        std::span<const Pixel> outer);
/// The same, exact by escalation, with the type that served.
Escalated<std::optional<SeparatingCircle>>
is_digital_circular_arc_exact(std::span<const Pixel> inner, std::span<const Pixel> outer);

struct MaximalArc {
  std::size_t begin = 0, end = 0; // inclusive pair indices; end < begin when a closed run wraps
  std::size_t length = 0;         // number of pairs
  SeparatingCircle circle;        // separates the run's inner from its outer points
  double curvature = 0;           // circle.curvature(), grid units
};

/// The tangential cover of the pair sequence by maximal digital circular arcs, computed on I
/// (may throw OverflowError). Throws InvalidArgument when the sequences are empty or of
/// different lengths, or when a pair is not two 4-adjacent pixels (a linel's two sides).
template <TowerInt I>
std::vector<MaximalArc> maximal_circular_arcs(std::span<const Pixel> inner,
                                              std::span<const Pixel> outer, bool closed);
/// The same, exact by escalation, with the type that served.
Escalated<std::vector<MaximalArc>> maximal_circular_arcs_exact(std::span<const Pixel> inner,
                                                               std::span<const Pixel> outer,
                                                               bool closed);

/// The inner and outer pixels of the linels of a contour, in contour order.
struct LinelPairs {
  std::vector<Pixel> inner, outer;
};
LinelPairs linel_pairs(const DigitalContour& contour);

} // namespace zdg
