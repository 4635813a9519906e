// The proven convergence rates the driver checks measured slopes against (see
// ../shared/THEORY.md, table "Rates"). A rate applies to an estimator on a class of
// shapes; the check reads "fitted l_inf slope >= proven rate - tolerance" on the finest
// levels (published experiments observe slopes at or above the proven rates).
#pragma once

#include <zdg/convergence/shape.hpp>

#include <optional>
#include <string>

namespace zdg {

struct TheoryRate {
  double slope;          // proven exponent of h
  std::string statement; // "O(h^{1/3}) for C^3 boundaries with positive reach"
  std::string source;    // paper, as cited in THEORY.md
};

/// The proven rate of `estimator` on `shape` with the radius exponent alpha (for the
/// estimators whose law has one), or nullopt when theory proves none for that shape class
/// (then the fit is reported without a verdict).
std::optional<TheoryRate> theory_rate(const std::string& estimator, const Shape& shape,
                                      double alpha);

} // namespace zdg
