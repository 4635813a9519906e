#include <zdg/convergence/laplacian_comparison.hpp>

#include <zdg/arith/error.hpp>
#include <zdg/convergence/digitized_3d.hpp>
#include <zdg/convergence/shape.hpp>
#include <zdg/estimators/digital_integration.hpp>
#include <zdg/estimators/heat_laplace_beltrami.hpp>
#include <zdg/estimators/ii_3d.hpp>
#include <zdg/kernel/calculus/polygonal_calculus.hpp>
#include <zdg/kernel/linalg/cotan_laplacian.hpp>
#include <zdg/kernel/linalg/intrinsic_delaunay.hpp>
#include <zdg/kernel/linalg/mean_value_laplacian.hpp>
#include <zdg/kernel/surfaces/marching_cubes.hpp>
#include <zdg/kernel/surfaces/surfel_complex.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace zdg {

namespace {

using P3 = Point3<double>;

// A digitized closed surface: the voxel set, its box, its boundary surfels, the step.
struct Surface {
  VoxelPredicate inside;
  VoxelBox box;
  std::vector<Surfel> surfels;
  double h = 1;
};

// L = diag(w)^{-1} s at the points; radius: how far its normal estimate reaches.
struct Operator {
  SparseMatrix s;
  std::vector<double> w;
  std::vector<P3> points;
  double normal_radius = 0;
};

constexpr double kPolygonalLambda = 1.0; // as lb-polygonal
constexpr double kHeatAlpha = 0.4;       // as lb-heat: t = h^{2/5}
constexpr double kHeatCut = 5.0;
constexpr std::int64_t kHeatMaxPairs = 50'000'000;
// The II radius on the cube at h = 1 (the laws would give 1 and 2 voxels).
constexpr double kCubeNormalRadius = 3.0;

std::vector<P3> ii_normals(const Surface& s, double R, unsigned threads) {
  std::vector<P3> n;
  for (const auto& c : ii_principal_curvatures(s.inside, s.box, s.surfels, s.h, R, threads))
    n.push_back(c.normal);
  return n;
}

SparseMatrix row_scaled(SparseMatrix a, const std::vector<double>& w) {
  for (std::int64_t i = 0; i < a.rows; ++i)
    for (auto p = a.row_start[std::size_t(i)]; p < a.row_start[std::size_t(i) + 1]; ++p)
      a.value[std::size_t(p)] *= w[std::size_t(i)];
  return a;
}

// The operator `op` on the surface; normal_radius > 0 replaces the II radius laws (h^{1/3} for
// polygonal, 2 h^{1/3} for heat).
Operator build(const std::string& op, const Surface& sf, double normal_radius, unsigned threads) {
  const SurfelComplex c = surfel_complex(primal_surface(sf.surfels), sf.h);
  if (op == "cotan") {
    CotanLaplacian L = cotan_laplacian(c.pointels, triangulate_quads(c.surfels));
    return {std::move(L.stiffness), std::move(L.mass), c.pointels, 0};
  }
  if (op == "idt" || op == "meanvalue") {
    SheetTriangles m = sheet_triangles(c);
    if (op == "idt") {
      CotanLaplacian L = intrinsic_delaunay_laplacian(m.vertices, m.triangles);
      return {std::move(L.stiffness), std::move(L.mass), std::move(m.vertices), 0};
    }
    MeanValueLaplacian L = mean_value_laplacian(m.vertices, m.triangles);
    return {std::move(L.weights), std::move(L.mass), std::move(m.vertices), 0};
  }
  if (op == "cotan-mc") {
    const PolygonMesh mesh = marching_cubes(sf.inside, sf.box, sf.h, threads);
    CotanLaplacian L = cotan_laplacian(mesh);
    return {std::move(L.stiffness), std::move(L.mass), mesh.vertices, 0};
  }
  if (op == "polygonal") {
    const double R = normal_radius > 0 ? normal_radius : std::cbrt(sf.h);
    PolygonMesh mesh;
    mesh.face_size = 4;
    mesh.vertices = c.pointels;
    for (const auto& q : c.surfels) mesh.indices.insert(mesh.indices.end(), q.begin(), q.end());
    const PolygonalCalculus calculus(mesh, ii_normals(sf, R, threads));
    SparseMatrix L = calculus.laplacian(kPolygonalLambda, threads); // D^T M D: minus the weights
    for (double& v : L.value) v = -v;
    return {std::move(L), calculus.vertex_masses(), c.pointels, R};
  }
  if (op == "heat") {
    const double t = heat_kernel_time(sf.h, kHeatAlpha);
    // The size first (the pairs do not depend on the weights), before the II normals.
    const std::int64_t pairs =
        HeatLaplaceBeltrami(c.centres, c.areas, t, kHeatCut, threads).pair_count();
    if (pairs > kHeatMaxPairs)
      throw InvalidArgument("laplacians: the heat kernel has " + std::to_string(pairs) +
                            " pairs at h = " + std::to_string(sf.h) + " (more than " +
                            std::to_string(kHeatMaxPairs) + "; take a larger h)");
    const double R = normal_radius > 0 ? normal_radius : 2 * std::cbrt(sf.h);
    const auto normals = ii_normals(sf, R, threads);
    const auto w = surfel_weights(surfel_measure(normals, c.normals), c.areas);
    const HeatLaplaceBeltrami L(c.centres, w, t, kHeatCut, threads);
    return {row_scaled(L.matrix(), w), w, c.centres, R};
  }
  if (op == "combinatorial") {
    return {row_scaled(combinatorial_laplacian(c), c.areas), c.areas, c.centres, 0};
  }
  throw InvalidArgument("laplacians: unknown operator '" + op + "'");
}

double max_abs(const SparseMatrix& a) {
  double m = 0;
  for (double v : a.value) m = std::max(m, std::abs(v));
  return m;
}

double distance(P3 a, P3 b) {
  const P3 d = a - b;
  return std::sqrt(dot(d, d));
}

// The algebraic measures on the closed surface (support radius in units of h).
void measure_closed(const Operator& o, double h, LaplacianProperties& r) {
  const double scale = max_abs(o.s), tiny = 1e-12 * scale;
  r.size = o.s.rows;
  r.asymmetry = o.s.asymmetry() / scale;
  const std::vector<double> one(o.w.size(), 1.0);
  const auto s1 = o.s.multiply(one);
  std::int64_t entries = 0, negative = 0;
  r.min_weight = std::numeric_limits<double>::infinity();
  double support = 0;
  for (std::int64_t i = 0; i < o.s.rows; ++i) {
    const auto ui = std::size_t(i);
    if (o.w[ui] > 0) r.constants = std::max(r.constants, std::abs(s1[ui] / o.w[ui]));
    std::int64_t row = 0;
    for (auto p = o.s.row_start[ui]; p < o.s.row_start[ui + 1]; ++p) {
      const auto j = o.s.column[std::size_t(p)];
      const double v = o.s.value[std::size_t(p)];
      if (j == i) continue;
      r.min_weight = std::min(r.min_weight, v / scale);
      if (std::abs(v) <= tiny) continue; // an explicit zero (a right angle's cotangent)
      ++row;
      if (v < -tiny) ++negative;
      support = std::max(support, distance(o.points[ui], o.points[std::size_t(j)]));
    }
    entries += row;
    r.max_row_entries = std::max(r.max_row_entries, row);
  }
  r.mean_row_entries = double(entries) / double(std::max<std::int64_t>(1, o.s.rows));
  r.negative_fraction = double(negative) / double(std::max<std::int64_t>(1, entries));
  r.support_radius = support / h;
}

// The cube |Q x|_inf <= a, Q the rotation by 0.5 rad about (1, 2, 3) (Rodrigues).
struct RotatedCube {
  double q[3][3];
  double a;
  explicit RotatedCube(double half_side) : q{}, a(half_side) {
    const double n = std::sqrt(14.0), kx = 1 / n, ky = 2 / n, kz = 3 / n, th = 0.5;
    const double c = std::cos(th), s = std::sin(th), v = 1 - c;
    const double m[3][3] = {{c + kx * kx * v, kx * ky * v - kz * s, kx * kz * v + ky * s},
                            {ky * kx * v + kz * s, c + ky * ky * v, ky * kz * v - kx * s},
                            {kz * kx * v - ky * s, kz * ky * v + kx * s, c + kz * kz * v}};
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) q[i][j] = m[i][j];
  }
  std::array<double, 3> local(P3 p) const {
    return {q[0][0] * p.x + q[0][1] * p.y + q[0][2] * p.z,
            q[1][0] * p.x + q[1][1] * p.y + q[1][2] * p.z,
            q[2][0] * p.x + q[2][1] * p.y + q[2][2] * p.z};
  }
  // The face whose plane is nearest (2 axis + (positive side)), and the distance from the
  // point's projection on it to its edges.
  std::pair<int, double> face(P3 p) const {
    const auto l = local(p);
    int f = 0;
    for (int i = 1; i < 3; ++i)
      if (std::abs(l[std::size_t(i)]) > std::abs(l[std::size_t(f)])) f = i;
    double d = std::numeric_limits<double>::infinity();
    for (int i = 0; i < 3; ++i)
      if (i != f) d = std::min(d, a - std::abs(l[std::size_t(i)]));
    return {2 * f + (l[std::size_t(f)] > 0 ? 1 : 0), d};
  }
  P3 normal(int face) const { // row face / 2 of Q, signed: Q^T e_a
    const int ax = face / 2;
    const double s = face % 2 ? 1.0 : -1.0;
    return {s * q[ax][0], s * q[ax][1], s * q[ax][2]};
  }
};

