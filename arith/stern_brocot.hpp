// The Stern-Brocot tree of the positive rationals.
//
// Every reduced p/q > 0 is the mediant (a+c)/(b+d) of exactly two fractions a/b < p/q < c/d
// with c b - a d = 1, its left and right parents (0/1 and 1/0 for 1/1). The path from the
// root 1/1 spells L (go to smaller) and R (go to larger): with p/q = [a0; a1, ..., an] it is
// R^a0 L^a1 R^a2 ... with the last exponent decreased by one, so depth(p/q) = a0+...+an - 1.
// One parent is the convergent p_{n-1}/q_{n-1} (the right one when n is even), the other is
// (p - p_{n-1}) / (q - q_{n-1}).
//
// Complexity: O(log max(p, q)) through the continued fraction; the path as a string is
// O(depth) (can be huge: use stern_brocot_path_runs). Width: the input's type.
// Source: Graham, Knuth, Patashnik, Concrete Mathematics, 4.5; Stern (1858), Brocot (1861).
#pragma once

#include <zdg/arith/integer.hpp>

#include <string>
#include <utility>
#include <vector>

namespace zdg {

template <TowerInt I>
struct Fraction {
  I p, q;
  friend bool operator==(const Fraction&, const Fraction&) = default;
};

template <TowerInt I>
struct SternBrocotParents {
  Fraction<I> left, right; // left < p/q < right, p/q their mediant
};

/// (a+c)/(b+d); not reduced in general (it is for Stern-Brocot neighbours).
template <TowerInt I>
Fraction<I> mediant(const Fraction<I>& x, const Fraction<I>& y) {
  return {x.p + y.p, x.q + y.q};
}

/// Parents of p/q; p > 0, q > 0, gcd(p, q) = 1, else InvalidArgument.
template <TowerInt I>
SternBrocotParents<I> stern_brocot_parents(const I& p, const I& q);

/// Depth of p/q in the tree (1/1 has depth 0); same domain.
template <TowerInt I>
I stern_brocot_depth(const I& p, const I& q);

/// Path from 1/1 as runs (letter 'L' or 'R', length >= 1); same domain.
template <TowerInt I>
std::vector<std::pair<char, I>> stern_brocot_path_runs(const I& p, const I& q);

/// Path from 1/1 as a string of L and R (empty for 1/1); InvalidArgument when it would be
/// longer than max_length letters.
template <TowerInt I>
std::string stern_brocot_path(const I& p, const I& q, std::size_t max_length = 1u << 26);

/// The fraction at the end of a path of L and R from 1/1; InvalidArgument for other letters.
template <TowerInt I>
Fraction<I> stern_brocot_follow(const std::string& path);

} // namespace zdg
