#include <zdg/kernel/calculus/hodge_star.hpp>

#include <zdg/arith/error.hpp>

#include <cmath>
#include <limits>
#include <string>

namespace zdg {

HodgeStars hodge_stars(const SurfelComplex& c, CellMeasure measure,
                       std::span<const Point3<double>> normals) {
  HodgeStars h;
  h.measure = measure;
  const auto nf = std::size_t(c.surfel_count()), ne = std::size_t(c.linel_count()),
             nv = std::size_t(c.pointel_count());
  if (measure == CellMeasure::cubical) {
    h.surfel_measure.assign(nf, 1.0);
    h.linel_measure.assign(ne, 1.0);
    h.dual_linel_measure.assign(ne, 1.0);
    h.dual_pointel_measure.assign(nv, 1.0);
  } else {
    if (normals.size() != nf)
      throw InvalidArgument("hodge stars: " + std::to_string(normals.size()) + " normals for " +
                            std::to_string(nf) + " surfels");
    h.surfel_measure.resize(nf);
    for (std::size_t s = 0; s < nf; ++s) {
      const auto& n = normals[s];
      if (!std::isfinite(n.x) || !std::isfinite(n.y) || !std::isfinite(n.z))
        throw InvalidArgument("hodge stars: the normal of surfel " + std::to_string(s) +
                              " is not finite");
      const double mu = dot(n, c.normals[s]);
      h.surfel_measure[s] =
          c.areas[s] *
          (measure == CellMeasure::corrected_clamped ? std::max(0.0, mu) : std::abs(mu));
    }
    h.linel_measure.resize(ne);
    h.dual_linel_measure.resize(ne);
    for (std::size_t e = 0; e < ne; ++e) {
      const auto& l = c.linels[e];
      const auto d = c.pointels[std::size_t(l.b)] - c.pointels[std::size_t(l.a)];
      const double len = std::sqrt(dot(d, d));
      h.linel_measure[e] = len;
      h.dual_linel_measure[e] =
          (h.surfel_measure[std::size_t(l.face[0])] + h.surfel_measure[std::size_t(l.face[1])]) /
          (2 * len);
    }
    h.dual_pointel_measure.assign(nv, 0.0);
    for (std::size_t s = 0; s < nf; ++s)
      for (auto p : c.surfels[s]) h.dual_pointel_measure[std::size_t(p)] += h.surfel_measure[s] / 4;
  }
  h.star0 = h.dual_pointel_measure;
  h.star1.resize(ne);
  for (std::size_t e = 0; e < ne; ++e) h.star1[e] = h.dual_linel_measure[e] / h.linel_measure[e];
  h.star2.resize(nf);
  for (std::size_t s = 0; s < nf; ++s)
    h.star2[s] =
        h.surfel_measure[s] > 0 ? 1 / h.surfel_measure[s] : std::numeric_limits<double>::infinity();
  return h;
}

} // namespace zdg
