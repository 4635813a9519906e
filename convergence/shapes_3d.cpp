#include <zdg/convergence/shapes_3d.hpp>

#include <zdg/arith/error.hpp>
#include <zdg/kernel/digitization/polynomial_sign.hpp>

#include <array>
#include <cmath>
#include <memory>
#include <numbers>
#include <sstream>
#include <utility>

namespace zdg {

namespace {

using P3 = Point3<double>;

double norm(P3 a) {
  return std::sqrt(dot(a, a));
}
P3 unit(P3 a) {
  return (1.0 / norm(a)) * a;
}

// Damped Newton towards F = 0 from q (the 2D `poly:` scheme, in three variables).
P3 newton(const Polynomial& f, P3 q) {
  double p[3] = {q.x, q.y, q.z}, g[3];
  for (int it = 0; it < 40; ++it) {
    const double v = f.value(p);
    if (v == 0) break;
    f.gradient(p, g);
    const double g2 = g[0] * g[0] + g[1] * g[1] + g[2] * g[2];
    if (!(g2 > 0)) break;
    const double s[3] = {v * g[0] / g2, v * g[1] / g2, v * g[2] / g2};
    double damp = 1.0;
    for (int k = 0; k < 30; ++k) { // halve the step while |F| does not decrease
      double r[3] = {p[0] - damp * s[0], p[1] - damp * s[1], p[2] - damp * s[2]};
      if (std::abs(f.value(r)) <= std::abs(v)) break;
      damp /= 2;
    }
    for (int i = 0; i < 3; ++i) p[i] -= damp * s[i];
    const double step = damp * std::sqrt(s[0] * s[0] + s[1] * s[1] + s[2] * s[2]);
    if (step < 1e-15 * (1 + std::sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]))) break;
  }
  return {p[0], p[1], p[2]};
}

class PolyShape3 final : public Shape3 {
public:
  PolyShape3(std::string spec, Polynomial f, double lo, double hi, std::optional<double> volume,
             ShapeClass regularity, std::optional<double> area = std::nullopt)
      : spec_(std::move(spec)), sign_(std::make_shared<const PolynomialSign>(std::move(f))),
        f_(&sign_->polynomial()), lo_(lo), hi_(hi), volume_(volume), area_(area),
        regularity_(regularity) {}
  ShapeClass shape_class() const override { return regularity_; }
  std::string spec() const override { return spec_; }
  std::optional<std::vector<std::pair<double, double>>> bounding_box() const override {
    return std::vector<std::pair<double, double>>(3, {lo_, hi_});
  }
  // Exact membership of h z - t in { F <= 0 } (kernel/digitization/polynomial_sign.hpp). The
  // predicate shares the polynomial, so it may outlive the shape.
  VoxelPredicate digitize(double h, P3 t) const override {
    const std::array<double, 3> tt{t.x, t.y, t.z};
    return PolynomialDigitization(sign_, h, tt);
  }
  bool contains(P3 p) const override {
    const double q[3] = {p.x, p.y, p.z};
    return f_->value(q) <= 0;
  }
  SurfacePoint3 project(P3 p) const override {
    return at_point_ ? implicit_surface_geometry(*f_, p) : project_implicit_surface(*f_, p);
  }
  std::optional<double> volume() const override { return volume_; }
  std::optional<double> area() const override { return area_; }
  /// The same solid whose ground truth is the geometry of F's level set at the query point
  /// itself (the `unprojected:` kind).
  std::unique_ptr<Shape> unprojected() const {
    auto s = std::make_unique<PolyShape3>(*this);
    s->spec_ = "unprojected:" + spec_;
    s->at_point_ = true;
    return s;
  }

private:
  std::string spec_;
  std::shared_ptr<const PolynomialSign> sign_;
  const Polynomial* f_; // sign_->polynomial()
  double lo_, hi_;
  std::optional<double> volume_, area_;
  ShapeClass regularity_;
  bool at_point_ = false;
};

