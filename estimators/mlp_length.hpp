// Minimum length polygon (MLP) of a closed 4-connected digital contour, and the length
// estimator h * |MLP| (O(h) on convex shapes; Klette-Rosenfeld, Digital Geometry 2004;
// Provencal-Lachaud, DGCI 2009; papers/THEORY.md, "Rates").
//
// The MLP is the shortest closed polygon in the band between the polygon of the inner
// pixel centres and that of the outer pixel centres of the contour. Each linel gives a
// portal, the unit segment from its inner to its outer pixel centre; the MLP is the
// shortest closed path crossing the portals in order. It is computed by the funnel
// algorithm (string pulling, Lee-Preparata 1984) started at the lexicographically smallest
// inner pixel centre, an extreme point of the inner polygon hence a vertex of the MLP.
// The vertices are pixel centres; orientation tests are exact int64_t cross products
// (coordinates below 2^30 are checked at entry, so products fit). Cost O(n) amortized on
// smooth contours (a restart rescans back to the apex: O(n L) with L the longest MLP edge
// in linels, worst case O(n^2)).
#pragma once

#include <zdg/kernel/curves/digital_contour.hpp>

#include <vector>

namespace zdg {

/// The MLP vertices (pixel centres, in pixel coordinates), counter-clockwise, not closed.
std::vector<Pixel> minimum_length_polygon(const DigitalContour& contour);

/// h times the Euclidean length of the MLP.
double mlp_length(const DigitalContour& contour, double h);

} // namespace zdg
