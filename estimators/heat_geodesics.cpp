#include <zdg/arith/error.hpp>
#include <zdg/estimators/heat_geodesics.hpp>
#include <zdg/kernel/linalg/cotan_laplacian.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace zdg {

namespace {

using P3 = Point3<double>;

// The surfels of the 2-ring of s (s first, then its neighbours across linels, then theirs),
// without repeats.
void two_ring(const SurfelComplex& c, std::int64_t s, std::vector<std::int64_t>& out) {
  out.clear();
  out.push_back(s);
  const auto add = [&](std::int64_t r) {
    if (std::find(out.begin(), out.end(), r) == out.end()) out.push_back(r);
  };
  for (int i = 0; i < 4; ++i) add(c.neighbour(s, i));
  const std::size_t ring1 = out.size();
  for (std::size_t k = 1; k < ring1; ++k) {
    for (int i = 0; i < 4; ++i) add(c.neighbour(out[k], i));
  }
}

} // namespace

SparseMatrix tangential_gradient(const SurfelComplex& c, std::span<const Point3<double>> normals) {
  const std::int64_t n = c.surfel_count();
  if (static_cast<std::int64_t>(normals.size()) != n) {
    throw InvalidArgument("tangential_gradient: " + std::to_string(normals.size()) +
                          " normals for " + std::to_string(n) + " surfels");
  }
  std::vector<SparseTriplet> triplets;
  triplets.reserve(static_cast<std::size_t>(n) * 3 * 13);
  std::vector<std::int64_t> ring;
  std::vector<double> a1, a2;
  for (std::int64_t s = 0; s < n; ++s) {
    const P3 nn = normals[std::size_t(s)];
    const double len = std::sqrt(dot(nn, nn));
    if (!(std::abs(len - 1) < 1e-6)) {
      throw InvalidArgument("tangential_gradient: the normal of surfel " + std::to_string(s) +
                            " is not a unit vector");
    }
    // An orthonormal tangent basis (e1, e2) of n.
    const P3 helper = std::abs(nn.x) < 0.6 ? P3{1, 0, 0} : P3{0, 1, 0};
    P3 e1{helper.y * nn.z - helper.z * nn.y, helper.z * nn.x - helper.x * nn.z,
          helper.x * nn.y - helper.y * nn.x};
    const double l1 = std::sqrt(dot(e1, e1));
    e1 = {e1.x / l1, e1.y / l1, e1.z / l1};
    const P3 e2{nn.y * e1.z - nn.z * e1.y, nn.z * e1.x - nn.x * e1.z, nn.x * e1.y - nn.y * e1.x};
    two_ring(c, s, ring);
    const P3 xs = c.centres[std::size_t(s)];
    // Normal equations M g = sum_r a_r (u_r - u_s), M = sum_r a_r a_r^T (2 x 2).
    double m11 = 0, m12 = 0, m22 = 0;
    a1.assign(ring.size(), 0);
    a2.assign(ring.size(), 0);
    for (std::size_t k = 1; k < ring.size(); ++k) {
      const P3 xr = c.centres[std::size_t(ring[k])];
      const P3 d{xr.x - xs.x, xr.y - xs.y, xr.z - xs.z};
      a1[k] = dot(d, e1);
      a2[k] = dot(d, e2);
      m11 += a1[k] * a1[k];
      m12 += a1[k] * a2[k];
      m22 += a2[k] * a2[k];
    }
    const double det = m11 * m22 - m12 * m12;
    if (!(det > 1e-12 * (m11 + m22) * (m11 + m22))) {
      throw Error("tangential_gradient: the stencil of surfel " + std::to_string(s) +
                  " is degenerate (its neighbours lie on one line of the tangent plane)");
    }
    // g = M^{-1} sum_r a_r (u_r - u_s): the coefficient of u_r in component j of g.
    double sum[3] = {0, 0, 0};
    for (std::size_t k = 1; k < ring.size(); ++k) {
      const double g1 = (m22 * a1[k] - m12 * a2[k]) / det;
      const double g2 = (-m12 * a1[k] + m11 * a2[k]) / det;
      const double ambient[3] = {g1 * e1.x + g2 * e2.x, g1 * e1.y + g2 * e2.y,
                                 g1 * e1.z + g2 * e2.z};
      for (int a = 0; a < 3; ++a) {
        triplets.push_back({3 * s + a, ring[k], ambient[a]});
        sum[a] += ambient[a];
      }
    }
    for (int a = 0; a < 3; ++a) triplets.push_back({3 * s + a, s, -sum[a]});
  }
  return SparseMatrix::from_triplets(3 * n, n, std::move(triplets));
}

