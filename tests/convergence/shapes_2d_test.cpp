#include <zdg/convergence/shapes_2d.hpp>

#include <zdg/arith/error.hpp>
#include <zdg/kernel/curves/digital_contour.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <functional>
#include <numbers>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

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
  // papers/THEORY.md: a = 20, b = 7 gives 89.8147914563.
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

TEST(Shapes2d, StarSectorFilterAgreesWithThePolarTest) {
  // The digitization of the flowers (sector bounds, then the polar test) answers as the
  // plain test |p| <= r(atan2(p)) away from ties.
  for (const char* spec : {"flower:20,7,6", "flower:5,2,3,1/2", "accflower:20,5,5"}) {
    auto s = shape2(spec);
    const double h = 0.0137;
    auto d = s->digitize(h, {0.001, -0.002}, zdg::Box2{{-3000, -3000}, {3000, 3000}});
    std::uint64_t state = 12345;
    int disagreements = 0;
    for (int i = 0; i < 200000; ++i) {
      state = state * 6364136223846793005ULL + 1442695040888963407ULL;
      auto x = static_cast<std::int64_t>((state >> 33) % 4001) - 2000;
      auto y = static_cast<std::int64_t>((state >> 13) % 4001) - 2000;
      Point2<double> p{h * static_cast<double>(x) - 0.001, h * static_cast<double>(y) + 0.002};
      disagreements += d->contains({x, y}) != s->contains(p) ? 1 : 0;
    }
    EXPECT_EQ(disagreements, 0) << spec;
  }
}

// The linel midpoints and pointels of the outer contour of G_h(X + t), back in the frame
// of X, in contour order (what the estimators project).
std::vector<Point2<double>> contour_chain(const Shape2& s, double h, Point2<double> t) {
  auto bb = *s.bounding_box();
  auto n = static_cast<std::int64_t>(std::ceil((bb[0].second + 2 * h) / h));
  auto set = s.digitize(h, t, zdg::Box2{{-n, -n}, {n, n}});
  auto contour = zdg::digital_contours(*set, {0}, {}).at(0);
  zdg::ContourEmbedding e{h};
  std::vector<Point2<double>> pts;
  zdg::Pixel p = contour.start;
  for (auto c : contour.codes) {
    auto m = e.linel_midpoint(p, c), q = e.pointel(p);
    pts.push_back({q.x - t.x, q.y - t.y});
    pts.push_back({m.x - t.x, m.y - t.y});
    auto d = zdg::freeman_step(c);
    p = {p.x + d.x, p.y + d.y};
  }
  return pts;
}

// n points walking along the boundary from near `from` by steps of h along the tangent,
// each pushed off the boundary by up to h along the normal (deterministic jitter).
std::vector<Point2<double>> walk_chain(const Shape2& s, Point2<double> from, double h, int n) {
  std::vector<Point2<double>> pts;
  auto q = s.project(from);
  for (int i = 0; i < n; ++i) {
    double off = h * std::sin(1.7 * i + 0.3);
    pts.push_back({q.point.x - off * q.tangent.y, q.point.y + off * q.tangent.x});
    q = s.project({q.point.x + h * q.tangent.x, q.point.y + h * q.tangent.y});
  }
  return pts;
}

