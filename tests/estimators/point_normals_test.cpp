// Normals of point clouds (estimators/point_normals.hpp). Oracles: the normal of an exact plane
// (PCA of points on it is that normal up to sign, to rounding); the exact outward normal of a
// sphere and of a torus (every MST-oriented normal has a positive dot with it); the same run
// on one thread (the result does not depend on the thread count); the errors of the contract.
#include <zdg/arith/error.hpp>
#include <zdg/estimators/point_normals.hpp>

#include "tests/support/tower.hpp"

#include <gtest/gtest.h>
#include <rapidcheck.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>
#include <string>

namespace zdg {
namespace {

using P = Point3<double>;

P unit(const P& v) {
  return (1 / std::sqrt(dot(v, v))) * v;
}

// A random unit vector from RapidCheck (z and the longitude: uniform on the sphere; no
// rejection loop, which RapidCheck's small sizes could keep failing).
P random_direction() {
  const double z = *rc::gen::inRange(-100000, 100001) / 100000.0;
  const double t = *rc::gen::inRange(0, 100000) / 100000.0 * 2 * std::numbers::pi;
  const double r = std::sqrt(std::max(0.0, 1 - z * z));
  return {r * std::cos(t), r * std::sin(t), z};
}

// A rotation of R^3 taking e_z to a random direction (its frame as columns).
struct Frame {
  P a, b, n;
  P apply(const P& p) const { return p.x * a + p.y * b + p.z * n; }
};

Frame random_frame() {
  const P n = random_direction();
  const P t = std::abs(n.x) < 0.9 ? P{1, 0, 0} : P{0, 1, 0};
  const P a = unit(cross(n, t));
  return {a, cross(n, a), n};
}

// Oracle: the plane's normal. Random plane (a random frame and offset), random points on it in
// a square: every PCA normal is +-n to 1e-9.
TEST(PointNormals, PcaOfAnExactPlaneIsThePlaneNormal) {
  test::check_property([] {
    const Frame f = random_frame();
    const P o{*rc::gen::inRange(-100, 101) / 10.0, *rc::gen::inRange(-100, 101) / 10.0,
              *rc::gen::inRange(-100, 101) / 10.0};
    const std::size_t k = *rc::gen::inRange<std::size_t>(3, 16);
    std::mt19937_64 rng(*rc::gen::arbitrary<std::uint32_t>());
    std::uniform_real_distribution<double> u(-1, 1);
    PointCloud c;
    for (int i = 0; i < 80; ++i) c.points.push_back(o + f.apply({u(rng), u(rng), 0}));
    PointNormalsOptions opt;
    opt.k = k;
    opt.orientation = PointNormalOrientation::none;
    opt.threads = 2;
    const PointNormals r = point_normals(c, opt);
    RC_ASSERT(r.normals.size() == c.size());
    RC_ASSERT(!r.oriented);
    for (const P& n : r.normals) {
      const P d1 = n - f.n, d2 = n + f.n;
      RC_ASSERT(std::min(std::sqrt(dot(d1, d1)), std::sqrt(dot(d2, d2))) <= 1e-9);
    }
  });
}

TEST(PointNormals, PcaNormalOfThreePoints) {
  const std::vector<P> t{{0, 0, 5}, {1, 0, 5}, {0, 2, 5}};
  const P n = pca_normal(t);
  EXPECT_NEAR(std::abs(n.z), 1.0, 1e-15);
  EXPECT_NEAR(n.x, 0.0, 1e-15);
  EXPECT_NEAR(n.y, 0.0, 1e-15);
}

// Points uniform on the area of a sphere of radius 1 and of a torus (R = 2, r = 0.7), in a
// random rotation, with their exact outward normals.
struct Sample {
  PointCloud cloud;
  std::vector<P> outward;
};

Sample sphere_sample(std::size_t n, std::uint64_t seed, const Frame& f) {
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> g;
  Sample s;
  while (s.cloud.size() < n) {
    const P v{g(rng), g(rng), g(rng)};
    if (dot(v, v) < 1e-6) continue;
    const P p = f.apply(unit(v));
    s.cloud.points.push_back(p);
    s.outward.push_back(p);
  }
  return s;
}

Sample torus_sample(std::size_t n, std::uint64_t seed, const Frame& f) {
  const double R = 2, r = 0.7, pi = std::numbers::pi;
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0, 1);
  Sample s;
  while (s.cloud.size() < n) {
    const double a = 2 * pi * u(rng), b = 2 * pi * u(rng);
    // The area element is proportional to R + r cos b: rejection keeps the sampling uniform.
    if (u(rng) * (R + r) > R + r * std::cos(b)) continue;
    const P nrm{std::cos(b) * std::cos(a), std::cos(b) * std::sin(a), std::sin(b)};
    const P p{(R + r * std::cos(b)) * std::cos(a), (R + r * std::cos(b)) * std::sin(a),
              r * std::sin(b)};
    s.cloud.points.push_back(f.apply(p));
    s.outward.push_back(f.apply(nrm));
  }
  return s;
}

void expect_outward(const Sample& s, const PointNormalsOptions& opt) {
  const PointNormals r = point_normals(s.cloud, opt);
  RC_ASSERT(r.oriented);
  RC_ASSERT(r.components == 1u);
  for (std::size_t i = 0; i < r.normals.size(); ++i) {
    RC_ASSERT(std::abs(dot(r.normals[i], r.normals[i]) - 1) < 1e-12);
    RC_ASSERT(dot(r.normals[i], s.outward[i]) > 0);
  }
}

// Oracle: the exact outward normal. Orientation is consistent on closed shapes: every oriented
// normal points out (the seed, the highest point, has the outward normal +z).
TEST(PointNormals, MstOrientationPointsOutOnASphere) {
  test::check_property([] {
    const Sample s = sphere_sample(1500, *rc::gen::arbitrary<std::uint32_t>(), random_frame());
    PointNormalsOptions opt;
    opt.method = *rc::gen::element(PointNormalMethod::pca, PointNormalMethod::jet);
    opt.k = *rc::gen::inRange<std::size_t>(8, 16);
    expect_outward(s, opt);
  });
}

TEST(PointNormals, MstOrientationPointsOutOnATorus) {
  test::check_property([] {
    const Sample s = torus_sample(4000, *rc::gen::arbitrary<std::uint32_t>(), random_frame());
    PointNormalsOptions opt;
    opt.k = *rc::gen::inRange<std::size_t>(8, 16);
    expect_outward(s, opt);
  });
}

// Two spheres far apart: two components of the graph, each seeded at its own top.
TEST(PointNormals, EachComponentHasItsSeed) {
  Sample a = sphere_sample(800, 1, {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}});
  const Sample b = sphere_sample(800, 2, {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}});
  for (std::size_t i = 0; i < b.cloud.size(); ++i) {
    a.cloud.points.push_back(b.cloud.points[i] + P{10, 0, -3});
    a.outward.push_back(b.outward[i]);
  }
  const PointNormals r = point_normals(a.cloud, PointNormalsOptions{});
  EXPECT_EQ(r.components, 2u);
  for (std::size_t i = 0; i < r.normals.size(); ++i) EXPECT_GT(dot(r.normals[i], a.outward[i]), 0);
}

