// An SVG drawing of the contours of a 2D image (kernel/curves/image_contours.hpp): the object
// filled (even-odd rule over all its contours), outer contours in blue and holes in red, or, when a
// per-linel field is given (an estimate such as ii-curvature), every linel coloured by its
// value on a diverging blue-white-red scale symmetric about 0, with a colour bar giving the
// range. Pixel (x, y) of the image is the unit square [x - 1/2, x + 1/2] x [y - 1/2, y + 1/2];
// SVG's y axis points down, so the drawing shows the image as image viewers do (row 0 on top).
// The scale makes the longer side about 800 units. O(linels) time and output size; the file
// is written as given (callers write to an OutputSet staging file).
#pragma once

#include <zdg/kernel/curves/digital_contour.hpp>
#include <zdg/kernel/images/box.hpp>

#include <string>
#include <vector>

namespace zdg {

struct ContourDrawing {
  Box2 box;                                                ///< the image's pixel box
  std::string field_name;                                  ///< legend of the field
  const std::vector<std::vector<double>>* field = nullptr; ///< [contour][linel], or none
};

/// The SVG text of the drawing.
std::string contour_svg(const std::vector<DigitalContour>& contours, const ContourDrawing& drawing);

/// Writes contour_svg() to path (IoError when it cannot).
void write_contour_svg(const std::string& path, const std::vector<DigitalContour>& contours,
                       const ContourDrawing& drawing);

} // namespace zdg