void measure_linear(const Operator& o, const RotatedCube& cube, LaplacianProperties& r) {
  // The operator's support on the cube, absolute (h = 1).
  double support = 0;
  const double tiny = 1e-12 * max_abs(o.s);
  for (std::int64_t i = 0; i < o.s.rows; ++i)
    for (auto p = o.s.row_start[std::size_t(i)]; p < o.s.row_start[std::size_t(i) + 1]; ++p)
      if (std::abs(o.s.value[std::size_t(p)]) > tiny)
        support = std::max(support, distance(o.points[std::size_t(i)],
                                             o.points[std::size_t(o.s.column[std::size_t(p)])]));
  const double margin = support + o.normal_radius + 2;
  const P3 g{0.48, -0.6, 0.64};
  for (int f = 0; f < 6; ++f) {
    const P3 n = cube.normal(f);
    P3 gf = g - dot(g, n) * n;
    gf = (1 / std::sqrt(dot(gf, gf))) * gf;
    std::vector<double> u;
    u.reserve(o.points.size());
    for (const auto& p : o.points) u.push_back(dot(gf, p));
    const auto su = o.s.multiply(u);
    for (std::size_t i = 0; i < su.size(); ++i) {
      const auto [face, edge] = cube.face(o.points[i]);
      if (face != f || edge <= margin || !(o.w[i] > 0)) continue;
      r.linear_defect = std::max(r.linear_defect, std::abs(su[i] / o.w[i]));
      ++r.linear_points;
    }
  }
  if (r.linear_points == 0)
    throw InvalidArgument("laplacians: no element of the cube of half-side " +
                          std::to_string(cube.a) + " is farther than " + std::to_string(margin) +
                          " from its edges (operator " + r.op + "; take a larger cube)");
}

