// The estimator registry of the convergence driver. A registry entry owns everything about
// its estimator: its dimension, what its error measures, the parameters it reads (the radius
// law R = k h^alpha, the mask n = k h^{-alpha}, ...) with their defaults and ranges, the rate
// that theory proves for it (as a function of the shape's regularity class and of the
// parameters, with the source and the hypotheses: papers/THEORY.md), and how to run it once
// on a shape at one grid step and translation, returning the error statistics over its
// boundary elements (or of its global quantity: then linf = l2 = mean = |error|, n = 1).
//
// Adding an estimator is one file: define a register function that appends Estimator
// entries, and call it from estimators() in convergence/estimator.cpp (2D: estimators_2d.cpp;
// the DSS-based and 3D estimators plug in the same way). The driver loop, the error norms,
// the fit, the theory check and the outputs never look inside an estimator.
//
// Per-estimator parameters. An experiment names an estimator with its own parameters,
// `NAME[:KEY=VALUE,...]` (parse_estimator_spec): `bc-curvature:k=1,alpha=14/9`,
// `ii-curvature:k=5`. A key must be one of the estimator's parameters; a value is a positive
// rational or decimal in the parameter's range. Parameters not given take the experiment's
// defaults (--k, --alpha), then the registry's. The canonical text of the spec (its label) names
// the entry in results.csv and summary.json, so two entries of one estimator with different
// parameters stay apart.
#pragma once

