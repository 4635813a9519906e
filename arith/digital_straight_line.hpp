// Digital straight lines (DSL), naive and standard, in every octant.
//
//   D(a, b, mu, omega) = { (x, y) in Z^2 : mu <= a x - b y < mu + omega },  gcd(a, b) = 1,
//   omega = max(|a|, |b|)  (naive, 8-connected)   or   |a| + |b|  (standard, 4-connected).
//
// r(x, y) = a x - b y is the remainder; points with r = mu are the upper leaning points and
// points with r = mu + omega - 1 the lower leaning points. The DSL is the digitization of the
// lines a x - b y = mu .. mu + omega - 1; it is oriented by its direction vector (b, a): the
// iteration goes from a point to the next one in the direction (b, a). (-a, -b, -mu-omega+1)
// is the same set of points, oriented the other way.
//
// Steps. A DSL is a path that uses two elementary steps s0, s1 (one per point), chosen so that
// r(s0) - r(s1) = omega: naive lines use the axis step closest to (b, a) and the diagonal step,
// standard lines the two axis steps (sign(b), 0) and (0, sign(a)) (sign 0 counted as +).
// From a point with remainder r the next point is p + s0 when r + r(s0) < mu + omega, else
// p + s1. The shift s0 - s1 adds omega to the remainder.
//
// Christoffel words. Read from an upper leaning point, one period (omega steps) of the DSL,
// with s0 written 0 and s1 written 1, is the lower Christoffel word of slope p/q where
// p = r(s0) >= 0 and q = -r(s1) >= 0 (p + q = omega; the word of 1/0 is "1"). In the first
// quadrant this is the Christoffel word of a/b for a standard line, and of a/(b-a) for a naive
// line of the first octant (0 <= a < b): the other octants follow by the symmetries of the
// square, which permute the steps.
//
// Complexity: every query is O(1) arithmetic except the leaning points (extended gcd,
// O(log max(|a|, |b|))) and the iteration (O(1) per point). Width: remainders need the width
// of |a| |x| + |b| |y|; the tower types report an overflow (escalate to a wider type).
// Source: Reveilles, Geometrie discrete, calcul en nombres entiers et algorithmique (1991);
// Debled-Rennesson and Reveilles, IJPRAI 9(4), 1995; Berstel et al., Christoffel words (2008).
#pragma once

#include <zdg/arith/integer.hpp>
#include <zdg/arith/point.hpp>

#include <cstddef>
#include <ostream>
#include <string>
#include <utility>
#include <vector>

namespace zdg {

enum class DslKind { naive, standard };

/// An elementary step: a vector with coordinates in {-1, 0, 1}.
struct Step {
  int x = 0, y = 0;
  friend bool operator==(const Step&, const Step&) = default;
};

/// Closed integer interval [lo, hi] (empty when lo > hi).
template <TowerInt I>
struct IntRange {
  I lo, hi;
  bool empty() const { return lo > hi; }
};

template <TowerInt I>
class DigitalStraightLine {
public:
  using Point = Point2<I>;

  /// Requires (a, b) != (0, 0) and gcd(a, b) = 1; InvalidArgument otherwise.
  DigitalStraightLine(I a, I b, I mu, DslKind kind = DslKind::naive);

  const I& a() const { return a_; }
  const I& b() const { return b_; }
  const I& mu() const { return mu_; }
  const I& omega() const { return omega_; }
  DslKind kind() const { return kind_; }

  I remainder(const Point& p) const { return a_ * p.x - b_ * p.y; }
  bool contains(const Point& p) const {
    I r = remainder(p);
    return r >= mu_ && r < mu_ + omega_;
  }
  bool is_upper_leaning(const Point& p) const { return remainder(p) == mu_; }
  bool is_lower_leaning(const Point& p) const { return remainder(p) == mu_ + omega_ - 1; }

  /// The two steps s0, s1 (r(s0) - r(s1) = omega) and the shift s0 - s1.
  Step step0() const { return s0_; }
  Step step1() const { return s1_; }
  Step shift() const { return {s0_.x - s1_.x, s0_.y - s1_.y}; }

  /// The ordinates y with (x, y) in the line; requires b != 0 (InvalidArgument).
  IntRange<I> ordinates_at(const I& x) const;
  /// The abscissas x with (x, y) in the line; requires a != 0 (InvalidArgument).
  IntRange<I> abscissas_at(const I& y) const;
  /// The unique point of abscissa x: naive line with |a| <= |b| (InvalidArgument otherwise).
  Point point_at_abscissa(const I& x) const;
  /// The unique point of ordinate y: naive line with |a| >= |b| (InvalidArgument otherwise).
  Point point_at_ordinate(const I& y) const;

  /// The point after p (p must be in the line; InvalidArgument otherwise).
  Point next(const Point& p) const;
  /// count points from start (in the line) on, in the direction (b, a).
  std::vector<Point> points(const Point& start, std::size_t count) const;

  /// The leaning point with remainder r in {mu, mu + omega - 1} and 0 <= x < |b| (b != 0), or
  /// y = 0 (b = 0).
  Point upper_leaning_point() const { return point_with_remainder(mu_); }
  Point lower_leaning_point() const { return point_with_remainder(mu_ + omega_ - 1); }
  /// A point with a x - b y = r: 0 <= x < |b| when b != 0, else y = 0.
  Point point_with_remainder(const I& r) const;

  /// One period read from the upper leaning point: s0 -> '0', s1 -> '1'; it equals
  /// lower_christoffel_word(r(s0), -r(s1)) (see the header comment). Periods longer than 2^30
  /// letters: InvalidArgument.
  std::string period_word() const;

  friend bool operator==(const DigitalStraightLine&, const DigitalStraightLine&) = default;

private:
  I a_, b_, mu_, omega_;
  DslKind kind_;
  Step s0_, s1_;
  I r0_, r1_; // remainders of the steps
};

/// The steps (s0, s1) of a line of direction (b, a) (no gcd or range check; used by the
/// recognizers too).
template <TowerInt I>
std::pair<Step, Step> dsl_steps(const I& a, const I& b, DslKind kind);

extern template class DigitalStraightLine<Int64>;
extern template class DigitalStraightLine<Int128>;
extern template class DigitalStraightLine<BigInt>;

} // namespace zdg
