// Exact rationals p/q over a tower integer type: always reduced (gcd(p, q) = 1) with q > 0;
// zero is 0/1. Arithmetic is exact or throws OverflowError (checked types), like the
// integer it is built on. Parsing accepts "7", "-3/4" and decimals "1000.5" / "-0.125".
#pragma once

#include <zdg/arith/integer.hpp>

#include <compare>
#include <ostream>
#include <string>
#include <string_view>

namespace zdg {

template <TowerInt I>
class Rational {
public:
  Rational() : p_(0), q_(1) {}
  Rational(I p) : p_(std::move(p)), q_(1) {} // NOLINT(google-explicit-constructor)
  template <MachineInt U>
  Rational(U p) : p_(int_cast<I>(p)), q_(1) {} // NOLINT(google-explicit-constructor)
  /// p/q reduced; q == 0 throws InvalidArgument.
  Rational(I p, I q) : p_(std::move(p)), q_(std::move(q)) {
    if (q_ == 0) throw InvalidArgument("zero denominator in " + to_string(p_) + "/0");
    normalize();
  }

  const I& num() const { return p_; }
  const I& den() const { return q_; }

  friend Rational operator+(const Rational& a, const Rational& b) {
    I g = gcd(a.q_, b.q_);
    I bq = b.q_ / g;
    return Rational(a.p_ * bq + b.p_ * (a.q_ / g), a.q_ * bq);
  }
  friend Rational operator-(const Rational& a, const Rational& b) { return a + (-b); }
  friend Rational operator*(const Rational& a, const Rational& b) {
    I g1 = gcd(a.p_, b.q_), g2 = gcd(b.p_, a.q_);
    if (g1 == 0) g1 = 1;
    if (g2 == 0) g2 = 1;
    return raw((a.p_ / g1) * (b.p_ / g2), (a.q_ / g2) * (b.q_ / g1));
  }
  friend Rational operator/(const Rational& a, const Rational& b) {
    if (b.p_ == 0) throw InvalidArgument("division by zero: " + a.str() + " / 0");
    return a * raw(b.q_, b.p_);
  }
  Rational operator-() const { return raw(I(-p_), q_); }
  Rational& operator+=(const Rational& b) { return *this = *this + b; }
  Rational& operator-=(const Rational& b) { return *this = *this - b; }
  Rational& operator*=(const Rational& b) { return *this = *this * b; }
  Rational& operator/=(const Rational& b) { return *this = *this / b; }

  friend bool operator==(const Rational& a, const Rational& b) {
    return a.p_ == b.p_ && a.q_ == b.q_;
  }
  friend std::strong_ordering operator<=>(const Rational& a, const Rational& b) {
    I l = a.p_ * b.q_, r = b.p_ * a.q_;
    return l < r ? std::strong_ordering::less
                 : (l == r ? std::strong_ordering::equal : std::strong_ordering::greater);
  }

  /// floor(p/q) and ceil(p/q).
  I floor() const { return floor_div(p_, q_); }
  I ceil() const { return ceil_div(p_, q_); }
  double to_double() const { return zdg::to_double(p_) / zdg::to_double(q_); }

  /// "p/q", or "p" when q = 1.
  std::string str() const { return q_ == 1 ? to_string(p_) : to_string(p_) + "/" + to_string(q_); }
  friend std::ostream& operator<<(std::ostream& os, const Rational& r) { return os << r.str(); }

private:
  I p_, q_;
  // Already reduced, sign on p: no gcd.
  static Rational raw(I p, I q) {
    Rational r;
    if (q < 0) {
      p = -p;
      q = -q;
    }
    r.p_ = std::move(p);
    r.q_ = std::move(q);
    return r;
  }
  void normalize() {
    I g = gcd(p_, q_);
    p_ /= g;
    q_ /= g;
    if (q_ < 0) {
      p_ = -p_;
      q_ = -q_;
    }
  }
};

/// Parses "7", "-3/4", "+5/10" or a decimal "1000.5", "-.25", "3."; every integer part is read
/// by parse_integer (arith/integer.hpp), so it is decimal whatever its leading zeros ("010/3"
/// is 10/3, "0.010" is 1/100). Throws InvalidArgument naming the text when it is none of
/// these (or has a zero denominator), OverflowError when it does not fit I (the value before
/// reduction: "20/10" needs 20 to fit).
template <TowerInt I>
Rational<I> parse_rational(std::string_view text);

} // namespace zdg
