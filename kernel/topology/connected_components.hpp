// Connected components of a binary image of Z^2 or Z^3 under any adjacency
// (kernel/topology/adjacency.hpp): labels, sizes, ranking by size, and counts of the components
// that do not touch the border of the domain (the bounded components, for the background).
//
// Phase::object: the nonzero points; Phase::background: the zeros, with the outside of the box,
// connected under every adjacency, so the background components that do not touch the border
// are exactly the bounded ones (cavities in 3D, holes in 2D). Algorithm: union-find over runs
// along the last axis (Rosenfeld and Pfaltz 1966 in run form; Wu, Otoo, Suzuki, PAA 12, 2009),
// parallel by rows and chunks: O(N) scan plus O(R alpha(R)) for R runs, memory O(R) plus the
// labels, independent of the thread count (details: docs/NOTES.md,
// "kernel/topology/connected_components.hpp"). Width: labels uint32 (OverflowError past 2^32 - 1
// components), sizes and counts int64.
#pragma once

#include <zdg/kernel/images/image.hpp>

#include <cstdint>
#include <vector>

namespace zdg {

/// Which points form the set whose components are computed.
enum class Phase { object, background };

/// How components are numbered: by decreasing size (ties: the component whose first point in
/// C order comes first), or in the C order of their first point.
enum class ComponentOrder { by_size, by_scan };

struct ComponentOptions {
  Phase phase = Phase::object;
  ComponentOrder order = ComponentOrder::by_size;
  /// Worker threads; 0 = all cores. The result does not depend on it.
  unsigned threads = 0;
};

struct Components {
  /// 0 on the points not in the set, 1..count() on the points of component c.
  Image<std::uint32_t> labels;
  /// sizes[c - 1]: the number of points of component c.
  std::vector<std::int64_t> sizes;
  /// touches_border[c - 1]: component c has a point on the boundary of the domain.
  std::vector<bool> touches_border;

  std::int64_t count() const { return static_cast<std::int64_t>(sizes.size()); }
};

/// The k-components of the set (2D: k = 4, 8; 3D: k = 6, 18, 26). InvalidArgument for another
/// dimension or adjacency.
Components connected_components(const Image<std::uint8_t>& image, int k,
                                const ComponentOptions& options = {});

struct ComponentCount {
  std::int64_t components = 0;
  /// Components with no point on the boundary of the domain.
  std::int64_t bounded = 0;
};

/// The numbers of k-components and of bounded ones, without building labels.
ComponentCount count_components(const Image<std::uint8_t>& image, int k,
                                Phase phase = Phase::object, unsigned threads = 0);

} // namespace zdg
