// Freeman chains: a start point and a word over {0, 1, 2, 3}, letter k meaning the step
// (1,0), (0,1), (-1,0), (0,-1) respectively (a 4-connected path of pointels or pixels).
//
// Text form: "x0 y0 0123..." (decimal start coordinates, then the codes; whitespace inside
// the codes is ignored). Complexity O(n). Width: coordinates are int64; a path leaving int64
// throws OverflowError.
// Source: Freeman, On the encoding of arbitrary geometric configurations, IRE Trans. 1961.
#pragma once

#include <zdg/arith/point.hpp>

#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace zdg {

struct FreemanChain {
  Point2<std::int64_t> start;
  std::string codes; // letters '0'..'3'
  friend bool operator==(const FreemanChain&, const FreemanChain&) = default;
};

/// The step of a code letter '0'..'3'; InvalidArgument for anything else.
Point2<std::int64_t> freeman_step(char code);

/// Parses "x0 y0 codes"; InvalidArgument naming the offending token or letter (and its
/// position) when malformed.
FreemanChain parse_freeman_chain(std::string_view text);

/// "x0 y0 codes".
std::string to_string(const FreemanChain& chain);

/// The codes.size() + 1 points of the path (the start first).
std::vector<Point2<std::int64_t>> freeman_points(const FreemanChain& chain);

/// The chain of a 4-connected path (at least one point); InvalidArgument when two consecutive
/// points are not 4-adjacent (naming their indices).
FreemanChain freeman_chain_of(std::span<const Point2<std::int64_t>> points);

/// True when the path ends where it starts (a closed contour; its points list then omits the
/// repeated start: use the first codes.size() points).
bool is_closed(const FreemanChain& chain);

} // namespace zdg