// project_chain answers as project, point by point: position to 1e-12, curvature to 1e-9
// (relative to max(1, |kappa|)). Returns how many points were compared.
std::size_t expect_chain_matches_project(const Shape2& s, const std::vector<Point2<double>>& pts,
                                         const std::string& what) {
  auto chain = s.project_chain(pts);
  EXPECT_EQ(chain.size(), pts.size()) << what;
  int failures = 0;
  for (std::size_t i = 0; i < pts.size() && i < chain.size() && failures < 5; ++i) {
    auto q = s.project(pts[i]);
    const auto& c = chain[i];
    double dp = std::hypot(q.point.x - c.point.x, q.point.y - c.point.y);
    double dk = std::abs(q.curvature - c.curvature) / std::max(1.0, std::abs(q.curvature));
    double dt = std::hypot(q.tangent.x - c.tangent.x, q.tangent.y - c.tangent.y);
    if (dp > 1e-12 || dk > 1e-9 || dt > 1e-10) {
      ++failures;
      ADD_FAILURE() << what << " point " << i << " (" << pts[i].x << ", " << pts[i].y
                    << "): position differs by " << dp << ", curvature by " << dk << ", tangent by "
                    << dt << " resid project "
                    << ((pts[i].x - q.point.x) * q.tangent.x + (pts[i].y - q.point.y) * q.tangent.y)
                    << " chain "
                    << ((pts[i].x - c.point.x) * c.tangent.x + (pts[i].y - c.point.y) * c.tangent.y)
                    << " d " << std::hypot(pts[i].x - q.point.x, pts[i].y - q.point.y) << " "
                    << std::hypot(pts[i].x - c.point.x, pts[i].y - c.point.y);
    }
  }
  return pts.size();
}

const char* const kParametric[] = {"ball:5/2",
                                   "ellipse:20,7",
                                   "ellipse:20,7,1/3",
                                   "ellipse:3,8,2",
                                   "flower:20,7,6",
                                   "flower:5,2,3,1/2",
                                   "accflower:20,5,1.0132118364233778",
                                   "accflower:20,5,5"};

TEST(Shapes2d, ProjectChainAgreesWithProjectOnDigitalContours) {
  // Coarse h puts contour points beyond reach/2 (the robust fallback), fine h certifies.
  for (const char* spec : kParametric) {
    auto s = shape2(spec);
    for (double h : {1.0, 0.37, 0.1, 0.047}) {
      expect_chain_matches_project(*s, contour_chain(*s, h, {0.17 * h, -0.29 * h}),
                                   std::string(spec) + " h=" + std::to_string(h));
    }
  }
}

TEST(Shapes2d, ProjectChainAgreesWithProjectOnFineChains) {
  // Fine steps, including across the seam t = +-pi of the parametrization.
  for (const char* spec : kParametric) {
    auto s = shape2(spec);
    for (double h : {1e-2, 1.7e-4}) {
      expect_chain_matches_project(*s, walk_chain(*s, {-30, 0.5}, h, 1500),
                                   std::string(spec) + " h=" + std::to_string(h));
    }
  }
}

TEST(Shapes2d, ProjectChainFallsBackFarFromTheBoundary) {
  // Points deep inside (distance > reach/2) and jumps between them go through project.
  for (const char* spec : {"flower:20,7,6", "ellipse:20,7", "ball:5/2"}) {
    auto s = shape2(spec);
    std::vector<Point2<double>> pts;
    for (int i = 0; i < 200; ++i) {
      double a = 0.05 * i, r = 1 + 0.5 * std::sin(0.3 * i);
      pts.push_back({r * std::cos(a), r * std::sin(a)});
    }
    pts.push_back({0, 0.5});
    pts.push_back({40, -3});
    pts.push_back({40, -3});
    expect_chain_matches_project(*s, pts, spec);
  }
  // Default implementation (no warm start) for shapes with corners or no parametrization.
  for (const char* spec : {"polygon:0,0,4,0,4,2,0,2", "poly:x^4 + y^4 - 16"}) {
    auto s = shape2(spec);
    std::vector<Point2<double>> pts;
    for (int i = 0; i < 50; ++i)
      pts.push_back({2.5 * std::cos(0.13 * i), 2.5 * std::sin(0.13 * i)});
    expect_chain_matches_project(*s, pts, spec);
  }
  EXPECT_TRUE(shape2("flower:20,7,6")->project_chain({}).empty());
}

