// The number readers of experiment descriptions: rationals exact, decimals in scientific
// notation, and every non-finite or out-of-range text refused (one line naming it).
#include <zdg/convergence/number_text.hpp>

#include <zdg/arith/error.hpp>
#include <zdg/arith/rational.hpp>
#include <zdg/convergence/config.hpp>
#include <zdg/convergence/scalar_field.hpp>
#include <zdg/convergence/shape.hpp>
#include <zdg/kernel/digitization/polynomial.hpp>

#include "tests/support/tower.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <functional>
#include <limits>
#include <optional>
#include <regex>
#include <string>

namespace {

using zdg::InvalidArgument;

TEST(NumberText, RationalsAndScientificDecimals) {
  EXPECT_EQ(zdg::parse_real("7", "x"), 7.0);
  EXPECT_EQ(zdg::parse_real("-3/4", "x"), -0.75);
  EXPECT_EQ(zdg::parse_real("0.125", "x"), 0.125);
  EXPECT_EQ(zdg::parse_real("1.7e-4", "x"), 1.7e-4);
  EXPECT_EQ(zdg::parse_real("+2E3", "x"), 2000.0);
  EXPECT_EQ(zdg::parse_real("14/9", "x"), 14.0 / 9.0);
  EXPECT_EQ(zdg::parse_real("0", "x"), 0.0);
}

TEST(NumberText, NonFiniteTextIsRefused) {
  for (const char* bad : {"inf", "-inf", "nan", "1e400", "1e-400", "1/0", "", "abc", "1e", "--1",
                          "0x10", "1.5.2", "2e-310"}) {
    EXPECT_THROW(zdg::parse_real(bad, "tolerance"), InvalidArgument) << bad;
  }
  const std::string huge = "1" + std::string(400, '0');
  EXPECT_THROW(zdg::parse_real(huge, "x"), InvalidArgument);
  EXPECT_THROW(zdg::parse_real("0." + std::string(400, '0') + "1", "x"), InvalidArgument);
  try {
    zdg::parse_real("inf", "key 'tolerance'");
    FAIL();
  } catch (const InvalidArgument& e) {
    EXPECT_EQ(std::string(e.what()), "key 'tolerance': 'inf' is not a finite number");
  }
}

TEST(NumberText, RangesAndIntegers) {
  EXPECT_EQ(zdg::parse_real_in("10", "t", 0, 10), 10.0);
  EXPECT_THROW(zdg::parse_real_in("0", "t", 0, 10), InvalidArgument); // lo is open
  EXPECT_THROW(zdg::parse_real_in("1e300", "t", 0, 10), InvalidArgument);
  EXPECT_EQ(zdg::parse_integer_in("42", "n", 0, 100), 42);
  EXPECT_EQ(zdg::parse_integer_in("010", "n", 0, 100), 10); // decimal, not octal
  for (const char* bad : {"-1", "101", "1.5", "", "1e2", "99999999999999999999", "4x"}) {
    EXPECT_THROW(zdg::parse_integer_in(bad, "n", 0, 100), InvalidArgument) << bad;
  }
}

// real_text reads back exactly (the TOML numbers pass through it).
TEST(NumberText, RealTextRoundTrips) {
  zdg::test::check_property([](double v) {
    RC_PRE(std::isfinite(v) && (v == 0 || std::abs(v) >= std::numeric_limits<double>::min()));
    RC_ASSERT(zdg::parse_real(zdg::real_text(v), "v") == v);
  });
}

// --- decimal everywhere (issue #41) ---------------------------------------------------------

// A number literal in some base and form: sign, 0x/0o/0b prefixes, leading zeros,
// underscores, a fraction, an exponent.
rc::Gen<std::string> literal() {
  return rc::gen::exec([] {
    std::string s = *rc::gen::element<std::string>("", "", "+", "-");
    const std::string prefix =
        *rc::gen::element<std::string>("", "", "", "0", "00", "0x", "0X", "0o", "0O", "0b", "0B");
    s += prefix;
    const bool hexy = prefix == "0x" || prefix == "0X";
    const std::string alphabet = hexy ? "0123456789abcdefABCDEF" : "0123456789";
    const int n = *rc::gen::inRange(1, 7);
    for (int i = 0; i < n; ++i) {
      s += alphabet[*rc::gen::inRange<std::size_t>(0, alphabet.size())];
      if (i + 1 < n && *rc::gen::inRange(0, 8) == 0) s += '_';
    }
    if (*rc::gen::inRange(0, 4) == 0) {
      s += '.';
      const int f = *rc::gen::inRange(0, 4);
      for (int i = 0; i < f; ++i) s += static_cast<char>('0' + *rc::gen::inRange(0, 10));
    }
    if (*rc::gen::inRange(0, 4) == 0) {
      s += *rc::gen::element<std::string>("e", "E", "e+", "e-", "p");
      s += std::to_string(*rc::gen::inRange(0, 30));
    }
    return s;
  });
}

// The decimal meaning of a literal: its value when, underscores between digits aside, it is
// [sign] digits [. digits] [e [sign] digits] in base 10 (leading zeros included); none
// otherwise (0x10, 0b1, 1e, 0x1p3, _1: no decimal meaning, to be refused).
std::optional<double> decimal_meaning(const std::string& lit) {
  static const std::regex underscore("([0-9])_(?=[0-9])");
  const std::string t = std::regex_replace(lit, underscore, "$1");
  static const std::regex decimal("[+-]?([0-9]+(\\.[0-9]*)?|\\.[0-9]+)([eE][+-]?[0-9]+)?");
  if (!std::regex_match(t, decimal)) return std::nullopt;
  return std::strtod(t.c_str(), nullptr);
}

// Accepted with the decimal meaning, or refused: never read as something else.
void decimal_or_refused(const std::string& parser, const std::string& lit,
                        const std::function<double()>& read, bool integer_only) {
  std::optional<double> got;
  try {
    got = read();
  } catch (const zdg::Error&) {
    return; // refused (one line, InvalidArgument or OverflowError)
  }
  const auto want = decimal_meaning(lit);
  RC_LOG() << parser << " read '" << lit << "' as " << *got << std::endl;
  RC_ASSERT(want.has_value());
  if (integer_only) RC_ASSERT(*want == std::floor(*want));
  RC_ASSERT(*got == *want || std::abs(*got - *want) <= 1e-15 * std::abs(*want));
}

// Theorem (zdg's rule: numbers are decimal everywhere): every reader of numbers reads a
// literal in any base and form either as its decimal meaning or refuses it.
TEST(DecimalOnly, EveryParserReadsTheDecimalMeaningOrRefuses) {
  zdg::test::check_property([] {
    const std::string lit = *literal();
    decimal_or_refused(
        "parse_real", lit, [&] { return zdg::parse_real(lit, "x"); }, false);
    decimal_or_refused(
        "parse_integer_in", lit,
        [&] { return double(zdg::parse_integer_in(lit, "n", -100000000, 100000000)); }, true);
    // The command line's integer options (cli/main.cpp) and every integer argument.
    decimal_or_refused(
        "parse_integer<int64>", lit, [&] { return double(zdg::parse_integer<std::int64_t>(lit)); },
        true);
    decimal_or_refused(
        "parse_integer<uint64>", lit,
        [&] { return double(zdg::parse_integer<std::uint64_t>(lit)); }, true);
    decimal_or_refused(
        "parse_rational", lit, [&] { return zdg::parse_rational<zdg::BigInt>(lit).to_double(); },
        false);
    // Shape specs (ellipse:20,7) and expressions (poly:..., --function).
    decimal_or_refused(
        "parse_number_list", lit,
        [&] {
          const auto v = zdg::parse_number_list(lit, "shape");
          if (v.size() != 1) throw zdg::InvalidArgument("not one number");
          return v[0];
        },
        false);
    decimal_or_refused(
        "Polynomial::parse", lit,
        [&] {
          const auto p = zdg::Polynomial::parse(lit, 2);
          if (p.degree() > 0) throw zdg::InvalidArgument("test: not a constant");
          const double at[2] = {0, 0};
          return p.value(at);
        },
        false);
    decimal_or_refused(
        "ScalarField", lit,
        [&] {
          return zdg::ScalarField(lit).value({0.3, 0.5, 0.7});
        },
        false);
    // Experiment descriptions: a TOML value and the same text as a flag.
    const std::string head = "shape = \"ball:10\"\nestimator = \"gauss-area\"\nh = \"0.5,0.25\"\n";
    decimal_or_refused(
        "toml seed", lit,
        [&] {
          const auto c = zdg::parse_experiment_config(head + "seed = " + lit + "\n", "t.toml");
          return double(c.seed);
        },
        true);
    decimal_or_refused(
        "toml tolerance", lit,
        [&] {
          return zdg::parse_experiment_config(head + "tolerance = " + lit + "\n", "t.toml")
              .tolerance;
        },
        false);
    decimal_or_refused(
        "toml translations (string)", lit,
        [&] {
          return double(
              zdg::parse_experiment_config(head + "translations = \"" + lit + "\"\n", "t.toml")
                  .translations);
        },
        true);
  });
}

// The examples, and the one rule of the README: bare TOML numbers follow TOML's grammar
// (which refuses a leading zero, 010), everything else reads 010 as ten; 0x, 0o, 0b never pass.
TEST(DecimalOnly, BaseLiteralsAreRefusedWithAMessage) {
  const std::string head = "shape = \"ball:10\"\nestimator = \"gauss-area\"\nh = \"0.5,0.25\"\n";
  auto toml_error = [&](const std::string& line) -> std::string {
    try {
      zdg::parse_experiment_config(head + line + "\n", "run.toml");
    } catch (const InvalidArgument& e) {
      return e.what();
    }
    return "no error";
  };
  EXPECT_EQ(toml_error("translations = 0x10"),
            "run.toml:4: key 'translations' is a hexadecimal integer: zdg reads decimal numbers "
            "only (write 16 if that value is meant)");
  EXPECT_NE(toml_error("translations = 0o10").find("octal integer"), std::string::npos);
  EXPECT_NE(toml_error("translations = 0b10").find("binary integer"), std::string::npos);
  EXPECT_NE(toml_error("seed = 0xDEADBEEF").find("hexadecimal"), std::string::npos);
  EXPECT_NE(toml_error("k = 0x5").find("hexadecimal"), std::string::npos);
  EXPECT_NE(toml_error("k = [0x5]").find("key 'k' element is a hexadecimal"), std::string::npos);
  EXPECT_NE(toml_error("translations = 010").find("run.toml:4"), std::string::npos); // TOML
  EXPECT_EQ(toml_error("translations = \"010\""), "no error");
  EXPECT_EQ(zdg::parse_experiment_config(head + "translations = \"010\"\n", "t").translations, 10);
  EXPECT_EQ(zdg::parse_experiment_config(head + "translations = 1_0\n", "t").translations, 10);
  for (const char* bad : {"x^2+y^2-0x10", "x^2+y^2-0b1", "x^2-1e5", "x^2-0o7", "x2+y^2-1",
                          "x^2+y^2-0X1F", "1/0x10"}) {
    EXPECT_THROW(zdg::Polynomial::parse(bad, 2), InvalidArgument) << bad;
  }
  try {
    zdg::Polynomial::parse("x^2+y^2-0x10", 2);
  } catch (const InvalidArgument& e) {
    EXPECT_NE(std::string(e.what()).find("numbers are decimal"), std::string::npos) << e.what();
  }
  // Still products: 3x, 2(x+y), 0x (zero times x), x y.
  EXPECT_EQ(zdg::Polynomial::parse("3x^2 + 2(x+y) + 0x + x y - 010", 2).degree(), 2);
}

} // namespace