struct HeatGeodesics::Solvers {
  SparseSpdSolver heat, poisson;
};

namespace {

// A = G^T diag(w repeated 3 times) G, assembled row by row: row j of A is the sum over the
// rows r of G that hold column j of w(r) G_rj G_r (a dense accumulator over the columns,
// reset after each row), so that no triplet list of n k^2 entries is built. O(n k^2) time,
// O(nnz(A)) memory (the 4-ring of a surfel: about 41 entries per row).
SparseMatrix dirichlet_matrix(const SparseMatrix& g, std::span<const double> w) {
  const std::int64_t n = g.cols;
  const SparseMatrix gt = g.transpose();
  SparseMatrix a;
  a.rows = a.cols = n;
  a.row_start.assign(std::size_t(n) + 1, 0);
  std::vector<double> acc(std::size_t(n), 0.0);
  std::vector<char> used(std::size_t(n), 0);
  std::vector<std::int64_t> cols;
  for (std::int64_t j = 0; j < n; ++j) {
    cols.clear();
    for (auto p = gt.row_start[std::size_t(j)]; p < gt.row_start[std::size_t(j) + 1]; ++p) {
      const std::int64_t r = gt.column[std::size_t(p)];
      const double f = w[std::size_t(r / 3)] * gt.value[std::size_t(p)];
      for (auto q = g.row_start[std::size_t(r)]; q < g.row_start[std::size_t(r) + 1]; ++q) {
        const std::int64_t k = g.column[std::size_t(q)];
        if (!used[std::size_t(k)]) {
          used[std::size_t(k)] = 1;
          cols.push_back(k);
        }
        acc[std::size_t(k)] += f * g.value[std::size_t(q)];
      }
    }
    std::sort(cols.begin(), cols.end());
    for (std::int64_t k : cols) {
      a.column.push_back(k);
      a.value.push_back(acc[std::size_t(k)]);
      acc[std::size_t(k)] = 0;
      used[std::size_t(k)] = 0;
    }
    a.row_start[std::size_t(j) + 1] = static_cast<std::int64_t>(a.column.size());
  }
  return a;
}

} // namespace

