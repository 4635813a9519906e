#include <zdg/estimators/hausdorff.hpp>

#include <zdg/arith/error.hpp>

#include <algorithm>
#include <cmath>
#include <string>

namespace zdg {

double hausdorff_bound(int dimension, double h) {
  if (dimension != 2 && dimension != 3) {
    throw InvalidArgument("hausdorff_bound: dimension " + std::to_string(dimension) +
                          " is not 2 or 3");
  }
  if (!(h > 0) || !std::isfinite(h)) {
    throw InvalidArgument("hausdorff_bound: grid step " + std::to_string(h) + " is not > 0");
  }
  return std::sqrt(double(dimension)) * h / 2;
}

std::vector<double> projection_distances(std::span<const Point2<double>> centres,
                                         const std::function<Point2<double>(Point2<double>)>& xi) {
  std::vector<double> out;
  out.reserve(centres.size());
  for (const auto& c : centres) {
    const auto q = xi(c);
    out.push_back(std::hypot(c.x - q.x, c.y - q.y));
  }
  return out;
}

std::vector<double> projection_distances(std::span<const Point3<double>> centres,
                                         const std::function<Point3<double>(Point3<double>)>& xi) {
  std::vector<double> out;
  out.reserve(centres.size());
  for (const auto& c : centres) {
    const auto q = xi(c);
    out.push_back(std::hypot(c.x - q.x, c.y - q.y, c.z - q.z));
  }
  return out;
}

HausdorffCheck check_hausdorff_bound(std::span<const double> distances, int dimension, double h) {
  HausdorffCheck c;
  c.bound = hausdorff_bound(dimension, h);
  for (double d : distances) {
    if (std::isnan(d)) return {d, c.bound}; // a NaN distance never satisfies the bound
    c.max_distance = std::max(c.max_distance, d);
  }
  return c;
}

} // namespace zdg
