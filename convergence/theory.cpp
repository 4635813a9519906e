#include "convergence/theory.hpp"

#include <cmath>

namespace zdg {

std::optional<TheoryRate> theory_rate(const std::string& estimator, const Shape& shape,
                                      double alpha) {
  const std::string spec = shape.spec();
  const std::string kind = spec.substr(0, spec.find(':'));
  const bool smooth_convex = kind == "ball" || kind == "ellipse"; // C^3 strictly convex
  const bool polygon = kind == "polygon";
  const bool smooth = smooth_convex || kind == "flower" || kind == "poly"; // C^3 (poly: assumed)
  if (estimator == "gauss-area") {
    if (smooth_convex) {
      return TheoryRate{15.0 / 11.0, "O(h^{15/11} log^{47/22}(1/h)) for C^3 strictly convex shapes",
                        "Huxley 1990"};
    }
    if (polygon) return TheoryRate{1.0, "O(h) for convex shapes", "Gauss, Dirichlet"};
    return std::nullopt;
  }
  if (estimator == "moments") {
    if (smooth_convex || polygon) {
      return TheoryRate{1.0, "O(h) for C^3 piecewise strictly convex shapes",
                        "Coeurjolly, Lachaud, Roussillon 2012"};
    }
    return std::nullopt;
  }
  if (estimator == "mlp-length") {
    if (smooth_convex || polygon) {
      return TheoryRate{1.0, "O(h) for convex shapes", "Klette-Rosenfeld 2004; DGA 2012 survey"};
    }
    return std::nullopt;
  }
  if (estimator == "ii-curvature") {
    if (smooth && std::abs(alpha - 1.0 / 3.0) < 1e-12) {
      return TheoryRate{1.0 / 3.0,
                        "O(h^{1/3}) with R = k h^{1/3}, C^3 boundary with positive reach",
                        "Coeurjolly, Lachaud, Levallois, DGCI 2013 / CVIU 2014"};
    }
    return std::nullopt;
  }
  if (estimator == "bc-tangent" && smooth) {
    return TheoryRate{2.0 / 3.0, "O(h^{2/3}) with mask ~ h^{-4/3}, C^3 curves",
                      "Esbelin, Malgouyres, Cartade 2011"};
  }
  if (estimator == "bc-curvature" && smooth) {
    return TheoryRate{4.0 / 9.0, "O(h^{4/9}) with mask ~ h^{-4/3}, C^3 curves",
                      "Esbelin, Malgouyres, Cartade 2011"};
  }
  return std::nullopt;
}

} // namespace zdg
