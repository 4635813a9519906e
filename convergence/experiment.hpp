// A multigrid convergence experiment: shapes x estimator entries x grid steps x translations.
// For every (shape, entry, h, translation) one run records the error statistics over the
// boundary elements (ErrorStats) and its time; then, per (shape, entry) and norm, log(error)
// is fitted against log(h) on the finest levels and the l_inf slope is checked against the
// rate the entry's estimator proves on that shape (convergence/estimator.hpp,
// papers/THEORY.md): pass when slope >= rate - tolerance. Per h, the errors of the
// translations are aggregated before the fit: the maximum for l_inf (the worst case over
// translations), the average for l_2 and the mean.
//
// An estimator entry is a registry estimator with its parameters (`bc-curvature:alpha=14/9`):
// two entries of one estimator with different parameters are two curves of the experiment.
//
// The steps, each a function (run_experiment composes them):
//   plan_experiment    validation: shapes parse, entries resolve, dimensions agree, grid steps
//                      sorted decreasing without repeats, counts in range. O(input).
//   run_plan           scheduling: one job per run (plan_jobs), largest first (for load balance)
//                      over `threads` workers (kernel/parallel/parallel_for.hpp); the runs of
//                      one (h, shape, translation) whose estimators share a computation
//                      (Estimator::shared_computation) are one job (run_job); a front end may
//                      hand the same jobs to other processes (`zdg converge --mpi`).
//   aggregate_levels   aggregation per (shape, entry, h), after sorting the records: O(n log n)
//                      for n runs.
//   fit_experiment     the fits per norm on the finest levels, and the theory verdicts.
// Dimension-agnostic: shapes and estimators know their dimension (they must agree); the loop,
// the norms, the fit and the outputs are the same in 2D and 3D.
//
// Samples sweeps. In place of grid steps an experiment may give sample counts N
// (ExperimentConfig::samples, `zdg converge --samples`): its estimators must all be sampled
// ones (Estimator::sampled: a run draws N points of the shape and derives its own grid step
// from N), and the levels are the counts, the largest the finest. A run gets h = 0, N and a
// seed (the experiment's seed mixed with the repetition index); `translations` R > 0 gives R
// independent samplings per N (no translation: the offsets are 0). The fit is log(error)
// against log(N), the rate the estimator proves is an exponent of N (error = O(N^rate),
// rate < 0) and the verdict is slope <= rate + tolerance (check_rate_in_samples).
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
  std::vector<std::string> estimators;   // entries NAME[:KEY=VALUE,...]
  std::vector<double> hs;                // grid steps (any order; sorted decreasing)
  std::string h_text;                    // as given, for the provenance
  std::optional<std::string> k_text;     // default k (rational) of every entry that uses k,
                                         // or one per shape "K1,K2,..." (see parse_k_per_shape)
  std::optional<std::string> alpha_text; // default alpha of every entry that uses alpha
  int translations = 0;                  // 0: the untranslated shape only
  std::uint64_t seed = 0;
  std::optional<std::pair<double, double>> box; // [LO, HI]^d, default: the shape's box
  int fit_levels = 0;                           // 0: all levels
  double tolerance = 0.1;
  unsigned threads = 0; // 0: all cores (worker_count, kernel/parallel/parallel_for.hpp)
  std::string title;    // plot title (provenance only)
  // Test functions of the estimators that take one (`u`, the Laplace-Beltrami estimators):
  // each such entry without its own `u=` runs once per function; empty: the defaults
  // (default_test_functions()).
  std::vector<std::string> functions;
  // A samples sweep (exclusive with hs): the counts N (any order; sorted increasing), as given.
  std::vector<std::int64_t> samples;
  std::string samples_text;

  bool samples_sweep() const { return !samples.empty(); }
};

