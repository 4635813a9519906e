#include <zdg/kernel/surfaces/image_surfaces.hpp>

#include <zdg/kernel/surfaces/digital_surface.hpp>
#include <zdg/kernel/topology/betti_numbers.hpp>

#include "tests/support/binary_images.hpp"
#include "tests/support/check_registry.hpp"
#include "tests/support/tower.hpp"
#include "tests/support/volumes.hpp"

#include <gtest/gtest.h>

#include <map>
#include <set>

namespace {

using zdg::SurfaceConvention;
using zdg::test::SmallVolume;

constexpr int kPairs[4][2] = {{6, 26}, {6, 18}, {18, 6}, {26, 6}};

zdg::ImageSurfaces surfaces_of(const SmallVolume& v, int k, int kbar, unsigned threads = 1) {
  const auto img = zdg::test::to_image(v);
  return zdg::image_surfaces(img, zdg::image_surfels(img, threads), SurfaceConvention::of(k, kbar),
                             threads);
}

std::int64_t voxels(const SmallVolume& v) {
  std::int64_t n = 0;
  for (auto b : v.data) n += b != 0;
  return n;
}

// chi(dM) = 2 chi(M) for the pair's continuous analog M of X, corrected by 2 per pinched
// pointel (kernel/surfaces/image_surfaces.hpp): object_euler() = b0 - b1 + b2 with the Betti
// numbers of the brute-force homology of the cell complex of X under the pair
// (tests/support/cubical_homology.hpp), and = the Euler characteristic of
// kernel/topology/betti_numbers.hpp (a 2x2x2-block table). For (6,18) and
// (18,6) there is no pinch: the sum of the surfaces' chi is exactly 2 (b0 - b1 + b2).
TEST(ImageSurfaces, EulerOfTheSurfacesIsTwiceTheObjectsUnderEveryPair) {
  zdg::test::check_property([] {
    const SmallVolume v = *zdg::test::small_volume(5);
    for (const auto& p : kPairs) {
      const auto s = surfaces_of(v, p[0], p[1]);
      const auto b = zdg::test::object_betti(v, p[0], p[1]);
      RC_ASSERT(s.object_euler() == b[0] - b[1] + b[2]);
      RC_ASSERT(s.object_euler() ==
                zdg::euler_characteristic(zdg::test::to_image(v),
                                          zdg::make_adjacency_pair(3, p[0], p[1]), 1));
      if (p[0] == 18 || p[1] == 18) {
        RC_ASSERT(s.pinched_pointels == 0);
        RC_ASSERT(s.euler_sum() == 2 * (b[0] - b[1] + b[2]));
      }
    }
  });
}

// The divergence theorem: the enclosed volumes of the surfaces sum to the number of voxels;
// surfaces with a positive volume bound the components from outside and those with a
// negative one the cavities: b0 of the object taken 6-connected (or 18) is the number of
// positive surfaces, b2 of the background taken 6-connected the number of negative ones.
TEST(ImageSurfaces, EnclosedVolumesCountVoxelsComponentsAndCavities) {
  zdg::test::check_property([] {
    const SmallVolume v = *zdg::test::small_volume(5);
    for (const auto& p : kPairs) {
      const auto s = surfaces_of(v, p[0], p[1]);
      std::int64_t total = 0, positive = 0, negative = 0;
      for (const auto& f : s.surfaces) {
        RC_ASSERT(f.volume != 0);
        RC_ASSERT(f.euler == 2 - 2 * f.genus);
        RC_ASSERT(f.euler <= 2);
        total += f.volume;
        (f.volume > 0 ? positive : negative) += 1;
      }
      RC_ASSERT(total == voxels(v));
      const auto b = zdg::test::object_betti(v, p[0], p[1]);
      if (p[1] != 26) RC_ASSERT(negative == b[2]);
      if (p[0] != 26) RC_ASSERT(positive == b[0]);
    }
  });
}

// The surfaces are the connected components of the bel-adjacency: tracking from the first
// surfel of each surface (kernel/surfaces/digital_surface.hpp, track_surface) finds exactly its
// surfels.
TEST(ImageSurfaces, SurfacesAreTheTrackedSurfaces) {
  zdg::test::check_property([] {
    const SmallVolume v = *zdg::test::small_volume(5);
    const auto p = *rc::gen::elementOf(std::vector<std::pair<int, int>>{{6, 26}, {18, 6}});
    const auto img = zdg::test::to_image(v);
    const auto sf = zdg::image_surfels(img, 2);
    const auto s = zdg::image_surfaces(img, sf, SurfaceConvention::of(p.first, p.second), 2);
    const auto box = sf.grid.box();
    auto inside = [&](const zdg::Voxel& z) { return v.at(int(z.x), int(z.y), int(z.z)); };
    std::int64_t covered = 0;
    for (std::size_t k = 0; k < s.surfaces.size(); ++k) {
      const auto tracked = zdg::track_surface(inside, box, sf.surfel(s.surfaces[k].first),
                                              SurfaceConvention::of(p.first, p.second).linels);
      RC_ASSERT(std::int64_t(tracked.size()) == s.surfaces[k].surfels);
      for (const auto& t : tracked) {
        const auto i = sf.find(zdg::surfel_code(
            sf.grid.index(zdg::inner_voxel(t).x, zdg::inner_voxel(t).y, zdg::inner_voxel(t).z),
            zdg::orthogonal_axis(t), t.direct));
        RC_ASSERT(i >= 0);
        RC_ASSERT(s.surface_of[std::size_t(i)] == k);
      }
      covered += std::int64_t(tracked.size());
    }
    RC_ASSERT(covered == sf.size());
  });
}

TEST(ImageSurfaces, ThreadsDoNotChangeTheResult) {
  const auto img = zdg::test::ball_image(10, 70);
  const auto sf = zdg::image_surfels(img, 1);
  for (const auto& p : kPairs) {
    const auto c = SurfaceConvention::of(p[0], p[1]);
    const auto a = zdg::image_surfaces(img, sf, c, 1), b = zdg::image_surfaces(img, sf, c, 3);
    EXPECT_EQ(a.surface_of, b.surface_of);
    ASSERT_EQ(a.surfaces.size(), 1u);
    EXPECT_EQ(a.surfaces[0].euler, 2);
    EXPECT_EQ(b.surfaces[0].surfels, a.surfaces[0].surfels);
  }
}

// Worked examples with known topology.
TEST(ImageSurfaces, WorkedExamples) {
  // Two voxels meeting at a corner: two spheres; under (26,6) one component pinched once.
  SmallVolume corner{2, 2, 2, {1, 0, 0, 0, 0, 0, 0, 1}};
  auto s = surfaces_of(corner, 26, 6);
  EXPECT_EQ(s.surfaces.size(), 2u);
  EXPECT_EQ(s.pinched_pointels, 1);
  EXPECT_EQ(s.object_euler(), 1);
  s = surfaces_of(corner, 6, 26);
  EXPECT_EQ(s.pinched_pointels, 0);
  EXPECT_EQ(s.object_euler(), 2);
  // A 4x4x4 cube with two corner-touching voxels removed inside: under (6,26) the cavity is one
  // background component (b = 1, 0, 1) whose boundary is two spheres pinched at a pointel.
  SmallVolume cavity{4, 4, 4, std::vector<std::uint8_t>(64, 1)};
  cavity.data[std::size_t((1 * 4 + 1) * 4 + 1)] = 0;
  cavity.data[std::size_t((2 * 4 + 2) * 4 + 2)] = 0;
  s = surfaces_of(cavity, 6, 26);
  EXPECT_EQ(s.surfaces.size(), 3u);
  EXPECT_EQ(s.euler_sum(), 6);
  EXPECT_EQ(s.pinched_pointels, 1);
  EXPECT_EQ(s.object_euler(), 2);
  // A solid torus of square section (a 4x4x1 ring... thickened to 2 slices): genus 1.
  const auto ring = zdg::test::volume_from_rows(4, {"####", "#..#", "#..#", "####", //
                                                    "####", "#..#", "#..#", "####"});
  s = surfaces_of(ring, 6, 26);
  ASSERT_EQ(s.surfaces.size(), 1u);
  EXPECT_EQ(s.surfaces[0].genus, 1);
  EXPECT_EQ(s.surfaces[0].volume, 24);
  // A hollow cube: outer surface +, cavity surface -.
  SmallVolume hollow{3, 3, 3, std::vector<std::uint8_t>(27, 1)};
  hollow.data[13] = 0;
  s = surfaces_of(hollow, 18, 6);
  ASSERT_EQ(s.surfaces.size(), 2u);
  EXPECT_EQ(s.surfaces[0].volume, 27);
  EXPECT_EQ(s.surfaces[1].volume, -1);
  EXPECT_EQ(s.object_euler(), 2);
}

TEST(ImageSurfaces, RefusesOtherPairs) {
  EXPECT_THROW(SurfaceConvention::of(6, 6), zdg::InvalidArgument);
  EXPECT_THROW(SurfaceConvention::of(26, 26), zdg::InvalidArgument);
  EXPECT_THROW(SurfaceConvention::of(18, 26), zdg::InvalidArgument);
  EXPECT_THROW(SurfaceConvention::of(4, 8), zdg::InvalidArgument);
}

// The registered property surface.counts (zdg check): surfels, Herman's one surface per
// touching (component, background component) pair without pinches, the Euler sum formula.
TEST(ImageSurfaces, RegisteredCountsPropertyHolds) {
  zdg::test::expect_registered_property("surface.counts", zdg::IntKind::int64, 300);
}

} // namespace
