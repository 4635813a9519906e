// Sturmian words of quadratic irrational slopes, exact.
//
// A quadratic surd x = (P + sqrt D) / Q (D > 0 not a square, Q != 0, Q divides D - P^2; every
// (a + b sqrt d) / c with b != 0 is brought to this form by make_surd) has an eventually periodic
// continued fraction (Lagrange, 1770): x = [a_0; a_1, ..., a_{r-1}, (b_1, ..., b_m)]. The terms
// come from the complete quotients x_k = (P_k + sqrt D) / Q_k: a_k = floor(x_k), computed in
// integers (floor((P + s) / Q) for Q > 0, floor((P + s + 1) / Q) for Q < 0, s = floor(sqrt D)),
// P_{k+1} = a_k Q_k - P_k, Q_{k+1} = (D - P_{k+1}^2) / Q_k (exact division); the expansion is
// periodic from the first repeated pair (P_k, Q_k). Reference: Perron, "Die Lehre von den
// Kettenbruechen", 1913, ch. III; Cohen, "A Course in Computational Algebraic Number Theory",
// 1993, section 5.7. The preperiod and period have at most O(sqrt(D) log D) terms; max_terms
// bounds the work (InvalidArgument past it).
//
// The characteristic (Sturmian) word of a slope alpha in (0, 1) irrational: c_alpha = s_1 s_2
// ..., s_n = floor((n + 1) alpha) - floor(n alpha) in {0, 1} (the density of the letter 1 is
// alpha). It is the limit of the standard words of the continued fraction alpha = [0; d_1, d_2,
// ...]: t_{-1} = "1", t_0 = "0", t_1 = t_0^(d_1 - 1) t_{-1}, t_n = t_{n-1}^(d_n) t_{n-2}; each t_n
// (n >= 1) is a prefix of t_{n+1}, hence of c_alpha (Lothaire,
// "Algebraic Combinatorics on Words", 2002, ch. 2, Prop. 2.2.24; Berstel, Lauve, Reutenauer,
// Saliola, "Combinatorics on Words: Christoffel Words and Repetitions in Words", 2008). With
// zdg's Christoffel convention (the lower word of slope p/q has q letters 0 and p letters 1), the
// Christoffel convergents of alpha are the lower words of slopes p_n / (q_n - p_n) for the
// convergents p_n / q_n of alpha: 0 w 1 with w a prefix of c_alpha (the central words).
// c_alpha is balanced (two factors of one length differ by at most one letter 1) and has n + 1
// factors of each length n (Morse, Hedlund, "Symbolic dynamics II. Sturmian trajectories",
// 1940).
//
// Integer width: f<I> computes on I and throws OverflowError when an intermediate leaves I (D
// grows by c^2 in make_surd; floor(n x) needs n^2 D); the _exact forms escalate Int64 -> Int128
// -> BigInt.
#pragma once

#include <zdg/arith/escalate.hpp>
#include <zdg/arith/integer.hpp>

#include <cstddef>
#include <string>
#include <utility>
#include <vector>

namespace zdg {

/// (P + sqrt D) / Q with D > 0 not a square, Q != 0 and Q | D - P^2.
template <TowerInt I>
struct QuadraticSurd {
  I P, D, Q;
  /// "(P + sqrt(D))/Q".
  std::string str() const;
};

/// (a + b sqrt d) / c as a quadratic surd: b != 0, c != 0, d > 0 and not a perfect square,
/// else InvalidArgument. Multiplies through by |c| when c does not divide b^2 d - a^2.
template <TowerInt I>
QuadraticSurd<I> make_surd(const I& a, const I& b, const I& d, const I& c);

/// floor(sqrt(n)) for n >= 0 (InvalidArgument for n < 0).
template <TowerInt I>
I isqrt(const I& n);

/// floor(k x) for an integer k (exact: isqrt of k^2 D).
template <TowerInt I>
I floor_multiple(const QuadraticSurd<I>& x, const I& k);

/// x - floor(x) = (P - floor(x) Q + sqrt D) / Q, in (0, 1).
template <TowerInt I>
QuadraticSurd<I> fractional_part(const QuadraticSurd<I>& x);

/// The eventually periodic expansion [preperiod; (period)].
template <TowerInt I>
struct PeriodicContinuedFraction {
  std::vector<I> preperiod; // a_0 .. a_{r-1}
  std::vector<I> period;    // b_1 .. b_m (m >= 1)
  /// The k-th term (k >= 0).
  const I& term(std::size_t k) const {
    return k < preperiod.size() ? preperiod[k] : period[(k - preperiod.size()) % period.size()];
  }
};

/// The continued fraction of x; InvalidArgument when the preperiod and the period together need
/// more than max_terms terms.
template <TowerInt I>
PeriodicContinuedFraction<I> periodic_continued_fraction(const QuadraticSurd<I>& x,
                                                         std::size_t max_terms = 1000000);
Escalated<PeriodicContinuedFraction<BigInt>>
periodic_continued_fraction_exact(const BigInt& a, const BigInt& b, const BigInt& d,
                                  const BigInt& c, std::size_t max_terms = 1000000);

/// The first n letters of the characteristic word of alpha in (0, 1), from the definition
/// floor((k + 1) alpha) - floor(k alpha) (exact: one isqrt per letter). InvalidArgument when
/// alpha is not in (0, 1).
template <TowerInt I>
std::string characteristic_word(const QuadraticSurd<I>& alpha, std::size_t n);

/// The first n letters of the characteristic word of alpha in (0, 1) from the standard words of
/// its continued fraction [0; d_1, d_2, ...] (linear time in n). InvalidArgument when the
/// expansion does not start with 0 (alpha not in (0, 1)).
template <TowerInt I>
std::string standard_word_prefix(const PeriodicContinuedFraction<I>& alpha, std::size_t n);

/// The convergents p_k / q_k (k = 0 .. count-1) of the expansion.
template <TowerInt I>
std::vector<std::pair<I, I>> surd_convergents(const PeriodicContinuedFraction<I>& cf,
                                              std::size_t count);

} // namespace zdg
