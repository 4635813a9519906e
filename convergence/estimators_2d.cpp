// The 2D estimators of the registry: digitize the translated shape, extract its contours,
// run the estimator of estimators/, and compare with the shape's ground truth at the
// projection of each boundary element.
#include <zdg/arith/error.hpp>
#include <zdg/convergence/digitized_2d.hpp>
#include <zdg/convergence/estimator.hpp>
#include <zdg/estimators/binomial_convolver.hpp>
#include <zdg/estimators/dss_length.hpp>
#include <zdg/estimators/gauss_area.hpp>
#include <zdg/estimators/ii_curvature.hpp>
#include <zdg/estimators/lambda_mst.hpp>
#include <zdg/estimators/mdss_curvature.hpp>
#include <zdg/estimators/mlp_length.hpp>
#include <zdg/estimators/moments.hpp>
#include <zdg/kernel/digital_contour.hpp>

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
  Digitized2 d = digitize(in);
  const double radius = in.k * std::pow(in.h, in.alpha);
  ErrorAccumulator acc;
  std::optional<ContourBallCounter> green;
  if (d.complete && radius / in.h <= 1e6) green.emplace(*d.set, d.contours, radius / in.h);
  for (const auto& c : d.contours) {
    auto kappa =
        green ? ii_curvature(*green, c, in.h, radius) : ii_curvature(*d.set, c, in.h, radius);
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

} // namespace

namespace detail {

void register_2d_estimators(std::vector<Estimator>& out) {
  out.push_back({"gauss-area", 2, "h^2 times the number of digitized pixels (from the contours)",
                 "none", "area", false, false, 0, 0, run_gauss_area});
  out.push_back({"moments", 2,
                 "moments m00, m10, m01, m20, m11, m02 of the digitization (6 errors per run)",
                 "none", "moment", false, false, 0, 0, run_moments});
  out.push_back({"mlp-length", 2, "perimeter by the minimum length polygon of the contour", "none",
                 "length", false, false, 0, 0, run_mlp_length});
  out.push_back({"dss-length", 2,
                 "perimeter by the polygon through the ends of the greedy DSS segmentation", "none",
                 "length", false, false, 0, 0, run_dss_length});
  out.push_back({"lmst-length", 2, "perimeter from the lambda-MST tangents of every linel",
                 "none (parameter-free)", "length", false, false, 0, 0, run_lmst_length});
  out.push_back({"lmst-tangent", 2,
                 "lambda-MST tangent at every pointel (weighted pencil of maximal segments)",
                 "none (parameter-free)", "angle (rad)", false, false, 0, 0,
                 run_maximal_segment_estimator<true>});
  out.push_back({"mdss-curvature", 2,
                 "curvature of the circle through the ends of the half-tangents (maximal DSS); "
                 "not convergent: a negative control",
                 "none", "curvature", false, false, 0, 0, run_maximal_segment_estimator<false>});
  out.push_back({"ii-curvature", 2,
                 "integral-invariant curvature 3pi/(2R) - 3A/R^3 at every linel (inner/outer "
                 "pixel average)",
                 "R = k h^alpha (defaults k = 3, alpha = 1/3)", "curvature", true, true, 3.0,
                 1.0 / 3.0, run_ii_curvature});
  out.push_back({"bc-tangent", 2, "binomial convolver tangent at every pointel",
                 "mask order n = k h^(-alpha) (defaults k = 1, alpha = 4/3)", "angle (rad)", true,
                 true, 1.0, 4.0 / 3.0, run_binomial<true>});
  out.push_back({"bc-curvature", 2, "binomial convolver curvature at every pointel",
                 "mask order n = k h^(-alpha) (defaults k = 1, alpha = 14/9)", "curvature", true,
                 true, 1.0, 14.0 / 9.0, run_binomial<false>});
}

} // namespace detail

} // namespace zdg
