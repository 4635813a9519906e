#include <zdg/estimators/surface_regularization.hpp>

#include <zdg/arith/error.hpp>
#include <zdg/kernel/surfaces/cubical_cells.hpp>
#include <zdg/kernel/surfaces/primal_surface_mesh.hpp>

#include "tests/support/tower.hpp"
#include "tests/support/volumes.hpp"

#include <gtest/gtest.h>
#include <rapidcheck.h>

#include <algorithm>
#include <cmath>
#include <random>

namespace {

using zdg::Point3;
using zdg::PolygonMesh;
using zdg::RegularizationParameters;
using Vec = Point3<double>;

struct Surface {
  PolygonMesh mesh;
  std::vector<Vec> elementary; // per face
};

// The primal mesh of the image at grid step h (the lattice placement scaled by h), with the
// elementary normals of its surfels.
Surface primal(const zdg::Image<std::uint8_t>& img, double h) {
  const auto sf = zdg::image_surfels(img, 1);
  auto place = zdg::VoxelPlacement::lattice(sf.grid);
  place.spacing = h * place.spacing;
  place.origin = h * place.origin;
  Surface s;
  s.mesh = zdg::primal_surface_mesh(img, sf, zdg::SurfaceConvention::of(6, 26), place, 1);
  for (std::int64_t i = 0; i < sf.size(); ++i) {
    const auto n = zdg::trivial_normal(sf.surfel(i));
    s.elementary.push_back({double(n.x), double(n.y), double(n.z)});
  }
  return s;
}

Vec unit(Vec v) {
  return (1.0 / std::sqrt(dot(v, v))) * v;
}

// The elementary normals tilted by up to `tilt` per coordinate (a stand-in for an estimate).
std::vector<Vec> tilted(const std::vector<Vec>& n, double tilt, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-tilt, tilt);
  std::vector<Vec> out;
  for (const auto& v : n) out.push_back(unit(v + Vec{u(rng), u(rng), u(rng)}));
  return out;
}

zdg::Image<std::uint8_t> box(int nx, int ny, int nz, std::int64_t lx = 0, std::int64_t ly = 0,
                             std::int64_t lz = 0) {
  zdg::test::SmallVolume v;
  v.nx = nx + 2;
  v.ny = ny + 2;
  v.nz = nz + 2;
  v.data.assign(std::size_t(v.nx * v.ny * v.nz), 0);
  for (int z = 1; z <= nz; ++z)
    for (int y = 1; y <= ny; ++y)
      for (int x = 1; x <= nx; ++x) v.data[std::size_t((z * v.ny + y) * v.nx + x)] = 1;
  return zdg::test::to_image(v, lx, ly, lz);
}

// A ball of radius r voxels, its centre off the lattice.
zdg::Image<std::uint8_t> ball(double r) {
  zdg::test::SmallVolume v;
  v.nx = v.ny = v.nz = int(2 * r) + 5;
  v.data.assign(std::size_t(v.nx * v.ny * v.nz), 0);
  const double c = v.nx / 2.0 + 0.3;
  for (int z = 0; z < v.nz; ++z)
    for (int y = 0; y < v.ny; ++y)
      for (int x = 0; x < v.nx; ++x)
        v.data[std::size_t((z * v.ny + y) * v.nx + x)] =
            (x - c) * (x - c) + (y - c + 0.1) * (y - c + 0.1) + (z - c - 0.2) * (z - c - 0.2) <=
            r * r;
  return zdg::test::to_image(v);
}

// The true normals of the ball above (at the surfel centres) as the estimate.
std::vector<Vec> radial_normals(const PolygonMesh& m, Vec centre) {
  std::vector<Vec> out;
  for (std::int64_t f = 0; f < m.face_count(); ++f) {
    Vec c{0, 0, 0};
    for (auto v : m.face(f)) c += 0.25 * m.vertices[std::size_t(v)];
    out.push_back(unit(c - centre));
  }
  return out;
}

double max_offset(const PolygonMesh& m, const std::vector<Vec>& x) {
  double d = 0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    const Vec e = x[i] - m.vertices[i];
    d = std::max({d, std::abs(e.x), std::abs(e.y), std::abs(e.z)});
  }
  return d;
}

// 2 (Q d + g): the gradient of E in the displacements d.
std::vector<double> gradient(const zdg::RegularizationSystem& s, const PolygonMesh& m,
                             const std::vector<Vec>& x) {
  std::vector<double> d;
  for (std::size_t i = 0; i < x.size(); ++i) {
    const Vec e = x[i] - m.vertices[i];
    d.insert(d.end(), {e.x, e.y, e.z});
  }
  auto q = s.q.multiply(d);
  for (std::size_t k = 0; k < q.size(); ++k) q[k] = 2 * (q[k] + s.g[k]);
  return q;
}

