// floor_sum(n, m, a, b) = sum_{i=0}^{n-1} floor((a i + b) / m), the number of lattice points
// under a line segment, in O(log m) steps.
//
// Reduction: with a = qa m + ra and b = qb m + rb (floor division, 0 <= ra, rb < m) the sum is
// qa n(n-1)/2 + qb n + S(n, m, ra, rb), and for 0 <= a, b < m the points under the line are
// counted by exchanging the axes: S(n, m, a, b) = S(y, a, m, (a n + b) mod m) with
// y = floor((a n + b) / m) -- a Euclid-like descent on (m, a).
// Domain: n >= 0, m != 0 (m < 0 is folded into the signs), any sign of a and b.
// Width: intermediates reach about a n + b and the result about a n^2 / (2 m); a checked
// type reports overflow, and floor_sum_exact escalates Int64 -> Int128 -> BigInt.
// Source: the "floor sum" of competitive programming (AtCoder Library, floor_sum), a form
// of the classical reciprocity of Dedekind-like sums; Knuth TAOCP vol. 1, 1.2.4 ex. 37.
#pragma once

#include <zdg/arith/escalate.hpp>
#include <zdg/arith/integer.hpp>

namespace zdg {

template <TowerInt I>
I floor_sum(I n, I m, I a, I b);

/// floor_sum on arbitrary-size inputs, computed on the narrowest tower type that holds
/// every intermediate; says which one served.
Escalated<BigInt> floor_sum_exact(const BigInt& n, const BigInt& m, const BigInt& a,
                                  const BigInt& b);

} // namespace zdg
