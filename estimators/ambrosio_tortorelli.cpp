#include <zdg/estimators/ambrosio_tortorelli.hpp>

#include <zdg/arith/error.hpp>
#include <zdg/kernel/linalg/sparse_spd_solver.hpp>

#include <algorithm>
#include <cmath>
#include <optional>
#include <string>

namespace zdg {

namespace {

std::size_t idx(std::int64_t i) {
  return static_cast<std::size_t>(i);
}

void check_eps(double eps) {
  if (!(eps > 0) || !std::isfinite(eps))
    throw InvalidArgument("Ambrosio-Tortorelli: eps must be positive, got " + std::to_string(eps));
}

void check_surfel_field(const SurfelComplex& c, std::span<const Point3<double>> f,
                        const char* name) {
  if (static_cast<std::int64_t>(f.size()) != c.surfel_count())
    throw InvalidArgument(std::string("Ambrosio-Tortorelli: ") + name + " has " +
                          std::to_string(f.size()) + " entries for " +
                          std::to_string(c.surfel_count()) + " surfels");
  for (std::size_t i = 0; i < f.size(); ++i)
    if (!std::isfinite(f[i].x) || !std::isfinite(f[i].y) || !std::isfinite(f[i].z))
      throw InvalidArgument(std::string("Ambrosio-Tortorelli: ") + name + " at surfel " +
                            std::to_string(i) + " is not finite");
}

void check_linel_field(const SurfelComplex& c, std::span<const double> v) {
  if (static_cast<std::int64_t>(v.size()) != c.linel_count())
    throw InvalidArgument("Ambrosio-Tortorelli: v has " + std::to_string(v.size()) +
                          " entries for " + std::to_string(c.linel_count()) + " linels");
  for (std::size_t i = 0; i < v.size(); ++i)
    if (!std::isfinite(v[i]))
      throw InvalidArgument("Ambrosio-Tortorelli: v at linel " + std::to_string(i) +
                            " is not finite");
}

/// |d0 u|^2 per linel.
std::vector<double> squared_coboundary(const SurfelComplex& c, std::span<const Point3<double>> u) {
  std::vector<double> d(c.linels.size());
  for (std::size_t e = 0; e < d.size(); ++e) {
    const auto& l = c.linels[e];
    const Point3<double> du = u[idx(l.face[1])] - u[idx(l.face[0])];
    d[e] = dot(du, du);
  }
  return d;
}

/// The triplets of L (see the header): per cell c with k incident linels, (1/k)(k I - 1 1^T).
void append_laplacian(const SurfelComplex& c, double scale, std::vector<SparseTriplet>& t) {
  const auto add_clique = [&](std::span<const std::int64_t> cell) {
    const double w = scale / static_cast<double>(cell.size());
    for (std::size_t i = 0; i < cell.size(); ++i)
      for (std::size_t j = 0; j < cell.size(); ++j)
        t.push_back(
            {cell[i], cell[j], (i == j ? static_cast<double>(cell.size()) - 1.0 : -1.0) * w});
  };
  for (const auto& sides : c.surfel_linels) add_clique(sides);
  // Linels around each pointel: counting sort by pointel.
  const std::size_t np = c.pointels.size();
  std::vector<std::int64_t> start(np + 1, 0);
  for (const auto& l : c.linels) {
    ++start[idx(l.a) + 1];
    ++start[idx(l.b) + 1];
  }
  for (std::size_t p = 0; p < np; ++p) start[p + 1] += start[p];
  std::vector<std::int64_t> around(idx(start[np]));
  std::vector<std::int64_t> fill(start.begin(), start.end() - 1);
  for (std::size_t e = 0; e < c.linels.size(); ++e) {
    around[idx(fill[idx(c.linels[e].a)]++)] = static_cast<std::int64_t>(e);
    around[idx(fill[idx(c.linels[e].b)]++)] = static_cast<std::int64_t>(e);
  }
  for (std::size_t p = 0; p < np; ++p)
    if (start[p + 1] > start[p])
      add_clique(
          std::span<const std::int64_t>(around.data() + start[p], idx(start[p + 1] - start[p])));
}

} // namespace

SparseMatrix at_linel_laplacian(const SurfelComplex& complex) {
  std::vector<SparseTriplet> t;
  t.reserve(complex.linels.size() * 36);
  append_laplacian(complex, 1.0, t);
  return SparseMatrix::from_triplets(complex.linel_count(), complex.linel_count(), std::move(t));
}

namespace {

double energy(const SurfelComplex& complex, std::span<const Point3<double>> g,
              std::span<const Point3<double>> u, std::span<const double> v,
              const ATParameters& parameters, double eps, const SparseMatrix& L) {
  double data = 0;
  for (std::size_t s = 0; s < g.size(); ++s) {
    const Point3<double> d = u[s] - g[s];
    data += dot(d, d);
  }
  const auto du2 = squared_coboundary(complex, u);
  double coupling = 0, well = 0;
  for (std::size_t e = 0; e < v.size(); ++e) {
    coupling += v[e] * v[e] * du2[e];
    well += (1 - v[e]) * (1 - v[e]);
  }
  const auto lv = L.multiply(v);
  double dirichlet = 0;
  for (std::size_t e = 0; e < v.size(); ++e) dirichlet += v[e] * lv[e];
  const double a = parameters.alpha, l = parameters.lambda;
  return a * data + coupling + l * eps * dirichlet + l / (4 * eps) * well;
}

} // namespace

double at_energy(const SurfelComplex& complex, std::span<const Point3<double>> g,
                 std::span<const Point3<double>> u, std::span<const double> v,
                 const ATParameters& parameters, double eps) {
  check_at_parameters(parameters, "Ambrosio-Tortorelli");
  check_eps(eps);
  check_surfel_field(complex, g, "g");
  check_surfel_field(complex, u, "u");
  check_linel_field(complex, v);
  return energy(complex, g, u, v, parameters, eps, at_linel_laplacian(complex));
}

namespace {

struct USolve {
  std::vector<Point3<double>> u;
  SpdBackend backend = SpdBackend::automatic;
};

// The matrices of the two steps; their patterns do not change from one iteration to the next
// (explicit zeros are kept), so each solver is analysed once and refactored after.
SparseMatrix u_matrix(const SurfelComplex& c, std::span<const double> v, double alpha) {
  const std::int64_t n = c.surfel_count();
  std::vector<SparseTriplet> t;
  t.reserve(idx(n) + 4 * c.linels.size());
  for (std::int64_t s = 0; s < n; ++s) t.push_back({s, s, alpha});
  for (std::size_t e = 0; e < c.linels.size(); ++e) {
    const double w = v[e] * v[e];
    const auto f0 = c.linels[e].face[0], f1 = c.linels[e].face[1];
    t.push_back({f0, f0, w});
    t.push_back({f1, f1, w});
    t.push_back({f0, f1, -w});
    t.push_back({f1, f0, -w});
  }
  return SparseMatrix::from_triplets(n, n, std::move(t));
}

// Factors m into the solver (the first time: analysis and factorization).
void factor(std::optional<SparseSpdSolver>& solver, const SparseMatrix& m) {
  if (solver) {
    solver->refactor(m);
  } else {
    solver.emplace(m);
  }
}

USolve solve_u(const SurfelComplex& c, std::span<const Point3<double>> g, std::span<const double> v,
               double alpha, std::optional<SparseSpdSolver>& solver) {
  const std::int64_t n = c.surfel_count();
  factor(solver, u_matrix(c, v, alpha));
  std::vector<double> b(idx(n));
  USolve r;
  r.u.resize(idx(n));
  for (int k = 0; k < 3; ++k) {
    for (std::size_t s = 0; s < b.size(); ++s)
      b[s] = alpha * (k == 0 ? g[s].x : k == 1 ? g[s].y : g[s].z);
    const auto x = solver->solve(b);
    for (std::size_t s = 0; s < b.size(); ++s)
      (k == 0 ? r.u[s].x : k == 1 ? r.u[s].y : r.u[s].z) = x[s];
  }
  r.backend = solver->backend();
  return r;
}

std::vector<double> solve_v(const SurfelComplex& c, std::span<const Point3<double>> u,
                            double lambda, double eps, const SparseMatrix& L,
                            std::optional<SparseSpdSolver>& solver) {
  const double well = lambda / (4 * eps);
  auto d = squared_coboundary(c, u);
  for (auto& x : d) x += well;
  factor(solver, add(1.0, SparseMatrix::diagonal(d), lambda * eps, L));
  const std::vector<double> b(d.size(), well);
  return solver->solve(b);
}

} // namespace

std::vector<Point3<double>> at_solve_u(const SurfelComplex& complex,
                                       std::span<const Point3<double>> g, std::span<const double> v,
                                       const ATParameters& parameters) {
  check_at_parameters(parameters, "Ambrosio-Tortorelli");
  check_surfel_field(complex, g, "g");
  check_linel_field(complex, v);
  std::optional<SparseSpdSolver> solver;
  return solve_u(complex, g, v, parameters.alpha, solver).u;
}

std::vector<double> at_solve_v(const SurfelComplex& complex, std::span<const Point3<double>> u,
                               const ATParameters& parameters, double eps) {
  check_at_parameters(parameters, "Ambrosio-Tortorelli");
  check_eps(eps);
  check_surfel_field(complex, u, "u");
  std::optional<SparseSpdSolver> solver;
  return solve_v(complex, u, parameters.lambda, eps, at_linel_laplacian(complex), solver);
}

ATResult at_normals(const SurfelComplex& complex, std::span<const Point3<double>> g,
                    const ATParameters& parameters) {
  check_at_parameters(parameters, "Ambrosio-Tortorelli");
  check_surfel_field(complex, g, "g");
  ATResult r;
  r.u.assign(g.begin(), g.end());
  r.v.assign(complex.linels.size(), 1.0);
  SpdBackend backend = SpdBackend::automatic;
  const SparseMatrix L = at_linel_laplacian(complex);
  std::optional<SparseSpdSolver> u_solver, v_solver; // analysed once, refactored after
  const auto energy_now = [&](double eps) {
    return energy(complex, g, r.u, r.v, parameters, eps, L);
  };
  // The levels eps_k = epsilon1 / factor^k >= epsilon2 (a relative slack of 1e-12 so that
  // 2 -> 0.25 by halving keeps 0.25 whatever the rounding).
  for (int k = 0;; ++k) {
    const double eps = parameters.epsilon1 / std::pow(parameters.epsilon_factor, k);
    if (eps < parameters.epsilon2 * (1 - 1e-12)) break;
    r.steps.push_back({ATStep::Kind::start, eps, energy_now(eps), 0});
    for (int i = 0; i < parameters.max_iterations; ++i) {
      auto us = solve_u(complex, g, r.v, parameters.alpha, u_solver);
      r.u = std::move(us.u);
      backend = us.backend;
      r.steps.push_back({ATStep::Kind::u, eps, energy_now(eps), 0});
      auto v = solve_v(complex, r.u, parameters.lambda, eps, L, v_solver);
      double change = 0;
      for (std::size_t e = 0; e < v.size(); ++e) change = std::max(change, std::abs(v[e] - r.v[e]));
      r.v = std::move(v);
      r.steps.push_back({ATStep::Kind::v, eps, energy_now(eps), change});
      ++r.iterations;
      if (change < parameters.tolerance) break;
    }
  }
  r.normals.resize(r.u.size());
  for (std::size_t s = 0; s < r.u.size(); ++s) {
    const double n = std::sqrt(dot(r.u[s], r.u[s]));
    r.normals[s] = n > 0 ? (1 / n) * r.u[s] : g[s];
  }
  r.backend = spd_backend_name(
      backend == SpdBackend::automatic
          ? (SparseSpdSolver::cholmod_available() ? SpdBackend::cholmod : SpdBackend::eigen_ldlt)
          : backend);
  return r;
}

std::vector<double> at_surfel_v(const SurfelComplex& complex, std::span<const double> v,
                                ATSurfelPolicy policy) {
  check_linel_field(complex, v);
  std::vector<double> out(complex.surfel_linels.size());
  for (std::size_t s = 0; s < out.size(); ++s) {
    const auto& sides = complex.surfel_linels[s];
    double m = policy == ATSurfelPolicy::minimum ? v[idx(sides[0])] : 0.0;
    for (const auto e : sides)
      m = policy == ATSurfelPolicy::minimum ? std::min(m, v[idx(e)]) : m + 0.25 * v[idx(e)];
    out[s] = m;
  }
  return out;
}

void check_at_parameters(const ATParameters& p, const std::string& who) {
  const auto bad = [&who](const std::string& what) { throw InvalidArgument(who + ": " + what); };
  if (!(p.alpha > 0) || !std::isfinite(p.alpha))
    bad("alpha must be positive, got " + std::to_string(p.alpha));
  if (!(p.lambda > 0) || !std::isfinite(p.lambda))
    bad("lambda must be positive, got " + std::to_string(p.lambda));
  if (!(p.epsilon2 > 0) || !std::isfinite(p.epsilon2))
    bad("epsilon2 must be positive, got " + std::to_string(p.epsilon2));
  if (!(p.epsilon1 >= p.epsilon2) || !std::isfinite(p.epsilon1))
    bad("epsilon1 = " + std::to_string(p.epsilon1) +
        " must be at least epsilon2 = " + std::to_string(p.epsilon2));
  if (!(p.epsilon_factor > 1) || !std::isfinite(p.epsilon_factor))
    bad("the epsilon factor must be above 1, got " + std::to_string(p.epsilon_factor));
  if (p.max_iterations < 1)
    bad("max_iterations must be at least 1, got " + std::to_string(p.max_iterations));
  if (!(p.tolerance >= 0) || !std::isfinite(p.tolerance))
    bad("the tolerance must be non-negative, got " + std::to_string(p.tolerance));
}

} // namespace zdg
