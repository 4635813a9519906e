// The mean-value Laplacian (Floater 2003) and the intrinsic Delaunay Laplacian (Bobenko,
// Springborn 2007) against their theorems, on random meshes: constants in the kernel of both;
// mean-value weights positive and linear precision on planar meshes (Floater's theorem), not
// symmetric; the intrinsic Delaunay weights all non-negative after the flips, the vertex set
// and the total area kept, every edge locally Delaunay, linear precision on planar meshes, S
// symmetric; the intrinsic Delaunay Laplacian equals the cotangent Laplacian on a mesh that is
// already Delaunay (a perturbed triangular lattice, a digital sphere's split quads: all ties or
// positive); the cotangent Laplacian's linear precision on planar meshes; worked examples and
// the bad inputs.
#include <zdg/arith/error.hpp>
#include <zdg/kernel/linalg/cotan_laplacian.hpp>
#include <zdg/kernel/linalg/intrinsic_delaunay.hpp>
#include <zdg/kernel/linalg/mean_value_laplacian.hpp>

#include "tests/support/digital_sphere.hpp"

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <set>

namespace zdg {
namespace {

using P3 = Point3<double>;
using Tri = std::array<std::int64_t, 3>;

struct Mesh {
  std::vector<P3> x;
  std::vector<Tri> t;
  std::vector<bool> interior; // per vertex
};

double coord(int lo, int hi, double scale) {
  return *rc::gen::inRange(lo, hi) * scale;
}

// A random orthonormal frame (a, b, n).
std::array<P3, 3> random_frame() {
  P3 n{coord(-100, 101, 0.01), coord(-100, 101, 0.01), coord(-100, 101, 0.01)};
  RC_PRE(dot(n, n) > 0.01);
  n = (1 / std::sqrt(dot(n, n))) * n;
  P3 a = std::abs(n.x) < 0.9 ? P3{1, 0, 0} : P3{0, 1, 0};
  a = a - dot(a, n) * n;
  a = (1 / std::sqrt(dot(a, a))) * a;
  return {a, cross(n, a), n};
}

// An nx x ny grid of unit squares, corners jittered by up to `jitter` per coordinate, each
// square split along a random diagonal, lying in a random plane (heights 0) or with random
// heights up to `height`; counterclockwise in the plane's frame. Jitter below 1/4 keeps every
// square convex, so both splits are valid triangulations.
Mesh random_grid(double jitter, double height, bool plane_frame) {
  const int nx = *rc::gen::inRange(3, 8), ny = *rc::gen::inRange(3, 8);
  const auto f =
      plane_frame ? random_frame() : std::array<P3, 3>{P3{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  Mesh m;
  const auto id = [&](int i, int j) { return std::int64_t(j * (nx + 1) + i); };
  for (int j = 0; j <= ny; ++j)
    for (int i = 0; i <= nx; ++i) {
      const double u = i + jitter * coord(-100, 101, 0.01), v = j + jitter * coord(-100, 101, 0.01);
      const double w = height * coord(-100, 101, 0.01);
      m.x.push_back(u * f[0] + v * f[1] + w * f[2]);
      m.interior.push_back(i > 0 && i < nx && j > 0 && j < ny);
    }
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      const auto a = id(i, j), b = id(i + 1, j), c = id(i + 1, j + 1), d = id(i, j + 1);
      if (*rc::gen::arbitrary<bool>()) {
        m.t.push_back({a, b, c});
        m.t.push_back({a, c, d});
      } else {
        m.t.push_back({a, b, d});
        m.t.push_back({b, c, d});
      }
    }
  return m;
}

// A closed torus (radii 3 and 1) of nu x nv quads, angles jittered by up to 0.4 of a cell and
// radii by up to 10%, each quad split along a random diagonal; outward orientation.
Mesh random_torus() {
  const int nu = *rc::gen::inRange(6, 14), nv = *rc::gen::inRange(4, 10);
  Mesh m;
  const auto id = [&](int i, int j) { return std::int64_t((j % nv) * nu + (i % nu)); };
  for (int j = 0; j < nv; ++j)
    for (int i = 0; i < nu; ++i) {
      const double a = 2 * std::numbers::pi * (i + 0.4 * coord(-100, 101, 0.01)) / nu;
      const double b = 2 * std::numbers::pi * (j + 0.4 * coord(-100, 101, 0.01)) / nv;
      const double r = 1 + 0.1 * coord(-100, 101, 0.01);
      m.x.push_back({(3 + r * std::cos(b)) * std::cos(a), (3 + r * std::cos(b)) * std::sin(a),
                     r * std::sin(b)});
      m.interior.push_back(true);
    }
  for (int j = 0; j < nv; ++j)
    for (int i = 0; i < nu; ++i) {
      const auto a = id(i, j), b = id(i + 1, j), c = id(i + 1, j + 1), d = id(i, j + 1);
      if (*rc::gen::arbitrary<bool>()) {
        m.t.push_back({a, b, c});
        m.t.push_back({a, c, d});
      } else {
        m.t.push_back({a, b, d});
        m.t.push_back({b, c, d});
      }
    }
  return m;
}

double total_area(const std::vector<P3>& x, const std::vector<Tri>& t) {
  double s = 0;
  for (const auto& f : t) {
    const auto c = cross(x[std::size_t(f[1])] - x[std::size_t(f[0])],
                         x[std::size_t(f[2])] - x[std::size_t(f[0])]);
    s += 0.5 * std::sqrt(dot(c, c));
  }
  return s;
}

double max_abs(const SparseMatrix& a) {
  double s = 0;
  for (double v : a.value) s = std::max(s, std::abs(v));
  return s;
}

double min_off_diagonal(const SparseMatrix& a) {
  double s = std::numeric_limits<double>::infinity();
  for (std::int64_t i = 0; i < a.rows; ++i)
    for (auto p = a.row_start[std::size_t(i)]; p < a.row_start[std::size_t(i) + 1]; ++p)
      if (a.column[std::size_t(p)] != i) s = std::min(s, a.value[std::size_t(p)]);
  return s;
}

// The same over the entries (i, j) with i or j an interior vertex: edges with two triangles.
// A boundary edge has the one weight cot(a)/2 of its one triangle, negative when a is obtuse,
// and no flip can change it (Bobenko, Springborn 2007 give cot a + cot b >= 0 for the interior
// edges of an intrinsic Delaunay triangulation only).
double min_interior_off_diagonal(const SparseMatrix& a, const std::vector<bool>& interior) {
  double s = std::numeric_limits<double>::infinity();
  for (std::int64_t i = 0; i < a.rows; ++i)
    for (auto p = a.row_start[std::size_t(i)]; p < a.row_start[std::size_t(i) + 1]; ++p) {
      const auto j = a.column[std::size_t(p)];
      if (j != i && (interior[std::size_t(i)] || interior[std::size_t(j)]))
        s = std::min(s, a.value[std::size_t(p)]);
    }
  return s;
}

// max over the interior vertices of |(A u)_i| for u = g . x, relative to max |A| |g| (the
// size of one term).
double linear_defect(const SparseMatrix& a, const Mesh& m, P3 g) {
  std::vector<double> u;
  for (const auto& p : m.x) u.push_back(dot(g, p));
  const auto au = a.multiply(u);
  double e = 0;
  for (std::size_t i = 0; i < au.size(); ++i)
    if (m.interior[i]) e = std::max(e, std::abs(au[i]));
  return e / max_abs(a);
}

std::vector<double> ones(std::size_t n) {
  return std::vector<double>(n, 1.0);
}

RC_GTEST_PROP(MeanValueLaplacian, ConstantsInKernelPositiveWeightsLinearPrecision, ()) {
  const Mesh m = random_grid(0.24, 0, true);
  const MeanValueLaplacian L = mean_value_laplacian(m.x, m.t);
  for (double v : L.apply(ones(m.x.size()))) RC_ASSERT(std::abs(v) < 1e-9);
  RC_ASSERT(min_off_diagonal(L.weights) > 0);
  for (double d : L.mass) RC_ASSERT(d > 0);
  // Floater: sum_j w_ij (x_j - x_i) = 0 at an interior vertex of a planar mesh.
  RC_ASSERT(linear_defect(L.weights, m, {0.3, -1.1, 0.7}) < 1e-12);
}

RC_GTEST_PROP(MeanValueLaplacian, PositiveAndConstantsOnCurvedClosedMeshes, ()) {
  const Mesh m = random_torus();
  const MeanValueLaplacian L = mean_value_laplacian(m.x, m.t);
  for (double v : L.apply(ones(m.x.size()))) RC_ASSERT(std::abs(v) < 1e-9);
  RC_ASSERT(min_off_diagonal(L.weights) > 0);
}

RC_GTEST_PROP(IntrinsicDelaunay, NonNegativeWeightsSameVerticesSameArea, ()) {
  const bool closed = *rc::gen::arbitrary<bool>();
  const Mesh m = closed ? random_torus() : random_grid(0.24, 0.5, false);
  IntrinsicTriangulation t = intrinsic_triangulation(m.x, m.t);
  make_intrinsic_delaunay(t);
  // Every interior edge locally Delaunay (to the flip tolerance).
  for (std::size_t s = 0; s < t.twin.size(); ++s)
    if (t.twin[s] >= 0) {
      const auto o = std::size_t(t.twin[s]);
      RC_ASSERT(t.cotangent(s / 3, int(s % 3)) + t.cotangent(o / 3, int(o % 3)) >= -1e-9);
      RC_ASSERT(std::size_t(t.twin[o]) == s);
    }
  // The same vertices, the same total area.
  std::set<std::int64_t> before, after;
  for (const auto& f : m.t) before.insert(f.begin(), f.end());
  for (const auto& f : t.triangles) after.insert(f.begin(), f.end());
  RC_ASSERT(before == after);
  double area = 0;
  for (std::size_t f = 0; f < t.triangles.size(); ++f) area += t.area(f);
  const double a0 = total_area(m.x, m.t);
  RC_ASSERT(std::abs(area - a0) < 1e-9 * a0);
  // The Laplacian: S symmetric, weights >= 0, constants in the kernel, mass = area.
  const CotanLaplacian L = intrinsic_cotan_laplacian(t, std::int64_t(m.x.size()));
  RC_ASSERT(L.stiffness.asymmetry() <= 1e-13 * max_abs(L.stiffness));
  // Interior edges only: a boundary edge keeps the weight cot(a)/2 of its one triangle (CI
  // found an open grid with an obtuse angle opposite a boundary edge).
  RC_ASSERT(min_interior_off_diagonal(L.stiffness, m.interior) >= -1e-9 * max_abs(L.stiffness));
  for (double v : L.apply(ones(m.x.size()))) RC_ASSERT(std::abs(v) < 1e-9);
  double mass = 0;
  for (double v : L.mass) mass += v;
  RC_ASSERT(std::abs(mass - a0) < 1e-9 * a0);
}

RC_GTEST_PROP(IntrinsicDelaunay, LinearPrecisionOnPlanarMeshesWhereCotanHasNegativeWeights, ()) {
  const Mesh m = random_grid(0.24, 0, true);
  const P3 g{0.3, -1.1, 0.7};
  const CotanLaplacian c = cotan_laplacian(m.x, m.t);
  const CotanLaplacian d = intrinsic_delaunay_laplacian(m.x, m.t);
  RC_ASSERT(linear_defect(c.stiffness, m, g) < 1e-12);
  RC_ASSERT(linear_defect(d.stiffness, m, g) < 1e-12);
  // A shrunk counterexample (a 7 x 3 grid, jitters at -0.24) had an obtuse angle opposite a
  // boundary edge: only the interior edges' weights are nonnegative.
  RC_ASSERT(min_interior_off_diagonal(d.stiffness, m.interior) >= -1e-9 * max_abs(d.stiffness));
  RC_TAG(min_interior_off_diagonal(c.stiffness, m.interior) < 0 ? "cotan had a negative weight"
                                                                : "cotan >= 0");
}

// A triangular lattice, vertices jittered by up to 3% of the edge, heights up to 3%: every
// angle stays below 70 degrees, every edge Delaunay, and no flip happens.
RC_GTEST_PROP(IntrinsicDelaunay, EqualsCotanOnADelaunayMesh, ()) {
  const int n = *rc::gen::inRange(3, 9);
  Mesh m;
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) {
      const double x = i + 0.5 * j + 0.03 * coord(-100, 101, 0.01);
      const double y = std::sqrt(3.0) / 2 * j + 0.03 * coord(-100, 101, 0.01);
      m.x.push_back({x, y, 0.03 * coord(-100, 101, 0.01)});
    }
  const auto id = [&](int i, int j) { return std::int64_t(j * (n + 1) + i); };
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      m.t.push_back({id(i, j), id(i + 1, j), id(i, j + 1)});
      m.t.push_back({id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)});
    }
  IntrinsicTriangulation t = intrinsic_triangulation(m.x, m.t);
  make_intrinsic_delaunay(t);
  RC_ASSERT(t.flips == 0);
  const CotanLaplacian c = cotan_laplacian(m.x, m.t);
  const CotanLaplacian d = intrinsic_cotan_laplacian(t, std::int64_t(m.x.size()));
  RC_ASSERT(max_abs(add(1, c.stiffness, -1, d.stiffness)) < 1e-12 * max_abs(c.stiffness));
  for (std::size_t i = 0; i < c.mass.size(); ++i)
    RC_ASSERT(std::abs(c.mass[i] - d.mass[i]) < 1e-12);
}