// Oracle: the same run on one thread. Every method and orientation gives the same doubles.
TEST(PointNormals, IndependentOfTheThreadCount) {
  test::check_property([] {
    const Sample s = torus_sample(600, *rc::gen::arbitrary<std::uint32_t>(), random_frame());
    PointNormalsOptions opt;
    opt.method = *rc::gen::element(PointNormalMethod::pca, PointNormalMethod::jet);
    opt.orientation = *rc::gen::element(PointNormalOrientation::none, PointNormalOrientation::mst);
    opt.threads = 1;
    const PointNormals one = point_normals(s.cloud, opt);
    opt.threads = *rc::gen::inRange(2u, 9u);
    const PointNormals many = point_normals(s.cloud, opt);
    RC_ASSERT(one.normals == many.normals);
    RC_ASSERT(one.components == many.components);
  });
}

// orient_normals_mst on normals of any length: only their signs change.
TEST(PointNormals, OrientKeepsLengths) {
  const Sample s = sphere_sample(500, 3, {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}});
  std::vector<P> n;
  for (std::size_t i = 0; i < s.outward.size(); ++i)
    n.push_back((i % 2 ? -2.0 : 0.5) * s.outward[i]);
  const std::vector<P> given = n;
  const KdTree tree(s.cloud.points);
  EXPECT_EQ(orient_normals_mst(tree, 10, n), 1u);
  for (std::size_t i = 0; i < n.size(); ++i) {
    EXPECT_TRUE(n[i] == given[i] || n[i] == -given[i]);
    EXPECT_GT(dot(n[i], s.outward[i]), 0);
  }
}

std::string error_of(const PointCloud& c, const PointNormalsOptions& o) {
  try {
    (void)point_normals(c, o, "in.xyz");
  } catch (const InvalidArgument& e) {
    return e.what();
  }
  return "";
}

TEST(PointNormals, TooFewNeighboursAndBadCloudsAreOneLine) {
  PointCloud c;
  for (int i = 0; i < 5; ++i) c.points.push_back({double(i), double(i * i), 0});
  PointNormalsOptions o;
  EXPECT_EQ(error_of(c, o), "point normals: too few neighbours: k = 10 needs at least 11 points, "
                            "the cloud has 5");
  o.k = 4;
  EXPECT_EQ(error_of(c, o), "");
  o.k = 2;
  EXPECT_EQ(error_of(c, o), "point normals: k = 2 neighbours are too few (at least 3)");
  o.k = 4;
  o.method = PointNormalMethod::jet;
  EXPECT_EQ(error_of(c, o), "point normals: the jet needs k >= 5 neighbours (the 6 coefficients "
                            "of a quadric), got k = 4");
  EXPECT_EQ(error_of(PointCloud{}, o), "in.xyz: no points");
  c.points.push_back(c.points[1]);
  EXPECT_EQ(error_of(c, PointNormalsOptions{}).rfind("in.xyz: point 5 repeats point 1", 0), 0u);
  EXPECT_THROW((void)point_normal_method_from_name("vcm"), InvalidArgument);
  EXPECT_THROW((void)point_normal_orientation_from_name("bfs"), InvalidArgument);
}

} // namespace
} // namespace zdg
