// The integer tower of zdg: Int64, Int128 (arith/checked.hpp, no Boost) and BigInt.
//
//   Int64  = Checked<int64_t>   the fast path; +, -, *, unary -, abs, /, % report overflow
//   Int128 = Checked<__int128>  the same checks on 128 bits
//   BigInt = Boost.Multiprecision number on GMP's mpz (expression templates off): exact for
//            every size, limited by memory only.
//
// Checked<T> never wraps: an operation whose exact result leaves T throws zdg::OverflowError
// (built on the compiler's __builtin_*_overflow, a flag test after the machine instruction,
// so the fast path costs about one predictable branch). Algorithms are templates over the
// integer type and use plain operators; "exact by escalation" (arith/escalate.hpp) re-runs
// an algorithm on the next wider type when OverflowError is thrown.
//
// Also here, for every type of the tower: floor and ceiling division, modulo (floor and
// Euclidean), gcd, extended gcd (Bezout), checked conversions between the types, decimal
// parsing and printing.
#pragma once

#include <zdg/arith/checked.hpp>
#include <zdg/arith/error.hpp>

#include <boost/multiprecision/gmp.hpp>

#include <compare>
#include <concepts>
#include <cstdint>
#include <limits>
#include <ostream>
#include <string>
#include <string_view>
#include <type_traits>
#include <utility>

