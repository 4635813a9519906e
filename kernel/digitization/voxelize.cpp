#include <zdg/kernel/digitization/polynomial.hpp>
#include <zdg/kernel/digitization/voxelize.hpp>
#include <zdg/kernel/parallel/parallel_for.hpp>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <optional>
#include <utility>
#include <vector>

namespace zdg {

namespace {

// A double with a bound on its distance to the exact value it stands for. Each operation adds
// its own rounding error, obtained exactly by TwoSum or FMA, so that values computed without
// rounding keep e = 0 and their sign (zero included) is certain.
struct Fe {
  double v = 0, e = 0;
};

// Absolute slack for the (tiny) errors of gradual underflow in the bound's own arithmetic.
constexpr double kTiny = 0x1p-1060;

inline Fe operator+(Fe a, Fe b) {
  const double s = a.v + b.v;
  const double bb = s - a.v;
  const double err = (a.v - (s - bb)) + (b.v - bb);
  const double in = a.e + b.e;
  return {s, in + std::fabs(err) + (in > 0 ? kTiny : 0)};
}
inline Fe operator-(Fe a) {
  return {-a.v, a.e};
}
inline Fe operator-(Fe a, Fe b) {
  return a + (-b);
}
inline Fe operator*(Fe a, Fe b) {
  const double p = a.v * b.v;
  const double err = std::fma(a.v, b.v, -p); // exact unless |p| is near the underflow range
  const double in = std::fabs(a.v) * b.e + std::fabs(b.v) * a.e + a.e * b.e;
  const bool low = std::fabs(p) < 0x1p-960 && p != 0;
  return {p, in + std::fabs(err) + ((in > 0 || low) ? kTiny : 0)};
}

// The certified sign, or `unsure` set (the returned sign is then a guess).
inline int sgn(const Fe& x, bool& unsure) {
  const int guess = (x.v > 0) - (x.v < 0);
  if (!std::isfinite(x.v) || !std::isfinite(x.e)) {
    unsure = true;
    return guess;
  }
  if (x.e == 0) return guess;
  const double b = x.e * (1 + 0x1p-40);
  if (x.v > b) return 1;
  if (x.v < -b) return -1;
  unsure = true;
  return guess;
}
inline int sgn(const BigRational& x, bool& /*unsure*/) {
  return x.num() > 0 ? 1 : (x.num() < 0 ? -1 : 0);
}

template <class T>
T num(std::int64_t c);
template <>
Fe num<Fe>(std::int64_t c) {
  return {static_cast<double>(c), 0}; // |c| < 2^53: grid indices
}
template <>
BigRational num<BigRational>(std::int64_t c) {
  return BigRational(c);
}

template <class T>
using Vec = std::array<T, 3>;
template <class T>
using Tri = std::array<Vec<T>, 3>;

template <class T>
Vec<T> sub(const Vec<T>& a, const Vec<T>& b) {
  return {a[0] - b[0], a[1] - b[1], a[2] - b[2]};
}
template <class T>
T dot(const Vec<T>& a, const Vec<T>& b) {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}
template <class T>
Vec<T> cross(const Vec<T>& a, const Vec<T>& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
template <class T>
T absv(const T& x, bool& unsure) {
  return sgn(x, unsure) < 0 ? T(-x) : x;
}
// |v - X| <= e implies ||v| - |X|| <= e: no sign needed.
inline Fe absv(const Fe& x, bool& /*unsure*/) {
  return {std::fabs(x.v), x.e};
}

// Whether some component of n is certainly nonzero (else: whether n is exactly zero, flagging
// `u` when that is uncertain).
template <class T>
bool nonzero(const Vec<T>& n, bool& u) {
  for (int i = 0; i < 3; ++i) {
    bool local = false;
    if (sgn(n[i], local) != 0 && !local) return true;
  }
  return sgn(n[0], u) != 0 || sgn(n[1], u) != 0 || sgn(n[2], u) != 0;
}

// Grid coordinates are doubled, 2 (p - o) / h, so that centres (2i + 1) are integers; a voxel
// in local coordinates (its centre subtracted) is the cube [-1, 1]^3.

// Akenine-Moller's separating axis test: does the closed triangle a meet [-1, 1]^3?
template <class T>
bool meets_cube(const Tri<T>& a, const Tri<T>& f, bool& u) {
  const T one = num<T>(1);
  for (int d = 0; d < 3; ++d) {
    if (sgn(a[0][d] - one, u) > 0 && sgn(a[1][d] - one, u) > 0 && sgn(a[2][d] - one, u) > 0)
      return false;
    if (sgn(a[0][d] + one, u) < 0 && sgn(a[1][d] + one, u) < 0 && sgn(a[2][d] + one, u) < 0)
      return false;
  }
  {
    const Vec<T> n = cross(f[0], f[1]);
    const T s = dot(n, a[0]);
    const T r = absv(n[0], u) + absv(n[1], u) + absv(n[2], u);
    if (sgn(s - r, u) > 0 || sgn(s + r, u) < 0) return false;
  }
  const T zero = num<T>(0);
  for (int k = 0; k < 3; ++k) {
    for (int d = 0; d < 3; ++d) {
      // L = e_d x f_k
      Vec<T> l;
      if (d == 0) l = {zero, -f[k][2], f[k][1]};
      if (d == 1) l = {f[k][2], zero, -f[k][0]};
      if (d == 2) l = {-f[k][1], f[k][0], zero};
      const int o1 = (d + 1) % 3, o2 = (d + 2) % 3;
      T p[3];
      for (int v = 0; v < 3; ++v) p[v] = l[o1] * a[v][o1] + l[o2] * a[v][o2];
      const T r = absv(l[o1], u) + absv(l[o2], u);
      if (sgn(p[0] - r, u) > 0 && sgn(p[1] - r, u) > 0 && sgn(p[2] - r, u) > 0) return false;
      if (sgn(p[0] + r, u) < 0 && sgn(p[1] + r, u) < 0 && sgn(p[2] + r, u) < 0) return false;
    }
  }
  return true;
}

// Huang et al.'s test for the centre 0: slab |n.a0| <= N(n) (N = l_inf for six, l_1 for 26)
// with the centre projecting into the triangle, or squared distance to an edge <= r2 (1 or 3).
template <class T>
bool meets_huang(const Tri<T>& a, const Tri<T>& f, bool six, bool& u) {
  const Vec<T> n = cross(f[0], f[1]);
  if (nonzero(n, u)) {
    const T s = dot(n, a[0]);
    bool slab = false;
    if (six) {
      for (int i = 0; i < 3 && !slab; ++i) {
        const T m = absv(n[i], u);
        slab = sgn(s - m, u) <= 0 && sgn(s + m, u) >= 0;
      }
    } else {
      const T r = absv(n[0], u) + absv(n[1], u) + absv(n[2], u);
      slab = sgn(s - r, u) <= 0 && sgn(s + r, u) >= 0;
    }
    if (slab) {
      bool inside = true;
      for (int k = 0; k < 3 && inside; ++k) {
        // (n x f_k) . (0 - a_k) >= 0: the centre on the inner side of edge k
        inside = sgn(dot(cross(n, f[k]), a[k]), u) <= 0;
      }
      if (inside) return true;
    }
  }
  const T r2 = num<T>(six ? 1 : 3);
  for (int k = 0; k < 3; ++k) {
    const Vec<T>& p = a[k];
    const Vec<T>& q = a[(k + 1) % 3];
    const T t = -dot(p, f[k]); // (0 - p) . (q - p)
    const T len = dot(f[k], f[k]);
    if (sgn(t, u) <= 0) {
      if (sgn(dot(p, p) - r2, u) <= 0) return true;
    } else if (sgn(t - len, u) >= 0) {
      if (sgn(dot(q, q) - r2, u) <= 0) return true;
    } else if (sgn(dot(p, p) * len - t * t - r2 * len, u) <= 0) {
      return true;
    }
  }
  return false;
}

// The test of the voxel whose centre is `centre` (doubled units, relative to g's frame).
template <class T>
bool surface_test(const Tri<T>& g, const Tri<T>& f, const std::array<std::int64_t, 3>& centre,
                  VoxelizationMode mode, bool& u) {
  Tri<T> a;
  for (int k = 0; k < 3; ++k)
    for (int d = 0; d < 3; ++d) a[k][d] = g[k][d] - num<T>(centre[static_cast<std::size_t>(d)]);
  if (mode == VoxelizationMode::conservative) return meets_cube(a, f, u);
  return meets_huang(a, f, mode == VoxelizationMode::six, u);
}

// The edges f_k = g_{k+1} - g_k.
template <class T>
Tri<T> edges(const Tri<T>& g) {
  return {sub(g[1], g[0]), sub(g[2], g[1]), sub(g[0], g[2])};
}

// 2 (p - o) / h with a certified error bound.
Fe grid_coordinate(double p, double o, double h) {
  const double d = p - o;
  const double bb = d - p;
  const double derr = (p - (d - bb)) + (-o - bb); // TwoSum(p, -o): d + derr = p - o
  const double q = d / h;
  const double r = std::fma(q, h, -d); // q h - d, exact away from underflow
  double e = (std::fabs(r) + std::fabs(derr)) / h;
  e = e * (1 + 0x1p-50);
  if (e > 0 || std::fabs(d) < 0x1p-900 || std::fabs(q) < 0x1p-900) e += 0x1p-1000;
  if (d == 0 && derr == 0) e = 0;
  return {2 * q, 2 * e};
}

// 2 (p - o) / h - c0 (c0 an integer, the doubled centre of an anchor voxel) with an error
// bound relative to the result, not to 2 (p - o) / h: with d + derr = p - o (TwoSum) and
// q h = d + r (FMA), 2 (p - o) / h = 2 q + 2 (derr - r) / h.
Fe anchored_coordinate(double p, double o, double h, double c0) {
  const double d = p - o;
  const double bb = d - p;
  const double derr = (p - (d - bb)) + (-o - bb);
  const double q = d / h;
  const double r = std::fma(q, h, -d);
  const Fe w = Fe{2 * q, 0} - Fe{c0, 0}; // TwoSum: the error of 2q - c0 exactly
  const double corr = 2 * (derr - r) / h;
  const bool tiny = std::fabs(d) < 0x1p-900 || std::fabs(q) < 0x1p-900;
  const Fe c{corr, std::fabs(corr) * 0x1p-50 + ((corr != 0 || tiny) ? 0x1p-1000 : 0)};
  return w + c;
}

BigRational exact_grid_coordinate(double p, double o, double h) {
  return (exact_rational(p) - exact_rational(o)) * BigRational(2) / exact_rational(h);
}

// floor of a finite-or-not double, clamped to [lo, hi].
std::int64_t clamp_floor(double x, std::int64_t lo, std::int64_t hi) {
  if (std::isnan(x)) return lo;
  const double f = std::floor(x);
  if (f <= static_cast<double>(lo)) return lo;
  if (f >= static_cast<double>(hi)) return hi;
  return static_cast<std::int64_t>(f);
}

struct Prepared {
  std::vector<std::array<std::int64_t, 3>> tris; // vertex indices
  std::vector<Vec<Fe>> coords;                   // per vertex, doubled grid coordinates
};

Prepared prepare(const PolygonMesh& mesh, const VoxelizationGrid& grid) {
  Prepared p;
  const std::int64_t nf = mesh.face_count();
  for (std::int64_t f = 0; f < nf; ++f) {
    const auto face = mesh.face(f);
    for (std::size_t k = 1; k + 1 < face.size(); ++k)
      p.tris.push_back({face[0], face[k], face[k + 1]});
  }
  const double o[3] = {grid.origin.x, grid.origin.y, grid.origin.z};
  p.coords.reserve(mesh.vertices.size());
  for (std::size_t i = 0; i < mesh.vertices.size(); ++i) {
    const auto& v = mesh.vertices[i];
    const double c[3] = {v.x, v.y, v.z};
    Vec<Fe> g;
    for (int d = 0; d < 3; ++d) {
      g[d] = grid_coordinate(c[d], o[d], grid.h);
      if (!std::isfinite(g[d].v) || !std::isfinite(g[d].e))
        throw InvalidArgument(
            "voxelize: vertex " + std::to_string(i) +
            " is too far from the origin for the step h = " + std::to_string(grid.h));
    }
    p.coords.push_back(g);
  }
  return p;
}

Tri<BigRational> exact_triangle(const PolygonMesh& mesh, const VoxelizationGrid& grid,
                                const std::array<std::int64_t, 3>& t) {
  Tri<BigRational> r;
  const double o[3] = {grid.origin.x, grid.origin.y, grid.origin.z};
  for (int k = 0; k < 3; ++k) {
    const auto& v = mesh.vertices[static_cast<std::size_t>(t[static_cast<std::size_t>(k)])];
    const double c[3] = {v.x, v.y, v.z};
    for (int d = 0; d < 3; ++d) r[k][d] = exact_grid_coordinate(c[d], o[d], grid.h);
  }
  return r;
}

void check_grid(const VoxelizationGrid& g) {
  if (!(g.h > 0) || !std::isfinite(g.h))
    throw InvalidArgument("voxelize: the step h = " + std::to_string(g.h) +
                          " is not positive and finite");
  if (!std::isfinite(g.origin.x) || !std::isfinite(g.origin.y) || !std::isfinite(g.origin.z))
    throw InvalidArgument("voxelize: the origin is not finite");
  for (auto n : g.extents)
    if (n < 1 || n > (std::int64_t(1) << 40))
      throw InvalidArgument("voxelize: a grid extent of " + std::to_string(n) +
                            " (1 to 2^40 allowed)");
}

void check_mesh(const PolygonMesh& mesh) {
  mesh.validate();
  for (std::size_t i = 0; i < mesh.vertices.size(); ++i) {
    const auto& v = mesh.vertices[i];
    if (!std::isfinite(v.x) || !std::isfinite(v.y) || !std::isfinite(v.z))
      throw InvalidArgument("mesh: vertex " + std::to_string(i) + " has a non-finite coordinate");
  }
  const std::int64_t nf = mesh.face_count();
  for (std::int64_t f = 0; f < nf; ++f) {
    const auto face = mesh.face(f);
    for (std::size_t a = 0; a < face.size(); ++a)
      for (std::size_t b = a + 1; b < face.size(); ++b)
        if (face[a] == face[b])
          throw InvalidArgument("mesh: face " + std::to_string(f) + " uses vertex " +
                                std::to_string(face[a]) + " twice (a degenerate face)");
  }
}

// The voxels of one triangle in a surface mode, restricted to z in [z0, z1).
void voxelize_triangle(const PolygonMesh& mesh, const VoxelizationGrid& grid, const Prepared& p,
                       const std::array<std::int64_t, 3>& t, VoxelizationMode mode, std::int64_t z0,
                       std::int64_t z1, std::uint8_t* out) {
  Tri<Fe> g;
  for (int k = 0; k < 3; ++k)
    g[k] = p.coords[static_cast<std::size_t>(t[static_cast<std::size_t>(k)])];
  std::optional<Tri<BigRational>> exact;
  Tri<BigRational> exact_edges;
  // The edges as 2 (q - p) / h from the doubles themselves: exact zeros where coordinates are
  // equal, and errors relative to the edge, not to the distance from the origin.
  Tri<Fe> f;
  for (int k = 0; k < 3; ++k) {
    const auto& pa = mesh.vertices[static_cast<std::size_t>(t[static_cast<std::size_t>(k)])];
    const auto& pb =
        mesh.vertices[static_cast<std::size_t>(t[static_cast<std::size_t>((k + 1) % 3)])];
    f[k] = {grid_coordinate(pb.x, pa.x, grid.h), grid_coordinate(pb.y, pa.y, grid.h),
            grid_coordinate(pb.z, pa.z, grid.h)};
  }
  // The voxels of each mode have their centre within `reach` (doubled units) of the triangle:
  // 1 (l_inf, the cube; l_2, six) or sqrt 3 (twenty_six). The pruning below works on the
  // doubles with a slack far above their rounding; every voxel it keeps is tested exactly.
  const double reach = mode == VoxelizationMode::twenty_six ? 1.7320508075688773 : 1.0;
  std::int64_t lo[3], hi[3];
  const std::int64_t n[3] = {grid.extents[0], grid.extents[1], grid.extents[2]};
  for (int d = 0; d < 3; ++d) {
    const double mn = std::min({g[0][d].v, g[1][d].v, g[2][d].v});
    const double mx = std::max({g[0][d].v, g[1][d].v, g[2][d].v});
    const double slack = 1e-3 + 1e-12 * (std::fabs(mn) + std::fabs(mx));
    lo[d] = clamp_floor(std::ceil((mn - reach - 1) / 2 - slack), 0, n[d]);
    hi[d] = clamp_floor((mx + reach - 1) / 2 + slack, -1, n[d] - 1);
  }
  lo[2] = std::max(lo[2], z0);
  hi[2] = std::min(hi[2], z1 - 1);
  if (lo[0] > hi[0] || lo[1] > hi[1] || lo[2] > hi[2]) return;
  // The vertices relative to the centre of voxel lo, to about 1e-16 of their (small) size: the
  // filter then certifies all but the near-exact ties (relative to the origin, the coordinates
  // carry an error of 1e-16 times the grid's size, which left ties of 1e-13 voxel undecided).
  Tri<Fe> ga;
  {
    const double o[3] = {grid.origin.x, grid.origin.y, grid.origin.z};
    for (int k = 0; k < 3; ++k) {
      const auto& pk = mesh.vertices[static_cast<std::size_t>(t[static_cast<std::size_t>(k)])];
      const double c[3] = {pk.x, pk.y, pk.z};
      for (int e = 0; e < 3; ++e)
        ga[k][e] = anchored_coordinate(c[e], o[e], grid.h, static_cast<double>(2 * lo[e] + 1));
    }
  }
  // Rows along the dominant axis d of the (approximate) normal n, cut to the slab
  // |n.(c - v0)| <= B: B = ||n||_1 (the plane meets the cube), |n| (distance 1, six) or sqrt 3
  // |n| (twenty_six). Not cut when n is too small to trust (a sliver: whole rows).
  double nv[3];
  double size = 0;
  {
    const double e1[3] = {g[1][0].v - g[0][0].v, g[1][1].v - g[0][1].v, g[1][2].v - g[0][2].v};
    const double e2[3] = {g[2][0].v - g[0][0].v, g[2][1].v - g[0][1].v, g[2][2].v - g[0][2].v};
    nv[0] = e1[1] * e2[2] - e1[2] * e2[1];
    nv[1] = e1[2] * e2[0] - e1[0] * e2[2];
    nv[2] = e1[0] * e2[1] - e1[1] * e2[0];
    size = std::sqrt((e1[0] * e1[0] + e1[1] * e1[1] + e1[2] * e1[2]) *
                     (e2[0] * e2[0] + e2[1] * e2[1] + e2[2] * e2[2]));
  }
  int d = 0;
  for (int k = 1; k < 3; ++k)
    if (std::fabs(nv[k]) > std::fabs(nv[d])) d = k;
  const int b = (d + 1) % 3, c = (d + 2) % 3;
  const double nn = std::sqrt(nv[0] * nv[0] + nv[1] * nv[1] + nv[2] * nv[2]);
  const bool cut = std::isfinite(nn) && std::isfinite(size) && nn > 1e-9 * size;
  double bound = 0;
  if (mode == VoxelizationMode::conservative)
    bound = std::fabs(nv[0]) + std::fabs(nv[1]) + std::fabs(nv[2]);
  else
    bound = reach * nn;
  const double w = cut ? bound / std::fabs(nv[d]) : 0;
  const double off = nv[0] * g[0][0].v + nv[1] * g[0][1].v + nv[2] * g[0][2].v;
  const std::int64_t nx = n[0], ny = n[1];
  std::array<std::int64_t, 3> v{};
  for (std::int64_t ib = lo[b]; ib <= hi[b]; ++ib) {
    for (std::int64_t ic = lo[c]; ic <= hi[c]; ++ic) {
      std::int64_t a0 = lo[d], a1 = hi[d];
      if (cut) {
        const double cb = static_cast<double>(2 * ib + 1), cc = static_cast<double>(2 * ic + 1);
        const double base = (off - nv[b] * cb - nv[c] * cc) / nv[d];
        const double slack = 1e-3 + 1e-12 * (std::fabs(base) + w);
        a0 = std::max(a0, clamp_floor(std::ceil((base - w - 1) / 2 - slack), lo[d], hi[d] + 1));
        a1 = std::min(a1, clamp_floor((base + w - 1) / 2 + slack, lo[d] - 1, hi[d]));
      }
      v[static_cast<std::size_t>(b)] = ib;
      v[static_cast<std::size_t>(c)] = ic;
      for (std::int64_t ia = a0; ia <= a1; ++ia) {
        v[static_cast<std::size_t>(d)] = ia;
        const std::int64_t idx = ((v[2] - z0) * ny + v[1]) * nx + v[0];
        std::uint8_t& cell = out[idx];
        if (cell) continue;
        bool unsure = false;
        const std::array<std::int64_t, 3> rel = {2 * (v[0] - lo[0]), 2 * (v[1] - lo[1]),
                                                 2 * (v[2] - lo[2])};
        bool in = surface_test(ga, f, rel, mode, unsure);
        if (unsure) {
          if (!exact) {
            exact = exact_triangle(mesh, grid, t);
            exact_edges = edges(*exact);
          }
          bool dummy = false;
          const std::array<std::int64_t, 3> centre = {2 * v[0] + 1, 2 * v[1] + 1, 2 * v[2] + 1};
          in = surface_test(*exact, exact_edges, centre, mode, dummy);
        }
        if (in) cell = 1;
      }
    }
  }
}

// ---- solid ----

// The sign of edge a -> b's function at (Y + e, Z + e^2) in the (y, z) projection.
template <class T>
int perturbed_edge_sign(const Vec<T>& a, const Vec<T>& bv, const T& y, const T& z, bool& u) {
  const T dy = bv[1] - a[1], dz = bv[2] - a[2];
  int s = sgn(dy * (z - a[2]) - dz * (y - a[1]), u);
  if (s != 0) return s;
  s = -sgn(dz, u);
  if (s != 0) return s;
  return sgn(dy, u);
}

// Whether the row (Y, Z) (perturbed) crosses the triangle; then s = sign of n_x and the
// crossing's numerator and denominator of q = (X - 1) / 2, X the crossing's x.
template <class T>
bool row_crossing(const Tri<T>& g, const T& y, const T& z, int& s, T& qn, T& qd, bool& u) {
  const Vec<T> e1 = sub(g[1], g[0]), e2 = sub(g[2], g[0]);
  const T nx = e1[1] * e2[2] - e1[2] * e2[1];
  s = sgn(nx, u);
  if (s == 0) return false;
  for (int k = 0; k < 3; ++k)
    if (perturbed_edge_sign(g[k], g[(k + 1) % 3], y, z, u) != s) return false;
  const T ny = e1[2] * e2[0] - e1[0] * e2[2];
  const T nz = e1[0] * e2[1] - e1[1] * e2[0];
  // X = x0 - (ny (y - y0) + nz (z - z0)) / nx; q = (X - 1) / 2
  qn = g[0][0] * nx - ny * (y - g[0][1]) - nz * (z - g[0][2]) - nx;
  qd = nx + nx;
  return true;
}

// ceil(n / d) certified, or unsure.
std::int64_t ceil_quotient(const Fe& n, const Fe& d, bool& u) {
  if (!(std::fabs(d.v) > d.e) || !std::isfinite(n.v) || !std::isfinite(n.e)) {
    u = true;
    return 0;
  }
  const double q = n.v / d.v;
  const double r = std::fma(q, d.v, -n.v);
  const double err =
      ((std::fabs(r) + n.e + std::fabs(q) * d.e) / (std::fabs(d.v) - d.e)) * (1 + 0x1p-40) + kTiny;
  // ceil(Q) = c for every Q in [q - err, q + err] when q + err <= c and q - err > c - 1; the
  // gaps are computed apart from q - err, whose rounding could swallow err.
  const double c = std::ceil(q);
  if (!std::isfinite(c) || std::fabs(c) > 0x1p62) {
    u = true;
    return 0;
  }
  if (r == 0 && n.e == 0 && d.e == 0) return static_cast<std::int64_t>(c); // q exact
  const double margin = err * (1 + 0x1p-30) + kTiny;
  if (!(c - q > margin) || !(q - (c - 1) > margin)) {
    u = true;
    return 0;
  }
  return static_cast<std::int64_t>(c);
}

std::int64_t ceil_quotient(const BigRational& n, const BigRational& d, std::int64_t lo,
                           std::int64_t hi) {
  const BigInt c = (n / d).ceil();
  if (c <= BigInt(lo)) return lo;
  if (c >= BigInt(hi)) return hi;
  return static_cast<std::int64_t>(c);
}

// Triangles by bucket (of layers): bucket b holds list[start[b] .. start[b + 1]).
struct LayerLists {
  std::vector<std::int64_t> start, list;
};

// The triangles of each of `buckets` buckets, each triangle in the buckets [b0, b1] that
// range(t, b0, b1) gives (counting sort: O(F + entries)).
template <class Range>
LayerLists bucket_lists(const Prepared& p, std::int64_t buckets, Range&& range) {
  LayerLists l;
  l.start.assign(static_cast<std::size_t>(buckets) + 1, 0);
  for (const auto& t : p.tris) {
    std::int64_t b0, b1;
    range(t, b0, b1);
    for (std::int64_t b = b0; b <= b1; ++b) ++l.start[static_cast<std::size_t>(b) + 1];
  }
  for (std::size_t b = 0; b < static_cast<std::size_t>(buckets); ++b) l.start[b + 1] += l.start[b];
  l.list.resize(static_cast<std::size_t>(l.start.back()));
  std::vector<std::int64_t> fill(l.start.begin(), l.start.end() - 1);
  for (std::size_t i = 0; i < p.tris.size(); ++i) {
    std::int64_t b0, b1;
    range(p.tris[i], b0, b1);
    for (std::int64_t b = b0; b <= b1; ++b)
      l.list[static_cast<std::size_t>(fill[static_cast<std::size_t>(b)]++)] =
          static_cast<std::int64_t>(i);
  }
  return l;
}

// The z range of a triangle's doubled grid coordinates.
void z_range(const Prepared& p, const std::array<std::int64_t, 3>& t, double& mn, double& mx) {
  mn = mx = p.coords[static_cast<std::size_t>(t[0])][2].v;
  for (int k = 1; k < 3; ++k) {
    mn = std::min(mn, p.coords[static_cast<std::size_t>(t[static_cast<std::size_t>(k)])][2].v);
    mx = std::max(mx, p.coords[static_cast<std::size_t>(t[static_cast<std::size_t>(k)])][2].v);
  }
}

// The triangles each layer of centres z = 2k + 1 may cross (one layer of slack for rounding).
LayerLists solid_lists(const VoxelizationGrid& grid, const Prepared& p) {
  const std::int64_t nz = grid.extents[2];
  return bucket_lists(
      p, nz, [&](const std::array<std::int64_t, 3>& t, std::int64_t& k0, std::int64_t& k1) {
        double mn, mx;
        z_range(p, t, mn, mx);
        k0 = clamp_floor((mn - 1) / 2 - 1, 0, nz);
        k1 = clamp_floor((mx - 1) / 2 + 1, -1, nz - 1);
      });
}

// The solid's layers k in [z0, z1) into out (layer z0 first; zero on entry).
void solid_layers(const PolygonMesh& mesh, const VoxelizationGrid& grid, const Prepared& p,
                  const LayerLists& lists, std::int64_t z0, std::int64_t z1, std::uint8_t* vol,
                  unsigned threads) {
  const std::int64_t nx = grid.extents[0], ny = grid.extents[1];
  const auto& start = lists.start;
  const auto& list = lists.list;
  parallel_for(z1 - z0, threads, [&](std::int64_t kk) {
    const std::int64_t k = z0 + kk;
    std::vector<std::vector<std::pair<std::int64_t, int>>> events(static_cast<std::size_t>(ny));
    const Fe z{static_cast<double>(2 * k + 1), 0};
    for (std::int64_t li = start[static_cast<std::size_t>(k)];
         li < start[static_cast<std::size_t>(k) + 1]; ++li) {
      const auto& t = p.tris[static_cast<std::size_t>(list[static_cast<std::size_t>(li)])];
      Tri<Fe> g;
      for (int q = 0; q < 3; ++q)
        g[q] = p.coords[static_cast<std::size_t>(t[static_cast<std::size_t>(q)])];
      std::optional<Tri<BigRational>> exact;
      const double mn = std::min({g[0][1].v, g[1][1].v, g[2][1].v});
      const double mx = std::max({g[0][1].v, g[1][1].v, g[2][1].v});
      const std::int64_t j0 = clamp_floor((mn - 1) / 2 - 1, 0, ny);
      const std::int64_t j1 = clamp_floor((mx - 1) / 2 + 1, -1, ny - 1);
      for (std::int64_t j = j0; j <= j1; ++j) {
        bool u = false;
        int s = 0;
        Fe qn, qd;
        const Fe y{static_cast<double>(2 * j + 1), 0};
        bool hit = row_crossing(g, y, z, s, qn, qd, u);
        std::int64_t e = 0;
        if (hit && !u) e = ceil_quotient(qn, qd, u);
        if (u) {
          if (!exact) exact = exact_triangle(mesh, grid, t);
          bool dummy = false;
          BigRational bn, bd;
          hit = row_crossing(*exact, BigRational(2 * j + 1), BigRational(2 * k + 1), s, bn, bd,
                             dummy);
          if (hit) e = ceil_quotient(bn, bd, 0, nx);
        }
        if (!hit) continue;
        e = std::clamp<std::int64_t>(e, 0, nx);
        events[static_cast<std::size_t>(j)].push_back({e, s});
      }
    }
    // w(i) = sum of s over events e > i.
    for (std::int64_t j = 0; j < ny; ++j) {
      auto& ev = events[static_cast<std::size_t>(j)];
      if (ev.empty()) continue;
      std::sort(ev.begin(), ev.end());
      std::int64_t w = 0;
      std::size_t at = ev.size();
      std::uint8_t* row = vol + (kk * ny + j) * nx;
      for (std::int64_t i = nx - 1; i >= 0; --i) {
        while (at > 0 && ev[at - 1].first > i) w += ev[--at].second;
        row[i] = w != 0;
      }
    }
  });
}

} // namespace

std::string voxelization_mode_name(VoxelizationMode mode) {
  switch (mode) {
  case VoxelizationMode::conservative:
    return "conservative";
  case VoxelizationMode::six:
    return "6";
  case VoxelizationMode::twenty_six:
    return "26";
  case VoxelizationMode::solid:
    return "solid";
  }
  return "?";
}

VoxelizationMode parse_voxelization_mode(const std::string& text) {
  if (text == "conservative") return VoxelizationMode::conservative;
  if (text == "6") return VoxelizationMode::six;
  if (text == "26") return VoxelizationMode::twenty_six;
  if (text == "solid") return VoxelizationMode::solid;
  throw InvalidArgument("voxelization mode '" + text + "' is not 6, 26, conservative or solid");
}

VoxelizationGrid voxel_grid_for(const PolygonMesh& mesh, double h,
                                const std::optional<Point3<double>>& origin,
                                std::int64_t max_voxels) {
  check_mesh(mesh);
  if (!(h > 0) || !std::isfinite(h))
    throw InvalidArgument("voxelize: the step h = " + std::to_string(h) +
                          " is not positive and finite");
  if (mesh.vertices.empty()) throw InvalidArgument("mesh: no vertices");
  double mn[3], mx[3];
  for (int d = 0; d < 3; ++d) {
    mn[d] = std::numeric_limits<double>::infinity();
    mx[d] = -mn[d];
  }
  for (const auto& v : mesh.vertices) {
    const double c[3] = {v.x, v.y, v.z};
    for (int d = 0; d < 3; ++d) {
      mn[d] = std::min(mn[d], c[d]);
      mx[d] = std::max(mx[d], c[d]);
    }
  }
  VoxelizationGrid g;
  g.h = h;
  double o[3];
  for (int d = 0; d < 3; ++d) {
    o[d] = origin ? (d == 0   ? origin->x
                     : d == 1 ? origin->y
                              : origin->z)
                  : h * (std::floor(mn[d] / h) - 2);
    if (!std::isfinite(o[d]))
      throw InvalidArgument("voxelize: the origin is not finite (coordinates too large for h = " +
                            std::to_string(h) + ")");
  }
  g.origin = {o[0], o[1], o[2]};
  double total = 1;
  for (int d = 0; d < 3; ++d) {
    const double top = std::floor((mx[d] - o[d]) / h) + 3;
    if (!std::isfinite(top) || top > 0x1p40)
      throw InvalidArgument("voxelize: the mesh spans more than 2^40 voxels of step h = " +
                            std::to_string(h) + " along axis " + std::string(1, "xyz"[d]));
    g.extents[static_cast<std::size_t>(d)] =
        std::max<std::int64_t>(1, static_cast<std::int64_t>(top));
    total *= static_cast<double>(g.extents[static_cast<std::size_t>(d)]);
  }
  if (total > static_cast<double>(max_voxels))
    throw InvalidArgument("voxelize: the grid of " + std::to_string(g.extents[0]) + " x " +
                          std::to_string(g.extents[1]) + " x " + std::to_string(g.extents[2]) +
                          " voxels exceeds the limit of " + std::to_string(max_voxels) +
                          " (a larger h?)");
  return g;
}

Image<std::uint8_t> voxelize_winding(const PolygonMesh& mesh, const VoxelizationGrid& grid,
                                     double threshold, unsigned threads, double max_work) {
  check_grid(grid);
  check_mesh(mesh);
  if (!std::isfinite(threshold))
    throw InvalidArgument("voxelize: the winding threshold is not finite");
  const Prepared p = prepare(mesh, grid);
  const std::int64_t nx = grid.extents[0], ny = grid.extents[1], nz = grid.extents[2];
  const double work = static_cast<double>(p.tris.size()) * static_cast<double>(nx) *
                      static_cast<double>(ny) * static_cast<double>(nz);
  if (work > max_work)
    throw InvalidArgument("voxelize: the generalized winding number of " +
                          std::to_string(p.tris.size()) + " triangles at " +
                          std::to_string(nx * ny * nz) + " voxels is " + std::to_string(work) +
                          " solid angles, past the limit of " + std::to_string(max_work) +
                          " (a larger h, or a closed mesh for the exact solid)");
  Image<std::uint8_t> out(Domain({nz, ny, nx}));
  auto& vol = out.values();
  constexpr double kFourPi = 12.566370614359172;
  parallel_for(nz, threads, [&](std::int64_t k) {
    const double cz = grid.origin.z + grid.h * (static_cast<double>(k) + 0.5);
    for (std::int64_t j = 0; j < ny; ++j) {
      const double cy = grid.origin.y + grid.h * (static_cast<double>(j) + 0.5);
      for (std::int64_t i = 0; i < nx; ++i) {
        const double cx = grid.origin.x + grid.h * (static_cast<double>(i) + 0.5);
        double sum = 0;
        for (const auto& t : p.tris) {
          double v[3][3];
          for (int q = 0; q < 3; ++q) {
            const auto& w = mesh.vertices[static_cast<std::size_t>(t[static_cast<std::size_t>(q)])];
            v[q][0] = w.x - cx;
            v[q][1] = w.y - cy;
            v[q][2] = w.z - cz;
          }
          const auto len = [](const double* a) {
            return std::sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]);
          };
          const auto dt = [](const double* a, const double* b) {
            return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
          };
          const double la = len(v[0]), lb = len(v[1]), lc = len(v[2]);
          const double det = v[0][0] * (v[1][1] * v[2][2] - v[1][2] * v[2][1]) -
                             v[0][1] * (v[1][0] * v[2][2] - v[1][2] * v[2][0]) +
                             v[0][2] * (v[1][0] * v[2][1] - v[1][1] * v[2][0]);
          const double den =
              la * lb * lc + dt(v[0], v[1]) * lc + dt(v[1], v[2]) * la + dt(v[2], v[0]) * lb;
          sum += 2 * std::atan2(det, den);
        }
        vol[static_cast<std::size_t>((k * ny + j) * nx + i)] = sum / kFourPi >= threshold;
      }
    }
  });
  return out;
}

