// A picture of a 2D binary image with its contours coloured by a per-point value (a
// curvature, a tangent angle): the image in two greys (object darker), the contours as thick
// polylines whose colour is interpolated along each segment between the values of its ends,
// a colour bar with the value range (chosen as in render_mesh.hpp: percentiles, coolwarm for
// signed values, viridis otherwise) and a title.
//
// Coordinates: a point (x, y) is in the image's lattice coordinates, x along axis 1 and y
// along axis 0 (as in kernel/curves/digital_contour.hpp: pixel z is the unit square centred at z,
// a pointel at a half-integer corner); row y = lower(0) is drawn at the top, as an image
// viewer shows the file. The image is scaled to fill the drawing area (any real factor;
// nearest-pixel sampling). Cost: O(picture pixels + contour length x line width^2).
#pragma once

#include <zdg/arith/point.hpp>
#include <zdg/kernel/images/image.hpp>
#include <zdg/kernel/render/picture.hpp>

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace zdg {

struct ContourPolyline {
  std::vector<Point2<double>> points; ///< (x, y) in lattice coordinates
  std::vector<double> values;         ///< one per point, or empty (drawn in black)
  bool closed = true;                 ///< a segment joins the last point to the first
};

struct ContourRenderOptions {
  int width = 1000, height = 800;
  std::optional<ColorMap> color_map;
  std::optional<double> value_min, value_max;
  double clip_percent = 1.0;
  double line_width = 0; ///< pixels; 0: from the scale (between 2 and 8)
  std::string title;     ///< default: the field name and the contour count
};

struct ContourRenderReport {
  double value_min = 0, value_max = 0;
  ColorMap color_map = ColorMap::viridis;
  double pixels_per_unit = 1; ///< the scale of the picture
};

/// Renders a 2D image (nonzero = object) and its contours; `field` names the values (for the
/// colour bar; "" when the contours carry none).
RgbImage render_contours(const Image<std::uint8_t>& image,
                         const std::vector<ContourPolyline>& contours, const std::string& field,
                         const ContourRenderOptions& options = {},
                         ContourRenderReport* report = nullptr);

/// render_contours, written as a PNG file (atomically).
ContourRenderReport render_contours_png(const std::string& path, const Image<std::uint8_t>& image,
                                        const std::vector<ContourPolyline>& contours,
                                        const std::string& field,
                                        const ContourRenderOptions& options = {});

} // namespace zdg
