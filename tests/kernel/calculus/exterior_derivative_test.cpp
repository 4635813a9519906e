#include <zdg/kernel/calculus/exterior_derivative.hpp>

#include "tests/support/image_complex.hpp"
#include "tests/support/tower.hpp"

#include <gtest/gtest.h>
#include <rapidcheck.h>

#include <cmath>

namespace {

constexpr int kPairs[4][2] = {{6, 26}, {6, 18}, {18, 6}, {26, 6}};

// d1 d0 = 0 and dual_d1 dual_d0 = 0 exactly (integer products), on the boundary of random
// voxel sets under every adjacency pair; entries are +-1 with two per row of d0 and four per
// row of d1, the duals are the signed transposes.
TEST(ExteriorDerivative, DdIsZeroInIntegers) {
  zdg::test::check_property([] {
    const auto v = *zdg::test::small_volume(5);
    for (const auto& p : kPairs) {
      const auto c = zdg::test::image_complex(v, p[0], p[1]).complex;
      const auto d0 = zdg::primal_d0(c), d1 = zdg::primal_d1(c);
      RC_ASSERT(d0.rows == c.linel_count() && d0.cols == c.pointel_count());
      RC_ASSERT(d1.rows == c.surfel_count() && d1.cols == c.linel_count());
      RC_ASSERT(d0.nonzeros() == 2 * d0.rows);
      RC_ASSERT(d1.nonzeros() == 4 * d1.rows);
      RC_ASSERT(zdg::integer_product(d1, d0).empty());
      const auto dd0 = zdg::dual_d0(c), dd1 = zdg::dual_d1(c);
      RC_ASSERT(zdg::integer_product(dd1, dd0).empty());
      for (std::int64_t e = 0; e < c.linel_count(); ++e) {
        const auto& l = c.linels[std::size_t(e)];
        RC_ASSERT(dd0.at(e, l.face[0]) == 1 && dd0.at(e, l.face[1]) == -1);
        RC_ASSERT(dd1.at(l.a, e) == 1 && dd1.at(l.b, e) == -1);
      }
      // Every linel is in two surfels, once each way: d1's columns hold one +1 and one -1.
      const auto d1t = d1.transpose();
      for (std::int64_t e = 0; e < d1t.rows; ++e) {
        const auto b = d1t.row_start[std::size_t(e)];
        RC_ASSERT(d1t.row_start[std::size_t(e) + 1] - b == 2);
        RC_ASSERT(d1t.value[std::size_t(b)] + d1t.value[std::size_t(b) + 1] == 0);
      }
    }
  });
}

// Stokes' theorem on every surfel, for random integer 1-forms: (d1 w)(s) is the circulation of
// w around the boundary of s, walked through its corners c0 -> c1 -> c2 -> c3 -> c0 (each
// step a linel, counted + when the step runs it from a to b). And for a 0-form u:
// (d0 u)(e) = u(b) - u(a), whose circulation around every surfel is 0.
TEST(ExteriorDerivative, StokesOnEveryFace) {
  zdg::test::check_property([] {
    const auto v = *zdg::test::small_volume(5);
    const auto c = zdg::test::image_complex(v, 6, 26).complex;
    const auto w = *rc::gen::container<std::vector<std::int64_t>>(
        std::size_t(c.linel_count()), rc::gen::inRange<std::int64_t>(-1000000, 1000000));
    const auto u = *rc::gen::container<std::vector<std::int64_t>>(
        std::size_t(c.pointel_count()), rc::gen::inRange<std::int64_t>(-1000000, 1000000));
    const auto dw = zdg::primal_d1(c).multiply(std::span<const std::int64_t>(w));
    const auto du = zdg::primal_d0(c).multiply(std::span<const std::int64_t>(u));
    for (std::int64_t e = 0; e < c.linel_count(); ++e) {
      const auto& l = c.linels[std::size_t(e)];
      RC_ASSERT(du[std::size_t(e)] == u[std::size_t(l.b)] - u[std::size_t(l.a)]);
    }
    for (std::int64_t s = 0; s < c.surfel_count(); ++s) {
      std::int64_t circulation = 0, exact = 0;
      const auto& q = c.surfels[std::size_t(s)];
      for (std::size_t i = 0; i < 4; ++i) {
        const auto from = q[i], to = q[(i + 1) % 4];
        const auto e = std::size_t(c.surfel_linels[std::size_t(s)][i]);
        const auto& l = c.linels[e];
        RC_ASSERT((l.a == from && l.b == to) || (l.a == to && l.b == from));
        const std::int64_t sign = l.a == from ? 1 : -1;
        circulation += sign * w[e];
        exact += sign * du[e];
      }
      RC_ASSERT(dw[std::size_t(s)] == circulation);
      RC_ASSERT(exact == 0);
    }
  });
}

// d0 of the pointels' coordinates is the linel's vector b - a (a unit step of the lattice).
TEST(ExteriorDerivative, CoordinateDifferentials) {
  const auto c = zdg::test::image_complex(zdg::test::ring_torus()).complex;
  std::vector<double> x;
  for (const auto& p : c.pointels) x.push_back(p.x);
  const auto dx = zdg::primal_d0(c).multiply(std::span<const double>(x));
  for (std::size_t e = 0; e < dx.size(); ++e) {
    const auto& l = c.linels[e];
    EXPECT_EQ(dx[e], c.pointels[std::size_t(l.b)].x - c.pointels[std::size_t(l.a)].x);
    EXPECT_LE(std::abs(dx[e]), 1.0);
  }
}

} // namespace
