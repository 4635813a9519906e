// The plane-probing normal estimator of the registry (estimators/probing_normal.hpp): the
// R-algorithm, the one Lachaud, Meyron, Roussillon (JMIV 62, 2020) recommend (reduced bases,
// far fewer steps than H), at every boundary surfel with the predicate "x is a voxel of the
// digitized shape", compared with the true normal at the projection xi of the surfel centre
// (oriented angle: both normals point outward). Exact on digital planes; no rate is proven on
// curved surfaces, so no theory check applies.
#include <zdg/convergence/digitized_3d.hpp>
#include <zdg/convergence/estimator.hpp>
#include <zdg/estimators/probing_normal.hpp>

#include <cmath>
#include <vector>

namespace zdg {

namespace {

double angle(const Point3<double>& a, const Point3<double>& b) {
  const double cx = a.y * b.z - a.z * b.y, cy = a.z * b.x - a.x * b.z, cz = a.x * b.y - a.y * b.x;
  return std::atan2(std::sqrt(cx * cx + cy * cy + cz * cz), a.x * b.x + a.y * b.y + a.z * b.z);
}

ErrorStats run_probing_normal(const RunInput& in) {
  const detail::Digitized3 d = detail::digitize_3d(in);
  // Probes stay near the surface on the shapes of the registry; surfels within 4 voxels of a
  // face where the shape is clipped see the cut.
  const auto surfels = detail::evaluated_surfels(d, 4 * in.h);
  const auto est = probing_normals(d.inside, d.box, surfels, ProbingAlgorithm::r, 1);
  ErrorAccumulator acc;
  for (std::size_t i = 0; i < surfels.size(); ++i) {
    const auto c = surfel_centre(surfels[i], in.h);
    const auto truth = d.shape->project({c.x - d.t.x, c.y - d.t.y, c.z - d.t.z});
    acc.add(angle(est[i].normal, truth.normal));
  }
  return acc.stats();
}

} // namespace

namespace detail {

void register_probing_estimators(std::vector<Estimator>& out) {
  out.push_back({"probing-normal",
                 3,
                 "plane-probing normal (R-algorithm) at every surfel, probing the digitized "
                 "set from a tetrahedron on the surfel; parameter-free",
                 "angle (rad)",
                 {},
                 {"none proven on curved surfaces: exact on digital planes (Lachaud, Provencal, "
                  "Roussillon, JMIV 2017; Lachaud, Meyron, Roussillon, JMIV 2020)",
                  {}},
                 run_probing_normal});
}

} // namespace detail

} // namespace zdg
