// Digital moments up to order 2: S_pq = sum over z in G_h(X) of z.x^p z.y^q, and the
// estimate m_pq(X) ~ h^{2+p+q} S_pq (Coeurjolly-Lachaud-Roussillon 2012: O(h) for
// C^3 piecewise strictly convex shapes).
//
// Computed from the contours without visiting pixels: each row of the set is a union of
// intervals [a, b] bounded by vertical linels, and sum_{x=a}^{b} x^p = F_p(b+1) - F_p(a)
// with F_0(x) = x, F_1(x) = x(x-1)/2, F_2(x) = (x-1)x(2x-1)/6; a linel going up ends an
// interval, one going down starts one. O(contour length). Exact: digital_moments<I> computes
// on the tower type I (OverflowError past it: the second moments of a set of diameter D need
// about 3 log2 D bits); digital_moments_exact escalates Int64 -> Int128 -> BigInt.
#pragma once

#include <zdg/arith/escalate.hpp>
#include <zdg/arith/integer.hpp>
#include <zdg/kernel/curves/digital_contour.hpp>

#include <array>
#include <vector>

namespace zdg {

/// S_00, S_10, S_01, S_20, S_11, S_02 computed on I (may throw OverflowError).
template <TowerInt I>
std::array<I, 6> digital_moments(const std::vector<DigitalContour>& contours);
/// The same, exact by escalation, as BigInt with the type that served.
Escalated<std::array<BigInt, 6>> digital_moments_exact(const std::vector<DigitalContour>& contours);

/// h^{2+p+q} S_pq in the same order.
std::array<double, 6> moments_estimate(const std::vector<DigitalContour>& contours, double h);

} // namespace zdg
