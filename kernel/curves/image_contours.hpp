// The contours of a binary 2D image: every boundary linel, split into closed 4-connected linel
// chains (kernel/curves/digital_contour.hpp) under an adjacency pair, and the Betti numbers.
//
// The image is a 2D Image<uint8_t> (axes (y, x), x contiguous; pixel (i, j) stands for the
// point lower + (i, j) of Z^2); the object X is its nonzero pixels, pixels outside the domain
// are outside. A boundary linel separates a pixel of X (on its left) from a 4-neighbour not
// in X. Through the pointel at its end each boundary linel has exactly one follower: straight
// on, or a turn; where the four pixels around the pointel are two diagonal pairs, the pair
// decides: (4,8) (the object 4-connected) turns around the inner pixel and separates the two
// object pixels, (8,4) turns the other way and joins them. So the boundary linels split into
// closed contours, run counterclockwise around X: the outer contour of each component of X
// counterclockwise (positive area), the contour of each hole clockwise (negative area).
// Hence b0 (components of X) = number of counterclockwise contours, b1 (bounded components
// of the complement, under the other adjacency) = number of clockwise ones, and the signed
// areas add up to the number of pixels (Rosenfeld, "Digital topology", Amer. Math. Monthly
// 1979; Kong-Rosenfeld 1989 for the Jordan property of the pairs).
//
// Algorithm: one scan of the pixels in image order; each boundary linel not yet on a contour
// starts one, tracked with four look-ups per linel and marked in a 4-bit-per-pixel table.
// O(N) time, N + 8 (linels) bytes. Contours are listed in the order of their first linel
// (smallest pixel, then code). Width: coordinates int64 (the Domain's); areas are exact
// (checked int128 sums in DigitalContour).
#pragma once

#include <zdg/kernel/curves/digital_contour.hpp>
#include <zdg/kernel/images/image.hpp>

#include <cstdint>
#include <vector>

namespace zdg {

struct ImageContours {
  std::vector<DigitalContour> contours; ///< in Z^2 coordinates (lower bounds included)
  std::int64_t b0 = 0;                  ///< counterclockwise contours: components of X
  std::int64_t b1 = 0;                  ///< clockwise contours: holes
  std::int64_t linels() const;          ///< total number of boundary linels
};

/// The contours of the nonzero pixels of a 2D image under the pair (k, kbar) = (4,8) or (8,4)
/// (InvalidArgument for another pair or an image that is not 2D).
ImageContours image_contours(const Image<std::uint8_t>& image, int k, int kbar);

} // namespace zdg
