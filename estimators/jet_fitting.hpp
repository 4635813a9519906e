// Osculating-jet fitting on a point cloud: normals and principal curvatures at each point from
// the degree-d polynomial height function fitted by least squares to its neighbours in a ball.
//
//   At a point p, the points of the cloud within distance R of p are expressed in a frame of
//   their principal component analysis, the height function z = J(x, y) of degree d (a
//   "d-jet", (d + 1)(d + 2)/2 coefficients) is fitted by least squares, and its Monge form
//   (the tangent frame where J has no linear and no xy term) gives the normal n and the
//   principal curvatures and directions (Cazals, Pouget, "Estimating differential quantities
//   using polynomial fitting of osculating jets", CAGD 22, 2005). The fit and the Monge
//   form are CGAL's Monge_via_jet_fitting (CGAL::Jet_fitting_3, Eigen's SVD); only the
//   neighbourhoods are zdg's: a uniform grid of cells of side R, 27 cells per query (the
//   query point first: CGAL computes the Monge form at the first point of its range).
// Orientation: n is turned towards the given outward hint (for a digital surface, the
//   surfel's elementary normal pointing out of the object), and curvatures are then signed
//   as in the rest of zdg: positive on convex parts (a sphere of radius r has k1 = k2 = 1/r),
//   k1 <= k2.
// Rates: Cazals and Pouget prove O(r^{d-k+1}) for the k-th order quantities of a jet of
//   degree d on exact samples at spacing r; on digital surfaces (samples off the surface by
//   up to h) no rate is proven (the driver reports the fit without a verdict).
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

} // namespace zdg
