// The digitized boundary of a 2D shape for the estimators of the registry (internal to
// convergence/): the predicate of G_h(X + t) on the pixel box of the run and the contours of
// its components found by scanning 10 rows and 10 columns spread over the box (a component
// that no scan line meets is not found; see kernel/curves/digital_contour.hpp).
//
// Completeness certificate. The contours found are the whole boundary of the digitization
// (`complete`) when the shape is a topological disc with a known reach lower bound rho
// (Shape2::reach_lower_bound), h <= rho / 2, the translated shape lies inside the box with
// a margin of two pixels, and exactly one contour, counter-clockwise, was found: an
// r-regular set digitized at such a step is topologically faithful (Latecki, Conrad, Gross
// 1998; Stelldinger, Koethe 2005), so G_h(X + t) is one 4-connected component without holes
// and its boundary is that contour. Estimators may then use boundary-only algorithms
// (estimators/contour_ball_count.hpp).
#pragma once

#include <zdg/convergence/estimator.hpp>
#include <zdg/convergence/shape.hpp>
#include <zdg/kernel/curves/digital_contour.hpp>

#include <memory>
#include <utility>
#include <vector>

namespace zdg::detail {

struct Digitized2 {
  const Shape2* shape = nullptr;
  Point2<double> t;
  Box2 box;
  std::unique_ptr<GaussDigitization2> set;
  std::vector<DigitalContour> contours;
  bool complete = false; // contours certified to be the whole boundary (see above)
  ContourEmbedding embed;
};

const Shape2& as_2d(const Shape& s);

/// Pixel box of the continuous box at step h (a margin of one pixel); InvalidArgument when h
/// is too small for int64 pixel coordinates and contour scans.
Box2 pixel_box(const std::vector<std::pair<double, double>>& box, double h);

/// Digitizes the translated shape and extracts its contours.
Digitized2 digitize_2d(const RunInput& in);

} // namespace zdg::detail
