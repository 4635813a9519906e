#include <zdg/kernel/calculus/wedge_product.hpp>

#include <zdg/arith/error.hpp>
#include <zdg/kernel/calculus/exterior_derivative.hpp>

#include "tests/support/image_complex.hpp"
#include "tests/support/tower.hpp"

#include <gtest/gtest.h>
#include <rapidcheck.h>

namespace {

// dx ^ dy = area n_z, dy ^ dz = area n_x, dz ^ dx = area n_y on every surfel (the projected
// oriented areas), exactly; antisymmetric, alternating and bilinear on random integer forms.
TEST(WedgeProduct, CoordinateFormsGiveProjectedAreas) {
  zdg::test::check_property([] {
    const auto v = *zdg::test::small_volume(5);
    const auto c = zdg::test::image_complex(v, 18, 6).complex;
    const auto d0 = zdg::primal_d0(c);
    std::vector<double> x, y, z;
    for (const auto& p : c.pointels) {
      x.push_back(p.x);
      y.push_back(p.y);
      z.push_back(p.z);
    }
    const auto dx = d0.multiply(std::span<const double>(x)),
               dy = d0.multiply(std::span<const double>(y)),
               dz = d0.multiply(std::span<const double>(z));
    const auto xy = zdg::wedge_product(c, dx, dy), yz = zdg::wedge_product(c, dy, dz),
               zx = zdg::wedge_product(c, dz, dx);
    for (std::size_t s = 0; s < xy.size(); ++s) {
      RC_ASSERT(xy[s] == c.areas[s] * c.normals[s].z);
      RC_ASSERT(yz[s] == c.areas[s] * c.normals[s].x);
      RC_ASSERT(zx[s] == c.areas[s] * c.normals[s].y);
    }
    const auto gen = rc::gen::container<std::vector<double>>(
        std::size_t(c.linel_count()),
        rc::gen::map(rc::gen::inRange(-1000, 1000), [](int i) { return double(i); }));
    const auto a = *gen, b = *gen, e = *gen;
    std::vector<double> a2(a.size());
    for (std::size_t i = 0; i < a.size(); ++i) a2[i] = 3 * a[i] - e[i];
    const auto ab = zdg::wedge_product(c, a, b), ba = zdg::wedge_product(c, b, a),
               aa = zdg::wedge_product(c, a, a), a2b = zdg::wedge_product(c, a2, b),
               eb = zdg::wedge_product(c, e, b);
    for (std::size_t s = 0; s < ab.size(); ++s) {
      RC_ASSERT(ab[s] == -ba[s]);
      RC_ASSERT(aa[s] == 0);
      RC_ASSERT(a2b[s] == 3 * ab[s] - eb[s]);
      RC_ASSERT(4 * ab[s] == std::floor(4 * ab[s])); // integers over 4
    }
  });
}

TEST(WedgeProduct, SizesAreChecked) {
  const auto c = zdg::test::image_complex(zdg::test::ring_torus()).complex;
  EXPECT_THROW(zdg::wedge_product(c, std::vector<double>(3), std::vector<double>(3)),
               zdg::InvalidArgument);
}

} // namespace
