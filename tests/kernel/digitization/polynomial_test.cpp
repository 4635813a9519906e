#include <zdg/kernel/digitization/polynomial.hpp>

#include "tests/support/tower.hpp"

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <string>

namespace {

using zdg::BigInt;
using zdg::BigRational;
using zdg::Polynomial;

double eval(const Polynomial& p, double x, double y) {
  double q[2] = {x, y};
  return p.value(q);
}

TEST(Polynomial, ParsesSumsProductsPowersAndRationals) {
  auto p = Polynomial::parse("x^2 + y^2 - 1", 2);
  EXPECT_EQ(p.degree(), 2);
  EXPECT_DOUBLE_EQ(eval(p, 1, 0), 0.0);
  EXPECT_DOUBLE_EQ(eval(p, 2, 3), 12.0);
  auto q = Polynomial::parse("3x^2y - 1/2 + 0.25*(x - y)", 2);
  EXPECT_DOUBLE_EQ(eval(q, 2, 1), 12 - 0.5 + 0.25);
  // Implicit products and unary minus.
  auto r = Polynomial::parse("-2(x+y)^2", 2);
  EXPECT_DOUBLE_EQ(eval(r, 1, 2), -18.0);
  EXPECT_EQ(Polynomial::parse("(x+y)^2", 2).str(), Polynomial::parse("x^2+2xy+y^2", 2).str());
}

TEST(Polynomial, ExactValueWithRationalCoefficients) {
  auto p = Polynomial::parse("1/3 x - 2/7 y^2", 2);
  BigRational pt[2] = {BigRational(BigInt(3)), BigRational(BigInt(7), BigInt(2))};
  EXPECT_EQ(p.value_exact(pt), BigRational(1) - BigRational(BigInt(7), BigInt(2)));
  EXPECT_THROW(Polynomial::parse("x/3", 2), zdg::InvalidArgument); // divide numbers only
}

TEST(Polynomial, RejectsMalformedTextNamingThePosition) {
  auto message = [](const char* text, int nvars = 2) {
    try {
      Polynomial::parse(text, nvars);
    } catch (const zdg::InvalidArgument& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_NE(message("x^2+q").find("position 5"), std::string::npos) << message("x^2+q");
  EXPECT_NE(message("x+z").find("position 3"), std::string::npos);
  EXPECT_NE(message("x^").find("exponent"), std::string::npos);
  EXPECT_NE(message("1/0").find("zero denominator"), std::string::npos);
  EXPECT_NE(message("(x+1").find("')'"), std::string::npos);
  EXPECT_NE(message("").find("empty"), std::string::npos);
  EXPECT_NE(message("x^2 y^-1").find("exponent"), std::string::npos);
  EXPECT_EQ(message("x+y+z", 3), "no error");
}

TEST(Polynomial, DoublesAreExactDyadicRationals) {
  EXPECT_EQ(zdg::exact_rational(0.5), BigRational(BigInt(1), BigInt(2)));
  EXPECT_EQ(zdg::exact_rational(-3.0), BigRational(-3));
  EXPECT_EQ(zdg::exact_rational(0.1),
            BigRational(BigInt(3602879701896397LL), BigInt(36028797018963968LL)));
}

TEST(Polynomial, ExactSignOnTheZeroSet) {
  // (3/5, 4/5) lies on the unit circle exactly; doubles cannot decide it.
  auto p = Polynomial::parse("x^2 + y^2 - 1", 2);
  BigRational pt[2] = {BigRational(BigInt(3), BigInt(5)), BigRational(BigInt(4), BigInt(5))};
  EXPECT_EQ(p.sign_exact(pt), 0);
  pt[0] = BigRational(BigInt(3000001), BigInt(5000000));
  EXPECT_EQ(p.sign_exact(pt), 1);
}

// Bounded work from small text (issue #18): nesting depth, total degree after expansion
// (checked before a product is expanded), work of the expansion, coefficient range.
TEST(Polynomial, LimitsRefuseUnboundedInputQuickly) {
  auto message = [](const std::string& text, int nvars = 2) {
    try {
      Polynomial::parse(text, nvars);
    } catch (const zdg::InvalidArgument& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  const std::string deep = std::string(5000, '(') + "x" + std::string(5000, ')');
  EXPECT_NE(message(deep).find("nesting deeper than 200"), std::string::npos) << message(deep);
  EXPECT_LT(message(deep).size(), 200u); // one short line, not the 10,000 characters
  EXPECT_NE(message(std::string(5000, '-') + "x").find("nesting"), std::string::npos);
  const std::string ok_depth = std::string(200, '(') + "x" + std::string(200, ')');
  EXPECT_EQ(message(ok_depth), "no error");
  // Degree 64 is allowed; a product of powers past it is refused before the second factor is
  // expanded.
  EXPECT_EQ(message("(x+y+1)^16*(x-y)^16"), "no error");
  EXPECT_EQ(message("x^64 + y^64 - 1"), "no error");
  EXPECT_NE(message("(x+y)^40*(x-y)^40").find("total degree 80 larger than 64"), std::string::npos);
  EXPECT_NE(message("x^30*((x+y)^20*(x+y+1)^20)").find("total degree 70"), std::string::npos);
  // The reproducer of issue #18: refused at once (by the work bound: (x+y+1)^64 alone has 2145
  // terms), not after minutes.
  std::string product = "(x+y+1)^64";
  for (int i = 0; i < 40; ++i) product += "*(x+y+1)^64";
  const auto t0 = std::chrono::steady_clock::now();
  EXPECT_NE(message(product).find("poly: "), std::string::npos);
  EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count(), 2.0);
  EXPECT_NE(message("(x^2+y)^33").find("total degree 66"), std::string::npos);
  // Many large expansions: the work budget.
  std::string sum = "(x+y+z+1)^40";
  for (int i = 2; i < 40; ++i) sum += "+(x+y+z+" + std::to_string(i) + ")^40";
  EXPECT_NE(message(sum, 3).find("expansion too large"), std::string::npos) << message(sum, 3);
  // A coefficient beyond the range of double.
  EXPECT_NE(message("1" + std::string(400, '0') + "x").find("beyond the range of double"),
            std::string::npos);
  EXPECT_NE(message("(100000000000x+1)^64").find("beyond the range of double"), std::string::npos);
}

TEST(Polynomial, GradientAndHessianMatchClosedForms) {
  auto p = Polynomial::parse("x^3 y + 2 y^2 - x", 2);
  double q[2] = {1.5, -2.0}, g[2], h[4];
  p.gradient(q, g);
  p.hessian(q, h);
  EXPECT_DOUBLE_EQ(g[0], 3 * 1.5 * 1.5 * -2.0 - 1);
  EXPECT_DOUBLE_EQ(g[1], 1.5 * 1.5 * 1.5 + 4 * -2.0);
  EXPECT_DOUBLE_EQ(h[0], 6 * 1.5 * -2.0);
  EXPECT_DOUBLE_EQ(h[1], 3 * 1.5 * 1.5);
  EXPECT_DOUBLE_EQ(h[2], 3 * 1.5 * 1.5);
  EXPECT_DOUBLE_EQ(h[3], 4.0);
  auto s = Polynomial::parse("x y z - z^2", 3);
  double r[3] = {1, 2, 3}, g3[3];
  s.gradient(r, g3);
  EXPECT_DOUBLE_EQ(g3[2], 2 - 6.0);
}

} // namespace
