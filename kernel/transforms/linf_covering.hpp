// Largest covering l_inf ball: for values v >= 0 (v(c) > 0: the open cube
// Q(c) = { y : d_inf(c, y) < v(c) }), computes for every point y
//     R(y) = max { v(c) : y in Q(c) }   (0 when no cube covers y)
// and a centre attaining it. This replaces the power map for l_inf, where
// d_inf(y, c) - v(c) does not split over the axes, while R does: by induction over the axes,
// after the passes along axes 0..k-1, R_k(y) = max { v(c) : c agrees with y on the other
// axes, |y_j - c_j| < v(c) for the processed axes j } (the cube of the maximiser of a slice
// is admissible whenever any cube of the slice is). Each 1D pass keeps, in one sweep per
// direction, a deque of candidates in decreasing value (a candidate with both a smaller value
// and a shorter reach is dropped): O(N d). Comparisons are |y - c| < v with |y - c| < 3n: no
// overflow for any int64 v. Torus axes: three copies of the line. Used by
// reverse_distance_transform (union of the cubes: R > 0) and reduced_medial_axis for l_inf.
#pragma once

#include <zdg/kernel/images/image.hpp>
#include <zdg/kernel/transforms/lp_metric.hpp>

#include <cstdint>
#include <vector>

namespace zdg::detail {

/// In place on r (size N, values >= 0); sites (optional): the linear index of a maximiser
/// (-1 where R = 0).
void linf_covering(const Domain& dom, const TransformOptions& opt, std::vector<std::int64_t>& r,
                   std::vector<std::int64_t>* sites);

} // namespace zdg::detail