// The KKT residual of min E over the cubes at x, the gradient scaled by D^{-1/2} (D = diag Q):
// per coordinate, the gradient on the free ones, its part pointing out of the box on the
// clamped ones (zero exactly at the constrained minimizer). Returns |.|_2 relative to the same at
// the pointels (where every coordinate is free), and counts the clamped coordinates.
double relative_kkt_residual(const zdg::RegularizationSystem& s, const PolygonMesh& m,
                             const std::vector<Vec>& x, double h, int* clamped = nullptr) {
  const auto grad = gradient(s, m, x);
  double num = 0, den = 0;
  int count = 0;
  for (std::size_t k = 0; k < grad.size(); ++k) {
    const Vec e = x[k / 3] - m.vertices[k / 3];
    const double dk = k % 3 == 0 ? e.x : (k % 3 == 1 ? e.y : e.z);
    const double scale = 1 / std::sqrt(s.q.at(std::int64_t(k), std::int64_t(k)));
    const double slack = 1e-12 * (1 + std::abs(m.vertices[k / 3].x) +
                                  std::abs(m.vertices[k / 3].y) + std::abs(m.vertices[k / 3].z));
    double r = grad[k];
    if (dk >= h / 2 - slack) {
      ++count;
      r = std::max(r, 0.0); // E must decrease outward: a positive gradient violates KKT
    } else if (dk <= -h / 2 + slack) {
      ++count;
      r = std::min(r, 0.0);
    }
    num += scale * scale * r * r;
    den += scale * scale * 4 * s.g[k] * s.g[k];
  }
  if (clamped) *clamped = count;
  return den > 0 ? std::sqrt(num / den) : std::sqrt(num);
}

// The guarantee: on random digital objects with normals tilted from the elementary ones, random
// parameters and grid step, every regularized vertex lies in the cube of side h centred at its
// pointel, and the energy does not exceed that of the pointels.
TEST(SurfaceRegularization, EveryVertexStaysInItsCube) {
  zdg::test::check_property([] {
    const auto v = *zdg::test::small_volume(4);
    const double h = *rc::gen::element(1.0, 0.5, 0.1, 3.0);
    const auto s = primal(zdg::test::to_image(v), h);
    RC_PRE(s.mesh.face_count() > 0);
    RegularizationParameters p;
    p.alpha = *rc::gen::element(1e-4, 1e-3, 0.1);
    p.beta = *rc::gen::element(0.5, 1.0, 10.0);
    p.gamma = *rc::gen::element(0.01, 0.05, 1.0);
    p.solver = *rc::gen::element(zdg::RegularizationSolver::direct,
                                 zdg::RegularizationSolver::conjugate_gradient);
    const auto normals = tilted(s.elementary, 0.6, *rc::gen::inRange(0u, 1000u));
    const auto r = zdg::regularize_surface(s.mesh, normals, h, p);
    RC_ASSERT(r.positions.size() == s.mesh.vertices.size());
    for (std::size_t i = 0; i < r.positions.size(); ++i) {
      const Vec e = r.positions[i] - s.mesh.vertices[i];
      const double slack =
          1e-15 * (1 + std::abs(s.mesh.vertices[i].x) + std::abs(s.mesh.vertices[i].y) +
                   std::abs(s.mesh.vertices[i].z));
      RC_ASSERT(std::max({std::abs(e.x), std::abs(e.y), std::abs(e.z)}) <= h / 2 + slack);
    }
    RC_ASSERT(r.max_displacement <= 0.5);
    RC_ASSERT(r.after.total() <= r.before.total() * (1 + 1e-9));
  });
}

