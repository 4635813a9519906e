// The number readers of experiment descriptions: rationals exact, decimals in scientific
// notation, and every non-finite or out-of-range text refused (one line naming it).
#include <zdg/convergence/number_text.hpp>

#include <zdg/arith/error.hpp>

#include "tests/support/tower.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
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

} // namespace