// Radius of curvature of the star r(t) (cos t, sin t):
// kappa = (r^2 + 2 r'^2 - r r'') / (r^2 + r'^2)^{3/2}; minimum of 1/|kappa| over n samples.
double min_star_curvature_radius(const std::function<std::array<double, 3>(double)>& radius,
                                 int n) {
  double best = std::numeric_limits<double>::infinity();
  for (int i = 0; i < n; ++i) {
    double t = -std::numbers::pi + 2 * std::numbers::pi * (i + 0.5) / n;
    auto [r, d1, d2] = radius(t);
    double k = (r * r + 2 * d1 * d1 - r * d2) / std::pow(r * r + d1 * d1, 1.5);
    best = std::min(best, 1 / std::abs(k));
  }
  return best;
}

// Federer's function |y - x|^2 / (2 |(y - x).n_x|) on pairs of n boundary points obtained by
// projecting points of a circle of radius rho (an independent sampling): every value is
// >= the reach, hence >= any lower bound of it.
double federer_sampled(const Shape2& s, double rho, int n) {
  std::vector<zdg::BoundaryPoint2> b;
  for (int i = 0; i < n; ++i) {
    double a = 2 * std::numbers::pi * (i + 0.25) / n;
    b.push_back(s.project({rho * std::cos(a), rho * std::sin(a)}));
  }
  double best = std::numeric_limits<double>::infinity();
  for (const auto& x : b) {
    for (const auto& y : b) {
      double dx = y.point.x - x.point.x, dy = y.point.y - x.point.y;
      double dn = std::abs(-dx * x.tangent.y + dy * x.tangent.x);
      if (dn > 0) best = std::min(best, (dx * dx + dy * dy) / (2 * dn));
    }
  }
  return best;
}

TEST(Shapes2d, ReachOfBallAndEllipseClosedForms) {
  EXPECT_DOUBLE_EQ(*shape2("ball:3")->reach_lower_bound(), 3);
  // Minimal radius of curvature b^2/a at the vertices (a, 0): 49/20.
  EXPECT_DOUBLE_EQ(*shape2("ellipse:20,7")->reach_lower_bound(), 2.45);
  EXPECT_DOUBLE_EQ(*shape2("ellipse:7,20,1/3")->reach_lower_bound(), 2.45);
  auto e = shape2("ellipse:20,7");
  EXPECT_NEAR(1 / e->project({25, 0}).curvature, 2.45, 1e-12);
  EXPECT_LE(2.45, federer_sampled(*e, 15, 600));
  EXPECT_DOUBLE_EQ(*shape2("polygon:0,0,4,0,4,2,0,2")->reach_lower_bound(), 0);
  EXPECT_FALSE(shape2("poly:x^2 + y^2 - 4")->reach_lower_bound().has_value());
}

