#include <zdg/arith/error.hpp>
#include <zdg/kernel/points/point_cloud.hpp>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <sstream>

namespace zdg {
namespace {

bool finite(const Point3<double>& p) {
  return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z);
}

std::string text(const Point3<double>& p) {
  std::ostringstream out;
  out.precision(17);
  out << p.x << ' ' << p.y << ' ' << p.z;
  return out.str();
}

} // namespace

void validate_point_cloud(const PointCloud& cloud, const std::string& source) {
  const std::size_t n = cloud.points.size();
  if (n == 0) throw InvalidArgument(source + ": no points");
  for (std::size_t i = 0; i < n; ++i) {
    if (!finite(cloud.points[i]))
      throw InvalidArgument(source + ": point " + std::to_string(i) +
                            " has a coordinate that is not finite (" + text(cloud.points[i]) + ")");
  }
  if (!cloud.normals.empty()) {
    if (cloud.normals.size() != n)
      throw InvalidArgument(source + ": " + std::to_string(cloud.normals.size()) + " normals for " +
                            std::to_string(n) + " points");
    for (std::size_t i = 0; i < n; ++i) {
      const auto& v = cloud.normals[i];
      if (!finite(v))
        throw InvalidArgument(source + ": the normal of point " + std::to_string(i) +
                              " is not finite (" + text(v) + ")");
      if (v.x == 0 && v.y == 0 && v.z == 0)
        throw InvalidArgument(source + ": the normal of point " + std::to_string(i) + " is zero");
    }
  }
  std::vector<std::size_t> order(n);
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    const auto& p = cloud.points[a];
    const auto& q = cloud.points[b];
    if (p.x != q.x) return p.x < q.x;
    if (p.y != q.y) return p.y < q.y;
    if (p.z != q.z) return p.z < q.z;
    return a < b;
  });
  for (std::size_t k = 1; k < n; ++k) {
    const auto a = order[k - 1], b = order[k];
    if (cloud.points[a] == cloud.points[b])
      throw InvalidArgument(source + ": point " + std::to_string(b) + " repeats point " +
                            std::to_string(a) + " (" + text(cloud.points[a]) + ")");
  }
}

double PointBounds::diagonal() const {
  return std::sqrt((hi.x - lo.x) * (hi.x - lo.x) + (hi.y - lo.y) * (hi.y - lo.y) +
                   (hi.z - lo.z) * (hi.z - lo.z));
}

PointBounds point_bounds(const PointCloud& cloud) {
  if (cloud.points.empty()) throw InvalidArgument("point bounds: no points");
  PointBounds b{cloud.points[0], cloud.points[0]};
  for (const auto& p : cloud.points) {
    b.lo = {std::min(b.lo.x, p.x), std::min(b.lo.y, p.y), std::min(b.lo.z, p.z)};
    b.hi = {std::max(b.hi.x, p.x), std::max(b.hi.y, p.y), std::max(b.hi.z, p.z)};
  }
  return b;
}

} // namespace zdg
