#include <zdg/kernel/linalg/sparse_spd_solver.hpp>

#include "tests/support/peak_memory.hpp"
#include "tests/support/tower.hpp"

#include <zdg/arith/error.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <numbers>
#include <string>

namespace {

// A = B^T B + I for a random sparse B is SPD: the solver's x satisfies A x = b to rounding
// (the residual is the oracle), with every backend zdg was built with, and both backends
// agree.
TEST(SparseSpdSolver, SolvesRandomSpdSystemsOnEveryBackend) {
  zdg::test::check_property([] {
    const auto n = *rc::gen::inRange<std::int64_t>(1, 30);
    std::vector<zdg::SparseTriplet> tb;
    const int nb = *rc::gen::inRange(0, 60);
    for (int k = 0; k < nb; ++k)
      tb.push_back({*rc::gen::inRange<std::int64_t>(0, n), *rc::gen::inRange<std::int64_t>(0, n),
                    double(*rc::gen::inRange(-4, 5))});
    const auto b = zdg::SparseMatrix::from_triplets(n, n, tb);
    // B^T B as the sum over rows r of B of the outer products of the row.
    std::vector<zdg::SparseTriplet> ta;
    for (std::int64_t r = 0; r < n; ++r)
      for (auto k = b.row_start[std::size_t(r)]; k < b.row_start[std::size_t(r) + 1]; ++k)
        for (auto l = b.row_start[std::size_t(r)]; l < b.row_start[std::size_t(r) + 1]; ++l)
          ta.push_back({b.column[std::size_t(k)], b.column[std::size_t(l)],
                        b.value[std::size_t(k)] * b.value[std::size_t(l)]});
    for (std::int64_t i = 0; i < n; ++i) ta.push_back({i, i, 1.0});
    const auto a = zdg::SparseMatrix::from_triplets(n, n, ta);
    std::vector<double> rhs(static_cast<std::size_t>(n));
    for (auto& v : rhs) v = *rc::gen::inRange(-10, 11);
    std::vector<zdg::SpdBackend> backends{zdg::SpdBackend::eigen_ldlt};
    if (zdg::SparseSpdSolver::cholmod_available()) backends.push_back(zdg::SpdBackend::cholmod);
    std::vector<std::vector<double>> xs;
    const auto ordering =
        *rc::gen::element(zdg::SpdOrdering::minimum_degree, zdg::SpdOrdering::nested_dissection);
    for (auto be : backends) {
      const zdg::SparseSpdSolver s(a, be, ordering);
      RC_ASSERT(s.backend() == be);
      const auto x = s.solve(rhs);
      const auto ax = a.multiply(x);
      double scale = 1;
      for (auto v : a.value) scale = std::max(scale, std::abs(v));
      for (std::size_t i = 0; i < rhs.size(); ++i)
        RC_ASSERT(std::abs(ax[i] - rhs[i]) <= 1e-9 * scale * (1 + std::abs(rhs[i])));
      xs.push_back(x);
    }
    for (std::size_t k = 1; k < xs.size(); ++k)
      for (std::size_t i = 0; i < xs[0].size(); ++i)
        RC_ASSERT(std::abs(xs[k][i] - xs[0][i]) <= 1e-8 * (1 + std::abs(xs[0][i])));
  });
}

TEST(SparseSpdSolver, AutomaticTakesCholmodWhenBuiltWithIt) {
  const auto a = zdg::SparseMatrix::diagonal(std::vector<double>{2, 3});
  const zdg::SparseSpdSolver s(a);
  EXPECT_EQ(s.backend(), zdg::SparseSpdSolver::cholmod_available() ? zdg::SpdBackend::cholmod
                                                                   : zdg::SpdBackend::eigen_ldlt);
  const auto x = s.solve(std::vector<double>{4, 9});
  EXPECT_DOUBLE_EQ(x[0], 2.0);
  EXPECT_DOUBLE_EQ(x[1], 3.0);
  EXPECT_EQ(zdg::spd_backend_name(s.backend()),
            zdg::SparseSpdSolver::cholmod_available() ? "cholmod" : "eigen-simplicial-ldlt");
}

// A zdg built with CHOLMOD finds its library at run time (it is loaded, not linked: a missing
// or renamed library would silently fall back to Eigen's solver without this check).
TEST(SparseSpdSolver, BuiltWithCholmodLoadsIt) {
  if (zdg::SparseSpdSolver::cholmod_library().empty()) GTEST_SKIP() << "built without CHOLMOD";
  EXPECT_TRUE(zdg::SparseSpdSolver::cholmod_available())
      << zdg::SparseSpdSolver::cholmod_library() << " did not load";
}

// CHOLMOD (and OpenBLAS behind it) is loaded by the first solver that asks for it, not when a
// process starts: in a fresh process (the death test's child runs this binary again with this
// test alone) it is not mapped before the solver and is after.
TEST(SparseSpdSolver, CholmodIsLoadedAtItsFirstUseOnly) {
  if (zdg::SparseSpdSolver::cholmod_library().empty()) GTEST_SKIP() << "built without CHOLMOD";
  GTEST_FLAG_SET(death_test_style, "threadsafe");
  EXPECT_EXIT(
      {
        const bool before = zdg::test::library_mapped("libcholmod");
        const zdg::SparseSpdSolver s(zdg::SparseMatrix::diagonal(std::vector<double>{2, 3}),
                                     zdg::SpdBackend::cholmod);
        const bool after = zdg::test::library_mapped("libcholmod");
        std::exit(!before && after && std::abs(s.solve(std::vector<double>{4, 9})[1] - 3.0) < 1e-12
                      ? 0
                      : 1);
      },
      ::testing::ExitedWithCode(0), "");
}

TEST(SparseSpdSolver, RefusesIndefiniteNonSquareAndWrongSizes) {
  const auto indefinite = zdg::SparseMatrix::diagonal(std::vector<double>{1, -1});
  EXPECT_THROW(zdg::SparseSpdSolver(indefinite, zdg::SpdBackend::eigen_ldlt), zdg::Error);
  if (zdg::SparseSpdSolver::cholmod_available())
    EXPECT_THROW(zdg::SparseSpdSolver(indefinite, zdg::SpdBackend::cholmod), zdg::Error);
  else
    EXPECT_THROW(zdg::SparseSpdSolver(indefinite, zdg::SpdBackend::cholmod), zdg::InvalidArgument);
  EXPECT_THROW(zdg::SparseSpdSolver(zdg::SparseMatrix::from_triplets(2, 3, {})),
               zdg::InvalidArgument);
  const zdg::SparseSpdSolver s(zdg::SparseMatrix::diagonal(std::vector<double>{1, 1}));
  EXPECT_THROW(s.solve(std::vector<double>{1}), zdg::InvalidArgument);
}

} // namespace

