#include "convergence/shapes_2d.hpp"

#include "arith/error.hpp"
#include "kernel/digital_contour.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace {

using zdg::Point2;
using zdg::Shape2;

std::unique_ptr<Shape2> shape2(const char* spec) {
  auto s = zdg::parse_shape(spec);
  auto* p = dynamic_cast<Shape2*>(s.get());
  EXPECT_NE(p, nullptr);
  s.release();
  return std::unique_ptr<Shape2>(p);
}

TEST(Shapes2d, EllipsePerimeterSeriesAndQuadratureMatchThePublishedValue) {
  // THEORY.md: a = 20, b = 7 gives 89.8147914563.
  EXPECT_NEAR(zdg::ellipse_perimeter(20, 7), 89.8147914563, 1e-9);
  auto e = shape2("ellipse:20,7");
  EXPECT_NEAR(*e->perimeter(), 89.8147914563, 1e-9);
  EXPECT_NEAR(zdg::quadrature_perimeter(*e, 1 << 14), 89.8147914563, 1e-9);
  EXPECT_NEAR(zdg::ellipse_perimeter(5, 5), 10 * std::numbers::pi, 1e-12);
}

TEST(Shapes2d, CircleProjectionTangentAndCurvature) {
  auto b = shape2("ball:5/2");
  for (int i = 0; i < 50; ++i) {
    double a = 0.37 * i, r = 2.5 + 0.3 * std::sin(3.0 * i);
    auto q = b->project({r * std::cos(a), r * std::sin(a)});
    EXPECT_NEAR(std::hypot(q.point.x, q.point.y), 2.5, 1e-12);
    EXPECT_NEAR(q.curvature, 0.4, 1e-10);
    // Counter-clockwise tangent: perpendicular to the radius, turning left.
    EXPECT_NEAR(q.tangent.x * q.point.x + q.tangent.y * q.point.y, 0.0, 1e-10);
    EXPECT_GT(q.point.x * q.tangent.y - q.point.y * q.tangent.x, 0.0);
  }
  EXPECT_NEAR(*b->area(), std::numbers::pi * 6.25, 1e-9);
}

TEST(Shapes2d, EllipseCurvatureClosedForm) {
  // kappa(s) = a b / (a^2 sin^2 s + b^2 cos^2 s)^{3/2} at (a cos s, b sin s).
  auto e = shape2("ellipse:20,7");
  for (int i = 0; i < 40; ++i) {
    double s = -3.1 + 0.155 * i;
    Point2<double> p{20 * std::cos(s), 7 * std::sin(s)};
    auto q = e->project({p.x * 1.01, p.y * 1.01});
    double t = std::atan2(q.point.y / 7, q.point.x / 20);
    double expected =
        140 / std::pow(400 * std::sin(t) * std::sin(t) + 49 * std::cos(t) * std::cos(t), 1.5);
    EXPECT_NEAR(q.curvature, expected, 1e-9 * expected);
    EXPECT_NEAR(q.point.x * q.point.x / 400 + q.point.y * q.point.y / 49, 1.0, 1e-12);
  }
}

TEST(Shapes2d, StarCurvatureFormulaAndFlowerArea) {
  // Flower: area pi (r0^2 + a^2/2) closed form = Green quadrature.
  auto f = shape2("flower:20,7,6");
  EXPECT_NEAR(*f->area(), std::numbers::pi * (400 + 24.5), 1e-9);
  EXPECT_NEAR((*f->moments())[0], *f->area(), 1e-7);
  // Curvature at the tip t = 0: r = 27, r' = 0, r'' = -252: (r^2 - r r'') / r^3.
  auto q = f->project({28, 0});
  EXPECT_NEAR(q.point.x, 27, 1e-10);
  EXPECT_NEAR(q.curvature, (27.0 * 27 + 27.0 * 252) / (27.0 * 27 * 27), 1e-9);
}