const char* estimator_of(const std::string& op) {
  return op == "cotan"       ? "lb-cotan"
         : op == "cotan-mc"  ? "lb-cotan-mc"
         : op == "meanvalue" ? "lb-meanvalue"
         : op == "idt"       ? "lb-idt"
         : op == "polygonal" ? "lb-polygonal"
         : op == "heat"      ? "lb-heat"
                             : "lb-combinatorial";
}

const char* elements_of(const std::string& op) {
  return op == "cotan-mc"                        ? "marching-cubes vertices"
         : op == "heat" || op == "combinatorial" ? "surfel centres"
                                                 : "pointels";
}

} // namespace

SheetTriangles sheet_triangles(const SurfelComplex& c) {
  const std::size_t F = c.surfels.size();
  std::vector<std::int64_t> parent(4 * F);
  for (std::size_t i = 0; i < parent.size(); ++i) parent[i] = std::int64_t(i);
  const auto find = [&](std::int64_t x) {
    while (parent[std::size_t(x)] != x) {
      parent[std::size_t(x)] = parent[std::size_t(parent[std::size_t(x)])];
      x = parent[std::size_t(x)];
    }
    return x;
  };
  const auto unite = [&](std::int64_t a, std::int64_t b) {
    a = find(a);
    b = find(b);
    if (a != b) parent[std::size_t(std::max(a, b))] = std::min(a, b);
  };
  for (std::size_t s = 0; s < F; ++s) {
    for (int i = 0; i < 4; ++i) {
      const auto e = c.surfel_linels[s][std::size_t(i)];
      const auto o = std::size_t(c.neighbour(std::int64_t(s), i));
      int j = 0;
      while (j < 4 && c.surfel_linels[o][std::size_t(j)] != e) ++j;
      if (j == 4) throw Error("sheet_triangles: linel " + std::to_string(e) + " not on its surfel");
      // Side i of s runs corner i -> i + 1, side j of o the reverse.
      unite(std::int64_t(4 * s) + i, std::int64_t(4 * o) + (j + 1) % 4);
      unite(std::int64_t(4 * s) + (i + 1) % 4, std::int64_t(4 * o) + j);
    }
  }
  SheetTriangles out;
  std::vector<std::int64_t> id(4 * F, -1);
  for (std::size_t x = 0; x < 4 * F; ++x) {
    const auto r = std::size_t(find(std::int64_t(x)));
    if (id[r] < 0) {
      id[r] = std::int64_t(out.vertices.size());
      out.vertices.push_back(c.pointels[std::size_t(c.surfels[x / 4][x % 4])]);
    }
    id[x] = id[r];
  }
  out.triangles.reserve(2 * F);
  for (std::size_t s = 0; s < F; ++s) {
    const std::int64_t* v = &id[4 * s];
    out.triangles.push_back({v[0], v[1], v[2]});
    out.triangles.push_back({v[0], v[2], v[3]});
  }
  return out;
}

