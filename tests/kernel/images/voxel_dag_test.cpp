#include <zdg/arith/error.hpp>
#include <zdg/kernel/images/voxel_dag.hpp>

#include "tests/support/tower.hpp"

#include <gtest/gtest.h>
#include <rapidcheck.h>

#include <algorithm>
#include <map>
#include <set>

namespace zdg {
namespace {

using Voxel = std::array<std::int64_t, 3>;
constexpr VoxelDagKind kKinds[] = {VoxelDagKind::svo, VoxelDagKind::dag, VoxelDagKind::ssvdag};

std::uint8_t at(const Image<std::uint8_t>& img, const Voxel& v) {
  const auto& d = img.domain();
  return img.values()[static_cast<std::size_t>((v[2] * d.extent(1) + v[1]) * d.extent(2) + v[0])];
}

// A random volume of extent (nx, ny, nz) in [1, hi]: blobs (runs of set voxels, so that some
// 4^3 and 8^3 cubes are full and many are equal) or scattered voxels.
Image<std::uint8_t> random_volume(std::int64_t hi) {
  const std::int64_t nx = *rc::gen::inRange<std::int64_t>(1, hi + 1),
                     ny = *rc::gen::inRange<std::int64_t>(1, hi + 1),
                     nz = *rc::gen::inRange<std::int64_t>(1, hi + 1);
  Image<std::uint8_t> img(Domain({nz, ny, nx}));
  const int style = *rc::gen::inRange(0, 3);
  auto& v = img.values();
  if (style == 0) {
    const int pct = *rc::gen::inRange(0, 101);
    for (auto& x : v) x = *rc::gen::inRange(0, 100) < pct ? 1 : 0;
  } else {
    const int boxes = *rc::gen::inRange(0, 6);
    for (int b = 0; b < boxes; ++b) {
      Voxel lo{}, up{};
      const Voxel n{nx, ny, nz};
      for (std::size_t a = 0; a < 3; ++a) {
        lo[a] = *rc::gen::inRange<std::int64_t>(0, n[a]);
        up[a] = *rc::gen::inRange<std::int64_t>(lo[a], n[a]) + 1;
      }
      const std::uint8_t value = style == 2 && b % 2 == 1 ? 0 : 1;
      for (std::int64_t z = lo[2]; z < up[2]; ++z)
        for (std::int64_t y = lo[1]; y < up[1]; ++y)
          for (std::int64_t x = lo[0]; x < up[0]; ++x)
            v[static_cast<std::size_t>((z * ny + y) * nx + x)] = value;
    }
  }
  return img;
}

// Rays with coarse numerators: through edges, corners and in face planes, every octant.
DigitalRay random_ray(const Voxel& n) {
  DigitalRay r;
  r.denominator = *rc::gen::inRange<std::int64_t>(1, 7);
  for (std::size_t a = 0; a < 3; ++a) {
    r.origin[a] = *rc::gen::inRange<std::int64_t>(-3 * r.denominator, (n[a] + 3) * r.denominator);
    r.direction[a] = *rc::gen::inRange<std::int64_t>(-4, 5);
  }
  if (r.direction == Voxel{0, 0, 0}) r.direction[std::size_t(*rc::gen::inRange(0, 3))] = 1;
  return r;
}

// The oracle of a hit's axis: the entry axis of the line's chord of that voxel alone (the
// line moved by -v), the lowest axis among the faces it enters by at once.
int entry_axis(const DigitalRay& r, const Voxel& v) {
  DigitalRay s = r;
  for (std::size_t a = 0; a < 3; ++a) s.origin[a] -= v[a] * r.denominator;
  const RayChord c = digital_ray_chord(s, {1, 1, 1});
  return c.in_axis;
}

Voxel extent_of(const Image<std::uint8_t>& img) {
  return {img.domain().extent(2), img.domain().extent(1), img.domain().extent(0)};
}

// The structure stores the volume: decoding and membership equal the dense volume, for every
// kind, including the points outside the extent and the padding of the cube.
TEST(VoxelDag, MembershipAndDecodingEqualTheDenseVolume) {
  test::check_property([] {
    const auto img = random_volume(13);
    const Voxel n = extent_of(img);
    for (auto kind : kKinds) {
      const VoxelDag g = build_voxel_dag(img, kind);
      RC_ASSERT(g.to_image().values() == img.values());
      std::int64_t count = 0;
      for (std::int64_t z = -1; z <= n[2]; ++z)
        for (std::int64_t y = -1; y <= n[1]; ++y)
          for (std::int64_t x = -1; x <= n[0]; ++x) {
            const Voxel v{x, y, z};
            const bool inside = x >= 0 && y >= 0 && z >= 0 && x < n[0] && y < n[1] && z < n[2];
            const bool set = inside && at(img, v) != 0;
            RC_ASSERT(g.contains(v) == set);
            count += set;
          }
      RC_ASSERT(g.stats().voxels == count);
    }
  });
}

// Ray queries against the dense oracle: the set voxels among digital_ray_voxels (the kernel's
// exact Amanatides-Woo line, itself checked against a brute-force walk of every face crossing),
// in the same order, each with the axis of the face the line enters it by; first_hit the first.
TEST(VoxelDag, RayHitsAreTheSetVoxelsOfTheDigitalRay) {
  test::check_property([] {
    const auto img = random_volume(11);
    const Voxel n = extent_of(img);
    const DigitalRay r = random_ray(n);
    std::vector<DagRayHit> want;
    for (const Voxel& v : digital_ray_voxels(r, n))
      if (at(img, v) != 0) want.push_back({v, entry_axis(r, v)});
    for (auto kind : kKinds) {
      const VoxelDag g = build_voxel_dag(img, kind);
      RC_ASSERT(g.ray_hits(r) == want);
      const auto first = g.first_hit(r);
      RC_ASSERT(first.has_value() == !want.empty());
      if (first) RC_ASSERT(*first == want.front());
      const std::size_t k = *rc::gen::inRange<std::size_t>(0, want.size() + 2);
      const auto some = g.ray_hits(r, k);
      RC_ASSERT(some.size() == std::min(k, want.size()));
      RC_ASSERT(std::equal(some.begin(), some.end(), want.begin()));
    }
  });
}

// Long rays through a larger scene with big numerators (up to 2^42): the 128-bit comparisons
// at the bounds of digital_ray.hpp.
TEST(VoxelDag, LargeNumeratorsGiveTheSameHits) {
  test::check_property([] {
    const auto img = random_volume(20);
    const Voxel n = extent_of(img);
    const DigitalRay r = random_ray(n);
    const std::int64_t k = *rc::gen::inRange<std::int64_t>(1, std::int64_t{1} << 34);
    DigitalRay s = r;
    s.denominator *= k;
    for (std::size_t a = 0; a < 3; ++a) {
      s.origin[a] *= k;
      s.direction[a] *= std::int64_t{1} << 37;
    }
    const VoxelDag g = build_voxel_dag(img, VoxelDagKind::ssvdag);
    RC_ASSERT(g.ray_hits(s) == g.ray_hits(r));
  });
}

// Node counts against brute force: the tree has one node per non-empty aligned cube of each
// level; the DAG one per distinct subtree (distinct leaf masks, distinct child lists); the
// SSVDAG one per class under the 8 reflections. ssvdag <= dag <= svo level by level.
TEST(VoxelDag, NodeCountsAreTheDistinctSubtrees) {
  test::check_property([] {
    const auto img = random_volume(16);
    const Voxel n = extent_of(img);
    const VoxelDag svo = build_voxel_dag(img, VoxelDagKind::svo);
    const VoxelDag dag = build_voxel_dag(img, VoxelDagKind::dag);
    const VoxelDag ss = build_voxel_dag(img, VoxelDagKind::ssvdag);
    const int depth = svo.depth();
    const std::int64_t side = svo.side();
    auto bit = [&](const Voxel& v) {
      return v[0] < n[0] && v[1] < n[1] && v[2] < n[2] && at(img, v) != 0;
    };
    // The content of each aligned cube of level l as the sorted list of its set voxels
    // (relative), and its 8 reflections.
    for (int level = 2; level <= depth; ++level) {
      const std::int64_t e = std::int64_t{1} << level;
      std::int64_t cubes = 0;
      std::set<std::vector<Voxel>> distinct, classes;
      for (std::int64_t cz = 0; cz < side; cz += e)
        for (std::int64_t cy = 0; cy < side; cy += e)
          for (std::int64_t cx = 0; cx < side; cx += e) {
            std::array<std::vector<Voxel>, 8> refl;
            for (std::int64_t z = 0; z < e; ++z)
              for (std::int64_t y = 0; y < e; ++y)
                for (std::int64_t x = 0; x < e; ++x)
                  if (bit({cx + x, cy + y, cz + z}))
                    for (unsigned m = 0; m < 8; ++m)
                      refl[m].push_back(
                          {m & 1 ? e - 1 - x : x, m & 2 ? e - 1 - y : y, m & 4 ? e - 1 - z : z});
            if (refl[0].empty()) continue;
            ++cubes;
            for (auto& r : refl) std::sort(r.begin(), r.end());
            distinct.insert(refl[0]);
            classes.insert(*std::min_element(refl.begin(), refl.end()));
          }
      const auto i = static_cast<std::size_t>(depth - level);
      RC_ASSERT(svo.stats().nodes_per_level[i] == cubes);
      RC_ASSERT(dag.stats().nodes_per_level[i] == std::int64_t(distinct.size()));
      RC_ASSERT(ss.stats().nodes_per_level[i] == std::int64_t(classes.size()));
    }
    const auto a = svo.stats(), b = dag.stats(), c = ss.stats();
    RC_ASSERT(a.svo_inner_nodes == a.inner_nodes);
    RC_ASSERT(a.svo_leaves == a.leaves);
    RC_ASSERT(b.svo_inner_nodes == a.inner_nodes && c.svo_leaves == a.leaves);
    RC_ASSERT(c.bytes <= b.bytes);
    RC_ASSERT(b.bytes <= a.bytes);
    RC_ASSERT(a.bytes == a.svo_bytes);
    RC_ASSERT(a.pointers == a.svo_pointers && b.svo_pointers == a.pointers);
  });
}

// Streaming: slices given in any grouping build the same structure as the whole volume.
TEST(VoxelDag, SlabsInAnyGroupingBuildTheSameDag) {
  test::check_property([] {
    const auto img = random_volume(14);
    const Voxel n = extent_of(img);
    const auto kind =
        *rc::gen::elementOf(std::vector<VoxelDagKind>(std::begin(kKinds), std::end(kKinds)));
    const VoxelDag whole = build_voxel_dag(img, kind);
    VoxelDagBuilder b(n, kind);
    std::int64_t z = 0;
    while (z < n[2]) {
      const std::int64_t k = *rc::gen::inRange<std::int64_t>(0, n[2] - z + 1);
      b.add_slices(img.values().data() + z * n[0] * n[1], k);
      z += k;
      if (*rc::gen::inRange(0, 4) == 0) break; // the rest left out: empty
    }
    const VoxelDag part = b.finish();
    Image<std::uint8_t> want = img;
    std::fill(want.values().begin() + z * n[0] * n[1], want.values().end(), 0);
    RC_ASSERT(part.to_image().values() == want.values());
    if (z == n[2]) {
      const auto s = part.stats(), t = whole.stats();
      RC_ASSERT(s.nodes_per_level == t.nodes_per_level);
      RC_ASSERT(s.bytes == t.bytes);
    }
  });
}

// A reflected scene (the whole cube reflected) has the same SSVDAG counts.
TEST(VoxelDag, ReflectedScenesShareTheSymmetricCounts) {
  test::check_property([] {
    const std::int64_t side = std::int64_t{1} << *rc::gen::inRange(2, 5);
    Image<std::uint8_t> img(Domain({side, side, side}));
    for (auto& x : img.values()) x = *rc::gen::inRange(0, 5) == 0 ? 1 : 0;
    const unsigned m = *rc::gen::inRange(1u, 8u);
    Image<std::uint8_t> refl(Domain({side, side, side}));
    for (std::int64_t z = 0; z < side; ++z)
      for (std::int64_t y = 0; y < side; ++y)
        for (std::int64_t x = 0; x < side; ++x) {
          const std::int64_t rx = m & 1 ? side - 1 - x : x, ry = m & 2 ? side - 1 - y : y,
                             rz = m & 4 ? side - 1 - z : z;
          refl.values()[std::size_t((rz * side + ry) * side + rx)] =
              img.values()[std::size_t((z * side + y) * side + x)];
        }
    const auto a = build_voxel_dag(img, VoxelDagKind::ssvdag).stats();
    const auto b = build_voxel_dag(refl, VoxelDagKind::ssvdag).stats();
    RC_ASSERT(a.nodes_per_level == b.nodes_per_level);
    RC_ASSERT(a.bytes == b.bytes);
  });
}

TEST(VoxelDag, WorkedExamples) {
  // A full 16^3 cube: the tree has 64 leaves and 8 + 1 nodes; the DAG one node per level.
  Image<std::uint8_t> full(Domain({16, 16, 16}));
  std::fill(full.values().begin(), full.values().end(), 1);
  const auto t = build_voxel_dag(full, VoxelDagKind::svo).stats();
  EXPECT_EQ(t.depth, 4);
  EXPECT_EQ(t.nodes_per_level, (std::vector<std::int64_t>{1, 8, 64}));
  EXPECT_EQ(t.bytes, 4 * (9 + 72) + 8 * 64);
  const auto d = build_voxel_dag(full, VoxelDagKind::dag).stats();
  EXPECT_EQ(d.nodes_per_level, (std::vector<std::int64_t>{1, 1, 1}));
  EXPECT_EQ(d.bytes, 4 * (2 + 16) + 8);
  EXPECT_EQ(d.voxels, 4096);
  EXPECT_DOUBLE_EQ(d.bits_per_voxel(), 8.0 * 80 / 4096);
  // One voxel in each corner of an 8^3 cube: 8 leaves in the tree, 8 distinct masks in the DAG,
  // one class under reflection in the SSVDAG.
  Image<std::uint8_t> corners(Domain({8, 8, 8}));
  for (std::int64_t z : {0, 7})
    for (std::int64_t y : {0, 7})
      for (std::int64_t x : {0, 7}) corners.values()[std::size_t((z * 8 + y) * 8 + x)] = 1;
  EXPECT_EQ(build_voxel_dag(corners, VoxelDagKind::svo).stats().leaves, 8);
  EXPECT_EQ(build_voxel_dag(corners, VoxelDagKind::dag).stats().leaves, 8);
  const VoxelDag ss = build_voxel_dag(corners, VoxelDagKind::ssvdag);
  EXPECT_EQ(ss.stats().leaves, 1);
  EXPECT_EQ(ss.stats().inner_nodes, 1);
  // The diagonal ray (0,0,0) + t (1,1,1) meets the corners (0,0,0) and (7,7,7) only, entering
  // the second through its corner (the lowest axis, x, is reported).
  const auto hits = ss.ray_hits({{0, 0, 0}, {1, 1, 1}, 1});
  ASSERT_EQ(hits.size(), 2u);
  EXPECT_EQ(hits[0].voxel, (Voxel{0, 0, 0}));
  EXPECT_EQ(hits[1].voxel, (Voxel{7, 7, 7}));
  EXPECT_EQ(hits[1].axis, 0);
  // Backwards along z at x = 7, y = 0: the first hit is (7, 0, 7), entered by its z face.
  const auto h = ss.first_hit({{7, 0, 100}, {0, 0, -1}, 1});
  ASSERT_TRUE(h.has_value());
  EXPECT_EQ(h->voxel, (Voxel{7, 0, 7}));
  EXPECT_EQ(h->axis, 2);
  EXPECT_FALSE(ss.first_hit({{3, 3, -5}, {0, 0, 1}, 1}).has_value());
  // Regression (shrunk by NodeCountsAreTheDistinctSubtrees): two 8^3 cubes, mirror images along
  // x, each with a full 4^3 brick (symmetric under every reflection) and one voxel. Their
  // references to the full brick differ by the reflection x unless the bits are taken modulo the
  // brick's symmetries: one level-3 class, not two.
  Image<std::uint8_t> pair(Domain({8, 8, 16}));
  auto put = [&](std::int64_t x, std::int64_t y, std::int64_t z) {
    pair.values()[std::size_t((z * 8 + y) * 16 + x)] = 1;
  };
  for (std::int64_t z = 0; z < 4; ++z)
    for (std::int64_t y = 0; y < 4; ++y)
      for (std::int64_t x = 0; x < 4; ++x) {
        put(x, y, z);
        put(15 - x, y, z);
      }
  put(5, 0, 0);
  put(10, 0, 0);
  const auto p = build_voxel_dag(pair, VoxelDagKind::ssvdag).stats();
  EXPECT_EQ(p.nodes_per_level, (std::vector<std::int64_t>{1, 1, 2}));
  EXPECT_EQ(build_voxel_dag(pair, VoxelDagKind::dag).stats().nodes_per_level,
            (std::vector<std::int64_t>{1, 2, 3}));
  // The empty scene.
  const VoxelDag none = build_voxel_dag(Image<std::uint8_t>(Domain({3, 3, 3})), VoxelDagKind::dag);
  EXPECT_FALSE(none.contains({0, 0, 0}));
  EXPECT_TRUE(none.ray_hits({{0, 0, 0}, {1, 2, 3}, 1}).empty());
  EXPECT_EQ(none.stats().bytes, 0);
  EXPECT_EQ(none.to_image().values(), std::vector<std::uint8_t>(27, 0));
}

TEST(VoxelDag, Errors) {
  EXPECT_THROW(VoxelDagBuilder({0, 4, 4}, VoxelDagKind::dag), InvalidArgument);
  EXPECT_THROW(VoxelDagBuilder({4, (std::int64_t{1} << 20) + 1, 4}, VoxelDagKind::dag),
               InvalidArgument);
  EXPECT_THROW(build_voxel_dag(Image<std::uint8_t>(Domain({4, 4})), VoxelDagKind::dag),
               InvalidArgument);
  VoxelDagBuilder b({2, 2, 2}, VoxelDagKind::dag);
  const std::uint8_t data[12] = {};
  b.add_slices(data, 2);
  EXPECT_THROW(b.add_slices(data, 1), InvalidArgument);
  const VoxelDag g = b.finish();
  EXPECT_THROW((void)g.ray_hits({{0, 0, 0}, {0, 0, 0}, 1}), InvalidArgument);
  EXPECT_THROW((void)g.ray_hits({{0, 0, 0}, {1, 0, 0}, 0}), InvalidArgument);
  EXPECT_EQ(parse_voxel_dag_kind("ssvdag"), VoxelDagKind::ssvdag);
  EXPECT_THROW((void)parse_voxel_dag_kind("octree"), InvalidArgument);
}

} // namespace
} // namespace zdg
