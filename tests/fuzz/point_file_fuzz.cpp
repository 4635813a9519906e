// Fuzz target: point files and digital path files (kernel/io/point_file.hpp), the inputs of
// `zdg hull points` and `zdg dss`.
#include <zdg/arith/error.hpp>
#include <zdg/kernel/io/point_file.hpp>

#include <cstddef>
#include <cstdint>
#include <string_view>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  try {
    const auto p = zdg::parse_point_file(text, "fuzz.txt", {2, 3});
    if (p.coords.size() != p.size() * static_cast<std::size_t>(p.dim)) __builtin_trap();
  } catch (const zdg::Error&) {
  }
  try {
    const auto f = zdg::parse_digital_path_file(text, "fuzz.txt");
    if (f.chain) (void)zdg::freeman_points(*f.chain); // may leave int64: OverflowError
  } catch (const zdg::Error&) {
  }
  return 0;
}
