// Binomial convolver tangent and curvature (Esbelin, Malgouyres, Cartade, "Convergence of
// binomial-based derivative estimation for C2 noisy discretized curves", TCS 2011).
//
// The pointels p_0..p_{N-1} of a closed contour (step h) are smoothed by the binomial
// kernel of order n, H_n(j) = binom(n, j) / 2^n, j = 0..n, centred. With the smoothed steps
// T(k) = sum_j H_n(j) (p_{k+j-n/2+1} - p_{k+j-n/2}), the derivatives at pointel k are
// D1 = (T(k) + T(k-1)) / 2 and D2 = T(k) - T(k-1) (differences of the binomially smoothed
// curve); tangent = D1 / |D1|, curvature = (D1 x D2) / (h |D1|^3).
//
// Mask law n = k h^{-a}: the error is O(h^{min(2 - a, a/2)}) for tangents and O(h^{min(2 - a,
// a - 1)}) for curvatures; a = 4/3 gives tangents O(h^{2/3}), a = 14/9 (the driver's curvature
// default) curvatures O(h^{4/9}) (Malgouyres, Brunet, Fourey, DGCI 2008; derivation and
// measured slopes: papers/cviu2014-comparison-2d/README.md).
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
