// Distance of a digitized boundary to the true boundary, against the bound of Lachaud and
// Thibert ("Properties of Gauss digitized shapes for digital surface integration", JMIV
// 2016, Thm 1): if X has reach > rho and h < 2 rho / sqrt(d), the Hausdorff distance
// between dX and the boundary dX_h of its Gauss digitization is at most sqrt(d) h / 2.
//
// The sampled one-sided distance: for boundary elements with centres c_i (linel midpoints
// in 2D, surfel centres in 3D, all points of dX_h) and the projection xi onto dX (the
// nearest point), d_i = |c_i - xi(c_i)| and max_i d_i <= sqrt(d) h / 2 under the theorem's
// hypotheses. Cost: one projection per element. Floating point: the distances are not
// rational (xi is the root of a polynomial system); xi comes from the shape.
#pragma once

#include <zdg/arith/point.hpp>

#include <functional>
#include <span>
#include <vector>

namespace zdg {

/// sqrt(d) h / 2 (d = 2 or 3, h > 0; InvalidArgument otherwise).
double hausdorff_bound(int dimension, double h);

/// |c - xi(c)| for every centre.
std::vector<double> projection_distances(std::span<const Point2<double>> centres,
                                         const std::function<Point2<double>(Point2<double>)>& xi);
std::vector<double> projection_distances(std::span<const Point3<double>> centres,
                                         const std::function<Point3<double>(Point3<double>)>& xi);

/// The largest distance and the bound: holds when max_distance <= bound.
struct HausdorffCheck {
  double max_distance = 0;
  double bound = 0;
  bool holds() const { return max_distance <= bound; }
};

HausdorffCheck check_hausdorff_bound(std::span<const double> distances, int dimension, double h);

} // namespace zdg
