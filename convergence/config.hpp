// Experiment descriptions: the flags of `zdg converge` and TOML files are both read into
// ExperimentSettings (each value as text, with where it came from), then checked by one
// function, validate_experiment_settings, into an ExperimentConfig. A TOML value therefore
// passes exactly the checks of the flag with the same name (`tolerance = inf`, `1e300`, `-3.0`
// and `nan` are refused like `--tolerance inf`), and every refusal is one line naming the flag
// or the file, line and key.
//
// TOML keys (a file holds a table at the top level; flags given on the command line take
// precedence over the file):
//   shape / shapes          a string or an array of strings (shape specs, `zdg converge --list`)
//   estimator / estimators  a string, an array of strings `NAME[:KEY=VALUE,...]`, or tables
//                           { name = "bc-curvature", k = 1, alpha = "14/9" } (inline, or
//                           [[estimators]] sections): one entry per element
//   h                       grid steps: "HMAX:HMIN:N", "exp:I0:I1[:STEP]", "h1,h2,..." or an
//                           array of numbers
//   samples                 sample counts of a samples sweep, in place of h (sampled
//                           estimators): "exp:I0:I1[:STEP]", "NMIN:NMAX:COUNT", "n1,n2,..." or
//                           an array of integers
//   k, alpha                defaults of every entry that uses them (numbers or "14/9")
//   box                     "LO:HI" or [LO, HI]
//   translations, seed, fit_levels (or fit-levels), threads    integers
//   tolerance               a number in [0, 10]
//   title                   a string
// Numbers may be written as TOML numbers or as strings ("14/9", "1.7e-4").
//
// Cost: linear in the text, plus parse_shape and the estimator specs (bounded, see
// kernel/digitization/polynomial.hpp for `poly:`).
#pragma once

#include <zdg/convergence/experiment.hpp>

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace zdg {

/// A value as written, and where: "--tolerance" or "run.toml:7: key 'tolerance'".
struct Setting {
  std::string text;
  std::string origin;
};

struct ExperimentSettings {
  std::vector<Setting> shapes, estimators, functions;
  std::optional<Setting> h, samples, k, alpha, box, title, translations, seed, fit_levels, threads,
      tolerance;

  /// Takes every setting not given here from `file` (the command line overrides a file).
  void fill_from(const ExperimentSettings& file);
};

/// Reads a TOML experiment description (keys above); checks the TOML types (a table where an
/// estimator table is expected, a string or number where a value is), not the values. Throws
/// InvalidArgument "SOURCE:LINE: ..." for syntax errors, unknown keys and wrong types.
ExperimentSettings parse_experiment_toml(std::string_view text, const std::string& source);

/// The one validation of flags and files: grid steps, counts, tolerance, box, k and alpha
/// (finite, in range), then the shapes and estimator entries (plan_experiment). Throws
/// InvalidArgument naming the setting's origin.
ExperimentConfig validate_experiment_settings(const ExperimentSettings& settings);

/// A TOML text to a validated configuration: parse_experiment_toml, then
/// validate_experiment_settings.
ExperimentConfig parse_experiment_config(std::string_view text, const std::string& source);

} // namespace zdg
