// Connected components of a binary image of Z^2 or Z^3 under any adjacency
// (kernel/topology/adjacency.hpp): labels, sizes, ranking by size, and counts of the components
// that do not touch the border of the domain (the bounded components, for the background).
//
// The object is the set of points with a nonzero value (Phase::object) or of value 0
// (Phase::background). A component is a maximal k-connected subset. It touches the border
// when one of its points lies on the boundary of the domain box (in 2D along the two axes,
// in 3D along the three). Points outside the domain count as background and the outside of a
// box is connected under every adjacency, so for Phase::background the components that touch
// the border are the ones connected to infinity, and the others are exactly the bounded
// background components (the cavities in 3D, the holes in 2D).
//
// Algorithm: union-find over runs (maximal segments of the object along the last, contiguous
// axis; Rosenfeld and Pfaltz 1966 in its run form, e.g. Wu, Otoo and Suzuki, "Optimizing
// two-pass connected-component labeling algorithms", PAA 12, 2009). A run meets the runs of
// its preceding neighbour rows: with d the l1 norm of the row offset and m = m(k), runs
// [a, b) and [c, e) are adjacent when they overlap, or when they overlap after widening by
// one point on each side if d < m. Union by smaller index with path halving, so every parent
// precedes its child and one sequential pass flattens the forest. Multi-threaded: runs are
// found per row in parallel, rows are split into contiguous chunks united in parallel, the
// few rows at chunk seams are united afterwards, and labels are written in parallel.
// Cost O(N) time for scanning plus O(R alpha(R)) for R runs; memory O(R) plus the labels.
// The result does not depend on the number of threads.
//
// Width: labels are uint32 (OverflowError past 2^32 - 1 components, which needs more than
// 2^32 points); sizes and counts are int64 (they are at most the number of points, which
// Domain keeps inside int64).
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
