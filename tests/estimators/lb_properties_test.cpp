// The property table of the Laplace-Beltrami operators on digital surfaces (Caissard,
// Coeurjolly, Lachaud, Roussillon, JMIV 2019, Table 1; Wardetzky et al., "Discrete Laplace
// operators: no free lunch", SGP 2007, for the list of properties), measured here on the same
// digital surfaces for the heat-kernel operator (estimators/heat_laplace_beltrami.hpp), the
// cotangent Laplacian of the triangulated primal surface and the combinatorial Laplacian
// (kernel/linalg/cotan_laplacian.hpp) and the cotangent Laplacian of the marching-cubes mesh
// (kernel/surfaces/marching_cubes.hpp). Each property is measured, printed as one row of the table
// (papers/lb-digital/README.md quotes it) and checked against what the operator's theory says:
//   constants   max |L 1|                                  (all: 0)
//   symmetry    max |M_i L_ij - M_j L_ji| / max |M L|        (all: 0 for their mass M)
//   locality    most stored entries in a row               (heat: grows like t / h^2)
//   positivity  min off-diagonal entry / max |L|           (all: >= 0)
//   PSD         min Rayleigh quotient -u^T M L u / u^T M u over random u (all: >= 0)
//   linear      max |L u| for u linear on the faces of a rotated digital cube, away from its
//               edges, relative to |grad u| / h (no operator is exact on a staircase; the
//               heat operator's bias falls with h)
//   convergence l_inf error of L x against Delta_S x = -2x on the unit sphere at h = 0.1 and
//               0.05 (heat: falls; cotangent and combinatorial: do not)
#include <zdg/estimators/digital_integration.hpp>
#include <zdg/estimators/heat_laplace_beltrami.hpp>
#include <zdg/estimators/ii_3d.hpp>
#include <zdg/kernel/linalg/cotan_laplacian.hpp>
#include <zdg/kernel/surfaces/marching_cubes.hpp>

#include "tests/support/digital_sphere.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>
#include <string>

