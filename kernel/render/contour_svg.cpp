#include <zdg/kernel/render/contour_svg.hpp>

#include <zdg/arith/error.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>

namespace zdg {

namespace {

std::string num(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.6g", v);
  return buf;
}

// Diverging scale: t in [-1, 1] -> blue (-1), white (0), red (+1).
std::string colour(double t) {
  t = std::clamp(t, -1.0, 1.0);
  int r = 255, g = 255, b = 255;
  if (t < 0) {
    r = g = int(std::lround(255 * (1 + t)));
  } else {
    g = b = int(std::lround(255 * (1 - t)));
  }
  char buf[16];
  std::snprintf(buf, sizeof buf, "#%02x%02x%02x", r, g, b);
  return buf;
}

// Appends the pieces (GCC 12 warns wrongly about long chains of string temporaries).
template <class... Pieces>
void add(std::string& s, const Pieces&... pieces) {
  (s.append(pieces), ...);
}

} // namespace

std::string contour_svg(const std::vector<DigitalContour>& contours, const ContourDrawing& d) {
  if (d.box.empty()) throw InvalidArgument("contour_svg: empty image box");
  const double w = double(d.box.hi.x - d.box.lo.x + 1), h = double(d.box.hi.y - d.box.lo.y + 1);
  const double scale = 800.0 / std::max(w, h);
  const bool coloured = d.field != nullptr;
  const double bar = coloured ? 60 : 0;
  auto X = [&](std::int64_t px) { return num(double(px - d.box.lo.x) * scale); };
  auto Y = [&](std::int64_t py) { return num(double(py - d.box.lo.y) * scale); };
  std::string s;
  add(s, "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"", num(w * scale + bar), "\" height=\"",
      num(h * scale), "\" viewBox=\"0 0 ", num(w * scale + bar), " ", num(h * scale), "\">\n");
  add(s, "<rect width=\"", num(w * scale), "\" height=\"", num(h * scale),
      "\" fill=\"#f4f4f4\"/>\n");
  // The object, filled.
  add(s, "<path fill=\"", coloured ? "#d9d9d9" : "#c6dbef",
      "\" fill-rule=\"evenodd\" stroke=\"none\" d=\"");
  for (const auto& c : contours) {
    Pixel p = c.start;
    add(s, "M", X(p.x), " ", Y(p.y));
    for (auto code : c.codes) {
      p = p + freeman_step(code);
      add(s, "L", X(p.x), " ", Y(p.y));
    }
    s += "Z";
  }
  s += "\"/>\n";
  const double sw = std::max(1.0, scale * 0.25);
  if (!coloured) {
    for (const auto& c : contours) {
      const bool outer = c.twice_signed_area() > 0;
      Pixel p = c.start;
      add(s, "<path fill=\"none\" stroke=\"", outer ? "#08519c" : "#cb181d", "\" stroke-width=\"",
          num(sw), "\" d=\"M", X(p.x), " ", Y(p.y));
      for (auto code : c.codes) {
        p = p + freeman_step(code);
        add(s, "L", X(p.x), " ", Y(p.y));
      }
      s += "Z\"/>\n";
    }
  } else {
    double m = 0;
    for (const auto& v : *d.field)
      for (double x : v)
        if (std::isfinite(x)) m = std::max(m, std::abs(x));
    if (m == 0) m = 1;
    for (std::size_t k = 0; k < contours.size(); ++k) {
      const auto& c = contours[k];
      const auto& v = (*d.field).at(k);
      Pixel p = c.start;
      for (std::size_t i = 0; i < c.size(); ++i) {
        const Pixel q = p + freeman_step(c.codes[i]);
        const double x = i < v.size() ? v[i] : 0.0;
        add(s, "<line x1=\"", X(p.x), "\" y1=\"", Y(p.y), "\" x2=\"", X(q.x), "\" y2=\"", Y(q.y),
            "\" stroke=\"", std::isfinite(x) ? colour(x / m) : std::string("#000000"),
            "\" stroke-width=\"", num(2 * sw), "\" stroke-linecap=\"round\"/>\n");
        p = q;
      }
    }
    // Colour bar: +m on top, -m at the bottom.
    const double x0 = w * scale + 15, H = h * scale;
    for (int i = 0; i < 50; ++i) {
      const double t = 1 - 2 * (i + 0.5) / 50;
      add(s, "<rect x=\"", num(x0), "\" y=\"", num(H * 0.1 + H * 0.8 * i / 50),
          "\" width=\"15\" height=\"", num(H * 0.8 / 50 + 0.5), "\" fill=\"", colour(t), "\"/>\n");
    }
    const double fs = std::max(8.0, H * 0.03);
    add(s, "<text x=\"", num(x0), "\" y=\"", num(H * 0.1 - 4), "\" font-size=\"", num(fs), "\">",
        num(m), "</text>\n");
    add(s, "<text x=\"", num(x0), "\" y=\"", num(H * 0.9 + fs), "\" font-size=\"", num(fs), "\">",
        num(-m), "</text>\n");
    add(s, "<text x=\"", num(x0), "\" y=\"", num(H * 0.5), "\" font-size=\"", num(fs),
        "\" transform=\"rotate(90 ", num(x0 + 20), " ", num(H * 0.5), ")\">", d.field_name,
        "</text>\n");
  }
  s += "</svg>\n";
  return s;
}

void write_contour_svg(const std::string& path, const std::vector<DigitalContour>& contours,
                       const ContourDrawing& drawing) {
  const std::string text = contour_svg(contours, drawing);
  std::ofstream f(path, std::ios::binary);
  if (!f) throw IoError(path + ": cannot be written");
  f << text;
  if (!f) throw IoError(path + ": write failed");
}

} // namespace zdg
