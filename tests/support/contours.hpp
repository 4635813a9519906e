// Test and benchmark helper: the 4-connected contour of pointels (counter-clockwise, start not
// repeated) of the union of the unit squares centred on the pixels of a column-convex set
// given by its columns [bottom(x), top(x)], x = x0 .. x0 + n - 1. Pointel (X, Y) is the corner
// (X - 1/2, Y - 1/2): pixel x spans X in [x, x + 1].
#pragma once

#include <zdg/arith/point.hpp>

#include <cmath>
#include <cstdint>
#include <vector>

namespace zdg::test {

inline std::vector<Point2<std::int64_t>>
column_convex_contour(std::int64_t x0, const std::vector<std::int64_t>& bottom,
                      const std::vector<std::int64_t>& top) {
  std::vector<Point2<std::int64_t>> c;
  const std::int64_t n = static_cast<std::int64_t>(bottom.size());
  auto col = [&](std::int64_t k) { return static_cast<std::size_t>(k); };
  std::int64_t X = x0, Y = bottom[0];
  auto go = [&](std::int64_t tx, std::int64_t ty) {
    while (X != tx || Y != ty) {
      c.push_back({X, Y});
      if (X != tx) {
        X += tx > X ? 1 : -1;
      } else {
        Y += ty > Y ? 1 : -1;
      }
    }
  };
  for (std::int64_t k = 0; k < n; ++k) {
    go(x0 + k, bottom[col(k)]);
    go(x0 + k + 1, bottom[col(k)]);
  }
  go(x0 + n, top[col(n - 1)] + 1);
  for (std::int64_t k = n - 1; k >= 0; --k) {
    go(x0 + k + 1, top[col(k)] + 1);
    go(x0 + k, top[col(k)] + 1);
  }
  go(x0, bottom[0]);
  return c;
}

inline std::int64_t isqrt(std::int64_t v) {
  auto r = static_cast<std::int64_t>(std::sqrt(static_cast<double>(v)));
  while (r * r > v) --r;
  while ((r + 1) * (r + 1) <= v) ++r;
  return r;
}

/// Contour of the digital disc (x - cx)^2 + (y - cy)^2 <= r2.
inline std::vector<Point2<std::int64_t>> disc_contour(std::int64_t cx, std::int64_t cy,
                                                      std::int64_t r2) {
  std::int64_t r = isqrt(r2);
  std::vector<std::int64_t> bottom, top;
  for (std::int64_t x = -r; x <= r; ++x) {
    std::int64_t h = isqrt(r2 - x * x);
    bottom.push_back(cy - h);
    top.push_back(cy + h);
  }
  return column_convex_contour(cx - r, bottom, top);
}

} // namespace zdg::test
