// Osculating-jet fitting on a point cloud: normals and principal curvatures at each point from
// the degree-d polynomial height function fitted by least squares to its neighbours in a ball.
//
//   The points within R of p, in their PCA frame, are fitted by a height function of degree d
//   ((d + 1)(d + 2)/2 coefficients) whose Monge form gives n and the principal curvatures and
//   directions (Cazals, Pouget, CAGD 22, 2005). Fit and Monge form: CGAL's Jet_fitting_3 (Eigen
//   SVD); the neighbourhoods: a grid of cells of side R, 27 cells per query, query point first.
// Orientation: n is turned towards the given outward hint (for a digital surface, the
//   surfel's elementary normal pointing out of the object), and curvatures are then signed
//   as in the rest of zdg: positive on convex parts (a sphere of radius r has k1 = k2 = 1/r),
//   k1 <= k2.
// Rates: O(r^{d-k+1}) on exact samples at spacing r (Cazals and Pouget); none proven on digital
//   surfaces (the driver reports the fit without a verdict).
// Complexity: O(n m d^4 + n m) for n queries of m neighbours (an SVD of an m x (d+1)(d+2)/2
//   system each), after an O(N log N) grid sort; threads through parallel_for.
// Input: R > 0, 1 <= d <= 4 (monge degree min(d, 4)); a query with fewer neighbours than the
//   jet has coefficients gets ok = false (InvalidArgument for bad parameters).
#pragma once

#include <zdg/arith/point.hpp>

#include <span>
#include <vector>

namespace zdg {

struct JetEstimate {
  bool ok = false;            // enough neighbours for the jet
  Point3<double> normal{};    // unit, towards the outward hint
  double k1 = 0, k2 = 0;      // principal curvatures, k1 <= k2, convex > 0
  Point3<double> d1{}, d2{};  // unit principal directions of k1, k2
  std::size_t neighbours = 0; // points in the ball
  double mean() const { return (k1 + k2) / 2; }
  double gaussian() const { return k1 * k2; }
};

/// Jet fitting at points[queries[i]] for each i, on the neighbours in the closed ball of
/// radius `radius` among all `points`; outward[i] orients the normal of query i.
std::vector<JetEstimate> jet_fitting(std::span<const Point3<double>> points,
                                     std::span<const std::size_t> queries,
                                     std::span<const Point3<double>> outward, double radius,
                                     int degree, unsigned threads = 0);

/// Jet fitting on one given neighbourhood (the k nearest of a point cloud, for instance):
/// neighbourhood[0] is the point where the Monge form is taken, the others its neighbours;
/// the normal is turned towards `outward`. ok = false when there are fewer points than the jet
/// has coefficients ((d + 1)(d + 2)/2); InvalidArgument for a degree outside 1..4.
JetEstimate jet_fit(std::span<const Point3<double>> neighbourhood, const Point3<double>& outward,
                    int degree);

} // namespace zdg