struct Named {
  const char* name;
  const char* polynomial;
  double lo, hi;
  const char* note;
  ShapeClass regularity;
};

// The regularity classes (papers/THEORY.md, "Shape classes"): spheres and the ellipsoid are
// smooth and strictly convex (spheres umbilic everywhere); the rounded cube is smooth and
// convex but flat at the face centres (Gaussian curvature 0); torus, cylinder, the Goursat
// surfaces and Leopold are smooth (C^3, positive reach inside the box); distel, diabolo (singular
// at 0), heart (cusps) and crixxi are not.
constexpr ShapeClass kSphere{
    .convex = true, .c3 = true, .positive_curvature = true, .umbilic = true};
constexpr ShapeClass kStrictlyConvex{.convex = true, .c3 = true, .positive_curvature = true};
constexpr ShapeClass kConvex{.convex = true, .c3 = true};
constexpr ShapeClass kSmooth{.c3 = true};
constexpr ShapeClass kNone{};

// DGtal's list (Shortcuts::getPolynomialList, src/DGtal/helpers/Shortcuts.h, and the box
// bounds of its examples), with goursat-hole from papers/THEORY.md. DGtal's distel, heart
// and crixxi are negated here so that their bounded solid is F < 0; diabolo and cylinder
// are unbounded and distel reaches |x| = 100 along the axes: the box clips them.
constexpr Named kNamed[] = {
    {"sphere1", "x^2+y^2+z^2-1", -1.25, 1.25, "unit sphere", kSphere},
    {"sphere9", "x^2+y^2+z^2-81", -10, 10, "sphere of radius 9", kSphere},
    {"ellipsoid", "3*x^2+2*y^2+z^2-90", -10, 10, "ellipsoid, half-axes sqrt 30, sqrt 45, sqrt 90",
     kStrictlyConvex},
    {"cylinder", "x^2+2*z^2-90", -10, 10, "elliptic cylinder along y (clipped by the box)",
     kSmooth},
    {"torus", "(x^2+y^2+z^2+6*6-2*2)^2-4*6*6*(x^2+y^2)", -10, 10, "torus R = 6, r = 2", kSmooth},
    {"rcube", "x^4+y^4+z^4-6561", -10, 10, "rounded cube x^4 + y^4 + z^4 <= 9^4", kConvex},
    {"goursat", "-1*(8-0.03*x^4-0.03*y^4-0.03*z^4+2*x^2+2*y^2+2*z^2)", -10, 10, "Goursat surface",
     kSmooth},
    {"goursat-hole", "x^4+y^4+z^4-8*(x^2+y^2+z^2)+30", -10, 10,
     "Goursat surface with holes (genus > 0)", kSmooth},
    {"distel", "x^2+y^2+z^2+1000*(x^2+y^2)*(x^2+z^2)*(y^2+z^2)-10000", -10, 10,
     "distel (spikes along the axes, clipped by the box)", kNone},
    {"leopold", "(x^2*y^2*z^2+4*x^2+4*y^2+3*z^2)-100", -10, 10, "Leopold surface", kSmooth},
    {"diabolo", "x^2-(y^2+z^2)^2", -10, 10, "diabolo (unbounded, singular at 0; clipped)", kNone},
    {"heart", "(x^2+2.25*y^2+z^2-1)^3-x^2*z^3-0.1125*y^2*z^3", -2, 2, "heart surface", kNone},
    {"crixxi", "0.9*(y^2+z^2-1)^2+(x^2+y^2-1)^3", -2, 2, "crixxi surface", kNone},
};

