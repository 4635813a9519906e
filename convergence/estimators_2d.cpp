// The 2D estimators of the registry: digitize the translated shape, extract its contours,
// run the estimator of estimators/, and compare with the shape's ground truth at the
// projection of each boundary element.
#include <zdg/arith/error.hpp>
#include <zdg/convergence/digitized_2d.hpp>
#include <zdg/convergence/estimator.hpp>
#include <zdg/convergence/ii_runs.hpp>
#include <zdg/estimators/binomial_convolver.hpp>
#include <zdg/estimators/dss_length.hpp>
#include <zdg/estimators/gauss_area.hpp>
#include <zdg/estimators/ii_curvature.hpp>
#include <zdg/estimators/lambda_mst.hpp>
#include <zdg/estimators/mdss_curvature.hpp>
#include <zdg/estimators/mlp_length.hpp>
#include <zdg/estimators/moments.hpp>
#include <zdg/kernel/curves/digital_contour.hpp>

#include <algorithm>
#include <cmath>
#include <memory>
#include <optional>
#include <sstream>

namespace zdg {

namespace {

using detail::Digitized2;

Digitized2 digitize(const RunInput& in) {
  return detail::digitize_2d(in);
}

// Ground truth at embedded points of the translated shape, given in contour order (the
// projections warm-start from each other, Shape2::project_chain).
std::vector<BoundaryPoint2> truths(const Digitized2& d, std::vector<Point2<double>> pts) {
  for (auto& p : pts) p = {p.x - d.t.x, p.y - d.t.y};
  return d.shape->project_chain(pts);
}

std::vector<BoundaryPoint2> pointel_truths(const Digitized2& d, const std::vector<Pixel>& pts) {
  std::vector<Point2<double>> e;
  e.reserve(pts.size());
  for (const auto& p : pts) e.push_back(d.embed.pointel(p));
  return truths(d, std::move(e));
}

double tangent_angle(Point2<double> a, Point2<double> b) {
  return std::atan2(std::abs(a.x * b.y - a.y * b.x), a.x * b.x + a.y * b.y);
}

ErrorStats run_gauss_area(const RunInput& in) {
  Digitized2 d = digitize(in);
  auto area = d.shape->area();
  if (!area) throw InvalidArgument("the area of '" + in.shape.spec() + "' is not known");
  ErrorAccumulator acc;
  acc.add(gauss_area(d.contours, in.h) - *area);
  return acc.stats();
}

ErrorStats run_moments(const RunInput& in) {
  Digitized2 d = digitize(in);
  auto m = d.shape->moments();
  if (!m) throw InvalidArgument("the moments of '" + in.shape.spec() + "' are not known");
  Moments2 truth_m = translate_moments(*m, d.t);
  auto est = moments_estimate(d.contours, in.h);
  ErrorAccumulator acc;
  for (std::size_t i = 0; i < 6; ++i) acc.add(est[i] - truth_m[i]);
  return acc.stats();
}

// With a certified complete boundary the ball counts come from Green's formula over the
// contour (O(log n) per linel); otherwise from the symmetric-difference updates (O(R/h)).
// Both give the same integers.
ErrorStats run_ii_curvature(const RunInput& in) {
  return detail::ii_curvature_errors(digitize(in), in.h, in.k * std::pow(in.h, in.alpha));
}

} // namespace

ErrorStats detail::ii_curvature_errors(const Digitized2& d, double h, double radius) {
  ErrorAccumulator acc;
  std::optional<ContourBallCounter> green;
  if (d.complete && radius / h <= 1e6) green.emplace(*d.set, d.contours, radius / h);
  for (const auto& c : d.contours) {
    auto kappa = green ? ii_curvature(*green, c, h, radius) : ii_curvature(*d.set, c, h, radius);
    std::vector<Point2<double>> mid;
    mid.reserve(c.size());
    Pixel p = c.start;
    for (auto code : c.codes) {
      mid.push_back(d.embed.linel_midpoint(p, code));
      Pixel s = freeman_step(code);
      p = Pixel{p.x + s.x, p.y + s.y};
    }
    auto truth = truths(d, std::move(mid));
    for (std::size_t i = 0; i < c.size(); ++i) acc.add(kappa[i] - truth[i].curvature);
  }
  return acc.stats();
}

namespace {

ErrorStats run_mlp_length(const RunInput& in) {
  Digitized2 d = digitize(in);
  auto perimeter = d.shape->perimeter();
  if (!perimeter) throw InvalidArgument("the perimeter of '" + in.shape.spec() + "' is not known");
  double len = 0;
  for (const auto& c : d.contours) len += mlp_length(c, in.h);
  ErrorAccumulator acc;
  acc.add(len - *perimeter);
  return acc.stats();
}

template <bool Tangent>
ErrorStats run_binomial(const RunInput& in) {
  Digitized2 d = digitize(in);
  const long n = binomial_mask_order(in.h, in.k, in.alpha);
  ErrorAccumulator acc;
  for (const auto& c : d.contours) {
    // Contours shorter than the mask (specks) are skipped.
    if (static_cast<double>(c.size()) < 12.0 * std::sqrt(double(n)) + 8) continue;
    auto est = binomial_convolver(c, in.h, n);
    auto truth = pointel_truths(d, c.pointels());
    for (std::size_t i = 0; i < truth.size(); ++i) {
      if constexpr (Tangent) {
        acc.add(tangent_angle(est.tangent[i], truth[i].tangent));
      } else {
        acc.add(est.curvature[i] - truth[i].curvature);
      }
    }
  }
  return acc.stats();
}

// Global length estimators of the contours: the sum over all contours against the perimeter.
template <class LengthOfContour>
ErrorStats run_length(const RunInput& in, LengthOfContour length_of) {
  Digitized2 d = digitize(in);
  auto perimeter = d.shape->perimeter();
  if (!perimeter) throw InvalidArgument("the perimeter of '" + in.shape.spec() + "' is not known");
  double len = 0;
  for (const auto& c : d.contours) len += length_of(c.pointels(), in.h);
  ErrorAccumulator acc;
  acc.add(len - *perimeter);
  return acc.stats();
}

ErrorStats run_dss_length(const RunInput& in) {
  return run_length(
      in, [](const std::vector<Pixel>& pts, double h) { return dss_length(pts, true, h); });
}

ErrorStats run_lmst_length(const RunInput& in) {
  return run_length(
      in, [](const std::vector<Pixel>& pts, double h) { return lambda_mst_length(pts, h); });
}

// Per-pointel estimators built on the maximal segments of each contour.
template <bool Tangent>
ErrorStats run_maximal_segment_estimator(const RunInput& in) {
  Digitized2 d = digitize(in);
  ErrorAccumulator acc;
  for (const auto& c : d.contours) {
    auto pts = c.pointels();
    auto truth = pointel_truths(d, pts);
    if constexpr (Tangent) {
      auto t = lambda_mst_tangents(pts, true);
      for (std::size_t i = 0; i < pts.size(); ++i) acc.add(tangent_angle(t[i], truth[i].tangent));
    } else {
      auto kappa = mdss_curvature(pts, in.h);
      for (std::size_t i = 0; i < pts.size(); ++i) acc.add(kappa[i] - truth[i].curvature);
    }
  }
  return acc.stats();
}

// --- theory (papers/THEORY.md, "Rates") -----------------------------------------------------

ProvenRate rate(double slope, std::string statement, std::string hypotheses, std::string source) {
  return {slope, std::move(statement), std::move(hypotheses), std::move(source)};
}

bool smooth_strictly_convex(const ShapeClass& c) {
  return c.c3 && c.convex && c.positive_curvature;
}

const char* const kEMC = "Esbelin, Malgouyres, Cartade 2011";
const char* const kLVV = "Lachaud, Vialard, de Vieilleville 2007";

} // namespace

namespace detail {

void register_2d_estimators(std::vector<Estimator>& out) {
  out.push_back(
      {"gauss-area",
       2,
       "h^2 times the number of digitized pixels (from the contours)",
       "area",
       {},
       {"O(h^{15/11} log^{47/22}(1/h)) on C^3 strictly convex shapes (Huxley 1990), O(h) on convex "
        "shapes (Gauss, Dirichlet)",
        [](const ShapeClass& c, const EstimatorParameters&) -> std::optional<ProvenRate> {
          if (smooth_strictly_convex(c)) {
            return rate(15.0 / 11.0, "O(h^{15/11} log^{47/22}(1/h))",
                        "X convex with C^3 boundary of positive curvature", "Huxley 1990");
          }
          if (c.convex) return rate(1.0, "O(h)", "X convex", "Gauss, Dirichlet");
          return std::nullopt;
        }},
       run_gauss_area});
  out.push_back(
      {"moments",
       2,
       "moments m00, m10, m01, m20, m11, m02 of the digitization (6 errors per run)",
       "moment",
       {},
       {"O(h) on C^3 piecewise strictly convex shapes (Coeurjolly, Lachaud, Roussillon 2012)",
        [](const ShapeClass& c, const EstimatorParameters&) -> std::optional<ProvenRate> {
          if (smooth_strictly_convex(c) || (c.convex && c.polygon)) {
            return rate(1.0, "O(h)", "X convex, boundary C^3 piecewise with positive curvature",
                        "Coeurjolly, Lachaud, Roussillon 2012");
          }
          return std::nullopt;
        }},
       run_moments});
  out.push_back({"mlp-length",
                 2,
                 "perimeter by the minimum length polygon of the contour",
                 "length",
                 {},
                 {"O(h) on convex shapes (Klette, Rosenfeld 2004; DGA 2012 survey)",
                  [](const ShapeClass& c, const EstimatorParameters&) -> std::optional<ProvenRate> {
                    if (c.convex) {
                      return rate(1.0, "O(h)", "X convex",
                                  "Klette, Rosenfeld 2004; DGA 2012 survey");
                    }
                    return std::nullopt;
                  }},
                 run_mlp_length});
  out.push_back({"dss-length",
                 2,
                 "perimeter by the polygon through the ends of the greedy DSS segmentation",
                 "length",
                 {},
                 {"O(h) on convex polygons (DGA 2012 survey)",
                  [](const ShapeClass& c, const EstimatorParameters&) -> std::optional<ProvenRate> {
                    if (c.convex && c.polygon) {
                      return rate(1.0, "O(h)", "X a convex polygon", "DGA 2012 survey");
                    }
                    return std::nullopt;
                  }},
                 run_dss_length});
  out.push_back(
      {"lmst-length",
       2,
       "perimeter from the lambda-MST tangents of every linel",
       "length",
       {},
       {"O(h^{1/3}) on C^3 strictly convex curves, parameter-free (observed ~h^{4/3}; LVV 2007)",
        [](const ShapeClass& c, const EstimatorParameters&) -> std::optional<ProvenRate> {
          if (smooth_strictly_convex(c)) {
            return rate(1.0 / 3.0, "O(h^{1/3})",
                        "X convex with C^3 boundary of positive curvature (piecewise allowed)",
                        kLVV);
          }
          return std::nullopt;
        }},
       run_lmst_length});
  out.push_back({"lmst-tangent",
                 2,
                 "lambda-MST tangent at every pointel (weighted pencil of maximal segments)",
                 "angle (rad)",
                 {},
                 {"O(h^{1/3}) on C^3 convex curves, parameter-free (observed ~h^{2/3}; LVV 2007)",
                  [](const ShapeClass& c, const EstimatorParameters&) -> std::optional<ProvenRate> {
                    if (smooth_strictly_convex(c)) {
                      return rate(1.0 / 3.0, "O(h^{1/3})",
                                  "X convex with C^3 boundary of positive curvature", kLVV);
                    }
                    return std::nullopt;
                  }},
                 run_maximal_segment_estimator<true>});
  out.push_back({"mdss-curvature",
                 2,
                 "curvature of the circle through the ends of the half-tangents (maximal DSS); "
                 "not convergent: a negative control",
                 "curvature",
                 {},
                 {"none: not convergent (a negative control, DGA 2012 survey)", {}},
                 run_maximal_segment_estimator<false>});
  out.push_back(
      {"ii-curvature",
       2,
       "integral-invariant curvature 3pi/(2R) - 3A/R^3 at every linel (inner/outer pixel "
       "average)",
       "curvature",
       radius_law_parameters(),
       {"O(h^{1/3}) with R = k h^{1/3} on C^3 boundaries with positive reach (Coeurjolly, "
        "Lachaud, Levallois DGCI 2013, CVIU 2014)",
        [](const ShapeClass& c, const EstimatorParameters& p) -> std::optional<ProvenRate> {
          if (c.c3 && is_one_third(p.alpha)) {
            return rate(1.0 / 3.0, "O(h^{1/3})",
                        "C^3 boundary with positive reach, R = k h^{1/3} (R below half the reach)",
                        "Coeurjolly, Lachaud, Levallois, DGCI 2013 / CVIU 2014");
          }
          return std::nullopt;
        }},
       run_ii_curvature});
  // Binomial convolver with mask n = k h^{-alpha}: smoothing bias O(h^{2 - alpha}) against
  // noise O(h^{alpha/2}) (tangent) or O(h^{alpha - 1}) (curvature); see
  // estimators/binomial_convolver.hpp and papers/THEORY.md.
  out.push_back(
      {"bc-tangent",
       2,
       "binomial convolver tangent at every pointel",
       "angle (rad)",
       {{"k", "1", 0.0, 1e6, "mask factor: order n = k h^(-alpha)"},
        {"alpha", "4/3", 0.0, 2.0, "mask exponent: order n = k h^(-alpha)"}},
       {"O(h^{min(2 - a, a/2)}) with mask n = k h^{-a} (O(h^{2/3}) at a = 4/3) on C^3 curves "
        "(Esbelin, Malgouyres, Cartade 2011)",
        [](const ShapeClass& c, const EstimatorParameters& p) -> std::optional<ProvenRate> {
          if (c.c3 && p.alpha > 0 && p.alpha < 2) {
            return rate(std::min(2 - p.alpha, p.alpha / 2), "O(h^{min(2 - a, a/2)})",
                        "C^3 boundary, mask n = k h^{-a}, 0 < a < 2", kEMC);
          }
          return std::nullopt;
        }},
       run_binomial<true>});
  out.push_back(
      {"bc-curvature",
       2,
       "binomial convolver curvature at every pointel",
       "curvature",
       {{"k", "1", 0.0, 1e6, "mask factor: order n = k h^(-alpha)"},
        {"alpha", "14/9", 0.0, 2.0, "mask exponent: order n = k h^(-alpha)"}},
       {"O(h^{min(2 - a, a - 1)}) with mask n = k h^{-a} (O(h^{4/9}) at a = 14/9, only "
        "O(h^{1/3}) at 4/3) on C^3 curves (Malgouyres, Brunet, Fourey 2008; Esbelin, "
        "Malgouyres, Cartade 2011)",
        [](const ShapeClass& c, const EstimatorParameters& p) -> std::optional<ProvenRate> {
          if (c.c3 && p.alpha > 1 && p.alpha < 2) {
            return rate(std::min(2 - p.alpha, p.alpha - 1), "O(h^{min(2 - a, a - 1)})",
                        "C^3 boundary, mask n = k h^{-a}, 1 < a < 2",
                        "Malgouyres, Brunet, Fourey 2008; Esbelin, Malgouyres, Cartade 2011");
          }
          return std::nullopt;
        }},
       run_binomial<false>});
}

} // namespace detail

} // namespace zdg