namespace zdg {

/// Arbitrary-precision integer (GMP mpz through Boost.Multiprecision, no expression templates).
using BigInt =
    boost::multiprecision::number<boost::multiprecision::gmp_int, boost::multiprecision::et_off>;

/// The three shipped integer types, for tests and explicit instantiations.
template <class I>
concept TowerInt = std::same_as<I, Int64> || std::same_as<I, Int128> || std::same_as<I, BigInt>;

/// Name of a tower type: "int64", "int128" or "bigint".
template <TowerInt I>
constexpr const char* int_name() {
  if constexpr (std::same_as<I, BigInt>) {
    return "bigint";
  } else {
    return I::type_name;
  }
}

// --- conversions ---------------------------------------------------------------------------

/// Exact decimal string.
std::string to_string(Int64 v);
std::string to_string(Int128 v);
std::string to_string(const BigInt& v);

/// Exact conversion to BigInt.
inline BigInt to_bigint(Int64 v) {
  return BigInt(v.value());
}
BigInt to_bigint(Int128 v);
inline const BigInt& to_bigint(const BigInt& v) {
  return v;
}

/// Nearest double (rounding as the conversion of the type does).
inline double to_double(Int64 v) {
  return static_cast<double>(v.value());
}
inline double to_double(Int128 v) {
  return static_cast<double>(v.value());
}
inline double to_double(const BigInt& v) {
  return v.convert_to<double>();
}

/// Exact conversion between tower types (or from a machine integer); throws OverflowError
/// when the value does not fit the target.
template <TowerInt To, class From>
To int_cast(const From& v) {
  if constexpr (std::same_as<To, From>) {
    return v;
  } else if constexpr (std::same_as<To, BigInt>) {
    if constexpr (MachineInt<From>) {
      if constexpr (sizeof(From) == 16) {
        return to_bigint(Int128(v));
      } else {
        return BigInt(v);
      }
    } else {
      return to_bigint(v);
    }
  } else if constexpr (MachineInt<From>) {
    return To(v);
  } else if constexpr (std::same_as<From, BigInt>) {
    using T = typename To::value_type;
    static const BigInt lo = to_bigint(Int128(std::numeric_limits<T>::min()));
    static const BigInt hi = to_bigint(Int128(std::numeric_limits<T>::max()));
    if (v < lo || v > hi) detail::throw_overflow(To::type_name, "conversion of", v.str(), "");
    if constexpr (sizeof(T) == 8) {
      return To::from_raw(v.template convert_to<std::int64_t>());
    } else {
      // Two 64-bit halves: the magnitude fits 127 bits.
      BigInt mag = v < 0 ? BigInt(-v) : v;
      uint128_t lo64 = static_cast<std::uint64_t>(mag & BigInt(UINT64_MAX));
      uint128_t hi64 = static_cast<std::uint64_t>(mag >> 64);
      uint128_t u = (hi64 << 64) | lo64;
      int128_t r = v < 0 ? -static_cast<int128_t>(u - 1) - 1 : static_cast<int128_t>(u);
      return To::from_raw(r);
    }
  } else {
    return To(v.value()); // Checked -> Checked
  }
}

/// The types parse_integer reads: the tower, and the machine integers of at most 64 bits.
template <class T>
concept SmallMachineInt = MachineInt<T> && sizeof(T) <= 8;
template <class T>
concept ParsableInt = TowerInt<T> || SmallMachineInt<T>;

/// The one parser of integer text in zdg (command-line arguments, point and half-plane files,
/// Freeman chains, image headers, configuration values; rationals are built on it).
///
/// Accepts exactly an optional sign '+' or '-' followed by one or more digits 0-9: always
/// decimal, so leading zeros are allowed and mean nothing ("010" is ten, "-007" is -7, never
/// octal), and there is no base prefix ("0x10"), space, digit separator or exponent. Anything
/// else throws InvalidArgument naming the text (cut to its first 40 characters); a value that
/// does not fit T throws OverflowError. T is a tower type (Int64, Int128, BigInt: BigInt takes
/// any length, through GMP's subquadratic base-10 conversion) or a machine integer of
/// at most 64 bits (int, unsigned, std::int64_t, std::uint64_t, ...; "-0" is 0 for unsigned
/// types). Every type gives the same value whenever it fits.
template <ParsableInt T>
T parse_integer(std::string_view text);

/// True when parse_integer accepts the text for some type (an optional sign, then digits):
/// the syntax alone, so that a composite text (a fraction "P/Q") is rejected for its syntax
/// before any part is converted, whatever the type.
bool is_decimal_integer(std::string_view text);

// --- division, modulo, gcd (every sign) ----------------------------------------------------

/// |a|; throws OverflowError for the minimum of a machine type.
template <TowerInt I>
I abs(const I& a) {
  return a < 0 ? I(-a) : a;
}

/// Sign: -1, 0 or 1.
template <TowerInt I>
int sign(const I& a) {
  return a < 0 ? -1 : (a > 0 ? 1 : 0);
}

namespace detail {
// Checked<> throws on a zero divisor by itself; GMP's would throw std::overflow_error.
template <TowerInt I>
void check_divisor(const I& a, const I& b) {
  if constexpr (std::same_as<I, BigInt>) {
    if (b == 0) throw_division_by_zero(a.str());
  }
}
} // namespace detail

/// floor(a / b) for every sign; b == 0 throws InvalidArgument.
template <TowerInt I>
I floor_div(const I& a, const I& b) {
  detail::check_divisor(a, b);
  I q = a / b;
  I r = a - q * b;
  if (r != 0 && ((r < 0) != (b < 0))) q -= 1;
  return q;
}

/// ceil(a / b) for every sign; b == 0 throws InvalidArgument.
template <TowerInt I>
I ceil_div(const I& a, const I& b) {
  detail::check_divisor(a, b);
  I q = a / b;
  I r = a - q * b;
  if (r != 0 && ((r < 0) == (b < 0))) q += 1;
  return q;
}

/// a - b floor(a / b): the remainder of the floor division, with the sign of b (or 0).
template <TowerInt I>
I floor_mod(const I& a, const I& b) {
  detail::check_divisor(a, b);
  I r = a % b;
  if (r != 0 && ((r < 0) != (b < 0))) r += b;
  return r;
}

/// Mathematical (Euclidean) modulo: the r in [0, |b|) with a = q b + r.
template <TowerInt I>
I mod(const I& a, const I& b) {
  detail::check_divisor(a, b);
  I r = a % b;
  // r - b rather than r + |b|: |b| does not fit when b is the minimum of a machine type.
  if (r < 0) r = b < 0 ? I(r - b) : I(r + b);
  return r;
}

/// Greatest common divisor, >= 0; gcd(0, 0) = 0.
template <TowerInt I>
I gcd(I a, I b) {
  while (b != 0) {
    I r = a % b;
    a = b;
    b = r;
  }
  return abs(a);
}

/// Bezout: g = gcd(a, b) >= 0 and coefficients with a x + b y = g; |x| <= max(1, |b|/g),
/// |y| <= max(1, |a|/g), so the coefficients fit whenever a and b do.
template <TowerInt I>
struct BezoutResult {
  I g, x, y;
};

template <TowerInt I>
BezoutResult<I> ext_gcd(const I& a, const I& b) {
  I old_r = a, r = b, old_s = 1, s = 0, old_t = 0, t = 1;
  while (r != 0) {
    I q = old_r / r;
    I nr = old_r - q * r;
    old_r = r;
    r = nr;
    I ns = old_s - q * s;
    old_s = s;
    s = ns;
    I nt = old_t - q * t;
    old_t = t;
    t = nt;
  }
  if (old_r < 0) return {I(-old_r), I(-old_s), I(-old_t)};
  return {old_r, old_s, old_t};
}

} // namespace zdg
