#include <zdg/estimators/mdss_curvature.hpp>

#include <zdg/arith/error.hpp>
#include <zdg/kernel/curves/maximal_segments.hpp>

#include <algorithm>
#include <cmath>
#include <string>

namespace zdg {

std::vector<double> mdss_curvature(std::span<const Point2<std::int64_t>> points, double h) {
  if (!(h > 0)) throw InvalidArgument("mdss_curvature: grid step h = " + std::to_string(h));
  const std::size_t n = points.size();
  std::vector<double> kappa(n, 0.0);
  if (n < 3) return kappa;
  // Reach of the half-tangents at each point, in points along the curve.
  std::vector<std::size_t> forward(n, 0), backward(n, 0);
  for (const auto& s : maximal_segments_exact(points, true).value) {
    for (std::size_t k = 0; k < s.length; ++k) {
      const std::size_t i = (s.begin + k) % n;
      forward[i] = std::max(forward[i], s.length - 1 - k);
      backward[i] = std::max(backward[i], k);
    }
  }
  for (std::size_t i = 0; i < n; ++i) {
    const auto& p = points[i];
    const auto& f = points[(i + forward[i]) % n];
    const auto& b = points[(i + n - backward[i] % n) % n];
    const double ux = double(p.x - b.x), uy = double(p.y - b.y);
    const double vx = double(f.x - p.x), vy = double(f.y - p.y);
    const double wx = double(f.x - b.x), wy = double(f.y - b.y);
    const double denom = std::hypot(ux, uy) * std::hypot(vx, vy) * std::hypot(wx, wy);
    kappa[i] = denom > 0 ? 2.0 * (ux * vy - uy * vx) / denom / h : 0.0;
  }
  return kappa;
}

} // namespace zdg
