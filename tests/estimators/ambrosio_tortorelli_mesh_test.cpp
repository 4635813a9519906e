// Ambrosio-Tortorelli with u on the faces and v on the vertices (estimators/
// ambrosio_tortorelli_mesh.hpp; Coeurjolly, Foare, Gueth, Lachaud, CGF 35(7) 2016). Oracles:
//  - the quadratic identity of an exact block minimiser: E(x* + t d) - E(x*) = t^2 d^T A d for
//    the u-step (x* = u, A = the u-step matrix) and the v-step, E evaluated edge by edge
//    independently of the matrices (so the matrices are those of the energy, symmetric and
//    positive semi-definite, and the solves minimise);
//  - closed forms: alpha -> inf gives u = g; u constant gives v = 1; a worked two-triangle
//    example; sum_v A_v = sum_f A_f; the unit measures of a digital surface;
//  - behaviour on shapes of known answer: a smooth sphere mesh keeps v near 1 and one
//    segment; a noisy cube mesh is segmented into its 6 faces with better normals than its
//    noisy face normals; an inpainted patch of a plane gets the plane's normal.
#include <zdg/arith/error.hpp>
#include <zdg/estimators/ambrosio_tortorelli_mesh.hpp>
#include <zdg/kernel/linalg/sparse_spd_solver.hpp>
#include <zdg/kernel/surfaces/digital_surface.hpp>

#include "tests/support/triangle_meshes.hpp"

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>
#include <random>
#include <set>
#include <vector>

