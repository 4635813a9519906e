// Discrete Voronoi map of the background of a binary image in the l_p metrics, exact.
//
// For every point x, a background point s(x) (value 0) with d_p(x, s(x)) minimal, so that
// d_p(x, s(x))^p (d_inf for l_inf) equals the distance transform at x; d is periodic along
// the torus axes, and s(x) is then the representative of the site inside the domain. Among
// equidistant sites the separable sweep keeps, axis by axis, the one with the smaller
// coordinate (deterministic: the same map for every thread count).
//
// Algorithm: the distance transform's separable lower envelopes carrying the site along
// (kernel/transforms/separable_engine.hpp; Maurer et al. 2003, Breu et al. 1995), O(N d) for l_1,
// l_2, l_inf and O(N d log n) otherwise; exact integers chosen at entry as for the distance
// transform. No background: InvalidArgument.
#pragma once

#include <zdg/kernel/images/image.hpp>
#include <zdg/kernel/transforms/lp_metric.hpp>

#include <cstdint>
#include <vector>

namespace zdg {

struct VoronoiMap {
  Domain domain;
  /// site[i]: linear index (in domain) of the nearest background point of point i.
  std::vector<std::int64_t> site;

  std::vector<std::int64_t> site_point(std::int64_t i) const {
    return domain.point(site[static_cast<std::size_t>(i)]);
  }
};

VoronoiMap voronoi_map(const Image<std::uint8_t>& shape, const TransformOptions& opt = {});
/// The same on a mask read in place (no copy): dom.size() items of mask_item_bytes bytes (1, 2,
/// 4 or 8) in C order, nonzero = object.
VoronoiMap voronoi_map(const Domain& dom, const std::uint8_t* mask,
                       const TransformOptions& opt = {}, int mask_item_bytes = 1);

} // namespace zdg
