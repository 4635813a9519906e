#include <zdg/kernel/curves/marching_squares.hpp>

#include <algorithm>
#include <array>
#include <cmath>

namespace zdg {

double InterpolatedContour::length() const {
  double l = 0;
  for (std::size_t i = 0; i < vertices.size(); ++i) {
    const auto& u = vertices[i];
    const auto& v = vertices[(i + 1) % vertices.size()];
    l += std::hypot(v.x - u.x, v.y - u.y);
  }
  return l;
}

double InterpolatedContour::signed_area() const {
  double a = 0;
  for (std::size_t i = 0; i < vertices.size(); ++i) {
    const auto& u = vertices[i];
    const auto& v = vertices[(i + 1) % vertices.size()];
    a += u.x * v.y - u.y * v.x;
  }
  return a / 2;
}

std::vector<InterpolatedContour> marching_squares(const ImageContours& contours,
                                                  const Domain& domain, const GreyLevel2* grey) {
  auto inside = [&](const Pixel& z) {
    const std::array<std::int64_t, 2> p{z.y, z.x};
    return domain.contains(p);
  };
  std::vector<InterpolatedContour> out(contours.contours.size());
  for (std::size_t c = 0; c < contours.contours.size(); ++c) {
    const DigitalContour& dc = contours.contours[c];
    auto& poly = out[c].vertices;
    poly.reserve(dc.size());
    Pixel p = dc.start;
    for (const std::uint8_t code : dc.codes) {
      const Pixel a = DigitalContour::inner_pixel(p, code);
      const Pixel b = DigitalContour::outer_pixel(p, code);
      double t = 0.5;
      if (grey != nullptr && inside(a) && inside(b)) {
        const double fa = grey->value(a), fb = grey->value(b);
        if (fa != fb && std::isfinite(fa) && std::isfinite(fb))
          t = std::clamp((grey->level - fa) / (fb - fa), 0.0, 1.0);
      }
      poly.push_back({double(a.x) + t * double(b.x - a.x), double(a.y) + t * double(b.y - a.y)});
      const Pixel d = freeman_step(code);
      p = Pixel{p.x + d.x, p.y + d.y};
    }
  }
  return out;
}

} // namespace zdg
