#include <zdg/estimators/corrected_curvature.hpp>
#include <zdg/estimators/ii_3d.hpp>

#include "tests/support/digital_sphere.hpp"
#include "tests/support/lattice_symmetry.hpp"
#include "tests/support/tower.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace {

using P3 = zdg::Point3<double>;
using zdg::Surfel;
using zdg::Voxel;
using zdg::VoxelBox;

P3 unit(P3 v) {
  return (1.0 / std::sqrt(dot(v, v))) * v;
}

// Closed forms of the paper on a unit square with one constant normal: area 1, no curvature.
TEST(CorrectedCurvature, FlatSquareHasAreaOneAndNoCurvature) {
  const std::array<P3, 4> x{{{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}}};
  const std::array<P3, 4> u{{{0, 0, 1}, {0, 0, 1}, {0, 0, 1}, {0, 0, 1}}};
  const auto m = zdg::quad_corrected_measures(x, u);
  EXPECT_NEAR(m.mu0, 1.0, 1e-15);
  EXPECT_NEAR(m.mu1, 0.0, 1e-15);
  EXPECT_NEAR(m.mu2, 0.0, 1e-15);
  for (double v : m.muxy) EXPECT_NEAR(v, 0.0, 1e-15);
}

// On a triangle (a degenerate quad with x[2] = x[3], u[2] = u[3]) the bilinear measures are the
// paper's linear closed forms: mu0 = 1/2 <u_M, AB x AC>, mu1 = 1/2 sum det(u_M, u_C - u_B, A),
// mu2 = 1/2 det(u_A, u_B, u_C), muXY = 1/2 <u_M, <Y,u_C-u_A> X x AB - <Y,u_B-u_A> X x AC>.
TEST(CorrectedCurvature, DegenerateQuadGivesTheTriangleClosedForms) {
  zdg::test::check_property([] {
    auto coord = [] { return double(*rc::gen::inRange(-100, 101)) / 37.0; };
    auto vec = [&] { return P3{coord(), coord(), coord()}; };
    const P3 a = vec(), b = vec(), c = vec(), ua = vec(), ub = vec(), uc = vec();
    const auto m = zdg::quad_corrected_measures({a, b, c, c}, {ua, ub, uc, uc});
    const P3 um = (1.0 / 3.0) * (ua + ub + uc);
    auto det = [](P3 p, P3 q, P3 r) { return dot(p, cross(q, r)); };
    const double mu0 = 0.5 * dot(um, cross(b - a, c - a));
    const double mu1 = 0.5 * (det(um, uc - ub, a) + det(um, ua - uc, b) + det(um, ub - ua, c));
    const double mu2 = 0.5 * det(ua, ub, uc);
    RC_ASSERT(std::abs(m.mu0 - mu0) < 1e-9);
    RC_ASSERT(std::abs(m.mu1 - mu1) < 1e-9);
    RC_ASSERT(std::abs(m.mu2 - mu2) < 1e-9);
    const P3 e[3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) {
        const double t = 0.5 * dot(um, dot(e[j], uc - ua) * cross(e[i], b - a) -
                                           dot(e[j], ub - ua) * cross(e[i], c - a));
        RC_ASSERT(std::abs(m.muxy[std::size_t(3 * i + j)] - t) < 1e-9);
      }
  });
}

// u_i = x_i / rho on every corner gives u = x / rho on the face: mu1 = 2 mu0 / rho,
// mu2 = mu0 / rho^2 and muXY = -mu0/rho times the projection on the face (trace -mu1), for any
// quad.
TEST(CorrectedCurvature, RadialFieldGivesTheSphereIdentitiesOnAnyQuad) {
  zdg::test::check_property([] {
    auto coord = [] { return double(*rc::gen::inRange(-100, 101)) / 23.0; };
    const double rho = double(*rc::gen::inRange(1, 50)) / 7.0;
    std::array<P3, 4> x, u;
    for (std::size_t i = 0; i < 4; ++i) {
      x[i] = {coord(), coord(), coord()};
      u[i] = (1.0 / rho) * x[i];
    }
    const auto m = zdg::quad_corrected_measures(x, u);
    const double scale = 1 + std::abs(m.mu0) / (rho * rho);
    RC_ASSERT(std::abs(m.mu1 - 2 * m.mu0 / rho) < 1e-9 * scale);
    RC_ASSERT(std::abs(m.mu2 - m.mu0 / (rho * rho)) < 1e-9 * scale);
    RC_ASSERT(std::abs(m.muxy[0] + m.muxy[4] + m.muxy[8] + m.mu1) < 1e-9 * scale);
  });
}

