// Well-composedness of a binary image of Z^2 or Z^3 (Latecki, Eckhardt, Rosenfeld, "Well-composed
// sets", CVIU 61, 1995; Latecki, "3D well-composed pictures", GMIP 59, 1997): the set and its
// complement have no critical configuration, so that 4- and 8-connectivity (6 and 26 in 3D)
// agree on both and the boundary of the continuous analog is a manifold.
//   C1: a 2x2 square (in 3D, in any of the three axis planes) whose two points on one diagonal
//       are in X and the two on the other are not;
//   C2 (3D): a 2x2x2 cube whose points in X are exactly two antipodal ones, or whose points
//       not in X are exactly two antipodal ones.
// The outside of the box is background (a critical block lies inside the box: its points in X,
// or in 3D its 6 points in X, span it). O(N), one pass; the first critical block in C order is
// the witness.
#pragma once

#include <zdg/kernel/images/image.hpp>

#include <cstdint>
#include <string>
#include <vector>

namespace zdg {

struct WellComposedness {
  bool well_composed = true;
  /// When not: the lower corner of the first critical block (array order, like the image's
  /// points) and its configuration: "C1 axes (i, j)" (the square spans array axes i and j) or
  /// "C2".
  std::vector<std::int64_t> corner;
  std::string configuration;
};

/// The well-composedness of the nonzero points of a 2D or 3D image (InvalidArgument otherwise).
WellComposedness well_composedness(const Image<std::uint8_t>& image);

} // namespace zdg
