#include <zdg/estimators/dss_length.hpp>

#include <zdg/arith/error.hpp>
#include <zdg/kernel/curves/maximal_segments.hpp>

#include <cmath>
#include <string>

namespace zdg {

double dss_length(std::span<const Point2<std::int64_t>> points, bool closed, double h) {
  if (!(h > 0)) throw InvalidArgument("dss_length: grid step h = " + std::to_string(h));
  if (points.size() < 2) return 0.0;
  double len = 0;
  for (const auto& s : greedy_segmentation_exact(points, closed).value) {
    const auto& p = points[s.begin];
    const auto& q = points[s.end];
    len += std::hypot(static_cast<double>(q.x - p.x), static_cast<double>(q.y - p.y));
  }
  return h * len;
}

} // namespace zdg