// A digital plane with its exact (constant) normal: H = G = k1 = k2 = 0 at every surfel away
// from the box (u_s = u_t = 0 on every face).
TEST(CorrectedCurvature, DigitalPlaneWithItsNormalIsFlat) {
  zdg::test::check_property([] {
    const auto a = *rc::gen::inRange<std::int64_t>(-5, 6);
    const auto b = *rc::gen::inRange<std::int64_t>(-5, 6);
    const auto c = *rc::gen::inRange<std::int64_t>(1, 6);
    const zdg::VoxelPredicate in = [=](const Voxel& z) { return a * z.x + b * z.y + c * z.z <= 0; };
    const VoxelBox box{{-12, -12, -40}, {12, 12, 40}};
    const auto surfels = zdg::boundary_surfels(in, box);
    const P3 n = unit({double(a), double(b), double(c)});
    std::vector<P3> normals(surfels.size(), n);
    std::vector<std::size_t> queries;
    for (std::size_t i = 0; i < surfels.size(); ++i) {
      const auto v = zdg::inner_voxel(surfels[i]);
      if (std::abs(v.x) <= 4 && std::abs(v.y) <= 4 && std::abs(v.z) < 30 &&
          box.contains(zdg::outer_voxel(surfels[i])))
        queries.push_back(i);
    }
    RC_ASSERT(!queries.empty());
    const auto est = zdg::cnc_curvatures(surfels, normals, 1.0, 3.0, queries, 2);
    for (const auto& e : est) {
      RC_ASSERT(std::abs(e.mean) < 1e-12);
      RC_ASSERT(std::abs(e.gaussian) < 1e-12);
      RC_ASSERT(std::abs(e.k1) < 1e-9);
      RC_ASSERT(std::abs(e.k2) < 1e-9);
    }
  });
}

struct SphereErrors {
  double mean_h = 0, max_h = 0, mean_g = 0, mean_k = 0;
};

SphereErrors sphere_errors(const zdg::test::DigitalSphere& s, const std::vector<P3>& normals,
                           double R) {
  const auto est = zdg::cnc_curvatures(s.surfels, normals, s.h, R, 2);
  SphereErrors e;
  for (const auto& c : est) {
    e.mean_h += std::abs(c.mean - 1);
    e.max_h = std::max(e.max_h, std::abs(c.mean - 1));
    e.mean_g += std::abs(c.gaussian - 1);
    e.mean_k += std::max(std::abs(c.k1 - 1), std::abs(c.k2 - 1));
  }
  const double n = double(est.size());
  e.mean_h /= n;
  e.mean_g /= n;
  e.mean_k /= n;
  return e;
}

// The exact unit normal of the unit sphere at each pointel (u_i = x_i / |x_i|): the corrected
// measures see the sphere up to the O(h) offset of the pointels, H, G, k1, k2 = 1 within a few h.
TEST(CorrectedCurvature, DigitalSphereWithItsExactNormalsHasCurvatureOne) {
  const double h = 0.05;
  const auto s = zdg::test::digital_sphere(h, false);
  // Surfel normals whose pointel averages are close to radial: the radial unit vector at the
  // surfel centre (the corner normals are then the normalised sums of radial vectors).
  std::vector<P3> normals;
  for (const auto& f : s.surfels) normals.push_back(unit(zdg::surfel_centre(f, h)));
  const auto e = sphere_errors(s, normals, std::sqrt(h));
  EXPECT_LT(e.mean_h, 0.5 * h);
  EXPECT_LT(e.max_h, 1.5 * h);
  EXPECT_LT(e.mean_g, h);
  EXPECT_LT(e.mean_k, h);
}

