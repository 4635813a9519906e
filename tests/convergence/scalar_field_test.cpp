// Test functions with exact derivatives (convergence/scalar_field.hpp). Oracles: closed forms
// (derivatives of polynomials, the spherical harmonics' eigenvalues -l(l+1)/R^2 of the
// Laplace-Beltrami operator of a sphere, Delta_S e^z = (1 - z^2 - 2z) e^z on the unit sphere by
// the chain rule Delta_S f(z) = f''(z) |grad_S z|^2 + f'(z) Delta_S z) and central finite
// differences for random expressions (the jet's gradient against its values, its Hessian
// against its gradients).
#include <zdg/arith/error.hpp>
#include <zdg/convergence/scalar_field.hpp>

#include "tests/support/tower.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>

namespace zdg {
namespace {

using P = Point3<double>;

TEST(ScalarField, DerivativesOfAPolynomial) {
  const ScalarField u("x^2 - y^2 + 3*x*y*z - 2");
  const Jet3 j = u.jet({1.5, -2, 0.5});
  EXPECT_DOUBLE_EQ(j.value, 2.25 - 4 + 3 * 1.5 * -2 * 0.5 - 2);
  EXPECT_DOUBLE_EQ(j.gradient[0], 3 + 3 * -2 * 0.5);
  EXPECT_DOUBLE_EQ(j.gradient[1], 4 + 3 * 1.5 * 0.5);
  EXPECT_DOUBLE_EQ(j.gradient[2], 3 * 1.5 * -2);
  // xx, yy, zz, xy, xz, yz
  EXPECT_DOUBLE_EQ(j.hessian[0], 2);
  EXPECT_DOUBLE_EQ(j.hessian[1], -2);
  EXPECT_DOUBLE_EQ(j.hessian[2], 0);
  EXPECT_DOUBLE_EQ(j.hessian[3], 3 * 0.5);
  EXPECT_DOUBLE_EQ(j.hessian[4], 3 * -2);
  EXPECT_DOUBLE_EQ(j.hessian[5], 3 * 1.5);
}

TEST(ScalarField, PrecedenceAndAssociativity) {
  const P p{2, 3, 0.5};
  EXPECT_DOUBLE_EQ(ScalarField("-x^2").value(p), -4);      // -(x^2)
  EXPECT_DOUBLE_EQ(ScalarField("2^3^2").value(p), 512);    // 2^(3^2)
  EXPECT_DOUBLE_EQ(ScalarField("x^-1").value(p), 0.5);     // a unary minus in the exponent
  EXPECT_DOUBLE_EQ(ScalarField("8/x/2").value(p), 2);      // left associative
  EXPECT_DOUBLE_EQ(ScalarField("1 - y - 1").value(p), -3); // left associative
  EXPECT_DOUBLE_EQ(ScalarField("2*pi").value(p), 2 * std::numbers::pi);
  EXPECT_DOUBLE_EQ(ScalarField("1.5e1 + .5").value(p), 15.5);
  EXPECT_DOUBLE_EQ(ScalarField("(-x)^3").value(p), -8); // integer power of a negative number
  EXPECT_DOUBLE_EQ(ScalarField("sqrt(exp(log(z)))").value(p), std::sqrt(0.5));
  EXPECT_NEAR(ScalarField("x^y").jet(p).gradient[1], 8 * std::log(2.0), 1e-12); // exp(y log x)
}

TEST(ScalarField, BadTextIsRefusedWithItsPosition) {
  const auto message = [](const std::string& text) -> std::string {
    try {
      ScalarField u(text);
    } catch (const InvalidArgument& e) {
      return e.what();
    }
    return "(accepted)";
  };
  EXPECT_EQ(message("x^^2"), "function 'x^^2': unexpected '^' at position 3");
  EXPECT_EQ(message(""), "function '': empty at position 1");
  EXPECT_EQ(message("2x"), "function '2x': unexpected 'x' at position 2");
  EXPECT_EQ(message("sin x"), "function 'sin x': '(' expected after sin at position 5");
  EXPECT_EQ(message("(x+1"), "function '(x+1': ')' expected at position 5");
  EXPECT_NE(message("foo(x)").find("unknown name 'foo'"), std::string::npos);
  EXPECT_NE(message("atan2(y,x)").find("unknown name 'atan2'"), std::string::npos);
  EXPECT_NE(message("1e999").find("bad number"), std::string::npos);
  EXPECT_NE(message(std::string(300, '(') + "x" + std::string(300, ')')).find("nested deeper"),
            std::string::npos);
  EXPECT_NE(message(std::string(1001, 'x')).find("longer than 1000"), std::string::npos);
  // Not finite at a point: refused there, with the point.
  const ScalarField u("log(x)");
  EXPECT_THROW(u.value({0, 1, 1}), InvalidArgument);
  EXPECT_THROW(ScalarField("sqrt(x)").jet({0, 0, 0}), InvalidArgument); // infinite derivative
  EXPECT_THROW(ScalarField("1/(x-y)").value({1, 1, 0}), InvalidArgument);
}

// Spherical harmonics: Delta_S Y = -l(l+1)/R^2 Y on the sphere of radius R (x: l = 1,
// x^2 - y^2 and xy: l = 2), and the chain rule's closed form for e^z on the unit sphere.
TEST(ScalarField, LaplaceBeltramiOnSpheres) {
  for (double R : {1.0, 9.0}) {
    for (const P d : {P{0.3, -0.5, 0.81}, P{1, 0, 0}, P{-0.2, 0.9, -0.1}}) {
      const double len = std::sqrt(d.x * d.x + d.y * d.y + d.z * d.z);
      const P n{d.x / len, d.y / len, d.z / len};
      const P p{R * n.x, R * n.y, R * n.z};
      EXPECT_NEAR(ScalarField("x").laplace_beltrami(p, n, 1 / R, 1 / R), -2 * p.x / (R * R), 1e-12);
      EXPECT_NEAR(ScalarField("x^2-y^2").laplace_beltrami(p, n, 1 / R, 1 / R),
                  -6 * (p.x * p.x - p.y * p.y) / (R * R), 1e-10);
      EXPECT_NEAR(ScalarField("x*y").laplace_beltrami(p, n, 1 / R, 1 / R), -6 * p.x * p.y / (R * R),
                  1e-10);
      if (R == 1) {
        EXPECT_NEAR(ScalarField("exp(z)").laplace_beltrami(p, n, 1, 1),
                    (1 - p.z * p.z - 2 * p.z) * std::exp(p.z), 1e-12);
      }
    }
  }
  // On a plane (no curvature) it is the Laplacian in the plane: u = x^2 + z^2 on z = 0 -> 2.
  EXPECT_DOUBLE_EQ(ScalarField("x^2+z^2").laplace_beltrami({0.3, 0.2, 0}, {0, 0, 1}, 0, 0), 2);
}

// Random expressions of bounded growth (depth <= 4, arguments of exp and the powers bounded).
rc::Gen<std::string> expression(int depth) {
  if (depth == 0) {
    return rc::gen::oneOf(rc::gen::element<std::string>("x", "y", "z", "pi"),
                          rc::gen::map(rc::gen::inRange(-9, 10),
                                       [](int k) { return "(" + std::to_string(k) + "/4)"; }));
  }
  const auto sub = expression(depth - 1);
  return rc::gen::oneOf(
      sub,
      rc::gen::map(rc::gen::pair(sub, sub),
                   [](const auto& ab) { return "(" + ab.first + "+" + ab.second + ")"; }),
      rc::gen::map(rc::gen::pair(sub, sub),
                   [](const auto& ab) { return "(" + ab.first + "-" + ab.second + ")"; }),
      rc::gen::map(rc::gen::pair(sub, sub),
                   [](const auto& ab) { return "(" + ab.first + "*" + ab.second + ")"; }),
      rc::gen::map(rc::gen::pair(sub, sub),
                   [](const auto& ab) { return ab.first + "/(2+sin(" + ab.second + "))"; }),
      rc::gen::map(
          rc::gen::pair(sub, rc::gen::inRange(0, 4)),
          [](const auto& ab) { return "atan(" + ab.first + ")^" + std::to_string(ab.second); }),
      rc::gen::map(sub, [](const std::string& a) { return "-" + a; }),
      rc::gen::map(sub, [](const std::string& a) { return "exp(tanh(" + a + "))"; }),
      rc::gen::map(sub, [](const std::string& a) { return "cos(" + a + ")"; }),
      rc::gen::map(sub, [](const std::string& a) { return "sqrt(1+(" + a + ")^2)"; }),
      rc::gen::map(sub, [](const std::string& a) { return "log(2+sin(" + a + "))"; }),
      rc::gen::map(sub, [](const std::string& a) { return "(1.5+cos(" + a + "))^(sin(x))"; }));
}

// Theorem checked: the jet is the function's Taylor expansion to order two, by central
// differences (error O(delta^2) times the third derivatives): the gradient against the values,
// the Hessian against the gradients.
TEST(ScalarField, JetAgreesWithCentralDifferences) {
  test::check_property([] {
    const std::string text = *expression(4);
    const ScalarField u(text);
    const P p{*rc::gen::inRange(-100, 101) / 100.0, *rc::gen::inRange(-100, 101) / 100.0,
              *rc::gen::inRange(-100, 101) / 100.0};
    const Jet3 j = u.jet(p);
    const double d = 1e-5;
    const auto shifted = [&](int a, double s) {
      P q = p;
      (a == 0 ? q.x : a == 1 ? q.y : q.z) += s;
      return u.jet(q);
    };
    double scale = 1 + std::abs(j.value);
    for (double g : j.gradient) scale = std::max(scale, 1 + std::abs(g));
    for (double h : j.hessian) scale = std::max(scale, 1 + std::abs(h));
    for (int a = 0; a < 3; ++a) {
      const Jet3 plus = shifted(a, d), minus = shifted(a, -d);
      const double fd = (plus.value - minus.value) / (2 * d);
      RC_ASSERT(std::abs(fd - j.gradient[std::size_t(a)]) <= 1e-4 * scale * scale);
      // Column a of the Hessian: (xx, yy, zz, xy, xz, yz) indices of (b, a).
      const int index[3][3] = {{0, 3, 4}, {3, 1, 5}, {4, 5, 2}};
      for (int b = 0; b < 3; ++b) {
        const double fdh =
            (plus.gradient[std::size_t(b)] - minus.gradient[std::size_t(b)]) / (2 * d);
        RC_ASSERT(std::abs(fdh - j.hessian[std::size_t(index[b][a])]) <= 1e-4 * scale * scale);
      }
    }
  });
}

TEST(ScalarField, DefaultTestFunctionsParse) {
  const auto names = default_test_functions();
  ASSERT_EQ(names.size(), 3u);
  for (const auto& f : names) EXPECT_NO_THROW(ScalarField{f});
}

} // namespace
} // namespace zdg
