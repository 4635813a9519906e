// Marching squares with linear interpolation, beside the linel contours: the iso-contour of a
// grey image at a level, as closed polygons with one vertex per boundary linel.
//
// The dual of the linel contours (kernel/curves/image_contours.hpp), as zdg's marching cubes
// is the dual of the digital surface: each boundary linel separates an inner pixel a (in the
// object, the pixels whose values pass the level) from an outer 4-neighbour b; its vertex is
// on the segment of the pixel centres, a + t (b - a) with t = (level - f(a)) / (f(b) - f(a))
// clamped to [0, 1] (linear interpolation of f along the grid edge, the classical marching
// squares vertex: Lorensen, Cline, SIGGRAPH 1987, in 2D), t = 1/2 without grey values or
// when b is outside the image (the linel's midpoint). The vertices follow the linel contour,
// so the ambiguous saddle cells are resolved by the adjacency pair of the contours and the
// polygons have the contours' topology: counterclockwise around the object, clockwise around
// holes, b0 and b1 unchanged. On a binary image at level 1/2 the vertices are the linels'
// midpoints; on samples of an affine function f they lie on its level line exactly up to
// rounding.
//
// Coordinates: lattice (x, y), pixel z at z (the caller scales by h or the spacing).
// Cost: O(linels) evaluations of f; memory 16 bytes a linel.
#pragma once

#include <zdg/arith/point.hpp>
#include <zdg/kernel/curves/image_contours.hpp>

#include <functional>
#include <vector>

namespace zdg {

struct InterpolatedContour {
  std::vector<Point2<double>> vertices; ///< one per linel, in the contour's order
  /// The closed polygon's length and signed area (shoelace; > 0 counterclockwise).
  double length() const;
  double signed_area() const;
};

/// Grey values: value(z) at the pixel z of the image's domain, and the level; the object's
/// pixels are those on the side of the level the contours were extracted for.
struct GreyLevel2 {
  std::function<double(const Pixel&)> value;
  double level = 0.5;
};

/// The interpolated polygon of each contour (grey null: the linel midpoints). `domain` is the
/// contours' image domain (pixels outside it give t = 1/2).
std::vector<InterpolatedContour> marching_squares(const ImageContours& contours,
                                                  const Domain& domain,
                                                  const GreyLevel2* grey = nullptr);

} // namespace zdg
