#include <zdg/kernel/linalg/generalized_eigen.hpp>

#include "tests/support/tower.hpp"

#include <zdg/arith/error.hpp>

#include <Eigen/Dense>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

namespace {

using zdg::SparseMatrix;
using zdg::SparseTriplet;

// x^T A y.
double form(const SparseMatrix& a, const std::vector<double>& x, const std::vector<double>& y) {
  const auto ay = a.multiply(y);
  double s = 0;
  for (std::size_t i = 0; i < x.size(); ++i) s += x[i] * ay[i];
  return s;
}

Eigen::MatrixXd dense(const SparseMatrix& a) {
  Eigen::MatrixXd d = Eigen::MatrixXd::Zero(a.rows, a.cols);
  for (std::int64_t i = 0; i < a.rows; ++i)
    for (auto p = a.row_start[std::size_t(i)]; p < a.row_start[std::size_t(i) + 1]; ++p)
      d(i, a.column[std::size_t(p)]) += a.value[std::size_t(p)];
  return d;
}

// B^T B + shift I for a random sparse B with small integer entries (symmetric, positive
// semi-definite; definite when shift > 0).
SparseMatrix random_gram(std::int64_t n, int entries, double shift) {
  std::vector<SparseTriplet> tb;
  for (int k = 0; k < entries; ++k)
    tb.push_back({*rc::gen::inRange<std::int64_t>(0, n), *rc::gen::inRange<std::int64_t>(0, n),
                  double(*rc::gen::inRange(-4, 5))});
  const auto b = SparseMatrix::from_triplets(n, n, tb);
  std::vector<SparseTriplet> t;
  for (std::int64_t r = 0; r < n; ++r)
    for (auto p = b.row_start[std::size_t(r)]; p < b.row_start[std::size_t(r) + 1]; ++p)
      for (auto q = b.row_start[std::size_t(r)]; q < b.row_start[std::size_t(r) + 1]; ++q)
        t.push_back({b.column[std::size_t(p)], b.column[std::size_t(q)],
                     b.value[std::size_t(p)] * b.value[std::size_t(q)]});
  for (std::int64_t i = 0; i < n; ++i) t.push_back({i, i, shift});
  return SparseMatrix::from_triplets(n, n, t);
}

// The graph Laplacian of the path 0 - 1 - ... - (n-1), closed into a cycle when `cycle`.
SparseMatrix graph_laplacian(std::int64_t n, bool cycle) {
  std::vector<SparseTriplet> t;
  const std::int64_t edges = cycle ? n : n - 1;
  for (std::int64_t i = 0; i < edges; ++i) {
    const std::int64_t j = (i + 1) % n;
    t.push_back({i, i, 1.0});
    t.push_back({j, j, 1.0});
    t.push_back({i, j, -1.0});
    t.push_back({j, i, -1.0});
  }
  return SparseMatrix::from_triplets(n, n, t);
}

SparseMatrix identity(std::int64_t n) {
  return SparseMatrix::diagonal(std::vector<double>(std::size_t(n), 1.0));
}

// Oracle: Eigen's dense GeneralizedSelfAdjointEigenSolver (A x = lambda B x, B SPD). Random
// SPD L = B^T B + I and a random sparse SPD mass M = C^T C + I: the k smallest eigenvalues
// agree to 1e-8 relative to the largest, the pairs satisfy L x = lambda M x, and the vectors
// are M-orthonormal.
TEST(GeneralizedEigen, MatchesDenseGeneralizedSelfAdjointSolver) {
  zdg::test::check_property([] {
    const auto n = *rc::gen::inRange<std::int64_t>(3, 40);
    const auto k = *rc::gen::inRange<std::int64_t>(1, n);
    const SparseMatrix l = random_gram(n, *rc::gen::inRange(0, 80), 1.0);
    const SparseMatrix m = random_gram(n, *rc::gen::inRange(0, 40), 1.0);
    const auto got = zdg::smallest_generalized_eigenpairs(l, m, k);
    Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> oracle(dense(l), dense(m));
    RC_ASSERT(oracle.info() == Eigen::Success);
    const Eigen::VectorXd want = oracle.eigenvalues(); // increasing
    const double scale = want(n - 1);
    RC_ASSERT(got.values.size() == std::size_t(k));
    for (std::int64_t i = 0; i < k; ++i) {
      RC_ASSERT(std::abs(got.values[std::size_t(i)] - want(i)) <= 1e-8 * scale);
      const auto& x = got.vectors[std::size_t(i)];
      const auto lx = l.multiply(x), mx = m.multiply(x);
      double r = 0;
      for (std::int64_t j = 0; j < n; ++j)
        r = std::max(
            r, std::abs(lx[std::size_t(j)] - got.values[std::size_t(i)] * mx[std::size_t(j)]));
      RC_ASSERT(r <= 1e-7 * scale);
      for (std::int64_t j = 0; j < k; ++j)
        RC_ASSERT(std::abs(form(m, x, got.vectors[std::size_t(j)]) - (i == j ? 1.0 : 0.0)) <= 1e-8);
    }
  });
}

// Regression (shrunk by RapidCheck from MatchesDenseGeneralizedSelfAdjointSolver: n = 23,
// k = 7, an eigenvalue 1 of high multiplicity): Lanczos from one starting vector sees one copy
// of a multiple eigenvalue; the inertia certificate and the deflated runs find every copy.
TEST(GeneralizedEigen, RegressionEveryCopyOfAMultipleEigenvalueIsFound) {
  const std::int64_t n = 30;
  std::vector<SparseTriplet> t;
  for (std::int64_t i = 0; i < n; ++i) t.push_back({i, i, i < 6 ? 1.0 : double(i - 4)});
  const SparseMatrix l = SparseMatrix::from_triplets(n, n, t);
  const auto got = zdg::smallest_generalized_eigenpairs(l, identity(n), 8);
  const std::vector<double> want{1, 1, 1, 1, 1, 1, 2, 3};
  ASSERT_EQ(got.values.size(), want.size());
  for (std::size_t i = 0; i < want.size(); ++i) EXPECT_NEAR(got.values[i], want[i], 1e-9) << i;
  for (std::size_t i = 0; i < want.size(); ++i)
    for (std::size_t j = 0; j < want.size(); ++j)
      EXPECT_NEAR(form(identity(n), got.vectors[i], got.vectors[j]), i == j ? 1.0 : 0.0, 1e-9);
}

// Path graph P_n: eigenvalues 2 - 2 cos(pi j / n); cycle C_n: 2 - 2 cos(2 pi j / n), each
// j and n - j together (multiplicity 2 for 0 < j < n/2).
TEST(GeneralizedEigen, PathAndCycleGraphLaplaciansHaveTheirClosedFormSpectra) {
  for (const bool cycle : {false, true}) {
    for (const std::int64_t n : {5, 12, 60}) {
      const std::int64_t k = std::min<std::int64_t>(n - 1, 9);
      const auto got =
          zdg::smallest_generalized_eigenpairs(graph_laplacian(n, cycle), identity(n), k);
      std::vector<double> want;
      for (std::int64_t j = 0; j < n; ++j)
        want.push_back(2 -
                       2 * std::cos((cycle ? 2 : 1) * std::numbers::pi * double(j) / double(n)));
      std::sort(want.begin(), want.end());
      for (std::int64_t i = 0; i < k; ++i)
        EXPECT_NEAR(got.values[std::size_t(i)], want[std::size_t(i)], 1e-9)
            << (cycle ? "cycle" : "path") << " n = " << n << " i = " << i;
    }
  }
}

// A connected graph's Laplacian with a positive diagonal mass: lambda_1 = 0 with the constant
// eigenvector (M-normalized: 1 / sqrt(sum M_ii)), the others positive; the eigenvectors are
// M-orthonormal.
TEST(GeneralizedEigen, ConstantsSpanTheKernelAndVectorsAreMOrthonormal) {
  const std::int64_t n = 40;
  std::vector<double> mass;
  for (std::int64_t i = 0; i < n; ++i) mass.push_back(0.5 + 0.01 * double(i * i % 17));
  const SparseMatrix m = SparseMatrix::diagonal(mass);
  const auto got = zdg::smallest_generalized_eigenpairs(graph_laplacian(n, true), m, 6);
  double total = 0;
  for (double w : mass) total += w;
  EXPECT_NEAR(got.values[0], 0.0, 1e-10);
  for (double v : got.vectors[0]) EXPECT_NEAR(std::abs(v), 1 / std::sqrt(total), 1e-9);
  for (std::size_t i = 1; i < got.values.size(); ++i) EXPECT_GT(got.values[i], 1e-4);
  for (std::size_t i = 0; i < got.vectors.size(); ++i)
    for (std::size_t j = 0; j < got.vectors.size(); ++j)
      EXPECT_NEAR(form(m, got.vectors[i], got.vectors[j]), i == j ? 1.0 : 0.0, 1e-10);
  EXPECT_LT(got.shift, 0.0);
  EXPECT_GT(got.operations, 0);
}

// The error's message, or "" when f does not throw E.
template <class E, class F>
std::string message(F&& f) {
  try {
    f();
  } catch (const E& e) {
    return e.what();
  }
  return "";
}

TEST(GeneralizedEigen, BadInputIsOneLineInvalidArgument) {
  const SparseMatrix l = graph_laplacian(6, true), m = identity(6);
  auto eigs = [&](const SparseMatrix& a, const SparseMatrix& b, std::int64_t k) {
    return [&a, &b, k] { zdg::smallest_generalized_eigenpairs(a, b, k); };
  };
  const auto too_many = message<zdg::InvalidArgument>(eigs(l, m, 6));
  EXPECT_NE(too_many.find("k = 6"), std::string::npos) << too_many;
  EXPECT_NE(message<zdg::InvalidArgument>(eigs(l, m, 0)).find("1 <= k < n"), std::string::npos);
  const SparseMatrix m5 = identity(5);
  EXPECT_NE(message<zdg::InvalidArgument>(eigs(l, m5, 2)).find("sizes differ"), std::string::npos);
  const SparseMatrix rect = SparseMatrix::from_triplets(6, 5, {{0, 0, 1.0}});
  EXPECT_NE(message<zdg::InvalidArgument>(eigs(rect, m, 2)).find("not square"), std::string::npos);
  const SparseMatrix skew = SparseMatrix::from_triplets(6, 6, {{0, 1, 1.0}, {1, 1, 2.0}});
  EXPECT_NE(message<zdg::InvalidArgument>(eigs(skew, m, 2)).find("not symmetric"),
            std::string::npos);
  const SparseMatrix singular_mass = SparseMatrix::diagonal(std::vector<double>{1, 1, 0, 1, 1, 1});
  EXPECT_NE(message<zdg::InvalidArgument>(eigs(l, singular_mass, 2)).find("M is not positive"),
            std::string::npos);
  // An indefinite L: L - sigma M does not factor.
  const SparseMatrix indefinite = zdg::add(-1.0, l, 0.0, l);
  EXPECT_NE(message<zdg::Error>(eigs(indefinite, m, 2)).find("not positive definite"),
            std::string::npos);
  for (const auto& text : {too_many}) EXPECT_EQ(text.find('\n'), std::string::npos);
}

} // namespace