// With the II normals (R_II = 2 h^{1/3}) at R = h^{1/2}: H, G close to 1 and the error decreases
// with h.
TEST(CorrectedCurvature, DigitalSphereWithIINormalsConverges) {
  double last = 1e9;
  for (const double h : {0.2, 0.1, 0.05}) {
    const auto s = zdg::test::digital_sphere(h, true);
    const auto e = sphere_errors(s, s.ii_normals, std::sqrt(h));
    EXPECT_LT(e.mean_h, last) << "h = " << h;
    last = e.mean_h;
    if (h == 0.05) {
      EXPECT_LT(e.mean_h, 0.03);
      EXPECT_LT(e.mean_g, 0.06);
      EXPECT_LT(e.mean_k, 0.08);
    }
  }
}

// The 48 lattice symmetries: the estimates at the image surfel are the same numbers, the
// principal directions the images of the directions (up to sign).
TEST(CorrectedCurvature, InvariantUnderTheLatticeSymmetries) {
  const zdg::VoxelPredicate in = [](const Voxel& z) {
    const auto x = z.x - 1, y = z.y + 2, w = z.z;
    return 3 * x * x + 2 * y * y + w * w + x * y <= 120;
  };
  const VoxelBox box{{-20, -20, -20}, {20, 20, 20}};
  const auto surfels = zdg::boundary_surfels(in, box);
  const double R = 4.0;
  auto ii = [&](const zdg::VoxelPredicate& p, const VoxelBox& b, std::span<const Surfel> ss) {
    std::vector<P3> n;
    for (const auto& c : zdg::ii_principal_curvatures(p, b, ss, 1.0, 3.0, 2)) n.push_back(c.normal);
    return n;
  };
  const auto ref = zdg::cnc_curvatures(surfels, ii(in, box, surfels), 1.0, R, 1);
  for (const auto& g : zdg::test::lattice_symmetries()) {
    std::vector<Surfel> image;
    for (const auto& s : surfels) image.push_back(g.apply(s));
    const auto gin = g.apply(in);
    const auto gbox = g.apply(box);
    const auto est = zdg::cnc_curvatures(image, ii(gin, gbox, image), 1.0, R, 1);
    for (std::size_t i = 0; i < surfels.size(); ++i) {
      ASSERT_NEAR(est[i].mean, ref[i].mean, 1e-9);
      ASSERT_NEAR(est[i].gaussian, ref[i].gaussian, 1e-9);
      ASSERT_NEAR(est[i].k1, ref[i].k1, 1e-9);
      ASSERT_NEAR(est[i].k2, ref[i].k2, 1e-9);
      if (ref[i].k2 - ref[i].k1 > 1e-3) {
        ASSERT_NEAR(std::abs(dot(est[i].d1, g.apply(ref[i].d1))), 1.0, 1e-6);
      }
    }
  }
}

TEST(CorrectedCurvature, BadParametersAreRefused) {
  const std::vector<Surfel> s{zdg::surfel_between({0, 0, 0}, 2, 1)};
  const std::vector<P3> n{{0, 0, 1}};
  EXPECT_THROW(zdg::cnc_curvatures(s, n, 1.0, 0.0), zdg::InvalidArgument);
  EXPECT_THROW(zdg::cnc_curvatures(s, n, -1.0, 2.0), zdg::InvalidArgument);
  EXPECT_THROW(zdg::cnc_curvatures(s, std::vector<P3>{}, 1.0, 2.0), zdg::InvalidArgument);
  EXPECT_THROW(zdg::cnc_curvatures(s, std::vector<P3>{{0, 0, 2}}, 1.0, 2.0), zdg::InvalidArgument);
  const std::vector<std::size_t> q{3};
  EXPECT_THROW(zdg::cnc_curvatures(s, n, 1.0, 2.0, q), zdg::InvalidArgument);
}

} // namespace
