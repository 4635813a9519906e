// Maximal segments (the tangential cover) and greedy segmentation of a digital curve.
//
// A curve is a list of points p_0 .. p_{n-1}, consecutive points 4- or 8-adjacent; a closed
// curve also has p_{n-1} adjacent to p_0 (do not repeat p_0 at the end). A DSS of the curve is
// a run of consecutive points p_i .. p_j (indices modulo n when closed) that is a digital
// straight segment (arith/dss_recognizer.hpp); it is maximal when neither p_{i-1} nor p_{j+1}
// can be added. The tangential cover is the sequence of all maximal segments, ordered by their
// first point (both ends then increase strictly); on a closed curve the list starts with the
// maximal segment through p_0 found by extending from p_0 backwards first (it may wrap) and
// goes once around. The greedy segmentation cuts the curve into longest DSS from p_0 on,
// consecutive segments sharing their end point.
//
// Connectivity: when every step is an axis step (4-connected curves, e.g. contours of
// pointels) the segments are standard DSS (omega = |a| + |b|); otherwise naive DSS
// (omega = max(|a|, |b|)), and 8-connected curves that mix axis steps of both directions in one
// run simply give shorter segments. Pass a Connectivity to choose.
//
// Each MaximalSegment is a plain struct:
//   begin, end   inclusive indices into the input; for a closed curve a segment may wrap
//                (end < begin), and length = number of points (end - begin + 1 modulo n);
//   a, b         minimal characteristics, oriented along the curve: (b, a) is the direction
//                vector of the segment, pointing from p_begin towards p_end (gcd(a, b) = 1;
//                the tangent angle is atan2(a, b));
//   mu, omega    mu <= a x - b y < mu + omega for every point of the segment, with both bounds
//                reached (upper and lower leaning points). mu is 128-bit: a x0 exceeds int64 for
//                coordinates near 2^62.
// A one-point curve gives one segment (a, b, mu, omega) = (0, 1, -y, 1).
//
//   std::vector<zdg::Point2<std::int64_t>> contour = ...;  // closed 4-connected pointels
//   for (const auto& s : zdg::maximal_segments_exact(contour, true).value) {
//     double angle = std::atan2(double(s.a), double(s.b));  // tangent direction of s
//     // points contour[(s.begin + k) % contour.size()], k = 0 .. s.length - 1
//   }
//
// Complexity: O(n) for both (each point enters and leaves the recognizer at most once per
// turn; Feschet and Tougne 1999, Lachaud, Vialard and de Vieilleville 2007). Width: the
// recognizer works in local coordinates; maximal_segments<I> runs it on I (OverflowError when
// its checked arithmetic overflows: on Int64 only for curves longer than about 2^31 points),
// maximal_segments_exact escalates Int64 -> Int128 -> BigInt (arith/escalate.hpp); mu must fit
// 128 bits and a, b, omega 64 bits (OverflowError otherwise).
// Source: Feschet and Tougne, Optimal time computation of the tangent of a discrete curve,
// DGCI 1999; Lachaud, Vialard, de Vieilleville, Fast, accurate and convergent tangent
// estimation on digital contours, Image Vis. Comput. 25(10), 2007.
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
