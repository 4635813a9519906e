// Fuzz target: the small parsers behind the command-line option values (and the same TOML
// keys): --metric (kernel/transforms/lp_metric.hpp parse_metric), --h (parse_grid_steps), --box
// (parse_box), --k per shape (parse_k_per_shape), --estimator NAME[:KEY=VALUE,...]
// (parse_estimator_spec), --raw-shape (parse_raw_shape), --skeleton (parse_skeleton_kind) and
// the finite reals and bounded integers of every other option (convergence/number_text.hpp).
// The first byte picks the parser, the rest is the text. Expected outcomes: a value that
// satisfies the parser's documented contract, or zdg::InvalidArgument (one line).
#include <zdg/arith/error.hpp>
#include <zdg/convergence/estimator.hpp>
#include <zdg/convergence/experiment.hpp>
#include <zdg/convergence/number_text.hpp>
#include <zdg/kernel/io/raw_io.hpp>
#include <zdg/kernel/topology/skeleton_constraints.hpp>
#include <zdg/kernel/transforms/lp_metric.hpp>

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>

namespace {

void require(bool ok) {
  if (!ok) __builtin_trap();
}

void check(std::uint8_t which, const std::string& text) {
  switch (which % 9) {
  case 0: {
    const zdg::Metric m = zdg::parse_metric(text);
    require(m.is_inf() || (m.p >= 1 && m.p <= zdg::kMaxMetricP));
    break;
  }
  case 1: {
    const auto hs = zdg::parse_grid_steps(text);
    require(!hs.empty() && hs.size() <= 10000);
    for (double h : hs) require(std::isfinite(h) && h > 0 && h <= 1e6);
    break;
  }
  case 2: {
    const auto [lo, hi] = zdg::parse_box(text);
    require(std::isfinite(lo) && std::isfinite(hi) && lo < hi);
    break;
  }
  case 3: {
    for (std::size_t shapes : {1, 3}) {
      try {
        const auto ks = zdg::parse_k_per_shape(text, shapes);
        require(ks.size() == shapes);
        for (double k : ks) require(std::isfinite(k) && k > 0);
      } catch (const zdg::InvalidArgument&) {
      }
    }
    break;
  }
  case 4: {
    const zdg::EstimatorSpec spec = zdg::parse_estimator_spec(text);
    // The canonical label reads back to the same entry.
    const zdg::EstimatorSpec again = zdg::parse_estimator_spec(spec.label());
    require(again.name == spec.name && again.parameters == spec.parameters);
    // Resolved with the registry's defaults: the values of a run, or InvalidArgument.
    (void)zdg::resolve_parameters(spec, std::nullopt, std::nullopt);
    break;
  }
  case 5: {
    const auto shape = zdg::parse_raw_shape(text);
    require(shape.size() == 2 || shape.size() == 3);
    for (std::int64_t n : shape) require(n > 0);
    break;
  }
  case 6: {
    const auto kind = zdg::parse_skeleton_kind(text);
    require(zdg::parse_skeleton_kind(zdg::skeleton_kind_name(kind)) == kind);
    break;
  }
  case 7: {
    const double v = zdg::parse_real(text, "--value");
    require(std::isfinite(v));
    require(zdg::parse_real(zdg::real_text(v), "--value") == v);
    break;
  }
  default: {
    const std::int64_t v = zdg::parse_integer_in(text, "--count", -1000, 1000);
    require(v >= -1000 && v <= 1000);
    break;
  }
  }
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return 0;
  const std::string text(reinterpret_cast<const char*>(data + 1), size - 1);
  try {
    check(data[0], text);
  } catch (const zdg::InvalidArgument&) {
  }
  return 0;
}