#include <zdg/convergence/shape.hpp>

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace zdg {

/// Errors over the n boundary elements of one run: max, root mean square, mean of |error|.
struct ErrorStats {
  double linf = 0, l2 = 0, mean = 0;
  std::int64_t n = 0;
};

/// Accumulates absolute errors.
class ErrorAccumulator {
public:
  void add(double error) {
    double a = error < 0 ? -error : error;
    if (!(a <= linf_)) linf_ = a; // a NaN error propagates
    sum_ += a;
    sum2_ += a * a;
    ++n_;
  }
  ErrorStats stats() const;

private:
  double linf_ = 0, sum_ = 0, sum2_ = 0;
  std::int64_t n_ = 0;
};

/// The parameters an estimator may read (each entry declares which ones it uses).
struct EstimatorParameters {
  double k = 0;      // radius or mask factor
  double alpha = 0;  // exponent of the law R = k h^alpha (or n = k h^{-alpha})
  double degree = 0; // polynomial degree (jet fitting); 0 where unused
  std::string function =
      {};                  // test function u (text, convergence/scalar_field.hpp); "" where unused
  double count = 0;        // how many (lb-spectrum: eigenvalues, `n`); 0 where unused
  std::string choice = {}; // a named variant (lb-spectrum: `operator`); "" where unused
  double sigma = 0;        // noise standard deviation of sampled points (recon-*); 0 where unused
};

/// Everything one run needs.
struct RunInput {
  const Shape& shape;
  double h;
  std::vector<double> translation;            // the shape is X + translation
  std::vector<std::pair<double, double>> box; // continuous digitization domain per axis
  double k;                                   // estimator parameter (radius/mask factor)
  double alpha;                               // exponent of the radius law
  double degree = 0;                          // polynomial degree (jet fitting)
  std::string function = {};                  // test function u (Laplace-Beltrami estimators)
  double count = 0;                           // how many (lb-spectrum: eigenvalues)
  std::string choice = {};                    // a named variant (lb-spectrum: the operator)
  // A samples sweep (ExperimentConfig::samples; Estimator::sampled): h is 0 and the run
  // samples `samples` points of the shape itself (convergence/surface_sampling.hpp) from
  // `seed` (the experiment's seed and the run's repetition), with noise sigma.
  std::int64_t samples = 0;
  std::uint64_t seed = 0;
  double sigma = 0;
};

/// One parameter of an estimator: its name (`k`, `alpha`, `degree`, `u`, `sigma`), default (a
/// rational, as text), the admissible values lo < value <= hi (lo < value < hi when open_above,
/// lo <= value <= hi when closed_below), and what it means for this estimator. A text parameter
/// (`u`, the test function of the Laplace-Beltrami estimators) has check_text, which throws
/// InvalidArgument for a value it refuses; lo, hi do not apply to it.
struct EstimatorParameter {
  std::string name;
  std::string default_text;
  double lo = 0, hi = 0;
  std::string meaning;
  bool open_above = false;
  std::function<void(const std::string&)> check_text = {};
  bool closed_below = false;
};

/// A rate that theory proves: error = O(h^slope) under the hypotheses, from the source. For a
/// sampled estimator (Estimator::sampled) the rate is in the number of points N: error =
/// O(N^slope), slope < 0, checked as fitted slope <= slope + tolerance.
struct ProvenRate {
  double slope = 0;
  std::string statement;  // "O(h^{1/3})"
  std::string hypotheses; // "C^3 boundary with positive reach, R = k h^{1/3}"
  std::string source;     // the paper (papers/THEORY.md lists them)
};

/// What theory says about an estimator: a one-line summary of its rates with their sources,
/// and the rate for a shape class and parameters (nullopt where theory proves none: then the
/// fit is reported without a verdict).
struct EstimatorTheory {
  std::string summary;
  std::function<std::optional<ProvenRate>(const ShapeClass&, const EstimatorParameters&)> rate;
};

struct Estimator {
  std::string name;
  int dimension; // 2 or 3; 0: any (the run dispatches on the shape)
  std::string description;
  std::string quantity; // what the error measures ("curvature", "angle (rad)", ...)
  std::vector<EstimatorParameter> parameters;
  EstimatorTheory theory;
  std::function<ErrorStats(const RunInput&)> run;
  /// Non-empty when the run shares one computation with the other estimators of the same tag
  /// (the 3D integral invariants: one set of ball moments per shape, h, translation and R):
  /// run_plan then runs them one after the other on one thread, where the estimators' own
  /// cache serves them all.
  std::string shared_computation = {};
  /// True when a run samples N points of the shape (RunInput::samples) instead of digitizing
  /// it at a grid step: such an estimator runs in samples sweeps only (`zdg converge
  /// --samples`), and the others in grid-step sweeps only.
  bool sampled = false;

  /// The declared parameter `name`, or nullptr.
  const EstimatorParameter* parameter(std::string_view name) const;
  /// The proven rate on `shape` with parameters p (theory.rate on the shape's class).
  std::optional<ProvenRate> proven_rate(const Shape& shape, const EstimatorParameters& p) const;
};

const std::vector<Estimator>& estimators();
/// Throws InvalidArgument listing the known names.
const Estimator& find_estimator(const std::string& name);

/// A positive rational (7, 14/9) or decimal (0.25, 1.7e-4) parameter value as a double,
/// naming `what` in errors; finite, > 0 (InvalidArgument otherwise).
double parse_parameter(const std::string& text, const std::string& what);

/// One estimator of an experiment with its own parameter values (text as given).
struct EstimatorSpec {
  std::string name;
  std::vector<std::pair<std::string, std::string>> parameters; // in the registry's order

  /// The canonical text: `name` alone, or `name:k=5,alpha=1/3` (the order of the registry's
  /// parameter list, values as given).
  std::string label() const;
  /// The value of parameter `key` given here, if any.
  std::optional<std::string> value(std::string_view key) const;
};

/// Parses `NAME[:KEY=VALUE,...]`: the estimator must exist, each key be one of its parameters
/// (given once), each value in the parameter's range. Throws InvalidArgument naming the part.
EstimatorSpec parse_estimator_spec(std::string_view text);

/// The parameters of a run of `spec`: its own values, then the experiment's defaults k, alpha
/// (text, when given), then the registry's defaults; each checked against its range.
EstimatorParameters resolve_parameters(const EstimatorSpec& spec,
                                       const std::optional<std::string>& default_k,
                                       const std::optional<std::string>& default_alpha);

namespace detail {
/// k and alpha of the radius law R = k h^alpha of the integral invariants (defaults k = 3,
/// alpha = 1/3; alpha in (0, 1] so that R / h does not vanish as h -> 0).
std::vector<EstimatorParameter> radius_law_parameters();
/// alpha = 1/3 up to the rounding of its text: the law the integral-invariant theorems assume.
bool is_one_third(double alpha);

void register_2d_estimators(std::vector<Estimator>& out);
void register_3d_estimators(std::vector<Estimator>& out);
void register_hausdorff_estimators(std::vector<Estimator>& out); // dimension 0: any
void register_jet_estimators(std::vector<Estimator>& out);
void register_calculus_estimators(std::vector<Estimator>& out);
void register_vcm_cnc_estimators(std::vector<Estimator>& out);
void register_mdca_estimators(std::vector<Estimator>& out); // mdca-curvature (2D)
void register_ii_auto_estimators(std::vector<Estimator>& out);
void register_probing_estimators(std::vector<Estimator>& out);
void register_spectrum_estimators(std::vector<Estimator>& out);       // lb-spectrum
void register_reconstruction_estimators(std::vector<Estimator>& out); // recon-* (sampled)
} // namespace detail

} // namespace zdg
