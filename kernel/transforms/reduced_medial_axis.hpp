// Reduced discrete medial axis of a binary shape in the l_p metrics, exact.
//
// The distance transform gives every shape point c the largest open ball
// B(c) = { y : d_p(c, y)^p < DT(c) } free of background. The reduced discrete medial axis
// (Coeurjolly and Montanvert, IEEE PAMI 29(3), 2007) keeps the balls whose power cell (power
// map of all the DT balls, weights DT(c)) contains a shape point: every shape point y lies in
// the ball of the site that minimises its power (that power is <= d(y, y)^p - DT(y) < 0), so
// the kept balls cover the shape, and each lies inside it. The centres are a subset of the
// DT centres; the union of the balls is exactly the shape (tests check both).
//
// Cost: one distance transform and one power map, O(N d) (l_1, l_2), O(N d log n) otherwise;
// width chosen at entry (the weights are at most the largest DT value). For l_inf, where the
// power map is not separable, a ball is kept when it is the (deterministic) largest DT cube
// covering some shape point (kernel/transforms/linf_covering.hpp): same guarantees (DT centres,
// union = shape). No background: InvalidArgument. A value that does not fit int64 (p huge) is an
// OverflowError.
#pragma once

#include <zdg/kernel/images/image.hpp>
#include <zdg/kernel/transforms/lp_metric.hpp>

#include <cstdint>
#include <vector>

namespace zdg {

struct MedialBall {
  std::vector<std::int64_t> centre;
  /// DT(centre): the radius to the power p (squared for l_2) of the open ball.
  std::int64_t value = 0;
  friend bool operator==(const MedialBall&, const MedialBall&) = default;
};

/// The balls in increasing linear index of their centre.
std::vector<MedialBall> reduced_medial_axis(const Image<std::uint8_t>& shape,
                                            const TransformOptions& opt = {});
/// The same on a mask read in place (no copy): dom.size() items of mask_item_bytes bytes (1, 2,
/// 4 or 8) in C order, nonzero = object.
std::vector<MedialBall> reduced_medial_axis(const Domain& dom, const std::uint8_t* mask,
                                            const TransformOptions& opt = {},
                                            int mask_item_bytes = 1);

} // namespace zdg