// The split quads of a digital surface: right isosceles triangles, every edge's opposite
// angles 45 or 90 degrees (cot a + cot b >= 0, = 0 on the diagonals): already Delaunay, so
// the intrinsic Delaunay Laplacian is the cotangent Laplacian.
TEST(IntrinsicDelaunay, EqualsCotanOnADigitalSphere) {
  const auto s = test::digital_sphere(0.2, false);
  const auto tri = triangulate_quads(s.complex.surfels);
  const CotanLaplacian c = cotan_laplacian(s.complex.pointels, tri);
  const CotanLaplacian d = intrinsic_delaunay_laplacian(s.complex.pointels, tri);
  EXPECT_LT(max_abs(add(1, c.stiffness, -1, d.stiffness)), 1e-12);
}

TEST(IntrinsicDelaunay, FlipsTheLongDiagonalOfARhombus) {
  // A flat rhombus split along its long diagonal (0, 2): the angles opposite it are obtuse
  // (152 degrees), one flip makes the short diagonal (1, 3).
  const std::vector<P3> x{{-2, 0, 0}, {0, -0.5, 0}, {2, 0, 0}, {0, 0.5, 0}};
  const std::vector<Tri> t{{0, 1, 2}, {0, 2, 3}}; // the long diagonal (0, 2)
  IntrinsicTriangulation it = intrinsic_triangulation(x, t);
  make_intrinsic_delaunay(it);
  EXPECT_EQ(it.flips, 1);
  // The new edge (1, 3) has the Euclidean length 1.
  bool found = false;
  for (std::size_t f = 0; f < 2; ++f)
    for (int k = 0; k < 3; ++k) {
      const auto a = it.triangles[f][std::size_t((k + 1) % 3)],
                 b = it.triangles[f][std::size_t((k + 2) % 3)];
      if (std::min(a, b) == 1 && std::max(a, b) == 3) {
        EXPECT_NEAR(it.lengths[f][std::size_t(k)], 1.0, 1e-14);
        found = true;
      }
    }
  EXPECT_TRUE(found);
  const CotanLaplacian c = cotan_laplacian(x, t);
  EXPECT_LT(c.stiffness.at(0, 2), 0); // the obtuse angles' negative weight
  const CotanLaplacian d = intrinsic_delaunay_laplacian(x, t);
  EXPECT_EQ(d.stiffness.at(0, 2), 0.0);
  EXPECT_GT(d.stiffness.at(1, 3), 0);
}