/// Parses `HMAX:HMIN:N` (N geometric steps), `exp:I0:I1[:STEP]` (h = exp(-i/10)) or a
/// comma-separated list `h1,h2,...` (rationals allowed), each step in (0, 1e6], at most 10000;
/// throws InvalidArgument naming `what`.
std::vector<double> parse_grid_steps(const std::string& text, const std::string& what = "--h");
/// Parses sample counts: `exp:I0:I1[:STEP]` (N = round(exp(i/10)), i = I0, I0 + STEP, ..., I1
/// in 0..180), `NMIN:NMAX:COUNT` (COUNT counts geometric from NMIN to NMAX, rounded) or a
/// comma-separated list of integers; each count in 1..10^8, at most 10000 of them, repeats
/// (after rounding) dropped; throws InvalidArgument naming `what`.
std::vector<std::int64_t> parse_sample_counts(const std::string& text,
                                              const std::string& what = "--samples");
/// Parses `LO:HI` (finite, LO < HI, |LO|, |HI| <= 1e9).
std::pair<double, double> parse_box(const std::string& text, const std::string& what = "--box");

/// The default k of each of `shapes` shapes from `K` (one value for all) or `K1,K2,...` (one
/// per shape, in the order of ExperimentConfig::shapes: papers whose shapes were run with
/// different constants, e.g. the CVIU 2014 2D figure), as texts; each a positive rational or
/// decimal. InvalidArgument naming `what` otherwise.
std::vector<std::string> k_texts_per_shape(const std::string& text, std::size_t shapes,
                                           const std::string& what = "--k");
/// The same as numbers.
std::vector<double> parse_k_per_shape(const std::string& text, std::size_t shapes,
                                      const std::string& what = "--k");

/// One estimator entry of an experiment.
struct EstimatorEntry {
  const Estimator* estimator = nullptr;
  std::string label;              // canonical spec text: the name in results.csv and summary.json
  EstimatorParameters parameters; // with the default k of the first shape
  // The parameters on each shape (they differ only when k is given per shape and the entry
  // does not set its own k).
  std::vector<EstimatorParameters> shape_parameters;
  const EstimatorParameters& on_shape(std::size_t shape) const {
    return shape < shape_parameters.size() ? shape_parameters[shape] : parameters;
  }
};

/// A validated experiment.
struct ExperimentPlan {
  std::vector<std::unique_ptr<Shape>> shapes;
  std::vector<EstimatorEntry> entries;
  std::vector<double> hs;            // decreasing, no repeats (empty in a samples sweep)
  std::vector<std::int64_t> samples; // increasing, no repeats (empty in a grid-step sweep)
  int runs_per_level = 1;            // translations per (shape, entry, h): max(1, translations)
};

struct RunRecord {
  std::size_t shape_index = 0, entry_index = 0; // into the plan
  std::string shape, estimator;                 // shape spec and entry label
  double h = 0;                                 // 0 in a samples sweep
  std::int64_t samples = 0;                     // N in a samples sweep, 0 otherwise
  int translation = 0; // in a samples sweep: the repetition (an independent sampling)
  std::vector<double> offset;
  double k = 0, alpha = 0;
  ErrorStats errors;
  double seconds = 0;
};

/// The errors of one level: the runs of one (shape, entry, h), aggregated over translations.
struct LevelErrors {
  std::size_t shape_index = 0, entry_index = 0;
  double h = 0;
  std::int64_t samples = 0;
  double linf = 0, l2 = 0, mean = 0; // max of l_inf (NaN if one is), averages of l_2, mean
  int runs = 0;
  std::int64_t elements = 0; // the fewest boundary elements measured by one of its runs
};

struct FitRecord {
  std::string shape, estimator, norm; // estimator: the entry label
  LogLogFit fit;
  std::vector<double> hs; // levels used (a samples sweep: the counts N, as doubles)
  std::optional<double> expected;
  std::string theory, hypotheses, source;
  std::optional<bool> pass; // the l_inf verdict (check_rate), when theory proves a rate
  std::string reason;       // why the verdict is not a pass (empty otherwise)
};

struct ExperimentResult {
  std::vector<EstimatorEntry> entries; // of the plan, in the configuration's order
  std::vector<RunRecord> runs;         // order: shape, entry, h decreasing, translation
  std::vector<FitRecord> fits;
  bool all_pass = true;
  unsigned threads = 1; // the workers the runs used (worker_count of the config's threads)
};

