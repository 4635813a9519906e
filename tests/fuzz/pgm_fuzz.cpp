// Fuzz target: the PGM reader on the bytes of a file (kernel/io/pgm_io.hpp parse_pgm).
#include <zdg/arith/error.hpp>
#include <zdg/kernel/io/pgm_io.hpp>

#include <cstddef>
#include <cstdint>
#include <string_view>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view bytes(reinterpret_cast<const char*>(data), size);
  try {
    const auto img = zdg::parse_pgm(bytes, "fuzz.pgm");
    // The raster announced by the header was in the file: one byte a pixel at least.
    if (static_cast<std::size_t>(img.size()) > size) __builtin_trap();
  } catch (const zdg::Error&) {
  }
  return 0;
}
