// Discrete power map of weighted sites in the l_p metrics (p finite), exact.
//
// Sites are the points c with weight w(c) > 0. The power of x with respect to c is
// pow(x, c) = d_p(x, c)^p - w(c) (for l_2, w the squared radius: the classical power
// distance); the power map gives, for every point x, a site minimising pow(x, .), and the
// minimal power. The transform is separable because pow is a sum over the axes plus a term
// of c alone (Coeurjolly and Montanvert, "Optimal separable algorithms to compute the
// reverse Euclidean distance transformation and discrete medial axis in arbitrary
// dimension", IEEE PAMI 29(3), 2007, for l_2; the same sweep holds for every finite p).
// l_inf is rejected: max_k |x_k - c_k| - w(c) does not split over the axes.
//
// Cost O(N d) (l_1, l_2), O(N d log n) otherwise; ties go to the smaller coordinate axis by
// axis; torus axes are periodic. Width chosen at entry from the extents and the largest
// weight (int32, int64, __int128, GMP). No site at all: InvalidArgument; negative weights:
// InvalidArgument.
#pragma once

#include <zdg/arith/integer.hpp>
#include <zdg/kernel/images/image.hpp>
#include <zdg/kernel/transforms/lp_metric.hpp>

#include <cstdint>
#include <vector>

namespace zdg {

struct PowerMap {
  Domain domain;
  /// site[i]: linear index of a site minimising the power of point i.
  std::vector<std::int64_t> site;
  /// negative[i]: the minimal power is < 0 (i lies in the open ball of its site).
  std::vector<std::uint8_t> negative;
};

PowerMap power_map(const Image<std::int64_t>& weights, const TransformOptions& opt = {});
/// The same on weights read in place (no copy): dom.size() values in C order.
PowerMap power_map(const Domain& dom, const std::int64_t* weights,
                   const TransformOptions& opt = {});

namespace detail {
/// Throws for l_inf (the power map is not separable there).
void require_finite_p(const TransformOptions& opt, const char* what);
/// Checks weights >= 0 and returns the largest; InvalidArgument when no weight is > 0.
std::int64_t check_weights(const Image<std::int64_t>& weights);
std::int64_t check_weights(const Domain& dom, const std::int64_t* weights);
} // namespace detail

} // namespace zdg
