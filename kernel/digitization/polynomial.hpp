// Polynomials in n = 2 or 3 variables (x, y, z) with rational coefficients, as written on
// the command line after `poly:` (F < 0 is the inside of an implicit shape).
//
// Syntax: sums and differences of products of factors; a factor is a number (integer,
// rational a/b, or decimal 1.25, all exact), a variable x, y or z, or a parenthesized
// expression, optionally raised to a non-negative integer power `^k`. Multiplication is
// explicit (`3*x^2`) or implicit between a number and a variable / parenthesis (`3x^2`,
// `2(x+y)`). Unary minus is allowed. Numbers are decimal: a number directly followed by a
// letter other than x, y, z (`1e5`, `0b1`, `0o7`) or a variable directly followed by a digit
// (`x2`, the tail of `0x10`) is refused, never read as a product. Errors name the offending
// position.
//
// Limits (small text must not mean unbounded work): parentheses and unary signs nest at most
// kPolynomialMaxNesting = 200 deep; every intermediate result of the expansion has total
// degree at most kPolynomialMaxDegree = 64, checked before a product or a power is expanded
// (`(x+y)^40*(x-y)^40` is refused before the second power is expanded); the whole expansion
// performs at most kPolynomialMaxWork = 2^14 products and sums of terms (about 20 ms; enough
// for (x+y+1)^20 or (x+y+z+1)^14, refusing (x+y+1)^64*(x+y+1)^64*... within that time); a
// coefficient must be finite as a double. Beyond a limit: InvalidArgument saying which.
//
// Evaluation: exact value and sign at a rational point (Rational<BigInt>), double value,
// gradient and Hessian. The exact sign with a floating-point filter, which the digitizations
// use, is kernel/digitization/polynomial_sign.hpp. Parsing costs O(work) (bounded as above);
// evaluation O(#terms deg).
#pragma once

#include <zdg/arith/integer.hpp>
#include <zdg/arith/rational.hpp>

#include <array>
#include <string>
#include <string_view>
#include <vector>

namespace zdg {

using BigRational = Rational<BigInt>;

inline constexpr int kPolynomialMaxNesting = 200;
inline constexpr int kPolynomialMaxDegree = 64;
inline constexpr long kPolynomialMaxWork = 1L << 14;

struct Monomial {
  std::array<int, 3> exponent{}; // powers of x, y, z
  BigRational coefficient;
  double coefficient_double = 0.0;
  int degree() const { return exponent[0] + exponent[1] + exponent[2]; }
};

class Polynomial {
public:
  Polynomial() = default;
  /// Parses EXPR in the variables x, y (and z when nvars == 3); throws InvalidArgument
  /// naming the position ("poly: unexpected 'q' at position 5 of 'x^2+q'").
  static Polynomial parse(std::string_view text, int nvars);

  int nvars() const { return nvars_; }
  int degree() const { return degree_; }
  const std::vector<Monomial>& terms() const { return terms_; }
  bool is_zero() const { return terms_.empty(); }
  std::string str() const;

  /// F(p) in double (p has nvars entries).
  double value(const double* p) const;
  /// Gradient (nvars entries) and Hessian (nvars x nvars, row-major) in double.
  void gradient(const double* p, double* g) const;
  void hessian(const double* p, double* hess) const;
  /// Exact sign of F at a rational point.
  int sign_exact(const BigRational* p) const;
  /// Exact value at a rational point.
  BigRational value_exact(const BigRational* p) const;

  /// Algebra used by the parser (exact).
  friend Polynomial operator+(const Polynomial& a, const Polynomial& b);
  friend Polynomial operator-(const Polynomial& a, const Polynomial& b);
  friend Polynomial operator*(const Polynomial& a, const Polynomial& b);
  Polynomial pow(int k) const;
  static Polynomial constant(const BigRational& c, int nvars);
  static Polynomial variable(int index, int nvars);

private:
  int nvars_ = 2;
  int degree_ = 0;
  std::vector<Monomial> terms_; // sorted by exponent, no zero coefficient
  void normalize();
};

/// Exact conversion of a finite double to a rational (a double is a dyadic rational).
BigRational exact_rational(double v);

} // namespace zdg