// MPRGP's stopping criterion, checked against the assembled system (an oracle independent of
// the matrix-free product the solver uses): at the result, the scaled KKT residual of the
// box-constrained problem is at most `tolerance` times its value at the pointels, and the result
// reports the ratio it reached.
TEST(SurfaceRegularization, MprgpStopsAtTheStatedKktResidual) {
  zdg::test::check_property([] {
    const auto v = *zdg::test::small_volume(4);
    const double h = *rc::gen::element(1.0, 0.5, 0.1);
    const auto s = primal(zdg::test::to_image(v), h);
    RC_PRE(s.mesh.face_count() > 0);
    RegularizationParameters p;
    p.alpha = *rc::gen::element(1e-4, 1e-3, 0.1);
    p.gamma = *rc::gen::element(0.01, 0.05, 1.0);
    p.tolerance = *rc::gen::element(1e-4, 1e-6, 1e-9);
    p.clamp = *rc::gen::arbitrary<bool>();
    p.solver = zdg::RegularizationSolver::conjugate_gradient;
    const auto normals = tilted(s.elementary, 1.0, *rc::gen::inRange(0u, 1000u));
    const auto r = zdg::regularize_surface(s.mesh, normals, h, p);
    RC_ASSERT(r.converged);
    RC_ASSERT(r.solver == "mprgp");
    RC_ASSERT(r.kkt_residual <= p.tolerance);
    const auto sys = zdg::regularization_system(s.mesh, normals, p);
    const double kkt = relative_kkt_residual(sys, s.mesh, r.positions, p.clamp ? h : 1e300);
    // The positions are p + d rounded: a few units of 1e-16 |p| |Q| on top of the criterion.
    RC_ASSERT(kkt <= p.tolerance * 1.01 + 1e-11);
  });
}

// E(p + d) = d^T Q d + 2 g^T d + E(p): the assembled system is the energy.
TEST(SurfaceRegularization, SystemIsTheEnergysQuadraticForm) {
  const auto s = primal(ball(3.5), 0.5);
  const auto normals = tilted(s.elementary, 0.4, 7);
  RegularizationParameters p;
  p.alpha = 0.01;
  p.gamma = 0.3;
  const auto sys = zdg::regularization_system(s.mesh, normals, p);
  EXPECT_LT(sys.q.asymmetry(), 1e-14);
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-0.3, 0.3);
  std::vector<double> d;
  std::vector<Vec> x = s.mesh.vertices;
  for (auto& xi : x) {
    const Vec e{u(rng), u(rng), u(rng)};
    d.insert(d.end(), {e.x, e.y, e.z});
    xi += e;
  }
  const auto qd = sys.q.multiply(d);
  double form = 0;
  for (std::size_t k = 0; k < d.size(); ++k) form += d[k] * qd[k] + 2 * sys.g[k] * d[k];
  const double e0 = zdg::regularization_energy(s.mesh, normals, s.mesh.vertices, p).total();
  const double e1 = zdg::regularization_energy(s.mesh, normals, x, p).total();
  EXPECT_NEAR(e1, e0 + form, 1e-10 * std::max(1.0, e1));
}

// Without the box, the result is the minimizer: the gradient vanishes there (and so does the
// central difference of the energy itself, on a few coordinates), and both solvers agree.
TEST(SurfaceRegularization, UnclampedResultIsTheMinimizer) {
  const double h = 0.5;
  const auto s = primal(ball(3.5), h);
  const auto normals = tilted(s.elementary, 0.5, 11);
  RegularizationParameters p;
  p.clamp = false;
  p.solver = zdg::RegularizationSolver::direct;
  const auto r = zdg::regularize_surface(s.mesh, normals, h, p);
  const auto sys = zdg::regularization_system(s.mesh, normals, p);
  const auto grad = gradient(sys, s.mesh, r.positions);
  double gmax = 0;
  for (double x : grad) gmax = std::max(gmax, std::abs(x));
  EXPECT_LT(gmax, 1e-10);
  const double eps = 1e-4 * h;
  for (std::size_t i : {std::size_t(0), r.positions.size() / 2, r.positions.size() - 1}) {
    auto plus = r.positions, minus = r.positions;
    plus[i].y += eps;
    minus[i].y -= eps;
    const double de = zdg::regularization_energy(s.mesh, normals, plus, p).total() -
                      zdg::regularization_energy(s.mesh, normals, minus, p).total();
    EXPECT_NEAR(de / (2 * eps), 0.0, 1e-8);
  }
  EXPECT_LT(r.after.total(), r.before.total());
  p.solver = zdg::RegularizationSolver::conjugate_gradient;
  p.tolerance = 1e-12;
  const auto c = zdg::regularize_surface(s.mesh, normals, h, p);
  double diff = 0;
  for (std::size_t i = 0; i < c.positions.size(); ++i) {
    const Vec e = c.positions[i] - r.positions[i];
    diff = std::max({diff, std::abs(e.x), std::abs(e.y), std::abs(e.z)});
  }
  EXPECT_LT(diff, 1e-8 * h);
  EXPECT_EQ(c.solver, "mprgp");
}

