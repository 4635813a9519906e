// Fuzz target: the "convex check" requests of zdg serve (cli/serve_handlers.cpp,
// serve_convex_check: a list of 2D or 3D integer points of any size, a definition, a column
// limit) and the digital convexity behind them (kernel/hulls/digital_convexity.hpp). The bytes
// are the request line; when it parses as a JSON object its "max_columns" is set to 4096, which
// bounds the H-convexity sweep of a long thin set ({(0,0), (10^12,1)} is H-convex over 10^12
// columns); full convexity is bounded by the number of points. Expected outcome: one line of
// JSON, an object (the answer or {"error": ...}), never an exception.
#include <zdg/cli/serve.hpp>

#include <nlohmann/json.hpp>

#include <cstddef>
#include <cstdint>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  std::string line(reinterpret_cast<const char*>(data), size);
  auto request = nlohmann::json::parse(line, nullptr, false);
  if (!request.is_discarded() && request.is_object()) {
    request["max_columns"] = 4096;
    line = request.dump();
  }
  const std::string answer = zdg::cli::serve_answer("convex check", line);
  const auto j = nlohmann::json::parse(answer, nullptr, false);
  if (j.is_discarded() || !j.is_object()) __builtin_trap();
  return 0;
}
