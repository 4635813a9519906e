#include <zdg/estimators/lambda_mst.hpp>

#include <zdg/arith/error.hpp>
#include <zdg/kernel/curves/maximal_segments.hpp>

#include <cmath>
#include <limits>
#include <numbers>
#include <string>

namespace zdg {

double lambda_mst_weight(double t) {
  return 64.0 * (((((-t + 3.0) * t - 3.0) * t + 1.0) * t) * t * t);
}

std::vector<Point2<double>> lambda_mst_tangents(std::span<const Point2<std::int64_t>> points,
                                                bool closed) {
  const std::size_t n = points.size();
  std::vector<Point2<double>> out(n, Point2<double>{1.0, 0.0});
  if (n < 2) return out;
  const double nan = std::numeric_limits<double>::quiet_NaN();
  // Per point: a reference angle (the first segment of its pencil), the weighted and the
  // plain sums of the angle offsets.
  std::vector<double> ref(n, nan), wsum(n, 0), wdev(n, 0), dev(n, 0);
  std::vector<int> count(n, 0);
  for (const auto& s : maximal_segments_exact(points, closed).value) {
    const double theta = std::atan2(static_cast<double>(s.a), static_cast<double>(s.b));
    for (std::size_t k = 0; k < s.length; ++k) {
      const std::size_t i = (s.begin + k) % n;
      if (std::isnan(ref[i])) ref[i] = theta;
      double d = theta - ref[i];
      d -= 2 * std::numbers::pi * std::round(d / (2 * std::numbers::pi));
      const double w =
          s.length > 1 ? lambda_mst_weight(static_cast<double>(k) / double(s.length - 1)) : 0.0;
      wsum[i] += w;
      wdev[i] += w * d;
      dev[i] += d;
      ++count[i];
    }
  }
  for (std::size_t i = 0; i < n; ++i) {
    if (count[i] == 0) continue;
    const double a = ref[i] + (wsum[i] > 0 ? wdev[i] / wsum[i] : dev[i] / count[i]);
    out[i] = {std::cos(a), std::sin(a)};
  }
  return out;
}

double lambda_mst_length(std::span<const Point2<std::int64_t>> points, double h) {
  if (!(h > 0)) throw InvalidArgument("lambda_mst_length: grid step h = " + std::to_string(h));
  const std::size_t n = points.size();
  if (n < 2) return 0.0;
  auto t = lambda_mst_tangents(points, true);
  double len = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t j = (i + 1) % n;
    const double sx = static_cast<double>(points[j].x - points[i].x);
    const double sy = static_cast<double>(points[j].y - points[i].y);
    if (std::abs(sx) + std::abs(sy) != 1.0) {
      throw InvalidArgument("lambda_mst_length: the contour is not 4-connected at point " +
                            std::to_string(i));
    }
    double tx = t[i].x + t[j].x, ty = t[i].y + t[j].y;
    const double norm = std::hypot(tx, ty);
    if (norm > 0) len += std::abs(tx * sx + ty * sy) / norm;
  }
  return h * len;
}

} // namespace zdg
