// Fuzz target: the .npy reader on the bytes of a file (kernel/io/npy_io.hpp parse_npy). An array
// it accepts must survive the conversions the commands apply and a write/read round trip.
#include <zdg/arith/error.hpp>
#include <zdg/kernel/io/npy_io.hpp>

#include <cstddef>
#include <cstdint>
#include <string_view>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view bytes(reinterpret_cast<const char*>(data), size);
  try {
    const zdg::NpyArray a = zdg::parse_npy(bytes, "fuzz.npy");
    // The data size was checked against the header: count * itemsize == bytes.
    if (static_cast<std::uint64_t>(a.count()) * zdg::dtype_size(a.dtype) != a.bytes.size())
      __builtin_trap();
    const zdg::NpyArray b = zdg::parse_npy(zdg::npy_file_bytes(a), "round-trip.npy");
    if (b.shape != a.shape || b.dtype != a.dtype || b.bytes != a.bytes) __builtin_trap();
    // The conversions' errors name the file (issue #41: "empty array" named none).
    for (int k = 0; k < 2; ++k) {
      try {
        if (k == 0) {
          (void)zdg::npy_to_mask(a, {}, "fuzz.npy");
        } else {
          (void)zdg::npy_to_int64(a, {}, "fuzz.npy");
        }
      } catch (const zdg::Error& e) {
        if (std::string_view(e.what()).rfind("fuzz.npy: ", 0) != 0) __builtin_trap();
      }
    }
  } catch (const zdg::Error&) {
  }
  return 0;
}
