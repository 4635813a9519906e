#include <zdg/kernel/curves/freeman_chain.hpp>

#include <zdg/arith/error.hpp>
#include <zdg/arith/integer.hpp>

#include <cctype>
#include <sstream>

namespace zdg {

Point2<std::int64_t> freeman_step(char code) {
  switch (code) {
  case '0':
    return {1, 0};
  case '1':
    return {0, 1};
  case '2':
    return {-1, 0};
  case '3':
    return {0, -1};
  default:
    throw InvalidArgument(std::string("Freeman chain: invalid code '") + code +
                          "' (codes are 0, 1, 2, 3)");
  }
}

FreemanChain parse_freeman_chain(std::string_view text) {
  std::size_t pos = 0;
  auto next_token = [&]() -> std::string_view {
    while (pos < text.size() && std::isspace(static_cast<unsigned char>(text[pos]))) ++pos;
    std::size_t b = pos;
    while (pos < text.size() && !std::isspace(static_cast<unsigned char>(text[pos]))) ++pos;
    return text.substr(b, pos - b);
  };
  auto coordinate = [&](const char* what) {
    std::string_view tok = next_token();
    if (tok.empty()) {
      throw InvalidArgument(std::string("Freeman chain: missing ") + what + " in '" +
                            std::string(text) + "' (expected 'x0 y0 codes')");
    }
    try {
      return parse_integer<Int64>(tok).value();
    } catch (const Error&) {
      throw InvalidArgument(std::string("Freeman chain: ") + what + " '" + std::string(tok) +
                            "' is not a 64-bit integer");
    }
  };
  FreemanChain chain;
  chain.start.x = coordinate("x0");
  chain.start.y = coordinate("y0");
  std::size_t k = 0;
  for (; pos < text.size(); ++pos) {
    char c = text[pos];
    if (std::isspace(static_cast<unsigned char>(c))) continue;
    if (c < '0' || c > '3') {
      throw InvalidArgument(std::string("Freeman chain: invalid code '") + c + "' at code " +
                            std::to_string(k + 1) + " (codes are 0, 1, 2, 3)");
    }
    chain.codes.push_back(c);
    ++k;
  }
  return chain;
}

std::string to_string(const FreemanChain& chain) {
  return std::to_string(chain.start.x) + " " + std::to_string(chain.start.y) + " " + chain.codes;
}

std::vector<Point2<std::int64_t>> freeman_points(const FreemanChain& chain) {
  std::vector<Point2<std::int64_t>> pts;
  pts.reserve(chain.codes.size() + 1);
  Int64 x = chain.start.x, y = chain.start.y;
  pts.push_back(chain.start);
  for (char c : chain.codes) {
    auto s = freeman_step(c);
    x += s.x;
    y += s.y;
    pts.push_back({x.value(), y.value()});
  }
  return pts;
}

FreemanChain freeman_chain_of(std::span<const Point2<std::int64_t>> points) {
  if (points.empty()) throw InvalidArgument("Freeman chain of an empty path");
  FreemanChain chain{points[0], {}};
  chain.codes.reserve(points.size() - 1);
  for (std::size_t k = 1; k < points.size(); ++k) {
    int128_t dx = int128_t(points[k].x) - points[k - 1].x;
    int128_t dy = int128_t(points[k].y) - points[k - 1].y;
    char c = dx == 1 && dy == 0    ? '0'
             : dx == 0 && dy == 1  ? '1'
             : dx == -1 && dy == 0 ? '2'
             : dx == 0 && dy == -1 ? '3'
                                   : 'x';
    if (c == 'x') {
      std::ostringstream m;
      m << "Freeman chain: point " << k << " " << points[k] << " is not 4-adjacent to point "
        << k - 1 << " " << points[k - 1];
      throw InvalidArgument(m.str());
    }
    chain.codes.push_back(c);
  }
  return chain;
}

bool is_closed(const FreemanChain& chain) {
  std::int64_t dx = 0, dy = 0;
  for (char c : chain.codes) {
    auto s = freeman_step(c);
    dx += s.x;
    dy += s.y;
  }
  return dx == 0 && dy == 0;
}

} // namespace zdg