// With the box: the KKT conditions of min E over the cubes (the gradient is zero on the free
// coordinates and points out of the box on the clamped ones), up to the stopping tolerance, for
// ADMM with the factorization and for MPRGP; the two agree. The normals are tilted hard so that
// some vertices clamp.
TEST(SurfaceRegularization, ClampedResultIsTheBoxConstrainedMinimizer) {
  const double h = 1;
  const auto s = primal(ball(4.5), h);
  const auto normals = tilted(s.elementary, 1.5, 5);
  RegularizationParameters p;
  p.solver = zdg::RegularizationSolver::direct;
  p.tolerance = 1e-8;
  const auto r = zdg::regularize_surface(s.mesh, normals, h, p);
  ASSERT_TRUE(r.converged);
  const auto sys = zdg::regularization_system(s.mesh, normals, p);
  int clamped = 0;
  EXPECT_LT(relative_kkt_residual(sys, s.mesh, r.positions, h, &clamped), 1e-5);
  EXPECT_GT(clamped, 0);
  p.solver = zdg::RegularizationSolver::conjugate_gradient;
  p.tolerance = 1e-12;
  const auto c = zdg::regularize_surface(s.mesh, normals, h, p);
  ASSERT_TRUE(c.converged);
  EXPECT_EQ(c.solver, "mprgp");
  int clamped_c = 0;
  EXPECT_LT(relative_kkt_residual(sys, s.mesh, c.positions, h, &clamped_c), 1e-11);
  EXPECT_GT(clamped_c, 0);
  double diff = 0;
  for (std::size_t i = 0; i < c.positions.size(); ++i) {
    const Vec e = c.positions[i] - r.positions[i];
    diff = std::max({diff, std::abs(e.x), std::abs(e.y), std::abs(e.z)});
  }
  EXPECT_LT(diff, 1e-6 * h);
}

// A box with its own surfel normals: the alignment term is zero at the pointels and has no
// force there (every side is orthogonal to its face's normal), so the only force is the
// fairness pull at the box's edges and corners: the unconstrained displacement is exactly
// linear in gamma (d = -Q^{-1} gamma F^T F p) and vanishes with it.
TEST(SurfaceRegularization, AxisAlignedBoxMovesOnlyByFairness) {
  const double h = 0.25;
  const auto s = primal(box(4, 3, 5), h);
  RegularizationParameters p;
  p.clamp = false;
  p.gamma = 1e-12;
  EXPECT_EQ(zdg::regularization_energy(s.mesh, s.elementary, s.mesh.vertices, p).alignment, 0.0);
  const auto small = zdg::regularize_surface(s.mesh, s.elementary, h, p);
  p.gamma = 2e-12;
  const auto twice = zdg::regularize_surface(s.mesh, s.elementary, h, p);
  EXPECT_LT(small.max_displacement, 1e-8);
  EXPECT_GT(small.max_displacement, 0.0);
  EXPECT_NEAR(twice.max_displacement / small.max_displacement, 2.0, 1e-6);
  // The faces' interiors far from the edges: a 2x2 patch centre stays within the tolerance.
  p.gamma = 0.05;
  const auto r = zdg::regularize_surface(s.mesh, s.elementary, h, p);
  EXPECT_GT(r.max_displacement, 1e-3);
}

// A very large data weight pins the vertices.
TEST(SurfaceRegularization, LargeAlphaPinsTheVertices) {
  const double h = 0.5;
  const auto s = primal(ball(3.5), h);
  const auto normals = tilted(s.elementary, 0.5, 1);
  RegularizationParameters p;
  p.alpha = 1e9;
  const auto r = zdg::regularize_surface(s.mesh, normals, h, p);
  EXPECT_LT(max_offset(s.mesh, r.positions) / h, 1e-8);
  EXPECT_NEAR(r.max_displacement, max_offset(s.mesh, r.positions) / h, 1e-15);
  p.alpha = 1e-3;
  EXPECT_GT(zdg::regularize_surface(s.mesh, normals, h, p).max_displacement, 1e-2);
}

