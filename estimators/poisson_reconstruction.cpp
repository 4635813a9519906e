// The Poisson field of estimators/implicit_reconstruction.hpp through CGAL (the only
// translation unit that includes CGAL's Poisson reconstruction).
#include <zdg/arith/error.hpp>
#include <zdg/estimators/implicit_reconstruction.hpp>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Poisson_reconstruction_function.h>
#include <CGAL/property_map.h>

#include <utility>
#include <vector>

namespace zdg {

ImplicitField poisson_field(const PointCloud& cloud, const SampleGrid& grid, unsigned threads) {
  (void)threads; // CGAL's hint makes the samples' order matter: sampled in one thread
  using K = CGAL::Exact_predicates_inexact_constructions_kernel;
  using Pwn = std::pair<K::Point_3, K::Vector_3>;
  validate_point_cloud(cloud, "reconstruct");
  if (!cloud.has_normals()) throw InvalidArgument("reconstruct: poisson needs oriented normals");
  if (cloud.size() < 7)
    throw InvalidArgument("reconstruct: poisson needs at least 7 points (" +
                          std::to_string(cloud.size()) + " given)");
  std::vector<Pwn> pts;
  pts.reserve(cloud.size());
  for (std::size_t i = 0; i < cloud.size(); ++i) {
    const auto& p = cloud.points[i];
    const auto& n = cloud.normals[i];
    pts.emplace_back(K::Point_3(p.x, p.y, p.z), K::Vector_3(n.x, n.y, n.z));
  }
  CGAL::Poisson_reconstruction_function<K> f(pts.begin(), pts.end(),
                                             CGAL::First_of_pair_property_map<Pwn>(),
                                             CGAL::Second_of_pair_property_map<Pwn>());
  if (!f.compute_implicit_function())
    throw Error("reconstruct: CGAL's Poisson solver did not converge");
  ImplicitField out{grid, std::vector<double>(static_cast<std::size_t>(grid.size()))};
  for (std::int64_t v = 0; v < grid.size(); ++v) {
    const auto q = grid.at(v);
    out.values[std::size_t(v)] = CGAL::to_double(f(K::Point_3(q.x, q.y, q.z)));
  }
  return out;
}

} // namespace zdg
