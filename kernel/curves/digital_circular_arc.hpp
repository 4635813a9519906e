// Digital circular arcs (DCA): recognition by circular separability, and the tangential cover
// of a contour by maximal digital circular arcs.
//
// Definition (Coeurjolly et al. 2004; DGtal's StabbingCircleComputer): inner points P_i and outer
// points Q_j form a DCA when a circle or line strictly separates them (inner inside: convex,
// or the reverse: concave). For a contour, linel l gives P_l = inner_pixel, Q_l = outer_pixel.
// Exact test: f(p) = d (x^2 + y^2) + a x + b y + c with f(P_i) > 0 > f(Q_j), a linear
// feasibility problem in R^4 solved by Seidel's randomized incremental algorithm (fixed order:
// deterministic) with fraction-free Bareiss elimination. Cover: the maximal arcs, ordered by
// first pair, by a two-pointer sweep keeping the last circle as a witness; a whole closed
// sequence that is one DCA gives one arc. Each arc carries an exact (BigInt) separating circle,
// whose curvature MDCA reads (derivations: docs/NOTES.md,
// "kernel/curves/digital_circular_arc.hpp").
//
// Complexity: a recognition is O(m) expected per Seidel (heuristic for this feasibility
// variant; exact either way); the cover costs O(n) witness checks plus O(L) per solve and
// O(log L) per maximal arc of length L (measurements: bench/README.md). Width: lifted points in
// a local frame, rows are minors of entries <= 2 e^2 for a run of extent e: Int64 serves e below
// about 2^10, Int128 about 2^25; f<I> throws OverflowError past its type, f_exact escalates
// Int64 -> Int128 -> BigInt (arith/escalate.hpp); a wider cover still solves short runs on Int64.
// Sources: Coeurjolly, Gerard, Reveilles, Tougne, Discrete Applied Math. 139, 2004; Roussillon,
// Sivignon, Tougne, DGCI 2009; Roussillon, Lachaud, IWCIA 2011, LNCS 6636; Seidel, DCG 6, 1991.
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
