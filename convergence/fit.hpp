// Least-squares fit of log(error) = slope log(h) + c, with the standard error of the slope
// sqrt(SSE / (n - 2) / S_hh) (0 when n = 2). Points with a zero or non-finite error are
// left out (an exact estimate has no logarithm); fewer than two points left gives
// n < 2 and a NaN slope.
//
// Rate check (check_rate): the verdict "the error decays at least like h^(expected -
// tolerance)" on a sequence of levels (check_rate_in_samples: "like N^(expected + tolerance)",
// levels indexed by the number of points N). A level is usable when h is finite and > 0, the level
// measured at least one element and its error is finite and >= 0. The check passes only when
// every level is usable, there are at least two, and either every error is 0 (an estimator
// exact at every level) or the fit over the levels with a positive error has n >= 2 and a
// finite slope >= expected - tolerance. Otherwise it fails with the reason (one sentence): a
// check with nothing to check is not a pass, and a NaN slope never passes. O(levels).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace zdg {

struct LogLogFit {
  double slope = 0, intercept = 0, stderr_slope = 0;
  int n = 0;
};

LogLogFit fit_loglog(const std::vector<double>& h, const std::vector<double>& error);

/// One level of a rate check: the grid step, the error, the number of elements measured.
struct FitLevel {
  double h = 0, error = 0;
  std::int64_t elements = 0;
};

struct RateVerdict {
  LogLogFit fit; // over the levels with a positive finite error
  bool pass = false;
  std::string reason; // why the check does not pass; empty when it passes
};

/// The verdict slope >= expected - tolerance on the levels (see above).
RateVerdict check_rate(const std::vector<FitLevel>& levels, double expected, double tolerance);

/// The same check for a samples sweep: FitLevel::h holds the number of points N, the fit is
/// log(error) against log(N), and the verdict is slope <= expected + tolerance (an error
/// O(N^expected), expected < 0); the reasons name N.
RateVerdict check_rate_in_samples(const std::vector<FitLevel>& levels, double expected,
                                  double tolerance);

} // namespace zdg
