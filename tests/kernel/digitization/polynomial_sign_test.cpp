// The filtered polynomial sign against exact Rational<BigInt> evaluation (the oracle):
// points at distance about 2^-60 of the zero set (where doubles cannot decide and the exact
// fallback must), random points (where the filter decides), the error bound itself
// (|F~ - F| <= bound, checked exactly), and worked examples on the circle of radius 5.
#include <zdg/kernel/digitization/polynomial_sign.hpp>

#include "tests/support/tower.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <memory>
#include <vector>

namespace {

using zdg::BigInt;
using zdg::BigRational;
using zdg::GridFrame;
using zdg::Polynomial;
using zdg::PolynomialSign;

int exact_sign(const BigRational& v) {
  return v < BigRational(0) ? -1 : (v > BigRational(0) ? 1 : 0);
}

// A random polynomial G in nvars variables: 1 to 6 terms of total degree <= 4 with rational
// coefficients n / d (|n| <= 50, 1 <= d <= 9).
Polynomial random_polynomial(int nvars) {
  const int terms = *rc::gen::inRange(1, 7);
  Polynomial g = Polynomial::constant(BigRational(0), nvars);
  for (int k = 0; k < terms; ++k) {
    Polynomial m = Polynomial::constant(
        BigRational(BigInt(*rc::gen::inRange(-50, 51)), BigInt(*rc::gen::inRange(1, 10))), nvars);
    const int degree = *rc::gen::inRange(1, 5);
    for (int e = 0; e < degree; ++e) {
      m = m * Polynomial::variable(*rc::gen::inRange(0, nvars), nvars);
    }
    g = g + m;
  }
  return g;
}

// Theorem checked: the filtered sign of F at h z - t equals the sign of F evaluated exactly in
// Rational<BigInt>, for F = G - G(h z) (so that h z lies on the zero set exactly) and a
// translation t of about 2^-60: the point h z - t is within ~2^-60 of the zero set, below the
// resolution of its double coordinates (ulp(1) = 2^-52), so only the exact fallback can
// decide; and F(h z - t) is usually not zero (t is generic), so a wrong answer shows.
void near_zero_set_property(int nvars) {
  int fallbacks = 0;
  zdg::test::check_property([nvars, &fallbacks] {
    Polynomial g = random_polynomial(nvars);
    const double h = std::ldexp(static_cast<double>(*rc::gen::inRange(1, 1 << 20)), -20);
    std::array<std::int64_t, 3> z{};
    std::array<double, 3> t{};
    std::array<BigRational, 3> a;
    for (int i = 0; i < nvars; ++i) {
      z[static_cast<std::size_t>(i)] = *rc::gen::inRange<std::int64_t>(-4000, 4001);
      t[static_cast<std::size_t>(i)] = std::ldexp(*rc::gen::inRange(-8, 9), -60);
      a[static_cast<std::size_t>(i)] =
          zdg::exact_rational(h) * BigRational(BigInt(z[static_cast<std::size_t>(i)]));
    }
    Polynomial f = g - Polynomial::constant(g.value_exact(a.data()), nvars);
    PolynomialSign sign(f);
    GridFrame frame(h, std::span<const double>(t.data(), static_cast<std::size_t>(nvars)));
    const auto p = frame.exact(z.data());
    for (int i = 0; i < nvars; ++i) {
      const auto k = static_cast<std::size_t>(i);
      RC_ASSERT(p[k] == a[k] - zdg::exact_rational(t[k])); // the frame is exact
    }
    double pd[3], m[3];
    frame.approximate(z.data(), pd, m);
    const int s = sign.sign(pd, m, [&] {
      ++fallbacks;
      return frame.exact(z.data());
    });
    RC_ASSERT(s == exact_sign(f.value_exact(p.data())));
    RC_ASSERT(frame.sign(sign, z.data()) == s);
  });
  EXPECT_GT(fallbacks, 0); // the points are close enough to the zero set to need it
}

TEST(PolynomialSign, AgreesWithRationalEvaluationNearTheZeroSet2d) {
  near_zero_set_property(2);
}

TEST(PolynomialSign, AgreesWithRationalEvaluationNearTheZeroSet3d) {
  near_zero_set_property(3);
}

// Theorem checked: PolynomialDigitization::column gives, at every point of a column, the
// exact sign test F(h z - t) <= 0 (Rational<BigInt> evaluation), the answer of the voxel
// predicate: random polynomials of three variables made to vanish at one grid point of the
// column (so that the exact fallback decides there), random steps and translations, columns
// of 1 to 40 points.
TEST(PolynomialSign, ColumnAnswersEqualPointAnswers) {
  zdg::test::check_property([] {
    Polynomial g = random_polynomial(3);
    const double h = std::ldexp(static_cast<double>(*rc::gen::inRange(1, 1 << 20)), -20);
    const std::array<double, 3> t{std::ldexp(*rc::gen::inRange(-8, 9), -4),
                                  std::ldexp(*rc::gen::inRange(-8, 9), -4),
                                  std::ldexp(*rc::gen::inRange(-8, 9), -4)};
    const std::int64_t x = *rc::gen::inRange<std::int64_t>(-300, 301);
    const std::int64_t y = *rc::gen::inRange<std::int64_t>(-300, 301);
    const std::int64_t z0 = *rc::gen::inRange<std::int64_t>(-300, 301);
    const std::int64_t n = *rc::gen::inRange<std::int64_t>(1, 41);
    const std::int64_t zero_at = z0 + *rc::gen::inRange<std::int64_t>(0, n);
    GridFrame frame(h, t);
    const std::int64_t q[3] = {x, y, zero_at};
    const auto a = frame.exact(q);
    const Polynomial f = g - Polynomial::constant(g.value_exact(a.data()), 3);
    const auto sign = std::make_shared<const PolynomialSign>(f);
    const zdg::PolynomialDigitization dig(sign, h, t);
    std::vector<std::uint8_t> out(std::size_t(n), 7);
    dig.column(x, y, z0, z0 + n - 1, out.data());
    for (std::int64_t k = 0; k < n; ++k) {
      const std::int64_t p[3] = {x, y, z0 + k};
      const auto e = frame.exact(p);
      const bool inside = exact_sign(f.value_exact(e.data())) <= 0;
      RC_ASSERT(out[std::size_t(k)] == (inside ? 1 : 0));
      RC_ASSERT(dig({x, y, z0 + k}) == inside);
    }
    RC_ASSERT(out[std::size_t(zero_at - z0)] == 1); // F = 0 there: inside
  });
}

// Theorem checked (the filter itself, Higham's forward bound): for doubles p and X = 2 |p|,
// |value(p) - F(p)| <= error_bound(X), with F(p) exact in Rational<BigInt>; hence the sign is
// right whenever the filter decides. Random points, random polynomials, 2 and 3 variables.
TEST(PolynomialSign, ErrorBoundHoldsExactly) {
  zdg::test::check_property([] {
    const int nvars = *rc::gen::inRange(2, 4);
    PolynomialSign sign(random_polynomial(nvars));
    double p[3], m[3];
    std::array<BigRational, 3> q;
    for (int i = 0; i < nvars; ++i) {
      p[i] = std::ldexp(static_cast<double>(*rc::gen::inRange(-(1 << 30), 1 << 30)),
                        *rc::gen::inRange(-40, -20));
      m[i] = 2 * std::abs(p[i]);
      q[static_cast<std::size_t>(i)] = zdg::exact_rational(p[i]);
    }
    const double v = sign.value(p), bound = sign.error_bound(m);
    const BigRational exact = sign.polynomial().value_exact(q.data());
    BigRational diff = zdg::exact_rational(v) - exact;
    if (diff < BigRational(0)) diff = -diff;
    RC_ASSERT(diff <= zdg::exact_rational(bound));
    RC_ASSERT(sign.sign(p, m, [&] { return q; }) == exact_sign(exact));
  });
}

// The quadric form (degree 2 in two variables) and the general evaluation agree with the
// exact value on random grid points of a rotated ellipse with double coefficients.
TEST(PolynomialSign, QuadricFormAgreesWithExactEvaluation) {
  zdg::test::check_property([] {
    const double theta = *rc::gen::inRange(0, 628) / 100.0;
    const double c = std::cos(theta), s = std::sin(theta);
    Polynomial x = Polynomial::variable(0, 2), y = Polynomial::variable(1, 2);
    Polynomial f =
        Polynomial::constant(zdg::exact_rational(c * c / 400 + s * s / 49), 2) * x * x +
        Polynomial::constant(zdg::exact_rational(2 * c * s * (1.0 / 400 - 1.0 / 49)), 2) * x * y +
        Polynomial::constant(zdg::exact_rational(s * s / 400 + c * c / 49), 2) * y * y -
        Polynomial::constant(BigRational(1), 2);
    PolynomialSign sign(f);
    RC_ASSERT(sign.is_quadric());
    const double h = 1.0 / *rc::gen::inRange(1, 64);
    const std::array<double, 2> t{std::ldexp(*rc::gen::inRange(-1000, 1000), -10),
                                  std::ldexp(*rc::gen::inRange(-1000, 1000), -10)};
    GridFrame frame(h, t);
    const std::int64_t z[2] = {*rc::gen::inRange<std::int64_t>(-25 * 64, 25 * 64),
                               *rc::gen::inRange<std::int64_t>(-25 * 64, 25 * 64)};
    const auto p = frame.exact(z);
    RC_ASSERT(frame.sign(sign, z) == exact_sign(f.value_exact(p.data())));
  });
}

// Worked example: (3, 4) lies on x^2 + y^2 = 25. At h = 1, z = (3, 4), t = (-2^-60, 0) the
// point (3 + 2^-60, 4) is outside; t = (2^-60, 0) gives a point inside; t = 0 is on the circle.
// In double, 3 + 2^-60 rounds to 3 and F~ = 0: only the exact fallback can tell them apart.
TEST(PolynomialSign, CircleOfRadiusFiveAtDistanceTwoToMinusSixty) {
  PolynomialSign circle(Polynomial::parse("x^2 + y^2 - 25", 2));
  const std::int64_t z[2] = {3, 4};
  const double eps = std::ldexp(1.0, -60);
  EXPECT_EQ(GridFrame(1.0, std::array<double, 2>{-eps, 0.0}).sign(circle, z), 1);
  EXPECT_EQ(GridFrame(1.0, std::array<double, 2>{eps, 0.0}).sign(circle, z), -1);
  EXPECT_EQ(GridFrame(1.0, std::array<double, 2>{0.0, 0.0}).sign(circle, z), 0);
  // Far from the circle the filter decides without the exact point.
  const std::int64_t far[2] = {2, 2}; // (1, 1), well inside
  double p[2], m[2];
  GridFrame frame(0.5, std::array<double, 2>{0.0, 0.0});
  frame.approximate(far, p, m);
  bool called = false;
  EXPECT_EQ(circle.sign(p, m,
                        [&] {
                          called = true;
                          return frame.exact(far);
                        }),
            -1);
  EXPECT_FALSE(called);
}

// A coefficient below the smallest normal double counts with that normal as its magnitude:
// F = 10^-400 x - 10^-400 has a zero at x = 1 which its doubles (0 x - 0) cannot see.
TEST(PolynomialSign, SubnormalCoefficientsStayRigorous) {
  BigInt ten400(1);
  for (int i = 0; i < 400; ++i) ten400 *= 10;
  const BigRational tiny(BigInt(1), ten400);
  Polynomial f =
      Polynomial::constant(tiny, 2) * Polynomial::variable(0, 2) - Polynomial::constant(tiny, 2);
  PolynomialSign sign(f);
  const double eps = std::ldexp(1.0, -60);
  const std::int64_t z[2] = {1, 0};
  EXPECT_EQ(GridFrame(1.0, std::array<double, 2>{-eps, 0.0}).sign(sign, z), 1);
  EXPECT_EQ(GridFrame(1.0, std::array<double, 2>{eps, 0.0}).sign(sign, z), -1);
  const std::int64_t two[2] = {2, 0};
  EXPECT_EQ(GridFrame(1.0, std::array<double, 2>{0.0, 0.0}).sign(sign, two), 1);
}

} // namespace
