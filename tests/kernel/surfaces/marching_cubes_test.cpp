#include <zdg/kernel/surfaces/marching_cubes.hpp>

#include "tests/support/binary_images.hpp"
#include "tests/support/mesh_checks.hpp"
#include "tests/support/tower.hpp"
#include "tests/support/volumes.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>

namespace {

using zdg::SurfaceConvention;
using zdg::test::SmallVolume;

constexpr int kPairs[4][2] = {{6, 26}, {6, 18}, {18, 6}, {26, 6}};

// Marching cubes is a closed oriented 2-manifold (each edge in two triangles run both ways,
// one fan per vertex) whose components have the Euler characteristics of the digital
// surfaces of the pair (image_surfaces), so that they sum to 2 (b0 - b1 + b2) + 2 pinched
// pointels with the brute-force Betti numbers of the object: for (6,18) and (18,6) exactly
// twice the object's Euler characteristic. Also where the primal quad mesh has pinched
// linels.
TEST(MarchingCubes, ClosedOrientedManifoldWithTheDigitalSurfacesEuler) {
  zdg::test::check_property([] {
    const SmallVolume v = *zdg::test::small_volume(5);
    const auto img = zdg::test::to_image(v, 0, 3, -2);
    const auto sf = zdg::image_surfels(img, 1);
    for (const auto& p : kPairs) {
      const auto conv = SurfaceConvention::of(p[0], p[1]);
      const auto mesh =
          zdg::marching_cubes(img, sf, conv, zdg::VoxelPlacement::lattice(sf.grid), nullptr, 1);
      mesh.validate();
      RC_ASSERT(zdg::test::manifold_defect(mesh) == "");
      const auto surfaces = zdg::image_surfaces(img, sf, conv, 1);
      std::vector<std::int64_t> mine, theirs;
      std::int64_t sum = 0;
      for (const auto& c : zdg::test::mesh_components(mesh)) {
        mine.push_back(c.euler());
        sum += c.euler();
      }
      for (const auto& s : surfaces.surfaces) theirs.push_back(s.euler);
      std::sort(mine.begin(), mine.end());
      std::sort(theirs.begin(), theirs.end());
      RC_ASSERT(mine == theirs);
      const auto b = zdg::test::object_betti(v, p[0], p[1]);
      RC_ASSERT(sum == 2 * (b[0] - b[1] + b[2]) + 2 * surfaces.pinched_pointels);
      RC_ASSERT(zdg::test::enclosed_volume(mesh) > 0 || sf.size() == 0);
    }
  });
}

// On binary input the first vertices are the surfel centres, in code order.
TEST(MarchingCubes, BinaryVerticesAreSurfelCentres) {
  zdg::test::check_property([] {
    const SmallVolume v = *zdg::test::small_volume(4);
    const auto img = zdg::test::to_image(v, -2, 1, 4);
    const auto sf = zdg::image_surfels(img, 1);
    const auto mesh = zdg::marching_cubes(img, sf, SurfaceConvention::of(6, 26),
                                          zdg::VoxelPlacement::lattice(sf.grid));
    RC_ASSERT(mesh.vertex_count() >= sf.size());
    for (std::int64_t i = 0; i < sf.size(); ++i) {
      const auto c = zdg::surfel_centre(sf.surfel(i), 1.0);
      RC_ASSERT(mesh.vertices[std::size_t(i)] == c);
    }
  });
}

// The enclosed volume of the binary marching cubes of the digitized ball of radius r
// converges to 4/3 pi r^3: the relative error decreases with r (O(1/r): the surface cuts
// each boundary voxel at a bounded distance from the sphere).
TEST(MarchingCubes, EnclosedVolumeConvergesOnDigitizedBalls) {
  double previous = 1;
  for (std::int64_t r : {4, 8, 16, 32}) {
    const auto img = zdg::test::ball_image(r + 1, r * r);
    const auto sf = zdg::image_surfels(img);
    const auto mesh = zdg::marching_cubes(img, sf, SurfaceConvention::of(6, 26),
                                          zdg::VoxelPlacement::lattice(sf.grid));
    const double exact = 4.0 / 3.0 * std::numbers::pi * double(r * r * r);
    const double err = std::abs(zdg::test::enclosed_volume(mesh) - exact) / exact;
    std::printf("binary ball r = %d: relative volume error %.5f\n", int(r), err);
    EXPECT_LT(err, 1.0 / double(r)) << "r = " << r;
    EXPECT_LT(err, previous) << "r = " << r;
    previous = err;
  }
}

// Grey input: the signed distance to a sphere of radius R (value R - |x - c|, the object is
// value >= 0), interpolated at level 0: the vertices lie within O(h^2 / R) of the sphere and
// the enclosed volume of the inscribed triangles converges like 1/R^2 (much faster than the
// binary one).
TEST(MarchingCubes, InterpolatedLevelFollowsTheGreyValues) {
  double previous = 1;
  for (double R : {4.3, 8.3, 16.3}) {
    const auto n = std::int64_t(2 * R + 6);
    const double c = double(n / 2) + 0.2;
    zdg::Image<std::uint8_t> img(zdg::Domain({n, n, n}));
    std::vector<double> f(std::size_t(n * n * n));
    for (std::int64_t i = 0; i < n * n * n; ++i) {
      const double x = double(i % n) - c, y = double((i / n) % n) - c, z = double(i / (n * n)) - c;
      f[std::size_t(i)] = R - std::sqrt(x * x + y * y + z * z);
      img[i] = f[std::size_t(i)] >= 0 ? 1 : 0;
    }
    const auto sf = zdg::image_surfels(img);
    const zdg::IsoLevel level{[&](std::int64_t v) { return f[std::size_t(v)]; }, 0.0};
    const auto mesh = zdg::marching_cubes(img, sf, SurfaceConvention::of(6, 26),
                                          zdg::VoxelPlacement::lattice(sf.grid), &level, 2);
    EXPECT_EQ(zdg::test::manifold_defect(mesh), "");
    for (std::int64_t i = 0; i < sf.size(); ++i) {
      const auto& p = mesh.vertices[std::size_t(i)];
      const double d =
          std::sqrt((p.x - c) * (p.x - c) + (p.y - c) * (p.y - c) + (p.z - c) * (p.z - c));
      EXPECT_NEAR(d, R, 0.5 / R);
    }
    const double exact = 4.0 / 3.0 * std::numbers::pi * R * R * R;
    const double err = std::abs(zdg::test::enclosed_volume(mesh) - exact) / exact;
    std::printf("grey ball R = %.1f: relative volume error %.6f\n", R, err);
    EXPECT_LT(err, 1.0 / (R * R)) << "R = " << R;
    EXPECT_LT(err, previous) << "R = " << R;
    previous = err;
  }
}

TEST(MarchingCubes, ThreadsDoNotChangeTheResult) {
  const auto img = zdg::test::ball_image(9, 61);
  const auto sf = zdg::image_surfels(img, 1);
  const auto conv = SurfaceConvention::of(6, 26);
  const auto a =
      zdg::marching_cubes(img, sf, conv, zdg::VoxelPlacement::lattice(sf.grid), nullptr, 1);
  const auto b =
      zdg::marching_cubes(img, sf, conv, zdg::VoxelPlacement::lattice(sf.grid), nullptr, 3);
  EXPECT_EQ(a.indices, b.indices);
  EXPECT_EQ(a.vertices, b.vertices);
  EXPECT_EQ(zdg::test::manifold_defect(a), "");
}

// Worked cases of the ambiguity: two object voxels at opposite corners of a cube are
// separated (two spheres); the (6,26) neck of the background along a linel is a tube (one
// torus) where the primal mesh has a pinched linel.
TEST(MarchingCubes, AmbiguousCubesAndFaces) {
  SmallVolume corner{2, 2, 2, {1, 0, 0, 0, 0, 0, 0, 1}};
  auto img = zdg::test::to_image(corner);
  auto sf = zdg::image_surfels(img);
  auto mesh = zdg::marching_cubes(img, sf, SurfaceConvention::of(6, 26),
                                  zdg::VoxelPlacement::lattice(sf.grid));
  EXPECT_EQ(zdg::test::mesh_components(mesh).size(), 2u);
  EXPECT_EQ(mesh.face_count(), 16);
  const auto block = zdg::test::volume_from_rows(2, {"##", "##", "#.", ".#", "##", "##"});
  img = zdg::test::to_image(block);
  sf = zdg::image_surfels(img);
  mesh = zdg::marching_cubes(img, sf, SurfaceConvention::of(6, 26),
                             zdg::VoxelPlacement::lattice(sf.grid));
  EXPECT_EQ(zdg::test::manifold_defect(mesh), "");
  const auto comps = zdg::test::mesh_components(mesh);
  ASSERT_EQ(comps.size(), 1u);
  EXPECT_EQ(comps[0].euler(), 0);
}

} // namespace
