#include <zdg/arith/rational.hpp>

#include <algorithm>
#include <string>

namespace zdg {

template <TowerInt I>
Rational<I> parse_rational(std::string_view text) {
  auto bad = [&]() {
    std::string shown(text.substr(0, 40));
    for (char& c : shown) {
      if (static_cast<unsigned char>(c) < 0x20 || c == 0x7f) c = '?';
    }
    if (text.size() > 40) shown += "...";
    return InvalidArgument("not a rational number: '" + shown + "'");
  };
  if (auto slash = text.find('/'); slash != std::string_view::npos) {
    std::string_view ps = text.substr(0, slash), qs = text.substr(slash + 1);
    // Syntax first: a malformed part is InvalidArgument for every type, even when the other
    // part would not fit the type.
    if (!is_decimal_integer(ps) || !is_decimal_integer(qs)) throw bad();
    // A zero denominator is in the text ("0", "-000"): the same error for every type.
    if (qs.find_first_not_of("+-0") == std::string_view::npos) {
      throw InvalidArgument("zero denominator in '" + std::string(text.substr(0, 40)) + "'");
    }
    I p, q;
    try {
      p = parse_integer<I>(ps);
      q = parse_integer<I>(qs);
    } catch (const InvalidArgument&) {
      throw bad();
    }
    if (q == 0)
      throw InvalidArgument("zero denominator in '" + std::string(text.substr(0, 40)) + "'");
    return Rational<I>(p, q);
  }
  if (auto dot = text.find('.'); dot != std::string_view::npos) {
    // [sign] digits '.' digits, at least one digit in all: (integer part and fraction digits
    // read as one integer) / 10^(number of fraction digits).
    std::string_view ip = text.substr(0, dot), fp = text.substr(dot + 1);
    std::string_view sign, ip_digits = ip;
    if (!ip.empty() && (ip.front() == '-' || ip.front() == '+')) {
      sign = ip.substr(0, 1);
      ip_digits = ip.substr(1);
    }
    if (ip_digits.empty() && fp.empty()) throw bad();
    auto all_digits = [](std::string_view s) {
      return std::all_of(s.begin(), s.end(), [](char c) { return c >= '0' && c <= '9'; });
    };
    if (!all_digits(ip_digits) || !all_digits(fp)) throw bad();
    std::string joined;
    joined.reserve(text.size());
    joined.append(sign).append(ip_digits).append(fp);
    I p;
    try {
      p = parse_integer<I>(joined);
    } catch (const InvalidArgument&) {
      throw bad();
    }
    I q = 1;
    if constexpr (std::same_as<I, BigInt>) {
      q = boost::multiprecision::pow(BigInt(10), static_cast<unsigned>(fp.size()));
    } else {
      for (std::size_t k = 0; k < fp.size(); ++k) q *= 10; // overflows within 39 steps
    }
    return Rational<I>(p, q);
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
