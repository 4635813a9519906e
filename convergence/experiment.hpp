// A multigrid convergence experiment: shapes x estimators x grid steps x translations.
// For every (shape, estimator, h, translation) one run records the error statistics over
// the boundary elements (ErrorStats) and its time; then, per (shape, estimator) and norm,
// log(error) is fitted against log(h) on the finest levels and the l_inf slope is checked
// against the proven rate (convergence/theory.hpp): pass when slope >= rate - tolerance.
// Per h, the errors of the translations are aggregated before the fit: the maximum for
// l_inf (the worst case over translations), the average for l_2 and the mean.
//
// Dimension-agnostic: shapes and estimators know their dimension (they must agree); the
// loop, the norms, the fit and the outputs are the same in 2D and 3D. Runs are spread
// over `threads` std::threads, finest grid steps first.
#pragma once

#include <zdg/convergence/estimator.hpp>
#include <zdg/convergence/fit.hpp>
#include <zdg/convergence/shape.hpp>

#include <cstdint>
#include <functional>
#include <iosfwd>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace zdg {

struct ExperimentConfig {
  std::vector<std::string> shapes;
  std::vector<std::string> estimators;
  std::vector<double> hs;                // grid steps (any order; sorted decreasing)
  std::string h_text;                    // as given, for the provenance
  std::optional<std::string> k_text;     // k (rational), or one per shape; default per estimator
  std::optional<std::string> alpha_text; // exponent alpha (rational), default per estimator
  int translations = 0;                  // 0: the untranslated shape only
  std::uint64_t seed = 0;
  std::optional<std::pair<double, double>> box; // [LO, HI]^d, default: the shape's box
  int fit_levels = 0;                           // 0: all levels
  double tolerance = 0.1;
  int threads = 1;
};

/// Parses `HMAX:HMIN:N` (N geometric steps), `exp:I0:I1[:STEP]` (h = exp(-i/10)) or a
/// comma-separated list `h1,h2,...` (rationals allowed); throws InvalidArgument.
std::vector<double> parse_grid_steps(const std::string& text);
/// Parses `LO:HI`.
std::pair<double, double> parse_box(const std::string& text);
/// A positive rational or decimal as a double, naming `what` in errors.
double parse_parameter(const std::string& text, const std::string& what);
/// The parameter k of each of `shapes` shapes from `K` (one value for all) or `K1,K2,...`
/// (one per shape, in the order of ExperimentConfig::shapes: papers whose shapes were run
/// with different constants); throws InvalidArgument otherwise.
std::vector<double> parse_k_per_shape(const std::string& text, std::size_t shapes);

struct RunRecord {
  std::string shape, estimator;
  double h = 0;
  int translation = 0;
  std::vector<double> offset;
  double k = 0, alpha = 0;
  ErrorStats errors;
  double seconds = 0;
};

struct FitRecord {
  std::string shape, estimator, norm;
  LogLogFit fit;
  std::vector<double> hs; // levels used
  std::optional<double> expected;
  std::string theory, source;
  std::optional<bool> pass;
};

struct ExperimentResult {
  std::vector<RunRecord> runs;
  std::vector<FitRecord> fits;
  bool all_pass = true;
};

/// Progress callback: (runs done, runs total, the run just finished).
using ProgressFn = std::function<void(std::size_t, std::size_t, const RunRecord&)>;

/// Validates the configuration (shapes parse, estimators exist, dimensions agree, steps
/// positive) and runs it.
ExperimentResult run_experiment(const ExperimentConfig& config, const ProgressFn& progress = {});

/// results.csv: one row per shape, estimator, h, translation.
void write_results_csv(const ExperimentResult& result, std::ostream& out);

} // namespace zdg