TEST(MeanValueLaplacian, HexagonalLatticeAndAsymmetry) {
  // The regular hexagon of side a around 0: L = 2 / (3 a^2) sum (u_j - u_i), as the cotangent.
  const double a = 0.7;
  std::vector<P3> x{{0, 0, 0}};
  std::vector<Tri> t;
  for (int k = 0; k < 6; ++k)
    x.push_back(
        {a * std::cos(k * std::numbers::pi / 3), a * std::sin(k * std::numbers::pi / 3), 0});
  for (int k = 0; k < 6; ++k) t.push_back({0, 1 + k, 1 + (k + 1) % 6});
  const MeanValueLaplacian L = mean_value_laplacian(x, t);
  const CotanLaplacian C = cotan_laplacian(x, t);
  std::vector<double> u{0};
  for (int k = 0; k < 6; ++k) u.push_back(double(k * k));
  EXPECT_NEAR(L.apply(u)[0], 2 / (3 * a * a) * (0 + 1 + 4 + 9 + 16 + 25), 1e-12);
  EXPECT_NEAR(C.apply(u)[0], L.apply(u)[0], 1e-12);
  // Exact on |x|^2 at the centre: 4 (the planar Laplacian of |x|^2).
  std::vector<double> r2;
  for (const auto& p : x) r2.push_back(dot(p, p));
  EXPECT_NEAR(L.apply(r2)[0], 4, 1e-12);
  // Not symmetric: w_01 uses the angles at 0 (60 degrees), w_10 those at 1 (60 and 60 here, but
  // a longer second edge elsewhere): on a scalene pair of triangles they differ.
  const std::vector<P3> y{{0, 0, 0}, {1, 0, 0}, {0.2, 0.9, 0}, {0.6, -0.4, 0}};
  const MeanValueLaplacian M = mean_value_laplacian(y, std::vector<Tri>{{0, 1, 2}, {0, 3, 1}});
  EXPECT_GT(std::abs(M.weights.at(0, 1) - M.weights.at(1, 0)), 0.1);
}

