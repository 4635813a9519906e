// The estimator registry: every entry states its parameters (defaults inside their ranges),
// its theory (a summary, and rates as functions of the shape class and the parameters), and
// the per-estimator parameter syntax NAME[:KEY=VALUE,...] with its canonical label.
#include <zdg/convergence/estimator.hpp>

#include <zdg/arith/error.hpp>
#include <zdg/convergence/number_text.hpp>

#include "tests/support/experiments.hpp"

#include <gtest/gtest.h>

#include <set>
#include <string>

namespace {

using zdg::InvalidArgument;
using zdg::test::theory_rate;

std::string message(const std::string& spec) {
  try {
    zdg::parse_estimator_spec(spec);
  } catch (const InvalidArgument& e) {
    return e.what();
  }
  return "no error";
}

TEST(EstimatorRegistry, EveryEntryStatesParametersAndTheory) {
  std::set<std::string> names;
  for (const auto& e : zdg::estimators()) {
    EXPECT_TRUE(names.insert(e.name).second) << e.name << " registered twice";
    EXPECT_FALSE(e.theory.summary.empty()) << e.name;
    EXPECT_TRUE(e.run) << e.name;
    for (const auto& p : e.parameters) {
      EXPECT_FALSE(p.meaning.empty());
      if (p.check_text) { // a text parameter (the test function u, lb-spectrum's operator, the
                          // reconstructions' method): its default passes its check
        EXPECT_TRUE(p.name == "u" || p.name == "operator" || p.name == "method") << e.name;
        EXPECT_NO_THROW(p.check_text(p.default_text)) << e.name;
        continue;
      }
      // The names resolve_parameters maps onto EstimatorParameters.
      EXPECT_TRUE(p.name == "k" || p.name == "alpha" || p.name == "degree" || p.name == "n" ||
                  p.name == "sigma")
          << e.name << " " << p.name;
      const double v = zdg::parse_real(p.default_text, p.name);
      if (p.closed_below) {
        EXPECT_GE(v, p.lo) << e.name << " " << p.name;
      } else {
        EXPECT_GT(v, p.lo) << e.name << " " << p.name;
      }
      if (p.open_above) {
        EXPECT_LT(v, p.hi) << e.name << " " << p.name;
      } else {
        EXPECT_LE(v, p.hi) << e.name << " " << p.name;
      }
    }
    // The defaults resolve, and a rate (where one applies) has its statement and source.
    const auto params = zdg::resolve_parameters(zdg::parse_estimator_spec(e.name), {}, {});
    const zdg::ShapeClass all{true, true, true, true, false};
    if (auto r = e.theory.rate ? e.theory.rate(all, params) : std::nullopt) {
      // A rate in h is a positive exponent; a rate in N (sampled estimators) a negative one.
      if (e.sampled) {
        EXPECT_LT(r->slope, 0) << e.name;
      } else {
        EXPECT_GT(r->slope, 0) << e.name;
      }
      EXPECT_FALSE(r->source.empty()) << e.name;
      EXPECT_FALSE(r->hypotheses.empty()) << e.name;
    }
  }
}

// The rates of papers/THEORY.md, as functions of the parameters: the binomial convolver's
// O(h^{min(2 - a, a - 1)}) (curvature) and O(h^{min(2 - a, a/2)}) (tangent) with mask
// n = k h^{-a}; the integral invariants only with R = k h^{1/3}.
TEST(EstimatorRegistry, RatesFollowTheParameters) {
  auto e = zdg::parse_shape("ellipse:20,7");
  EXPECT_NEAR(theory_rate("ii-curvature", *e, 1.0 / 3)->slope, 1.0 / 3, 1e-15);
  EXPECT_FALSE(theory_rate("ii-curvature", *e, 0.5).has_value());
  EXPECT_NEAR(theory_rate("bc-curvature", *e, 14.0 / 9)->slope, 4.0 / 9, 1e-15);
  EXPECT_NEAR(theory_rate("bc-curvature", *e, 4.0 / 3)->slope, 1.0 / 3, 1e-15);
  EXPECT_NEAR(theory_rate("bc-curvature", *e, 1.5)->slope, 0.5, 1e-15);
  EXPECT_NEAR(theory_rate("bc-tangent", *e, 4.0 / 3)->slope, 2.0 / 3, 1e-15);
  EXPECT_NEAR(theory_rate("bc-tangent", *e, 1.0)->slope, 0.5, 1e-15);
  EXPECT_FALSE(theory_rate("bc-curvature", *e, 1.0).has_value());
  EXPECT_NEAR(theory_rate("gauss-area", *e, 0)->slope, 15.0 / 11, 1e-15);
  EXPECT_FALSE(theory_rate("mdss-curvature", *e, 0).has_value()); // the negative control
  auto p = zdg::parse_shape("polygon:0,0,1,0,0,1");
  EXPECT_EQ(theory_rate("gauss-area", *p, 0)->slope, 1.0);
  EXPECT_EQ(theory_rate("dss-length", *p, 0)->slope, 1.0);
  EXPECT_FALSE(theory_rate("ii-curvature", *p, 1.0 / 3).has_value()); // corners
  EXPECT_FALSE(theory_rate("dss-length", *e, 0).has_value());
  auto flower = zdg::parse_shape("flower:20,7,6");
  EXPECT_NEAR(theory_rate("ii-curvature", *flower, 1.0 / 3)->slope, 1.0 / 3, 1e-15);
  EXPECT_FALSE(theory_rate("gauss-area", *flower, 0).has_value()); // not convex
  // DGtal's AccFlower2D is C^2, not C^3 at t = +-pi: no theory check.
  auto acc = zdg::parse_shape("accflower:20,5,1.0132118364233778");
  EXPECT_FALSE(theory_rate("ii-curvature", *acc, 1.0 / 3).has_value());
}

TEST(EstimatorSpec, CanonicalLabelsAndParameters) {
  auto s = zdg::parse_estimator_spec("bc-curvature:alpha=14/9,k=1");
  EXPECT_EQ(s.name, "bc-curvature");
  EXPECT_EQ(s.label(), "bc-curvature:k=1,alpha=14/9"); // the registry's order
  auto p = zdg::resolve_parameters(s, std::string("7"), std::string("1/2"));
  EXPECT_EQ(p.k, 1.0);
  EXPECT_EQ(p.alpha, 14.0 / 9);
  // Defaults: the experiment's (--k, --alpha), then the registry's.
  auto ii = zdg::parse_estimator_spec("ii-curvature:k=5");
  EXPECT_EQ(ii.label(), "ii-curvature:k=5");
  auto q = zdg::resolve_parameters(ii, std::string("7"), {});
  EXPECT_EQ(q.k, 5.0);
  EXPECT_EQ(q.alpha, 1.0 / 3);
  auto r = zdg::resolve_parameters(zdg::parse_estimator_spec("ii-curvature"), std::string("7"), {});
  EXPECT_EQ(r.k, 7.0);
  EXPECT_EQ(zdg::parse_estimator_spec("mdss-curvature").label(), "mdss-curvature");
}

TEST(EstimatorSpec, ErrorsNameTheProblem) {
  EXPECT_NE(message("no-such:k=1").find("unknown estimator 'no-such'"), std::string::npos);
  EXPECT_NE(message("bc-curvature:q=3").find("has no parameter 'q'"), std::string::npos);
  EXPECT_NE(message("mdss-curvature:k=3").find("it has none"), std::string::npos);
  EXPECT_NE(message("bc-curvature:k=1,k=2").find("given twice"), std::string::npos);
  EXPECT_NE(message("bc-curvature:alpha=3").find("must be in (0, 2]"), std::string::npos);
  EXPECT_NE(message("ii-curvature:alpha=2").find("must be in (0, 1]"), std::string::npos);
  EXPECT_NE(message("ii-curvature:k=0").find("must be in"), std::string::npos);
  EXPECT_NE(message("ii-curvature:k=inf").find("not a finite number"), std::string::npos);
  EXPECT_NE(message("ii-curvature:k=nan").find("not a finite number"), std::string::npos);
  EXPECT_NE(message("ii-curvature:k").find("expected KEY=VALUE"), std::string::npos);
  EXPECT_NE(message("ii-curvature:").find("no parameter after"), std::string::npos);
  EXPECT_NE(message("ii-curvature:k=1,").find("expected KEY=VALUE"), std::string::npos);
  EXPECT_THROW(
      zdg::resolve_parameters(zdg::parse_estimator_spec("bc-tangent"), std::string("-1"), {}),
      InvalidArgument); // --k out of range for an entry that uses k
}

} // namespace
