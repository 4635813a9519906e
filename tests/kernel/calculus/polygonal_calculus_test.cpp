// The corrected polygonal calculus: de Goes, Butts, Desbrun's identities as properties on random
// planar polygons in random planes (U V = I - n n^T, the gradient's linear precision, P D u = 0
// on linear u, D 1 = 0, L symmetric positive semi-definite), the Laplacian's linear precision on
// a perturbed planar quad grid, the re-embedding (a face's normal becomes the given one), the
// global matrices against the per-face blocks, and the bad inputs.
#include <zdg/arith/error.hpp>
#include <zdg/kernel/calculus/polygonal_calculus.hpp>

#include "tests/support/voxel_mesh.hpp"

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <cmath>
#include <numbers>

namespace zdg {
namespace {

using P3 = Point3<double>;

P3 unit(P3 v) {
  return (1.0 / std::sqrt(dot(v, v))) * v;
}

// A random star-shaped polygon of n vertices in a random plane through a random point, and the
// plane's frame (normal last).
struct Polygon {
  std::vector<P3> x;
  P3 a, b, n;
};

Polygon random_polygon() {
  const int n = *rc::gen::inRange(3, 9);
  const auto g = rc::gen::map(rc::gen::inRange(-1000, 1000), [](int v) { return v / 500.0; });
  P3 nrm{*g, *g, *g};
  RC_PRE(dot(nrm, nrm) > 0.01);
  nrm = unit(nrm);
  P3 a = std::abs(nrm.x) < 0.9 ? P3{1, 0, 0} : P3{0, 1, 0};
  a = unit(a - dot(a, nrm) * nrm);
  const P3 b = cross(nrm, a);
  const P3 o{*g, *g, *g};
  Polygon p{{}, a, b, nrm};
  for (int i = 0; i < n; ++i) {
    const double t = 2 * std::numbers::pi * (i + 0.1 + 0.8 * *rc::gen::inRange(0, 100) / 100.0) / n;
    const double r = 0.5 + *rc::gen::inRange(0, 100) / 100.0;
    p.x.push_back(o + (r * std::cos(t)) * a + (r * std::sin(t)) * b);
  }
  return p;
}

PolygonMesh one_face(const std::vector<P3>& x) {
  PolygonMesh m;
  m.face_size = int(x.size());
  m.vertices = x;
  for (std::size_t i = 0; i < x.size(); ++i) m.indices.push_back(std::int64_t(i));
  return m;
}

RC_GTEST_PROP(PolygonalCalculus, IdentitiesOfAPlanarFace, ()) {
  const Polygon poly = random_polygon();
  const PolygonalCalculus calc(one_face(poly.x));
  const PolygonalFace& F = calc.face(0);
  const int n = F.n;
  RC_ASSERT(std::abs(dot(F.normal, poly.n) - 1) < 1e-9); // counterclockwise about n
  // U V = I - n n^T
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) {
      double s = 0;
      for (int k = 0; k < n; ++k) s += F.U[std::size_t(r * n + k)] * F.V[std::size_t(k * 3 + c)];
      const double nr[3] = {F.normal.x, F.normal.y, F.normal.z};
      RC_ASSERT(std::abs(s - ((r == c) - nr[r] * nr[c])) < 1e-9);
    }
  // u = g . x: G u = the in-plane part of g, C u = n x it, P D u = 0, D 1 = 0
  const P3 g{0.3, -1.7, 2.2};
  const P3 gt = g - dot(g, F.normal) * F.normal;
  std::vector<double> u;
  for (const auto& p : F.x) u.push_back(dot(g, p));
  for (int r = 0; r < 3; ++r) {
    double s = 0, c = 0;
    for (int k = 0; k < n; ++k) {
      s += F.G[std::size_t(r * n + k)] * u[std::size_t(k)];
      c += F.C[std::size_t(r * n + k)] * u[std::size_t(k)];
    }
    const P3 ng = cross(F.normal, gt);
    RC_ASSERT(std::abs(s - (r == 0 ? gt.x : r == 1 ? gt.y : gt.z)) < 1e-9);
    RC_ASSERT(std::abs(c - (r == 0 ? ng.x : r == 1 ? ng.y : ng.z)) < 1e-9);
  }
  std::vector<double> du(std::size_t(n), 0.0);
  for (int i = 0; i < n; ++i) {
    double one = 0;
    for (int k = 0; k < n; ++k) {
      du[std::size_t(i)] += F.D[std::size_t(i * n + k)] * u[std::size_t(k)];
      one += F.D[std::size_t(i * n + k)];
    }
    RC_ASSERT(one == 0);
  }
  for (int i = 0; i < n; ++i) {
    double s = 0;
    for (int k = 0; k < n; ++k) s += F.P[std::size_t(i * n + k)] * du[std::size_t(k)];
    RC_ASSERT(std::abs(s) < 1e-9);
  }
  // L symmetric, positive semi-definite, L 1 = 0
  const double lambda = *rc::gen::inRange(1, 100) / 10.0;
  const auto L = F.L(lambda);
  for (int i = 0; i < n; ++i) {
    double row = 0;
    for (int j = 0; j < n; ++j) {
      RC_ASSERT(std::abs(L[std::size_t(i * n + j)] - L[std::size_t(j * n + i)]) < 1e-9);
      row += L[std::size_t(i * n + j)];
    }
    RC_ASSERT(std::abs(row) < 1e-9);
  }
  std::vector<double> v;
  for (int i = 0; i < n; ++i) v.push_back(*rc::gen::inRange(-100, 100) / 10.0);
  double q = 0;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j)
      q += v[std::size_t(i)] * L[std::size_t(i * n + j)] * v[std::size_t(j)];
  RC_ASSERT(q > -1e-9);
}

