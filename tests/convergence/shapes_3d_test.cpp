#include <zdg/convergence/shapes_3d.hpp>

#include <zdg/arith/error.hpp>
#include <zdg/estimators/gauss_volume.hpp>
#include <zdg/kernel/digitization/polynomial.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

namespace {

using zdg::Point3;
using zdg::Shape3;
using P3 = Point3<double>;

std::unique_ptr<Shape3> shape3(const std::string& spec) {
  auto s = zdg::parse_shape(spec);
  auto* p = dynamic_cast<Shape3*>(s.get());
  EXPECT_NE(p, nullptr) << spec;
  s.release();
  return std::unique_ptr<Shape3>(p);
}

double norm(P3 a) {
  return std::sqrt(dot(a, a));
}
// |cos| of the angle between two lines.
double line_cos(P3 a, P3 b) {
  return std::abs(dot(a, b)) / (norm(a) * norm(b));
}

// The frame and curvatures of any surface point: k1 <= k2, k1 + k2 = 2H, k1 k2 = K, (d1, d2,
// n) orthonormal and direct.
void expect_consistent(const zdg::SurfacePoint3& s) {
  EXPECT_LE(s.k1, s.k2);
  EXPECT_NEAR(s.k1 + s.k2, 2 * s.mean, 1e-10 * (1 + std::abs(s.mean)));
  EXPECT_NEAR(s.k1 * s.k2, s.gaussian, 1e-10 * (1 + std::abs(s.gaussian)));
  EXPECT_NEAR(norm(s.normal), 1, 1e-12);
  EXPECT_NEAR(norm(s.d1), 1, 1e-12);
  EXPECT_NEAR(norm(s.d2), 1, 1e-12);
  EXPECT_NEAR(dot(s.d1, s.normal), 0, 1e-12);
  EXPECT_NEAR(dot(s.d2, s.normal), 0, 1e-12);
  EXPECT_NEAR(dot(s.d1, s.d2), 0, 1e-12);
  const P3 c{s.d1.y * s.d2.z - s.d1.z * s.d2.y, s.d1.z * s.d2.x - s.d1.x * s.d2.z,
             s.d1.x * s.d2.y - s.d1.y * s.d2.x};
  EXPECT_NEAR(dot(c, s.normal), 1, 1e-12);
}

TEST(Shapes3d, SphereSignConventionHIsOneOverR) {
  // papers/THEORY.md: fix the sign once, a sphere of radius r has H = 1/r > 0 (outward normal).
  auto s = shape3("sphere9");
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(-12, 12);
  for (int i = 0; i < 100; ++i) {
    P3 p{u(rng), u(rng), u(rng)};
    if (norm(p) < 0.5) continue;
    auto q = s->project(p);
    EXPECT_NEAR(norm(q.point), 9, 1e-12);
    EXPECT_NEAR(q.mean, 1.0 / 9, 1e-12);
    EXPECT_NEAR(q.gaussian, 1.0 / 81, 1e-12);
    EXPECT_NEAR(q.k1, 1.0 / 9, 1e-9);
    EXPECT_NEAR(q.k2, 1.0 / 9, 1e-9);
    // Nearest point: on the ray from 0 through p; the normal points outward.
    EXPECT_NEAR(dot(q.normal, p) / norm(p), 1, 1e-12);
    EXPECT_NEAR(q.point.x * norm(p), 9 * p.x, 1e-9);
    expect_consistent(q);
  }
  auto unit = shape3("sphere1");
  EXPECT_NEAR(unit->project({0.3, -0.2, 0.5}).mean, 1.0, 1e-12);
  EXPECT_NEAR(*unit->volume(), 4.0 / 3.0 * std::numbers::pi, 1e-12);
}

TEST(Shapes3d, EllipsoidCurvaturesMatchTheClosedForms) {
  // 3x^2 + 2y^2 + z^2 = 90: a^2 = 30, b^2 = 45, c^2 = 90. With p^2 = x^2/a^4 + y^2/b^4 +
  // z^2/c^4: K = 1/(a^2 b^2 c^2 p^4), H = (a^2 + b^2 + c^2 - |x|^2) / (2 a^2 b^2 c^2 p^3).
  auto s = shape3("ellipsoid");
  const double a2 = 30, b2 = 45, c2 = 90;
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> u(-1, 1);
  for (int i = 0; i < 200; ++i) {
    P3 dir{u(rng), u(rng), u(rng)};
    if (norm(dir) < 0.1) continue;
    // A point of the surface (on the ray of dir) moved by up to 1.5 per coordinate, inside the
    // smallest curvature radius 30 / sqrt 90 = 3.2 (surfel centres are within h of it).
    const double on = 1 / std::sqrt(dir.x * dir.x / a2 + dir.y * dir.y / b2 + dir.z * dir.z / c2);
    P3 p{dir.x * on + 1.5 * u(rng), dir.y * on + 1.5 * u(rng), dir.z * on + 1.5 * u(rng)};
    auto q = s->project(p);
    const P3 x = q.point;
    EXPECT_NEAR(x.x * x.x / a2 + x.y * x.y / b2 + x.z * x.z / c2, 1, 1e-12);
    const double p2 = x.x * x.x / (a2 * a2) + x.y * x.y / (b2 * b2) + x.z * x.z / (c2 * c2);
    const double K = 1 / (a2 * b2 * c2 * p2 * p2);
    const double H = (a2 + b2 + c2 - dot(x, x)) / (2 * a2 * b2 * c2 * p2 * std::sqrt(p2));
    EXPECT_NEAR(q.gaussian, K, 1e-10 * K);
    EXPECT_NEAR(q.mean, H, 1e-10 * H);
    EXPECT_GT(q.k1, 0); // convex
    expect_consistent(q);
    // Nearest point: p - xi(p) is along the normal.
    const P3 w{p.x - x.x, p.y - x.y, p.z - x.z};
    if (norm(w) > 1e-6) {
      EXPECT_NEAR(line_cos(w, q.normal), 1, 1e-10);
    }
  }
}

TEST(Shapes3d, EllipsoidVertexPrincipalCurvaturesMatchedByValue) {
  // At the vertex (a, 0, 0) the curvatures are a/b^2 along y and a/c^2 along z: the smaller
  // one, a/c^2 (c is the longest axis), belongs to the z direction, not to "the first axis".
  auto s = shape3("ellipsoid");
  auto q = s->project({6.5, 0, 0});
  const double a = std::sqrt(30.0);
  EXPECT_NEAR(q.point.x, a, 1e-12);
  EXPECT_NEAR(q.k1, a / 90, 1e-12);
  EXPECT_NEAR(q.k2, a / 45, 1e-12);
  EXPECT_NEAR(line_cos(q.d1, {0, 0, 1}), 1, 1e-12);
  EXPECT_NEAR(line_cos(q.d2, {0, 1, 0}), 1, 1e-12);
  // At (0, 0, c): c/a^2 along x (the larger) and c/b^2 along y (the smaller).
  auto top = s->project({0, 0, 9.9});
  const double c = std::sqrt(90.0);
  EXPECT_NEAR(top.k1, c / 45, 1e-12);
  EXPECT_NEAR(top.k2, c / 30, 1e-12);
  EXPECT_NEAR(line_cos(top.d1, {0, 1, 0}), 1, 1e-12);
  EXPECT_NEAR(line_cos(top.d2, {1, 0, 0}), 1, 1e-12);
}

TEST(Shapes3d, TorusCurvaturesAndDirectionsMatchTheClosedForms) {
  // Torus R = 6, r = 2 at angles (u, v): one curvature 1/r along the meridian, the other
  // cos v / (R + r cos v) along the parallel; as 1/r > cos v / (R + r cos v), k2 = 1/r.
  auto s = shape3("torus");
  const double R = 6, r = 2;
  for (int i = 0; i < 24; ++i) {
    for (int j = 0; j < 24; ++j) {
      const double uu = 0.26 * i + 0.1, v = 0.26 * j + 0.05;
      const double rr = r * 1.1; // off the surface, along the normal
      P3 p{(R + rr * std::cos(v)) * std::cos(uu), (R + rr * std::cos(v)) * std::sin(uu),
           rr * std::sin(v)};
      auto q = s->project(p);
      const double kpar = std::cos(v) / (R + r * std::cos(v));
      EXPECT_NEAR(q.k1, kpar, 1e-9) << uu << " " << v;
      EXPECT_NEAR(q.k2, 1 / r, 1e-9);
      EXPECT_NEAR(q.gaussian, kpar / r, 1e-9);
      EXPECT_NEAR(line_cos(q.d1, {-std::sin(uu), std::cos(uu), 0}), 1, 1e-9);
      EXPECT_NEAR(
          line_cos(q.d2, {-std::sin(v) * std::cos(uu), -std::sin(v) * std::sin(uu), std::cos(v)}),
          1, 1e-9);
      EXPECT_NEAR(q.point.x, (R + r * std::cos(v)) * std::cos(uu), 1e-9);
      expect_consistent(q);
    }
  }
  EXPECT_NEAR(*s->volume(), 2 * std::numbers::pi * std::numbers::pi * R * r * r, 1e-9);
}

TEST(Shapes3d, DigitizationIsExactOnTheSurface) {
  // F = 0 at h z - t counts as inside; a translation of 2^-60 decides it either way, far
  // below what the double filter sees: the exact fallback answers.
  auto s = shape3("sphere9");
  const double eps = std::ldexp(1.0, -60);
  EXPECT_TRUE(s->digitize(1.0, {0, 0, 0})({9, 0, 0}));
  EXPECT_TRUE(s->digitize(1.0, {eps, 0, 0})({9, 0, 0}));   // 9 - 2^-60
  EXPECT_FALSE(s->digitize(1.0, {-eps, 0, 0})({9, 0, 0})); // 9 + 2^-60
  EXPECT_FALSE(s->digitize(0.5, {0, 0, -eps})({0, 0, 18}));
  // Against the exact sign on random voxels and dyadic steps (oracle: Polynomial::sign_exact).
  auto f = zdg::Polynomial::parse(*zdg::named_polynomial_3d("goursat"), 3);
  auto g = shape3("goursat");
  std::mt19937_64 rng(3);
  std::uniform_int_distribution<int> zi(-40, 40);
  for (int i = 0; i < 300; ++i) {
    const double h = 0.25, t[3] = {0.0625 * (i % 3), -0.03125 * (i % 5), 0.125};
    auto pred = g->digitize(h, {t[0], t[1], t[2]});
    zdg::Voxel z{zi(rng), zi(rng), zi(rng)};
    zdg::BigRational q[3] = {zdg::exact_rational(h * double(z.x) - t[0]),
                             zdg::exact_rational(h * double(z.y) - t[1]),
                             zdg::exact_rational(h * double(z.z) - t[2])};
    EXPECT_EQ(pred(z), f.sign_exact(q) <= 0) << z;
  }
}

TEST(Shapes3d, NamedShapesParseAndHaveTheirBoxes) {
  for (const auto& name : zdg::named_shapes_3d()) {
    auto s = shape3(name);
    EXPECT_EQ(s->spec(), name);
    EXPECT_EQ(s->dimension(), 3);
    auto box = s->bounding_box();
    ASSERT_TRUE(box.has_value());
    EXPECT_EQ(box->size(), 3u);
  }
  EXPECT_EQ(zdg::named_shapes_3d().size(), 13u);
  EXPECT_EQ((*shape3("sphere1")->bounding_box())[0], std::make_pair(-1.25, 1.25));
  EXPECT_EQ((*shape3("goursat")->bounding_box())[2], std::make_pair(-10.0, 10.0));
  // The bounded ones are inside at the origin and outside at the corner of their box.
  for (const char* name :
       {"sphere9", "ellipsoid", "rcube", "goursat", "leopold", "heart", "crixxi", "distel"}) {
    auto s = shape3(name);
    EXPECT_TRUE(s->contains({0.01, 0.02, 0.03})) << name;
    const double hi = (*s->bounding_box())[0].second;
    EXPECT_FALSE(s->contains({hi, hi, hi})) << name;
  }
}

TEST(Shapes3d, GaussVolumeApproachesTheClosedFormVolumes) {
  for (const char* name : {"sphere9", "ellipsoid", "torus", "rcube"}) {
    auto s = shape3(name);
    const double h = 0.25;
    zdg::VoxelBox box{{-42, -42, -42}, {42, 42, 42}};
    auto v = zdg::gauss_volume(s->digitize(h, {0.01, 0.02, 0.03}), box, h, 1);
    EXPECT_NEAR(v.volume, *s->volume(), 5e-3 * *s->volume()) << name;
  }
  EXPECT_FALSE(shape3("goursat")->volume().has_value());
}

TEST(Shapes3d, PolyAndErrors) {
  auto p = shape3("poly:x^2+y^2+z^2-4");
  EXPECT_NEAR(p->project({3, 0, 0}).mean, 0.5, 1e-12);
  EXPECT_EQ((*p->bounding_box())[0], std::make_pair(-10.0, 10.0));
  EXPECT_EQ(zdg::parse_shape("poly:x^2+y^2-4")->dimension(), 2); // no z: the 2D shape
  EXPECT_THROW(zdg::parse_shape("sphere9:3"), zdg::InvalidArgument);
  EXPECT_THROW(zdg::parse_shape("poly:z-z+1"), zdg::InvalidArgument); // constant
  EXPECT_THROW(zdg::parse_shape("poly:x^2+q*z"), zdg::InvalidArgument);
  // The gradient vanishes at the apex of the diabolo: loud, not a NaN.
  auto f = zdg::Polynomial::parse("x^2-(y^2+z^2)^2", 3);
  EXPECT_THROW(zdg::implicit_surface_geometry(f, {0, 0, 0}), zdg::InvalidArgument);
  EXPECT_FALSE(zdg::named_polynomial_3d("nope").has_value());
}

} // namespace

