// Fuzz target: DGtal .vol files (Version 2 and 3) through read_vol. Every input must end in
// an image or a zdg::Error; a crash, a sanitizer report, a leak or an allocation the file's
// size cannot justify is a bug.
#include <zdg/arith/error.hpp>
#include <zdg/kernel/io/vol_io.hpp>

#include <cstddef>
#include <cstdint>
#include <sstream>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  std::istringstream in(std::string(reinterpret_cast<const char*>(data), size));
  try {
    const auto img = zdg::read_vol(in, "fuzz.vol");
    if (static_cast<std::uint64_t>(img.size()) > size * 1032 + 64) __builtin_trap();
  } catch (const zdg::Error&) {
  }
  return 0;
}
