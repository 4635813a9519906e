// Least-squares fit of log(error) = slope log(h) + c, with the standard error of the slope
// sqrt(SSE / (n - 2) / S_hh) (0 when n = 2). Points with a zero or non-finite error are
// left out (an exact estimate has no logarithm); fewer than two points left gives
// n < 2 and a NaN slope.
#pragma once

#include <vector>

namespace zdg {

struct LogLogFit {
  double slope = 0, intercept = 0, stderr_slope = 0;
  int n = 0;
};

LogLogFit fit_loglog(const std::vector<double>& h, const std::vector<double>& error);

} // namespace zdg
