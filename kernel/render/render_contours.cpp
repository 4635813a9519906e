#include <zdg/kernel/render/render_contours.hpp>

#include <zdg/arith/error.hpp>

#include <algorithm>
#include <cmath>

namespace zdg {

namespace {

// A filled disc of radius r centred at (cx, cy).
void disc(RgbImage& img, double cx, double cy, double r, Rgb c) {
  const int x0 = static_cast<int>(std::floor(cx - r)), x1 = static_cast<int>(std::ceil(cx + r));
  const int y0 = static_cast<int>(std::floor(cy - r)), y1 = static_cast<int>(std::ceil(cy + r));
  for (int y = y0; y <= y1; ++y)
    for (int x = x0; x <= x1; ++x) {
      const double dx = x + 0.5 - cx, dy = y + 0.5 - cy;
      if (dx * dx + dy * dy <= r * r) img.set(x, y, c);
    }
}

} // namespace

RgbImage render_contours(const Image<std::uint8_t>& image,
                         const std::vector<ContourPolyline>& contours, const std::string& field,
                         const ContourRenderOptions& opt, ContourRenderReport* report) {
  if (image.dim() != 2)
    throw InvalidArgument("render: contours are drawn over a 2D image, not a " +
                          std::to_string(image.dim()) + "-D one");
  for (int k = 0; k < 2; ++k) {
    if (image.domain().extent(k) > (std::int64_t{1} << 24))
      throw InvalidArgument("render: image extent " + std::to_string(image.domain().extent(k)) +
                            " beyond 2^24");
  }
  check_picture_size(opt.width, opt.height);
  std::vector<double> all;
  bool have_values = false;
  for (const auto& c : contours) {
    if (!c.values.empty() && c.values.size() != c.points.size())
      throw InvalidArgument("render: a contour has " + std::to_string(c.values.size()) +
                            " values for " + std::to_string(c.points.size()) + " points");
    have_values = have_values || !c.values.empty();
    const auto& d = image.domain();
    for (const auto& p : c.points) {
      // Contours of the image lie within one pixel of its box (NaN fails the test too).
      if (!(p.x >= static_cast<double>(d.lower(1)) - 1 &&
            p.x <= static_cast<double>(d.upper(1)) + 1 &&
            p.y >= static_cast<double>(d.lower(0)) - 1 &&
            p.y <= static_cast<double>(d.upper(0)) + 1))
        throw InvalidArgument("render: contour point (" + short_number(p.x) + ", " +
                              short_number(p.y) + ") is outside the image");
    }
    all.insert(all.end(), c.values.begin(), c.values.end());
  }
  const bool bar = have_values;
  const ColorScale scale =
      bar ? choose_color_scale(all, opt.value_min, opt.value_max, opt.clip_percent, opt.color_map)
          : ColorScale{};
  const int W = opt.width, H = opt.height;
  const int ts = std::max(1, std::min(W, H) / 400);
  const int margin = W / 40, top = 16 * ts + margin, bar_space = bar ? 30 * 6 * ts : 0;
  const auto& d = image.domain();
  const double ny = static_cast<double>(d.extent(0)), nx = static_cast<double>(d.extent(1));
  const double aw = W - 2 * margin - bar_space, ah = H - top - margin;
  const double s = std::min(aw / nx, ah / ny);
  const double ox = margin + (aw - s * nx) / 2, oy = top + (ah - s * ny) / 2;
  RgbImage img(W, H);
  // The image: object pixels grey, background light, nearest-pixel sampling.
  const int px0 = static_cast<int>(std::floor(ox)), px1 = static_cast<int>(std::ceil(ox + s * nx));
  const int py0 = static_cast<int>(std::floor(oy)), py1 = static_cast<int>(std::ceil(oy + s * ny));
  for (int y = std::max(0, py0); y < std::min(H, py1); ++y) {
    const auto iy = static_cast<std::int64_t>(std::floor((y + 0.5 - oy) / s));
    if (iy < 0 || iy >= d.extent(0)) continue;
    for (int x = std::max(0, px0); x < std::min(W, px1); ++x) {
      const auto ix = static_cast<std::int64_t>(std::floor((x + 0.5 - ox) / s));
      if (ix < 0 || ix >= d.extent(1)) continue;
      img.set(x, y, image[iy * d.extent(1) + ix] != 0 ? Rgb{170, 170, 170} : Rgb{242, 242, 242});
    }
  }
  const Rgb ink{20, 20, 20};
  img.fill_rect(px0 - 1, py0 - 1, px1 + 1, py0, ink);
  img.fill_rect(px0 - 1, py1, px1 + 1, py1 + 1, ink);
  img.fill_rect(px0 - 1, py0 - 1, px0, py1 + 1, ink);
  img.fill_rect(px1, py0 - 1, px1 + 1, py1 + 1, ink);
  // The contours: pixel centre (x, y) of the lattice sits at ox + (x - lower_x + 1/2) s.
  const double lx = static_cast<double>(d.lower(1)), ly = static_cast<double>(d.lower(0));
  const double width = opt.line_width > 0 ? opt.line_width : std::clamp(s * 0.35, 2.0, 8.0);
  const double r = width / 2;
  for (const auto& c : contours) {
    const std::size_t n = c.points.size();
    if (n == 0) continue;
    const std::size_t segments = c.closed ? n : n - 1;
    for (std::size_t k = 0; k < std::max<std::size_t>(segments, 1); ++k) {
      const auto& a = c.points[k];
      const auto& b = c.points[(k + 1) % n];
      const double ax = ox + (a.x - lx + 0.5) * s, ay = oy + (a.y - ly + 0.5) * s;
      const double bx = ox + (b.x - lx + 0.5) * s, by = oy + (b.y - ly + 0.5) * s;
      const double len = std::hypot(bx - ax, by - ay);
      const int steps = std::max(1, static_cast<int>(std::ceil(len / std::max(0.5, r / 2))));
      for (int i = 0; i <= steps; ++i) {
        const double t = static_cast<double>(i) / steps;
        Rgb col = ink;
        if (!c.values.empty()) {
          const double va = c.values[k], vb = c.values[(k + 1) % n];
          col = scale(std::isnan(va) || std::isnan(vb) ? (t < 0.5 ? va : vb) : va + (vb - va) * t);
        }
        disc(img, ax + (bx - ax) * t, ay + (by - ay) * t, r, col);
      }
    }
  }
  std::string title = opt.title;
  if (title.empty())
    title = (field.empty() ? std::string("contours") : field) +
            " (contours: " + std::to_string(contours.size()) + ")";
  draw_text(img, margin, margin / 2, title, ink, ts);
  if (bar) {
    const int bw = 12 * ts, bh = (H - top - margin) * 2 / 3;
    draw_color_bar(img, W - bar_space + 2 * ts, top + (H - top - margin - bh) / 2, bw, bh,
                   scale.map, scale.lo, scale.hi, field, ts);
  }
  if (report != nullptr) {
    report->value_min = scale.lo;
    report->value_max = scale.hi;
    report->color_map = scale.map;
    report->pixels_per_unit = s;
  }
  return img;
}

ContourRenderReport render_contours_png(const std::string& path, const Image<std::uint8_t>& image,
                                        const std::vector<ContourPolyline>& contours,
                                        const std::string& field,
                                        const ContourRenderOptions& options) {
  ContourRenderReport report;
  const RgbImage img = render_contours(image, contours, field, options, &report);
  write_png(path, img);
  return report;
}

} // namespace zdg