void check_closed_mesh(const PolygonMesh& mesh) {
  check_mesh(mesh);
  // Merge vertices of equal coordinates.
  const std::size_t nv = mesh.vertices.size();
  std::vector<std::int64_t> order(nv), rep(nv);
  for (std::size_t i = 0; i < nv; ++i) order[i] = static_cast<std::int64_t>(i);
  auto key = [&](std::int64_t i) {
    const auto& v = mesh.vertices[static_cast<std::size_t>(i)];
    return std::array<double, 3>{v.x, v.y, v.z};
  };
  std::sort(order.begin(), order.end(), [&](std::int64_t a, std::int64_t b) {
    return key(a) < key(b) || (key(a) == key(b) && a < b);
  });
  for (std::size_t i = 0; i < nv; ++i)
    rep[static_cast<std::size_t>(order[i])] = (i > 0 && key(order[i]) == key(order[i - 1]))
                                                  ? rep[static_cast<std::size_t>(order[i - 1])]
                                                  : order[i];
  std::vector<std::pair<std::int64_t, std::int64_t>> edges;
  const std::int64_t nf = mesh.face_count();
  for (std::int64_t f = 0; f < nf; ++f) {
    const auto face = mesh.face(f);
    for (std::size_t k = 1; k + 1 < face.size(); ++k) {
      const std::int64_t t[3] = {rep[static_cast<std::size_t>(face[0])],
                                 rep[static_cast<std::size_t>(face[k])],
                                 rep[static_cast<std::size_t>(face[k + 1])]};
      if (t[0] == t[1] || t[1] == t[2] || t[0] == t[2]) continue;
      for (int e = 0; e < 3; ++e) edges.push_back({t[e], t[(e + 1) % 3]});
    }
  }
  std::sort(edges.begin(), edges.end());
  auto count = [&](std::pair<std::int64_t, std::int64_t> e) {
    const auto r = std::equal_range(edges.begin(), edges.end(), e);
    return r.second - r.first;
  };
  for (std::size_t i = 0; i < edges.size(); ++i) {
    if (i > 0 && edges[i] == edges[i - 1]) continue;
    const auto forward = count(edges[i]);
    const auto back = count({edges[i].second, edges[i].first});
    if (forward != 1 || back != 1)
      throw InvalidArgument(
          "mesh: not closed: the edge between vertices " + std::to_string(edges[i].first) +
          " and " + std::to_string(edges[i].second) + " is used " + std::to_string(forward) +
          " time(s) in this direction and " + std::to_string(back) +
          " in the other (a closed, consistently oriented mesh uses it once each way)");
  }
}

