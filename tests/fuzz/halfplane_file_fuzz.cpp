// Fuzz target: half-plane files "a b c" (kernel/io/halfplane_file.hpp), the input of
// `zdg hull halfplanes`.
#include <zdg/arith/error.hpp>
#include <zdg/kernel/io/halfplane_file.hpp>

#include <cstddef>
#include <cstdint>
#include <string_view>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  try {
    const auto hs = zdg::parse_halfplane_file(text, "fuzz.txt");
    for (const auto& h : hs) {
      if (h.a.den() <= 0 || h.b.den() <= 0 || h.c.den() <= 0) __builtin_trap();
    }
  } catch (const zdg::Error&) {
  }
  return 0;
}
