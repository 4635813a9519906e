#include <zdg/kernel/calculus/hodge_decomposition.hpp>

#include <zdg/arith/error.hpp>
#include <zdg/kernel/calculus/exterior_derivative.hpp>
#include <zdg/kernel/calculus/sharp_flat.hpp>

#include "tests/support/image_complex.hpp"
#include "tests/support/tower.hpp"

#include <Eigen/Dense>
#include <gtest/gtest.h>
#include <rapidcheck.h>

#include <cmath>
#include <random>

namespace {

using zdg::CellMeasure;
using zdg::Point3;

double inner(const std::vector<double>& a, const std::vector<double>& b,
             const std::vector<double>& w) {
  double s = 0;
  for (std::size_t i = 0; i < a.size(); ++i) s += w[i] * a[i] * b[i];
  return s;
}

double max_abs(const std::vector<double>& v) {
  double m = 0;
  for (double x : v) m = std::max(m, std::abs(x));
  return m;
}

// Normals a little off the elementary ones (positive measures, unequal stars).
std::vector<Point3<double>> tilted_normals(const zdg::SurfelComplex& c) {
  std::vector<Point3<double>> n;
  for (std::size_t s = 0; s < c.normals.size(); ++s) {
    const auto t =
        c.normals[s] + Point3<double>{0.1 * std::sin(double(s)), 0.2 * std::cos(double(s)), 0.05};
    n.push_back((1 / std::sqrt(dot(t, t))) * t);
  }
  return n;
}

// The decomposition adds up, its parts are what they claim (h closed and co-closed, the three
// parts orthogonal in the star1 inner product), and the harmonic parts of 2g + 3 random
// 1-forms span a space of dimension 2g (numerical rank of their Gram matrix): the numerical
// counterpart of kernel/calculus/harmonic_dimension.hpp, for both kinds of stars.
void check_decomposition(const zdg::test::ImageComplex& ic, std::int64_t genus) {
  const auto& c = ic.complex;
  const auto d0 = zdg::primal_d0(c), d1 = zdg::primal_d1(c);
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> uni(-1, 1);
  for (const auto m : {CellMeasure::cubical, CellMeasure::corrected_absolute}) {
    const auto stars = zdg::hodge_stars(c, m, tilted_normals(c));
    const int k = int(2 * genus + 3);
    Eigen::MatrixXd gram(k, k);
    std::vector<std::vector<double>> hs;
    for (int r = 0; r < k; ++r) {
      std::vector<double> omega(std::size_t(c.linel_count()));
      for (auto& x : omega) x = uni(rng);
      const auto h = zdg::hodge_decomposition(c, stars, omega);
      for (std::size_t e = 0; e < omega.size(); ++e)
        EXPECT_NEAR(h.exact[e] + h.coexact[e] + h.harmonic[e], omega[e], 1e-12);
      EXPECT_LT(max_abs(d1.multiply(std::span<const double>(h.harmonic))), 1e-9);
      std::vector<double> sh(h.harmonic.size());
      for (std::size_t e = 0; e < sh.size(); ++e) sh[e] = stars.star1[e] * h.harmonic[e];
      EXPECT_LT(max_abs(d0.transpose().multiply(std::span<const double>(sh))), 1e-9);
      EXPECT_NEAR(inner(h.exact, h.coexact, stars.star1), 0.0, 1e-9);
      EXPECT_NEAR(inner(h.exact, h.harmonic, stars.star1), 0.0, 1e-9);
      EXPECT_NEAR(inner(h.coexact, h.harmonic, stars.star1), 0.0, 1e-9);
      hs.push_back(h.harmonic);
    }
    for (int i = 0; i < k; ++i)
      for (int j = 0; j < k; ++j)
        gram(i, j) = inner(hs[std::size_t(i)], hs[std::size_t(j)], stars.star1);
    const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(gram);
    const double top = eig.eigenvalues().maxCoeff();
    int rank = 0;
    for (int i = 0; i < k; ++i) rank += eig.eigenvalues()(i) > 1e-9 * std::max(top, 1.0);
    EXPECT_EQ(rank, 2 * genus);
  }
}

TEST(HodgeDecomposition, HarmonicPartsHaveDimensionTwiceTheGenus) {
  check_decomposition(zdg::test::image_complex(zdg::test::ring_torus()), 1);
  check_decomposition(zdg::test::image_complex(zdg::test::double_ring(), 26, 6), 2);
  check_decomposition(zdg::test::image_complex(zdg::test::hollow_cube()), 0);
}

// An exact form d0 u has no coexact or harmonic part; the flat of a field decomposes.
TEST(HodgeDecomposition, ExactFormsAreExact) {
  const auto ic = zdg::test::image_complex(zdg::test::double_ring());
  const auto& c = ic.complex;
  std::vector<double> u;
  for (const auto& p : c.pointels) u.push_back(p.x * p.x - 2 * p.y + p.z);
  const auto omega = zdg::primal_d0(c).multiply(std::span<const double>(u));
  const auto h = zdg::hodge_decomposition(c, zdg::hodge_stars(c, CellMeasure::cubical), omega);
  EXPECT_LT(max_abs(h.coexact), 1e-9);
  EXPECT_LT(max_abs(h.harmonic), 1e-9);
  const std::vector<Point3<double>> field(c.normals.size(), Point3<double>{1, 2, 3});
  const auto f = zdg::flat(c, field);
  const auto hf = zdg::hodge_decomposition(c, zdg::hodge_stars(c, CellMeasure::cubical), f);
  // A constant field is the gradient of a linear function: exact.
  EXPECT_LT(max_abs(hf.harmonic), 1e-9);
  EXPECT_LT(max_abs(hf.coexact), 1e-9);
}

TEST(HodgeDecomposition, BadInput) {
  const auto c = zdg::test::image_complex(zdg::test::ring_torus()).complex;
  const auto stars = zdg::hodge_stars(c, CellMeasure::cubical);
  EXPECT_THROW(zdg::hodge_decomposition(c, stars, std::vector<double>(3)), zdg::InvalidArgument);
  auto n = c.normals;
  n[0] = -n[0]; // points inwards: clamped measure 0
  const auto clamped = zdg::hodge_stars(c, CellMeasure::corrected_clamped, n);
  EXPECT_THROW(
      zdg::hodge_decomposition(c, clamped, std::vector<double>(std::size_t(c.linel_count()))),
      zdg::InvalidArgument);
}

} // namespace
