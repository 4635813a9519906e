#include <zdg/arith/integer.hpp>

#include <algorithm>
#include <cctype>

namespace zdg {

namespace detail {

std::string int128_to_string(int128_t v) {
  if (v == 0) return "0";
  bool neg = v < 0;
  // Work on the magnitude as unsigned so that the minimum converts too.
  uint128_t u = neg ? static_cast<uint128_t>(-(v + 1)) + 1 : static_cast<uint128_t>(v);
  std::string s = machine_to_string(u);
  return neg ? "-" + s : s;
}

void throw_overflow(const char* type, const char* op, const std::string& a, const std::string& b) {
  std::string what = std::string(type) + " overflow: ";
  if (b.empty()) {
    what += std::string(op) + " " + a + " does not fit";
  } else if (a == "0" && std::string(op) == "-") {
    what += "-(" + b + ") does not fit";
  } else {
    what += a + " " + op + " " + b + " does not fit";
  }
  throw OverflowError(what);
}

void throw_division_by_zero(const std::string& a) {
  throw InvalidArgument("division by zero: " + a + " / 0");
}

} // namespace detail

std::string to_string(Int64 v) {
  return std::to_string(v.value());
}
std::string to_string(Int128 v) {
  return detail::int128_to_string(v.value());
}
std::string to_string(const BigInt& v) {
  return v.str();
}

BigInt to_bigint(Int128 v) {
  int128_t x = v.value();
  bool neg = x < 0;
  uint128_t u = neg ? static_cast<uint128_t>(-(x + 1)) + 1 : static_cast<uint128_t>(x);
  BigInt r = BigInt(static_cast<std::uint64_t>(u >> 64));
  r <<= 64;
  r += BigInt(static_cast<std::uint64_t>(u));
  return neg ? BigInt(-r) : r;
}

template <TowerInt I>
I parse_integer(std::string_view text) {
  std::string_view digits = text;
  bool neg = false;
  if (!digits.empty() && (digits.front() == '+' || digits.front() == '-')) {
    neg = digits.front() == '-';
    digits.remove_prefix(1);
  }
  if (digits.empty() ||
      !std::all_of(digits.begin(), digits.end(), [](char c) { return c >= '0' && c <= '9'; })) {
    throw InvalidArgument("not an integer: '" + std::string(text) + "'");
  }
  if constexpr (std::same_as<I, BigInt>) {
    BigInt r{std::string(digits)};
    return neg ? BigInt(-r) : r;
  } else {
    // Accumulate negatively so that the minimum parses.
    I r = 0;
    for (char c : digits) r = r * 10 - (c - '0');
    return neg ? r : I(-r);
  }
}

template Int64 parse_integer<Int64>(std::string_view);
template Int128 parse_integer<Int128>(std::string_view);
template BigInt parse_integer<BigInt>(std::string_view);

} // namespace zdg
