// Subsegment of a digital straight line: the minimal characteristics of
//
//   S = { (x, y) : mu <= a x - b y < mu + b,  x0 <= x <= x1 },   0 <= a < b
//
// (the naive line of slope a/b, one point per abscissa), i.e. the DSL of smallest period that
// contains S, oriented towards increasing x (b' > 0, 0 <= a' <= b'), with mu' tight (S has an
// upper leaning point a' x - b' y = mu' and a lower one); equal to what the DSS recognizer
// (arith/dss_recognizer.hpp) finds on the enumerated points. One point gives (0, 1, -y).
// (a, b) need not be coprime: the line is reduced first (a/g, b/g, ceil(mu/g)).
//
// Mathematics. The slopes of the real lines that digitize to S form an open interval
// (alpha_min, alpha_max) (the preimage's projection), and S lies in a naive DSL of slope p/q iff
// p/q is in it; the minimal slope is the simplest fraction of the interval, which is an
// ancestor of a/b in the Stern-Brocot tree (every fraction of an interval descends from its
// simplest one). Along the path of a/b, the nodes of one run (a maximal block of moves in one
// direction) approach a/b monotonically, so feasibility is monotone inside a run; and when
// p/q is not minimal, one of its two Stern-Brocot parents is feasible.
//
// Two searches over that tree, cross-checked in the tests:
// - subsegment_top_down: descends from the root (0/1, then 1/1, then the runs of the
//   continued fraction of a/b), binary search inside each run for the first feasible node
//   (the search order of Said and Lachaud's SmartDSS);
// - subsegment_bottom_up: climbs from a/b, jumping to the other parent of a run when it is
//   feasible and else binary searching up the run (the search order of ReversedSmartDSS).
// The feasibility test is our own, not the papers' pattern arithmetic: the remainders
// g(x) = p x - q y(x) over S have min g found by a binary search on m of "some point has
// g < m", each decided exactly with two floor sums (arith/floor_sum.hpp) on the side of the
// crossing of the two real lines where the difference of the floors has a constant sign.
//
// Complexity: O(log b) runs, O(log b) feasibility tests per run in the worst case, each
// O(log b) floor sums of O(log b) steps: polylogarithmic, independent of x1 - x0 (a window of
// more than 2b points is answered at once: it holds two periods). Width: intermediates of the
// floor sums reach about b^3; the _exact front-end escalates Int64 -> Int128 -> BigInt.
// Sources: Said and Lachaud, Computing the characteristics of a subsegment of a digital
// straight line in logarithmic time, DGCI 2011, LNCS 6607; Said, Lachaud, Feschet,
// Multiscale discrete geometry, DGCI 2009; Debled-Rennesson and Reveilles 1995 (minimality).
#pragma once

#include "arith/escalate.hpp"
#include "arith/integer.hpp"

namespace zdg {

template <TowerInt I>
struct DslSubsegment {
  I a, b, mu;
  friend bool operator==(const DslSubsegment&, const DslSubsegment&) = default;
};

/// Requires b > 0, 0 <= a < b and x0 <= x1 (InvalidArgument otherwise).
template <TowerInt I>
DslSubsegment<I> subsegment_top_down(const I& a, const I& b, const I& mu, const I& x0, const I& x1);

template <TowerInt I>
DslSubsegment<I> subsegment_bottom_up(const I& a, const I& b, const I& mu, const I& x0,
                                      const I& x1);

template <TowerInt I>
DslSubsegment<I> subsegment_reversed_smart_dss(const I& a, const I& b, const I& mu, const I& x0,
                                               const I& x1);

/// Top-down search on arbitrary-size values, on the narrowest tower type that serves.
Escalated<DslSubsegment<BigInt>> dsl_subsegment_exact(const BigInt& a, const BigInt& b,
                                                      const BigInt& mu, const BigInt& x0,
                                                      const BigInt& x1);

} // namespace zdg
