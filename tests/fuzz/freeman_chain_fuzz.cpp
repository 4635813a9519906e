// Fuzz target: Freeman chains "x0 y0 codes" (kernel/curves/freeman_chain.hpp). A chain that parses
// prints back to text that parses to the same chain, and its points (when they stay in int64)
// give the same chain back.
#include <zdg/arith/error.hpp>
#include <zdg/kernel/curves/freeman_chain.hpp>

#include <cstddef>
#include <cstdint>
#include <string_view>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  try {
    const zdg::FreemanChain c = zdg::parse_freeman_chain(text);
    if (!(zdg::parse_freeman_chain(zdg::to_string(c)) == c)) __builtin_trap();
    const auto pts = zdg::freeman_points(c);
    if (pts.size() != c.codes.size() + 1) __builtin_trap();
    if (!(zdg::freeman_chain_of(pts) == c)) __builtin_trap();
  } catch (const zdg::Error&) {
  }
  return 0;
}