bool triangle_voxel_test(const std::array<Point3<double>, 3>& triangle,
                         const VoxelizationGrid& grid, const std::array<std::int64_t, 3>& voxel,
                         VoxelizationMode mode) {
  check_grid(grid);
  if (mode == VoxelizationMode::solid)
    throw InvalidArgument("triangle_voxel_test: solid is not a surface mode");
  Tri<BigRational> t;
  const double o[3] = {grid.origin.x, grid.origin.y, grid.origin.z};
  for (int k = 0; k < 3; ++k) {
    const double c[3] = {triangle[static_cast<std::size_t>(k)].x,
                         triangle[static_cast<std::size_t>(k)].y,
                         triangle[static_cast<std::size_t>(k)].z};
    for (int d = 0; d < 3; ++d) t[k][d] = exact_grid_coordinate(c[d], o[d], grid.h);
  }
  bool u = false;
  const std::array<std::int64_t, 3> centre = {2 * voxel[0] + 1, 2 * voxel[1] + 1, 2 * voxel[2] + 1};
  return surface_test(t, edges(t), centre, mode, u);
}

namespace {

constexpr std::int64_t kSlab = 4; // the surface modes' unit of work: 4 layers

// The triangles of each group of kSlab layers (surface modes).
LayerLists surface_lists(const VoxelizationGrid& grid, const Prepared& p) {
  const std::int64_t nz = grid.extents[2];
  return bucket_lists(
      p, (nz + kSlab - 1) / kSlab,
      [&](const std::array<std::int64_t, 3>& t, std::int64_t& s0, std::int64_t& s1) {
        double mn, mx;
        z_range(p, t, mn, mx);
        const std::int64_t k0 = clamp_floor((mn - 3) / 2 - 1, 0, nz);
        const std::int64_t k1 = clamp_floor((mx + 1) / 2 + 1, -1, nz - 1);
        s0 = k0 / kSlab;
        s1 = k1 < 0 ? -1 : k1 / kSlab;
      });
}

// The voxelization in slabs of `depth` layers (a multiple of kSlab): for each, buffer(z0) gives
// the zeroed memory of layers [z0, z1), then done(z0, z1).
template <class Buffer, class Done>
void voxelize_slabs(const PolygonMesh& mesh, const VoxelizationGrid& grid, VoxelizationMode mode,
                    std::int64_t depth, unsigned threads, Buffer&& buffer, Done&& done) {
  check_grid(grid);
  check_mesh(mesh);
  if (mode == VoxelizationMode::solid) check_closed_mesh(mesh);
  Prepared p = prepare(mesh, grid);
  const std::int64_t nx = grid.extents[0], ny = grid.extents[1], nz = grid.extents[2];
  if (mode == VoxelizationMode::solid) {
    const LayerLists lists = solid_lists(grid, p);
    for (std::int64_t z0 = 0; z0 < nz; z0 += depth) {
      const std::int64_t z1 = std::min(nz, z0 + depth);
      solid_layers(mesh, grid, p, lists, z0, z1, buffer(z0, z1), threads);
      done(z0, z1);
    }
    return;
  }
  // Identical triangles once (the set is a union).
  for (auto& t : p.tris) std::sort(t.begin(), t.end());
  std::sort(p.tris.begin(), p.tris.end());
  p.tris.erase(std::unique(p.tris.begin(), p.tris.end()), p.tris.end());
  const LayerLists lists = surface_lists(grid, p);
  for (std::int64_t z0 = 0; z0 < nz; z0 += depth) {
    const std::int64_t z1 = std::min(nz, z0 + depth);
    std::uint8_t* vol = buffer(z0, z1);
    const std::int64_t g0 = z0 / kSlab, g1 = (z1 + kSlab - 1) / kSlab;
    parallel_for(g1 - g0, threads, [&](std::int64_t gi) {
      const std::int64_t s = g0 + gi;
      const std::int64_t a = s * kSlab, b = std::min(nz, a + kSlab);
      std::uint8_t* slab = vol + (a - z0) * ny * nx;
      for (std::int64_t li = lists.start[static_cast<std::size_t>(s)];
           li < lists.start[static_cast<std::size_t>(s) + 1]; ++li)
        voxelize_triangle(
            mesh, grid, p,
            p.tris[static_cast<std::size_t>(lists.list[static_cast<std::size_t>(li)])], mode, a, b,
            slab);
    });
    done(z0, z1);
  }
}

} // namespace