TEST(Shapes2d, PolygonGroundTruthAndMoments) {
  auto p = shape2("polygon:0,0,4,0,4,2,0,2");
  EXPECT_DOUBLE_EQ(*p->area(), 8);
  EXPECT_DOUBLE_EQ(*p->perimeter(), 12);
  auto m = *p->moments();
  EXPECT_DOUBLE_EQ(m[1], 16);           // integral of x = 8 * 2
  EXPECT_DOUBLE_EQ(m[3], 64.0 / 3 * 2); // integral of x^2 = (4^3/3) * 2
  EXPECT_DOUBLE_EQ(m[4], 8 * 2);        // (4^2/2)(2^2/2)
  auto q = p->project({2, -0.3});
  EXPECT_DOUBLE_EQ(q.point.y, 0);
  EXPECT_DOUBLE_EQ(q.tangent.x, 1);
  // Clockwise input is reoriented.
  auto cw = shape2("polygon:0,0,0,2,4,2,4,0");
  EXPECT_DOUBLE_EQ(*cw->area(), 8);
}

TEST(Shapes2d, PolyShapeProjectionAndCurvature) {
  auto s = shape2("poly:x^2 + y^2 - 100");
  auto q = s->project({3, 9});
  EXPECT_NEAR(std::hypot(q.point.x, q.point.y), 10, 1e-12);
  EXPECT_NEAR(q.curvature, 0.1, 1e-12);
  EXPECT_FALSE(s->area().has_value());
}

TEST(Shapes2d, DigitizationDecidesBoundaryPointsExactly) {
  // h = 1/2 is exact: z = (6, 8) maps to (3, 4), on the circle of radius 5: inside.
  auto s = shape2("poly:x^2 + y^2 - 25");
  auto d = s->digitize(0.5, {0, 0}, zdg::Box2{{-20, -20}, {20, 20}});
  EXPECT_TRUE(d->contains({6, 8}));
  EXPECT_TRUE(d->contains({10, 0}));
  EXPECT_FALSE(d->contains({6, 9}));
  EXPECT_FALSE(d->contains({11, 0}));
  // The same through the batch path of the quadratic.
  std::vector<zdg::Pixel> pts{{6, 8}, {10, 0}, {6, 9}, {-8, -6}};
  EXPECT_EQ(d->count(pts), 3);
  auto ball = shape2("ball:5");
  auto db = ball->digitize(0.5, {0, 0}, zdg::Box2{{-20, -20}, {20, 20}});
  EXPECT_EQ(db->count(pts), 3);
}

TEST(Shapes2d, ParseErrorsNameTheProblem) {
  auto message = [](const char* spec) {
    try {
      zdg::parse_shape(spec);
    } catch (const zdg::InvalidArgument& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_NE(message("ellipse:20").find("ellipse:A,B"), std::string::npos);
  EXPECT_NE(message("circle:3").find("unknown shape 'circle'"), std::string::npos);
  EXPECT_NE(message("ball:-1").find("must be > 0"), std::string::npos);
  EXPECT_NE(message("ball:abc").find("'abc' is not a number"), std::string::npos);
  EXPECT_NE(message("polygon:0,0,1,1,2,2").find("degenerate"), std::string::npos);
  EXPECT_NE(message("polygon:0,0,2,0,1,1,2,2,0,2").find("convex"), std::string::npos);
  EXPECT_NE(message("flower:20,7,1/2").find("integer"), std::string::npos);
  EXPECT_NE(message("poly:x^2+").find("position"), std::string::npos);
  EXPECT_EQ(message("ellipse:20,7,1/3"), "no error");
}

TEST(Shapes2d, TranslationsAreSeededAndSubPixel) {
  auto a = zdg::random_translation(7, 3, 2, 0.1), b = zdg::random_translation(7, 3, 2, 0.1);
  EXPECT_EQ(a, b);
  EXPECT_NE(a, zdg::random_translation(7, 4, 2, 0.1));
  for (int i = 0; i < 100; ++i) {
    for (double v : zdg::random_translation(1, i, 3, 0.1)) {
      EXPECT_LE(std::abs(v), 0.1);
    }
  }
}

} // namespace
