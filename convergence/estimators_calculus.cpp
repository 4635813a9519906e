// Estimators of the registry from the calculus on digital surfaces (#14): di-area, the digital
// integral of 1 with the surfel measure of the integral-invariant normal (estimators/
// digital_integration.hpp), compared with the shape's area in closed form.
#include <zdg/arith/error.hpp>
#include <zdg/convergence/digitized_3d.hpp>
#include <zdg/convergence/estimator.hpp>
#include <zdg/estimators/digital_integration.hpp>
#include <zdg/estimators/ii_3d.hpp>

#include <cmath>

namespace zdg {

namespace {

// DI_h(1) = sum over the boundary surfels of h^2 n_II(s) . n_elem(s), minus the area. The
// whole surface must be digitized: a box that clips the shape cuts the integral.
ErrorStats run_di_area(const RunInput& in) {
  const auto& shape = detail::as_3d(in.shape);
  const auto area = shape.area();
  if (!area) throw InvalidArgument("the area of '" + in.shape.spec() + "' is not known");
  const detail::Digitized3 d = detail::digitize_3d(in);
  for (bool c : d.clipped) {
    if (c) {
      throw InvalidArgument("di-area: the box clips '" + in.shape.spec() +
                            "': the digital integral needs the whole surface");
    }
  }
  const double R = in.k * std::pow(in.h, in.alpha);
  const auto ii = ii_principal_curvatures(d.inside, d.box, d.surfels, in.h, R, 1);
  std::vector<Point3<double>> estimated, elementary;
  estimated.reserve(ii.size());
  elementary.reserve(ii.size());
  for (std::size_t i = 0; i < ii.size(); ++i) {
    estimated.push_back(ii[i].normal);
    const auto n = trivial_normal(d.surfels[i]);
    elementary.push_back({double(n.x), double(n.y), double(n.z)});
  }
  const auto mu = surfel_measure(estimated, elementary);
  const std::vector<double> areas(mu.size(), in.h * in.h), one(mu.size(), 1.0);
  ErrorAccumulator acc;
  acc.add(digital_integral(surfel_weights(mu, areas), one) - *area);
  return acc.stats();
}

} // namespace

namespace detail {

void register_calculus_estimators(std::vector<Estimator>& out) {
  out.push_back(
      {"di-area",
       3,
       "digital integral of 1: sum over the surfels of h^2 n_II . n_elem (II normal, R = k "
       "h^alpha), against the area in closed form",
       "area",
       radius_law_parameters(),
       {"O(h^{2/3}) with the II normal (R = k h^{1/3}) on C^3 surfaces with positive reach "
        "(Lachaud, Thibert, JMIV 2016: O(h) + O(normal error))",
        [](const ShapeClass& c, const EstimatorParameters& p) -> std::optional<ProvenRate> {
          if (c.c3 && is_one_third(p.alpha)) {
            return ProvenRate{2.0 / 3.0, "O(h^{2/3})",
                              "C^3 surface with positive reach, II normal with R = k h^{1/3}",
                              "Lachaud, Thibert, JMIV 2016; Coeurjolly, Lachaud, Levallois, "
                              "CVIU 2014"};
          }
          return std::nullopt;
        }},
       run_di_area});
}

} // namespace detail

} // namespace zdg
