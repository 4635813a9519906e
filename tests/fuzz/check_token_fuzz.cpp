// Fuzz target: the replay tokens of zdg check (convergence/check/property.hpp parse_token,
// "TYPE.BITS.MAXSIZE.SEED16HEX", from the command line's --replay). Expected outcomes: a token
// that make_token writes back identically, or zdg::InvalidArgument.
#include <zdg/arith/error.hpp>
#include <zdg/convergence/check/property.hpp>

#include <cstddef>
#include <cstdint>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    const auto [params, seed] = zdg::check::parse_token(text);
    const std::string back = zdg::check::make_token(params, seed);
    // The canonical form parses to the same parameters.
    const auto [p2, s2] = zdg::check::parse_token(back);
    if (p2.type != params.type || p2.bits != params.bits || p2.max_size != params.max_size ||
        s2 != seed) {
      __builtin_trap();
    }
  } catch (const zdg::InvalidArgument&) {
  }
  return 0;
}
