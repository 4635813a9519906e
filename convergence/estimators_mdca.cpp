// The MDCA curvature estimator of the registry (mdca-curvature): the curvature of the most
// centred maximal digital circular arc at every linel (estimators/mdca_curvature.hpp), compared
// with the shape's curvature at the projection of the linel midpoint, like ii-curvature.
#include <zdg/convergence/digitized_2d.hpp>
#include <zdg/convergence/estimator.hpp>
#include <zdg/estimators/mdca_curvature.hpp>
#include <zdg/kernel/curves/digital_contour.hpp>

#include <utility>
#include <vector>

namespace zdg {

namespace {

ErrorStats run_mdca_curvature(const RunInput& in) {
  const detail::Digitized2 d = detail::digitize_2d(in);
  ErrorAccumulator acc;
  for (const auto& c : d.contours) {
    if (c.size() < 4) continue;
    const auto kappa = mdca_curvature(c, in.h);
    std::vector<Point2<double>> mid;
    mid.reserve(c.size());
    Pixel p = c.start;
    for (auto code : c.codes) {
      const Point2<double> m = d.embed.linel_midpoint(p, code);
      mid.push_back({m.x - d.t.x, m.y - d.t.y});
      const Pixel s = freeman_step(code);
      p = Pixel{p.x + s.x, p.y + s.y};
    }
    const auto truth = d.shape->project_chain(mid);
    for (std::size_t i = 0; i < c.size(); ++i) acc.add(kappa[i] - truth[i].curvature);
  }
  return acc.stats();
}

} // namespace

namespace detail {

void register_mdca_estimators(std::vector<Estimator>& out) {
  out.push_back(
      {"mdca-curvature",
       2,
       "curvature of the separating circle of the most centred maximal digital circular arc at "
       "every linel (Roussillon, Lachaud 2011)",
       "curvature",
       {},
       {"none proven under the registry's hypotheses: Roussillon and Lachaud (IWCIA 2011) report "
        "experimental convergence only (papers/THEORY.md)",
        [](const ShapeClass&, const EstimatorParameters&) -> std::optional<ProvenRate> {
          return std::nullopt;
        }},
       run_mdca_curvature});
}

} // namespace detail

} // namespace zdg
