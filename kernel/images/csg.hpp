// Constructive solid geometry on binary images: union, intersection, difference, symmetric
// difference and complement, point by point on images of one domain (nonzero = object; the
// results hold 0 and 1). O(N), multi-threaded (parallel_for; the result does not depend on the
// thread count). The complement is taken in the image's box: a set and its complement under the
// dual adjacency pairs (26,6) / (6,26) are tied by Alexander duality (betti_numbers.hpp).
// Errors: InvalidArgument when the two domains differ (extents or lower bounds), naming both.
#pragma once

#include <zdg/kernel/images/image.hpp>

#include <cstdint>
#include <string>

namespace zdg {

enum class CsgOperation { union_of, intersection, difference, symmetric_difference };

/// "union", "intersection", "difference", "symmetric-difference".
std::string csg_name(CsgOperation op);

/// a op b.
Image<std::uint8_t> csg(CsgOperation op, const Image<std::uint8_t>& a, const Image<std::uint8_t>& b,
                        unsigned threads = 0);

/// The complement of a in its domain.
Image<std::uint8_t> csg_complement(const Image<std::uint8_t>& a, unsigned threads = 0);

} // namespace zdg
