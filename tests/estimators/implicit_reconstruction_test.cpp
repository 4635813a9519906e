#include <zdg/estimators/implicit_reconstruction.hpp>

#include "tests/support/tower.hpp"
#include <zdg/arith/error.hpp>

#include <gtest/gtest.h>
#include <rapidcheck.h>

#include <cmath>
#include <numbers>
#include <random>

namespace zdg {
namespace {

using P3 = Point3<double>;

P3 gaussian3(std::mt19937_64& rng) {
  std::normal_distribution<double> g;
  return {g(rng), g(rng), g(rng)};
}

// N points uniform on the sphere of radius r about c, with outward unit normals.
PointCloud sphere_points(std::size_t n, double r, std::uint64_t seed, P3 c = {0.1, -0.2, 0.3}) {
  std::mt19937_64 rng(seed);
  PointCloud cloud;
  while (cloud.size() < n) {
    P3 u = gaussian3(rng);
    const double l = std::sqrt(dot(u, u));
    if (l < 1e-9) continue;
    u = u * (1 / l);
    cloud.points.push_back(c + u * r);
    cloud.normals.push_back(u);
  }
  return cloud;
}

// N points uniform (by area) on the torus of radii (R, r) about the z axis.
PointCloud torus_points(std::size_t n, double big, double small, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0, 2 * std::numbers::pi), a(0, 1);
  PointCloud cloud;
  while (cloud.size() < n) {
    const double s = u(rng), t = u(rng);
    if (a(rng) > (big + small * std::cos(t)) / (big + small)) continue;
    const P3 nn{std::cos(t) * std::cos(s), std::cos(t) * std::sin(s), std::sin(t)};
    cloud.points.push_back(P3{big * std::cos(s), big * std::sin(s), 0} + nn * small);
    cloud.normals.push_back(nn);
  }
  return cloud;
}

double max_sphere_distance(const PolygonMesh& m, double r, P3 c = {0.1, -0.2, 0.3}) {
  double d = 0;
  for (const auto& v : m.vertices) d = std::max(d, std::fabs(std::sqrt(dot(v - c, v - c)) - r));
  return d;
}

// Worked example: on the planar lattice s Z^2 every interior point's Voronoi cell is the
// square of side s (Barill et al.'s areas are those cells on the tangent plane).
TEST(PointAreas, PlanarLatticeCellsAreSquares) {
  PointCloud c;
  const double s = 0.25;
  for (int i = -6; i <= 6; ++i)
    for (int j = -6; j <= 6; ++j) {
      c.points.push_back({i * s, j * s, 1.0});
      c.normals.push_back({0, 0, 2});
    }
  const KdTree tree(c.points);
  const auto a = point_areas(c, tree, 12);
  for (std::size_t i = 0; i < c.size(); ++i) {
    const auto& p = c.points[i];
    if (std::fabs(p.x) <= 4 * s && std::fabs(p.y) <= 4 * s) {
      EXPECT_NEAR(a[i], s * s, 1e-12) << p;
    }
  }
}

// The areas of uniform samples of a sphere add up to its area (4 pi r^2) within 1 % with 20
// neighbours (with 10, missing Voronoi neighbours inflate the cells by about 9 %).
TEST(PointAreas, SphereAreasSumToTheSphereArea) {
  const auto c = sphere_points(4000, 2.0, 7);
  const KdTree tree(c.points);
  const auto a = point_areas(c, tree, 20);
  double sum = 0;
  for (double x : a) sum += x;
  EXPECT_NEAR(sum / (16 * std::numbers::pi), 1.0, 0.01);
}

// Theorem (Barill et al. 2018, section 3): the winding number of a closed surface is 1 inside
// and 0 outside; the points' quadrature approaches it. Oracle: the brute-force sum.
TEST(WindingNumber, NearOneInsideAndZeroOutsideOfASphere) {
  const auto c = sphere_points(3000, 1.0, 11);
  const KdTree tree(c.points);
  const auto a = point_areas(c, tree, 20);
  const WindingTree wt(c, a);
  std::mt19937_64 rng(3);
  for (int t = 0; t < 200; ++t) {
    P3 u = gaussian3(rng);
    u = u * (1 / std::sqrt(dot(u, u)));
    const double rad = t % 2 == 0 ? 0.6 * (t % 7) / 7.0 : 1.4 + (t % 5);
    const P3 q = P3{0.1, -0.2, 0.3} + u * rad;
    const double exact = winding_number_exact(c, a, q);
    EXPECT_NEAR(exact, rad < 1 ? 1.0 : 0.0, 0.03) << q;
    EXPECT_NEAR(wt(q, 2.0), exact, 0.01) << q;
  }
}

// The tree with every node opened (beta huge) is the exact sum up to rounding; the expansion's
// error falls as (1 / beta)^3: below 3e-2 at beta = 2 and 3e-3 at beta = 4 on sparse random
// clouds (20 to 400 points, where one cluster weighs most); the sphere test above holds the
// dense case to 1e-2 at beta = 2 (the first-order expansion was off by 0.09 there).
TEST(WindingNumber, TreeConvergesToTheBruteForceSum) {
  test::check_property([] {
    const auto n = *rc::gen::inRange<std::size_t>(20, 400);
    const auto c = sphere_points(n, 1.0, *rc::gen::arbitrary<std::uint32_t>());
    const KdTree tree(c.points);
    const auto a = point_areas(c, tree, 8);
    const WindingTree wt(c, a);
    for (int t = 0; t < 10; ++t) {
      const P3 q{*rc::gen::inRange(-30, 31) / 10.0, *rc::gen::inRange(-30, 31) / 10.0,
                 *rc::gen::inRange(-30, 31) / 10.0};
      const double exact = winding_number_exact(c, a, q);
      RC_ASSERT(std::fabs(wt(q, 1e9) - exact) <= 1e-9);
      RC_ASSERT(std::fabs(wt(q, 2.0) - exact) <= 3e-2);
      RC_ASSERT(std::fabs(wt(q, 4.0) - exact) <= 3e-3);
    }
  });
}

class Methods : public ::testing::TestWithParam<ReconstructionMethod> {};

// Reconstructions of sphere samples: the digitization of the negative set is one ball
// (Betti numbers of the solid 1, 0, 0) and the mesh's Hausdorff distance to the sphere is below a
// bound that falls as the sampling grows (here: 600 then 4000 points, h = 0.1 on r = 1).
TEST_P(Methods, SphereHasTheRightTopologyAndDistanceFallsWithN) {
  ReconstructionOptions o;
  o.method = GetParam();
  double previous = 1e9;
  for (std::size_t n : {600u, 4000u}) {
    const auto c = sphere_points(n, 1.0, 5 + n);
    const auto r = reconstruct(c, 0.1, o);
    EXPECT_EQ(r.betti.b[0], 1) << n;
    EXPECT_EQ(r.betti.b[1], 0) << n;
    EXPECT_EQ(r.betti.b[2], 0) << n;
    const double d = max_sphere_distance(r.mesh, 1.0);
    EXPECT_LT(d, 0.12) << n;
    EXPECT_LT(d, previous * 1.05) << n;
    previous = d;
  }
}

// A torus of radii (1, 0.4) sampled by 6000 points at h = 0.08: a solid torus, Betti numbers
// 1, 1, 0.
TEST_P(Methods, TorusHasGenusOne) {
  ReconstructionOptions o;
  o.method = GetParam();
  o.rbf_centers = 1500;
  const auto c = torus_points(6000, 1.0, 0.4, 17);
  const auto r = reconstruct(c, 0.08, o);
  EXPECT_EQ(r.betti.b[0], 1);
  EXPECT_EQ(r.betti.b[1], 1);
  EXPECT_EQ(r.betti.b[2], 0);
}

// Results do not depend on the thread count (poisson: estimators/poisson_reconstruction.cpp,
// sampled in one thread, is the same on any count).
TEST_P(Methods, IndependentOfTheThreadCount) {
  const auto c = sphere_points(500, 1.0, 23);
  ReconstructionOptions o;
  o.method = GetParam();
  o.threads = 1;
  const auto g = grid_around(c, 0.2);
  const auto one = reconstruct_field(c, g, o);
  o.threads = 3;
  const auto three = reconstruct_field(c, g, o);
  EXPECT_EQ(one.values, three.values);
}

INSTANTIATE_TEST_SUITE_P(All, Methods,
                         ::testing::Values(ReconstructionMethod::hoppe,
                                           ReconstructionMethod::winding,
                                           ReconstructionMethod::poisson, ReconstructionMethod::rbf,
                                           ReconstructionMethod::imls),
                         [](const ::testing::TestParamInfo<ReconstructionMethod>& p) {
                           return to_string(p.param);
                         });

// Hoppe's field of points on a plane is the signed distance to that plane, exactly up to
// rounding.
TEST(Hoppe, PlanePointsGiveTheSignedDistance) {
  PointCloud c;
  for (int i = -5; i <= 5; ++i)
    for (int j = -5; j <= 5; ++j) {
      c.points.push_back({i * 0.5, j * 0.5, 0.25});
      c.normals.push_back({0, 0, 1});
    }
  ReconstructionOptions o;
  o.k = 6;
  const auto g = grid_around(c, 0.5, 2);
  const auto f = reconstruct_field(c, g, o);
  for (std::int64_t v = 0; v < g.size(); ++v)
    EXPECT_NEAR(f.values[std::size_t(v)], g.at(v).z - 0.25, 1e-12);
}

TEST(Reconstruct, BadInputIsOneClearError) {
  auto c = sphere_points(50, 1.0, 1);
  ReconstructionOptions o;
  auto message = [&](const PointCloud& cc, double h, const ReconstructionOptions& oo) {
    try {
      (void)reconstruct(cc, h, oo);
    } catch (const InvalidArgument& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_NE(message(c, 0, o).find("grid step"), std::string::npos);
  EXPECT_NE(message(c, std::nan(""), o).find("grid step"), std::string::npos);
  EXPECT_NE(message(c, 1e-6, o).find("more than"), std::string::npos);
  o.k = 50;
  EXPECT_NE(message(c, 0.1, o).find("neighbours"), std::string::npos);
  o.k = 10;
  auto bare = c;
  bare.normals.clear();
  EXPECT_NE(message(bare, 0.1, o).find("no normals"), std::string::npos);
  auto dup = c;
  dup.points[7] = dup.points[3];
  EXPECT_NE(message(dup, 0.1, o).find("repeats point 3"), std::string::npos);
  auto nan = c;
  nan.points[4].y = std::nan("");
  EXPECT_NE(message(nan, 0.1, o).find("not finite"), std::string::npos);
  EXPECT_THROW(reconstruction_method_of("marching"), InvalidArgument);
}

} // namespace
} // namespace zdg
