#include <zdg/estimators/mlp_length.hpp>

#include <zdg/arith/error.hpp>

#include <cmath>
#include <cstdlib>
#include <string>

namespace zdg {

namespace {

// (b - a) x (c - a): > 0 when c is on the left of a -> b.
std::int64_t cross(const Pixel& a, const Pixel& b, const Pixel& c) {
  return (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
}

} // namespace

std::vector<Pixel> minimum_length_polygon(const DigitalContour& contour) {
  const std::size_t n = contour.size();
  if (n < 4) throw InvalidArgument("minimum_length_polygon: contour with fewer than 4 linels");
  std::vector<Pixel> left(n), right(n);
  Pixel p = contour.start;
  std::size_t start = 0;
  for (std::size_t i = 0; i < n; ++i) {
    int code = contour.codes[i];
    left[i] = DigitalContour::inner_pixel(p, code);
    right[i] = DigitalContour::outer_pixel(p, code);
    if (std::llabs(left[i].x) > (1LL << 30) || std::llabs(left[i].y) > (1LL << 30)) {
      throw InvalidArgument("minimum_length_polygon: coordinates beyond 2^30");
    }
    if (left[i] < left[start]) start = i;
    Pixel d = freeman_step(code);
    p = Pixel{p.x + d.x, p.y + d.y};
  }
  // Portals start+1, ..., start+n-1, then the degenerate portal (s, s).
  const Pixel s = left[start];
  auto portal = [&](std::size_t k, bool is_left) -> Pixel {
    if (k == n) return s;
    std::size_t i = (start + k) % n;
    return is_left ? left[i] : right[i];
  };
  std::vector<Pixel> path{s};
  Pixel apex = s, fl = s, fr = s;
  std::size_t apex_k = 0, left_k = 0, right_k = 0;
  for (std::size_t k = 1; k <= n; ++k) {
    const Pixel l = portal(k, true), r = portal(k, false);
    // Right side: r tightens the funnel when it is on the left of (or on) apex -> fr.
    if (cross(apex, fr, r) >= 0) {
      if (apex == fr || cross(apex, fl, r) <= 0) {
        fr = r;
        right_k = k;
      } else {
        // r crosses the left edge: fl is a vertex of the MLP.
        apex = fl;
        apex_k = left_k;
        if (path.back() != apex) path.push_back(apex);
        fl = fr = apex;
        left_k = right_k = apex_k;
        k = apex_k;
        continue;
      }
    }
    // Left side: l tightens the funnel when it is on the right of (or on) apex -> fl.
    if (cross(apex, fl, l) <= 0) {
      if (apex == fl || cross(apex, fr, l) >= 0) {
        fl = l;
        left_k = k;
      } else {
        apex = fr;
        apex_k = right_k;
        if (path.back() != apex) path.push_back(apex);
        fl = fr = apex;
        left_k = right_k = apex_k;
        k = apex_k;
        continue;
      }
    }
  }
  if (path.size() > 1 && path.back() == s) path.pop_back();
  return path;
}

double mlp_length(const DigitalContour& contour, double h) {
  auto v = minimum_length_polygon(contour);
  double len = 0;
  for (std::size_t i = 0; i < v.size(); ++i) {
    const Pixel& a = v[i];
    const Pixel& b = v[(i + 1) % v.size()];
    len += std::hypot(static_cast<double>(b.x - a.x), static_cast<double>(b.y - a.y));
  }
  return h * len;
}

} // namespace zdg
