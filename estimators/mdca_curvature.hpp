// Curvature from maximal digital circular arcs (MDCA).
//
// Along a closed contour of linels, the tangential cover by maximal digital circular arcs
// (kernel/curves/digital_circular_arc.hpp: maximal runs of linels whose inner and outer pixels some
// circle strictly separates) is computed; at each linel l the estimate is the signed
// curvature of the separating circle of the MOST CENTRED maximal arc covering l (the arc
// i .. j that maximizes min(l - i, j - l); ties go to the first arc of the cover), divided by
// the grid step h:
//     kappa(l) = -2d / sqrt(a^2 + b^2 - 4dc) / h    for the circle d |p|^2 + a x + b y + c = 0,
// positive where the inner pixels are inside the circle (convex parts of a counter-clockwise
// contour: the sign convention of the other 2D estimators), negative on concave parts, zero
// on straight parts. This is the estimator of Roussillon and Lachaud (IWCIA 2011), the most
// centred arc as in DGtal's MostCenteredMaximalSegmentEstimator with CurvatureFromDCAEstimator;
// the circle is the one the exact recognizer returns (any circle of the separating set: the
// paper and DGtal also take one element of that set, and for long arcs the set is thin).
// Multigrid convergence: no rate proven under the hypotheses of the registry; the authors
// report experimental convergence (papers/THEORY.md).
// Complexity: the cover (kernel/curves/digital_circular_arc.hpp) plus O(sum of arc lengths).
// Width: exact integer recognition by escalation (int64 coordinates), double curvature.
#pragma once

#include <zdg/kernel/curves/digital_contour.hpp>

#include <vector>

namespace zdg {

/// MDCA curvature at every linel of a closed contour (in contour order), at step h (h > 0).
/// Throws InvalidArgument for h <= 0 or a contour of fewer than 4 linels.
std::vector<double> mdca_curvature(const DigitalContour& contour, double h);

} // namespace zdg
