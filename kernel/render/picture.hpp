// Raster pictures for zdg's figures: an RGB image, PNG output (libpng), colour maps, a 5x7
// bitmap font and a colour bar with its value range. Shared by render_mesh.hpp (3D surfaces)
// and render_contours.hpp (2D contours).
//
//   colour maps  viridis (sequential; perceptually uniform, readable in grey and by colour-
//                blind readers) and coolwarm (diverging, white at the middle: for signed
//                quantities such as curvature), both sampled from matplotlib at 17 points and
//                interpolated linearly; NaN gets grey
//   font         printable ASCII, 5x7 pixels per glyph on a 6x8 cell, scaled by an integer
//   PNG          8-bit RGB, written through a staging file (kernel/io/output_files.hpp)
// Cost: O(width x height) for writing; drawing text O(pixels drawn).
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace zdg {

struct Rgb {
  std::uint8_t r = 0, g = 0, b = 0;
  friend bool operator==(const Rgb&, const Rgb&) = default;
};

struct RgbImage {
  int width = 0, height = 0;
  std::vector<std::uint8_t> rgb; // row-major, 3 bytes per pixel, row 0 at the top

  RgbImage() = default;
  RgbImage(int w, int h, Rgb fill = {255, 255, 255});
  Rgb at(int x, int y) const;
  /// Sets a pixel; outside the image nothing happens.
  void set(int x, int y, Rgb c);
  void fill_rect(int x0, int y0, int x1, int y1, Rgb c); ///< [x0, x1) x [y0, y1), clipped
};

/// The picture sizes the renderers accept: 200 x 150 to 8192 x 8192 pixels (InvalidArgument
/// otherwise, naming the size; `what` starts the message, e.g. "render" or "--png-size").
void check_picture_size(int width, int height, const std::string& what = "render");

/// Writes an 8-bit RGB PNG (IoError naming the file on failure; atomic).
void write_png(const std::string& path, const RgbImage& image);

enum class ColorMap { viridis, coolwarm };

/// The colour of t in [0, 1] (clamped; NaN -> grey).
Rgb map_color(ColorMap map, double t);
/// "viridis", "coolwarm".
std::string color_map_name(ColorMap map);

/// A colour map over a value range: value v gets map_color(map, (v - lo) / (hi - lo)).
struct ColorScale {
  ColorMap map = ColorMap::viridis;
  double lo = 0.0, hi = 1.0;
  Rgb operator()(double v) const;
};

/// The scale of a field: [lo, hi] as given, else the clip_percent and 100 - clip_percent
/// percentiles of the finite values (0: min and max; a sample of 10^6 values past that
/// many); a range with both signs becomes symmetric about 0 with the coolwarm map, otherwise
/// viridis (unless `map` is given). An empty or constant range is widened by 1/2 each side.
ColorScale choose_color_scale(std::span<const double> values, std::optional<double> lo,
                              std::optional<double> hi, double clip_percent,
                              std::optional<ColorMap> map);

/// Width in pixels of the text at this scale (6 scale per character, less the last gap).
int text_width(std::string_view text, int scale);
/// Draws the text with its top-left corner at (x, y); characters outside printable ASCII are
/// drawn as '?'.
void draw_text(RgbImage& image, int x, int y, std::string_view text, Rgb color, int scale);

/// "0.0123", "-4.5e+06": a value in at most `digits` significant digits.
std::string short_number(double value, int digits = 4);

/// A vertical colour bar in the box [x, x + w) x [y, y + h), `lo` at the bottom and `hi` at
/// the top, with the values written to its right (top, middle, bottom) and `label` above.
void draw_color_bar(RgbImage& image, int x, int y, int w, int h, ColorMap map, double lo, double hi,
                    const std::string& label, int scale);

} // namespace zdg
