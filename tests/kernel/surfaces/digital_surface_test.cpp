#include <zdg/kernel/surfaces/digital_surface.hpp>

#include "tests/support/tower.hpp"

#include "tests/support/digital_sets.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <set>
#include <unordered_set>

namespace {

using zdg::Surfel;
using zdg::SurfelAdjacency;
using zdg::Voxel;
using zdg::VoxelBox;

zdg::VoxelPredicate ball(Voxel c, std::int64_t r2) {
  return zdg::test::ball_predicate(c, r2);
}

// Torus of radii (R, r) around the z axis: (|p|^2 + R^2 - r^2)^2 <= 4 R^2 (x^2 + y^2).
zdg::VoxelPredicate torus(std::int64_t R, std::int64_t r) {
  return [=](const Voxel& z) {
    const auto s = z.x * z.x + z.y * z.y + z.z * z.z + R * R - r * r;
    return s * s <= 4 * R * R * (z.x * z.x + z.y * z.y);
  };
}

// Oracle: the boundary surfels by definition, over the box grown by one voxel.
std::vector<Surfel> brute_surfels(const zdg::VoxelPredicate& inside, const VoxelBox& box) {
  auto in = [&](const Voxel& z) { return box.contains(z) && inside(z); };
  std::vector<Surfel> out;
  for (auto z = box.lo.z; z <= box.hi.z; ++z)
    for (auto y = box.lo.y; y <= box.hi.y; ++y)
      for (auto x = box.lo.x; x <= box.hi.x; ++x) {
        if (!in({x, y, z})) continue;
        for (int a = 0; a < 3; ++a)
          for (int s : {-1, 1}) {
            Voxel n{x, y, z};
            zdg::coord(n, a) += s;
            if (!in(n)) out.push_back(zdg::surfel_between({x, y, z}, a, s));
          }
      }
  std::sort(out.begin(), out.end());
  return out;
}

// Each boundary surfel has exactly four followers, all boundary surfels, one through each
// of its linels, and the relation is symmetric: the follower of s through the linel l has s
// as its follower through l (Herman's bel-adjacency is an involution on linel incidences).
void check_closed(const zdg::VoxelPredicate& inside, const VoxelBox& box,
                  const std::vector<Surfel>& surfels, SurfelAdjacency adj) {
  const std::set<Surfel> all(surfels.begin(), surfels.end());
  for (const Surfel& s : surfels) {
    const auto ls = zdg::surfel_linels(s);
    const auto ns = zdg::surfel_neighbours(inside, box, s, adj);
    for (std::size_t i = 0; i < 4; ++i) {
      const Surfel& n = ns[i];
      ASSERT_TRUE(all.count(n)) << "follower not a boundary surfel";
      ASSERT_NE(n, s);
      const auto ln = zdg::surfel_linels(n);
      const auto j = std::size_t(std::find(ln.begin(), ln.end(), ls[i]) - ln.begin());
      ASSERT_LT(j, 4u) << "follower does not share the linel";
      ASSERT_EQ(zdg::surfel_neighbours(inside, box, n, adj)[j], s) << "adjacency not symmetric";
    }
  }
}

TEST(DigitalSurface, BallSurfaceIsClosedWithEulerCharacteristicTwo) {
  for (std::int64_t r2 : {0, 1, 2, 3, 20, 50, 81}) {
    const VoxelBox box{{-10, -10, -10}, {10, 10, 10}};
    const auto inside = ball({0, 0, 0}, r2);
    const auto s = zdg::boundary_surfels(inside, box);
    ASSERT_EQ(s, brute_surfels(inside, box));
    check_closed(inside, box, s, SurfelAdjacency::interior);
    EXPECT_EQ(zdg::euler_characteristic(zdg::primal_surface(s)), 2) << "r2 = " << r2;
  }
}

// Digitized balls of random radius and centre: closed, Euler characteristic 2, and tracked
// entirely from the seed found by walking from the centre.
TEST(DigitalSurface, RandomBallsAreSpheres) {
  zdg::test::check_property([] {
    const auto r2 = *rc::gen::inRange<std::int64_t>(0, 50);
    const Voxel c{*rc::gen::inRange<std::int64_t>(-30, 30),
                  *rc::gen::inRange<std::int64_t>(-30, 30),
                  *rc::gen::inRange<std::int64_t>(-30, 30)};
    const VoxelBox box{{c.x - 8, c.y - 8, c.z - 8}, {c.x + 8, c.y + 8, c.z + 8}};
    const auto inside = ball(c, r2);
    const auto s = zdg::boundary_surfels(inside, box);
    check_closed(inside, box, s, SurfelAdjacency::interior);
    RC_ASSERT(!::testing::Test::HasFailure());
    RC_ASSERT(zdg::euler_characteristic(zdg::primal_surface(s)) == 2);
    auto t = zdg::track_surface(inside, box, zdg::find_boundary_surfel(inside, box, c));
    std::sort(t.begin(), t.end());
    RC_ASSERT(t == s);
  });
}

TEST(DigitalSurface, PrimalSurfaceOfBallIsConsistentlyOriented) {
  // Each directed edge of a closed oriented quad mesh appears once, and so does its reverse.
  const auto s = zdg::boundary_surfels(ball({0, 0, 0}, 30), {{-7, -7, -7}, {7, 7, 7}});
  const auto q = zdg::primal_surface(s);
  std::map<std::pair<std::uint32_t, std::uint32_t>, int> directed;
  for (const auto& f : q.quads)
    for (std::size_t i = 0; i < 4; ++i) ++directed[{f[i], f[(i + 1) % 4]}];
  for (const auto& [e, n] : directed) {
    EXPECT_EQ(n, 1);
    EXPECT_EQ(directed.count({e.second, e.first}), 1u);
  }
  EXPECT_EQ(directed.size(), 2 * q.edge_count);
  EXPECT_EQ(q.quads.size(), s.size());
}

TEST(DigitalSurface, TorusHasEulerCharacteristicZero) {
  const VoxelBox box{{-16, -16, -6}, {16, 16, 6}};
  const auto inside = torus(10, 4);
  const auto s = zdg::boundary_surfels(inside, box);
  check_closed(inside, box, s, SurfelAdjacency::interior);
  EXPECT_EQ(zdg::euler_characteristic(zdg::primal_surface(s)), 0);
  const auto seed = zdg::find_boundary_surfel(inside, box, {10, 0, 0});
  auto t = zdg::track_surface(inside, box, seed);
  std::sort(t.begin(), t.end());
  EXPECT_EQ(t, s);
}

TEST(DigitalSurface, TrackingFindsTheScannedSurfaceWithArbitraryLowerBounds) {
  const Voxel c{-103, 41, 7};
  const VoxelBox box{{-115, 30, -5}, {-90, 52, 19}};
  const auto inside = ball(c, 70);
  const auto scan = zdg::boundary_surfels(inside, box);
  const auto seed = zdg::find_boundary_surfel(inside, box, c);
  EXPECT_EQ(seed, zdg::surfel_between({c.x + 8, c.y, c.z}, 0, +1));
  auto t = zdg::track_surface(inside, box, seed);
  EXPECT_EQ(t.front(), seed);
  std::sort(t.begin(), t.end());
  EXPECT_EQ(t, scan);
  // The binary-volume scan agrees with the predicate scan.
  EXPECT_EQ(zdg::boundary_surfels(zdg::BinaryVolume::from_predicate(inside, box)), scan);
}

TEST(DigitalSurface, TrackingStaysOnOneComponent) {
  const auto b1 = ball({-6, 0, 0}, 9), b2 = ball({6, 0, 0}, 9);
  const zdg::VoxelPredicate two = [&](const Voxel& z) { return b1(z) || b2(z); };
  const VoxelBox box{{-12, -6, -6}, {12, 6, 6}};
  const auto scan = zdg::boundary_surfels(two, box);
  EXPECT_EQ(zdg::euler_characteristic(zdg::primal_surface(scan)), 4);
  auto t = zdg::track_surface(two, box, zdg::find_boundary_surfel(two, box, {6, 0, 0}));
  std::sort(t.begin(), t.end());
  EXPECT_EQ(2 * t.size(), scan.size());
  EXPECT_TRUE(std::includes(scan.begin(), scan.end(), t.begin(), t.end()));
  EXPECT_EQ(zdg::euler_characteristic(zdg::primal_surface(t)), 2);
}

// Seeds from one line reach every component the line crosses: two balls and a torus (whose
// line meets the same surface four times) are recovered without a scan, each surfel once.
TEST(DigitalSurface, SeedsFromALineTrackEveryComponent) {
  const auto b1 = ball({-3, 0, 0}, 4), b2 = ball({3, 0, 0}, 4), t = torus(10, 3);
  const zdg::VoxelPredicate three = [&](const Voxel& z) { return b1(z) || b2(z) || t(z); };
  const VoxelBox box{{-15, -15, -5}, {15, 15, 5}};
  const auto seeds = zdg::line_boundary_surfels(three, box, 0, 0);
  EXPECT_EQ(seeds.size(), 8u);
  auto all = zdg::track_surfaces(three, box, seeds);
  const auto n = all.size();
  std::sort(all.begin(), all.end());
  EXPECT_EQ(std::unique(all.begin(), all.end()) - all.begin(), std::ptrdiff_t(n));
  EXPECT_EQ(all, zdg::boundary_surfels(three, box));
  EXPECT_EQ(zdg::euler_characteristic(zdg::primal_surface(all)), 2 + 2 + 0);
  EXPECT_TRUE(zdg::line_boundary_surfels(three, box, 99, 0).empty());
}

// Two voxels sharing only an edge: interior adjacency joins them into one surface of 12
// surfels, exterior adjacency keeps two cubes of 6.
TEST(DigitalSurface, EdgeConnectedVoxelsInteriorVersusExterior) {
  const zdg::VoxelPredicate two = [](const Voxel& z) {
    return z.z == 0 && ((z.x == 0 && z.y == 0) || (z.x == 1 && z.y == 1));
  };
  const VoxelBox box{{-2, -2, -2}, {3, 3, 2}};
  const auto seed = zdg::surfel_between({0, 0, 0}, 2, +1);
  EXPECT_EQ(zdg::track_surface(two, box, seed, SurfelAdjacency::interior).size(), 12u);
  EXPECT_EQ(zdg::track_surface(two, box, seed, SurfelAdjacency::exterior).size(), 6u);
  // Through the linel of the shared edge, the follower of the +x face of (0,0,0) turns to
  // the -y face of (1,1,0) (interior) or to the +y face of (0,0,0) (exterior).
  const auto s = zdg::surfel_between({0, 0, 0}, 0, +1);
  EXPECT_EQ(zdg::adjacent_surfel(two, box, s, 1, +1, SurfelAdjacency::interior),
            zdg::surfel_between({1, 1, 0}, 1, -1));
  EXPECT_EQ(zdg::adjacent_surfel(two, box, s, 1, +1, SurfelAdjacency::exterior),
            zdg::surfel_between({0, 0, 0}, 1, +1));
}

TEST(DigitalSurface, BoxClipsTheSet) {
  // The whole box inside: the surface is the box boundary, 2 (ab + bc + ca) surfels.
  const VoxelBox box{{-1, 0, 5}, {2, 2, 5}};
  const auto s = zdg::boundary_surfels([](const Voxel&) { return true; }, box);
  EXPECT_EQ(s.size(), 2u * (4 * 3 + 3 * 1 + 1 * 4));
  EXPECT_EQ(zdg::euler_characteristic(zdg::primal_surface(s)), 2);
}

TEST(DigitalSurface, Errors) {
  const VoxelBox box{{-3, -3, -3}, {3, 3, 3}};
  const auto inside = ball({0, 0, 0}, 4);
  EXPECT_THROW(zdg::find_boundary_surfel(inside, box, {3, 3, 3}), zdg::InvalidArgument);
  EXPECT_THROW(zdg::track_surface(inside, box, zdg::surfel_between({0, 0, 0}, 0, 1)),
               zdg::InvalidArgument);
  EXPECT_THROW(zdg::track_surface(inside, box, {{1, 1, 1}, true}), zdg::InvalidArgument);
}

// Random sets in a small box: the slice scan equals the definition, and for both
// adjacencies every surfel has four symmetric followers.
TEST(DigitalSurface, RandomSetsScanAndAdjacency) {
  zdg::test::check_property([] {
    const auto bits = *rc::gen::container<std::vector<bool>>(5 * 4 * 3, rc::gen::arbitrary<bool>());
    const VoxelBox box{{-2, 1, -1}, {2, 4, 1}};
    const zdg::VoxelPredicate inside = [&](const Voxel& z) {
      return bits[std::size_t(((z.z + 1) * 4 + (z.y - 1)) * 5 + (z.x + 2))];
    };
    const auto s = zdg::boundary_surfels(inside, box);
    RC_ASSERT(s == brute_surfels(inside, box));
    for (auto adj : {SurfelAdjacency::interior, SurfelAdjacency::exterior}) {
      check_closed(inside, box, s, adj);
      RC_ASSERT(!::testing::Test::HasFailure());
      // The surfaces partition the boundary.
      std::set<Surfel> left(s.begin(), s.end());
      while (!left.empty()) {
        const auto t = zdg::track_surface(inside, box, *left.begin(), adj);
        for (const auto& u : t) RC_ASSERT(left.erase(u) == 1u);
      }
    }
  });
}

} // namespace
