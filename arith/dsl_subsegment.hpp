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
// subsegment_reversed_smart_dss (the algorithm of the front-end): the bottom-up climb of Said
// and Lachaud's ReversedSmartDSS, from a/b towards the root, moving an upper leaning point
// exactly. Let t be the current slope, with parents l < t < r (q_l + q_r = q_t), and a line of
// slope t containing S with upper leaning points U + k q_t. Lemma (proved in the .cpp): the
// line of slope l through the upper leaning point U coincides with the t-line exactly on
// [U - q_l + 1, U + q_t - 1], the line of slope r on [U - q_t + 1, U + q_r - 1]; so S fits slope
// l iff S does not hold a lower leaning point L and the upper one L + q_l, and then the
// l-line through the last U <= x0 + q_l - 1 contains S (same for r, mirrored). Along a run
// N_j = N_0 + j beta of the Stern-Brocot path whose bound beta does not fit, every line of
// slope N_j containing S has the same upper leaning point v in S, and N_{j-1} fits iff q(N_j)
// and q(N_{j-1}) exceed fixed distances from v to the ends of S: the first fitting node of the
// run is found by one division. t is the answer iff neither parent fits. Each step leaves a
// run: O(log b) steps of O(1) operations, whatever x1 - x0.
//
// subsegment_smart_dss: the top-down SmartDSS of Said, Lachaud and Feschet, which reads the
// window from its first point and descends the Stern-Brocot path of a/b: the minimal slopes s
// of the prefixes [x0, x] are ancestors of a/b, deeper as x grows (the feasible interval
// shrinks). With s and the tight remainder of the prefix, the first point of the line that
// leaves the s-line is weakly exterior (Debled-Rennesson and Reveilles), above it when s < a/b
// and below when s > a/b; relative to the prefix's first upper (resp. lower) leaning point it
// lies in one residue class mod q(s) past one threshold: one ceiling division. The update:
// the new slope is the vector from that leaning point to the exit (which stays the first
// leaning point). Along a run of the path, each update adds the same parent: whether the next
// exit is exactly one parent further is a linear inequality in the run index, so a whole run
// is crossed in one division. Every other update turns in the tree:
// iterations <= 1 + the number of partial quotients of the answer's slope (its denominator is
// <= x1 - x0 + 1), each of O(1) divisions: O(log min(x1 - x0, b)), never more than O(log b)
// whatever the window (the paper's version walks the pattern repetitions one by one: the sum
// of the partial quotients).
//
// Two independent searches, kept as cross-check oracles (tests, benchmarks):
// - subsegment_top_down_search: descends from the root (0/1, then 1/1, then the runs of the
//   continued fraction of a/b), binary search inside each run for the first feasible node
//   (the search order of Said, Lachaud and Feschet's SmartDSS);
// - subsegment_bottom_up: climbs from a/b, jumping to the other parent of a run when it is
//   feasible and else binary searching up the run (the search order of ReversedSmartDSS).
// Their feasibility test is our own, not the papers' pattern arithmetic: the remainders
// g(x) = p x - q y(x) over S have min g found by a binary search on m of "some point has
// g < m", each decided exactly with two floor sums (arith/floor_sum.hpp) on the side of the
// crossing of the two real lines where the difference of the floors has a constant sign:
// polylogarithmic, O(log^3 b) floor sums in the worst case, and slower on long windows (deeper
// answers).
//
// Width: both climbs handle numbers of about 4 b and products of about 2 b^2 (the mu of the
// answer; SmartDSS's thresholds q R and b q stay below b^2); the searches' floor sums reach
// about b^3. The _exact front-end escalates Int64 -> Int128 -> BigInt on overflow.
//
// Sources: Said and Lachaud, Computing the characteristics of a subsegment of a digital
// straight line in logarithmic time, DGCI 2011, LNCS 6607 (ReversedSmartDSS); Said, Lachaud,
// Feschet, Multiscale discrete geometry, DGCI 2009 (SmartDSS); Lachaud and Said, Two efficient
// algorithms for computing the characteristics of a subsegment of a digital straight line,
// Discrete Applied Mathematics 161 (2013); Debled-Rennesson and Reveilles 1995 (minimality;
// the update of SmartDSS).
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