/// Progress callback: (runs done, runs total, the run just finished).
using ProgressFn = std::function<void(std::size_t, std::size_t, const RunRecord&)>;

/// Validation: throws InvalidArgument (one line naming the offending part) for empty lists,
/// unknown or repeated shapes and entries, mismatched dimensions, counts out of range.
ExperimentPlan plan_experiment(const ExperimentConfig& config);

/// One job of run_plan: the run of one entry at one (level, shape, translation), or the runs of
/// the entries whose estimators share a computation (Estimator::shared_computation), one after
/// the other on one thread (their cache then makes the shared part once).
struct ExperimentJob {
  std::size_t shape = 0;
  std::vector<std::size_t> entries; // into the plan, in the plan's order
  double h = 0;                     // 0 in a samples sweep
  std::int64_t samples = 0;         // 0 in a grid-step sweep
  int translation = 0;
  // The estimate that orders the jobs largest first: the grid points of the untranslated run's
  // digitization box (the sample count N in a samples sweep) times the number of entries.
  double size = 0;
};

/// The jobs of the plan, largest first (ExperimentJob::size decreasing; ties in the order of
/// the levels, finest first, then shape, entry, translation): the order a dynamic scheduler
/// hands them out in, so that the longest runs do not come last. O(J log J) for J jobs.
std::vector<ExperimentJob> plan_jobs(const ExperimentPlan& plan, const ExperimentConfig& config);

/// The records of a job without their measurements (errors and seconds zero): shape, entry,
/// h, N, translation, offset, k and alpha, one per entry of the job, in the job's order.
std::vector<RunRecord> job_records(const ExperimentPlan& plan, const ExperimentConfig& config,
                                   const ExperimentJob& job);

/// Runs a job on the calling thread: job_records with the errors and the seconds measured.
/// Throws Error for a non-finite error, and what the estimator throws.
std::vector<RunRecord> run_job(const ExperimentPlan& plan, const ExperimentConfig& config,
                               const ExperimentJob& job);

/// Sorts records into the order of ExperimentResult::runs (shape, entry, h decreasing or N
/// increasing, translation): the order does not depend on which worker ran what. O(n log n).
void sort_runs(std::vector<RunRecord>& runs);

/// Scheduling: runs every job of the plan (plan_jobs, largest first, over `threads` workers of
/// parallel_for); records in the order of ExperimentResult::runs. `workers`, when given,
/// receives the number of workers used.
std::vector<RunRecord> run_plan(const ExperimentPlan& plan, const ExperimentConfig& config,
                                const ProgressFn& progress = {}, unsigned* workers = nullptr);

/// Aggregation per (shape, entry, h), ordered by shape, entry, h decreasing. O(n log n).
std::vector<LevelErrors> aggregate_levels(std::vector<RunRecord> runs);

/// The fits per (shape, entry) and norm (linf, l2, mean) on the `fit_levels` finest levels
/// (0: all), with the proven rate and the l_inf verdict (check_rate, convergence/fit.hpp: fewer
/// than two levels that measured an element with a finite error is no pass); all_pass is false
/// when a verdict fails.
std::vector<FitRecord> fit_experiment(const ExperimentPlan& plan,
                                      const std::vector<LevelErrors>& levels, int fit_levels,
                                      double tolerance, bool& all_pass);

/// The result of a plan's runs (every run of the plan, in any order; `threads`: the workers
/// that ran them): sort_runs, aggregate_levels, fit_experiment.
ExperimentResult experiment_result(const ExperimentPlan& plan, const ExperimentConfig& config,
                                   std::vector<RunRecord> runs, unsigned threads);

/// plan_experiment, run_plan, aggregate_levels, fit_experiment.
ExperimentResult run_experiment(const ExperimentConfig& config, const ProgressFn& progress = {});

/// results.csv: one row per shape, estimator entry, h, translation; a samples sweep adds the
/// column `samples` (N) at the end and leaves h empty.
void write_results_csv(const ExperimentResult& result, std::ostream& out);

} // namespace zdg
