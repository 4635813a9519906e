#include <zdg/arith/rational.hpp>

namespace zdg {

template <TowerInt I>
Rational<I> parse_rational(std::string_view text) {
  const std::string whole(text);
  auto bad = [&]() { return InvalidArgument("not a rational number: '" + whole + "'"); };
  if (auto slash = text.find('/'); slash != std::string_view::npos) {
    std::string_view ps = text.substr(0, slash), qs = text.substr(slash + 1);
    if (ps.empty() || qs.empty()) throw bad();
    I p, q;
    try {
      p = parse_integer<I>(ps);
      q = parse_integer<I>(qs);
    } catch (const InvalidArgument&) {
      throw bad();
    }
    if (q == 0) throw InvalidArgument("zero denominator in '" + whole + "'");
    return Rational<I>(p, q);
  }
  if (auto dot = text.find('.'); dot != std::string_view::npos) {
    std::string_view ip = text.substr(0, dot), fp = text.substr(dot + 1);
    bool neg = !ip.empty() && ip.front() == '-';
    std::string_view ip_digits =
        (!ip.empty() && (ip.front() == '-' || ip.front() == '+')) ? ip.substr(1) : ip;
    if (ip_digits.empty() && fp.empty()) throw bad();
    for (char c : fp) {
      if (c < '0' || c > '9') throw bad();
    }
    I p;
    try {
      p = ip_digits.empty() ? I(0) : parse_integer<I>(ip_digits);
    } catch (const InvalidArgument&) {
      throw bad();
    }
    I q = 1;
    for (char c : fp) {
      p = p * 10 + (c - '0');
      q = q * 10;
    }
    return Rational<I>(neg ? I(-p) : p, q);
  }
  try {
    return Rational<I>(parse_integer<I>(text));
  } catch (const InvalidArgument&) {
    throw bad();
  }
}

template class Rational<Int64>;
template class Rational<Int128>;
template class Rational<BigInt>;
template Rational<Int64> parse_rational<Int64>(std::string_view);
template Rational<Int128> parse_rational<Int128>(std::string_view);
template Rational<BigInt> parse_rational<BigInt>(std::string_view);

} // namespace zdg
