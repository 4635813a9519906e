#include <zdg/kernel/calculus/hodge_decomposition.hpp>

#include <zdg/arith/error.hpp>
#include <zdg/kernel/calculus/exterior_derivative.hpp>

#include <cmath>
#include <numeric>

namespace zdg {

namespace {

// Union-find over n items: the representative of each item's component (for grounding).
struct Components {
  std::vector<std::int64_t> parent;
  explicit Components(std::size_t n) : parent(n) { std::iota(parent.begin(), parent.end(), 0); }
  std::int64_t find(std::int64_t x) {
    while (parent[std::size_t(x)] != x) {
      parent[std::size_t(x)] = parent[std::size_t(parent[std::size_t(x)])];
      x = parent[std::size_t(x)];
    }
    return x;
  }
  void join(std::int64_t a, std::int64_t b) {
    a = find(a);
    b = find(b);
    if (a != b) parent[std::size_t(std::max(a, b))] = std::min(a, b);
  }
};

// Solves (D^T W D) x = D^T W y grounded at one unknown per component: D is an incidence
// matrix (rows: the edges of a graph on its columns, weights W per row), rhs = D^T W y.
std::vector<double> grounded_solve(const IncidenceMatrix& d, std::span<const double> w,
                                   std::span<const double> y, SpdBackend backend,
                                   std::string& solver) {
  const auto n = std::size_t(d.cols);
  Components comp(n);
  for (std::int64_t r = 0; r < d.rows; ++r)
    for (auto k = d.row_start[std::size_t(r)] + 1; k < d.row_start[std::size_t(r) + 1]; ++k)
      comp.join(d.column[std::size_t(d.row_start[std::size_t(r)])], d.column[std::size_t(k)]);
  std::vector<char> grounded(n, 0);
  for (std::size_t i = 0; i < n; ++i) grounded[i] = comp.find(std::int64_t(i)) == std::int64_t(i);
  std::vector<SparseTriplet> t;
  std::vector<double> rhs(n, 0.0);
  for (std::int64_t r = 0; r < d.rows; ++r) {
    const auto b = d.row_start[std::size_t(r)], e = d.row_start[std::size_t(r) + 1];
    const double wr = w[std::size_t(r)];
    for (auto k = b; k < e; ++k) {
      const auto i = d.column[std::size_t(k)];
      if (grounded[std::size_t(i)]) continue;
      rhs[std::size_t(i)] += d.value[std::size_t(k)] * wr * y[std::size_t(r)];
      for (auto l = b; l < e; ++l) {
        const auto j = d.column[std::size_t(l)];
        if (grounded[std::size_t(j)]) continue;
        t.push_back({i, j, double(d.value[std::size_t(k)] * d.value[std::size_t(l)]) * wr});
      }
    }
  }
  for (std::size_t i = 0; i < n; ++i)
    if (grounded[i]) t.push_back({std::int64_t(i), std::int64_t(i), 1.0});
  const SparseSpdSolver solve(
      SparseMatrix::from_triplets(std::int64_t(n), std::int64_t(n), std::move(t)), backend);
  solver = spd_backend_name(solve.backend());
  auto x = solve.solve(rhs);
  for (std::size_t i = 0; i < n; ++i)
    if (grounded[i]) x[i] = 0;
  return x;
}

} // namespace

HodgeDecomposition hodge_decomposition(const SurfelComplex& c, const HodgeStars& stars,
                                       std::span<const double> omega, SpdBackend backend) {
  const auto ne = std::size_t(c.linel_count()), nf = std::size_t(c.surfel_count());
  if (omega.size() != ne)
    throw InvalidArgument("hodge decomposition: a 1-form of " + std::to_string(omega.size()) +
                          " values for " + std::to_string(ne) + " linels");
  if (stars.star1.size() != ne || stars.star2.size() != nf)
    throw InvalidArgument("hodge decomposition: the stars are not those of this complex");
  for (std::size_t e = 0; e < ne; ++e)
    if (!(stars.star1[e] > 0) || !std::isfinite(stars.star1[e]))
      throw InvalidArgument("hodge decomposition: star1 of linel " + std::to_string(e) + " is " +
                            std::to_string(stars.star1[e]) + " (positive stars needed)");
  for (std::size_t s = 0; s < nf; ++s)
    if (!(stars.star2[s] > 0) || !std::isfinite(stars.star2[s]))
      throw InvalidArgument("hodge decomposition: surfel " + std::to_string(s) +
                            " has measure 0 (star2 infinite)");
  HodgeDecomposition h;
  const auto d0 = primal_d0(c);
  h.alpha = grounded_solve(d0, stars.star1, omega, backend, h.solver);
  h.exact = d0.multiply(std::span<const double>(h.alpha));
  // d1 star1^{-1} d1^T gamma = d1 omega: the graph of d1^T (linels joining surfels), weights
  // 1 / star1, and y = star1 omega gives d1 (star1^{-1} star1 omega) = d1 omega.
  const auto d1t = dual_d0(c);
  std::vector<double> inv(ne), y(ne);
  for (std::size_t e = 0; e < ne; ++e) {
    inv[e] = 1 / stars.star1[e];
    y[e] = stars.star1[e] * omega[e];
  }
  const auto gamma = grounded_solve(d1t, inv, y, backend, h.solver);
  h.coexact = d1t.multiply(std::span<const double>(gamma));
  for (std::size_t e = 0; e < ne; ++e) h.coexact[e] *= inv[e];
  h.beta.resize(nf);
  for (std::size_t s = 0; s < nf; ++s) h.beta[s] = gamma[s] / stars.star2[s];
  h.harmonic.resize(ne);
  for (std::size_t e = 0; e < ne; ++e) h.harmonic[e] = omega[e] - h.exact[e] - h.coexact[e];
  return h;
}

} // namespace zdg
