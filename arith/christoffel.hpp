// Christoffel words.
//
// The lower Christoffel word of slope p/q (p >= 0, q > 0, gcd(p, q) = 1) has n = p + q letters:
// q letters 0 (the step (1,0)) and p letters 1 (the step (0,1)); it is the lattice path from
// (0,0) to (q,p) that stays below the segment and closest to it. Its prefix of length k has
// floor(k p / n) letters 1, so letter k (1-based) is floor(k p/n) - floor((k-1) p/n).
// The upper word is its reverse. For p, q > 0 the lower word is 0 w 1 with w a palindrome,
// is a Lyndon word and is balanced. Standard factorization: for n >= 2 the lower word is
// u v with u, v the lower words of the two Stern-Brocot parents of p/q (left then right;
// the word of 1/0 is "1").
//
// Complexity: O(n) letters, one addition and one comparison each; single letters and prefix
// counts in O(1). Width: n + p must fit the type (escalate otherwise); materialized words are
// limited to christoffel_max_letters. Source: Berstel, Lauve, Reutenauer, Saliola, CRM 2008.
#pragma once

#include <zdg/arith/integer.hpp>
#include <zdg/arith/stern_brocot.hpp>

#include <cstddef>
#include <string>

namespace zdg {

/// Longest word the generators materialize (letters); longer requests are InvalidArgument.
inline constexpr std::size_t christoffel_max_letters = std::size_t{1} << 30;

/// Lower Christoffel word of p/q as a string of '0' and '1'. Requires p >= 0, q > 0 and
/// gcd(p, q) = 1 (InvalidArgument otherwise; reduce first).
template <TowerInt I>
std::string lower_christoffel_word(const I& p, const I& q);

/// Upper Christoffel word (the reverse of the lower one).
template <TowerInt I>
std::string upper_christoffel_word(const I& p, const I& q);

/// Number of letters 1 in the prefix of length k (0 <= k <= p+q) of the lower word:
/// floor(k p / (p + q)).
template <TowerInt I>
I christoffel_prefix_ones(const I& p, const I& q, const I& k);

/// Letter k (1 <= k <= p+q) of the lower word, 0 or 1, without generating the word.
template <TowerInt I>
int christoffel_letter(const I& p, const I& q, const I& k);

template <TowerInt I>
struct StandardFactorization {
  std::string u, v;         // lower word = u + v
  SternBrocotParents<I> of; // u is the word of of.left, v of of.right
};

/// Standard factorization of the lower word of p/q; requires p >= 1 (the word of 0/1 is a
/// single letter) besides the domain above.
template <TowerInt I>
StandardFactorization<I> standard_factorization(const I& p, const I& q);

/// The conjugate of w by k: its rotation w[k..] + w[..k] (k taken modulo |w|).
std::string conjugate(const std::string& w, std::size_t k);

} // namespace zdg