TEST(Laplacians, BadInput) {
  const std::vector<P3> x{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 1, 1}};
  const auto mv = [&](std::vector<Tri> t) { return mean_value_laplacian(x, t); };
  const auto idt = [&](std::vector<Tri> t) { return intrinsic_delaunay_laplacian(x, t); };
  const auto message = [](auto&& f) {
    try {
      f();
    } catch (const InvalidArgument& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  // Out of range, repeated vertex, degenerate (collinear), non-manifold edge.
  const std::vector<Tri> out{{0, 1, 7}}, repeat{{0, 1, 1}}, flat{{0, 1, 1}};
  EXPECT_NE(message([&] { mv(out); }).find("uses vertex 7 of 5"), std::string::npos);
  EXPECT_NE(message([&] { idt(out); }).find("uses vertex 7 of 5"), std::string::npos);
  EXPECT_NE(message([&] { mv(repeat); }).find("repeats a vertex"), std::string::npos);
  EXPECT_NE(message([&] { idt(repeat); }).find("repeats a vertex"), std::string::npos);
  const std::vector<P3> line{{0, 0, 0}, {1, 0, 0}, {2, 0, 0}};
  EXPECT_NE(message([&] {
              mean_value_laplacian(line, std::vector<Tri>{{0, 1, 2}});
            }).find("degenerate"),
            std::string::npos);
  EXPECT_NE(message([&] {
              intrinsic_delaunay_laplacian(line, std::vector<Tri>{{0, 1, 2}});
            }).find("degenerate"),
            std::string::npos);
  const std::vector<Tri> fan{{0, 1, 2}, {1, 0, 3}, {0, 1, 4}}; // edge (0, 1) in three triangles
  EXPECT_NE(message([&] { mv(fan); }).find("not a manifold"), std::string::npos);
  EXPECT_NE(message([&] { idt(fan); }).find("not a manifold"), std::string::npos);
  const std::vector<Tri> flipped{{0, 1, 2}, {0, 1, 3}}; // (0, 1) run twice in the same direction
  EXPECT_NE(message([&] { idt(flipped); }).find("not consistently oriented"), std::string::npos);
  EXPECT_EQ(message([&] { mv(flipped); }), "no error"); // mean value does not need orientation
}

} // namespace
} // namespace zdg
