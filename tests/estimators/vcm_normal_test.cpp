#include <zdg/estimators/vcm_normal.hpp>

#include "tests/support/digital_sphere.hpp"
#include "tests/support/lattice_symmetry.hpp"
#include "tests/support/tower.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <numeric>

namespace {

using P3 = zdg::Point3<double>;
using zdg::Surfel;
using zdg::Voxel;
using zdg::VoxelBox;

double angle(P3 a, P3 b) {
  const P3 c = cross(a, b);
  return std::atan2(std::sqrt(dot(c, c)), dot(a, b));
}

// A digital half-space a x + b y + c z <= 0 (gcd(a, b, c) = 1): at the surfels away from the
// box, the VCM normal is the plane's normal (a, b, c) / |(a, b, c)| within 0.05 rad (R = r = 5
// voxels; measured up to 0.03 on these normals).
TEST(VcmNormal, DigitalPlaneGivesItsNormal) {
  zdg::test::check_property([] {
    const auto a = *rc::gen::inRange<std::int64_t>(-4, 5);
    const auto b = *rc::gen::inRange<std::int64_t>(-4, 5);
    const auto c = *rc::gen::inRange<std::int64_t>(1, 5);
    RC_PRE(std::gcd(std::gcd(a, b), c) == 1);
    const zdg::VoxelPredicate in = [=](const Voxel& z) { return a * z.x + b * z.y + c * z.z <= 0; };
    const VoxelBox box{{-12, -12, -36}, {12, 12, 36}};
    const auto surfels = zdg::boundary_surfels(in, box);
    const auto n = zdg::vcm_normals(surfels, 1.0, 5.0, 5.0, 1);
    const double len = std::sqrt(double(a * a + b * b + c * c));
    const P3 truth{double(a) / len, double(b) / len, double(c) / len};
    std::size_t checked = 0;
    for (std::size_t i = 0; i < surfels.size(); ++i) {
      const auto v = zdg::inner_voxel(surfels[i]);
      if (std::abs(v.x) > 2 || std::abs(v.y) > 2 || !box.contains(zdg::outer_voxel(surfels[i])))
        continue;
      RC_ASSERT(angle(n[i], truth) < 0.05);
      ++checked;
    }
    RC_ASSERT(checked > 0);
  });
}

// The 48 lattice symmetries: the normal at the image surfel is the image of the normal (ties
// between nearest points are split equally, so the measure commutes with the symmetries).
TEST(VcmNormal, EquivariantUnderTheLatticeSymmetries) {
  const zdg::VoxelPredicate in = [](const Voxel& z) {
    const auto x = z.x - 1, y = z.y + 2, w = z.z;
    return 3 * x * x + 2 * y * y + w * w + x * y <= 200;
  };
  const VoxelBox box{{-20, -20, -20}, {20, 20, 20}};
  const auto surfels = zdg::boundary_surfels(in, box);
  const auto ref = zdg::vcm_normals(surfels, 1.0, 4.0, 3.0, 1);
  for (const auto& g : zdg::test::lattice_symmetries()) {
    std::vector<Surfel> image;
    for (const auto& s : surfels) image.push_back(g.apply(s));
    const auto n = zdg::vcm_normals(image, 1.0, 4.0, 3.0, 2);
    for (std::size_t i = 0; i < surfels.size(); ++i) {
      const P3 e = g.apply(ref[i]);
      ASSERT_LT(angle(n[i], e), 1e-9) << "surfel " << i;
    }
  }
}

// Unit sphere: the mean angle to the radial direction decreases with h (R = r = h^{1/2}) and is
// below 0.04 rad at h = 0.05 (measured 0.028).
TEST(VcmNormal, DigitalSphereConverges) {
  double last = 1e9;
  for (const double h : {0.2, 0.1, 0.05}) {
    const auto s = zdg::test::digital_sphere(h, false);
    const double R = std::sqrt(h);
    const auto n = zdg::vcm_normals(s.surfels, h, R, R, 2);
    double mean = 0;
    for (std::size_t i = 0; i < n.size(); ++i) {
      const P3 c = zdg::surfel_centre(s.surfels[i], h);
      mean += angle(n[i], (1.0 / std::sqrt(dot(c, c))) * c);
    }
    mean /= double(n.size());
    EXPECT_LT(mean, last) << "h = " << h;
    last = mean;
  }
  EXPECT_LT(last, 0.04);
}

TEST(VcmNormal, BadParametersAreRefused) {
  const std::vector<Surfel> s{zdg::surfel_between({0, 0, 0}, 2, 1)};
  EXPECT_THROW(zdg::vcm_normals(s, 0.0, 1.0, 1.0), zdg::InvalidArgument);
  EXPECT_THROW(zdg::vcm_normals(s, 1.0, 0.0, 1.0), zdg::InvalidArgument);
  EXPECT_THROW(zdg::vcm_normals(s, 1.0, 1.0, -1.0), zdg::InvalidArgument);
  EXPECT_THROW(zdg::vcm_normals(s, 1.0, 300.0, 1.0), zdg::InvalidArgument);
  EXPECT_THROW(zdg::vcm_normals(std::vector<Surfel>{}, 1.0, 1.0, 1.0), zdg::InvalidArgument);
}

} // namespace