// refactor: the numeric factorization of a matrix with the analysed pattern gives the solution
// of the new system on every backend (a tridiagonal SPD matrix whose values change, explicit
// zeros included); a different pattern is refused.
TEST(SparseSpdSolver, RefactorReusesTheAnalysisOfThePattern) {
  const auto tridiagonal = [](double diag, double off) {
    std::vector<zdg::SparseTriplet> t;
    for (std::int64_t i = 0; i < 50; ++i) {
      t.push_back({i, i, diag + 0.01 * double(i)});
      if (i > 0) {
        t.push_back({i, i - 1, off});
        t.push_back({i - 1, i, off});
      }
    }
    return zdg::SparseMatrix::from_triplets(50, 50, std::move(t));
  };
  std::vector<zdg::SpdBackend> backends{zdg::SpdBackend::eigen_ldlt};
  if (zdg::SparseSpdSolver::cholmod_available()) backends.push_back(zdg::SpdBackend::cholmod);
  const std::vector<double> rhs(50, 1.0);
  for (auto be : backends) {
    zdg::SparseSpdSolver s(tridiagonal(4, -1), be);
    for (double off : {-1.5, 0.0, 0.7}) { // 0: explicit zeros keep the pattern
      const auto a = tridiagonal(3, off);
      s.refactor(a);
      const auto x = s.solve(rhs);
      const auto ax = a.multiply(x);
      for (std::size_t i = 0; i < rhs.size(); ++i) EXPECT_NEAR(ax[i], rhs[i], 1e-12);
    }
    EXPECT_THROW(s.refactor(zdg::SparseMatrix::diagonal(std::vector<double>(50, 1.0))),
                 zdg::InvalidArgument);
    // Not positive definite: an Error, and no line of CHOLMOD's own (it prints its warnings
    // with printf, on stdout, where a command's --json goes): the caller reports the failure.
    testing::internal::CaptureStdout();
    testing::internal::CaptureStderr();
    EXPECT_THROW(s.refactor(tridiagonal(0.5, -2)), zdg::Error);
    EXPECT_EQ(testing::internal::GetCapturedStderr(), "");
    EXPECT_EQ(testing::internal::GetCapturedStdout(), "");
  }
}

