// Maximal segments (the tangential cover) and greedy segmentation of a digital curve.
//
// p_0 .. p_{n-1}, consecutive points 4- or 8-adjacent (closed: also p_{n-1}, p_0; p_0 not
// repeated). A DSS p_i .. p_j (indices mod n when closed; arith/dss_recognizer.hpp) is maximal
// when neither p_{i-1} nor p_{j+1} can be added; the cover lists them by first point (closed:
// from the one through p_0, once around). Greedy: longest DSS from p_0, sharing end points.
// Standard DSS when every step is an axis step, else naive (or as Connectivity says).
// MaximalSegment: begin, end (inclusive, may wrap), length; (b, a) the direction from p_begin
// to p_end, gcd 1; mu <= a x - b y < mu + omega with both bounds reached (mu 128-bit). One
// point gives (0, 1, -y, 1). Example of use: docs/NOTES.md, "kernel/curves/maximal_segments.hpp".
// Complexity: O(n) for both (Feschet and Tougne, DGCI 1999; Lachaud, Vialard, de Vieilleville,
// Image Vis. Comput. 25(10), 2007). Width: local coordinates; maximal_segments<I> throws
// OverflowError past I (on Int64 only beyond about 2^31 points), _exact escalates Int64 ->
// Int128 -> BigInt; mu must fit 128 bits, a, b, omega 64 bits (OverflowError otherwise).
#pragma once

#include <zdg/arith/dss_recognizer.hpp>
#include <zdg/arith/escalate.hpp>
#include <zdg/arith/integer.hpp>
#include <zdg/arith/point.hpp>

#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

namespace zdg {

struct MaximalSegment {
  std::size_t begin = 0, end = 0; // inclusive indices; end < begin when a closed curve wraps
  std::size_t length = 0;         // number of points
  std::int64_t a = 0, b = 0;      // direction (b, a) from p_begin to p_end
  int128_t mu = 0;                // mu <= a x - b y < mu + omega on the segment
  std::int64_t omega = 0;
  friend bool operator==(const MaximalSegment&, const MaximalSegment&) = default;
};

/// The tangential cover of the curve (empty for an empty curve), the recognizer computing on
/// I (may throw OverflowError). Throws InvalidArgument when two consecutive points (or the last
/// and the first of a closed curve) are not adjacent.
template <TowerInt I>
std::vector<MaximalSegment> maximal_segments(std::span<const Point2<std::int64_t>> points,
                                             bool closed,
                                             std::optional<Connectivity> connectivity = {});
/// The same, exact by escalation, with the type that served.
Escalated<std::vector<MaximalSegment>>
maximal_segments_exact(std::span<const Point2<std::int64_t>> points, bool closed,
                       std::optional<Connectivity> connectivity = {});

/// Greedy segmentation: longest DSS from p_0, the next one starting at its last point, and so
/// on to p_{n-1} (open) or back to p_0 (closed: the last segment ends at index 0). Computed on
/// I (may throw OverflowError).
template <TowerInt I>
std::vector<MaximalSegment> greedy_segmentation(std::span<const Point2<std::int64_t>> points,
                                                bool closed,
                                                std::optional<Connectivity> connectivity = {});
/// The same, exact by escalation, with the type that served.
Escalated<std::vector<MaximalSegment>>
greedy_segmentation_exact(std::span<const Point2<std::int64_t>> points, bool closed,
                          std::optional<Connectivity> connectivity = {});

} // namespace zdg
