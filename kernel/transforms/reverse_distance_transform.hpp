// Reverse distance transform: the union of open l_p balls, exact.
//
// Input: an image v of ball values (v(c) > 0: the open ball B(c) = { y : d_p(c, y)^p < v(c) },
// v the radius to the power p, squared for l_2). Output: the indicator (0/1) of the union of
// the balls. With this convention the reverse transform of a distance transform rebuilds the
// shape exactly: y is covered iff min_c (d_p(c, y)^p - v(c)) < 0, the sign of the power map
// (Coeurjolly and Montanvert, IEEE PAMI 29(3), 2007).
//
// Cost, width, torus and thread behaviour: those of kernel/transforms/power_map.hpp. For l_inf
// (cubes d_inf < v) the sign of the power is not separable; the union is read from the largest
// covering cube instead (kernel/transforms/linf_covering.hpp, O(N d)).
// Negative values: InvalidArgument; an image without any ball gives the empty set.
#pragma once

#include <zdg/kernel/images/image.hpp>
#include <zdg/kernel/transforms/lp_metric.hpp>

#include <cstdint>

namespace zdg {

Image<std::uint8_t> reverse_distance_transform(const Image<std::int64_t>& values,
                                               const TransformOptions& opt = {});
/// The same on values read in place (no copy): dom.size() values in C order.
Image<std::uint8_t> reverse_distance_transform(const Domain& dom, const std::int64_t* values,
                                               const TransformOptions& opt = {});

} // namespace zdg