namespace zdg {
namespace {

// Sylvester's law of inertia: the negative pivots of LDL^T count the negative eigenvalues.
// Oracle: the closed form of a diagonal matrix congruent-transformed by a random unit lower
// bidiagonal B (A = B D B^T has the inertia of D), with D's signs drawn at random; |d_i| in
// {4, 5} and |b_i| <= 1/8 keep A strictly diagonally dominant, so that no pivot is 0 in any
// elimination order (a singular leading minor is an Error by the contract).
TEST(SparseSpdSolver, NegativeInertiaIsTheNumberOfNegativeEigenvalues) {
  test::check_property([] {
    const auto n = *rc::gen::inRange<std::int64_t>(1, 40);
    std::vector<double> d;
    std::int64_t negative = 0;
    for (std::int64_t i = 0; i < n; ++i) {
      const double v = double(*rc::gen::inRange(4, 6)) * (*rc::gen::arbitrary<bool>() ? 1 : -1);
      negative += v < 0;
      d.push_back(v);
    }
    std::vector<double> b(std::size_t(n), 0.0); // B = I + sub-diagonal b
    for (std::int64_t i = 1; i < n; ++i) b[std::size_t(i)] = double(*rc::gen::inRange(-1, 2)) / 8;
    // (B D B^T)_ii = d_i + b_i^2 d_{i-1}, (B D B^T)_{i,i-1} = b_i d_{i-1}.
    std::vector<SparseTriplet> t;
    for (std::int64_t i = 0; i < n; ++i) {
      const auto u = std::size_t(i);
      t.push_back({i, i, d[u] + (i > 0 ? b[u] * b[u] * d[u - 1] : 0.0)});
      if (i > 0) {
        t.push_back({i, i - 1, b[u] * d[u - 1]});
        t.push_back({i - 1, i, b[u] * d[u - 1]});
      }
    }
    RC_ASSERT(negative_inertia(SparseMatrix::from_triplets(n, n, t)) == negative);
  });
  EXPECT_THROW(negative_inertia(SparseMatrix::from_triplets(2, 3, {})), InvalidArgument);
  EXPECT_THROW(negative_inertia(SparseMatrix::from_triplets(2, 2, {{0, 0, 1.0}})), Error);
}

// The a x b grid graph's Laplacian G (the Cartesian product of two paths) has the closed-form
// eigenvalues (2 - 2 cos(pi i / a)) + (2 - 2 cos(pi j / b)), 0 <= i < a, 0 <= j < b: the
// solver's inertia of G - mu I, on the analysis of G + I (same pattern), is the number of them
// below mu, for mu between two consecutive distinct ones, on every backend and ordering.
// Grids up to 70 x 70 make supernodes wider than the 32-column blocks of the CHOLMOD panel.
TEST(SparseSpdSolver, SolverNegativeInertiaCountsTheGridLaplacianEigenvaluesBelowMu) {
  test::check_property([] {
    const auto a = *rc::gen::inRange<std::int64_t>(1, 71);
    const auto b = *rc::gen::inRange<std::int64_t>(2, 71);
    const auto shifted = [&](double mu) {
      std::vector<SparseTriplet> t;
      for (std::int64_t x = 0; x < a; ++x) {
        for (std::int64_t y = 0; y < b; ++y) {
          const std::int64_t i = x * b + y;
          const double degree = double((x > 0) + (x + 1 < a) + (y > 0) + (y + 1 < b));
          t.push_back({i, i, degree - mu});
          for (const std::int64_t j : {x + 1 < a ? i + b : i, y + 1 < b ? i + 1 : i}) {
            if (j == i) continue;
            t.push_back({i, j, -1.0});
            t.push_back({j, i, -1.0});
          }
        }
      }
      return SparseMatrix::from_triplets(a * b, a * b, t);
    };
    std::vector<double> spectrum;
    for (std::int64_t i = 0; i < a; ++i)
      for (std::int64_t j = 0; j < b; ++j)
        spectrum.push_back(4 - 2 * std::cos(std::numbers::pi * double(i) / double(a)) -
                           2 * std::cos(std::numbers::pi * double(j) / double(b)));
    std::sort(spectrum.begin(), spectrum.end());
    const auto at = *rc::gen::inRange<std::size_t>(1, spectrum.size());
    RC_PRE(spectrum[at] - spectrum[at - 1] > 1e-6);
    // Not halfway, nor at 1/sqrt 2 of the gap (the spectrum has sqrt 2 in it): the integer
    // matrix minus an integer or dyadic mu can have a leading minor exactly 0.
    const double mu = spectrum[at - 1] + (spectrum[at] - spectrum[at - 1]) / std::numbers::pi;
    const auto want = static_cast<std::int64_t>(at);
    std::vector<SpdBackend> backends{SpdBackend::eigen_ldlt};
    if (SparseSpdSolver::cholmod_available()) backends.push_back(SpdBackend::cholmod);
    for (const auto backend : backends) {
      for (const auto ordering : {SpdOrdering::minimum_degree, SpdOrdering::nested_dissection}) {
        const SparseSpdSolver s(shifted(-1), backend, ordering);
        RC_ASSERT(s.negative_inertia(shifted(-0.5)) == 0);
        const SparseMatrix shifted_mu = shifted(mu);
        RC_ASSERT(s.negative_inertia(shifted_mu) == want);
        // The LDL^T kept solves B x = r (CHOLMOD): the residual is the oracle (B is at least
        // (1 - 1/pi) of the gap away from singular).
        std::vector<double> r(std::size_t(shifted_mu.rows), 0.0);
        for (std::size_t i = 0; i < r.size(); ++i) r[i] = double(int(i % 7) - 3);
        if (backend == SpdBackend::cholmod) {
          const auto x = s.solve_counted(r);
          const auto bx = shifted_mu.multiply(x);
          double gap = spectrum[at] - spectrum[at - 1], xmax = 0;
          for (const double v : x) xmax = std::max(xmax, std::abs(v));
          for (std::size_t i = 0; i < r.size(); ++i)
            RC_ASSERT(std::abs(bx[i] - r[i]) <= 1e-8 * (1 + xmax) / std::min(gap, 1.0));
        } else {
          RC_ASSERT_THROWS_AS(s.solve_counted(r), InvalidArgument);
        }
      }
    }
  });
  const SparseSpdSolver s(SparseMatrix::diagonal(std::vector<double>{1, 2, 3}));
  EXPECT_THROW(s.solve_counted(std::vector<double>{1, 2, 3}), InvalidArgument); // nothing counted
  EXPECT_EQ(s.negative_inertia(SparseMatrix::diagonal(std::vector<double>{-1, 2, -3})), 2);
  EXPECT_THROW(s.negative_inertia(SparseMatrix::diagonal(std::vector<double>{1, 0, 3})), Error);
  EXPECT_THROW(s.negative_inertia(SparseMatrix::diagonal(std::vector<double>{1, 2})),
               InvalidArgument);
  EXPECT_THROW(s.negative_inertia(SparseMatrix::from_triplets(3, 3, {{0, 1, 1.0}})),
               InvalidArgument);
}

} // namespace
} // namespace zdg
