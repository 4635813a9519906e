// Fuzz target: raw volumes through read_raw_bytes. The first four bytes choose the layout
// (three extents in 1..16, or two when the third byte is 0, and the dtype); the rest is the
// file. Every input must end in a volume or a zdg::Error.
#include <zdg/arith/error.hpp>
#include <zdg/kernel/io/raw_io.hpp>

#include <cstddef>
#include <cstdint>
#include <string_view>
#include <vector>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size < 4) return 0;
  std::vector<std::int64_t> shape{1 + data[0] % 16, 1 + data[1] % 16};
  if (data[2] != 0) shape.push_back(1 + data[2] % 16);
  const zdg::DType types[] = {zdg::DType::Bool, zdg::DType::U8,  zdg::DType::I8,  zdg::DType::U16,
                              zdg::DType::I16,  zdg::DType::U32, zdg::DType::I32, zdg::DType::U64,
                              zdg::DType::I64,  zdg::DType::F32, zdg::DType::F64};
  const zdg::DType t = types[data[3] % 11];
  try {
    const auto v = zdg::read_raw_bytes(
        std::string_view(reinterpret_cast<const char*>(data + 4), size - 4), "fuzz.raw", shape, t);
    for (std::int64_t i = 0; i < v.count(); ++i) (void)v.value(i);
  } catch (const zdg::Error&) {
  }
  return 0;
}