namespace zdg {
namespace {

using P = Point3<double>;

double angle_degrees(P a, P b) {
  const double c = dot(a, b) / std::sqrt(dot(a, a) * dot(b, b));
  return std::acos(std::clamp(c, -1.0, 1.0)) * 180 / std::numbers::pi;
}

double quadratic_form(const SparseMatrix& a, const std::vector<double>& x) {
  const auto ax = a.multiply(x);
  double s = 0;
  for (std::size_t i = 0; i < x.size(); ++i) s += x[i] * ax[i];
  return s;
}

// The regime of raw face normals (noisy at the scale of one face): a smoothing length of
// 1 / sqrt(alpha) = 4.5 faces, the defaults of `zdg mesh at`.
ATParameters mesh_regime() {
  ATParameters p;
  p.alpha = 0.05;
  p.lambda = 0.05;
  return p;
}

ATMeshOptions exact() {
  ATMeshOptions o;
  o.solver = ATLinearSolver::cholesky;
  return o;
}

// The quadratic identity for both steps on noisy cube meshes with random v, u, directions.
RC_GTEST_PROP(AmbrosioTortorelliMesh, BlockMinimisersSatisfyTheQuadraticIdentity, ()) {
  const int n = *rc::gen::inRange(1, 4);
  const unsigned seed = *rc::gen::arbitrary<unsigned>();
  auto m = test::cube_mesh(n);
  test::add_vertex_noise(m.mesh, 0.2 / n, seed);
  const ATMesh cx = at_mesh(m.mesh);
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> unit(-1, 1);
  const auto g = mesh_face_normals(m.mesh);
  std::vector<double> v(std::size_t(cx.vertex_count)), w(g.size());
  for (auto& x : v) x = 0.5 + 0.7 * unit(rng);
  for (auto& x : w) x = unit(rng) > 0 ? 1.0 : 0.25;
  ATParameters p;
  p.alpha = 0.5 + unit(rng) * 0.4;
  p.lambda = 0.05;
  const double eps = 0.75;

  // u-step: u* solves U u = alpha A g per coordinate.
  const SparseMatrix U = at_mesh_u_matrix(cx, v, p.alpha, w);
  RC_ASSERT(U.asymmetry() == 0.0);
  const SparseSpdSolver su(U);
  std::vector<P> u(g.size());
  for (int k = 0; k < 3; ++k) {
    std::vector<double> b(g.size());
    for (std::size_t f = 0; f < g.size(); ++f)
      b[f] = p.alpha * cx.face_area[f] * w[f] * (k == 0 ? g[f].x : k == 1 ? g[f].y : g[f].z);
    const auto x = su.solve(b);
    for (std::size_t f = 0; f < g.size(); ++f) (k == 0 ? u[f].x : k == 1 ? u[f].y : u[f].z) = x[f];
  }
  std::vector<double> d(g.size());
  for (auto& x : d) x = unit(rng);
  const double t = 0.3;
  std::vector<P> moved = u;
  for (std::size_t f = 0; f < g.size(); ++f) moved[f].y += t * d[f];
  const double e0 = at_mesh_energy(cx, g, u, v, p, eps, w);
  const double e1 = at_mesh_energy(cx, g, moved, v, p, eps, w);
  const double dud = quadratic_form(U, d);
  RC_ASSERT(dud > 0);
  RC_ASSERT(std::abs((e1 - e0) - t * t * dud) <= 1e-9 * (e0 + e1));

  // v-step: v* solves V v = lambda / (4 eps) D_v 1.
  const SparseMatrix V = at_mesh_v_matrix(cx, u, p.lambda, eps);
  RC_ASSERT(V.asymmetry() == 0.0);
  std::vector<double> b(v.size());
  for (std::size_t q = 0; q < b.size(); ++q) b[q] = p.lambda / (4 * eps) * cx.vertex_area[q];
  const auto vs = SparseSpdSolver(V).solve(b);
  std::vector<double> dv(v.size()), vm = vs;
  for (auto& x : dv) x = unit(rng);
  for (std::size_t q = 0; q < v.size(); ++q) vm[q] += t * dv[q];
  const double f0 = at_mesh_energy(cx, g, u, vs, p, eps, w);
  const double f1 = at_mesh_energy(cx, g, u, vm, p, eps, w);
  const double dvd = quadratic_form(V, dv);
  RC_ASSERT(dvd > 0);
  RC_ASSERT(std::abs((f1 - f0) - t * t * dvd) <= 1e-9 * (f0 + f1));
}

// The dual areas partition the area: sum_v A_v = sum_f A_f, on any mesh.
RC_GTEST_PROP(AmbrosioTortorelliMesh, VertexAreasSumToTheFaceAreas, ()) {
  const int n = *rc::gen::inRange(1, 5);
  auto m = test::sphere_mesh(n);
  test::add_vertex_noise(m.mesh, 0.1 / n, *rc::gen::arbitrary<unsigned>());
  const ATMesh cx = at_mesh(m.mesh);
  double a = 0, b = 0;
  for (const double x : cx.face_area) a += x;
  for (const double x : cx.vertex_area) b += x;
  RC_ASSERT(std::abs(a - b) <= 1e-12 * a);
  RC_ASSERT(cx.edge_count() == 3 * cx.face_count() / 2); // closed triangle mesh
}

// Two triangles of the unit square split by its diagonal: the diagonal's jump weight is
// l / d = sqrt(2) / (2 sqrt(2) / 6) = 3 whatever the unit, A_f = 1 / (2 h^2) with h = (4 +
// sqrt 2) / 5 the mean edge length, and with v = 1, alpha = 1, g0 = e_x, g1 = e_y the u-step is
// [[A + 3, -3], [-3, A + 3]] u = A g: u0 = ((A + 3) e_x + 3 e_y) / (A + 6), u1 symmetric.
TEST(AmbrosioTortorelliMesh, WorkedExampleTwoTriangles) {
  PolygonMesh mesh;
  mesh.face_size = 3;
  mesh.vertices = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
  mesh.indices = {0, 1, 2, 0, 2, 3};
  const ATMesh cx = at_mesh(mesh);
  ASSERT_EQ(cx.edge_count(), 5);
  const double h = (4 + std::sqrt(2.0)) / 5;
  EXPECT_NEAR(cx.unit, h, 1e-15);
  const double A = 0.5 / (h * h);
  EXPECT_NEAR(cx.face_area[0], A, 1e-14);
  for (std::size_t e = 0; e < 5; ++e) {
    const bool diagonal = cx.edges[e].a == 0 && cx.edges[e].b == 2;
    EXPECT_NEAR(cx.jump_weight[e], diagonal ? 3.0 : 0.0, 1e-14) << e;
  }
  EXPECT_NEAR(cx.vertex_area[0], 2 * A / 3, 1e-14); // in both triangles
  EXPECT_NEAR(cx.vertex_area[1], A / 3, 1e-14);
  const std::vector<double> v(4, 1.0);
  const SparseMatrix U = at_mesh_u_matrix(cx, v, 1.0);
  EXPECT_NEAR(U.at(0, 0), A + 3, 1e-14);
  EXPECT_NEAR(U.at(0, 1), -3, 1e-14);
  // The first u-step of the minimisation (v = 1): U u = alpha A g, here for x.
  const SparseSpdSolver s(U);
  const auto x = s.solve(std::vector<double>{A, 0});
  EXPECT_NEAR(x[0], (A + 3) / (A + 6), 1e-12);
  EXPECT_NEAR(x[1], 3 / (A + 6), 1e-12);
}

TEST(AmbrosioTortorelliMesh, LargeAlphaGivesTheData) {
  auto m = test::cube_mesh(4);
  test::add_vertex_noise(m.mesh, 0.05, 7);
  const ATMesh cx = at_mesh(m.mesh);
  const auto g = mesh_face_normals(m.mesh);
  for (const double alpha : {1e4, 1e8}) {
    ATParameters p;
    p.alpha = alpha;
    const auto r = at_mesh_normals(cx, g, p, exact());
    double worst = 0;
    for (std::size_t f = 0; f < g.size(); ++f) {
      const P d = r.u[f] - g[f];
      worst = std::max(worst, std::sqrt(dot(d, d)));
    }
    // |u - g| = O(1 / alpha): the coupling's rows sum to at most a few units.
    EXPECT_LT(worst, 100 / alpha) << alpha;
  }
}

TEST(AmbrosioTortorelliMesh, ConstantUGivesVOne) {
  const auto m = test::sphere_mesh(3);
  const ATMesh cx = at_mesh(m.mesh);
  const std::vector<P> u(std::size_t(cx.face_count()), P{0.3, -0.2, 0.9});
  const SparseMatrix V = at_mesh_v_matrix(cx, u, 0.015, 0.5);
  std::vector<double> b(std::size_t(cx.vertex_count));
  for (std::size_t q = 0; q < b.size(); ++q) b[q] = 0.015 / 2 * cx.vertex_area[q];
  for (const double x : SparseSpdSolver(V).solve(b)) EXPECT_NEAR(x, 1.0, 1e-12);
}

TEST(AmbrosioTortorelliMesh, EnergyDoesNotIncreaseAtAnyHalfStep) {
  auto m = test::cube_mesh(6);
  test::add_vertex_noise(m.mesh, 0.02, 3);
  const ATMesh cx = at_mesh(m.mesh);
  const auto g = mesh_face_normals(m.mesh);
  ATMeshOptions cg;
  cg.cg_tolerance = 1e-12;
  for (const auto& o : {exact(), cg}) {
    const auto r = at_mesh_normals(cx, g, {}, o);
    for (std::size_t i = 1; i < r.steps.size(); ++i) {
      if (r.steps[i].kind == ATStep::Kind::start) continue;
      EXPECT_LE(r.steps[i].energy, r.steps[i - 1].energy * (1 + 1e-9)) << i << " " << r.solver;
    }
    for (const auto& n : r.normals) EXPECT_NEAR(dot(n, n), 1.0, 1e-12);
  }
}

// CG and Cholesky reach the same minimiser (up to CG's tolerance).
TEST(AmbrosioTortorelliMesh, ConjugateGradientsAgreeWithCholesky) {
  auto m = test::cube_mesh(5);
  test::add_vertex_noise(m.mesh, 0.03, 11);
  const ATMesh cx = at_mesh(m.mesh);
  const auto g = mesh_face_normals(m.mesh);
  ATMeshOptions cg;
  cg.cg_tolerance = 1e-12;
  cg.threads = 2;
  const auto a = at_mesh_normals(cx, g, {}, exact());
  const auto b = at_mesh_normals(cx, g, {}, cg);
  ASSERT_EQ(a.iterations, b.iterations);
  for (std::size_t q = 0; q < a.v.size(); ++q) EXPECT_NEAR(a.v[q], b.v[q], 1e-8);
  EXPECT_GT(b.cg_iterations, 0);
  EXPECT_EQ(b.solver, "conjugate-gradient");
}

// The conjugate gradients sum their dot products by fixed blocks of rows in block order, so
// the minimiser is the same, bit for bit, on any number of threads (a mesh of several blocks).
TEST(AmbrosioTortorelliMesh, ResultDoesNotDependOnTheThreadCount) {
  auto m = test::cube_mesh(30); // 10,800 faces: 3 blocks of rows in the u-step
  test::add_vertex_noise(m.mesh, 0.01, 5);
  const ATMesh cx = at_mesh(m.mesh);
  const auto g = mesh_face_normals(m.mesh);
  ATParameters p;
  p.max_iterations = 2;
  ATMeshOptions o;
  o.threads = 1;
  const auto one = at_mesh_normals(cx, g, p, o);
  for (const unsigned t : {2u, 3u}) {
    o.threads = t;
    const auto many = at_mesh_normals(cx, g, p, o);
    EXPECT_EQ(many.cg_iterations, one.cg_iterations);
    EXPECT_EQ(many.v, one.v);
    for (std::size_t f = 0; f < one.u.size(); ++f) {
      EXPECT_EQ(many.u[f].x, one.u[f].x);
      EXPECT_EQ(many.u[f].y, one.u[f].y);
      EXPECT_EQ(many.u[f].z, one.u[f].z);
    }
  }
}

// A smooth sphere mesh with its own face normals (no noise): no discontinuity, v stays near 1
// (the normal turns by about 0.05 rad per face at n = 32: v = c / (c + |delta u|^2 l / d) is
// about 0.93 with c = lambda / (4 eps)), one segment, normals close to the input.
TEST(AmbrosioTortorelliMesh, SmoothSphereKeepsVNearOne) {
  const auto m = test::sphere_mesh(32);
  const ATMesh cx = at_mesh(m.mesh);
  const auto g = mesh_face_normals(m.mesh);
  ATMeshOptions o;
  o.threads = 2;
  const auto r = at_mesh_normals(cx, g, mesh_regime(), o);
  const auto [lo, hi] = std::minmax_element(r.v.begin(), r.v.end());
  EXPECT_GT(*lo, 0.85);
  EXPECT_LE(*hi, 1.0 + 1e-9);
  EXPECT_EQ(r.segments, 1);
  double mean = 0;
  for (std::size_t f = 0; f < g.size(); ++f) mean += angle_degrees(r.normals[f], g[f]);
  EXPECT_LT(mean / double(g.size()), 2.0);
}

// A cube mesh with vertex noise: AT's segments are the 6 faces (each large segment lies on one
// side; they cover most faces) and its normals are closer to the sides' than the noisy ones.
TEST(AmbrosioTortorelliMesh, NoisyCubeIsSegmentedIntoItsSixFaces) {
  const int n = 16;
  auto m = test::cube_mesh(n);
  test::add_vertex_noise(m.mesh, 0.15 * 2.0 / n, 5);
  const ATMesh cx = at_mesh(m.mesh);
  const auto g = mesh_face_normals(m.mesh);
  ATMeshOptions o;
  o.threads = 2;
  const auto r = at_mesh_normals(cx, g, mesh_regime(), o);
  const auto faces = std::size_t(cx.face_count());
  std::map<std::int64_t, std::map<int, std::int64_t>> sides; // segment -> side -> faces
  for (std::size_t f = 0; f < faces; ++f) ++sides[r.segment[f]][m.side[f]];
  int large = 0;
  std::int64_t covered = 0;
  std::set<int> seen;
  for (const auto& [label, count] : sides) {
    std::int64_t total = 0;
    for (const auto& [s, c] : count) total += c;
    if (total < std::int64_t(faces / 100)) continue;
    ++large;
    ASSERT_EQ(count.size(), 1u) << "segment " << label << " spans several sides";
    seen.insert(count.begin()->first);
    covered += total;
  }
  EXPECT_EQ(large, 6);
  EXPECT_EQ(seen.size(), 6u);
  EXPECT_GT(double(covered), 0.9 * double(faces));
  double before = 0, after = 0;
  for (std::size_t f = 0; f < faces; ++f) {
    before += angle_degrees(g[f], test::side_normal(m.side[f]));
    after += angle_degrees(r.normals[f], test::side_normal(m.side[f]));
  }
  EXPECT_LT(after, 0.1 * before) << "mean angle before " << before / double(faces) << ", after "
                                 << after / double(faces);
}

// A plane whose normals are scrambled in a square patch that is inpainted (weight 0): the
// patch gets the plane's normal (the v-weighted harmonic extension of a constant).
TEST(AmbrosioTortorelliMesh, InpaintedPatchOfAPlaneGetsThePlanesNormal) {
  const int n = 20;
  const auto m = test::plane_mesh(n);
  const ATMesh cx = at_mesh(m.mesh);
  std::vector<P> g(std::size_t(cx.face_count()), P{0, 0, 1});
  std::vector<double> w(g.size(), 1.0);
  std::mt19937_64 rng(1);
  std::normal_distribution<double> d;
  int masked = 0;
  for (std::size_t f = 0; f < g.size(); ++f) {
    const auto q = cx.face_vertices[3 * f];
    const auto x = q % (n + 1), y = q / (n + 1);
    if (x >= 7 && x < 13 && y >= 7 && y < 13) {
      g[f] = P{d(rng), d(rng), d(rng)};
      w[f] = 0;
      ++masked;
    }
  }
  ASSERT_EQ(masked, 72);
  ATMeshOptions o;
  o.cg_tolerance = 1e-12;
  const auto r = at_mesh_normals(cx, g, {}, o, w);
  for (std::size_t f = 0; f < g.size(); ++f)
    EXPECT_LT(angle_degrees(r.normals[f], P{0, 0, 1}), 1e-6) << f;
  for (const double x : r.v) EXPECT_NEAR(x, 1.0, 1e-9);
  EXPECT_EQ(r.segments, 1);
}

// On the primal mesh of a digital surface (an axis-aligned cube of 4^3 voxels) every face has
// area 1, every edge length 1, d_e = 1, and A_v = (surfels at the pointel) / 4.
TEST(AmbrosioTortorelliMesh, DigitalSurfaceHasUnitMeasures) {
  const VoxelPredicate inside = [](const Voxel& z) {
    return z.x >= 0 && z.x < 4 && z.y >= 0 && z.y < 4 && z.z >= 0 && z.z < 4;
  };
  const auto surfels = boundary_surfels(inside, VoxelBox{{-2, -2, -2}, {6, 6, 6}});
  const SurfelComplex c = surfel_complex(primal_surface(surfels), 0.5);
  const ATMesh cx = at_mesh(c);
  EXPECT_EQ(cx.face_count(), 96);
  EXPECT_NEAR(cx.unit, 0.5, 1e-15);
  for (const double a : cx.face_area) EXPECT_NEAR(a, 1.0, 1e-14);
  for (std::size_t e = 0; e < cx.edges.size(); ++e) {
    EXPECT_NEAR(cx.jump_weight[e], 1.0, 1e-14);
    EXPECT_NEAR(cx.edge_weight[e], 1.0, 1e-14);
  }
  std::vector<int> corners(std::size_t(cx.vertex_count), 0);
  for (const auto q : cx.face_vertices) ++corners[std::size_t(q)];
  for (std::size_t q = 0; q < corners.size(); ++q)
    EXPECT_NEAR(cx.vertex_area[q], corners[q] / 4.0, 1e-14);
}

TEST(AmbrosioTortorelliMesh, BadInputIsOneLine) {
  const auto expect_error = [](auto f, const std::string& part) {
    try {
      f();
      ADD_FAILURE() << "no error, expected " << part;
    } catch (const InvalidArgument& e) {
      EXPECT_NE(std::string(e.what()).find(part), std::string::npos) << e.what();
      EXPECT_EQ(std::string(e.what()).find('\n'), std::string::npos) << e.what();
    }
  };
  PolygonMesh empty;
  empty.face_size = 3;
  expect_error([&] { at_mesh(empty); }, "empty");
  PolygonMesh fin; // three triangles on the edge (0, 1)
  fin.face_size = 3;
  fin.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}};
  fin.indices = {0, 1, 2, 1, 0, 3, 0, 1, 4};
  expect_error([&] { at_mesh(fin); }, "not a manifold");
  PolygonMesh flat;
  flat.face_size = 3;
  flat.vertices = {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}};
  flat.indices = {0, 1, 2};
  expect_error([&] { at_mesh(flat); }, "zero area");
  PolygonMesh twice;
  twice.face_size = 3;
  twice.vertices = {{0, 0, 0}, {1, 0, 0}};
  twice.indices = {0, 1, 0};
  expect_error([&] { at_mesh(twice); }, "twice");
  const auto m = test::plane_mesh(2);
  const ATMesh cx = at_mesh(m.mesh);
  const std::vector<P> g(8, P{0, 0, 1});
  expect_error([&] { at_mesh_normals(cx, std::vector<P>(3, P{0, 0, 1})); }, "3 entries");
  expect_error([&] { at_mesh_normals(cx, g, {}, {}, std::vector<double>(8, 0.0)); },
               "all inpainted");
  expect_error([&] { at_mesh_normals(cx, g, {}, {}, std::vector<double>(8, -1.0)); },
               "non-negative");
  ATParameters p;
  p.lambda = 0;
  expect_error([&] { at_mesh_normals(cx, g, p); }, "lambda must be positive");
  ATMeshOptions o;
  o.threshold = 2;
  expect_error([&] { at_mesh_normals(cx, g, {}, o); }, "threshold");
}

} // namespace
} // namespace zdg