namespace zdg {
namespace {

using P3 = Point3<double>;

// An operator as L = diag(1 / M) K with K stored (so that M L = K), on some points.
struct Operator {
  SparseMatrix k;         // M L
  std::vector<double> m;  // mass
  std::vector<P3> points; // where it is evaluated
};

// heat: M = w, K = W L; cotan: M = lumped mass, K = S; combinatorial: M = area, K = area L.
Operator heat_operator(const SurfelComplex& c, const std::vector<double>& w, double h) {
  const HeatLaplaceBeltrami L(c.centres, w, heat_kernel_time(h, 0.4), 5.0, 2);
  SparseMatrix k = L.matrix();
  for (std::int64_t i = 0; i < k.rows; ++i)
    for (auto p = k.row_start[std::size_t(i)]; p < k.row_start[std::size_t(i) + 1]; ++p)
      k.value[std::size_t(p)] *= w[std::size_t(i)];
  return {std::move(k), w, c.centres};
}

Operator cotan_operator(const SurfelComplex& c) {
  const CotanLaplacian L = cotan_laplacian(c.pointels, triangulate_quads(c.surfels));
  return {L.stiffness, L.mass, c.pointels};
}

// The cotangent Laplacian of the marching-cubes mesh of the digitization ((6,26), vertices at
// the surfel centres: level 1/2 between voxel centres), at its vertices: M = lumped mass.
Operator marching_cubes_operator(const VoxelPredicate& inside, const VoxelBox& b, double h) {
  const PolygonMesh mesh = marching_cubes(inside, b, h, 1);
  const CotanLaplacian L = cotan_laplacian(mesh);
  return {L.stiffness, L.mass, mesh.vertices};
}

Operator combinatorial_operator(const SurfelComplex& c) {
  SparseMatrix k = combinatorial_laplacian(c);
  for (std::int64_t i = 0; i < k.rows; ++i)
    for (auto p = k.row_start[std::size_t(i)]; p < k.row_start[std::size_t(i) + 1]; ++p)
      k.value[std::size_t(p)] *= c.areas[std::size_t(i)];
  return {std::move(k), c.areas, c.centres};
}

std::vector<double> apply_operator(const Operator& op, const std::vector<double>& u) {
  auto r = op.k.multiply(u);
  for (std::size_t i = 0; i < r.size(); ++i) r[i] = op.m[i] > 0 ? r[i] / op.m[i] : 0;
  return r;
}

struct Row {
  double constants = 0, symmetry = 0, positivity = 0, psd = 0, linear = 0;
  std::int64_t locality = 0;
  double error_coarse = 0, error_fine = 0;
};

void measure_algebra(const Operator& op, Row& row) {
  const auto& k = op.k;
  double scale = 0;
  for (double v : k.value) scale = std::max(scale, std::abs(v));
  std::vector<double> one(op.m.size(), 1.0);
  for (double v : apply_operator(op, one)) row.constants = std::max(row.constants, std::abs(v));
  row.symmetry = k.asymmetry() / scale;
  row.positivity = 0;
  for (std::int64_t i = 0; i < k.rows; ++i) {
    row.locality =
        std::max(row.locality, k.row_start[std::size_t(i) + 1] - k.row_start[std::size_t(i)]);
    for (auto p = k.row_start[std::size_t(i)]; p < k.row_start[std::size_t(i) + 1]; ++p)
      if (k.column[std::size_t(p)] != i)
        row.positivity = std::min(row.positivity, k.value[std::size_t(p)] / scale);
  }
  std::mt19937_64 rng(2019);
  std::normal_distribution<double> g;
  row.psd = std::numeric_limits<double>::infinity();
  for (int trial = 0; trial < 50; ++trial) {
    std::vector<double> u(op.m.size());
    for (auto& x : u) x = g(rng);
    const auto ku = k.multiply(u);
    double num = 0, den = 0;
    for (std::size_t i = 0; i < u.size(); ++i) {
      num -= u[i] * ku[i];
      den += u[i] * u[i] * op.m[i];
    }
    row.psd = std::min(row.psd, num / den);
  }
}

double sphere_error(const Operator& op) {
  const auto u = [&] {
    std::vector<double> v;
    for (const auto& p : op.points) v.push_back(p.x);
    return v;
  }();
  const auto lu = apply_operator(op, u);
  double e = 0;
  for (std::size_t i = 0; i < u.size(); ++i) {
    const P3 p = op.points[i];
    const double r = std::sqrt(p.x * p.x + p.y * p.y + p.z * p.z);
    e = std::max(e, std::abs(lu[i] + 2 * p.x / r));
  }
  return e;
}

// The cube |Q x|_inf <= a (Q a rotation) digitized at step h, with the true distance of a
// point to the cube's edges (to keep the faces' interiors).
struct RotatedCube {
  double q[3][3];
  double a;
  P3 local(P3 p) const {
    return {q[0][0] * p.x + q[0][1] * p.y + q[0][2] * p.z,
            q[1][0] * p.x + q[1][1] * p.y + q[1][2] * p.z,
            q[2][0] * p.x + q[2][1] * p.y + q[2][2] * p.z};
  }
  double edge_distance(P3 p) const { // distance from the projection on a face to its boundary
    const P3 l = local(p);
    const double c[3] = {std::abs(l.x), std::abs(l.y), std::abs(l.z)};
    const int f = int(std::max_element(c, c + 3) - c);
    double d = std::numeric_limits<double>::infinity();
    for (int i = 0; i < 3; ++i)
      if (i != f) d = std::min(d, a - c[i]);
    return d;
  }
};

TEST(LaplaceBeltramiProperties, MeasuredTable) {
  // A rotation by Rodrigues' formula about (1, 2, 3) by 0.5 rad.
  RotatedCube cube{{}, 12};
  {
    const double n = std::sqrt(14.0), kx = 1 / n, ky = 2 / n, kz = 3 / n, th = 0.5;
    const double c = std::cos(th), s = std::sin(th), v = 1 - c;
    const double m[3][3] = {{c + kx * kx * v, kx * ky * v - kz * s, kx * kz * v + ky * s},
                            {ky * kx * v + kz * s, c + ky * ky * v, ky * kz * v - kx * s},
                            {kz * kx * v - ky * s, kz * ky * v + kx * s, c + kz * kz * v}};
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) cube.q[i][j] = m[i][j];
  }
  const double h = 1;
  const VoxelPredicate inside = [&](const Voxel& z) {
    const P3 l = cube.local({double(z.x), double(z.y), double(z.z)});
    return std::max({std::abs(l.x), std::abs(l.y), std::abs(l.z)}) <= cube.a;
  };
  const std::int64_t n = 22;
  const VoxelBox box{{-n, -n, -n}, {n, n, n}};
  const auto surfels = boundary_surfels(inside, box);
  const SurfelComplex cc = surfel_complex(primal_surface(surfels), h);
  std::vector<P3> normals;
  for (const auto& c : ii_principal_curvatures(inside, box, surfels, h, 3.0, 2))
    normals.push_back(c.normal);
  const auto wc = surfel_weights(surfel_measure(normals, cc.normals), cc.areas);

