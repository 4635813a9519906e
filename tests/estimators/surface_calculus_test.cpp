// Calculus on digital surfaces (#14): the surfel complex, digital integration, the heat-kernel
// Laplace-Beltrami operator and its comparators, on Gauss digitizations of the unit sphere.
// Oracles: closed forms (area 4 pi, Delta_S x = -2 x on the unit sphere, linear precision of
// the cotangent weights) and algebraic identities (L 1 = 0, symmetry of W L, V - E + F = 2).
#include <zdg/arith/error.hpp>
#include <zdg/estimators/digital_integration.hpp>
#include <zdg/estimators/heat_laplace_beltrami.hpp>
#include <zdg/estimators/ii_3d.hpp>
#include <zdg/kernel/linalg/cotan_laplacian.hpp>
#include <zdg/kernel/surfaces/digital_surface.hpp>
#include <zdg/kernel/surfaces/surfel_complex.hpp>

#include "tests/support/digital_sphere.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>

namespace zdg {
namespace {

using test::digital_sphere;
using test::DigitalSphere;

TEST(SurfelComplex, DigitalSphereIsAClosedSurfaceOfEulerCharacteristicTwo) {
  const DigitalSphere s = digital_sphere(0.2, false);
  const SurfelComplex& c = s.complex;
  ASSERT_EQ(c.surfel_count(), static_cast<std::int64_t>(s.surfels.size()));
  EXPECT_EQ(c.pointel_count() - c.linel_count() + c.surfel_count(), 2);
  EXPECT_EQ(2 * c.linel_count(), 4 * c.surfel_count()); // each linel bounds two surfels
  for (std::int64_t f = 0; f < c.surfel_count(); ++f) {
    const auto k = static_cast<std::size_t>(f);
    EXPECT_NEAR(c.areas[k], 0.04, 1e-12);
    const auto& n = c.normals[k];
    EXPECT_NEAR(std::abs(n.x) + std::abs(n.y) + std::abs(n.z), 1.0, 1e-12); // +-e_a
    // Outward: the normal points away from the centre of the sphere.
    EXPECT_GT(n.x * c.centres[k].x + n.y * c.centres[k].y + n.z * c.centres[k].z, 0);
    for (int i = 0; i < 4; ++i) { // adjacency is symmetric: f is a neighbour of its neighbours
      const std::int64_t r = c.neighbour(f, i);
      ASSERT_NE(r, f);
      int back = 0;
      for (int j = 0; j < 4; ++j) back += c.neighbour(r, j) == f ? 1 : 0;
      EXPECT_GE(back, 1);
    }
  }
}

// Lachaud-Thibert (JMIV 2016): DI_h(1) with a convergent normal tends to the area; with the
// elementary normal (mu = 1) it is the staircase area, about 1.5 times too large.
TEST(DigitalIntegration, AreaOfTheSphereConvergesWithIINormals) {
  std::vector<double> errors;
  for (double h : {0.2, 0.1, 0.05}) {
    const DigitalSphere s = digital_sphere(h);
    const auto mu = surfel_measure(s.ii_normals, s.complex.normals);
    const auto w = surfel_weights(mu, s.complex.areas);
    const std::vector<double> one(w.size(), 1.0);
    const double area = digital_integral(w, one);
    const double staircase = digital_integral(s.complex.areas, one);
    errors.push_back(std::abs(area - 4 * std::numbers::pi) / (4 * std::numbers::pi));
    std::printf("h = %g: surfels %zu, DI(1) = %.6f (rel. error %.2e), staircase %.4f\n", h,
                w.size(), area, errors.back(), staircase / (4 * std::numbers::pi));
    EXPECT_GT(staircase / (4 * std::numbers::pi), 1.3);
  }
  // Measured: 6.0e-2, 1.2e-2, 3.8e-3; the theorem's rate with the II normal is h^{2/3}.
  EXPECT_LT(errors[2], 1e-2);
  EXPECT_LT(errors[1], errors[0]);
  EXPECT_LT(errors[2], errors[1]);
  EXPECT_GT(std::log(errors[0] / errors[2]) / std::log(4.0), 2.0 / 3.0);
}

// Caissard et al. (JMIV 2019): the heat LB of u = x on the unit sphere tends to -2x (t = h^0.4,
// inside the theorem's range alpha < min(1/2, 2 beta / 3) = 4/9 for the II normal), and it
// annihilates constants exactly.
TEST(HeatLaplaceBeltrami, LinearFunctionOnTheSphere) {
  std::vector<double> errors;
  for (double h : {0.1, 0.05}) {
    const DigitalSphere s = digital_sphere(h);
    const auto mu = surfel_measure(s.ii_normals, s.complex.normals);
    const auto w = surfel_weights(mu, s.complex.areas);
    for (double alpha : {0.4}) {
      const double t = heat_kernel_time(h, alpha);
      HeatLaplaceBeltrami L(s.complex.centres, w, t, 5.0, 2);
      std::vector<double> u, one(w.size(), 1.0);
      for (const auto& p : s.complex.centres) u.push_back(p.x);
      const auto lu = L.apply(u);
      const auto l1 = L.apply(one);
      double err = 0, zero = 0;
      for (std::size_t i = 0; i < u.size(); ++i) {
        const auto& p = s.complex.centres[i];
        const double r = std::sqrt(p.x * p.x + p.y * p.y + p.z * p.z);
        err = std::max(err, std::abs(lu[i] + 2 * p.x / r));
        zero = std::max(zero, std::abs(l1[i]));
      }
      std::printf("h = %g alpha %g t %g: pairs %lld, linf error %.3e, L1 %.1e\n", h, alpha, t,
                  static_cast<long long>(L.pair_count()), err, zero);
      EXPECT_EQ(zero, 0.0);
      errors.push_back(err);
    }
  }
  // Measured: 0.60 at h = 0.1 and 0.33 at h = 0.05 (the O(t) bias dominates at these steps).
  EXPECT_LT(errors[1], 0.75 * errors[0]);
  EXPECT_LT(errors[1], 0.45);
}

// apply() against the matrix's row-by-row product (std::exp in double precision): apply()'s
// kernel values are single precision, within a relative 1e-5 of the matrix entries (the
// header's bound), so row i may differ by 1e-5 sum_j |L_ij| |u_j - u_i| -- the pairs at the
// cut rho (kernel value exp(-12.5) = 4e-6 of the largest) may fall on either side of it, which
// the same slack covers. Returns the largest ratio of the difference to that sum.
double apply_against_matrix(const std::vector<double>& a, const SparseMatrix& m,
                            const std::vector<double>& u) {
  const auto b = m.multiply(u);
  double worst = 0;
  for (std::int64_t i = 0; i < m.rows; ++i) {
    const auto k = static_cast<std::size_t>(i);
    double spread = 0;
    for (auto p = m.row_start[k]; p < m.row_start[k + 1]; ++p)
      spread += std::abs(m.value[static_cast<std::size_t>(p)]) *
                std::abs(u[static_cast<std::size_t>(m.column[static_cast<std::size_t>(p)])] - u[k]);
    const double d = std::abs(a[k] - b[k]);
    worst = std::max(worst, spread > 0 ? d / spread : (d == 0 ? 0.0 : HUGE_VAL));
  }
  return worst;
}

// The property table of Caissard et al. (Table 1), measured: W L symmetric (W = diag(w)),
// L 1 = 0, off-diagonal entries >= 0 where w > 0, so -W L is positive semi-definite; the
// matrix and the matrix-free product agree.
TEST(HeatLaplaceBeltrami, MatrixIsSymmetricForTheWeightsAndNegativeSemiDefinite) {
  const DigitalSphere s = digital_sphere(0.2);
  const auto w = surfel_weights(surfel_measure(s.ii_normals, s.complex.normals), s.complex.areas);
  HeatLaplaceBeltrami L(s.complex.centres, w, heat_kernel_time(0.2, 0.4), 5.0, 2);
  const SparseMatrix m = L.matrix();
  ASSERT_EQ(m.rows, static_cast<std::int64_t>(w.size()));
  EXPECT_EQ(m.nonzeros() - m.rows, L.pair_count());
  double scale = 0;
  for (double v : m.value) scale = std::max(scale, std::abs(v));
  for (std::int64_t i = 0; i < m.rows; ++i) {
    double row = 0;
    for (auto k = m.row_start[static_cast<std::size_t>(i)];
         k < m.row_start[static_cast<std::size_t>(i) + 1]; ++k) {
      const auto j = m.column[static_cast<std::size_t>(k)];
      const double v = m.value[static_cast<std::size_t>(k)];
      row += v;
      if (j != i) {
        EXPECT_GE(v, 0.0);
        EXPECT_NEAR(w[static_cast<std::size_t>(i)] * v, w[static_cast<std::size_t>(j)] * m.at(j, i),
                    1e-12 * scale);
      }
    }
    EXPECT_NEAR(row, 0.0, 1e-12 * scale);
  }
  std::vector<double> u;
  for (const auto& p : s.complex.centres) u.push_back(std::sin(3 * p.x) + p.y * p.z);
  const auto a = L.apply(u);
  EXPECT_LT(apply_against_matrix(a, m, u), 1e-5);
  double quad = 0;
  for (std::size_t i = 0; i < u.size(); ++i) quad += u[i] * w[i] * a[i];
  EXPECT_LE(quad, 0.0); // u^T W L u <= 0
  EXPECT_THROW(heat_kernel_time(0.1, 1.0), InvalidArgument);
  EXPECT_THROW(heat_kernel_time(0.1, 0.0), InvalidArgument);
  EXPECT_THROW(heat_kernel_time(-0.1, 0.4), InvalidArgument);
}

// apply() evaluates each pair once for both of its rows, by rounds of pairs of blocks (many
// cells and blocks here: t = 4 h^2 on 7,000 surfels): the same bits for any number of threads,
// constants annihilated exactly, and the row-by-row matrix product within the single-precision
// kernel's bound.
TEST(HeatLaplaceBeltrami, SymmetricScheduleIsDeterministicAndAgreesWithTheMatrix) {
  const DigitalSphere s = digital_sphere(0.05, false);
  std::vector<double> w;
  for (const double a : s.complex.areas) w.push_back(a);
  w[3] = 0; // a zero weight is allowed (its row still sums the others)
  std::vector<double> u, one(w.size(), 1.0);
  for (const auto& p : s.complex.centres) u.push_back(std::exp(p.z) + p.x * p.y);
  const double t = 4 * 0.05 * 0.05;
  const HeatLaplaceBeltrami L1(s.complex.centres, w, t, 5.0, 1);
  const auto a = L1.apply(u);
  for (unsigned threads : {2u, 3u}) {
    const HeatLaplaceBeltrami L(s.complex.centres, w, t, 5.0, threads);
    const auto b = L.apply(u);
    ASSERT_EQ(b.size(), a.size());
    for (std::size_t i = 0; i < a.size(); ++i) ASSERT_EQ(a[i], b[i]) << "surfel " << i;
    for (const double v : L.apply(one)) ASSERT_EQ(v, 0.0);
  }
  ASSERT_GT(L1.pair_count(), std::int64_t(50) * std::int64_t(u.size()));
  const double worst = apply_against_matrix(a, L1.matrix(), u);
  std::printf("apply() against the matrix: largest difference %.2e of sum |L_ij| |u_j - u_i|\n",
              worst);
  EXPECT_LT(worst, 1e-5);
}

// Units: scaling the centres by s, the weights (areas) by s^2 and t by s^2 divides L by s^2,
// also far outside single precision's range (s = 1e-30: t = 1e-62; s = 1e30) -- apply()'s
// float kernel works in units of rho, so no exponent or coordinate leaves its range.
TEST(HeatLaplaceBeltrami, ScalesAsOneOverLengthSquared) {
  const DigitalSphere sphere = digital_sphere(0.1, false);
  std::vector<double> w(sphere.complex.areas.begin(), sphere.complex.areas.end()), u;
  for (const auto& p : sphere.complex.centres) u.push_back(std::sin(2 * p.x) + p.y * p.z);
  const double t = 4 * 0.1 * 0.1;
  const auto base = HeatLaplaceBeltrami(sphere.complex.centres, w, t, 5.0, 2).apply(u);
  double top = 0;
  for (const double v : base) top = std::max(top, std::abs(v));
  ASSERT_GT(top, 0.1);
  for (const double s : {1e-30, 1e30}) {
    std::vector<Point3<double>> c;
    std::vector<double> ws;
    for (const auto& p : sphere.complex.centres) c.push_back({p.x * s, p.y * s, p.z * s});
    for (const double a : w) ws.push_back(a * s * s);
    const auto scaled = HeatLaplaceBeltrami(c, ws, t * s * s, 5.0, 2).apply(u);
    for (std::size_t i = 0; i < u.size(); ++i)
      ASSERT_NEAR(scaled[i] * s * s, base[i], 1e-6 * top) << "s = " << s << ", surfel " << i;
  }
}

// Pinkall-Polthier: the cotangent stiffness of a planar triangulation annihilates linear
// functions at interior vertices (linear precision); S is symmetric with zero row sums.
TEST(CotanLaplacian, LinearPrecisionOnAPlanarPatchAndSymmetry) {
  std::vector<Point3<double>> v;
  const int n = 6;
  for (int y = 0; y < n; ++y)
    for (int x = 0; x < n; ++x) // a sheared grid: obtuse and acute angles
      v.push_back({x + 0.3 * y, 0.8 * y + 0.05 * x * x, 0.0});
  std::vector<std::array<std::int64_t, 4>> quads;
  for (int y = 0; y + 1 < n; ++y)
    for (int x = 0; x + 1 < n; ++x)
      quads.push_back({y * n + x, y * n + x + 1, (y + 1) * n + x + 1, (y + 1) * n + x});
  const auto tris = triangulate_quads(quads);
  const CotanLaplacian c = cotan_laplacian(v, tris);
  std::vector<double> u;
  for (const auto& p : v) u.push_back(2 * p.x - 3 * p.y + 1);
  const auto su = c.stiffness.multiply(u);
  for (int y = 1; y + 1 < n; ++y)
    for (int x = 1; x + 1 < n; ++x) EXPECT_NEAR(su[static_cast<std::size_t>(y * n + x)], 0, 1e-12);
  EXPECT_LT(c.stiffness.asymmetry(), 1e-14);
  const std::vector<double> one(v.size(), 1.0);
  for (double r : c.stiffness.multiply(one)) EXPECT_NEAR(r, 0, 1e-12);
  double total = 0;
  for (double m : c.mass) total += m;
  double area = 0; // the patch's area, by the shoelace formula of each quad's two triangles
  for (const auto& t : tris) {
    const auto &a = v[static_cast<std::size_t>(t[0])], &b = v[static_cast<std::size_t>(t[1])],
               &d = v[static_cast<std::size_t>(t[2])];
    area += 0.5 * std::abs((b.x - a.x) * (d.y - a.y) - (d.x - a.x) * (b.y - a.y));
  }
  EXPECT_NEAR(total, area, 1e-12);
  const std::vector<std::array<std::int64_t, 3>> flat = {{0, 1, 1}};
  EXPECT_THROW(cotan_laplacian(v, flat), InvalidArgument);
  // The same operator from the quad mesh (split the same way), and no other face size.
  zdg::PolygonMesh mesh;
  mesh.vertices = v;
  mesh.face_size = 4;
  for (const auto& q : quads) mesh.indices.insert(mesh.indices.end(), q.begin(), q.end());
  const CotanLaplacian m = cotan_laplacian(mesh);
  EXPECT_EQ(m.mass, c.mass);
  EXPECT_EQ(m.stiffness.multiply(u), su);
  mesh.face_size = 5;
  mesh.indices.resize(5);
  EXPECT_THROW(cotan_laplacian(mesh), InvalidArgument);
}

// The combinatorial Laplacian of the surfel adjacency: four neighbours per surfel, L 1 = 0,
// area-weighted symmetric, -L positive semi-definite.
TEST(CombinatorialLaplacian, FourNeighboursSymmetricAndNegative) {
  const DigitalSphere s = digital_sphere(0.2, false);
  const SparseMatrix L = combinatorial_laplacian(s.complex);
  const std::vector<double> one(static_cast<std::size_t>(L.rows), 1.0);
  for (double r : L.multiply(one)) EXPECT_NEAR(r, 0, 1e-9);
  EXPECT_LT(L.asymmetry(), 1e-9); // equal areas: symmetric
  std::vector<double> u;
  for (const auto& p : s.complex.centres) u.push_back(p.x * p.x - p.y + std::cos(p.z));
  const auto lu = L.multiply(u);
  double quad = 0;
  for (std::size_t i = 0; i < u.size(); ++i) quad += u[i] * lu[i];
  EXPECT_LT(quad, 0.0);
  for (std::int64_t i = 0; i < L.rows; ++i)
    EXPECT_EQ(
        L.row_start[static_cast<std::size_t>(i) + 1] - L.row_start[static_cast<std::size_t>(i)], 5);
}

} // namespace
} // namespace zdg