const std::vector<std::string>& laplacian_operator_names() {
  static const std::vector<std::string> names{"cotan",     "cotan-mc", "meanvalue",    "idt",
                                              "polygonal", "heat",     "combinatorial"};
  return names;
}

std::vector<LaplacianProperties>
measure_laplacian_properties(const LaplacianComparisonSettings& s) {
  std::vector<std::string> ops = s.operators.empty() ? laplacian_operator_names() : s.operators;
  for (const auto& op : ops)
    if (std::find(laplacian_operator_names().begin(), laplacian_operator_names().end(), op) ==
        laplacian_operator_names().end())
      throw InvalidArgument("laplacians: unknown operator '" + op +
                            "' (known: cotan, cotan-mc, meanvalue, idt, polygonal, heat, "
                            "combinatorial)");
  if (!(s.h > 0) || !std::isfinite(s.h))
    throw InvalidArgument("laplacians: h must be positive, not " + std::to_string(s.h));
  if (!(s.cube_half_side >= 1) || !(s.cube_half_side <= 1000))
    throw InvalidArgument("laplacians: the cube's half-side must be in [1, 1000] voxels");
  const auto shape = parse_shape(s.shape);
  if (shape->dimension() != 3)
    throw InvalidArgument("laplacians: shape '" + s.shape + "' is not 3D");
  const auto box = shape->bounding_box();
  if (!box) throw InvalidArgument("laplacians: shape '" + s.shape + "' has no box");
  const RunInput in{*shape, s.h, {0, 0, 0}, *box, 0, 0, 0, {}};
  detail::Digitized3 d = detail::digitize_3d(in);
  for (bool c : d.clipped)
    if (c)
      throw InvalidArgument("laplacians: the box clips '" + s.shape +
                            "' (the operators need a closed surface)");
  const Surface closed{d.inside, d.box, d.surfels, s.h};

  const RotatedCube cube(s.cube_half_side);
  Surface plane;
  plane.inside = [cube](const Voxel& z) {
    const auto l = cube.local({double(z.x), double(z.y), double(z.z)});
    return std::max({std::abs(l[0]), std::abs(l[1]), std::abs(l[2])}) <= cube.a;
  };
  const auto n = std::int64_t(std::ceil(cube.a * std::sqrt(3.0))) + 2;
  plane.box = VoxelBox{{-n, -n, -n}, {n, n, n}};
  plane.surfels = boundary_surfels(plane.inside, plane.box);
  plane.h = 1;

  std::vector<LaplacianProperties> out;
  for (const auto& op : ops) {
    LaplacianProperties r;
    r.op = op;
    r.estimator = estimator_of(op);
    r.elements = elements_of(op);
    measure_closed(build(op, closed, 0, s.threads), s.h, r);
    measure_linear(build(op, plane, kCubeNormalRadius, s.threads), cube, r);
    out.push_back(std::move(r));
  }
  return out;
}

} // namespace zdg
