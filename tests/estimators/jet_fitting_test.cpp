// Jet fitting (CGAL's osculating jets on zdg's neighbourhoods):
// - exact quadrics: on samples of z = (a x^2 + b y^2) / 2 a degree-2 jet is exact, so the
//   normal at the origin is e_z and the principal curvatures are -a and -b (the outward
//   hint +e_z sees this surface bend towards it: concave, negative in zdg's convention);
// - the sphere of radius 9: curvatures 1/9 within the O(R) bias of a degree-2 jet
//   (Cazals-Pouget), the normal radial, with the convex sign;
// - invariance under the 48 symmetries of the lattice: the estimate of the transformed cloud
//   is the transformed estimate;
// - bad parameters are refused, and too few neighbours give ok = false.
#include <zdg/arith/error.hpp>
#include <zdg/estimators/jet_fitting.hpp>

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <random>
#include <vector>

namespace {

using zdg::jet_fitting;
using P3 = zdg::Point3<double>;

double angle(const P3& a, const P3& b) {
  const double c =
      (a.x * b.x + a.y * b.y + a.z * b.z) /
      std::sqrt((a.x * a.x + a.y * a.y + a.z * a.z) * (b.x * b.x + b.y * b.y + b.z * b.z));
  return std::acos(std::min(1.0, std::max(-1.0, c)));
}

TEST(JetFitting, ExactOnQuadrics) {
  for (const auto& [a, b] : {std::pair{0.3, 0.1}, std::pair{-0.2, 0.5}, std::pair{0.0, 0.0}}) {
    std::vector<P3> pts{{0, 0, 0}};
    for (int i = -6; i <= 6; ++i) {
      for (int j = -6; j <= 6; ++j) {
        if (i == 0 && j == 0) continue;
        const double x = 0.1 * i, y = 0.1 * j;
        pts.push_back({x, y, (a * x * x + b * y * y) / 2});
      }
    }
    const std::size_t q = 0;
    const P3 up{0, 0, 1};
    auto e = jet_fitting(pts, std::span(&q, 1), std::span(&up, 1), 1.0, 2);
    ASSERT_TRUE(e[0].ok);
    EXPECT_LT(angle(e[0].normal, up), 1e-9);
    EXPECT_NEAR(e[0].k1, -std::max(a, b), 1e-9);
    EXPECT_NEAR(e[0].k2, -std::min(a, b), 1e-9);
    if (a != b) {
      // The direction of k1 (curvature -max(a, b)) is the axis of the larger coefficient.
      const P3 axis = a > b ? P3{1, 0, 0} : P3{0, 1, 0};
      EXPECT_LT(std::min(angle(e[0].d1, axis), M_PI - angle(e[0].d1, axis)), 1e-6);
    }
  }
}

std::vector<P3> sphere_points(double r, int n, unsigned seed) {
  std::mt19937 g(seed);
  std::normal_distribution<double> n01;
  std::vector<P3> pts;
  for (int i = 0; i < n; ++i) {
    const double x = n01(g), y = n01(g), z = n01(g), l = std::sqrt(x * x + y * y + z * z);
    pts.push_back({r * x / l, r * y / l, r * z / l});
  }
  return pts;
}

TEST(JetFitting, SphereOfRadiusNine) {
  const auto pts = sphere_points(9, 20000, 1);
  std::vector<std::size_t> q{0, 1, 2, 3, 4, 5, 6, 7};
  std::vector<P3> out(pts.begin(), pts.begin() + 8);
  auto e = jet_fitting(pts, q, out, 1.5, 2, 2);
  for (std::size_t i = 0; i < q.size(); ++i) {
    ASSERT_TRUE(e[i].ok);
    EXPECT_LT(angle(e[i].normal, pts[i]), 2e-3);
    EXPECT_NEAR(e[i].k1, 1.0 / 9, 0.02 / 9);
    EXPECT_NEAR(e[i].k2, 1.0 / 9, 0.02 / 9);
    EXPECT_GT(e[i].neighbours, 100u);
  }
}

TEST(JetFitting, InvariantUnderTheLatticeSymmetries) {
  // An ellipsoid-like cloud (anisotropic curvatures), and each of the 48 signed axis
  // permutations applied to the cloud and to the hint.
  std::vector<P3> base;
  for (const auto& p : sphere_points(1, 6000, 7)) base.push_back({6 * p.x, 4 * p.y, 3 * p.z});
  const std::size_t q = 0;
  const P3 hint = base[0];
  const auto ref = jet_fitting(base, std::span(&q, 1), std::span(&hint, 1), 1.2, 2)[0];
  ASSERT_TRUE(ref.ok);
  const std::array<std::array<int, 3>, 6> perms{
      {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}}};
  for (const auto& perm : perms) {
    for (int signs = 0; signs < 8; ++signs) {
      auto f = [&](const P3& p) {
        const double v[3] = {p.x, p.y, p.z};
        auto c = [&](int i) { return ((signs >> i) & 1 ? -1.0 : 1.0) * v[perm[std::size_t(i)]]; };
        return P3{c(0), c(1), c(2)};
      };
      std::vector<P3> pts;
      for (const auto& p : base) pts.push_back(f(p));
      const P3 h2 = f(hint);
      const auto e = jet_fitting(pts, std::span(&q, 1), std::span(&h2, 1), 1.2, 2)[0];
      ASSERT_TRUE(e.ok);
      EXPECT_NEAR(e.k1, ref.k1, 1e-9);
      EXPECT_NEAR(e.k2, ref.k2, 1e-9);
      EXPECT_LT(angle(e.normal, f(ref.normal)), 1e-7);
    }
  }
}

TEST(JetFitting, BadParametersAndSparseNeighbourhoods) {
  const std::vector<P3> pts{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  const std::size_t q = 0;
  const P3 up{0, 0, 1};
  EXPECT_THROW(jet_fitting(pts, std::span(&q, 1), std::span(&up, 1), 0.0, 2), zdg::InvalidArgument);
  EXPECT_THROW(jet_fitting(pts, std::span(&q, 1), std::span(&up, 1), 1.0, 0), zdg::InvalidArgument);
  EXPECT_THROW(jet_fitting(pts, std::span(&q, 1), std::span(&up, 1), 1.0, 5), zdg::InvalidArgument);
  EXPECT_THROW(jet_fitting(pts, std::span(&q, 1), std::span<const P3>(), 1.0, 2),
               zdg::InvalidArgument);
  // 3 points, a degree-2 jet has 6 coefficients.
  auto e = jet_fitting(pts, std::span(&q, 1), std::span(&up, 1), 2.0, 2);
  EXPECT_FALSE(e[0].ok);
  EXPECT_EQ(e[0].neighbours, 3u);
}

} // namespace
