// The digitized boundary of a 2D shape for the estimators of the registry (internal to
// convergence/): the predicate of G_h(X + t) on the pixel box of the run and the contours of
// its components found by scanning 10 rows and 10 columns spread over the box (a component
// that no scan line meets is not found; see kernel/digital_contour.hpp).
#pragma once

#include "convergence/estimator.hpp"
#include "convergence/shape.hpp"
#include "kernel/digital_contour.hpp"

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
  ContourEmbedding embed;
};

const Shape2& as_2d(const Shape& s);

/// Pixel box of the continuous box at step h (a margin of one pixel); InvalidArgument when h
/// is too small for int64 pixel coordinates and contour scans.
Box2 pixel_box(const std::vector<std::pair<double, double>>& box, double h);

/// Digitizes the translated shape and extracts its contours.
Digitized2 digitize_2d(const RunInput& in);

} // namespace zdg::detail
