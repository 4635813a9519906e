#include <zdg/convergence/polynomial.hpp>

#include "tests/support/tower.hpp"

#include <gtest/gtest.h>

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

TEST(Polynomial, FilterBoundCertifiesTheDoubleSign) {
  // Theorem (forward error bound): |v| > bound implies sign(v) = exact sign.
  auto p = Polynomial::parse("x^4 - 3/7 x^2 y + 5y^3 - 2/3", 2);
  zdg::test::check_property([&](int a, int b, int c) {
    double x = (a % 2001) / 1000.0, y = (b % 2001) / 997.0 + (c % 3) * 1e-9;
    double q[2] = {x, y}, m[2] = {2 * std::abs(x), 2 * std::abs(y)}, bound = 0;
    double v = p.value_with_bound(q, m, bound);
    BigRational e[2] = {zdg::exact_rational(x), zdg::exact_rational(y)};
    int s = p.sign_exact(e);
    if (v > bound) RC_ASSERT(s == 1);
    if (v < -bound) RC_ASSERT(s == -1);
  });
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
