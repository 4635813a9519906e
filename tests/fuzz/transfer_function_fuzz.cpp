// Fuzz target: the transfer-function reader of zdg render volume
// (kernel/render/volume_render.hpp parse_transfer_function, text and JSON forms). Every input
// ends in a valid function or a one-line zdg::Error naming the file; an accepted function
// evaluates inside [0, 1] everywhere.
#include <zdg/arith/error.hpp>
#include <zdg/kernel/render/volume_render.hpp>

#include <cstddef>
#include <cstdint>
#include <string_view>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  try {
    const zdg::TransferFunction tf = zdg::parse_transfer_function(text, "fuzz.tf");
    tf.validate("fuzz.tf");
    for (const auto& p : tf.points)
      for (double v : {p.value - 1, p.value, p.value + 0.5}) {
        const zdg::Rgba c = tf(v);
        for (double x : {c.r, c.g, c.b, c.a})
          if (!(x >= 0 && x <= 1)) __builtin_trap();
      }
  } catch (const zdg::Error& e) {
    const std::string_view w = e.what();
    if (w.rfind("fuzz.tf", 0) != 0 || w.find('\n') != std::string_view::npos) __builtin_trap();
  }
  return 0;
}