// Translating the object by a lattice vector (through the digitization and the mesh) translates
// the result: the same displacements.
TEST(SurfaceRegularization, TranslationEquivariant) {
  const double h = 0.5;
  zdg::test::SmallVolume v;
  v.nx = v.ny = v.nz = 6;
  std::mt19937 rng(42);
  for (int i = 0; i < 216; ++i) v.data.push_back(std::uint8_t(rng() % 3 != 0));
  const auto a = primal(zdg::test::to_image(v, 0, 0, 0), h);
  const auto b = primal(zdg::test::to_image(v, 7, -3, 12), h);
  ASSERT_EQ(a.mesh.indices, b.mesh.indices);
  const auto normals = tilted(a.elementary, 0.7, 9);
  for (bool clamp : {false, true}) {
    RegularizationParameters p;
    p.clamp = clamp;
    const auto ra = zdg::regularize_surface(a.mesh, normals, h, p);
    const auto rb = zdg::regularize_surface(b.mesh, normals, h, p);
    double diff = 0;
    for (std::size_t i = 0; i < ra.positions.size(); ++i) {
      const Vec da = ra.positions[i] - a.mesh.vertices[i];
      const Vec db = rb.positions[i] - b.mesh.vertices[i];
      EXPECT_EQ(b.mesh.vertices[i] - a.mesh.vertices[i], (Vec{7 * h, -3 * h, 12 * h}));
      diff = std::max({diff, std::abs(da.x - db.x), std::abs(da.y - db.y), std::abs(da.z - db.z)});
    }
    EXPECT_LT(diff, 1e-12);
  }
}

// A sphere with its true normals: the regularized quads' normals are closer to the truth than
// the staircase's elementary normals, and the area is closer to 4 pi r^2.
TEST(SurfaceRegularization, SphereQuadsAlignWithTheNormals) {
  const double r = 6;
  const auto img = ball(r);
  const auto s = primal(img, 1.0);
  const double c = (int(2 * r) + 5) / 2.0 + 0.3;
  // The lattice placement puts voxel (x, y, z) at its index: the centre in those coordinates.
  const Vec centre{c, c - 0.1, c + 0.2};
  const auto normals = radial_normals(s.mesh, centre);
  const auto res = zdg::regularize_surface(s.mesh, normals, 1.0);
  double before = 0, after = 0, area0 = 0, area1 = 0;
  for (std::int64_t f = 0; f < s.mesh.face_count(); ++f) {
    const Vec a0 = zdg::quad_vector_area(s.mesh, s.mesh.vertices, f);
    const Vec a1 = zdg::quad_vector_area(s.mesh, res.positions, f);
    area0 += std::sqrt(dot(a0, a0));
    area1 += std::sqrt(dot(a1, a1));
    const Vec n = normals[std::size_t(f)];
    before += std::acos(std::min(1.0, dot(unit(a0), n)));
    after += std::acos(std::min(1.0, dot(unit(a1), n)));
  }
  EXPECT_LT(after, 0.5 * before);
  const double exact = 4 * M_PI * r * r;
  EXPECT_LT(std::abs(area1 - exact), 0.5 * std::abs(area0 - exact));
}

TEST(SurfaceRegularization, BadInputIsOneLine) {
  const auto s = primal(box(2, 2, 2), 1.0);
  auto expect_one_line = [](auto&& f, const std::string& needle) {
    try {
      f();
      ADD_FAILURE() << "no error for " << needle;
    } catch (const zdg::InvalidArgument& e) {
      const std::string m = e.what();
      EXPECT_NE(m.find(needle), std::string::npos) << m;
      EXPECT_EQ(m.find('\n'), std::string::npos) << m;
    }
  };
  RegularizationParameters p;
  p.alpha = 0;
  expect_one_line([&] { zdg::regularize_surface(s.mesh, s.elementary, 1.0, p); }, "alpha = 0");
  p = {};
  p.beta = -1;
  expect_one_line([&] { zdg::regularize_surface(s.mesh, s.elementary, 1.0, p); }, "beta = -1");
  p = {};
  p.gamma = std::nan("");
  expect_one_line([&] { zdg::regularize_surface(s.mesh, s.elementary, 1.0, p); }, "gamma");
  expect_one_line([&] { zdg::regularize_surface(s.mesh, s.elementary, 0.0); }, "h = 0");
  auto shorter = s.elementary;
  shorter.pop_back();
  expect_one_line([&] { zdg::regularize_surface(s.mesh, shorter, 1.0); }, "normals for");
  auto longer = s.elementary;
  longer[3] = 2.0 * longer[3];
  expect_one_line([&] { zdg::regularize_surface(s.mesh, longer, 1.0); }, "face 3 has length 2");
  PolygonMesh tri;
  tri.face_size = 3;
  tri.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  tri.indices = {0, 1, 2};
  const std::vector<Vec> one{{0, 0, 1}};
  expect_one_line([&] { zdg::regularize_surface(tri, one, 1.0); }, "faces of 3 vertices");
}

} // namespace
