// Checked machine integers: Int64 = Checked<int64_t> and Int128 = Checked<__int128>, whose
// + - * / % and unary - throw zdg::OverflowError instead of wrapping (built on the compiler's
// __builtin_*_overflow: a flag test after the machine instruction, about one predictable
// branch). The machine rungs of the integer tower (arith/integer.hpp adds BigInt, the
// conversions and the number theory); this header needs no Boost, for headers that use the
// machine types only.
#pragma once

#include <zdg/arith/error.hpp>

#include <compare>
#include <concepts>
#include <cstdint>
#include <limits>
#include <ostream>
#include <string>
#include <type_traits>
#include <utility>

namespace zdg {

__extension__ typedef __int128 int128_t;
__extension__ typedef unsigned __int128 uint128_t;

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

} // namespace zdg
