// Fuzz target: a TOML experiment description through the library's one reader and validation
// (convergence/config.hpp), as `zdg converge CONFIG.toml` reads it. Expected outcomes: a
// validated ExperimentConfig, or zdg::Error (one line). Anything else (another exception, a
// crash, a sanitizer report, unbounded time or memory) is a finding.
#include <zdg/arith/error.hpp>
#include <zdg/convergence/config.hpp>

#include <cstddef>
#include <cstdint>
#include <string_view>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  try {
    const zdg::ExperimentConfig c = zdg::parse_experiment_config(text, "fuzz.toml");
    // A validated configuration is one the driver accepts.
    if (c.shapes.empty() || c.estimators.empty() || c.hs.empty()) __builtin_trap();
  } catch (const zdg::Error&) {
  }
  return 0;
}
