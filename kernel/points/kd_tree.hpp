// A kd-tree over a cloud of points of R^3 for k-nearest and fixed-radius queries: the
// neighbourhoods of the normal estimators on points and of the implicit reconstructions.
//
// Built by nanoflann (Debian libnanoflann-dev; Friedman, Bentley, Finkel, "An algorithm for
// finding best matches in logarithmic expected time", ACM TOMS 3(3), 1977), with zdg's own
// result sets so that the answer is a function of the points alone: distances are the squared
// Euclidean distances computed as (q.x - p.x)^2 + (q.y - p.y)^2 + (q.z - p.z)^2 in double, and
// results are ordered by (squared distance, index). `nearest(q, k)` returns the first k points
// of that order (all of them when k >= size()), exactly what sorting every point would give,
// ties included; `within(q, r)` returns every point with squared distance <= r * r.
//
// The tree keeps its own copy of the points (24 bytes each plus the index, about 40 bytes a
// point). Cost: building O(N log N); a query O(log N + k) expected on well-spread points.
// Queries are const and may run from several threads at once.
#pragma once

#include <zdg/arith/point.hpp>

#include <cstddef>
#include <memory>
#include <span>
#include <vector>

namespace zdg {

struct Neighbour {
  std::size_t index = 0;
  double distance2 = 0; ///< squared Euclidean distance to the query
};

class KdTree {
public:
  /// Builds the tree over a copy of the points (any number, none included).
  explicit KdTree(std::span<const Point3<double>> points);
  ~KdTree();
  KdTree(KdTree&&) noexcept;
  KdTree& operator=(KdTree&&) noexcept;
  KdTree(const KdTree&) = delete;
  KdTree& operator=(const KdTree&) = delete;

  std::size_t size() const;
  const Point3<double>& point(std::size_t i) const;

  /// The min(k, size()) first points in the order (squared distance to q, index), into out
  /// (cleared first).
  void nearest(const Point3<double>& q, std::size_t k, std::vector<Neighbour>& out) const;
  /// Every point at squared distance <= r * r from q, in the order (squared distance, index),
  /// into out (cleared first). r < 0 gives none.
  void within(const Point3<double>& q, double r, std::vector<Neighbour>& out) const;

private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

} // namespace zdg
