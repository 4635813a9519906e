// Boundaries of a digitized set as closed 4-connected contours of linels.
//
// Cells: pixel z is the unit square centred at z; pointel p is the corner
// p - (1/2, 1/2) (pixel z has the pointels z, z + (1,0), z + (0,1), z + (1,1)); a linel is
// the unit edge from pointel p to p + d(c), Freeman code c in 0..3 for
// d = (1,0), (0,1), (-1,0), (0,-1). A contour is a start pointel and a Freeman chain; it
// runs counter-clockwise around the set (the set is on the left of every linel): outer
// boundaries are counter-clockwise, hole boundaries clockwise, so the shoelace area of the
// pointel polygon, summed over all contours of a set, is its number of pixels.
//
// Components are 4-connected (two pixels meeting at a corner only are two components).
// Tracking (turn right / go straight / turn left from the two pixels ahead) costs O(length)
// predicate calls. Contours are found by scanning given rows and columns for boundary
// crossings (O(width) per line): a component that no scan line meets is not found.
//
// Embedding at step h: pointel p -> h (p - (1/2, 1/2)), linel -> its midpoint, pixel z -> h z.
// Integer width: coordinates are int64_t; the shoelace sums use checked Int128.
#pragma once

#include <zdg/arith/point.hpp>
#include <zdg/kernel/digitization/gauss_digitization.hpp>

#include <cstdint>
#include <vector>

namespace zdg {

constexpr Pixel freeman_step(int code) {
  constexpr std::int64_t dx[4] = {1, 0, -1, 0};
  constexpr std::int64_t dy[4] = {0, 1, 0, -1};
  return Pixel{dx[code & 3], dy[code & 3]};
}

struct DigitalContour {
  Pixel start;                     // start pointel
  std::vector<std::uint8_t> codes; // Freeman codes 0..3, closed: the steps sum to zero

  std::size_t size() const { return codes.size(); }
  /// The pointels p_0 = start, p_1, ..., p_{n-1} (the closing pointel is not repeated).
  std::vector<Pixel> pointels() const;
  /// Twice the signed area of the pointel polygon (shoelace): 2 x (pixel count) for an outer
  /// contour, minus twice the hole area for a hole.
  std::int64_t twice_signed_area() const;
  /// Pixel on the left (inside) and on the right (outside) of the linel from p with code c.
  static Pixel inner_pixel(const Pixel& p, int code);
  static Pixel outer_pixel(const Pixel& p, int code);
};

/// Tracks the contour through the linel from pointel `start` with Freeman code `code`
/// (inner pixel in the set, outer pixel not). Throws InvalidArgument when that linel is not
/// a boundary linel of `set`.
DigitalContour track_contour(const GaussDigitization2& set, const Pixel& start, int code);

/// The contours (outer and holes) of `set` that cross the given rows (y values) or columns
/// (x values) inside the box, each once.
std::vector<DigitalContour> digital_contours(const GaussDigitization2& set,
                                             const std::vector<std::int64_t>& rows,
                                             const std::vector<std::int64_t>& columns);

/// Continuous embedding at step h.
struct ContourEmbedding {
  double h;
  Point2<double> pointel(const Pixel& p) const {
    return {h * (static_cast<double>(p.x) - 0.5), h * (static_cast<double>(p.y) - 0.5)};
  }
  Point2<double> linel_midpoint(const Pixel& p, int code) const {
    Pixel d = freeman_step(code);
    return {h * (static_cast<double>(p.x) + 0.5 * static_cast<double>(d.x) - 0.5),
            h * (static_cast<double>(p.y) + 0.5 * static_cast<double>(d.y) - 0.5)};
  }
  Point2<double> pixel(const Pixel& z) const {
    return {h * static_cast<double>(z.x), h * static_cast<double>(z.y)};
  }
};

} // namespace zdg
