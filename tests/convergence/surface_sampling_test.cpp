// Uniform sampling on the area of the registry's 3D shapes (convergence/surface_sampling.hpp).
// Oracles: closed forms (Archimedes' cap area on the sphere, the torus's area element
// (R + r cos t) r, the sphere's area), the symmetry of the sphere (the mean is its centre) and
// the projection itself (every point on the surface). Tolerances are 5 standard deviations of
// the binomial or mean estimate for the stated N.
#include <zdg/convergence/surface_sampling.hpp>

#include "tests/support/tower.hpp"
#include <zdg/arith/error.hpp>
#include <zdg/convergence/shapes_3d.hpp>

#include <gtest/gtest.h>
#include <rapidcheck.h>

#include <cmath>
#include <numbers>

namespace zdg {
namespace {

using P3 = Point3<double>;

std::unique_ptr<Shape3> shape3(const std::string& spec) {
  auto s = parse_shape(spec);
  auto* p = dynamic_cast<Shape3*>(s.get());
  EXPECT_NE(p, nullptr);
  s.release();
  return std::unique_ptr<Shape3>(p);
}

double norm(const P3& p) {
  return std::sqrt(dot(p, p));
}

// Symmetry: the mean of uniform points of the unit sphere is its centre (each coordinate has
// variance 1/3: standard deviation of the mean sqrt(1 / (3 N))); Archimedes: the cap z > 1/2
// holds a quarter of the area (binomial standard deviation sqrt(3 / 16 / N)).
TEST(SurfaceSampling, SphereMeanIsTheCentreAndCapsHoldTheirAreaFraction) {
  const auto s = shape3("sphere1");
  const std::int64_t n = 20000;
  const auto r = sample_surface(*s, n, 0, 42);
  ASSERT_EQ(r.cloud.size(), std::size_t(n));
  EXPECT_DOUBLE_EQ(r.area, 4 * std::numbers::pi);
  EXPECT_GE(r.candidates, n);
  P3 mean{0, 0, 0};
  std::int64_t cap = 0;
  for (std::size_t i = 0; i < r.exact.size(); ++i) {
    const P3& p = r.exact[i];
    EXPECT_NEAR(norm(p), 1.0, 1e-9) << p;
    EXPECT_NEAR(norm(r.cloud.normals[i] - p), 0.0, 1e-9) << "the unit normal of the unit sphere";
    EXPECT_EQ(r.cloud.points[i], p) << "no noise";
    mean = mean + p * (1.0 / double(n));
    cap += p.z > 0.5;
  }
  const double sd_mean = std::sqrt(1.0 / (3.0 * double(n)));
  EXPECT_LT(norm(mean), 5 * std::sqrt(3.0) * sd_mean) << mean;
  EXPECT_NEAR(double(cap) / double(n), 0.25, 5 * std::sqrt(3.0 / 16.0 / double(n)));
}

// The torus (R = 6, r = 2): the area element is (R + r cos t) r dt ds, so the outer half
// (x^2 + y^2 > R^2, |t| < pi/2) holds 1/2 + r / (pi R) of the area.
TEST(SurfaceSampling, TorusOuterHalfHoldsItsAreaFraction) {
  const auto s = shape3("torus");
  const std::int64_t n = 20000;
  const auto r = sample_surface(*s, n, 0, 7);
  std::int64_t outer = 0;
  for (const auto& p : r.exact) {
    const double rho = std::hypot(p.x, p.y);
    EXPECT_NEAR(std::hypot(rho - 6, p.z), 2.0, 1e-9) << p;
    outer += rho > 6;
  }
  const double expected = 0.5 + 2 / (std::numbers::pi * 6);
  EXPECT_NEAR(double(outer) / double(n), expected,
              5 * std::sqrt(expected * (1 - expected) / double(n)));
}

// Every point lies on the surface (to 1e-9) with its outward unit normal, for any seed; the
// same seed gives the same points.
TEST(SurfaceSampling, PointsLieOnTheSurfaceForEverySeed) {
  const auto s = shape3("sphere9");
  test::check_property([&] {
    const auto seed = *rc::gen::arbitrary<std::uint64_t>();
    const auto n = *rc::gen::inRange<std::int64_t>(1, 300);
    const auto r = sample_surface(*s, n, 0, seed);
    RC_ASSERT(r.cloud.size() == std::size_t(n));
    for (std::size_t i = 0; i < r.exact.size(); ++i) {
      RC_ASSERT(std::abs(norm(r.exact[i]) - 9) < 1e-9);
      RC_ASSERT(norm(r.cloud.normals[i] - r.exact[i] * (1.0 / 9)) < 1e-9);
    }
    const auto again = sample_surface(*s, n, 0, seed);
    RC_ASSERT(again.cloud.points == r.cloud.points);
  });
}

// Noise: the kept point is the surface point plus sigma times a standard Gaussian vector; on
// the big sphere its radial part has standard deviation sigma (within 5 percent at N = 20000:
// the relative standard deviation of a sample deviation is 1 / sqrt(2 N) = 0.5 percent).
TEST(SurfaceSampling, NoiseHasTheStatedDeviation) {
  const auto s = shape3("sphere9");
  const double sigma = 0.01;
  const auto r = sample_surface(*s, 20000, sigma, 3);
  double sum2 = 0;
  for (std::size_t i = 0; i < r.exact.size(); ++i) {
    const P3 e = r.cloud.points[i] - r.exact[i];
    sum2 += dot(e, e);
  }
  EXPECT_NEAR(std::sqrt(sum2 / (3.0 * double(r.exact.size()))), sigma, 0.05 * sigma);
  EXPECT_NE(sample_surface(*s, 10, 0, 3).cloud.points, sample_surface(*s, 10, 0, 4).cloud.points);
}

// Without a closed form the area is the fine mesh's estimate (the sphere of radius 2 as a
// polynomial: 16 pi within 1 percent); the Betti numbers are those of the shape.
TEST(SurfaceSampling, AreaEstimateAndBettiNumbersOfTheFineMesh) {
  const auto ball = shape3("poly:x^2+y^2+z^2-4");
  const auto m = sampling_mesh(*ball);
  EXPECT_FALSE(m->area_exact);
  EXPECT_NEAR(m->area / (16 * std::numbers::pi), 1.0, 0.01);
  EXPECT_EQ(m->betti.b, (std::array<std::int64_t, 3>{1, 0, 0})) << "the solid ball";
  EXPECT_EQ(sampling_mesh(*shape3("torus"))->betti.b, (std::array<std::int64_t, 3>{1, 1, 0}))
      << "the solid torus";
  EXPECT_TRUE(sampling_mesh(*shape3("sphere1"))->area_exact);
}

TEST(SurfaceSampling, BadInputIsRefused) {
  const auto s = shape3("sphere1");
  EXPECT_THROW(sample_surface(*s, 0, 0, 1), InvalidArgument);
  EXPECT_THROW(sample_surface(*s, 10, -0.1, 1), InvalidArgument);
  EXPECT_THROW(sample_surface(*s, 10, std::nan(""), 1), InvalidArgument);
  EXPECT_THROW(sample_surface(*shape3("cylinder"), 10, 0, 1), InvalidArgument);
}

} // namespace
} // namespace zdg
