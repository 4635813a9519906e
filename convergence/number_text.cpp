#include <zdg/convergence/number_text.hpp>

#include <zdg/arith/error.hpp>
#include <zdg/arith/rational.hpp>

#include <charconv>
#include <cmath>
#include <limits>

namespace zdg {

namespace {

std::string shown(const std::string& text) {
  return "'" + (text.size() <= 40 ? text : text.substr(0, 37) + "...") + "'";
}

} // namespace

// A rational P/Q exactly, then to the double; a decimal (7, 0.125, 1.7e-4) by std::from_chars,
// correctly rounded.
double parse_real(const std::string& text, const std::string& what) {
  double v = 0;
  bool ok = false;
  if (text.find('/') != std::string::npos) {
    try {
      const auto q = parse_rational<BigInt>(text);
      v = q.to_double();
      ok = true;
      if (v == 0 && q.num() != 0) {
        throw InvalidArgument(what + ": " + shown(text) + " is too small (it rounds to 0)");
      }
    } catch (const InvalidArgument& e) {
      if (ok) throw;
    }
  } else if (!text.empty() && text.find_first_not_of("0123456789.eE+-") == std::string::npos &&
             text.find_first_of("0123456789") != std::string::npos) {
    const char* first = text.data();
    if (*first == '+' && text.size() > 1 && text[1] != '-') ++first;
    auto [end, ec] = std::from_chars(first, text.data() + text.size(), v);
    ok = (ec == std::errc() || ec == std::errc::result_out_of_range) &&
         end == text.data() + text.size();
    if (ok && ec == std::errc::result_out_of_range) {
      throw InvalidArgument(what + ": " + shown(text) + " is beyond the range of double");
    }
  }
  if (!ok || !std::isfinite(v) || (v != 0 && std::abs(v) < std::numeric_limits<double>::min())) {
    throw InvalidArgument(what + ": " + shown(text) + " is not a finite number");
  }
  return v;
}

double parse_real_in(const std::string& text, const std::string& what, double lo, double hi) {
  const double v = parse_real(text, what);
  if (!(v > lo && v <= hi)) {
    throw InvalidArgument(what + " = " + shown(text) + " must be in (" + real_text(lo) + ", " +
                          real_text(hi) + "]");
  }
  return v;
}

std::int64_t parse_integer_in(const std::string& text, const std::string& what, std::int64_t lo,
                              std::int64_t hi) {
  std::int64_t v = 0;
  const char* first = text.data();
  const char* last = text.data() + text.size();
  if (first != last && *first == '+') ++first;
  auto [end, ec] = std::from_chars(first, last, v, 10);
  if (text.empty() || ec != std::errc() || end != last) {
    throw InvalidArgument(what + ": " + shown(text) + " is not an integer");
  }
  if (v < lo || v > hi) {
    throw InvalidArgument(what + " = " + shown(text) + " must be in " + std::to_string(lo) + ".." +
                          std::to_string(hi));
  }
  return v;
}

std::string real_text(double v) {
  char buf[64];
  auto [end, ec] = std::to_chars(buf, buf + sizeof buf, v);
  return ec == std::errc() ? std::string(buf, end) : std::string("?");
}

} // namespace zdg
