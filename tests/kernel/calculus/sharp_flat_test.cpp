#include <zdg/kernel/calculus/sharp_flat.hpp>

#include <zdg/arith/error.hpp>

#include "tests/support/image_complex.hpp"
#include "tests/support/tower.hpp"

#include <gtest/gtest.h>
#include <rapidcheck.h>

#include <cmath>

namespace {

using zdg::Point3;

// A constant field tangent to a flat piece: on each surfel whose four neighbours share its
// elementary normal, sharp(flat(V)) = V, with the surfel's plane and with n_est = n_elem;
// flat(V) on a linel is V . (b - a) there. The normal component of V is ignored.
TEST(SharpFlat, ConstantTangentFieldOnFlatPieces) {
  zdg::test::check_property([] {
    const auto c = zdg::test::image_complex(zdg::test::double_ring()).complex;
    const Point3<double> g{double(*rc::gen::inRange(-100, 100)),
                           double(*rc::gen::inRange(-100, 100)),
                           double(*rc::gen::inRange(-100, 100))};
    const std::vector<Point3<double>> field(c.normals.size(), g); // normal parts included
    const auto w = zdg::flat(c, field);
    const auto back = zdg::sharp(c, w);
    const auto back_est = zdg::sharp(c, w, c.normals);
    for (std::int64_t s = 0; s < c.surfel_count(); ++s) {
      bool flat_piece = true;
      for (int i = 0; i < 4; ++i)
        flat_piece =
            flat_piece && c.normals[std::size_t(c.neighbour(s, i))] == c.normals[std::size_t(s)];
      if (!flat_piece) continue;
      const auto& n = c.normals[std::size_t(s)];
      const auto tangent = g - dot(g, n) * n;
      RC_ASSERT(back[std::size_t(s)] == tangent);
      RC_ASSERT(back_est[std::size_t(s)] == tangent);
    }
    for (std::size_t e = 0; e < w.size(); ++e) {
      const auto& l = c.linels[e];
      RC_ASSERT(w[e] == dot(g, c.pointels[std::size_t(l.b)] - c.pointels[std::size_t(l.a)]));
    }
  });
}

// With an estimated normal the result is tangent to the estimated plane and keeps the
// circulations along the surfel's sides.
TEST(SharpFlat, SharpIsTangentToTheEstimatedPlane) {
  const auto c = zdg::test::image_complex(zdg::test::ring_torus()).complex;
  std::vector<double> w(std::size_t(c.linel_count()));
  for (std::size_t e = 0; e < w.size(); ++e) w[e] = double(int(e % 7) - 3);
  std::vector<Point3<double>> n;
  for (const auto& m : c.normals) {
    const auto t = m + Point3<double>{0.2, -0.1, 0.3};
    n.push_back((1 / std::sqrt(dot(t, t))) * t);
  }
  const auto plain = zdg::sharp(c, w), est = zdg::sharp(c, w, n);
  for (std::size_t s = 0; s < est.size(); ++s) {
    const auto& q = c.surfels[s];
    const auto u = c.pointels[std::size_t(q[1])] - c.pointels[std::size_t(q[0])];
    const auto v = c.pointels[std::size_t(q[3])] - c.pointels[std::size_t(q[0])];
    EXPECT_NEAR(dot(est[s], n[s]), 0.0, 1e-12);
    EXPECT_NEAR(dot(plain[s], c.normals[s]), 0.0, 1e-12);
    EXPECT_NEAR(dot(est[s], u), dot(plain[s], u), 1e-12);
    EXPECT_NEAR(dot(est[s], v), dot(plain[s], v), 1e-12);
  }
}

TEST(SharpFlat, BadInput) {
  const auto c = zdg::test::image_complex(zdg::test::ring_torus()).complex;
  EXPECT_THROW(zdg::flat(c, std::vector<Point3<double>>(2)), zdg::InvalidArgument);
  EXPECT_THROW(zdg::sharp(c, std::vector<double>(2)), zdg::InvalidArgument);
  const std::vector<double> w(std::size_t(c.linel_count()), 1.0);
  auto n = c.normals;
  const auto& q = c.surfels[0];
  n[0] = c.pointels[std::size_t(q[1])] - c.pointels[std::size_t(q[0])]; // in the plane
  EXPECT_THROW(zdg::sharp(c, w, n), zdg::InvalidArgument);
}

} // namespace
