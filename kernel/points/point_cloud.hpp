// A cloud of points of R^3, optionally with one normal per point: the input of the normal
// estimators on points (estimators/point_normals.hpp) and of the implicit reconstructions
// (estimators/implicit_reconstruction.hpp), read by kernel/io/point_cloud_io.hpp.
//
// Invariants checked by validate_point_cloud: at least one point, every coordinate finite,
// normals empty or one per point, each finite and of non-zero length, no point given twice
// (equal coordinates, compared exactly). Cost: O(N log N) (a sort for the duplicates).
#pragma once

#include <zdg/arith/point.hpp>

#include <cstddef>
#include <string>
#include <vector>

namespace zdg {

struct PointCloud {
  std::vector<Point3<double>> points;
  std::vector<Point3<double>> normals; ///< empty, or one per point (not necessarily unit)

  std::size_t size() const { return points.size(); }
  bool has_normals() const { return !normals.empty(); }
};

/// Throws InvalidArgument "SOURCE: what was wrong" (empty cloud, a non-finite coordinate or
/// normal naming the point, a zero normal, a normal count that is not the point count, two
/// equal points naming both indices).
void validate_point_cloud(const PointCloud& cloud, const std::string& source);

/// The axis-aligned bounding box of the points (lo, hi); InvalidArgument when empty.
struct PointBounds {
  Point3<double> lo, hi;
  double diagonal() const;
};
PointBounds point_bounds(const PointCloud& cloud);

} // namespace zdg