HeatGeodesics::HeatGeodesics(const SurfelComplex& complex, std::span<const Point3<double>> normals,
                             std::span<const double> weights, double t, double mu_min,
                             SpdBackend backend)
    : n_(complex.surfel_count()) {
  if (static_cast<std::int64_t>(weights.size()) != n_) {
    throw InvalidArgument("HeatGeodesics: " + std::to_string(weights.size()) + " weights for " +
                          std::to_string(n_) + " surfels");
  }
  if (n_ == 0) throw InvalidArgument("HeatGeodesics: no surfel");
  if (!(t >= 0 && std::isfinite(t))) throw InvalidArgument("HeatGeodesics: t must be >= 0");
  if (!(mu_min > 0 && mu_min <= 1))
    throw InvalidArgument("HeatGeodesics: mu_min must be in (0, 1]");
  double mean_area = 0;
  for (double a : complex.areas) mean_area += a;
  mean_area /= double(n_);
  t_ = t > 0 ? t : mean_area;
  weights_.resize(std::size_t(n_));
  double trace_w = 0;
  for (std::int64_t s = 0; s < n_; ++s) {
    const double area = complex.areas[std::size_t(s)];
    const double w = weights[std::size_t(s)];
    if (!std::isfinite(w)) throw InvalidArgument("HeatGeodesics: a weight is not finite");
    weights_[std::size_t(s)] = std::max(w, mu_min * area);
    trace_w += weights_[std::size_t(s)];
  }
  gradient_ = tangential_gradient(complex, normals);
  const SparseMatrix a = dirichlet_matrix(gradient_, weights_);
  double trace_a = 0;
  for (std::int64_t v = 0; v < n_; ++v) trace_a += a.at(v, v);
  // The graph Laplacian of the surfel adjacency (sum over linels of (u(r) - u(s))^2): the
  // least-squares stiffness A does not see the checkerboard modes of the 2-ring stencil (their
  // fitted gradient vanishes), so the heat step alone would ring around the source; K damps
  // them (a monotone M-matrix), A keeps the metric of the estimated tangent planes.
  // K = -diag(area) L_comb (kernel/linalg/cotan_laplacian.hpp): unit weights per linel.
  SparseMatrix graph = combinatorial_laplacian(complex);
  for (std::int64_t i = 0; i < n_; ++i)
    for (auto p = graph.row_start[std::size_t(i)]; p < graph.row_start[std::size_t(i) + 1]; ++p)
      graph.value[std::size_t(p)] *= -complex.areas[std::size_t(i)];
  // (W + t (A + K)): the heat step; (A + eps W): the Poisson step (A is singular on constants).
  SparseMatrix heat = add(t_, add(1.0, a, 1.0, graph), 1.0, SparseMatrix::diagonal(weights_));
  const double eps = 1e-9 * trace_a / trace_w;
  SparseMatrix poisson = add(1.0, a, eps, SparseMatrix::diagonal(weights_));
  solvers_ = std::make_unique<Solvers>(
      Solvers{SparseSpdSolver(heat, backend), SparseSpdSolver(poisson, backend)});
}

HeatGeodesics::~HeatGeodesics() = default;
HeatGeodesics::HeatGeodesics(HeatGeodesics&&) noexcept = default;
HeatGeodesics& HeatGeodesics::operator=(HeatGeodesics&&) noexcept = default;

SpdBackend HeatGeodesics::backend() const {
  return solvers_->heat.backend();
}

std::vector<double> HeatGeodesics::distance(std::int64_t source) const {
  if (source < 0 || source >= n_) {
    throw InvalidArgument("HeatGeodesics: source surfel " + std::to_string(source) +
                          " outside [0, " + std::to_string(n_) + ")");
  }
  std::vector<double> delta(std::size_t(n_), 0.0);
  delta[std::size_t(source)] = 1;
  const std::vector<double> u = solvers_->heat.solve(delta);
  std::vector<double> x = gradient_.multiply(u);
  for (std::int64_t s = 0; s < n_; ++s) {
    double* g = &x[std::size_t(3 * s)];
    const double len = std::sqrt(g[0] * g[0] + g[1] * g[1] + g[2] * g[2]);
    const double f = len > 0 ? -weights_[std::size_t(s)] / len : 0;
    for (int a = 0; a < 3; ++a) g[a] *= f; // w_s X_s
  }
  const std::vector<double> b = gradient_.transpose().multiply(x); // G^T W X
  std::vector<double> phi = solvers_->poisson.solve(b);
  const double at_source = phi[std::size_t(source)];
  for (double& p : phi) p -= at_source;
  return phi;
}

std::pair<std::int64_t, double> nearest_surfel(const SurfelComplex& complex, Point3<double> p) {
  if (complex.surfel_count() == 0) throw InvalidArgument("nearest_surfel: no surfel");
  std::int64_t best = 0;
  double d2 = std::numeric_limits<double>::infinity();
  for (std::int64_t s = 0; s < complex.surfel_count(); ++s) {
    const P3 c = complex.centres[std::size_t(s)];
    const P3 d{c.x - p.x, c.y - p.y, c.z - p.z};
    const double e = dot(d, d);
    if (e < d2) {
      d2 = e;
      best = s;
    }
  }
  return {best, std::sqrt(d2)};
}

} // namespace zdg
