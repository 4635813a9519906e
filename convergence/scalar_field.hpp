// Test functions u : R^3 -> R given as text (`--function`, the `u=` parameter of the
// Laplace-Beltrami estimators of the driver), with exact first and second derivatives, and the
// Laplace-Beltrami operator of their restriction to a surface.
//
// Syntax: numbers (decimal, exponent allowed), the variables x, y, z, the constant pi, the
// operators + - * / ^ (power, right associative, binds tighter than unary minus: -x^2 is
// -(x^2)), parentheses, and the functions sin cos tan exp log sqrt sinh cosh tanh atan. At most
// 1000 characters and 200 levels of nesting. No commas (the text is a value inside an estimator
// spec `NAME:KEY=VALUE,...`). A text that does not parse: InvalidArgument naming the position.
//
// Derivatives: forward-mode automatic differentiation with second-order jets (value, gradient,
// Hessian) through each operation by the chain rule (Griewank, Walther, "Evaluating
// Derivatives", SIAM 2008, ch. 13): exact up to the rounding of the double operations, no
// finite differences. A point where the function or a derivative is not finite (log of a
// non-positive number, a division by zero, sqrt at 0): InvalidArgument naming the point.
//
// Laplace-Beltrami of the restriction to a surface S with unit normal n and principal
// curvatures k1, k2 (positive where the solid is convex, n outward) at a point of S:
//     Delta_S u = tr(Hess u) - n^T (Hess u) n - (k1 + k2) (grad u . n)
// (the ambient Laplacian minus the normal second derivative minus the mean-curvature term;
// e.g. Delta_S x = -2 x / R^2 on the sphere of radius R; do Carmo, "Riemannian Geometry", ch. 6,
// or Reilly 1982 for the formula). Negative semi-definite sign convention.
//
// Cost: O(length) to parse; O(nodes) per evaluation (about 30 flops per node for the jet).
#pragma once

#include <zdg/arith/point.hpp>

#include <array>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

namespace zdg {

/// The value, gradient and Hessian (xx, yy, zz, xy, xz, yz) of u at a point.
struct Jet3 {
  double value = 0;
  std::array<double, 3> gradient{};
  std::array<double, 6> hessian{};
};

class ScalarField {
public:
  /// Parses `text` (syntax above). InvalidArgument with the position of the first error.
  explicit ScalarField(std::string_view text);
  ~ScalarField();
  ScalarField(const ScalarField&);
  ScalarField& operator=(const ScalarField&);
  ScalarField(ScalarField&&) noexcept;
  ScalarField& operator=(ScalarField&&) noexcept;

  /// The text as given.
  const std::string& text() const { return text_; }
  /// u(p). InvalidArgument where it is not finite.
  double value(Point3<double> p) const;
  /// u and its first and second derivatives at p. InvalidArgument where one is not finite.
  Jet3 jet(Point3<double> p) const;
  /// Delta_S u at p on a surface with unit normal n and principal curvatures k1, k2.
  double laplace_beltrami(Point3<double> p, Point3<double> n, double k1, double k2) const;

  struct Node; ///< one instruction of the postfix program (opaque)

private:
  std::string text_;
  std::vector<Node> nodes_; // postfix order: the last node is the root
};

/// The default test functions of the Laplace-Beltrami estimators (Caissard et al., JMIV 2019):
/// u = x, u = x^2 - y^2, u = exp(z).
std::vector<std::string> default_test_functions();

} // namespace zdg
