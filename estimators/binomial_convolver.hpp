// Binomial convolver tangent and curvature (Esbelin, Malgouyres, Cartade, "Convergence of
// binomial-based derivative estimation for C2 noisy discretized curves", TCS 2011).
//
// The pointels p_0..p_{N-1} of a closed contour (step h) are smoothed by the binomial
// kernel of order n, H_n(j) = binom(n, j) / 2^n, j = 0..n, centred. With the smoothed steps
// T(k) = sum_j H_n(j) (p_{k+j-n/2+1} - p_{k+j-n/2}), the derivatives at pointel k are
// D1 = (T(k) + T(k-1)) / 2 and D2 = T(k) - T(k-1) (differences of the binomially smoothed
// curve); tangent = D1 / |D1|, curvature = (D1 x D2) / (h |D1|^3).
//
// Mask law n = k h^{-a}. The smoothed curve has a standard deviation s ~ h sqrt(n) / 2 =
// O(h^{1 - a/2}) in arc length; smoothing biases the j-th derivative by O(s^2) and the
// digitization noise (amplitude O(h)) reaches it amplified by 1/s^j, so the error is
// O(h^{min(2 - a, a/2)}) for tangents (j = 1) and O(h^{min(2 - a, a - 1)}) for curvatures
// (j = 2). a = 4/3 balances the tangent: O(h^{2/3}) (Esbelin, Malgouyres, Cartade 2011). For
// the curvature the same mask gives only O(h^{1/3}) (measured l_inf slopes 0.32 on the ellipse
// (20, 7), h down to 4e-4); the rate O(h^{(2/3)^2}) = O(h^{4/9}) of Malgouyres, Brunet,
// Fourey (DGCI 2008) and Esbelin, Malgouyres, Cartade is reached with a = 14/9 (the mask that
// estimates a derivative from a first derivative known to O(h^{2/3}): s^2 = O(h^{4/9})), the
// default of the curvature estimator in the driver (measured slopes 0.58 with a = 13/9, 0.75
// with a = 3/2 on the same sweep).
//
// Cost: the kernel is truncated where binom(n, j)/2^n < 1e-20 (|j - n/2| > 5 sqrt(n) + 2,
// negligible against the estimator's error), so O(N sqrt(n)) flops; the weights are
// computed through lgamma to avoid overflow.
#pragma once

#include <zdg/kernel/curves/digital_contour.hpp>

#include <vector>

namespace zdg {

struct BinomialEstimates {
  std::vector<Point2<double>> tangent; // unit, per pointel
  std::vector<double> curvature;       // per pointel
};

/// Mask order for a grid step: max(2, round(k h^{-exponent})) rounded up to even
/// (exponent in (0, 2]; 4/3 for tangents).
long binomial_mask_order(double h, double k, double exponent = 4.0 / 3.0);

/// Tangent and curvature at every pointel of the contour with mask order n (even).
BinomialEstimates binomial_convolver(const DigitalContour& contour, double h, long n);

} // namespace zdg
