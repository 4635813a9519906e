// The integer tower of zdg: Int64, Int128 and BigInt.
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

__extension__ typedef __int128 int128_t;
__extension__ typedef unsigned __int128 uint128_t;

/// Arbitrary-precision integer (GMP mpz through Boost.Multiprecision, no expression templates).
using BigInt =
    boost::multiprecision::number<boost::multiprecision::gmp_int, boost::multiprecision::et_off>;

/// The machine types Checked<> wraps.
template <class T>
concept BuiltinInt = std::same_as<T, std::int64_t> || std::same_as<T, int128_t>;

/// Any standard or extended signed/unsigned integer a Checked<> can be built from.
template <class U>
concept MachineInt = (std::is_integral_v<U> && !std::same_as<U, bool>) ||
                     std::same_as<U, int128_t> || std::same_as<U, uint128_t>;

namespace detail {
std::string int128_to_string(int128_t v);
[[noreturn]] void throw_overflow(const char* type, const char* op, const std::string& a,
                                 const std::string& b);
[[noreturn]] void throw_division_by_zero(const std::string& a);

template <MachineInt U>
std::string machine_to_string(U v) {
  if constexpr (std::same_as<U, int128_t>) {
    return int128_to_string(v);
  } else if constexpr (std::same_as<U, uint128_t>) {
    std::string s;
    do {
      s.insert(s.begin(), static_cast<char>('0' + static_cast<int>(v % 10)));
      v /= 10;
    } while (v != 0);
    return s;
  } else {
    return std::to_string(v);
  }
}
} // namespace detail

/// A machine integer whose arithmetic throws zdg::OverflowError instead of wrapping.
template <BuiltinInt T>
class Checked {
public:
  using value_type = T;
  static constexpr const char* type_name = sizeof(T) == 8 ? "int64" : "int128";

  constexpr Checked() = default;

  /// Implicit from any machine integer whose value fits; throws OverflowError otherwise.
  template <MachineInt U>
  constexpr Checked(U u) : v_(static_cast<T>(u)) { // NOLINT(google-explicit-constructor)
    if (!in_range_check(u)) {
      detail::throw_overflow(type_name, "conversion of", detail::machine_to_string(u), "");
    }
  }

  static constexpr Checked min() { return from_raw(std::numeric_limits<T>::min()); }
  static constexpr Checked max() { return from_raw(std::numeric_limits<T>::max()); }
  static constexpr Checked from_raw(T v) {
    Checked c;
    c.v_ = v;
    return c;
  }

  constexpr T value() const { return v_; }
  constexpr explicit operator T() const { return v_; }
  constexpr explicit operator double() const { return static_cast<double>(v_); }
  constexpr explicit operator bool() const { return v_ != 0; }

  friend constexpr Checked operator+(Checked a, Checked b) {
    T r;
    if (__builtin_add_overflow(a.v_, b.v_, &r)) fail("+", a, b);
    return from_raw(r);
  }
  friend constexpr Checked operator-(Checked a, Checked b) {
    T r;
    if (__builtin_sub_overflow(a.v_, b.v_, &r)) fail("-", a, b);
    return from_raw(r);
  }
  friend constexpr Checked operator*(Checked a, Checked b) {
    T r;
    if (__builtin_mul_overflow(a.v_, b.v_, &r)) fail("*", a, b);
    return from_raw(r);
  }
  /// Truncating division, as for the machine type; b == 0 throws InvalidArgument.
  friend constexpr Checked operator/(Checked a, Checked b) {
    if (b.v_ == 0) detail::throw_division_by_zero(detail::machine_to_string(a.v_));
    if (b.v_ == -1) return -a;
    return from_raw(a.v_ / b.v_);
  }
  /// Remainder of the truncating division (sign of a).
  friend constexpr Checked operator%(Checked a, Checked b) {
    if (b.v_ == 0) detail::throw_division_by_zero(detail::machine_to_string(a.v_));
    if (b.v_ == -1) return Checked{};
    return from_raw(a.v_ % b.v_);
  }
  constexpr Checked operator-() const {
    if (v_ == std::numeric_limits<T>::min()) fail("-", Checked{}, *this);
    return from_raw(-v_);
  }
  constexpr Checked operator+() const { return *this; }

  constexpr Checked& operator+=(Checked b) { return *this = *this + b; }
  constexpr Checked& operator-=(Checked b) { return *this = *this - b; }
  constexpr Checked& operator*=(Checked b) { return *this = *this * b; }
  constexpr Checked& operator/=(Checked b) { return *this = *this / b; }
  constexpr Checked& operator%=(Checked b) { return *this = *this % b; }
  constexpr Checked& operator++() { return *this += 1; }
  constexpr Checked& operator--() { return *this -= 1; }
  constexpr Checked operator++(int) {
    Checked old = *this;
    ++*this;
    return old;
  }
  constexpr Checked operator--(int) {
    Checked old = *this;
    --*this;
    return old;
  }

  friend constexpr bool operator==(Checked, Checked) = default;
  friend constexpr auto operator<=>(Checked, Checked) = default;

  friend std::ostream& operator<<(std::ostream& os, Checked c) {
    return os << detail::machine_to_string(c.v_);
  }

private:
  T v_{};

  template <MachineInt U>
  static constexpr bool in_range_check(U u) {
    if constexpr (std::same_as<U, uint128_t>) {
      return u <= static_cast<uint128_t>(std::numeric_limits<T>::max());
    } else if constexpr (std::same_as<U, int128_t>) {
      return u >= static_cast<int128_t>(std::numeric_limits<T>::min()) &&
             u <= static_cast<int128_t>(std::numeric_limits<T>::max());
    } else {
      if constexpr (sizeof(T) == 16) {
        return true; // every standard integer fits 128 bits
      } else {
        return std::in_range<std::int64_t>(u);
      }
    }
  }
  [[noreturn]] static void fail(const char* op, Checked a, Checked b) {
    detail::throw_overflow(type_name, op, detail::machine_to_string(a.v_),
                           detail::machine_to_string(b.v_));
  }
};

using Int64 = Checked<std::int64_t>;
using Int128 = Checked<int128_t>;

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