// A planar grid of quads with its interior vertices moved at random within their cells, in a
// tilted plane: L u = 0 at every interior vertex for linear u (linear precision).
TEST(PolygonalCalculus, LinearPrecisionOnAPerturbedPlanarGrid) {
  const int N = 8;
  const P3 a = unit({1, 2, 0.5}), n0 = unit({-2, 1, 3});
  const P3 b = unit(cross(n0, a)); // a unit frame (a, b) of the plane
  const P3 nrm = unit(cross(a, b));
  PolygonMesh m;
  m.face_size = 4;
  std::uint32_t seed = 12345;
  auto rnd = [&] {
    seed = seed * 1664525u + 1013904223u;
    return double(seed >> 8) / double(1u << 24) - 0.5;
  };
  for (int j = 0; j <= N; ++j)
    for (int i = 0; i <= N; ++i) {
      const bool inner = i > 0 && j > 0 && i < N && j < N;
      const double s = i + (inner ? 0.4 * rnd() : 0), t = j + (inner ? 0.4 * rnd() : 0);
      m.vertices.push_back(s * a + t * b);
    }
  for (int j = 0; j < N; ++j)
    for (int i = 0; i < N; ++i) {
      const std::int64_t v = j * (N + 1) + i;
      m.indices.insert(m.indices.end(), {v, v + 1, v + N + 2, v + N + 1});
    }
  const PolygonalCalculus calc(m);
  EXPECT_NEAR(dot(calc.face(0).normal, nrm), 1, 1e-12);
  const P3 g{1.5, -0.25, 0.75};
  std::vector<double> u;
  for (const auto& p : m.vertices) u.push_back(dot(g, p));
  for (const double lambda : {0.1, 1.0, 10.0}) {
    const auto lu = calc.laplacian(lambda).multiply(u);
    for (int j = 1; j < N; ++j)
      for (int i = 1; i < N; ++i) EXPECT_NEAR(lu[std::size_t(j * (N + 1) + i)], 0, 1e-10);
    // the weak divergence of the gradient field is -L u everywhere
    const auto grad = calc.gradient().multiply(u);
    const auto div = calc.divergence(lambda).multiply(grad);
    for (std::size_t v = 0; v < lu.size(); ++v) EXPECT_NEAR(div[v], -lu[v], 1e-10);
  }
  // the global matrices are the faces' blocks: D 1 = 0, L symmetric
  const std::vector<double> one(m.vertices.size(), 1.0);
  for (const double x : calc.derivative().multiply(one)) EXPECT_EQ(x, 0);
  EXPECT_LT(calc.laplacian(1).asymmetry(), 1e-12);
  EXPECT_EQ(calc.corner_count(), 4 * N * N);
  double area = 0;
  for (const double x : calc.vertex_masses()) area += x;
  EXPECT_NEAR(area, N * N, 1e-6); // the perturbed grid tiles the same square
}