namespace {

// unprojected:SHAPE keeps the solid and its digitization, and takes the ground truth at the
// query point itself: on the sphere of radius 9 the level set through p is the sphere of
// radius |p|, so H = k1 = k2 = 1/|p| there (the projection gives 1/9).
TEST(Shapes3d, UnprojectedTruthIsTheLevelSetAtThePoint) {
  const auto u = shape3("unprojected:sphere9");
  const auto s = shape3("sphere9");
  EXPECT_EQ(u->spec(), "unprojected:sphere9");
  EXPECT_EQ(zdg::parse_shape(u->spec())->spec(), u->spec());
  std::mt19937_64 rng(19);
  std::uniform_real_distribution<double> d(-9.5, 9.5);
  for (int i = 0; i < 50; ++i) {
    const P3 p{d(rng), d(rng), d(rng)};
    if (norm(p) < 1) continue;
    const auto t = u->project(p);
    EXPECT_NEAR(t.mean, 1 / norm(p), 1e-12);
    EXPECT_NEAR(t.k1, 1 / norm(p), 1e-6);
    EXPECT_NEAR(t.k2, 1 / norm(p), 1e-6);
    EXPECT_NEAR(s->project(p).mean, 1.0 / 9.0, 1e-12);
    EXPECT_EQ(u->contains(p), s->contains(p));
  }
  const auto du = u->digitize(0.3, {0.1, 0.2, 0.3}), ds = s->digitize(0.3, {0.1, 0.2, 0.3});
  for (std::int64_t z = -35; z <= 35; z += 5)
    for (std::int64_t y = -35; y <= 35; y += 3)
      for (std::int64_t x = -35; x <= 35; ++x) EXPECT_EQ(du({x, y, z}), ds({x, y, z}));
  EXPECT_EQ(shape3("unprojected:poly:x^2+y^2+z^2-4")->spec(), "unprojected:poly:x^2+y^2+z^2-4");
  EXPECT_THROW(zdg::parse_shape("unprojected:ellipse:20,7"), zdg::InvalidArgument);
  EXPECT_THROW(zdg::parse_shape("unprojected:nosuch"), zdg::InvalidArgument);
}

} // namespace
