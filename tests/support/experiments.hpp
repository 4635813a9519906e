// Test support for convergence experiments: a seeded sweep, the l_inf fit of a run, and the
// check that every l_inf verdict passes.
#pragma once

#include <zdg/convergence/experiment.hpp>

#include <gtest/gtest.h>

#include <optional>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace zdg::test {

/// Runs shapes x estimators over the grid steps `h` (parse_grid_steps syntax) with seed 42
/// and 2 threads, fitting on the `fit_levels` finest levels (0: all); k as text or default.
inline ExperimentResult sweep(std::vector<std::string> shapes, std::vector<std::string> ests,
                              const std::string& h, int translations, int fit_levels,
                              const char* k = nullptr) {
  ExperimentConfig c;
  c.shapes = std::move(shapes);
  c.estimators = std::move(ests);
  c.hs = parse_grid_steps(h);
  c.translations = translations;
  c.seed = 42;
  c.fit_levels = fit_levels;
  c.threads = 2;
  if (k != nullptr) c.k_text = k;
  return run_experiment(c);
}

/// The proven rate of the registry estimator `est` on `shape` with exponent alpha (k = 1).
inline std::optional<ProvenRate> theory_rate(const std::string& est, const Shape& shape,
                                             double alpha) {
  return find_estimator(est).proven_rate(shape, EstimatorParameters{1.0, alpha});
}

/// The l_inf fit of `est` (on `shape` when given).
inline const FitRecord& linf_fit(const ExperimentResult& r, const std::string& est,
                                 const std::string& shape = "") {
  for (const auto& f : r.fits) {
    if (f.estimator == est && f.norm == "linf" && (shape.empty() || f.shape == shape)) return f;
  }
  throw std::runtime_error("no l_inf fit for " + shape + " " + est);
}

/// Every l_inf fit with a verdict passes.
inline void expect_all_linf_pass(const ExperimentResult& r) {
  for (const auto& f : r.fits) {
    if (f.norm != "linf" || !f.pass) continue;
    EXPECT_TRUE(*f.pass) << f.shape << " " << f.estimator << ": slope " << f.fit.slope
                         << " expected >= " << *f.expected << " - 0.1";
  }
  EXPECT_TRUE(r.all_pass);
}

} // namespace zdg::test
