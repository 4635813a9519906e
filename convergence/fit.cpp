#include <zdg/convergence/fit.hpp>

#include <cmath>
#include <limits>

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

} // namespace zdg
