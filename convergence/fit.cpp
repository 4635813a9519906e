#include <zdg/convergence/fit.hpp>

#include <cmath>
#include <limits>
#include <sstream>

namespace zdg {

LogLogFit fit_loglog(const std::vector<double>& h, const std::vector<double>& error) {
  std::vector<double> x, y;
  for (std::size_t i = 0; i < h.size() && i < error.size(); ++i) {
    if (h[i] > 0 && error[i] > 0 && std::isfinite(error[i])) {
      x.push_back(std::log(h[i]));
      y.push_back(std::log(error[i]));
    }
  }
  LogLogFit f;
  f.n = static_cast<int>(x.size());
  if (f.n < 2) {
    f.slope = std::numeric_limits<double>::quiet_NaN();
    return f;
  }
  double mx = 0, my = 0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    mx += x[i];
    my += y[i];
  }
  mx /= f.n;
  my /= f.n;
  double sxx = 0, sxy = 0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    sxx += (x[i] - mx) * (x[i] - mx);
    sxy += (x[i] - mx) * (y[i] - my);
  }
  if (sxx == 0) {
    f.slope = std::numeric_limits<double>::quiet_NaN();
    return f;
  }
  f.slope = sxy / sxx;
  f.intercept = my - f.slope * mx;
  if (f.n > 2) {
    double sse = 0;
    for (std::size_t i = 0; i < x.size(); ++i) {
      double r = y[i] - (f.intercept + f.slope * x[i]);
      sse += r * r;
    }
    f.stderr_slope = std::sqrt(sse / (f.n - 2) / sxx);
  }
  return f;
}

namespace {

// in_samples: the levels are counts N and the error must fall at least like N^expected.
RateVerdict check(const std::vector<FitLevel>& levels, double expected, double tolerance,
                  bool in_samples) {
  RateVerdict v;
  std::vector<double> hs, errors;
  bool all_zero = true;
  for (const auto& l : levels) {
    std::ostringstream at;
    at.precision(6);
    at << (in_samples ? "N = " : "h = ") << l.h;
    if (!(std::isfinite(l.h) && l.h > 0)) {
      v.reason = "no verdict: a level has " + at.str() +
                 (in_samples ? " (not a positive count)" : " (not a positive grid step)");
    } else if (l.elements <= 0) {
      v.reason = "no verdict: no element measured at " + at.str();
    } else if (!(std::isfinite(l.error) && l.error >= 0)) {
      v.reason = "the error at " + at.str() + " is not a finite number";
    }
    if (!v.reason.empty()) break;
    hs.push_back(l.h);
    errors.push_back(l.error);
    all_zero = all_zero && l.error == 0;
  }
  v.fit = fit_loglog(hs, errors);
  if (!v.reason.empty()) return v;
  if (levels.size() < 2) {
    v.reason = "no verdict: " + std::to_string(levels.size()) +
               " level(s) measured, a slope needs at least 2";
    return v;
  }
  if (all_zero) { // exact at every level: the error bound holds for every rate
    v.pass = true;
    return v;
  }
  if (v.fit.n < 2 || !std::isfinite(v.fit.slope)) {
    v.reason = "no verdict: " + std::to_string(v.fit.n) +
               (in_samples ? " level(s) with a positive error, no slope (a fit needs at least 2 "
                             "distinct counts)"
                           : " level(s) with a positive error, no slope (a fit needs at least 2 "
                             "distinct grid steps)");
    return v;
  }
  v.pass = in_samples ? v.fit.slope <= expected + tolerance : v.fit.slope >= expected - tolerance;
  if (!v.pass) {
    std::ostringstream r;
    r.precision(4);
    if (in_samples) {
      r << "slope " << v.fit.slope << " > expected " << expected << " + tolerance " << tolerance;
    } else {
      r << "slope " << v.fit.slope << " < expected " << expected << " - tolerance " << tolerance;
    }
    v.reason = r.str();
  }
  return v;
}

} // namespace

RateVerdict check_rate(const std::vector<FitLevel>& levels, double expected, double tolerance) {
  return check(levels, expected, tolerance, false);
}

RateVerdict check_rate_in_samples(const std::vector<FitLevel>& levels, double expected,
                                  double tolerance) {
  return check(levels, expected, tolerance, true);
}

} // namespace zdg
