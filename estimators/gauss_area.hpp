// Gauss area estimator: Area(X) ~ h^2 #G_h(X).
//
// The pixel count is read off the contours of G_h(X) (outer ones counter-clockwise, holes
// clockwise) by the shoelace formula, in O(contour length): no pixel is visited. Exact
// (checked Int128 sums; OverflowError past it, far beyond any grid that fits memory).
// Convergence: O(h) for convex X, O(h^{15/11} log^{47/22}(1/h)) for C^3 strictly convex X
// (Huxley 1990); see papers/THEORY.md.
#pragma once

#include <zdg/kernel/curves/digital_contour.hpp>

#include <cstdint>
#include <vector>

namespace zdg {

/// Number of pixels enclosed by the contours (sum of their signed areas).
std::int64_t pixel_count(const std::vector<DigitalContour>& contours);

/// h^2 times the pixel count.
double gauss_area(const std::vector<DigitalContour>& contours, double h);

} // namespace zdg
