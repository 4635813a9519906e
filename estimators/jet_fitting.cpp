// The only translation unit of zdg that includes CGAL (Jet_fitting_3).
#include <zdg/arith/error.hpp>
#include <zdg/estimators/jet_fitting.hpp>
#include <zdg/kernel/parallel/parallel_for.hpp>

#include <CGAL/Monge_via_jet_fitting.h>
#include <CGAL/Simple_cartesian.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <numeric>
#include <string>

namespace zdg {

namespace {

using K = CGAL::Simple_cartesian<double>;
using Monge = CGAL::Monge_via_jet_fitting<K>;
using Cell = std::array<std::int64_t, 3>;

Cell cell_of(const Point3<double>& p, double side) {
  return {static_cast<std::int64_t>(std::floor(p.x / side)),
          static_cast<std::int64_t>(std::floor(p.y / side)),
          static_cast<std::int64_t>(std::floor(p.z / side))};
}

Point3<double> unit(const K::Vector_3& v) {
  const double n = std::sqrt(v.squared_length());
  return {v.x() / n, v.y() / n, v.z() / n};
}

void check_degree(int degree) {
  if (degree < 1 || degree > 4) {
    throw InvalidArgument("jet fitting: the degree must be 1, 2, 3 or 4 (got " +
                          std::to_string(degree) + ")");
  }
}

// The jet of degree `degree` fitted to nb, its Monge form at nb[0], n towards o.
JetEstimate fit_monge(std::span<const Point3<double>> nb, const Point3<double>& o, int degree) {
  const std::size_t coefficients = static_cast<std::size_t>((degree + 1) * (degree + 2) / 2);
  // Monge degree 2 carries the principal curvatures; degree 1 only the normal.
  const std::size_t monge_degree = degree >= 2 ? 2 : 1;
  JetEstimate e;
  e.neighbours = nb.size();
  if (nb.size() < coefficients) return e;
  std::vector<K::Point_3> pts;
  pts.reserve(nb.size());
  for (const auto& x : nb) pts.emplace_back(x.x, x.y, x.z);
  Monge fit;
  const auto form = fit(pts.begin(), pts.end(), static_cast<std::size_t>(degree), monge_degree);
  Point3<double> n = unit(form.normal_direction());
  // CGAL: k_max = coefficient 0 along d1, k_min along d2, both relative to n.
  double kmax = 0, kmin = 0;
  if (monge_degree >= 2) {
    kmax = form.principal_curvatures(0);
    kmin = form.principal_curvatures(1);
  }
  const Point3<double> dmax = unit(form.maximal_principal_direction()),
                       dmin = unit(form.minimal_principal_direction());
  if (n.x * o.x + n.y * o.y + n.z * o.z < 0) {
    n = {-n.x, -n.y, -n.z};
    kmax = -kmax;
    kmin = -kmin;
  }
  // With n outward, a convex surface bends away from n: CGAL's curvatures are negative there;
  // zdg's convention is positive.
  const double a = -kmax, b = -kmin; // a <= b
  e.ok = true;
  e.normal = n;
  e.k1 = std::min(a, b);
  e.k2 = std::max(a, b);
  e.d1 = a <= b ? dmax : dmin;
  e.d2 = a <= b ? dmin : dmax;
  return e;
}

} // namespace

JetEstimate jet_fit(std::span<const Point3<double>> neighbourhood, const Point3<double>& outward,
                    int degree) {
  check_degree(degree);
  return fit_monge(neighbourhood, outward, degree);
}

std::vector<JetEstimate> jet_fitting(std::span<const Point3<double>> points,
                                     std::span<const std::size_t> queries,
                                     std::span<const Point3<double>> outward, double radius,
                                     int degree, unsigned threads) {
  if (!(radius > 0) || !std::isfinite(radius)) {
    throw InvalidArgument("jet fitting: the radius must be positive and finite");
  }
  check_degree(degree);
  if (outward.size() != queries.size()) {
    throw InvalidArgument("jet fitting: one outward hint per query is needed");
  }
  // Points sorted by grid cell; a cell's points are an equal range.
  std::vector<std::pair<Cell, std::size_t>> sorted(points.size());
  for (std::size_t i = 0; i < points.size(); ++i) sorted[i] = {cell_of(points[i], radius), i};
  std::sort(sorted.begin(), sorted.end());
  std::vector<JetEstimate> out(queries.size());
  const double r2 = radius * radius;
  parallel_for(static_cast<std::int64_t>(queries.size()), static_cast<unsigned>(threads),
               [&](std::int64_t qi) {
                 const auto q = static_cast<std::size_t>(qi);
                 const Point3<double>& p = points[queries[q]];
                 const Cell c = cell_of(p, radius);
                 // CGAL computes the Monge form at the first point of the range: p itself.
                 std::vector<Point3<double>> nb{p};
                 for (std::int64_t dx = -1; dx <= 1; ++dx) {
                   for (std::int64_t dy = -1; dy <= 1; ++dy) {
                     for (std::int64_t dz = -1; dz <= 1; ++dz) {
                       const Cell cc{c[0] + dx, c[1] + dy, c[2] + dz};
                       auto lo = std::lower_bound(sorted.begin(), sorted.end(),
                                                  std::pair<Cell, std::size_t>{cc, 0});
                       for (auto it = lo; it != sorted.end() && it->first == cc; ++it) {
                         const auto& x = points[it->second];
                         const double ex = x.x - p.x, ey = x.y - p.y, ez = x.z - p.z;
                         if (it->second != queries[q] && ex * ex + ey * ey + ez * ez <= r2) {
                           nb.push_back(x);
                         }
                       }
                     }
                   }
                 }
                 out[q] = fit_monge(nb, outward[q], degree);
               });
  return out;
}

} // namespace zdg
