// Length of a digital curve from its greedy DSS segmentation.
//
// The curve (closed 4-connected contour of pointels, or an open 4/8-connected path) is cut
// into longest digital straight segments from p_0 on (kernel/curves/maximal_segments.hpp,
// greedy_segmentation); the estimate is h times the length of the polygon through the
// segment ends: L = h sum_k |p_{e_k} - p_{b_k}|.
// Exact on a digitized straight segment (one DSS: the distance between its ends) and on
// lattice polygons whose edges the segmentation finds; O(h) on convex polygons.
// Complexity O(n). Width: int64 coordinates (the recognizer escalates internally).
// Source: Klette and Rosenfeld, Digital Geometry (2004), 10.3; Coeurjolly and Klette,
// A comparative evaluation of length estimators of digital curves, IEEE TPAMI 26(2), 2004.
#pragma once

#include <zdg/arith/point.hpp>

#include <cstdint>
#include <span>

namespace zdg {

/// DSS length of the curve at step h (h > 0; InvalidArgument otherwise).
double dss_length(std::span<const Point2<std::int64_t>> points, bool closed, double h);

} // namespace zdg
