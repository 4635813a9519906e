#include <zdg/convergence/theory.hpp>

#include <algorithm>
#include <cmath>

namespace zdg {

std::optional<TheoryRate> theory_rate(const std::string& estimator, const Shape& shape,
                                      double alpha) {
  std::string spec = shape.spec();
  // unprojected:SHAPE is SHAPE with its ground truth at the surfel centre: same rates.
  if (spec.rfind("unprojected:", 0) == 0) spec = spec.substr(12);
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
  if (estimator == "dss-length" && polygon) {
    return TheoryRate{1.0, "O(h) on convex polygons", "DGA 2012 survey"};
  }
  if (estimator == "lmst-length" && smooth_convex) {
    return TheoryRate{1.0 / 3.0, "O(h^{1/3}) for C^3 piecewise strictly convex curves",
                      "Lachaud, Vialard, de Vieilleville 2007"};
  }
  if (estimator == "lmst-tangent" && smooth_convex) {
    return TheoryRate{1.0 / 3.0, "O(h^{1/3}) for C^3 convex curves, parameter-free",
                      "Lachaud, Vialard, de Vieilleville 2007"};
  }
  // 3D shapes (convergence/shapes_3d.hpp). poly: with z is assumed C^3 with positive reach,
  // as in 2D; diabolo (singular at 0), heart (cusps) and crixxi are not; distel and the
  // cylinder are clipped by the box, which their estimators avoid (digitized_3d.hpp).
  const bool sphere = kind == "sphere1" || kind == "sphere9";
  const bool convex3 = sphere || kind == "ellipsoid" || kind == "rcube";
  const bool smooth3 = convex3 || kind == "torus" || kind == "goursat" || kind == "goursat-hole" ||
                       kind == "leopold" || kind == "cylinder" ||
                       (kind == "poly" && shape.dimension() == 3);
  const bool third = std::abs(alpha - 1.0 / 3.0) < 1e-12;
  if (estimator == "gauss-volume") {
    if (sphere || kind == "ellipsoid") {
      return TheoryRate{243.0 / 158.0, "O(h^{243/158}) for C^3 strictly convex bodies",
                        "Kraetzel; Guo (lattice points in smooth convex bodies)"};
    }
    if (convex3) return TheoryRate{1.0, "O(h) for convex bodies", "lattice-point theory"};
    return std::nullopt;
  }
  if ((estimator == "ii-mean" || estimator == "ii-gaussian" || estimator == "ii-k1" ||
       estimator == "ii-k2") &&
      smooth3 && third) {
    return TheoryRate{1.0 / 3.0, "O(h^{1/3}) with R = k h^{1/3}, C^3 surface with positive reach",
                      "Coeurjolly, Lachaud, Levallois, CVIU 2014 (Thm 6 for k1, k2)"};
  }
  if (estimator == "ii-normal" && smooth3 && third) {
    return TheoryRate{2.0 / 3.0, "O(h^{2/3}) with R = k h^{1/3}, C^3 surface with positive reach",
                      "Lachaud, Coeurjolly, Levallois 2017"};
  }
  if (estimator == "ii-directions" && smooth3 && !sphere && third) {
    return TheoryRate{1.0 / 3.0, "O(h^{1/3}) / |k1 - k2| with R = k h^{1/3}, away from umbilics",
                      "Lachaud, Coeurjolly, Levallois 2017"};
  }
  if (estimator == "hausdorff" && (shape.dimension() == 3 ? smooth3 : smooth)) {
    return TheoryRate{1.0, "O(h): at most sqrt(d) h / 2 for h < 2 rho / sqrt(d), reach > rho",
                      "Lachaud, Thibert, JMIV 2016"};
  }
  // Binomial convolver with mask n = k h^{-alpha}: smoothing bias O(h^{2 - alpha}) against
  // noise O(h^{alpha/2}) (tangent) or O(h^{alpha - 1}) (curvature); see
  // estimators/binomial_convolver.hpp. alpha = 4/3 gives the tangent's 2/3, alpha = 14/9 the
  // curvature's 4/9.
  if (estimator == "bc-tangent" && smooth && alpha > 0 && alpha < 2) {
    const double rate = std::min(2 - alpha, alpha / 2);
    return TheoryRate{
        rate, "O(h^{min(2 - a, a/2)}) with mask ~ h^{-a} (O(h^{2/3}) at a = 4/3), C^3 curves",
        "Esbelin, Malgouyres, Cartade 2011"};
  }
  if (estimator == "bc-curvature" && smooth && alpha > 1 && alpha < 2) {
    const double rate = std::min(2 - alpha, alpha - 1);
    return TheoryRate{rate,
                      "O(h^{min(2 - a, a - 1)}) with mask ~ h^{-a} (O(h^{4/9}) at a = 14/9), C^3 "
                      "curves",
                      "Malgouyres, Brunet, Fourey 2008; Esbelin, Malgouyres, Cartade 2011"};
  }
  return std::nullopt;
}

} // namespace zdg
