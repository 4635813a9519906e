#include <zdg/kernel/digitization/voxelize.hpp>

#include "tests/support/triangle_meshes.hpp"
#include <zdg/arith/error.hpp>
#include <zdg/kernel/digitization/polynomial.hpp>

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <algorithm>
#include <array>
#include <random>
#include <vector>

namespace zdg {
namespace {

using Q = BigRational;
using V3 = std::array<Q, 3>;
using Mode = VoxelizationMode;

Q qd(double x) {
  return exact_rational(x);
}
V3 qv(const Point3<double>& p) {
  return {qd(p.x), qd(p.y), qd(p.z)};
}
V3 sub(const V3& a, const V3& b) {
  return {a[0] - b[0], a[1] - b[1], a[2] - b[2]};
}
Q dot(const V3& a, const V3& b) {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}
V3 cross(const V3& a, const V3& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
Q qabs(const Q& x) {
  return x < Q(0) ? -x : x;
}
int qsign(const Q& x) {
  return x > Q(0) ? 1 : (x < Q(0) ? -1 : 0);
}

// The exact cube of voxel v: lo = o + h v, hi = lo + h; its centre.
struct QBox {
  V3 lo, hi, centre;
};
QBox qbox(const VoxelizationGrid& g, const std::array<std::int64_t, 3>& v) {
  const V3 o = qv(g.origin);
  const Q h = qd(g.h);
  QBox b;
  for (int d = 0; d < 3; ++d) {
    b.lo[d] = o[d] + h * Q(v[static_cast<std::size_t>(d)]);
    b.hi[d] = b.lo[d] + h;
    b.centre[d] = b.lo[d] + h / Q(2);
  }
  return b;
}

// Oracle 1: the closed triangle meets the closed box iff clipping it by the box's six closed
// half-spaces (Sutherland-Hodgman, exact) leaves a point.
bool clip_meets(std::vector<V3> poly, const QBox& b) {
  for (int d = 0; d < 3 && !poly.empty(); ++d) {
    for (int side = 0; side < 2 && !poly.empty(); ++side) {
      // keep s * (x_d - bound) <= 0
      const Q bound = side == 0 ? b.hi[d] : b.lo[d];
      const Q s(side == 0 ? 1 : -1);
      std::vector<V3> out;
      for (std::size_t k = 0; k < poly.size(); ++k) {
        const V3& p = poly[k];
        const V3& q = poly[(k + 1) % poly.size()];
        const Q fp = s * (p[d] - bound), fq = s * (q[d] - bound);
        if (fp <= Q(0)) out.push_back(p);
        if ((fp < Q(0) && fq > Q(0)) || (fp > Q(0) && fq < Q(0))) {
          const Q t = fp / (fp - fq);
          V3 x;
          for (int e = 0; e < 3; ++e) x[e] = p[e] + t * (q[e] - p[e]);
          out.push_back(x);
        }
      }
      poly = std::move(out);
    }
  }
  return !poly.empty();
}

// Oracle 2: Huang et al.'s region, written with triple products and clamped projections: the
// centre projects into the triangle and (n.(c - v0))^2 <= (h/2)^2 N(n)^2 (N = l_inf or l_1),
// or its squared distance to a point of the boundary is <= r^2 (h^2 / 4 or 3 h^2 / 4).
bool huang_meets(const std::array<V3, 3>& t, const QBox& b, const Q& h, bool six) {
  const V3& c = b.centre;
  const V3 n = cross(sub(t[1], t[0]), sub(t[2], t[0]));
  const Q h2 = h * h / Q(4);
  if (qsign(n[0]) != 0 || qsign(n[1]) != 0 || qsign(n[2]) != 0) {
    bool inside = true;
    for (int k = 0; k < 3; ++k)
      inside = inside && qsign(dot(cross(sub(t[(k + 1) % 3], c), sub(t[(k + 2) % 3], c)), n)) >= 0;
    const Q s = dot(n, sub(c, t[0]));
    const Q norm =
        six ? std::max({qabs(n[0]), qabs(n[1]), qabs(n[2])}) : qabs(n[0]) + qabs(n[1]) + qabs(n[2]);
    if (inside && s * s <= h2 * norm * norm) return true;
  }
  const Q r2 = six ? h2 : Q(3) * h2;
  for (int k = 0; k < 3; ++k) {
    const V3& a = t[k];
    const V3 e = sub(t[(k + 1) % 3], a);
    const Q len = dot(e, e);
    Q s = len > Q(0) ? dot(sub(c, a), e) / len : Q(0);
    s = std::clamp(s, Q(0), Q(1));
    V3 x;
    for (int d = 0; d < 3; ++d) x[d] = a[d] + s * e[d] - c[d];
    if (dot(x, x) <= r2) return true;
  }
  return false;
}

bool oracle(const PolygonMesh& m, const VoxelizationGrid& g, const std::array<std::int64_t, 3>& v,
            Mode mode) {
  const QBox b = qbox(g, v);
  for (std::int64_t f = 0; f < m.face_count(); ++f) {
    const auto face = m.face(f);
    for (std::size_t k = 1; k + 1 < face.size(); ++k) {
      const std::array<V3, 3> t = {qv(m.vertices[static_cast<std::size_t>(face[0])]),
                                   qv(m.vertices[static_cast<std::size_t>(face[k])]),
                                   qv(m.vertices[static_cast<std::size_t>(face[k + 1])])};
      const bool hit = mode == Mode::conservative ? clip_meets({t[0], t[1], t[2]}, b)
                                                  : huang_meets(t, b, qd(g.h), mode == Mode::six);
      if (hit) return true;
    }
  }
  return false;
}

std::int64_t at(const VoxelizationGrid& g, std::int64_t i, std::int64_t j, std::int64_t k) {
  return (k * g.extents[1] + j) * g.extents[0] + i;
}

std::int64_t count(const Image<std::uint8_t>& img) {
  std::int64_t n = 0;
  for (auto x : img.values()) n += x != 0;
  return n;
}

// Random grids and coordinates; half of the coordinates on the lattice of half steps
// (o + h k / 2, rounded to double: the cases where floating point decides wrongly).
struct Rng {
  std::mt19937 r;
  int pick(int lo, int hi) {
    return lo + static_cast<int>(r() % static_cast<unsigned>(hi - lo + 1));
  }
  double step() {
    static const double hs[] = {1.0, 0.5, 0.1, 0.3, 0.7, 1.0 / 3.0, 0.125};
    return hs[pick(0, 6)];
  }
  double coordinate(double o, double h, int n) {
    if (pick(0, 1) == 0) return o + h * (pick(-1, 2 * n + 1) / 2.0);
    return o + h * (n + 1) * (static_cast<double>(r()) / 4294967296.0) - h / 2;
  }
};

VoxelizationGrid small_grid(Rng& rng, int n) {
  VoxelizationGrid g;
  g.h = rng.step();
  g.origin = {rng.pick(-3, 3) * 0.25, rng.pick(-3, 3) * 0.1, rng.pick(-3, 3) * 0.3};
  g.extents = {n, rng.pick(1, n), rng.pick(1, n)};
  return g;
}

PolygonMesh random_triangles(Rng& rng, const VoxelizationGrid& g, int count) {
  PolygonMesh m;
  m.face_size = 3;
  const double o[3] = {g.origin.x, g.origin.y, g.origin.z};
  for (int t = 0; t < count; ++t) {
    for (int k = 0; k < 3; ++k) {
      double c[3];
      for (int d = 0; d < 3; ++d)
        c[d] = rng.coordinate(o[d], g.h, static_cast<int>(g.extents[static_cast<std::size_t>(d)]));
      if (k > 0 && rng.pick(0, 5) == 0) { // a degenerate (collinear) triangle now and then
        const auto& p = m.vertices[m.vertices.size() - 1];
        c[0] = p.x;
        c[1] = p.y;
      }
      m.vertices.push_back({c[0], c[1], c[2]});
      m.indices.push_back(static_cast<std::int64_t>(m.vertices.size()) - 1);
    }
  }
  return m;
}

void expect_oracle(const PolygonMesh& m, const VoxelizationGrid& g, Mode mode) {
  const Image<std::uint8_t> got = voxelize(m, g, mode, static_cast<unsigned>(1 + g.extents[0] % 3));
  for (std::int64_t k = 0; k < g.extents[2]; ++k)
    for (std::int64_t j = 0; j < g.extents[1]; ++j)
      for (std::int64_t i = 0; i < g.extents[0]; ++i) {
        const bool want = oracle(m, g, {i, j, k}, mode);
        RC_ASSERT((got[at(g, i, j, k)] != 0) == want);
      }
}

// Theorem (definition checked against an independent oracle): the conservative set is the set
// of voxels whose closed cube meets a triangle, by exact Sutherland-Hodgman clipping.
RC_GTEST_PROP(Voxelize, ConservativeIsExactTriangleBoxOverlap, ()) {
  Rng rng{std::mt19937(*rc::gen::arbitrary<std::uint32_t>())};
  const VoxelizationGrid g = small_grid(rng, 5);
  expect_oracle(random_triangles(rng, g, rng.pick(1, 3)), g, Mode::conservative);
}

// Huang et al.'s 6- and 26-separating regions against their definition in another form.
RC_GTEST_PROP(Voxelize, SixAndTwentySixAreHuangRegions, ()) {
  Rng rng{std::mt19937(*rc::gen::arbitrary<std::uint32_t>())};
  const VoxelizationGrid g = small_grid(rng, 5);
  const PolygonMesh m = random_triangles(rng, g, rng.pick(1, 3));
  expect_oracle(m, g, Mode::six);
  expect_oracle(m, g, Mode::twenty_six);
}

// Inclusions: six <= conservative <= twenty_six (the ball of radius h/2 lies in the cube, the
// cube in the ball of radius sqrt(3) h / 2), on larger random meshes.
RC_GTEST_PROP(Voxelize, SixInConservativeInTwentySix, ()) {
  Rng rng{std::mt19937(*rc::gen::arbitrary<std::uint32_t>())};
  const VoxelizationGrid g = small_grid(rng, 12);
  const PolygonMesh m = random_triangles(rng, g, rng.pick(1, 12));
  const auto six = voxelize(m, g, Mode::six, 2);
  const auto cons = voxelize(m, g, Mode::conservative, 1);
  const auto thick = voxelize(m, g, Mode::twenty_six, 3);
  for (std::int64_t i = 0; i < six.size(); ++i) {
    RC_ASSERT(six[i] <= cons[i]);
    RC_ASSERT(cons[i] <= thick[i]);
  }
}

// ---- closed meshes ----

// The axial octahedron with vertices c +- r e_d (convex), faces oriented outwards; `flip`
// reverses them all (an inside-out shell, winding number -1 inside).
void add_octahedron(PolygonMesh& m, const Point3<double>& c, const std::array<double, 6>& r,
                    bool flip) {
  const auto base = static_cast<std::int64_t>(m.vertices.size());
  m.vertices.push_back({c.x + r[0], c.y, c.z});
  m.vertices.push_back({c.x - r[1], c.y, c.z});
  m.vertices.push_back({c.x, c.y + r[2], c.z});
  m.vertices.push_back({c.x, c.y - r[3], c.z});
  m.vertices.push_back({c.x, c.y, c.z + r[4]});
  m.vertices.push_back({c.x, c.y, c.z - r[5]});
  for (int sx = 0; sx < 2; ++sx)
    for (int sy = 0; sy < 2; ++sy)
      for (int sz = 0; sz < 2; ++sz) {
        std::int64_t a = base + sx, b = base + 2 + sy, cc = base + 4 + sz;
        if (((sx + sy + sz) % 2 == 1) != flip) std::swap(b, cc);
        for (auto v : {a, b, cc}) m.indices.push_back(v);
      }
}

// The planes of faces [f0, f1) of a convex closed mesh, exact, oriented outwards (flip: the
// faces are inside-out); side(): -1 inside, 1 outside, 0 on the boundary.
struct ConvexPlanes {
  std::vector<std::pair<V3, Q>> planes; // n, n.a
  ConvexPlanes(const PolygonMesh& m, std::int64_t f0, std::int64_t f1, bool flip) {
    for (std::int64_t f = f0; f < f1; ++f) {
      const auto face = m.face(f);
      const V3 a = qv(m.vertices[static_cast<std::size_t>(face[0])]);
      V3 n = cross(sub(qv(m.vertices[static_cast<std::size_t>(face[1])]), a),
                   sub(qv(m.vertices[static_cast<std::size_t>(face[2])]), a));
      if (flip) n = {-n[0], -n[1], -n[2]};
      planes.push_back({n, dot(n, a)});
    }
  }
  int side(const V3& p) const {
    int worst = -1;
    for (const auto& [n, c] : planes) worst = std::max(worst, qsign(dot(n, p) - c));
    return worst;
  }
};

struct Shells {
  PolygonMesh mesh;
  VoxelizationGrid grid;
  std::vector<bool> flip;
};

Shells random_shells(Rng& rng) {
  Shells s;
  s.mesh.face_size = 3;
  s.grid.h = rng.step();
  s.grid.origin = {rng.pick(-2, 2) * 0.1, rng.pick(-2, 2) * 0.25, 0.0};
  const int n = 10;
  s.grid.extents = {n, n, n};
  const int shells = rng.pick(1, 2);
  for (int k = 0; k < shells; ++k) {
    const double o[3] = {s.grid.origin.x, s.grid.origin.y, s.grid.origin.z};
    double c[3];
    for (int d = 0; d < 3; ++d) c[d] = o[d] + s.grid.h * (rng.pick(8, 12) / 2.0);
    std::array<double, 6> r{};
    for (auto& x : r)
      x = rng.pick(0, 1) ? s.grid.h * (rng.pick(1, 7) / 2.0)
                         : s.grid.h * rng.pick(200, 800) / 200.0;
    const bool flip = rng.pick(0, 3) == 0;
    add_octahedron(s.mesh, {c[0], c[1], c[2]}, r, flip);
    s.flip.push_back(flip);
  }
  return s;
}

// Solid: equal to the exact point-in-polyhedron test at every centre not on the surface: the
// winding number is the sum over the shells containing the centre of +1 (outward faces) or -1
// (inside-out shell), and the nonzero ones are inside (an outward and an inside-out shell cancel
// where they overlap); a centre on the surface
// follows the perturbation rule, checked by the worked examples below.
RC_GTEST_PROP(Voxelize, SolidIsPointInPolyhedronAtCentres, ()) {
  Rng rng{std::mt19937(*rc::gen::arbitrary<std::uint32_t>())};
  const Shells s = random_shells(rng);
  const auto solid = voxelize(s.mesh, s.grid, Mode::solid, static_cast<unsigned>(rng.pick(1, 3)));
  std::vector<ConvexPlanes> planes;
  for (std::size_t sh = 0; sh < s.flip.size(); ++sh) {
    const auto f0 = static_cast<std::int64_t>(8 * sh);
    planes.emplace_back(s.mesh, f0, f0 + 8, s.flip[sh]);
  }
  for (std::int64_t k = 0; k < 10; ++k)
    for (std::int64_t j = 0; j < 10; ++j)
      for (std::int64_t i = 0; i < 10; ++i) {
        const V3 c = qbox(s.grid, {i, j, k}).centre;
        int winding = 0;
        bool on = false;
        for (std::size_t sh = 0; sh < s.flip.size(); ++sh) {
          const int side = planes[sh].side(c);
          if (side < 0) winding += s.flip[sh] ? -1 : 1;
          on = on || side == 0;
        }
        if (on) continue;
        RC_ASSERT((solid[at(s.grid, i, j, k)] != 0) == (winding != 0));
      }
}

// The generalized winding number at threshold 1/2 equals the exact solid at centres farther
// than 10^-6 h from the surface (closed shells, outward or inside-out: w in {-1, 0, 1, 2});
// with one face removed, the centres far inside stay inside.
RC_GTEST_PROP(Voxelize, WindingNumberAgreesWithSolidAwayFromTheSurface, ()) {
  Rng rng{std::mt19937(*rc::gen::arbitrary<std::uint32_t>())};
  Shells s = random_shells(rng);
  for (std::size_t sh = 0; sh < s.flip.size(); ++sh) RC_PRE(!s.flip[sh]);
  s.grid.extents = {8, 8, 8};
  const auto solid = voxelize(s.mesh, s.grid, Mode::solid, 1);
  const auto wind = voxelize_winding(s.mesh, s.grid, 0.5, 2);
  std::vector<ConvexPlanes> planes;
  for (std::size_t sh = 0; sh < s.flip.size(); ++sh)
    planes.emplace_back(s.mesh, static_cast<std::int64_t>(8 * sh),
                        static_cast<std::int64_t>(8 * sh + 8), false);
  for (std::int64_t k = 0; k < 8; ++k)
    for (std::int64_t j = 0; j < 8; ++j)
      for (std::int64_t i = 0; i < 8; ++i) {
        const V3 c = qbox(s.grid, {i, j, k}).centre;
        bool near = false;
        for (const auto& pl : planes) {
          for (const auto& [n, off] : pl.planes) {
            const double dist =
                std::fabs((dot(n, c) - off).to_double()) / std::sqrt(dot(n, n).to_double());
            near = near || dist < 1e-6 * s.grid.h;
          }
        }
        if (near) continue;
        RC_ASSERT(solid[at(s.grid, i, j, k)] == wind[at(s.grid, i, j, k)]);
      }
}

// Separation (the theorems of the header): in the complement of the six set no two 6-adjacent
// voxels have centres on different sides of the closed surface; in the complement of the
// conservative and twenty_six sets no two 26-adjacent voxels do.
RC_GTEST_PROP(Voxelize, SurfaceSetsSeparateInsideFromOutside, ()) {
  Rng rng{std::mt19937(*rc::gen::arbitrary<std::uint32_t>())};
  const Shells s = random_shells(rng);
  const auto solid = voxelize(s.mesh, s.grid, Mode::solid, 2);
  for (const Mode mode : {Mode::six, Mode::conservative, Mode::twenty_six}) {
    const auto set = voxelize(s.mesh, s.grid, mode, 2);
    const int reach = mode == Mode::six ? 1 : 3;
    for (std::int64_t k = 0; k < 10; ++k)
      for (std::int64_t j = 0; j < 10; ++j)
        for (std::int64_t i = 0; i < 10; ++i) {
          if (set[at(s.grid, i, j, k)]) continue;
          for (int dz = -1; dz <= 1; ++dz)
            for (int dy = -1; dy <= 1; ++dy)
              for (int dx = -1; dx <= 1; ++dx) {
                if (std::abs(dx) + std::abs(dy) + std::abs(dz) > reach) continue;
                const std::int64_t a = i + dx, b = j + dy, c = k + dz;
                if (a < 0 || b < 0 || c < 0 || a >= 10 || b >= 10 || c >= 10) continue;
                if (set[at(s.grid, a, b, c)]) continue;
                RC_ASSERT(solid[at(s.grid, i, j, k)] == solid[at(s.grid, a, b, c)]);
              }
        }
  }
}

// Two boxes sharing a face: their solids partition the solid of their union (the perturbation
// sends each centre on the shared face to exactly one side).
PolygonMesh box_mesh(const std::array<double, 3>& lo, const std::array<double, 3>& hi) {
  PolygonMesh m = test::cube_mesh(1).mesh;
  for (auto& p : m.vertices) {
    p.x = p.x < 0 ? lo[0] : hi[0];
    p.y = p.y < 0 ? lo[1] : hi[1];
    p.z = p.z < 0 ? lo[2] : hi[2];
  }
  return m;
}

RC_GTEST_PROP(Voxelize, SolidsOfBoxesSharingAFacePartition, ()) {
  Rng rng{std::mt19937(*rc::gen::arbitrary<std::uint32_t>())};
  VoxelizationGrid g;
  g.h = rng.step();
  g.extents = {9, 9, 9};
  std::array<double, 3> lo, mid, hi;
  for (int d = 0; d < 3; ++d) {
    lo[d] = g.h * (rng.pick(1, 5) / 2.0);
    hi[d] = lo[d] + g.h * (rng.pick(1, 6) / 2.0);
  }
  const int axis = rng.pick(0, 2);
  mid = hi;
  mid[axis] = lo[axis] + (hi[axis] - lo[axis]) * rng.pick(1, 3) / 4.0;
  std::array<double, 3> lo2 = lo;
  lo2[axis] = mid[axis];
  const auto a = voxelize(box_mesh(lo, mid), g, Mode::solid, 1);
  const auto b = voxelize(box_mesh(lo2, hi), g, Mode::solid, 2);
  const auto u = voxelize(box_mesh(lo, hi), g, Mode::solid, 3);
  for (std::int64_t i = 0; i < u.size(); ++i) {
    RC_ASSERT(!(a[i] && b[i]));
    RC_ASSERT((a[i] || b[i]) == (u[i] != 0));
  }
}

RC_GTEST_PROP(Voxelize, ResultDoesNotDependOnThreads, ()) {
  Rng rng{std::mt19937(*rc::gen::arbitrary<std::uint32_t>())};
  const Shells s = random_shells(rng);
  for (const Mode mode : {Mode::six, Mode::conservative, Mode::twenty_six, Mode::solid})
    RC_ASSERT(voxelize(s.mesh, s.grid, mode, 1) == voxelize(s.mesh, s.grid, mode, 4));
}

// Streaming: the slabs of any depth (a multiple of 4) concatenate to the whole voxelization,
// in every mode (the exact predicates do not depend on where a slab starts).
RC_GTEST_PROP(Voxelize, SlabsConcatenateToTheWholeVolume, ()) {
  Rng rng{std::mt19937(*rc::gen::arbitrary<std::uint32_t>())};
  const Shells s = random_shells(rng);
  const std::int64_t depth = 4 * *rc::gen::inRange<std::int64_t>(1, 4);
  for (const Mode mode : {Mode::six, Mode::conservative, Mode::twenty_six, Mode::solid}) {
    const Image<std::uint8_t> whole = voxelize(s.mesh, s.grid, mode, 2);
    std::vector<std::uint8_t> got;
    std::int64_t next = 0;
    voxelize_by_slabs(
        s.mesh, s.grid, mode, depth,
        [&](std::int64_t z0, std::int64_t n, const std::uint8_t* data) {
          RC_ASSERT(z0 == next);
          RC_ASSERT(n == std::min(depth, s.grid.extents[2] - z0));
          got.insert(got.end(), data, data + n * s.grid.extents[0] * s.grid.extents[1]);
          next += n;
        },
        2);
    RC_ASSERT(got == whole.values());
  }
}

TEST(Voxelize, SlabDepthMustBeAMultipleOfFour) {
  Rng rng{std::mt19937(7)};
  const Shells s = random_shells(rng);
  const auto ignore = [](std::int64_t, std::int64_t, const std::uint8_t*) {};
  EXPECT_THROW(voxelize_by_slabs(s.mesh, s.grid, Mode::six, 6, ignore), InvalidArgument);
  EXPECT_THROW(voxelize_by_slabs(s.mesh, s.grid, Mode::six, 0, ignore), InvalidArgument);
}

// ---- worked examples: lattice-aligned boxes ----

// Grid units: the box [A, B]^3. Closed forms, per axis: m = floor(B) - ceil(A) + 2 voxels meet
// [A, B]; q = ceil(B - 1) - floor(A) - 1 voxels lie in (A, B); the boundary meets m^3 - q^3.
TEST(Voxelize, BoxOnVoxelCentresAtUnitStep) {
  VoxelizationGrid g;
  g.h = 1;
  g.extents = {6, 6, 6};
  const PolygonMesh m = box_mesh({0.5, 0.5, 0.5}, {3.5, 3.5, 3.5});
  // m = 4, q = 2: the centres 0.5 .. 3.5 on the boundary, in every surface mode.
  EXPECT_EQ(count(voxelize(m, g, Mode::conservative)), 4 * 4 * 4 - 2 * 2 * 2);
  EXPECT_EQ(count(voxelize(m, g, Mode::six)), 56);
  EXPECT_EQ(count(voxelize(m, g, Mode::twenty_six)), 56);
  // Solid: the centres 0.5 + (d, e, e^2) with 0.5, 1.5, 2.5 per axis, not 3.5.
  const auto s = voxelize(m, g, Mode::solid);
  EXPECT_EQ(count(s), 27);
  EXPECT_EQ(s[at(g, 0, 0, 0)], 1);
  EXPECT_EQ(s[at(g, 3, 0, 0)], 0);
}

TEST(Voxelize, BoxOnVoxelBoundariesAtUnitStep) {
  VoxelizationGrid g;
  g.h = 1;
  g.extents = {5, 5, 5};
  const PolygonMesh m = box_mesh({1, 1, 1}, {3, 3, 3});
  EXPECT_EQ(count(voxelize(m, g, Mode::conservative)), 4 * 4 * 4); // m = 4, q = 0
  // six: the 2^3 inside and a layer of 2^2 on each face (edge neighbours at sqrt(2)/2 > 1/2).
  EXPECT_EQ(count(voxelize(m, g, Mode::six)), 8 + 6 * 4);
  // 26: the edge neighbours (sqrt(2)/2) and corner neighbours (sqrt(3)/2) join: all of 4^3.
  EXPECT_EQ(count(voxelize(m, g, Mode::twenty_six)), 64);
  EXPECT_EQ(count(voxelize(m, g, Mode::solid)), 8);
}

// h = 0.1, the box [0.5, 1.1]^3: in double 0.5 / 0.1 and 1.1 / 0.1 round to 5 and 11, but the
// doubles' exact quotients are A = 5 - 2.8e-16 and B = 11 + 2.8e-16. Exactly: m = 8, q = 6 (the
// voxels 5..10 lie inside (A, B)) where the rounded box would give q = 4: 296 voxels, not 448;
// six: one layer of 6 x 6 outside each face (the inner centres 5.5 and 10.5 are at 1/2 + 2.8e-16
// from the faces), 216, not 368.
TEST(Voxelize, TenthStepBoxDecidedByTheDoublesExactValues) {
  VoxelizationGrid g;
  g.h = 0.1;
  g.extents = {14, 14, 14};
  const PolygonMesh m = box_mesh({0.5, 0.5, 0.5}, {1.1, 1.1, 1.1});
  const Q a = qd(0.5) / qd(0.1), b = qd(1.1) / qd(0.1);
  ASSERT_LT(a, Q(5));
  ASSERT_GT(b, Q(11));
  ASSERT_EQ(0.5 / 0.1, 5.0); // what floating point sees
  ASSERT_EQ(1.1 / 0.1, 11.0);
  const std::int64_t mm = static_cast<std::int64_t>(b.floor() - a.ceil() + 2);
  const std::int64_t qq = static_cast<std::int64_t>((b - Q(1)).ceil() - a.floor() - 1);
  EXPECT_EQ(mm, 8);
  EXPECT_EQ(qq, 6);
  EXPECT_EQ(count(voxelize(m, g, Mode::conservative)), mm * mm * mm - qq * qq * qq);
  EXPECT_EQ(count(voxelize(m, g, Mode::six)), 6 * 6 * 6);
  EXPECT_EQ(count(voxelize(m, g, Mode::solid)), 6 * 6 * 6);
}

// Many copies of one face on one voxel: voxelized once.
TEST(Voxelize, MillionCopiesOfOneFace) {
  PolygonMesh m;
  m.face_size = 3;
  m.vertices = {{0.1, 0.1, 0.1}, {0.2, 0.1, 0.1}, {0.1, 0.2, 0.1}};
  for (int k = 0; k < 1000000; ++k) m.indices.insert(m.indices.end(), {0, 1, 2});
  const VoxelizationGrid g = voxel_grid_for(m, 1.0);
  EXPECT_EQ(count(voxelize(m, g, Mode::conservative)), 1);
}

TEST(Voxelize, Errors) {
  PolygonMesh m = box_mesh({0, 0, 0}, {1, 1, 1});
  EXPECT_THROW(voxel_grid_for(m, 0.0), InvalidArgument);
  EXPECT_THROW(voxel_grid_for(m, 1e-7), InvalidArgument); // 10^21 voxels
  PolygonMesh bad = m;
  bad.indices[1] = bad.indices[0];
  EXPECT_THROW(voxel_grid_for(bad, 1.0), InvalidArgument);
  bad = m;
  bad.vertices[0].x = std::nan("");
  EXPECT_THROW(voxel_grid_for(bad, 1.0), InvalidArgument);
  bad = m;
  bad.indices.resize(bad.indices.size() - 3); // a missing face: open
  const VoxelizationGrid g = voxel_grid_for(bad, 0.5);
  EXPECT_THROW(voxelize(bad, g, Mode::solid), InvalidArgument);
  EXPECT_NO_THROW(voxelize(bad, g, Mode::conservative));
  EXPECT_THROW(parse_voxelization_mode("18"), InvalidArgument);
  EXPECT_EQ(parse_voxelization_mode("26"), Mode::twenty_six);
}

// The default grid covers the mesh with a voxel of margin: a sphere's conservative set stays
// inside the grid and its solid is the sphere's volume within the surface layer.
TEST(Voxelize, SphereSolidWithinItsSurfaceLayer) {
  const PolygonMesh m = test::sphere_mesh(8).mesh;
  const VoxelizationGrid g = voxel_grid_for(m, 0.125);
  const auto cons = voxelize(m, g, Mode::conservative);
  const auto solid = voxelize(m, g, Mode::solid);
  const auto n = g.extents;
  for (std::int64_t k = 0; k < n[2]; ++k)
    for (std::int64_t j = 0; j < n[1]; ++j)
      for (std::int64_t i = 0; i < n[0]; ++i) {
        const bool border =
            i == 0 || j == 0 || k == 0 || i == n[0] - 1 || j == n[1] - 1 || k == n[2] - 1;
        if (border) {
          EXPECT_EQ(cons[at(g, i, j, k)], 0);
          EXPECT_EQ(solid[at(g, i, j, k)], 0);
        }
        // A centre at distance > sqrt(3)/2 h from the sphere's mesh is decided by its radius.
        const double x = g.origin.x + g.h * (i + 0.5), y = g.origin.y + g.h * (j + 0.5),
                     z = g.origin.z + g.h * (k + 0.5);
        const double r = std::sqrt(x * x + y * y + z * z);
        if (r < 0.9) {
          EXPECT_EQ(solid[at(g, i, j, k)], 1);
        }
        if (r > 1.05) {
          EXPECT_EQ(solid[at(g, i, j, k)], 0);
        }
      }
}

// Shrunk from SolidIsPointInPolyhedronAtCentres: the row of centres runs along the octahedron's
// axis through both tips; the +x tip's crossing is at q = 7 + 1.6e-16 (in half steps), which the
// filter rounded to 7 (q - err == q in double) before the ceiling's test compared the gaps.
TEST(Voxelize, RegressionRowThroughBothTips) {
  PolygonMesh m;
  m.face_size = 3;
  m.vertices = {{3.8500000000000001, 2, 2.25},   {0.85000000000000009, 2, 2.25},
                {2.6000000000000001, 2.5, 2.25}, {2.6000000000000001, 0.032499999999999973, 2.25},
                {2.6000000000000001, 2, 3},      {2.6000000000000001, 2, 2}};
  m.indices = {0, 2, 4, 0, 5, 2, 0, 4, 3, 0, 3, 5, 1, 4, 2, 1, 2, 5, 1, 3, 4, 1, 5, 3};
  VoxelizationGrid g;
  g.h = 0.5;
  g.origin = {0.10000000000000001, -0.25, 0};
  g.extents = {10, 10, 10};
  const auto s = voxelize(m, g, Mode::solid, 1);
  std::string row;
  for (std::int64_t x = 0; x < 10; ++x) row += s[at(g, x, 4, 4)] ? '1' : '0';
  EXPECT_EQ(row, "0011111100");
}

TEST(Voxelize, WindingNumberOfAnOpenBox) {
  PolygonMesh m = box_mesh({0, 0, 0}, {1, 1, 1});
  m.indices.resize(m.indices.size() - 3); // half of one face missing
  const VoxelizationGrid g = voxel_grid_for(m, 0.125);
  EXPECT_THROW(voxelize(m, g, Mode::solid), InvalidArgument);
  const auto w = voxelize_winding(m, g, 0.5);
  EXPECT_EQ(count(w), 8 * 8 * 8); // the missing triangle's solid angle stays below 2 pi
  EXPECT_THROW(voxelize_winding(m, g, 0.5, 1, 1e3), InvalidArgument);
}

} // namespace
} // namespace zdg