std::optional<double> named_volume(const std::string& name) {
  constexpr double pi = std::numbers::pi;
  if (name == "sphere1") return 4.0 / 3.0 * pi;
  if (name == "sphere9") return 4.0 / 3.0 * pi * 729.0;
  if (name == "ellipsoid") return 4.0 / 3.0 * pi * std::sqrt(30.0 * 45.0 * 90.0);
  if (name == "torus") return 2.0 * pi * pi * 6.0 * 4.0; // 2 pi^2 R r^2
  if (name == "rcube") {
    // |x|^4 + |y|^4 + |z|^4 <= a^4: 8 a^3 Gamma(5/4)^3 / Gamma(7/4).
    return 8.0 * 729.0 * std::pow(std::tgamma(1.25), 3) / std::tgamma(1.75);
  }
  return std::nullopt;
}

// Surface areas: 4 pi r^2; the torus 4 pi^2 R r; the ellipsoid with half-axes a >= b >= c by
// Legendre's formula 2 pi c^2 + 2 pi a b (E(phi, k) sin^2 phi + F(phi, k) cos^2 phi) / sin phi,
// cos phi = c / a, k^2 = a^2 (b^2 - c^2) / (b^2 (a^2 - c^2)) (incomplete elliptic integrals).
std::optional<double> named_area(const std::string& name) {
  constexpr double pi = std::numbers::pi;
  if (name == "sphere1") return 4.0 * pi;
  if (name == "sphere9") return 4.0 * pi * 81.0;
  if (name == "torus") return 4.0 * pi * pi * 6.0 * 2.0;
  if (name == "ellipsoid") {
    const double a = std::sqrt(90.0), b = std::sqrt(45.0), c = std::sqrt(30.0);
    const double phi = std::acos(c / a), s = std::sin(phi);
    const double k = std::sqrt(a * a * (b * b - c * c) / (b * b * (a * a - c * c)));
    return 2 * pi * c * c +
           2 * pi * a * b / s *
               (std::ellint_2(k, phi) * s * s + std::ellint_1(k, phi) * (1 - s * s));
  }
  return std::nullopt;
}

constexpr double kFootTolerance = 1e-12;

// The component of p - q orthogonal to the normal at q (zero at a foot point of p).
P3 tangential_part(const Polynomial& f, P3 p, P3 q) {
  const double x[3] = {q.x, q.y, q.z};
  double g[3];
  f.gradient(x, g);
  const P3 gv{g[0], g[1], g[2]};
  const double gn = norm(gv);
  if (!(gn > 0)) return {0, 0, 0};
  const P3 n = (1.0 / gn) * gv, w = p - q;
  return w - dot(w, n) * n;
}

double tangential_residual(const Polynomial& f, P3 p, P3 q) {
  return norm(tangential_part(f, p, q));
}

// One Newton step on (q - p + mu g(q), F(q)) = 0 (the critical points of |q - p|^2 on
// F = 0), mu from the current point; Gaussian elimination with partial pivoting on the 4x4
// system [[I + mu M, g], [g^T, 0]]. False when the system is singular.
bool lagrange_step(const Polynomial& f, P3 p, P3 q, P3& out) {
  const double x[3] = {q.x, q.y, q.z};
  double g[3], m[9];
  f.gradient(x, g);
  f.hessian(x, m);
  const double g2 = g[0] * g[0] + g[1] * g[1] + g[2] * g[2];
  if (!(g2 > 0)) return false;
  const double w[3] = {p.x - q.x, p.y - q.y, p.z - q.z};
  const double mu = (w[0] * g[0] + w[1] * g[1] + w[2] * g[2]) / g2;
  double a[4][5];
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) a[i][j] = (i == j ? 1.0 : 0.0) + mu * m[3 * i + j];
    a[i][3] = g[i];
    a[i][4] = w[i] - mu * g[i]; // -(q - p + mu g)
  }
  for (int j = 0; j < 3; ++j) a[3][j] = g[j];
  a[3][3] = 0;
  a[3][4] = -f.value(x);
  for (int c = 0; c < 4; ++c) {
    int piv = c;
    for (int r = c + 1; r < 4; ++r) {
      if (std::abs(a[r][c]) > std::abs(a[piv][c])) piv = r;
    }
    if (!(std::abs(a[piv][c]) > 1e-300)) return false;
    for (int k = 0; k < 5; ++k) std::swap(a[c][k], a[piv][k]);
    for (int r = 0; r < 4; ++r) {
      if (r == c) continue;
      const double t = a[r][c] / a[c][c];
      for (int k = c; k < 5; ++k) a[r][k] -= t * a[c][k];
    }
  }
  out = {q.x + a[0][4] / a[0][0], q.y + a[1][4] / a[1][1], q.z + a[2][4] / a[2][2]};
  return std::isfinite(out.x) && std::isfinite(out.y) && std::isfinite(out.z);
}

} // namespace

