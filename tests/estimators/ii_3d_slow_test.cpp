// The target case of the issue (sphere1 at h = 0.025, R = 3 h^{1/3}, r ~ 35 voxels, ~30,000
// surfels), checked for accuracy and against the brute-force kernel on sampled surfels.
#include <zdg/estimators/ii_3d.hpp>

#include <gtest/gtest.h>

#include <cmath>

namespace {

TEST(IntegralInvariants3DSlow, Sphere1TargetCase) {
  const std::int64_t n = 40;
  const double h = 1.0 / double(n), R = 3.0 * std::cbrt(h);
  const zdg::VoxelPredicate in = [&](const zdg::Voxel& z) {
    return z.x * z.x + z.y * z.y + z.z * z.z <= n * n;
  };
  const zdg::VoxelBox box{{-50, -50, -50}, {50, 50, 50}};
  const auto surfels = zdg::track_surface(in, box, zdg::find_boundary_surfel(in, box, {0, 0, 0}));
  EXPECT_EQ(zdg::euler_characteristic(zdg::primal_surface(surfels)), 2);
  const auto r2 = zdg::ii_digital_radius2(R, h);
  const auto m = zdg::ii_surfel_moments(in, box, surfels, r2, 2, true);
  for (std::size_t i = 0; i < surfels.size(); i += 997) {
    EXPECT_EQ(m.moments[i].inner,
              zdg::direct_ball_moments(in, box, zdg::inner_voxel(surfels[i]), r2));
    EXPECT_EQ(m.moments[i].outer,
              zdg::direct_ball_moments(in, box, zdg::outer_voxel(surfels[i]), r2));
  }
  double eH = 0, eK = 0, eN = 0;
  for (std::size_t i = 0; i < surfels.size(); ++i) {
    const double H = zdg::ii_mean_curvature_from_moments(m.moments[i], h, R);
    const auto P = zdg::ii_principal_curvatures_from_moments(m.moments[i], surfels[i], h, R);
    const auto p = zdg::surfel_centre(surfels[i], h);
    const double norm = std::sqrt(p.x * p.x + p.y * p.y + p.z * p.z);
    eH = std::max(eH, std::abs(H - 1));
    eK = std::max({eK, std::abs(P.k1 - 1), std::abs(P.k2 - 1)});
    eN = std::max(eN, std::acos(std::min(
                          1.0, (P.normal.x * p.x + P.normal.y * p.y + P.normal.z * p.z) / norm)));
  }
  EXPECT_LT(eH, 0.08);
  EXPECT_LT(eK, 0.1);
  EXPECT_LT(eN, 0.01);
}

} // namespace