TEST(Shapes2d, ReachOfFlowersIsBelowTheirMinimalRadiusOfCurvature) {
  // flower:20,7,6: r = 20 + 7 cos 6t.
  auto f = shape2("flower:20,7,6");
  double rc = min_star_curvature_radius(
      [](double t) {
        return std::array<double, 3>{20 + 7 * std::cos(6 * t), -42 * std::sin(6 * t),
                                     -252 * std::cos(6 * t)};
      },
      1 << 20);
  double bound = *f->reach_lower_bound();
  EXPECT_LE(bound, rc);
  EXPECT_GE(bound, rc / 2.5);
  EXPECT_LE(bound, federer_sampled(*f, 20, 700));
  // flower:10,3,2: the narrowest bottleneck (the waist, half-width 7) and the tips compete.
  auto g = shape2("flower:10,3,2");
  EXPECT_LE(*g->reach_lower_bound(), 7.0);
  EXPECT_LE(*g->reach_lower_bound(), federer_sampled(*g, 10, 700));
  EXPECT_GT(*g->reach_lower_bound(), 0.0);
  // DGtal's AccFlower2D(20, 5, 5 petals): P = 10/pi^2, C^2 at t = +-pi. Radius of
  // curvature at the tip t = +-pi (r = 25, r' = 0, r'' = -5 (3 P pi^2)^2 = -4500):
  // r^3 / (r^2 - r r'') = 0.138; the sharpest points are the concave valleys next to it
  // (r = 15, r'' ~ 5 * 29^2), about 0.0578.
  const double p = 1.0132118364233778;
  auto a = shape2("accflower:20,5,1.0132118364233778");
  double rca = min_star_curvature_radius(
      [p](double t) {
        double u = p * t * t * t, du = 3 * p * t * t, ddu = 6 * p * t;
        return std::array<double, 3>{20 + 5 * std::cos(u), -5 * std::sin(u) * du,
                                     -5 * (std::cos(u) * du * du + std::sin(u) * ddu)};
      },
      1 << 21);
  EXPECT_NEAR(rca, 0.0578, 0.0005);
  EXPECT_NEAR(1 / a->project({-26, 0}).curvature, 15625.0 / 113125, 1e-6);
  double ba = *a->reach_lower_bound();
  EXPECT_GT(ba, 0.0);
  EXPECT_LE(ba, rca);
  EXPECT_GE(ba, rca / 2.5);
  // P = 5: r' jumps at t = +-pi, a corner: reach 0.
  EXPECT_EQ(*shape2("accflower:20,5,5")->reach_lower_bound(), 0.0);
  EXPECT_EQ(*shape2("accflower:20,5,1.0132")->reach_lower_bound(), 0.0);
  EXPECT_EQ(*shape2("accflower:20,5,1.0132118374")->reach_lower_bound(), 0.0);
  // P = 2K/pi^2 for other K, and odd m / pi^2: smooth, positive.
  EXPECT_GT(*shape2("accflower:20,5,0.20264236728467555")->reach_lower_bound(), 0.0);
  EXPECT_GT(*shape2("accflower:20,5,0.5066059182116889")->reach_lower_bound(), 0.0);
  std::printf("reach lower bounds: flower:20,7,6 %.6g (min radius of curvature %.6g), "
              "accflower:20,5,10/pi^2 %.6g (%.6g)\n",
              bound, rc, ba, rca);
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

// Issue #18 item 10: parameters are finite and in range (a radius that rounds to 0, an angle
// that overflows the double range, absurd petal counts), refused with one short line.
TEST(Shapes2d, NonFiniteAndOutOfRangeParametersAreRefused) {
  auto message = [](const std::string& spec) {
    try {
      zdg::parse_shape(spec);
    } catch (const zdg::InvalidArgument& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  // 10^400 (infinite as a double) and 10^-401 (0 as a double), written out.
  std::ostringstream huge_text, tiny_text;
  huge_text << '1' << std::string(400, '0');
  tiny_text << "0." << std::string(400, '0') << '1';
  const std::string huge = huge_text.str(), tiny = tiny_text.str();
  std::vector<std::string> specs;
  for (const char* prefix :
       {"flower:20,7,6,", "ball:", "ellipse:20,7,", "accflower:20,5,", "ball:1/"}) {
    specs.push_back(prefix);
    specs.back().append(huge);
  }
  for (const char* prefix : {"ball:", "ellipse:20,"}) {
    specs.push_back(prefix);
    specs.back().append(tiny);
  }
  specs.push_back("polygon:0,0,");
  specs.back().append(huge).append(",0,0,1");
  specs.push_back("ball:2000000000");
  for (const auto& spec : specs) {
    const auto m = message(spec);
    EXPECT_NE(m.find("out of range"), std::string::npos) << spec << ": " << m;
    EXPECT_LT(m.size(), 200u) << m;
  }
  EXPECT_NE(message("flower:20,7,100000").find("-1000..1000"), std::string::npos);
  EXPECT_EQ(message("flower:20,7,6,0"), "no error");
  EXPECT_EQ(message("ball:1/1000000"), "no error");
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
