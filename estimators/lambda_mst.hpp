// lambda-MST: tangent (and length) of a digital curve from its maximal segments.
//
// Every point p_i lies in a pencil of maximal segments S_j (kernel/curves/maximal_segments.hpp);
// with e_j in [0, 1] the eccentricity of p_i in S_j (its index along S_j divided by
// |S_j| - 1) and theta_j the direction of S_j, the tangent direction at p_i is
//     theta_i = sum_j lambda(e_j) theta_j / sum_j lambda(e_j),
// lambda(t) = 64 (-t^6 + 3 t^5 - 3 t^4 + t^3), a C^2 bump vanishing at both ends of a
// segment (angles are averaged relative to one member of the pencil, so no wrap-around).
// A point that is an end of every segment of its pencil gets the plain mean.
// Length: each linel (unit step s from p_i to p_{i+1}) contributes h |t . s| with t the
// normalised mean of the tangents at its two ends (exact for straight lines: the steps
// project onto the line direction).
// Rates (papers/THEORY.md): tangent O(h^{1/3}) proven for C^3 convex curves, about h^{2/3}
// observed; length O(h^{1/3}) proven, about h^{4/3} observed.
// Complexity O(n + sum |S_j|) = O(n) on digitized smooth curves (bounded pencils).
// Source: Lachaud, Vialard, de Vieilleville, Fast, accurate and convergent tangent
// estimation on digital contours, Image Vis. Comput. 25(10), 2007.
#pragma once

#include <zdg/arith/point.hpp>

#include <cstdint>
#include <span>
#include <vector>

namespace zdg {

/// lambda(t) = 64 (-t^6 + 3 t^5 - 3 t^4 + t^3) on [0, 1].
double lambda_mst_weight(double t);

/// Unit tangent at every point, oriented along the curve.
std::vector<Point2<double>> lambda_mst_tangents(std::span<const Point2<std::int64_t>> points,
                                                bool closed);

/// Length of a closed 4-connected contour at step h from its lambda-MST tangents.
double lambda_mst_length(std::span<const Point2<std::int64_t>> points, double h);

} // namespace zdg
