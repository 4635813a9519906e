// Continued fractions of rationals.
//
//   p/q = a0 + 1/(a1 + 1/(a2 + ... + 1/an)),  a0 = floor(p/q) (any sign), ai >= 1 for i >= 1,
//   and an >= 2 when n >= 1 (the canonical expansion; Euclid's algorithm with floor division).
//   Convergents p_k/q_k: p_k = a_k p_{k-1} + p_{k-2}, q_k = a_k q_{k-1} + q_{k-2}, with
//   p_{-1}/q_{-1} = 1/0 and p_{-2}/q_{-2} = 0/1; they satisfy p_k q_{k-1} - p_{k-1} q_k =
//   (-1)^{k+1} and the last one is p/q reduced (with q > 0).
//
// Complexity: O(log min(|p|, |q|)) terms and operations (Lame), each on numbers no larger
// than max(|p|, |q|): the terms and convergents fit the input's type, except that negating
// the minimum of a machine type overflows (reported; escalate to a wider type).
// Source: Khinchin, Continued Fractions (1964); Graham, Knuth, Patashnik, Concrete
// Mathematics, 6.7.
#pragma once

#include <zdg/arith/integer.hpp>
#include <zdg/arith/rational.hpp>

#include <span>
#include <utility>
#include <vector>

namespace zdg {

/// Canonical continued fraction of p/q (q != 0, any signs; the fraction need not be reduced).
template <TowerInt I>
std::vector<I> continued_fraction(I p, I q);

/// The rational number [a0; a1, ..., an] (reduced); terms after the first must be >= 1,
/// otherwise InvalidArgument. Accepts non-canonical expansions (a last term of 1).
template <TowerInt I>
Rational<I> from_continued_fraction(std::span<const I> terms);

/// All convergents (p_k, q_k), k = 0..n, of the expansion [a0; a1, ..., an].
template <TowerInt I>
std::vector<std::pair<I, I>> convergents(std::span<const I> terms);

} // namespace zdg
