#include <zdg/arith/integer.hpp>

#include <gmp.h>

#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <new>
#include <optional>

namespace zdg {

namespace {

// GMP's allocation functions: its default ones print "GNU MP: Cannot allocate memory" and
// abort the process (the command line, `zdg serve`, the Python interpreter). These throw
// std::bad_alloc instead, which every front end turns into its one-line "out of memory" error.
// The exception unwinds through GMP's C frames (built with unwind tables on the supported
// platforms: tests/arith/integer_test.cpp checks it under RLIMIT_AS). malloc/realloc/free as
// GMP's defaults, so memory allocated before the installation is freed correctly.
void* gmp_allocate(std::size_t n) {
  void* p = std::malloc(n);
  if (p == nullptr && n != 0) throw std::bad_alloc();
  return p;
}
void* gmp_reallocate(void* p, std::size_t /*old*/, std::size_t n) {
  void* q = std::realloc(p, n);
  if (q == nullptr && n != 0) throw std::bad_alloc();
  return q;
}
void gmp_free(void* p, std::size_t /*size*/) {
  std::free(p);
}

// Installed when the library is loaded: this file defines BigInt's conversions (to_string,
// parse_integer), which every program using BigInt links.
[[maybe_unused]] const bool gmp_allocation_installed =
    (mp_set_memory_functions(gmp_allocate, gmp_reallocate, gmp_free), true);

} // namespace

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

namespace {

// The text of a decimal integer: its sign and its digits without leading zeros ("" for zero).
struct DecimalText {
  bool negative = false;
  std::string_view digits;
};

std::string quoted_excerpt(std::string_view text) {
  constexpr std::size_t kShown = 40;
  std::string s(text.substr(0, kShown));
  for (char& c : s) {
    if (static_cast<unsigned char>(c) < 0x20 || c == 0x7f) c = '?';
  }
  return "'" + s +
         (text.size() > kShown ? "...' (" + std::to_string(text.size()) + " characters)" : "'");
}

// The digits after an optional sign, when the text is [+-]digits.
std::optional<std::string_view> decimal_digits(std::string_view text) {
  std::string_view rest = text;
  if (!rest.empty() && (rest.front() == '+' || rest.front() == '-')) rest.remove_prefix(1);
  if (rest.empty() ||
      !std::all_of(rest.begin(), rest.end(), [](char c) { return c >= '0' && c <= '9'; })) {
    return std::nullopt;
  }
  return rest;
}

DecimalText decimal_text(std::string_view text) {
  DecimalText d;
  const auto digits = decimal_digits(text);
  if (!digits) throw InvalidArgument("not a decimal integer: " + quoted_excerpt(text));
  d.negative = text.front() == '-';
  std::string_view rest = *digits;
  while (!rest.empty() && rest.front() == '0') rest.remove_prefix(1);
  d.digits = rest;
  if (rest.empty()) d.negative = false; // -0 is 0
  return d;
}

// Accumulates negatively so that the minimum of a checked type parses.
template <BuiltinInt T>
Checked<T> accumulate(const DecimalText& d) {
  Checked<T> r = 0;
  for (char c : d.digits) r = r * 10 - (c - '0');
  return d.negative ? r : Checked<T>(-r);
}

} // namespace

bool is_decimal_integer(std::string_view text) {
  return decimal_digits(text).has_value();
}

template <ParsableInt T>
T parse_integer(std::string_view text) {
  const DecimalText d = decimal_text(text);
  if constexpr (std::same_as<T, BigInt>) {
    BigInt r;
    if (d.digits.empty()) return r;
    // GMP reads the digits in base 10 as told: the leading zeros are gone, no prefix remains.
    const std::string digits(d.digits);
    if (mpz_set_str(r.backend().data(), digits.c_str(), 10) != 0) {
      throw InvalidArgument("not a decimal integer: " + quoted_excerpt(text));
    }
    return d.negative ? BigInt(-r) : r;
  } else if constexpr (TowerInt<T>) {
    try {
      return accumulate<typename T::value_type>(d);
    } catch (const OverflowError&) {
      throw OverflowError("integer " + quoted_excerpt(text) + " does not fit " + T::type_name);
    }
  } else {
    // A machine type of at most 64 bits: read on 128 bits (every uint64 fits), then narrow.
    int128_t wide = 0;
    bool fits = d.digits.size() <= 20;
    if (fits) {
      wide = accumulate<int128_t>(d).value();
      fits = wide >= static_cast<int128_t>(std::numeric_limits<T>::min()) &&
             wide <= static_cast<int128_t>(std::numeric_limits<T>::max());
    }
    if (!fits) {
      throw OverflowError("integer " + quoted_excerpt(text) + " is out of range for " +
                          (std::is_signed_v<T> ? "a signed " : "an unsigned ") +
                          std::to_string(8 * sizeof(T)) + "-bit integer");
    }
    return static_cast<T>(wide);
  }
}

template Int64 parse_integer<Int64>(std::string_view);
template Int128 parse_integer<Int128>(std::string_view);
template BigInt parse_integer<BigInt>(std::string_view);
template int parse_integer<int>(std::string_view);
template unsigned parse_integer<unsigned>(std::string_view);
template long parse_integer<long>(std::string_view);
template unsigned long parse_integer<unsigned long>(std::string_view);
template long long parse_integer<long long>(std::string_view);
template unsigned long long parse_integer<unsigned long long>(std::string_view);

} // namespace zdg