// laplacian() builds its rows from the vertex-face incidence; oracle: the faces' blocks
// face(f).L(lambda) summed by triplets (the definition L = sum_f P_f^T L_f P_f). Random voxel
// sets (non-planar neighbourhoods, pinched vertices), random per-face normals for the
// re-embedding, random lambda; the result does not depend on the worker count.
RC_GTEST_PROP(PolygonalCalculus, LaplacianRowsAreTheSumOfTheFaceBlocks, ()) {
  const int side = *rc::gen::inRange(2, 6);
  const auto bits = *rc::gen::container<std::vector<bool>>(std::size_t(side * side * side),
                                                           rc::gen::arbitrary<bool>());
  const PolygonMesh m = test::voxel_primal_mesh(
      [&](std::int64_t x, std::int64_t y, std::int64_t z) {
        return bits[std::size_t((z * side + y) * side + x)];
      },
      0, side - 1);
  RC_PRE(m.face_count() > 0);
  std::vector<P3> normals;
  for (std::int64_t f = 0; f < m.face_count(); ++f) {
    // the face's own normal, tilted at random (less than 45 degrees: the face stays non-degenerate)
    const auto idx = m.face(f);
    const P3 own = unit(cross(m.vertices[std::size_t(idx[1])] - m.vertices[std::size_t(idx[0])],
                              m.vertices[std::size_t(idx[2])] - m.vertices[std::size_t(idx[1])]));
    const auto g = rc::gen::map(rc::gen::inRange(-50, 50), [](int v) { return v / 100.0; });
    normals.push_back(own + P3{*g, *g, *g});
  }
  const double lambda = *rc::gen::element(0.01, 0.5, 1.0, 7.0);
  const PolygonalCalculus calc(m, normals);
  std::vector<SparseTriplet> t;
  for (std::int64_t f = 0; f < m.face_count(); ++f) {
    const auto l = calc.face(f).L(lambda);
    const auto idx = m.face(f);
    for (std::size_t i = 0; i < 4; ++i)
      for (std::size_t j = 0; j < 4; ++j) t.push_back({idx[i], idx[j], l[i * 4 + j]});
  }
  const SparseMatrix ref = SparseMatrix::from_triplets(m.vertex_count(), m.vertex_count(), t);
  const SparseMatrix one = calc.laplacian(lambda);
  RC_ASSERT(one.row_start == ref.row_start);
  RC_ASSERT(one.column == ref.column);
  double scale = 0;
  for (const double x : ref.value) scale = std::max(scale, std::abs(x));
  for (std::size_t i = 0; i < ref.value.size(); ++i)
    RC_ASSERT(std::abs(one.value[i] - ref.value[i]) <= 1e-12 * scale);
  for (const unsigned threads : {2u, 3u}) {
    const SparseMatrix many = calc.laplacian(lambda, threads);
    RC_ASSERT(many.column == one.column);
    RC_ASSERT(many.value == one.value);
  }
}

// The re-embedding: a non-planar quad projected orthogonally to nu gets nu as its normal.
TEST(PolygonalCalculus, ReEmbeddingTakesTheGivenNormal) {
  const std::vector<P3> x = {{0, 0, 0}, {1, 0, 0.2}, {1, 1, -0.1}, {0, 1, 0.3}};
  const P3 nu = unit({0.1, -0.2, 1});
  const std::vector<P3> normals = {3.0 * nu};
  const PolygonalCalculus calc(one_face(x), normals);
  EXPECT_NEAR(dot(calc.face(0).normal, nu), 1, 1e-12);
  for (const auto& p : calc.face(0).x) EXPECT_NEAR(dot(p - calc.face(0).centroid, nu), 0, 1e-12);
}

TEST(PolygonalCalculus, BadInputIsOneLine) {
  const std::vector<P3> x = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
  const PolygonalCalculus calc(one_face(x));
  EXPECT_THROW(calc.laplacian(0), InvalidArgument);
  EXPECT_THROW(calc.laplacian(-1), InvalidArgument);
  EXPECT_THROW(calc.inner_product(std::nan("")), InvalidArgument);
  const std::vector<P3> two = {{0, 0, 1}, {0, 0, 1}};
  EXPECT_THROW(PolygonalCalculus(one_face(x), two), InvalidArgument);
  const std::vector<P3> zero = {{0, 0, 0}};
  EXPECT_THROW(PolygonalCalculus(one_face(x), zero), InvalidArgument);
  const std::vector<P3> line = {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}};
  try {
    PolygonalCalculus c(one_face(line));
    ADD_FAILURE();
  } catch (const InvalidArgument& e) {
    EXPECT_NE(std::string(e.what()).find("face 0: a degenerate face"), std::string::npos);
  }
}

} // namespace
} // namespace zdg
