// The digital disc of radius rho (in pixels): D = { d in Z^2 : |d|^2 <= rho^2 }, stored as its
// row half-widths w(dy) = max { dx : dx^2 + dy^2 <= rho^2 } for |dy| <= r = floor(rho). D is
// 4-connected and digitally convex, its rows are centred intervals and w is non-increasing in
// |dy|, so a rectangle lies in D iff its row farthest from the centre does, and misses D iff
// its row nearest to the centre does (both O(1)).
//
// The half-widths come from a double square root corrected by exact integer comparisons,
// so they are exact for rho <= 1e8 (dy^2 + dx^2 < 2^63); larger radii are refused.
#pragma once

#include <zdg/arith/error.hpp>
#include <zdg/kernel/digitization/gauss_digitization.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <string>
#include <vector>

namespace zdg {

struct DigitalDisc {
  std::int64_t r = 0;          // floor(rho): rows dy in [-r, r]
  std::vector<std::int64_t> w; // half-width of row dy, index dy + r
  std::int64_t size = 0;       // number of pixels

  explicit DigitalDisc(double rho) {
    if (!(rho >= 0) || rho > 1e8) {
      throw InvalidArgument("digital disc radius " + std::to_string(rho) +
                            " pixels is out of range [0, 1e8]");
    }
    const double r2 = rho * rho;
    auto fits = [r2](std::int64_t a, std::int64_t b) {
      return static_cast<double>(a * a + b * b) <= r2;
    };
    r = static_cast<std::int64_t>(std::floor(rho));
    while (fits(r + 1, 0)) ++r;
    while (r > 0 && !fits(r, 0)) --r;
    w.resize(static_cast<std::size_t>(2 * r + 1));
    for (std::int64_t dy = -r; dy <= r; ++dy) {
      auto x =
          static_cast<std::int64_t>(std::floor(std::sqrt(std::max(0.0, r2 - double(dy * dy)))));
      while (fits(x + 1, dy)) ++x;
      while (x > 0 && !fits(x, dy)) --x;
      w[static_cast<std::size_t>(dy + r)] = x;
      size += 2 * x + 1;
    }
  }

  std::int64_t half_width(std::int64_t dy) const { return w[static_cast<std::size_t>(dy + r)]; }
  /// d in D.
  bool contains(std::int64_t dx, std::int64_t dy) const {
    return dy >= -r && dy <= r && std::llabs(dx) <= half_width(dy);
  }
  /// The rectangle [x0, x1] x [y0, y1] (offsets from the centre, x0 <= x1, y0 <= y1) lies in D.
  bool contains_rect(std::int64_t x0, std::int64_t x1, std::int64_t y0, std::int64_t y1) const {
    const std::int64_t far_y = std::max(std::llabs(y0), std::llabs(y1));
    return far_y <= r && std::max(std::llabs(x0), std::llabs(x1)) <= half_width(far_y);
  }
  /// The rectangle misses D.
  bool misses_rect(std::int64_t x0, std::int64_t x1, std::int64_t y0, std::int64_t y1) const {
    const std::int64_t near_y = y0 > 0 ? y0 : (y1 < 0 ? -y1 : 0);
    if (near_y > r) return true;
    const std::int64_t hw = half_width(near_y);
    return x0 > hw || x1 < -hw;
  }
};

/// D as a Gauss digitization centred at the origin (for contour tracking).
class DigitalDiscSet final : public GaussDigitization2 {
public:
  explicit DigitalDiscSet(const DigitalDisc& d)
      : GaussDigitization2(Box2{{-d.r - 2, -d.r - 2}, {d.r + 2, d.r + 2}}), d_(d) {}

protected:
  bool inside(const Pixel& z) const override { return d_.contains(z.x, z.y); }

private:
  const DigitalDisc& d_;
};

} // namespace zdg