SurfacePoint3 implicit_surface_geometry(const Polynomial& f, P3 q) {
  const double p[3] = {q.x, q.y, q.z};
  double g[3], m[9];
  f.gradient(p, g);
  f.hessian(p, m);
  const P3 gv{g[0], g[1], g[2]};
  const double gn = norm(gv);
  if (!(gn > 0) || !std::isfinite(gn)) {
    throw InvalidArgument("the gradient of '" + f.str() + "' vanishes at (" + std::to_string(q.x) +
                          ", " + std::to_string(q.y) + ", " + std::to_string(q.z) +
                          "): no normal or curvature there");
  }
  SurfacePoint3 s;
  s.point = q;
  s.normal = (1.0 / gn) * gv;
  auto mv = [&](P3 a) {
    return P3{m[0] * a.x + m[1] * a.y + m[2] * a.z, m[3] * a.x + m[4] * a.y + m[5] * a.z,
              m[6] * a.x + m[7] * a.y + m[8] * a.z};
  };
  const double tr = m[0] + m[4] + m[8];
  s.mean = (gn * gn * tr - dot(gv, mv(gv))) / (2 * gn * gn * gn);
  // g^T adj(M) g = -det [[M, g], [g^T, 0]].
  const double c00 = m[4] * m[8] - m[5] * m[7], c11 = m[0] * m[8] - m[2] * m[6],
               c22 = m[0] * m[4] - m[1] * m[3], c01 = m[2] * m[7] - m[1] * m[8],
               c02 = m[1] * m[5] - m[2] * m[4], c12 = m[2] * m[3] - m[0] * m[5];
  const double gag = g[0] * g[0] * c00 + g[1] * g[1] * c11 + g[2] * g[2] * c22 +
                     2 * (g[0] * g[1] * c01 + g[0] * g[2] * c02 + g[1] * g[2] * c12);
  s.gaussian = gag / (gn * gn * gn * gn);
  // Shape operator on an orthonormal tangent basis (t1, t2).
  const P3 n = s.normal;
  const P3 e = std::abs(n.x) <= std::abs(n.y) && std::abs(n.x) <= std::abs(n.z)
                   ? P3{1, 0, 0}
                   : (std::abs(n.y) <= std::abs(n.z) ? P3{0, 1, 0} : P3{0, 0, 1});
  const P3 t1 = unit(cross(n, e)), t2 = cross(n, t1);
  const double a = dot(t1, mv(t1)) / gn, b = dot(t1, mv(t2)) / gn, c = dot(t2, mv(t2)) / gn;
  const double mid = 0.5 * (a + c), disc = std::hypot(0.5 * (a - c), b);
  s.k1 = mid - disc;
  s.k2 = mid + disc;
  // Eigenvector of k1: (b, k1 - a) or (k1 - c, b), whichever is longer (both are when b != 0).
  double u = b, v = s.k1 - a;
  if (std::hypot(s.k1 - c, b) > std::hypot(u, v)) {
    u = s.k1 - c;
    v = b;
  }
  if (std::hypot(u, v) == 0) { // umbilic: any tangent direction
    u = 1;
    v = 0;
  }
  s.d1 = unit(u * t1 + v * t2);
  s.d2 = cross(n, s.d1);
  return s;
}

