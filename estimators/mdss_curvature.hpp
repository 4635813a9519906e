// Curvature from maximal DSS (MDSS): the osculating circle through a point and the far ends
// of its two half-tangents.
//
// At p_i, the forward half-tangent is the longest DSS starting at p_i, the backward one the
// longest ending at p_i; their far ends p_f and p_b are read off the pencil of maximal
// segments (kernel/curves/maximal_segments.hpp). The curvature is the signed inverse radius of the
// circle through p_b, p_i, p_f (Menger curvature), divided by h:
//     kappa = 2 cross(p_i - p_b, p_f - p_i) / (|p_i - p_b| |p_f - p_i| |p_f - p_b|) / h,
// positive where the curve turns left (convex parts of a counter-clockwise contour).
// This estimator is NOT multigrid convergent (the half-tangents grow like h^{-1/2} while
// their sagitta stays about one pixel): it is the negative control of the 2D experiments.
// Complexity O(n + sum |S_j|). Width: int64 coordinates, double geometry.
// Source: Coeurjolly, Miguet, Tougne, Discrete curvature based on osculating circle
// estimation, IWVF 2001, LNCS 2059.
#pragma once

#include <zdg/arith/point.hpp>

#include <cstdint>
#include <span>
#include <vector>

namespace zdg {

/// MDSS curvature at every point of a closed curve, at step h (h > 0).
std::vector<double> mdss_curvature(std::span<const Point2<std::int64_t>> points, double h);

} // namespace zdg
