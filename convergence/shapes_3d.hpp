// The 3D shapes of the registry: implicit polynomial solids X = { F <= 0 } (F < 0 inside,
// the surface F = 0 counted as inside, as in 2D), see convergence/shape.hpp for the contract.
//
//   poly:EXPR     F(x, y, z), rational coefficients (a `poly:` without z is the 2D shape)
//   sphere1, sphere9, ellipsoid, cylinder, torus, rcube, goursat, goursat-hole, distel,
//   leopold, diabolo, heart, crixxi    the classic test polynomials (named_polynomial_3d)
//
// Digitization G_h(X + t) = { z in Z^3 : h z - t in X }: the sign of F at the point
// h z - t (exact dyadic rational) by the filtered predicate of
// kernel/digitization/polynomial_sign.hpp (double with a rigorous error bound, Rational<BigInt>
// when the bound does not certify it), the one predicate of the 2D polynomial shapes too.
//
// Ground truth (formulas: papers/THEORY.md, "Ground-truth formulas"): xi(p) by damped Newton on
// F, foot-point refinement and Newton on the Lagrange system, to 1e-12 relative (iteration
// limits: docs/NOTES.md, "convergence/shapes_3d.hpp"); H, K, k1 <= k2, d1, d2 from grad F and
// Hessian F, positive where the solid is convex. Membership: O(#terms deg) flops, plus a BigInt
// evaluation within the filter bound (rare); the predicate is safe from several threads.
#pragma once

#include <zdg/convergence/shape.hpp>
#include <zdg/kernel/surfaces/digital_surface.hpp>

#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace zdg {

// kernel/digitization/polynomial.hpp (its Rational<BigInt> coefficients are not needed here).
class Polynomial;

/// A point of the true surface with its differential geometry (outward normal).
struct SurfacePoint3 {
  Point3<double> point;
  Point3<double> normal;         ///< unit, outward (grad F / |grad F|)
  double mean = 0, gaussian = 0; ///< H = (k1 + k2) / 2, K = k1 k2
  double k1 = 0, k2 = 0;         ///< principal curvatures, k1 <= k2
  Point3<double> d1, d2;         ///< unit principal directions of k1 and k2
};

class Shape3 : public Shape {
public:
  int dimension() const final { return 3; }
  /// The membership predicate of G_h(X + t) (exact; callable from several threads).
  virtual VoxelPredicate digitize(double h, Point3<double> t) const = 0;
  /// Membership of a point (double; diagnostics and tests).
  virtual bool contains(Point3<double> p) const = 0;
  /// The nearest surface point of p (untranslated frame) with its curvatures.
  virtual SurfacePoint3 project(Point3<double> p) const = 0;
  virtual std::optional<double> volume() const { return std::nullopt; }
  /// The area of the surface when known in closed form (spheres, torus, ellipsoid).
  virtual std::optional<double> area() const { return std::nullopt; }
};

/// The differential geometry of the surface F = 0 at q (q need not lie exactly on it: the
/// formulas are evaluated at q). Throws InvalidArgument where grad F = 0.
SurfacePoint3 implicit_surface_geometry(const Polynomial& f, Point3<double> q);

/// xi(p) on F = 0 with its geometry (damped Newton and foot-point refinement, above).
SurfacePoint3 project_implicit_surface(const Polynomial& f, Point3<double> p);

/// The classic polynomial of a named shape (sphere9 -> "x^2+y^2+z^2-81"), oriented so that
/// its bounded solid is F < 0, or nullopt for an unknown name.
std::optional<std::string> named_polynomial_3d(const std::string& name);

/// The names of the classic 3D shapes, in registry order.
std::vector<std::string> named_shapes_3d();

namespace detail {
void register_3d_shapes(std::vector<ShapeKind>& kinds);
}

} // namespace zdg
