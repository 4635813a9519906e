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
// Algorithms (Stern-Brocot reasoning, lemmas: docs/NOTES.md, "arith/dsl_subsegment.hpp"):
// - subsegment_reversed_smart_dss (the front-end's): ReversedSmartDSS, the bottom-up climb
//   from a/b towards the root, one division per run: O(log b) whatever x1 - x0;
// - subsegment_smart_dss: top-down SmartDSS with run jumps, O(log min(x1 - x0, b));
// - subsegment_top_down_search, subsegment_bottom_up: cross-check oracles with floor-sum
//   feasibility tests (arith/floor_sum.hpp), O(log^3 b) floor sums, slower on long windows.
// Width: both climbs handle numbers of about 4 b and products of about 2 b^2 (the mu of the
// answer; SmartDSS's thresholds q R and b q stay below b^2); the searches' floor sums reach
// about b^3. The _exact front-end escalates Int64 -> Int128 -> BigInt on overflow.
// Sources: Said and Lachaud, DGCI 2011, LNCS 6607 (ReversedSmartDSS); Said, Lachaud, Feschet,
// DGCI 2009 (SmartDSS); Lachaud and Said, Discrete Applied Mathematics 161 (2013);
// Debled-Rennesson and Reveilles 1995 (minimality; the SmartDSS update).
#pragma once

#include <zdg/arith/escalate.hpp>
#include <zdg/arith/integer.hpp>

namespace zdg {

template <TowerInt I>
struct DslSubsegment {
  I a, b, mu;
  friend bool operator==(const DslSubsegment&, const DslSubsegment&) = default;
};

/// All require b > 0, 0 <= a < b and x0 <= x1 (InvalidArgument otherwise).
template <TowerInt I>
DslSubsegment<I> subsegment_reversed_smart_dss(const I& a, const I& b, const I& mu, const I& x0,
                                               const I& x1);

/// SmartDSS with run jumps (top-down): same answer as the reversed climb.
template <TowerInt I>
DslSubsegment<I> subsegment_smart_dss(const I& a, const I& b, const I& mu, const I& x0,
                                      const I& x1);

/// Oracle: top-down search with floor-sum feasibility tests (polylog, grows with x1 - x0).
template <TowerInt I>
DslSubsegment<I> subsegment_top_down_search(const I& a, const I& b, const I& mu, const I& x0,
                                            const I& x1);

/// Oracle: bottom-up search with floor-sum feasibility tests.
template <TowerInt I>
DslSubsegment<I> subsegment_bottom_up(const I& a, const I& b, const I& mu, const I& x0,
                                      const I& x1);

enum class DslSubsegmentAlgorithm { reversed_smart_dss, smart_dss };

/// The reversed climb (default) or SmartDSS on arbitrary-size values, on the narrowest tower
/// type that serves.
Escalated<DslSubsegment<BigInt>>
dsl_subsegment_exact(const BigInt& a, const BigInt& b, const BigInt& mu, const BigInt& x0,
                     const BigInt& x1,
                     DslSubsegmentAlgorithm algorithm = DslSubsegmentAlgorithm::reversed_smart_dss);

} // namespace zdg