SurfacePoint3 project_implicit_surface(const Polynomial& f, P3 p) {
  P3 q = newton(f, p);
  double residual = tangential_residual(f, p, q);
  for (int round = 0; round < 8 && residual > kFootTolerance * (1 + norm((p - q)) + norm(q));
       ++round) {
    const P3 next = newton(f, (q + tangential_part(f, p, q)));
    const double r = tangential_residual(f, p, next);
    if (!(r < residual)) break;
    q = next;
    residual = r;
  }
  // Polish by Newton on the Lagrange system when the tangential rounds converge slowly
  // (points far from the surface compared with its curvature radius).
  for (int it = 0; it < 12 && residual > kFootTolerance * (1 + norm((p - q)) + norm(q)); ++it) {
    P3 next;
    if (!lagrange_step(f, p, q, next)) break;
    next = newton(f, next);
    const double r = tangential_residual(f, p, next);
    if (!(r < residual)) break;
    q = next;
    residual = r;
  }
  return implicit_surface_geometry(f, q);
}

std::optional<std::string> named_polynomial_3d(const std::string& name) {
  for (const auto& s : kNamed) {
    if (name == s.name) return std::string(s.polynomial);
  }
  return std::nullopt;
}

std::vector<std::string> named_shapes_3d() {
  std::vector<std::string> out;
  for (const auto& s : kNamed) out.emplace_back(s.name);
  return out;
}

namespace detail {

void register_3d_shapes(std::vector<ShapeKind>& kinds) {
  kinds.push_back({"poly", 3, "poly:EXPR",
                   "F(x, y, z) <= 0 with z present, rational coefficients (exact), box "
                   "[-10,10]^3",
                   [](std::string_view args, std::string_view spec) -> std::unique_ptr<Shape> {
                     if (args.find('z') == std::string_view::npos) return nullptr; // 2D
                     Polynomial f = Polynomial::parse(args, 3);
                     if (f.degree() < 1) {
                       throw InvalidArgument("shape 'poly:" + std::string(args.substr(0, 40)) +
                                             (args.size() > 40 ? "..." : "") +
                                             "': the polynomial must not be constant");
                     }
                     // Assumed C^3 with positive reach, as the 2D poly: shapes.
                     return std::make_unique<PolyShape3>(std::string(spec), std::move(f), -10.0,
                                                         10.0, std::nullopt, kSmooth);
                   }});
  kinds.push_back(
      {"unprojected", 3, "unprojected:SHAPE",
       "a 3D polynomial shape (named or poly:) whose ground truth is taken at the surfel "
       "centre itself (the curvatures of the level set of F through it), not at its projection "
       "on F = 0: the protocol of DGtalTools' 3dLocalEstimators behind CVIU 2014",
       [](std::string_view args, std::string_view spec) -> std::unique_ptr<Shape> {
         auto inner = parse_shape(args);
         const auto* poly = dynamic_cast<const PolyShape3*>(inner.get());
         if (poly == nullptr) {
           throw InvalidArgument("shape '" + std::string(spec) +
                                 "': unprojected: takes a 3D polynomial shape");
         }
         return poly->unprojected();
       }});
  for (const auto& s : kNamed) {
    const Named named = s;
    std::ostringstream description;
    description << named.note << ": " << named.polynomial << " <= 0, box [" << named.lo << ","
                << named.hi << "]^3";
    kinds.push_back(
        {named.name, 3, named.name, description.str(),
         [named](std::string_view args, std::string_view spec) -> std::unique_ptr<Shape> {
           if (!args.empty() || spec.find(':') != std::string_view::npos) {
             throw InvalidArgument("shape '" + std::string(named.name) + ":...': " + named.name +
                                   " takes no parameters");
           }
           return std::make_unique<PolyShape3>(named.name, Polynomial::parse(named.polynomial, 3),
                                               named.lo, named.hi, named_volume(named.name),
                                               named.regularity, named_area(named.name));
         }});
  }
}

} // namespace detail

} // namespace zdg
