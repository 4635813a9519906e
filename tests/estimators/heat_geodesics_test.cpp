// The heat method on digital surfaces (estimators/heat_geodesics.hpp). Oracles: linear
// precision of the least-squares tangential gradient on the faces of a digital cube (exact),
// G 1 = 0, and the great-circle distance R acos(n . n0) on the unit sphere, whose error must
// fall with h (Crane, Weischedel, Wardetzky 2013).
#include <zdg/arith/error.hpp>
#include <zdg/estimators/heat_geodesics.hpp>

#include "tests/support/digital_sphere.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace zdg {
namespace {

using P3 = Point3<double>;

// The digital cube [-m, m]^3 (voxels), its complex at step 1 and its exact face normals.
struct DigitalCube {
  SurfelComplex complex;
  std::vector<P3> normals;
};

DigitalCube digital_cube(std::int64_t m) {
  const VoxelPredicate inside = [m](const Voxel& z) {
    return std::max({std::abs(z.x), std::abs(z.y), std::abs(z.z)}) <= m;
  };
  const auto surfels =
      boundary_surfels(inside, VoxelBox{{-m - 2, -m - 2, -m - 2}, {m + 2, m + 2, m + 2}});
  DigitalCube c;
  c.complex = surfel_complex(primal_surface(surfels), 1.0);
  c.normals = c.complex.normals;
  return c;
}

// Linear precision: on the interior of a flat face the gradient of u = a . x is the tangential
// part of a, exactly (the least-squares fit of a plane to a linear function is that function).
TEST(HeatGeodesics, TangentialGradientIsExactForLinearFunctionsOnFlatFaces) {
  const std::int64_t m = 6;
  const DigitalCube cube = digital_cube(m);
  const SparseMatrix g = tangential_gradient(cube.complex, cube.normals);
  ASSERT_EQ(g.rows, 3 * cube.complex.surfel_count());
  const P3 a{0.7, -1.3, 2.1};
  std::vector<double> u, one(std::size_t(cube.complex.surfel_count()), 1.0);
  for (const auto& x : cube.complex.centres) u.push_back(a.x * x.x + a.y * x.y + a.z * x.z);
  const auto gu = g.multiply(u);
  const auto g1 = g.multiply(one);
  int interior = 0;
  for (std::int64_t s = 0; s < cube.complex.surfel_count(); ++s) {
    const auto k = std::size_t(s);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(g1[3 * k + std::size_t(c)], 0, 1e-12); // G 1 = 0
    const P3 x = cube.complex.centres[k], n = cube.normals[k];
    // Two rings inside the face: every stencil surfel is on the face.
    const double depth = m + 0.5 - 2.0;
    const double tx = n.x != 0 ? 0 : std::abs(x.x), ty = n.y != 0 ? 0 : std::abs(x.y),
                 tz = n.z != 0 ? 0 : std::abs(x.z);
    if (std::max({tx, ty, tz}) > depth - 1) continue;
    ++interior;
    const double an = a.x * n.x + a.y * n.y + a.z * n.z;
    EXPECT_NEAR(gu[3 * k], a.x - an * n.x, 1e-12);
    EXPECT_NEAR(gu[3 * k + 1], a.y - an * n.y, 1e-12);
    EXPECT_NEAR(gu[3 * k + 2], a.z - an * n.z, 1e-12);
  }
  EXPECT_GT(interior, 6 * 25);
}

double great_circle(P3 a, P3 b) {
  const double la = std::sqrt(a.x * a.x + a.y * a.y + a.z * a.z);
  const double lb = std::sqrt(b.x * b.x + b.y * b.y + b.z * b.z);
  const double c = (a.x * b.x + a.y * b.y + a.z * b.z) / (la * lb);
  return std::acos(std::clamp(c, -1.0, 1.0));
}

// The heat method on the unit sphere: the distance to the surfel nearest to the north pole
// against the great-circle distance between the rays of the surfel centres.
TEST(HeatGeodesics, ErrorOnTheSphereFallsWithH) {
  std::vector<double> mean_errors, max_errors;
  for (double h : {0.1, 0.05}) {
    const test::DigitalSphere s = test::digital_sphere(h);
    const HeatGeodesics geo(s.complex, s.ii_normals, s.weights);
    const auto [source, gap] = nearest_surfel(s.complex, {0, 0, 1});
    EXPECT_LT(gap, h);
    const auto d = geo.distance(source);
    const P3 c0 = s.complex.centres[std::size_t(source)];
    double mean = 0, worst = 0;
    for (std::int64_t r = 0; r < s.complex.surfel_count(); ++r) {
      const double e =
          std::abs(d[std::size_t(r)] - great_circle(s.complex.centres[std::size_t(r)], c0));
      mean += e;
      worst = std::max(worst, e);
    }
    mean /= double(s.complex.surfel_count());
    std::printf("h = %g: %lld surfels, t = %.3g (%s), mean error %.4f, max error %.4f\n", h,
                static_cast<long long>(s.complex.surfel_count()), geo.time(),
                spd_backend_name(geo.backend()).c_str(), mean, worst);
    mean_errors.push_back(mean);
    max_errors.push_back(worst);
    EXPECT_EQ(d[std::size_t(source)], 0.0);
  }
  EXPECT_LT(mean_errors[1], mean_errors[0]);
  EXPECT_LT(max_errors[1], max_errors[0]);
  EXPECT_LT(mean_errors[1], 0.05); // pi is the largest distance
}

TEST(HeatGeodesics, BadInput) {
  const test::DigitalSphere s = test::digital_sphere(0.25);
  const HeatGeodesics geo(s.complex, s.ii_normals, s.weights);
  EXPECT_THROW(geo.distance(-1), InvalidArgument);
  EXPECT_THROW(geo.distance(s.complex.surfel_count()), InvalidArgument);
  const std::vector<double> short_weights(3, 1.0);
  EXPECT_THROW(HeatGeodesics(s.complex, s.ii_normals, short_weights), InvalidArgument);
  EXPECT_THROW(HeatGeodesics(s.complex, s.ii_normals, s.weights, -1.0), InvalidArgument);
  std::vector<P3> bad = s.ii_normals;
  bad[0] = {2, 0, 0};
  EXPECT_THROW(tangential_gradient(s.complex, bad), InvalidArgument);
}

} // namespace
} // namespace zdg