  const test::DigitalSphere s1 = test::digital_sphere(0.1), s2 = test::digital_sphere(0.05);
  const char* names[4] = {"heat kernel (t = h^0.4)", "cotangent (primal, split)",
                          "combinatorial (4 neighbours)", "cotangent (marching cubes)"};
  Row rows[4];
  for (int o = 0; o < 4; ++o) {
    const auto make = [&](const test::DigitalSphere& s) {
      return o == 0   ? heat_operator(s.complex, s.weights, s.h)
             : o == 1 ? cotan_operator(s.complex)
             : o == 2 ? combinatorial_operator(s.complex)
                      : marching_cubes_operator(s.inside, s.box, s.h);
    };
    const Operator a = make(s1), b = make(s2);
    measure_algebra(a, rows[o]);
    rows[o].error_coarse = sphere_error(a);
    rows[o].error_fine = sphere_error(b);
    // Linear precision on the rotated cube's faces, 8 units (heat: 5 sqrt(2t) = 7.1) away from
    // the edges; u = g . x with |g| = 1.
    const Operator c = o == 0   ? heat_operator(cc, wc, h)
                       : o == 1 ? cotan_operator(cc)
                       : o == 2 ? combinatorial_operator(cc)
                                : marching_cubes_operator(inside, box, h);
    std::vector<double> u;
    const P3 g{0.48, -0.6, 0.64};
    for (const auto& p : c.points) u.push_back(g.x * p.x + g.y * p.y + g.z * p.z);
    const auto lu = apply_operator(c, u);
    for (std::size_t i = 0; i < u.size(); ++i)
      if (cube.edge_distance(c.points[i]) > 8)
        rows[o].linear = std::max(rows[o].linear, std::abs(lu[i]));
  }
  std::printf("\n| operator | L 1 | symmetry of M L | entries per row | min off-diagonal | min "
              "Rayleigh -u'MLu/u'Mu | linear u on tilted faces: max abs(L u) | l_inf error of L "
              "x on the unit sphere, h = 0.1 / 0.05 |\n|---|---|---|---|---|---|---|---|\n");
  for (int o = 0; o < 4; ++o) {
    const Row& r = rows[o];
    std::printf("| %s | %.1e | %.1e | %lld | %.1e | %.3g | %.3g | %.3f / %.3f |\n", names[o],
                r.constants, r.symmetry, static_cast<long long>(r.locality), r.positivity, r.psd,
                r.linear, r.error_coarse, r.error_fine);
  }
  for (const Row& r : rows) {
    EXPECT_LT(r.constants, 1e-9);
    EXPECT_LT(r.symmetry, 1e-12);
    EXPECT_GE(r.positivity, 0.0);
    EXPECT_GE(r.psd, 0.0);
  }
  // Locality: the cotangent and combinatorial stencils are the 1-rings (at most 13: a pointel
  // of six quads at a saddle, and 5
  // entries); the heat kernel spans hundreds of surfels.
  EXPECT_LE(rows[1].locality, 13);
  EXPECT_EQ(rows[2].locality, 5);
  EXPECT_GT(rows[0].locality, 100);
  // A marching-cubes vertex (a surfel) lies in the 4 cubes of its pointels, with at most three
  // neighbours in each (its two along the polygon, a diagonal or a fan centre): 13 entries.
  EXPECT_LE(rows[3].locality, 13);
  // Convergence: only the heat operator's error falls, and it is the smallest at h = 0.05.
  EXPECT_LT(rows[0].error_fine, rows[0].error_coarse);
  EXPECT_GE(rows[1].error_fine, rows[1].error_coarse);
  EXPECT_GE(rows[2].error_fine, rows[2].error_coarse);
  EXPECT_GE(rows[3].error_fine, rows[3].error_coarse);
  EXPECT_LT(rows[0].error_fine, rows[1].error_fine);
  EXPECT_LT(rows[0].error_fine, rows[2].error_fine);
  EXPECT_LT(rows[0].error_fine, rows[3].error_fine);
}

} // namespace
} // namespace zdg