Image<std::uint8_t> voxelize(const PolygonMesh& mesh, const VoxelizationGrid& grid,
                             VoxelizationMode mode, unsigned threads) {
  check_grid(grid);
  const std::int64_t nx = grid.extents[0], ny = grid.extents[1], nz = grid.extents[2];
  std::optional<Image<std::uint8_t>> out; // allocated once the mesh is checked
  voxelize_slabs(
      mesh, grid, mode, (nz + kSlab - 1) / kSlab * kSlab, threads,
      [&](std::int64_t z0, std::int64_t) {
        if (!out) out.emplace(Domain({nz, ny, nx}));
        return out->values().data() + z0 * ny * nx;
      },
      [](std::int64_t, std::int64_t) {});
  return std::move(*out);
}

void voxelize_by_slabs(
    const PolygonMesh& mesh, const VoxelizationGrid& grid, VoxelizationMode mode,
    std::int64_t depth,
    const std::function<void(std::int64_t, std::int64_t, const std::uint8_t*)>& slab,
    unsigned threads) {
  check_grid(grid);
  if (depth < 1 || depth % kSlab != 0)
    throw InvalidArgument("voxelize: the slab depth " + std::to_string(depth) +
                          " is not a positive multiple of 4");
  const std::int64_t nx = grid.extents[0], ny = grid.extents[1];
  std::vector<std::uint8_t> buf;
  voxelize_slabs(
      mesh, grid, mode, depth, threads,
      [&](std::int64_t z0, std::int64_t z1) {
        buf.assign(static_cast<std::size_t>((z1 - z0) * ny * nx), 0);
        return buf.data();
      },
      [&](std::int64_t z0, std::int64_t z1) { slab(z0, z1 - z0, buf.data()); });
}

} // namespace zdg
