// Continuous shapes with exact ground truth, for multigrid convergence experiments.
//
// A Shape knows its dimension, its canonical text (`ellipse:20,7`), and an optional
// bounding box. Shape2 (this file) adds what the 2D estimators are checked against:
// the Gauss digitization G_h(X + t) = { z in Z^2 : h z - t in X } at grid step h of the
// shape translated by t; the projection xi onto the boundary with the unit tangent
// (counter-clockwise, the inside on the left) and the curvature there (> 0 where convex);
// area, perimeter and moments up to order 2 when known. A 3D shape derives from Shape
// with its own queries; the driver only needs Shape.
//
// Grid step and exactness. h = exp(-i/10) is not rational: the grid step actually used
// is the double nearest to it, a dyadic rational, and the translation is a double too, so
// the point h z - t is a rational known exactly. Shapes given by rational polynomials
// (ball, ellipse without rotation, polygon, poly:) decide membership exactly: the sign of
// F(h z - t) by the filtered predicate of kernel/digitization/polynomial_sign.hpp (double with a
// rigorous error bound, Rational<BigInt> when the bound does not certify it). A rotated ellipse is
// the quadric whose coefficients are the doubles of its rotated implicit equation (exact from then
// on). Flowers are transcendental: membership is decided in double (r(theta) vs |p|).
#pragma once

#include <zdg/arith/point.hpp>
#include <zdg/kernel/digitization/gauss_digitization.hpp>

#include <array>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace zdg {

/// The regularity class of a shape: what the hypotheses of the convergence theorems ask
/// (papers/THEORY.md, "Shape classes"). Each shape states its own; the estimators' proven rates
/// read it (convergence/estimator.hpp).
struct ShapeClass {
  bool convex = false;             ///< X convex
  bool c3 = false;                 ///< boundary C^3 (compact, hence positive reach)
  bool positive_curvature = false; ///< curvature (2D) / Gaussian curvature (3D) > 0 everywhere
  bool polygon = false;            ///< boundary piecewise linear (a polygon)
  bool umbilic = false;            ///< 3D: every boundary point umbilic (k1 = k2: spheres)
};

class Shape {
public:
  virtual ~Shape() = default;
  virtual int dimension() const = 0;
  /// Canonical text of the shape (what parse_shape reads back).
  virtual std::string spec() const = 0;
  /// [lo, hi] per axis when the shape is bounded and the box is known.
  virtual std::optional<std::vector<std::pair<double, double>>> bounding_box() const {
    return std::nullopt;
  }
  /// Digitization domain when --box is not given and the shape has no bounding box:
  /// [-20,20]^d by default (3D implicit shapes override it with [-10,10]^3).
  virtual std::pair<double, double> default_domain() const { return {-20.0, 20.0}; }
  /// The regularity class (default: nothing known, so no theory check applies).
  virtual ShapeClass shape_class() const { return {}; }
};

/// A point of the true boundary with its unit tangent and curvature.
struct BoundaryPoint2 {
  Point2<double> point;
  Point2<double> tangent;
  double curvature = 0.0;
};

/// Moments m_pq = integral of x^p y^q over the shape, order <= 2, in the order
/// m00, m10, m01, m20, m11, m02.
using Moments2 = std::array<double, 6>;

class Shape2 : public Shape {
public:
  int dimension() const final { return 2; }
  /// G_h(X + t) restricted to the box.
  virtual std::unique_ptr<GaussDigitization2> digitize(double h, Point2<double> t,
                                                       Box2 box) const = 0;
  /// Membership of a point (double; diagnostics and tests).
  virtual bool contains(Point2<double> p) const = 0;
  /// The nearest boundary point of p (untranslated frame) with tangent and curvature.
  virtual BoundaryPoint2 project(Point2<double> p) const = 0;
  /// The nearest boundary points of a sequence of points in chain order (consecutive
  /// points close to each other, e.g. the linels of a digital contour). Same answers as
  /// `project` on each point; shapes may override it to warm-start each projection from
  /// the previous one (ParametricShape does, with a reach certificate).
  virtual std::vector<BoundaryPoint2> project_chain(std::span<const Point2<double>> pts) const {
    std::vector<BoundaryPoint2> out;
    out.reserve(pts.size());
    for (const auto& p : pts) out.push_back(project(p));
    return out;
  }
  /// A lower bound of the reach of the boundary (Federer 1959):
  ///   reach = inf over boundary points x != y of |y - x|^2 / (2 |(y - x) . n_x|),
  /// the smaller of the minimal radius of curvature and half the narrowest bottleneck;
  /// 0 when the boundary has a corner; nullopt when unknown. Never an overestimate: a point
  /// at distance < reach from the boundary has a unique nearest boundary point, and the
  /// Gauss digitization at step h <= reach / 2 is topologically faithful (Latecki, Conrad,
  /// Gross 1998; Stelldinger, Koethe 2005).
  virtual std::optional<double> reach_lower_bound() const { return std::nullopt; }
  virtual std::optional<double> area() const { return std::nullopt; }
  virtual std::optional<double> perimeter() const { return std::nullopt; }
  virtual std::optional<Moments2> moments() const { return std::nullopt; }
};

/// Moments of X + t from those of X.
Moments2 translate_moments(const Moments2& m, Point2<double> t);

/// One kind of shape in the registry: its name (text before ':'), dimension, syntax and
/// factory. A factory may return nullptr to decline (`poly:` with z is not 2D).
struct ShapeKind {
  std::string name;
  int dimension;
  std::string syntax;
  std::string description;
  std::function<std::unique_ptr<Shape>(std::string_view args, std::string_view spec)> make;
};

/// The registered shape kinds (2D ones first; 3D ones plug in with register_shape_kind).
const std::vector<ShapeKind>& shape_kinds();
void register_shape_kind(ShapeKind kind);

/// Parses `name:args`; throws InvalidArgument naming the offending part.
std::unique_ptr<Shape> parse_shape(std::string_view spec);

/// Parses a comma-separated list of rationals (`a/b`, decimals) as doubles, naming
/// `what` in errors; `count` < 0 accepts any number of values.
std::vector<double> parse_number_list(std::string_view args, std::string_view what);

/// Seeded sub-pixel translation h * u, u uniform in [-1, 1)^d, reproducible on every
/// platform (mt19937_64 seeded with seed and the index).
std::vector<double> random_translation(std::uint64_t seed, int index, int dimension, double h);

namespace detail {
void register_2d_shapes(std::vector<ShapeKind>& kinds);
}

} // namespace zdg
