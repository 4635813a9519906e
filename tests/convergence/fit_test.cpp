// The rate check (convergence/fit.hpp): a verdict needs at least two levels that measured an
// element with a finite error (issue #41: a fit over no level passed, a NaN slope passed).
#include <zdg/convergence/fit.hpp>

#include "tests/support/tower.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

namespace {

using zdg::check_rate;
using zdg::FitLevel;

// Any double, special values included.
rc::Gen<double> any_double() {
  const double inf = std::numeric_limits<double>::infinity();
  return rc::gen::oneOf(rc::gen::arbitrary<double>(),
                        rc::gen::element(0.0, -0.0, 1.0, -1.0, 0.5, 1e-300, 1e300, inf, -inf,
                                         std::numeric_limits<double>::quiet_NaN()));
}

rc::Gen<FitLevel> any_level() {
  return rc::gen::build<FitLevel>(
      rc::gen::set(&FitLevel::h, any_double()), rc::gen::set(&FitLevel::error, any_double()),
      rc::gen::set(&FitLevel::elements, rc::gen::oneOf(rc::gen::arbitrary<std::int64_t>(),
                                                       rc::gen::inRange<std::int64_t>(-2, 5))));
}

bool usable(const FitLevel& l) {
  return std::isfinite(l.h) && l.h > 0 && l.elements > 0 && std::isfinite(l.error) && l.error >= 0;
}

// Theorem: whatever the data, the expected rate and the tolerance, a check passes only when
// every level is usable and there are at least two; a failed check says why; a passing check
// has a finite slope within the tolerance, or zero error everywhere.
TEST(RateCheck, FewerThanTwoUsableLevelsNeverPass) {
  zdg::test::check_property([] {
    const auto levels = *rc::gen::container<std::vector<FitLevel>>(any_level());
    const double expected = *any_double();
    const double tolerance = *any_double();
    const auto v = check_rate(levels, expected, tolerance);
    std::size_t good = 0;
    bool all_zero = true;
    for (const auto& l : levels) {
      good += usable(l) ? 1 : 0;
      all_zero = all_zero && l.error == 0;
    }
    if (good < 2 || good < levels.size()) RC_ASSERT(!v.pass);
    RC_ASSERT(v.pass == v.reason.empty());
    if (v.pass && !all_zero) {
      RC_ASSERT(std::isfinite(v.fit.slope));
      RC_ASSERT(v.fit.n >= 2);
      RC_ASSERT(v.fit.slope >= expected - tolerance);
    }
  });
}

// The same with only usable levels: fewer than two never pass, even with a generous tolerance.
TEST(RateCheck, OneUsableLevelIsNoVerdict) {
  zdg::test::check_property([] {
    const double h = *rc::gen::inRange(1, 1000) / 1000.0;
    const double e = *rc::gen::element(0.0, 0.5, 1.0, 3.0);
    const auto v = check_rate({{h, e, 10}}, 1.0, 10.0);
    RC_ASSERT(!v.pass);
    RC_ASSERT(v.reason.find("no verdict") != std::string::npos);
  });
  EXPECT_FALSE(check_rate({}, 1.0, 0.1).pass);
  EXPECT_EQ(check_rate({}, 1.0, 0.1).reason,
            "no verdict: 0 level(s) measured, a slope needs at least 2");
}

TEST(RateCheck, Examples) {
  // A power law h^1.5 at three levels passes a rate 1 check and fails a rate 2 check.
  std::vector<FitLevel> law;
  for (double h : {0.5, 0.25, 0.125}) law.push_back({h, 3 * std::pow(h, 1.5), 100});
  EXPECT_TRUE(check_rate(law, 1.0, 0.1).pass);
  const auto strict = check_rate(law, 2.0, 0.1);
  EXPECT_FALSE(strict.pass);
  EXPECT_NE(strict.reason.find("slope 1.5 < expected 2"), std::string::npos) << strict.reason;
  // The cases: no element at any level (a box away from the shape, an empty shape).
  EXPECT_FALSE(check_rate({{1, 0, 0}, {0.5, 0, 0}, {0.25, 0, 0}}, 1.0 / 3, 0.1).pass);
  // An exact estimator at every level passes; exact at one level only is no verdict.
  EXPECT_TRUE(check_rate({{1, 0, 5}, {0.5, 0, 9}}, 1.0, 0.1).pass);
  EXPECT_FALSE(check_rate({{1, 0, 5}}, 1.0, 0.1).pass);
  // A NaN error fails, wherever it is; one positive error among zeros has no slope.
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_FALSE(check_rate({{1, 0.5, 5}, {0.5, nan, 5}, {0.25, 0.1, 5}}, 0.0, 10).pass);
  EXPECT_FALSE(check_rate({{1, 0, 5}, {0.5, 0.1, 5}}, 0.0, 10).pass);
}

} // namespace
