#include <zdg/kernel/linalg/principal_angles.hpp>

#include "tests/support/tower.hpp"

#include <zdg/arith/error.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace {

using Vectors = std::vector<std::vector<double>>;

std::vector<double> unit(std::size_t n, std::size_t i) {
  std::vector<double> v(n, 0.0);
  v[i] = 1;
  return v;
}

// span(e0, e1) and span(cos t e0 + sin t e2, e1): the angles are 0 and t, for t from 1e-9 (the
// sines keep it) to pi/2; with weights W the same holds for the W-orthonormal e_i / sqrt(w_i).
TEST(PrincipalAngles, RotatedPlaneHasAnglesZeroAndT) {
  const std::vector<double> w{4.0, 0.25, 9.0, 1.0};
  for (const double t : {1e-9, 1e-4, 0.3, 1.2, std::numbers::pi / 2}) {
    Vectors a{unit(4, 0), unit(4, 1)}, b(2, std::vector<double>(4, 0.0));
    b[0][0] = std::cos(t) / 2;
    b[0][2] = std::sin(t) / 3;
    b[1][1] = 2;
    for (auto& x : a)
      for (std::size_t i = 0; i < 4; ++i) x[i] /= std::sqrt(w[i]);
    const auto angles = zdg::principal_angles(a, b, w);
    ASSERT_EQ(angles.size(), 2u);
    EXPECT_NEAR(angles[0], 0.0, 1e-14);
    EXPECT_NEAR(angles[1], t, 1e-14 + 1e-12 * t) << "t = " << t;
  }
}

// The angles depend on the subspaces only: span(a) against span(a T) for an invertible mixing T
// gives zeros; against a subspace and its complement, pi/2; symmetric in (a, b).
TEST(PrincipalAngles, DependOnTheSubspacesOnly) {
  zdg::test::check_property([] {
    const auto n = *rc::gen::inRange<std::size_t>(3, 12);
    const auto p = *rc::gen::inRange<std::size_t>(1, n);
    Vectors a(p, std::vector<double>(n));
    for (std::size_t j = 0; j < p; ++j)
      for (std::size_t i = 0; i < n; ++i)
        a[j][i] = double(*rc::gen::inRange(-9, 10)) + (i == j ? 40 : 0);
    std::vector<double> w(n);
    for (auto& x : w) x = double(*rc::gen::inRange(1, 20)) / 4;
    // a T with T = I + upper triangle of small integers (invertible).
    Vectors mixed(p, std::vector<double>(n, 0.0));
    for (std::size_t j = 0; j < p; ++j)
      for (std::size_t k = 0; k <= j; ++k) {
        const double t = k == j ? 1.0 : double(*rc::gen::inRange(-3, 4));
        for (std::size_t i = 0; i < n; ++i) mixed[j][i] += t * a[k][i];
      }
    for (double angle : zdg::principal_angles(a, mixed, w)) RC_ASSERT(std::abs(angle) <= 1e-9);
    const auto ab = zdg::principal_angles(a, Vectors{unit(n, 0)}, w);
    const auto ba = zdg::principal_angles(Vectors{unit(n, 0)}, a, w);
    RC_ASSERT(ab.size() == 1u);
    RC_ASSERT(std::abs(ab[0] - ba[0]) <= 1e-12);
  });
}

TEST(PrincipalAngles, BadInputIsInvalidArgument) {
  const std::vector<double> w{1, 1, 1};
  EXPECT_THROW(zdg::principal_angles(Vectors{unit(3, 0)}, Vectors{}, w), zdg::InvalidArgument);
  EXPECT_THROW(zdg::principal_angles(Vectors{unit(3, 0)}, Vectors{unit(2, 0)}, w),
               zdg::InvalidArgument);
  EXPECT_THROW(zdg::principal_angles(Vectors{unit(3, 0), unit(3, 0)}, Vectors{unit(3, 1)}, w),
               zdg::InvalidArgument);
  EXPECT_THROW(
      zdg::principal_angles(Vectors{unit(3, 0)}, Vectors{unit(3, 1)}, std::vector<double>{1, 0, 1}),
      zdg::InvalidArgument);
}

} // namespace
